// How the fragments that land in one voxel combine into the stored value (docs/pipeline.md,
// "Reduction" and "Storage"): the exact mean, the shared fixed-point scheme the GL build matches
// bit for bit, and a model of the GPU's RGBA8 compare-and-swap running average with the interval
// of values any fragment order can produce.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/math.h"
#include "core/settings.h"

namespace vct {

/// Order-independent mean of n values: sorted ascending, summed in double, divided, rounded to
/// float once. The same bits for any input order.
float exact_mean(std::vector<float> values);

/// The shared fixed-point reduction of one channel (shared/voxel_fixed_point.h): uint32 sum of
/// fixed_point_encode with wrap-around, then fixed_point_resolve.
float fixed_point_mean(const std::vector<float>& values);

/// What one fragment's channel value v contributes to the reduction `r`: the fixed-point scheme
/// encodes min(max(v, 0), FIXED_POINT_MAX) (shared/voxel_fixed_point.h), the CAS loop
/// clamp(v, 0, 1), the exact mean v itself. Monotone, so an interval [lo, hi] of a fragment's value
/// maps to [reduction_input(lo), reduction_input(hi)]: a fragment whose extrapolated vertex colour
/// turns its light negative adds 0 (large hunt seed 25, docs/compare.md "Campaign 6").
float reduction_input(float v, Reduction r);

/// One step of the OpenGL Insights ch. 22 running average on one 8-bit channel, in the GPU's units
/// (stored s in 0..255 with count c already averaged; new value x = clamp(v,0,1)*255 as float):
/// s' = uint((float(s)*float(c) + x) / float(c+1)).
int cas_step(int s, int count, float x);

/// The value the CAS loop leaves (as s/255) when fragments arrive in the given order.
float cas_sequential(const std::vector<float>& values);

/// Lowest and highest value (as s/255) a correct GPU may leave for any order of `values`:
/// exact subset enumeration for up to kCasExactLimit fragments (admitting both neighbours of
/// floor() where the GPU's division may round across an integer), a proven bound otherwise.
constexpr size_t kCasExactLimit = 8;
struct CasInterval {
  float lo = 0.0f, hi = 0.0f;
};
CasInterval cas_interval(const std::vector<float>& values);
/// The bound alone (used above kCasExactLimit; exposed for tests).
CasInterval cas_interval_bound(const std::vector<float>& values);

/// Storage quantization: RGBA8 UNORM (clamp to [0,1], round to nearest of 255 steps) and IEEE
/// binary16 (round to nearest even, overflow to infinity, subnormals kept).
float quantize_unorm8(float v);
float quantize_half(float v);
float quantize_storage(float v, VoxelStorage storage);

}  // namespace vct
