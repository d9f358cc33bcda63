// glTF alphaMode MASK on GL against the CPU reference: the hand-computed half-masked card
// (tests/ref/alpha_card_scene.h) shows only its right half in GL's shadow map, G-buffer and
// voxels; every stage of the foliage scene agrees with the reference as `vct validate` judges it;
// and a GL that ignores the mask in one pass fails that pass's stage first (gl/gl_faults.h:
// alpha_shadow, alpha_voxel).
#include <cstdio>

#include "../ref/alpha_card_scene.h"
#include "compare/isolated_stages.h"
#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "gl_test_util.h"
#include "freedoms/reference_frame.h"

namespace vct::gl::test {
namespace {

using vct::test::card_side;
using vct::test::CardSide;

const Scene& foliage() {
  static const Scene scene = load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/foliage.gltf");
  return scene;
}

// The report `vct validate` gives GL against the reference (cone stages on GL's own inputs).
cmp::Report judge(GlContext& ctx, const Scene& scene, const Settings& s, const FrameResult& ref,
                  const std::string& fault) {
  const FrameResult gl = render_gl_frame(ctx, scene, s, {"", fault});
  const cmp::StageSet gl_set = cmp::stage_set_from_frame(gl, s.vct);
  cmp::Report rep = cmp::compare_stage_sets(cmp::stage_set_from_frame(ref, s.vct), gl_set);
  cmp::judge_cones_on_test_inputs(rep, scene, gl, s.vct, gl_set);  // as validate does
  std::printf("  foliage, gl_fault '%s': failing stages: %s\n", fault.c_str(),
              failing_stages(rep).c_str());
  return rep;
}

// The size `vct validate` is asked to pass at (issue 13): 128^2, grid 64, the default 1024^2
// shadow map. Two known gaps at other sizes (docs/compare.md, "Alpha-mask ties"): at grid 32 a
// correct GL fails voxel.radiance on 8 of 1227 voxels (0.65 % against the 0.5 % shading-tie
// share: 3 whole PCF-tap differences under the leaves' shadows, 5 textured leaf voxels one
// fixed-point quantum past 2^-7 |r|, issue 13 case 1's voxel minification); with a 512^2 shadow
// map it fails shadow_map.0 on one alpha-tie texel that no depth edge flags and whose flipped
// value (the front card's depth) its 3x3 neighbourhood does not hold.
Settings foliage_settings() {
  Settings s = small_settings(64, 128);
  s.vct.shadow_map_size = 1024;
  return s;
}

const FrameResult& foliage_reference() {
  static const FrameResult ref = render_ref_frame(foliage(), foliage_settings());
  return ref;
}

TEST(GlAlphaMask, HalfMaskedCardShowsOnlyItsRightHalf) {
  VCT_REQUIRE_GL();
  Scene scene = vct::test::half_masked_card(true);
  Light l;
  l.position = vec3(0.3f, 0.2f, 3.0f);
  l.direction = vec3(0.0f, 0.0f, -1.0f);
  l.outer_cone_angle = 0.6f;
  scene.lights.push_back(l);
  Settings s = small_settings(16, 48);
  s.vct.shadow_map_size = 64;
  const FrameResult gl = render_gl_frame(*ctx, scene, s);
  // G-buffer: position z is the card (0) through the right half, the backdrop (-1) elsewhere.
  const mat4 inv = glm::inverse(scene.camera.projection(1.0f) * scene.camera.view());
  int kept = 0, cut = 0;
  for (int row = 0; row < 48; ++row)
    for (int x = 0; x < 48; ++x) {
      const float nx = (float(x) + 0.5f) / 24.0f - 1.0f,
                  ny = (float(47 - row) + 0.5f) / 24.0f - 1.0f;
      const vec4 a = inv * vec4(nx, ny, -1.0f, 1.0f), b = inv * vec4(nx, ny, 1.0f, 1.0f);
      const vec3 pa = vec3(a) / a.w, pb = vec3(b) / b.w;
      const vec3 q = pa + (pb - pa) * (pa.z / (pa.z - pb.z));
      const CardSide side = card_side(q.x, q.y, 0.02f);
      if (side == CardSide::Undecided) continue;
      EXPECT_NEAR(gl.gbuffer.position.at(x, row, 2), side == CardSide::Kept ? 0.0f : -1.0f, 1e-4f)
          << x << "," << row;
      (side == CardSide::Kept ? kept : cut) += 1;
    }
  EXPECT_GT(kept, 150);
  EXPECT_GT(cut, 300);
  // Shadow map and voxels: the same as the reference's (which tests/ref/alpha_mask_test.cpp checks
  // against the hand-computed halves), stage by stage.
  const FrameResult ref = render_ref_frame(scene, s);
  const cmp::Report rep = cmp::compare_stage_sets(cmp::stage_set_from_frame(ref, s.vct),
                                                  cmp::stage_set_from_frame(gl, s.vct));
  EXPECT_EQ(rep.first_failing(), "") << failing_stages(rep);
}

TEST(GlAlphaMask, FoliageAgreesWithTheReferenceStageByStage) {
  VCT_REQUIRE_GL();
  const cmp::Report rep = judge(*ctx, foliage(), foliage_settings(), foliage_reference(), "");
  EXPECT_EQ(rep.first_failing(), "") << failing_stages(rep);
}

TEST(GlAlphaMask, IgnoringTheMaskInTheShadowPassFailsTheShadowMap) {
  VCT_REQUIRE_GL();
  const cmp::Report rep =
      judge(*ctx, foliage(), foliage_settings(), foliage_reference(), "alpha_shadow");
  EXPECT_EQ(rep.first_failing(), "shadow_map.0") << failing_stages(rep);
}

TEST(GlAlphaMask, IgnoringTheMaskInTheVoxelizationFailsOccupancy) {
  VCT_REQUIRE_GL();
  const cmp::Report rep =
      judge(*ctx, foliage(), foliage_settings(), foliage_reference(), "alpha_voxel");
  EXPECT_EQ(rep.first_failing(), "voxel.occupancy") << failing_stages(rep);
}

}  // namespace
}  // namespace vct::gl::test
