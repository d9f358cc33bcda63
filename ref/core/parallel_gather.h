// Items made per index in parallel and gathered in index order: what a vector per index gives,
// without one heap block per index. A million-triangle mesh made a million small vectors per
// voxelization and per raster set-up, and the freed blocks stay in the worker threads' heaps
// (docs/performance.md, memory on heightfields). Indices are taken in fixed blocks, each block's
// items kept in one vector, and the blocks joined in order: the same items in the same order for
// any thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "core/parallel.h"

namespace vct {

/// Indices per block: large enough that a block's vector is not a small allocation, small enough
/// that the blocks balance over the workers.
constexpr int64_t kGatherBlock = 1024;

/// Calls body(i, out) for i in [0, n) on the worker threads, `out` a vector body appends index i's
/// items to; returns every item, index by index in order, each index's in the order appended.
template <class T, class Body>
std::vector<T> parallel_gather(int64_t n, Body&& body) {
  const int64_t blocks = (n + kGatherBlock - 1) / kGatherBlock;
  std::vector<std::vector<T>> per_block(static_cast<size_t>(blocks > 0 ? blocks : 0));
  parallel_for(blocks, [&](int64_t b) {
    std::vector<T>& out = per_block[static_cast<size_t>(b)];
    const int64_t end = (b + 1) * kGatherBlock < n ? (b + 1) * kGatherBlock : n;
    for (int64_t i = b * kGatherBlock; i < end; ++i) body(i, out);
  });
  size_t total = 0;
  for (const std::vector<T>& v : per_block) total += v.size();
  std::vector<T> all;
  all.reserve(total);
  for (std::vector<T>& v : per_block) {
    all.insert(all.end(), v.begin(), v.end());
    std::vector<T>().swap(v);
  }
  return all;
}

}  // namespace vct
