// Independent tasks that may throw (file writes: a full disk, a read-only directory) run through
// parallel_for. An exception must not leave an OpenMP region, so each task's is caught and kept,
// and the one of the lowest index is rethrown after all have run: the same error for any thread
// count (docs/CONVENTIONS.md, determinism).
#pragma once

#include <cstdint>
#include <exception>
#include <functional>
#include <vector>

#include "core/parallel.h"

namespace vct {

/// Runs task(i) for i in [0, n) on the worker threads; rethrows the lowest-index task's exception.
inline void parallel_tasks(int64_t n, const std::function<void(int64_t)>& task) {
  std::vector<std::exception_ptr> errors(size_t(n > 0 ? n : 0));
  parallel_for(n, [&](int64_t i) {
    try {
      task(i);
    } catch (...) {
      errors[size_t(i)] = std::current_exception();
    }
  });
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace vct
