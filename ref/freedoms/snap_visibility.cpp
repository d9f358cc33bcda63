#include "freedoms/snap_visibility.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <vector>

#include "core/pcf_taps.h"
#include "core/precision.h"
#include "stages/cube_map.h"
#include "stages/shadow_map.h"

namespace vct {

namespace {

constexpr double kU = 1.0 / 16777216.0;  // 2^-24, one float rounding
constexpr double kG4 = 4.0 * kU / (1.0 - 4.0 * kU);

using Point = glm::dvec2;  // (a, b) in [-1, 1]^2

/// A convex polygon's vertices in order. The unit square clipped a few times keeps a handful of
/// them (one more per clip at most, on convex input), so they live inline; past kInline they move
/// to the heap. A polygon is made per candidate texel cell and per tap: a heap vector for each
/// was a fifth of the voxel slack's time.
class Polygon {
 public:
  Polygon() = default;
  Polygon(std::initializer_list<Point> points) {
    for (const Point& p : points) push_back(p);
  }
  Polygon(const Polygon& o) {
    for (const Point& p : o) push_back(p);
  }
  Polygon& operator=(const Polygon& o) {
    if (this == &o) return *this;
    n_ = 0;
    spill_.clear();
    for (const Point& p : o) push_back(p);
    return *this;
  }
  void push_back(const Point& p) {
    if (n_ < kInline) {
      inline_[n_++] = p;
      return;
    }
    if (n_ == kInline) spill_.assign(inline_, inline_ + kInline);
    spill_.push_back(p);
    ++n_;
  }
  const Point* begin() const { return n_ > kInline ? spill_.data() : inline_; }
  const Point* end() const { return begin() + n_; }
  const Point& operator[](size_t i) const { return begin()[i]; }
  size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }

 private:
  static constexpr size_t kInline = 16;
  Point inline_[kInline];
  size_t n_ = 0;
  std::vector<Point> spill_;
};

/// c + a x + b y over the parallelogram's parameters.
struct Linear {
  double c = 0.0, a = 0.0, b = 0.0;
  double at(const Point& p) const { return c + a * p.x + b * p.y; }
  Linear operator-(const Linear& o) const { return {c - o.c, a - o.a, b - o.b}; }
  Linear operator+(const Linear& o) const { return {c + o.c, a + o.a, b + o.b}; }
  Linear operator*(double k) const { return {c * k, a * k, b * k}; }
};

const Polygon& unit_square() {
  static const Polygon square = {{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}};
  return square;
}

/// The part of a convex polygon where g >= 0 (one Sutherland–Hodgman step).
Polygon clip(const Polygon& in, const Linear& g) {
  Polygon out;
  for (size_t i = 0; i < in.size(); ++i) {
    const Point& p = in[i];
    const Point& n = in[(i + 1) % in.size()];
    const double gp = g.at(p), gn = g.at(n);
    if (gp >= 0.0) out.push_back(p);
    if ((gp >= 0.0) != (gn >= 0.0)) out.push_back(p + (n - p) * (gp / (gp - gn)));
  }
  return out;
}

/// Clip-space row `row` of world -> clip matrix m at the parallelogram's points, exactly.
Linear clip_row(const mat4& m, const SnapParallelogram& q, int row) {
  Linear l{double(m[3][row]), 0.0, 0.0};
  for (int j = 0; j < 3; ++j) {
    const double k = double(m[j][row]);
    l.c += k * double(q.centre[j]);
    l.a += k * double(q.du[j]);
    l.b += k * double(q.dv[j]);
  }
  return l;
}

std::array<vec3, 5> points_of(const SnapParallelogram& q) {
  std::array<vec3, 5> out;
  out[0] = q.centre;
  size_t k = 1;
  for (const Point& c : unit_square()) out[k++] = q.centre + float(c.x) * q.du + float(c.y) * q.dv;
  return out;
}

/// The largest NDC rounding margin (shadow_ties.h) of row `row` over the centre and corners.
double ndc_margin(const mat4& m, const SnapParallelogram& q, int row) {
  double e = 0.0;
  for (const vec3& p : points_of(q)) e = std::max(e, ndc_error(m, p, row, q.margin));
  return e;
}

/// A texel coordinate (num / den + 1) / 2 * size with den > 0 on the region (a texel column of a
/// 2D map: clip x over w; of a cube face: sc over ma), and its float margin in texels.
struct Coordinate {
  Linear num, den;
  int size;
  double margin;
  double den_margin = 0.0;  // how far a correct GL's den may lie from the exact one (taps per 1/w)
  double at(const Point& p) const { return (num.at(p) / den.at(p) + 1.0) * 0.5 * double(size); }
  /// g >= 0 exactly where the coordinate is >= x (den > 0).
  Linear at_least(double x) const { return num - den * (2.0 * x / double(size) - 1.0); }
};

/// What one texel's compare sees: the lookup point's clip z and w on the map that texel lies on,
/// its stored depth + bias (rounded in float, as both sides add them), and the depth's margin.
struct TexelCompare {
  Linear z, w;
  double stored_plus_bias;
  double margin;
};

struct TapState {
  bool lit_everywhere = true, lit_somewhere = false;
};

/// One compare over a region: the window depth z / w * 0.5 + 0.5, a ratio of affine functions,
/// takes its extremes over the convex region at its vertices (it is monotone along every line
/// where w > 0). A point outside [0, 1] is lit, as the lookup makes it.
void compare_over(const Polygon& region, const TexelCompare& t, TapState& s) {
  double lo = 1e300, hi = -1e300;
  for (const Point& p : region) {
    const double w = t.w.at(p);
    if (!(w > 0.0)) {  // behind the light's plane somewhere: lit there, unknown elsewhere
      s.lit_somewhere = true;
      s.lit_everywhere = false;
      return;
    }
    const double z = t.z.at(p) / w * 0.5 + 0.5;
    lo = std::min(lo, z);
    hi = std::max(hi, z);
  }
  lo -= t.margin;
  hi += t.margin;
  const bool may_be_outside = lo < 0.0 || hi > 1.0;
  s.lit_somewhere = s.lit_somewhere || may_be_outside || lo <= t.stored_plus_bias;
  s.lit_everywhere = s.lit_everywhere && hi <= t.stored_plus_bias;
}

/// Where a tap's offset lies over a region: `tu`, `tv` its offset in texels (the midpoint of its
/// range where it scales with 1/w) and `spread` how far it may lie from them (the range's half
/// width plus the offset's own roundings); the fractions and the cells widen by it.
struct TapOffset {
  double tu = 0.0, tv = 0.0, spread = 0.0;
};

/// A filter-then-compare tap over a cell (filters_depth_first): the blend of the four texels'
/// stored depth + bias (the weights sum to 1, so blending stored + bias is blending the depths and
/// adding the bias) is bilinear in the fractions, so over the box of fractions -- the cell's, +-
/// the offset's spread and the filter weights' 8 sub-texel bits (precision table row
/// filter-weights) -- it takes its extremes at the box's corners; the blend's float arithmetic
/// adds g4 of the largest value (shadow_ties.cpp's filtered_tap_range). The tap is then one
/// compare of the point's depth over the cell with [D_lo, D_hi].
VisibilityRange filtered_tap_over(const Polygon& cell, const TexelCompare (&t)[4], double ax_lo, double ax_hi,
                                  double ay_lo, double ay_hi) {
  double d_lo = 1e300, d_hi = -1e300, largest = 0.0;
  for (const TexelCompare& c : t) largest = std::max(largest, std::abs(c.stored_plus_bias));
  for (const double ax : {ax_lo, ax_hi})
    for (const double ay : {ay_lo, ay_hi}) {
      const double d = (1 - ax) * (1 - ay) * t[0].stored_plus_bias + ax * (1 - ay) * t[1].stored_plus_bias +
                       (1 - ax) * ay * t[2].stored_plus_bias + ax * ay * t[3].stored_plus_bias;
      d_lo = std::min(d_lo, d), d_hi = std::max(d_hi, d);
    }
  const double ef = (4.0 * kU / (1.0 - 4.0 * kU)) * largest + kU * largest;
  TexelCompare low = t[0], high = t[0];
  low.stored_plus_bias = d_lo - ef, high.stored_plus_bias = d_hi + ef;
  TapState everywhere, somewhere;
  compare_over(cell, low, everywhere);
  compare_over(cell, high, somewhere);
  return {everywhere.lit_everywhere ? 1.0f : 0.0f, somewhere.lit_somewhere ? 1.0f : 0.0f};
}

/// One tap's [lo, hi] over a region where it reads fixed texels: nearest, one compare; linear, GL
/// 4.5 section 8.23.1's bilinear blend of the four compares around the coordinate - 1/2, whose
/// weights are bilinear in the fractions (ax, ay), so over any box of fractions they take their
/// extremes at its corners (the box of the region's fractions contains the region's); or, an
/// engine that filters first, filtered_tap_over.
VisibilityRange tap_over(const Polygon& cell, const Coordinate& u, const Coordinate& v, const TapOffset& o, int i,
                         int j, const VctSettings& s, const std::function<TexelCompare(int, int)>& texel) {
  if (s.shadow_compare == ShadowCompare::Nearest) {
    TapState st;
    compare_over(cell, texel(i, j), st);
    return {st.lit_everywhere ? 1.0f : 0.0f, st.lit_somewhere ? 1.0f : 0.0f};
  }
  const bool filter_first = filters_depth_first(s);
  // A filtered tap's weights carry their 8-bit freedom here; compared first, linear_compare_slack does.
  const double widen = o.spread + (filter_first ? precision(Precision::FilterWeights) : 0.0);
  double ax_lo = 1.0, ax_hi = 0.0, ay_lo = 1.0, ay_hi = 0.0;
  for (const Point& p : cell) {
    const double ax = u.at(p) + o.tu - double(i), ay = v.at(p) + o.tv - double(j);
    ax_lo = std::min(ax_lo, std::clamp(ax - widen, 0.0, 1.0)), ax_hi = std::max(ax_hi, std::clamp(ax + widen, 0.0, 1.0));
    ay_lo = std::min(ay_lo, std::clamp(ay - widen, 0.0, 1.0)), ay_hi = std::max(ay_hi, std::clamp(ay + widen, 0.0, 1.0));
  }
  const TexelCompare t[4] = {texel(i, j), texel(i + 1, j), texel(i, j + 1), texel(i + 1, j + 1)};
  if (filter_first) return filtered_tap_over(cell, t, ax_lo, ax_hi, ay_lo, ay_hi);
  TapState st[4];
  for (int k = 0; k < 4; ++k) compare_over(cell, t[k], st[k]);
  VisibilityRange r{1.0f, 0.0f};
  for (const double ax : {ax_lo, ax_hi})
    for (const double ay : {ay_lo, ay_hi}) {
      const double w[4] = {(1 - ax) * (1 - ay), ax * (1 - ay), (1 - ax) * ay, ax * ay};
      double lo = 0.0, hi = 0.0;
      for (int k = 0; k < 4; ++k) {
        lo += st[k].lit_everywhere ? w[k] : 0.0;
        hi += st[k].lit_somewhere ? w[k] : 0.0;
      }
      r.lo = std::min(r.lo, float(lo));
      r.hi = std::max(r.hi, float(hi));
    }
  return r;
}

/// The taps' offsets over `region` (TapOffset), `w` the lookup's clip w there (a 2D map's w, a
/// cube face's major axis), known within e_w, and `size` the map's: texel offsets as given; UV
/// ones times the size (one rounding); per 1/w, the range of o / w over the region's w widened by
/// e_w (w > e_w there, else no bound: empty), and the divide's rounding (2.5 ulp, GLSL 4.50
/// section 4.7.1, with the UV multiply 4 u).
std::vector<TapOffset> tap_offsets_over(const Polygon& region, const Linear& w, double e_w, int size,
                                        const VctSettings& s) {
  std::vector<TapOffset> out;
  const bool inv_w = !s.pcf_taps.empty() && s.pcf_tap_scale == PcfTapScale::InvW;
  double w_lo = 1e300, w_hi = 0.0;
  for (const Point& p : region) w_lo = std::min(w_lo, w.at(p)), w_hi = std::max(w_hi, w.at(p));
  for (const vec2& t : tap_positions(0.0f, 0.0f, s, size, 1.0f)) {
    if (!inv_w) {
      const double round = s.pcf_taps.empty() || s.pcf_tap_unit == PcfTapUnit::Texel ? 0.0 : 4.0 * kU * double(glm::length(t));
      out.push_back({double(t.x), double(t.y), round});
      continue;
    }
    if (!(w_lo - e_w > 0.0)) return {};
    const double lo = 1.0 / (w_hi + e_w), hi = 1.0 / (w_lo - e_w);
    const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    const double big = std::max(std::abs(double(t.x)), std::abs(double(t.y)));
    out.push_back({double(t.x) * mid, double(t.y) * mid, big * half + 4.0 * kU * big * hi});
  }
  return out;
}

/// [lo, hi] of the PCF mean over `region`: each tap at (u, v) + its offset, over every cell of
/// texels its coordinate may fall in on part of the region (edges widened by the margins).
VisibilityRange pcf_over(const Polygon& region, const Coordinate& u, const Coordinate& v, const VctSettings& s,
                         const std::function<TexelCompare(int, int)>& texel) {
  double u_lo = 1e300, u_hi = -1e300, v_lo = 1e300, v_hi = -1e300;
  for (const Point& p : region) {
    u_lo = std::min(u_lo, u.at(p)), u_hi = std::max(u_hi, u.at(p));
    v_lo = std::min(v_lo, v.at(p)), v_hi = std::max(v_hi, v.at(p));
  }
  const std::vector<TapOffset> taps = tap_offsets_over(region, u.den, u.den_margin, u.size, s);
  if (taps.empty()) return {0.0f, 1.0f};  // w may reach 0 on the region: no bound
  double largest_offset = 16.0;  // parse_pcf_taps' limit, the largest a texel offset may be
  for (const TapOffset& o : taps) largest_offset = std::max({largest_offset, std::abs(o.tu), std::abs(o.tv)});
  // Adding an offset rounds once more on each side (as shadow_ties.cpp's pcf_range).
  const double e_tap = 4.0 * kU * (std::max(std::abs(u_hi), std::abs(v_hi)) + largest_offset);
  // Nearest reads the texel floor(t); linear the four from floor(t - 1/2).
  const double half = s.shadow_compare == ShadowCompare::Nearest ? 0.0 : 0.5;
  double lo = 0.0, hi = 0.0;
  for (const TapOffset& offset : taps) {
    const double eu = u.margin + e_tap + offset.spread, ev = v.margin + e_tap + offset.spread;
    const TapOffset o{offset.tu - half, offset.tv - half, offset.spread};
    const double tu = o.tu, tv = o.tv;
    VisibilityRange tap{1.0f, 0.0f};
    for (int i = int(std::floor(u_lo + tu - eu)); i <= int(std::floor(u_hi + tu + eu)); ++i)
      for (int j = int(std::floor(v_lo + tv - ev)); j <= int(std::floor(v_hi + tv + ev)); ++j) {
        Polygon cell = clip(region, u.at_least(double(i) - tu - eu));
        cell = clip(cell, u.at_least(double(i + 1) - tu + eu) * -1.0);
        cell = clip(cell, v.at_least(double(j) - tv - ev));
        cell = clip(cell, v.at_least(double(j + 1) - tv + ev) * -1.0);
        if (cell.empty()) continue;
        const VisibilityRange r = tap_over(cell, u, v, o, i, j, s, texel);
        tap.lo = std::min(tap.lo, r.lo);
        tap.hi = std::max(tap.hi, r.hi);
      }
    lo += double(tap.lo);
    hi += double(tap.hi);
  }
  const double n = double(std::max<size_t>(taps.size(), 1));
  return {float(lo / n), float(hi / n)};
}

double stored_plus_bias(const Image& depth, int x, int y, float bias) {
  return double(depth.at(x, depth.height - 1 - y, 0) + bias);
}

VisibilityRange range_2d(const ShadowMap& map, const SnapParallelogram& q, const VctSettings& s) {
  const mat4& m = map.view_proj;
  const Linear x = clip_row(m, q, 0), y = clip_row(m, q, 1), z = clip_row(m, q, 2), w = clip_row(m, q, 3);
  for (const Point& p : unit_square())
    if (!(w.at(p) > 0.0)) return {0.0f, 1.0f};  // the light's plane crosses it: lit on one side
  const double e[3] = {ndc_margin(m, q, 0), ndc_margin(m, q, 1), ndc_margin(m, q, 2)};
  // Outside the frustum the lookup is lit: inside everywhere, outside everywhere, or either.
  bool inside_everywhere = true, outside_everywhere = false;
  const Linear* rows[3] = {&x, &y, &z};
  for (int k = 0; k < 3; ++k) {
    double lo = 1e300, hi = -1e300;
    for (const Point& p : unit_square()) {
      const double ndc = rows[k]->at(p) / w.at(p);
      lo = std::min(lo, ndc), hi = std::max(hi, ndc);
    }
    inside_everywhere = inside_everywhere && lo - e[k] >= -1.0 && hi + e[k] <= 1.0;
    outside_everywhere = outside_everywhere || lo - e[k] > 1.0 || hi + e[k] < -1.0;
  }
  if (outside_everywhere) return {};
  const Image& depth = map.depth;
  // A correct GL's clip w: 4 terms within g4 of their magnitude, the point within q.margin.
  double e_w = 0.0;
  for (const vec3& p : points_of(q)) {
    double s_w = std::abs(double(m[3][3])), a_w = 0.0;
    for (int k = 0; k < 3; ++k) s_w += std::abs(double(m[k][3]) * double(p[k])), a_w += std::abs(double(m[k][3]));
    e_w = std::max(e_w, kG4 * s_w + a_w * q.margin);
  }
  const Coordinate u{x, w, depth.width, texel_margin(e[0], depth.width), e_w};
  const Coordinate v{y, w, depth.height, texel_margin(e[1], depth.height)};
  const double ez = depth_margin(e[2]);
  VisibilityRange r = pcf_over(unit_square(), u, v, s, [&](int i, int j) {
    // Past the edge: the edge texel (clamp) or the border's depth (stages/shadow_map.h, stored_depth).
    return TexelCompare{z, w, double(stored_depth(depth, i, j, s.shadow_border) + s.shadow_bias), ez};
  });
  if (!inside_everywhere) r.hi = 1.0f;
  return r;
}

/// r = point - light, per world axis.
Linear axis_of(const SnapParallelogram& q, const vec3& light, int k) {
  return {double(q.centre[k]) - double(light[k]), double(q.du[k]), double(q.dv[k])};
}

Linear dot_axis(const Linear r[3], const vec3& axis) {
  Linear out;
  for (int k = 0; k < 3; ++k) out = out + r[k] * double(axis[k]);
  return out;
}

/// The direction r = point - light over q, per world axis, and how far a lookup's may be off:
/// p - light rounds once on each side, and p itself is known within q.margin.
struct CubeDirections {
  Linear r[3];
  double er = 0.0;
};

CubeDirections cube_directions(const SnapParallelogram& q, const vec3& light) {
  CubeDirections d{{axis_of(q, light, 0), axis_of(q, light, 1), axis_of(q, light, 2)}, 0.0};
  double largest = 0.0;
  for (const Point& p : unit_square())
    for (int k = 0; k < 3; ++k) largest = std::max(largest, std::abs(d.r[k].at(p)));
  d.er = 2.0 * kU * largest + q.margin;
  return d;
}

/// Where face `home` may be selected: ma >= |r_k| of the other axes, within the rounding.
Polygon face_region(const CubeDirections& d, int home) {
  const CubeFaceAxes& axes = cube_face_axes(home);
  const Linear ma = dot_axis(d.r, axes.major_axis);
  Polygon region = clip(unit_square(), ma);
  for (int k = 0; k < 3 && !region.empty(); ++k) {
    if (std::abs(axes.major_axis[k]) > 0.0f) continue;
    region = clip(region, ma - d.r[k] + Linear{2.0 * d.er, 0.0, 0.0});
    region = clip(region, ma + d.r[k] + Linear{2.0 * d.er, 0.0, 0.0});
  }
  return region;
}

VisibilityRange range_cube(const ShadowMap& map, const vec3& light, const SnapParallelogram& q,
                           const VctSettings& s) {
  const CubeDirections dirs = cube_directions(q, light);
  const Linear* r = dirs.r;
  const double er = dirs.er;
  const int size = map.cube[0].width;
  VisibilityRange out{1.0f, 0.0f};
  for (int home = 0; home < 6; ++home) {
    const CubeFaceAxes& axes = cube_face_axes(home);
    const Linear ma = dot_axis(r, axes.major_axis);
    const Polygon region = face_region(dirs, home);
    if (region.empty()) continue;
    double ma_min = 1e300;
    for (const Point& p : region) ma_min = std::min(ma_min, ma.at(p));
    if (!(ma_min > er)) return {0.0f, 1.0f};  // a face seen edge-on at the light: no bound here
    // s = (sc / |ma| + 1) / 2 with sc, ma each off by er (shadow_ties.cpp's range_cube).
    const double e_q = 2.0 * er / (ma_min - er) + 3.0 * kU;
    const Coordinate u{dot_axis(r, axes.sc_axis), ma, size, texel_margin(e_q, size), er};
    const Coordinate v{dot_axis(r, axes.tc_axis), ma, size, texel_margin(e_q, size)};
    const VisibilityRange one = pcf_over(region, u, v, s, [&](int i, int j) {
      const CubeTexel t = cube_texel(home, i, j, size);
      const mat4& m = map.cube_view_proj[size_t(t.face)];
      return TexelCompare{clip_row(m, q, 2), clip_row(m, q, 3),
                          stored_plus_bias(map.cube[size_t(t.face)], t.x, t.y, s.shadow_bias),
                          depth_margin(ndc_margin(m, q, 2))};
    });
    out.lo = std::min(out.lo, one.lo);
    out.hi = std::max(out.hi, one.hi);
  }
  return out.lo > out.hi ? VisibilityRange{} : out;
}

// The parallelogram of lookup points p + K w(p) n through matrix m (w affine in a, b), with its
// margin taken at the corner that needs the widest.
// False where w <= 0 somewhere on q (behind the light's plane: no bound here).
bool offset_parallelogram(const mat4& m, const SnapParallelogram& q, const vec3& n, const VctSettings& s,
                          SnapParallelogram& out) {
  const float k = normal_offset_per_w(m, n, s);
  const Linear w = clip_row(m, q, 3);
  for (const Point& p : unit_square())
    if (!(w.at(p) > 0.0)) return false;
  out = q;
  out.centre = q.centre + (k * float(w.c)) * n;
  out.du = q.du + (k * float(w.a)) * n;
  out.dv = q.dv + (k * float(w.b)) * n;
  for (const vec3& p : points_of(q)) out.margin = std::max(out.margin, q.margin + lookup_point_margin(m, p, n, s));
  // The parallelogram's own float corners against the lookup's float point: one more rounding.
  out.margin += 2.0 * kU * double(glm::length(out.du) + glm::length(out.dv) + glm::length(out.centre));
  return true;
}

/// The cube faces some point of q may select (range_cube's regions, before the lookup).
std::vector<int> faces_over(const SnapParallelogram& q, const vec3& light) {
  const CubeDirections dirs = cube_directions(q, light);
  std::vector<int> out;
  for (int home = 0; home < 6; ++home)
    if (!face_region(dirs, home).empty()) out.push_back(home);
  return out;
}

}  // namespace

VisibilityRange snap_surface_visibility_range(const ShadowMap& map, const Light& light, const SnapParallelogram& q,
                                              const vec3& n, const VctSettings& settings) {
  if (settings.shadow_normal_offset == 0.0f) return snap_visibility_range(map, light, q, settings);
  if (light.is_point()) {
    if (!map.is_cube()) return {};
    VisibilityRange out{1.0f, 0.0f};
    SnapParallelogram lookup;
    for (int f : faces_over(q, light.position)) {
      if (!offset_parallelogram(map.cube_view_proj[size_t(f)], q, n, settings, lookup)) return {0.0f, 1.0f};
      const VisibilityRange one = range_cube(map, light.position, lookup, settings);
      out.lo = std::min(out.lo, one.lo), out.hi = std::max(out.hi, one.hi);
    }
    return out.lo > out.hi ? VisibilityRange{} : out;
  }
  if (map.depth.empty()) return {};
  SnapParallelogram lookup;
  if (!offset_parallelogram(map.view_proj, q, n, settings, lookup)) return {0.0f, 1.0f};
  return range_2d(map, lookup, settings);
}

VisibilityRange snap_visibility_range(const ShadowMap& map, const Light& light, const SnapParallelogram& q,
                                      const VctSettings& settings) {
  if (light.is_point()) return map.is_cube() ? range_cube(map, light.position, q, settings) : VisibilityRange{};
  return map.depth.empty() ? VisibilityRange{} : range_2d(map, q, settings);
}

}  // namespace vct
