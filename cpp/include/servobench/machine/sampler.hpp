// Sampler: the card's data sampling (the tuning workbench's scope). Chosen signals of chosen axes every N servo
// ticks into a buffer of a given depth, started by a trigger: immediate, a channel crossing a level (rising or
// falling, between two samples), or a latched card event turning on; optional pre-trigger samples. One-shot (the
// ADLINK APS_wait_trigger_sampling, L3544-3665) or continuous blocks (the GE watch, GE L2464-2884).
//
// Signals (SERVOBENCH_SAMPLE_SIGNALS) are the Axis trace, the MotionLoop trace and the card's own: what the
// manuals' lists name maps onto them (docs/card.md, "Scope"): ADLINK SAMP_COM_POS -> pos, SAMP_FBK_POS ->
// actual_pos, SAMP_CMD_VEL -> prf_vel / Ts, SAMP_FBK_VEL -> fbk_vel / Ts, SAMP_MIO -> mio, SAMP_MSTS -> msts,
// SAMP_CONTROL_VOL -> volts * 1000, SAMP_ENCODER_RAW -> fb_pos, SAMP_ERROR_POS -> error; PID_KP_CALC -> p, ...,
// PID_CALC -> u, BIQUAD_0/1_CALC -> biquad0/1, PID_ERR_POS_SUM -> error_sum, PID_LAST_ERR_POS -> error_prev,
// PID_ERR_POS_DIFF -> error_diff; GE watch bits 0/1/2/3/6 -> pos, actual_pos, prf_vel, fbk_vel, volts.
// A sample at tick k holds the values after tick k (the card's state when the host would read it).
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "servobench/machine/motion_loop.hpp"
#include "servobench/machine/trace.hpp"

// X(name, unit, description): the card's own per-axis signals, next to the Axis and loop traces.
#define SERVOBENCH_CARD_SAMPLE_SIGNALS(X)                                                                \
  X(events, "bits", "latched CardEvent bits")                                                           \
  X(moving, "bool", "the profile runs (GT status bit 10)")                                              \
  X(servo_on, "bool", "drive enabled (GT status bit 9)")                                                \
  X(prf_vel, "pulse/tick", "profile velocity")                                                          \
  X(prf_acc, "pulse/tick^2", "profile acceleration")                                                    \
  X(fbk_vel, "pulse/tick", "feedback velocity: actual position change over the last tick")              \
  X(msts, "bits", "ADLINK motion status word (APS_motion_status)")                                      \
  X(mio, "bits", "ADLINK motion I/O word (APS_motion_io_status)")                                       \
  X(gt_status, "bits", "GT axis status register (Table 4-14)")                                          \
  X(error_sum, "pulse*tick", "the law's error accumulator (PID_ERR_POS_SUM)")                           \
  X(error_prev, "pulse", "the law's error of the previous tick (PID_LAST_ERR_POS)")                     \
  X(error_diff, "pulse", "error minus the previous tick's (PID_ERR_POS_DIFF)")                          \
  X(trg_pulses, "count", "pulses the trigger output (channel = the 'axis') emitted in the tick")        \
  X(trg_level, "bool", "trigger output level at the end of the tick, logic applied")

#define SERVOBENCH_SAMPLE_SIGNALS(X) \
  SERVOBENCH_TRACE_SIGNALS(X)        \
  SERVOBENCH_LOOP_SIGNALS(X)         \
  SERVOBENCH_CARD_SAMPLE_SIGNALS(X)

namespace servobench::machine {

// One per signal of SERVOBENCH_SAMPLE_SIGNALS, in that order. Loop's `pos` is the command position.
enum class SampleSignal : int {
#define SERVOBENCH_ENUM(name, unit, doc) name,
  SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_ENUM)
#undef SERVOBENCH_ENUM
#define SERVOBENCH_ENUM(name, unit, doc) loop_##name,
  SERVOBENCH_LOOP_SIGNALS(SERVOBENCH_ENUM)
#undef SERVOBENCH_ENUM
#define SERVOBENCH_ENUM(name, unit, doc) card_##name,
  SERVOBENCH_CARD_SAMPLE_SIGNALS(SERVOBENCH_ENUM)
#undef SERVOBENCH_ENUM
  count_
};
constexpr int kTraceSignalCount = static_cast<int>(SampleSignal::loop_pos);
constexpr int kLoopSignalEnd = static_cast<int>(SampleSignal::card_events);
constexpr int kSampleSignalCount = static_cast<int>(SampleSignal::count_);

struct SampleSignalInfo {
  const char* name;
  const char* unit;
  const char* doc;
};
const SampleSignalInfo& sample_signal_info(SampleSignal s);
// By name (the info name); throws std::invalid_argument listing the names.
SampleSignal sample_signal_from(const std::string& name);

// One channel: a signal of an axis (0-based; for trg_* the trigger output channel 0..3).
struct SampleChannel {
  int axis = 0;
  SampleSignal signal = SampleSignal::cmd_pos;
};

enum class SampleTrigger : int { Immediate = 0, Rising = 1, Falling = 2, Event = 3 };

struct SamplerConfig {
  std::vector<SampleChannel> channels;  // 1..16
  double every_ticks = 1;    // a sample every N servo ticks, 1..1e6
  double depth = 1000;       // samples per block, 1..1e7 (depth x channels <= 1e8)
  SampleTrigger trigger = SampleTrigger::Immediate;
  double trigger_channel = 0;  // Rising/Falling: index into channels
  double level = 0.0;          // Rising: previous sample < level <= this one; Falling: previous > level >= this
  double event_axis = 0;       // Event: this axis's latched events ...
  double event_bits = 0;       // ... any of these CardEvent bits turning on (1..4095)
  double pretrigger = 0;       // samples kept before the trigger sample, 0..depth-1
  bool continuous = false;     // after a full block, start the next one at once (no new trigger)
  void validate(std::size_t axes) const;
};

// Where the sampler is: waiting for the pre-trigger part to fill / for the trigger, filling, done (one-shot).
enum class SamplerState : int { Idle = 0, Armed = 1, Filling = 2, Done = 3 };

// One block: `ticks[j]` the card tick of sample j, `values[j * channels + c]` its channel c.
struct SampleBlock {
  std::vector<long long> ticks;
  std::vector<double> values;
  long long trigger_tick = -1;  // the tick of the trigger sample (index = pretrigger), -1: immediate
};

class Sampler {
 public:
  static constexpr std::size_t kMaxBlocks = 256;  // continuous mode keeps the newest blocks (V73)

  // Starts sampling now (at the card tick `tick`): validated; previous data are dropped.
  void start(const SamplerConfig& config, std::size_t axes, long long tick);
  void stop();
  bool active() const { return state_ == SamplerState::Armed || state_ == SamplerState::Filling; }
  SamplerState state() const { return state_; }
  const SamplerConfig& config() const { return cfg_; }
  // Which signals of axis i the sampler reads this tick.
  bool needs(std::size_t axis, SampleSignal s) const;
  const std::vector<std::vector<bool>>& needed() const { return need_; }
  bool sample_due(long long tick) const { return active() && (tick - start_tick_) % every_ == 0; }
  // Called every tick while active: the event bits that turned on this tick (event trigger), and, at a sample
  // instant, the channel values.
  void note_events(std::uint32_t rising_on_event_axis) { if (rising_on_event_axis & event_mask_) event_seen_ = true; }
  void take(long long tick, const std::vector<double>& values);
  // The samples of the one-shot run (or the block being filled): count so far.
  std::size_t filled() const { return filled_; }
  // The finished one-shot block (state Done), or the oldest completed continuous block.
  bool block_ready() const { return !blocks_.empty(); }
  SampleBlock pop_block();
  const std::deque<SampleBlock>& blocks() const { return blocks_; }
  std::size_t dropped_blocks() const { return dropped_; }
  long long trigger_tick() const { return trigger_tick_; }
  // The pre-trigger buffer and the current block, oldest first (what a stop would keep).
  SampleBlock snapshot() const;

 private:
  void push(long long tick, const std::vector<double>& values);
  void finish_block();

  SamplerConfig cfg_{};
  SamplerState state_ = SamplerState::Idle;
  std::vector<std::vector<bool>> need_;
  long long start_tick_ = 0;
  long long every_ = 1;
  std::size_t depth_ = 0, nch_ = 0, pre_ = 0;
  std::uint32_t event_mask_ = 0;
  bool event_seen_ = false;
  bool have_prev_ = false;
  double prev_trigger_value_ = 0.0;
  // pre-trigger ring (Armed) and the block being filled
  std::deque<long long> ring_ticks_;
  std::deque<std::vector<double>> ring_values_;
  SampleBlock cur_;
  std::size_t filled_ = 0;
  long long trigger_tick_ = -1;
  std::deque<SampleBlock> blocks_;
  std::size_t dropped_ = 0;
};

}  // namespace servobench::machine
