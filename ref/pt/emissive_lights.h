// Emissive triangles as area lights: Lambertian emitters (radiance independent of direction),
// emitting from the front face (the winding's normal) only, or from both faces when the material
// is double_sided (docs/pathtracer.md). Sampled by area x emission-factor luminance.
#pragma once

#include <cstdint>
#include <vector>

#include "core/math.h"
#include "scene/scene.h"
#include "scene/surface.h"

namespace vct::pt {

/// Radiance a surface point emits toward w (unit, pointing away from the surface).
vec3 emitted_radiance(const Scene& scene, const SurfacePoint& p, const SurfaceMaterial& m, const vec3& w);

class EmissiveTriangles {
 public:
  explicit EmissiveTriangles(const Scene& scene);

  bool empty() const { return triangles_.empty(); }
  size_t size() const { return triangles_.size(); }

  struct Sample {
    uint32_t triangle = 0;
    uint32_t emitter = 0;  // index among the emissive triangles (geometry())
    float b1 = 0.0f, b2 = 0.0f;
    float pdf_area = 0.0f;  // selection probability / triangle area
  };
  /// What a sample of an untextured emitter needs, kept per emissive triangle so that a sample
  /// reads one record instead of the scene's index, position and material arrays: the corners,
  /// the unit geometric normal and the material's constant radiance. position() and the normal
  /// are interpolate_position's expressions, so the bits are the same (docs/performance.md
  /// "Issue 37, session 17").
  struct Geometry {
    vec3 p0, p1, p2;
    vec3 normal;          // glm::normalize(cross(p1 - p0, p2 - p0)), as interpolate_position
    vec3 emission;        // Material::emission(): the radiance where no emissive texture varies it
    bool textured = false;  // an emissive texture: the caller evaluates the material instead
    bool alpha_tested = false;  // glTF MASK/BLEND: a sampled point may be cut away (surface_masked)
    bool double_sided = false;
    vec3 position(float b1, float b2) const { return (1.0f - b1 - b2) * p0 + b1 * p1 + b2 * p2; }
  };
  const Geometry& geometry(const Sample& s) const { return geometry_[s.emitter]; }
  /// Picks a triangle with u_select, then a uniform point on it with u.
  Sample sample(float u_select, vec2 u) const;
  /// The same distribution from one coordinate fewer: x in [0, 1) picks the triangle, and where
  /// it fell inside the triangle's CDF interval, rescaled to [0, 1), is the point's u.x (uniform
  /// given the triangle). A stratified (x, u_y) thus stays stratified over the lights' total area.
  Sample sample_reusing(double x, float u_y) const;
  /// Area density of sample() at any point of `triangle` (0 if it is not an emitter).
  float pdf_area(uint32_t triangle) const { return pdf_area_[triangle]; }

 private:
  std::vector<uint32_t> triangles_;
  std::vector<Geometry> geometry_;  // per emissive triangle, in triangles_' order
  std::vector<double> cdf_;       // inclusive prefix sums, normalised to end at 1
  std::vector<float> pdf_area_;   // per scene triangle
};

}  // namespace vct::pt
