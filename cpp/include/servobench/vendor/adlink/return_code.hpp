// The ADLINK APS library's return codes (I32; ERR_NoError = success). The manual (seed 004) names only
// ERR_NoError (L2309) and includes ErrorCodeDef.h (L2285); the values and meanings are that header's (decision V49).
// The kernel refuses with a neutral machine::CommandFault; the APS dialect maps it to these with one table.
#pragma once

namespace servobench::vendor::adlink {

enum class AdlinkCode : int {
  NoError = 0,                 // ERR_NoError (L2309)
  DeviceNotInitial = -4,       // ERR_DeviceNotInitial: APS_initial not called
  DeviceAlreadyInitialed = -7, // ERR_DeviceAlreadyInitialed: APS_initial twice
  InterruptNotEnable = -8,     // ERR_InterruptNotEnable: a wait on an interrupt whose main switch or factor is off
  TimeOut = -9,                // ERR_TimeOut: a wait (sampling, interrupt) ran out of its time-out
  ParametersInvalid = -10,     // ERR_ParametersInvalid: bad axis ID, parameter number or value
  FunctionNotAvailable = -13,  // ERR_FunctionNotAvailable: refused in this state ("not available in this step")
  DistantNotEnough = -22,      // ERR_DistantNotEnough: a PTP shorter than its VS -> VE ramps (decision M9)
};

const char* to_string(AdlinkCode code);

}  // namespace servobench::vendor::adlink
