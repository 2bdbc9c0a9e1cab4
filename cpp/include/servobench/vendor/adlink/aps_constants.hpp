// The ADLINK APS library's header constants (APS_define.h, ErrorCodeDef.h, type_def.h as manual seed 004 uses them)
// as one table: name, value, whether the header writes it in hex, what it is (units, manual lines). Session 13:
// AX1-AX2.
//
// Where the C++ vendor module has the value (return codes AdlinkCode, status bits ApsMsts/ApsMio, stop codes,
// PRA_* numbers pra::Number, sampling parameter numbers, watchdog and point-table bits), the row reads it from
// there, so the dialect's constant and the module's value cannot differ; the other rows are the header's numbers.
// Bound as _core.APS_CONSTANTS; scripts/aps_constants.py writes python/servobench/dialects/_aps_constants.py from
// it (a committed, generated table module, so `from servobench.dialects.aps import *` stays typed for mypy) and
// test_dialect_layout_aps checks the two are equal.
#pragma once

#include <vector>

namespace servobench::vendor::adlink {

struct ApsConstant {
  const char* name;  // the header's name (the dialect's Python name)
  long long value;
  bool hex;          // written in hex by the header (register and parameter numbers, bit masks)
  const char* doc;   // what it is: units, manual lines, decisions
};

// Every constant, in the order the dialect lists them (return codes, PRA_*, status bits, stop codes, options,
// sampling, trigger, interrupts, board, VAO, watchdog, point tables).
const std::vector<ApsConstant>& aps_constants();

}  // namespace servobench::vendor::adlink
