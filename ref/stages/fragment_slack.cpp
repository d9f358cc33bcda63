#include "stages/fragment_slack.h"

#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "stages/direct.h"
#include "stages/direct_slack.h"
#include "stages/texture_slack.h"
#include "stages/voxel_lod.h"

namespace vct {

namespace {

float largest_channel(const vec3& d) { return std::max(d.x, std::max(d.y, d.z)); }

/// The fragment moved by (du, dv) voxels in its triangle's dominant-axis window: barycentrics are
/// affine in window coordinates, so the shift solves [P1 - P0, P2 - P0] (db1, db2) = (du, dv) on
/// the projected vertices (voxel units). Null when the projection is degenerate.
bool shifted_fragment(const Scene& scene, int n, const VoxelFragment& f, double du, double dv,
                      VoxelFragment& out) {
  const uvec3 t = scene.triangles[f.triangle];
  const vec3 w[3] = {scene.positions[t.x], scene.positions[t.y], scene.positions[t.z]};
  const int axis = dominant_axis(w[0], w[1], w[2]);
  const int pu = axis == 0 ? 1 : 0, pv = axis == 2 ? 1 : 2;  // as voxelize_gpu.cpp's window axes
  glm::dvec3 v[3];
  for (int i = 0; i < 3; ++i) v[i] = to_voxel_space(scene, n, w[i]);
  const double a = v[1][pu] - v[0][pu], b = v[2][pu] - v[0][pu];
  const double c = v[1][pv] - v[0][pv], d = v[2][pv] - v[0][pv];
  const double det = a * d - b * c;
  if (std::abs(det) < 1e-300) return false;
  const double db1 = (d * du - b * dv) / det, db2 = (-c * du + a * dv) / det;
  out = f;
  out.b1 = float(double(f.b1) + db1);
  out.b2 = float(double(f.b2) + db2);
  const SurfacePoint sp = interpolate_surface(scene, f.triangle, out.b1, out.b2);
  out.position = sp.position;
  out.normal = sp.normal;
  return true;
}

/// Largest change over the position shifts, every lookup at the reference's own lambdas.
float position_slack(const Scene& scene, const Voxelization& vox, const VoxelFragment& f,
                     const SlotLods& lods, const vec3& value, const std::vector<ShadowMap>& maps,
                     const VctSettings& settings, const BounceLight* bounce) {
  float slack = 0.0f;
  for (int k = 1; k < kTexelShifts; ++k) {  // the four corners (+-s, +-s)
    const double du = (k & 1) ? kVoxelSnapShift : -kVoxelSnapShift;
    const double dv = (k & 2) ? kVoxelSnapShift : -kVoxelSnapShift;
    VoxelFragment g;
    if (!shifted_fragment(scene, vox.n, f, du, dv, g)) continue;
    const SurfaceMaterial m =
        evaluate_material(scene, interpolate_surface(scene, g.triangle, g.b1, g.b2), lods);
    slack = std::max(slack,
                     largest_channel(glm::abs(light_leaving(scene, g, m, maps, settings, bounce) - value)));
  }
  return slack;
}

/// Largest change over every admissible lambda of the slots diffuse light reads, each with the
/// sRGB decode before or after filtering, times the sub-texel weight shifts.
float lookup_slack(const Scene& scene, const VoxelFragment& f, const SurfaceLods& l,
                   const vec3& value, const std::vector<ShadowMap>& maps,
                   const VctSettings& settings, const BounceLight* bounce) {
  // Diffuse light reads albedo (base colour), the normal map and emission; the light mixes them
  // (albedo x n.l + emission), so every combination of the three slots' candidates is tried. A
  // normal map lit at a grazing angle turns a 2^-8 texel shift into a large relative change of
  // n.l, which no share of the voxel's own value bounds.
  static constexpr int kSlots[3] = {kSlotBaseColor, kSlotNormal, kSlotEmissive};
  double cand[3][kMaxLodCandidates];
  int count[3];
  for (int k = 0; k < 3; ++k) count[k] = lod_candidates(l.range[kSlots[k]], cand[k]);
  const SurfacePoint p = interpolate_surface(scene, f.triangle, f.b1, f.b2);
  float slack = 0.0f;
  SlotLods s = l.exact;
  for (int k = 0; k < kTexelShifts; ++k)
    for (int i0 = 0; i0 < count[0]; ++i0)
      for (int i1 = 0; i1 < count[1]; ++i1)
        for (int i2 = 0; i2 < count[2] * 2; ++i2) {  // x2: sRGB decoded before / after filtering
          s.texel_shift = texel_shift(k);
          s.srgb_after_filter = i2 >= count[2];
          s.lambda[kSlots[0]] = cand[0][i0];
          s.lambda[kSlots[1]] = cand[1][i1];
          s.lambda[kSlots[2]] = cand[2][i2 % count[2]];
          const vec3 d = glm::abs(
              light_leaving(scene, f, evaluate_material(scene, p, s), maps, settings, bounce) - value);
          slack = std::max(slack, largest_channel(d));
        }
  return slack;
}

/// Largest change over the 8-bit precision of the filtered normal-map texel (kUnorm8Step per
/// channel), at the reference's position and lambdas.
float normal_precision_slack(const Scene& scene, const VoxelFragment& f, const SlotLods& lods,
                             const vec3& value, const std::vector<ShadowMap>& maps,
                             const VctSettings& settings, const BounceLight* bounce) {
  const SurfacePoint p = interpolate_surface(scene, f.triangle, f.b1, f.b2);
  SlotLods s = lods;
  float slack = 0.0f;
  for (int k = 0; k < kUnorm8Corners; ++k) {
    s.normal_texel_offset = unorm8_corner(k);
    const vec3 d =
        glm::abs(light_leaving(scene, f, evaluate_material(scene, p, s), maps, settings, bounce) - value);
    slack = std::max(slack, largest_channel(d));
  }
  return slack;
}

/// GL LINEAR's 8-bit sub-texel weights on a shadow sampler (an engine's shadow_compare = linear):
/// each tap's bilinear blend of compares moves by at most 2^-8 + 2^-8 = 2^-7 (its derivative in
/// each weight is at most 1), so does the mean over the taps, and the fragment's light from each
/// light by 2^-7 of that light's unshadowed contribution (docs/compare.md, the engine's PCF row).
float linear_compare_slack(const Scene& scene, const VoxelFragment& f, const SlotLods& lods,
                           const VctSettings& settings) {
  const SurfaceMaterial m = evaluate_material(scene, interpolate_surface(scene, f.triangle, f.b1, f.b2), lods);
  // No maps: every light unshadowed; no emission or bounce (no shadow lookup moves them).
  const vec3 open = diffuse_outgoing_radiance(scene, {}, settings, f.position, m.shading_normal, m.albedo);
  return kLinearCompareWeightStep * largest_channel(open);
}

}  // namespace

std::vector<float> fragment_shading_slack(const Scene& scene, const Voxelization& vox,
                                          const std::vector<vec3>& values,
                                          const std::vector<ShadowMap>& maps,
                                          const VctSettings& settings,
                                          const BounceLight* bounce) {
  const std::vector<SurfaceLods> lods = voxel_lods_per_triangle(scene, vox.n);
  std::vector<float> out(vox.fragments.size(), 0.0f);
  parallel_for(int64_t(out.size()), [&](int64_t i) {
    const VoxelFragment& f = vox.fragments[size_t(i)];
    const SurfaceLods& l = lods[f.triangle];
    float slack = position_slack(scene, vox, f, l.exact, values[size_t(i)], maps, settings, bounce);
    const Material& m = scene.materials[scene.triangle_material[f.triangle]];
    if (is_textured(m)) slack += lookup_slack(scene, f, l, values[size_t(i)], maps, settings, bounce);
    if (m.normal_texture.present())
      slack += normal_precision_slack(scene, f, l.exact, values[size_t(i)], maps, settings, bounce);
    if (settings.shadow_compare == ShadowCompare::Linear) slack += linear_compare_slack(scene, f, l.exact, settings);
    out[size_t(i)] = slack;
  });
  return out;
}

Volume voxel_shading_slack(const Voxelization& vox, const std::vector<float>& slack) {
  Volume v(vox.n, vox.n, vox.n, 1);
  v.channel_names = {"slack"};
  // Runs of fragments per voxel (sorted by voxel): the mean of the fragments' slacks bounds how
  // far the voxel's mean may move. Summed in double in fragment order: deterministic.
  size_t b = 0;
  while (b < vox.fragments.size()) {
    size_t e = b;
    double sum = 0.0;
    while (e < vox.fragments.size() && vox.fragments[e].voxel == vox.fragments[b].voxel)
      sum += double(slack[e++]);
    const ivec3 c = vox.fragments[b].voxel;
    *v.voxel(c.x, c.y, c.z) = float(sum / double(e - b));
    b = e;
  }
  return v;
}

}  // namespace vct
