// Stability of a simulated axis's position loop from its linear model, and the analytic margins that carry it
// (issue 20: stability before margins).
//
// The loop (docs/bode.md, "the analytic loop"): controller K = output stage * biquad 1 * biquad 0 * PID, E -> V,
//   PID     u = kp e + ki Sum + kd (e - e(k-1)), Sum(k) = Sum(k-1) + e(k)   (GT L801-803, ADLINK L1723-1731;
//           the integral state exists only when the integral term acts: ki != 0 and a non-zero integral limit)
//   biquads in transposed direct form II from their coefficients (ADLINK integers through to_float)
// and plant P, V -> Y (pulse): the power train's tick model lifted exactly to the servo rate with the one-tick
// output delay. Closing e = -y gives the closed loop's state matrix; its eigenvalues are the closed-loop poles
// (feed-forward acts on the command only and moves none of them). Open-loop poles: the eigenvalues of K and P;
// those within 1e-6 of z = 1 are integrators, those with |z| > 1 otherwise the P of the Nyquist criterion.
// Exact for a linear configuration: no friction, saturation, quantisation or noise.
#pragma once

#include <complex>
#include <vector>

#include "servobench/machine/axis.hpp"
#include "servobench/tuning/loop_response.hpp"
#include "servobench/tuning/margins.hpp"

namespace servobench::tuning {

struct LoopPoles {
  std::vector<Complex> closed_loop;  // closed-loop poles, z
  std::vector<Complex> open_loop;    // poles of K and P, z
  double max_radius = 0;             // largest |closed-loop pole|
  int integrators = 0;               // open-loop poles at z = 1 (within 1e-6)
  int open_loop_unstable = 0;        // other open-loop poles with |z| > 1 + 1e-9
};

// The loop's poles (options.filters false: the biquads bypassed, as a measurement without them runs). Throws
// std::invalid_argument for a pulse-output axis (no position loop on the card).
LoopPoles loop_poles(const machine::AxisConfig& config, const LoopOptions& options = {});

// The verdict from the closed-loop poles: stable iff every |z| < 1.
Stability pole_stability(const LoopPoles& poles);

// Largest |pole| of the closed position loop with both biquads: < 1 means stable.
double closed_loop_pole_radius(const machine::AxisConfig& config);

// The loop's margins (margins.hpp) from the analytic loop gain: stability from the closed-loop poles, every
// crossing found on `freq_hz` (increasing, each in (0, Nyquist)) refined on the exact L, plus a phase crossover
// at the Nyquist frequency when L is real negative there and the grid reaches past 0.45 / Ts. Empty freq_hz: a
// log grid of 4000 points from 1e-5 / Ts to the Nyquist frequency (everything python-control's allmargin finds).
Margins analytic_margins(const machine::AxisConfig& config, const std::vector<double>& freq_hz = {},
                         const LoopOptions& options = {});

}  // namespace servobench::tuning
