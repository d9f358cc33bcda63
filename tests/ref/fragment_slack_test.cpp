// The voxel shading slack (freedoms/fragment_slack.h) against hand-computed values: the sub-texel
// weight shift of a bilinear lookup, and the position term of a floor under a point light, whose
// light falls off as h / d^3 (glTF point light: I cos(theta) / d^2, cos(theta) = h / d).
#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>
#include <random>

#include "snapped_triangle_fixture.h"
#include "freedoms/fragment_exactness.h"
#include "freedoms/fragment_slack.h"
#include "freedoms/lookup_precision.h"
#include "freedoms/texture_slack.h"
#include "scene/gltf_loader.h"
#include "scene/texture_mips.h"
#include "scene/texture_sample.h"
#include "stage_test_scene.h"
#include "stages/inject.h"
#include "stages/shadow_map.h"

namespace vct {
namespace {

// A 2x1 texture (0, 255) read at u = 0.5 lies halfway between the two texel centres: bilinear
// gives 0.5, and a sample point moved by t texels gives 0.5 + t (slope one per texel).
TEST(FragmentSlack, TexelShiftMovesTheBilinearSamplePointInTexels) {
  Texture t;
  t.width = 2;
  t.height = 1;
  t.rgba8 = {0, 0, 0, 255, 255, 255, 255, 255};
  const vec2 uv(0.5f, 0.5f);
  EXPECT_FLOAT_EQ(sample_level(t, t.rgba8.data(), 2, 1, uv, true, false).r, 0.5f);
  for (int k = 1; k < kTexelShifts; ++k) {
    const vec2 shift = texel_shift(k);
    EXPECT_FLOAT_EQ(std::abs(shift.x), kSubtexelShift);
    EXPECT_FLOAT_EQ(std::abs(shift.y), kSubtexelShift);
    EXPECT_NEAR(sample_level(t, t.rgba8.data(), 2, 1, uv, true, false, shift).r, 0.5f + shift.x, 1e-6f);
  }
  EXPECT_EQ(texel_shift(0), vec2(0.0f));
}

// A 4 m floor at y = 0 under a point light at height h above the origin, nothing else: every
// fragment's light is c h / d^3 with d its distance to the light. The position term moves the
// fragment by (+-2^-8, +-2^-8) voxels along x and z (the floor's dominant-axis window), so the
// slack is the largest |L(p + delta) - L(p)| over those four corners: no texture, no shadow edge.
TEST(FragmentSlack, PositionTermIsTheLightsChangeOverASnapOfTheVoxelRaster) {
  Scene s;
  const uint32_t m = test::add_material(s, vec3(0.8f));
  test::add_quad(s, {-2, 0, -2}, {2, 0, -2}, {2, 0, 2}, {-2, 0, 2}, {0, 1, 0}, m);
  const float h = 1.5f;
  Light lamp;
  lamp.kind = LightKind::Point;
  lamp.position = vec3(0.0f, h, 0.0f);
  lamp.intensity = 10.0f;
  s.lights.push_back(lamp);
  s.volume = fit_volume(s.bounds);
  VctSettings settings;
  settings.grid = 16;
  const std::vector<ShadowMap> maps = render_shadow_maps(s, settings);
  const Voxelization vox = voxelize_gpu_rule(s, settings.grid, 4);
  ASSERT_FALSE(vox.fragments.empty());
  const std::vector<vec3> values = fragment_radiance(s, vox, maps, settings);
  const std::vector<float> slack = fragment_shading_slack(s, vox, maps, settings);
  const double step = double(s.volume.size) / double(settings.grid) / 256.0;  // 2^-8 voxel, metres
  const auto falloff = [&](double x, double z) {
    const double d = std::sqrt(x * x + z * z + double(h) * double(h));
    return double(h) / (d * d * d);
  };
  const VoxelFragment& f0 = vox.fragments.front();
  const double c = double(values.front().x) / falloff(f0.position.x, f0.position.z);
  int checked = 0;
  for (size_t i = 0; i < vox.fragments.size(); i += 7) {
    const VoxelFragment& f = vox.fragments[i];
    const double x = f.position.x, z = f.position.z;
    // The reference's own light follows c h / d^3 (no shadow, no texture): the model holds.
    ASSERT_NEAR(double(values[i].x), c * falloff(x, z), 1e-5 * c * falloff(x, z));
    double expected = 0.0;
    for (double dx : {-step, step})
      for (double dz : {-step, step})
        expected = std::max(expected, std::abs(c * (falloff(x + dx, z + dz) - falloff(x, z))));
    // Float evaluation of both lights: a few ulps of the light, far below the slack itself.
    EXPECT_NEAR(double(slack[i]), expected, 1e-6 * c * falloff(x, z) + 0.02 * expected) << "fragment " << i;
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

// `s` under a sun of intensity 2 pointing along `direction`, voxelized at 8^3 (4 samples): each
// fragment's light and shading slack.
struct SunlitVoxels {
  Light sun;
  VctSettings settings;
  Voxelization vox;
  std::vector<vec3> values;
  std::vector<float> slack;
};
SunlitVoxels sunlit_voxels(Scene& s, const vec3& direction) {
  SunlitVoxels v;
  v.sun.kind = LightKind::Directional;
  v.sun.direction = direction;
  v.sun.intensity = 2.0f;
  s.lights.push_back(v.sun);
  s.volume = fit_volume(s.bounds);
  build_texture_mips(s);
  v.settings.grid = 8;
  const std::vector<ShadowMap> maps = render_shadow_maps(s, v.settings);
  v.vox = voxelize_gpu_rule(s, v.settings.grid, 4);
  v.values = fragment_radiance(s, v.vox, maps, v.settings);
  v.slack = fragment_shading_slack(s, v.vox, maps, v.settings);
  return v;
}

// A floor whose normal map is one texel (128, 128, 255) under a sun at 60 degrees elevation along
// +x: tn = 2 t - 1 = (1/255, 1/255, 1), so with normal +y and tangent +x (bitangent n x t = -z)
// the shading normal is (tn.x, tn.z, -tn.y) / |tn| and n.l = (tn.x cos e + tn.z sin e) / |tn|.
// Nothing varies across the floor (position and LOD terms are zero), so the slack is the 8-bit
// precision term alone: the largest |L(corner) - L| over texels moved by +-1/255 per channel
// (clamped to [0, 1]), L proportional to n.l.
TEST(FragmentSlack, NormalMapTexelMayBeOneUnorm8StepOff) {
  Scene s;
  const uint32_t m = test::add_material(s, vec3(0.8f));
  test::add_quad(s, {-2, 0, -2}, {2, 0, -2}, {2, 0, 2}, {-2, 0, 2}, {0, 1, 0}, m);
  s.tangents.assign(s.positions.size(), vec4(1, 0, 0, 1));
  Texture t;
  t.width = t.height = 1;
  t.rgba8 = {128, 128, 255, 255};
  s.textures.push_back(t);
  s.materials[m].normal_texture.texture = 0;
  const double e = glm::radians(60.0);
  // The direction is where the light points.
  const SunlitVoxels lit = sunlit_voxels(s, -vec3(float(std::cos(e)), float(std::sin(e)), 0.0f));
  const Voxelization& vox = lit.vox;
  const std::vector<vec3>& values = lit.values;
  const std::vector<float>& slack = lit.slack;
  const auto n_dot_l = [&](double tx, double ty, double tz) {
    const glm::dvec3 tn(2.0 * tx - 1.0, 2.0 * ty - 1.0, 2.0 * tz - 1.0);
    return (tn.x * std::cos(e) + tn.z * std::sin(e)) / glm::length(tn);
  };
  const double ref = n_dot_l(128 / 255.0, 128 / 255.0, 1.0);
  double expected_rel = 0.0;  // largest |n.l(corner) - n.l| / n.l
  for (double dx : {-1.0, 1.0})
    for (double dy : {-1.0, 1.0})
      for (double dz : {-1.0, 1.0}) {
        const double nl = n_dot_l((128 + dx) / 255.0, (128 + dy) / 255.0, std::min(1.0, (255 + dz) / 255.0));
        expected_rel = std::max(expected_rel, std::abs(nl - ref) / ref);
      }
  ASSERT_GT(expected_rel, 0.004);  // ~ (2/255) cot(e) = 0.0045: far above float noise
  int checked = 0;
  for (size_t i = 0; i < vox.fragments.size(); ++i) {
    const double light = values[i].x;
    ASSERT_GT(light, 0.0) << "fragment " << i << " in shadow";
    EXPECT_NEAR(double(slack[i]), expected_rel * light, 1e-4 * light) << "fragment " << i;
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

// A floor textured with a 4096 x 1 strip of random grey texels, NEAREST without mipmaps, under a
// sun: the light is albedo(u) E cos / pi with nothing else varying. At grid 8 a voxel holds about
// 560 texels along u, so the snap square (+-2^-8 voxel and a little more) spans about four texels,
// and a texel inside it may be brighter or darker than those under all four corners. The slack must
// reach the largest |albedo change| over every texel the square covers
// (freedoms/texel_breakpoints.h); the corners alone miss them.
TEST(FragmentSlack, PositionTermReachesEveryNearestTexelInsideTheSnap) {
  Scene s;
  const uint32_t m = test::add_material(s, vec3(1.0f));
  test::add_quad(s, {-2, 0, -2}, {2, 0, -2}, {2, 0, 2}, {-2, 0, 2}, {0, 1, 0}, m);
  for (size_t i = 0; i < s.positions.size(); ++i) s.uv0[i] = vec2((s.positions[i].x + 2.0f) / 4.0f, 0.5f);
  Texture t;
  t.width = 4096;
  t.height = 1;
  t.min_filter = MinFilter::Nearest;
  t.mag_filter = Filter::Nearest;
  std::mt19937 rng(3);
  for (int i = 0; i < t.width; ++i) {
    const uint8_t g = uint8_t(rng() % 256);
    t.rgba8.insert(t.rgba8.end(), {g, g, g, 255});
  }
  s.textures.push_back(t);
  s.materials[m].base_color_texture.texture = 0;
  const SunlitVoxels lit = sunlit_voxels(s, glm::normalize(vec3(0.3f, -1.0f, 0.2f)));
  const Light& sun = lit.sun;
  const VctSettings& settings = lit.settings;
  const Voxelization& vox = lit.vox;
  const std::vector<vec3>& values = lit.values;
  const std::vector<float>& slack = lit.slack;
  const double e_cos = double(sun.intensity) * double(-sun.direction.y) * double(kInvPi);
  // The square's half-width along u: at least 2^-8 voxel (the reach grows a little with the
  // triangle's gradients, never shrinks).
  const double half = double(s.volume.size) / settings.grid / 256.0 / 4.0 * t.width;  // texels
  int checked = 0, inside_beyond_corners = 0;
  for (size_t i = 0; i < vox.fragments.size(); ++i) {
    const double centre = (double(vox.fragments[i].position.x) + 2.0) / 4.0 * t.width;
    const double albedo = double(values[i].x) / e_cos;
    double largest = 0.0, corners = 0.0;
    for (int k = int(std::floor(centre - half)); k <= int(std::floor(centre + half)); ++k)
      largest = std::max(largest, std::abs(double(srgb8_to_linear(t.rgba8[size_t(4 * k)])) - albedo));
    for (double c : {centre - half, centre + half})
      corners = std::max(corners, std::abs(double(srgb8_to_linear(t.rgba8[size_t(4 * int(std::floor(c)))])) - albedo));
    if (largest > corners + 0.01) ++inside_beyond_corners;
    // Float rounding of the light: a few ulps.
    EXPECT_GE(double(slack[i]), largest * e_cos - 1e-5) << "fragment " << i;
    ++checked;
  }
  EXPECT_GT(checked, 50);
  EXPECT_GT(inside_beyond_corners, 5);  // the case the corners alone would miss
}

// scenes/regressions/seed-229-small: the voxel at (10, 8, 8) holds one fragment extrapolated far
// past its triangle, under a sun; its snap square covers a dark texel of a 33x33 NEAREST texture
// that no corner reads. Mesa llvmpipe stored 0.01678 (red) against the reference's 0.58643: the
// slack must reach that 0.5697 (the square's corners alone gave 0.551).
// A regression case's scene, its shadow maps, its GPU-rule voxelization (4 samples) and every
// fragment's shading slack at `grid` and `map_size`.
struct RegressionSlack {
  Scene scene;
  VctSettings settings;
  std::vector<ShadowMap> maps;
  Voxelization vox;
  std::vector<float> slack;
};
RegressionSlack regression_slack(const std::string& name, int grid, int map_size) {
  RegressionSlack r;
  r.scene = load_scene(std::string(VCT_SOURCE_DIR) + "/scenes/regressions/" + name + "/scene.gltf");
  r.settings.grid = grid;
  r.settings.shadow_map_size = map_size;
  r.maps = render_shadow_maps(r.scene, r.settings);
  r.vox = voxelize_gpu_rule(r.scene, grid, 4);
  r.slack = fragment_shading_slack(r.scene, r.vox, r.maps, r.settings);
  return r;
}

TEST(FragmentSlack, Seed229SnapSquareReachesTheDarkTexel) {
  const RegressionSlack r = regression_slack("seed-229-small", 16, 64);
  const Volume v = voxel_shading_slack(r.vox, r.slack);
  EXPECT_GE(*v.voxel(10, 8, 8), 0.58643f - 0.01678f);
}

// Exact fragments: untextured, no light reaching them by the margin, no bounce. A floor with
// emission under (a) a sun from below (n.l = -0.5: exact), (b) a sun from above (lit: not),
// (c) a spot above pointing sideways, the floor outside its 30 degree cone (exact; pointing down
// with a 60 degree cone it reaches the floor), (d) a textured floor or a bounce frame (never).
TEST(FragmentSlack, ExactFragmentsAreThoseNoFreedomReaches) {
  Scene s;
  const uint32_t m = test::add_material(s, vec3(0.5f), vec3(0.3f));
  test::add_quad(s, {-1, 0, -1}, {1, 0, -1}, {1, 0, 1}, {-1, 0, 1}, {0, 1, 0}, m);
  s.volume = fit_volume(s.bounds);
  const Voxelization vox = voxelize_gpu_rule(s, 4, 4);
  ASSERT_FALSE(vox.fragments.empty());
  const VoxelFragment& f = vox.fragments.front();
  VctSettings settings;
  Light sun;
  sun.kind = LightKind::Directional;
  sun.direction = glm::normalize(vec3(0.0f, 1.0f, 1.0f));  // points up: the light comes from below
  s.lights = {sun};
  EXPECT_TRUE(fragment_light_is_exact(s, f, settings, 4, false));
  EXPECT_FALSE(fragment_light_is_exact(s, f, settings, 4, true));  // a bounce term: float cones
  s.lights[0].direction = -s.lights[0].direction;
  EXPECT_FALSE(fragment_light_is_exact(s, f, settings, 4, false));
  Light spot;
  spot.kind = LightKind::Spot;
  spot.position = vec3(0.0f, 1.0f, 0.0f);
  spot.direction = glm::normalize(vec3(1.0f, 0.0f, 0.0f));  // sideways: 90 degrees off the floor
  spot.outer_cone_angle = glm::radians(30.0f);
  s.lights = {spot};
  EXPECT_TRUE(fragment_light_is_exact(s, f, settings, 4, false));
  s.lights[0].direction = vec3(0.0f, -1.0f, 0.0f);  // down: every fragment within 47 degrees of it
  s.lights[0].outer_cone_angle = glm::radians(60.0f);
  EXPECT_FALSE(fragment_light_is_exact(s, f, settings, 4, false));
  s.lights.clear();
  Texture t;
  t.width = t.height = 1;
  t.rgba8 = {255, 255, 255, 255};
  s.textures.push_back(t);
  s.materials[m].emissive_texture.texture = 0;
  EXPECT_FALSE(fragment_light_is_exact(s, f, settings, 4, false));
  // Per voxel: 1 where every fragment is exact.
  s.materials[m].emissive_texture.texture = -1;
  const Volume v = voxel_exactness(s, vox, settings, false);
  for (const VoxelFragment& g : vox.fragments) EXPECT_EQ(*v.voxel(g.voxel.x, g.voxel.y, g.voxel.z), 1.0f);
}

// The snap square decides exactness (large hunt seed 116: a heightfield triangle 1/20 voxel wide
// whose vertex normals differ by 1.6, n.l = -0.018 to the sun at its fragment; llvmpipe lit it).
// Vertex normals whose n.l (light from +y) is -0.3, +0.3 and -0.06: -0.02 at the centroid, past
// the margin, but a 2^-8-voxel snap moves the barycentrics of a triangle 0.08 voxel wide by ~0.1
// and n.l with them past zero. The same triangle 25 times larger moves them 25 times less.
TEST(FragmentSlack, AFragmentIsExactOnlyWhereNoSnapOfItsPointLetsLightIn) {
  for (const float size : {0.04f, 1.0f}) {  // world units; the voxel is 0.5 (grid 4 over 2 units)
    Scene s;
    const uint32_t m = test::add_material(s, vec3(0.5f), vec3(0.3f));
    test::add_triangle(s, {0, 0, 0}, {size, 0, 0}, {0, 0, size}, m);
    const float ys[3] = {-0.3f, 0.3f, -0.06f};
    for (int k = 0; k < 3; ++k) s.normals[size_t(k)] = glm::normalize(vec3(std::sqrt(1.0f - ys[k] * ys[k]), ys[k], 0.0f));
    s.volume.origin = vec3(-1.0f);
    s.volume.size = 2.0f;
    Light sun;
    sun.kind = LightKind::Directional;
    sun.direction = vec3(0.0f, -1.0f, 0.0f);  // the light comes from +y
    s.lights = {sun};
    VoxelFragment f;
    f.triangle = 0;
    f.b1 = f.b2 = 1.0f / 3.0f;
    f.position = interpolate_surface(s, 0, f.b1, f.b2).position;
    const vec3 n = interpolate_surface(s, 0, f.b1, f.b2).normal;
    ASSERT_LT(glm::dot(n, vec3(0.0f, 1.0f, 0.0f)), -kBehindLightMargin);  // behind the light at the centroid
    EXPECT_EQ(fragment_light_is_exact(s, f, VctSettings{}, 4, false), size > 0.5f) << size;
  }
}

// A triangle a quarter voxel wide, its fragment's pixel centre far outside it (an MSAA sample
// covered, the attributes extrapolated): barycentrics (-3, 2, 2), sum |l| = 7, G = 16 per voxel,
// so the reach is 2^-8 x 7 / (1 - 16 / 256) = 7/240 voxel. Every snap of the three vertices by at
// most 2^-8 per axis (the 64 extreme ones and 4000 random ones) moves the point GL interpolates
// within it (the extreme ones reach it exactly), some 6.5x further than the snap itself.
TEST(FragmentSlack, SnapReachCoversExtrapolatedAttributes) {
  Scene s;
  const uint32_t m = test::add_material(s, vec3(0.8f));
  test::add_triangle(s, {4.0f, 4.0f, 3.5f}, {4.25f, 4.0f, 3.5f}, {4.0f, 4.25f, 3.5f}, m);
  s.volume.origin = vec3(0.0f);
  s.volume.size = 16.0f;  // one voxel = one unit at n = 16
  VoxelFragment f;
  f.voxel = ivec3(4, 4, 3);
  f.position = vec3(4.5f, 4.5f, 3.5f);
  f.b1 = 2.0f;
  f.b2 = 2.0f;
  const double reach = voxel_snap_reach(s, 16, f);
  EXPECT_NEAR(reach, 7.0 / 240.0, 1e-12);
  const double step = 1.0 / 256.0;
  double largest = test::largest_corner_move(step);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-step, step);
  for (int k = 0; k < 4000; ++k) {
    double d[6];
    for (double& x : d) x = u(rng);
    const glm::dvec2 e = test::extrapolated_point_move(d);
    largest = std::max({largest, std::abs(e.x), std::abs(e.y)});
  }
  EXPECT_LE(largest, reach * (1.0 + 1e-9));  // attained: the bound is tight here
  EXPECT_GT(largest, 6.5 * step);  // the 2^-8 of a centre inside the triangle would miss it
  // Inside the triangle the reach is the snap itself, up to G's term.
  f.position = vec3(4.05f, 4.05f, 3.5f);
  f.b1 = f.b2 = 0.2f;
  EXPECT_NEAR(voxel_snap_reach(s, 16, f), step / (1.0 - 16.0 * step), 1e-9);
}

// The voxel's slack is the mean of its fragments' slacks.
TEST(FragmentSlack, VoxelSlackIsTheMeanOfItsFragments) {
  Voxelization vox;
  vox.n = 2;
  VoxelFragment a, b, c;
  a.voxel = b.voxel = ivec3(1, 0, 0);
  c.voxel = ivec3(0, 1, 1);
  vox.fragments = {a, b, c};
  const Volume v = voxel_shading_slack(vox, {0.25f, 0.75f, 0.125f});
  EXPECT_FLOAT_EQ(*v.voxel(1, 0, 0), 0.5f);
  EXPECT_FLOAT_EQ(*v.voxel(0, 1, 1), 0.125f);
  EXPECT_FLOAT_EQ(*v.voxel(0, 0, 0), 0.0f);
}


// scenes/regressions/seed-24-large: at voxel (47, 105, 121) one of the two fragments is extrapolated
// (barycentrics (1.11, -2.76, 2.64)) and so is its COLOR_0, whose red turns negative (-2.3): its
// light from the sun is negative, and a PCF tap it may read lit lowers it. Mesa llvmpipe wrote
// red 0.02484 against the reference's 0.03546 (the other fragment is the emission alone). The
// shadow term counts the unshadowed light's magnitude; counted as non-negative it was 0 and the
// voxel's slack 0.0065.
TEST(FragmentSlack, ANegativeLightsVisibilityIsInTheSlack) {
  const RegressionSlack r = regression_slack("seed-24-large", 128, 1024);
  const Scene& s = r.scene;
  const Voxelization& vox = r.vox;
  const std::vector<vec3> values = fragment_radiance(s, vox, r.maps, r.settings);
  const ivec3 v(47, 105, 121);
  double mean = 0.0;
  int count = 0;
  bool negative_albedo = false;
  for (size_t i = 0; i < vox.fragments.size(); ++i) {
    if (vox.fragments[i].voxel != v) continue;
    mean += double(values[i].x), ++count;
    negative_albedo = negative_albedo || interpolate_surface(s, vox.fragments[i].triangle, vox.fragments[i].b1,
                                                              vox.fragments[i].b2).color.x < 0.0f;
  }
  ASSERT_EQ(count, 2);
  EXPECT_TRUE(negative_albedo);
  mean /= double(count);
  EXPECT_NEAR(mean, 0.03546, 1e-4);
  EXPECT_GE(double(*voxel_shading_slack(vox, r.slack).voxel(v.x, v.y, v.z)), mean - 0.02484);
}

}  // namespace
}  // namespace vct
