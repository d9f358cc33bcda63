// A GPU that ignores the glTF min filter (every lookup at level 0, no mipmapping) must still be
// caught although textured stages now carry the admissible-LOD slack (docs/compare.md, "Texture
// LOD"): simulated by rendering the reference from the same scene with every texture's min filter
// set to LINEAR, and judged against the correct reference, on issue 13's tiled floor. The GL
// build's own version of this bug is the `texture_level_zero` fault
// (tests/gl/gl_textures_test.cpp).
#include <gtest/gtest.h>

#include <cstdio>

#include "compare/stage_compare.h"
#include "find_verdict.h"
#include "scene/gltf_loader.h"
#include "freedoms/reference_frame.h"

namespace vct::cmp {
namespace {

TEST(TextureLodFault, LevelZeroLookupsFailTheGBufferAndTheVoxels) {
  const Scene scene = load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/tiled_floor.gltf");
  Settings s;
  s.vct.width = s.vct.height = 64;
  s.vct.grid = 32;
  s.vct.shadow_map_size = 256;
  s.vct.voxelizer = Voxelizer::GpuEmulation;
  s.vct.reduction = Reduction::FixedPoint;
  const FrameResult ref = render_ref_frame(scene, s);
  Scene level_zero = scene;
  for (Texture& t : level_zero.textures) t.min_filter = MinFilter::Linear;
  FrameResult bad = render_ref_frame(level_zero, s);
  bad.backend = "gl";
  const StageSet rs = stage_set_from_frame(ref, s.vct);
  // The correct frame against itself passes; the level-0 frame fails where the textures are read.
  EXPECT_EQ(compare_stage_sets(rs, rs).overall(), Verdict::Pass);
  const Report r = compare_stage_sets(rs, stage_set_from_frame(bad, s.vct));
  for (const char* st : {"gbuffer.normal", "gbuffer.albedo", "voxel.radiance"}) {
    const StageVerdict& v = test::find(r, st);
    std::printf("  level-0 lookups: %s %s, %zu of %zu beyond the bound\n", st,
                to_string(v.verdict).c_str(), v.out_of_bound, v.checked);
    EXPECT_EQ(v.verdict, Verdict::Fail) << st << ": " << v.note;
  }
  EXPECT_EQ(r.first_failing(), "gbuffer.normal");
}

}  // namespace
}  // namespace vct::cmp
