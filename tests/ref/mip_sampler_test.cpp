// The frame's fast sampler (stages/mip_sampler.h) against the readable one (voxel_sampler.h): the
// same bits for every lookup, including empty cells it skips, the border, lod outside the chain
// and axis-aligned directions; and the cone march on both.
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "stages/cone_trace.h"
#include "stages/march_schedule.h"
#include "stages/mip_sampler.h"
#include "stages/mips.h"
#include "stages/voxel_sampler.h"

namespace vct {
namespace {

// A sparse 16^3 volume: most voxels exactly 0 (some -0), a few walls and blobs of varied values,
// so lookups hit empty, partly filled and full cells at every level.
Volume sparse_volume(uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  Volume v(16, 16, 16, 4);
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i < 16; ++i) {
        const bool wall = i == 0 || j == 15 || (k == 9 && i > 4);
        const bool blob = u(rng) < 0.03f;
        if (wall || blob) v.set_rgba(i, j, k, vec4(u(rng), u(rng) * 3.0f, u(rng) * 1e-3f, blob ? u(rng) : 1.0f));
        else if (u(rng) < 0.1f) v.set_rgba(i, j, k, vec4(-0.0f));
      }
  return v;
}

bool same_bits(const vec4& a, const vec4& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expect_same_lookups(const VoxelMips& mips, uint32_t seed) {
  const MipSampler fast(mips);
  ASSERT_TRUE(fast.usable());
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f), lod(-1.0f, 6.0f), d(-1.0f, 1.0f);
  int differ = 0, nonzero = 0, zero = 0;
  for (int n = 0; n < 40000; ++n) {
    vec3 p(u(rng), u(rng), u(rng));
    if (n % 7 == 0) p.x = float(int(p.x * 16.0f)) / 16.0f + 1.0f / 32.0f;  // a texel centre
    if (n % 11 == 0) p.y = n % 2 ? 0.0f : 1.0f;                           // the faces of the volume
    vec3 dir(d(rng), d(rng), d(rng));
    if (n % 5 == 0) dir = vec3(n % 10 ? 1.0f : -1.0f, 0.0f, 0.0f);        // axis-aligned: zero weights
    dir = glm::normalize(dir);
    const float l = n % 13 == 0 ? float(n % 5) : lod(rng);                // whole lods: one level
    const vec4 a = fast.sample(p, l, dir), b = sample_voxels(mips, p, l, dir);
    differ += !same_bits(a, b);
    (b == vec4(0.0f) ? zero : nonzero)++;
  }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(zero, 1000);  // both kinds of cell were exercised
  EXPECT_GT(nonzero, 1000);
}

TEST(MipSampler, IsotropicLookupsHaveTheReferenceBits) {
  expect_same_lookups(build_mips(sparse_volume(1), false), 11);
}

TEST(MipSampler, AnisotropicLookupsHaveTheReferenceBits) {
  expect_same_lookups(build_mips(sparse_volume(2), true), 12);
}

TEST(MipSampler, ConeMarchHasTheReferenceBits) {
  for (bool aniso : {false, true}) {
    const VoxelMips mips = build_mips(sparse_volume(3), aniso);
    const MipSampler fast(mips);
    std::mt19937 rng(4);
    std::uniform_real_distribution<float> u(0.05f, 0.95f), d(-1.0f, 1.0f);
    MarchParams params;
    params.start_offset = 1.0f / 16.0f;
    int differ = 0;
    for (int n = 0; n < 3000; ++n) {
      Cone c;
      c.origin = vec3(u(rng), u(rng), u(rng));
      c.direction = glm::normalize(vec3(d(rng), d(rng), d(rng)));
      c.aperture = 0.02f + 1.2f * u(rng);
      params.min_lod = n % 3 == 0 ? 1.0f : 0.0f;
      differ += !same_bits(trace_cone(fast, c, params), trace_cone(mips, c, params));
    }
    EXPECT_EQ(differ, 0) << (aniso ? "anisotropic" : "isotropic");
  }
}

// A zero aperture keeps the diameter at one voxel: every step is voxel x quality, so the steps
// are counted by hand. 1/16 start, 1/32 steps (exact binary fractions), t < 1: t = 1/16 + k/32
// for k = 0..29, 30 steps.
TEST(MarchSchedule, ZeroApertureStepsAreCountedByHand) {
  MarchParams params;
  params.start_offset = 1.0f / 16.0f;
  params.max_distance = 1.0f;
  params.quality = 0.5f;
  const MarchSchedule schedule(0.0f, params, 1.0f / 16.0f);
  ASSERT_EQ(schedule.size(), 30u);
  for (size_t k = 0; k < schedule.size(); ++k) {
    EXPECT_EQ(schedule[k].diameter, 1.0f / 16.0f);
    EXPECT_EQ(schedule[k].lod, 0.0f);
    EXPECT_EQ(schedule[k].step, 1.0f / 32.0f);
  }
  EXPECT_TRUE(schedule.fits(0.0f, params, 1.0f / 16.0f));
  MarchParams other = params;
  other.max_distance = 0.5f;  // stops earlier on the same steps
  EXPECT_TRUE(schedule.fits(0.0f, other, 1.0f / 16.0f));
  other = params;
  other.quality = 0.25f;
  EXPECT_FALSE(schedule.fits(0.0f, other, 1.0f / 16.0f));
  other = params;
  other.start_offset = 0.0f;
  EXPECT_FALSE(schedule.fits(0.0f, other, 1.0f / 16.0f));
  other = params;
  other.min_lod = 1.0f;
  EXPECT_FALSE(schedule.fits(0.0f, other, 1.0f / 16.0f));
  EXPECT_FALSE(schedule.fits(0.1f, params, 1.0f / 16.0f));
  EXPECT_FALSE(schedule.fits(0.0f, params, 1.0f / 32.0f));
}

// The frame's march with a schedule (whole, shorter than the march so that it computes the rest,
// or for another aperture so that it is ignored) against the readable march: the same bits.
TEST(MarchSchedule, ScheduledMarchHasTheReferenceBits) {
  for (bool aniso : {false, true}) {
    const VoxelMips mips = build_mips(sparse_volume(5), aniso);
    const MipSampler fast(mips);
    std::mt19937 rng(6);
    std::uniform_real_distribution<float> u(0.05f, 0.95f), d(-1.0f, 1.0f);
    int differ = 0, scheduled = 0;
    for (int n = 0; n < 3000; ++n) {
      MarchParams params;
      params.start_offset = 1.0f / 16.0f;
      params.min_lod = n % 3 == 0 ? 1.0f : 0.0f;
      params.step_correction = n % 4 == 0;
      Cone c;
      c.origin = vec3(u(rng), u(rng), u(rng));
      c.direction = glm::normalize(vec3(d(rng), d(rng), d(rng)));
      c.aperture = 0.02f + 1.2f * u(rng);
      MarchParams built = params;
      if (n % 5 == 1) built.max_distance = 0.2f;  // runs out before the march ends
      const MarchSchedule schedule(n % 5 == 2 ? c.aperture * 0.5f : c.aperture, built, 1.0f / 16.0f);
      scheduled += schedule.fits(c.aperture, params, 1.0f / 16.0f);
      differ += !same_bits(trace_cone(fast, c, params, &schedule), trace_cone(mips, c, params));
    }
    EXPECT_EQ(differ, 0) << (aniso ? "anisotropic" : "isotropic");
    EXPECT_EQ(scheduled, 2400);  // all but the other-aperture fifth
  }
}

TEST(MipSampler, NonRgbaMipsAreNotPrepared) {
  VoxelMips mips;
  mips.iso.push_back(Volume(4, 4, 4, 1));
  EXPECT_FALSE(MipSampler(mips).usable());
}

}  // namespace
}  // namespace vct
