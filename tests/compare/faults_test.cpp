// "It must catch real bugs": deliberate GPU bugs, one at a time, simulated by perturbing a CPU
// reference frame the way each bug would perturb a GL frame (the GL build has no fault switch
// yet), then recomputing the stages downstream of the fault where the bug would propagate
// (voxel faults rebuild the mips). compare must fail, and name the right first failing stage.
#include <gtest/gtest.h>

#include <functional>

#include "compare/stage_compare.h"
#include "core/parallel.h"
#include "scene/gltf_loader.h"
#include "stages/mips.h"
#include "freedoms/reference_frame.h"

namespace vct::cmp {
namespace {

struct Fixture {
  Settings s;
  FrameResult frame;
  StageSet ref;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture x;
    x.s.vct.width = x.s.vct.height = 64;
    x.s.vct.grid = 32;
    x.s.vct.shadow_map_size = 256;
    x.s.vct.voxelizer = Voxelizer::GpuEmulation;
    x.s.vct.reduction = Reduction::FixedPoint;
    x.s.vct.anisotropic = true;
    const Scene scene = load_scene("");
    x.frame = render_ref_frame(scene, x.s);
    x.ref = stage_set_from_frame(x.frame, x.s.vct);
    return x;
  }();
  return f;
}

// Applies `fault` to a copy of the reference frame; voxel faults rebuild the mips from the
// faulty base, as a GPU would.
Report run_fault(const std::function<void(FrameResult&)>& fault, bool rebuild_mips) {
  const Fixture& f = fixture();
  FrameResult bad = f.frame;
  bad.backend = "gl";
  fault(bad);
  if (rebuild_mips) bad.mips = build_mips(bad.voxels.radiance, f.s.vct.anisotropic);
  return compare_stage_sets(f.ref, stage_set_from_frame(bad, f.s.vct));
}

TEST(Faults, UnperturbedFramePasses) {
  const Fixture& f = fixture();
  const Report r = compare_stage_sets(f.ref, f.ref);
  EXPECT_EQ(r.overall(), Verdict::Pass);
}

TEST(Faults, HalfTexelOffsetInVoxelCoordinatesFailsOccupancy) {
  // Rounding voxel coordinates half a texel off moves surfaces into the next voxel along x.
  const Report r = run_fault([](FrameResult& b) {
    Volume& v = b.voxels.radiance;
    Volume shifted(v.nx, v.ny, v.nz, v.channels);
    for (int z = 0; z < v.nz; ++z)
      for (int y = 0; y < v.ny; ++y)
        for (int x = 0; x + 1 < v.nx; ++x) shifted.set_rgba(x + 1, y, z, v.rgba(x, y, z));
    v = shifted;
  }, true);
  EXPECT_EQ(r.first_failing(), "voxel.occupancy");
}

TEST(Faults, WrongDominantAxisFailsOccupancy) {
  // Projecting floor/ceiling triangles (normal ~y) along x rasterises them edge-on: their voxels
  // vanish. Simulated: the lowest and highest occupied layers in y lose their voxels.
  const Report r = run_fault([](FrameResult& b) {
    Volume& v = b.voxels.radiance;
    int lo = v.ny, hi = -1;
    for (int z = 0; z < v.nz; ++z)
      for (int y = 0; y < v.ny; ++y)
        for (int x = 0; x < v.nx; ++x)
          if (v.rgba(x, y, z).a > 0) lo = std::min(lo, y), hi = std::max(hi, y);
    for (int z = 0; z < v.nz; ++z)
      for (int x = 0; x < v.nx; ++x) v.set_rgba(x, lo, z, vec4(0)), v.set_rgba(x, hi, z, vec4(0));
  }, true);
  EXPECT_EQ(r.first_failing(), "voxel.occupancy");
}

TEST(Faults, RacyAverageFailsVoxelRadiance) {
  // A load/average/store race keeps one fragment's value: voxels with several fragments end up
  // with a value off the true mean (here: 20% too bright), occupancy unchanged.
  const Report r = run_fault([](FrameResult& b) {
    Volume& v = b.voxels.radiance;
    for (size_t i = 0; i < v.voxel_count(); ++i)
      if (b.voxels.fragments.data[i] >= 2)
        for (int c = 0; c < 3; ++c) v.data[i * 4 + size_t(c)] *= 1.2f;
  }, true);
  EXPECT_EQ(r.first_failing(), "voxel.radiance");
}

TEST(Faults, WrongMipLevelFailsThatLevel) {
  // Level 2 built by point-sampling level 0 (a wrong source level) instead of averaging level 1.
  const Report r = run_fault([](FrameResult& b) {
    Volume& l2 = b.mips.iso[2];
    const Volume& l0 = b.mips.iso[0];
    for (int z = 0; z < l2.nz; ++z)
      for (int y = 0; y < l2.ny; ++y)
        for (int x = 0; x < l2.nx; ++x) l2.set_rgba(x, y, z, l0.rgba(4 * x + 1, 4 * y + 1, 4 * z + 1));
  }, false);
  EXPECT_EQ(r.first_failing(), "mip.iso.2");
}

TEST(Faults, AlphaNotClampedFailsAnisotropicMip) {
  // Compositing opacities by addition without the clamp: a = a_front + a_back can exceed 1.
  const Report r = run_fault([](FrameResult& b) {
    Volume& l1 = b.mips.aniso[kPosX][0];
    for (size_t i = 0; i < l1.voxel_count(); ++i)
      if (l1.data[i * 4 + 3] >= 1.0f) l1.data[i * 4 + 3] = 1.5f;
  }, false);
  EXPECT_EQ(r.first_failing(), "mip.posx.1");
}

TEST(Faults, OffByOneConeStepFailsIndirectDiffuse) {
  // Starting the march one step late skips the nearest samples: indirect light drops (by 10%
  // here) and everything composed from it follows.
  const Report r = run_fault([](FrameResult& b) {
    for (Image* img : {&b.images.indirect_diffuse, &b.images.diffuse_term})
      for (float& v : img->data) v *= 0.9f;
    for (size_t i = 0; i < b.images.final_image.data.size(); ++i)
      b.images.final_image.data[i] -= 0.1f * b.images.diffuse_term.data[i] / 0.9f;
  }, false);
  EXPECT_EQ(r.first_failing(), "image.indirect_diffuse");
}

TEST(Faults, SameFrameOnOneAndTwoThreadsPasses) {
  const Fixture& f = fixture();
  set_thread_count(1);
  const FrameResult one = render_ref_frame(load_scene(""), f.s);
  set_thread_count(0);
  EXPECT_EQ(compare_stage_sets(f.ref, stage_set_from_frame(one, f.s.vct)).overall(), Verdict::Pass);
}

}  // namespace
}  // namespace vct::cmp
