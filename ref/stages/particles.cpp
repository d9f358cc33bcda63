#include "stages/particles.h"

#include <algorithm>
#include <cmath>

#include "core/parallel.h"

namespace vct {

sh::ParticleEmitterBlock emitter_block(const ParticleEmitter& e) {
  sh::ParticleEmitterBlock b;
  b.origin_count = vec4(e.origin, float(e.count));
  b.spawn_extent_lifetime = vec4(e.spawn_extent, e.lifetime);
  b.velocity_min = vec4(e.velocity_min, 0.0f);
  b.velocity_max = vec4(e.velocity_max, 0.0f);
  b.acceleration = vec4(e.acceleration, 0.0f);
  b.color_size_start = vec4(e.color_start, e.size_start);
  b.color_size_end = vec4(e.color_end, e.size_end);
  return b;
}

std::vector<sh::ParticleState> particles_at(const Scene& scene, float time) {
  std::vector<sh::ParticleState> out;
  for (size_t ei = 0; ei < scene.emitters.size(); ++ei) {
    const sh::ParticleEmitterBlock block = emitter_block(scene.emitters[ei]);
    for (int id = 0; id < scene.emitters[ei].count; ++id) {
      out.push_back(sh::particle_state(block, uint32_t(ei), uint32_t(id), time));
    }
  }
  return out;
}

namespace {

struct ScreenParticle {
  vec3 center;
  float radius;
  vec3 color;
  vec3 plane_normal;  // unit, eye -> centre
  float x0, x1, y0, y1;  // conservative pixel bounds (row 0 = top)
};

// Conservative screen bounds from the projected bounding sphere's corners; a particle crossing
// the near plane gets the whole screen (the per-pixel disc test decides).
ScreenParticle project(const sh::ParticleState& p, const Camera& cam, const mat4& view_proj, int w, int h) {
  ScreenParticle sp;
  sp.center = vec3(p.position_radius);
  sp.radius = p.position_radius.w;
  sp.color = vec3(p.color_age);
  sp.plane_normal = -cam.to_eye(sp.center);
  sp.x0 = 0.0f, sp.x1 = float(w), sp.y0 = 0.0f, sp.y1 = float(h);
  float lo_x = 1e30f, hi_x = -1e30f, lo_y = 1e30f, hi_y = -1e30f;
  for (int c = 0; c < 8; ++c) {
    const vec3 corner = sp.center + sp.radius * vec3(c & 1 ? 1.0f : -1.0f, c & 2 ? 1.0f : -1.0f, c & 4 ? 1.0f : -1.0f);
    const vec4 clip = view_proj * vec4(corner, 1.0f);
    if (clip.w <= 1e-6f) return sp;
    const float sx = (clip.x / clip.w * 0.5f + 0.5f) * float(w);
    const float sy = (0.5f - clip.y / clip.w * 0.5f) * float(h);
    lo_x = std::min(lo_x, sx), hi_x = std::max(hi_x, sx);
    lo_y = std::min(lo_y, sy), hi_y = std::max(hi_y, sy);
  }
  sp.x0 = lo_x, sp.x1 = hi_x, sp.y0 = lo_y, sp.y1 = hi_y;
  return sp;
}

}  // namespace

Image render_particles(const Scene& scene, const GBuffer& g, const VctSettings& s) {
  const int w = g.coverage.width, h = g.coverage.height;
  Image out(w, h, 3);
  out.channel_names = {"R", "G", "B"};
  if (scene.emitters.empty() || !s.particles) return out;
  const Camera& cam = scene.camera;
  const mat4 view_proj = cam.projection(float(w) / float(h)) * cam.view();
  const mat4 inv_view_proj = glm::inverse(view_proj);
  std::vector<ScreenParticle> screen;
  for (const sh::ParticleState& p : particles_at(scene, s.time)) screen.push_back(project(p, cam, view_proj, w, h));
  parallel_rows(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      const float px = float(x) + 0.5f, py = float(y) + 0.5f;
      // Pixel-centre ray through the far plane point (GL NDC: y up, so row 0 = +1).
      const vec2 ndc(2.0f * px / float(w) - 1.0f, 1.0f - 2.0f * py / float(h));
      const vec4 far_h = inv_view_proj * vec4(ndc, 1.0f, 1.0f);
      // Orthographic views start each ray on the near plane; perspective ones at the eye.
      const vec4 near_h = inv_view_proj * vec4(ndc, -1.0f, 1.0f);
      const vec3 origin = cam.orthographic ? vec3(near_h) / near_h.w : cam.position;
      const vec3 dir = glm::normalize(vec3(far_h) / far_h.w - origin);
      const float surface_depth = g.coverage.at(x, y, 0) > 0.0f ? g.depth.at(x, y, 0) : 1.0f;
      vec3 sum(0.0f);
      for (const ScreenParticle& sp : screen) {
        if (px < sp.x0 || px > sp.x1 || py < sp.y0 || py > sp.y1) continue;
        const float denom = glm::dot(dir, sp.plane_normal);
        if (denom <= 1e-6f) continue;
        const float t = glm::dot(sp.center - origin, sp.plane_normal) / denom;
        const vec3 hit = origin + t * dir;
        const float profile = sh::particle_profile(glm::length(hit - sp.center), sp.radius);
        if (profile <= 0.0f) continue;
        const vec4 clip = view_proj * vec4(hit, 1.0f);
        const float depth = clip.z / clip.w * 0.5f + 0.5f;  // window depth, depth range [0,1]
        if (!(depth < surface_depth) || depth < 0.0f) continue;
        sum += sp.color * profile;
      }
      out.set_rgb(x, y, sum);
    }
  });
  return out;
}

std::vector<std::pair<ivec3, vec3>> particle_voxel_light(const Scene& scene, const VctSettings& s, int n) {
  std::vector<std::pair<ivec3, vec3>> out;
  if (scene.emitters.empty() || !s.particles) return out;
  const float voxel_size = scene.volume.size / float(n);
  for (const sh::ParticleState& p : particles_at(scene, s.time)) {
    const vec3 t = scene.volume.to_texture(vec3(p.position_radius)) * float(n);
    const ivec3 v(glm::floor(t));
    if (v.x < 0 || v.y < 0 || v.z < 0 || v.x >= n || v.y >= n || v.z >= n) continue;
    out.emplace_back(v, sh::particle_voxel_radiance(p, voxel_size));
  }
  return out;
}

void add_particles_to_voxels(const Scene& scene, const VctSettings& s, Volume& radiance) {
  // Sequential in particle order: a fixed summation order keeps the bytes thread-independent.
  for (const auto& [v, add] : particle_voxel_light(scene, s, radiance.nx)) {
    if (!radiance.contains(v.x, v.y, v.z)) continue;
    float* px = radiance.voxel(v.x, v.y, v.z);
    for (int c = 0; c < 3; ++c) {
      px[c] += add[c];
      // RGBA8 voxels saturate and quantize like the GL store would.
      if (s.storage == VoxelStorage::Rgba8) px[c] = std::round(std::min(px[c], 1.0f) * 255.0f) / 255.0f;
    }
  }
}

}  // namespace vct
