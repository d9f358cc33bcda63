#include "pt/particle_lights.h"

#include <algorithm>

#include "core/parallel.h"
#include "pt/bsdf_sampling.h"
#include "pt/camera_ray.h"
#include "stages/particles.h"

namespace vct::pt {

namespace {
vec3 intensity_of(const sh::ParticleState& p) {
  const float r = p.position_radius.w;
  return vec3(p.color_age) * (0.5f * kPi * r * r);
}
}  // namespace

ParticleLights::ParticleLights(const Scene& scene, const ParticleOptions& opt) {
  if (!opt.enabled) return;
  std::vector<double> w;
  for (const sh::ParticleState& p : particles_at(scene, opt.time)) {
    const double lum = double(luminance(intensity_of(p)));
    if (!(lum > 0.0)) continue;
    particles_.push_back(p);
    w.push_back(lum);
  }
  pick_ = AliasTable(w);
}

ParticleLights::Sample ParticleLights::sample(float u) const {
  Sample s;
  if (particles_.empty()) return s;
  const size_t i = pick_.sample(u);
  s.position = vec3(particles_[i].position_radius);
  s.intensity = intensity_of(particles_[i]);
  s.pmf = pick_.pmf(i);
  return s;
}

Image ParticleLights::camera_layer(const Scene& scene, const EmbreeScene& rt, int width, int height) const {
  Image out(width, height, 3);
  out.channel_names = {"R", "G", "B"};
  if (particles_.empty()) return out;
  const Camera& cam = scene.camera;
  parallel_rows(height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const Ray ray = camera_ray(cam, width, height, float(x) + 0.5f, float(y) + 0.5f);
      const Hit hit = rt.intersect(ray.org, ray.dir, ray.tnear, ray.tfar);
      const float t_max = hit.hit ? hit.t : ray.tfar;
      vec3 sum(0.0f);
      for (const sh::ParticleState& p : particles_) {  // particle order, as the pipelines add
        const vec3 c(p.position_radius);
        const float r = p.position_radius.w;
        const vec3 n = glm::normalize(c - cam.position);  // disc faces the eye
        const float denom = glm::dot(ray.dir, n);
        if (denom <= 0.0f) continue;
        const float t = glm::dot(c - ray.org, n) / denom;
        if (!(t > ray.tnear && t < t_max)) continue;
        const float rho = glm::length(ray.org + t * ray.dir - c);
        if (rho >= r) continue;
        sum += vec3(p.color_age) * sh::particle_profile(rho, r);
      }
      out.set_rgb(x, y, sum);
    }
  });
  return out;
}

}  // namespace vct::pt
