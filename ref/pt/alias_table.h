// Walker's alias method: picks index i with probability w_i / sum(w) in O(1), for the light
// lists the path tracer samples at every vertex (1024 fire particles in the demo room: a binary
// search over their CDF was 4 % of the render). One uniform number per pick, as the CDF used:
// bucket floor(u n), then the bucket's own index or its alias by the rest of u n. With a float u
// the pick resolution is 2^-24 either way.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace vct::pt {

class AliasTable {
 public:
  AliasTable() = default;
  /// weights: finite, >= 0, with a positive sum (callers drop zero-weight entries first).
  explicit AliasTable(const std::vector<double>& weights);

  bool empty() const { return pmf_.empty(); }
  size_t size() const { return pmf_.size(); }
  /// Index for u in [0, 1).
  size_t sample(float u) const;
  /// Probability that sample() returns i: w_i / sum(w).
  float pmf(size_t i) const { return pmf_[i]; }

 private:
  std::vector<double> keep_;     // per bucket: probability of keeping the bucket's own index
  std::vector<uint32_t> alias_;  // per bucket: the index taken otherwise
  std::vector<float> pmf_;
};

}  // namespace vct::pt
