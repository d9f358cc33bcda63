// The precision GL leaves a texture lookup (GL 4.5 §8.14.2 leaves filter arithmetic open): the
// sub-texel weight bits and the 8-bit UNORM step a filtered result may be off by. The freedoms
// evaluate the reference's lookup at the corners of those ranges (docs/compare.md, "Texture LOD"
// and "Voxel shading slack").
#pragma once

#include "core/math.h"

namespace vct {

/// Sub-texel weight precision: GL leaves the filter weights' precision open (§8.14.2); current
/// GPUs keep 8 fractional bits (D3D11 functional spec §7.18.16.1, dEQP LookupPrecision), so a
/// weight may be the exact weight of a point up to 2^-8 texel away on each axis of each level.
constexpr float kSubtexelShift = 1.0f / 256.0f;
constexpr int kTexelShifts = 5;
/// Shift k of the lookup's sample point, in texels: k = 0 none, 1..4 the (+-s, +-s) corners
/// (a bilinear lookup is linear in each weight, so its extremes over the square are at corners).
inline vec2 texel_shift(int k) {
  const float s = kSubtexelShift;
  return k == 0 ? vec2(0.0f) : vec2((k & 1) ? s : -s, (k & 2) ? s : -s);
}

/// Precision of a filtered 8-bit UNORM lookup: GL leaves the filtering arithmetic open, and a
/// result may be off by one step of the format (dEQP's texture verifiers take the colour threshold
/// of an 8-bit format as one step; llvmpipe filters RGBA8 in 8-bit integers). A normal map lit at
/// a grazing angle turns that step into a large relative change of n.l (docs/compare.md, "Voxel
/// shading slack").
constexpr float kUnorm8Step = 1.0f / 255.0f;
constexpr int kUnorm8Corners = 8;
/// Corner k of the cube [-kUnorm8Step, kUnorm8Step]^3 (the light is nearly linear-fractional in
/// the texel, so its extremes over the cube lie at corners).
inline vec3 unorm8_corner(int k) {
  const float s = kUnorm8Step;
  return vec3((k & 1) ? s : -s, (k & 2) ? s : -s, (k & 4) ? s : -s);
}

}  // namespace vct
