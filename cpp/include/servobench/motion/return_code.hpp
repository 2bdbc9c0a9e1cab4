// The Googol return codes (GUC-ECAT Tab 2-1, L165-180; iDEABOX Table 3-1, L333-361), kept ready for the
// virtual card's vendor facades.
//
// The generators of this folder signal the same conditions with exceptions: a parameter error (code 7) is a
// std::invalid_argument (ValueError in Python) naming the parameter and its range; a command error (code 1:
// wrong state, full FIFO or table, empty table) is a MotionCommandRefused (RuntimeError in Python) whose
// message says "return code 1". The card's facades will map them back to these numbers.
#pragma once

namespace servobench::motion {

enum class ReturnCode : int {
  Success = 0,          // 0: success
  CommandError = 1,     // 1: execution condition not met (state, full FIFO/table, empty table)
  LicenseError = 2,     // 2: feature not licensed
  ParameterError = 7,   // 7: parameter out of range
  CommError = -1,       // -1: host <-> controller communication failed
  OpenFailed = -6,      // -6: opening the card failed (e.g. GT_Open twice)
  NoResponse = -7,      // -7: controller does not respond
};

inline const char* to_string(ReturnCode code) {
  switch (code) {
    case ReturnCode::Success: return "success";
    case ReturnCode::CommandError: return "command error";
    case ReturnCode::LicenseError: return "license error";
    case ReturnCode::ParameterError: return "parameter error";
    case ReturnCode::CommError: return "communication error";
    case ReturnCode::OpenFailed: return "open card failed";
    case ReturnCode::NoResponse: return "no response from controller";
  }
  return "?";
}

}  // namespace servobench::motion
