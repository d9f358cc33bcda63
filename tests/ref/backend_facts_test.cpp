// Typed backend facts (stages/backend_facts.h) survive JSON (run.json, stage-set manifests), and
// the CPU reference records the sample positions its GPU-rule voxelizer used.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "scene/gltf_loader.h"
#include "stages/backend_facts.h"
#include "freedoms/reference_frame.h"
#include "stages/raster.h"

namespace vct {
namespace {

TEST(BackendFacts, JsonRoundTrip) {
  BackendFacts f;
  f.msaa_samples = 8;
  f.msaa_samples_requested = 16;
  f.sample_positions = {{0.5625f, 0.3125f}, {0.4375f, 0.6875f}};
  f.reduction = "fixed_point";
  f.reduction_note = "why";
  f.gl_fault = "wrong_mip";
  f.device = "egl device 1 (EGL_EXT_device_drm)";
  f.vendor = "V";
  f.renderer = "R";
  f.version = "4.6";
  f.max_samples = 32;
  f.subpixel_bits = 8;
  f.conservative_raster = {"GL_NV_conservative_raster"};
  f.unreported = {"texture filtering: no query"};
  const nlohmann::json j = f;
  const BackendFacts g = j.get<BackendFacts>();
  EXPECT_EQ(nlohmann::json(g), j);
  EXPECT_EQ(g.sample_positions, f.sample_positions);
  EXPECT_TRUE(BackendFacts().empty());
  EXPECT_FALSE(g.empty());
  EXPECT_THROW(nlohmann::json({{"sample_positions", {{1}}}}).get<BackendFacts>(), nlohmann::json::exception);
  EXPECT_THROW(nlohmann::json({{"msaa_samples", "four"}}).get<BackendFacts>(), nlohmann::json::exception);
  EXPECT_THROW(nlohmann::json(3).get<BackendFacts>(), nlohmann::json::exception);
}

TEST(BackendFacts, ReferenceRecordsTheSamplePositionsItUsed) {
  Settings s;
  s.vct.width = s.vct.height = 16;
  s.vct.grid = 16;
  s.vct.shadow_map_size = 64;
  s.vct.voxelizer = Voxelizer::GpuEmulation;
  s.vct.msaa_samples = 4;
  s.vct.particles = false;
  const Scene scene = load_scene("");
  const FrameResult standard = render_ref_frame(scene, s);
  EXPECT_EQ(standard.facts.sample_positions, standard_sample_positions(4));
  EXPECT_EQ(standard.facts.msaa_samples, 4);
  // A driver's 2-sample pattern (D3D's): the emulation runs it and says so.
  const std::vector<vec2> two = {{0.75f, 0.75f}, {0.25f, 0.25f}};
  const FrameResult mirrored = render_ref_frame(scene, s, two);
  EXPECT_EQ(mirrored.facts.sample_positions, two);
  EXPECT_EQ(mirrored.facts.msaa_samples, 2);
  EXPECT_NE(mirrored.voxels.fragments.data, standard.voxels.fragments.data);
}

}  // namespace
}  // namespace vct
