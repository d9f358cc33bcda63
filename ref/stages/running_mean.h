// The non-atomic running mean some engines reduce voxel fragments with (issue 21; the source
// design's renderer): each fragment loads the stored mean s and count c, stores
// (s*c + x)/(c+1) rounded to binary16, with no lock. Racing fragments overwrite each other, so
// the value left is the running mean of some non-empty subset of the voxel's fragments, in some
// order. The reference cannot pick that subset; it states the interval every such value lies in
// (freedoms/reduction_interval.h), and the comparison judges the test against it
// (docs/compare.md, "running-mean-half-interval").
#pragma once

#include <vector>


namespace vct {

/// The value the running mean leaves when the given fragments arrive in this order with no lost
/// update: s_1 = h(x_1), s_k = h((s_{k-1}*(k-1) + x_k)/k) in float32, h = round to binary16.
float running_mean_half_sequential(const std::vector<float>& values);

}  // namespace vct
