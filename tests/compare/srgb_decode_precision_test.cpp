// The sRGB decode's precision carried into voxel.radiance (core/precision.h, srgb-decode;
// docs/compare.md, "Precision table"). scenes/regressions/seed-9-small: one triangle lit only by an
// emissive 2x3 sRGB texture of 0 and 26, NEAREST, no light; llvmpipe decoded 26 1.8 % low (about a
// quarter step) and failed voxel.radiance before. A test backend whose decode lies within half a
// step of the encoding is emulated by scaling the emissive factor by decode(26 + s) / decode(26)
// (texel 0 stays black): within half a step it passes, without the slack's sRGB term it fails, and
// a whole step either way fails (the reverse: a decode off by one 8-bit step must FAIL).
#include <gtest/gtest.h>

#include "compare/judge.h"
#include "find_verdict.h"
#include "freedoms/reference_frame.h"
#include "io/srgb.h"
#include "scene/gltf_loader.h"
#include "stages/stage_registry.h"

namespace vct::cmp {
namespace {

const Scene& seed9() {
  static const Scene scene = load_scene(std::string(VCT_SOURCE_DIR) + "/scenes/regressions/seed-9-small/scene.gltf");
  return scene;
}

Settings seed9_settings() {  // the case's settings.json
  Settings s;
  s.vct.width = 8;
  s.vct.height = 14;
  s.vct.grid = 16;
  s.vct.shadow_map_size = 64;
  s.threads = 2;
  return s;
}

// The frame of a backend decoding the texel 26 `steps` steps of the encoding off.
FrameResult decoded_off(float steps) {
  Scene scene = seed9();
  const float ratio = srgb_to_linear((26.0f + steps) / 255.0f) / srgb_to_linear(26.0f / 255.0f);
  for (Material& m : scene.materials) m.emissive_factor *= ratio;
  FrameResult f = render_ref_frame(scene, seed9_settings());
  f.backend = "decode";
  return f;
}

Verdict radiance(const FrameResult& ref, const FrameResult& test, bool without_srgb_term = false) {
  const Settings s = seed9_settings();
  StageSet rs = stage_set_from_frame(ref, s.vct);
  if (without_srgb_term) {
    // The scene's only freedom is the decode (flat NEAREST texels, no light): its slack is that term.
    Volume& slack = rs.volumes.at(stage_names::kVoxelShadingSlack);
    std::fill(slack.data.begin(), slack.data.end(), 0.0f);
  }
  const Report rep = judge(rs, stage_set_from_frame(test, s.vct), {&seed9(), &test, &s.vct});
  const StageVerdict& v = test::find(rep, stage_names::kVoxelRadiance);
  std::printf("  %s: %s\n", to_string(v.verdict).c_str(), v.note.c_str());
  return v.verdict;
}

TEST(SrgbDecodePrecision, WithinHalfAStepPassesAndFailsWithoutTheTerm) {
  const FrameResult ref = render_ref_frame(seed9(), seed9_settings());
  for (float steps : {-0.45f, -0.27f, 0.45f}) {  // -0.27: llvmpipe's -1.8 % at 26
    const FrameResult test = decoded_off(steps);
    EXPECT_NE(radiance(ref, test), Verdict::Fail) << steps;
    EXPECT_EQ(radiance(ref, test, true), Verdict::Fail) << steps << " without the sRGB term";
  }
}

TEST(SrgbDecodePrecision, AWholeStepOffFails) {
  const FrameResult ref = render_ref_frame(seed9(), seed9_settings());
  for (float steps : {-1.0f, 1.0f}) EXPECT_EQ(radiance(ref, decoded_off(steps)), Verdict::Fail) << steps;
}

}  // namespace
}  // namespace vct::cmp
