#include "stages/raster.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/parallel.h"
#include "core/parallel_gather.h"
#include "scene/alpha_mask.h"

namespace vct {

namespace {

// Vertices further out than this many viewport half-widths are clipped against x/y (guard band).
// Keeps fixed-point window coordinates well inside 2^31.
constexpr double kGuardBand = 4.0;

// Floor and ceiling of n / d for d > 0 (C++ division truncates toward zero).
int64_t floor_div(int64_t n, int64_t d) { return n >= 0 ? n / d : -((-n + d - 1) / d); }
int64_t ceil_div(int64_t n, int64_t d) { return -floor_div(-n, d); }

struct ClipVertex {
  glm::dvec4 c;
  glm::dvec3 b;
};

// Signed distance to one of the clip planes; >= 0 is inside.
double plane_distance(const glm::dvec4& c, int plane) {
  switch (plane) {
    case 0: return c.w + c.z;  // near: z >= -w
    case 1: return c.w - c.z;  // far: z <= w
    case 2: return kGuardBand * c.w + c.x;
    case 3: return kGuardBand * c.w - c.x;
    case 4: return kGuardBand * c.w + c.y;
    default: return kGuardBand * c.w - c.y;
  }
}

// Sutherland–Hodgman against one plane.
std::vector<ClipVertex> clip_polygon(const std::vector<ClipVertex>& in, int plane) {
  std::vector<ClipVertex> out;
  const size_t n = in.size();
  for (size_t i = 0; i < n; ++i) {
    const ClipVertex& a = in[i];
    const ClipVertex& b = in[(i + 1) % n];
    const double da = plane_distance(a.c, plane), db = plane_distance(b.c, plane);
    if (da >= 0.0) out.push_back(a);
    if ((da >= 0.0) != (db >= 0.0)) {
      const double t = da / (da - db);
      out.push_back({a.c + (b.c - a.c) * t, a.b + (b.b - a.b) * t});
    }
  }
  return out;
}

bool needs_clip(const ClipVertex v[3], int plane) {
  for (int i = 0; i < 3; ++i)
    if (plane_distance(v[i].c, plane) < 0.0) return true;
  return false;
}

void emit_triangle(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, int width, int height,
                   uint32_t source, std::vector<RasterTriangle>& out) {
  RasterTriangle t;
  const ClipVertex* v[3] = {&v0, &v1, &v2};
  for (int i = 0; i < 3; ++i)
    if (!(v[i]->c.w > 0.0)) return;  // only possible for non-perspective w; nothing to draw
  for (int i = 0; i < 3; ++i) {
    const double inv_w = 1.0 / v[i]->c.w;
    const double wx = (v[i]->c.x * inv_w * 0.5 + 0.5) * double(width);
    const double wy = (v[i]->c.y * inv_w * 0.5 + 0.5) * double(height);
    t.x[i] = int64_t(std::nearbyint(wx * double(kSubpixelScale)));
    t.y[i] = int64_t(std::nearbyint(wy * double(kSubpixelScale)));
    t.z[i] = v[i]->c.z * inv_w * 0.5 + 0.5;
    t.inv_w[i] = inv_w;
    t.bary[i] = vec3(v[i]->b);
  }
  int64_t area2 = (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.y[1] - t.y[0]) * (t.x[2] - t.x[0]);
  if (area2 == 0) return;  // degenerate after snapping: GL produces no fragments
  t.front_facing = area2 > 0;
  t.facing_tie = facing_may_flip(t.x, t.y, area2);
  if (area2 < 0) {  // make it counter-clockwise so every edge has the interior on its left
    std::swap(t.x[1], t.x[2]);
    std::swap(t.y[1], t.y[2]);
    std::swap(t.z[1], t.z[2]);
    std::swap(t.inv_w[1], t.inv_w[2]);
    std::swap(t.bary[1], t.bary[2]);
    area2 = -area2;
  }
  t.area2 = area2;
  const int64_t xmin = std::min({t.x[0], t.x[1], t.x[2]}), xmax = std::max({t.x[0], t.x[1], t.x[2]});
  const int64_t ymin = std::min({t.y[0], t.y[1], t.y[2]}), ymax = std::max({t.y[0], t.y[1], t.y[2]});
  // Pixels whose square touches the box; samples are then tested exactly.
  t.xmin = int(std::max<int64_t>(0, xmin >> kSubpixelBits));
  t.xmax = int(std::min<int64_t>(width - 1, xmax >> kSubpixelBits));
  t.ymin = int(std::max<int64_t>(0, ymin >> kSubpixelBits));
  t.ymax = int(std::min<int64_t>(height - 1, ymax >> kSubpixelBits));
  if (t.xmin > t.xmax || t.ymin > t.ymax) return;
  t.source = source;
  out.push_back(t);
}

}  // namespace

int64_t area_snap_reach(const int64_t x[3], const int64_t y[3]) {
  int64_t perimeter = 0;  // L1 length of the three edges, in sub-pixel steps
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    perimeter += std::abs(x[j] - x[i]) + std::abs(y[j] - y[i]);
  }
  return perimeter + 8;
}

bool facing_may_flip(const int64_t x[3], const int64_t y[3], int64_t area2) {
  return std::abs(area2) <= area_snap_reach(x, y);
}

const std::vector<vec2>& standard_sample_positions(int samples) {
  static const std::vector<vec2> one = {{0.5f, 0.5f}};
  static const std::vector<vec2> four = {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
  // D3D11 standard 8x pattern, offsets in 1/16 pixel from the centre.
  static const std::vector<vec2> eight = [] {
    const int o[8][2] = {{1, -3}, {-1, 3}, {5, 1}, {-3, -5}, {-5, 5}, {-7, -1}, {3, 7}, {7, -7}};
    std::vector<vec2> p;
    for (auto& s : o) p.emplace_back(0.5f + float(s[0]) / 16.0f, 0.5f + float(s[1]) / 16.0f);
    return p;
  }();
  switch (samples) {
    case 1: return one;
    case 4: return four;
    case 8: return eight;
    default: throw std::invalid_argument("sample count must be 1, 4 or 8");
  }
}

void setup_triangle(const vec4 clip[3], int width, int height, uint32_t source, std::vector<RasterTriangle>& out) {
  ClipVertex v[3];
  for (int i = 0; i < 3; ++i) {
    v[i].c = glm::dvec4(clip[i]);
    v[i].b = glm::dvec3(i == 0, i == 1, i == 2);
  }
  bool clip_any = false;
  for (int p = 0; p < 6; ++p) clip_any = clip_any || needs_clip(v, p);
  if (!clip_any) {
    emit_triangle(v[0], v[1], v[2], width, height, source, out);
    return;
  }
  std::vector<ClipVertex> poly(v, v + 3);
  for (int p = 0; p < 6 && poly.size() >= 3; ++p) poly = clip_polygon(poly, p);
  for (size_t i = 1; i + 1 < poly.size(); ++i) emit_triangle(poly[0], poly[i], poly[i + 1], width, height, source, out);
}

EdgeSetup edge_setup(const RasterTriangle& t) {
  EdgeSetup e{};
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;  // edge i runs from vertex j to vertex k
    const int64_t dx = t.x[k] - t.x[j], dy = t.y[k] - t.y[j];
    e.a[i] = -dy;
    e.b[i] = dx;
    e.c[i] = dy * t.x[j] - dx * t.y[j];
    const bool left = dy < 0, top = dy == 0 && dx < 0;  // CCW, y up: interior on the left
    e.bias[i] = (left || top) ? 0 : -1;
  }
  return e;
}

int64_t edge_snap_reach(const RasterTriangle& t, int i, int64_t px, int64_t py) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;  // edge i runs from vertex j to vertex k (edge_setup)
  return std::abs(px - t.x[j]) + std::abs(py - t.y[j]) + std::abs(px - t.x[k]) + std::abs(py - t.y[k]) + 4;
}

void interpolate_at_centre(const RasterTriangle& t, const EdgeSetup& e, int x, int y, RasterFragment& f) {
  const int64_t px = int64_t(x) * kSubpixelScale + kSubpixelScale / 2;
  const int64_t py = int64_t(y) * kSubpixelScale + kSubpixelScale / 2;
  double b[3], q[3], qsum = 0.0;
  for (int i = 0; i < 3; ++i) {
    b[i] = double(e.a[i] * px + e.b[i] * py + e.c[i]) / double(t.area2);
    q[i] = b[i] * t.inv_w[i];
    qsum += q[i];
  }
  glm::dvec3 bary(0.0);
  for (int i = 0; i < 3; ++i) bary += glm::dvec3(t.bary[i]) * (q[i] / qsum);
  f.bary = vec3(bary);
  f.depth = interpolate_window_depth(b[0], b[1], b[2], t.z);
}

bool centre_row_span(const EdgeSetup& e, int y, int& x0, int& x1) {
  return sample_row_span(e, y, kSubpixelScale / 2, kSubpixelScale / 2, x0, x1);
}

bool sample_row_span(const EdgeSetup& e, int y, int64_t sx, int64_t sy, int& x0, int& x1) {
  const int64_t py = int64_t(y) * kSubpixelScale + sy;
  int64_t lo = x0, hi = x1;
  for (int i = 0; i < 3; ++i) {
    // rasterize() covers the sample of pixel x iff e_i + bias_i >= 0 at px = x*S + sx, i.e.
    // step*x + r >= 0 with:
    const int64_t step = e.a[i] * kSubpixelScale;
    const int64_t r = e.a[i] * sx + e.b[i] * py + e.c[i] + e.bias[i];
    if (step > 0) {
      lo = std::max(lo, ceil_div(-r, step));
    } else if (step < 0) {
      hi = std::min(hi, floor_div(r, -step));
    } else if (r < 0) {
      return false;  // horizontal edge with the whole row outside
    }
  }
  if (lo > hi) return false;
  x0 = int(lo);
  x1 = int(hi);
  return true;
}

BinnedTriangles setup_and_bin(const std::vector<vec3>& positions, const std::vector<uvec3>& triangles,
                              const mat4& view_proj, int width, int height) {
  // Set-up per source triangle in parallel, gathered in index order.
  BinnedTriangles b;
  b.triangles = parallel_gather<RasterTriangle>(int64_t(triangles.size()), [&](int64_t i, std::vector<RasterTriangle>& out) {
    const uvec3 tri = triangles[size_t(i)];
    const vec4 clip[3] = {view_proj * vec4(positions[tri.x], 1.0f), view_proj * vec4(positions[tri.y], 1.0f),
                          view_proj * vec4(positions[tri.z], 1.0f)};
    setup_triangle(clip, width, height, uint32_t(i), out);
  });

  b.bands.resize(size_t((height + kRasterBandRows - 1) / kRasterBandRows));
  for (size_t i = 0; i < b.triangles.size(); ++i) {
    const RasterTriangle& t = b.triangles[i];
    for (int band = t.ymin / kRasterBandRows; band <= t.ymax / kRasterBandRows; ++band)
      b.bands[size_t(band)].push_back(uint32_t(i));
  }
  return b;
}

VisibilityBuffer empty_visibility(int width, int height) {
  VisibilityBuffer vb;
  vb.width = width;
  vb.height = height;
  const size_t n = size_t(width) * size_t(height);
  vb.depth.assign(n, 1.0f);
  vb.triangle.assign(n, -1);
  vb.bary.assign(n, vec3(0.0f));
  vb.front_facing.assign(n, 0);
  vb.facing_tie.assign(n, 0);
  return vb;
}

void store_fragment(VisibilityBuffer& vb, size_t i, const RasterTriangle& t, const RasterFragment& f) {
  vb.depth[i] = f.depth;
  vb.triangle[i] = int32_t(t.source);
  vb.bary[i] = f.bary;
  vb.front_facing[i] = t.front_facing ? 1 : 0;
  vb.facing_tie[i] = t.facing_tie ? 1 : 0;
}

SpanEdges::SpanEdges(const EdgeSetup& e, int y, int x0) {
  const int64_t px = int64_t(x0) * kSubpixelScale + kSubpixelScale / 2;
  const int64_t py = int64_t(y) * kSubpixelScale + kSubpixelScale / 2;
  for (int i = 0; i < 3; ++i) {
    e0[i] = double(e.a[i] * px + e.b[i] * py + e.c[i]);
    step[i] = double(e.a[i] * kSubpixelScale);
  }
}

VisibilityBuffer render_visibility(const std::vector<vec3>& positions,
                                   const std::vector<uvec3>& triangles, const mat4& view_proj,
                                   int width, int height, const Scene* alpha_scene, vec2 sample) {
  const BinnedTriangles binned = setup_and_bin(positions, triangles, view_proj, width, height);
  VisibilityBuffer vb = empty_visibility(width, height);
  const std::vector<vec2> samples = {sample};
  parallel_for(int64_t(binned.bands.size()), [&](int64_t band) {
    const int y0 = int(band) * kRasterBandRows, y1 = std::min(height, y0 + kRasterBandRows) - 1;
    for (uint32_t ti : binned.bands[size_t(band)]) {
      const RasterTriangle& t = binned.triangles[ti];
      const bool alpha_tested = alpha_scene && triangle_alpha_tested(*alpha_scene, t.source);
      rasterize(t, samples, 0, width - 1, y0, y1, [&](const RasterFragment& f) {
        const size_t idx = vb.index(f.x, height - 1 - f.y);
        if (!(f.depth < vb.depth[idx])) return;  // GL_LESS
        if (alpha_tested && surface_masked(*alpha_scene, t.source, f.bary.y, f.bary.z)) return;
        store_fragment(vb, idx, t, f);
      });
    }
  });
  return vb;
}

}  // namespace vct
