// PositionCompare: the ADLINK high-speed position compare with trigger outputs (PCI-8254/8258, seed 004
// L3348-3435; digest adlink.md §6.10). Two linear comparators LCMP0/1 (start P1, count N, signed interval L:
// points P1 + i*L, i = 0..N-1, compared in the direction of L's sign), two table comparators TCMP0/1 (any list of
// points, compared in a set direction), four trigger outputs TRG0-3, each fed by any set of sources (manual,
// TCMP0/1, LCMP0/1), with a pulse width, a logic (active high/low) and a pulse or level-toggle format; a trigger
// counter per output.
//
// A comparator source is an axis's feedback (the encoder, card coordinates: what APS_get_position reads) or
// command position. The card gives the source values at the end of each tick; a point p is reached when the
// source passes it in the compare direction within the tick (previous < p <= now going up, > p >= now going
// down): the counter reaching the point, as the hardware's equality compare of a counter that steps through every
// count. Several points may be passed in one tick (the hardware compares at up to 1 MHz, L3395); each one
// emits a pulse at the instant interpolated linearly between the tick's ends, recorded in the trigger log.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace servobench::machine {

// Bits of a trigger output's source set (TGR_TRGx_SRC, decision V77).
enum TriggerSourceBit : std::uint32_t {
  kTrgSrcManual = 1u << 0, kTrgSrcTcmp0 = 1u << 1, kTrgSrcTcmp1 = 1u << 2, kTrgSrcLcmp0 = 1u << 3,
  kTrgSrcLcmp1 = 1u << 4,
};

struct CompareSource {
  int axis = 0;          // 0..axes-1
  bool command = false;  // false: feedback (encoder), true: command position
};

struct TriggerOutputConfig {
  std::uint32_t sources = 0;     // TriggerSourceBit set
  double pulse_width_s = 1e-7;   // 100 ns (the manual's minimum, L383) .. 1 s
  bool active_low = false;       // TGR_TRGx_LOGIC 1: the output idles high and pulses low
  bool toggle = false;           // TGR_TRGx_TGL 1: each trigger toggles the level instead of a pulse
};

// One emitted trigger pulse (or toggle).
struct TriggerEvent {
  double time_s = 0.0;   // interpolated instant on the card clock
  long long tick = 0;    // the tick during which it happened (the tick's end is tick + 1 servo periods)
  int output = 0;        // TRG 0..3
  int comparator = -1;   // 0/1 LCMP0/1, 2/3 TCMP0/1, -1 manual
  double point = 0.0;    // the compare point, pulse (manual: NaN)
};

class PositionCompare {
 public:
  static constexpr int kOutputs = 4;
  static constexpr std::size_t kMaxLog = 1000000;  // trigger log entries kept (the oldest dropped beyond)

  // Comparator index: 0/1 linear LCMP0/1, 2/3 table TCMP0/1.
  void set_source(int comparator, const CompareSource& src, std::size_t axes);
  const CompareSource& source(int comparator) const { return src_.at(static_cast<std::size_t>(comparator)); }
  // Linear compare (APS_set_trigger_linear): points start + i*interval, i = 0..count-1; interval != 0, its sign
  // the direction; count 0 disables. Whole pulses, 32-bit (L3395).
  void set_linear(int ch, double start, double count, double interval);
  // Table compare (APS_set_trigger_table): the points in order; direction +1 up, -1 down, 0 either way.
  void set_table(int ch, const std::vector<double>& points);
  void set_table_direction(int ch, int dir);
  int table_direction(int ch) const { return tdir_.at(static_cast<std::size_t>(ch)); }
  void set_output(int trg, const TriggerOutputConfig& cfg);
  const TriggerOutputConfig& output(int trg) const { return out_.at(static_cast<std::size_t>(trg)); }
  void set_enabled_mask(std::uint32_t mask) { enabled_ = mask & 0xFu; }  // TGR_TRG_EN
  std::uint32_t enabled_mask() const { return enabled_; }
  // APS_set_trigger_manual: a pulse now on `trg` if its sources include the manual one.
  void manual(int trg, double time_s, long long tick);

  // Remaining points (APS_get_trigger_linear_cmp: the next point), comparator done flags.
  double next_point(int comparator) const;
  std::size_t remaining(int comparator) const;
  long long count(int trg) const { return counts_.at(static_cast<std::size_t>(trg)); }
  void reset_count(int trg) { counts_.at(static_cast<std::size_t>(trg)) = 0; }
  bool active() const;
  // Comparators whose last point was passed in the last tick (bit c = comparator c): ILCF0/1, IFCF0/1.
  std::uint32_t finished_now() const { return finished_now_; }

  // One tick [t0, t0 + h): the source values at its start (prev) and end (now) per comparator.
  void tick(long long tick, double t0, double h, const std::array<double, 4>& prev, const std::array<double, 4>& now);
  // Per output during the last tick: pulses emitted, level at the tick's end (logic applied).
  int pulses(int trg) const { return pulses_.at(static_cast<std::size_t>(trg)); }
  bool level(int trg) const;
  const std::vector<TriggerEvent>& log() const { return log_; }
  void clear_log() { log_.clear(); }
  void reset();

 private:
  void emit(int comparator, double point, double time_s, long long tick);
  std::uint32_t source_bit(int comparator) const;

  std::array<CompareSource, 4> src_{};
  // linear
  std::array<double, 2> lstart_{}, linterval_{};
  std::array<std::size_t, 2> lcount_{}, lnext_{};
  // table
  std::array<std::vector<double>, 2> table_{};
  std::array<std::size_t, 2> tnext_{};
  std::array<int, 2> tdir_{{1, 1}};
  std::array<TriggerOutputConfig, kOutputs> out_{};
  std::uint32_t enabled_ = 0;
  std::array<long long, kOutputs> counts_{};
  std::array<int, kOutputs> pulses_{};
  std::array<int, kOutputs> pending_{};       // manual pulses since the last tick
  std::array<bool, kOutputs> toggled_{};      // toggle-format level (before logic)
  std::array<double, kOutputs> pulse_end_s_{{-1.0, -1.0, -1.0, -1.0}};
  double now_s_ = 0.0;
  std::uint32_t finished_now_ = 0;
  std::vector<TriggerEvent> log_;
};

}  // namespace servobench::machine
