// A partial G-buffer (issue 21): an engine that dumps only depth, normals, its voxels and mips and
// its cone images gets its cone stages judged on its own mips (compare/partial_gbuffer.h). The
// engine here is the reference frame cut down to those stages; a marcher that read a wrong mip
// (level 2 x 1.5) while dumping the right ones fails at the cone stage.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "compare/isolated_stages.h"
#include "compare/partial_gbuffer.h"
#include "compare/stage_set_frame.h"
#include "core/error.h"
#include "scene/gltf_loader.h"
#include "stages/indirect_pass.h"
#include "freedoms/reference_frame.h"
#include "stages/stage_registry.h"

namespace vct::cmp {
namespace {

namespace st = stage_names;

struct Fixture {
  Scene scene;
  Settings s;
  FrameResult frame;
  StageSet ref;
};

const Fixture& fixture() {
  static const Fixture f = [] {
    Fixture x;
    x.scene = load_scene("");
    x.s.vct.width = x.s.vct.height = 48;
    x.s.vct.grid = 32;
    x.s.vct.shadow_map_size = 128;
    x.frame = render_ref_frame(x.scene, x.s);
    x.ref = stage_set_from_frame(x.frame, x.s.vct);
    return x;
  }();
  return f;
}

// Depth + normal, voxels + every iso mip, and the engine's two indirect images.
StageSet engine_set(const IndirectImages& cones) {
  const Fixture& f = fixture();
  StageSet e;
  e.backend = "engine";
  for (const char* stage : {st::kGbufferDepth, st::kGbufferNormal}) e.images[stage] = f.ref.images.at(stage);
  for (const auto& [name, vol] : f.ref.volumes)
    if (name == st::kVoxelRadiance || name.rfind("mip.iso.", 0) == 0) e.volumes[name] = vol;
  e.images["image.indirect_diffuse"] = cones.diffuse;
  e.images["image.indirect_specular"] = cones.specular;
  return e;
}

StageVerdict isolated(const StageSet& e, const std::string& stage) {
  const Fixture& f = fixture();
  const FrameResult test = frame_from_stage_set(e, f.scene, f.s.vct, &f.ref);
  Report rep = compare_stage_sets(f.ref, e);
  judge_cones_on_test_inputs(rep, f.scene, test, f.s.vct, e);
  for (const StageVerdict& v : rep.stages)
    if (v.stage == stage) {
      std::printf("[partial gbuffer] %s: %s, %s\n", stage.c_str(), to_string(v.verdict).c_str(), v.note.c_str());
      return v;
    }
  ADD_FAILURE() << "no verdict for " << stage;
  return {};
}

TEST(PartialGbuffer, PositionFromDepthMatchesTheReferencePositions) {
  const Fixture& f = fixture();
  const StageSet done =
      complete_partial_gbuffer(engine_set(IndirectImages{}), f.scene, &f.ref, cone_input_stages(f.scene, f.s.vct));
  const Image& rebuilt = done.images.at(st::kGbufferPosition);
  const Image& truth = f.ref.images.at(st::kGbufferPosition);
  const Image& coverage = done.images.at(st::kGbufferCoverage);
  EXPECT_EQ(coverage.data, f.ref.images.at(st::kGbufferCoverage).data);
  double worst = 0.0;
  size_t covered = 0;
  for (int y = 0; y < truth.height; ++y)
    for (int x = 0; x < truth.width; ++x) {
      if (coverage.at(x, y, 0) <= 0.5f) continue;
      ++covered;
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(rebuilt.at(x, y, c)) - double(truth.at(x, y, c))));
    }
  std::printf("[partial gbuffer] position from depth: max |d| %.3g over %zu pixels\n", worst, covered);
  ASSERT_GT(covered, 1000u);
  // The depth is float32 window z: near the far plane one ulp of it moves the point by far more
  // than one of the position itself, but far less than a voxel (the scene is ~1 unit, 32 voxels).
  EXPECT_LT(worst, 1e-3);
  EXPECT_TRUE(done.info.contains("partial_gbuffer"));
}

TEST(PartialGbuffer, DepthNormalMipsAndConeImagesPass) {
  const Fixture& f = fixture();
  const StageSet e = engine_set({f.frame.images.indirect_diffuse, f.frame.images.indirect_specular, {}});
  for (const char* stage : {"image.indirect_diffuse", "image.indirect_specular"}) {
    const StageVerdict v = isolated(e, stage);
    EXPECT_NE(v.verdict, Verdict::Fail) << stage << ": " << v.note;
  }
}

TEST(PartialGbuffer, MarcherOnAWrongMipFailsAtTheConeStage) {
  const Fixture& f = fixture();
  VoxelMips wrong = f.frame.mips;
  for (float& v : wrong.iso[2].data) v *= 1.5f;
  const IndirectImages cones = trace_indirect(f.scene, f.frame.gbuffer, wrong, f.s.vct);
  const StageVerdict v = isolated(engine_set(cones), "image.indirect_diffuse");
  EXPECT_EQ(v.verdict, Verdict::Fail) << v.note;
}

TEST(PartialGbuffer, WithoutAReferenceTheMissingMaterialIsNamed) {
  const Fixture& f = fixture();
  const StageSet e = engine_set({f.frame.images.indirect_diffuse, f.frame.images.indirect_specular, {}});
  EXPECT_THROW(frame_from_stage_set(e, f.scene, f.s.vct, nullptr), InputError);
}

}  // namespace
}  // namespace vct::cmp
