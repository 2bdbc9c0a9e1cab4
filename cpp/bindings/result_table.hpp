// Results described once: a result struct's static describe(visitor) lists its fields (name, member, unit,
// meaning; a field of a nested struct by two member pointers, e.g. RelayTuneResult::mean.kp). These helpers turn
// that list into the Python dict of a result, into columns or rows of a vector of results, and into its field table,
// so the binding retypes neither the keys nor the docs (decisions OP6, OQ6, OR1). A field is a number, a bool, a
// string, or a vector of numbers (a NumPy array) or of strings (a list).
#pragma once

#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "arrays.hpp"

namespace servobench::bindings {

namespace detail {

template <class T>
struct is_vector : std::false_type {};
template <class T>
struct is_vector<std::vector<T>> : std::true_type {};

// The Python type a field reads as (the annotation of the Python result's field).
template <class T>
const char* python_type() {
  if constexpr (std::is_same_v<T, std::string>) {
    return "str";
  } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
    return "list";
  } else if constexpr (is_vector<T>::value) {
    return "np.ndarray";
  } else {
    return std::is_same_v<T, bool> ? "bool" : (std::is_integral_v<T> ? "int" : "float");
  }
}

// A field's value as Python reads it: a vector of numbers as a NumPy array, anything else cast.
template <class T>
pybind11::object python_value(const T& v) {
  if constexpr (is_vector<T>::value && !std::is_same_v<T, std::vector<std::string>> &&
                !std::is_same_v<T, std::vector<bool>>) {
    return to_array(v);
  } else {
    return pybind11::cast(v);
  }
}

// d[name] = r.member (or r.outer.inner) for every described field.
template <class R>
struct PutDescribed {
  pybind11::dict& d;
  const R& r;
  template <class M>
  void operator()(const char* name, M R::*m, const char*, const char*) const {
    d[name] = python_value(r.*m);
  }
  template <class O, class M>
  void operator()(const char* name, O R::*o, M O::*m, const char*, const char*) const {
    d[name] = python_value((r.*o).*m);
  }
};

// d[name] = the column of r.member over the rows (an array; a list for strings and bools) for every described field.
template <class R>
struct PutColumns {
  pybind11::dict& d;
  const std::vector<R>& rows;
  template <class M>
  void column(const char* name, const std::function<M(const R&)>& get) const {
    std::vector<M> c;
    c.reserve(rows.size());
    for (const R& r : rows) c.push_back(get(r));
    d[name] = python_value(c);
  }
  template <class M>
  void operator()(const char* name, M R::*m, const char*, const char*) const {
    column<M>(name, [m](const R& r) { return r.*m; });
  }
  template <class O, class M>
  void operator()(const char* name, O R::*o, M O::*m, const char*, const char*) const {
    column<M>(name, [o, m](const R& r) { return (r.*o).*m; });
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

// The described fields of each row as a column: {name: array (list for strings, bools)}.
template <class R>
pybind11::dict described_columns(const std::vector<R>& rows) {
  pybind11::dict d;
  R::describe(detail::PutColumns<R>{d, rows});
  return d;
}

// Each row as a dict of its described fields.
template <class R>
pybind11::list described_rows(const std::vector<R>& rows) {
  pybind11::list out;
  for (const R& r : rows) {
    pybind11::dict d;
    put_described(d, r);
    out.append(d);
  }
  return out;
}

template <class R>
pybind11::tuple described_fields() {
  pybind11::list out;
  R::describe(detail::ListDescribed<R>{out});
  return pybind11::tuple(out);
}

}  // namespace servobench::bindings
