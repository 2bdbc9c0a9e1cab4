// The one axis-index check of the card bindings (bind_card*.cpp): every card axis argument goes through card_axis().
// The argument converts like a number (so 1.5, NaN or -1 reach the check and get its ValueError naming the axis and
// the card's range 0..axes-1, not a TypeError). Next step (docs/architecture.md): an `int` in the signatures.
#pragma once

#include <cstddef>

#include "servobench/common/validate.hpp"
#include "servobench/machine/card.hpp"

namespace servobench::bindings {

// Axis i of card c: ValueError "Card.axis = i ..." unless i is a whole number in 0..axis_count()-1.
inline std::size_t card_axis(const machine::Card& c, double i) {
  check_integer("Card", "axis", i, 0, static_cast<double>(c.axis_count()) - 1);
  return static_cast<std::size_t>(i);
}

}  // namespace servobench::bindings
