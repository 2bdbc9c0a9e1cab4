// Helpers shared by the binding files: vectors to NumPy arrays, a motion state as a tuple, and the tick-by-tick
// recorder of a profile generator (any object with step(), moving() and a reported position).
#pragma once

#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "flag.hpp"

#include <algorithm>
#include <complex>
#include <cstdlib>
#include <functional>
#include <memory>
#include <new>
#include <string>
#include <vector>

#include "servobench/common/validate.hpp"
#include "servobench/motion/profile.hpp"

namespace servobench::bindings {

template <class T>
pybind11::array_t<T> to_array(const std::vector<T>& v) {
  pybind11::array_t<T> a(static_cast<pybind11::ssize_t>(v.size()));
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

// A float64 array of n samples for a run's recording (decision SP3). From 1 MiB up it is allocated with malloc and
// owned by a capsule instead of NumPy's allocator: NumPy advises the kernel to back arrays of 4 MiB and more with
// transparent huge pages (madvise MADV_HUGEPAGE), and faulting in fresh huge pages cost 18 ns per 8-byte sample on
// the benchmark machine against 3 ns for ordinary pages -- the "10^7-tick cliff" of a run that records the feedback
// only. The array is an ordinary writeable, aligned NumPy array (its base is the capsule).
inline pybind11::array_t<double> output_array(pybind11::ssize_t n) {
  constexpr std::size_t kOwnBytes = std::size_t{1} << 20;
  const std::size_t bytes = static_cast<std::size_t>(n) * sizeof(double);
  if (bytes < kOwnBytes) return pybind11::array_t<double>(n);
  void* p = std::malloc(bytes);
  if (p == nullptr) throw std::bad_alloc();
  pybind11::capsule owner(p, [](void* q) { std::free(q); });
  return pybind11::array_t<double>({n}, {static_cast<pybind11::ssize_t>(sizeof(double))}, static_cast<double*>(p),
                                   owner);
}

inline std::vector<double> real_vector(const pybind11::handle& obj, const char* name) {
  auto a = pybind11::array_t<double, pybind11::array::c_style | pybind11::array::forcecast>::ensure(obj);
  if (!a || a.ndim() != 1) throw pybind11::value_error(std::string(name) + " must be a 1-D array of numbers");
  return std::vector<double>(a.data(), a.data() + a.shape(0));
}
inline std::vector<std::complex<double>> complex_vector(const pybind11::handle& obj, const char* name) {
  auto a = pybind11::array_t<std::complex<double>, pybind11::array::c_style | pybind11::array::forcecast>::ensure(obj);
  if (!a || a.ndim() != 1) throw pybind11::value_error(std::string(name) + " must be a 1-D array of complex numbers");
  return std::vector<std::complex<double>>(a.data(), a.data() + a.shape(0));
}

// A Python callable(done, total) -> bool|None as a C++ progress callback (the GIL taken for the call); empty if None.
// A C++ progress callback (called without the GIL) from a Python one (None: no callback). It also checks for
// Ctrl-C: a pending signal stops the work (the callback returns false) and is kept in `*interrupt`, which the
// binding raises once the C++ call has returned (raise_pending) -- an exception must not cross the C++ solver.
inline std::function<bool(int, int)> progress_callback(const pybind11::object& progress,
                                                       std::shared_ptr<pybind11::error_already_set>* interrupt = nullptr) {
  if (progress.is_none() && interrupt == nullptr) return {};
  const pybind11::object* pp = &progress;  // pointers only: the callback may be copied without the GIL
  return [pp, interrupt](int done, int total) {
    const pybind11::object& progress = *pp;
    if (interrupt != nullptr && *interrupt) return false;
    pybind11::gil_scoped_acquire gil;
    if (interrupt != nullptr && PyErr_CheckSignals() != 0) {
      *interrupt = std::make_shared<pybind11::error_already_set>();
      return false;
    }
    if (progress.is_none()) return true;
    pybind11::object r = progress(done, total);
    return r.is_none() || r.cast<bool>();
  };
}

// Raises the Ctrl-C a progress callback kept (see progress_callback); call with the GIL held.
inline void raise_pending(const std::shared_ptr<pybind11::error_already_set>& interrupt) {
  if (interrupt) throw pybind11::error_already_set(*interrupt);
}

inline pybind11::tuple state_tuple(const motion::MotionState& s) {
  return pybind11::make_tuple(s.pos, s.vel, s.acc, s.jerk);
}

// Steps `ticks` times (or until the motion ends, if until_done), the GIL released; returns arrays pos (whole
// pulses, as reported), pos_exact, vel, acc, jerk in per-tick units.
template <class Step, class Moving, class Reported>
pybind11::dict run_ticks(const char* owner, double ticks, Flag until_done, Step step, Moving moving,
                         Reported reported) {
  check_integer(owner, "ticks", ticks, 0, 1e8);
  std::vector<double> pos, exact, vel, acc, jerk;
  {
    // The GIL stays held (the generator is then never stepped by two threads at once); Ctrl-C is checked every
    // 65536 ticks (a few ms).
    const auto n = static_cast<std::size_t>(ticks);
    for (std::size_t k = 0; k < n; ++k) {
      if ((k & 0xFFFF) == 0xFFFF && PyErr_CheckSignals() != 0) throw pybind11::error_already_set();
      if (until_done && !moving()) break;
      const motion::MotionState& s = step();
      pos.push_back(static_cast<double>(reported()));
      exact.push_back(s.pos);
      vel.push_back(s.vel);
      acc.push_back(s.acc);
      jerk.push_back(s.jerk);
    }
  }
  pybind11::dict d;
  d["pos"] = to_array(pos);
  d["pos_exact"] = to_array(exact);
  d["vel"] = to_array(vel);
  d["acc"] = to_array(acc);
  d["jerk"] = to_array(jerk);
  return d;
}

}  // namespace servobench::bindings
