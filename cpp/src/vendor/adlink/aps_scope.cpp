#include "servobench/vendor/adlink/aps_scope.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "servobench/machine/card_scope.hpp"

namespace servobench::vendor::adlink {

namespace {

constexpr double kI32Max = 2147483647.0;
constexpr double kWaitForeverS = 3600.0;  // Time_Out -1: at most one simulated hour (V83)
constexpr double kPwdUnitS = 100e-9;      // TGR_TRGx_PWD unit (L383; V77)
constexpr int kTcmp0Dir = 0x04, kTrgEn = 0x06, kTrg0Src = 0x10, kTrg0Pwd = 0x14, kTrg0Logic = 0x18, kTrg0Tgl = 0x1C;
constexpr int kTimrItv = 0x20, kTimrDir = 0x21, kTimrRing = 0x22, kTimrEn = 0x23;
constexpr int kSrcCommand = 0x10;         // a comparator source 0x10 + n: axis n's command position (V76)
constexpr int kSampComPos = 0x00, kSampFbkPos = 0x01, kSampControlVol = 0x20, kSampErrorPos = 0x23;

// Table 4-5 (L3558-3588, header values) and Table 4-6 (closed-loop PID_* counts, V79): code -> source.
struct Row {
  int code;
  ApsSampleSource src;
};
constexpr Row kSources[] = {
    {0x00, {"pos", 1, false, true, -1}},          {0x01, {"actual_pos", 1, false, true, -1}},
    {0x02, {"prf_vel", 1, true, true, -1}},       {0x03, {"fbk_vel", 1, true, true, -1}},
    {0x04, {"mio", 1, false, true, -1}},          {0x05, {"msts", 1, false, true, -1}},
    {0x06, {"msts", 1, false, true, 2}},          {0x07, {"msts", 1, false, true, 1}},   // ACC, MV
    {0x08, {"msts", 1, false, true, 3}},          {0x09, {"msts", 1, false, true, 0}},   // DEC, CSTP
    {0x0A, {"msts", 1, false, true, 5}},          {0x0B, {"mio", 1, false, true, 6}},    // MDN, INP
    {0x0D, {"mio", 1, false, true, 3}},                                                  // ORG
    {0x10, {"pos", 1, false, false, -1}},         {0x11, {"actual_pos", 1, false, false, -1}},
    {0x12, {"prf_vel", 1, true, false, -1}},      {0x13, {"fbk_vel", 1, true, false, -1}},
    {0x14, {"volts", 1000, false, false, -1}},    {0x15, {"error", 1, false, false, -1}},
    {0x20, {"volts", 1000, false, true, -1}},     {0x22, {"fb_pos", 1, false, true, -1}},
    {0x23, {"error", 1, false, true, -1}},
    {0x40, {"cmd_pos", 1, false, true, -1}},      {0x41, {"cmd_vel", 1, false, true, -1}},
    {0x42, {"cmd_acc", 1, false, true, -1}},      {0x43, {"error", 1, false, true, -1}},
    {0x44, {"p", 1, false, true, -1}},            {0x45, {"i", 1, false, true, -1}},
    {0x46, {"d", 1, false, true, -1}},            {0x47, {"vff", 1, false, true, -1}},
    {0x48, {"aff", 1, false, true, -1}},          {0x49, {"u", 1, false, true, -1}},
    {0x4A, {"biquad0", 1, false, true, -1}},      {0x4B, {"biquad1", 1, false, true, -1}},
    {0x4C, {"error_sum", 1, false, true, -1}},    {0x4D, {"error_prev", 1, false, true, -1}},
    {0x4E, {"error_diff", 1, false, true, -1}},
};

// An integer value of a register argument: finite and whole.
bool whole(double v) { return std::isfinite(v) && v == std::floor(v); }

std::int64_t reg32(std::int64_t v) {
  const std::int64_t m = std::int64_t{1} << 32;
  return ((v + (std::int64_t{1} << 31)) % m + m) % m - (std::int64_t{1} << 31);
}

}  // namespace

const ApsSampleSource* aps_sample_source(int src) {
  for (const Row& r : kSources)
    if (r.code == src) return &r.src;
  return nullptr;
}

ApsScope::ApsScope(machine::Card& card) : card_(card) { power_on(); }

int ApsScope::slot(double para) {
  if (!whole(para)) return -1;
  switch (static_cast<int>(para)) {
    case kSampRate: return 0;
    case kSampEdge: return 1;
    case kSampLevel: return 2;
    case kSampTrigCh: return 3;
    case kSampSrcCh0: return 4;
    case kSampSrcCh0 + 1: return 5;
    case kSampSrcCh0 + 2: return 6;
    case kSampSrcCh0 + 3: return 7;
    default: return -1;
  }
}

void ApsScope::power_on() {
  const int ticks_per_ms = std::max(1, static_cast<int>(std::lround(1e-3 / card_.servo_period_s())));
  samp_ = {ticks_per_ms, 2, 0, 0, kSampComPos, kSampFbkPos, kSampErrorPos, kSampControlVol};
  tgr_.fill(0);
  tgr_[kTcmp0Dir] = tgr_[kTcmp0Dir + 1] = 1;
  tgr_[0x01] = tgr_[0x03] = 1;  // TGR_LCMP1_SRC, TGR_TCMP1_SRC: axis 1
  for (int t = 0; t < 4; ++t) tgr_[kTrg0Pwd + t] = 1;
  tgr_[kTimrItv] = 1;
  timer_value_ = 0;
  timer_since_ = card_.tick();
  running_ = false;
  run_done_ = -1;
  buffer_.reset();
}

// -- data sampling --------------------------------------------------------------------------------------------
AdlinkCode ApsScope::set_sampling_param(double para, double value) {
  const int k = slot(para);
  if (k < 0 || !whole(value)) return AdlinkCode::ParametersInvalid;
  if (std::fabs(value) > kI32Max) return AdlinkCode::ParametersInvalid;
  const auto v = static_cast<std::int64_t>(value);
  bool ok = false;
  switch (k) {
    case 0: ok = v >= 1 && v <= 65535; break;
    case 1: ok = v >= 0 && v <= 2; break;
    case 2: ok = true; break;
    case 3: ok = v >= 0 && v <= 3; break;
    default: {  // a source: axis << 8 | source
      const std::int64_t axis = (v & 0xF00) >> 8;
      if (v < 0 || (v & ~std::int64_t{0xFFF}) || static_cast<std::size_t>(axis) >= card_.axis_count())
        return AdlinkCode::ParametersInvalid;
      if (aps_sample_source(static_cast<int>(v & 0xFF)) == nullptr) return AdlinkCode::FunctionNotAvailable;
      ok = true;
    }
  }
  if (!ok) return AdlinkCode::ParametersInvalid;
  samp_[static_cast<std::size_t>(k)] = static_cast<int>(v);
  return AdlinkCode::NoError;
}

AdlinkCode ApsScope::sampling_param(double para, int& value) const {
  const int k = slot(para);
  if (k < 0) return AdlinkCode::ParametersInvalid;
  value = samp_[static_cast<std::size_t>(k)];
  return AdlinkCode::NoError;
}

double ApsScope::factor(const ApsSampleSource& s) const {
  return s.per_second ? 1.0 / card_.servo_period_s() : s.scale;
}

AdlinkCode ApsScope::start_sampling(double length, double pretrigger, double timeout_ms) {
  if (!whole(length) || length < 1 || length > 1e6 || !whole(pretrigger) || pretrigger < 0 || pretrigger >= length)
    return AdlinkCode::ParametersInvalid;
  if (!whole(timeout_ms) || (timeout_ms < 0 && timeout_ms != -1)) return AdlinkCode::ParametersInvalid;
  const int edge = samp_[1];
  if (edge == 2 && pretrigger > 0) return AdlinkCode::ParametersInvalid;
  std::array<std::size_t, 4> axis{};
  std::array<const ApsSampleSource*, 4> src{};
  for (std::size_t k = 0; k < 4; ++k) {
    axis[k] = static_cast<std::size_t>((samp_[4 + k] & 0xF00) >> 8);
    src[k] = aps_sample_source(samp_[4 + k] & 0xFF);
  }
  const auto trig = static_cast<std::size_t>(samp_[3]);
  if (edge != 2 && src[trig]->bit >= 0) return AdlinkCode::FunctionNotAvailable;  // trigger on the word (V80)
  machine::SamplerConfig cfg;
  for (std::size_t k = 0; k < 4; ++k)
    cfg.channels.push_back({static_cast<int>(axis[k]), machine::sample_signal_from(src[k]->signal)});
  cfg.every_ticks = samp_[0];
  cfg.depth = length;
  cfg.trigger = edge == 0 ? machine::SampleTrigger::Rising
                          : edge == 1 ? machine::SampleTrigger::Falling : machine::SampleTrigger::Immediate;
  cfg.trigger_channel = static_cast<double>(trig);
  cfg.level = samp_[2] / factor(*src[trig]);
  cfg.pretrigger = pretrigger;
  cfg.event_bits = 1;  // unused without an event trigger; kept in its range
  try {
    card_.scope().start_sampler(cfg);
  } catch (const std::invalid_argument&) {
    return AdlinkCode::ParametersInvalid;
  }
  running_ = true;
  run_axis_ = axis;
  run_src_ = src;
  run_length_ = static_cast<std::size_t>(length);
  const double wait_s = timeout_ms == -1 ? kWaitForeverS : timeout_ms * 1e-3;
  run_until_ = card_.tick() + std::llround(wait_s / card_.servo_period_s());
  run_done_ = -1;
  buffer_ = std::make_shared<std::vector<ApsSample>>(run_length_, ApsSample{0, {0, 0, 0, 0}});
  return AdlinkCode::NoError;
}

bool ApsScope::sampling_block_ready() const { return card_.has_scope() && card_.scope().sampler().block_ready(); }

long long ApsScope::sampling_ticks_left() const { return running_ ? std::max(0LL, run_until_ - card_.tick()) : 0; }

int ApsScope::fill(const machine::SampleBlock& block) {
  const std::size_t m = std::min(block.ticks.size(), run_length_);
  std::vector<ApsSample>& out = *buffer_;
  for (std::size_t j = 0; j < m; ++j) {
    out[j].tick = block.ticks[j];
    for (std::size_t k = 0; k < 4; ++k) {
      const ApsSampleSource& s = *run_src_[k];
      double v = block.values[j * 4 + k] * factor(s);
      if (s.bit >= 0) v = static_cast<double>((static_cast<std::int64_t>(v) >> s.bit) & 1);
      out[j].data[k] = s.integer ? std::nearbyint(v) : v;
    }
  }
  return static_cast<int>(m);
}

AdlinkCode ApsScope::finish_sampling() {
  if (!running_) return AdlinkCode::FunctionNotAvailable;
  if (!sampling_block_ready()) {
    stop_sampling();
    return AdlinkCode::TimeOut;
  }
  fill(card_.scope().sampler().pop_block());
  return AdlinkCode::NoError;
}

int ApsScope::sampling_count() {
  if (!running_) return 0;
  if (sampling_block_ready()) run_done_ = fill(card_.scope().sampler().pop_block());
  if (run_done_ >= 0) return run_done_;
  if (card_.tick() >= run_until_) stop_sampling();
  if (!card_.has_scope() || card_.scope().sampler().state() != machine::SamplerState::Filling) return 0;
  return fill(card_.scope().sampler().snapshot());
}

void ApsScope::stop_sampling() {
  if (card_.has_scope()) card_.scope().sampler().stop();
}

// -- trigger and timer ----------------------------------------------------------------------------------------
AdlinkCode ApsScope::set_trigger_param(double para, double value) {
  if (!whole(para) || para < 0 || para >= static_cast<double>(tgr_.size()) || !whole(value) ||
      std::fabs(value) > 1e18)
    return AdlinkCode::ParametersInvalid;
  const int p = static_cast<int>(para);
  const auto v = static_cast<std::int64_t>(value);
  if (p >= kTimrItv) {
    const bool ok = p == kTimrItv ? (v >= 1 && v <= static_cast<std::int64_t>(kI32Max)) : (v == 0 || v == 1);
    if (!ok) return AdlinkCode::ParametersInvalid;
    timer_value_ = timer_counter();  // the count so far stays; the new setting counts from now
    timer_since_ = card_.tick();
    tgr_[static_cast<std::size_t>(p)] = v;
    return AdlinkCode::NoError;
  }
  const auto n_trg = static_cast<std::int64_t>(trigger_outputs());
  bool ok = false;
  if (p <= 0x03) {
    ok = v >= 0 && (v & ~std::int64_t{kSrcCommand}) < static_cast<std::int64_t>(card_.axis_count());
  } else if (p == kTcmp0Dir || p == kTcmp0Dir + 1) {
    ok = v >= 0 && v <= 2;
  } else if (p == kTrgEn) {
    ok = v >= 0 && v < (std::int64_t{1} << n_trg);
  } else if (p >= kTrg0Src) {
    const int t = (p - kTrg0Src) % 4, kind = (p - kTrg0Src) / 4;
    ok = t < n_trg && (kind == 0 ? (v >= 0 && v <= 31) : kind == 1 ? (v >= 1 && v <= 10000000) : (v == 0 || v == 1));
  }
  if (!ok) return AdlinkCode::ParametersInvalid;
  const std::int64_t old = tgr_[static_cast<std::size_t>(p)];
  tgr_[static_cast<std::size_t>(p)] = v;
  try {
    apply_trigger();
  } catch (const std::invalid_argument&) {
    tgr_[static_cast<std::size_t>(p)] = old;
    return AdlinkCode::ParametersInvalid;
  }
  return AdlinkCode::NoError;
}

AdlinkCode ApsScope::trigger_param(double para, int& value) const {
  if (!whole(para) || para < 0 || para >= static_cast<double>(tgr_.size())) return AdlinkCode::ParametersInvalid;
  value = static_cast<int>(tgr_[static_cast<std::size_t>(para)]);
  return AdlinkCode::NoError;
}

void ApsScope::apply_trigger() {
  machine::PositionCompare& cmp = card_.scope().compare();
  for (int comp = 0; comp < 4; ++comp) {
    const std::int64_t v = tgr_[static_cast<std::size_t>(comp)];
    machine::CompareSource s;
    s.axis = static_cast<int>(v & 0xF);
    s.command = (v & kSrcCommand) != 0;
    cmp.set_source(comp, s, card_.axis_count());
  }
  for (int ch = 0; ch < 2; ++ch) {
    const std::int64_t d = tgr_[static_cast<std::size_t>(kTcmp0Dir + ch)];
    cmp.set_table_direction(ch, d == 0 ? -1 : d == 1 ? 1 : 0);
  }
  for (int t = 0; t < 4; ++t) {
    machine::TriggerOutputConfig o;
    o.sources = static_cast<std::uint32_t>(tgr_[static_cast<std::size_t>(kTrg0Src + t)]);
    o.pulse_width_s = static_cast<double>(tgr_[static_cast<std::size_t>(kTrg0Pwd + t)]) * kPwdUnitS;
    o.active_low = tgr_[static_cast<std::size_t>(kTrg0Logic + t)] != 0;
    o.toggle = tgr_[static_cast<std::size_t>(kTrg0Tgl + t)] != 0;
    cmp.set_output(t, o);
  }
  cmp.set_enabled_mask(static_cast<std::uint32_t>(tgr_[kTrgEn]));
}

std::int64_t ApsScope::timer_counter() const {
  if (tgr_[kTimrEn] == 0) return timer_value_;
  const std::int64_t n = (card_.tick() - timer_since_) / std::max<std::int64_t>(1, tgr_[kTimrItv]);
  const std::int64_t v = timer_value_ + (tgr_[kTimrDir] != 0 ? -n : n);
  if (tgr_[kTimrRing] != 0) return reg32(v);
  return std::clamp<std::int64_t>(v, -(std::int64_t{1} << 31), (std::int64_t{1} << 31) - 1);
}

AdlinkCode ApsScope::set_timer_counter(double value) {
  if (!whole(value) || value < -2147483648.0 || value > kI32Max) return AdlinkCode::ParametersInvalid;
  timer_value_ = static_cast<std::int64_t>(value);
  timer_since_ = card_.tick();
  return AdlinkCode::NoError;
}

ApsScope& aps_scope(machine::Card& card) { return card.module<ApsScope>(); }

}  // namespace servobench::vendor::adlink
