// The ADLINK APS functions as the manual describes them, one row each: the manual name, the arguments as the Python
// signature spells them ("Axis_ID, Option, Position, Wait=None"), what the function does (units, manual lines of
// seed 004, decisions). Written once here, beside the vendor module that carries them out; the dialect
// (servobench.dialects.aps) takes each function's docstring from its row, and tests/python/test_dialect_layout_aps.py
// checks every row's arguments against the function's signature. Session 12: the point table's rows (AW7,
// pt_commands in aps_point_table.cpp); session 13: the other APS_* functions (AX2, aps_commands).
#pragma once

#include <vector>

namespace servobench::vendor::adlink {

struct ApsCommandDoc {
  const char* name;
  const char* args;
  const char* doc;
};

// APS_pt_* and APS_get_pt_status (§4.10.6); the arguments after (Board_ID, PtbId). _core.APS_PT_COMMANDS.
const std::vector<ApsCommandDoc>& pt_commands();

// Every other APS_* function the dialect writes out (system, axis parameters, motion, interpolation, positions,
// status, sampling, compare trigger, interrupts, counters, watchdog, board, VAO); the arguments after self.
// _core.APS_COMMANDS.
const std::vector<ApsCommandDoc>& aps_commands();

// The arcs and spirals (APS_arc2_ca ... APS_sprial_ce, each with its _v and _all form; L2899-3063): their own table,
// as the _v / _all forms' one-line docs name their base function rather than the manual's C signature.
// _core.APS_ARC_COMMANDS.
const std::vector<ApsCommandDoc>& aps_arc_commands();

}  // namespace servobench::vendor::adlink
