#include "servobench/vendor/adlink/aps_interrupts.hpp"

#include <cmath>

#include "servobench/vendor/adlink/aps_status.hpp"
#include "servobench/vendor/scope_words.hpp"

namespace servobench::vendor::adlink {

namespace {

constexpr int kSystemItem = 8, kIhov = 6, kIpred = 18, kIpostd = 19;
constexpr double kWaitForeverS = 3600.0;  // Time_Out -1 (V83)

// Axis factor bit -> (word: 0 MSTS, 1 MIO; bit of that word), -1 when the bit is not an axis factor.
struct Watch {
  int word;
  int bit;
};
Watch axis_watch(int factor) {
  const int mio = 1, msts = 0;
  switch (factor) {
    case 0: return {mio, static_cast<int>(ApsMio::ALM)};
    case 1: return {mio, static_cast<int>(ApsMio::PEL)};
    case 2: return {mio, static_cast<int>(ApsMio::MEL)};
    case 3: return {mio, static_cast<int>(ApsMio::ORG)};
    case 4: return {mio, static_cast<int>(ApsMio::EZ)};
    case 5: return {mio, static_cast<int>(ApsMio::INP)};
    case 6: return {mio, static_cast<int>(ApsMio::EMG)};
    case 8: return {msts, static_cast<int>(ApsMsts::CSTP)};
    case 9: return {msts, static_cast<int>(ApsMsts::VM)};
    case 10: return {msts, static_cast<int>(ApsMsts::ACC)};
    case 11: return {msts, static_cast<int>(ApsMsts::DEC)};
    case 12: return {msts, static_cast<int>(ApsMsts::MDN)};
    case 13: return {msts, static_cast<int>(ApsMsts::ASTP)};
    case 15: return {mio, static_cast<int>(ApsMio::SPEL)};
    case 16: return {mio, static_cast<int>(ApsMio::SMEL)};
    default: return {-1, -1};
  }
}

bool whole(double v) { return std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e15; }

}  // namespace

void ApsInterrupts::power_on() {
  main_ = false;
  enabled_.clear();
  signaled_.clear();
  waiting_.clear();
  if (card_.has_scope()) card_.scope().clear_vendor_watch(*this);
}

void ApsInterrupts::rewatch() {
  machine::CardScope& s = card_.scope();
  if (!s.words().msts) s.set_words(vendor::scope_words());  // the vendor words, as the bindings give them
  machine::EventWatch w;
  for (std::size_t i = 0; i < card_.axis_count(); ++i) {
    w.msts.push_back(msts_mask(i));
    w.mio.push_back(mio_mask(i));
  }
  w.system = system_mask();
  s.set_vendor_watch(*this, w);
}

void ApsInterrupts::on_watch(const machine::FiredEvent& e) {
  using machine::WatchWord;
  fired(e.axis, e.word == WatchWord::Msts ? "msts" : e.word == WatchWord::Mio ? "mio" : "system", e.bits);
  if (!waiting_.empty() && wait_done()) card_.scope().request_stop();
}

AdlinkCode ApsInterrupts::set_main(double enable) {
  if (enable != 0 && enable != 1) return AdlinkCode::ParametersInvalid;
  main_ = enable == 1;
  return AdlinkCode::NoError;
}

bool ApsInterrupts::bit_of(double factor, long long& bit) {
  if (!whole(factor)) return false;
  auto f = static_cast<long long>(factor);
  if (f > 31 && (f & (f - 1)) == 0) {  // a one-bit mask: its bit (V82)
    int b = 0;
    while ((f >> b) != 1) ++b;
    f = b;
  }
  bit = f;
  return true;
}

int ApsInterrupts::set_factor(double item, double factor, double enable) {
  const int no = set_factor_(item, factor, enable);
  rewatch();
  return no;
}

int ApsInterrupts::set_factor_(double item, double factor, double enable) {
  long long bit = 0;
  if (!whole(item) || !bit_of(factor, bit) || (enable != 0 && enable != 1))
    return static_cast<int>(AdlinkCode::ParametersInvalid);
  if (bit < 0 || bit > 31 || item < 0 || item > 10) return static_cast<int>(AdlinkCode::ParametersInvalid);
  const int f = static_cast<int>(bit);
  const int it = static_cast<int>(item);
  if (it == 9 || it == 10) return static_cast<int>(AdlinkCode::FunctionNotAvailable);  // no digital inputs
  if (it < kSystemItem) {
    if (static_cast<std::size_t>(it) >= card_.axis_count()) return static_cast<int>(AdlinkCode::ParametersInvalid);
    if (axis_watch(f).word < 0)
      return static_cast<int>(f == kIpred || f == kIpostd ? AdlinkCode::FunctionNotAvailable
                                                          : AdlinkCode::ParametersInvalid);
  } else if (f > kIhov) {
    return static_cast<int>(AdlinkCode::ParametersInvalid);
  }
  const int no = it * 32 + f;
  if (enable == 1) {
    enabled_.insert(no);
    signaled_.emplace(no, false);
  } else {
    enabled_.erase(no);
  }
  return no;
}

AdlinkCode ApsInterrupts::factor_enabled(double item, double factor, int& enabled) const {
  long long f = 0;
  if (!whole(item) || !bit_of(factor, f)) return AdlinkCode::ParametersInvalid;
  const long long no = static_cast<long long>(item) * 32 + f;
  enabled = no >= 0 && no < (1LL << 30) && enabled_.count(static_cast<int>(no)) ? 1 : 0;
  return AdlinkCode::NoError;
}

std::uint32_t ApsInterrupts::msts_mask(std::size_t axis) const {
  std::uint32_t m = 0;
  for (int no : enabled_) {
    const Watch w = axis_watch(no % 32);
    if (no / 32 == static_cast<int>(axis) && no / 32 < kSystemItem && w.word == 0) m |= 1u << w.bit;
  }
  return m;
}

std::uint32_t ApsInterrupts::mio_mask(std::size_t axis) const {
  std::uint32_t m = 0;
  for (int no : enabled_) {
    const Watch w = axis_watch(no % 32);
    if (no / 32 == static_cast<int>(axis) && no / 32 < kSystemItem && w.word == 1) m |= 1u << w.bit;
  }
  return m;
}

std::uint32_t ApsInterrupts::system_mask() const {
  std::uint32_t m = 0;
  for (int no : enabled_)
    if (no / 32 == kSystemItem && no % 32 <= 4) m |= 1u << (no % 32);  // IMOV / IHOV never fire
  return m;
}

void ApsInterrupts::fired(int axis, const std::string& word, std::uint32_t bits) {
  if (!main_) return;
  for (int no : enabled_) {
    const int item = no / 32, f = no % 32;
    if (item == kSystemItem) {
      if (word == "system" && (bits >> f & 1u)) signaled_[no] = true;
    } else if (item == axis) {
      const Watch w = axis_watch(f);
      if (word == (w.word == 0 ? "msts" : "mio") && (bits >> w.bit & 1u)) signaled_[no] = true;
    }
  }
}

AdlinkCode ApsInterrupts::set_signaled(double int_no, bool on) {
  if (!whole(int_no)) return AdlinkCode::ParametersInvalid;
  auto it = signaled_.find(static_cast<int>(int_no));
  if (it == signaled_.end()) return AdlinkCode::ParametersInvalid;
  it->second = on;
  return AdlinkCode::NoError;
}

AdlinkCode ApsInterrupts::begin_wait(double count, const std::vector<double>& nos, double wait_all,
                                     double time_out_ms, long long& max_ticks) {
  if (!whole(count) || count < 1 || nos.size() < static_cast<std::size_t>(count) || (wait_all != 0 && wait_all != 1) ||
      !whole(time_out_ms) || (time_out_ms < 0 && time_out_ms != -1))
    return AdlinkCode::ParametersInvalid;
  std::vector<int> list;
  for (std::size_t k = 0; k < static_cast<std::size_t>(count); ++k) {
    if (!whole(nos[k]) || !signaled_.count(static_cast<int>(nos[k]))) return AdlinkCode::ParametersInvalid;
    list.push_back(static_cast<int>(nos[k]));
  }
  if (!main_) return AdlinkCode::InterruptNotEnable;
  for (int no : list)
    if (!enabled_.count(no)) return AdlinkCode::InterruptNotEnable;
  waiting_ = list;
  wait_all_ = wait_all == 1;
  const double wait_s = time_out_ms == -1 ? kWaitForeverS : time_out_ms * 1e-3;
  max_ticks = std::llround(wait_s / card_.servo_period_s());
  return AdlinkCode::NoError;
}

bool ApsInterrupts::wait_done() const {
  bool all = true, any = false;
  for (int no : waiting_) {
    const auto it = signaled_.find(no);
    const bool s = it != signaled_.end() && it->second;
    all = all && s;
    any = any || s;
  }
  return wait_all_ ? all : any;
}

ApsInterrupts& aps_interrupts(machine::Card& card) { return card.module<ApsInterrupts>(); }

}  // namespace servobench::vendor::adlink
