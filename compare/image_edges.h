// Where two rasterisations of one frame may legitimately differ (docs/compare.md, "Edges"): the
// edge map (discontinuities, where coverage and shadow-test ties live) and the screen-space slope
// that sub-pixel snapping multiplies. Both are read from the reference only, so a faulty test
// image cannot widen its own tolerance.
#pragma once

#include <cstdint>
#include <vector>

#include "core/image.h"

namespace vct::cmp {

/// A window-depth second difference above this is a discontinuity (a silhouette or a sharp
/// crease), not a slope: window depth is affine in screen space on a plane (GL 4.5 §14.6.1
/// interpolates it without perspective correction), so on a plane the second difference is zero
/// at any resolution.
constexpr double kDepthDiscontinuity = 1e-3;

/// 1 per pixel where rasterisation may tie: local contrast in `ref` (3x3 range > 25% of the 3x3
/// maximum of max |channel|), or, with a depth `hint` of the same size, a window-depth second
/// difference along the row, column or a diagonal above kDepthDiscontinuity.
std::vector<uint8_t> edge_map(const Image& ref, const Image* hint);

/// |d/dx| + |d/dy| of channel `c` of `ref` at (x, y), each the larger of the two one-sided
/// differences inside the image (an attribute is continuous across a crease, so a sample moved
/// to either surface moves by at most the larger secant slope).
double attribute_slope(const Image& ref, int x, int y, int c);

}  // namespace vct::cmp
