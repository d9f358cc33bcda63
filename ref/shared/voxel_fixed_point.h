// The deterministic voxel reduction shared by the CPU reference and the GL build (docs/pipeline.md):
// every fragment adds round(value * 2^14) per channel to a uint32 counter with an integer atomic
// add (wrapping modulo 2^32 on both sides), a fourth counter counts fragments, and a resolve pass
// turns (sum, count) into the stored value with integer arithmetic only. Every step is exact in
// IEEE binary32 and uint32, so the two backends agree bit for bit (docs/pipeline.md,
// "Reduction"). Compiles as C++17 (namespace vct::sh) and as GLSL 4.50 (VCT_GLSL defined).
#ifndef VCT_VOXEL_FIXED_POINT_H
#define VCT_VOXEL_FIXED_POINT_H

#ifdef VCT_GLSL
#define VCT_FP_FN
#define VCT_FP_CONST const
#else
#include "core/math.h"
namespace vct {
namespace sh {
#define VCT_FP_FN inline
#define VCT_FP_CONST constexpr
using namespace glm;
using fp_uint = glm::uint;
#endif

#ifdef VCT_GLSL
#define fp_uint uint
#endif

// 2^14: 6.1e-5 resolution; a power of two so value * scale is exact (also under FMA contraction).
VCT_FP_CONST float FIXED_POINT_SCALE = 16384.0f;
VCT_FP_CONST float FIXED_POINT_INV_SCALE = 1.0f / 16384.0f;
// Values are clamped to [0, 1024] before encoding: one fragment adds at most 2^24, so a voxel's
// sum cannot wrap before 256 fragments at the maximum value.
VCT_FP_CONST float FIXED_POINT_MAX = 1024.0f;

// One channel of one fragment. max/min (not clamp) so NaN maps to 0 on both sides.
VCT_FP_FN fp_uint fixed_point_encode(float v) {
  float c = min(max(v, 0.0f), FIXED_POINT_MAX);
  return fp_uint(c * FIXED_POINT_SCALE + 0.5f);
}

// The resolved channel: the rounded integer mean, then an exact scale (float(q) is exact since
// q <= 2^24). Unsigned arithmetic wraps identically in C++ and GLSL.
VCT_FP_FN float fixed_point_resolve(fp_uint sum, fp_uint count) {
  if (count == 0u) return 0.0f;
  fp_uint q = (sum + count / 2u) / count;
  return float(q) * FIXED_POINT_INV_SCALE;
}

#ifdef VCT_GLSL
#undef fp_uint
#else
}  // namespace sh
}  // namespace vct
#endif

#endif  // VCT_VOXEL_FIXED_POINT_H
