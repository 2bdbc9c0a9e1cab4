// The GE commands as one table and the per-axis / card commands that act on the kernel (GE manual seed 001; digest
// ge.md §7; decisions GV6, GW1-GW4).
//
// ge_command_table(): every GE function the dialect (servobench.dialects.ge) makes from a row, described once:
// the manual's name, its parameters as the Python names and defaults, the variant whose command set has it (ch11
// Table 11-1 PX / 11-2 SX; the other variant returns 1), whether its C form writes through pointers (a read: the
// Python function returns (rtn, value)), and what the manual says (units, the manual's lines) -- the docstring of
// the generated Python function.
//
// ge_command(card, variant, name, args): runs one of the commands implemented here, arguments as doubles in the
// manual's units (pulse, pulse/ms, pulse/ms^2, pulse/ms^3, DAC counts; axis numbers 1..axes). The argument checks
// are here, once: a bad axis number records IllegalControlParam and returns 7, a value out of the manual's range
// records the row's fault (MotionParamOverflow for a motion parameter, else IllegalControlParam) and returns 7, a
// card refusal (machine::CardCommandRefused, the fault recorded by the kernel) returns 1, a value the kernel finds
// invalid (std::invalid_argument) returns 7. Never throws for a name in ge_axis_command_names() given its row's
// arguments (the dialect passes exactly the row's parameters); an unknown name
// throws std::invalid_argument (a programming error of the dialect, not a program's).
#pragma once

#include <string>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/vendor/googol/ge_status.hpp"
#include "servobench/vendor/googol/return_code.hpp"

namespace servobench::vendor::googol {

enum class GeCommandSet : int { Both = 0, PX = 1, SX = 2 };

struct GeCommandRow {
  const char* name;    // GT_* as the manual spells it
  const char* params;  // the parameters, Python names and defaults ("axis, pos", "pMsg=None")
  GeCommandSet set;    // which variant's command set has it
  bool read;           // the C form writes through pointers: (rtn, value) in Python
  const char* doc;     // what it does, units, the manual's lines
};

const std::vector<GeCommandRow>& ge_command_table();

// A command's reply: the code and, for a read, the value (`integer`: a C integer type, else double).
struct GeReply {
  GeCode code = GeCode::Success;
  double value = 0.0;
  bool integer = true;
  bool read = false;  // a read: (rtn, value) in Python
};

// The names ge_command runs (the per-axis and card commands on the kernel and the GE registers module).
std::vector<std::string> ge_axis_command_names();
GeReply ge_command(machine::Card& card, GeVariant variant, const std::string& name, const std::vector<double>& args);

// GE argument ranges (GE manual): whole pulses -2^30..2^30-1 (L991, L5457-5463); velocity 0..40957 pulse/ms,
// -40958 in velocity mode (L5780-5786, L1202-1206); acceleration 0..102400 pulse/ms^2 (L5435-5437); jerk
// 0..256000 pulse/ms^3 (L5518-5520); gains 0..32767 (L5530-5620).
inline constexpr double kGePosMin = -1073741824, kGePosMax = 1073741823;
inline constexpr double kGeVelMax = 40957, kGeVelMinJog = -40958;
inline constexpr double kGeAccMax = 102400, kGeJerkMax = 256000, kGeGainMax = 32767;

}  // namespace servobench::vendor::googol
