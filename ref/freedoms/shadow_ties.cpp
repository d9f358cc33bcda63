#include "freedoms/shadow_ties.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/pcf_taps.h"
#include "core/precision.h"
#include "freedoms/direct_slack.h"
#include "stages/cube_map.h"
#include "stages/shadow_map.h"

namespace vct {

namespace {

constexpr double kU = 1.0 / 16777216.0;  // 2^-24, one float rounding
constexpr double kG4 = 4.0 * kU / (1.0 - 4.0 * kU);

// A texel's compare for a point whose window depth is z +- ez: 2 lit for every admissible z,
// 0 shadowed for every one, 1 either (stored + bias rounds the same way on both sides).
int compare_state(float z, double ez, float stored, float bias) {
  const double sb = double(stored + bias);
  if (double(z) + ez <= sb) return 2;
  if (double(z) - ez > sb) return 0;
  return 1;
}

// The admissible lit fraction [lo, hi] of one tap at texel position t (y up) whose coordinate may
// be off by e texels: nearest reads the texel t floors to (either neighbour within e of an edge),
// linear weights the four around t - 1/2 (GL 4.5 section 8.23.1) with either floor.
template <typename State>
VisibilityRange tap_range(const vec2& t, double e, ShadowCompare compare, const State& state) {
  VisibilityRange r{1.0f, 0.0f};
  if (compare == ShadowCompare::Nearest) {
    bool all_lit = true, any_lit = false;
    for (int x = int(std::floor(double(t.x) - e)); x <= int(std::floor(double(t.x) + e)); ++x)
      for (int y = int(std::floor(double(t.y) - e)); y <= int(std::floor(double(t.y) + e)); ++y) {
        const int s = state(x, y);
        all_lit = all_lit && s == 2;
        any_lit = any_lit || s >= 1;
      }
    return {all_lit ? 1.0f : 0.0f, any_lit ? 1.0f : 0.0f};
  }
  const vec2 s = t - 0.5f;
  for (int x0 = int(std::floor(double(s.x) - e)); x0 <= int(std::floor(double(s.x) + e)); ++x0)
    for (int y0 = int(std::floor(double(s.y) - e)); y0 <= int(std::floor(double(s.y) + e)); ++y0) {
      const float ax = std::clamp(s.x - float(x0), 0.0f, 1.0f), ay = std::clamp(s.y - float(y0), 0.0f, 1.0f);
      const float w[4] = {(1 - ax) * (1 - ay), ax * (1 - ay), (1 - ax) * ay, ax * ay};
      const int st[4] = {state(x0, y0), state(x0 + 1, y0), state(x0, y0 + 1), state(x0 + 1, y0 + 1)};
      float lo = 0.0f, hi = 0.0f;
      for (int i = 0; i < 4; ++i) {
        lo += st[i] == 2 ? w[i] : 0.0f;
        hi += st[i] >= 1 ? w[i] : 0.0f;
      }
      r.lo = std::min(r.lo, lo);
      r.hi = std::max(r.hi, hi);
    }
  return r;
}

// What a lookup that filters depths first (filters_depth_first) compares each tap's blend with:
// the point's window depth z, admissible within ez, and the bias.
struct DepthCompare {
  float z = 0.0f;
  double ez = 0.0;
  float bias = 0.0f;
};

// The admissible lit value {lo, hi} (each 0 or 1) of a filter-then-compare tap at texel position
// t (y up) whose coordinate may be off by e texels: the blend D of the four depths around
// t - 1/2 is bilinear in the fractions (ax, ay), so over the box of fractions a correct GL may use
// -- the exact ones +- e, +- the filter weights' 8 sub-texel bits (precision table row
// filter-weights, GL 4.5 section 8.14.2), clamped to [0, 1] -- it takes its extremes at the box's
// corners; every floor within e is tried (the blend is continuous across texel edges). The blend's
// own float arithmetic (4 products, 3 sums: g4 of the largest |depth|) and the add of the bias
// (one rounding) widen [D_lo, D_hi]; the tap is lit for every admissible lookup when
// z + ez <= D_lo + bias and for some when z - ez <= D_hi + bias (docs/compare.md, "Engine PCF").
template <typename Stored>
VisibilityRange filtered_tap_range(const vec2& t, double e, const DepthCompare& c, const Stored& stored) {
  const double step = precision(Precision::FilterWeights);
  const double sx = double(t.x) - 0.5, sy = double(t.y) - 0.5;
  double d_lo = 1e300, d_hi = -1e300, largest = 0.0;
  for (int x0 = int(std::floor(sx - e)); x0 <= int(std::floor(sx + e)); ++x0)
    for (int y0 = int(std::floor(sy - e)); y0 <= int(std::floor(sy + e)); ++y0) {
      const double d[4] = {stored(x0, y0), stored(x0 + 1, y0), stored(x0, y0 + 1), stored(x0 + 1, y0 + 1)};
      for (const double v : d) largest = std::max(largest, std::abs(v));
      const double ax = sx - double(x0), ay = sy - double(y0);
      for (const double fx : {std::clamp(ax - e - step, 0.0, 1.0), std::clamp(ax + e + step, 0.0, 1.0)})
        for (const double fy : {std::clamp(ay - e - step, 0.0, 1.0), std::clamp(ay + e + step, 0.0, 1.0)}) {
          const double blend =
              (1 - fx) * (1 - fy) * d[0] + fx * (1 - fy) * d[1] + (1 - fx) * fy * d[2] + fx * fy * d[3];
          d_lo = std::min(d_lo, blend), d_hi = std::max(d_hi, blend);
        }
    }
  const double ef = kG4 * largest + kU * (largest + std::abs(double(c.bias)));
  const bool lit_always = double(c.z) + c.ez <= d_lo + double(c.bias) - ef;
  const bool lit_sometimes = double(c.z) - c.ez <= d_hi + double(c.bias) + ef;
  return {lit_always ? 1.0f : 0.0f, lit_sometimes ? 1.0f : 0.0f};
}

// How the taps of one lookup sit on its map: the map's size (UV offsets), the point's light-clip
// w and how far a correct GL's w may be from it (offsets declared per 1/w), and -- for a lookup
// that filters first -- the compare and the stored depths.
struct TapFrame {
  int size = 0;
  float clip_w = 1.0f;
  double e_w = 0.0;
  DepthCompare compare;
};

// How far (texels) a correct GL's tap offset may be from tap_positions' beyond the coordinate's
// own margin: a UV offset's multiply by the size and a 1/w scaling's divide round once each (the
// divide within 2.5 ulp, GLSL 4.50 section 4.7.1: 4 u in all), and w itself is known within e_w:
// |o / w - o / w'| <= |o| e_w / (|w| (|w| - e_w)). Negative: no bound (w may reach 0).
double offset_error(const VctSettings& s, const std::vector<vec2>& offsets, const TapFrame& f) {
  const bool uv = s.pcf_tap_unit == PcfTapUnit::Uv, inv_w = s.pcf_tap_scale == PcfTapScale::InvW;
  if (s.pcf_taps.empty() || (!uv && !inv_w)) return 0.0;
  double largest = 0.0;  // the largest offset in texels at the point's w
  for (const vec2& o : offsets) largest = std::max({largest, double(std::abs(o.x)), double(std::abs(o.y))});
  if (!inv_w) return 4.0 * kU * largest;
  const double w = std::abs(double(f.clip_w));
  if (!(f.e_w < 0.5 * w)) return -1.0;
  return 4.0 * kU * largest + largest * w * f.e_w / (w * (w - f.e_w));
}

// The mean of the taps' ranges, widened by the linear filter weights' 8-bit freedom (compare then
// filter; a filtered tap carries it in its depth, filtered_tap_range). `stored(tx, ty)`: the
// texel's depth, read only by a lookup that filters first.
template <typename State, typename Stored>
VisibilityRange pcf_range(float u, float v, double e, const VctSettings& s, const TapFrame& frame, const State& state,
                          const Stored& stored) {
  const std::vector<vec2> taps = tap_positions(u, v, s, frame.size, frame.clip_w);  // as the lookup places them
  const std::vector<vec2> offsets = tap_positions(0.0f, 0.0f, s, frame.size, frame.clip_w);
  double largest_offset = 16.0;  // parse_pcf_taps' limit, the largest a texel offset may be
  for (const vec2& o : offsets) largest_offset = std::max({largest_offset, double(std::abs(o.x)), double(std::abs(o.y))});
  const double e_offset = offset_error(s, offsets, frame);
  if (e_offset < 0.0) return {0.0f, 1.0f};
  // The tap offsets add to the coordinate on each side: two more roundings of magnitude <= |u| + the offset.
  const double e_tap = e + 4.0 * kU * (double(std::max(std::abs(u), std::abs(v))) + largest_offset) + e_offset;
  const bool filter_first = filters_depth_first(s);
  double lo = 0.0, hi = 0.0;
  for (const vec2& t : taps) {
    const VisibilityRange r = filter_first ? filtered_tap_range(t, e_tap, frame.compare, stored)
                                           : tap_range(t, e_tap, s.shadow_compare, state);
    lo += double(r.lo);
    hi += double(r.hi);
  }
  const double n = double(std::max<size_t>(taps.size(), 1));
  const double w =
      s.shadow_compare == ShadowCompare::Linear && !filter_first ? double(kLinearCompareWeightStep) : 0.0;
  return {float(std::max(0.0, lo / n - w)), float(std::min(1.0, hi / n + w))};
}

// How far a correct GL's light-clip w of p through m may lie from the reference's: a 4-term dot
// product within g4 of its terms' magnitudes, and p itself known within e_world per axis.
double clip_w_error(const mat4& m, const vec3& p, double e_world) {
  double s_w = std::abs(double(m[3][3])), a_w = 0.0;
  for (int j = 0; j < 3; ++j) s_w += std::abs(double(m[j][3]) * double(p[j])), a_w += std::abs(double(m[j][3]));
  return kG4 * s_w + a_w * e_world;
}

VisibilityRange range_2d(const ShadowMap& map, const vec3& p, const VctSettings& s, double e_world) {
  const vec4 c = map.view_proj * vec4(p, 1.0f);
  if (c.w <= 0.0f) return {};
  const vec3 ndc = vec3(c) / c.w;
  double e[3];
  bool near_border = false;
  for (int i = 0; i < 3; ++i) {
    e[i] = ndc_error(map.view_proj, p, i, e_world);
    near_border = near_border || std::abs(std::abs(double(ndc[i])) - 1.0) <= e[i];
  }
  const bool inside = std::abs(ndc.x) <= 1.0f && std::abs(ndc.y) <= 1.0f && std::abs(ndc.z) <= 1.0f;
  if (!inside && !near_border) return {};
  const Image& depth = map.depth;
  const int w = depth.width, h = depth.height;
  const float z = ndc.z * 0.5f + 0.5f;
  const double ez = depth_margin(e[2]);
  const auto stored = [&](int tx, int ty) { return double(stored_depth(depth, tx, ty, s.shadow_border)); };
  const auto state = [&](int tx, int ty) {
    return compare_state(z, ez, stored_depth(depth, tx, ty, s.shadow_border), s.shadow_bias);
  };
  const float u = (ndc.x * 0.5f + 0.5f) * float(w), v = (ndc.y * 0.5f + 0.5f) * float(h);
  const TapFrame frame{w, c.w, clip_w_error(map.view_proj, p, e_world), {z, ez, s.shadow_bias}};
  VisibilityRange r = pcf_range(u, v, std::max(texel_margin(e[0], w), texel_margin(e[1], h)), s, frame, state, stored);
  if (near_border) r.hi = 1.0f;  // either side of the frustum's border: outside is lit
  return r;
}

// A point light's cube: every face its direction may select (a near tie of the largest
// coordinates), each with the taps and the past-the-edge reprojection of cube_shadow_visibility.
VisibilityRange range_cube(const ShadowMap& map, const vec3& light_position, const vec3& p, const VctSettings& s,
                           double e_world) {
  const vec3 r = p - light_position;
  if (r == vec3(0.0f)) return {};
  const int size = map.cube[0].width;
  // The subtraction rounds once on each side; p itself is known within e_world.
  const double er = 2.0 * kU * double(std::max({std::abs(r.x), std::abs(r.y), std::abs(r.z)})) + e_world;
  const double largest = std::max({std::abs(r.x), std::abs(r.y), std::abs(r.z)});
  VisibilityRange out{1.0f, 0.0f};
  for (int home = 0; home < 6; ++home) {
    const vec3& axis = cube_face_axes(home).major_axis;
    const double ma = double(glm::dot(r, axis));
    if (home != cube_face(r) && !(ma > 0.0 && ma >= largest - 2.0 * er)) continue;
    // s = (sc / |ma| + 1) / 2: sc and ma each off by er, the division 3 u relative.
    const double e_q = 2.0 * er / std::max(std::abs(ma), 1e-30) + 3.0 * kU;
    const vec2 st = cube_face_st(home, r);
    const auto state = [&](int tx, int ty) {
      const CubeTexel texel = cube_texel(home, tx, ty, size);
      const int face = texel.face;
      tx = texel.x, ty = texel.y;
      const mat4& m = map.cube_view_proj[size_t(face)];
      const vec4 c = m * vec4(p, 1.0f);
      const float z = c.z / c.w * 0.5f + 0.5f;
      const double ez = c.w > 0.0f ? depth_margin(ndc_error(m, p, 2, e_world)) : 0.0;
      const double zd = z;
      if (!(c.w > 0.0f) || z < 0.0f || z > 1.0f) return zd + ez < 0.0 || zd - ez > 1.0 || !(c.w > 0.0f) ? 2 : 1;
      const int st_ = compare_state(z, ez, map.cube[size_t(face)].at(tx, size - 1 - ty, 0), s.shadow_bias);
      // Within the depth margin of the range's ends the point may count as outside (lit).
      return (zd - ez < 0.0 || zd + ez > 1.0) ? std::max(st_, 1) : st_;
    };
    // The home face's clip w scales taps declared per 1/w (cube_shadow_visibility); a cube never
    // filters first (render_shadow_maps refuses it), so no depths are read.
    const mat4& home_m = map.cube_view_proj[size_t(home)];
    const TapFrame frame{size, (home_m * vec4(p, 1.0f)).w, clip_w_error(home_m, p, e_world), {}};
    const auto no_depth = [](int, int) { return 0.0; };
    const VisibilityRange one =
        pcf_range(st.x * float(size), st.y * float(size), texel_margin(e_q, size), s, frame, state, no_depth);
    out.lo = std::min(out.lo, one.lo);
    out.hi = std::max(out.hi, one.hi);
  }
  return out;
}

// The faces a correct GL may select for direction r (the largest coordinate within the
// subtraction's rounding of the largest), as range_cube's home loop.
std::vector<int> faces_may_select(const vec3& r) {
  const double largest = std::max({std::abs(r.x), std::abs(r.y), std::abs(r.z)});
  const double er = 2.0 * kU * largest;
  std::vector<int> out;
  for (int f = 0; f < 6; ++f) {
    const double ma = double(glm::dot(r, cube_face_axes(f).major_axis));
    if (f == cube_face(r) || (ma > 0.0 && ma >= largest - 2.0 * er)) out.push_back(f);
  }
  return out;
}

VisibilityRange unite(VisibilityRange a, const VisibilityRange& b) { return {std::min(a.lo, b.lo), std::max(a.hi, b.hi)}; }

// The reference's lookup point through matrix m (shadow_lookup_point's arithmetic).
vec3 offset_point(const mat4& m, const vec3& p, const vec3& n, const VctSettings& s) {
  const float w = (m * vec4(p, 1.0f)).w;
  if (!(w > 0.0f) || s.shadow_normal_offset == 0.0f) return p;
  return p + (normal_offset_per_w(m, n, s) * w) * n;
}

}  // namespace

double lookup_point_margin(const mat4& m, const vec3& p, const vec3& n, const VctSettings& s) {
  if (s.shadow_normal_offset == 0.0f) return 0.0;
  constexpr double g3 = 3.0 * kU / (1.0 - 3.0 * kU);
  const vec2 reach = pcf_reach(s);
  double k_lo = 0.0, k_hi = 0.0;
  for (int row = 0; row < 2; ++row) {
    double dot = 0.0, mag = 0.0, rr = 0.0;
    for (int j = 0; j < 3; ++j) {
      const double r = double(m[j][row]);
      dot += double(n[j]) * r, mag += std::abs(double(n[j]) * r), rr += r * r;
    }
    k_hi += double(reach[row]) * (std::abs(dot) + g3 * mag) / (rr * (1.0 - g3));
    k_lo += double(reach[row]) * std::max(0.0, std::abs(dot) - g3 * mag) / (rr * (1.0 + g3));
  }
  const double scale = double(s.shadow_normal_offset) * 2.0 / double(s.shadow_map_size);
  k_hi *= scale * (1.0 + 12.0 * kU), k_lo *= scale * (1.0 - 12.0 * kU);
  double w = double(m[3][3]), s_w = std::abs(w);
  for (int j = 0; j < 3; ++j) w += double(m[j][3]) * double(p[j]), s_w += std::abs(double(m[j][3]) * double(p[j]));
  const double w_hi = w + kG4 * s_w, w_lo = w - kG4 * s_w;
  if (!(w_hi > 0.0)) return 0.0;  // no offset on either side
  const double d_hi = k_hi * w_hi * (1.0 + kU), d_lo = w_lo > 0.0 ? k_lo * w_lo * (1.0 - kU) : 0.0;
  const double largest = double(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)})) + d_hi;
  return (d_hi - d_lo) + 2.0 * kU * (d_hi + largest);
}

VisibilityRange surface_visibility_range(const ShadowMap& map, const Light& light, const vec3& p, const vec3& n,
                                         const VctSettings& s) {
  if (light.is_point()) {
    if (!map.is_cube() || p == light.position) return {};
    VisibilityRange out{1.0f, 0.0f};
    for (int f : faces_may_select(p - light.position)) {
      const mat4& m = map.cube_view_proj[size_t(f)];
      out = unite(out, range_cube(map, light.position, offset_point(m, p, n, s), s, lookup_point_margin(m, p, n, s)));
    }
    return out;
  }
  if (map.depth.empty()) return {};
  return range_2d(map, offset_point(map.view_proj, p, n, s), s, lookup_point_margin(map.view_proj, p, n, s));
}

double texel_margin(double e_ndc, int size) { return 0.5 * double(size) * e_ndc + 4.0 * kU * double(size); }

double depth_margin(double e_ndc) { return 0.5 * e_ndc + 2.0 * kU; }

double ndc_error(const mat4& m, const vec3& p, int row, double e_world) {
  const vec4 q(p, 1.0f);
  double s_row = 0.0, s_w = 0.0, c_row = 0.0, c_w = 0.0;
  for (int j = 0; j < 4; ++j) {
    s_row += std::abs(double(m[j][row]) * double(q[j]));
    s_w += std::abs(double(m[j][3]) * double(q[j]));
    c_row += double(m[j][row]) * double(q[j]);
    c_w += double(m[j][3]) * double(q[j]);
  }
  if (c_w == 0.0) return 1e30;
  const double ndc = std::abs(c_row / c_w);
  double a_row = 0.0, a_w = 0.0;  // how fast clip row and w move per world unit
  for (int j = 0; j < 3; ++j) a_row += std::abs(double(m[j][row])), a_w += std::abs(double(m[j][3]));
  // The division: GLSL's 2.5 ulp on one side, C++'s 0.5 on the other (the precision table's
  // division-rcp-rsqrt row), and one ulp of a float x is up to 2u|x| (x at the bottom of its binade).
  const double division = 2.0 * (precision(Precision::DivisionRcpRsqrt) + 0.5) * kU * ndc;
  return 2.0 * kG4 * (s_row + ndc * s_w) / std::abs(c_w) + division + (a_row + ndc * a_w) * e_world / std::abs(c_w);
}

VisibilityRange light_visibility_range(const ShadowMap& map, const Light& light, const vec3& p,
                                       const VctSettings& settings) {
  if (light.is_point()) return map.is_cube() ? range_cube(map, light.position, p, settings, 0.0) : VisibilityRange{};
  return map.depth.empty() ? VisibilityRange{} : range_2d(map, p, settings, 0.0);
}

}  // namespace vct
