#include "compare/partial_gbuffer.h"

#include <algorithm>
#include <cmath>

#include "stages/raster.h"
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

namespace {
// The window-to-world map of position_from_depth in double, so that the margins below are not
// themselves buried in float rounding.
struct WindowUnprojection {
  glm::dmat4 inverse;
  int w, h;
  glm::dvec3 at(double px, double py, double depth) const {
    const glm::dvec4 p = inverse * glm::dvec4(px / w * 2.0 - 1.0, 1.0 - py / h * 2.0, 2.0 * depth - 1.0, 1.0);
    return glm::dvec3(p) / p.w;
  }
  // Where the ray through window point (px, py) meets the plane through p with normal n.
  glm::dvec3 on_plane(double px, double py, const glm::dvec3& p, const glm::dvec3& n) const {
    const glm::dvec3 a = at(px, py, 0.0), b = at(px, py, 1.0);
    return a + (b - a) * (glm::dot(p - a, n) / glm::dot(b - a, n));
  }
};
}  // namespace

Image position_margin_from_depth(const Scene& scene, const GBuffer& g) {
  const int w = g.depth.width, h = g.depth.height;
  const WindowUnprojection window{
      glm::inverse(glm::dmat4(scene.camera.projection(float(w) / float(h))) * glm::dmat4(scene.camera.view())), w, h};
  constexpr double kDepth = 4.0 / 16777216.0, kSnap = kVertexSnapStep, kRounding = 4.0 / 16777216.0;
  Image margin(w, h, 3, 0.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (g.coverage.at(x, y, 0) <= 0.5f) continue;
      const double px = x + 0.5, py = y + 0.5, d = g.depth.at(x, y, 0);
      const glm::dvec3 p = window.at(px, py, d), n(g.normal.rgb(x, y));
      const glm::dvec3 along_ray = glm::abs(window.at(px, py, d + kDepth) - window.at(px, py, d - kDepth)) * 0.5;
      const glm::dvec3 snap_x = glm::abs(window.on_plane(px + kSnap, py, p, n) - window.on_plane(px - kSnap, py, p, n));
      const glm::dvec3 snap_y = glm::abs(window.on_plane(px, py + kSnap, p, n) - window.on_plane(px, py - kSnap, p, n));
      for (int c = 0; c < 3; ++c) {
        // Each snap difference spans two shifts of 2^-8: half of it is one shift's reach.
        const double m = along_ray[c] + 0.5 * (snap_x[c] + snap_y[c]) + kRounding * std::abs(p[c]);
        margin.at(x, y, c) = float(std::isfinite(m) ? std::min(m, double(scene.volume.size)) : double(scene.volume.size));
      }
    }
  return margin;
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
