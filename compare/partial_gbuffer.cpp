#include "compare/partial_gbuffer.h"

#include "stages/stage_registry.h"

namespace vct::cmp {

namespace st = stage_names;

bool is_partial_gbuffer(const StageSet& set) {
  return set.images.count(st::kGbufferDepth) && set.images.count(st::kGbufferNormal) &&
         !set.has(st::kGbufferPosition);
}

vec3 position_from_depth(const Scene& scene, int w, int h, float px, float py, float depth) {
  // Inverse of check_scene_matches' projection (stage_set_frame.cpp): NDC x, y from the pixel,
  // NDC z = 2 depth - 1 (glDepthRange(0, 1), GL 4.5 §13.6.1), then the perspective divide.
  const mat4 inv = glm::inverse(scene.camera.projection(float(w) / float(h)) * scene.camera.view());
  const vec4 ndc(px / float(w) * 2.0f - 1.0f, 1.0f - py / float(h) * 2.0f, 2.0f * depth - 1.0f, 1.0f);
  const vec4 p = inv * ndc;
  return vec3(p) / p.w;
}

StageSet complete_partial_gbuffer(const StageSet& set, const Scene& scene, const StageSet* reference,
                                  const std::vector<std::string>& needed) {
  StageSet out = set;
  const Image& depth = set.images.at(st::kGbufferDepth);
  const int w = depth.width, h = depth.height;
  std::string filled;
  auto note = [&filled](const std::string& what) { filled += (filled.empty() ? "" : ", ") + what; };
  if (!out.images.count(st::kGbufferCoverage)) {
    Image coverage(w, h, 1, 0.0f);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) coverage.at(x, y, 0) = depth.at(x, y, 0) < 1.0f ? 1.0f : 0.0f;
    out.images[st::kGbufferCoverage] = coverage;
    note("gbuffer.coverage from depth < 1");
  }
  const Image& coverage = out.images.at(st::kGbufferCoverage);
  Image position(w, h, 3, 0.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (coverage.at(x, y, 0) <= 0.5f) continue;
      const vec3 p = position_from_depth(scene, w, h, float(x) + 0.5f, float(y) + 0.5f, depth.at(x, y, 0));
      for (int c = 0; c < 3; ++c) position.at(x, y, c) = p[c];
    }
  out.images[st::kGbufferPosition] = position;
  note("gbuffer.position from depth and the scene camera");
  if (reference)
    for (const std::string& stage : needed)
      if (!out.images.count(stage) && !out.volumes.count(stage) && reference->images.count(stage)) {
        out.images[stage] = reference->images.at(stage);
        note(stage + " from the reference");
      }
  out.info["partial_gbuffer"] = filled;
  return out;
}

}  // namespace vct::cmp
