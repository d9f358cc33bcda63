// compare/metamorphic.h on the CPU reference (docs/metamorphic.md): every relation holds on the
// built-in Cornell box (64^2, 32^3), linearity holds bit for bit where the pipeline is float, and
// backends broken on purpose (a volume that does not move, a clipped image, a mirrored axis) are
// caught by the relation that sees them. The GL side: tests/gl/gl_metamorphic_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "compare/metamorphic.h"
#include "compare/metamorphic_map.h"
#include "scene/gltf_loader.h"
#include "scene/scene_transform.h"
#include "freedoms/reference_frame.h"
#include "stages/stage_registry.h"

namespace vct::cmp {
namespace {

namespace st = stage_names;

bool is_cone_traced_stage(const std::string& stage) {
  const auto ref = find_stage(stage);
  return ref && judged_on_own_inputs(*ref->row, false);
}

Settings small() {
  Settings s;
  s.vct.width = s.vct.height = 64;
  s.vct.grid = 32;
  s.vct.shadow_map_size = 256;
  s.vct.voxelizer = Voxelizer::GpuEmulation;
  s.vct.msaa_samples = 4;
  s.vct.reduction = Reduction::FixedPoint;
  s.threads = 2;
  return s;
}

const Scene& cornell() {
  static const Scene s = load_scene("");
  return s;
}

FrameRenderer ref_renderer() {
  return [](const Scene& scene, const Settings& s) { return render_ref_frame(scene, s); };
}

const RelationResult& relation(const MetamorphicRun& run, const std::string& name) {
  for (const RelationResult& r : run.relations)
    if (r.name == name) return r;
  throw std::runtime_error("no relation " + name);
}

std::string failing(const RelationResult& r) {
  std::string out;
  for (const StageVerdict& v : r.stages)
    if (v.verdict == Verdict::Fail) out += v.stage + " ";
  return out;
}

void print(const MetamorphicRun& run, const char* what) {
  for (const RelationResult& r : run.relations)
    std::printf("  [%s] %-16s %-4s %s | failing: %s\n", what, r.name.c_str(),
                to_string(r.verdict).c_str(), r.note.c_str(), failing(r).c_str());
}

TEST(MetamorphicMap, TurnedVoxelFollowsTheTurn) {
  // About z, base voxel (i, j, k) is turned voxel (N-1-j, i, k).
  EXPECT_EQ(turned_voxel(ivec3(1, 2, 3), 8, 2), ivec3(5, 1, 3));
  EXPECT_EQ(turned_voxel(ivec3(1, 2, 3), 8, 0), ivec3(1, 4, 2));  // about x: (i, N-1-k, j)
  EXPECT_EQ(turned_voxel(ivec3(1, 2, 3), 8, 1), ivec3(3, 2, 6));  // about y: (k, j, N-1-i)
}

TEST(MetamorphicMap, UnturnedReadsTheDirectionalMipOfTheTurnedDirection) {
  StageSet t;
  for (int d = 0; d < 6; ++d) t.volumes[stage_name(mip_row(d), 1)] = Volume(2, 2, 2, 4, float(d));
  const StageSet b = unturned(t, 2);  // about z: +x -> +y, +y -> -x
  EXPECT_EQ(b.volumes.at("mip.posx.1").data[0], float(kPosY));
  EXPECT_EQ(b.volumes.at("mip.posy.1").data[0], float(kNegX));
  EXPECT_EQ(b.volumes.at("mip.posz.1").data[0], float(kPosZ));
}

TEST(MetamorphicRef, EveryRelationHoldsOnTheCornellBox) {
  const MetamorphicRun run = run_metamorphic(cornell(), small(), ref_renderer());
  print(run, "ref");
  ASSERT_EQ(run.relations.size(), metamorphic_rows().size());
  for (const RelationResult& r : run.relations) {
    EXPECT_NE(r.verdict, Verdict::Fail) << r.name << ": " << r.note << " failing: " << failing(r);
    EXPECT_FALSE(r.stages.empty()) << r.name;
  }
  // Translation with the volume: the voxel stages are identical, index by index.
  for (const StageVerdict& v : relation(run, "translate").stages) {
    if (v.stage == st::kVoxelRadiance || v.stage == st::kVoxelOccupancy) {
      EXPECT_EQ(v.max_abs, 0.0) << v.stage;
    }
  }
}

TEST(MetamorphicRef, LinearityIsBitExactWhereThePipelineIsFloat) {
  Settings s = small();
  s.vct.reduction = Reduction::ExactMean;
  s.vct.voxelizer = Voxelizer::Conservative;
  const MetamorphicRun run = run_metamorphic(cornell(), s, ref_renderer(), {"linearity"});
  const RelationResult& r = relation(run, "linearity");
  print(run, "ref exact");
  EXPECT_EQ(r.verdict, Verdict::Pass);
  for (const StageVerdict& v : r.stages) {
    const auto ref = find_stage(v.stage);
    ASSERT_TRUE(ref) << v.stage;
    const bool reads_voxels = ref->row->kind == StageKind::Volume || is_cone_traced_stage(v.stage);
    if (reads_voxels) {
      // Half subnormals (below 2^-14) have a fixed spacing: doubling may round one 2^-24 apart
      // there, and the mips and cones carry that on (docs/metamorphic.md, Linearity).
      EXPECT_LE(v.max_abs, v.extra.at("bound").get<double>()) << v.stage;
    } else {
      EXPECT_EQ(v.max_abs, 0.0) << v.stage << ": " << v.note;  // float products of doubled inputs
    }
  }
  for (const StageVerdict& v : r.stages) {
    if (v.stage == st::kVoxelRadiance) {
      EXPECT_LE(v.max_abs, std::ldexp(1.0, -24));
    }
  }
}

TEST(MetamorphicRef, FurnaceIsBoundedAndItsBiasReported) {
  const MetamorphicRun run = run_metamorphic(cornell(), small(), ref_renderer(), {"furnace"});
  const RelationResult& r = relation(run, "furnace");
  print(run, "ref");
  EXPECT_EQ(r.verdict, Verdict::Pass) << failing(r);
  // Le = 1, rho = 0.5: one-bounce analytic 1.5; VCT can only fall short (cones lose opacity).
  EXPECT_EQ(r.extra.at("analytic_final").get<double>(), 1.5);
  EXPECT_LE(r.extra.at("mean_final").get<double>(), 1.5);
  EXPECT_GE(r.extra.at("mean_final").get<double>(), 1.0);
}

// A backend whose voxelizer ignores the volume's origin (it voxelizes in world coordinates): the
// translation that moves the volume along must see the voxels move.
TEST(MetamorphicRef, CatchesAVoxelizerThatIgnoresTheVolumeOrigin) {
  const Scene base = on_voxel_lattice(cornell(), 32, shift_voxels_for_grid(32));
  const FrameRenderer broken = [&base](const Scene& scene, const Settings& s) {
    Scene fixed_volume = scene;
    fixed_volume.volume = base.volume;  // a backend that keeps the first volume it saw
    return render_ref_frame(fixed_volume, s);
  };
  const MetamorphicRun run = run_metamorphic(cornell(), small(), broken, {"translate"});
  print(run, "broken origin");
  EXPECT_EQ(relation(run, "translate").verdict, Verdict::Fail);
}

// A backend that clips its final image at 1 (an LDR framebuffer): not linear.
TEST(MetamorphicRef, CatchesAClippedFinalImage) {
  const FrameRenderer clipped = [](const Scene& scene, const Settings& s) {
    FrameResult f = render_ref_frame(scene, s);
    for (float& v : f.images.final_image.data) v = std::min(v, 0.05f);
    return f;
  };
  const MetamorphicRun run = run_metamorphic(cornell(), small(), clipped, {"linearity"});
  print(run, "clipped");
  const RelationResult& r = relation(run, "linearity");
  EXPECT_EQ(r.verdict, Verdict::Fail);
  EXPECT_EQ(failing(r), std::string(st::kImageFinal) + " ");
}

// A backend whose voxelizer mirrors one axis of the grid: the turns about the other two axes
// permute that axis with another and see it.
TEST(MetamorphicRef, CatchesAMirroredVoxelAxis) {
  const FrameRenderer mirrored = [](const Scene& scene, const Settings& s) {
    FrameResult f = render_ref_frame(scene, s);
    Volume& v = f.voxels.radiance;
    Volume m = v;
    for (int z = 0; z < v.nz; ++z)
      for (int y = 0; y < v.ny; ++y)
        for (int x = 0; x < v.nx; ++x) m.set_rgba(x, y, z, v.rgba(v.nx - 1 - x, y, z));
    v = m;
    return f;
  };
  const MetamorphicRun run = run_metamorphic(cornell(), small(), mirrored, {"turn_z", "translate"});
  print(run, "mirrored x");
  EXPECT_EQ(relation(run, "turn_z").verdict, Verdict::Fail);
  EXPECT_NE(relation(run, "translate").verdict, Verdict::Fail);  // a mirror moves with the scene
}

}  // namespace
}  // namespace vct::cmp
