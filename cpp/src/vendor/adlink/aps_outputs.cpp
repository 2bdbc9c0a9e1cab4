#include "servobench/vendor/adlink/aps_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace servobench::vendor::adlink {

namespace {

constexpr int kEmgLogic = 0x00, kPwm0MapDo = 0x110;
constexpr int kOutputType = 0x00, kConfig = 0x10, kSource = 0x20;

// A whole number register value (finite, integral, I32 or wider).
bool whole(double v) { return std::isfinite(v) && v == std::floor(v) && std::fabs(v) < 1e15; }

// Power range per output type (L3489-3495) and the VAO_TABLE_PWM_Config range (L3462-3474, L3508).
struct Range {
  double lo, hi;
};
Range power_range(int type) { return type == 1 ? Range{0, 2000} : Range{3, 50e6}; }
Range config_range(int type) {
  return type == 1 ? Range{3, 50e6} : type == 2 ? Range{20, 335544320} : Range{1, 2000};
}

}  // namespace

void ApsOutputs::power_on() {
  do_word_ = 0;
  emg_logic_ = 0;
  pwm_map_.fill(-1);
  vao_.fill(0);
  for (int n = 0; n < 8; ++n) {
    vao_[static_cast<std::size_t>(kOutputType + 2 * n)] = 1;   // PWM duty
    vao_[static_cast<std::size_t>(kOutputType + 2 * n + 1)] = 0;  // feedback speed (set 1 as the examples do)
    vao_[static_cast<std::size_t>(kConfig + n)] = 100;
    vao_[static_cast<std::size_t>(kSource + n)] = 0x01;
  }
  tables_.fill(Table{});
  table_of_ = {0, 0};
  on_ = {false, false};
}

AdlinkCode ApsOutputs::write_do(double group, double data) {
  if (group != 0 || !whole(data) || data < 0 || data > 0xFF) return AdlinkCode::ParametersInvalid;
  do_word_ = static_cast<int>(data);
  return AdlinkCode::NoError;
}

AdlinkCode ApsOutputs::read_do(double group, int& data) const {
  if (group != 0) return AdlinkCode::ParametersInvalid;
  data = do_word_;
  return AdlinkCode::NoError;
}

void ApsOutputs::set_do_bit(int channel, bool on) {
  if (channel < 0 || channel > 7) throw std::invalid_argument("ApsOutputs.set_do_bit: channel must be 0..7");
  do_word_ = on ? (do_word_ | (1 << channel)) : (do_word_ & ~(1 << channel));
}

AdlinkCode ApsOutputs::set_board_param(double para, double value) {
  if (!whole(para) || !whole(value)) return AdlinkCode::ParametersInvalid;
  const auto p = static_cast<long long>(para);
  const auto v = static_cast<long long>(value);
  if (p == kEmgLogic)  // the simulated EMG input is the active state; inverting its wiring is not simulated (AF17)
    return v == 0 ? AdlinkCode::NoError : v == 1 ? AdlinkCode::FunctionNotAvailable : AdlinkCode::ParametersInvalid;
  if (p < kPwm0MapDo || p > kPwm0MapDo + 3) return AdlinkCode::ParametersInvalid;
  if (v != -1 && !(v >= 0 && v <= 0x1FF && (v & 0xFF) <= 7)) return AdlinkCode::ParametersInvalid;
  pwm_map_[static_cast<std::size_t>(p - kPwm0MapDo)] = static_cast<int>(v);
  return AdlinkCode::NoError;
}

AdlinkCode ApsOutputs::board_param(double para, int& value) const {
  if (!whole(para)) return AdlinkCode::ParametersInvalid;
  const auto p = static_cast<long long>(para);
  if (p == kEmgLogic) value = emg_logic_;
  else if (p >= kPwm0MapDo && p <= kPwm0MapDo + 3) value = pwm_map_[static_cast<std::size_t>(p - kPwm0MapDo)];
  else return AdlinkCode::ParametersInvalid;
  return AdlinkCode::NoError;
}

AdlinkCode ApsOutputs::set_vao_param(double para, double value) {
  if (!whole(para) || !whole(value)) return AdlinkCode::ParametersInvalid;
  const auto p = static_cast<long long>(para);
  const auto v = static_cast<long long>(value);
  const bool known = (p >= 0 && p < 0x10) || (p >= kConfig && p < kConfig + 8) || (p >= kSource && p < kSource + 8);
  if (!known) return AdlinkCode::ParametersInvalid;
  bool ok = false;
  if (p < kConfig) {
    if (p % 2 == 0) {
      ok = v >= 1 && v <= 3;
    } else {
      if (v == 0) return AdlinkCode::FunctionNotAvailable;  // the feedback speed is not simulated (AF19)
      ok = v == 1;
    }
  } else if (p < kSource) {
    const Range r = config_range(output_type(static_cast<int>(p - kConfig)));
    ok = value >= r.lo && value <= r.hi;
  } else {
    ok = v >= 1 && v < (1LL << card_.axis_count());
  }
  if (!ok) return AdlinkCode::ParametersInvalid;
  vao_[static_cast<std::size_t>(p)] = static_cast<int>(v);
  return AdlinkCode::NoError;
}

AdlinkCode ApsOutputs::set_vao_table(double table, double min_velocity, double interval, double count,
                                     const std::vector<double>& powers) {
  if (!whole(table) || table < 0 || table > 7 || !whole(min_velocity) || !whole(interval) || !whole(count) ||
      min_velocity < 0 || interval <= 0 || count < 1 || count > 32 || powers.size() < static_cast<std::size_t>(count))
    return AdlinkCode::ParametersInvalid;
  const int n = static_cast<int>(table);
  const Range r = power_range(output_type(n));
  std::vector<double> pw(powers.begin(), powers.begin() + static_cast<long>(count));
  for (double x : pw)
    if (!std::isfinite(x) || x < r.lo || x > r.hi) return AdlinkCode::ParametersInvalid;
  tables_[static_cast<std::size_t>(n)] = Table{true, min_velocity, interval, pw};
  return AdlinkCode::NoError;
}

AdlinkCode ApsOutputs::switch_vao_table(double table) {
  if (!whole(table) || table < 0 || table > 7) return AdlinkCode::ParametersInvalid;
  select_vao(0, static_cast<int>(table));
  return AdlinkCode::NoError;
}

void ApsOutputs::select_vao(int ctrl, int table) {
  if (ctrl < 0 || ctrl > 1 || table < 0 || table > 7)
    throw std::invalid_argument("ApsOutputs.select_vao: ctrl must be 0..1 and table 0..7");
  table_of_[static_cast<std::size_t>(ctrl)] = table;
}

AdlinkCode ApsOutputs::start_vao(double channel, double enable) {
  if ((channel != 0 && channel != 1) || (enable != 0 && enable != 1)) return AdlinkCode::ParametersInvalid;
  const auto ch = static_cast<std::size_t>(channel);
  const int n = table_of_[ch];
  if (enable == 1 && (!tables_[static_cast<std::size_t>(n)].set || input_type(n) != 1))
    return AdlinkCode::FunctionNotAvailable;  // no table, or a table on the feedback speed (AF19)
  on_[ch] = enable == 1;
  return AdlinkCode::NoError;
}

VaoOutput ApsOutputs::vao_output(int ctrl) const {
  if (ctrl < 0 || ctrl > 1) throw std::invalid_argument("vao_output.ctrl must be 0 or 1 (the VAO controllers)");
  VaoOutput out;
  const int n = table_of_[static_cast<std::size_t>(ctrl)];
  out.table = n;
  const int src = vao_[static_cast<std::size_t>(kSource + n)];
  double sum = 0.0;
  for (std::size_t a = 0; a < card_.axis_count(); ++a)
    if (src >> a & 1) {
      const double v = card_.profile_vel(a) / card_.servo_period_s();
      sum += v * v;
    }
  out.speed = std::sqrt(sum);
  const int m = pwm_map_[static_cast<std::size_t>(ctrl)];
  const bool do_ok = m == -1 || (((do_word_ >> (m & 0xFF)) & 1) != 0) == (((m >> 8) & 1) != 0);
  const Table& t = tables_[static_cast<std::size_t>(n)];
  out.on = on_[static_cast<std::size_t>(ctrl)] && do_ok && t.set && input_type(n) == 1;
  if (out.on) {
    const double x = (out.speed - t.vmin) / t.interval;
    const int last = static_cast<int>(t.powers.size()) - 1;
    const int k = std::min(std::max(static_cast<int>(std::floor(x)), 0), last);
    out.power = k >= last ? t.powers.back()
                          : t.powers[k] + (t.powers[k + 1] - t.powers[k]) * std::min(std::max(x - k, 0.0), 1.0);
  }
  out.unit = output_type(n) == 1 ? "0.05 %" : "Hz";
  return out;
}

ApsOutputs& aps_outputs(machine::Card& card) { return card.module<ApsOutputs>(); }

}  // namespace servobench::vendor::adlink
