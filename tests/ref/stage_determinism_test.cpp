// Every part-1 stage gives the same bytes for 1, 2 and 8 threads; and the dump writer's names.
#include <cstring>
#include <filesystem>
#include <gtest/gtest.h>

#include "core/parallel.h"
#include "freedoms/coverage_ties.h"
#include "freedoms/gbuffer_freedoms.h"
#include "freedoms/shadow_map_ties.h"
#include "freedoms/voxel_freedoms.h"
#include "io/run_dir.h"
#include "stage_test_scene.h"
#include "stages/direct.h"
#include "stages/dumps.h"
#include "stages/gbuffer.h"
#include "stages/inject.h"
#include "stages/mips.h"
#include "stages/shadow_map.h"
#include "stages/voxelize.h"

namespace vct {
namespace {

// Everything the stages produce, flattened to bytes.
std::vector<uint8_t> run_all(const Scene& s, int threads) {
  set_thread_count(threads);
  std::vector<uint8_t> bytes;
  auto add = [&](const std::vector<float>& v) {
    const size_t o = bytes.size();
    bytes.resize(o + v.size() * sizeof(float));
    if (!v.empty()) std::memcpy(&bytes[o], v.data(), v.size() * sizeof(float));
  };
  VctSettings st;
  st.width = 64;
  st.height = 48;
  st.shadow_map_size = 128;
  auto maps = render_shadow_maps(s, st);
  add_shadow_tie_ranges(s, st, maps);
  for (const auto& m : maps) {
    add(m.depth.data);
    add(m.tie_range.data);
  }
  const GBuffer g = render_gbuffer_with_freedoms(s, st);
  for (const Image* i : {&g.position, &g.normal, &g.albedo, &g.material, &g.depth, &g.coverage, &g.texture_slack, &g.tie_range})
    add(i->data);
  add(shade_direct(s, g, maps, st).data);
  const Voxelization c = voxelize_conservative(s, 32), gp = voxelize_gpu_rule(s, 32, 4);
  add(c.occupancy.data);
  add(gp.occupancy.data);
  add(hole_map(c, gp).data);
  for (Reduction r : {Reduction::ExactMean, Reduction::FixedPoint, Reduction::CasRgba8}) {
    st.reduction = r;
    Voxelization vox = r == Reduction::FixedPoint ? gp : c;
    add_coverage_ties(s, vox);
    const VoxelGrid vg = judged_voxels(s, vox, maps, st);
    add(vg.radiance.data);
    add(vg.cas_lo.data);
    add(vg.cas_hi.data);
    add(vg.shading_slack.data);
    add(vg.exact.data);
    const VoxelMips m = build_mips(vg.radiance, true);
    for (const Volume& v : m.iso) add(v.data);
    for (const auto& d : m.aniso)
      for (const Volume& v : d) add(v.data);
  }
  set_thread_count(0);
  return bytes;
}

TEST(StageDeterminism, SameBytesFor1_2_8Threads) {
  const Scene s = test::stage_room();
  const std::vector<uint8_t> one = run_all(s, 1);
  EXPECT_GT(one.size(), 100000u);
  EXPECT_TRUE(one == run_all(s, 2));
  EXPECT_TRUE(one == run_all(s, 8));
}

TEST(StageDumps, WritesTheDocumentedNames) {
  const Scene s = test::stage_room();
  VctSettings st;
  st.width = 32;
  st.height = 24;
  st.shadow_map_size = 64;
  st.grid = 16;
  FrameResult f;
  f.backend = "ref";
  f.shadow_maps = render_shadow_maps(s, st);
  f.gbuffer = render_gbuffer(s, st);
  f.images.direct = shade_direct(s, f.gbuffer, f.shadow_maps, st);
  const Voxelization c = voxelize_conservative(s, 16), g = voxelize_gpu_rule(s, 16, 8);
  f.conservative_occupancy = c.occupancy;
  f.holes = hole_map(c, g);
  f.voxels = inject_and_reduce(s, c, f.shadow_maps, st);
  f.mips = build_mips(f.voxels.radiance, true);
  f.timings_ms["voxelize"] = 1.5;
  const std::string dir = ::testing::TempDir() + "/vct_stage_dumps";
  std::filesystem::remove_all(dir);
  RunDir run(dir);
  write_frame_dumps(run, f, s);
  for (const char* name :
       {"shadow_map_0.exr", "shadow_map_0.png", "gbuffer_position.exr", "gbuffer_normal.png", "gbuffer_albedo.exr",
        "gbuffer_material.exr", "gbuffer_depth.exr", "gbuffer_coverage.png", "gbuffer_emission.exr", "direct.exr",
        "direct.png", "voxels_occupancy.nrrd", "voxels_occupancy.png", "voxels_radiance_L0.nrrd",
        "voxels_radiance_L4.nrrd", "voxels_radiance_L4.png", "aniso_posx_L1.nrrd", "aniso_negz_L4.nrrd", "holes.nrrd",
        "voxels_conservative_occupancy.nrrd", "voxels_fragments.nrrd", "run.json"})
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + name)) << name;
  EXPECT_FALSE(std::filesystem::exists(dir + "/final.exr"));  // absent components are not written
  EXPECT_FALSE(std::filesystem::exists(dir + "/voxels_radiance_L5.nrrd"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vct
