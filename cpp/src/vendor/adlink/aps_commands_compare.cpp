// The APS runner's compare-trigger chapter (aps_commands.hpp): the linear and table comparators, the manual trigger,
// the trigger counters and the comparators' next points (manual seed 004 L3348-3435), and the compare timer counter
// (L3363-3378, the ApsScope module's TIMR_* register). Board_ID 0 only; a comparator channel 0..1, a trigger
// output 0..1 on a 4-axis card, 0..3 on an 8-axis card. Positions in pulse. Decisions AY1, AY5; the checks are the
// ones the dialect made (V71-V85, AF15), in the same order.
#include <cmath>

#include "aps_commands_detail.hpp"
#include "servobench/vendor/adlink/aps_scope.hpp"
#include "servobench/vendor/scope_words.hpp"

namespace servobench::vendor::adlink::detail {

namespace {

using C = AdlinkCode;
using machine::Card;

// The card's position compare, with the vendor words the scope samples (as Card.compare_* does).
machine::PositionCompare& compare(Card& k) {
  machine::CardScope& s = k.scope();
  if (!s.words().msts) s.set_words(vendor::scope_words());
  return s.compare();
}

bool board_ok(const Call& c) { return c.card != nullptr && c.num(0) == 0.0; }
bool channel_ok(const Call& c, std::size_t k) { return c.num(k) == 0.0 || c.num(k) == 1.0; }
bool output_ok(const Call& c, std::size_t k) {  // TrgCh: 0..1 (PCI-8254), 0..3 (PCI-8258)
  const double v = c.num(k);
  return whole(v) && v >= 0 && v < (c.card->axis_count() == 4 ? 2 : 4);
}

ApsReply set_linear(const Call& c) {  // Board_ID, LCmpCh, StartPoint, RepeatTimes, Interval
  if (!board_ok(c)) return code(c.bad());
  if (!channel_ok(c, 1)) return code(C::ParametersInvalid);
  for (std::size_t n = 2; n <= 4; ++n)
    if (!std::isfinite(c.num(n))) return code(C::ParametersInvalid);  // not a number
  Card& k = *c.card;
  return code(run(k, [&] { compare(k).set_linear(static_cast<int>(c.num(1)), c.num(2), c.num(3), c.num(4)); }));
}

ApsReply set_table(const Call& c) {  // Board_ID, TCmpCh, DataArr, ArraySize
  if (!board_ok(c)) return code(c.bad());
  const std::vector<double>& pts = c.vec(2);
  const double n = c.num(3);
  for (double p : pts)
    if (std::isnan(p)) return code(C::ParametersInvalid);  // not a number
  if (!channel_ok(c, 1) || !whole(n) || n < 0 || n > static_cast<double>(pts.size())) return code(C::ParametersInvalid);
  Card& k = *c.card;
  const std::vector<double> first(pts.begin(), pts.begin() + static_cast<std::ptrdiff_t>(n));
  return code(run(k, [&] { compare(k).set_table(static_cast<int>(c.num(1)), first); }));
}

template <int Reset>
ApsReply trigger_output(const Call& c) {  // Board_ID, TrgCh: APS_set_trigger_manual / APS_reset_trigger_count
  if (!board_ok(c)) return code(c.bad());
  if (!output_ok(c, 1)) return code(C::ParametersInvalid);
  Card& k = *c.card;
  const int trg = static_cast<int>(c.num(1));
  if (Reset) return code(run(k, [&] { compare(k).reset_count(trg); }));
  return code(run(k, [&] {
    compare(k).manual(trg, static_cast<double>(k.tick()) * k.servo_period_s(), k.tick());
  }));
}

ApsReply trigger_count(const Call& c) {
  if (!board_ok(c)) return ApsReply{c.bad(), {0.0}, "i"};
  if (!output_ok(c, 1)) return ApsReply{C::ParametersInvalid, {0.0}, "i"};
  return ApsReply{C::NoError, {static_cast<double>(compare(*c.card).count(static_cast<int>(c.num(1))))}, "i"};
}

template <int Base>
ApsReply next_cmp(const Call& c) {  // the next compare point of the linear (0, 1) or table (2, 3) comparator
  if (!board_ok(c)) return ApsReply{c.bad(), {0.0}, "i"};
  if (!channel_ok(c, 1)) return ApsReply{C::ParametersInvalid, {0.0}, "i"};
  const double v = compare(*c.card).next_point(Base + static_cast<int>(c.num(1)));
  return ApsReply{C::NoError, {std::isnan(v) ? 0.0 : std::trunc(v)}, "i"};
}

ApsReply get_timer(const Call& c) {  // Board_ID, TmrCh 0
  if (!board_ok(c)) return ApsReply{c.bad(), {0.0}, "i"};
  if (c.num(1) != 0.0) return ApsReply{C::ParametersInvalid, {0.0}, "i"};
  return ApsReply{C::NoError, {static_cast<double>(aps_scope(*c.card).timer_counter())}, "i"};
}

ApsReply set_timer(const Call& c) {  // Board_ID, TmrCh 0, Cnt
  if (!board_ok(c)) return code(c.bad());
  if (c.num(1) != 0.0) return code(C::ParametersInvalid);
  return code(aps_scope(*c.card).set_timer_counter(c.num(2)));
}

}  // namespace

const std::vector<Named>& compare_commands() {
  static const std::vector<Named> kRows = {
      {"APS_set_trigger_linear", {&set_linear, "nnnnn", ""}},
      {"APS_set_trigger_table", {&set_table, "nnan", ""}},
      {"APS_set_trigger_manual", {&trigger_output<0>, "nn", ""}},
      {"APS_reset_trigger_count", {&trigger_output<1>, "nn", ""}},
      {"APS_get_trigger_count", {&trigger_count, "nn", "i"}},
      {"APS_get_trigger_linear_cmp", {&next_cmp<0>, "nn", "i"}},
      {"APS_get_trigger_table_cmp", {&next_cmp<2>, "nn", "i"}},
      {"APS_get_timer_counter", {&get_timer, "nn", "i"}},
      {"APS_set_timer_counter", {&set_timer, "nnn", ""}},
  };
  return kRows;
}

}  // namespace servobench::vendor::adlink::detail
