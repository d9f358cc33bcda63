#include "freedoms/direct_slack.h"

#include <algorithm>
#include <vector>

#include "core/parallel.h"
#include "core/pcf_taps.h"
#include "freedoms/lod_candidates.h"
#include "freedoms/lookup_precision.h"
#include "freedoms/texel_pieces.h"
#include "freedoms/texture_slack.h"
#include "scene/alpha_mask.h"
#include "stages/direct.h"
#include "stages/raster.h"
#include "stages/uv_derivatives.h"

namespace vct {

void add_direct_texture_slack(const Scene& scene, const std::vector<ShadowMap>& maps,
                              const VctSettings& settings, const Image& direct, GBuffer& g,
                              const VisibilityBuffer* camera) {
  const int w = settings.width, h = settings.height;
  if (g.texture_slack.channels <= kSlackDirect || direct.width != w || direct.height != h) return;
  const mat4 view_proj = scene.camera.projection(float(w) / float(h)) * scene.camera.view();
  // The G-buffer keeps no triangle ids: the same visibility again (same rasterizer, same bits),
  // masks ignored. Without an alpha-tested material the G-buffer's own raster is that buffer.
  const bool reuse = camera && camera->width == w && camera->height == h && !scene_has_alpha_test(scene);
  const VisibilityBuffer rendered =
      reuse ? VisibilityBuffer() : render_visibility(scene.positions, scene.triangles, view_proj, w, h);
  const VisibilityBuffer& vb = reuse ? *camera : rendered;
  const WindowBarycentrics wb(view_proj, w, h);
  const vec3 eye = scene.camera.position;
  // Direct light reads albedo, metallic, roughness and the shading normal; not emission.
  static constexpr int kSlots[3] = {kSlotBaseColor, kSlotMetallicRoughness, kSlotNormal};
  parallel_rows(h, [&](int row) {
    for (int x = 0; x < w; ++x) {
      const size_t i = vb.index(x, row);
      if (vb.triangle[i] < 0) continue;
      const uint32_t tri = uint32_t(vb.triangle[i]);
      // Untextured surfaces too: the snapped sample point moves the interpolated normal (a dense
      // smooth mesh at a grazing angle) and the shadow-map lookup (a PCF tap at a texel edge).
      // Combinations that would give a material already tried are left out (scene/surface.h,
      // material_reads_lods): the slack is a maximum, so that changes no bit. An untextured
      // material reads no lods: one combination, at default lods.
      const Material& material = scene.materials[scene.triangle_material[tri]];
      const bool reads_lods = material_reads_lods(material);
      const SurfaceLods lods =
          reads_lods ? pixel_lods(scene, tri, ScreenBarycentrics(scene, tri, view_proj, w, h), x, h - 1 - row)
                     : SurfaceLods();
      double cand[3][kMaxLodCandidates];
      int count[3];
      for (int k = 0; k < 3; ++k) count[k] = reads_lods ? lod_candidates(lods.range[kSlots[k]], cand[k]) : 1;
      if (!reads_lods)
        for (int k = 0; k < 3; ++k) cand[k][0] = 0.0;
      const int orders = material_reads_srgb_order(material) ? 2 : 1;
      // The centre, the corners and a point in every NEAREST texel piece of the snap square
      // (freedoms/texel_pieces.h).
      thread_local std::vector<SurfacePoint> points;
      const int n = snap_surface_points(scene, wb, x, row, tri, vb.bary[i], lods, points);
      const vec3 ref = direct.rgb(x, row);
      float slack = 0.0f;
      SlotLods l = lods.exact;
      for (size_t p = 0; p < points.size(); ++p)
        for (int i0 = 0; i0 < count[0]; ++i0)
          for (int i1 = 0; i1 < count[1]; ++i1)
            for (int i2 = 0; i2 < count[2] * orders;
                 ++i2) {  // x2: sRGB decoded before / after filtering
              l.srgb_after_filter = i2 >= count[2];
              l.lambda[kSlots[0]] = cand[0][i0];
              l.lambda[kSlots[1]] = cand[1][i1];
              l.lambda[kSlots[2]] = cand[2][i2 % count[2]];
              const SurfaceMaterial m = evaluate_material(scene, points[p], l);
              const vec3 nrm = vb.front_facing[i] ? m.shading_normal : -m.shading_normal;
              const vec3 v = glm::normalize(eye - points[p].position);
              const vec3 d = glm::abs(
                  direct_radiance(scene, maps, settings, points[p].position, nrm, v, m) - ref);
              slack = std::max(slack, std::max(d.x, std::max(d.y, d.z)));
            }
      // Plus the normal map's 8-bit lookup precision at the centre (freedoms/lookup_precision.h
      // kUnorm8Step), a freedom independent of the above: the sum bounds both (as the voxels').
      float precision = 0.0f;
      if (n > 0 && scene.materials[scene.triangle_material[tri]].normal_texture.present())
        for (int k = 0; k < kUnorm8Corners; ++k) {
          SlotLods c = lods.exact;
          c.normal_texel_offset = unorm8_corner(k);
          const SurfaceMaterial m = evaluate_material(scene, points[0], c);
          const vec3 nrm = vb.front_facing[i] ? m.shading_normal : -m.shading_normal;
          const vec3 v = glm::normalize(eye - points[0].position);
          const vec3 d =
              glm::abs(direct_radiance(scene, maps, settings, points[0].position, nrm, v, m) - ref);
          precision = std::max(precision, std::max(d.x, std::max(d.y, d.z)));
        }
      // Plus GL LINEAR's 8-bit sub-texel weights under an engine's linear shadow compare: each
      // light's visibility moves by at most 2^-7 (docs/compare.md, the engine's PCF row), so its
      // light by 2^-7 of what it gives unshadowed (direct_radiance without maps).
      float weights = 0.0f;
      // (Filtering first, the weights move the filtered depth instead: shadow_ties.h's filtered taps.)
      if (n > 0 && settings.shadow_compare == ShadowCompare::Linear && !filters_depth_first(settings)) {
        const SurfaceMaterial m = evaluate_material(scene, points[0], lods.exact);
        const vec3 nrm = vb.front_facing[i] ? m.shading_normal : -m.shading_normal;
        const vec3 v = glm::normalize(eye - points[0].position);
        const vec3 open = direct_radiance(scene, {}, settings, points[0].position, nrm, v, m);
        weights = kLinearCompareWeightStep * std::max(open.x, std::max(open.y, open.z));
      }
      g.texture_slack.at(x, row, kSlackDirect) = slack + precision + weights;
    }
  });
}

}  // namespace vct
