#include "servobench/vendor/adlink/return_code.hpp"

namespace servobench::vendor::adlink {

const char* to_string(AdlinkCode code) {
  switch (code) {
    case AdlinkCode::NoError: return "ERR_NoError";
    case AdlinkCode::DeviceNotInitial: return "ERR_DeviceNotInitial";
    case AdlinkCode::DeviceAlreadyInitialed: return "ERR_DeviceAlreadyInitialed";
    case AdlinkCode::InterruptNotEnable: return "ERR_InterruptNotEnable";
    case AdlinkCode::TimeOut: return "ERR_TimeOut";
    case AdlinkCode::ParametersInvalid: return "ERR_ParametersInvalid";
    case AdlinkCode::FunctionNotAvailable: return "ERR_FunctionNotAvailable";
    case AdlinkCode::DistantNotEnough: return "ERR_DistantNotEnough";
  }
  return "?";
}

}  // namespace servobench::vendor::adlink
