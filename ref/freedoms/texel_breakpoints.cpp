#include "freedoms/texel_breakpoints.h"

#include <algorithm>
#include <cmath>

#include "scene/texture_lod.h"
#include "scene/texture_mips.h"

namespace vct {

namespace {

using Polygon = std::vector<glm::dvec2>;

// The part of `poly` (convex, window offsets) where a . d + b >= 0 (Sutherland-Hodgman, one plane).
Polygon clip(const Polygon& poly, const glm::dvec2& a, double b) {
  Polygon out;
  for (size_t k = 0; k < poly.size(); ++k) {
    const glm::dvec2 &p = poly[k], &q = poly[(k + 1) % poly.size()];
    const double fp = glm::dot(a, p) + b, fq = glm::dot(a, q) + b;
    if (fp >= 0.0) out.push_back(p);
    if ((fp >= 0.0) != (fq >= 0.0)) out.push_back(p + (fp / (fp - fq)) * (q - p));
  }
  return out;
}

// Integers k with lo <= k <= hi.
double integer_count(double lo, double hi) { return std::max(0.0, std::floor(hi) - std::ceil(lo) + 1.0); }

// The texel (i, j)'s piece of the square: the square cut by i <= x < i + 1 and j <= y < j + 1,
// each texel coordinate affine in the window offset (texels = at_centre + d.x per_u + d.y per_v).
Polygon texel_piece(const TexelMap& m, const Polygon& square, double i, double j) {
  const glm::dvec2 gx(m.per_u.x, m.per_v.x), gy(m.per_u.y, m.per_v.y);  // gradients of x and y
  Polygon p = clip(square, gx, m.at_centre.x - i);
  p = clip(p, -gx, i + 1.0 - m.at_centre.x);
  p = clip(p, gy, m.at_centre.y - j);
  return clip(p, -gy, j + 1.0 - m.at_centre.y);
}

// A sixty-fourth of the way from each corner to the piece's centre: inside the piece (it is
// convex), near enough to the corner that a smooth light barely moves.
constexpr double kPull = 1.0 / 64.0;

}  // namespace

bool texel_breakpoints(const TexelMap& map, double r, size_t cap, std::vector<glm::dvec2>& out) {
  const Polygon square = {{-r, -r}, {r, -r}, {r, r}, {-r, r}};
  glm::dvec2 lo(INFINITY), hi(-INFINITY);
  for (const glm::dvec2& c : square) {
    const glm::dvec2 t = map.at_centre + c.x * map.per_u + c.y * map.per_v;
    lo = glm::min(lo, t);
    hi = glm::max(hi, t);
  }
  if (!std::isfinite(lo.x + lo.y + hi.x + hi.y)) return false;
  // At most 8 corners per piece (a square cut by four lines), one piece per texel of the box.
  const double texels = integer_count(std::floor(lo.x), hi.x) * integer_count(std::floor(lo.y), hi.y);
  if (8.0 * texels > double(cap)) return false;
  for (double i = std::floor(lo.x); i <= hi.x; i += 1.0)
    for (double j = std::floor(lo.y); j <= hi.y; j += 1.0) {
      const Polygon piece = texel_piece(map, square, i, j);
      if (piece.size() < 3) continue;
      glm::dvec2 centre(0.0);
      for (const glm::dvec2& p : piece) centre += p;
      centre /= double(piece.size());
      for (const glm::dvec2& p : piece) out.push_back(p + kPull * (centre - p));
    }
  return true;
}

void append_nearest_level_maps(const Texture& texture, bool srgb, double lambda, const glm::dvec2& uv,
                               const glm::dvec2& per_u, const glm::dvec2& per_v, std::vector<TexelMap>& out) {
  const LevelBlend b = select_levels(texture, lambda, available_levels(texture, srgb) - 1);
  if (b.linear) return;
  const int levels[2] = {b.level1, b.level2};
  const int read = b.weight2 != 0.0f && b.level2 != b.level1 ? 2 : 1;
  for (int k = 0; k < read; ++k) {
    int width = 0, height = 0;
    mip_level_texels(texture, srgb, levels[k], width, height);
    const glm::dvec2 size(width, height);
    out.push_back({uv * size, per_u * size, per_v * size});
  }
}

}  // namespace vct
