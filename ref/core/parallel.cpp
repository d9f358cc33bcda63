#include "core/parallel.h"

#include <algorithm>

#include <omp.h>

namespace vct {

namespace {
int g_threads = 0;

// Items handed out per grab: about 8 grabs per worker, so uneven rows still balance while the
// shared counter is touched n/chunk times instead of n times (with dynamic,1 and more workers
// than cores, small loops spent ~100x their work contending for it).
int64_t chunk_size(int64_t n, int workers) { return std::max<int64_t>(1, n / (int64_t(workers) * 8)); }
}  // namespace

void set_thread_count(int threads) {
  g_threads = threads;
  if (threads > 0) omp_set_num_threads(threads);
}

int thread_count() { return g_threads > 0 ? g_threads : omp_get_max_threads(); }

// Which worker runs an item never changes what the item writes (the header's contract), so any
// split of [0, n) gives the same bytes: determinism does not depend on the schedule below.
void parallel_for(int64_t n, const std::function<void(int64_t)>& body) {
  if (n <= 0) return;
  const int workers = int(std::min<int64_t>(thread_count(), n));
  if (workers <= 1 || omp_in_parallel()) {  // nothing to share, or already inside a parallel loop
    for (int64_t i = 0; i < n; ++i) body(i);
    return;
  }
  const int64_t chunk = chunk_size(n, workers);
#pragma omp parallel for schedule(dynamic, chunk) num_threads(workers)
  for (int64_t i = 0; i < n; ++i) body(i);
}

}  // namespace vct
