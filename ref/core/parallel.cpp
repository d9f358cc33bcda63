#include "core/parallel.h"

#include <algorithm>

#include <omp.h>

#ifdef VCT_TSAN_THREADS
#include <atomic>
#include <thread>
#include <vector>
#endif

namespace vct {

namespace {
int g_threads = 0;

// Items handed out per grab: about 8 grabs per worker, so uneven rows still balance while the
// shared counter is touched n/chunk times instead of n times (with dynamic,1 and more workers
// than cores, small loops spent ~100x their work contending for it).
int64_t chunk_size(int64_t n, int workers) { return std::max<int64_t>(1, n / (int64_t(workers) * 8)); }

#ifdef VCT_TSAN_THREADS
// ThreadSanitizer builds: GCC's libgomp is not instrumented, so TSan cannot see its barriers and
// reports every write-in-loop / read-after-loop pair as a race. The same dynamic chunked schedule
// on std::thread + an atomic counter is fully visible to TSan, so what it reports is ours.
void run_on_std_threads(int64_t n, int workers, int64_t chunk, const std::function<void(int64_t)>& body) {
  std::atomic<int64_t> next{0};
  auto work = [&] {
    for (int64_t begin; (begin = next.fetch_add(chunk)) < n;) {
      for (int64_t i = begin; i < std::min(n, begin + chunk); ++i) body(i);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
}
#endif
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
#ifdef VCT_TSAN_THREADS
  run_on_std_threads(n, workers, chunk, body);
  return;
#endif
#pragma omp parallel for schedule(dynamic, chunk) num_threads(workers)
  for (int64_t i = 0; i < n; ++i) body(i);
}

}  // namespace vct
