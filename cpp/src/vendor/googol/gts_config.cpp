// The GUC-ECAT system-configuration calls and read-backs (vendor/googol/gts_config.hpp).
#include "servobench/vendor/googol/gts_config.hpp"

#include <algorithm>
#include <cmath>

#include "servobench/vendor/googol/gts_card.hpp"

namespace servobench::vendor::googol {

using machine::Card;

namespace {

bool whole_in(double v, double lo, double hi) { return std::isfinite(v) && v == std::floor(v) && lo <= v && v <= hi; }
bool valid_axis(const Card& card, double axis) { return whole_in(axis, 1, static_cast<double>(card.axis_count())); }
std::size_t index(double axis) { return static_cast<std::size_t>(axis) - 1; }
double ms(const Card& card) { return card.servo_period_s() * 1e3; }

}  // namespace

GucCode gts_alarm(Card& card, double axis, bool on) {
  if (!valid_axis(card, axis)) return GucCode::ParameterError;
  card.set_alarm_enabled(index(axis), on);
  return GucCode::Success;
}

GucCode gts_limits(Card& card, double axis, double limit_type, bool on) {
  if (!valid_axis(card, axis) || !whole_in(limit_type, -1, 1)) return GucCode::ParameterError;
  machine::LimitConfig lim = card.state(index(axis)).limits;
  if (limit_type != -1 && lim.enabled != on) return GucCode::CommandError;  // one enable per axis (GS3)
  lim.enabled = on;
  card.set_limits(index(axis), lim);
  return GucCode::Success;
}

GucCode gts_limit_sense(Card& card, double sense) {
  if (!whole_in(sense, 0, 0xFFFF)) return GucCode::ParameterError;
  const auto s = static_cast<std::uint32_t>(sense);
  for (std::size_t k = 0; k < std::min<std::size_t>(8, card.axis_count()); ++k) {
    machine::LimitConfig lim = card.state(k).limits;
    lim.pos_active_low = (s >> (2 * k)) & 1u;
    lim.neg_active_low = (s >> (2 * k + 1)) & 1u;
    card.set_limits(k, lim);
  }
  return GucCode::Success;
}

GucCode gts_enc_sense(Card& /*card*/, double sense) {
  if (!whole_in(sense, 0, 0x1FF)) return GucCode::ParameterError;
  return sense != 0 ? GucCode::CommandError : GucCode::Success;
}

GucCode gts_scale(Card& card, double axis, double alpha, double beta) {
  if (!valid_axis(card, axis) || !whole_in(alpha, -32768, 32767) || !whole_in(beta, -32768, 32767) || beta == 0)
    return GucCode::ParameterError;
  return alpha == beta ? GucCode::Success : GucCode::CommandError;  // one pulse per unit: 1:1 only (GS5)
}

std::pair<GucCode, std::uint32_t> gts_get_di(Card& card, double type) {
  if (!whole_in(type, 0, 5)) return {GucCode::ParameterError, 0};
  const auto word = gts(card).input_word(static_cast<GtsInput>(static_cast<int>(type)));
  if (!word) return {GucCode::CommandError, 0};
  return {GucCode::Success, *word};
}

GucCode gts_set_adc_filter(Card& /*card*/, double adc, double filter_time) {
  if (!whole_in(adc, 1, 8) || !whole_in(filter_time, 1, 50)) return GucCode::ParameterError;
  return GucCode::CommandError;  // no analog inputs on the simulated card
}

std::tuple<GucCode, double, double> gts_get_stop_dec(Card& card, double profile) {
  if (!valid_axis(card, profile)) return {GucCode::ParameterError, 0.0, 0.0};
  const auto [s, a] = gts(card).stop_dec(index(profile));
  return {GucCode::Success, s, a};
}

std::tuple<GucCode, double, double> gts_get_crd_stop_dec(Card& card, double crd) {
  if (!whole_in(crd, 1, 2)) return {GucCode::ParameterError, 0.0, 0.0};
  const auto [s, a] = gts(card).crd_stop_dec(static_cast<int>(crd));
  return {GucCode::Success, s, a};
}

GucCode gts_set_stop_io(Card& card, double axis, double stop_type, double input_type, double index_) {
  if (!valid_axis(card, axis)) return GucCode::ParameterError;
  return gts(card).set_stop_io(axis, stop_type, input_type, index_);
}

std::tuple<GucCode, double, double> gts_get_acc(Card& card, double profile) {
  if (!valid_axis(card, profile)) return {GucCode::ParameterError, 0.0, 0.0};
  const std::size_t a = index(profile);
  return {GucCode::Success, card.state(a).staged.acc / (ms(card) * ms(card)), gts(card).jog_smooth(a)};
}

std::pair<GucCode, int> gts_get_vel_filter(Card& card, double axis, bool encoder) {
  if (!valid_axis(card, axis)) return {GucCode::ParameterError, 0};
  return {GucCode::Success, encoder ? gts(card).enc_vel_filter(index(axis)) : gts(card).prf_vel_filter(index(axis))};
}

std::pair<GucCode, double> gts_get_enc_vel(Card& card, double axis) {
  if (!valid_axis(card, axis)) return {GucCode::ParameterError, 0.0};
  return {GucCode::Success, gts(card).filtered_enc_vel(index(axis))};
}

}  // namespace servobench::vendor::googol
