// The one place threads are started. Work items must write disjoint outputs and never depend on
// which thread runs them: that is what keeps every stage byte-identical for any thread count.
#pragma once

#include <cstdint>
#include <functional>

namespace vct {

/// Sets the worker count for all later parallel loops (0 = all cores).
void set_thread_count(int threads);
int thread_count();

/// Calls body(i) for i in [0, n) on the worker threads; dynamic scheduling, so bodies must not
/// depend on their order or on the thread that runs them.
void parallel_for(int64_t n, const std::function<void(int64_t)>& body);

/// Calls body(y) for every row y in [0, height): the usual image/tile loop.
inline void parallel_rows(int height, const std::function<void(int)>& body) {
  parallel_for(height, [&](int64_t y) { body(int(y)); });
}

}  // namespace vct
