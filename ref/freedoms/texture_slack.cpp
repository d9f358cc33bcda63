#include "freedoms/texture_slack.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "freedoms/lod_candidates.h"
#include "freedoms/tangent_handedness.h"
#include "freedoms/texel_pieces.h"

namespace vct {

namespace {

float max_abs_diff(const vec3& a, const vec3& b) {
  const vec3 d = glm::abs(a - b);
  return std::max(d.x, std::max(d.y, d.z));
}

vec4 difference(const SurfaceMaterial& a, const SurfaceMaterial& b) {
  const vec3 ma(a.metallic, a.roughness, a.specular_factor), mb(b.metallic, b.roughness, b.specular_factor);
  return vec4(max_abs_diff(a.shading_normal, b.shading_normal), max_abs_diff(a.albedo, b.albedo), max_abs_diff(ma, mb),
              max_abs_diff(a.emission, b.emission));
}

}  // namespace

bool is_textured(const Material& m) {
  return m.base_color_texture.present() || m.metallic_roughness_texture.present() || m.normal_texture.present() ||
         m.emissive_texture.present();
}

vec4 texture_slack(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                   uint32_t triangle, const vec3& bary, const SurfaceMaterial& centre,
                   const SurfaceLods& lods) {
  // Untextured surfaces move too: the interpolated vertex normal (and COLOR_0's albedo) is an
  // attribute like the texture coordinates, read at the snapped sample point. On a dense smooth
  // mesh seen at a grazing angle that is a large change (scenes/scanned_statue.gltf at 64^2: 0.031
  // next to its silhouette); on flat-shaded triangles it is zero.
  // And a point in every NEAREST texel piece of the snap square (freedoms/texel_pieces.h).
  thread_local std::vector<SurfacePoint> points;
  snap_surface_points(scene, wb, x, row, triangle, bary, lods, points);
  return texture_slack(scene, points.data(), int(points.size()), triangle, centre, lods);
}

vec4 texture_slack(const Scene& scene, const SurfacePoint* points, int n, uint32_t triangle,
                   const SurfaceMaterial& centre, const SurfaceLods& lods) {
  // Each slot's candidates; evaluation j takes the j-th of every slot (the last once a slot has
  // fewer), and each slack channel reads one slot only, so every candidate of every slot is seen.
  double cand[kTextureSlots][kMaxLodCandidates];
  int count[kTextureSlots], rounds = 1;
  for (int slot = 0; slot < kTextureSlots; ++slot) {
    count[slot] = lod_candidates(lods.range[slot], cand[slot]);
    rounds = std::max(rounds, count[slot]);
  }
  vec4 slack(0.0f);
  // On a triangle whose tangents disagree on handedness, each with either bitangent too
  // (freedoms/tangent_handedness.h).
  const int bitangents = handedness_may_flip(scene, triangle) ? 2 : 1;
  // Evaluations that would give a material already tried are left out (scene/surface.h,
  // material_reads_lods): the slack is a maximum, so that changes no bit.
  const Material& material = scene.materials[scene.triangle_material[triangle]];
  if (!material_reads_lods(material)) rounds = 1;
  const int orders = material_reads_srgb_order(material) ? 2 : 1;
  // Each at both ends of where GL may decode sRGB (before or after filtering, GL 4.5 §8.24).
  for (int i = 0; i < n; ++i)
    for (int h = 0; h < bitangents; ++h)
      for (int j = 0; j < rounds; ++j)
        for (int order = 0; order < orders; ++order) {
          const bool after = order == 1;
          SlotLods l;
          for (int slot = 0; slot < kTextureSlots; ++slot)
            l.lambda[slot] = cand[slot][std::min(j, count[slot] - 1)];
          l.srgb_after_filter = after;
          const SurfacePoint& p = h ? with_other_handedness(points[i]) : points[i];
          slack = glm::max(slack, difference(evaluate_material(scene, p, l), centre));
        }
  return slack;
}

}  // namespace vct
