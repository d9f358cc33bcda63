// `vct metamorphic` end to end (docs/metamorphic.md): exit codes 0 / 1 / 2 / 3, run.json with one
// entry per relation and a finished run directory, bad input refused before anything is written,
// and the same bytes for 1 and 2 threads.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_run_util.h"

namespace vct::test {
namespace {

const std::string kSmall = " --width 32 --height 32 --grid 16 --threads 1";

TEST(MetamorphicCli, RefRunPassesAndWritesAFinishedRunDirectory) {
  const fs::path out = fresh_dir("meta_ref");
  ASSERT_EQ(run_vct("metamorphic --backend ref --only translate,linearity,furnace --out " +
                    out.string() + kSmall),
            0);
  EXPECT_FALSE(fs::exists(out / "INCOMPLETE"));
  const nlohmann::json j = nlohmann::json::parse(slurp(out / "run.json"));
  EXPECT_EQ(j.at("status"), "complete");
  EXPECT_EQ(j.at("command"), "metamorphic");
  ASSERT_EQ(j.at("relations").size(), 3u);
  for (const auto& r : j.at("relations")) {
    EXPECT_NE(r.at("verdict"), "fail") << r.at("name");
    EXPECT_FALSE(r.at("tolerance").get<std::string>().empty());
  }
  EXPECT_TRUE(fs::exists(out / "base" / "vct-stages.json"));
  EXPECT_TRUE(fs::exists(out / "translate" / "mapped" / "vct-stages.json"));
  EXPECT_TRUE(fs::exists(out / "linearity" / "doubled" / "vct-stages.json"));
  EXPECT_TRUE(fs::exists(out / "furnace" / "furnace" / "vct-stages.json"));
}

TEST(MetamorphicCli, BadInputIsRefusedBeforeAnyOutput) {
  const fs::path out = fresh_dir("meta_bad") / "run";
  EXPECT_EQ(run_vct("metamorphic --only no_such_relation --out " + out.string() + kSmall), 2);
  EXPECT_EQ(
      run_vct("metamorphic --backend ref --grid 33 --width 32 --height 32 --out " + out.string()),
      2);
  EXPECT_EQ(run_vct("metamorphic /no/such/scene.gltf --out " + out.string() + kSmall), 2);
  EXPECT_EQ(
      run_vct("metamorphic --backend gl --gl-fault no_such_fault --out " + out.string() + kSmall),
      2);
  EXPECT_EQ(
      run_vct("metamorphic --backend ref --gl-fault wrong_mip --out " + out.string() + kSmall), 2);
  EXPECT_FALSE(fs::exists(out));
}

TEST(MetamorphicCli, AGlFaultFailsWithExitOneOrNoGlIsThree) {
  const fs::path out = fresh_dir("meta_fault");
  const int rc = run_vct(
      "metamorphic --backend gl --gl-fault wrong_mip --only shift_in_volume --grid 32 --out " +
      out.string() + " --width 32 --height 32");
  if (rc == 3) GTEST_SKIP() << "no OpenGL 4.5 context";
  EXPECT_EQ(rc, 1);
  const nlohmann::json j = nlohmann::json::parse(slurp(out / "run.json"));
  EXPECT_EQ(j.at("overall"), "fail");
  EXPECT_EQ(j.at("gl_fault"), "wrong_mip");
}

TEST(MetamorphicCli, SameBytesForOneAndTwoThreads) {
  const fs::path a = fresh_dir("meta_t1"), b = fresh_dir("meta_t2");
  const std::string args =
      "metamorphic --backend ref --only turn_z,linearity --width 32 --height 32 --grid 16";
  ASSERT_EQ(run_vct(args + " --threads 1 --out " + a.string()), 0);
  ASSERT_EQ(run_vct(args + " --threads 2 --out " + b.string()), 0);
  EXPECT_EQ(differences(files_below(a), files_below(b)), "");
}

}  // namespace
}  // namespace vct::test
