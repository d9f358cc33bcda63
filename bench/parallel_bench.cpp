// parallel_for overhead: many small loops (n = 1..4096 items of ~50 ns each) and one large loop,
// at 1, 2 and 8 workers (8 oversubscribes a 2-core machine). Prints microseconds per loop call.
// Usage: parallel_bench [--calls K]
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "core/parallel.h"

namespace {

double us_per_call(int64_t n, int calls, std::vector<double>& out) {
  const auto t0 = std::chrono::steady_clock::now();
  for (int c = 0; c < calls; ++c) {
    vct::parallel_for(n, [&](int64_t i) {
      double x = double(i);
      for (int k = 0; k < 20; ++k) x = std::sqrt(x + 1.0);
      out[size_t(i)] = x;
    });
  }
  return std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / calls;
}

}  // namespace

int main(int argc, char** argv) {
  int calls = 2000;
  if (argc == 3 && !std::strcmp(argv[1], "--calls")) calls = std::atoi(argv[2]);
  std::vector<double> out(1 << 20);
  std::printf("%8s %10s %14s\n", "threads", "items", "us per call");
  for (int threads : {1, 2, 8}) {
    vct::set_thread_count(threads);
    for (int64_t n : {1, 8, 64, 512, 4096}) std::printf("%8d %10lld %14.2f\n", threads, (long long)n, us_per_call(n, calls, out));
    std::printf("%8d %10d %14.2f\n", threads, 1 << 20, us_per_call(1 << 20, 5, out));
  }
  return 0;
}
