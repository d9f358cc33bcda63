// The diffuse cone set as settings (diffuse_cone_count, diffuse_cone_tilt_deg): the host block
// reproduces the seed's constants bit for bit at the defaults, weights sum to one, directions sit
// at the stated tilt and spacing, and a uniform environment comes back unchanged for any count.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.h"
#include "shared/vct_shared.h"
#include "stages/cone_sets.h"
#include "stages/indirect_pass.h"
#include "stages/mips.h"

namespace vct {
namespace {

constexpr float kSeedSinCos = 0.70710678118654752f;  // the literal the seed set was written with

VctSettings cone_settings(int count, float tilt_deg, DiffuseWeighting w = DiffuseWeighting::Cosine) {
  VctSettings s;
  s.diffuse_cone_count = count;
  s.diffuse_cone_tilt_deg = tilt_deg;
  s.diffuse_weighting = w;
  return s;
}

// The seed set exactly as vct_shared.h wrote it before the count and tilt became settings.
vec3 seed_direction(int i, float rotation) {
  if (i == 0) return vec3(0.0f, 0.0f, 1.0f);
  const float phi = rotation + float(i - 1) * (0.5f * sh::SH_PI);
  const float s = kSeedSinCos;
  return vec3(s * std::cos(phi), s * std::sin(phi), s);
}
float seed_weight(int i, bool cosine) {
  if (!cosine) return 1.0f;
  const float c = kSeedSinCos;
  const float total = 1.0f + 4.0f * c;
  return (i == 0 ? 1.0f : c) / total;
}

TEST(DiffuseConeSet, DefaultBlockHoldsTheSeedConstantsBitForBit) {
  const sh::DiffuseConeBlock b = diffuse_cone_block(VctSettings{});
  EXPECT_EQ(b.shape.x, kSeedSinCos);
  EXPECT_EQ(b.shape.y, kSeedSinCos);
  EXPECT_EQ(b.shape.z, 0.5f * sh::SH_PI);
  EXPECT_EQ(sh::diffuse_cone_count(b), 5);
  for (bool cosine : {true, false}) {
    const sh::DiffuseConeBlock w =
        diffuse_cone_block(cone_settings(5, 45.0f, cosine ? DiffuseWeighting::Cosine : DiffuseWeighting::SeedSum));
    for (int i = 0; i < 5; ++i) EXPECT_EQ(sh::diffuse_cone_weight(i, w), seed_weight(i, cosine)) << i;
  }
  for (float rotation : {0.0f, 0.3f, 1.2345f, 1.5707f}) {
    for (int i = 0; i < 5; ++i) {
      const vec3 a = sh::diffuse_cone_direction(i, rotation, b), e = seed_direction(i, rotation);
      EXPECT_EQ(a.x, e.x) << i;
      EXPECT_EQ(a.y, e.y) << i;
      EXPECT_EQ(a.z, e.z) << i;
    }
  }
  for (uint32_t x : {0u, 7u, 511u})
    for (uint32_t frame : {0u, 3u}) {
      const uint32_t h = sh::hash_combine(sh::hash_combine(x, 2u * x + 1u), frame);
      EXPECT_EQ(sh::diffuse_cone_rotation(x, 2u * x + 1u, frame, b), sh::hash_to_unit(h) * (0.5f * sh::SH_PI));
    }
}

TEST(DiffuseConeSet, CosineWeightsSumToOneAndFollowTheCosine) {
  for (const auto& [count, tilt] : std::vector<std::pair<int, float>>{
           {1, 45.0f}, {2, 30.0f}, {3, 75.0f}, {5, 45.0f}, {9, 60.0f}, {16, 10.0f}, {16, 89.0f}}) {
    const sh::DiffuseConeBlock b = diffuse_cone_block(cone_settings(count, tilt));
    const double c = std::cos(double(tilt) * M_PI / 180.0);
    const double total = 1.0 + double(count - 1) * c;
    double sum = 0.0;
    for (int i = 0; i < count; ++i) sum += double(sh::diffuse_cone_weight(i, b));
    EXPECT_NEAR(sum, 1.0, 1e-6) << count << " cones at " << tilt;
    EXPECT_NEAR(sh::diffuse_cone_weight(0, b), 1.0 / total, 1e-7);
    if (count > 1) {
      EXPECT_NEAR(sh::diffuse_cone_weight(1, b), c / total, 1e-7);
    }
    const sh::DiffuseConeBlock seed = diffuse_cone_block(cone_settings(count, tilt, DiffuseWeighting::SeedSum));
    for (int i = 0; i < count; ++i) EXPECT_EQ(sh::diffuse_cone_weight(i, seed), 1.0f);
  }
}

TEST(DiffuseConeSet, DirectionsAreUnitAtTheTiltAndEvenlySpaced) {
  for (const auto& [count, tilt] :
       std::vector<std::pair<int, float>>{{2, 30.0f}, {5, 45.0f}, {7, 20.0f}, {9, 60.0f}, {16, 80.0f}}) {
    const sh::DiffuseConeBlock b = diffuse_cone_block(cone_settings(count, tilt));
    const double step = 2.0 * M_PI / double(count - 1);
    EXPECT_NEAR(b.shape.z, step, 1e-6);
    for (float rotation : {0.0f, 0.4f}) {
      const vec3 n = sh::diffuse_cone_direction(0, rotation, b);
      EXPECT_EQ(n, vec3(0.0f, 0.0f, 1.0f));
      for (int i = 1; i < count; ++i) {
        const vec3 d = sh::diffuse_cone_direction(i, rotation, b);
        EXPECT_NEAR(glm::length(d), 1.0f, 1e-6f);
        EXPECT_NEAR(std::acos(double(d.z)) * 180.0 / M_PI, double(tilt), 1e-4) << i;
        // Azimuth of cone i is rotation + (i-1) step (mod 2 pi).
        double az = std::atan2(double(d.y), double(d.x)) - double(rotation) - double(i - 1) * step;
        az = std::remainder(az, 2.0 * M_PI);
        EXPECT_NEAR(az, 0.0, 1e-5) << count << " cones, cone " << i;
      }
    }
    // The set repeats every step: turned by one step, cone i lands on cone i+1.
    for (int i = 1; i + 1 < count; ++i) {
      const vec3 turned = sh::diffuse_cone_direction(i, b.shape.z, b), next = sh::diffuse_cone_direction(i + 1, 0.0f, b);
      EXPECT_NEAR(glm::length(turned - next), 0.0f, 1e-5f);
    }
  }
}

TEST(DiffuseConeSet, RotationStaysWithinOneAzimuthStep) {
  for (int count : {2, 5, 16}) {
    const sh::DiffuseConeBlock b = diffuse_cone_block(cone_settings(count, 45.0f));
    for (uint32_t x = 0; x < 64; ++x) {
      const float r = sh::diffuse_cone_rotation(x, 3u * x, 9u, b);
      EXPECT_GE(r, 0.0f);
      EXPECT_LT(r, b.shape.z);
    }
  }
  EXPECT_EQ(diffuse_cone_block(cone_settings(1, 45.0f)).shape.z, 0.0f);  // one cone: nothing to turn
}

TEST(DiffuseConeSet, BlockRefusesCountsAndTiltsOutOfRange) {
  for (int count : {0, 17, -1}) EXPECT_THROW(diffuse_cone_block(cone_settings(count, 45.0f)), InputError) << count;
  for (float tilt : {0.0f, 90.0f, -5.0f, std::nanf("")})
    EXPECT_THROW(diffuse_cone_block(cone_settings(5, tilt)), InputError) << tilt;
}

// Every voxel of every level holds (R, 1, 1, 1) with opacity 1: each cone's first sample is the
// whole answer.
VoxelMips uniform_mips(float r) {
  VoxelMips m;
  for (int n = 16; n >= 1; n /= 2) m.iso.push_back(Volume(n, n, n, 4, 1.0f));
  for (Volume& v : m.iso)
    for (size_t i = 0; i < v.voxel_count(); ++i) v.data[i * 4] = r;
  return m;
}

TEST(DiffuseConeSet, UniformEnvironmentComesBackUnchangedForAnyCount) {
  const VoxelMips m = uniform_mips(0.25f);
  VoxelVolume vol;
  for (int count : {1, 5, 9, 16}) {
    for (float tilt : {20.0f, 45.0f, 70.0f}) {
      for (const vec3& n : {vec3(0, 1, 0), glm::normalize(vec3(0.3f, 0.4f, 0.8f)), glm::normalize(vec3(-1, -2, 0.5f))}) {
        VctSettings s = cone_settings(count, tilt);
        const DiffuseConeSet set = trace_diffuse_cones(m, vol, s, vec3(0.5f), n, 0.7f);
        ASSERT_EQ(set.count, count);
        EXPECT_NEAR(set.radiance.x, 0.25f, 1e-6f) << count << " cones at " << tilt;
        EXPECT_NEAR(set.radiance.y, 1.0f, 1e-6f) << count << " cones at " << tilt;
        s.diffuse_weighting = DiffuseWeighting::SeedSum;  // the plain sum: count x L
        EXPECT_NEAR(trace_diffuse_cones(m, vol, s, vec3(0.5f), n, 0.7f).radiance.y, float(count), 1e-5f * float(count));
      }
    }
  }
}

TEST(DiffuseConeSet, IndirectPassWritesOneImagePerConeAndTheirWeightedSum) {
  // A base level with a smooth gradient, so the cones of a set see different radiance.
  const int n = 16;
  Volume base(n, n, n, 4);
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x)
        if (x == 0 || y == n - 1 || z == 0) base.set_rgba(x, y, z, vec4(0.1f * float(x % 5), 0.05f * float(z), 0.3f, 1.0f));
  const VoxelMips m = build_mips(base, false);
  GBuffer g;
  g.coverage = Image(3, 2, 1, 1.0f);
  g.position = Image(3, 2, 3, 0.5f);
  g.normal = Image(3, 2, 3, 0.0f);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) g.normal.set_rgb(x, y, glm::normalize(vec3(float(x) - 1.0f, 1.0f, float(y) - 0.5f)));
  g.material = Image(3, 2, 4, 0.5f);
  Scene scene;
  scene.camera.position = vec3(0.5f, 0.5f, 3.0f);
  VctSettings s = cone_settings(9, 60.0f);
  s.random_rotation = true;
  s.frame = 2;
  const IndirectImages ind = trace_indirect(scene, g, m, s);
  ASSERT_EQ(ind.diffuse_cones.size(), 9u);
  const sh::DiffuseConeBlock b = diffuse_cone_block(s);
  double total = 0.0;
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x) {
      vec3 sum(0.0f);
      for (int i = 0; i < 9; ++i) sum += sh::diffuse_cone_weight(i, b) * ind.diffuse_cones[size_t(i)].rgb(x, y);
      EXPECT_EQ(sum, ind.diffuse.rgb(x, y)) << x << "," << y;  // same order of operations
      total += double(sum.x + sum.y + sum.z);
    }
  EXPECT_GT(total, 0.0);
}

}  // namespace
}  // namespace vct
