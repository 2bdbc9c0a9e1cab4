// The power train of a torque-mode axis held in a local object of compile-time size, for the fused tick
// (machine/axis_fused.cpp, decision P16).
//
// PowerTrain::Local<N, NB, W> copies the state (N = 2..5 states, NB = 1 or 2 bodies) and the scalars of one tick out of
// a PowerTrain, advances them with exactly the arithmetic of PowerTrain::set_input / advance_tick (torque drive:
// A/V and the current limit; the drive alarm; cogging, constant load and unbalance at the sub-step start; dry
// friction solved implicitly on the fixed-size discretisations), and writes them back with store(). Inside the
// loop nothing is reached through `this` of the PowerTrain, so the compiler keeps the state in registers instead of
// reloading it after every store to a recording buffer, and every size and body count is a constant.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

#include "servobench/common/elementary.hpp"
#include "servobench/machine/powertrain.hpp"

namespace servobench::machine {

namespace local_detail {
// Each body's friction flag and levels, formed once for the two-body solve (PowerTrain::Local<N, 2>).
struct Levels {
  bool active = false, slip_fixed = false;
  double fs_pos = 0.0, fs_neg = 0.0, slip_pos = 0.0, slip_neg = 0.0;
};
// The rows of a two-body state and of the discretisations' columns, element by element: N doubles one row at a time
// (W = 1, the SSE4.1 and portable kernels), rows 0-3 as a 4-lane vector and the rest as doubles (W = 4, the AVX2
// kernel, decision FV24), or one GCC vector of 8 lanes (W = 8, the AVX-512 kernel, decision FV21), where one
// instruction does a whole column of up to 8 states. Lane i of a sum or a product is row i's scalar operation on the
// same doubles (IEEE, element by element; no contraction: axis_fused.cpp is compiled with -ffp-contract=off), so
// both give the same doubles.
template <int N>
struct ScalarRows {
  double v[N] = {};
  __attribute__((always_inline)) double& operator[](int i) { return v[i]; }
  __attribute__((always_inline)) double operator[](int i) const { return v[i]; }
  __attribute__((always_inline)) ScalarRows operator+(const ScalarRows& b) const {
    ScalarRows r;
    for (int i = 0; i < N; ++i) r.v[i] = v[i] + b.v[i];
    return r;
  }
  __attribute__((always_inline)) ScalarRows operator*(double u) const {
    ScalarRows r;
    for (int i = 0; i < N; ++i) r.v[i] = v[i] * u;
    return r;
  }
};
// W = 4 (the AVX2 kernel): rows 0-3 as one 4-lane vector, rows 4.. one double each.
template <int N>
struct QuadRows {
  typedef double Quad __attribute__((vector_size(32)));
  static constexpr int kRest = N > 4 ? N - 4 : 1;
  Quad lo = Quad{};
  double hi[kRest] = {};
  __attribute__((always_inline)) double operator[](int i) const { return i < 4 ? lo[i] : hi[i - 4]; }
  __attribute__((always_inline)) void set(int i, double x) {
    if (i < 4)
      lo[i] = x;
    else
      hi[i - 4] = x;
  }
  __attribute__((always_inline)) QuadRows operator+(const QuadRows& b) const {
    QuadRows r;
    r.lo = lo + b.lo;
    for (int i = 0; i < N - 4; ++i) r.hi[i] = hi[i] + b.hi[i];
    return r;
  }
  __attribute__((always_inline)) QuadRows operator*(double u) const {
    QuadRows r;
    r.lo = lo * u;
    for (int i = 0; i < N - 4; ++i) r.hi[i] = hi[i] * u;
    return r;
  }
};
// Row i of r set to x, whatever holds the rows.
template <class R>
__attribute__((always_inline)) inline void set_row(R& r, int i, double x) {
  r[i] = x;
}
template <int N>
__attribute__((always_inline)) inline void set_row(QuadRows<N>& r, int i, double x) {
  r.set(i, x);
}

template <int N, int W>
struct RowsOf {
  using type = ScalarRows<N>;
};
template <int N>
struct RowsOf<N, 4> {
  using type = QuadRows<N>;
};
template <int N>
struct RowsOf<N, 8> {
  static_assert(N <= 8, "one AVX-512 register holds 8 doubles");
  typedef double type __attribute__((vector_size(64)));
};

// A one-body Local holds no more than its scalars: the rigid plain kernel is sensitive to its object's layout
// (decision FV12). Two bodies: both bodies' levels, and every discretisation's columns as rows, zero-padded.
template <int N, int NB, int W>
struct BodyTables {};
template <int N, int W>
struct BodyTables<N, 2, W> {
  Levels levels_[2];
  typename RowsOf<N, W>::type phi_[4][N], gam_[4][3];  // [locked mask][column]
};
}  // namespace local_detail

template <int N, int NB, int W>
class PowerTrain::Local : local_detail::BodyTables<N, NB, W> {
  using Levels = local_detail::Levels;
 public:
  using Vec = Eigen::Matrix<double, N, 1>;
  using Rows = typename local_detail::RowsOf<N, W>::type;
  // The state: an Eigen vector for one body (FV12), rows for two (FV21, FV24).
  using State = std::conditional_t<NB == 2, Rows, Vec>;

  explicit Local(const PowerTrain& p)
      : f_(*std::get_if<Fixed<N>>(&p.fixed_)),
        dist_(p.mech_.disturbances),
        amps_per_volt_(p.amps_per_volt_),
        i_max_(p.i_max_),
        kt_(p.kt_),
        h_(p.h_),
        alarm_at_s_(p.alarm_at_s_),
        n_sub_(p.n_sub_),
        drive_states_(p.drive_states_),
        motor_angle_(p.motor_angle_),
        motor_speed_(p.motor_speed_),
        load_angle_(p.load_angle_),
        load_speed_(p.load_speed_),
        substep_count_(p.substep_count_),
        volts_(p.volts_),
        i_cmd_(p.i_cmd_),
        alarm_(p.alarm_),
        alarm_before_(p.alarm_),
        alarm_sub_(first_alarm_substep(p.substep_count_, p.h_, p.alarm_at_s_)),
        cogging_(dist_.cogging_nm != 0.0),
        unbalance_(dist_.unbalance_nm != 0.0) {
    for (int i = 0; i < N; ++i) local_detail::set_row(x_, i, p.x_[i]);
    for (int b = 0; b < NB; ++b) {
      idx_[b] = p.body_index_[b];
      dry_[b] = p.dry_[b];
      stuck_[b] = p.stuck_[b];
    }
    // One body's friction levels, fixed for the run: the breakaway levels always; the sliding levels when they do
    // not depend on the speed (no Stribeck peak, no viscous asymmetry) -- then directional_sliding_nm(fr, w, dir)
    // is Fc + dir * a for every finite w (a + 0 * |w| = a), the same doubles as calling it every sub-step.
    const plant::DryFriction<double>& fr = dry_[0];
    fs_pos_ = plant::directional_breakaway_nm(fr, 1.0);
    fs_neg_ = plant::directional_breakaway_nm(fr, -1.0);
    slip_fixed_ = fr.breakaway_nm == fr.coulomb_nm && fr.viscous_asym_nms == 0.0;
    if (slip_fixed_) {
      slip_pos_ = plant::directional_sliding_nm(fr, 1.0, 1.0);
      slip_neg_ = plant::directional_sliding_nm(fr, -1.0, -1.0);
    }
    // Two bodies: both bodies' levels, the same way, and the discretisations' columns as rows.
    if constexpr (NB == 2) {
      for (int m = 0; m < 4; ++m) {
        for (int k = 0; k < N; ++k) column(f_.phi[m], k, this->phi_[m][k]);
        for (int c = 0; c < 3; ++c) column(f_.gamma[m], c, this->gam_[m][c]);
      }
      for (int b = 0; b < NB; ++b) {
        const plant::DryFriction<double>& fb = dry_[b];
        Levels& l = this->levels_[b];
        l.active = fb.active();
        l.fs_pos = plant::directional_breakaway_nm(fb, 1.0);
        l.fs_neg = plant::directional_breakaway_nm(fb, -1.0);
        l.slip_fixed = fb.breakaway_nm == fb.coulomb_nm && fb.viscous_asym_nms == 0.0;
        if (l.slip_fixed) {
          l.slip_pos = plant::directional_sliding_nm(fb, 1.0, 1.0);
          l.slip_neg = plant::directional_sliding_nm(fb, -1.0, -1.0);
        }
      }
    }
  }

  // Whether this Local applies to `p`: N states and NB bodies, and with one body (a rigid plant) its angle and speed
  // the last two states and its torque input column 1 -- the layout the one-body sub-step uses at compile time.
  static bool applies(const PowerTrain& p) {
    if (p.fused_states() != N || p.nb_ != static_cast<std::size_t>(NB)) return false;
    if constexpr (NB == 1)
      return p.body_index_[0].angle == kAngle && p.body_index_[0].speed == kSpeed && p.body_index_[0].input == 1 &&
             p.motor_angle_ == kAngle && p.load_angle_ == kAngle && p.motor_speed_ == kSpeed &&
             p.load_speed_ == kSpeed && p.drive_states_ == N - 2;
    // Two bodies: the two-mass layout (drive states, then motor angle and speed, load angle and speed; torque input
    // columns 1 and 2), so the two-body solve indexes the state with constants (decision TK2).
    const auto same = [](const plant::BodyIndex& a, const plant::BodyIndex& b) {
      return a.angle == b.angle && a.speed == b.speed && a.input == b.input;
    };
    return same(p.body_index_[0], kTwoMass[0]) && same(p.body_index_[1], kTwoMass[1]) && p.motor_angle_ == N - 4 &&
           p.motor_speed_ == N - 3 && p.load_angle_ == N - 2 && p.load_speed_ == N - 1 && p.drive_states_ == N - 4;
  }

  // Writes the state back (the tables are the PowerTrain's own and unchanged).
  void store(PowerTrain& p) const {
    for (int i = 0; i < N; ++i) p.x_[i] = x_[i];
    for (int b = 0; b < NB; ++b) p.stuck_[b] = stuck_[b];
    p.substep_count_ = substep_count_;
    p.sub_in_tick_ = n_sub_ - 1;
    p.volts_ = volts_;
    p.i_cmd_ = i_cmd_;
    p.alarm_ = alarm_;
    if (alarm_ && !alarm_before_) p.speed_loop_.reset();  // as substep() does when the alarm trips
  }

  // PowerTrain::set_input for a torque drive.
  __attribute__((always_inline)) void set_input(double volts) {
    volts_ = volts;
    const double i = amps_per_volt_ * volts;
    i_cmd_ = alarm_ ? 0.0 : (i > i_max_ ? i_max_ : (i < -i_max_ ? -i_max_ : i));
  }

  // set_input where |amps_per_volt * volts| cannot exceed the current limit (current_within_limit of a bound on
  // |volts| holds): the same i_cmd without the clamp (decision FV26).
  __attribute__((always_inline)) void set_input_within_limit(double volts) {
    volts_ = volts;
    i_cmd_ = alarm_ ? 0.0 : amps_per_volt_ * volts;
  }
  // Whether set_input's clamp is the identity for every |volts| <= max_volts (rounding is monotonic).
  bool current_within_limit(double max_volts) const { return std::fabs(amps_per_volt_ * max_volts) <= i_max_; }

  // PowerTrain::advance_tick for a torque drive: every sub-step with the held input (one sub-step per tick, the
  // torque drive's default, without a loop around it).
  __attribute__((always_inline)) void advance_tick() {
    if (n_sub_ == 1) {
      substep();
    } else {
      for (int s = 0; s < n_sub_; ++s) substep();
    }
  }

  // Whether advance_plain() applies to `p`: one sub-step per tick and no cogging or unbalance torque.
  static bool plain(const PowerTrain& p) {
    return p.n_sub_ == 1 && p.mech_.disturbances.cogging_nm == 0.0 && p.mech_.disturbances.unbalance_nm == 0.0;
  }

  // advance_tick() where plain() holds: the one sub-step with t_motor = 0 known at compile time.
  __attribute__((always_inline)) void advance_plain() {
    if (!alarm_ && substep_count_ >= alarm_sub_) alarm_ = true;
    if (alarm_) i_cmd_ = 0.0;
    ++substep_count_;
    one_body_substep(0.0, -dist_.load_nm);
  }

  __attribute__((always_inline)) void substep() {
    if (!alarm_ && substep_count_ >= alarm_sub_) alarm_ = true;  // = count * h >= alarm_at_s
    if (alarm_) i_cmd_ = 0.0;
    ++substep_count_;
    double t_motor = 0.0;
    if (cogging_) t_motor = dist_.cogging_nm * sin_inline(dist_.cogging_periods * motor_angle_rad());
    double t_load = -dist_.load_nm;
    if (unbalance_) t_load -= dist_.unbalance_nm * sin_inline(load_angle_rad());
    if constexpr (NB == 1) {
      one_body_substep(t_motor, t_load);
    } else {
      two_body_substep(t_motor, t_load);
    }
  }

  // The first sub-step count c >= from at which PowerTrain::substep's test `double(c) * h >= at_s` holds (the
  // drive alarm's time), or LLONG_MAX if none can be reached: the test is monotonic in c (h > 0, rounding to nearest
  // is monotonic), so the loop compares two integers instead of converting and multiplying every sub-step.
  static long long first_alarm_substep(long long from, double h, double at_s) {
    constexpr long long kNever = std::numeric_limits<long long>::max();
    const auto holds = [&](long long c) { return static_cast<double>(c) * h >= at_s; };
    if (holds(from)) return from;
    if (!(at_s / h < 0x1p62)) return kNever;  // +inf, NaN (never holds) or beyond any reachable count
    long long c = static_cast<long long>(std::ceil(at_s / h));
    if (c <= from) c = from + 1;
    while (c > from + 1 && holds(c - 1)) --c;
    while (!holds(c)) ++c;
    return c;
  }

  // plant::advance_with_dry_friction for one body (a rigid plant), written out on scalars: the same operations in
  // the same order (zoh_product's rows summed left to right from 0.0, add_input's zero skips, solve_dry_friction's
  // single sweep, the locked re-solve), so the same doubles, with the state in registers.
  __attribute__((always_inline)) void one_body_substep(double t_motor, double t_load) {
    const Eigen::Matrix<double, N, N>& phi0 = f_.phi[0];
    const Eigen::Matrix<double, N, 3>& gam0 = f_.gamma[0];
    double xf[N];
    free_motion(phi0, gam0, t_motor, t_load, xf);
    const plant::DryFriction<double>& fr = dry_[0];
    if (!fr.active()) {
      for (int i = 0; i < N; ++i) x_[i] = xf[i];
      return;
    }
    constexpr int sa = kAngle, sv = kSpeed, in = 1;  // the layout fused_states() checked
    const double v0 = x_[sv];
    // solve_dry_friction, one body, nothing locked.
    const double v_free = xf[sv], d = xf[sa] - x_[sa], g = gam0(sv, in), gth = gam0(sa, in);
    const double level = slip_fixed_ ? (v0 > 0.0 ? slip_pos_ : slip_neg_)
                                     : plant::directional_sliding_nm(fr, v0, v0 > 0.0 ? 1.0 : -1.0);
    bool st;
    double fb = plant::friction_decision(v0, v_free, d, g, gth, level, fs_pos_, fs_neg_, st);
    if (st && stuck_[0] && v0 == 0.0) {  // held by static friction: the locked discretisation, no friction work
      free_motion(f_.phi[1], f_.gamma[1], t_motor, t_load, xf);
      stuck_[0] = 1;
      for (int i = 0; i < N; ++i) x_[i] = xf[i];
      return;
    }
    if (fb != 0.0)
      for (int i = 0; i < N; ++i) xf[i] += gam0(i, in) * fb;
    if (st) xf[sv] = 0.0;
    stuck_[0] = st ? 1 : 0;
    for (int i = 0; i < N; ++i) x_[i] = xf[i];
  }

  // plant::advance_with_dry_friction for the two-mass layout (applies() checked it), written out: the same operations
  // in the same order (solve_dry_friction's Gauss-Seidel sweeps and their early end, the locked re-solve), so the
  // same doubles, with the bodies' indices known at compile time, their levels and flags formed once and the state's
  // rows held as the kernel holds them (Rows).
  __attribute__((always_inline)) void two_body_substep(double t_motor, double t_load) {
    Rows xf;
    free_rows(0u, t_motor, t_load, xf);
    if (!(this->levels_[0].active || this->levels_[NB - 1].active)) {
      x_ = xf;
      return;
    }
    double f[2] = {0.0, 0.0};
    bool stick[2] = {false, false};
    solve_two(xf, f_.gamma[0], 0u, f, stick);
    // Bodies at rest that static friction keeps at rest are integrated locked.
    unsigned locked = 0;
    for (int b = 0; b < 2; ++b)
      if (stick[b] && stuck_[b] && x_[kTwoMass[b].speed] == 0.0) locked |= 1u << b;
    if (locked != 0) {
      free_rows(locked, t_motor, t_load, xf);
      solve_two(xf, f_.gamma[locked], locked, f, stick);
    }
    for (int b = 0; b < 2; ++b) {
      if (locked & (1u << b)) {
        stuck_[b] = 1;
        continue;
      }
      if (f[b] != 0.0) xf = xf + this->gam_[locked][kTwoMass[b].input] * f[b];
    }
    for (int b = 0; b < 2; ++b) {
      if (locked & (1u << b)) continue;
      if (stick[b]) local_detail::set_row(xf, kTwoMass[b].speed, 0.0);  // stopped inside the sub-step (rounding)
      stuck_[b] = stick[b] ? 1 : 0;
    }
    x_ = xf;
  }

  // plant::solve_dry_friction for the two-mass layout: from x_ with the friction-free end state xf.
  __attribute__((always_inline)) void solve_two(const Rows& xf, const Eigen::Matrix<double, N, 3>& gamma,
                                                unsigned locked, double* f, bool* stick) const {
    double slip_level[2] = {0.0, 0.0};
    for (int b = 0; b < 2; ++b) {
      if (locked & (1u << b)) {
        f[b] = 0.0;
        stick[b] = true;
      } else if (this->levels_[b].active) {
        const double v0 = x_[kTwoMass[b].speed];
        const double dir = v0 > 0.0 ? 1.0 : -1.0;
        const Levels& l = this->levels_[b];
        slip_level[b] =
            l.slip_fixed ? (v0 > 0.0 ? l.slip_pos : l.slip_neg) : plant::directional_sliding_nm(dry_[b], v0, dir);
      }
    }
    std::uint64_t last_bits[2] = {0, 0};
    bool seen[2] = {false, false};
    for (int sweep = 0; sweep < 3; ++sweep) {
      for (int b = 0; b < 2; ++b) {
        if (locked & (1u << b)) continue;
        const int sa = kTwoMass[b].angle, sv = kTwoMass[b].speed, o = 1 - b;
        stick[b] = false;
        if (!this->levels_[b].active) {
          f[b] = 0.0;
          continue;
        }
        double v_free = xf[sv];
        double d = xf[sa] - x_[sa];
        v_free += gamma(sv, kTwoMass[o].input) * f[o];
        d += gamma(sa, kTwoMass[o].input) * f[o];
        const double g = gamma(sv, kTwoMass[b].input);
        const double gth = gamma(sa, kTwoMass[b].input);
        bool st;
        const double fb = plant::friction_decision(x_[sv], v_free, d, g, gth, slip_level[b], this->levels_[b].fs_pos,
                                                   this->levels_[b].fs_neg, st);
        f[b] = fb;
        stick[b] = st;
        std::uint64_t bits;  // converged: see solve_dry_friction (decision SQ2)
        std::memcpy(&bits, &fb, sizeof bits);
        if (seen[b] && bits == last_bits[b]) return;
        last_bits[b] = bits;
        seen[b] = true;
      }
    }
  }

  // zoh_product and add_input: xf = phi x + gamma [i_cmd, t_motor, t_load], each input skipped when exactly 0.
  __attribute__((always_inline)) void free_motion(const Eigen::Matrix<double, N, N>& phi,
                                                  const Eigen::Matrix<double, N, 3>& gam, double t_motor, double t_load,
                                                  double* xf) const {
    for (int i = 0; i < N; ++i) {
      double s = 0.0;
      for (int k = 0; k < N; ++k) s += phi(i, k) * x_[k];
      xf[i] = s;
    }
    if (i_cmd_ != 0.0)
      for (int i = 0; i < N; ++i) xf[i] += gam(i, 0) * i_cmd_;
    if (t_motor != 0.0)
      for (int i = 0; i < N; ++i) xf[i] += gam(i, 1) * t_motor;
    if (t_load != 0.0)
      for (int i = 0; i < N; ++i) xf[i] += gam(i, 2) * t_load;
  }

  // free_motion on rows, for two bodies: xf = phi x + gamma [i_cmd, t_motor, t_load] with the discretisation of the
  // locked mask m; lane i is row i summed left to right from 0.0, then each input's column added unless the input is
  // exactly 0 -- free_motion's operations on the same doubles.
  __attribute__((always_inline)) void free_rows(unsigned m, double t_motor, double t_load, Rows& xf) const {
    Rows s = Rows{};
    for (int k = 0; k < N; ++k) s = s + this->phi_[m][k] * x_[k];
    if (i_cmd_ != 0.0) s = s + this->gam_[m][0] * i_cmd_;
    if (t_motor != 0.0) s = s + this->gam_[m][1] * t_motor;
    if (t_load != 0.0) s = s + this->gam_[m][2] * t_load;
    xf = s;
  }

  // Column c of a matrix as rows, the rows past its N zero.
  template <class M>
  static void column(const M& a, int c, Rows& v) {
    v = Rows{};
    for (int i = 0; i < N; ++i) local_detail::set_row(v, i, a(i, c));
  }

  // One body: the angle and speed are the last two states (after the drive's), known at compile time.
  // Two bodies: the two-mass layout applies() checked.
  double motor_angle_rad() const { return NB == 1 ? x_[kAngle] : x_[N - 4]; }
  double motor_speed_rad_s() const { return NB == 1 ? x_[kSpeed] : x_[N - 3]; }
  double load_angle_rad() const { return NB == 1 ? x_[kAngle] : x_[N - 2]; }
  double load_speed_rad_s() const { return NB == 1 ? x_[kSpeed] : x_[N - 1]; }
  double current_a() const { return (NB == 1 ? N == 3 : N == 5) ? x_[0] : i_cmd_; }
  double torque_nm() const { return kt_ * current_a(); }
  bool alarm() const { return alarm_; }

 private:
  static constexpr int kAngle = N - 2, kSpeed = N - 1;
  static constexpr plant::BodyIndex kTwoMass[2] = {{N - 4, N - 3, 1}, {N - 2, N - 1, 2}};
  const Fixed<N>& f_;
  const plant::Disturbances dist_;
  const double amps_per_volt_, i_max_, kt_, h_, alarm_at_s_;
  const int n_sub_, drive_states_, motor_angle_, motor_speed_, load_angle_, load_speed_;
  plant::BodyIndex idx_[2];
  plant::DryFriction<double> dry_[2];
  char stuck_[2] = {1, 1};
  State x_{};
  long long substep_count_;
  double volts_, i_cmd_;
  bool alarm_, alarm_before_;
  long long alarm_sub_;
  const bool cogging_, unbalance_;  // the disturbances' torques are not 0 (tested once, not every sub-step)
  double fs_pos_ = 0.0, fs_neg_ = 0.0, slip_pos_ = 0.0, slip_neg_ = 0.0;  // body 0's levels (constructor)
  bool slip_fixed_ = false;
};

}  // namespace servobench::machine
