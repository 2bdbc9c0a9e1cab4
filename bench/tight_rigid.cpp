// Bench-only peer (issue 22 point 5): the rigid chain's tick as one tight C++ loop of the same arithmetic as
// bench/numba_peer.py (GT law, 16-bit DAC, lagged torque drive, rigid plant with Coulomb friction solved implicitly
// with stiction, quantised encoder). Not part of the product: bench/tight_peer.py compiles it with the system C++
// compiler into build/bench-tight and calls it through ctypes; the bench checks its feedback equals servobench's on
// every tick before timing it. Constants: the vector of numba_peer.chain_constants (layout there).
#include <algorithm>
#include <cmath>

extern "C" void rigid_chain(const double* c, const double* pos, const double* vel, const double* acc, double* out,
                            long n) {
  const double cpr = c[0], kp = c[1], ki = c[2], kd = c[3], kvff = c[4], kaff = c[5], ilmt = c[6], bias = c[7],
               mlim = c[8];
  const double apv = c[9], ilim = c[10], coul = c[11], load = c[12], fs = c[13];
  const double p00 = c[14], p01 = c[15], p02 = c[16], p10 = c[17], p11 = c[18], p12 = c[19], p20 = c[20],
               p21 = c[21], p22 = c[22];
  const double g00 = c[23], g01 = c[24], g10 = c[25], g11 = c[26], g20 = c[27], g21 = c[28];
  const double pl00 = c[29], gl00 = c[30], gl01 = c[31];
  const double g = g21, gth = g11;
  double i = 0, th = 0, w = 0, s = 0, e_prev = 0, pending = 0;
  bool stuck = true;
  for (long k = 0; k < n; ++k) {
    const double icmd = std::max(-ilim, std::min(ilim, apv * pending));
    const double y = std::floor(th * cpr + 0.5);
    const double err = pos[k] - y;
    s = std::max(-ilmt, std::min(ilmt, s + err));
    double u = kp * err + ki * s / 256 + kd * (err - e_prev) + kvff * vel[k] + kaff * acc[k] + bias;
    u = std::max(-mlim, std::min(mlim, u));
    e_prev = err;
    const double v = std::max(-10.0, std::min(10.0, u * (10 / 32767.0)));
    out[k] = y;
    pending = std::nearbyint(v * 3276.7) / 3276.7;
    const double ext = -load;
    const double xi = p00 * i + p01 * th + p02 * w + g00 * icmd + g01 * ext;
    const double xt = p10 * i + p11 * th + p12 * w + g10 * icmd + g11 * ext;
    const double xw = p20 * i + p21 * th + p22 * w + g20 * icmd + g21 * ext;
    if (fs == 0.0) {
      i = xi, th = xt, w = xw;
      continue;
    }
    const double d = xt - th;
    bool st = false;
    const double f_slip = w > 0 ? -coul : coul;
    double f;
    if (w != 0.0 && (xw + g * f_slip) * (w > 0 ? 1.0 : -1.0) > 0.0) {
      f = f_slip;
    } else {
      const double f_stick = -xw / g;
      if (-fs <= f_stick && f_stick <= fs) {
        f = f_stick;
        st = true;
      } else {
        f = xw > 0 ? -fs : fs;
      }
    }
    if (!(st && w == 0.0) && f * (d + gth * f) > 0.0) {
      st = false;
      f = d == 0.0 ? 0.0 : (d > 0 ? -1.0 : 1.0) * std::min(std::fabs(f), std::fabs(d) / gth);
    }
    if (st && stuck && w == 0.0) {
      i = pl00 * i + gl00 * icmd + gl01 * ext;
      continue;
    }
    i = xi + g01 * f, th = xt + g11 * f, w = xw + g21 * f;
    if (st) w = 0.0;
    stuck = st;
  }
}
