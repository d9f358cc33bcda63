// Punctual lights (spot, point, directional) with shadow maps: the falloff and BRDF come from
// vct_shared.h; the PCF lookup is
// this backend's own (texelFetch of a k x k block of depth texels around the texel holding the
// point, each a binary depth test, averaged).
const int MAX_LIGHTS = 8;
uniform int u_light_count;
uniform int u_light_model;  // LIGHT_MODEL_GLTF / LIGHT_MODEL_SEED
uniform int u_light_kind[MAX_LIGHTS];  // LIGHT_KIND_SPOT / _POINT / _DIRECTIONAL
uniform vec3 u_light_position[MAX_LIGHTS];
uniform vec3 u_light_direction[MAX_LIGHTS];
uniform vec3 u_light_color[MAX_LIGHTS];
uniform float u_light_intensity[MAX_LIGHTS];
uniform float u_light_cos_inner[MAX_LIGHTS];
uniform float u_light_cos_outer[MAX_LIGHTS];
uniform float u_light_range[MAX_LIGHTS];
// Shadow layers: light i's map is layer u_light_layer[i] of u_shadow_maps (a point light's six cube
// faces are layers u_light_layer[i] + face, GL's face order), each with its world -> clip matrix.
const int MAX_SHADOW_LAYERS = 6 * MAX_LIGHTS;
uniform int u_light_layer[MAX_LIGHTS];
uniform mat4 u_shadow_view_proj[MAX_SHADOW_LAYERS];
uniform int u_shadow_size;
uniform int u_pcf_kernel;
uniform float u_shadow_bias;
uniform float u_shadow_normal_offset;  // in units of the least offset that keeps a plane unshadowed
layout(binding = 4) uniform sampler2DArray u_shadow_maps;

// Irradiance on a surface facing light i at world point p (before n.l and shadowing).
vec3 light_irradiance(int i, vec3 p) {
  int kind = u_light_kind[i];
  vec3 l = to_light_direction(kind, u_light_position[i], u_light_direction[i], p);
  float dist = length(u_light_position[i] - p);
  float cos_axis = dot(-l, normalize(u_light_direction[i]));
  return punctual_irradiance(u_light_model, kind, u_light_color[i], u_light_intensity[i], dist, cos_axis,
                             u_light_cos_inner[i], u_light_cos_outer[i], u_light_range[i]);
}

// The BRDF's light vector. normalize() as before issue 14 for positional lights (it may round
// differently from to_light_direction's division, and spot dumps stay byte-identical).
vec3 light_vector(int i, vec3 p) {
  if (u_light_kind[i] == LIGHT_KIND_DIRECTIONAL) return -normalize(u_light_direction[i]);
  return normalize(u_light_position[i] - p);
}

// Fraction of the PCF taps that see p lit (the same taps as ref/stages/shadow_map.cpp):
// k x k texels at floor(texel coordinate + i - (k-1)/2), clamped to the edge; a tap is lit when the
// point's window depth <= stored + bias. Points outside the light's frustum are lit.
float shadow_visibility_2d(int layer, vec3 p) {
  vec4 clip = u_shadow_view_proj[layer] * vec4(p, 1.0f);
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
      float stored = texelFetch(u_shadow_maps, ivec3(t, layer), 0).r;
      if (z <= stored + u_shadow_bias) ++lit;
    }
  }
  return float(lit) / float(k * k);
}

// Cube-map addressing, GL 4.5 §8.13 and Table 8.19, written here from the spec (the CPU's copy is
// ref/stages/cube_map.cpp). Faces 0..5 = +x -x +y -y +z -z; ties go to x, then y (our
// deterministic rule; the spec lets the implementation pick one).
int cube_face_of(vec3 r) {
  vec3 a = abs(r);
  if (a.x >= a.y && a.x >= a.z) return r.x >= 0.0f ? 0 : 1;
  if (a.y >= a.z) return r.y >= 0.0f ? 2 : 3;
  return r.z >= 0.0f ? 4 : 5;
}

// (sc, tc, ma) of Table 8.19 for r on `face`.
vec3 cube_sc_tc_ma(int face, vec3 r) {
  if (face == 0) return vec3(-r.z, -r.y, r.x);
  if (face == 1) return vec3(r.z, -r.y, r.x);
  if (face == 2) return vec3(r.x, r.z, r.y);
  if (face == 3) return vec3(r.x, -r.z, r.y);
  if (face == 4) return vec3(r.x, -r.y, r.z);
  return vec3(-r.x, -r.y, r.z);
}

// Equation 8.6: s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2.
vec2 cube_st(int face, vec3 r) {
  vec3 c = cube_sc_tc_ma(face, r);
  return 0.5f * (c.xy / abs(c.z) + 1.0f);
}

// The direction whose (s, t) on `face` is st (Table 8.19 solved for r with |ma| = 1).
vec3 cube_direction(int face, vec2 st) {
  vec2 c = 2.0f * st - 1.0f;
  if (face == 0) return vec3(1.0f, -c.y, -c.x);
  if (face == 1) return vec3(-1.0f, -c.y, c.x);
  if (face == 2) return vec3(c.x, 1.0f, c.y);
  if (face == 3) return vec3(c.x, -1.0f, -c.y);
  if (face == 4) return vec3(c.x, -c.y, 1.0f);
  return vec3(-c.x, -c.y, -1.0f);
}

// A point light's PCF: k x k texels around p on the face its direction selects; a tap past that
// face's edge reads the texel its (virtual) centre's direction selects on the neighbouring face,
// and compares p's window depth in the face it reads.
float shadow_visibility_cube(int i, vec3 p) {
  vec3 r = p - u_light_position[i];
  if (r == vec3(0.0f)) return 1.0f;
  int size = u_shadow_size;
  int home = cube_face_of(r);
  vec2 uv = cube_st(home, r) * float(size);
  int k = max(u_pcf_kernel, 1);
  float half_k = 0.5f * float(k - 1);
  int lit = 0;
  for (int j = 0; j < k; ++j) {
    for (int i2 = 0; i2 < k; ++i2) {
      int face = home;
      ivec2 t = ivec2(floor(uv + vec2(float(i2), float(j)) - half_k));
      if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, ivec2(size)))) {
        vec3 d = cube_direction(home, (vec2(t) + 0.5f) / float(size));
        face = cube_face_of(d);
        t = clamp(ivec2(floor(cube_st(face, d) * float(size))), ivec2(0), ivec2(size - 1));
      }
      int layer = u_light_layer[i] + face;
      vec4 clip = u_shadow_view_proj[layer] * vec4(p, 1.0f);
      float z = clip.z / clip.w * 0.5f + 0.5f;
      if (!(clip.w > 0.0f) || z < 0.0f || z > 1.0f) {
        ++lit;
        continue;
      }
      if (z <= texelFetch(u_shadow_maps, ivec3(t, layer), 0).r + u_shadow_bias) ++lit;
    }
  }
  return float(lit) / float(k * k);
}

float shadow_visibility(int i, vec3 p) {
  if (u_light_kind[i] == LIGHT_KIND_POINT) return shadow_visibility_cube(i, p);
  return shadow_visibility_2d(u_light_layer[i], p);
}

// Normal-offset bias (ref/stages/shadow_map.h, shadow_lookup_point; docs/pipeline.md "Normal
// offset"): the surface point p with unit normal n is looked up at p + K w n, w = p's clip w
// through its map (a point light: the cube face p's direction selects), K = offset x (2 / S) x
// (R |n.r0| / |r0|^2 + R |n.r1| / |r1|^2), r0, r1 the matrix's rows 0 and 1, R = k / 2 the
// reach of k x k nearest taps in texels.
vec3 shadow_lookup_point(int i, vec3 p, vec3 n) {
  if (u_shadow_normal_offset == 0.0f) return p;
  int layer = u_light_layer[i];
  if (u_light_kind[i] == LIGHT_KIND_POINT) {
    vec3 r = p - u_light_position[i];
    if (r == vec3(0.0f)) return p;
    layer += cube_face_of(r);
  }
  mat4 m = u_shadow_view_proj[layer];
  float w = (m * vec4(p, 1.0f)).w;
  if (!(w > 0.0f)) return p;
  vec3 r0 = vec3(m[0][0], m[1][0], m[2][0]);
  vec3 r1 = vec3(m[0][1], m[1][1], m[2][1]);
  float reach = 0.5f * float(max(u_pcf_kernel, 1));
  float k = u_shadow_normal_offset * (2.0f / float(u_shadow_size)) *
            (reach * abs(dot(n, r0)) / dot(r0, r0) + reach * abs(dot(n, r1)) / dot(r1, r1));
  return p + (k * w) * n;
}

// The PCF visibility of light i at surface point p with unit normal n: direct light and injection.
float surface_visibility(int i, vec3 p, vec3 n) { return shadow_visibility(i, shadow_lookup_point(i, p, n)); }
