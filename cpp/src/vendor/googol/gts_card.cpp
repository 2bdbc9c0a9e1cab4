// GtsCard: the GUC-ECAT / iDEABOX registers the kernel does not hold (vendor/googol/gts_card.hpp).
#include "servobench/vendor/googol/gts_card.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "servobench/machine/card_modes.hpp"
#include "servobench/motion/crd_fifo_pair.hpp"
#include "servobench/motion/generator.hpp"

namespace servobench::vendor::googol {

using machine::AxisMode;

namespace {

bool whole_in(double v, double lo, double hi) { return std::isfinite(v) && v == std::floor(v) && lo <= v && v <= hi; }
bool dec_ok(double v) { return std::isfinite(v) && 0 < v && v <= 32767.0; }  // (0, 32767] (GUC L240-243)

}  // namespace

GtsCard::GtsCard(machine::Card& card)
    : card_(card),
      stop_dec_(card.axis_count()),
      stop_io_(card.axis_count()),
      prf_exp_(card.axis_count(), 0),
      enc_exp_(card.axis_count(), 0),
      jog_smooth_(card.axis_count(), 0.0) {}

GtsCard& gts(machine::Card& card) { return card.module<GtsCard>(); }

double GtsCard::ms() const { return card_.servo_period_s() * 1e3; }

bool GtsCard::valid_axis(double axis, double hi) const {
  return whole_in(axis, 1, std::min(hi, static_cast<double>(card_.axis_count())));
}

// -- look-ahead -----------------------------------------------------------------------------------------------------
void GtsCard::set_lookahead(int crd, int fifo, int n) { la_.at(crd - 1).at(fifo) = n; }
int GtsCard::lookahead(int crd, int fifo) const { return la_.at(crd - 1).at(fifo); }
void GtsCard::drop_lookahead(int crd) { la_.at(crd - 1) = {}; }

GucCode GtsCard::check_push(int crd, int fifo) {
  try {
    const motion::CrdFifoPair& pair = card_.modes().crd(crd);
    if (lookahead(crd, fifo) > 0 && pair.coords().dim() > 3) return GucCode::ParameterError;
  } catch (const motion::MotionCommandRefused&) {
    return GucCode::CommandError;
  }
  return GucCode::Success;
}

void GtsCard::reset() { la_ = {}; }

// -- general inputs --------------------------------------------------------------------------------------------------
void GtsCard::set_inputs(std::uint32_t levels) { gpi_ = levels & 0xFFFF; }

GucCode GtsCard::set_gpi_sense(double sense) {
  if (!whole_in(sense, 0, 0xFFFF)) return GucCode::ParameterError;
  gpi_sns_ = static_cast<std::uint32_t>(sense);
  return GucCode::Success;
}

std::optional<std::uint32_t> GtsCard::input_word(GtsInput type) const {
  const std::size_t n = std::min<std::size_t>(8, card_.axis_count());
  std::uint32_t w = 0;
  switch (type) {
    case GtsInput::Gpi: return gpi_ ^ gpi_sns_;
    case GtsInput::LimitPositive:  // 1 = the limit triggers (its polarity applied, GT_LmtSns)
      for (std::size_t k = 0; k < n; ++k) w |= static_cast<std::uint32_t>(card_.pos_limit_input(k)) << k;
      return w;
    case GtsInput::LimitNegative:
      for (std::size_t k = 0; k < n; ++k) w |= static_cast<std::uint32_t>(card_.neg_limit_input(k)) << k;
      return w;
    case GtsInput::Alarm:  // the latched drive-alarm event (status bit 1)
      for (std::size_t k = 0; k < n; ++k) w |= ((card_.events(k) >> 1) & 1u) << k;
      return w;
    default: return std::nullopt;
  }
}

// -- stops -------------------------------------------------------------------------------------------------------------
GucCode GtsCard::set_stop_dec(double profile, double smooth, double abrupt) {
  if (!valid_axis(profile) || !dec_ok(smooth) || !dec_ok(abrupt)) return GucCode::ParameterError;
  stop_dec_[static_cast<std::size_t>(profile) - 1] = std::make_pair(smooth, abrupt);
  return GucCode::Success;
}

std::pair<double, double> GtsCard::stop_dec(std::size_t profile) const {
  return stop_dec_.at(profile).value_or(std::make_pair(0.0, 0.0));
}

void GtsCard::set_crd_stop_dec(int crd, double smooth, double abrupt) {
  crd_stop_dec_.at(crd - 1) = std::make_pair(smooth, abrupt);
}

std::pair<double, double> GtsCard::crd_stop_dec(int crd) const {
  return crd_stop_dec_.at(crd - 1).value_or(std::make_pair(0.0, 0.0));
}

void GtsCard::stop_axis(std::size_t a, bool abrupt) {
  const auto& dec = stop_dec_.at(a);
  if (!dec || !card_.moving(a)) {
    if (abrupt) {
      card_.abrupt_stop(a);
    } else {
      card_.stage_smooth_stop(a);
      card_.update(1u << a);
    }
    return;
  }
  const double acc = card_.state(a).staged.acc;
  card_.stage_acc(a, (abrupt ? dec->second : dec->first) * ms() * ms());
  card_.stage_smooth_stop(a);
  card_.update(1u << a);
  if (acc > 0) card_.stage_acc(a, acc);  // the move's acc again for the next move (staged, committed by its update)
}

GucCode GtsCard::set_stop_io(double axis, double stop_type, double input_type, double index) {
  if (!valid_axis(axis, 8)) return GucCode::ParameterError;
  const double hi = input_type == static_cast<double>(GtsInput::Gpi) ? 16 : 8;
  if ((stop_type != 0 && stop_type != 1) || !whole_in(input_type, 0, 5) || !whole_in(index, 1, hi))
    return GucCode::ParameterError;
  const auto in = static_cast<GtsInput>(static_cast<int>(input_type));
  if (in == GtsInput::Home || in == GtsInput::Arrive) return GucCode::CommandError;  // not wired (GS6)
  stop_io_[static_cast<std::size_t>(axis) - 1] = GtsStopIo{static_cast<int>(stop_type), in, static_cast<int>(index)};
  any_stop_io_ = true;
  return GucCode::Success;
}

void GtsCard::check_stop_inputs() {
  for (std::size_t a = 0; a < stop_io_.size(); ++a) {
    if (!stop_io_[a]) continue;
    const GtsStopIo& s = *stop_io_[a];
    const auto word = input_word(s.input);
    if (!word || !((*word >> (s.index - 1)) & 1u)) continue;
    const AxisMode mode = card_.state(a).mode;
    if (!(card_.moving(a) || (mode != AxisMode::TCurve && mode != AxisMode::Jog))) continue;
    const machine::CardModes* modes = card_.modes_if_any();
    if (modes != nullptr && modes->group_of(a) >= 0) continue;
    if (mode == AxisMode::TCurve || mode == AxisMode::SCurve || mode == AxisMode::Jog)
      stop_axis(a, s.stop_type == 0);
    else
      card_.abrupt_stop(a);
  }
}

// -- velocity filters ----------------------------------------------------------------------------------------------
GucCode GtsCard::set_prf_vel_filter(double axis, double exp) {
  if (!valid_axis(axis) || !whole_in(exp, 0, kFilterExpMax)) return GucCode::ParameterError;
  prf_exp_[static_cast<std::size_t>(axis) - 1] = static_cast<int>(exp);
  start_history();
  return GucCode::Success;
}

GucCode GtsCard::set_enc_vel_filter(double axis, double exp) {
  if (!valid_axis(axis) || !whole_in(exp, 0, kFilterExpMax)) return GucCode::ParameterError;
  enc_exp_[static_cast<std::size_t>(axis) - 1] = static_cast<int>(exp);
  start_history();
  return GucCode::Success;
}

int GtsCard::prf_vel_filter(std::size_t axis) const { return prf_exp_.at(axis); }
int GtsCard::enc_vel_filter(std::size_t axis) const { return enc_exp_.at(axis); }

void GtsCard::start_history() {
  if (history_on_) return;
  history_on_ = true;
  record();
}

void GtsCard::record() {
  std::vector<std::pair<double, double>> now(card_.axis_count());
  for (std::size_t k = 0; k < now.size(); ++k) now[k] = {card_.profile_vel(k), card_.actual_pos(k)};
  history_.push_back(std::move(now));
  while (history_.size() > (1u << kFilterExpMax) + 1) history_.pop_front();
}

double GtsCard::filtered_prf_vel(std::size_t a) {
  card_.check_axis(a);
  start_history();
  const std::size_t n = std::min<std::size_t>(1u << prf_exp_[a], history_.size());
  if (n == 0) return 0.0;
  double sum = 0.0;
  for (std::size_t k = 0; k < n; ++k) sum += history_[history_.size() - 1 - k][a].first;
  return sum / (static_cast<double>(n) * ms());
}

double GtsCard::filtered_enc_vel(std::size_t a) {
  card_.check_axis(a);
  start_history();
  const long long n = std::min<long long>(1LL << enc_exp_[a], static_cast<long long>(history_.size()) - 1);
  if (n <= 0) return 0.0;
  const double now = history_.back()[a].second;
  const double then = history_[history_.size() - 1 - static_cast<std::size_t>(n)][a].second;
  return (now - then) / (static_cast<double>(n) * ms());
}

// -- the end of the tick ----------------------------------------------------------------------------------------------
void GtsCard::after_axis(std::size_t i, const machine::LoopTick& /*r*/) {
  if (i + 1 != card_.axis_count()) return;  // once per tick, after the last axis
  if (any_stop_io_) check_stop_inputs();
  if (history_on_) record();
}

}  // namespace servobench::vendor::googol
