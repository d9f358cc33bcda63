// Depth-only passes (shadow maps, depth pre-pass): the rasterizer writes depth; no colour. An
// alpha-masked fragment (alpha_mask.glsl) is discarded, so foliage casts leaf-shaped shadows and
// the pre-pass leaves the holes the G-buffer pass leaves.
#include "alpha_mask.glsl"
in vec2 v_uv0;
in vec2 v_uv1;
in vec4 v_color;  // COLOR_0

void main() {
#ifndef VCT_FAULT_ALPHA_SHADOW
  if (alpha_masked(v_uv0, v_uv1, v_color.a)) discard;
#endif
}
