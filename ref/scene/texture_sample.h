// Texture lookups as GL 4.5 §8.14-8.15 define them, written out plainly for the CPU: texel centres
// at i + 1/2, wrap modes per axis, NEAREST / LINEAR within a level, and the level(s) and blend
// weight that the minification filter picks for a given lambda (scene/texture_lod.h). sRGB
// textures are decoded per texel before filtering (SRGB8_ALPHA8, §8.24).
#pragma once

#include <cstdint>

#include "core/math.h"
#include "scene/scene.h"

namespace vct {

/// srgb_to_linear(v / 255) for an 8-bit value (a table of the same expression).
float srgb8_to_linear(uint8_t v);

/// One level: NEAREST (`linear` false) or bilinear (LINEAR) at uv in [0,1] units of that level.
/// `texel_shift` moves the sample point by that many texels of this level: the sub-texel
/// precision GL leaves open (a filter weight quantised to 8 bits is the exact weight at a point
/// at most 2^-8 texel away; docs/compare.md, "Sub-texel weight precision").
vec4 sample_level(const Texture& tex, const uint8_t* texels, int width, int height, vec2 uv,
                  bool linear, bool srgb, vec2 texel_shift = vec2(0.0f));

/// The lookup at scale factor lambda = log2(rho): magnification (lambda <= 0) with the mag
/// filter on level 0, else the min filter over the levels built for `srgb` reads
/// (Texture::mips; absent levels clamp the chain as a texture allocated with fewer levels).
/// `decode_after_filter` (sRGB only): the whole filter (texels and level blend) on the encoded
/// values, RGB decoded once at the end, which GL 4.5 §8.24 allows ("implementations are allowed
/// to perform this conversion after filtering", llvmpipe does); by convexity of the decode it is
/// the lower end of what any staging of the conversion gives, decode-before the upper end.
/// `texel_shift`: as sample_level's, in texels of each level fetched.
vec4 sample_texture_lod(const Texture& tex, vec2 uv, bool srgb, double lambda,
                        bool decode_after_filter = false, vec2 texel_shift = vec2(0.0f));

/// Level 0 with the magnification filter (lambda = 0).
inline vec4 sample_texture(const Texture& tex, vec2 uv, bool srgb) {
  return sample_texture_lod(tex, uv, srgb, 0.0);
}

}  // namespace vct
