// The one axis-index check of the card bindings (bind_card*.cpp). A card axis argument is an AxisIndex: Python
// shows it as `int`; it converts like a number (so 1.5, NaN or -1 reach the check and get its ValueError, naming
// the axis and the card's range 0..axes-1, not a TypeError), and card_axis() checks it against the card once.
#pragma once

#include <pybind11/pybind11.h>

#include <cstddef>

#include "servobench/common/validate.hpp"
#include "servobench/machine/card.hpp"

namespace servobench::bindings {

// A 0-based card axis as the caller gave it; checked by card_axis().
struct AxisIndex {
  double value = 0.0;
  operator double() const { return value; }  // NOLINT: the number as given (messages, the GT 1-based forms)
};

// Axis i of card c: ValueError "Card.axis = i ..." unless i is a whole number in 0..axis_count()-1.
inline std::size_t card_axis(const machine::Card& c, double i) {
  check_integer("Card", "axis", i, 0, static_cast<double>(c.axis_count()) - 1);
  return static_cast<std::size_t>(i);
}

}  // namespace servobench::bindings

namespace pybind11::detail {
template <>
struct type_caster<servobench::bindings::AxisIndex> {
  PYBIND11_TYPE_CASTER(servobench::bindings::AxisIndex, const_name("int"));
  bool load(handle src, bool convert) {
    make_caster<double> d;
    if (!d.load(src, convert)) return false;
    value.value = cast_op<double>(d);
    return true;
  }
  static handle cast(servobench::bindings::AxisIndex v, return_value_policy, handle) {
    return PyLong_FromSsize_t(static_cast<Py_ssize_t>(v.value));
  }
};
}  // namespace pybind11::detail
