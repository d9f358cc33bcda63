// glTF alphaMode MASK (and BLEND, rendered as MASK at 1/2) in every pass that rasterizes: the GLSL
// twin of ref/scene/alpha_mask.cpp. The alpha is base_color_factor.a x the base colour texture's
// alpha (glTF 2.0 §3.9.4; linear in SRGB8_ALPHA8), fetched with the same uniforms and texture unit
// as surface.glsl; the comparison is vct_shared.h's alpha_discards, shared with the CPU.
#include "surface.glsl"
uniform int u_alpha_mode;  // ALPHA_MODE_* (vct_shared.h); 0 = opaque, no fetch
uniform float u_alpha_cutoff;

float base_color_alpha(vec2 uv0, vec2 uv1, float color_alpha) {
  float alpha = u_base_color_factor.a;
  // Level 0, as every engine tests alpha (docs/scenes.md "Alpha modes"): an explicit LOD also needs no
  // derivatives, which are undefined after a discard in non-uniform control flow.
  if (u_tex_present[0] != 0) alpha *= textureLod(u_tex_base, slot_uv(0, uv0, uv1), 0.0f).a;
  return u_vertex_colors != 0 ? alpha * color_alpha : alpha;  // x COLOR_0's alpha
}

// True when the fragment is cut away: the caller discards it (no depth, no colour, no voxel).
bool alpha_masked(vec2 uv0, vec2 uv1, float color_alpha) {
  if (u_alpha_mode == ALPHA_MODE_OPAQUE) return false;
  return alpha_discards(u_alpha_mode, base_color_alpha(uv0, uv1, color_alpha), u_alpha_cutoff);
}
