// A strict Python bool for binding signatures. pybind11's `bool` caster converts anything with __bool__ in its
// convert pass, so a NaN, 2.5 or "no" became `true` (issue 21). A binding parameter declared `Flag` accepts only
// True/False, NumPy bools and the integers 0/1 (the vendor manuals' C programs pass 0/1), like the param classes'
// bool fields and servobench._checks.flag; anything else fails the overload and pybind11 raises TypeError showing
// the signature with the parameter's name. Python sees the type as `bool` (signatures, stubs).
#pragma once

#include <pybind11/pybind11.h>

#include <cstring>

namespace servobench::bindings {

struct Flag {
  bool value = false;
  Flag() = default;
  Flag(bool v) : value(v) {}  // NOLINT(google-explicit-constructor): defaults such as py::arg("abrupt") = false
  operator bool() const { return value; }  // NOLINT(google-explicit-constructor)
};

}  // namespace servobench::bindings

namespace pybind11::detail {

template <>
struct type_caster<servobench::bindings::Flag> {
  PYBIND11_TYPE_CASTER(servobench::bindings::Flag, const_name("bool"));

  bool load(handle src, bool /*convert*/) {
    PyObject* o = src.ptr();
    if (o == Py_True || o == Py_False) {
      value.value = (o == Py_True);
      return true;
    }
    const char* type_name = Py_TYPE(o)->tp_name;
    if (std::strcmp(type_name, "numpy.bool") == 0 || std::strcmp(type_name, "numpy.bool_") == 0) {
      const int truth = PyObject_IsTrue(o);
      if (truth < 0) {
        PyErr_Clear();
        return false;
      }
      value.value = truth == 1;
      return true;
    }
    if (PyLong_Check(o) || (PyIndex_Check(o) && !PyFloat_Check(o))) {  // int, NumPy integers: 0 or 1 only
      int overflow = 0;
      PyObject* as_int = PyNumber_Index(o);
      if (as_int == nullptr) {
        PyErr_Clear();
        return false;
      }
      const long v = PyLong_AsLongAndOverflow(as_int, &overflow);
      Py_DECREF(as_int);
      if (overflow != 0 || (v != 0 && v != 1)) {
        PyErr_Clear();
        return false;
      }
      value.value = v == 1;
      return true;
    }
    return false;
  }

  static handle cast(servobench::bindings::Flag src, return_value_policy /*policy*/, handle /*parent*/) {
    return handle(src.value ? Py_True : Py_False).inc_ref();
  }
};

}  // namespace pybind11::detail

namespace servobench::bindings {

template <class T>
struct strict_arg {
  using type = T;
};
template <>
struct strict_arg<bool> {
  using type = Flag;
};

// A member function bound with its `bool` parameters read as `Flag`: `.def("stop", strict(&PathGenerator::stop))`.
template <class R, class C, class... A>
auto strict(R (C::*f)(A...)) {
  return [f](C& self, typename strict_arg<A>::type... a) -> R { return (self.*f)(static_cast<A>(a)...); };
}
template <class R, class C, class... A>
auto strict(R (C::*f)(A...) const) {
  return [f](const C& self, typename strict_arg<A>::type... a) -> R { return (self.*f)(static_cast<A>(a)...); };
}

}  // namespace servobench::bindings
