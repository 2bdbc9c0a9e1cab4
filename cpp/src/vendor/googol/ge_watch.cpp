#include "servobench/vendor/googol/ge_watch.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "servobench/machine/card_scope.hpp"
#include "servobench/machine/sampler.hpp"
#include "servobench/vendor/googol/ge_registers.hpp"
#include "servobench/vendor/scope_words.hpp"

namespace servobench::vendor::googol {

namespace {

bool int_in(double v, double lo, double hi) { return std::isfinite(v) && lo <= v && v <= hi && v == std::floor(v); }

// Table 10-2's bit -> the sampler signal (the Axis trace's names).
machine::SampleSignal signal_of(int bit) {
  switch (bit) {
    case 0: return machine::sample_signal_from("pos");
    case 1: return machine::sample_signal_from("actual_pos");
    case 2: return machine::sample_signal_from("prf_vel");
    case 3: return machine::sample_signal_from("fbk_vel");
    default: return machine::sample_signal_from("volts");
  }
}

// A sample in the GE's unit: pulse (whole), pulse/tick -> pulse/ms, V -> DAC counts (short).
double ge_unit(int bit, double v, double ms_per_tick) {
  if (bit == 2 || bit == 3) return v / ms_per_tick;
  if (bit == 6) return std::clamp(std::nearbyint(v * 32767 / 10), -32768.0, 32767.0);
  return std::nearbyint(v);
}

}  // namespace

GeCode GeWatch::set_watch(const std::vector<double>& config, double size) {
  if (config.size() > card_.axis_count()) return GeCode::ParameterError;
  std::vector<std::pair<std::size_t, int>> channels;
  for (std::size_t k = 0; k < config.size(); ++k) {
    if (!int_in(config[k], 0, 0xFFFF)) return GeCode::ParameterError;
    const auto w = static_cast<std::uint32_t>(config[k]);
    if (w & 0xB0u) return GeCode::ParameterError;  // bits 4, 5, 7 reserved (Table 10-2)
    for (int bit : {0, 1, 2, 3, 6})
      if (w >> bit & 1u) channels.emplace_back(k, bit);
  }
  if (!int_in(size, 1, kWatchMemoryValues) || channels.empty() ||
      size * static_cast<double>(channels.size()) > kWatchMemoryValues)
    return GeCode::ParameterError;
  channels_ = std::move(channels);
  size_ = static_cast<int>(size);
  return GeCode::Success;
}

GeCode GeWatch::start(double n) {
  if (channels_.empty()) return GeCode::CommandError;
  if (!int_in(n, 0, 65535)) return GeCode::ParameterError;
  machine::SamplerConfig cfg;
  for (const auto& [axis, bit] : channels_) cfg.channels.push_back({static_cast<int>(axis), signal_of(bit)});
  cfg.every_ticks = n + 1;
  cfg.depth = size_;
  cfg.continuous = true;
  machine::CardScope& scope = card_.scope();
  if (!scope.words().msts) scope.set_words(vendor::scope_words());  // as every scope the bindings hand out
  try {
    scope.start_sampler(cfg);
  } catch (const std::invalid_argument&) {
    return GeCode::ParameterError;
  }
  return GeCode::Success;
}

GeCode GeWatch::next_block(std::vector<std::vector<double>>& block) {
  block.clear();
  if (channels_.empty()) return GeCode::CommandError;
  if (!card_.has_scope() || !card_.scope().sampler().block_ready()) return GeCode::Success;
  const machine::SampleBlock b = card_.scope().sampler().pop_block();
  const std::size_t nch = channels_.size();
  const std::size_t samples = std::min<std::size_t>(b.ticks.size(), static_cast<std::size_t>(size_));
  const double ms = card_.servo_period_s() * 1e3;
  block.assign(nch, std::vector<double>(samples));
  for (std::size_t j = 0; j < samples; ++j)
    for (std::size_t c = 0; c < nch; ++c) block[c][j] = ge_unit(channels_[c].second, b.values[j * nch + c], ms);
  return GeCode::Success;
}

void GeWatch::stop() {
  if (!card_.has_scope()) return;
  machine::Sampler& s = card_.scope().sampler();
  s.stop();
  while (s.block_ready()) s.pop_block();
}

GeWatch& ge_watch(machine::Card& card) { return ge_registers(card).watch(); }

}  // namespace servobench::vendor::googol
