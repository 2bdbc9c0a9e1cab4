// Unit conversions between the manuals' time bases and the generators' tick.
//
// GT: everything is already per sample time (pulse/ST, pulse/ST^2, pulse/ST^3; GT L854-858), so the tick
// is the ST and nothing converts. GE / GUC-ECAT / iDEABOX: pulse/ms, pulse/ms^2, pulse/ms^3 (GE L991-996).
// ADLINK: pulse/s, pulse/s^2 (the unit factor is 1 by default, ADLINK L2141).
#pragma once

namespace servobench::motion {

// Converts a quantity per ms^order to per tick^order for a tick of `period_s` seconds.
inline double per_ms_to_per_tick(double value, double period_s, int order) {
  const double ticks_per_ms = 1e-3 / period_s;
  double f = 1.0;
  for (int i = 0; i < order; ++i) f /= ticks_per_ms;
  return value * f;
}

// Converts a quantity per s^order to per tick^order for a tick of `period_s` seconds.
inline double per_s_to_per_tick(double value, double period_s, int order) {
  double f = 1.0;
  for (int i = 0; i < order; ++i) f *= period_s;
  return value * f;
}

}  // namespace servobench::motion
