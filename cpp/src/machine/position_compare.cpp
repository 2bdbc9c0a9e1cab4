#include "servobench/machine/position_compare.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "servobench/common/validate.hpp"

namespace servobench::machine {

namespace {
constexpr double kI32Min = -2147483648.0, kI32Max = 2147483647.0;

void check_comparator(int c) {
  check_integer("PositionCompare", "comparator", c, 0, 3, "0/1 LCMP0/1, 2/3 TCMP0/1");
}
void check_trg(int t) { check_integer("PositionCompare", "trigger output", t, 0, 3, "TRG0-3 (PCI-8258)"); }
}  // namespace

void PositionCompare::set_source(int comparator, const CompareSource& src, std::size_t axes) {
  check_comparator(comparator);
  check_integer("PositionCompare", "source axis", static_cast<double>(src.axis), 0, static_cast<double>(axes) - 1);
  src_[static_cast<std::size_t>(comparator)] = src;
}

void PositionCompare::set_linear(int ch, double start, double count, double interval) {
  check_integer("PositionCompare", "linear channel", ch, 0, 1, "LCMP0/1");
  check_integer("PositionCompare", "start", start, kI32Min, kI32Max, "pulse, 32-bit (L3395)");
  check_integer("PositionCompare", "count", count, 0, kI32Max, "repeat times");
  check_integer("PositionCompare", "interval", interval, kI32Min, kI32Max, "pulse, signed (L3393)");
  if (count > 0 && interval == 0.0)
    throw_invalid("PositionCompare", "interval", interval, "must not be 0 (its sign is the compare direction)");
  const auto c = static_cast<std::size_t>(ch);
  lstart_[c] = start;
  linterval_[c] = interval;
  lcount_[c] = static_cast<std::size_t>(count);
  lnext_[c] = 0;
}

void PositionCompare::set_table(int ch, const std::vector<double>& points) {
  check_integer("PositionCompare", "table channel", ch, 0, 1, "TCMP0/1");
  for (double p : points) check_integer("PositionCompare", "table point", p, kI32Min, kI32Max, "pulse, 32-bit");
  const auto c = static_cast<std::size_t>(ch);
  table_[c] = points;
  tnext_[c] = 0;
}

void PositionCompare::set_table_direction(int ch, int dir) {
  check_integer("PositionCompare", "table channel", ch, 0, 1, "TCMP0/1");
  check_integer("PositionCompare", "direction", dir, -1, 1, "-1 down, 0 either, +1 up");
  tdir_[static_cast<std::size_t>(ch)] = dir;
}

void PositionCompare::set_output(int trg, const TriggerOutputConfig& cfg) {
  check_trg(trg);
  check_integer("PositionCompare", "sources", cfg.sources, 0, 31, "manual, TCMP0, TCMP1, LCMP0, LCMP1 bits");
  check_range("PositionCompare", "pulse_width_s", cfg.pulse_width_s, 1e-7, 1.0, "100 ns minimum (L383)");
  out_[static_cast<std::size_t>(trg)] = cfg;
}

std::uint32_t PositionCompare::source_bit(int comparator) const {
  switch (comparator) {
    case 0: return kTrgSrcLcmp0;
    case 1: return kTrgSrcLcmp1;
    case 2: return kTrgSrcTcmp0;
    case 3: return kTrgSrcTcmp1;
    default: return kTrgSrcManual;
  }
}

void PositionCompare::emit(int comparator, double point, double time_s, long long tick) {
  const std::uint32_t bit = source_bit(comparator);
  for (int t = 0; t < kOutputs; ++t) {
    const auto k = static_cast<std::size_t>(t);
    if (!(enabled_ & (1u << t)) || !(out_[k].sources & bit)) continue;
    ++counts_[k];
    ++pulses_[k];
    if (out_[k].toggle) {
      toggled_[k] = !toggled_[k];
    } else {
      pulse_end_s_[k] = std::max(pulse_end_s_[k], time_s + out_[k].pulse_width_s);
    }
    if (log_.size() < kMaxLog) log_.push_back(TriggerEvent{time_s, tick, t, comparator, point});
  }
}

void PositionCompare::manual(int trg, double time_s, long long tick) {
  check_trg(trg);
  const auto k = static_cast<std::size_t>(trg);
  if (!(enabled_ & (1u << trg)) || !(out_[k].sources & kTrgSrcManual)) return;
  ++counts_[k];
  ++pending_[k];
  if (out_[k].toggle) {
    toggled_[k] = !toggled_[k];
  } else {
    pulse_end_s_[k] = std::max(pulse_end_s_[k], time_s + out_[k].pulse_width_s);
  }
  if (log_.size() < kMaxLog)
    log_.push_back(TriggerEvent{time_s, tick, trg, -1, std::numeric_limits<double>::quiet_NaN()});
}

double PositionCompare::next_point(int comparator) const {
  check_comparator(comparator);
  if (comparator < 2) {
    const auto c = static_cast<std::size_t>(comparator);
    if (lnext_[c] >= lcount_[c]) return std::numeric_limits<double>::quiet_NaN();
    return lstart_[c] + static_cast<double>(lnext_[c]) * linterval_[c];
  }
  const auto c = static_cast<std::size_t>(comparator - 2);
  return tnext_[c] < table_[c].size() ? table_[c][tnext_[c]] : std::numeric_limits<double>::quiet_NaN();
}

std::size_t PositionCompare::remaining(int comparator) const {
  check_comparator(comparator);
  if (comparator < 2) {
    const auto c = static_cast<std::size_t>(comparator);
    return lcount_[c] - lnext_[c];
  }
  const auto c = static_cast<std::size_t>(comparator - 2);
  return table_[c].size() - tnext_[c];
}

bool PositionCompare::active() const {
  for (int c = 0; c < 4; ++c)
    if (remaining(c) > 0) return true;
  for (int t = 0; t < kOutputs; ++t)
    if (pulse_end_s_[static_cast<std::size_t>(t)] > now_s_) return true;
  return false;
}

bool PositionCompare::level(int trg) const {
  const auto k = static_cast<std::size_t>(trg);
  const bool on = out_[k].toggle ? toggled_[k] : pulse_end_s_[k] > now_s_;
  return on != out_[k].active_low;
}

void PositionCompare::tick(long long tick, double t0, double h, const std::array<double, 4>& prev,
                           const std::array<double, 4>& now) {
  pulses_ = pending_;
  pending_.fill(0);
  finished_now_ = 0;
  auto at_time = [&](double a, double b, double p) {
    const double f = b != a ? (p - a) / (b - a) : 1.0;
    return t0 + std::min(1.0, std::max(0.0, f)) * h;
  };
  auto passed = [](double a, double b, double p, int dir) {
    const bool up = a < p && b >= p, down = a > p && b <= p;
    return dir > 0 ? up : (dir < 0 ? down : (up || down));
  };
  for (int c = 0; c < 2; ++c) {
    const auto k = static_cast<std::size_t>(c);
    if (lnext_[k] >= lcount_[k]) continue;
    const int dir = linterval_[k] > 0 ? 1 : -1;
    while (lnext_[k] < lcount_[k]) {
      const double p = lstart_[k] + static_cast<double>(lnext_[k]) * linterval_[k];
      if (!passed(prev[k], now[k], p, dir)) break;
      emit(c, p, at_time(prev[k], now[k], p), tick);
      ++lnext_[k];
    }
    if (lnext_[k] == lcount_[k]) finished_now_ |= 1u << c;
  }
  for (int c = 0; c < 2; ++c) {
    const auto k = static_cast<std::size_t>(c);
    const auto s = static_cast<std::size_t>(c + 2);
    if (tnext_[k] >= table_[k].size()) continue;
    while (tnext_[k] < table_[k].size()) {
      const double p = table_[k][tnext_[k]];
      if (!passed(prev[s], now[s], p, tdir_[k])) break;
      emit(c + 2, p, at_time(prev[s], now[s], p), tick);
      ++tnext_[k];
    }
    if (tnext_[k] == table_[k].size()) finished_now_ |= 1u << (c + 2);
  }
  now_s_ = t0 + h;
}

void PositionCompare::reset() { *this = PositionCompare{}; }

}  // namespace servobench::machine
