#include "freedoms/alpha_ties.h"

#include <algorithm>
#include <cmath>

#include "freedoms/lookup_precision.h"
#include "scene/alpha_mask.h"
#include "scene/texture_sample.h"
#include "shared/vct_shared.h"
#include "stages/raster.h"

namespace vct {

namespace {

// The (+-1, +-1) shift signs in order round the square, so their images are a convex quad's corners
// in order (a projective or affine map keeps a convex polygon's order).
constexpr int kSquareCorners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};

// A footprint larger than this many texels takes the whole texture's range (an edge-on surface:
// the square's image crosses most of the texture anyway); the range only widens.
constexpr int64_t kMaxFootprintTexels = int64_t(1) << 14;

float cutoff_of(const Scene& scene, uint32_t triangle) {
  const Material& m = scene.materials[scene.triangle_material[triangle]];
  return sh::effective_alpha_cutoff(int(m.alpha_mode), m.alpha_cutoff);
}

// Level 0's alpha at texel (i, j), wrapped as the lookup wraps it (alpha is linear in SRGB8_ALPHA8).
float texel_alpha(const Texture& tex, int i, int j) {
  const vec2 uv((float(i) + 0.5f) / float(tex.width), (float(j) + 0.5f) / float(tex.height));
  return sample_level(tex, tex.rgba8.data(), tex.width, tex.height, uv, false, false).a;
}

// Separating axes of the closed box [lo, hi] and the convex quad q (the box's two axes, the quad's
// four edge normals): true when they meet.
bool box_meets_quad(const glm::dvec2& lo, const glm::dvec2& hi, const glm::dvec2 q[4]) {
  for (int axis = 0; axis < 2; ++axis) {
    const double a = std::min({q[0][axis], q[1][axis], q[2][axis], q[3][axis]});
    const double b = std::max({q[0][axis], q[1][axis], q[2][axis], q[3][axis]});
    if (b < lo[axis] || a > hi[axis]) return false;
  }
  for (int e = 0; e < 4; ++e) {
    const glm::dvec2 d = q[(e + 1) % 4] - q[e], n(-d.y, d.x);
    double qa = 1e300, qb = -1e300, ba = 1e300, bb = -1e300;
    for (int k = 0; k < 4; ++k) {
      const double p = glm::dot(n, q[k]);
      qa = std::min(qa, p), qb = std::max(qb, p);
      const glm::dvec2 c((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y);
      const double r = glm::dot(n, c);
      ba = std::min(ba, r), bb = std::max(bb, r);
    }
    if (qb < ba || qa > bb) return false;
  }
  return true;
}

// The alpha range of every texel of level 0.
AlphaRange whole_texture(const Texture& tex) {
  AlphaRange r{1.0f, 0.0f};
  for (size_t i = 3; i < tex.rgba8.size(); i += 4) {
    const float a = float(tex.rgba8[i]) / 255.0f;
    r.lo = std::min(r.lo, a), r.hi = std::max(r.hi, a);
  }
  return r;
}

// The range of every texel of level 0 whose cell [i, i + 1]^2, grown by the sub-texel precision,
// the quad q (texel coordinates) meets: a NEAREST lookup (GL 4.5 §8.14.2) returns one of them
// anywhere in q.
AlphaRange nearest_alpha_over(const Texture& tex, const glm::dvec2 q[4], const glm::dvec2& qmin, const glm::dvec2& qmax) {
  const double g = double(kSubtexelShift);
  const double i0 = std::floor(qmin.x - g), i1 = std::floor(qmax.x + g);
  const double j0 = std::floor(qmin.y - g), j1 = std::floor(qmax.y + g);
  if ((i1 - i0 + 1.0) * (j1 - j0 + 1.0) > double(kMaxFootprintTexels)) return whole_texture(tex);
  AlphaRange r{1.0f, 0.0f};
  for (int j = int(j0); j <= int(j1); ++j)
    for (int i = int(i0); i <= int(i1); ++i) {
      if (!box_meets_quad({i - g, j - g}, {i + 1 + g, j + 1 + g}, q)) continue;
      const float a = texel_alpha(tex, i, j);
      r.lo = std::min(r.lo, a), r.hi = std::max(r.hi, a);
    }
  return r.lo <= r.hi ? r : whole_texture(tex);  // nothing met: only rounding can do that
}

// The range of a LINEAR lookup (GL 4.5 §8.14.2: texels floor(u - 1/2) and the next, per axis) over
// the quad's bounding box: in each cell between four texel centres the lookup is bilinear, linear
// in each coordinate apart, so over the box's piece in that cell its extremes are at the piece's
// corners. The filter weights' own precision is kAlphaWeightSlack, added by the caller.
AlphaRange linear_alpha_over(const Texture& tex, const glm::dvec2& qmin, const glm::dvec2& qmax) {
  const glm::dvec2 lo = qmin - 0.5, hi = qmax - 0.5;  // texel i's centre at i
  const double i0 = std::floor(lo.x), i1 = std::floor(hi.x), j0 = std::floor(lo.y), j1 = std::floor(hi.y);
  if ((i1 - i0 + 1.0) * (j1 - j0 + 1.0) > double(kMaxFootprintTexels)) return whole_texture(tex);
  AlphaRange r{1.0f, 0.0f};
  for (int j = int(j0); j <= int(j1); ++j)
    for (int i = int(i0); i <= int(i1); ++i) {
      const float a00 = texel_alpha(tex, i, j), a10 = texel_alpha(tex, i + 1, j);
      const float a01 = texel_alpha(tex, i, j + 1), a11 = texel_alpha(tex, i + 1, j + 1);
      const double u0 = std::max(lo.x, double(i)) - i, u1 = std::min(hi.x, double(i) + 1.0) - i;
      const double v0 = std::max(lo.y, double(j)) - j, v1 = std::min(hi.y, double(j) + 1.0) - j;
      for (int k = 0; k < 4; ++k) {
        const float u = float((k & 1) ? u1 : u0), v = float((k & 2) ? v1 : v0);
        const float a = (1.0f - v) * ((1.0f - u) * a00 + u * a10) + v * ((1.0f - u) * a01 + u * a11);
        r.lo = std::min(r.lo, a), r.hi = std::max(r.hi, a);
      }
    }
  return r;
}

// The texture alpha's range over the quad q of texel coordinates of level 0 (alpha is tested at
// level 0, and lambda 0 is magnification, GL 4.5 §8.14: the mag filter).
AlphaRange texture_alpha_over(const Texture& tex, const glm::dvec2 q[4]) {
  glm::dvec2 qmin = q[0], qmax = q[0];
  for (int k = 1; k < 4; ++k) qmin = glm::min(qmin, q[k]), qmax = glm::max(qmax, q[k]);
  if (!std::isfinite(qmin.x) || !std::isfinite(qmin.y) || !std::isfinite(qmax.x) || !std::isfinite(qmax.y))
    return whole_texture(tex);
  return tex.mag_filter == Filter::Linear ? linear_alpha_over(tex, qmin, qmax) : nearest_alpha_over(tex, q, qmin, qmax);
}

// The four corners' barycentrics (b1, b2) of the parallelogram centre + r (+-du +-dv), in order.
void parallelogram(const glm::dvec2& centre, double r, const glm::dvec2& du, const glm::dvec2& dv, glm::dvec2 out[4]) {
  for (int k = 0; k < 4; ++k)
    out[k] = centre + r * (double(kSquareCorners[k][0]) * du + double(kSquareCorners[k][1]) * dv);
}

bool range_holds_cutoff(const Scene& scene, uint32_t triangle, const AlphaRange& r) {
  const float c = cutoff_of(scene, triangle);
  return r.lo <= c && c <= r.hi;
}

}  // namespace

AlphaRange alpha_range_over(const Scene& scene, uint32_t triangle, const glm::dvec2 corners[4]) {
  const Material& m = scene.materials[scene.triangle_material[triangle]];
  AlphaRange tex{1.0f, 1.0f}, colour{1.0f, 1.0f};
  const uvec3 t = scene.triangles[triangle];
  const TextureRef& ref = m.base_color_texture;
  const std::vector<vec2>& uvs = ref.texcoord == 1 ? scene.uv1 : scene.uv0;
  if (ref.present() && scene.textures[size_t(ref.texture)].width > 0) {
    const Texture& texture = scene.textures[size_t(ref.texture)];
    glm::dvec2 q[4];
    for (int k = 0; k < 4; ++k) {  // as base_color_alpha: uv from the barycentrics, then the transform
      const float b1 = float(corners[k].x), b2 = float(corners[k].y), b0 = 1.0f - b1 - b2;
      vec2 uv(0.0f);
      if (!uvs.empty()) uv = b0 * uvs[t.x] + b1 * uvs[t.y] + b2 * uvs[t.z];
      if (!ref.transform.is_identity()) uv = ref.transform.apply(uv);
      q[k] = glm::dvec2(double(uv.x) * texture.width, double(uv.y) * texture.height);
    }
    tex = texture_alpha_over(texture, q);
  }
  if (!scene.colors.empty()) {
    colour = {1e30f, -1e30f};
    for (int k = 0; k < 4; ++k) {
      const float b1 = float(corners[k].x), b2 = float(corners[k].y), b0 = 1.0f - b1 - b2;
      const float a = (b0 * scene.colors[t.x] + b1 * scene.colors[t.y] + b2 * scene.colors[t.z]).a;
      colour.lo = std::min(colour.lo, a), colour.hi = std::max(colour.hi, a);
    }
  }
  // factor x texture x colour over the box of the three: a product's extremes are at the box's corners.
  AlphaRange r{1e30f, -1e30f};
  for (int k = 0; k < 4; ++k) {
    const float p = m.base_color_factor.a * ((k & 1) ? tex.hi : tex.lo) * ((k & 2) ? colour.hi : colour.lo);
    r.lo = std::min(r.lo, p), r.hi = std::max(r.hi, p);
  }
  return {r.lo - kAlphaWeightSlack, r.hi + kAlphaWeightSlack};
}

AlphaRange alpha_range(const Scene& scene, const WindowBarycentrics& wb, int x, int row, uint32_t triangle,
                       const vec3& bary) {
  const glm::dvec2 centre(bary.y, bary.z);
  glm::dvec2 corners[4] = {centre, centre, centre, centre};
  const double cx = double(x) + 0.5, cy = double(wb.height()) - double(row) - 0.5;
  glm::dvec2 bc;
  if (wb.at(scene, triangle, cx, cy, bc)) {
    constexpr double s = kVertexSnapStep;
    for (int k = 0; k < 4; ++k) {  // a shift whose ray misses the plane stays at the centre
      glm::dvec2 bs;
      if (wb.at(scene, triangle, cx + s * kSquareCorners[k][0], cy + s * kSquareCorners[k][1], bs))
        corners[k] = centre + (bs - bc);
    }
  }
  AlphaRange r = alpha_range_over(scene, triangle, corners);
  const float own = base_color_alpha(scene, triangle, bary.y, bary.z);
  r.lo = std::min(r.lo, own - kAlphaWeightSlack), r.hi = std::max(r.hi, own + kAlphaWeightSlack);
  return r;
}

float alpha_freedom(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                    uint32_t triangle, const vec3& bary) {
  const float own = base_color_alpha(scene, triangle, bary.y, bary.z);
  const AlphaRange r = alpha_range(scene, wb, x, row, triangle, bary);
  return std::max(r.hi - own, own - r.lo);
}

bool alpha_test_may_flip(const Scene& scene, const WindowBarycentrics& wb, int x, int row,
                         uint32_t triangle, const vec3& bary) {
  if (!triangle_alpha_tested(scene, triangle)) return false;
  return range_holds_cutoff(scene, triangle, alpha_range(scene, wb, x, row, triangle, bary));
}

bool alpha_test_may_flip_affine(const Scene& scene, uint32_t triangle, const vec3& bary, double reach,
                                const glm::dvec2& db_dx, const glm::dvec2& db_dy) {
  if (!triangle_alpha_tested(scene, triangle)) return false;
  glm::dvec2 corners[4];
  parallelogram(glm::dvec2(bary.y, bary.z), reach, db_dx, db_dy, corners);
  AlphaRange r = alpha_range_over(scene, triangle, corners);
  const float own = base_color_alpha(scene, triangle, bary.y, bary.z);
  r.lo = std::min(r.lo, own - kAlphaWeightSlack), r.hi = std::max(r.hi, own + kAlphaWeightSlack);
  return range_holds_cutoff(scene, triangle, r);
}

}  // namespace vct
