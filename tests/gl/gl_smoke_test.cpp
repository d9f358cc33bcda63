// Smoke: the whole GL frame runs on the Cornell box and every stage is read back.
#include "gl_test_util.h"
#include "io/image_io.h"

namespace vct::gl::test {

TEST(GlFrame, RendersEveryStage) {
  VCT_REQUIRE_GL();
  const FrameResult r = render_gl_frame(*ctx, cornell_box(), small_settings());
  EXPECT_EQ(r.backend, "gl");
  EXPECT_EQ(r.facts.renderer, ctx->renderer());
  EXPECT_FALSE(r.facts.version.empty());
  EXPECT_FALSE(r.facts.device.empty());
  EXPECT_EQ(r.facts.msaa_samples, 4);  // small_settings asks 4; every GL 4.5 driver offers 4
  EXPECT_EQ(r.facts.sample_positions.size(), 4u);
  EXPECT_EQ(r.facts.reduction, "");  // fixed point ran as asked
  for (const char* stage : {"shadow_maps", "depth_prepass", "gbuffer", "voxelize", "resolve", "mips", "direct",
                            "indirect_cones", "total"}) {
    ASSERT_TRUE(r.timings_ms.count(stage)) << stage;
    EXPECT_GT(r.timings_ms.at(stage), 0.0) << stage;
  }
  ASSERT_FALSE(r.shadow_maps.empty());
  EXPECT_EQ(r.gbuffer.position.width, 64);
  EXPECT_EQ(r.voxels.radiance.nx, 32);
  ASSERT_EQ(r.mips.iso.size(), 6u);
  for (size_t l = 0; l < 6; ++l) EXPECT_EQ(r.mips.iso[l].nx, 32 >> l);
  EXPECT_EQ(r.mips.iso[5].rgba(0, 0, 0).a > 0.0f, true);  // the closed box reaches the top level
  double energy = 0.0;
  for (float v : r.images.final_image.data) energy += double(v);
  EXPECT_GT(energy, 10.0);
  EXPECT_EQ(r.multibounce_energy.size(), 1u);
  if (const char* dir = std::getenv("VCT_GL_SMOKE_DIR")) {
    write_png(std::string(dir) + "/final.png", r.images.final_image);
    write_png(std::string(dir) + "/direct.png", r.images.direct);
    write_png(std::string(dir) + "/diffuse.png", r.images.indirect_diffuse);
    write_png_linear(std::string(dir) + "/shadow.png", r.shadow_maps[0].depth, 0.9f, 1.0f);
  }
}

}  // namespace vct::gl::test
