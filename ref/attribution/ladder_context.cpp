#include "attribution/ladder_context.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/parallel.h"
#include "pt/path_tracer.h"

namespace vct::attr {

LadderContext::LadderContext(const Scene& scene, const Settings& settings, const FrameResult& frame,
                             int rays_per_pixel, PtCache* pt_cache)
    : scene_(scene), settings_(settings), frame_(frame), sampler_(frame.mips), rays_(rays_per_pixel),
      pt_cache_(pt_cache ? pt_cache : &own_cache_) {
  if (rays_ < 1) throw InputError("--rays", "must be >= 1 (got " + std::to_string(rays_) + ")");
  if (!sampler_.usable()) throw std::logic_error("attribution: the frame's mips are not RGBA volumes");
  march_ = MarchParams::from_settings(settings.vct, std::max(sampler_.base_size(), 1));
}

RungImage LadderContext::for_each_pixel(const std::function<void(const PixelSurface&, RungImage&)>& per_pixel) const {
  const GBuffer& g = frame_.gbuffer;
  RungImage out = make_rung(width(), height());
  parallel_rows(height(), [&](int y) {
    for (int x = 0; x < width(); ++x) {
      if (g.coverage.at(x, y, 0) <= 0.0f) continue;
      PixelSurface s;
      s.x = x;
      s.y = y;
      s.p = g.position.rgb(x, y);
      s.n = g.normal.rgb(x, y);
      s.v = scene_.camera.to_eye(s.p);
      s.pbr = sh::surface_pbr(g.albedo.rgb(x, y), g.material.at(x, y, 0), g.material.at(x, y, 1),
                              g.material.at(x, y, 2), g.specular_color.rgb(x, y));
      // The composite's factors (stages/composite.cpp), so the middle rungs add what it adds.
      s.fresnel = sh::fresnel_schlick(s.pbr.f0, s.pbr.f90, std::max(glm::dot(s.n, s.v), 0.0f));
      s.kd_albedo = sh::diffuse_weight(s.pbr, s.fresnel) * s.pbr.albedo;
      per_pixel(s, out);
    }
  });
  return out;
}

const pt::Accumulator& LadderContext::path_traced(uint32_t stream) const {
  PtSettings ps = settings_.pt;
  ps.width = width();
  ps.height = height();
  ps.light_model = settings_.vct.light_model;  // the truth lit as the frame is
  // The rungs read one-bounce AOVs and pt_direct only, complete at any max_depth >= 2
  // (docs/compare.md, "Bias vs cone count"; ref/pt/integrator.cpp credits them at depths 1-2):
  // deeper paths would only cost time.
  ps.max_depth = std::min(ps.max_depth, 2);
  // One seed per stream: the two estimates of a path-traced rung share no random numbers.
  ps.seed = settings_.pt.seed * 16u + stream;
  nlohmann::json key;
  to_json(key, ps);
  const std::string key_text = key.dump();
  auto it = pt_cache_->find(key_text);
  if (it != pt_cache_->end()) return it->second;
  pt::PathTracer tracer(scene_, ps);
  pt::Accumulator acc(ps.width, ps.height);
  tracer.render(acc, uint32_t(ps.spp));
  return pt_cache_->emplace(key_text, std::move(acc)).first->second;
}

const pt::EmbreeScene& LadderContext::embree() const {
  if (!embree_) embree_ = std::make_unique<pt::EmbreeScene>(scene_);
  return *embree_;
}

RungImage image_rung(const Image& img, const Image& mask) {
  RungImage r = make_rung(mask.width, mask.height);
  if (img.empty()) return r;
  for (int y = 0; y < mask.height; ++y)
    for (int x = 0; x < mask.width; ++x) r.value.set_rgb(x, y, img.rgb(x, y));
  return r;
}

RungImage path_traced_rung(const pt::Accumulator& acc, pt::Aov aov) {
  RungImage r = make_rung(acc.width(), acc.height());
  r.value = acc.mean(aov);
  const double n = acc.samples(), n_even = (acc.samples() + 1) / 2, n_odd = acc.samples() / 2;
  if (n_odd < 1) return r;
  // As Accumulator::variance, but of the luminance of the half means (the channels of one path
  // are correlated, so per-channel variances would not add up to the luminance's).
  const double scale = n_even * n_odd / (n * n);
  const auto& sums = acc.sums();
  for (int y = 0; y < acc.height(); ++y)
    for (int x = 0; x < acc.width(); ++x) {
      const double* px = &sums[(size_t(y) * size_t(acc.width()) + size_t(x)) * pt::Accumulator::kValuesPerPixel];
      const double* odd = px + pt::kAovCount * 3;
      const double even_y = 0.2126 * px[aov * 3] + 0.7152 * px[aov * 3 + 1] + 0.0722 * px[aov * 3 + 2];
      const double odd_y = 0.2126 * odd[aov * 3] + 0.7152 * odd[aov * 3 + 1] + 0.0722 * odd[aov * 3 + 2];
      const double d = even_y / n_even - odd_y / n_odd;
      r.lum_var.at(x, y, 0) = float(d * d * scale);
    }
  return r;
}

}  // namespace vct::attr
