#include "core/parallel.h"

#include <omp.h>

namespace vct {

namespace {
int g_threads = 0;
}

void set_thread_count(int threads) {
  g_threads = threads;
  if (threads > 0) omp_set_num_threads(threads);
}

int thread_count() { return g_threads > 0 ? g_threads : omp_get_max_threads(); }

void parallel_for(int64_t n, const std::function<void(int64_t)>& body) {
#pragma omp parallel for schedule(dynamic, 1) num_threads(thread_count())
  for (int64_t i = 0; i < n; ++i) body(i);
}

}  // namespace vct
