// The per-object locks of the bindings (object_lock.hpp), without Python: a table of two recursive mutexes per
// object address. Kept free of pybind11 so the C++ thread stress test (tests/cpp/test_thread_stress.cpp, run
// under ThreadSanitizer) drives the same protocol the Python bindings use.
#pragma once

#include <memory>
#include <mutex>
#include <unordered_map>

namespace servobench::bindings {

struct ObjectLocks {
  std::recursive_mutex run;
  std::recursive_mutex state;
};

// The locks of the object at `key`, created on first use. An address a later object reuses keeps its (unlocked)
// entry: the table holds one small entry per address ever locked, which the allocator's reuse keeps few.
inline std::shared_ptr<ObjectLocks> locks_of(const void* key) {
  static std::mutex table_mutex;
  static auto* table = new std::unordered_map<const void*, std::shared_ptr<ObjectLocks>>();  // never destroyed
  std::lock_guard<std::mutex> g(table_mutex);
  auto& slot = (*table)[key];
  if (!slot) slot = std::make_shared<ObjectLocks>();
  return slot;
}

}  // namespace servobench::bindings
