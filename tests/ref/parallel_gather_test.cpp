// core/parallel_gather.h: items come back index by index, each index's in the order appended,
// across block boundaries and for any thread count.
#include <gtest/gtest.h>
#include <vector>

#include "core/parallel.h"
#include "core/parallel_gather.h"

namespace vct {
namespace {

TEST(ParallelGather, IndexOrderForAnyThreadCount) {
  // Index i yields i % 4 items (i, 0), (i, 1), ...: zero-item indices and blocks of every size.
  const int64_t n = 3 * kGatherBlock + 17;
  std::vector<std::pair<int64_t, int>> serial;
  for (int64_t i = 0; i < n; ++i)
    for (int k = 0; k < int(i % 4); ++k) serial.emplace_back(i, k);
  const int saved = thread_count();
  for (int threads : {1, 2, 3}) {
    set_thread_count(threads);
    const std::vector<std::pair<int64_t, int>> got = parallel_gather<std::pair<int64_t, int>>(
        n, [](int64_t i, std::vector<std::pair<int64_t, int>>& out) {
          for (int k = 0; k < int(i % 4); ++k) out.emplace_back(i, k);
        });
    EXPECT_EQ(got, serial) << threads << " threads";
  }
  set_thread_count(saved);
  EXPECT_TRUE(parallel_gather<int>(0, [](int64_t, std::vector<int>&) {}).empty());
}

}  // namespace
}  // namespace vct
