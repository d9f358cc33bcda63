#include "freedoms/shadow_map_ties.h"

#include <algorithm>
#include <array>

#include "core/parallel.h"
#include "freedoms/gbuffer_ties.h"
#include "freedoms/raster_alternatives.h"
#include "scene/alpha_mask.h"
#include "stages/raster.h"
#include "stages/shadow_map.h"

namespace vct {

namespace {

// Each snapped vertex coordinate may be one 2^-8 texel step off the reference's
// (raster_alternatives.h). Shared vertices snap alike, so a mesh stays watertight: the four common
// shifts of the sample by (+-1, +-1) steps (kShifts) move every edge together. But each vertex
// snaps on its own: at a point on an edge's segment the edge moves by a convex combination of its
// two ends' moves, so its edge function changes by at most |a| + |b| (a, b per step), and the
// `relaxed` world (each edge pushed out by its reach, closed, inside the vertices' box grown by
// one step, which every snapped triangle lies in) covers every centre any snapped triangle does.
// It adds coverage only, so it lowers a range's low end: a sliver thinner than two steps
// (scenes/regressions/seed-43-medium: 0.003 texel wide at a centre 0.003 texel off both edges)
// may cover a centre no common shift covers. (Its counterpart, a sliver GL may not cover where
// every common shift does, would need per-vertex snaps that keep shared edges shared: open.)
constexpr int kShifts = 4;
constexpr int kWorlds = kShifts + 1;  // the shifts, then relaxed
constexpr int kRelaxed = kWorlds;     // its index among the samples (0 is the centre)

struct SnapWorlds {
  EdgeSetup edges, relaxed;
  int64_t box_lo[2], box_hi[2];  // the vertices' box grown by one step
};

SnapWorlds snap_worlds(const RasterTriangle& t) {
  SnapWorlds w;
  w.edges = w.relaxed = edge_setup(t);
  for (int i = 0; i < 3; ++i) {
    w.relaxed.c[i] += std::abs(w.edges.a[i]) + std::abs(w.edges.b[i]);
    w.relaxed.bias[i] = 0;
  }
  w.box_lo[0] = std::min({t.x[0], t.x[1], t.x[2]}) - 1, w.box_hi[0] = std::max({t.x[0], t.x[1], t.x[2]}) + 1;
  w.box_lo[1] = std::min({t.y[0], t.y[1], t.y[2]}) - 1, w.box_hi[1] = std::max({t.y[0], t.y[1], t.y[2]}) + 1;
  return w;
}

// Which samples of row y (the centre, the four shifts, the relaxed world's centre) the triangle
// covers.
struct RowSpans {
  int x0[1 + kWorlds], x1[1 + kWorlds];
  bool any[1 + kWorlds];
  bool covers(int k, int x) const { return any[k] && x >= x0[k] && x <= x1[k]; }
};

// The relaxed world's span of row y, clipped to the grown box.
bool relaxed_row_span(const SnapWorlds& w, int y, int& x0, int& x1) {
  constexpr int64_t half = kSubpixelScale / 2;
  const int64_t py = int64_t(y) * kSubpixelScale + half;
  if (py < w.box_lo[1] || py > w.box_hi[1]) return false;
  if (!sample_row_span(w.relaxed, y, half, half, x0, x1)) return false;
  // Centres x S + half inside [box_lo, box_hi]: x >= ceil((lo - half) / S), x <= floor((hi - half) / S).
  const auto floor_div = [](int64_t n, int64_t d) { return n >= 0 ? n / d : -((-n + d - 1) / d); };
  x0 = int(std::max<int64_t>(x0, -floor_div(half - w.box_lo[0], kSubpixelScale)));
  x1 = int(std::min<int64_t>(x1, floor_div(w.box_hi[0] - half, kSubpixelScale)));
  return x0 <= x1;
}

// Covers sample k of row y (0 the centre, 1..4 the shifts, kRelaxed the relaxed world) in [x0, x1].
bool sample_span(const SnapWorlds& w, int k, int y, int& x0, int& x1) {
  if (k == kRelaxed) return relaxed_row_span(w, y, x0, x1);
  int64_t sx = kSubpixelScale / 2, sy = kSubpixelScale / 2;
  if (k > 0) shifted_sample_steps(k - 1, sx, sy);
  return sample_row_span(w.edges, y, sx, sy, x0, x1);
}

// The spans of the six samples, their union [ux0, ux1] and the texels all six cover [ix0, ix1]
// (empty when ix0 > ix1). False when no sample of the row is covered.
bool row_spans(const RasterTriangle& t, const SnapWorlds& w, int y, RowSpans& s, int& ux0, int& ux1, int& ix0,
               int& ix1) {
  ux0 = t.xmax + 1, ux1 = t.xmin - 1, ix0 = t.xmin, ix1 = t.xmax;
  for (int k = 0; k <= kWorlds; ++k) {
    s.x0[k] = t.xmin, s.x1[k] = t.xmax;
    s.any[k] = sample_span(w, k, y, s.x0[k], s.x1[k]);
    if (!s.any[k]) {
      ix0 = t.xmax + 1;
      continue;
    }
    ux0 = std::min(ux0, s.x0[k]), ux1 = std::max(ux1, s.x1[k]);
    ix0 = std::max(ix0, s.x0[k]), ix1 = std::min(ix1, s.x1[k]);
  }
  return ux0 <= ux1;
}

float clamped(double z) { return float(std::clamp(z, 0.0, 1.0)); }

// One band's rows (band row r = window y - y0) while its triangles are swept, each fragment's
// depth z with its plane's margin m = depth_tie_margin (a snapped plane moves in every world): the
// smallest z - m and z + m of the fragments covering all six samples (`common_lo`, `common_hi`,
// most of them), of those covering sample k + 1 but not all six (`partial_lo[k]`, `partial_hi[k]`,
// texels near an edge), and of the fragments covering the centre (`lo`, `hi`). Each shift's (and
// the relaxed world's) front lies in [min(common_lo, partial_lo[k]), min(common_hi,
// partial_hi[k])]; 1 (the clear value) where nothing is. (Without the margins a steep plane that
// covers a texel only in a shifted world was pinned to its reference depth: hunt seed 482, a
// texel 2.1e-4 below the range on a 64^2 map.)
// The partial rows are filled on first use (`edged`): most rows of a band hold no edge texel
// of any triangle when maps are large. One per thread, reset for each band: a band's arrays are
// larger than malloc's mmap threshold, and fresh pages per band cost more than the sweep.
struct BandDepths {
  int width = 0;
  std::vector<float> common_lo, common_hi, lo, hi;
  std::array<std::vector<float>, kWorlds> partial_lo, partial_hi;
  std::vector<uint8_t> edged;
  void reset(int w, int rows) {
    width = w;
    const size_t n = size_t(w) * size_t(rows);
    common_lo.assign(n, 1.0f), common_hi.assign(n, 1.0f), lo.assign(n, 1.0f), hi.assign(n, 1.0f);
    for (int k = 0; k < kWorlds; ++k) partial_lo[size_t(k)].resize(n), partial_hi[size_t(k)].resize(n);
    edged.assign(size_t(rows), 0);
  }
  void touch_partial(size_t row) {
    if (edged[row]) return;
    edged[row] = 1;
    for (int k = 0; k < kWorlds; ++k) {
      std::fill_n(partial_lo[size_t(k)].begin() + ptrdiff_t(row * size_t(width)), width, 1.0f);
      std::fill_n(partial_hi[size_t(k)].begin() + ptrdiff_t(row * size_t(width)), width, 1.0f);
    }
  }
};

// One fragment at texel x of band row r, whichever samples `spans` says it covers.
void add_fragment(const RowSpans& spans, int x, size_t r, float z, double m, BandDepths& b) {
  const size_t i = r * size_t(b.width) + size_t(x);
  const float l = clamped(double(z) - m), h = clamped(double(z) + m);
  bool all = true;
  for (int k = 0; k <= kWorlds; ++k) all = all && spans.covers(k, x);
  if (all) {
    b.common_lo[i] = std::min(b.common_lo[i], l);
    b.common_hi[i] = std::min(b.common_hi[i], h);
  } else {
    b.touch_partial(r);
    for (size_t k = 0; k < size_t(kWorlds); ++k) {
      if (!spans.covers(int(k) + 1, x)) continue;
      b.partial_lo[k][i] = std::min(b.partial_lo[k][i], l);
      b.partial_hi[k][i] = std::min(b.partial_hi[k][i], h);
    }
  }
  if (!spans.covers(0, x)) return;
  b.lo[i] = std::min(b.lo[i], l);
  b.hi[i] = std::min(b.hi[i], h);
}

// Texels x0..x1 of band row `row` covered by all six samples, as depth_raster.cpp's span loop:
// edge values carried in doubles as e(x0) + k * step (exact integers below 2^53), the same depth
// bits as the map's, and a loop that vectorizes.
void add_interior(const RasterTriangle& t, const EdgeSetup& e, int y, int x0, int x1, size_t row, double m,
                  BandDepths& b) {
  const SpanEdges span(e, y, x0);
  const double* e0 = span.e0;
  const double* step = span.step;
  const double area = double(t.area2);
  float* common_lo = b.common_lo.data() + row + size_t(x0);
  float* common_hi = b.common_hi.data() + row + size_t(x0);
  float* lo = b.lo.data() + row + size_t(x0);
  float* hi = b.hi.data() + row + size_t(x0);
  for (int k = 0; k <= x1 - x0; ++k) {
    const double dk = double(k);
    const float z = interpolate_window_depth((e0[0] + dk * step[0]) / area, (e0[1] + dk * step[1]) / area,
                                             (e0[2] + dk * step[2]) / area, t.z);
    const float l = clamped(double(z) - m), h = clamped(double(z) + m);
    common_lo[k] = l < common_lo[k] ? l : common_lo[k];
    common_hi[k] = h < common_hi[k] ? h : common_hi[k];
    lo[k] = l < lo[k] ? l : lo[k];
    hi[k] = h < hi[k] ? h : hi[k];
  }
}

// One triangle's fragments in the band's rows. The depth is the one every raster path computes at
// the centre (interpolate_window_depth from exact edge values), whichever sample decided coverage;
// an alpha-masked fragment writes nothing anywhere (GL discards it before the depth test, and its
// barycentrics are the centre's for every sample).
void sweep_triangle(const RasterTriangle& t, int y0, int y1, const Scene& scene, BandDepths& b) {
  const SnapWorlds w = snap_worlds(t);
  const EdgeSetup& e = w.edges;
  const double m = depth_tie_margin(t);
  const bool masked = triangle_alpha_tested(scene, t.source);
  const double area = double(t.area2);
  RowSpans spans;
  RasterFragment f;
  for (int y = std::max(y0, t.ymin); y <= std::min(y1, t.ymax); ++y) {
    int ux0, ux1, ix0, ix1;
    if (!row_spans(t, w, y, spans, ux0, ux1, ix0, ix1)) continue;
    const size_t row = size_t(y - y0) * size_t(b.width);
    if (!masked && ix0 <= ix1) add_interior(t, e, y, ix0, ix1, row, m, b);
    const int64_t py = int64_t(y) * kSubpixelScale + kSubpixelScale / 2;
    for (int x = ux0; x <= ux1; ++x) {
      if (!masked && x == ix0 && ix0 <= ix1) x = ix1 + 1;  // the interior is done
      if (x > ux1) break;
      float z;
      if (masked) {
        interpolate_at_centre(t, e, x, y, f);
        if (surface_masked(scene, t.source, f.bary.y, f.bary.z)) continue;
        z = f.depth;
      } else {
        const int64_t px = int64_t(x) * kSubpixelScale + kSubpixelScale / 2;
        z = interpolate_window_depth(double(e.a[0] * px + e.b[0] * py + e.c[0]) / area,
                                     double(e.a[1] * px + e.b[1] * py + e.c[1]) / area,
                                     double(e.a[2] * px + e.b[2] * py + e.c[2]) / area, t.z);
      }
      add_fragment(spans, x, size_t(y - y0), z, m, b);
    }
  }
}

// One sweep over the binned triangles, band by band in parallel (a band owns its rows and walks
// its triangles in index order; every value is a minimum, so the result does not depend on the
// thread count), each band folded into `range` (channels lo, hi; row 0 = top) as soon as it is
// done, so the scratch is one band per thread.
void sweep_alternatives(const Scene& scene, const mat4& view_proj, Image& range) {
  const int size = range.width;
  const BinnedTriangles binned = setup_and_bin(scene.positions, scene.triangles, view_proj, size, size);
  parallel_for(int64_t(binned.bands.size()), [&](int64_t band) {
    const int y0 = int(band) * kRasterBandRows, y1 = std::min(size, y0 + kRasterBandRows) - 1;
    thread_local BandDepths b;
    b.reset(size, y1 - y0 + 1);
    for (uint32_t ti : binned.bands[size_t(band)]) sweep_triangle(binned.triangles[ti], y0, y1, scene, b);
    for (int y = y0; y <= y1; ++y) {
      const bool edged = b.edged[size_t(y - y0)];
      for (int x = 0; x < size; ++x) {
        const size_t i = size_t(y - y0) * size_t(size) + size_t(x);
        float l = b.lo[i], h = b.hi[i];
        if (edged) {
          for (size_t k = 0; k < size_t(kWorlds); ++k) {
            l = std::min(l, std::min(b.common_lo[i], b.partial_lo[k][i]));
            h = std::max(h, std::min(b.common_hi[i], b.partial_hi[k][i]));
          }
        } else {  // no edge texel in the row: every shift sees the common fragments
          l = std::min(l, b.common_lo[i]), h = std::max(h, b.common_hi[i]);
        }
        float* out = range.pixel(x, size - 1 - y);
        out[0] = l, out[1] = h;
      }
    }
  });
}

// Every outcome of a chain of alpha tests that may flip (raster_alternatives.h): a texel's stored
// depth is the first fragment, front to back, that passes, and each fragment that may flip may pass
// or not, so a correct GL stores any depth from the front-most fragment it may keep (a flip the
// reference discarded) to the front-most one no GL discards (front_certainly_kept), or the clear
// value where every fragment may be cut away. Two flips in a row (a masked fold over a masked
// fold, seed-207 in scenes/regressions) reach past the surface behind the first.
// Per source triangle, the largest depth_tie_margin of its raster pieces (a clipped triangle's
// pieces share its plane).
std::vector<double> plane_margins(const Scene& scene, const mat4& view_proj, int size) {
  const BinnedTriangles binned = setup_and_bin(scene.positions, scene.triangles, view_proj, size, size);
  std::vector<double> m(scene.triangles.size(), 0.0);
  for (const RasterTriangle& t : binned.triangles) m[t.source] = std::max(m[t.source], depth_tie_margin(t));
  return m;
}

void widen_by_alpha_flips(const Scene& scene, const mat4& view_proj, Image& range) {
  const int size = range.width;
  const VisibilityBuffer vb = render_visibility(scene.positions, scene.triangles, view_proj, size, size, &scene);
  const AlphaFlipSurfaces flips = alpha_flip_surfaces(scene, view_proj, vb);
  const VisibilityBuffer kept = front_certainly_kept(scene, view_proj, size, size);
  // Each outcome's plane under the snap too, as every fragment's in the sweep (a sliver's plane
  // tilts far across its width: scenes/regressions/seed-482-small, 2.1e-4 at a 0.1-texel sliver).
  const std::vector<double> margin = plane_margins(scene, view_proj, size);
  const auto lo_hi = [&](const VisibilityBuffer& v, size_t i, float& lo, float& hi) {
    if (v.triangle[i] < 0) {
      lo = hi = 1.0f;  // the clear value
      return;
    }
    const double m = margin[size_t(v.triangle[i])];
    lo = clamped(double(v.depth[i]) - m), hi = clamped(double(v.depth[i]) + m);
  };
  parallel_rows(size, [&](int row) {
    for (int x = 0; x < size; ++x) {
      const size_t i = vb.index(x, row);
      if (!flips.may_flip[i]) continue;
      float flip_lo, flip_hi, deep_lo, deep_hi;
      lo_hi(flips.surface, i, flip_lo, flip_hi);
      lo_hi(kept, i, deep_lo, deep_hi);
      float* out = range.pixel(x, row);
      out[0] = std::min({out[0], flip_lo, deep_lo});
      out[1] = std::max({out[1], flip_hi, deep_hi});
    }
  });
}

}  // namespace

Image shadow_depth_range(const Scene& scene, const mat4& view_proj, int size, ShadowDepthFormat format) {
  Image range(size, size, 2);
  range.channel_names = {tie_range_channel_name("depth", 0, false), tie_range_channel_name("depth", 0, true)};
  sweep_alternatives(scene, view_proj, range);
  if (scene_has_alpha_test(scene)) widen_by_alpha_flips(scene, view_proj, range);
  // Rounding to the format is monotone, so the rounded ends still hold the map's own stored value.
  if (depth_quantum(format) > 0.0)
    for (float& z : range.data) z = stored_window_depth(z, format);
  return range;
}

void add_shadow_tie_ranges(const Scene& scene, const VctSettings& settings, std::vector<ShadowMap>& maps) {
  const int size = settings.shadow_map_size;
  const ShadowDepthFormat format = settings.shadow_depth_format;
  for (ShadowMap& m : maps) {
    if (m.is_cube()) {
      for (size_t f = 0; f < 6; ++f) m.cube_tie_range[f] = shadow_depth_range(scene, m.cube_view_proj[f], size, format);
    } else if (!m.depth.empty()) {
      m.tie_range = shadow_depth_range(scene, m.view_proj, size, format);
    }
  }
}

}  // namespace vct
