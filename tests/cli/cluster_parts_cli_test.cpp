// The `vct` side of cluster jobs (docs/cluster.md): `pathtrace --sample-range/--partial/--merge`
// and `validate --sweep-rows/--pt-from/--check-input` end to end, bad input as one line and exit
// 2 with no output written. (Dask itself is tested by tests/cluster/test_cluster.py.)
#include <gtest/gtest.h>

#include "cli_run_util.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

const std::string kSmall = " --quiet --width 24 --height 16 --spp 4";

TEST(ClusterPartsCli, RangesMergeIntoARunLikeOneProcess) {
  const auto dir = test::fresh_dir("cluster_parts");
  const std::string parts = (dir / "parts").string();
  ASSERT_EQ(test::run_vct("pathtrace" + kSmall + " --sample-range 0:1 --partial '" + parts + "/a.ptpart'"), 0);
  ASSERT_EQ(test::run_vct("pathtrace" + kSmall + " --sample-range 1:4 --partial '" + parts + "/b.ptpart'"), 0);
  ASSERT_EQ(test::run_vct("pathtrace" + kSmall + " --merge '" + parts + "' --out '" + (dir / "merged").string() + "'"),
            0);
  ASSERT_EQ(test::run_vct("pathtrace" + kSmall + " --out '" + (dir / "one").string() + "'"), 0);
  // The same checkpoint bytes, by construction for this split: each half-sum holds at most two
  // samples, and 0:1 + 1:4 adds them in the one-process order (s0 + s2, 0 + (s1 + s3) = s1 + s3).
  const auto merged = test::files_below(dir / "merged"), one = test::files_below(dir / "one");
  ASSERT_TRUE(merged.count("pt_full_var.exr"));
  EXPECT_EQ(merged.at("pt_checkpoint.bin"), one.at("pt_checkpoint.bin"));
  const test::VctOutput key = test::run_vct_captured("pathtrace" + kSmall + " --job-key");
  EXPECT_EQ(key.exit_code, 0);
  EXPECT_NE(key.out.find("\"settings_hash\""), std::string::npos);
}

TEST(ClusterPartsCli, BadRangesAndMergesAreExitTwoWithNothingWritten) {
  const auto dir = test::fresh_dir("cluster_bad");
  const std::string parts = (dir / "parts").string(), out = (dir / "out").string();
  EXPECT_EQ(test::run_vct("pathtrace" + kSmall + " --sample-range 3:3 --partial '" + parts + "/x.ptpart'"), 2);
  EXPECT_EQ(test::run_vct("pathtrace" + kSmall + " --sample-range 0:2"), 2);  // no --partial
  ASSERT_EQ(test::run_vct("pathtrace" + kSmall + " --sample-range 0:2 --partial '" + parts + "/a.ptpart'"), 0);
  const test::VctOutput gap = test::run_vct_captured("pathtrace" + kSmall + " --merge '" + parts + "' --out '" + out + "'");
  EXPECT_EQ(gap.exit_code, 2);
  EXPECT_NE(gap.err.find("cover samples 0..2, not the requested 4"), std::string::npos) << gap.err;
  EXPECT_FALSE(fs::exists(out));
  // The missing samples, but rendered with another seed: not this job's sums.
  ASSERT_EQ(test::run_vct("pathtrace" + kSmall + " --set pt.seed=9 --sample-range 2:4 --partial '" + parts +
                          "/b.ptpart'"),
            0);
  const test::VctOutput other = test::run_vct_captured("pathtrace" + kSmall + " --merge '" + parts + "' --out '" + out + "'");
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("different path tracer settings"), std::string::npos) << other.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(ClusterPartsCli, SweepRowsAgainstABaseRunAndCheckInput) {
  const auto dir = test::fresh_dir("cluster_sweep_rows");
  const std::string base = (dir / "base").string(), rows = (dir / "rows.json").string();
  const std::string v = "validate --width 24 --height 16 --grid 16 --spp 2";
  EXPECT_EQ(test::run_vct(v + " --sweep grid=16,7 --check-input"), 2);
  EXPECT_EQ(test::run_vct(v + " --sweep grid=16,32 --check-input"), 0);
  EXPECT_EQ(test::run_vct(v + " --sweep grid=32 --pt-from '" + base + "' --sweep-rows '" + rows + "'"), 2);  // no base yet
  EXPECT_FALSE(fs::exists(rows));
  ASSERT_LE(test::run_vct(v + " --no-report --out '" + base + "'"), 1);
  ASSERT_EQ(test::run_vct(v + " --sweep grid=32 --pt-from '" + base + "' --sweep-rows '" + rows + "'"), 0);
  const std::string json = test::slurp(rows);
  EXPECT_NE(json.find("\"key\": \"grid\""), std::string::npos) << json.substr(0, 200);
  EXPECT_NE(json.find("\"bias\""), std::string::npos);  // measured against the base run's path tracer
}

}  // namespace
}  // namespace vct
