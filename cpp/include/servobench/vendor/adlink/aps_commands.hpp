// The ADLINK APS functions whose arguments are numbers and arrays of numbers, with their argument checks (manual
// seed 004; decisions AY1-AY6): one runner, aps_command(card, name, args), over a map from the manual's name to one
// function of (card, arguments in the manual's units: pulse, pulse/s, pulse/s^2, degrees). Each function checks
// its arguments in the order the manual and the dialect always did, calls the card, and returns the APS code
// (return_code.hpp) -- it never throws:
//   ERR_DeviceNotInitial  no card open (APS_initial not called), where the function needs it;
//   ERR_ParametersInvalid an axis ID not 0..n-1, a value out of its range or not a number, a bad array;
//   a refusal of the card (machine::CardCommandRefused / motion::MotionCommandRefused) mapped by code_of() from
//   the fault the card recorded (EMG, ALM, a limit toward the move: ignored, ERR_NoError, L3931-4010, V47);
//   std::invalid_argument / domain_error / length_error of a value the card rejects: ERR_ParametersInvalid.
// Chapters: aps_commands_motion.cpp (servo, PTP, velocity, jog, home, stops, gear, positions, status, PRA_*),
// aps_commands_interp.cpp (APS_line / arc / spiral and the linear moves, L2813-3150), aps_commands_compare.cpp
// (the position compare trigger and the compare timer counter, L3348-3435).
#pragma once

#include <string>
#include <vector>

#include "servobench/machine/card.hpp"
#include "servobench/vendor/adlink/return_code.hpp"

namespace servobench::vendor::adlink {

// The arguments of one call in the order of the manual (after self): a number as one value, an array as its
// values; an argument that was not given (Python None) as no values; a value that is not a number as NaN.
using ApsArgs = std::vector<std::vector<double>>;

// What a function returns: its code; a read also its values ('i' integer, 'f' double per value; the zeros a failed
// read returns), a status word ("w") the word itself in values[0] (or the code, when it failed).
struct ApsReply {
  AdlinkCode code = AdlinkCode::NoError;
  std::vector<double> values;
  std::string kinds;
};

// One function the runner knows: its name, the kind of each argument ('n' number, 'a' array) and its reply kinds
// ("" a command: the code; "w" a status word; else the read's value kinds).
struct ApsCommandShape {
  std::string name;
  std::string args;
  std::string reply;
};

// Runs APS function `name` on `card` (nullptr: no card is open). Unknown name: std::invalid_argument.
ApsReply aps_command(machine::Card* card, const std::string& name, const ApsArgs& args);
// The functions aps_command runs, with their argument and reply kinds.
const std::vector<ApsCommandShape>& aps_command_shapes();

}  // namespace servobench::vendor::adlink
