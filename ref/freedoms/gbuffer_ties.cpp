#include "freedoms/gbuffer_ties.h"

#include <algorithm>
#include <cmath>

#include "core/parallel.h"
#include "freedoms/texture_slack.h"
#include "scene/alpha_mask.h"
#include "stages/gbuffer.h"
#include "stages/raster.h"

namespace vct {

namespace {

constexpr int kNormalOffset = 5;  // first normal value in GBufferSample (coverage, depth, position)

// Interleaved lo/hi per value: channel 2k is value k's lower end, 2k + 1 its upper end.
void widen(Image& range, int x, int row, const GBufferSample& s) {
  float* p = range.pixel(x, row);
  for (int k = 0; k < kGbufferSampleValues; ++k) {
    p[2 * k] = std::min(p[2 * k], s.values[k]);
    p[2 * k + 1] = std::max(p[2 * k + 1], s.values[k]);
  }
}

GBufferSample negated_normal(GBufferSample s) {
  for (int c = 0; c < 3; ++c) s.values[kNormalOffset + c] = -s.values[kNormalOffset + c];
  return s;
}

GBufferSample sample_of(const Scene& scene, const mat4& view_proj, const VisibilityBuffer& vb, int x, int row) {
  const size_t i = vb.index(x, row);
  if (vb.triangle[i] < 0) return GBufferSample();
  return gbuffer_sample(scene, view_proj, vb.width, vb.height, x, row, uint32_t(vb.triangle[i]), vb.bary[i],
                        vb.depth[i], vb.front_facing[i] != 0);
}

// The reference's own values at pixel (x, row) (lo = hi, read back from the G-buffer's images in
// GBufferSample order), widened by its facing alternative.
void start_range(const VisibilityBuffer& vb, int x, int row, GBuffer& g) {
  const Image* images[] = {&g.coverage, &g.depth, &g.position, &g.normal, &g.albedo, &g.material, &g.specular_color, &g.emission};
  GBufferSample own;
  float* v = own.values;
  for (const Image* im : images)
    for (int c = 0; c < im->channels; ++c) *v++ = im->at(x, row, c);
  float* p = g.tie_range.pixel(x, row);
  for (int k = 0; k < kGbufferSampleValues; ++k) p[2 * k] = p[2 * k + 1] = own.values[k];
  if (vb.triangle[vb.index(x, row)] >= 0 && vb.facing_tie[vb.index(x, row)])
    widen(g.tie_range, x, row, negated_normal(own));
}

constexpr int kDepthOffset = 1;     // the depth value in GBufferSample (after coverage)
constexpr int kPositionOffset = 2;  // first position value in GBufferSample (after coverage, depth)

// Window depth of world point p through view_proj (GL's default depth range [0, 1]).
float window_depth(const mat4& view_proj, const vec3& p) {
  const glm::dvec4 c = glm::dmat4(view_proj) * glm::dvec4(glm::dvec3(p), 1.0);
  return float(c.z / c.w * 0.5 + 0.5);
}

void widen_value(float* p, int v, float value) {
  p[2 * v] = std::min(p[2 * v], value);
  p[2 * v + 1] = std::max(p[2 * v + 1], value);
}

// A surface's own position and depth under the snap: its plane's points at the four (+-2^-8,
// +-2^-8) sample shifts (the texture slack's shifted_surface_points, extrapolated on the plane),
// and their window depths. A nearly edge-on triangle's position and depth move far along the view
// ray under a one-step snap, more than the models' slope terms, taken from the image's 3x3
// differences across other surfaces, allow there; the depth moves with the position (the same
// plane at the same shifted sample: hunt seeds 413, 579, whose position was admitted by its own
// plane and whose depth, 1.5e-4 off, was not).
void widen_by_positions(const mat4& view_proj, int x, int row, const vec3* positions, int n, GBuffer& g) {
  float* p = g.tie_range.pixel(x, row);
  for (int k = 0; k < n; ++k) {
    for (int c = 0; c < 3; ++c) widen_value(p, kPositionOffset + c, positions[k][c]);
    widen_value(p, kDepthOffset, window_depth(view_proj, positions[k]));
  }
}

void widen_by_plane_at_shifts(const Scene& scene, const mat4& view_proj, const WindowBarycentrics& wb, int x, int row,
                              uint32_t triangle, const vec3& bary, GBuffer& g) {
  vec3 points[kSlackShifts];
  const int n = shifted_surface_positions(scene, wb, x, row, triangle, bary, points);
  widen_by_positions(view_proj, x, row, points, n, g);
}

// The first GBufferSample value of each texture slack channel's stage, and its channel count.
struct SlackValues {
  TextureSlackChannel slack;
  int first, count;
};
constexpr SlackValues kSlackValues[] = {{kSlackNormal, kNormalOffset, 3},
                                        {kSlackAlbedo, kNormalOffset + 3, 3},
                                        {kSlackMaterial, kNormalOffset + 6, 4},
                                        {kSlackEmission, kNormalOffset + 13, 3}};

// An alternative surface's own texture freedom (docs/compare.md, "Raster alternatives", "An
// alternative's own freedoms"): a correct GL that shows that surface reads its attributes at its
// own snapped sample and looks its textures up at any admissible LOD (GL 4.5 §8.14.1, §14.6.1),
// exactly the freedom the bound gives the front surface through g.texture_slack. The bound the
// judge adds to the range is the front's, so the alternative's slack goes into the range: its
// values +- its slack.
void widen_by_texture_slack(const Scene& scene, const mat4& view_proj, const WindowBarycentrics& wb,
                            const VisibilityBuffer& other, int x, int row, const GBufferSample& alt, GBuffer& g) {
  const size_t i = other.index(x, row);
  const uint32_t tri = uint32_t(other.triangle[i]);
  const PixelMaterial centre = pixel_material_lods_if_read(scene, view_proj, other.width, other.height, x, row, tri, other.bary[i]);
  const vec4 slack = texture_slack(scene, wb, x, row, tri, other.bary[i], centre.material, centre.lods);
  float* p = g.tie_range.pixel(x, row);
  for (const SlackValues& s : kSlackValues)
    for (int k = s.first; k < s.first + s.count; ++k) {
      p[2 * k] = std::min(p[2 * k], alt.values[k] - slack[s.slack]);
      p[2 * k + 1] = std::max(p[2 * k + 1], alt.values[k] + slack[s.slack]);
    }
}

// Pixel (x, row) of `other` joins the range: its values, its negated normal where its facing ties,
// and its own freedoms, as the front surface's: its plane and its lookups under the snap
// (docs/compare.md, "Raster alternatives", "An alternative's own freedoms").
void widen_by_alternative(const Scene& scene, const mat4& view_proj, const WindowBarycentrics& wb,
                          const VisibilityBuffer& other, int x, int row, GBuffer& g) {
  const size_t i = other.index(x, row);
  const GBufferSample alt = sample_of(scene, view_proj, other, x, row);
  widen(g.tie_range, x, row, alt);
  if (other.triangle[i] < 0) return;  // the clear values: nothing looked up
  if (other.facing_tie[i]) widen(g.tie_range, x, row, negated_normal(alt));
  widen_by_plane_at_shifts(scene, view_proj, wb, x, row, uint32_t(other.triangle[i]), other.bary[i], g);
  widen_by_texture_slack(scene, view_proj, wb, other, x, row, alt, g);
}

void widen_by(const Scene& scene, const mat4& view_proj, const VisibilityBuffer& vb, const VisibilityBuffer& other,
              GBuffer& g) {
  const WindowBarycentrics wb(view_proj, vb.width, vb.height);
  parallel_rows(vb.height, [&](int row) {
    for (int x = 0; x < vb.width; ++x)
      if (other.triangle[vb.index(x, row)] != vb.triangle[vb.index(x, row)])  // else the same surface (or empty)
        widen_by_alternative(scene, view_proj, wb, other, x, row, g);
  });
}

// Alpha-mask ties (freedoms/alpha_ties.h): where the front-most surface, masks ignored, may pass or
// fail its alpha test in a correct GL, the other outcome is admissible (raster_alternatives.h),
// with its own freedoms as every alternative (hunt seed 660: a masked, textured flip whose albedo
// lay in its own texture slack, not at its centre value).
void widen_by_alpha_flips(const Scene& scene, const mat4& view_proj, const VisibilityBuffer& vb, GBuffer& g) {
  const AlphaFlipSurfaces flips = alpha_flip_surfaces(scene, view_proj, vb);
  const WindowBarycentrics wb(view_proj, vb.width, vb.height);
  parallel_rows(vb.height, [&](int row) {
    for (int x = 0; x < vb.width; ++x)
      if (flips.may_flip[vb.index(x, row)]) widen_by_alternative(scene, view_proj, wb, flips.surface, x, row, g);
  });
  // The end of a chain of flips (docs/compare.md, "Alpha-mask ties"), as in the shadow maps: every
  // layer in front of the front-most fragment no GL discards is cut away for certain or may flip,
  // so a correct GL may discard them all and show that fragment (or the clear values where there is
  // none) wherever it is not the reference's own front. Hunt seed 524: both faces of a masked thin
  // wall may flip at a pixel; the reference cut the first and kept the second, llvmpipe cut both
  // and showed the room behind.
  const VisibilityBuffer kept = front_certainly_kept(scene, view_proj, vb.width, vb.height);
  widen_by(scene, view_proj, vb, kept, g);
  // And every flip between (three or more layers that may flip at one pixel: masked foliage cards).
  for (const VisibilityBuffer& layer : alpha_chain_surfaces(scene, view_proj, vb, kept))
    widen_by(scene, view_proj, vb, layer, g);
}

}  // namespace

std::string tie_range_channel_name(const std::string& group, int c, bool upper) {
  return group + "." + std::to_string(c) + (upper ? ".hi" : ".lo");
}

void make_tie_ranges(int width, int height, GBuffer& g) {
  g.tie_range = Image(width, height, 2 * kGbufferSampleValues);
  g.tie_range.channel_names.clear();
  for (const TieRangeGroup& group : kTieRangeGroups)
    for (int c = 0; c < group.channels; ++c)
      for (bool upper : {false, true}) g.tie_range.channel_names.push_back(tie_range_channel_name(group.stage, c, upper));
}

// The front surface's own part: its values, its facing, its plane under the snap.
void start_tie_range(const mat4& view_proj, const VisibilityBuffer& vb, int x, int row, const vec3* positions, int n,
                     GBuffer& g) {
  start_range(vb, x, row, g);
  widen_by_positions(view_proj, x, row, positions, n, g);
}

void add_tie_ranges(const Scene& scene, const mat4& view_proj, const VisibilityBuffer& vb, GBuffer& g) {
  make_tie_ranges(vb.width, vb.height, g);
  const WindowBarycentrics wb(view_proj, vb.width, vb.height);
  parallel_rows(vb.height, [&](int row) {
    for (int x = 0; x < vb.width; ++x) {
      const size_t i = vb.index(x, row);
      vec3 positions[kSlackShifts];
      const int n = vb.triangle[i] >= 0 ? shifted_surface_positions(scene, wb, x, row, uint32_t(vb.triangle[i]),
                                                                    vb.bary[i], positions)
                                        : 0;
      start_tie_range(view_proj, vb, x, row, positions, n, g);
    }
  });
  widen_tie_ranges_by_alternatives(scene, view_proj, vb, g);
}

void widen_tie_ranges_by_alternatives(const Scene& scene, const mat4& view_proj, const VisibilityBuffer& vb,
                                      GBuffer& g) {
  const int w = vb.width, h = vb.height;
  // One shifted visibility buffer at a time (memory: one more VisibilityBuffer, not four).
  for (int k = 0; k < 4; ++k) {
    const float s = float(kVertexSnapStep);
    const vec2 sample(0.5f + ((k & 1) ? s : -s), 0.5f + ((k & 2) ? s : -s));
    // The same snap moves the depth planes: where the shifted sample's front surface ties in depth
    // with another one covering that sample (two faces meeting at a fold's edge, one front- and
    // one back-facing), that one may be in front (docs/compare.md, "Raster alternatives", "Depth
    // order under a shift"). Both from one raster pass (visibility_and_depth_ties).
    std::vector<VisibilityBuffer> ties;
    const VisibilityBuffer shifted = visibility_and_depth_ties(scene, view_proj, w, h, sample, ties);
    widen_by(scene, view_proj, vb, shifted, g);
    for (const VisibilityBuffer& tied : ties) widen_by(scene, view_proj, vb, tied, g);
  }
  // Every surface tied in depth with the reference's own front at the centre, not only the nearest
  // one (a plane, its coplanar twin and a surface crossing both at one centre: hunt seed 2717), and
  // every one some snap of its own vertices makes cover the centre (a sliver beside the front's
  // edge: hunt seed 6, large class).
  for (const VisibilityBuffer& tied : depth_tied_surfaces(scene, view_proj, vb, vec2(0.5f), SnapWorld::Possible))
    widen_by(scene, view_proj, vb, tied, g);
  if (scene_has_alpha_test(scene)) widen_by_alpha_flips(scene, view_proj, vb, g);
}

}  // namespace vct
