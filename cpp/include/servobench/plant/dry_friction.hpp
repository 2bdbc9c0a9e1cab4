// Dry friction over one integration sub-step, on any scalar type: the simulator runs it on double, the
// identification (identify/) on Ceres Jets for automatic differentiation -- one piece of code for both.
//
// The linear part of the bodies' motion (inertias, shaft, viscous friction) is integrated exactly over the sub-step
// by a zero-order-hold discretisation (phi, gamma); the dry friction of each body is a torque held over the
// sub-step, chosen implicitly (time-stepping):
//  - a sliding body keeps its sliding friction -sign(w) (Fc + (Fs - Fc) exp(-(|w|/ws)^delta)) if it still moves
//    the same way at the sub-step's end;
//  - otherwise the friction is the torque that stops it at the end, if static friction can (|f| <= Fs): it sticks;
//  - otherwise it breaks away (or passes through zero) against the breakaway level Fs;
//  - sliding friction never does positive work: f * (displacement over the sub-step) <= 0;
//  - a body at rest that static friction keeps at rest is integrated with an exactly locked discretisation.
// Branches compare values only (for Jets, the scalar part), so the result is piecewise smooth in the parameters.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include <Eigen/Core>

#include "servobench/common/elementary.hpp"

// The fused tick's kernels (machine/axis_fused.cpp) are compiled with a target attribute (SSE4.1), and GCC does not
// inline a plain inline function into them across the different target options, even under `flatten`: measured, the
// two-body solve and the sliding level stayed calls, ~600 of the full chain's instructions per tick. These helpers
// are the tick's hot path, so they are always inlined (decision TK2).
#define SERVOBENCH_TICK_INLINE __attribute__((always_inline)) inline

namespace servobench::plant {

// Where a body lives in the state vector, and its column in the discretisation's input matrix.
struct BodyIndex {
  int angle = 0;
  int speed = 1;
  int input = 1;
};

// A body's dry friction in scalar type T: Coulomb (sliding) level, breakaway level (>= Coulomb; equal: no
// Stribeck peak), Stribeck speed (> 0) and exponent; and its asymmetry (issue 19): the levels are Fc + a, Fs + a
// for positive speeds and Fc - a, Fs - a for negative ones (a = coulomb_asym_nm, |a| <= Fc), and the viscous
// friction, integrated linearly at its mean b, is b + bv for positive speeds and b - bv for negative ones
// (bv = viscous_asym_nms): the difference enters here as the extra sliding level bv |w|. Both 0: symmetric.
template <class T>
struct DryFriction {
  T coulomb_nm;
  T breakaway_nm;
  T stribeck_speed_rad_s;
  double stribeck_exponent = 2.0;
  double coulomb_asym_nm = 0.0;
  double viscous_asym_nms = 0.0;
  bool asymmetric() const { return coulomb_asym_nm != 0.0 || viscous_asym_nms != 0.0; }
  bool active() const { return breakaway_nm > 0.0 || viscous_asym_nms != 0.0; }
};

// The sliding level in the direction dir (+1 / -1) at speed w (N*m): the symmetric level plus, for an asymmetric
// body, dir * (a + bv |w|) -- friction -dir * level then gives Fc+/- and the viscous difference.
template <class T>
SERVOBENCH_TICK_INLINE T directional_sliding_nm(const DryFriction<T>& f, const T& speed_rad_s, double dir);

// The breakaway level resisting motion in the direction dir (+1 / -1), N*m: Fs + dir * a.
template <class T>
SERVOBENCH_TICK_INLINE T directional_breakaway_nm(const DryFriction<T>& f, double dir) {
  if (f.coulomb_asym_nm == 0.0) return f.breakaway_nm;
  return f.breakaway_nm + dir * f.coulomb_asym_nm;
}

// Sliding friction level at speed w (N*m, >= 0): Fc + (Fs - Fc) exp(-(|w|/ws)^delta).
template <class T>
SERVOBENCH_TICK_INLINE T sliding_friction_nm(const DryFriction<T>& f, const T& speed_rad_s) {
  using std::abs;
  using std::exp;
  using std::pow;
  // No Stribeck peak: the formula gives Fc; the simulator (double) skips the exponential, a Jet keeps the
  // derivative with respect to the breakaway level.
  if constexpr (std::is_same<T, double>::value)
    if (f.breakaway_nm == f.coulomb_nm) return f.coulomb_nm;
  const T r = abs(speed_rad_s) / f.stribeck_speed_rad_s;
  const T shape = f.stribeck_exponent == 2.0 ? T(r * r) : T(pow(r, f.stribeck_exponent));
  // Far above the Stribeck speed exp(-shape) underflows (below 1e-307), and libm takes its slow underflow path;
  // the peak's share is then below any double's resolution of Fc.
  if constexpr (std::is_same<T, double>::value)
    if (shape > 708.0) return f.coulomb_nm;
  // The simulator's doubles take exp without a library call (common/elementary.hpp, decision FV22).
  if constexpr (std::is_same<T, double>::value)
    return f.coulomb_nm + (f.breakaway_nm - f.coulomb_nm) * exp_inline(-shape);
  else
    return f.coulomb_nm + (f.breakaway_nm - f.coulomb_nm) * exp(-shape);
}

template <class T>
SERVOBENCH_TICK_INLINE T directional_sliding_nm(const DryFriction<T>& f, const T& speed_rad_s, double dir) {
  using std::abs;
  if (!f.asymmetric()) return sliding_friction_nm(f, speed_rad_s);
  return sliding_friction_nm(f, speed_rad_s) + dir * (f.coulomb_asym_nm + f.viscous_asym_nms * abs(speed_rad_s));
}

// One body's held dry-friction torque for a sub-step (N*m), the other bodies' forces already in v_free and d: from
// the start speed v0 and the friction-free end speed v_free (speed state's units) and displacement d (angle
// state's), with g and gth the end speed and displacement per N*m of its own friction, the sliding level slip_level
// at v0 and the breakaway levels fs_pos (resisting positive motion) and fs_neg (negative), all >= 0. The body keeps
// sliding, sticks (st = true: the torque that stops it, within the breakaway levels) or breaks away; then the work
// cap. The one decision of solve_dry_friction and of the fused tick's written-out sub-steps (powertrain_local.hpp).
template <class T>
SERVOBENCH_TICK_INLINE T friction_decision(const T& v0, const T& v_free, const T& d, const T& g, const T& gth,
                                           const T& slip_level, const T& fs_pos, const T& fs_neg, bool& st) {
  using std::abs;
  T fb;
  st = false;
  const double dir = v0 > 0.0 ? 1.0 : -1.0;
  const T f_slip = -dir * slip_level;
  if (v0 != 0.0 && (v_free + g * f_slip) * dir > 0.0) {
    fb = f_slip;  // keeps sliding the same way
  } else {
    const T f_stick = -v_free / g;  // holds the body at rest at the sub-step's end
    if (f_stick <= fs_neg && f_stick >= -fs_pos) {
      fb = f_stick;
      st = true;
    } else {
      fb = v_free > 0.0 ? T(-fs_pos) : fs_neg;  // breaks away, or passes zero
    }
  }
  // Sliding friction may only oppose the net displacement over the sub-step: f * (d + gth f) <= 0. (A hold from rest
  // is integrated locked, with no work at all.)
  if (!(st && v0 == 0.0) && fb * (d + gth * fb) > 0.0) {
    st = false;
    const T cap = gth > 0.0 ? T(abs(d) / gth) : T(0.0);
    const T afb = abs(fb);
    const T mag = afb < cap ? afb : cap;
    fb = d == 0.0 ? T(0.0) : (d > 0.0 ? T(-mag) : mag);
  }
  return fb;
}

// Chooses the held dry-friction torque f[b] of every body b for the sub-step from x0 whose friction-free end state
// is x_free (gamma: the discretisation's input matrix in use; bodies in the `locked` bit mask are frozen and get
// f = 0, stick = true). Two bodies are coupled through the shaft: three Gauss-Seidel sweeps.
template <class T, class Vec, class Mat>
SERVOBENCH_TICK_INLINE void solve_dry_friction(std::size_t nb, const BodyIndex* idx, const DryFriction<T>* fr,
                                               const Vec& x0, const Vec& x_free, const Mat& gamma, unsigned locked,
                                               T* f, bool* stick) {
  using std::abs;
  const int sweeps = nb > 1 ? 3 : 1;
  // Each body's levels depend only on its speed at the sub-step's start: computed once, not once per sweep (the
  // same values; the Stribeck curve's division and exponential are the costly part of a two-body sub-step). nb <= 2,
  // as the callers' f[2], stick[2].
  constexpr std::size_t kMaxBodies = 2;
  T slip_level[kMaxBodies], fs_pos[kMaxBodies], fs_neg[kMaxBodies];
  for (std::size_t b = 0; b < nb && b < kMaxBodies; ++b) {
    if (locked & (1u << b)) {
      f[b] = T(0.0);
      stick[b] = true;
    } else if (fr[b].active()) {
      const T v0 = x0[idx[b].speed];
      const double dir = v0 > 0.0 ? 1.0 : -1.0;
      slip_level[b] = directional_sliding_nm(fr[b], v0, dir);
      fs_pos[b] = directional_breakaway_nm(fr[b], 1.0);   // resists positive motion
      fs_neg[b] = directional_breakaway_nm(fr[b], -1.0);  // resists negative motion
    }
  }
  std::uint64_t last_bits[kMaxBodies] = {0, 0};
  bool seen[kMaxBodies] = {false, false};
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    for (std::size_t b = 0; b < nb; ++b) {
      if (locked & (1u << b)) continue;
      const BodyIndex& s = idx[b];
      stick[b] = false;
      if (!fr[b].active()) {
        f[b] = T(0.0);
        continue;
      }
      // End speed and displacement of this body without its own friction (the others' included).
      T v_free = x_free[s.speed];
      T d = x_free[s.angle] - x0[s.angle];
      for (std::size_t o = 0; o < nb; ++o) {
        if (o == b) continue;
        v_free += gamma(s.speed, idx[o].input) * f[o];
        d += gamma(s.angle, idx[o].input) * f[o];
      }
      const T g = gamma(s.speed, s.input);    // end speed per N*m of own friction
      const T gth = gamma(s.angle, s.input);  // displacement per N*m of own friction
      bool st;
      const T fb = friction_decision(x0[s.speed], v_free, d, g, gth, slip_level[b], fs_pos[b], fs_neg[b], st);
      f[b] = fb;
      stick[b] = st;
      // Converged (decision SQ2): with two bodies each evaluation depends only on the other body's latest force, so
      // once a body's force comes out bit for bit as its previous evaluation gave, every further evaluation repeats
      // one already made and the sweeps would end where they stand now. Doubles only (a Jet's derivatives may still
      // move).
      if constexpr (std::is_same<T, double>::value) {
        if (nb == 2) {
          std::uint64_t bits;
          std::memcpy(&bits, &fb, sizeof bits);
          if (seen[b] && bits == last_bits[b]) return;
          last_bits[b] = bits;
          seen[b] = true;
        }
      }
    }
  }
}

// One sub-step of the bodies with dry friction. phis[mask] / gammas[mask]: the discretisation with the bodies of
// `mask` locked (mask 0: none locked); u0, u1, u2: the inputs held over the sub-step (drive command, external
// torque on the motor body, on the load body). x is advanced in place (x_free is scratch of the same size);
// stuck[b] is the "at rest, held by static friction" flag of each body, carried from sub-step to sub-step.
// An input that is not there (the default fourth input).
struct NoInput {};

// y = a x, the linear part over a sub-step. On compile-time-sized double matrices (the simulator's 2..5-state power
// trains) an unrolled loop summing each row left to right from 0 -- the order Eigen's run-time-sized GEMV uses, so
// the result is the same double -- with no size checks, no zeroing pass and no call; otherwise Eigen's product.
template <class Vec, class Mat>
SERVOBENCH_TICK_INLINE void zoh_product(Vec& y, const Mat& a, const Vec& x) {
  if constexpr (Vec::RowsAtCompileTime != Eigen::Dynamic && std::is_same<typename Vec::Scalar, double>::value) {
    constexpr int n = Vec::RowsAtCompileTime;
    for (int i = 0; i < n; ++i) {
      double s = 0.0;
      for (int k = 0; k < n; ++k) s += a(i, k) * x[k];
      y[i] = s;
    }
  } else {
    y.noalias() = a * x;
  }
}

// x_free += gamma.col(c) * u for an input held over the sub-step. An input known in double (the identification's
// logged command) costs a scaling of the column rather than a product of Jets; an exactly zero double input costs
// nothing; NoInput is not even looked up.
template <int C, class Vec, class Gamma, class U>
SERVOBENCH_TICK_INLINE void add_input(Vec& x_free, const Gamma& gamma, const U& u) {
  if constexpr (!std::is_same<U, NoInput>::value) {
    if constexpr (std::is_same<U, double>::value)
      if (u == 0.0) return;
    if constexpr (Vec::RowsAtCompileTime != Eigen::Dynamic && std::is_same<typename Vec::Scalar, double>::value) {
      // Written out: with LTO, Eigen's compound assignment stayed an out-of-line call in the fused tick (TK3);
      // the same doubles (one product, one sum per element).
      for (int i = 0; i < Vec::RowsAtCompileTime; ++i) x_free[i] += gamma(i, C) * u;
    } else {
      x_free += gamma.col(C) * u;
    }
  }
}

// u0, u1, u2 (and u3, an optional fourth input column) may each be T or double (see add_input).
template <class T, class Vec, class PhiSet, class GammaSet, class U0, class U1, class U2, class U3 = NoInput>
SERVOBENCH_TICK_INLINE void advance_with_dry_friction(std::size_t nb, const BodyIndex* idx, const DryFriction<T>* fr,
                                                      const PhiSet& phis, const GammaSet& gammas, const U0& u0,
                                                      const U1& u1, const U2& u2, Vec& x, Vec& x_free, char* stuck,
                                                      const U3& u3 = U3()) {
  const auto& gamma0 = gammas[0];
  zoh_product(x_free, phis[0], x);
  add_input<0>(x_free, gamma0, u0);
  add_input<1>(x_free, gamma0, u1);
  add_input<2>(x_free, gamma0, u2);
  add_input<3>(x_free, gamma0, u3);
  bool any_dry = false;
  for (std::size_t b = 0; b < nb; ++b) any_dry = any_dry || fr[b].active();
  if (!any_dry) {
    x.swap(x_free);
    return;
  }
  T f[2] = {T(0.0), T(0.0)};
  bool stick[2] = {false, false};
  solve_dry_friction(nb, idx, fr, x, x_free, gamma0, 0u, f, stick);
  // Bodies at rest that static friction keeps at rest are integrated locked.
  unsigned locked = 0;
  for (std::size_t b = 0; b < nb; ++b)
    if (stick[b] && stuck[b] && x[idx[b].speed] == 0.0) locked |= 1u << b;
  const auto* gamma = &gamma0;
  if (locked != 0) {
    gamma = &gammas[locked];
    zoh_product(x_free, phis[locked], x);
    add_input<0>(x_free, *gamma, u0);
    add_input<1>(x_free, *gamma, u1);
    add_input<2>(x_free, *gamma, u2);
    add_input<3>(x_free, *gamma, u3);
    solve_dry_friction(nb, idx, fr, x, x_free, *gamma, locked, f, stick);
  }
  for (std::size_t b = 0; b < nb; ++b) {
    if (locked & (1u << b)) {
      stuck[b] = 1;
      continue;
    }
    if (f[b] != 0.0) x_free += gamma->col(idx[b].input) * f[b];
  }
  for (std::size_t b = 0; b < nb; ++b) {
    if (locked & (1u << b)) continue;
    if (stick[b]) x_free[idx[b].speed] = T(0.0);  // stopped inside the sub-step (the residual is rounding)
    stuck[b] = stick[b] ? 1 : 0;
  }
  x.swap(x_free);
}

}  // namespace servobench::plant
