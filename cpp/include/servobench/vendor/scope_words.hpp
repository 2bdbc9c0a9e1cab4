// The vendor status words the card scope samples and watches (machine/card_scope.hpp ScopeWords): the ADLINK
// motion status and motion I/O words (vendor/adlink/aps_status.hpp) and the GT axis status register
// (vendor/googol/gt_status.hpp). The bindings give them to every card's scope (one servobench.Card serves every
// dialect); a C++ program that samples or watches a vendor word sets them itself.
#pragma once

#include <cstddef>
#include <cstdint>

#include "servobench/machine/card_scope.hpp"
#include "servobench/vendor/adlink/aps_status.hpp"
#include "servobench/vendor/googol/gt_status.hpp"

namespace servobench::vendor {

inline std::uint32_t gt_axis_status_word(const machine::Card& card, std::size_t axis) {
  return googol::gt_axis_status(card, axis);
}

// msts = ADLINK MSTS, mio = ADLINK MIO, status = GT axis status (Table 4-14).
inline machine::ScopeWords scope_words() {
  return machine::ScopeWords{&adlink::aps_motion_status, &adlink::aps_motion_io_status, &gt_axis_status_word};
}

}  // namespace servobench::vendor
