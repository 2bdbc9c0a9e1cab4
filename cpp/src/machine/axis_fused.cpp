// The fused tick (issue 22 point 1, decision P16): Axis::run's loop specialised per configuration.
//
// For a servo-on axis with its law in place (no external controller) and a torque drive whose power train runs on
// fixed-size discretisations (2..5 states), the law, the two biquads, the DAC and the power train are copied into
// locals of compile-time size, and one loop is compiled per (law type, state count N, body count NB): the law's
// and the plant's choice is made once per run, not per tick, and inside the loop no state is reached through a
// member that a store to a recording buffer could alias. The ticks are those of Axis::run_with, operation for
// operation (the same doubles; tests/cpp/test_fused_tick.cpp compares every signal of both loops). The state is
// written back at the end (and at a guard's trip), so run() and step() continue from it as before.
#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "servobench/machine/axis.hpp"
#include "servobench/machine/powertrain_local.hpp"

namespace servobench::machine {

namespace {
// Every recording slot except fb_pos (the hot loop stores fb_pos itself and looks at the others only if one is set).
bool records_more_than_feedback(const Trace& tr) {
  Trace rest = tr;
  rest.fb_pos = nullptr;
#define SERVOBENCH_TRACE_ANY(name, unit, doc) \
  if (rest.name) return true;
  SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_TRACE_ANY)
#undef SERVOBENCH_TRACE_ANY
  return false;
}
}  // namespace

bool Axis::run_fused(const CommandInput& command, const Trace& trace, const RunGuard& guard, RunOutcome& outcome) {
  // Runs of a few ticks (the card's and the motion loop's one tick per call) take the general loop: the same
  // doubles, without the copies in and out that a long run pays once.
  constexpr std::size_t kMinTicks = 4;
  if (!fused_enabled_ || command.n < kMinTicks || command.external || !servo_on_ || power_.pulse_input())
    return false;
  const TickKernel kernel = kernel_ == TickKernel::kAuto ? auto_tick_kernel() : kernel_;
  bool done = false;
  std::visit(
      [&](auto& law) {
        using L = std::decay_t<decltype(law)>;
        const auto run = [&](auto n, auto nb) {
          constexpr int kN = decltype(n)::value, kNB = decltype(nb)::value;
#if SERVOBENCH_SSE41_KERNEL
          if (kernel == TickKernel::kSse41) return fused_sse41<L, kN, kNB>(law, command, trace, guard);
#endif
          return fused_portable<L, kN, kNB>(law, command, trace, guard);
        };
        using std::integral_constant;
        if (PowerTrain::Local<2, 1>::applies(power_))
          outcome = run(integral_constant<int, 2>{}, integral_constant<int, 1>{});
        else if (PowerTrain::Local<3, 1>::applies(power_))
          outcome = run(integral_constant<int, 3>{}, integral_constant<int, 1>{});
        else if (PowerTrain::Local<4, 2>::applies(power_))
          outcome = run(integral_constant<int, 4>{}, integral_constant<int, 2>{});
        else if (PowerTrain::Local<5, 2>::applies(power_))
          outcome = run(integral_constant<int, 5>{}, integral_constant<int, 2>{});
        else
          return;
        done = true;
      },
      law_);
  return done;
}

// Each kernel is flattened: every call inside it that can be inlined is (the power train's friction solve included),
// so a kernel is one function with its state in registers and, for SSE4.1, SSE4.1 code throughout.
template <class Law, int N, int NB>
__attribute__((flatten)) RunOutcome Axis::fused_portable(Law& law, const CommandInput& command, const Trace& trace,
                                                         const RunGuard& guard) {
  return fused_loop<Law, N, NB, PortableRounding>(law, command, trace, guard);
}

#if SERVOBENCH_SSE41_KERNEL
// The same loop compiled for SSE4.1: everything in it is inlined (fused_loop is always_inline, the law, filters, DAC,
// encoder and power train are header inline functions), so the whole tick is SSE4.1 code and rounds with `roundsd`;
// no other instruction set (no AVX, no FMA) enters, so the arithmetic is the portable kernel's.
template <class Law, int N, int NB>
__attribute__((target("sse4.1"), flatten)) RunOutcome Axis::fused_sse41(Law& law, const CommandInput& command,
                                                                        const Trace& trace, const RunGuard& guard) {
  return fused_loop<Law, N, NB, Sse41Rounding>(law, command, trace, guard);
}
#endif

TickKernel auto_tick_kernel() {
#if SERVOBENCH_SSE41_KERNEL
  static const bool sse41 = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("sse4.1") != 0;
  }();
  if (sse41) return TickKernel::kSse41;
#endif
  return TickKernel::kPortable;
}

bool tick_kernel_available(TickKernel k) {
  return k != TickKernel::kSse41 || auto_tick_kernel() == TickKernel::kSse41;
}

const char* tick_kernel_name(TickKernel k) {
  switch (k) {
    case TickKernel::kAuto: return "auto";
    case TickKernel::kPortable: return "portable";
    case TickKernel::kSse41: return "sse4.1";
  }
  return "?";
}

void Axis::set_tick_kernel(TickKernel k) {
  if (!tick_kernel_available(k))
    throw std::invalid_argument(std::string("Axis.tick_kernel: '") + tick_kernel_name(k) +
                                "' cannot run here (this build or CPU has no SSE4.1); the kernels here are 'auto' and "
                                "'portable'");
  kernel_ = k;
}

template <class Law, int N, int NB, class Round>
__attribute__((always_inline)) inline RunOutcome Axis::fused_loop(Law& law_state, const CommandInput& command,
                                                                  const Trace& tr, const RunGuard& guard) {
  RunOutcome outcome;
  const bool guarded = guard.error_limit_pulse > 0.0 || guard.stop_on_alarm;
  const double limit = guard.error_limit_pulse;
  const double ts = *config_.servo_period_s;
  const plant::SwitchParams& sw = config_.switches;
  const bool on_load = config_.encoder.on_load;
  const bool more = records_more_than_feedback(tr);
  const double* const pos = command.pos;
  const double* const vel_in = command.vel;
  const double* const acc_in = command.acc;
  const double* const volts_add = command.volts_add;
  double* const fb_out = tr.fb_pos;

  Law law = law_state;
  control::Biquad bq0 = biquads_[0], bq1 = biquads_[1];
  const drive::Dac dac = dac_;
  plant::Encoder& encoder = encoder_;
  PowerTrain::Local<N, NB> pt(power_);
  double pending = pending_volts_, prev_cmd = prev_cmd_, prev_vel = prev_vel_, prev_enc = prev_encoder_angle_;
  bool primed = primed_;
  long long tick = tick_;

  std::size_t k = 0;
  bool trip = false;
  for (; k < command.n; ++k) {
    const double r = pos[k];
    if (!primed) {
      prev_cmd = r;
      prev_vel = 0.0;
      primed = true;
    }
    const double v = vel_in ? vel_in[k] : r - prev_cmd;
    const double a = acc_in ? acc_in[k] : v - prev_vel;
    prev_cmd = r;
    prev_vel = v;

    const double enc_angle = on_load ? pt.load_angle_rad() : pt.motor_angle_rad();
    const double y = encoder.read<Round>(enc_angle);
    if (guarded) {
      if (limit > 0.0 && !(std::fabs(r - y) <= limit)) {  // NaN trips
        trip = true;
        outcome.stop = RunStop::kErrorLimit;
      } else if (guard.stop_on_alarm && pt.alarm()) {
        trip = true;
        outcome.stop = RunStop::kDriveAlarm;
      }
      if (trip) outcome.error_pulse = r - y;
    }
    pt.set_input(pending);  // the previous tick's output reaches the drive now
    control::LawTerms t;
    double f0 = 0.0, f1 = 0.0, volts = 0.0;
    if (!trip) {
      t = law.step(r, y, v, a);
      f0 = bq0.step(t.total);
      f1 = bq1.step(f0);
      const double request = law.counts_to_volts(f1);
      volts = dac.convert<Round>(volts_add ? request + volts_add[k] : request);
    } else {
      // The servo turns off at the tripping tick: no law, no filters, 0 V (plus any injection).
      t.vel = v;
      t.acc = a;
      if (volts_add) volts = dac.convert<Round>(volts_add[k]);
    }

    if (fb_out) fb_out[k] = y;
    if (more) {
      if (tr.time_s) tr.time_s[k] = static_cast<double>(tick) * ts;
      if (tr.cmd_pos) tr.cmd_pos[k] = r;
      if (tr.cmd_vel) tr.cmd_vel[k] = t.vel;
      if (tr.cmd_acc) tr.cmd_acc[k] = t.acc;
      if (tr.error) tr.error[k] = r - y;
      if (tr.p) tr.p[k] = t.p;
      if (tr.i) tr.i[k] = t.i;
      if (tr.d) tr.d[k] = t.d;
      if (tr.vff) tr.vff[k] = t.vff;
      if (tr.aff) tr.aff[k] = t.aff;
      if (tr.bias) tr.bias[k] = t.bias;
      if (tr.u) tr.u[k] = t.total;
      if (tr.biquad0) tr.biquad0[k] = f0;
      if (tr.biquad1) tr.biquad1[k] = f1;
      if (tr.volts) tr.volts[k] = volts;
      if (tr.current_a) tr.current_a[k] = pt.current_a();
      if (tr.torque_nm) tr.torque_nm[k] = pt.torque_nm();
      if (tr.angle_rad) tr.angle_rad[k] = pt.motor_angle_rad();
      if (tr.speed_rad_s) tr.speed_rad_s[k] = pt.motor_speed_rad_s();
      if (tr.load_angle_rad) tr.load_angle_rad[k] = pt.load_angle_rad();
      if (tr.load_speed_rad_s) tr.load_speed_rad_s[k] = pt.load_speed_rad_s();
      if (tr.alarm) tr.alarm[k] = pt.alarm() ? 1.0 : 0.0;
      if (tr.index) tr.index[k] = encoder.index_between<Round>(prev_enc, enc_angle) ? 1.0 : 0.0;
      const double load = pt.load_angle_rad();
      if (tr.home_sw) tr.home_sw[k] = sw.home(load) ? 1.0 : 0.0;
      if (tr.pos_limit_sw) tr.pos_limit_sw[k] = sw.pos_limit(load) ? 1.0 : 0.0;
      if (tr.neg_limit_sw) tr.neg_limit_sw[k] = sw.neg_limit(load) ? 1.0 : 0.0;
    }
    prev_enc = enc_angle;

    pt.advance_tick();
    pending = volts;
    ++tick;
    if (trip) break;
  }

  law_state = law;
  biquads_[0] = bq0;
  biquads_[1] = bq1;
  pt.store(power_);
  pending_volts_ = pending;
  prev_cmd_ = prev_cmd;
  prev_vel_ = prev_vel;
  prev_encoder_angle_ = prev_enc;
  primed_ = primed;
  tick_ = tick;
  if (trip) {
    servo_on_ = false;
    outcome.ticks = k + 1;
  } else {
    outcome.ticks = command.n;
  }
  return outcome;
}

}  // namespace servobench::machine
