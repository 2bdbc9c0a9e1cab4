// Decision P16: the fused tick (machine/axis_fused.cpp) gives the same doubles as the general loop, signal by signal,
// for every configuration it takes (GT/APS law; rigid or two-mass; ideal or lagged current loop; Coulomb, Stribeck,
// asymmetric friction; cogging, load, unbalance; encoder noise and load mounting; sub-steps; both biquads; injection;
// profile velocities; the error-limit and alarm guards; runs continued in pieces).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "servobench/machine/axis.hpp"
#include "servobench/plant/dry_friction.hpp"

namespace mc = servobench::machine;
namespace ctl = servobench::control;
namespace pl = servobench::plant;
namespace dr = servobench::drive;

namespace {
constexpr int kSignals = 27;

struct Recording {
  std::vector<std::vector<double>> sig;
  mc::RunOutcome outcome;
};

mc::Trace all_signals(std::vector<std::vector<double>>& buf, std::size_t n) {
  buf.assign(kSignals, std::vector<double>(n, -12345.0));
  mc::Trace t;
  int i = 0;
#define SB_SLOT(name, unit, doc) t.name = buf[i++].data();
  SERVOBENCH_TRACE_SIGNALS(SB_SLOT)
#undef SB_SLOT
  return t;
}

struct Case {
  std::string name;
  mc::AxisConfig cfg;
  mc::RunGuard guard;
  bool profile = false, inject = false;
};

// What a run records: every signal, fb_pos only (the benchmarks' runs), or nothing (decision SR1).
enum class Rec { kAll, kFeedback, kNothing };

// Runs the same command in three pieces (continuation) and the state read after it; `kernel` the fused tick's kernel
// (decision SP1), `rec` what it records (the slots not recorded keep their fill value in both loops).
std::vector<double> run_case(const Case& c, bool fused, mc::TickKernel kernel = mc::TickKernel::kAuto,
                             Rec rec = Rec::kAll) {
  mc::Axis axis(c.cfg);
  axis.set_fused_tick(fused);
  axis.set_tick_kernel(kernel);
  axis.reset(0.1);
  const std::size_t n = 3000;
  std::vector<double> pos(n), vel(n), acc(n), inj(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k);
    pos[k] = (k < 1500 ? 0.02 * t * t / 2 : 22500.0 - 0.5 * (t - 1500)) + 3.0 * std::sin(t / 40.0);
    vel[k] = 0.02 * t;
    acc[k] = 0.02;
    inj[k] = 0.3 * std::sin(t / 7.0);
  }
  std::vector<double> out;
  std::size_t start = 0;
  for (std::size_t piece : {std::size_t{1}, std::size_t{1200}, n - 1201}) {
    mc::CommandInput in;
    in.pos = pos.data() + start;
    if (c.profile) {
      in.vel = vel.data() + start;
      in.acc = acc.data() + start;
    }
    if (c.inject) in.volts_add = inj.data() + start;
    in.n = piece;
    std::vector<std::vector<double>> buf;
    const mc::Trace all = all_signals(buf, piece);
    mc::Trace tr = all;
    if (rec != Rec::kAll) {
      tr = mc::Trace{};
      if (rec == Rec::kFeedback) tr.fb_pos = all.fb_pos;
    }
    const mc::RunOutcome o = axis.run(in, tr, c.guard);
    for (const auto& s : buf) out.insert(out.end(), s.begin(), s.end());
    out.push_back(static_cast<double>(o.ticks));
    out.push_back(static_cast<double>(o.stop));
    out.push_back(o.error_pulse);
    start += piece;
    if (o.ticks < piece) break;
  }
  for (double v : {axis.feedback_pulse(), axis.angle_rad(), axis.speed_rad_s(), axis.load_angle_rad(),
                   axis.load_speed_rad_s(), axis.law_error_sum(), static_cast<double>(axis.tick()),
                   axis.servo_on() ? 1.0 : 0.0, axis.alarm() ? 1.0 : 0.0, axis.last_command_pulse()})
    out.push_back(v);
  return out;
}

// Two integer-form filters (ADLINK): an FIR (2 + z^-1 + z^-2) / 4 and a pole 1 / (2 - z^-1).
std::array<ctl::BiquadParams, 2> integer_filters() {
  ctl::AdlinkBiquadParams fir, pole;
  fir.b0 = 2;
  fir.b1 = 1;
  fir.b2 = 1;
  fir.div = 4;
  pole.b0 = 1;
  pole.a1 = 1;
  pole.div = 2;
  return {fir, pole};
}

std::vector<Case> cases() {
  std::vector<Case> cs;
  ctl::GtServoLawParams gt;
  gt.kp = 30;
  gt.ki = 40;
  gt.kd = 600;
  gt.kvff = 50;
  gt.kaff = 9000;
  gt.bias = 3;
  ctl::ApsServoLawParams aps;
  aps.kp = 2000;
  aps.ki = 300;
  aps.kd = 20000;
  aps.kvff = 20;
  dr::TorqueDriveParams lag, ideal;
  ideal.current_bw_hz = dr::kInf;
  pl::RigidPlantParams rigid;
  rigid.coulomb_nm = 0.01;
  rigid.static_nm = 0.015;
  rigid.stribeck_speed_rad_s = 0.5;
  rigid.cogging_nm = 0.002;
  rigid.cogging_periods = 6;
  rigid.load_nm = 0.003;
  rigid.unbalance_nm = 0.002;
  rigid.coulomb_asym_nm = 0.002;
  pl::TwoMassPlantParams two;
  two.motor_coulomb_nm = 0.01;
  two.motor_static_nm = 0.015;
  two.load_coulomb_nm = 0.02;
  two.load_static_nm = 0.03;
  two.cogging_nm = 0.002;
  two.cogging_periods = 6;
  two.unbalance_nm = 0.001;
  int i = 0;
  for (const mc::LawParams& law : {mc::LawParams{gt}, mc::LawParams{aps}}) {
    for (const mc::PlantParams& plant : {mc::PlantParams{pl::RigidPlantParams{}}, mc::PlantParams{rigid},
                                        mc::PlantParams{two}}) {
      for (const dr::TorqueDriveParams& d : {lag, ideal}) {
        Case c;
        c.name = "case " + std::to_string(i);
        c.cfg.law = law;
        c.cfg.plant = plant;
        c.cfg.drive = d;
        c.cfg.servo_period_s = 250e-6;
        c.profile = i % 2 == 0;
        c.inject = i % 3 == 0;
        c.cfg.substeps = 1 + i % 3;
        if (i % 4 == 1) c.cfg.filters = integer_filters();
        if (i % 5 == 2) c.cfg.encoder.noise_counts = 0.7;
        if (i % 3 == 2 && std::holds_alternative<pl::TwoMassPlantParams>(plant)) c.cfg.encoder.on_load = true;
        c.guard.error_limit_pulse = i % 2 ? 20000.0 : 0.0;
        cs.push_back(c);
        ++i;
      }
    }
  }
  // The plain kernel (decision TK1): rigid, pass-through filters, a profile with its velocity and acceleration, no
  // injection, one sub-step, no cogging or unbalance, no encoder noise -- with friction that keeps its sliding levels
  // fixed (Coulomb, asymmetric Coulomb) and friction that does not (a Stribeck peak, viscous asymmetry), a load.
  pl::RigidPlantParams coulomb, stribeck;
  coulomb.coulomb_nm = 0.01;
  coulomb.coulomb_asym_nm = 0.002;
  coulomb.load_nm = 0.003;
  stribeck.coulomb_nm = 0.01;
  stribeck.static_nm = 0.015;
  stribeck.stribeck_speed_rad_s = 0.5;
  stribeck.viscous_asym_nms = 2e-5;
  for (const mc::LawParams& law : {mc::LawParams{gt}, mc::LawParams{aps}}) {
    for (const pl::RigidPlantParams& plant : {pl::RigidPlantParams{}, coulomb, stribeck}) {
      for (const dr::TorqueDriveParams& d : {lag, ideal}) {
        Case c;
        c.name = "plain case " + std::to_string(i++);
        c.cfg.law = law;
        c.cfg.plant = plant;
        c.cfg.drive = d;
        c.cfg.servo_period_s = 250e-6;
        c.profile = true;
        c.guard.error_limit_pulse = i % 2 ? 20000.0 : 0.0;
        cs.push_back(c);
      }
    }
  }
  const std::size_t last_plain = cs.size() - 1;
  // Plain runs whose saturations bite (decision FV26 leaves a clamp out only where it cannot): a DAC whose full scale
  // is below the law's largest output, and a drive whose current limit is below the DAC's largest output x A/V.
  for (const mc::LawParams& law : {mc::LawParams{gt}, mc::LawParams{aps}}) {
    Case c;
    c.cfg.law = law;
    c.cfg.plant = coulomb;
    c.cfg.servo_period_s = 250e-6;
    c.profile = true;
    c.cfg.drive = ideal;  // its current is its command
    c.name = "plain, DAC full scale bites " + std::to_string(i++);
    c.cfg.dac.full_scale_v = 0.05;
    cs.push_back(c);
    c.name = "plain, current limit bites " + std::to_string(i++);
    c.cfg.dac = dr::DacParams{};
    dr::TorqueDriveParams weak = ideal;
    weak.current_limit_a = 0.2;
    c.cfg.drive = weak;
    cs.push_back(c);
  }
  {  // the general fused kernel (filters, injection) leaves the drive's clamp out the same way
    Case c;
    c.cfg.law = gt;
    c.cfg.plant = coulomb;
    c.cfg.servo_period_s = 250e-6;
    c.cfg.filters = integer_filters();
    c.inject = true;
    dr::TorqueDriveParams weak = ideal;
    weak.current_limit_a = 0.2;
    c.cfg.drive = weak;
    c.name = "filters, current limit bites " + std::to_string(i++);
    cs.push_back(c);
  }
  // Two-mass layouts the loops above leave out (the two-body solve written out in PowerTrain::Local): friction on one
  // body only (the other's force stays 0 in every sweep), asymmetric Coulomb and viscous friction, a constant load.
  pl::TwoMassPlantParams one_side, asym;
  one_side.motor_coulomb_nm = 0.01;
  one_side.motor_coulomb_asym_nm = 0.003;
  one_side.load_nm = 0.004;
  asym.motor_coulomb_nm = 0.01;
  asym.motor_static_nm = 0.015;
  asym.load_coulomb_nm = 0.02;
  asym.load_coulomb_asym_nm = -0.004;
  asym.load_viscous_nms = 3e-5;
  asym.load_viscous_asym_nms = 2e-5;
  asym.load_nm = -0.002;
  for (const pl::TwoMassPlantParams& plant : {one_side, asym}) {
    for (const dr::TorqueDriveParams& d : {lag, ideal}) {
      Case c;
      c.name = "two-mass case " + std::to_string(i++);
      c.cfg.law = gt;
      c.cfg.plant = plant;
      c.cfg.drive = d;
      c.cfg.servo_period_s = 250e-6;
      c.profile = i % 2 == 0;
      c.cfg.substeps = 1 + i % 2;
      cs.push_back(c);
    }
  }
  Case plain_trip = cs[last_plain];
  plain_trip.name = "plain, error-limit trip";
  plain_trip.guard.error_limit_pulse = 40.0;
  cs.push_back(plain_trip);
  Case plain_alarm = cs[last_plain - 1];
  plain_alarm.name = "plain, drive alarm";
  dr::TorqueDriveParams alarming = lag;
  alarming.alarm_at_s = 0.2;
  plain_alarm.cfg.drive = alarming;
  plain_alarm.guard.stop_on_alarm = true;
  cs.push_back(plain_alarm);
  plain_alarm.name = "plain, drive alarm, run on";
  plain_alarm.guard.stop_on_alarm = false;
  cs.push_back(plain_alarm);
  // The alarm's first sub-step on the second piece's last tick (1200) and on the third piece's first (1201).
  for (int at : {1200, 1201}) {
    plain_alarm.name = "plain, drive alarm at sub-step " + std::to_string(at);
    alarming.alarm_at_s = at * 250e-6;
    plain_alarm.cfg.drive = alarming;
    cs.push_back(plain_alarm);
  }

  Case trip = cs[0];  // the error limit trips inside the second piece
  trip.name = "error-limit trip";
  trip.guard.error_limit_pulse = 40.0;
  cs.push_back(trip);
  Case alarm = cs[5];
  alarm.name = "drive alarm";
  lag.alarm_at_s = 0.2;
  alarm.cfg.drive = lag;
  alarm.guard.stop_on_alarm = true;
  cs.push_back(alarm);
  Case alarm_on = alarm;
  alarm_on.name = "drive alarm, run on";
  alarm_on.guard.stop_on_alarm = false;
  cs.push_back(alarm_on);
  return cs;
}
}  // namespace

namespace {
// The kernels this build and CPU can run (on a machine with AVX-512: all four).
std::vector<mc::TickKernel> available_kernels() {
  std::vector<mc::TickKernel> ks{mc::TickKernel::kPortable};
  for (mc::TickKernel k : {mc::TickKernel::kSse41, mc::TickKernel::kAvx2, mc::TickKernel::kAvx512})
    if (mc::tick_kernel_available(k)) ks.push_back(k);
  return ks;
}
}  // namespace

TEST(FusedTick, SameDoublesAsTheGeneralLoopOnEverySignal) {
  for (const Case& c : cases()) {
    const std::vector<double> fused = run_case(c, true), general = run_case(c, false);
    ASSERT_EQ(fused.size(), general.size()) << c.name;
    EXPECT_EQ(0, std::memcmp(fused.data(), general.data(), fused.size() * sizeof(double))) << c.name;
  }
}

// Decisions SP1, FV20: every kernel of the fused tick (portable; SSE4.1, AVX2 and AVX-512 where the CPU has them),
// forced, gives the general loop's doubles on every signal; 'auto' picks the widest the CPU has.
TEST(FusedTick, EveryKernelGivesTheSameDoubles) {
  const std::vector<mc::TickKernel> kernels = available_kernels();
#if SERVOBENCH_SSE41_KERNEL
  const bool avx512 = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl");
  EXPECT_EQ(mc::auto_tick_kernel(), avx512                               ? mc::TickKernel::kAvx512
                                    : __builtin_cpu_supports("avx2")   ? mc::TickKernel::kAvx2
                                    : __builtin_cpu_supports("sse4.1") ? mc::TickKernel::kSse41
                                                                       : mc::TickKernel::kPortable);
#else
  EXPECT_EQ(mc::auto_tick_kernel(), mc::TickKernel::kPortable);
#endif
  for (const Case& c : cases()) {
    const std::vector<double> general = run_case(c, false);
    for (mc::TickKernel k : kernels) {
      const std::vector<double> fused = run_case(c, true, k);
      ASSERT_EQ(fused.size(), general.size()) << c.name << " " << mc::tick_kernel_name(k);
      EXPECT_EQ(0, std::memcmp(fused.data(), general.data(), fused.size() * sizeof(double)))
          << c.name << " " << mc::tick_kernel_name(k);
    }
  }
}

// Decision SR1: a run that records fb_pos only, or nothing (the fused loop skips its recording block), gives the
// general loop's feedback, outcome and end state bit for bit on every case, with each kernel.
TEST(FusedTick, FeedbackOnlyRunsGiveTheSameDoubles) {
  const std::vector<mc::TickKernel> kernels = available_kernels();
  for (const Case& c : cases()) {
    const std::vector<double> all = run_case(c, false);
    for (Rec rec : {Rec::kFeedback, Rec::kNothing}) {
      const std::vector<double> general = run_case(c, false, mc::TickKernel::kAuto, rec);
      ASSERT_EQ(general.size(), all.size()) << c.name;
      // The general loop itself: the same state at the end whatever it records.
      EXPECT_EQ(0, std::memcmp(general.data() + general.size() - 10, all.data() + all.size() - 10,
                               10 * sizeof(double)))
          << c.name;
      for (mc::TickKernel k : kernels) {
        const std::vector<double> fused = run_case(c, true, k, rec);
        ASSERT_EQ(fused.size(), general.size()) << c.name << " " << mc::tick_kernel_name(k);
        EXPECT_EQ(0, std::memcmp(fused.data(), general.data(), fused.size() * sizeof(double)))
            << c.name << " " << mc::tick_kernel_name(k) << (rec == Rec::kFeedback ? " fb_pos" : " nothing");
      }
    }
  }
}

// Decision FV26: the plain-kernel cases built to saturate do saturate (so the clamps the kernel keeps are tested):
// the general loop's volts reach the DAC's full scale, its current (an ideal current loop's: its command) the drive's
// limit.
TEST(FusedTick, ThePlainSaturationCasesSaturate) {
  int dac = 0, drive = 0;
  for (const Case& c : cases()) {
    const bool dac_case = c.name.find("DAC full scale bites") != std::string::npos;
    const bool drive_case = c.name.find("current limit bites") != std::string::npos;
    if (!dac_case && !drive_case) continue;
    const std::vector<double> rec = run_case(c, false);
    double peak = 0.0;
    int slot = 0, at = 0;
#define SB_FIND(name, unit, doc) \
  if (std::string(#name) == (dac_case ? "volts" : "current_a")) at = slot; \
  ++slot;
    SERVOBENCH_TRACE_SIGNALS(SB_FIND)
#undef SB_FIND
    const std::size_t piece = 1200;  // the second piece's signals follow the first's (1 tick) and its 3 outcome slots
    const std::size_t start = kSignals * 1 + 3 + static_cast<std::size_t>(at) * piece;
    for (std::size_t k = 0; k < piece; ++k) peak = std::max(peak, std::fabs(rec[start + k]));
    if (dac_case) {
      EXPECT_NEAR(peak, 0.05, 1e-12) << c.name;
      ++dac;
    } else {
      EXPECT_NEAR(peak, 0.2, 1e-12) << c.name;
      ++drive;
    }
  }
  EXPECT_EQ(dac, 2);
  EXPECT_EQ(drive, 3);
}

// Decision TK1: a pass-through run keeps no filter history in the loop but replays the law's last two outputs into
// the filters at the end, so filters set afterwards see the same past: a fused pass-through run followed by the two
// integer filters gives the general loop's doubles, for runs of 4, 5 and 3000 ticks.
TEST(FusedTick, FiltersSetAfterAPassThroughRunSeeTheSamePast) {
  for (std::size_t first : {std::size_t{4}, std::size_t{5}, std::size_t{3000}}) {
    std::vector<double> out[2];
    for (bool fused : {false, true}) {
      mc::AxisConfig cfg;
      cfg.servo_period_s = 250e-6;
      ctl::GtServoLawParams gt;
      gt.kp = 30;
      gt.kd = 600;
      gt.kvff = 50;
      cfg.law = gt;
      mc::Axis axis(cfg);
      axis.set_fused_tick(fused);
      const std::size_t n = first + 500;
      std::vector<double> pos(n), vel(n), acc(n), fb(n);
      for (std::size_t k = 0; k < n; ++k) {
        const double t = static_cast<double>(k);
        pos[k] = 0.01 * t * t + 2.0 * std::sin(t / 9.0);
        vel[k] = 0.02 * t;
        acc[k] = 0.02;
      }
      mc::CommandInput in;
      in.pos = pos.data();
      in.vel = vel.data();
      in.acc = acc.data();
      in.n = first;
      mc::Trace tr;
      tr.fb_pos = fb.data();
      axis.run(in, tr, {});
      axis.set_filters(integer_filters());
      mc::CommandInput rest = in;
      rest.pos += first;
      rest.vel += first;
      rest.acc += first;
      rest.n = n - first;
      mc::Trace tr2;
      tr2.fb_pos = fb.data() + first;
      axis.run(rest, tr2, {});
      out[fused] = fb;
      out[fused].push_back(axis.angle_rad());
    }
    EXPECT_EQ(0, std::memcmp(out[0].data(), out[1].data(), out[0].size() * sizeof(double))) << first << " ticks";
  }
}

TEST(FusedTick, AKernelTheCpuLacksIsRefused) {
  mc::Axis axis;
  axis.set_tick_kernel(mc::TickKernel::kPortable);
  EXPECT_EQ(axis.tick_kernel(), mc::TickKernel::kPortable);
  for (mc::TickKernel k : {mc::TickKernel::kSse41, mc::TickKernel::kAvx2, mc::TickKernel::kAvx512}) {
    axis.set_tick_kernel(mc::TickKernel::kPortable);
    if (!mc::tick_kernel_available(k)) {
      EXPECT_THROW(axis.set_tick_kernel(k), std::invalid_argument);
      EXPECT_EQ(axis.tick_kernel(), mc::TickKernel::kPortable);
    } else {
      axis.set_tick_kernel(k);
      EXPECT_EQ(axis.tick_kernel(), k);
    }
  }
  EXPECT_STREQ(mc::tick_kernel_name(mc::TickKernel::kSse41), "sse4.1");
  EXPECT_STREQ(mc::tick_kernel_name(mc::TickKernel::kAvx2), "avx2");
  EXPECT_STREQ(mc::tick_kernel_name(mc::TickKernel::kAvx512), "avx512");
}

TEST(FusedTick, TheGuardCasesTrip) {
  const std::vector<Case> cs = cases();
  const std::vector<double> trip = run_case(cs[cs.size() - 3], true);
  const std::vector<double> alarm = run_case(cs[cs.size() - 2], true);
  EXPECT_EQ(trip[trip.size() - 3], 0.0);   // servo off after the trip
  EXPECT_EQ(alarm[alarm.size() - 3], 0.0);
  EXPECT_EQ(alarm[alarm.size() - 2], 1.0);  // alarm set
}

namespace {
// The two-body friction solve as it was before decision SQ2: always three full Gauss-Seidel sweeps (the reference).
void solve_three_sweeps(const pl::BodyIndex* idx, const pl::DryFriction<double>* fr, const Eigen::Matrix<double, 5, 1>& x0,
                        const Eigen::Matrix<double, 5, 1>& x_free, const Eigen::Matrix<double, 5, 3>& gamma,
                        unsigned locked, double* f, bool* stick) {
  double slip_level[2], fs_pos[2], fs_neg[2];
  for (int b = 0; b < 2; ++b) {
    if (locked & (1u << b)) {
      f[b] = 0.0;
      stick[b] = true;
    } else if (fr[b].active()) {
      const double v0 = x0[idx[b].speed];
      const double dir = v0 > 0.0 ? 1.0 : -1.0;
      slip_level[b] = pl::directional_sliding_nm(fr[b], v0, dir);
      fs_pos[b] = pl::directional_breakaway_nm(fr[b], 1.0);
      fs_neg[b] = pl::directional_breakaway_nm(fr[b], -1.0);
    }
  }
  for (int sweep = 0; sweep < 3; ++sweep) {
    for (int b = 0; b < 2; ++b) {
      if (locked & (1u << b)) continue;
      const pl::BodyIndex& s = idx[b];
      stick[b] = false;
      if (!fr[b].active()) {
        f[b] = 0.0;
        continue;
      }
      double v_free = x_free[s.speed];
      double d = x_free[s.angle] - x0[s.angle];
      const int o = 1 - b;
      v_free += gamma(s.speed, idx[o].input) * f[o];
      d += gamma(s.angle, idx[o].input) * f[o];
      const double g = gamma(s.speed, s.input), gth = gamma(s.angle, s.input), v0 = x0[s.speed];
      double fb;
      bool st = false;
      const double dir = v0 > 0.0 ? 1.0 : -1.0;
      const double f_slip = -dir * slip_level[b];
      if (v0 != 0.0 && (v_free + g * f_slip) * dir > 0.0) {
        fb = f_slip;
      } else {
        const double f_stick = -v_free / g;
        if (f_stick <= fs_neg[b] && f_stick >= -fs_pos[b]) {
          fb = f_stick;
          st = true;
        } else {
          fb = v_free > 0.0 ? -fs_pos[b] : fs_neg[b];
        }
      }
      if (!(st && v0 == 0.0) && fb * (d + gth * fb) > 0.0) {
        st = false;
        const double cap = gth > 0.0 ? std::fabs(d) / gth : 0.0;
        const double afb = std::fabs(fb);
        const double mag = afb < cap ? afb : cap;
        fb = d == 0.0 ? 0.0 : (d > 0.0 ? -mag : mag);
      }
      f[b] = fb;
      stick[b] = st;
    }
  }
}
}  // namespace

// Decision SQ2: the two-body solve stops once a body's force repeats bit for bit; its forces and stick flags are the
// three full sweeps' on random sub-steps (sliding, sticking, breaking away, passing zero, locked bodies, zero speeds,
// Stribeck, asymmetry, an inactive body).
TEST(FusedTick, TheTwoBodySolveStopsWhenConvergedWithTheSameForces) {
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const pl::BodyIndex idx[2] = {{1, 2, 1}, {3, 4, 2}};
  for (int trial = 0; trial < 400000; ++trial) {
    pl::DryFriction<double> fr[2];
    for (auto& f : fr) {
      f.coulomb_nm = trial % 11 == 0 ? 0.0 : 0.01 + 0.02 * std::fabs(u(rng));
      f.breakaway_nm = trial % 3 == 0 ? f.coulomb_nm : f.coulomb_nm * (1.0 + std::fabs(u(rng)));
      f.stribeck_speed_rad_s = 0.05 + std::fabs(u(rng));
      f.coulomb_asym_nm = trial % 5 == 0 ? 0.3 * f.coulomb_nm * u(rng) : 0.0;
      f.viscous_asym_nms = trial % 7 == 0 ? 1e-4 * std::fabs(u(rng)) : 0.0;
    }
    if (trial % 13 == 0) fr[1].coulomb_nm = fr[1].breakaway_nm = 0.0;  // an inactive body
    Eigen::Matrix<double, 5, 1> x0, xf;
    Eigen::Matrix<double, 5, 3> gamma;
    for (int i = 0; i < 5; ++i) {
      x0[i] = u(rng);
      xf[i] = x0[i] + 0.05 * u(rng);
      for (int j = 0; j < 3; ++j) gamma(i, j) = 0.01 * u(rng);
    }
    for (int b = 0; b < 2; ++b) {
      gamma(idx[b].speed, idx[b].input) = 0.5 + std::fabs(u(rng));   // own force slows the body
      gamma(idx[b].angle, idx[b].input) = 1e-3 * std::fabs(u(rng));
      const int pick = (trial >> (2 * b)) % 4;
      if (pick == 0) x0[idx[b].speed] = 0.0;                          // at rest
      if (pick == 1) xf[idx[b].speed] = 1e-3 * u(rng);                // nearly stopping
    }
    const unsigned locked = trial % 17 == 0 ? 1u + static_cast<unsigned>(trial % 3) % 3 : 0u;
    double f_ref[2] = {0.0, 0.0}, f_new[2] = {0.0, 0.0};
    if (trial % 2) f_ref[0] = f_new[0] = f_ref[1] = f_new[1] = 0.01 * u(rng);  // a re-solve starts from forces
    bool s_ref[2] = {false, false}, s_new[2] = {false, false};
    solve_three_sweeps(idx, fr, x0, xf, gamma, locked, f_ref, s_ref);
    pl::solve_dry_friction(2, idx, fr, x0, xf, gamma, locked, f_new, s_new);
    ASSERT_EQ(0, std::memcmp(f_ref, f_new, sizeof f_ref)) << "trial " << trial;
    ASSERT_EQ(s_ref[0], s_new[0]) << "trial " << trial;
    ASSERT_EQ(s_ref[1], s_new[1]) << "trial " << trial;
  }
}
