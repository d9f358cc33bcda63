// Fire particles: the shared stateless particle function drives both backends; GL rasterizes
// eye-facing discs additively (depth-tested, no depth writes) where the CPU intersects pixel-centre
// rays with the same discs, and both add the particles' light into the voxels.
#include "gl_test_util.h"
#include "freedoms/reference_frame.h"

namespace vct::gl::test {

TEST(GlParticles, LayerAndVoxelsMatchTheCpu) {
  VCT_REQUIRE_GL();
  const Scene scene = load_gltf_file(std::string(VCT_SOURCE_DIR) + "/scenes/demo_room.gltf");
  ASSERT_FALSE(scene.emitters.empty());
  const Settings s = small_settings();
  const FrameResult g = render_gl_frame(*ctx, scene, s);
  const FrameResult r = render_ref_frame(scene, s);
  double sum_g = 0.0, sum_r = 0.0, diff = 0.0;
  for (size_t k = 0; k < g.images.particles.data.size(); ++k) {
    sum_g += double(g.images.particles.data[k]);
    sum_r += double(r.images.particles.data[k]);
    diff += std::abs(double(g.images.particles.data[k]) - double(r.images.particles.data[k]));
  }
  std::printf("[gl vs ref] particle layer: sum gl %.6g ref %.6g, relative L1 diff %.3g\n", sum_g, sum_r, diff / sum_r);
  EXPECT_GT(sum_r, 1.0);
  // Disc edges: GL interpolates the disc coordinate over the quad, the CPU intersects rays; the
  // profile is continuous, so the difference is rounding-sized.
  EXPECT_LE(diff / sum_r, 1e-3);
  // The final image includes the layer (added after the opaque composite).
  double final_g = 0.0, final_r = 0.0;
  for (size_t k = 0; k < g.images.final_image.data.size(); ++k) {
    final_g += double(g.images.final_image.data[k]);
    final_r += double(r.images.final_image.data[k]);
  }
  std::printf("[gl vs ref] final with particles: sum gl %.6g ref %.6g\n", final_g, final_r);
  EXPECT_NEAR(final_g, final_r, 0.02 * final_r);
  // Voxels: particle light is added (fixed point on GL, float on the CPU) into the base level.
  double vox_g = 0.0, vox_r = 0.0;
  for (size_t k = 0; k < g.voxels.radiance.voxel_count(); ++k)
    for (size_t c = 0; c < 3; ++c) {
      vox_g += double(g.voxels.radiance.data[k * 4 + c]);
      vox_r += double(r.voxels.radiance.data[k * 4 + c]);
    }
  std::printf("[gl vs ref] voxel radiance total with particles: gl %.6g ref %.6g\n", vox_g, vox_r);
  EXPECT_NEAR(vox_g, vox_r, 0.01 * vox_r);
}
}  // namespace vct::gl::test
