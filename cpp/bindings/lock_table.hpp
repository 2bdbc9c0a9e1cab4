// The per-object locks of the bindings (object_lock.hpp), without Python: a table of two recursive mutexes per
// object address. Kept free of pybind11 so the C++ thread stress test (tests/cpp/test_thread_stress.cpp, run
// under ThreadSanitizer) drives the same protocol the Python bindings use.
#pragma once

#include <cstddef>
#include <memory>
#include <mutex>
#include <unordered_map>

namespace servobench::bindings {

struct ObjectLocks {
  std::recursive_mutex run;
  std::recursive_mutex state;
};

namespace detail {
struct LockTable {
  std::mutex mutex;
  std::unordered_map<const void*, std::shared_ptr<ObjectLocks>> locks;
};
inline LockTable& lock_table() {
  static auto* table = new LockTable();  // never destroyed
  return *table;
}
}  // namespace detail

// The locks of the object at `key`, created on first use. An address a later object reuses keeps its (unlocked)
// entry: the table holds one small entry per address ever locked, which the allocator's reuse keeps few.
inline std::shared_ptr<ObjectLocks> locks_of(const void* key) {
  auto& t = detail::lock_table();
  std::lock_guard<std::mutex> g(t.mutex);
  auto& slot = t.locks[key];
  if (!slot) slot = std::make_shared<ObjectLocks>();
  return slot;
}

// The locks of keys[0..n) into out[0..n): locks_of of each, under one lock of the table (Card.step's five or nine
// objects, once per call: decision FV25).
inline void locks_of(const void* const* keys, std::size_t n, std::shared_ptr<ObjectLocks>* out) {
  auto& t = detail::lock_table();
  std::lock_guard<std::mutex> g(t.mutex);
  for (std::size_t i = 0; i < n; ++i) {
    auto& slot = t.locks[keys[i]];
    if (!slot) slot = std::make_shared<ObjectLocks>();
    out[i] = slot;
  }
}

// From now on the object at `key` (a vendor module a card owns) uses the locks of `owner` (its card), so its
// methods wait for the card's running chunk like the card's own. Undone by forget_locks(key) when the owner goes.
inline void share_locks(const void* key, const void* owner) {
  auto& t = detail::lock_table();
  std::lock_guard<std::mutex> g(t.mutex);
  auto& o = t.locks[owner];
  if (!o) o = std::make_shared<ObjectLocks>();
  t.locks[key] = o;
}

inline void forget_locks(const void* key) {
  auto& t = detail::lock_table();
  std::lock_guard<std::mutex> g(t.mutex);
  t.locks.erase(key);
}

}  // namespace servobench::bindings
