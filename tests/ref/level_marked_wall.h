// A wall whose texture's mip levels are constant (the LOD precision's tests: the compare test
// tests/compare/lod_precision_test.cpp and GL's own lambda, tests/gl/gl_lod_precision_test.cpp).
#pragma once

#include <cmath>
#include <vector>

#include "stage_test_scene.h"

namespace vct::test {

/// The wall's size in pixels (a square view) and its texture scale S.
constexpr int kLevelWallPixels = 16;
constexpr float kLevelWallScale = 0.5497f;
/// Roughness of even and odd mip levels (8-bit G of the linear metallic-roughness texture).
constexpr int kLevelWallEven = 25, kLevelWallOdd = 230;

/// A 4 m wall at z = -2 facing the camera (yfov 1 rad, a 16^2 view), u = S (x + 2) / 4, with a
/// 256^2 linear metallic-roughness texture whose mip levels are constant: even levels roughness
/// 25/255, odd ones 230/255. UV is affine in the window with aligned axes, so every pixel's
/// admissible lambda is the exact one +- the LOD precision, and roughness is linear in lambda
/// within a level: a lambda error reads back directly. rho = 256 S tan(0.5) / 16 texels per
/// pixel; S = 0.5497 puts lambda at 2.264, where log2's mantissa is near 1/ln 2 (a linear-mantissa
/// log2's worst).
inline Scene level_marked_wall() {
  Scene s;
  const uint32_t m = add_material(s, vec3(0.5f));
  add_quad(s, {-2, -2, -2}, {2, -2, -2}, {2, 2, -2}, {-2, 2, -2}, {0, 0, 1}, m);
  for (size_t i = 0; i < s.positions.size(); ++i)
    s.uv0[i] = kLevelWallScale * vec2(s.positions[i].x + 2.0f, s.positions[i].y + 2.0f) / 4.0f;
  const auto level = [](int size, int k) {
    const uint8_t g = uint8_t(k % 2 ? kLevelWallOdd : kLevelWallEven);
    return TextureLevel{size, size, std::vector<uint8_t>(size_t(size) * size_t(size) * 4, g)};
  };
  Texture t;
  t.width = t.height = 256;
  t.rgba8 = level(256, 0).rgba8;
  for (int k = 1, size = 128; size >= 1; ++k, size /= 2) t.mips[0].push_back(level(size, k));
  s.textures.push_back(t);
  s.materials[m].metallic_roughness_texture.texture = 0;
  s.materials[m].metallic_factor = 0.0f;
  s.materials[m].roughness_factor = 1.0f;
  s.camera.position = vec3(0.0f);
  s.camera.forward = vec3(0, 0, -1);
  s.camera.yfov = 1.0f;
  s.camera.znear = 0.5f;
  s.camera.zfar = 10.0f;
  s.volume = fit_volume(s.bounds);
  return s;
}

/// The wall's exact lambda: log2(256 S tan(0.5) / 16).
inline double level_wall_lambda() {
  return std::log2(256.0 * double(kLevelWallScale) * std::tan(0.5) / double(kLevelWallPixels));
}

/// llvmpipe's lambda from rho (gallivm computes 0.5 * fast_log2(rho^2), fast_log2(x) =
/// floor(log2 x) + x / 2^floor(log2 x) - 1: a linear mantissa, exact at powers of two).
inline double fast_log2_lambda(double rho) {
  int e = 0;
  const double m = std::frexp(rho * rho, &e);  // rho^2 = m 2^e, m in [1/2, 1)
  return 0.5 * (double(e - 1) + (2.0 * m - 1.0));
}

/// The lambda a roughness read back from the wall means: k + (r - c_k) / (c_k+1 - c_k) on the
/// level pair [k, k + 1] (trilinear: linear in lambda between them).
inline double level_wall_lambda_of(double roughness, int k) {
  const double ck = double(k % 2 ? kLevelWallOdd : kLevelWallEven) / 255.0;
  const double ck1 = double(k % 2 ? kLevelWallEven : kLevelWallOdd) / 255.0;
  return double(k) + (roughness - ck) / (ck1 - ck);
}

}  // namespace vct::test
