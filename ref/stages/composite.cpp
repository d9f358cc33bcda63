#include "stages/composite.h"

#include <algorithm>

#include "core/parallel.h"
#include "shared/vct_shared.h"

namespace vct {

namespace {
vec3 rgb_or_zero(const Image& img, int x, int y) { return img.empty() ? vec3(0.0f) : img.rgb(x, y); }
}  // namespace

vec3 indirect_fresnel(IndirectFresnel kind, const vec3& f0, float f90, float roughness, float cos_theta) {
  if (kind == IndirectFresnel::Schlick) return sh::fresnel_schlick(f0, f90, cos_theta);
  const float r = std::clamp(roughness, 0.0f, 1.0f);
  const float m = std::clamp(1.0f - cos_theta, 0.0f, 1.0f);
  const float m5 = m * m * m * m * m;
  return f0 + (glm::max(vec3(1.0f - r * r), f0) - f0) * m5;
}

void composite_frame(const Scene& scene, const GBuffer& g, const VctSettings& settings, FrameImages& im) {
  const int w = g.coverage.width, h = g.coverage.height;
  im.diffuse_term = Image(w, h, 3);
  im.specular_term = Image(w, h, 3);
  im.emission = Image(w, h, 3);
  im.final_image = Image(w, h, 3);
  for (Image* img : {&im.diffuse_term, &im.specular_term, &im.emission, &im.final_image}) {
    img->channel_names = {"R", "G", "B"};
  }
  parallel_rows(h, [&](int y) {
    for (int x = 0; x < w; ++x) {
      vec3 total = rgb_or_zero(im.particles, x, y);
      if (g.coverage.at(x, y, 0) > 0.0f) {
        const vec3 p = g.position.rgb(x, y);
        const vec3 n = g.normal.rgb(x, y);
        const vec3 v = scene.camera.to_eye(p);
        const sh::SurfacePbr s = sh::surface_pbr(g.albedo.rgb(x, y), g.material.at(x, y, 0), g.material.at(x, y, 1),
                                                 g.material.at(x, y, 2), g.specular_color.rgb(x, y));
        // n.v: the cosine of the specular cone's axis too (reflect keeps the angle to n), and
        // the split-sum convention for image-based light.
        const vec3 f = indirect_fresnel(settings.indirect_fresnel, s.f0, s.f90, g.material.at(x, y, 1),
                                        std::max(glm::dot(n, v), 0.0f));
        const vec3 diffuse = sh::diffuse_weight(s, f) * s.albedo * rgb_or_zero(im.indirect_diffuse, x, y);
        const vec3 specular = f * rgb_or_zero(im.indirect_specular, x, y);
        const vec3 emission = g.emission.rgb(x, y);
        im.diffuse_term.set_rgb(x, y, diffuse);
        im.specular_term.set_rgb(x, y, specular);
        im.emission.set_rgb(x, y, emission);
        total += rgb_or_zero(im.direct, x, y) + diffuse + specular + emission;
      }
      im.final_image.set_rgb(x, y, total);
    }
  });
}

}  // namespace vct
