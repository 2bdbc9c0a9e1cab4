// Results described once: a result struct's static describe(visitor) lists its single-figure fields (name, member,
// unit, meaning; a field of a nested struct by two member pointers, e.g. RelayTuneResult::mean.kp). These helpers
// turn that list into the Python dict of a result and into its field table, so the binding retypes neither the keys
// nor the docs (decisions OP6, OQ6).
#pragma once

#include <pybind11/pybind11.h>

#include <string>
#include <type_traits>

namespace servobench::bindings {

namespace detail {

template <class T>
const char* python_type() {
  return std::is_same_v<T, bool> ? "bool" : (std::is_integral_v<T> ? "int" : "float");
}

// d[name] = r.member (or r.outer.inner) for every described field.
template <class R>
struct PutDescribed {
  pybind11::dict& d;
  const R& r;
  template <class M>
  void operator()(const char* name, M R::*m, const char*, const char*) const {
    d[name] = r.*m;
  }
  template <class O, class M>
  void operator()(const char* name, O R::*o, M O::*m, const char*, const char*) const {
    d[name] = (r.*o).*m;
  }
};

// ({"name", "type", "unit", "doc"}, ...) of the described fields, in order.
template <class R>
struct ListDescribed {
  pybind11::list& out;
  static void add(pybind11::list& out, const char* name, const char* type, const char* unit, const char* doc) {
    out.append(pybind11::dict(pybind11::arg("name") = name, pybind11::arg("type") = type,
                              pybind11::arg("unit") = unit, pybind11::arg("doc") = doc));
  }
  template <class M>
  void operator()(const char* name, M R::*, const char* unit, const char* doc) const {
    add(out, name, python_type<M>(), unit, doc);
  }
  template <class O, class M>
  void operator()(const char* name, O R::*, M O::*, const char* unit, const char* doc) const {
    add(out, name, python_type<M>(), unit, doc);
  }
};

}  // namespace detail

template <class R>
void put_described(pybind11::dict& d, const R& r) {
  R::describe(detail::PutDescribed<R>{d, r});
}

template <class R>
pybind11::tuple described_fields() {
  pybind11::list out;
  R::describe(detail::ListDescribed<R>{out});
  return pybind11::tuple(out);
}

}  // namespace servobench::bindings
