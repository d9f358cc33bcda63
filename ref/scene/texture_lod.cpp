#include "scene/texture_lod.h"

#include <algorithm>
#include <cmath>

namespace vct {

TexelDerivatives texel_derivatives(const Texture& texture, const TextureRef& ref,
                                   const UvDerivatives& d) {
  const int set = ref.texcoord == 1 ? 1 : 0;
  glm::dvec2 dx(d.dx[set]), dy(d.dy[set]);
  const TextureTransform& t = ref.transform;
  if (!t.is_identity()) {
    // uv' = R S uv + offset (TextureTransform::apply): derivatives take the linear part only.
    auto linear = [&](const glm::dvec2& v) {
      const double c = std::cos(double(t.rotation)), s = std::sin(double(t.rotation));
      const glm::dvec2 sv(v.x * double(t.scale.x), v.y * double(t.scale.y));
      return glm::dvec2(c * sv.x + s * sv.y, -s * sv.x + c * sv.y);
    };
    dx = linear(dx);
    dy = linear(dy);
  }
  const glm::dvec2 size(double(texture.width), double(texture.height));
  return {dx * size, dy * size};
}

double exact_lod(const TexelDerivatives& d) {
  const double rho = std::max(glm::length(d.dx), glm::length(d.dy));
  return rho > 0.0 ? std::log2(rho) : -HUGE_VAL;
}

namespace {
double lower(const glm::dvec2& d) {
  return std::max(std::abs(d.x), std::abs(d.y));
}
double upper(const glm::dvec2& d) {
  return std::abs(d.x) + std::abs(d.y);
}
double log2_or_floor(double rho) {
  return rho > 0.0 ? std::log2(rho) : -1000.0;
}
}  // namespace

void RhoBounds::add_x(const glm::dvec2& d) {
  x_lo = std::min(x_lo, lower(d));
  x_hi = std::max(x_hi, upper(d));
}

void RhoBounds::add_y(const glm::dvec2& d) {
  y_lo = std::min(y_lo, lower(d));
  y_hi = std::max(y_hi, upper(d));
}

LodRange RhoBounds::range() const {
  return {log2_or_floor(std::max(x_lo, y_lo)) - kLodPrecision,
          log2_or_floor(std::max(x_hi, y_hi)) + kLodPrecision};
}

LevelBlend select_levels(const Texture& texture, double lambda, int q) {
  LevelBlend b;
  if (lambda <= 0.0 || !(lambda == lambda)) {  // magnification (NaN: no derivatives, level 0)
    b.linear = texture.mag_filter == Filter::Linear;
    return b;
  }
  switch (texture.min_filter) {
    case MinFilter::Nearest:
      b.linear = false;
      return b;
    case MinFilter::Linear:
      return b;
    case MinFilter::NearestMipmapNearest:
    case MinFilter::LinearMipmapNearest: {
      b.linear = texture.min_filter == MinFilter::LinearMipmapNearest;
      const int d = lambda <= 0.5 ? 0 : int(std::ceil(lambda + 0.5)) - 1;
      b.level1 = b.level2 = std::min(d, q);
      return b;
    }
    case MinFilter::NearestMipmapLinear:
    case MinFilter::LinearMipmapLinear:
    default: {
      b.linear = texture.min_filter == MinFilter::LinearMipmapLinear;
      if (lambda >= double(q)) {
        b.level1 = b.level2 = q;
        return b;
      }
      const double fl = std::floor(lambda);
      b.level1 = int(fl);
      b.level2 = std::min(b.level1 + 1, q);
      b.weight2 = float(lambda - fl);
      return b;
    }
  }
}

}  // namespace vct
