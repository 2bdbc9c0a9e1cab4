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

bool Axis::plain_run(const CommandInput& command, const Trace& trace) const {
  const plant::EncoderParams& e = encoder_.params();
  return trace.fb_pos && !records_more_than_feedback(trace) && command.vel && command.acc && !command.volts_add &&
         e.quantize && !(e.noise_counts > 0.0) && dac_.params().quantize;
}

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
        // Both filter slots pass-through (the cards' default) is a kernel of its own: no filter history to carry
        // through the loop, only the law's last two outputs, replayed into the filters at the end.
        const bool pass = biquads_[0].bypass() && biquads_[1].bypass();
        // One kernel instance, in the build `kernel` names (decisions SP1, FV20).
        const auto call = [&](auto n, auto nb, auto pass_c, auto plain_c) -> RunOutcome {
          constexpr int kN = decltype(n)::value, kNB = decltype(nb)::value;
          constexpr bool kPass = decltype(pass_c)::value, kPlain = decltype(plain_c)::value;
          switch (kernel) {
#if SERVOBENCH_SSE41_KERNEL
            case TickKernel::kAvx512: return fused_avx512<L, kN, kNB, kPass, kPlain>(law, command, trace, guard);
            case TickKernel::kAvx2: return fused_avx2<L, kN, kNB, kPass, kPlain>(law, command, trace, guard);
            case TickKernel::kSse41: return fused_sse41<L, kN, kNB, kPass, kPlain>(law, command, trace, guard);
#endif
            default: return fused_portable<L, kN, kNB, kPass, kPlain>(law, command, trace, guard);
          }
        };
        const std::true_type yes{};
        const std::false_type no{};
        const auto run = [&](auto n, auto nb) {
          if constexpr (decltype(nb)::value == 1) {
            // The plain kernel: a pass-through rigid axis recording its feedback only, driven by a profile with
            // its own velocity and acceleration, with a quantising encoder without noise, a quantising DAC, one
            // power-train sub-step per tick and no cogging or unbalance -- each of those a constant of the loop.
            if (pass && plain_run(command, trace) && PowerTrain::Local<decltype(n)::value, 1>::plain(power_))
              return call(n, nb, yes, yes);
          }
          return pass ? call(n, nb, yes, no) : call(n, nb, no, no);
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
template <class Law, int N, int NB, bool kPass, bool kPlain>
__attribute__((flatten)) RunOutcome Axis::fused_portable(Law& law, const CommandInput& command, const Trace& trace,
                                                         const RunGuard& guard) {
  return fused_loop<Law, N, NB, kPass, kPlain, PortableRounding, 1>(law, command, trace, guard);
}

#if SERVOBENCH_SSE41_KERNEL
// The same loop compiled for SSE4.1: everything in it is inlined (fused_loop is always_inline, the law, filters, DAC,
// encoder and power train are header inline functions), so the whole tick is SSE4.1 code and rounds with `roundsd`;
// no other instruction set (no AVX, no FMA) enters, so the arithmetic is the portable kernel's.
template <class Law, int N, int NB, bool kPass, bool kPlain>
__attribute__((target("sse4.1"), flatten)) RunOutcome Axis::fused_sse41(Law& law, const CommandInput& command,
                                                                        const Trace& trace, const RunGuard& guard) {
  return fused_loop<Law, N, NB, kPass, kPlain, Sse41Rounding, 1>(law, command, trace, guard);
}

// The same loop compiled for AVX2, for a CPU without AVX-512 (decision FV20): still 16 vector registers, but the
// three-operand VEX forms need fewer register copies than SSE's two-operand ones, and a two-mass power train's rows
// 0-3 are one 4-lane vector (decision FV24). No FMA (not enabled by this target, and the file is compiled with
// -ffp-contract=off), so the same doubles.
template <class Law, int N, int NB, bool kPass, bool kPlain>
__attribute__((target("avx2"), flatten)) RunOutcome Axis::fused_avx2(Law& law, const CommandInput& command,
                                                                     const Trace& trace, const RunGuard& guard) {
  return fused_loop<Law, N, NB, kPass, kPlain, Sse41Rounding, NB == 2 ? 4 : 1>(law, command, trace, guard);
}

// The same loop compiled for AVX-512 (F and VL), for its 32 vector registers (decision FV20): the scalar arithmetic
// is the SSE kernels' (EVEX-encoded addsd, mulsd, minsd, maxsd, vrndscalesd; no FMA -- this file is compiled with
// -ffp-contract=off), so the same doubles, but the tick's state, the law's sums and the held DAC voltage stay in
// registers instead of going through the stack every tick as they do with SSE's 16; a two-mass power train's rows
// are one 8-lane vector (decision FV21).
template <class Law, int N, int NB, bool kPass, bool kPlain>
__attribute__((target("avx512f,avx512vl"), flatten)) RunOutcome Axis::fused_avx512(Law& law,
                                                                                   const CommandInput& command,
                                                                                   const Trace& trace,
                                                                                   const RunGuard& guard) {
  return fused_loop<Law, N, NB, kPass, kPlain, Sse41Rounding, NB == 2 ? 8 : 1>(law, command, trace, guard);
}
#endif

namespace {
struct CpuKernels {
  bool sse41 = false, avx512 = false, avx2 = false;
};
const CpuKernels& cpu_kernels() {
  static const CpuKernels k = [] {
    CpuKernels c;
#if SERVOBENCH_SSE41_KERNEL
    __builtin_cpu_init();  // libgcc also checks that the OS saves the AVX-512 registers (XGETBV)
    c.sse41 = __builtin_cpu_supports("sse4.1") != 0;
    c.avx512 = __builtin_cpu_supports("avx512f") != 0 && __builtin_cpu_supports("avx512vl") != 0;
    c.avx2 = __builtin_cpu_supports("avx2") != 0;
#endif
    return c;
  }();
  return k;
}
}  // namespace

TickKernel auto_tick_kernel() {
  if (cpu_kernels().avx512) return TickKernel::kAvx512;
  if (cpu_kernels().avx2) return TickKernel::kAvx2;
  if (cpu_kernels().sse41) return TickKernel::kSse41;
  return TickKernel::kPortable;
}

bool tick_kernel_available(TickKernel k) {
  switch (k) {
    case TickKernel::kSse41: return cpu_kernels().sse41;
    case TickKernel::kAvx512: return cpu_kernels().avx512;
    case TickKernel::kAvx2: return cpu_kernels().avx2;
    default: return true;
  }
}

const char* tick_kernel_name(TickKernel k) {
  switch (k) {
    case TickKernel::kAuto: return "auto";
    case TickKernel::kPortable: return "portable";
    case TickKernel::kSse41: return "sse4.1";
    case TickKernel::kAvx512: return "avx512";
    case TickKernel::kAvx2: return "avx2";
  }
  return "?";
}

void Axis::set_tick_kernel(TickKernel k) {
  if (!tick_kernel_available(k)) {
    std::string here = "'auto', 'portable'";
    for (TickKernel o : {TickKernel::kSse41, TickKernel::kAvx2, TickKernel::kAvx512})
      if (tick_kernel_available(o)) here += std::string(", '") + tick_kernel_name(o) + "'";
    throw std::invalid_argument(std::string("Axis.tick_kernel: '") + tick_kernel_name(k) + "' cannot run here (this " +
                                "build or CPU lacks its instructions); the kernels here are " + here);
  }
  kernel_ = k;
}

template <class Law, int N, int NB, bool kPass, bool kPlain, class Round, int W>
__attribute__((always_inline)) inline RunOutcome Axis::fused_loop(Law& law_state, const CommandInput& command,
                                                                  const Trace& tr, const RunGuard& guard) {
  RunOutcome outcome;
  const bool guarded = guard.error_limit_pulse > 0.0 || guard.stop_on_alarm;
  const double limit = guard.error_limit_pulse;
  const double ts = *config_.servo_period_s;
  const plant::SwitchParams& sw = config_.switches;
  const bool on_load = config_.encoder.on_load;
  const bool more = !kPlain && records_more_than_feedback(tr);
  const double* const pos = command.pos;
  const double* const vel_in = command.vel;
  const double* const acc_in = command.acc;
  const double* const volts_add = command.volts_add;
  double* const fb_out = tr.fb_pos;

  Law law = law_state;
  control::Biquad bq0 = biquads_[0], bq1 = biquads_[1];
  // kPass: the law's outputs of the last two stepped ticks (indexed by tick parity), kept in memory rather than in
  // registers; the filters' histories are those outputs (a pass-through keeps x1 = y1 = its last input).
  double law_out[2] = {0.0, 0.0};
  const drive::Dac dac = dac_;
  const double dac_fs = dac.params().full_scale_v, dac_cpv = dac.codes_per_volt(), dac_vpc = dac.volts_per_code();
  plant::Encoder& encoder = encoder_;
  const double enc_cpr = encoder.counts_per_rad();
  PowerTrain::Local<N, NB, W> pt(power_);
  double pending = pending_volts_, prev_cmd = prev_cmd_, prev_vel = prev_vel_, prev_enc = prev_encoder_angle_;
  // The saturations that cannot bite in this run are left out (decision FV26). The drive sees the DAC's output (or
  // the held voltage the run starts from), at most its largest code; the plain kernel's DAC sees the law's own
  // output, at most law.max_volts(). Rounding is monotonic, so a clamp that holds at the bound holds below it.
  const double dac_top = dac.params().quantize ? Round::nearbyint(dac_fs * dac_cpv) * dac_vpc : dac_fs;
  const bool drive_clamps = !(std::fabs(pending) <= dac_top && pt.current_within_limit(dac_top));
  const bool dac_clamps = !(law.max_volts() <= dac_fs);
  bool primed = primed_;
  long long tick = tick_;

  const std::size_t n = command.n;
  std::size_t k = 0;
  bool trip = false;
  for (; k < n; ++k) {
    const double r = pos[k];
    double v, a;
    if constexpr (kPlain) {  // the profile's own velocity and acceleration; prev_cmd/prev_vel are set at the end
      v = vel_in[k];
      a = acc_in[k];
    } else {
      if (!primed) {
        prev_cmd = r;
        prev_vel = 0.0;
        primed = true;
      }
      v = vel_in ? vel_in[k] : r - prev_cmd;
      a = acc_in ? acc_in[k] : v - prev_vel;
      prev_cmd = r;
      prev_vel = v;
    }

    const double enc_angle = on_load ? pt.load_angle_rad() : pt.motor_angle_rad();
    // Plain: Encoder::read of a quantising encoder without noise, written out on the loop's constant.
    const double y = kPlain ? Round::floor(enc_angle * enc_cpr + 0.5) : encoder.read<Round>(enc_angle);
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
    if (!drive_clamps)  // the previous tick's output reaches the drive now
      pt.set_input_within_limit(pending);
    else
      pt.set_input(pending);
    control::LawTerms t;
    double f0 = 0.0, f1 = 0.0, volts = 0.0;
    if (!trip) {
      t = law.step(r, y, v, a);
      if constexpr (kPass) {
        f0 = f1 = t.total;
        law_out[k & 1] = t.total;
      } else {
        f0 = bq0.step(t.total);
        f1 = bq1.step(f0);
      }
      const double request = law.counts_to_volts(f1);
      if constexpr (kPlain) {  // Dac::convert of a quantising DAC, on the loop's constants
        const double c = !dac_clamps ? request : (request > dac_fs ? dac_fs : (request < -dac_fs ? -dac_fs : request));
        volts = Round::nearbyint(c * dac_cpv) * dac_vpc;
      } else {
        volts = dac.convert<Round>(volts_add ? request + volts_add[k] : request);
      }
    } else {
      // The servo turns off at the tripping tick: no law, no filters, 0 V (plus any injection).
      t.vel = v;
      t.acc = a;
      if (!kPlain && volts_add) volts = dac.convert<Round>(volts_add[k]);
    }

    if (kPlain || fb_out) fb_out[k] = y;
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

    if constexpr (kPlain)
      pt.advance_plain();
    else
      pt.advance_tick();
    pending = volts;
    ++tick;
    if (trip) break;
  }

  if constexpr (kPlain) {  // what the general loop leaves: the last tick's command and velocity
    const std::size_t last = trip ? k : n - 1;
    prev_cmd = pos[last];
    prev_vel = vel_in[last];
    primed = true;
  }
  law_state = law;
  if constexpr (kPass) {
    // Every tick before a trip stepped the filters: replay the last two outputs (a pass-through's state after
    // step(a), step(b) is x1 = y1 = b, x2 = y2 = a, whatever it held before).
    const std::size_t stepped = trip ? k : n;
    for (std::size_t j = stepped >= 2 ? stepped - 2 : 0; j < stepped; ++j) {
      bq0.step(law_out[j & 1]);
      bq1.step(law_out[j & 1]);
    }
  }
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
    outcome.ticks = n;
  }
  return outcome;
}

}  // namespace servobench::machine
