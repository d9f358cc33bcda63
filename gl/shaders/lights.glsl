// Spot lights with shadow maps: the falloff and BRDF come from vct_shared.h; the PCF lookup is
// this backend's own (texelFetch of a k x k block of depth texels around the texel holding the
// point, each a binary depth test, averaged).
const int MAX_LIGHTS = 8;
uniform int u_light_count;
uniform int u_light_model;  // LIGHT_MODEL_GLTF / LIGHT_MODEL_SEED
uniform vec3 u_light_position[MAX_LIGHTS];
uniform vec3 u_light_direction[MAX_LIGHTS];
uniform vec3 u_light_color[MAX_LIGHTS];
uniform float u_light_intensity[MAX_LIGHTS];
uniform float u_light_cos_inner[MAX_LIGHTS];
uniform float u_light_cos_outer[MAX_LIGHTS];
uniform float u_light_range[MAX_LIGHTS];
uniform mat4 u_light_view_proj[MAX_LIGHTS];
uniform int u_shadow_size;
uniform int u_pcf_kernel;
uniform float u_shadow_bias;
layout(binding = 4) uniform sampler2DArray u_shadow_maps;

// Irradiance on a surface facing light i at world point p (before n.l and shadowing).
vec3 light_irradiance(int i, vec3 p) {
  vec3 to_light = u_light_position[i] - p;
  float dist = length(to_light);
  vec3 l = dist > 0.0f ? to_light / dist : vec3(0.0f, 0.0f, 1.0f);
  float cos_axis = dot(-l, normalize(u_light_direction[i]));
  return spot_irradiance(u_light_model, u_light_color[i], u_light_intensity[i], dist, cos_axis,
                         u_light_cos_inner[i], u_light_cos_outer[i], u_light_range[i]);
}

vec3 light_vector(int i, vec3 p) { return normalize(u_light_position[i] - p); }

// Fraction of the PCF taps that see p lit (the same taps as ref/stages/shadow_map.cpp):
// k x k texels at floor(texel coordinate + i - (k-1)/2), clamped to the edge; a tap is lit when the
// point's window depth <= stored + bias. Points outside the light's frustum are lit.
float shadow_visibility(int i, vec3 p) {
  vec4 clip = u_light_view_proj[i] * vec4(p, 1.0f);
  if (clip.w <= 0.0f) return 1.0f;
  vec3 ndc = clip.xyz / clip.w;
  if (abs(ndc.x) > 1.0f || abs(ndc.y) > 1.0f || abs(ndc.z) > 1.0f) return 1.0f;
  float z = ndc.z * 0.5f + 0.5f;
  float size = float(u_shadow_size);
  vec2 uv = (ndc.xy * 0.5f + 0.5f) * size;
  int k = max(u_pcf_kernel, 1);
  float half_k = 0.5f * float(k - 1);
  int lit = 0;
  for (int j = 0; j < k; ++j) {
    for (int i2 = 0; i2 < k; ++i2) {
      ivec2 t = clamp(ivec2(floor(uv + vec2(float(i2), float(j)) - half_k)), ivec2(0), ivec2(u_shadow_size - 1));
      float stored = texelFetch(u_shadow_maps, ivec3(t, i), 0).r;
      if (z <= stored + u_shadow_bias) ++lit;
    }
  }
  return float(lit) / float(k * k);
}
