// Determinism end to end (issue 9 item 5): `vct render --dump` (final frame and every stage dump)
// and `vct pathtrace` (every AOV and the checkpoint) write the same bytes with --threads 1, 2, 8.
// 8 threads oversubscribe the 2-core CI machine, which shuffles the order work is done in.
// The GL build (fixed-point voxels) writes the same bytes under llvmpipe with LP_NUM_THREADS=1, 2, 4.
// `vct validate` decides the same verdicts and bias and writes the same files with --threads 1, 2
// (its checks as concurrent tasks) and 4 (one after the other, each on every thread).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_run_util.h"

namespace vct {
namespace {

using test::differences;
using test::files_below;

TEST(DeterminismCli, RenderDumpsSameBytesFor1_2_8Threads) {
  std::map<std::string, std::string> first;
  for (const char* t : {"1", "2", "8"}) {
    const auto dir = test::fresh_dir(std::string("render_t") + t);
    ASSERT_EQ(test::run_vct(std::string("render --width 48 --height 40 --grid 16 --shadow-map-size 128 --dump "
                                        "--bounces 2 --aniso --voxelizer gpu --reduction fixed --threads ") +
                            t + " --out '" + dir.string() + "'"),
              0);
    const auto files = files_below(dir);
    if (first.empty()) {
      first = files;
      ASSERT_GT(first.size(), 20u);  // final + many stage dumps really were written
      ASSERT_TRUE(first.count("final.exr"));
    } else {
      EXPECT_EQ(differences(first, files), "") << t << " threads";
    }
  }
}

TEST(DeterminismCli, PathtraceSameBytesFor1_2_8Threads) {
  std::map<std::string, std::string> first;
  for (const char* t : {"1", "2", "8"}) {
    const auto dir = test::fresh_dir(std::string("pt_t") + t);
    ASSERT_EQ(test::run_vct(std::string("pathtrace --quiet --width 40 --height 32 --spp 6 --threads ") + t +
                            " --out '" + dir.string() + "'"),
              0);
    const auto files = files_below(dir);
    if (first.empty()) {
      first = files;
      ASSERT_GT(first.size(), 3u);
    } else {
      EXPECT_EQ(differences(first, files), "") << t << " threads";
    }
  }
}

TEST(DeterminismCli, ValidateSameVerdictsAndFilesFor1_2_4Threads) {
  std::map<std::string, std::string> first;
  nlohmann::json first_json;
  for (const char* t : {"1", "2", "4"}) {
    const auto dir = test::fresh_dir(std::string("validate_t") + t);
    const int rc = test::run_vct(std::string("validate --no-report --width 48 --height 40 --grid 16 --spp 2 --threads ") +
                                 t + " --out '" + dir.string() + "'");
    ASSERT_TRUE(rc == 0 || rc == 1) << rc;  // a FAIL verdict is still a verdict to compare
    const nlohmann::json run = nlohmann::json::parse(test::slurp(dir / "run.json"));
    const nlohmann::json decided = {{"verdicts", run["verdicts"]}, {"bias", run["bias"]}, {"exit", run["exit_code"]}};
    const auto files = files_below(dir);
    if (first.empty()) {
      first = files, first_json = decided;
      ASSERT_TRUE(first.count("ref/voxel_radiance.nrrd"));
      ASSERT_GT(first.size(), 40u);
    } else {
      EXPECT_EQ(differences(first, files), "") << t << " threads";
      EXPECT_EQ(decided, first_json) << t << " threads";
    }
  }
}

TEST(GlDeterminismCli, GlDumpsSameBytesForLlvmpipeThreads1_2_4) {
  std::map<std::string, std::string> first;
  for (const char* t : {"1", "2", "4"}) {
    const auto dir = test::fresh_dir(std::string("gl_lp") + t);
    const int rc = test::run_vct("render --backend gl --width 48 --height 40 --grid 16 --shadow-map-size 128 --dump "
                                 "--voxelizer gpu --reduction fixed --out '" + dir.string() + "'",
                                 std::string("LP_NUM_THREADS=") + t);
    if (rc == 3) GTEST_SKIP() << "no GL context";
    ASSERT_EQ(rc, 0);
    const auto files = files_below(dir);
    if (first.empty()) {
      first = files;
      ASSERT_TRUE(first.count("voxels_radiance_L0.nrrd"));
      ASSERT_GT(first.size(), 20u);
    } else {
      EXPECT_EQ(differences(first, files), "") << "LP_NUM_THREADS=" << t;
    }
  }
}

}  // namespace
}  // namespace vct
