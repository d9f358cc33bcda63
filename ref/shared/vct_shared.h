// Definitions shared by the CPU reference and the GLSL shaders (docs/pipeline.md): the BRDF, the
// falloff of the three light kinds in both light models, the cone set, the hash and the parameter block layout.
// This file compiles as C++17 (with GLM, inside namespace vct::sh) and as GLSL 4.50 (the GL
// backend prepends "#version 450" and "#define VCT_GLSL 1"). Keep to the common subset:
// no references or out-parameters, no templates, float literals with an 'f' suffix,
// unsigned literals with 'u', structs of vec4/mat4 only for blocks (std140 == C++ layout).
// Mechanisms (rasterization, filtering, marching loops) do NOT belong here: they are written
// twice, independently, on purpose.
#ifndef VCT_SHARED_H
#define VCT_SHARED_H

#ifdef VCT_GLSL
#define VCT_FN
#define VCT_CONST const
#else
#include "core/math.h"
namespace vct {
namespace sh {
using namespace glm;
using uint = glm::uint;
#define VCT_FN inline
#define VCT_CONST constexpr
#endif

VCT_CONST float SH_PI = 3.14159265358979323846f;
VCT_CONST float SH_INV_PI = 0.31830988618379067154f;
VCT_CONST int LIGHT_MODEL_GLTF = 0;
VCT_CONST int LIGHT_MODEL_SEED = 1;
// KHR_lights_punctual kinds (the values of vct::LightKind, so the GL uniform is the enum itself).
VCT_CONST int LIGHT_KIND_SPOT = 0;
VCT_CONST int LIGHT_KIND_POINT = 1;
VCT_CONST int LIGHT_KIND_DIRECTIONAL = 2;
VCT_CONST int MAX_DIFFUSE_CONES = 16;  // settings.diffuse_cone_count is 1..this

// ---------------------------------------------------------------------------------------------
// Cook–Torrance as the seed defines it: GGX/Trowbridge-Reitz D with alpha = roughness^2,
// Schlick Fresnel, Schlick-GGX G with k = (roughness+1)^2/8 (the Disney/UE4 remapping).

// D is written with sin^2(theta_h) = |n x h|^2 instead of 1 - (n.h)^2: near the peak of a smooth
// lobe (alpha^2 ~ 1e-6 at MIN_ROUGHNESS) 1 - (n.h)^2 cancels in float and D came out 3-11 % off
// (and integrated to ~1.08); the cross product keeps full relative precision. Same function, better conditioned:
// (n.h)^2 (a^2 - 1) + 1 == (n.h)^2 a^2 + sin^2 for unit n, h. h below the surface counts as
// n.h = 0 (sin^2 = 1), as the old max(n.h, 0) did.
VCT_FN float ggx_distribution(vec3 n, vec3 h, float roughness) {
  float a = roughness * roughness;
  float a2 = a * a;
  float c = dot(n, h);
  vec3 x = cross(n, h);
  float sin2 = c > 0.0f ? dot(x, x) : 1.0f;
  float cos2 = c > 0.0f ? c * c : 0.0f;
  float d = cos2 * a2 + sin2;
  return a2 / max(SH_PI * d * d, 1e-12f);
}

VCT_FN float schlick_ggx_g1(float n_dot_x, float roughness) {
  float r1 = roughness + 1.0f;
  float k = r1 * r1 / 8.0f;
  return n_dot_x / (n_dot_x * (1.0f - k) + k);
}

// Schlick with an explicit F90: KHR_materials_specular scales both ends by specular_factor,
// so specular_factor = 0 gives F = 0 exactly (a pure Lambertian surface).
VCT_FN vec3 fresnel_schlick(vec3 f0, float f90, float cos_theta) {
  float m = clamp(1.0f - cos_theta, 0.0f, 1.0f);
#if defined(VCT_GLSL) && defined(VCT_FAULT_FRESNEL_EXPONENT_4)
  float m5 = m * m * m * m;  // the GL fault switch (gl/gl_faults.h): exponent 4, issue 13 case 2
#else
  float m5 = m * m * m * m * m;
#endif
  return f0 + (vec3(f90) - f0) * m5;
}

// Surface parameters after texturing, as both the G-buffer and the BRDF see them.
struct SurfacePbr {
  vec3 albedo;       // linear base colour
  float metallic;
  float roughness;   // perceptual, clamped to >= MIN_ROUGHNESS by surface_pbr()
  vec3 f0;           // normal-incidence reflectance
  float f90;         // grazing reflectance (1, or KHR_materials_specular's factor for dielectrics)
};

VCT_CONST float MIN_ROUGHNESS = 0.03f;  // keeps D finite for mirror-like surfaces

VCT_FN SurfacePbr surface_pbr(vec3 albedo, float metallic, float roughness, float specular_factor,
                              vec3 specular_color) {
  SurfacePbr s;
  s.albedo = albedo;
  s.metallic = clamp(metallic, 0.0f, 1.0f);
  s.roughness = clamp(roughness, MIN_ROUGHNESS, 1.0f);
  vec3 dielectric_f0 = min(vec3(0.04f) * specular_color, vec3(1.0f)) * specular_factor;
  s.f0 = mix(dielectric_f0, albedo, s.metallic);
  s.f90 = mix(specular_factor, 1.0f, s.metallic);
  return s;
}

// The diffuse weight kd = (1 - F)(1 - metallic): metals have no diffuse lobe.
VCT_FN vec3 diffuse_weight(SurfacePbr s, vec3 fresnel) { return (vec3(1.0f) - fresnel) * (1.0f - s.metallic); }

// The BRDF's two lobes, kept apart for the path tracer's AOV split (VCT's indirect diffuse and
// specular); cook_torrance is their sum.
struct BrdfLobes {
  vec3 diffuse;   // kd * albedo / pi
  vec3 specular;  // F D G / (4 n.l n.v)
};

// How the BRDF takes the view cosine n.v (the setting n_dot_v, issue 39), where a shading normal
// faces away from the viewer (silhouettes, normal maps): NV_ZERO (ours) leaves both lobes 0 at
// n.v <= 0; NV_ABS uses |n.v| (righier/gidemo's shading); NV_CLAMP uses max(n.v, NV_CLAMP_MIN)
// (Filament's clampNoV, MIN_N_DOT_V = 1e-4). Both are exact operations on the dot product.
VCT_CONST int NV_ZERO = 0;
VCT_CONST int NV_ABS = 1;
VCT_CONST int NV_CLAMP = 2;
VCT_CONST float NV_CLAMP_MIN = 1e-4f;

VCT_FN float view_cosine(float n_dot_v, int mode) {
  if (mode == NV_ABS) return n_dot_v < 0.0f ? -n_dot_v : n_dot_v;
  if (mode == NV_CLAMP) return max(n_dot_v, NV_CLAMP_MIN);
  return n_dot_v;
}

// BRDF lobes f(l, v) (without the n.l cosine) with the view cosine taken as `nv_mode` says. n, v,
// l unit; v and l point away from the surface.
VCT_FN BrdfLobes cook_torrance_lobes_nv(SurfacePbr s, vec3 n, vec3 v, vec3 l, int nv_mode) {
  BrdfLobes b;
  b.diffuse = vec3(0.0f);
  b.specular = vec3(0.0f);
  float n_dot_l = dot(n, l);
  float n_dot_v = view_cosine(dot(n, v), nv_mode);
  if (n_dot_l <= 0.0f || n_dot_v <= 0.0f) return b;
  vec3 h = normalize(v + l);
  vec3 f = fresnel_schlick(s.f0, s.f90, max(dot(h, v), 0.0f));
  float d = ggx_distribution(n, h, s.roughness);
  float g = schlick_ggx_g1(n_dot_l, s.roughness) * schlick_ggx_g1(n_dot_v, s.roughness);
  b.specular = f * (d * g / (4.0f * n_dot_l * n_dot_v));
  b.diffuse = diffuse_weight(s, f) * s.albedo * SH_INV_PI;
  return b;
}

// The oracle's lobes: both 0 where n.v <= 0.
VCT_FN BrdfLobes cook_torrance_lobes(SurfacePbr s, vec3 n, vec3 v, vec3 l) { return cook_torrance_lobes_nv(s, n, v, l, NV_ZERO); }

// BRDF value f(l, v) (without the n.l cosine), the view cosine taken as `nv_mode` says.
VCT_FN vec3 cook_torrance_nv(SurfacePbr s, vec3 n, vec3 v, vec3 l, int nv_mode) {
  BrdfLobes b = cook_torrance_lobes_nv(s, n, v, l, nv_mode);
  return b.diffuse + b.specular;
}

// BRDF value f(l, v) (without the n.l cosine).
VCT_FN vec3 cook_torrance(SurfacePbr s, vec3 n, vec3 v, vec3 l) { return cook_torrance_nv(s, n, v, l, NV_ZERO); }

// ---------------------------------------------------------------------------------------------
// Spot lights. Both models return the irradiance on a surface facing the light (before n.l and
// before shadowing), given the light-to-point distance and the cosine between the spot axis and
// the light-to-point direction.
//  glTF (KHR_lights_punctual): intensity in candela, inverse square law, the extension's
//   reference cone attenuation (a squared linear ramp in cos between outer and inner), and the
//   recommended range window when range > 0.
//  seed: smoothstep(cos outer, cos inner, cos) / (1 + d), intensity unitless.

// A hard spot (innerConeAngle == outerConeAngle: Blender's Blend 0) is the ramp's limit, a step:
// lit strictly inside the outer cone (cos_axis > cos_outer), dark on and outside its edge. Tested
// before any division, so no 0/0 (and no GLSL smoothstep with edge0 >= edge1, which is undefined).
// Tie freedom (docs/compare.md, "Hard spots"): a pixel whose cos_axis lies within float rounding of
// cos_outer may be lit on one backend and dark on the other.
VCT_FN bool spot_is_hard(float cos_inner, float cos_outer) { return cos_inner <= cos_outer; }
VCT_FN float spot_step(float cos_axis, float cos_outer) { return cos_axis > cos_outer ? 1.0f : 0.0f; }

VCT_FN float spot_cone_gltf(float cos_axis, float cos_inner, float cos_outer) {
  if (spot_is_hard(cos_inner, cos_outer)) return spot_step(cos_axis, cos_outer);
  float scale = 1.0f / max(0.001f, cos_inner - cos_outer);
  float t = clamp((cos_axis - cos_outer) * scale, 0.0f, 1.0f);
  return t * t;
}

VCT_FN float range_window(float dist, float range) {
  if (range <= 0.0f) return 1.0f;
  float r = dist / range;
  return clamp(1.0f - r * r * r * r, 0.0f, 1.0f);
}

VCT_FN vec3 spot_irradiance(int model, vec3 color, float intensity, float dist, float cos_axis,
                            float cos_inner, float cos_outer, float range) {
  if (model == LIGHT_MODEL_SEED) {
    float cone = spot_is_hard(cos_inner, cos_outer) ? spot_step(cos_axis, cos_outer)
                                                    : smoothstep(cos_outer, cos_inner, cos_axis);
    return color * intensity * cone / (1.0f + dist);
  }
  return color * intensity * spot_cone_gltf(cos_axis, cos_inner, cos_outer) * range_window(dist, range) /
         max(dist * dist, 1e-8f);
}

// Point lights (KHR_lights_punctual "point"): glTF: candela, inverse square law and the same
// recommended range window as the spot; seed: the seed's spot falloff without its cone,
// intensity / (1 + d).
VCT_FN vec3 point_irradiance(int model, vec3 color, float intensity, float dist, float range) {
  if (model == LIGHT_MODEL_SEED) return color * intensity / (1.0f + dist);
  return color * intensity * range_window(dist, range) / max(dist * dist, 1e-8f);
}

// Directional lights (KHR_lights_punctual "directional"): intensity in lux is the irradiance on a
// surface facing the light; no falloff, no range. The seed had no sun: both models use lux.
VCT_FN vec3 directional_irradiance(vec3 color, float intensity) { return color * intensity; }

// Irradiance of any kind on a surface facing the light (before n.l and shadowing). dist and
// cos_axis are those of spot_irradiance; a directional light ignores both.
VCT_FN vec3 punctual_irradiance(int model, int kind, vec3 color, float intensity, float dist, float cos_axis,
                                float cos_inner, float cos_outer, float range) {
  if (kind == LIGHT_KIND_DIRECTIONAL) return directional_irradiance(color, intensity);
  if (kind == LIGHT_KIND_POINT) return point_irradiance(model, color, intensity, dist, range);
  return spot_irradiance(model, color, intensity, dist, cos_axis, cos_inner, cos_outer, range);
}

// Unit vector from p toward the light: toward its position for spot and point lights (+z when p is
// the position itself), against its direction for a directional light (the sun is infinitely far).
VCT_FN vec3 to_light_direction(int kind, vec3 light_position, vec3 light_direction, vec3 p) {
  if (kind == LIGHT_KIND_DIRECTIONAL) return -normalize(light_direction);
  vec3 to_light = light_position - p;
  float dist = length(to_light);
  return dist > 0.0f ? to_light / dist : vec3(0.0f, 0.0f, 1.0f);
}

// ---------------------------------------------------------------------------------------------
// Hash (PCG-style integer permutation) for random cone rotation and particles: the same bits on
// the CPU and on the GPU for the same key.

VCT_FN uint pcg_hash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

VCT_FN uint hash_combine(uint a, uint b) { return pcg_hash(a ^ (b * 0x9E3779B9u + 0x7F4A7C15u)); }

// Uniform float in [0, 1) from the top 24 bits: exact in binary32 on both sides.
VCT_FN float hash_to_unit(uint h) { return float(h >> 8u) * (1.0f / 16777216.0f); }

// ---------------------------------------------------------------------------------------------
// Diffuse cone set: one cone along the normal and count-1 cones tilted by the same angle from it,
// evenly spaced in azimuth (step 2*pi/(count-1)) starting at azimuth `rotation` (radians). The
// seed's set is count 5, tilt 45 degrees. Directions are in the tangent frame (z = normal).
// The host (C++) computes every number of the set once, from the settings, into this block
// (stages/cone_sets.h, diffuse_cone_block); GLSL reads it as a std140 uniform block, so both
// backends use identical floats for sin/cos of the tilt, the azimuth step and the weights.
struct DiffuseConeBlock {
  vec4 shape;    // x = sin(tilt), y = cos(tilt), z = azimuth step (0 for count 1), w = count
  vec4 weights;  // x = weight of the normal cone, y = weight of each tilted cone, zw unused
};

VCT_FN int diffuse_cone_count(DiffuseConeBlock b) { return int(b.shape.w); }

VCT_FN vec3 diffuse_cone_direction(int i, float rotation, DiffuseConeBlock b) {
  if (i == 0) return vec3(0.0f, 0.0f, 1.0f);
  float phi = rotation + float(i - 1) * b.shape.z;
  float s = b.shape.x;
  return vec3(s * cos(phi), s * sin(phi), b.shape.y);
}

// Weight of cone i, precomputed on the host. Cosine mode: cos(theta_i) / sum_j cos(theta_j)
// (1/T for the normal cone, cos(tilt)/T for the others, T = 1 + (count-1) cos(tilt)), so the
// weighted sum of cone radiances estimates the cosine-weighted mean incident radiance (E / pi);
// the diffuse term is then kd * albedo * that. Seed mode: every cone weighs 1 (the seed's plain
// sum, count x L on a constant environment).
VCT_FN float diffuse_cone_weight(int i, DiffuseConeBlock b) { return i == 0 ? b.weights.x : b.weights.y; }

// Per-pixel, per-frame rotation of the diffuse cone set about the normal, in [0, azimuth step):
// the set repeats every step.
VCT_FN float diffuse_cone_rotation(uint pixel_x, uint pixel_y, uint frame, DiffuseConeBlock b) {
  uint h = hash_combine(hash_combine(pixel_x, pixel_y), frame);
  return hash_to_unit(h) * b.shape.z;
}

// Specular cone aperture (full angle, radians) from perceptual roughness. We use the width of the
// GGX lobe around the mirror direction, 2*atan(alpha) doubled for the reflection (the half vector
// spreads by atan(alpha); reflecting doubles angles), clamped to [MIN_SPECULAR_APERTURE, pi/2].
VCT_CONST float MIN_SPECULAR_APERTURE = 0.0174533f;  // 1 degree
VCT_FN float specular_cone_aperture(float roughness) {
  float a = roughness * roughness;
  return clamp(2.0f * atan(a), MIN_SPECULAR_APERTURE, 0.5f * SH_PI);
}

// Tangent frame with n as z (Frisvad-style branchless basis from Duff et al. 2017): the same frame
// on both sides so rotated cones coincide.
struct Frame {
  vec3 t;
  vec3 b;
  vec3 n;
};
VCT_FN Frame frame_from_normal(vec3 n) {
  float sign_z = n.z >= 0.0f ? 1.0f : -1.0f;
  float a = -1.0f / (sign_z + n.z);
  float b = n.x * n.y * a;
  Frame f;
  f.t = vec3(1.0f + sign_z * n.x * n.x * a, sign_z * b, -sign_z * n.x);
  f.b = vec3(b, sign_z + n.y * n.y * a, -n.y);
  f.n = n;
  return f;
}
VCT_FN vec3 frame_to_world(Frame f, vec3 local) { return f.t * local.x + f.b * local.y + f.n * local.z; }


// ---------------------------------------------------------------------------------------------
// Fire particles (the seed's stateless particle system): nothing is stored; particle `id` of an
// emitter at time `time` is a pure function of (emitter index, id, time) and the emitter block.
// Particle id is born at id/count*lifetime and respawns every lifetime; each life (cycle) draws
// fresh uniform randoms from the hash of (emitter, id, cycle). Position follows uniformly
// accelerated motion from a random point of the spawn box with a random velocity in
// [velocity_min, velocity_max]; colour and radius go linearly from start to end over the life.

struct ParticleEmitterBlock {
  vec4 origin_count;            // xyz world origin, w = particle count
  vec4 spawn_extent_lifetime;   // xyz half-size of the spawn box, w = lifetime (seconds)
  vec4 velocity_min;            // xyz
  vec4 velocity_max;            // xyz
  vec4 acceleration;            // xyz
  vec4 color_size_start;        // rgb linear radiance, w = world radius
  vec4 color_size_end;          // rgb, w = radius
};

struct ParticleState {
  vec4 position_radius;  // xyz world position, w = world radius
  vec4 color_age;        // rgb linear radiance, w = age / lifetime in [0, 1)
};

VCT_FN float particle_random(uint key, uint k) { return hash_to_unit(hash_combine(key, k)); }

VCT_FN ParticleState particle_state(ParticleEmitterBlock e, uint emitter, uint id, float time) {
  float lifetime = max(e.spawn_extent_lifetime.w, 1e-6f);
  float count = max(e.origin_count.w, 1.0f);
  float since_birth = time - float(id) / count * lifetime;
  float cycle = floor(since_birth / lifetime);
  float age = since_birth - cycle * lifetime;
  // The cycle may be negative before the first birth: int -> uint keeps the bit pattern on both
  // sides, so the key is the same.
  uint key = hash_combine(hash_combine(emitter, id), uint(int(cycle)));
  vec3 r_spawn = vec3(particle_random(key, 0u), particle_random(key, 1u), particle_random(key, 2u));
  vec3 r_vel = vec3(particle_random(key, 3u), particle_random(key, 4u), particle_random(key, 5u));
  vec3 spawn = vec3(e.origin_count) + (r_spawn * 2.0f - vec3(1.0f)) * vec3(e.spawn_extent_lifetime);
  vec3 velocity = mix(vec3(e.velocity_min), vec3(e.velocity_max), r_vel);
  vec3 position = spawn + velocity * age + vec3(e.acceleration) * (0.5f * age * age);
  float u = clamp(age / lifetime, 0.0f, 1.0f);
  ParticleState p;
  p.position_radius = vec4(position, mix(e.color_size_start.w, e.color_size_end.w, u));
  p.color_age = vec4(mix(vec3(e.color_size_start), vec3(e.color_size_end), u), u);
  return p;
}

// Splat profile of a particle: a camera-facing disc of radius r whose emitted radiance falls off
// as colour * (1 - (rho/r)^2) at distance rho from the centre in the disc plane.
VCT_FN float particle_profile(float rho, float radius) {
  float q = rho / max(radius, 1e-8f);
  return max(1.0f - q * q, 0.0f);
}

// What one particle adds to the radiance of the voxel holding its centre (added, not averaged):
// the disc's mean profile (1/2) times its area over a voxel face, so a cone looking through the
// voxel sees the disc's power spread over the voxel's cross-section.
VCT_FN vec3 particle_voxel_radiance(ParticleState p, float voxel_size) {
  float r = p.position_radius.w;
  return vec3(p.color_age) * (0.5f * SH_PI * r * r / (voxel_size * voxel_size));
}

// ---------------------------------------------------------------------------------------------
// Opacity step correction (settings.opacity_step_correction; docs/pipeline.md, "Cone marching"):
// a voxel's opacity a holds for a path of one voxel of its level (dt0 = 2^lod / N); a sample
// standing for a step dt of the same medium has opacity 1 - (1 - a)^(dt / dt0), the standard
// volume-rendering correction (Engel et al., Real-Time Volume Graphics, ch. 9 "opacity correction").
// Premultiplied radiance scales by the same factor as the opacity (a'/a, and dt/dt0 as a -> 0,
// the optically thin limit), so the sample's colour over opacity is unchanged.
VCT_FN float step_corrected_opacity(float a, float step_ratio) {
  return 1.0f - pow(clamp(1.0f - a, 0.0f, 1.0f), step_ratio);
}
VCT_FN vec4 step_corrected_sample(vec4 s, float step_ratio) {
  float a = step_corrected_opacity(s.w, step_ratio);
  float scale = s.w > 0.0f ? a / s.w : step_ratio;
  return vec4(vec3(s) * scale, a);
}

// ---------------------------------------------------------------------------------------------
// glTF 2.0 alphaMode (§3.9.4 "Alpha Coverage"): the one test every pass that rasterizes or traces
// applies to the base-colour alpha (base_color_factor.a x texture alpha). MASK discards a surface
// point whose alpha is below alphaCutoff; BLEND is treated as MASK at a fixed cutoff of 1/2, the
// only reading whose meaning is the same in the G-buffer, the shadow maps, the voxels and the path
// tracer (docs/scenes.md, "Alpha modes"). The alpha fetch itself is each engine's own.
VCT_CONST int ALPHA_MODE_OPAQUE = 0;
VCT_CONST int ALPHA_MODE_MASK = 1;
VCT_CONST int ALPHA_MODE_BLEND = 2;
VCT_CONST float BLEND_ALPHA_CUTOFF = 0.5f;

VCT_FN float effective_alpha_cutoff(int mode, float cutoff) {
  return mode == ALPHA_MODE_BLEND ? BLEND_ALPHA_CUTOFF : cutoff;
}

// True when the surface point is not there (discard the fragment, ignore the ray hit).
VCT_FN bool alpha_discards(int mode, float alpha, float cutoff) {
  return mode != ALPHA_MODE_OPAQUE && alpha < effective_alpha_cutoff(mode, cutoff);
}

#ifndef VCT_GLSL
}  // namespace sh
}  // namespace vct
#endif

#endif  // VCT_SHARED_H
