// Axis: one simulated servo axis, composed of the layers and stepped one servo tick at a time.
//
// The tick (docs/decisions.md, "order inside a tick"):
//   command -> encoder read -> servo law -> biquad 0 -> biquad 1 -> output stage and DAC,
//   then the drive and mechanics advance over Ts (in `substeps` equal sub-steps) with the DAC voltage of the
//   previous tick: the controller's output takes effect one tick later, as on the cards' DSPs.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <variant>

#include "servobench/control/aps_servo_law.hpp"
#include "servobench/control/biquad.hpp"
#include "servobench/control/gt_servo_law.hpp"
#include "servobench/drive/dac.hpp"
#include "servobench/drive/torque_drive.hpp"
#include "servobench/machine/powertrain.hpp"
#include "servobench/machine/trace.hpp"
#include "servobench/plant/encoder.hpp"
#include "servobench/plant/lti.hpp"
#include "servobench/plant/rigid.hpp"
#include "servobench/plant/switches.hpp"
#include "servobench/plant/two_mass.hpp"

namespace servobench::machine {

using LawParams = std::variant<control::GtServoLawParams, control::ApsServoLawParams>;
using PlantParams = std::variant<plant::RigidPlantParams, plant::TwoMassPlantParams, plant::LtiPlantParams>;

struct AxisConfig {
  LawParams law = control::GtServoLawParams{};
  DriveParams drive = drive::TorqueDriveParams{};
  PlantParams plant = plant::RigidPlantParams{};
  plant::EncoderParams encoder{};
  plant::SwitchParams switches{};
  drive::DacParams dac{};
  std::optional<double> servo_period_s;  // s; empty: the law's card default (GT 200 us, APS 250 us)
  int substeps = 1;             // plant integration sub-steps per tick, 1..1000 (bindings check the range)
  // The two biquads after the law (ADLINK L1735, L1873-1887), float or ADLINK integer form; default: the card's
  // pass-through (B0 = DIV = 1). Each must be stable and, if bound to a sample time, bound to this axis's period.
  std::array<control::BiquadParams, 2> filters{control::AdlinkBiquadParams{}, control::AdlinkBiquadParams{}};
  // Validates every part and the servo period against the law's card range; fills the default period.
  void validate_and_complete();
};

// Validates both filters for an axis with the given servo period (s): parameters, stability, sample time.
void validate_filters(const std::array<control::BiquadParams, 2>& filters, double servo_period_s);

// Command input for `run`: n positions (pulse); velocities/accelerations optional (null: backward
// differences of the positions, pulse/tick and pulse/tick^2).
// volts_add: optional voltage added to the output stage's request before the DAC, V (an injection at the plant
// input, as for open-loop or disturbance-injection experiments); it reaches the drive one tick later like the rest.
// external: optional outside controller in place of the servo law and the biquads (a tuning relay, a user's
// experiment): called every tick after the encoder read with (tick index in this run, command pulse, feedback
// pulse), it returns the voltage request (V) for the DAC; the servo must be on. The output still reaches the drive
// one tick later.
struct CommandInput {
  const double* pos = nullptr;
  const double* vel = nullptr;
  const double* acc = nullptr;
  const double* volts_add = nullptr;
  const std::function<double(std::size_t, double, double)>* external = nullptr;
  std::size_t n = 0;
};

// Protections checked every tick of a run (the card's position-error protection, ADLINK ERR_POS_LEVEL L4012-4023
// and the Bode tool's deviation limit L2031): when one trips, the servo is turned off at that tick (its output is
// 0 V from then on) and the run ends after it.
struct RunGuard {
  double error_limit_pulse = 0.0;  // |cmd_pos - fb_pos| above this turns the servo off, pulse; 0 = off
  bool stop_on_alarm = false;      // a drive alarm turns the servo off and ends the run
};

enum class RunStop { kCompleted, kErrorLimit, kDriveAlarm };

struct RunOutcome {
  std::size_t ticks = 0;  // ticks actually run (== n unless a guard tripped; the tripping tick included)
  RunStop stop = RunStop::kCompleted;
  double error_pulse = 0.0;  // the following error at the tick that tripped, pulse
  double last_error_pulse = 0.0;  // the law's error E = command - encoder read of the last tick run, pulse
};

// Which compiled kernel of the fused tick runs (decisions SP1, FV20): kAuto picks the fastest this CPU runs (AVX-512
// where present, else AVX2, else SSE4.1, else portable); the others force one (for the tests and benchmarks). All
// give the same doubles.
enum class TickKernel { kAuto, kPortable, kSse41, kAvx512, kAvx2 };
// The kernel kAuto picks on this CPU (never kAuto), and whether this build and CPU can run kernel k.
TickKernel auto_tick_kernel();
bool tick_kernel_available(TickKernel k);
const char* tick_kernel_name(TickKernel k);  // "auto", "portable", "sse4.1", "avx2", "avx512"

class Axis {
 public:
  explicit Axis(AxisConfig config = {});

  const AxisConfig& config() const { return config_; }
  double servo_period_s() const { return *config_.servo_period_s; }
  long long tick() const { return tick_; }

  // Power-on state at the given motor angle: law memories cleared, at rest, output 0 V, tick counter 0.
  void reset(double angle_rad = 0.0);
  // The same from any state (issue 19): motor angle and speed, load angle and speed (rad, rad/s; a rigid plant's
  // load values must equal the motor's). Values must be finite (std::invalid_argument naming them).
  void reset_state(double motor_angle_rad, double motor_speed_rad_s, double load_angle_rad, double load_speed_rad_s);
  // Replaces the servo-law parameters at the next tick (the card's Update); the law keeps its memories.
  void set_law(const LawParams& law);
  // Replaces both biquads' coefficients at the next tick; their histories are kept (validated first).
  void set_filters(const std::array<control::BiquadParams, 2>& filters);

  // Servo on/off (the card's AxisOn/AxisOff, servo ON/OFF). Off: the law is not evaluated and the output is 0 V
  // (plus any injection); turning it on starts the law and the filters from power-on memories.
  void set_servo_on(bool on);
  bool servo_on() const { return servo_on_; }

  // Runs n ticks; continues from the current state. Fills the non-null buffers of `trace` (the first
  // outcome.ticks entries when a guard trips).
  RunOutcome run(const CommandInput& command, const Trace& trace, const RunGuard& guard = {});

  // The step API (programs in the loop): advances n ticks holding the command position (pulse), nothing recorded,
  // and returns the feedback read at the last of them (pulse). `external`, if given, replaces the law and the
  // biquads as in CommandInput. The same ticks as run() over n copies of the command.
  double step(double command_pulse, std::size_t n = 1,
              const std::function<double(std::size_t, double, double)>* external = nullptr);

  // The command position of the last tick run, pulse (the feedback position before the first run).
  double last_command_pulse() const { return primed_ ? prev_cmd_ : feedback_pulse(); }

  // Present state.
  double feedback_pulse() const { return encoder_.read_ideal(encoder_angle()); }
  double angle_rad() const { return power_.motor_angle_rad(); }
  double speed_rad_s() const { return power_.motor_speed_rad_s(); }
  double load_angle_rad() const { return power_.load_angle_rad(); }
  double load_speed_rad_s() const { return power_.load_speed_rad_s(); }
  bool alarm() const { return power_.alarm(); }
  // The servo law's error accumulator now (GT_GetIntgr; the ADLINK error sum), pulse*tick.
  double law_error_sum() const {
    return std::visit([](const auto& law) { return law.error_sum(); }, law_);
  }
  // The drive's reset input (the card's GT_DrvRst): clears a tripped alarm and cancels a scheduled one.
  void clear_drive_alarm() { power_.clear_alarm(); }
  const PowerTrain& power_train() const { return power_; }
  // The axis's encoder (its resolution, index angle and noise-free reading); the card senses with it.
  const plant::Encoder& encoder() const { return encoder_; }

  // The fused tick (decision P16) is on by default; false makes run() take the general loop everywhere. The two give
  // the same doubles (tests/cpp/test_fused_tick.cpp compares them signal by signal); this switch exists for that test.
  void set_fused_tick(bool on) { fused_enabled_ = on; }
  // The fused tick's kernel (decision SP1; default kAuto). Throws std::invalid_argument if this build or CPU cannot
  // run it. Exists for the tests (each kernel against the general loop) and the benchmarks.
  void set_tick_kernel(TickKernel k);
  TickKernel tick_kernel() const { return kernel_; }

 private:
  // The fused tick (axis_fused.cpp): the same ticks as run_with for a servo-on axis with its law in place and a
  // torque drive on the power train's fixed-size discretisations, with the law, biquads, DAC and power train in
  // local copies of compile-time size and one loop specialised per (law, state count, body count). Returns false,
  // having done nothing, where it does not apply.
  bool run_fused(const CommandInput& command, const Trace& trace, const RunGuard& guard, RunOutcome& outcome);
  // Whether a run may take the plain kernel as far as the command, the recording, the encoder and the DAC go
  // (axis_fused.cpp; the power train's own conditions are PowerTrain::Local::plain).
  bool plain_run(const CommandInput& command, const Trace& trace) const;
  // W: the two-body power train's rows (PowerTrain::Local): 1, one double each; 4, rows 0-3 in an AVX2 vector; 8,
  // the lanes of an AVX-512 vector.
  template <class Law, int N, int NB, bool kPass, bool kPlain, class Round, int W>
  RunOutcome fused_loop(Law& law, const CommandInput& command, const Trace& trace, const RunGuard& guard);
  // The kernels: fused_loop inlined into a function compiled for the baseline ISA, into one compiled for SSE4.1
  // (`roundsd`), one for AVX2 (three-operand forms) and one for AVX-512 (32 vector registers), with the matching
  // rounding policy (common/rounding.hpp).
  template <class Law, int N, int NB, bool kPass, bool kPlain>
  RunOutcome fused_portable(Law& law, const CommandInput& command, const Trace& trace, const RunGuard& guard);
#if SERVOBENCH_SSE41_KERNEL
  template <class Law, int N, int NB, bool kPass, bool kPlain>
  __attribute__((target("sse4.1"))) RunOutcome fused_sse41(Law& law, const CommandInput& command,
                                                           const Trace& trace, const RunGuard& guard);
  template <class Law, int N, int NB, bool kPass, bool kPlain>
  __attribute__((target("avx2"))) RunOutcome fused_avx2(Law& law, const CommandInput& command, const Trace& trace,
                                                         const RunGuard& guard);
  template <class Law, int N, int NB, bool kPass, bool kPlain>
  __attribute__((target("avx512f,avx512vl"))) RunOutcome fused_avx512(Law& law, const CommandInput& command,
                                                                     const Trace& trace, const RunGuard& guard);
#endif
  template <class Law>
  RunOutcome run_with(Law& law, const CommandInput& command, const Trace& trace, const RunGuard& guard);
  double encoder_angle() const {
    return config_.encoder.on_load ? power_.load_angle_rad() : power_.motor_angle_rad();
  }

  AxisConfig config_;
  std::variant<control::GtServoLaw, control::ApsServoLaw> law_;
  std::array<control::Biquad, 2> biquads_;
  drive::Dac dac_;
  plant::Encoder encoder_;
  PowerTrain power_;
  double pending_volts_ = 0.0;  // DAC output of the previous tick, applied during this one
  double prev_cmd_ = 0.0, prev_vel_ = 0.0;
  double prev_encoder_angle_ = 0.0;
  bool primed_ = false;
  bool servo_on_ = true;
  bool fused_enabled_ = true;
  TickKernel kernel_ = TickKernel::kAuto;
  long long tick_ = 0;
};

}  // namespace servobench::machine
