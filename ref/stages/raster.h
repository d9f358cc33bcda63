// The software rasterizer behind the shadow maps (through its depth-only path,
// stages/depth_raster.h), the G-buffer and the GPU-rule voxelizer. It is a plain implementation of
// the GL rules (docs/pipeline.md, "Raster conventions"):
//  - window coordinates with the origin at the lower-left, y up; pixel (x, y) covers
//    [x, x+1) x [y, y+1) and its centre is (x+0.5, y+0.5);
//  - vertices snapped to 1/256 pixel (8 sub-pixel bits, as llvmpipe) and edge functions evaluated
//    exactly in 64-bit integers, so a sample on a shared edge is covered by exactly one triangle;
//  - the top-left fill rule stated in y-up window coordinates: a sample exactly on an edge is
//    covered if the edge is a left edge (interior to its right) or a top edge (horizontal,
//    interior below it);
//  - perspective-correct barycentrics at the pixel centre, window depth z_w = z_ndc/2 + 1/2
//    interpolated linearly in screen space (GL: depth is not perspective-divided again);
//  - clipping against the near and far planes always, and against x/y only for vertices beyond a
//    guard band (GL allows either; inside the guard band no clipping changes coverage).
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/math.h"

namespace vct {

struct Scene;  // scene/scene.h: only the alpha test reads it

constexpr int kSubpixelBits = 8;
constexpr int64_t kSubpixelScale = int64_t(1) << kSubpixelBits;
/// One step of the sub-pixel grid window coordinates snap to (GL_SUBPIXEL_BITS, GL 4.5 §14.6):
/// the most a correct GL's snapped vertex may differ from ours on each axis, in pixels (voxels in
/// the voxel raster, texels in the light-space raster). The one snap constant every freedom and
/// bound derived from vertex snapping uses (raster alternatives, texture and fragment slacks, the
/// rasterised models' slope term).
constexpr double kVertexSnapStep = 1.0 / double(kSubpixelScale);

/// A triangle after clipping, projection and snapping, ready to be scanned. The vertex order is
/// made counter-clockwise in window space (area > 0); `front_facing` remembers the original
/// winding (GL's default glFrontFace(GL_CCW)).
struct RasterTriangle {
  int64_t x[3], y[3];   // window coordinates in 1/256 pixel, y up
  double z[3];          // window depth in [0,1]
  double inv_w[3];      // 1/w_clip of each vertex (perspective correction)
  vec3 bary[3];         // barycentrics of each vertex w.r.t. the source triangle (clipping)
  int64_t area2;        // twice the signed area in fixed-point units squared (> 0)
  bool front_facing = true;
  // The winding may come out the other way in a correct GL: |area2| is within what moving each
  // snapped vertex coordinate by one sub-pixel step can change (facing_may_flip).
  bool facing_tie = false;
  int xmin = 0, xmax = -1, ymin = 0, ymax = -1;  // pixel bounding box, clamped to the viewport
  uint32_t source = 0;  // index of the source triangle
};

/// What the scanner reports for one pixel: which samples are covered and the interpolated values
/// at the pixel centre (GL evaluates non-centroid inputs at the centre even when the centre itself
/// is not covered, i.e. extrapolates; depth at the centre as well).
struct RasterFragment {
  int x = 0, y = 0;        // window pixel, y up
  uint32_t coverage = 0;   // bit s = sample s covered
  float depth = 0.0f;      // window depth at the pixel centre, clamped to [0,1]
  vec3 bary{0.0f};         // perspective-correct barycentrics (b0, b1, b2) of the source triangle
};

/// Sample positions of a pixel, offsets in [0,1)^2 from its lower-left corner (y up): 1 sample at
/// the centre; 4 and 8 samples: the D3D11/Vulkan standard patterns (what llvmpipe and most GPUs
/// report through GL_SAMPLE_POSITION). Throws std::invalid_argument for other counts.
const std::vector<vec2>& standard_sample_positions(int samples);

/// True when a triangle with snapped window coordinates x, y (1/256 pixel) and twice its signed
/// area `area2` may have the other winding in a correct GL. GL leaves how window coordinates are
/// computed and rounded to the sub-pixel grid to the implementation (GL 4.5 §14.6.1, "Basic
/// polygon rasterization", computes the area from window coordinates; GL_SUBPIXEL_BITS only says
/// how many bits they keep), so each snapped coordinate may be one step off the reference's.
/// area2 = (x1-x0)(y2-y0) - (y1-y0)(x2-x0) is bilinear in the coordinates: moving every one by at
/// most 1 changes it by at most P + 8, P = sum over the edges of |dx| + |dy| (the first-order
/// terms' coefficients are the edges' dx and dy; the two second-order products at most 2*2
/// each), so the sign may flip iff |area2| <= P + 8 (docs/compare.md, "Raster alternatives").
bool facing_may_flip(const int64_t x[3], const int64_t y[3], int64_t area2);

/// How far moving each snapped coordinate by at most one step may change area2: P + 8, P the
/// edges' L1 lengths (facing_may_flip's bound, above).
int64_t area_snap_reach(const int64_t x[3], const int64_t y[3]);

/// Clips the clip-space triangle, projects it into a width x height viewport and appends the
/// resulting triangles (0 if culled/degenerate, more than 1 if clipping split it) to `out`.
void setup_triangle(const vec4 clip[3], int width, int height, uint32_t source, std::vector<RasterTriangle>& out);

/// Exact coverage of one sample offset (fixed point, relative to the pixel's lower-left corner).
struct EdgeSetup {
  int64_t a[3], b[3], c[3];  // e_i(px, py) = a_i*px + b_i*py + c_i, fixed point
  int64_t bias[3];           // 0 for top/left edges, -1 otherwise (e + bias >= 0 covers)
};
EdgeSetup edge_setup(const RasterTriangle& t);

/// How far a snap of each vertex by up to one subpixel step per axis may move edge i's function
/// at (px, py): the signed area of (v_j', v_k', p) moves by at most s (|p - v_j|_1 + |p - v_k|_1)
/// + 4 s^2 with s = 1 (SnapWorld below), for any p.
int64_t edge_snap_reach(const RasterTriangle& t, int i, int64_t px, int64_t py);

/// Which samples count as covered: the reference's own snapped triangle's, or, for the judge's
/// coverage ties (freedoms/coverage_ties.h, gbuffer_ties.h), those every snap of each vertex by up
/// to one step covers (Certain) or some snap covers (Possible). A snap moves an edge function at
/// sample p by at most s (|p - v_j|_1 + |p - v_k|_1) + 4 s^2 (edge_snap_reach), exact for any p, also
/// beyond the edge's ends where a fragment is extrapolated.
enum class SnapWorld { Reference, Certain, Possible };

/// Whether `world` covers the sample at (px, py) (subpixel units) of triangle t with edges e. Every
/// snapped triangle lies in its vertices' box grown by one step, so Possible covers nothing outside
/// it: the edges' reach alone would (each edge may move that far, not all three at once), and on a
/// triangle a few steps wide it would cover most of the pixels around it (medium hunt seed 145:
/// 1.73 M fragments a snap "may add" to the 4 803 of the reference's, docs/compare.md "Campaign 6").
inline bool covered_in_world(const RasterTriangle& t, const EdgeSetup& e, SnapWorld world, int64_t px, int64_t py) {
  if (world == SnapWorld::Possible &&
      (px < std::min({t.x[0], t.x[1], t.x[2]}) - 1 || px > std::max({t.x[0], t.x[1], t.x[2]}) + 1 ||
       py < std::min({t.y[0], t.y[1], t.y[2]}) - 1 || py > std::max({t.y[0], t.y[1], t.y[2]}) + 1))
    return false;
  for (int i = 0; i < 3; ++i) {
    const int64_t v = e.a[i] * px + e.b[i] * py + e.c[i];
    const bool in = world == SnapWorld::Reference ? v + e.bias[i] >= 0
                    : world == SnapWorld::Certain ? v - edge_snap_reach(t, i, px, py) + e.bias[i] >= 0
                                                  : v + edge_snap_reach(t, i, px, py) >= 0;
    if (!in) return false;
  }
  return true;
}

/// Interpolates at the centre of pixel (x, y) (window coordinates), filling depth and bary.
void interpolate_at_centre(const RasterTriangle& t, const EdgeSetup& e, int x, int y, RasterFragment& f);

/// Window depth from the screen-space barycentrics b_i = e_i(centre) / area2, linear in screen
/// space (GL), clamped to [0,1]. Every raster path calls this one function so that all of them
/// produce the same bits (same operations in the same order).
inline float interpolate_window_depth(double b0, double b1, double b2, const double z[3]) {
  double depth = 0.0;
  depth += b0 * z[0];
  depth += b1 * z[1];
  depth += b2 * z[2];
  return float(std::clamp(depth, 0.0, 1.0));
}

/// Narrows [x0, x1] to the pixels of row y (window coordinates) whose centre the triangle covers:
/// the per-sample test of rasterize() with the centre sample, solved for x per edge in exact
/// integer arithmetic. Returns false when no centre of the row is covered.
bool centre_row_span(const EdgeSetup& e, int y, int& x0, int& x1);

/// The same for the sample at offset (sx, sy) in sub-pixel steps (0..255) from each pixel's
/// lower-left corner: what rasterize() covers with that one sample (centre_row_span is (128, 128)).
bool sample_row_span(const EdgeSetup& e, int y, int64_t sx, int64_t sy, int& x0, int& x1);

/// rasterize with the sample test `covers(edges, px, py)` (subpixel coordinates) and the pixel box
/// grown by `grow` pixels: the raster of a triangle whose edges may lie elsewhere (a vertex snap's
/// worlds, freedoms/voxel_snap_coverage.h); attributes are still interpolated at the pixel centre
/// from `t`.
template <class Covers, class Emit>
void rasterize_covering(const RasterTriangle& t, const std::vector<vec2>& samples, int x0, int x1, int y0, int y1,
                        int grow, Covers&& covers, Emit&& emit) {
  x0 = x0 > t.xmin - grow ? x0 : t.xmin - grow;
  x1 = x1 < t.xmax + grow ? x1 : t.xmax + grow;
  y0 = y0 > t.ymin - grow ? y0 : t.ymin - grow;
  y1 = y1 < t.ymax + grow ? y1 : t.ymax + grow;
  if (x0 > x1 || y0 > y1) return;
  const EdgeSetup e = edge_setup(t);
  int64_t sx[32], sy[32];
  const int ns = int(samples.size());
  for (int s = 0; s < ns; ++s) {
    sx[s] = int64_t(samples[size_t(s)].x * float(kSubpixelScale));
    sy[s] = int64_t(samples[size_t(s)].y * float(kSubpixelScale));
  }
  RasterFragment f;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      uint32_t mask = 0;
      for (int s = 0; s < ns; ++s)
        if (covers(e, int64_t(x) * kSubpixelScale + sx[s], int64_t(y) * kSubpixelScale + sy[s])) mask |= 1u << s;
      if (!mask) continue;
      f.x = x;
      f.y = y;
      f.coverage = mask;
      interpolate_at_centre(t, e, x, y, f);
      emit(static_cast<const RasterFragment&>(f));
    }
  }
}

/// Calls emit(const RasterFragment&) for every pixel of [x0,x1]x[y0,y1] (inclusive, window
/// coordinates) with at least one covered sample, in row-major order (y, then x).
template <class Emit>
void rasterize(const RasterTriangle& t, const std::vector<vec2>& samples, int x0, int x1, int y0, int y1,
               Emit&& emit) {
  const auto covers = [](const EdgeSetup& e, int64_t px, int64_t py) {
    for (int i = 0; i < 3; ++i)
      if (e.a[i] * px + e.b[i] * py + e.c[i] + e.bias[i] < 0) return false;
    return true;
  };
  rasterize_covering(t, samples, x0, x1, y0, y1, 0, covers, std::forward<Emit>(emit));
}

/// Every triangle of a mesh set up for one viewport (clipped, projected, snapped; flattened in
/// source index order) and binned into bands of kRasterBandRows rows (window y). A band is the
/// parallel work item of the full-viewport raster paths: it owns its rows and walks its triangles
/// in index order, so results do not depend on the thread count.
constexpr int kRasterBandRows = 16;
struct BinnedTriangles {
  std::vector<RasterTriangle> triangles;
  std::vector<std::vector<uint32_t>> bands;  // band b: indices into triangles, ascending
};
BinnedTriangles setup_and_bin(const std::vector<vec3>& positions, const std::vector<uvec3>& triangles,
                              const mat4& view_proj, int width, int height);

/// The closest surface at each pixel centre of a width x height view (depth test GL_LESS, depth
/// cleared to 1, no culling, triangles in index order), row 0 = top (image convention).
struct VisibilityBuffer {
  int width = 0, height = 0;
  std::vector<float> depth;          // window depth, 1 where empty
  std::vector<int32_t> triangle;     // source triangle, -1 where empty
  std::vector<vec3> bary;            // perspective-correct barycentrics of that triangle
  std::vector<uint8_t> front_facing; // 1 if the triangle is front facing (CCW in window space)
  std::vector<uint8_t> facing_tie;   // 1 if that facing may flip in a correct GL (facing_may_flip)
  size_t index(int x, int row) const { return size_t(row) * size_t(width) + size_t(x); }
};

/// A width x height buffer with every pixel empty (depth 1, no triangle).
VisibilityBuffer empty_visibility(int width, int height);

/// Writes fragment `f` of triangle `t` into pixel `i` of `vb` (depth, source, barycentrics, facing).
void store_fragment(VisibilityBuffer& vb, size_t i, const RasterTriangle& t, const RasterFragment& f);

/// Edge values along row y from pixel x0, e(x0 + k) = e0[i] + k * step[i], carried in doubles: every
/// term is an integer below 2^53 (|e| < 2^49 for a 16384^2 viewport with the 4-viewport guard band,
/// 8 sub-pixel bits), so they are exactly the int64 values rasterize() converts, and a span loop
/// over k has no int64 -> double conversion per pixel (it vectorizes).
struct SpanEdges {
  double e0[3], step[3];
  SpanEdges(const EdgeSetup& e, int y, int x0);
};

/// Rasterizes every triangle of `positions`/`triangles` (world space) through `view_proj`.
/// Parallel over bands of rows; each band walks the triangles in index order, so the result does
/// not depend on the thread count. With `alpha_scene` (whose triangles these are), a fragment that
/// scene/alpha_mask.h's surface_masked() cuts away is discarded before the depth test writes.
/// `sample`: the coverage sample's offset in the pixel ([0,1)^2, y up; multiples of 1/256), the
/// centre by default; depth and barycentrics are always those at the centre (as GL interpolates
/// at the centre whichever sample is covered), so an offset sample shows which surface a correct
/// GL whose edges lie that far off the reference's would have kept (freedoms/gbuffer_ties.h).
VisibilityBuffer render_visibility(const std::vector<vec3>& positions,
                                   const std::vector<uvec3>& triangles, const mat4& view_proj,
                                   int width, int height, const Scene* alpha_scene = nullptr,
                                   vec2 sample = vec2(0.5f));

}  // namespace vct
