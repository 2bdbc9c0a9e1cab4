#include "servobench/machine/card_scope.hpp"

#include <algorithm>
#include <cmath>

#include "servobench/common/validate.hpp"
#include "servobench/machine/card.hpp"
#include "servobench/machine/card_hooks.hpp"

namespace servobench::machine {

CardScope::CardScope(Card& card) : card_(card), n_(card.axis_count()) {
  scratch_.assign(n_, {});
  ptr_.assign(n_, {});
  any_need_.assign(n_, false);
  prev_actual_.assign(n_, 0.0);
  prev_command_.assign(n_, 0.0);
  prev_error_.assign(n_, 0.0);
  prev_events_.assign(n_, 0u);
  prev_msts_.assign(n_, 0u);
  prev_mio_.assign(n_, 0u);
  w_events_.assign(n_, 0u);
  w_msts_.assign(n_, 0u);
  w_mio_.assign(n_, 0u);
  v_events_.assign(n_, 0u);
  v_msts_.assign(n_, 0u);
  v_mio_.assign(n_, 0u);
  for (std::size_t i = 0; i < n_; ++i) {
    prev_events_[i] = card_.events(i);
    prev_msts_[i] = word(words_.msts, i);
    prev_mio_[i] = word(words_.mio, i);
  }
  prev_estop_ = card_.emergency_stop();
  resync();
}

void CardScope::set_words(const ScopeWords& words) {
  words_ = words;
  for (std::size_t i = 0; i < n_; ++i) {
    prev_msts_[i] = word(words_.msts, i);
    prev_mio_[i] = word(words_.mio, i);
  }
}

void CardScope::resync() {
  fired_.clear();
  stop_ = false;
  for (std::size_t i = 0; i < n_; ++i) {
    prev_actual_[i] = card_.actual_pos(i);
    prev_command_[i] = static_cast<double>(card_.profile_pos(i));
    // Bits the host cleared between runs count as off (their next latch fires); bits it set are not taken as
    // seen, so an input the host switched on (alarm, e-stop) fires at the next tick.
    prev_events_[i] &= card_.events(i);
    if (w_msts_[i] | v_msts_[i]) prev_msts_[i] &= word(words_.msts, i);
    if (w_mio_[i] | v_mio_[i]) prev_mio_[i] &= word(words_.mio, i);
  }
  prev_estop_ = prev_estop_ && card_.emergency_stop();
}

void CardScope::start_sampler(const SamplerConfig& config) {
  sampler_.start(config, n_, card_.tick());
  refresh_need();
  for (std::size_t i = 0; i < n_; ++i) prev_error_[i] = card_.following_error(i);
}

void CardScope::refresh_need() {
  for (std::size_t i = 0; i < n_; ++i) {
    bool any = false;
    for (int s = 0; s < kLoopSignalEnd; ++s) any = any || sampler_.needs(i, static_cast<SampleSignal>(s));
    any_need_[i] = any;
  }
}

void CardScope::set_watch(std::size_t axis, std::uint32_t events, std::uint32_t msts, std::uint32_t mio) {
  if (axis >= n_) throw_invalid("CardScope", "axis", static_cast<double>(axis), "is not an axis of this card");
  w_events_[axis] = events & kAllEvents;
  w_msts_[axis] = msts;
  w_mio_[axis] = mio;
  prev_events_[axis] = card_.events(axis);
  prev_msts_[axis] = word(words_.msts, axis);
  prev_mio_[axis] = word(words_.mio, axis);
  fired_.clear();
}

void CardScope::set_timer(double ticks) {
  check_integer("CardScope", "timer_ticks", ticks, 0, 1e9);
  timer_period_ = static_cast<long long>(ticks);
  timer_start_ = card_.tick();
}

void CardScope::set_vendor_watch(CardHooks& owner, const EventWatch& w) {
  if (w.events.size() > n_ || w.msts.size() > n_ || w.mio.size() > n_)
    throw_invalid("CardScope", "vendor watch axes", static_cast<double>(std::max({w.events.size(), w.msts.size(),
                                                                                    w.mio.size()})),
                  "must be at most the card's axes");
  check_integer("CardScope", "vendor timer_ticks", static_cast<double>(w.timer_ticks), 0, 1e9);
  clear_vendor_watch(owner);
  vendor_.push_back(VendorWatch{&owner, w, card_.tick()});
  refresh_vendor();
}

void CardScope::clear_vendor_watch(const CardHooks& owner) {
  for (std::size_t k = 0; k < vendor_.size(); ++k)
    if (vendor_[k].owner == &owner) {
      vendor_.erase(vendor_.begin() + static_cast<std::ptrdiff_t>(k));
      break;
    }
  refresh_vendor();
}

void CardScope::refresh_vendor() {
  const auto at = [](const std::vector<std::uint32_t>& v, std::size_t i) { return i < v.size() ? v[i] : 0u; };
  v_sys_ = 0;
  for (std::size_t i = 0; i < n_; ++i) {
    v_events_[i] = v_msts_[i] = v_mio_[i] = 0;
    for (const VendorWatch& v : vendor_) {
      v_events_[i] |= at(v.watch.events, i) & kAllEvents;
      v_msts_[i] |= at(v.watch.msts, i);
      v_mio_[i] |= at(v.watch.mio, i);
    }
    prev_events_[i] = card_.events(i);  // as set_watch: the words now are the reference
    prev_msts_[i] = word(words_.msts, i);
    prev_mio_[i] = word(words_.mio, i);
  }
  for (const VendorWatch& v : vendor_) v_sys_ |= v.watch.system & 0x1Fu;
}

void CardScope::dispatch_vendor(long long tick) {
  bool due = !vendor_fired_.empty();
  for (const VendorWatch& v : vendor_)
    due = due || (v.watch.timer_ticks > 0 && (tick + 1 - v.timer_start) % v.watch.timer_ticks == 0);
  if (!due) return;
  const std::vector<VendorWatch> watches = vendor_;  // on_watch may change the watches
  const std::vector<FiredEvent> events = std::move(vendor_fired_);
  vendor_fired_.clear();
  const auto at = [](const std::vector<std::uint32_t>& v, int i) {
    return i >= 0 && static_cast<std::size_t>(i) < v.size() ? v[static_cast<std::size_t>(i)] : 0u;
  };
  for (const VendorWatch& v : watches) {
    for (const FiredEvent& e : events) {
      const std::uint32_t mask = e.word == WatchWord::Events ? at(v.watch.events, e.axis)
                                 : e.word == WatchWord::Msts ? at(v.watch.msts, e.axis)
                                 : e.word == WatchWord::Mio  ? at(v.watch.mio, e.axis)
                                                             : v.watch.system;
      if (const std::uint32_t bits = e.bits & mask) v.owner->on_watch(FiredEvent{e.tick, e.axis, e.word, bits});
    }
    if (v.watch.timer_ticks > 0 && (tick + 1 - v.timer_start) % v.watch.timer_ticks == 0)
      v.owner->on_watch(FiredEvent{tick, -1, WatchWord::Timer, 1u});
  }
}

bool CardScope::watching() const {
  if (sys_mask_ || timer_period_) return true;
  for (std::size_t i = 0; i < n_; ++i)
    if (w_events_[i] | w_msts_[i] | w_mio_[i]) return true;
  return false;
}

void CardScope::set_probe_position(std::size_t axis, double pos) {
  check_integer("CardScope", "probe axis", static_cast<double>(axis), 0, static_cast<double>(n_) - 1);
  if (!std::isfinite(pos)) throw_invalid("CardScope", "probe position", pos, "must be finite (pulse)");
  probe_axis_ = static_cast<int>(axis);
  probe_pos_ = pos;
}

void CardScope::bind_signals(std::size_t i, Trace& tr, LoopTrace& lt) {
  int idx = 0;
#define SERVOBENCH_BIND(name, unit, doc)                                   \
  if (sampler_.needs(i, static_cast<SampleSignal>(idx))) {                 \
    if (!tr.name) tr.name = &scratch_[i][static_cast<std::size_t>(idx)];   \
    ptr_[i][static_cast<std::size_t>(idx)] = tr.name;                      \
  }                                                                        \
  ++idx;
  SERVOBENCH_TRACE_SIGNALS(SERVOBENCH_BIND)
#undef SERVOBENCH_BIND
#define SERVOBENCH_BIND(name, unit, doc)                                   \
  if (sampler_.needs(i, static_cast<SampleSignal>(idx))) {                 \
    if (!lt.name) lt.name = &scratch_[i][static_cast<std::size_t>(idx)];   \
    ptr_[i][static_cast<std::size_t>(idx)] = lt.name;                      \
  }                                                                        \
  ++idx;
  SERVOBENCH_LOOP_SIGNALS(SERVOBENCH_BIND)
#undef SERVOBENCH_BIND
}

std::uint32_t CardScope::probe(long long /*tick*/) {
  if (probe_axis_ < 0) return 0;
  const auto k = static_cast<std::size_t>(probe_axis_);
  const double a = prev_actual_[k], b = card_.actual_pos(k), p = probe_pos_;
  if (!((a < p && b >= p) || (a > p && b <= p))) return 0;
  const double f = (p - a) / (b - a);
  std::uint32_t latched = 0;
  for (std::size_t i = 0; i < n_; ++i) {
    CaptureUnit& cap = card_.loop(i).capture();
    if (cap.armed() != CaptureTrigger::Probe) continue;
    const double pos = i == k ? p : prev_actual_[i] + f * (card_.actual_pos(i) - prev_actual_[i]);
    if (cap.update(motion::SignalEvent{}, motion::SignalEvent{}, true, pos)) latched |= 1u << i;
  }
  return latched;
}

double CardScope::value(std::size_t i, SampleSignal s) const {
  const int k = static_cast<int>(s);
  // The card points the trace's error at a local of its tick; the same value is kept as the following error.
  if (s == SampleSignal::error) return card_.following_error(i);
  if (k < kLoopSignalEnd) return *ptr_[i][static_cast<std::size_t>(k)];
  switch (s) {
    case SampleSignal::card_events: return static_cast<double>(card_.events(i));
    case SampleSignal::card_moving: return card_.moving(i) ? 1.0 : 0.0;
    case SampleSignal::card_servo_on: return card_.servo_on(i) ? 1.0 : 0.0;
    case SampleSignal::card_prf_vel: return card_.profile_vel(i);
    case SampleSignal::card_prf_acc: return card_.loop(i).generator().state().acc;
    case SampleSignal::card_fbk_vel: return card_.actual_pos(i) - prev_actual_[i];
    case SampleSignal::card_msts: return static_cast<double>(word(words_.msts, i));
    case SampleSignal::card_mio: return static_cast<double>(word(words_.mio, i));
    case SampleSignal::card_gt_status: return static_cast<double>(word(words_.status, i));
    case SampleSignal::card_error_sum: return card_.axis(i).law_error_sum();
    case SampleSignal::card_error_prev: return prev_error_[i];
    case SampleSignal::card_error_diff: return card_.following_error(i) - prev_error_[i];
    case SampleSignal::card_trg_pulses: return static_cast<double>(compare_.pulses(static_cast<int>(i)));
    case SampleSignal::card_trg_level: return compare_.level(static_cast<int>(i)) ? 1.0 : 0.0;
    default: return 0.0;
  }
}

void CardScope::after_tick(long long tick) {
  const double h = card_.servo_period_s();
  // position compare on the sources' positions at the tick's ends
  std::array<double, 4> prev{}, now{};
  for (int c = 0; c < 4; ++c) {
    const CompareSource& src = compare_.source(c);
    const auto a = static_cast<std::size_t>(src.axis);
    if (a >= n_) continue;
    prev[static_cast<std::size_t>(c)] = src.command ? prev_command_[a] : prev_actual_[a];
    now[static_cast<std::size_t>(c)] = src.command ? static_cast<double>(card_.profile_pos(a)) : card_.actual_pos(a);
  }
  compare_.tick(tick, static_cast<double>(tick) * h, h, prev, now);
  // event watch
  for (std::size_t i = 0; i < n_; ++i) {
    const std::uint32_t ev = card_.events(i);
    const auto ax = static_cast<int>(i);
    if (const std::uint32_t r = ev & ~prev_events_[i] & w_events_[i])
      fired_.push_back(FiredEvent{tick, ax, WatchWord::Events, r});
    if (const std::uint32_t r = ev & ~prev_events_[i] & v_events_[i])
      vendor_fired_.push_back(FiredEvent{tick, ax, WatchWord::Events, r});
    if (sampler_.state() == SamplerState::Armed &&
        static_cast<std::size_t>(sampler_.config().event_axis) == i)
      sampler_.note_events(ev & ~prev_events_[i]);
    prev_events_[i] = ev;
    if (w_msts_[i] | v_msts_[i]) {
      const std::uint32_t w = word(words_.msts, i);
      if (const std::uint32_t r = w & ~prev_msts_[i] & w_msts_[i])
        fired_.push_back(FiredEvent{tick, ax, WatchWord::Msts, r});
      if (const std::uint32_t r = w & ~prev_msts_[i] & v_msts_[i])
        vendor_fired_.push_back(FiredEvent{tick, ax, WatchWord::Msts, r});
      prev_msts_[i] = w;
    }
    if (w_mio_[i] | v_mio_[i]) {
      const std::uint32_t w = word(words_.mio, i);
      // EZ (bit 5) reads 0 in the word (V44); as an event it is the index mark passing during this tick.
      const std::uint32_t ez = card_.loop(i).inputs().ez.rose ? (1u << 5) : 0u;
      if (const std::uint32_t r = ((w & ~prev_mio_[i]) | ez) & w_mio_[i])
        fired_.push_back(FiredEvent{tick, ax, WatchWord::Mio, r});
      if (const std::uint32_t r = ((w & ~prev_mio_[i]) | ez) & v_mio_[i])
        vendor_fired_.push_back(FiredEvent{tick, ax, WatchWord::Mio, r});
      prev_mio_[i] = w;
    }
  }
  const bool estop = card_.emergency_stop();
  std::uint32_t sys = (estop && !prev_estop_) ? kSysEmg : 0u;
  prev_estop_ = estop;
  const std::uint32_t fin = compare_.finished_now();
  if (fin & 1u) sys |= kSysLcf0;
  if (fin & 2u) sys |= kSysLcf1;
  if (fin & 4u) sys |= kSysFcf0;
  if (fin & 8u) sys |= kSysFcf1;
  if (sys & sys_mask_) fired_.push_back(FiredEvent{tick, -1, WatchWord::System, sys & sys_mask_});
  if (sys & v_sys_) vendor_fired_.push_back(FiredEvent{tick, -1, WatchWord::System, sys & v_sys_});
  if (timer_period_ > 0 && (tick + 1 - timer_start_) % timer_period_ == 0)
    fired_.push_back(FiredEvent{tick, -1, WatchWord::Timer, 1u});
  // sampler
  if (sampler_.sample_due(tick)) {
    const auto& ch = sampler_.config().channels;
    values_.resize(ch.size());
    for (std::size_t c = 0; c < ch.size(); ++c) values_[c] = value(static_cast<std::size_t>(ch[c].axis), ch[c].signal);
    sampler_.take(tick, values_);
    if (!sampler_.active()) refresh_need();
  }
  for (std::size_t i = 0; i < n_; ++i) {
    prev_actual_[i] = card_.actual_pos(i);
    prev_command_[i] = static_cast<double>(card_.profile_pos(i));
    prev_error_[i] = card_.following_error(i);
  }
  if (!vendor_.empty()) dispatch_vendor(tick);
}

void CardScope::reset_registers() {
  sampler_ = Sampler{};
  compare_.reset();
  clear_probe_position();
  clear_fired();
  refresh_need();
  resync();
}

}  // namespace servobench::machine
