// Decision P16: the fused tick (machine/axis_fused.cpp) gives the same doubles as the general loop, signal by signal,
// for every configuration it takes (GT/APS law; rigid or two-mass; ideal or lagged current loop; Coulomb, Stribeck,
// asymmetric friction; cogging, load, unbalance; encoder noise and load mounting; sub-steps; both biquads; injection;
// profile velocities; the error-limit and alarm guards; runs continued in pieces).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "servobench/machine/axis.hpp"

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

// Runs the same command in three pieces (continuation) and the state read after it; `kernel` the fused tick's kernel
// (decision SP1).
std::vector<double> run_case(const Case& c, bool fused, mc::TickKernel kernel = mc::TickKernel::kAuto) {
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
    const mc::Trace tr = all_signals(buf, piece);
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
  ctl::AdlinkBiquadParams fir, pole;
  fir.b0 = 2;
  fir.b1 = 1;
  fir.b2 = 1;
  fir.div = 4;
  pole.b0 = 1;
  pole.a1 = 1;
  pole.div = 2;
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
        if (i % 4 == 1) c.cfg.filters = {fir, pole};
        if (i % 5 == 2) c.cfg.encoder.noise_counts = 0.7;
        if (i % 3 == 2 && std::holds_alternative<pl::TwoMassPlantParams>(plant)) c.cfg.encoder.on_load = true;
        c.guard.error_limit_pulse = i % 2 ? 20000.0 : 0.0;
        cs.push_back(c);
        ++i;
      }
    }
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

TEST(FusedTick, SameDoublesAsTheGeneralLoopOnEverySignal) {
  for (const Case& c : cases()) {
    const std::vector<double> fused = run_case(c, true), general = run_case(c, false);
    ASSERT_EQ(fused.size(), general.size()) << c.name;
    EXPECT_EQ(0, std::memcmp(fused.data(), general.data(), fused.size() * sizeof(double))) << c.name;
  }
}

// Decision SP1: every kernel of the fused tick (portable; SSE4.1 where the CPU has it), forced, gives the general
// loop's doubles on every signal; 'auto' picks SSE4.1 exactly when the CPU has it.
TEST(FusedTick, EveryKernelGivesTheSameDoubles) {
  std::vector<mc::TickKernel> kernels{mc::TickKernel::kPortable};
  if (mc::tick_kernel_available(mc::TickKernel::kSse41)) kernels.push_back(mc::TickKernel::kSse41);
#if SERVOBENCH_SSE41_KERNEL
  EXPECT_EQ(mc::auto_tick_kernel(), __builtin_cpu_supports("sse4.1") ? mc::TickKernel::kSse41
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

TEST(FusedTick, AKernelTheCpuLacksIsRefused) {
  mc::Axis axis;
  axis.set_tick_kernel(mc::TickKernel::kPortable);
  EXPECT_EQ(axis.tick_kernel(), mc::TickKernel::kPortable);
  if (!mc::tick_kernel_available(mc::TickKernel::kSse41)) {
    EXPECT_THROW(axis.set_tick_kernel(mc::TickKernel::kSse41), std::invalid_argument);
    EXPECT_EQ(axis.tick_kernel(), mc::TickKernel::kPortable);
  } else {
    axis.set_tick_kernel(mc::TickKernel::kSse41);
    EXPECT_EQ(axis.tick_kernel(), mc::TickKernel::kSse41);
  }
  EXPECT_STREQ(mc::tick_kernel_name(mc::TickKernel::kSse41), "sse4.1");
}

TEST(FusedTick, TheGuardCasesTrip) {
  const std::vector<Case> cs = cases();
  const std::vector<double> trip = run_case(cs[cs.size() - 3], true);
  const std::vector<double> alarm = run_case(cs[cs.size() - 2], true);
  EXPECT_EQ(trip[trip.size() - 3], 0.0);   // servo off after the trip
  EXPECT_EQ(alarm[alarm.size() - 3], 0.0);
  EXPECT_EQ(alarm[alarm.size() - 2], 1.0);  // alarm set
}
