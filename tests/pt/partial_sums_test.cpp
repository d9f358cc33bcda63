// Partial sums of sample ranges (cluster tasks, docs/cluster.md): a range is exactly its samples'
// share of a one-machine render, the merge adds ranges in sample order whatever order it gets
// them in, one range holding every sample is the one-machine render byte for byte, and gaps,
// overlaps, other settings and damaged files are input errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "core/error.h"
#include "io/atomic_file.h"
#include "pt/pathtrace_run.h"
#include "run_dir_fixture.h"
#include "test_scenes.h"

namespace vct::pt {
namespace {

namespace fs = std::filesystem;

using test::settings_with;
using test::TempDir;

PartialSums range(const Scene& scene, const Settings& s, uint32_t a, uint32_t b, const TempDir& d) {
  return run_sample_range(scene, s, a, b, d.file(std::to_string(a) + "_" + std::to_string(b) + ".ptpart"), false);
}

TEST(PartialSums, FirstRangeIsTheStraightRenderOfItsSamples) {
  const Scene scene = test::demo_room();
  TempDir d("first");
  const PartialSums p = range(scene, settings_with(8), 0, 3, d);
  PathtraceRunOptions o;
  o.out_dir = d.file("straight");
  o.write_images = false;
  run_pathtrace(scene, settings_with(3), o);
  // A checkpoint and a partial from 0 hold the same sums after their headers (40 and 76 bytes).
  const std::string ckpt = read_file(d.file("straight/pt_checkpoint.bin"));
  const std::string part = read_file(d.file("0_3.ptpart"));
  ASSERT_EQ(ckpt.size() - 40, part.size() - 76);
  EXPECT_EQ(ckpt.substr(40), part.substr(76));
  EXPECT_EQ(p.end_sample, 3u);
  EXPECT_GT(p.rays.total(), 0u);
}

TEST(PartialSums, MergeIsInSampleOrderAndMatchesTheStraightRenderToRounding) {
  const Scene scene = test::demo_room();
  const Settings s = settings_with(8);
  TempDir d("merge");
  const CheckpointKey key = checkpoint_key(scene, s);
  std::vector<PartialSums> parts = {range(scene, s, 0, 3, d), range(scene, s, 3, 5, d), range(scene, s, 5, 8, d)};
  RayCounts rays;
  const Accumulator in_order = merge_partial_sums(parts, key, 20, 16, 8, rays);
  std::reverse(parts.begin(), parts.end());
  const Accumulator reversed = merge_partial_sums(parts, key, 20, 16, 8, rays);
  EXPECT_EQ(in_order.sums(), reversed.sums());
  EXPECT_EQ(in_order.samples(), 8u);
  // The same samples summed in another grouping: equal up to double rounding, per sum at most
  // a few ulps of the largest partial (8 adds of values < 1e3: relative 8 * 2^-53 ~ 1e-15).
  PathtraceRunOptions o;
  o.out_dir = d.file("straight");
  o.write_images = false;
  run_pathtrace(scene, s, o);
  Accumulator straight;
  std::string why;
  ASSERT_TRUE(load_checkpoint(d.file("straight/pt_checkpoint.bin"), key, 20, 16, straight, why)) << why;
  double worst = 0.0;
  for (size_t i = 0; i < straight.sums().size(); ++i)
    worst = std::max(worst, std::abs(straight.sums()[i] - in_order.sums()[i]) /
                                std::max(1e-300, std::abs(straight.sums()[i])));
  EXPECT_LT(worst, 1e-14);
}

TEST(PartialSums, OneRangeMergedIsTheOneMachineRunByteForByte) {
  const Scene scene = test::demo_room();
  const Settings s = settings_with(6);
  TempDir d("one");
  fs::create_directories(d.path / "parts");
  run_sample_range(scene, s, 0, 6, d.file("parts/all.ptpart"), false);
  PathtraceRunOptions o;
  o.out_dir = d.file("merged");
  merge_sample_ranges(scene, s, d.file("parts"), o);
  o.out_dir = d.file("straight");
  run_pathtrace(scene, s, o);
  EXPECT_EQ(read_file(d.file("merged/pt_checkpoint.bin")), read_file(d.file("straight/pt_checkpoint.bin")));
  EXPECT_EQ(read_file(d.file("merged/pt_full.png")), read_file(d.file("straight/pt_full.png")));
}

TEST(PartialSums, GapsOverlapsOtherSettingsAndDamageAreInputErrors) {
  const Scene scene = test::demo_room();
  const Settings s = settings_with(8);
  TempDir d("bad");
  const CheckpointKey key = checkpoint_key(scene, s);
  const PartialSums a = range(scene, s, 0, 3, d), b = range(scene, s, 4, 8, d), c = range(scene, s, 2, 8, d);
  RayCounts rays;
  EXPECT_THROW(merge_partial_sums({a, b}, key, 20, 16, 8, rays), InputError);          // 3 missing
  EXPECT_THROW(merge_partial_sums({a, c}, key, 20, 16, 8, rays), InputError);          // 2 twice
  EXPECT_THROW(merge_partial_sums({a}, key, 20, 16, 8, rays), InputError);             // short of spp
  const PartialSums other = run_sample_range(scene, settings_with(8, 2), 3, 8, d.file("seed2.ptpart"), false);
  EXPECT_THROW(merge_partial_sums({a, other}, key, 20, 16, 8, rays), InputError);      // another seed
  const std::string bytes = read_file(d.file("0_3.ptpart"));
  write_text_atomically(d.file("cut.ptpart"), bytes.substr(0, bytes.size() - 8));
  EXPECT_THROW(load_partial_sums(d.file("cut.ptpart")), InputError);
  EXPECT_EQ(load_partial_sums(d.file("0_3.ptpart")).sums.sums(), a.sums.sums());
  EXPECT_THROW(run_sample_range(scene, s, 3, 3, d.file("empty.ptpart"), false), InputError);
}

}  // namespace
}  // namespace vct::pt
