#include "servobench/vendor/googol/return_code.hpp"

namespace servobench::vendor::googol {

const char* to_string(GtCode code) {
  switch (code) {
    case GtCode::Success: return "success";
    case GtCode::CommandError: return "command error";
    case GtCode::ArcRadiusError: return "arc radius error";
    case GtCode::LineLengthError: return "line length error";
    case GtCode::SynParamError: return "vector velocity/acceleration error";
    case GtCode::ArcEndPointError: return "arc end point error";
    case GtCode::MapAxisError: return "axis mapping error";
    case GtCode::ParameterError: return "parameter error";
    case GtCode::CommError: return "communication error";
  }
  return "?";
}

const char* to_string(GeCode code) {
  switch (code) {
    case GeCode::Success: return "success";
    case GeCode::CommandError: return "command error";
    case GeCode::ArcRadiusError: return "arc radius error";
    case GeCode::LineLengthError: return "line length error";
    case GeCode::SynParamError: return "vector velocity/acceleration error";
    case GeCode::ArcChordError: return "arc chord error";
    case GeCode::ParameterError: return "parameter error";
    case GeCode::ProgramRunning: return "program running";
    case GeCode::Reentered: return "command re-entered";
    case GeCode::CommError: return "communication error";
  }
  return "?";
}

const char* to_string(GucCode code) {
  switch (code) {
    case GucCode::Success: return "success";
    case GucCode::CommandError: return "command error";
    case GucCode::LicenseError: return "license error";
    case GucCode::ParameterError: return "parameter error";
    case GucCode::CommError: return "communication error";
    case GucCode::OpenFailed: return "open card failed";
    case GucCode::NoResponse: return "no response from controller";
  }
  return "?";
}

}  // namespace servobench::vendor::googol
