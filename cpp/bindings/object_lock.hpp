// Thread safety and Ctrl-C for the objects whose long calls release the GIL (Axis, Card): one run at a time per
// object, every other method serialised with the run's chunks, and pending signals checked between chunks.
//
// Each bound C++ object gets two locks, kept in a table keyed by its address (the core classes stay unchanged):
//   run   held for the whole of a long call (Axis.run, Card.run, run_until_event, sweeps): a second run on the
//         same object waits for the first (with the GIL released, so the first can finish);
//   state held while a chunk of ticks steps (GIL released) and by every other method (GIL held, taken
//         after releasing the GIL if another thread has it). Between chunks the state is free, so the card's
//         scope and registers stay readable and writable while the card runs, as on a real card.
// Lock order (no deadlock): run locks before state locks, the card before its axes, axes by address; nobody
// waits for a lock while holding the GIL.
//
// Interruption: a long call runs in chunks of about kChunkSeconds of work; between chunks it takes the GIL and
// calls PyErr_CheckSignals(), so Ctrl-C raises KeyboardInterrupt within one chunk, with the object consistent
// (it stands at a whole tick; the run's arrays are discarded).
#pragma once

#include <pybind11/pybind11.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "lock_table.hpp"

namespace servobench::bindings {

namespace py = pybind11;

// Locks `m`; if another thread holds it, waits with the GIL released (the caller holds the GIL).
template <class Mutex>
std::unique_lock<Mutex> lock_releasing_gil(Mutex& m) {
  std::unique_lock<Mutex> lk(m, std::try_to_lock);
  if (!lk.owns_lock()) {
    py::gil_scoped_release release;
    lk.lock();
  }
  return lk;
}

// Holds the run locks of a set of objects (a card and its axes) for a whole long call; built with the GIL held.
class RunLock {
 public:
  explicit RunLock(std::vector<const void*> keys) {
    // Keep the first key (the owner) first, the rest by address: one global order.
    if (keys.size() > 2) std::sort(keys.begin() + 1, keys.end());
    for (const void* k : keys) locks_.push_back(locks_of(k));
    for (auto& l : locks_) held_.push_back(lock_releasing_gil(l->run));
  }
  // Locks every object's state for one chunk; call with the GIL released.
  std::vector<std::unique_lock<std::recursive_mutex>> chunk() {
    std::vector<std::unique_lock<std::recursive_mutex>> out;
    for (auto& l : locks_) out.emplace_back(l->state);
    return out;
  }

 private:
  std::vector<std::shared_ptr<ObjectLocks>> locks_;
  std::vector<std::unique_lock<std::recursive_mutex>> held_;
};

// The most a single call may allocate for its recordings, bytes: checked before allocating (issue 21.3).
constexpr double kMaxRecordBytes = 2e9;

// Seconds of work between two checks for Ctrl-C (the issue asks for about 50 ms).
constexpr double kChunkSeconds = 0.02;

// Adapts the chunk size (ticks) so each chunk takes about kChunkSeconds; results do not depend on it.
class ChunkClock {
 public:
  explicit ChunkClock(std::size_t first = 1024) : size_(first) {}
  std::size_t size() const { return size_; }
  void start() { t0_ = std::chrono::steady_clock::now(); }
  void stop() {
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count();
    if (s < 0.5 * kChunkSeconds && size_ < (std::size_t{1} << 22)) size_ *= 2;
    else if (s > 2.0 * kChunkSeconds && size_ > 16) size_ /= 2;
  }

 private:
  std::size_t size_;
  std::chrono::steady_clock::time_point t0_{};
};

// Takes the GIL and raises KeyboardInterrupt (or whatever a signal handler raised) if a signal is pending.
// Call with the GIL released, between chunks.
inline void check_signals() {
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

// The C++ object behind a pybind11 instance (the key of its locks in lock_table.hpp), or null for anything else.
inline void* cpp_object(py::handle h) {
  auto* type = py::detail::get_type_info(Py_TYPE(h.ptr()));
  if (type == nullptr) return nullptr;
  auto* inst = reinterpret_cast<py::detail::instance*>(h.ptr());
  return inst->get_value_and_holder(type).value_ptr();
}

// `f` (a method or a property accessor) wrapped so that each call holds the state lock of the object it is called
// on (keyed by the instance's C++ pointer: its own locks, or its card's once shared, lock_table.hpp). The wrapper
// keeps the wrapped function's docstring, whose first line is its typed signature: help(), the stubs
// (pybind11-stubgen) and the text signature of signatures.hpp read it, so (*args, **kwargs) stays hidden. A method
// bound without a name (cls.attr(n) = cpp_function(...)) has a signature line without one: named here.
inline py::object locked_method(py::object f, const std::string& name, py::handle scope, bool method) {
  if (f.is_none()) return f;
  py::options opts;
  opts.disable_function_signatures();
  const py::object original_doc = py::getattr(f, "__doc__", py::none());
  std::string doc = original_doc.is_none() ? "" : py::str(original_doc).cast<std::string>();
  if (method && !doc.empty() && doc.front() == '(') doc = name + doc;
  return py::cpp_function(
      [f](py::args args, py::kwargs kw) -> py::object {
        std::unique_lock<std::recursive_mutex> lk;
        if (args.size() > 0)
          if (const void* key = cpp_object(args[0])) lk = lock_releasing_gil(locks_of(key)->state);
        // The call's own tuple and dict, passed on as they are (f(*args, **kw) would copy both).
        PyObject* out = PyObject_Call(f.ptr(), args.ptr(), kw.size() > 0 ? kw.ptr() : nullptr);
        if (out == nullptr) throw py::error_already_set();
        return py::reinterpret_steal<py::object>(out);
      },
      py::name(name.c_str()), py::is_method(scope), py::doc(doc.c_str()));
}

// Wraps every method and property of a bound class (except the listed names and dunders other than __repr__)
// so that each call holds the object's state lock: methods then never run between the ticks of a chunk. Used by
// the classes with their own locks (Axis, Card, HomingRun) and by card_locks.cpp for the vendor modules that share
// their card's locks: one wrapper, keyed by the instance pointer.
inline void serialise_methods(py::handle cls, const std::vector<std::string>& except = {}) {
  const py::dict d = cls.attr("__dict__");
  const py::object property = py::module_::import("builtins").attr("property");
  std::vector<std::pair<std::string, py::object>> items;
  for (auto item : d) items.emplace_back(py::str(item.first).cast<std::string>(), py::reinterpret_borrow<py::object>(item.second));
  for (auto& [name, value] : items) {
    if (std::find(except.begin(), except.end(), name) != except.end()) continue;
    if (name.size() > 4 && name.rfind("__", 0) == 0 && name != "__repr__") continue;
    if (py::isinstance(value, property)) {
      py::setattr(cls, name.c_str(),
                  property(locked_method(value.attr("fget"), name, cls, false),
                           locked_method(value.attr("fset"), name, cls, false), py::none(), value.attr("__doc__")));
    } else if (PyInstanceMethod_Check(value.ptr())) {  // a bound C++ method (pybind11 wraps them so)
      py::object fn = py::reinterpret_borrow<py::object>(PyInstanceMethod_GET_FUNCTION(value.ptr()));
      py::setattr(cls, name.c_str(), locked_method(fn, name, cls, true));
    }
  }
}

// Runs `n` ticks as calls `ticks(k)` of at most one chunk each, as a long run does: the run locks of `keys` for the
// whole call, the GIL released, each chunk under the state locks, Ctrl-C checked between chunks. The step API's
// long steps (Axis.step, Card.step) use it; call with the GIL held.
template <class Ticks>
void run_in_chunks(std::vector<const void*> keys, std::size_t n, Ticks&& ticks) {
  RunLock lock(std::move(keys));
  py::gil_scoped_release release;
  ChunkClock clock;
  for (std::size_t done = 0; done < n;) {
    const std::size_t k = std::min(clock.size(), n - done);
    {
      auto held = lock.chunk();
      clock.start();
      ticks(k);
      clock.stop();
    }
    done += k;
    if (done < n) check_signals();
  }
}

}  // namespace servobench::bindings
