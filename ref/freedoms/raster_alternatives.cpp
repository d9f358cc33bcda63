#include "freedoms/raster_alternatives.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/parallel.h"
#include "freedoms/alpha_ties.h"
#include "freedoms/plane_setup.h"
#include "freedoms/texture_slack.h"
#include "scene/alpha_mask.h"

namespace vct {

namespace {

void copy_entry(const VisibilityBuffer& from, size_t i, VisibilityBuffer& to) {
  to.depth[i] = from.depth[i];
  to.triangle[i] = from.triangle[i];
  to.bary[i] = from.bary[i];
  to.front_facing[i] = from.front_facing[i];
  to.facing_tie[i] = from.facing_tie[i];
}

// Calls visit(ti, t, f) for every fragment of every triangle whose coverage sample (`sample`,
// pixel units from the pixel's corner; depth and barycentrics stay those at the centre) it covers,
// bands in parallel (each owns its rows), triangles in index order within a band: as
// render_visibility, so the result does not depend on the thread count.
template <class Visit>
void for_each_fragment_at(const BinnedTriangles& binned, int w, int h, vec2 sample, Visit&& visit) {
  const std::vector<vec2> samples = {sample};
  parallel_for(int64_t(binned.bands.size()), [&](int64_t band) {
    const int y0 = int(band) * kRasterBandRows, y1 = std::min(h, y0 + kRasterBandRows) - 1;
    for (uint32_t ti : binned.bands[size_t(band)]) {
      const RasterTriangle& t = binned.triangles[ti];
      rasterize(t, samples, 0, w - 1, y0, y1, [&](const RasterFragment& f) { visit(ti, t, f); });
    }
  });
}

// for_each_fragment_at with the coverage of snap world `world` (stages/raster.h SnapWorld): for
// Possible, every sample some snap of the vertices by one step covers.
template <class Visit>
void for_each_fragment_in_world(const BinnedTriangles& binned, int w, int h, vec2 sample, SnapWorld world,
                                Visit&& visit) {
  if (world == SnapWorld::Reference) return for_each_fragment_at(binned, w, h, sample, visit);
  const std::vector<vec2> samples = {sample};
  parallel_for(int64_t(binned.bands.size()), [&](int64_t band) {
    const int y0 = int(band) * kRasterBandRows, y1 = std::min(h, y0 + kRasterBandRows) - 1;
    for (uint32_t ti : binned.bands[size_t(band)]) {
      const RasterTriangle& t = binned.triangles[ti];
      const auto covers = [&](const EdgeSetup& e, int64_t px, int64_t py) { return covered_in_world(t, e, world, px, py); };
      rasterize_covering(t, samples, 0, w - 1, y0, y1, 1, covers, [&](const RasterFragment& f) { visit(ti, t, f); });
    }
  });
}

// Which alpha-tested fragments a front-most search keeps: every one a correct GL may keep (a
// fragment the reference cuts away is skipped only where its test cannot flip), or only those no
// correct GL discards (passing, and no flip).
enum class AlphaKeep { MayPass, SurelyPasses };

// The front-most fragment at each pixel centre that `keep` keeps. Layers in front that are cut
// away for certain (a leaf's transparent corner over another leaf) do not hide a tie behind them.
// Rasterized as render_visibility (bands, triangles in index order).
VisibilityBuffer front_most(const Scene& scene, const mat4& view_proj, int w, int h, AlphaKeep keep) {
  const BinnedTriangles binned = setup_and_bin(scene.positions, scene.triangles, view_proj, w, h);
  VisibilityBuffer vb = empty_visibility(w, h);
  const WindowBarycentrics wb(view_proj, w, h);
  for_each_fragment_at(binned, w, h, vec2(0.5f), [&](uint32_t, const RasterTriangle& t, const RasterFragment& f) {
    const int row = h - 1 - f.y;
    const size_t i = vb.index(f.x, row);
    if (!(f.depth < vb.depth[i])) return;  // GL_LESS
    if (triangle_alpha_tested(scene, t.source)) {
      const bool cut = surface_masked(scene, t.source, f.bary.y, f.bary.z);
      const bool skip = keep == AlphaKeep::MayPass
                            ? cut && !alpha_test_may_flip(scene, wb, f.x, row, t.source, f.bary)
                            : cut || alpha_test_may_flip(scene, wb, f.x, row, t.source, f.bary);
      if (skip) return;
    }
    store_fragment(vb, i, t, f);
  });
  return vb;
}

}  // namespace

VisibilityBuffer front_certainly_kept(const Scene& scene, const mat4& view_proj, int w, int h) {
  return front_most(scene, view_proj, w, h, AlphaKeep::SurelyPasses);
}

// How far beyond the plane's own slope a correct GL's interpolation may reach at a centre its
// coverage admits (docs/compare.md, "Raster alternatives", "A plane a snap may fold"). GL's
// interpolation triangle (eq. 14.10 takes barycentrics from the window vertices, whose rounding
// GL 4.5 §14.6.1 leaves open: llvmpipe sets its planes up from the unsnapped positions, its
// coverage from the snapped ones) has its vertices within one step of ours, v_i' = v_i + d_i. The
// reference plane z evaluated at v_i' is z_i + grad z . d_i, so GL's plane is z plus the plane
// through (v_i', -grad z . d_i): z'(c) - z(c) = -sum l_i'(c) grad z . d_i, l_i' the barycentrics of
// c in GL's triangle, and |z' - z| <= (|dz/dx| + |dz/dy|) sum |l_i'(c)| per step. Inside GL's
// triangle sum |l_i'| = 1 (the slope term alone); outside it (a centre the snapped coverage admits
// beyond the unsnapped edges) sum |l_i'| = 1 + 2 sum max(0, -e_i') / A'. Each edge function moves by
// at most its reach r_i (edge_snap_reach) and the area by at most R = P + 8 (area_snap_reach), and
// a centre any snap covers has e_i >= -r_i, so -e_i' <= 2 r_i and the factor is at most
// 1 + 4 sum r_i / (A - R), r_i at its largest over the vertices' box grown by one step (every such
// centre lies in it; an L1 distance is largest at a corner). Where A <= R a snap may close the
// triangle: GL's plane may be any plane, its depth anywhere in [0, 1] (infinity here).
double depth_plane_extrapolation_factor(const RasterTriangle& t) {
  const int64_t area_reach = area_snap_reach(t.x, t.y);
  if (t.area2 <= area_reach) return std::numeric_limits<double>::infinity();
  const int64_t x0 = std::min({t.x[0], t.x[1], t.x[2]}) - 1, x1 = std::max({t.x[0], t.x[1], t.x[2]}) + 1;
  const int64_t y0 = std::min({t.y[0], t.y[1], t.y[2]}) - 1, y1 = std::max({t.y[0], t.y[1], t.y[2]}) + 1;
  double reach_sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    int64_t worst = 0;
    for (int64_t px : {x0, x1})
      for (int64_t py : {y0, y1}) worst = std::max(worst, edge_snap_reach(t, i, px, py));
    reach_sum += double(worst);
  }
  return 1.0 + 4.0 * reach_sum / double(t.area2 - area_reach);
}

double depth_tie_margin(const RasterTriangle& t) {
  const double factor = depth_plane_extrapolation_factor(t);
  if (std::isinf(factor)) return 1.0;  // any window depth (GL clamps to [0, 1])
  const EdgeSetup e = edge_setup(t);
  double dzdx = 0.0, dzdy = 0.0;  // per sub-pixel step
  for (int i = 0; i < 3; ++i) {
    dzdx += double(e.a[i]) * t.z[i];
    dzdy += double(e.b[i]) * t.z[i];
  }
  // The evaluation's own roundings: 2^-22 from the barycentric form, or the plane equation's set-up
  // and evaluation in float (plane_setup.h; two more roundings for the reference's own value).
  const double arithmetic = std::max(std::ldexp(1.0, -22), plane_setup_margin(t) + 2.0 * kFloatRoundoff);
  return arithmetic + factor * (std::abs(dzdx) + std::abs(dzdy)) / double(t.area2);
}

VisibilityBuffer other_surfaces(const Scene& scene, const mat4& view_proj, const VisibilityBuffer& front) {
  const int w = front.width, h = front.height;
  const BinnedTriangles binned = setup_and_bin(scene.positions, scene.triangles, view_proj, w, h);
  VisibilityBuffer alt = empty_visibility(w, h);
  std::vector<float> best(front.depth.size(), 2.0f);  // above every clamped depth
  for_each_fragment_at(binned, w, h, vec2(0.5f), [&](uint32_t, const RasterTriangle& t, const RasterFragment& f) {
    const size_t i = front.index(f.x, h - 1 - f.y);
    if (triangle_alpha_tested(scene, t.source) && surface_masked(scene, t.source, f.bary.y, f.bary.z)) return;
    if (int32_t(t.source) == front.triangle[i] || !(f.depth < best[i])) return;
    best[i] = f.depth;
    store_fragment(alt, i, t, f);
  });
  return alt;
}

namespace {

// Whether the reference discards the fragment: alpha-masked there (render_visibility's test).
bool discarded(const Scene& scene, const RasterTriangle& t, const RasterFragment& f) {
  return triangle_alpha_tested(scene, t.source) && surface_masked(scene, t.source, f.bary.y, f.bary.z);
}

// What every correct GL does with the fragment's alpha test (docs/compare.md, "Alpha-mask ties"):
// keeps it (not alpha tested, or passing where the test cannot flip), discards it (cut where it
// cannot flip), or either. A depth tie only admits what some GL keeps, and only what every GL
// keeps bounds it (medium hunt seed 571: a masked plane behind its opaque coplanar twin, cut in
// the reference, kept by llvmpipe and drawn in front: a depth tie and a flip at one centre).
enum class AlphaOutcome { Kept, Discarded, Either };

AlphaOutcome alpha_outcome(const Scene& scene, const WindowBarycentrics& wb, const RasterTriangle& t,
                           const RasterFragment& f, int row) {
  if (!triangle_alpha_tested(scene, t.source)) return AlphaOutcome::Kept;
  if (alpha_test_may_flip(scene, wb, f.x, row, t.source, f.bary)) return AlphaOutcome::Either;
  return surface_masked(scene, t.source, f.bary.y, f.bary.z) ? AlphaOutcome::Discarded : AlphaOutcome::Kept;
}

std::vector<double> depth_tie_margins(const BinnedTriangles& binned) {
  std::vector<double> margins(binned.triangles.size());
  for (size_t i = 0; i < margins.size(); ++i) margins[i] = depth_tie_margin(binned.triangles[i]);
  return margins;
}

// The ceiling's fragment (depth_tied_surfaces): the deepest a fragment may lie and still come out in
// front of all the others is the smallest z + m at the pixel over the fragments every correct GL
// keeps (the alpha test's outcome is asked only of a fragment that would lower it: the same minimum).
void lower_ceiling(std::vector<double>& ceiling, size_t i, uint32_t ti, const RasterFragment& f,
                   const std::vector<double>& margins, const Scene& scene, const WindowBarycentrics& wb,
                   const RasterTriangle& t, int row) {
  const double top = double(f.depth) + margins[ti];
  if (top < ceiling[i] && alpha_outcome(scene, wb, t, f, row) == AlphaOutcome::Kept) ceiling[i] = top;
}

// depth_tied_surfaces' second pass, from its first pass's ceiling.
std::vector<VisibilityBuffer> tied_below_ceiling(const Scene& scene, const WindowBarycentrics& wb,
                                                 const BinnedTriangles& binned, const std::vector<double>& margins,
                                                 const std::vector<double>& ceiling, const VisibilityBuffer& front,
                                                 vec2 sample, SnapWorld candidates) {
  const int w = front.width, h = front.height;
  // Every other surface whose z - m reaches it: the first at a pixel into layer 0, any further one
  // (three surfaces or more tied at one pixel: rare) into its row's overflow. Bands own their rows,
  // so each pixel and row is written by one thread, in triangle order.
  struct Extra {
    int x;
    uint32_t ti;
    RasterFragment f;
  };
  std::vector<VisibilityBuffer> out(1, front);
  std::vector<uint8_t> has_first(front.depth.size(), 0);
  std::vector<std::vector<Extra>> overflow(static_cast<size_t>(h));
  for_each_fragment_in_world(binned, w, h, sample, candidates, [&](uint32_t ti, const RasterTriangle& t,
                                                                   const RasterFragment& f) {
    const int row = h - 1 - f.y;
    const size_t i = front.index(f.x, row);
    if (int32_t(t.source) == front.triangle[i] || !(double(f.depth) - margins[ti] <= ceiling[i])) return;
    if (alpha_outcome(scene, wb, t, f, row) == AlphaOutcome::Discarded) return;
    if (!has_first[i]) {
      has_first[i] = 1;
      store_fragment(out[0], i, t, f);
    } else if (out[0].triangle[i] != int32_t(t.source)) {  // else a clipped triangle's other piece
      overflow[size_t(row)].push_back({f.x, ti, f});
    }
  });
  for (int row = 0; row < h; ++row) {
    std::vector<size_t> placed(size_t(w), 1);  // layer 0 holds each pixel's first
    for (const Extra& e : overflow[size_t(row)]) {
      const size_t layer = placed[size_t(e.x)]++;
      if (out.size() <= layer) out.push_back(front);
      store_fragment(out[layer], front.index(e.x, row), binned.triangles[e.ti], e.f);
    }
  }
  if (std::none_of(has_first.begin(), has_first.end(), [](uint8_t first) { return first != 0; })) out.clear();
  return out;
}

}  // namespace

std::vector<VisibilityBuffer> depth_tied_surfaces(const Scene& scene, const mat4& view_proj,
                                                  const VisibilityBuffer& front, vec2 sample, SnapWorld candidates) {
  const int w = front.width, h = front.height;
  const BinnedTriangles binned = setup_and_bin(scene.positions, scene.triangles, view_proj, w, h);
  const std::vector<double> margins = depth_tie_margins(binned);
  const WindowBarycentrics wb(view_proj, w, h);
  std::vector<double> ceiling(front.depth.size(), 1e300);
  for_each_fragment_at(binned, w, h, sample, [&](uint32_t ti, const RasterTriangle& t, const RasterFragment& f) {
    const int row = h - 1 - f.y;
    lower_ceiling(ceiling, front.index(f.x, row), ti, f, margins, scene, wb, t, row);
  });
  return tied_below_ceiling(scene, wb, binned, margins, ceiling, front, sample, candidates);
}

VisibilityBuffer visibility_and_depth_ties(const Scene& scene, const mat4& view_proj, int w, int h, vec2 sample,
                                           std::vector<VisibilityBuffer>& tied) {
  const BinnedTriangles binned = setup_and_bin(scene.positions, scene.triangles, view_proj, w, h);
  const std::vector<double> margins = depth_tie_margins(binned);
  const WindowBarycentrics wb(view_proj, w, h);
  std::vector<double> ceiling(size_t(w) * size_t(h), 1e300);
  VisibilityBuffer vb = empty_visibility(w, h);
  for_each_fragment_at(binned, w, h, sample, [&](uint32_t ti, const RasterTriangle& t, const RasterFragment& f) {
    const int row = h - 1 - f.y;
    const size_t i = vb.index(f.x, row);
    lower_ceiling(ceiling, i, ti, f, margins, scene, wb, t, row);
    if (!(f.depth < vb.depth[i])) return;  // GL_LESS, then the mask: render_visibility's order
    if (discarded(scene, t, f)) return;
    store_fragment(vb, i, t, f);
  });
  tied = tied_below_ceiling(scene, wb, binned, margins, ceiling, vb, sample, SnapWorld::Reference);
  return vb;
}

std::vector<VisibilityBuffer> alpha_chain_surfaces(const Scene& scene, const mat4& view_proj,
                                                   const VisibilityBuffer& front, const VisibilityBuffer& kept) {
  const int w = front.width, h = front.height;
  const BinnedTriangles binned = setup_and_bin(scene.positions, scene.triangles, view_proj, w, h);
  const WindowBarycentrics wb(view_proj, w, h);
  struct Flip {
    int x;
    uint32_t ti;
    RasterFragment f;
  };
  // Bands own their rows, so each row's list is written by one thread, in triangle order.
  std::vector<std::vector<Flip>> rows(static_cast<size_t>(h));
  for_each_fragment_at(binned, w, h, vec2(0.5f), [&](uint32_t ti, const RasterTriangle& t, const RasterFragment& f) {
    const int row = h - 1 - f.y;
    const size_t i = front.index(f.x, row);
    // In front of the chain's end (GL_LESS against it, or against the clear value 1 where every
    // fragment may be cut). Only a flip can lie there: a fragment no GL discards would be the end.
    if (!(f.depth < kept.depth[i]) || int32_t(t.source) == front.triangle[i]) return;
    if (!triangle_alpha_tested(scene, t.source) || !alpha_test_may_flip(scene, wb, f.x, row, t.source, f.bary)) return;
    std::vector<Flip>& list = rows[size_t(row)];
    const bool seen = std::any_of(list.begin(), list.end(), [&](const Flip& e) {  // a clipped triangle's other piece
      return e.x == f.x && binned.triangles[e.ti].source == t.source;
    });
    if (!seen) list.push_back({f.x, ti, f});
  });
  std::vector<VisibilityBuffer> out;
  for (int row = 0; row < h; ++row) {
    std::vector<size_t> placed(size_t(w), 0);
    for (const Flip& e : rows[size_t(row)]) {
      const size_t layer = placed[size_t(e.x)]++;
      if (out.size() <= layer) out.push_back(front);
      store_fragment(out[layer], front.index(e.x, row), binned.triangles[e.ti], e.f);
    }
  }
  return out;
}

AlphaFlipSurfaces alpha_flip_surfaces(const Scene& scene, const mat4& view_proj, const VisibilityBuffer& vb) {
  const int w = vb.width, h = vb.height;
  const VisibilityBuffer unmasked = front_most(scene, view_proj, w, h, AlphaKeep::MayPass);
  AlphaFlipSurfaces out;
  out.surface = other_surfaces(scene, view_proj, vb);  // behind the reference's front
  out.may_flip.assign(vb.triangle.size(), 0);
  const WindowBarycentrics wb(view_proj, w, h);
  parallel_rows(h, [&](int row) {
    for (int x = 0; x < w; ++x) {
      const size_t i = vb.index(x, row);
      const int32_t top = unmasked.triangle[i];
      if (top < 0 || !alpha_test_may_flip(scene, wb, x, row, uint32_t(top), unmasked.bary[i])) continue;
      out.may_flip[i] = 1;
      if (vb.triangle[i] != top) copy_entry(unmasked, i, out.surface);  // the reference discarded it
    }
  });
  return out;
}

}  // namespace vct
