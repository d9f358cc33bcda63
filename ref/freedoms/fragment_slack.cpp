#include "freedoms/fragment_slack.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.h"
#include "core/pcf_taps.h"
#include "core/precision.h"
#include "freedoms/direct_slack.h"
#include "freedoms/direct_ties.h"
#include "freedoms/light_terms.h"
#include "freedoms/lod_candidates.h"
#include "freedoms/lookup_precision.h"
#include "freedoms/snap_visibility.h"
#include "freedoms/snap_window.h"
#include "freedoms/tangent_handedness.h"
#include "freedoms/texel_breakpoints.h"
#include "freedoms/texture_slack.h"
#include "stages/direct.h"
#include "stages/light_sample.h"
#include "stages/raster.h"
#include "stages/shadow_map.h"
#include "stages/voxel_lod.h"

namespace vct {

namespace {

float largest_channel(const vec3& d) { return std::max(d.x, std::max(d.y, d.z)); }

// A fragment's light may be negative: a vertex colour extrapolated beyond its triangle (an MSAA
// sample covered, the centre outside: GL 4.5 §14.9.3) can turn its base colour negative, and
// then more light means a lower value (large hunt seed 24: COLOR_0 at barycentrics (1.11, -2.76,
// 2.64), red -2.3). A light's size, its unshadowed light or a change of it, is therefore its
// largest magnitude, not its largest signed channel.
float largest_magnitude(const vec3& d) { return largest_channel(glm::abs(d)); }

/// The fragment moved by one snap offset, its surface point (surface_at's) and its material at
/// the reference's lambdas: what position_slack and shadow_snap_slack both read, made once.
struct ShiftedSurface {
  VoxelFragment fragment;
  SurfacePoint point;
  SurfaceMaterial material;
};

std::vector<ShiftedSurface> shifted_surfaces(const Scene& scene, const SnapWindow& w, const VoxelFragment& f,
                                             const SlotLods& lods, const std::vector<glm::dvec2>& offsets) {
  std::vector<ShiftedSurface> out(offsets.size());
  for (size_t k = 0; k < offsets.size(); ++k) {
    ShiftedSurface& s = out[k];
    s.fragment = shifted_fragment(scene, w, f, offsets[k].x, offsets[k].y, &s.point);
    s.material = evaluate_material(scene, s.point, lods);
  }
  return out;
}

/// One NEAREST-filtered level a slot's lookup reads at the fragment's own lambda, as a map from
/// window offsets to that level's texel coordinates (freedoms/texel_breakpoints.h).
void nearest_level_maps(const Scene& scene, const SnapWindow& w, const VoxelFragment& f, const SlotLods& lods,
                        std::vector<TexelMap>& out) {
  const Material& m = scene.materials[scene.triangle_material[f.triangle]];
  // Texture coordinates are affine in the window: three points give the map.
  const SurfacePoint at[3] = {surface_at(scene, w, f, 0.0, 0.0), surface_at(scene, w, f, w.reach, 0.0),
                              surface_at(scene, w, f, 0.0, w.reach)};
  for (int slot = 0; slot < kTextureSlots; ++slot) {
    const TextureRef* ref = slot_texture(m, slot);
    if (!ref) continue;
    const glm::dvec2 uv(slot_uv(*ref, at[0]));
    const glm::dvec2 per_u = (glm::dvec2(slot_uv(*ref, at[1])) - uv) / w.reach;
    const glm::dvec2 per_v = (glm::dvec2(slot_uv(*ref, at[2])) - uv) / w.reach;
    append_nearest_level_maps(scene.textures[size_t(ref->texture)], slot_is_srgb(slot), lods.lambda[slot], uv, per_u,
                              per_v, out);
  }
}

/// The window offsets whose light spans the light over the whole snap square: its four corners
/// (+-r, +-r), and where a NEAREST lookup jumps inside it, each texel piece's corners
/// (freedoms/texel_breakpoints.h). Beyond kBreakpointCap points (texels hundreds of times smaller
/// than the snap: a texture sampled far above its resolution without mipmaps) a 16 x 16 grid over
/// the square stands in for them: the one place the square is sampled, not enumerated (each point
/// costs a shading with every light's PCF lookup).
constexpr size_t kBreakpointCap = 512;
std::vector<glm::dvec2> snap_offsets(const Scene& scene, const SnapWindow& w, const VoxelFragment& f,
                                     const SlotLods& lods) {
  const double r = w.reach;
  std::vector<glm::dvec2> out = {{-r, -r}, {r, -r}, {-r, r}, {r, r}};
  std::vector<TexelMap> maps;
  nearest_level_maps(scene, w, f, lods, maps);
  for (const TexelMap& m : maps) {
    if (texel_breakpoints(m, r, kBreakpointCap, out)) continue;
    constexpr int kGrid = 16;
    for (int i = 0; i <= kGrid; ++i)
      for (int j = 0; j <= kGrid; ++j) out.push_back({r * (2.0 * i / kGrid - 1.0), r * (2.0 * j / kGrid - 1.0)});
  }
  return out;
}

/// Largest change over the snap square's offsets (snap_offsets, made into `shifted` by
/// shifted_surfaces), every lookup at the reference's own lambdas and visibility, against the
/// reference's terms `ref` (freedoms/light_terms.h).
float position_slack(const Scene& scene, const std::vector<ShiftedSurface>& shifted, const LightTerms& ref,
                     const std::vector<ShadowMap>& maps, const VctSettings& settings, const BounceLight* bounce) {
  float slack = 0.0f;
  for (const ShiftedSurface& s : shifted)
    slack = std::max(slack, light_change(light_terms(scene, s.fragment, s.material, maps, settings, bounce), ref));
  return slack;
}

/// A light's unshadowed diffuse light, per channel, at a surface point with material `m`, with the
/// signed cosine (negative behind the shading normal; GL's light is its max with 0).
vec3 unshadowed_light(const Light& light, const VctSettings& settings, const vec3& position, const SurfaceMaterial& m) {
  const LightSample ls = sample_light(light, settings.light_model, position);
  return m.albedo * ls.irradiance * glm::dot(m.shading_normal, ls.l) * kInvPi;
}

/// Every material a correct GL may compute at the reference's position, one group per freedom
/// (each group's changes are summed, freedoms/fragment_slack.h):
/// - every admissible lambda of the slots diffuse light reads, each with the sRGB decode before or
///   after filtering, times the sub-texel weight shifts. Diffuse light reads albedo (base colour),
///   the normal map and emission and mixes them (albedo x n.l + emission), so every combination of
///   the three slots' candidates is tried: a normal map lit at a grazing angle turns a 2^-8 texel
///   shift into a large relative change of n.l, which no share of the voxel's own value bounds;
/// - the 8-bit precision of the filtered normal-map texel (kUnorm8Step per channel);
/// - the other bitangent, where the triangle's vertices disagree on the tangent's handedness
///   (freedoms/tangent_handedness.h);
/// - the sRGB decode's precision at both ends (core/precision.h, srgb-decode): the light is
///   monotonic in albedo and emission.
using MaterialGroups = std::vector<std::vector<SurfaceMaterial>>;

std::vector<SurfaceMaterial> lookup_alternatives(const Scene& scene, const SurfacePoint& p, const SurfaceLods& l) {
  static constexpr int kSlots[3] = {kSlotBaseColor, kSlotNormal, kSlotEmissive};
  double cand[3][kMaxLodCandidates];
  int count[3];
  for (int k = 0; k < 3; ++k) count[k] = lod_candidates(l.range[kSlots[k]], cand[k]);
  // A material without an sRGB texture is the same decoded before or after filtering
  // (scene/surface.h, material_reads_srgb_order): each alternative once.
  const int orders = material_reads_srgb_order(scene.materials[scene.triangle_material[p.triangle]]) ? 2 : 1;
  std::vector<SurfaceMaterial> out;
  SlotLods s = l.exact;
  for (int k = 0; k < kTexelShifts; ++k)
    for (int i0 = 0; i0 < count[0]; ++i0)
      for (int i1 = 0; i1 < count[1]; ++i1)
        for (int i2 = 0; i2 < count[2] * orders; ++i2) {  // x2: sRGB decoded before / after filtering
          s.texel_shift = texel_shift(k);
          s.srgb_after_filter = i2 >= count[2];
          s.lambda[kSlots[0]] = cand[0][i0];
          s.lambda[kSlots[1]] = cand[1][i1];
          s.lambda[kSlots[2]] = cand[2][i2 % count[2]];
          out.push_back(evaluate_material(scene, p, s));
        }
  return out;
}

MaterialGroups material_alternatives(const Scene& scene, const VoxelFragment& f, const SurfaceLods& l) {
  const SurfacePoint p = interpolate_surface(scene, f.triangle, f.b1, f.b2);
  const Material& material = scene.materials[scene.triangle_material[f.triangle]];
  MaterialGroups groups;
  if (is_textured(material)) groups.push_back(lookup_alternatives(scene, p, l));
  if (material.normal_texture.present()) {
    std::vector<SurfaceMaterial>& g = groups.emplace_back();
    SlotLods s = l.exact;
    for (int k = 0; k < kUnorm8Corners; ++k) {
      s.normal_texel_offset = unorm8_corner(k);
      g.push_back(evaluate_material(scene, p, s));
    }
  }
  if (handedness_may_flip(scene, f.triangle))
    groups.push_back({evaluate_material(scene, with_other_handedness(p), l.exact)});
  if (material.base_color_texture.present() || material.emissive_texture.present()) {
    std::vector<SurfaceMaterial>& g = groups.emplace_back();
    SlotLods s = l.exact;
    for (float sign : {-1.0f, 1.0f}) {
      s.srgb_decode_steps = sign * float(precision(Precision::SrgbDecode));
      g.push_back(evaluate_material(scene, p, s));
    }
  }
  return groups;
}

/// Each group's largest change of the fragment's light against the reference's terms `ref`
/// (freedoms/light_terms.h), summed over the groups.
float material_slack(const Scene& scene, const VoxelFragment& f, const MaterialGroups& groups, const LightTerms& ref,
                     const std::vector<ShadowMap>& maps, const VctSettings& settings, const BounceLight* bounce) {
  float slack = 0.0f;
  for (const std::vector<SurfaceMaterial>& g : groups) {
    float largest = 0.0f;
    for (const SurfaceMaterial& m : g)
      largest = std::max(largest, light_change(light_terms(scene, f, m, maps, settings, bounce), ref));
    slack += largest;
  }
  return slack;
}

/// How far the material freedoms may move one light's unshadowed light from `exact`'s: each
/// group's largest change (signed cosine; its magnitude, as the light may be negative), summed.
float unshadowed_rise(const Light& light, const VctSettings& settings, const vec3& position, const SurfaceMaterial& exact,
                      const MaterialGroups& groups) {
  const vec3 base = unshadowed_light(light, settings, position, exact);
  float rise = 0.0f;
  for (const std::vector<SurfaceMaterial>& g : groups) {
    float largest = 0.0f;
    for (const SurfaceMaterial& m : g)
      largest = std::max(largest, largest_magnitude(unshadowed_light(light, settings, position, m) - base));
    rise += largest;
  }
  return rise;
}

/// The parallelogram the snap may move the fragment over, in world space.
SnapParallelogram snap_parallelogram(const SnapWindow& w, const VoxelFragment& f) {
  const double r = w.reach;
  const glm::dvec3 along_u = (w.d * r / w.det) * w.e1 + (-w.c * r / w.det) * w.e2;
  const glm::dvec3 along_v = (-w.b * r / w.det) * w.e1 + (w.a * r / w.det) * w.e2;
  return {f.position, vec3(along_u), vec3(along_v)};
}

/// The normal-offset lookup moves with the shading normal (seed 248: a normal map's LOD moved it a
/// third of a texel, lighting two more taps), so the visibility is looked up with the shading
/// normals the material freedoms give: a few representatives, each standing for the normals within
/// the cluster radius of it, the reference's first. The radius starts at 1/64 and doubles until at
/// most kNormalRepresentatives remain (a bumpy normal map's hundreds of alternatives cost a few
/// lookups). A normal within the radius moves the lookup point by at most 2 w Kmax radius
/// (normal_offset_per_w_bound); that move is not added as a margin: a margin lets the lookup point
/// reach the fragment's own plane, where every tap's compare ties and the range search grows
/// exponentially (hunt seed 4045 took minutes), so cluster members are represented, not bounded.
constexpr float kNormalCluster = 1.0f / 64.0f;
constexpr size_t kNormalRepresentatives = 4;
std::vector<vec3> cluster_normals(const vec3& exact, const MaterialGroups& groups, float radius) {
  std::vector<vec3> c = {exact};
  for (const std::vector<SurfaceMaterial>& g : groups)
    for (const SurfaceMaterial& alt : g) {
      // A degenerate frame's normal (a zero tangent normalised) looks nothing up; GL's lookup
      // with it is as undefined as the reference's.
      if (!std::isfinite(alt.shading_normal.x + alt.shading_normal.y + alt.shading_normal.z)) continue;
      float nearest = INFINITY;
      for (const vec3& r : c) nearest = std::min(nearest, glm::length(alt.shading_normal - r));
      if (nearest <= radius) continue;
      if (c.size() < kNormalRepresentatives)
        c.push_back(alt.shading_normal);
      else
        return {};  // too many at this radius
    }
  return c;
}
std::vector<vec3> normal_representatives(const vec3& exact, const MaterialGroups& groups) {
  // Unit normals lie within 2 of each other: at radius 2 the reference's normal stands for all.
  for (float radius = kNormalCluster; radius < 2.0f; radius *= 2.0f) {
    std::vector<vec3> c = cluster_normals(exact, groups, radius);
    if (!c.empty()) return c;
  }
  return cluster_normals(exact, groups, 2.0f);
}

/// The PCF taps a correct GL may read anywhere the snap may put the fragment: per light, its
/// unshadowed light times how far the visibility moves over the whole parallelogram (and the
/// lookup's own float ties), freedoms/snap_visibility.h. The corners alone miss a texel edge or
/// depth tie crossed inside it: on atrium a point lamp's cube face is nearly edge-on to a wall,
/// and GL's fragment, 0.05 texel from the reference's (well inside the snap), read one row of the
/// 3x3 kernel lit that every corner reads shadowed (docs/compare.md, "Voxel shading slack").
/// The visibility's change counts at the unshadowed light GL's fragment may have: the light at a
/// moved point, other material and other visibility differs from the reference's by (the position's
/// and material's changes, taken at the reference's visibility) + that unshadowed light x (the
/// visibility's change); so the largest unshadowed light over the square plus the material
/// freedoms' rise, not the centre's (seed 559: a normal map's LOD turned a light past the horizon
/// where the snap also lit the fragment).
float shadow_snap_slack(const Scene& scene, const SnapWindow& w, const VoxelFragment& f, const SlotLods& lods,
                        const std::vector<ShiftedSurface>& shifted, const MaterialGroups& groups,
                        const std::vector<ShadowMap>& maps, const VctSettings& settings) {
  if (maps.empty()) return 0.0f;
  const SnapParallelogram q = snap_parallelogram(w, f);
  const SurfaceMaterial m = evaluate_material(scene, interpolate_surface(scene, f.triangle, f.b1, f.b2), lods);
  const std::vector<vec3> normals = normal_representatives(m.shading_normal, groups);
  float slack = 0.0f;
  for (size_t i = 0; i < std::min(maps.size(), scene.lights.size()); ++i) {
    const Light& light = scene.lights[i];
    // The light GL's fragment may have from this light unshadowed: none, and no lookup matters
    // (a light behind the surface at every point and material: the range is not searched).
    float open = 0.0f;
    for (const ShiftedSurface& s : shifted) {
      const vec3 lit = unshadowed_light(light, settings, s.point.position, s.material);
      open = std::max(open, largest_magnitude(lit));
    }
    open += unshadowed_rise(light, settings, f.position, m, groups);
    if (open <= 0.0f) continue;
    const float vis = surface_visibility(maps[i], light, f.position, m.shading_normal, settings);
    // A sliver's shift has no bound: any visibility.
    VisibilityRange r{0.0f, 1.0f};
    if (w.bounded) {
      r = {1.0f, 0.0f};
      for (const vec3& n : normals) {
        const VisibilityRange one = snap_surface_visibility_range(maps[i], light, q, n, settings);
        r.lo = std::min(r.lo, one.lo), r.hi = std::max(r.hi, one.hi);
      }
    }
    const float moves = std::max(r.hi - vis, vis - r.lo);
    slack += open * moves;
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
  return kLinearCompareWeightStep * largest_magnitude(open);
}

/// A hard spot whose edge passes within float rounding of the fragment (direct_ties.h,
/// hard_spot_lit_sample): GL's step may light it or not, so its light from that spot may be the lit
/// side's diffuse light (unshadowed: an upper bound) or none, as image.direct's tie admits.
float hard_spot_slack(const Scene& scene, const VoxelFragment& f, const SlotLods& lods, const VctSettings& settings) {
  const SurfaceMaterial m = evaluate_material(scene, interpolate_surface(scene, f.triangle, f.b1, f.b2), lods);
  float slack = 0.0f;
  for (const Light& light : scene.lights) {
    const LightSample ls = hard_spot_lit_sample(light, settings.light_model, f.position);
    const float n_dot_l = glm::dot(m.shading_normal, ls.l);
    if (ls.irradiance == vec3(0.0f) || n_dot_l <= 0.0f) continue;
    slack += largest_magnitude(m.albedo * ls.irradiance * n_dot_l * kInvPi);
  }
  return slack;
}

bool has_hard_spot(const Scene& scene) {
  for (const Light& l : scene.lights)
    if (l.is_spot() && l.inner_cone_angle >= l.outer_cone_angle) return true;
  return false;
}

}  // namespace

float hard_spot_slack(const Scene& scene, int n, const VoxelFragment& f, const VctSettings& settings) {
  return hard_spot_slack(scene, f, voxel_lods_per_triangle(scene, n)[f.triangle].exact, settings);
}

double voxel_snap_reach(const Scene& scene, int n, const VoxelFragment& f) {
  SnapWindow w;
  if (!snap_window(scene, n, f, w) || !w.bounded) return std::numeric_limits<double>::infinity();
  return w.reach;
}

VoxelDepthTie voxel_depth_tie(const Scene& scene, int n, const VoxelFragment& f) {
  SnapWindow w;
  const bool window = snap_window(scene, n, f, w);
  VoxelDepthTie t;
  t.axis = w.axis;
  t.depth = w.depth0 + double(f.b1) * w.depth_e1 + double(f.b2) * w.depth_e2;
  if (!window || !w.bounded) {
    t.margin = std::numeric_limits<double>::infinity();
    return t;
  }
  // d(depth)/d(u, v): the depth edges times the inverse of the window edges' matrix.
  const double gu = (w.depth_e1 * w.d - w.depth_e2 * w.c) / w.det;
  const double gv = (w.depth_e2 * w.a - w.depth_e1 * w.b) / w.det;
  t.margin = w.reach * (std::abs(gu) + std::abs(gv)) + 0x1p-20 * (std::abs(w.depth_e1) + std::abs(w.depth_e2));
  return t;
}

std::vector<float> fragment_shading_slack(const Scene& scene, const Voxelization& vox,
                                          const std::vector<ShadowMap>& maps,
                                          const VctSettings& frame_settings,
                                          const BounceLight* bounce) {
  // The voxelizer's own PCF taps where the engine declares them (issue 39), as fragment_radiance.
  const VctSettings settings = voxel_pass_settings(frame_settings);
  const std::vector<SurfaceLods> lods = voxel_lods_per_triangle(scene, vox.n);
  const bool hard_spots = has_hard_spot(scene);
  std::vector<float> out(vox.fragments.size(), 0.0f);
  parallel_for(int64_t(out.size()), [&](int64_t i) {
    const VoxelFragment& f = vox.fragments[size_t(i)];
    const SurfaceLods& l = lods[f.triangle];
    // Every change below is taken light by light from the reference's terms (freedoms/light_terms.h).
    const SurfaceMaterial exact = evaluate_material(scene, interpolate_surface(scene, f.triangle, f.b1, f.b2), l.exact);
    const LightTerms ref = light_terms(scene, f, exact, maps, settings, bounce);
    const MaterialGroups groups = material_alternatives(scene, f, l);
    float slack = material_slack(scene, f, groups, ref, maps, settings, bounce);
    SnapWindow w;
    if (snap_window(scene, vox.n, f, w)) {
      const std::vector<ShiftedSurface> shifted = shifted_surfaces(scene, w, f, l.exact, snap_offsets(scene, w, f, l.exact));
      slack += position_slack(scene, shifted, ref, maps, settings, bounce) +
               shadow_snap_slack(scene, w, f, l.exact, shifted, groups, maps, settings);
    }
    // Filtering first, the weights' freedom moves the filtered depth instead: snap_visibility's
    // filtered taps carry it (freedoms/snap_visibility.h).
    if (settings.shadow_compare == ShadowCompare::Linear && !filters_depth_first(settings))
      slack += linear_compare_slack(scene, f, l.exact, settings);
    if (hard_spots) slack += hard_spot_slack(scene, f, l.exact, settings);
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
