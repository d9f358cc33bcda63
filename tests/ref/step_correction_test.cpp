// Opacity step correction (settings.opacity_step_correction, sh::step_corrected_sample) against
// closed forms: a uniform medium's transmittance no longer depends on the step, and a one-voxel
// slab sampled at quarter-voxel offsets gives the product of its hand-computed corrected samples.
#include <gtest/gtest.h>

#include <cmath>

#include "shared/vct_shared.h"
#include "stages/cone_trace.h"

namespace vct {
namespace {

constexpr int kN = 16;

// Every level holds the same value: the box filter of a constant is that constant.
VoxelMips constant_mips(vec4 value) {
  VoxelMips m;
  for (int size = kN; size >= 1; size /= 2) m.iso.push_back(Volume(size, size, size, 4));
  for (Volume& v : m.iso)
    for (int z = 0; z < v.nz; ++z)
      for (int y = 0; y < v.ny; ++y)
        for (int x = 0; x < v.nx; ++x) v.set_rgba(x, y, z, value);
  return m;
}

// A narrow cone along +x through the middle of the grid: diameter = one voxel, lod 0, so each
// step is quality voxels and dt / dt0 = quality.
float transmittance(const VoxelMips& m, float quality, bool corrected, float from, float length) {
  const Cone cone{vec3(0.0f, 8.5f / kN, 8.5f / kN), vec3(1.0f, 0.0f, 0.0f), 1e-4f};
  MarchParams p;
  p.start_offset = from / kN;
  p.max_distance = (from + length) / kN;
  p.quality = quality;
  p.step_correction = corrected;
  return 1.0f - trace_cone(m, cone, p).a;
}

TEST(StepCorrection, UniformMediumTransmittanceIsStepIndependent) {
  const float a = 0.2f;
  const VoxelMips m = constant_mips(vec4(0.3f * a, 0.0f, 0.0f, a));
  // 8 voxels of a medium of per-voxel opacity a: T = (1 - a)^8 whatever the step, once corrected.
  // Uncorrected, the march takes 8 / q samples of full opacity a: T = (1 - a)^(8 / q).
  for (float q : {1.0f, 0.5f, 0.25f}) {
    EXPECT_NEAR(transmittance(m, q, true, 4.0f, 8.0f), std::pow(1.0f - a, 8.0f), 1e-5f) << "q " << q;
    EXPECT_NEAR(transmittance(m, q, false, 4.0f, 8.0f), std::pow(1.0f - a, 8.0f / q), 1e-5f) << "q " << q;
  }
}

TEST(StepCorrection, OneVoxelSlabGivesTheClosedForm) {
  // Voxel x = 8 has opacity a, its neighbours 0. Half-voxel steps from x = 7.25 sample the tent of
  // trilinear filtering at 7.75, 8.25, 8.75, 9.25 (voxel units; texel centre 8.5): opacities
  // a/4, 3a/4, 3a/4, a/4 (and 0 at 7.25 and 9.75). Corrected with dt/dt0 = 1/2:
  // T = [(1 - a/4)(1 - 3a/4)]^(2 * 1/2).
  const float a = 0.6f;
  VoxelMips m = constant_mips(vec4(0.0f));
  for (int z = 0; z < kN; ++z)
    for (int y = 0; y < kN; ++y) m.iso[0].set_rgba(8, y, z, vec4(a));
  const float t_corr = transmittance(m, 0.5f, true, 7.25f, 3.0f);
  const float t_plain = transmittance(m, 0.5f, false, 7.25f, 3.0f);
  const float q1 = 1.0f - a / 4.0f, q3 = 1.0f - 3.0f * a / 4.0f;
  EXPECT_NEAR(t_corr, q1 * q3, 1e-5f);
  EXPECT_NEAR(t_plain, q1 * q1 * q3 * q3, 1e-5f);
}

TEST(StepCorrection, SharedDefinitionByHand) {
  // ratio 1 leaves a sample alone; an opaque sample stays opaque; a -> 0 scales rgb by the ratio.
  const vec4 s(0.2f, 0.1f, 0.05f, 0.5f);
  EXPECT_EQ(sh::step_corrected_sample(s, 1.0f), s);
  EXPECT_FLOAT_EQ(sh::step_corrected_opacity(1.0f, 0.25f), 1.0f);
  EXPECT_NEAR(sh::step_corrected_opacity(0.5f, 0.5f), 1.0f - std::sqrt(0.5f), 1e-7f);
  const vec4 c = sh::step_corrected_sample(s, 0.5f);
  EXPECT_NEAR(c.x / c.w, s.x / s.w, 1e-6f);  // colour over opacity unchanged
  EXPECT_EQ(sh::step_corrected_sample(vec4(0.4f, 0.0f, 0.0f, 0.0f), 0.5f), vec4(0.2f, 0.0f, 0.0f, 0.0f));
}

}  // namespace
}  // namespace vct
