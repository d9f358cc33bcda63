#include "pt/alias_table.h"

#include <algorithm>

namespace vct::pt {

AliasTable::AliasTable(const std::vector<double>& weights) {
  const size_t n = weights.size();
  double total = 0.0;
  for (double w : weights) total += w;
  if (n == 0 || !(total > 0.0)) return;
  keep_.resize(n);
  alias_.resize(n);
  pmf_.resize(n);
  // Vose's construction: scaled weights n w_i / total; each under-full bucket is topped up by one
  // over-full index. Worklists in index order, so the table is the same on every run.
  std::vector<double> scaled(n);
  std::vector<uint32_t> small, large;
  for (size_t i = 0; i < n; ++i) {
    pmf_[i] = float(weights[i] / total);
    scaled[i] = weights[i] / total * double(n);
    alias_[i] = uint32_t(i);
    (scaled[i] < 1.0 ? small : large).push_back(uint32_t(i));
  }
  while (!small.empty() && !large.empty()) {
    const uint32_t s = small.back(), l = large.back();
    small.pop_back();
    keep_[s] = scaled[s];
    alias_[s] = l;
    scaled[l] -= 1.0 - scaled[s];
    if (scaled[l] < 1.0) {
      large.pop_back();
      small.push_back(l);
    }
  }
  // What is left is full up to rounding.
  for (uint32_t i : small) keep_[i] = 1.0;
  for (uint32_t i : large) keep_[i] = 1.0;
}

size_t AliasTable::sample(float u) const {
  const double x = double(u) * double(keep_.size());
  const size_t bucket = std::min(size_t(x), keep_.size() - 1);
  return x - double(bucket) < keep_[bucket] ? bucket : alias_[bucket];
}

}  // namespace vct::pt
