// Issue 17's artifact fixes through the real binary: `vct validate` on the built-in scene with all
// three variants switched on (64^2, grid 32) judges GL against the reference with no FAIL, and
// run.json records the settings it ran.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_run_util.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

TEST(VariantsCli, ValidateWithEveryVariantHasNoFail) {
  const fs::path out = test::fresh_dir("variants_validate");
  const test::VctOutput r = test::run_vct_captured(
      "validate --no-report --width 64 --height 64 --grid 32 --spp 1 --set solid_voxelization=true "
      "--set surface_thickening_voxels=2 --set opacity_step_correction=true --out '" + out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out / "run.json");
  ASSERT_TRUE(in.good());
  const nlohmann::json run = nlohmann::json::parse(in);
  EXPECT_EQ(run["verdicts"].value("first_failing", ""), "");
  const nlohmann::json& v = run["settings"]["vct"];
  EXPECT_EQ(v.value("solid_voxelization", false), true);
  EXPECT_EQ(v.value("surface_thickening_voxels", 0), 2);
  EXPECT_EQ(v.value("opacity_step_correction", false), true);
}

}  // namespace
}  // namespace vct
