// What every rung of every ladder shares (docs/attribution.md): the scene, the settings, the VCT
// frame whose G-buffer, voxel field and images the rungs read, the path tracer's runs (made once
// per stream and shared by the components) and the per-pixel factors by which the composite turns
// incident radiance into the radiance the frame adds (kd x albedo, F).
#pragma once

#include <functional>
#include <map>
#include <memory>

#include "attribution/rung_image.h"
#include "core/settings.h"
#include "pt/accumulator.h"
#include "pt/embree_scene.h"
#include "scene/scene.h"
#include "shared/vct_shared.h"
#include "stages/cone_trace.h"
#include "stages/mip_sampler.h"
#include "stages/stage_types.h"

namespace vct::attr {

/// Path-traced runs keyed by their PtSettings (JSON) and stream: a sweep over VCT settings
/// renders the path tracer once, not once per value.
using PtCache = std::map<std::string, pt::Accumulator>;

/// One covered G-buffer pixel as the rungs see it.
struct PixelSurface {
  int x = 0, y = 0;
  vec3 p{0.0f}, n{0.0f}, v{0.0f};  // world position, unit normal, unit view vector (toward the eye)
  sh::SurfacePbr pbr;
  vec3 kd_albedo{0.0f};            // composite: (1-F(n.v))(1-metallic) albedo
  vec3 fresnel{0.0f};              // composite: F(n.v)
};

class LadderContext {
 public:
  /// `frame` is render_ref_frame(scene, settings) (or any frame with a G-buffer, mips and the
  /// component images); both must outlive the context. rays_per_pixel >= 1.
  /// `pt_cache` (may be null: the context keeps its own) must outlive the context.
  LadderContext(const Scene& scene, const Settings& settings, const FrameResult& frame, int rays_per_pixel,
                PtCache* pt_cache = nullptr);

  const Scene& scene() const { return scene_; }
  const Settings& settings() const { return settings_; }
  const FrameResult& frame() const { return frame_; }
  const MipSampler& mips() const { return sampler_; }
  const MarchParams& march() const { return march_; }
  int rays_per_pixel() const { return rays_; }
  int width() const { return frame_.gbuffer.coverage.width; }
  int height() const { return frame_.gbuffer.coverage.height; }
  const Image& mask() const { return frame_.gbuffer.coverage; }

  /// Runs `per_pixel` on every covered pixel in parallel (each writes its own pixel).
  RungImage for_each_pixel(const std::function<void(const PixelSurface&, RungImage&)>& per_pixel) const;

  /// The path tracer's accumulator for `stream` (rendered on first use, then kept).
  const pt::Accumulator& path_traced(uint32_t stream) const;
  /// The Embree scene (built on first use) for exact visibility.
  const pt::EmbreeScene& embree() const;

 private:
  const Scene& scene_;
  Settings settings_;
  const FrameResult& frame_;
  MipSampler sampler_;
  MarchParams march_;
  int rays_;
  mutable PtCache own_cache_;
  PtCache* pt_cache_;
  mutable std::unique_ptr<pt::EmbreeScene> embree_;
};

/// A deterministic rung: the VCT frame's own image (diffuse_term, specular_term, direct).
RungImage image_rung(const Image& img, const Image& mask);

/// The path tracer's AOV as a rung, with the variance of each pixel's luminance mean from the
/// accumulator's two half-sample sums (pt/accumulator.h).
RungImage path_traced_rung(const pt::Accumulator& acc, pt::Aov aov);

}  // namespace vct::attr
