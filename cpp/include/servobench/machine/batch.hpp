// Many independent axes at once: N plants, one command, run in C++ across threads.
//
// Each plant i is the base AxisConfig with the parameter overrides of row i applied (a parameter table: column j
// names a field such as "plant.inertia_kgm2", row i holds its value for plant i), built, validated and run from
// power-on over the same command. Plants share nothing, so each plant's result is the same whatever the thread
// count or the split into chunks (deterministic: plant i's encoder noise comes from its own encoder seed).
// Threads take fixed, contiguous blocks of plants; the caller owns every output buffer.
//
// Move metrics per plant are those of servobench.move_metrics (python/servobench/metrics.py), computed here
// from the command and the feedback with the same arithmetic:
//   progress = (fb - cmd[0]) / (cmd[n-1] - cmd[0]); rise time = t(first progress >= 0.9) - t(first >= 0.1);
//   overshoot = max(0, max((fb - target) * sign(distance))); settling time from the end of the command until
//   |fb - target| stays <= band (NaN if it never does); peak |cmd - fb|; final cmd - fb; t = k * Ts.
#pragma once

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "servobench/machine/axis.hpp"

namespace servobench::machine {

// A settable numeric field of an AxisConfig, addressed as "part.field" (part: law, drive, plant, encoder, dac).
// Throws std::invalid_argument naming the parameter when it does not exist on the base configuration's parts
// (e.g. "plant.k_nm_per_rad" on a rigid plant).
void set_axis_parameter(AxisConfig& config, const std::string& name, double value);
// The names set_axis_parameter accepts for this configuration (its law, drive and plant types).
std::vector<std::string> axis_parameter_names(const AxisConfig& config);

struct MoveMetricsRow {
  double rise_time_s, overshoot_pulse, overshoot_pct, settling_time_s, peak_following_error_pulse,
      final_error_pulse;
};
inline constexpr std::size_t kMoveMetricsCount = 6;

// The move metrics of one run (see the header comment); distance = cmd[n-1] - cmd[0] must be non-zero, n >= 2.
MoveMetricsRow move_metrics(const double* cmd, const double* fb, std::size_t n, double servo_period_s,
                            double settle_band_pulse);

struct BatchInput {
  AxisConfig base;
  std::vector<std::string> parameter_names;  // columns of the parameter table
  const double* parameters = nullptr;        // row-major, plants x parameter_names.size()
  std::size_t plants = 0;
  const double* pos = nullptr;  // the command, pulse, n ticks (vel/acc: optional, as in CommandInput)
  const double* vel = nullptr;
  const double* acc = nullptr;
  std::size_t n = 0;
};

struct BatchOutput {
  // Per signal: nullptr or a row-major plants x n buffer (Trace's signal list).
  Trace signals;
  MoveMetricsRow* metrics = nullptr;  // plants rows, or nullptr
  double settle_band_pulse = 5.0;     // pulse, > 0
};

struct BatchOptions {
  int threads = 0;  // worker threads, 0 = every hardware thread; never more than the plants
  // Called from the calling thread about every poll_seconds while the workers run, and once at the end, with the
  // plants finished so far and the total; returning false stops the batch (plants not started are not run) and
  // run_batch throws BatchStopped. Empty: no calls.
  std::function<bool(std::size_t done, std::size_t total)> poll;
  double poll_seconds = 0.05;
};

// What run_batch throws when options.poll asked it to stop.
struct BatchStopped : std::runtime_error {
  BatchStopped() : std::runtime_error("run_batch: stopped by its poll callback") {}
};

// Runs the batch; returns the threads used. Workers take the plants in small blocks from a shared counter, so a
// busy core slows the batch by its share only. A plant whose parameters are invalid makes the whole call throw
// std::invalid_argument naming the first such row (lowest index, so the message too is thread-count independent)
// and the parameter.
int run_batch(const BatchInput& input, const BatchOutput& output, const BatchOptions& options = {});

}  // namespace servobench::machine
