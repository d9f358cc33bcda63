// Texture LOD (scene/texture_lod.h, stages/uv_derivatives.h, stages/voxel_lod.h) against
// hand-computed values: GL 4.5 §8.14's level selection for every min filter, trilinear lookups on
// a built chain, rho's admissible approximations, and lambda of planes at known distances with
// known UV scales, for the camera and for the voxel grid.
#include <cmath>
#include <gtest/gtest.h>

#include "freedoms/lod_candidates.h"
#include "freedoms/texture_slack.h"
#include "scene/texture_lod.h"
#include "scene/texture_mips.h"
#include "scene/texture_sample.h"
#include "stage_test_scene.h"
#include "stages/uv_derivatives.h"
#include "stages/voxel_lod.h"

namespace vct {
namespace {

Texture with_filters(MinFilter min, Filter mag = Filter::Linear) {
  Texture t;
  t.width = t.height = 16;
  t.min_filter = min;
  t.mag_filter = mag;
  return t;
}

TEST(TextureLod, LevelSelectionPerMinFilter) {
  const int q = 4;  // a 16 x 16 chain: levels 0..4
  // Magnified (lambda <= 0): level 0 with the mag filter, whatever the min filter.
  LevelBlend b =
      select_levels(with_filters(MinFilter::LinearMipmapLinear, Filter::Nearest), -0.5, q);
  EXPECT_EQ(b.level1, 0);
  EXPECT_FALSE(b.linear);
  EXPECT_EQ(select_levels(with_filters(MinFilter::NearestMipmapNearest), 0.0, q).linear, true);
  // NEAREST / LINEAR: level 0 at any lambda.
  b = select_levels(with_filters(MinFilter::Nearest), 3.0, q);
  EXPECT_EQ(b.level1, 0);
  EXPECT_FALSE(b.linear);
  EXPECT_EQ(select_levels(with_filters(MinFilter::Linear), 3.0, q).level1, 0);
  // *_MIPMAP_NEAREST: d = 0 for lambda <= 1/2, else ceil(lambda + 1/2) - 1.
  const Texture lmn = with_filters(MinFilter::LinearMipmapNearest);
  EXPECT_EQ(select_levels(lmn, 0.5, q).level1, 0);
  EXPECT_EQ(select_levels(lmn, 0.51, q).level1, 1);
  EXPECT_EQ(select_levels(lmn, 1.4, q).level1, 1);
  EXPECT_EQ(select_levels(lmn, 1.6, q).level1, 2);
  EXPECT_EQ(select_levels(lmn, 9.0, q).level1, 4);  // clamped to q
  EXPECT_EQ(select_levels(lmn, 1.6, q).weight2, 0.0f);
  EXPECT_FALSE(select_levels(with_filters(MinFilter::NearestMipmapNearest), 1.6, q).linear);
  // *_MIPMAP_LINEAR: floor(lambda) and the next level, weight frac(lambda); both q beyond q.
  b = select_levels(with_filters(MinFilter::LinearMipmapLinear), 1.25, q);
  EXPECT_EQ(b.level1, 1);
  EXPECT_EQ(b.level2, 2);
  EXPECT_FLOAT_EQ(b.weight2, 0.25f);
  EXPECT_TRUE(b.linear);
  b = select_levels(with_filters(MinFilter::NearestMipmapLinear), 3.5, q);
  EXPECT_EQ(b.level1, 3);
  EXPECT_EQ(b.level2, 4);
  EXPECT_FALSE(b.linear);
  b = select_levels(with_filters(MinFilter::LinearMipmapLinear), 4.3, q);
  EXPECT_EQ(b.level1, 4);
  EXPECT_EQ(b.level2, 4);
}

TEST(TextureLod, TrilinearLookupBlendsTwoLevels) {
  // 2x2 linear checker 0 / 255: level 1 is (0 + 255 + 255 + 0 + 2) / 4 = 128. At the centre of
  // texel (0, 0) level 0 gives 0 (bilinear at a texel centre), level 1 gives 128/255.
  Texture t;
  t.width = t.height = 2;
  t.rgba8 = {0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255};
  t.mips[0] = build_mip_chain(t, false);
  const vec2 uv(0.25f, 0.25f);
  EXPECT_FLOAT_EQ(sample_texture_lod(t, uv, false, -1.0).r, 0.0f);
  EXPECT_FLOAT_EQ(sample_texture_lod(t, uv, false, 1.0).r, 128.0f / 255.0f);
  EXPECT_FLOAT_EQ(sample_texture_lod(t, uv, false, 0.25).r, 0.25f * 128.0f / 255.0f);
  EXPECT_FLOAT_EQ(sample_texture_lod(t, uv, false, 7.0).r, 128.0f / 255.0f);  // clamped to level 1
  // Without a chain (a texture allocated with one level) every lambda reads level 0.
  t.mips[0].clear();
  EXPECT_FLOAT_EQ(sample_texture_lod(t, uv, false, 1.0).r, 0.0f);
}

TEST(TextureLod, RhoApproximationBounds) {
  // Axis-aligned derivatives: max(|du|,|dv|) = |du| + |dv| = |d|, the range is the LOD precision.
  RhoBounds a;
  a.add_x({8.0, 0.0});
  a.add_y({0.0, 2.0});
  EXPECT_DOUBLE_EQ(a.range().lo, 3.0 - kLodPrecision);
  EXPECT_DOUBLE_EQ(a.range().hi, 3.0 + kLodPrecision);
  // At 45 degrees the exact |d| = 8 may be computed as 8/sqrt2 (max) up to 8 sqrt2 (sum):
  // lambda in [3 - 1/2, 3 + 1/2], widened by the precision.
  RhoBounds r;
  const double c = 8.0 / std::sqrt(2.0);
  r.add_x({c, c});
  r.add_y({-c, c});
  EXPECT_NEAR(r.range().lo, 2.5 - kLodPrecision, 1e-12);
  EXPECT_NEAR(r.range().hi, 3.5 + kLodPrecision, 1e-12);
  EXPECT_NEAR(exact_lod({{c, c}, {-c, c}}), 3.0, 1e-12);
}

// Camera at the origin looking down -z (yfov 1 rad, t = tan 0.5), a W x W view, a floor at y = -1
// with u = x / 4, v = -z / 4 and a 256^2 texture. The ray through NDC (nx, ny), ny < 0, meets the
// floor at distance s = -1 / (ny t), point (nx t s, -1, -s). Texel derivatives per window pixel:
//   d/dx: (du, dv) = (256/4) (2/W) t s (1, 0)
//   d/dy: (du, dv) = (256/4) (2/W) (nx t, 1) / (ny^2 t)
Scene floor_scene() {
  Scene s;
  const uint32_t m = test::add_material(s, vec3(1.0f));
  test::add_quad(s, {-40, -1, -60}, {40, -1, -60}, {40, -1, -0.6f}, {-40, -1, -0.6f}, {0, 1, 0}, m);
  for (size_t i = 0; i < s.positions.size(); ++i)
    s.uv0[i] = vec2(s.positions[i].x / 4.0f, -s.positions[i].z / 4.0f);
  Texture t;
  t.width = t.height = 256;
  t.rgba8.assign(256 * 256 * 4, 128);
  s.textures.push_back(t);
  s.materials[m].base_color_texture.texture = 0;
  s.camera.position = vec3(0.0f);
  s.camera.forward = vec3(0, 0, -1);
  s.camera.yfov = 1.0f;
  s.camera.znear = 0.5f;
  s.camera.zfar = 100.0f;
  s.volume = fit_volume(s.bounds);
  return s;
}

TEST(TextureLod, FloorLambdaIsExactInTheCamera) {
  const Scene s = floor_scene();
  const int w = 64;
  const mat4 vp = s.camera.projection(1.0f) * s.camera.view();
  const double t = std::tan(0.5), k = 256.0 / 4.0 * 2.0 / double(w);
  int checked = 0;
  for (int py : {2, 11, 20, 29}) {  // window rows below the horizon (ny < 0)
    for (int px : {3, 32, 60}) {
      const double nx = 2.0 * (px + 0.5) / w - 1.0, ny = 2.0 * (py + 0.5) / w - 1.0;
      const double dist = -1.0 / (ny * t);
      const glm::dvec2 dx = k * t * dist * glm::dvec2(1.0, 0.0),
                       dy = k / (ny * ny * t) * glm::dvec2(nx * t, 1.0);
      const double lambda = std::log2(std::max(glm::length(dx), glm::length(dy)));
      // Which triangle of the quad covers the pixel does not matter: both lie on the same plane.
      for (uint32_t tri = 0; tri < 2; ++tri) {
        const SurfaceLods l = pixel_lods(s, tri, ScreenBarycentrics(s, tri, vp, w, w), px, py);
        EXPECT_NEAR(l.exact.lambda[kSlotBaseColor], lambda, 1e-6) << px << "," << py;
        // Quad differences of a perspective floor differ from the derivative at the centre, but
        // the admissible range holds the exact value with room for the approximations.
        EXPECT_LT(l.range[kSlotBaseColor].lo, lambda - kLodPrecision * 0.99);
        EXPECT_GT(l.range[kSlotBaseColor].hi, lambda + kLodPrecision * 0.99);
        EXPECT_LT(l.range[kSlotBaseColor].hi - l.range[kSlotBaseColor].lo,
                  2.0);  // near the horizon: ~1.1
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 24);
}

TEST(TextureLod, FacingPlaneHasOnlyTheLodPrecisionAsFreedom) {
  // A plane facing the camera at z = -2 with u = (x + 2) / 4: pixels are 2 * 2 tan(0.5) / 16 =
  // 0.136576 world units, rho = 256 * 0.136576 / 4 = 8.7408 texels, lambda = 3.12777; UV is affine
  // in the window there, so quad differences are exact and only the LOD precision remains.
  Scene s;
  const uint32_t m = test::add_material(s, vec3(1.0f));
  test::add_quad(s, {-2, -2, -2}, {2, -2, -2}, {2, 2, -2}, {-2, 2, -2}, {0, 0, 1}, m);
  for (size_t i = 0; i < s.positions.size(); ++i)
    s.uv0[i] = vec2((s.positions[i].x + 2.0f) / 4.0f, 0.5f);
  Texture t;
  t.width = t.height = 256;
  s.textures.push_back(t);
  s.materials[m].base_color_texture.texture = 0;
  s.camera.position = vec3(0.0f);
  s.camera.forward = vec3(0, 0, -1);
  s.camera.yfov = 1.0f;
  s.camera.znear = 0.5f;
  const mat4 vp = s.camera.projection(1.0f) * s.camera.view();
  const double lambda = std::log2(256.0 * 4.0 * std::tan(0.5) / 16.0 / 4.0);
  EXPECT_NEAR(lambda, 3.12777, 1e-5);
  const SurfaceLods l = pixel_lods(s, 0, ScreenBarycentrics(s, 0, vp, 16, 16), 5, 9);
  EXPECT_NEAR(l.exact.lambda[kSlotBaseColor], lambda, 1e-6);  // float view-projection
  EXPECT_NEAR(l.range[kSlotBaseColor].lo, lambda - kLodPrecision, 1e-6);
  EXPECT_NEAR(l.range[kSlotBaseColor].hi, lambda + kLodPrecision, 1e-6);
  // The slot's transform scales the texel derivatives: scale 4 in u adds exactly 2 levels.
  s.materials[m].base_color_texture.transform.scale = vec2(4.0f, 1.0f);
  EXPECT_NEAR(
      pixel_lods(s, 0, ScreenBarycentrics(s, 0, vp, 16, 16), 5, 9).exact.lambda[kSlotBaseColor],
      lambda + 2.0, 1e-6);
}

TEST(TextureLod, VoxelGridLambdaFromTheDominantAxisProjection) {
  // The floor's dominant axis is y: projected onto (x, z), one pixel = one voxel = size / n world
  // units; u = x / 4 -> 256 / 4 texels per world unit along x, and v = -z / 4 likewise along z.
  const Scene s = floor_scene();
  const int n = 64;
  const double rho = 256.0 / 4.0 * double(s.volume.size) / double(n);
  const SurfaceLods l = voxel_lods(s, 0, n);
  EXPECT_NEAR(l.exact.lambda[kSlotBaseColor], std::log2(rho), 1e-6);
  EXPECT_NEAR(l.range[kSlotBaseColor].lo, std::log2(rho) - kLodPrecision, 1e-6);
  EXPECT_NEAR(l.range[kSlotBaseColor].hi, std::log2(rho) + kLodPrecision, 1e-6);
  // Untextured slots keep lambda 0.
  EXPECT_EQ(l.exact.lambda[kSlotNormal], 0.0);
}

TEST(TextureLod, CandidatesSpanTheAdmissibleValues) {
  // Trilinear values are linear in lambda between integers: the ends and the integers between.
  double c[kMaxLodCandidates];
  ASSERT_EQ(lod_candidates({0.3, 2.5}, c), 4);
  EXPECT_EQ(c[0], 0.3);
  EXPECT_EQ(c[1], 1.0);
  EXPECT_EQ(c[2], 2.0);
  EXPECT_EQ(c[3], 2.5);
  // Straddling 0: the magnified end, the minified lookup at 0+, then the rest.
  ASSERT_EQ(lod_candidates({-0.2, 0.7}, c), 3);
  EXPECT_EQ(c[0], -0.2);
  EXPECT_GT(c[1], 0.0);
  EXPECT_LT(c[1], 1e-6);
  EXPECT_EQ(c[2], 0.7);
  ASSERT_EQ(lod_candidates({1.25, 1.25}, c), 1);  // an untextured slot's {0, 0} likewise
}

}  // namespace
}  // namespace vct
