// Textured materials and normal mapping in the G-buffer: GL's samplers (SRGB8_ALPHA8 decoded
// before filtering, the glTF min/mag filters and wrap modes, implicit LOD over the mip chain the
// CPU built) against ref/scene/texture_sample.h, on the demo room (brick base colour and normal
// maps) and on issue 13's tiled floor (a strongly minified checker and bump map), judged as
// `vct validate` judges them (docs/compare.md, "Texture LOD").
#include <cstdio>

#include "compare/isolated_stages.h"
#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "gl_test_util.h"
#include "stages/gbuffer.h"
#include "stages/pipeline.h"

namespace vct::gl::test {
namespace {

const Scene& tiled_floor() {
  static const Scene scene = load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/tiled_floor.gltf");
  return scene;
}

const cmp::StageVerdict& verdict(const cmp::Report& r, const std::string& stage) {
  for (const auto& v : r.stages)
    if (v.stage == stage) return v;
  throw std::runtime_error("no stage " + stage);
}

// The report `vct validate` gives the GL frame (cone stages on its own inputs), with `fault`.
cmp::Report judge_tiled_floor(GlContext& ctx, const Settings& s, const FrameResult& ref, const std::string& fault) {
  const FrameResult gl = render_gl_frame(ctx, tiled_floor(), s, {"", fault});
  const cmp::StageSet gl_set = cmp::stage_set_from_frame(gl, s.vct);
  cmp::Report rep = cmp::compare_stage_sets(cmp::stage_set_from_frame(ref, s.vct), gl_set);
  const FrameResult ref_on_gl = cmp::reference_on_test_inputs(tiled_floor(), gl, s.vct);
  cmp::apply_isolated_verdicts(rep, cmp::compare_stage_sets(cmp::stage_set_from_frame(ref_on_gl, s.vct), gl_set),
                               s.vct.soft_shadows);
  for (const char* st : {"gbuffer.normal", "gbuffer.albedo", "voxel.radiance"}) {
    const cmp::StageVerdict& v = verdict(rep, st);
    std::printf("  tiled floor%s%s: %s %s, %zu of %zu beyond the bound, worst %.3g (bound %.3g)\n",
                fault.empty() ? "" : " with ", fault.c_str(), st, to_string(v.verdict).c_str(), v.out_of_bound,
                v.checked, v.worst.empty() ? 0.0 : double(v.worst[0].error),
                v.worst.empty() ? 0.0 : double(v.worst[0].bound));
  }
  return rep;
}

}  // namespace

// The minified checker and bump map: GL's LOD (quad derivatives, its own rho) and the CPU's
// (exact derivatives) may pick different lambdas within the admissible range; the G-buffer's and
// the voxels' texture slack cover exactly that, so no stage fails. With the lookups forced to
// level 0 (the texture_level_zero fault) the G-buffer fails at once.
TEST(GlTextures, MinifiedTiledFloorAgreesWithinTheLodBoundAndLevelZeroFails) {
  VCT_REQUIRE_GL();
  const Settings s = small_settings(32, 64);
  const FrameResult ref = render_ref_frame(tiled_floor(), s);
  const cmp::Report ok = judge_tiled_floor(*ctx, s, ref, "");
  EXPECT_EQ(ok.first_failing(), "");
  for (const char* st : {"gbuffer.normal", "gbuffer.albedo", "voxel.radiance"})
    EXPECT_NE(verdict(ok, st).verdict, cmp::Verdict::Missing) << st;
  const cmp::Report bad = judge_tiled_floor(*ctx, s, ref, "texture_level_zero");
  EXPECT_EQ(bad.first_failing(), "gbuffer.normal");
  EXPECT_EQ(verdict(bad, "gbuffer.albedo").verdict, cmp::Verdict::Fail);
}

TEST(GlTextures, TexturedGBufferMatchesTheCpu) {
  VCT_REQUIRE_GL();
  const Scene scene = load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/demo_room.gltf");
  ASSERT_FALSE(scene.textures.empty());
  const Settings s = small_settings(32, 96);
  const FrameResult g = render_gl_frame(*ctx, scene, s);
  const GBuffer r = render_gbuffer(scene, s.vct);
  size_t both = 0, coverage_mismatch = 0;
  double albedo_sum = 0.0, albedo_max = 0.0, normal_sum = 0.0, albedo_ref = 0.0;
  size_t albedo_over = 0;
  for (int y = 0; y < r.coverage.height; ++y)
    for (int x = 0; x < r.coverage.width; ++x) {
      const bool cg = g.gbuffer.coverage.at(x, y, 0) > 0.0f, cr = r.coverage.at(x, y, 0) > 0.0f;
      coverage_mismatch += cg != cr;
      if (!cg || !cr) continue;
      ++both;
      for (int c = 0; c < 3; ++c) {
        const double d = std::abs(double(g.gbuffer.albedo.at(x, y, c)) - double(r.albedo.at(x, y, c)));
        albedo_sum += d;
        albedo_ref += double(r.albedo.at(x, y, c));
        albedo_max = std::max(albedo_max, d);
        albedo_over += d > 4.0 / 255.0;
        normal_sum += std::abs(double(g.gbuffer.normal.at(x, y, c)) - double(r.normal.at(x, y, c)));
      }
    }
  std::printf("[gl vs ref] textured gbuffer: %zu pixels, coverage mismatches %zu, albedo mean %.3g max %.3g "
              "(> 4/255: %zu), normal mean %.3g\n",
              both, coverage_mismatch, albedo_sum / double(3 * both), albedo_max, albedo_over,
              normal_sum / double(3 * both));
  EXPECT_LE(coverage_mismatch, both / 200);  // silhouette ties of the statue only
  // Bilinear weights: llvmpipe filters sRGB-decoded texels with 8-bit fractional weights, the CPU
  // in float, so a texel step of contrast c differs by up to c/256; texture coordinates also differ
  // by interpolation rounding. Bound the mean tightly and the worst case loosely.
  EXPECT_LE(albedo_sum / albedo_ref, 5e-3);
  EXPECT_LE(albedo_over, both / 50);
  EXPECT_LE(normal_sum / double(3 * both), 5e-3);
}

}  // namespace vct::gl::test
