// The one axis-index check of the card bindings (bind_card*.cpp): every card axis argument is an AxisIndex and goes
// through card_axis(), which gives the C++ kernel its std::size_t index.
//
// AxisIndex is shown as `int` in the Python signatures (and the stubs). It converts like a number, as the axis
// arguments always did: an int, a NumPy integer or a whole float (2.0, from a dialect's arithmetic) is an axis; a
// float that is not whole (1.5), NaN or an index out of 0..axes-1 reaches card_axis() and gets its ValueError naming
// the axis and the card's range, not pybind11's TypeError "incompatible function arguments" (decision VK6).
#pragma once

#include <pybind11/pybind11.h>

#include <cstddef>

#include "servobench/common/validate.hpp"
#include "servobench/machine/card.hpp"

namespace servobench::bindings {

// A 0-based card axis as the caller gave it; card_axis() checks it against the card.
struct AxisIndex {
  double value = 0.0;
};

// Axis i of card c: ValueError "Card.axis = i ..." unless i is a whole number in 0..axis_count()-1.
inline std::size_t card_axis(const machine::Card& c, AxisIndex i) {
  check_integer("Card", "axis", i.value, 0, static_cast<double>(c.axis_count()) - 1);
  return static_cast<std::size_t>(i.value);
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
