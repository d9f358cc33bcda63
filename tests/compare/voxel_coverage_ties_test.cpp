// voxel.radiance where GL's voxel raster averaged another set of fragments than the reference
// (freedoms/coverage_ties.h, docs/compare.md "Voxel shading slack"): the built-in scene at grid 32
// with llvmpipe's 4 samples has voxel (14, 18, 11) made of a dark fragment of the box's side, at
// depth 14.99984 (within its snap margin of voxel 15), and a lit one of the box's top. llvmpipe
// wrote the dark one to voxel 15 and stored the top's light alone there: twice the reference's
// mean, at one fragment instead of two. That set is admissible; a value no set gives is not.
#include <gtest/gtest.h>

#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "find_verdict.h"
#include "freedoms/coverage_ties.h"
#include "freedoms/reference_frame.h"
#include "freedoms/voxel_freedoms.h"
#include "scene/gltf_loader.h"
#include "stages/inject.h"
#include "stages/raster.h"
#include "stages/voxelize.h"

namespace vct::cmp {
namespace {

using test::find;

const ivec3 kVoxel(14, 18, 11);

struct Case {
  Scene scene = load_scene("");
  Settings s;
  FrameResult ref;
  vec3 lit{0.0f};  // the light of the voxel's lit fragment alone
  Case() {
    s.vct.width = s.vct.height = 32;
    s.vct.grid = 32;
    s.vct.msaa_samples = 4;
    s.vct.voxelizer = Voxelizer::GpuEmulation;  // as `vct validate` runs the reference for the sample rule
    ref = render_ref_frame(scene, s);
    Voxelization vox = voxelize_gpu_rule(scene, s.vct.grid, 4);
    add_coverage_ties(scene, vox);
    const std::vector<vec3> values = fragment_radiance(scene, vox, ref.shadow_maps, s.vct);
    int count = 0, dropped = 0;
    for (size_t k = 0; k < vox.fragments.size(); ++k) {
      if (vox.fragments[k].voxel != kVoxel) continue;
      ++count;
      dropped += vox.may_drop[k];
      if (values[k].x > lit.x) lit = values[k];
    }
    EXPECT_EQ(count, 2);    // the scene still makes the measured case
    EXPECT_EQ(dropped, 1);  // its dark fragment may move to voxel 15
  }
  // GL's voxels: the reference's, with the voxel holding `value` from `fragments` fragments.
  StageVerdict judged(vec3 value, float fragments) const {
    FrameResult gl = ref;
    gl.voxels.radiance.set_rgba(kVoxel.x, kVoxel.y, kVoxel.z, vec4(value, 1.0f));
    *gl.voxels.fragments.voxel(kVoxel.x, kVoxel.y, kVoxel.z) = fragments;
    JudgeContext ctx;
    ctx.shading_tie_fraction = 0.0;  // as on the test's own shadow maps: no share of shading ties
    return find(compare_stage_sets(stage_set_from_frame(ref, s.vct), stage_set_from_frame(gl, s.vct), {}, ctx),
                "voxel.radiance");
  }
};

TEST(VoxelCoverageTies, TheLitFragmentAloneIsAnAdmissibleVoxel) {
  const Case c;
  const StageVerdict v = c.judged(c.lit, 1.0f);
  EXPECT_EQ(v.out_of_bound, 0u) << v.note;
  EXPECT_NE(v.verdict, Verdict::Fail) << v.note;
}

// Without the ties the same voxel is beyond its bound: the reference's slack alone (snap, LOD)
// does not reach a mean twice its own.
TEST(VoxelCoverageTies, WithoutTheTiesTheSameVoxelFails) {
  Case c;
  const Voxelization plain = voxelize_gpu_rule(c.scene, c.s.vct.grid, 4);  // no add_coverage_ties
  std::vector<vec3> light;
  VoxelGrid without = inject_and_reduce(c.scene, plain, c.ref.shadow_maps, c.s.vct, nullptr, &light);
  add_voxel_freedoms(c.scene, plain, light, c.ref.shadow_maps, c.s.vct, nullptr, without);
  c.ref.voxels.shading_slack = without.shading_slack;
  const StageVerdict v = c.judged(c.lit, 1.0f);
  EXPECT_EQ(v.out_of_bound, 1u) << v.note;
}

// A count that differs does not make any value a tie: 1.5 times the lit fragment is no set's mean.
TEST(VoxelCoverageTies, AValueNoSetGivesFailsWhateverTheCount) {
  const Case c;
  const StageVerdict v = c.judged(c.lit * 1.5f, 1.0f);
  EXPECT_EQ(v.out_of_bound, 1u) << v.note;
  EXPECT_EQ(v.verdict, Verdict::Fail) << v.note;
}

}  // namespace
}  // namespace vct::cmp
