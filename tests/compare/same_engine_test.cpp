// Two runs of one engine compared (issue 39 item 4): both dumps declare the same display transform
// and mip deviation, so the reference side's stored images are display-encoded and its mips carry
// opacity above 1. `vct compare DUMP DUMP` judged the reference's encoded image as linear (encoded
// twice: image.direct FAILed) and failed every mip voxel whose opacity was above 1 though the
// reference's was too. Identical dumps now pass; a real difference still fails.
#include <gtest/gtest.h>

#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "display_fixtures.h"
#include "find_verdict.h"

namespace vct::cmp {
namespace {

// A display-encoded 8-bit image of linear values from 0 to ~8 (what gidemo stores).
Image encoded_ramp(const DisplayTransform& d) {
  Image img(16, 16, 3);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = float(d.encode(0.03 * double(x + 16 * y + c)));
  img.channel_names = {"R", "G", "B"};
  return img;
}

// Level 0 opaque; level 1 the box filter times 1.9 (the engine's declared mip_scale): opacity 1.9.
void add_voxels(StageSet& set) {
  Volume base(4, 4, 4, 4);
  for (size_t i = 0; i < base.voxel_count(); ++i) {
    for (int c = 0; c < 3; ++c) base.data[i * 4 + size_t(c)] = 0.1f * float(c + 1);
    base.data[i * 4 + 3] = 1.0f;
  }
  Volume level1(2, 2, 2, 4), level2(1, 1, 1, 4);
  for (size_t i = 0; i < level1.voxel_count(); ++i)
    for (int c = 0; c < 4; ++c) level1.data[i * 4 + size_t(c)] = 1.9f * base.data[size_t(c)];
  for (int c = 0; c < 4; ++c) level2.data[size_t(c)] = 1.9f * level1.data[size_t(c)];
  base.channel_names = level1.channel_names = level2.channel_names = {"R", "G", "B", "A"};
  set.volumes["voxel.radiance"] = base;
  set.volumes["mip.iso.1"] = level1;
  set.volumes["mip.iso.2"] = level2;
}

StageSet engine_dump() {
  StageSet set;
  set.backend = "engine";
  set.storage = "rgba16f";
  set.reduction = "fixed_point";
  set.conventions.display = reinhard_22_8({"image.direct", "image.final"});
  set.conventions.mip_scale = 1.9;
  set.images["image.direct"] = encoded_ramp(set.conventions.display);
  add_voxels(set);
  return set;
}

TEST(SameEngine, TwoIdenticalDisplayEncodedDumpsPass) {
  const StageSet a = engine_dump(), b = engine_dump();
  const Report r = compare_stage_sets(a, b, CompareOptions());
  for (const StageVerdict& v : r.stages) EXPECT_NE(v.verdict, Verdict::Fail) << v.stage << ": " << v.note;
  EXPECT_EQ(test::find(r, "image.direct").out_of_bound, 0u);
  EXPECT_EQ(test::find(r, "mip.iso.1").extra["alpha_out_of_range"].get<size_t>(), 0u);
  EXPECT_FALSE(test::find(r, "mip.iso.1").extra.contains("explained_by_declared_mip_scale"));
}

TEST(SameEngine, TheReferenceSidesTransformIsWhatMakesThemPass) {
  // Without it the reference's encoded image is taken as linear and encoded again: the failure
  // the issue reports.
  StageSet a = engine_dump();
  a.conventions.display = DisplayTransform();
  const Report r = compare_stage_sets(a, engine_dump(), CompareOptions());
  EXPECT_EQ(test::find(r, "image.direct").verdict, Verdict::Fail);
}

TEST(SameEngine, ARealDifferenceStillFails) {
  StageSet b = engine_dump();
  // Three 8-bit steps darker at one pixel: beyond the one-step quantisation allowance.
  float& p = b.images["image.direct"].at(9, 9, 1);
  p = std::max(0.0f, p - 3.0f / 255.0f);
  const Report r = compare_stage_sets(engine_dump(), b, CompareOptions());
  EXPECT_EQ(test::find(r, "image.direct").verdict, Verdict::Fail);
  EXPECT_EQ(test::find(r, "image.direct").out_of_bound, 1u);
  // A test mip whose opacity leaves [0,1] where the reference's does not is still wrong.
  StageSet c = engine_dump();
  StageSet a = engine_dump();
  for (size_t i = 0; i < a.volumes["mip.iso.1"].voxel_count(); ++i) a.volumes["mip.iso.1"].data[i * 4 + 3] = 1.0f;
  const Report alpha = compare_stage_sets(a, c, CompareOptions());
  EXPECT_EQ(test::find(alpha, "mip.iso.1").verdict, Verdict::Fail);
}

}  // namespace
}  // namespace vct::cmp
