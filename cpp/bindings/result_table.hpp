// Results described once: a result struct's static describe(visitor) lists its single-figure fields (name, member,
// unit, meaning). These helpers turn that list into the Python dict of a result and into its field table, so the
// binding retypes neither the keys nor the docs (decision OP6).
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <type_traits>

namespace servobench::bindings {

// d[name] = r.member for every described field.
template <class R>
void put_described(pybind11::dict& d, const R& r) {
  R::describe([&](const char* name, auto member, const char*, const char*) { d[name] = r.*member; });
}

// ({"name", "type", "unit", "doc"}, ...) of the described fields, in order.
template <class R>
pybind11::tuple described_fields() {
  pybind11::list out;
  R::describe([&](const char* name, auto member, const char* unit, const char* doc) {
    using T = std::remove_reference_t<decltype(std::declval<R&>().*member)>;
    const char* type = std::is_same_v<T, bool> ? "bool" : (std::is_integral_v<T> ? "int" : "float");
    out.append(pybind11::dict(pybind11::arg("name") = name, pybind11::arg("type") = type,
                              pybind11::arg("unit") = unit, pybind11::arg("doc") = doc));
  });
  return pybind11::tuple(out);
}

}  // namespace servobench::bindings
