#include "attribution/base_level_ray.h"

#include <algorithm>
#include <cmath>

#include "shared/vct_shared.h"

namespace vct::attr {

vec3 base_level_ray(const MipSampler& mips, const MarchParams& params, const vec3& origin, const vec3& dir) {
  Cone ray;
  ray.origin = origin;
  ray.direction = dir;
  ray.aperture = 0.0f;  // diameter = max(voxel, 0): lod 0 at every step
  MarchParams p = params;
  p.min_lod = 0.0f;
  return vec3(trace_cone(mips, ray, p));
}

vec3 base_level_cone_steps(const MipSampler& mips, const MarchParams& params, const Cone& cone) {
  // stages/cone_trace.cpp's loop, term for term, with the lookup's lod pinned to 0.
  if (mips.base_size() == 0) return vec3(0.0f);
  const float voxel = 1.0f / float(mips.base_size());
  const float tan_half = std::tan(0.5f * cone.aperture);
  vec3 color(0.0f);
  float alpha = 0.0f;
  float t = params.start_offset;
  while (alpha < 1.0f && t < params.max_distance) {
    const vec3 pos = cone.origin + cone.direction * t;
    if (!(pos.x >= 0.0f && pos.y >= 0.0f && pos.z >= 0.0f && pos.x <= 1.0f && pos.y <= 1.0f && pos.z <= 1.0f)) break;
    const float diameter = std::max(voxel, 2.0f * t * tan_half);
    const vec4 s = mips.sample(pos, 0.0f, cone.direction);
    const float transmit = 1.0f - alpha;
    color += transmit * vec3(s);
    alpha += transmit * s.a;
    t += std::max(diameter * params.quality, 1e-6f);
  }
  return color;
}

vec3 direction_in_cone(const vec3& axis, float aperture, vec2 u) {
  // Uniform in solid angle: cos(theta) uniform on [cos(half), 1].
  const float cos_half = std::cos(0.5f * aperture);
  const float cos_t = 1.0f - u.x * (1.0f - cos_half);
  const float sin_t = std::sqrt(std::max(0.0f, 1.0f - cos_t * cos_t));
  const float phi = 2.0f * kPi * u.y;
  const sh::Frame f = sh::frame_from_normal(axis);
  return glm::normalize(sh::frame_to_world(f, vec3(sin_t * std::cos(phi), sin_t * std::sin(phi), cos_t)));
}

uint64_t pixel_seed(int x, int y, int width, uint32_t stream, uint32_t seed, uint32_t salt) {
  // SplitMix64 finaliser over the packed key: distinct keys give unrelated PCG seeds.
  uint64_t z = (uint64_t(uint32_t(y) * uint32_t(width) + uint32_t(x)) << 32) ^
               (uint64_t(stream) << 24) ^ (uint64_t(salt) << 16) ^ uint64_t(seed) * 0x9E3779B97F4A7C15ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace vct::attr
