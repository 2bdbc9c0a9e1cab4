#include "servobench/machine/sampler.hpp"

#include <cmath>
#include <stdexcept>

#include "servobench/common/validate.hpp"

namespace servobench::machine {

namespace {
const SampleSignalInfo kInfo[] = {
#define SERVOBENCH_INFO(name, unit, doc) {#name, unit, doc},
    SERVOBENCH_SAMPLE_SIGNALS(SERVOBENCH_INFO)
#undef SERVOBENCH_INFO
};
static_assert(sizeof(kInfo) / sizeof(kInfo[0]) == static_cast<std::size_t>(kSampleSignalCount));
}  // namespace

const SampleSignalInfo& sample_signal_info(SampleSignal s) {
  const int k = static_cast<int>(s);
  if (k < 0 || k >= kSampleSignalCount) throw std::invalid_argument("sample signal: not a signal");
  return kInfo[k];
}

SampleSignal sample_signal_from(const std::string& name) {
  for (int k = 0; k < kSampleSignalCount; ++k)
    if (name == kInfo[k].name) return static_cast<SampleSignal>(k);
  std::string list;
  for (int k = 0; k < kSampleSignalCount; ++k) list += (k ? ", " : "") + std::string(kInfo[k].name);
  throw std::invalid_argument("Sampler.signal: unknown signal '" + name + "'; the signals are: " + list);
}

void SamplerConfig::validate(std::size_t axes) const {
  check_integer("Sampler", "channels", static_cast<double>(channels.size()), 1, 16);
  for (const SampleChannel& c : channels) {
    const bool trg = c.signal == SampleSignal::card_trg_pulses || c.signal == SampleSignal::card_trg_level;
    check_integer("Sampler", trg ? "channel (trigger output)" : "axis", static_cast<double>(c.axis), 0,
                  trg ? 3.0 : static_cast<double>(axes) - 1);
    sample_signal_info(c.signal);
  }
  check_integer("Sampler", "every_ticks", every_ticks, 1, 1e6);
  check_integer("Sampler", "depth", depth, 1, 1e7);
  if (depth * static_cast<double>(channels.size()) > 1e8)
    throw_invalid("Sampler", "depth", depth, "times the channel count must be at most 1e8 values");
  check_integer("Sampler", "pretrigger", pretrigger, 0, depth - 1);
  switch (trigger) {
    case SampleTrigger::Immediate: break;
    case SampleTrigger::Rising:
    case SampleTrigger::Falling:
      check_integer("Sampler", "trigger_channel", trigger_channel, 0, static_cast<double>(channels.size()) - 1);
      if (!std::isfinite(level)) throw_invalid("Sampler", "level", level, "must be finite");
      break;
    case SampleTrigger::Event:
      check_integer("Sampler", "event_axis", event_axis, 0, static_cast<double>(axes) - 1);
      check_integer("Sampler", "event_bits", event_bits, 1, 4095, "CardEvent bits");
      break;
    default: throw std::invalid_argument("Sampler.trigger: not a trigger mode");
  }
  if (trigger == SampleTrigger::Immediate && pretrigger != 0)
    throw_invalid("Sampler", "pretrigger", pretrigger, "must be 0 with the immediate trigger");
}

void Sampler::start(const SamplerConfig& config, std::size_t axes, long long tick) {
  config.validate(axes);
  cfg_ = config;
  need_.assign(axes, std::vector<bool>(kSampleSignalCount, false));
  for (const SampleChannel& c : cfg_.channels) {
    if (c.signal == SampleSignal::card_trg_pulses || c.signal == SampleSignal::card_trg_level) continue;
    need_[static_cast<std::size_t>(c.axis)][static_cast<std::size_t>(c.signal)] = true;
  }
  start_tick_ = tick;
  every_ = static_cast<long long>(cfg_.every_ticks);
  depth_ = static_cast<std::size_t>(cfg_.depth);
  nch_ = cfg_.channels.size();
  pre_ = static_cast<std::size_t>(cfg_.pretrigger);
  event_mask_ = cfg_.trigger == SampleTrigger::Event ? static_cast<std::uint32_t>(cfg_.event_bits) : 0u;
  event_seen_ = false;
  have_prev_ = false;
  ring_ticks_.clear();
  ring_values_.clear();
  cur_ = SampleBlock{};
  filled_ = 0;
  trigger_tick_ = -1;
  blocks_.clear();
  dropped_ = 0;
  if (cfg_.trigger == SampleTrigger::Immediate) {
    state_ = SamplerState::Filling;
    cur_.ticks.reserve(depth_);
    cur_.values.reserve(depth_ * nch_);
  } else {
    state_ = SamplerState::Armed;
  }
}

void Sampler::stop() {
  if (active()) state_ = SamplerState::Idle;
}

bool Sampler::needs(std::size_t axis, SampleSignal s) const {
  return active() && axis < need_.size() && need_[axis][static_cast<std::size_t>(s)];
}

void Sampler::push(long long tick, const std::vector<double>& values) {
  cur_.ticks.push_back(tick);
  cur_.values.insert(cur_.values.end(), values.begin(), values.end());
  ++filled_;
  if (filled_ == depth_) finish_block();
}

void Sampler::finish_block() {
  if (blocks_.size() == kMaxBlocks) {
    blocks_.pop_front();
    ++dropped_;
  }
  blocks_.push_back(std::move(cur_));
  cur_ = SampleBlock{};
  filled_ = 0;
  if (cfg_.continuous) {
    cur_.ticks.reserve(depth_);
    cur_.values.reserve(depth_ * nch_);
  } else {
    state_ = SamplerState::Done;
  }
}

void Sampler::take(long long tick, const std::vector<double>& values) {
  if (state_ == SamplerState::Filling) {
    push(tick, values);
    return;
  }
  if (state_ != SamplerState::Armed) return;
  bool fire = false;
  if (cfg_.trigger == SampleTrigger::Event) {
    fire = event_seen_;
  } else {
    const double v = values[static_cast<std::size_t>(cfg_.trigger_channel)];
    if (have_prev_) {
      fire = cfg_.trigger == SampleTrigger::Rising ? (prev_trigger_value_ < cfg_.level && v >= cfg_.level)
                                                   : (prev_trigger_value_ > cfg_.level && v <= cfg_.level);
    }
    prev_trigger_value_ = v;
    have_prev_ = true;
  }
  event_seen_ = false;
  // The trigger counts once the pre-trigger part is full (an oscilloscope's "armed", V72).
  if (fire && ring_ticks_.size() == pre_) {
    state_ = SamplerState::Filling;
    trigger_tick_ = tick;
    cur_.trigger_tick = tick;
    cur_.ticks.reserve(depth_);
    cur_.values.reserve(depth_ * nch_);
    for (std::size_t j = 0; j < ring_ticks_.size(); ++j) {
      cur_.ticks.push_back(ring_ticks_[j]);
      cur_.values.insert(cur_.values.end(), ring_values_[j].begin(), ring_values_[j].end());
      ++filled_;
    }
    ring_ticks_.clear();
    ring_values_.clear();
    push(tick, values);
    return;
  }
  if (pre_ > 0) {
    if (ring_ticks_.size() == pre_) {
      ring_ticks_.pop_front();
      ring_values_.pop_front();
    }
    ring_ticks_.push_back(tick);
    ring_values_.push_back(values);
  }
}

SampleBlock Sampler::pop_block() {
  if (blocks_.empty()) return SampleBlock{};
  SampleBlock b = std::move(blocks_.front());
  blocks_.pop_front();
  return b;
}

SampleBlock Sampler::snapshot() const {
  SampleBlock b;
  if (state_ == SamplerState::Armed) {
    for (std::size_t j = 0; j < ring_ticks_.size(); ++j) {
      b.ticks.push_back(ring_ticks_[j]);
      b.values.insert(b.values.end(), ring_values_[j].begin(), ring_values_[j].end());
    }
    return b;
  }
  return cur_;
}

}  // namespace servobench::machine
