// `vct attribute` end to end (docs/attribution.md): exit 0 with a finished run directory holding
// attribution.json, a waterfall per component and a heat map per term; --sweep rows; bad input
// refused with exit 2 before anything is written. (Exit 1, a budget that does not add up, is
// attribution/ladder.h's check: tests/attribution/ladder_sum_test.cpp makes it fail.)
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_run_util.h"

namespace vct::test {
namespace {

const std::string kSize = " --width 16 --height 16 --grid 16 --spp 4 --threads 1";
const std::string kSmall = kSize + " --rays 2";

TEST(AttributeCli, WritesTheBudgetAndItsPictures) {
  const fs::path out = fresh_dir("attr_ok");
  ASSERT_EQ(run_vct("attribute --out " + out.string() + kSmall + " --sweep aperture=20,40"), 0);
  EXPECT_FALSE(fs::exists(out / "INCOMPLETE"));
  const nlohmann::json run = nlohmann::json::parse(slurp(out / "run.json"));
  EXPECT_EQ(run.at("status"), "complete");
  EXPECT_EQ(run.at("command"), "attribute");
  const nlohmann::json j = nlohmann::json::parse(slurp(out / "attribution.json"));
  EXPECT_TRUE(j.at("sums_to_totals").get<bool>());
  ASSERT_EQ(j.at("components").size(), 3u);
  const std::vector<size_t> term_counts = {5, 4, 2};  // diffuse, specular, direct ladders
  for (size_t i = 0; i < 3; ++i) {
    const nlohmann::json& c = j.at("components")[i];
    ASSERT_EQ(c.at("terms").size(), term_counts[i]) << c.at("component");
    EXPECT_EQ(c.at("rungs").size(), term_counts[i] + 1);
    EXPECT_TRUE(fs::exists(out / c.at("files").at("waterfall").get<std::string>()));
    for (const auto& [term, files] : c.at("files").at("heat_maps").items()) {
      EXPECT_TRUE(fs::exists(out / files.at("exr").get<std::string>())) << term;
      EXPECT_TRUE(fs::exists(out / files.at("png").get<std::string>())) << term;
    }
  }
  ASSERT_EQ(j.at("sweeps").size(), 1u);
  EXPECT_EQ(j.at("sweeps")[0].at("key"), "aperture");
  EXPECT_EQ(j.at("sweeps")[0].at("rows").size(), 2u);
}

// validate --attribute puts the budget into its run: attribution.json named in run.json, and one
// line per component for the report's first screen.
TEST(AttributeCli, ValidateAttributeAddsTheBudgetToTheRun) {
  const fs::path out = fresh_dir("attr_validate");
  const int rc = run_vct("validate --attribute --attribute-rays 2 --no-report --out " + out.string() + kSize);
  ASSERT_TRUE(rc == 0 || rc == 1) << rc;  // 1 would be a GL verdict, not the budget
  const nlohmann::json run = nlohmann::json::parse(slurp(out / "run.json"));
  ASSERT_EQ(run.at("attribution"), "attribution.json");
  EXPECT_EQ(run.at("error_budget").size(), 3u);
  const nlohmann::json j = nlohmann::json::parse(slurp(out / "attribution.json"));
  EXPECT_EQ(j.at("components").size(), 3u);
  EXPECT_TRUE(fs::exists(out / "attribution" / "indirect_diffuse_waterfall.png"));
}

TEST(AttributeCli, BadInputIsRefusedBeforeAnyOutput) {
  const fs::path out = fresh_dir("attr_bad") / "run";
  EXPECT_EQ(run_vct("attribute --components no_such_component --out " + out.string() + kSmall), 2);
  EXPECT_EQ(run_vct("attribute --rays 0 --out " + out.string() + kSize), 2);
  EXPECT_EQ(run_vct("attribute --sweep no_such_key=1,2 --out " + out.string() + kSmall), 2);
  EXPECT_EQ(run_vct("attribute --sweep grid=64,33 --out " + out.string() + kSmall), 2);
  EXPECT_EQ(run_vct("attribute /no/such/scene.gltf --out " + out.string() + kSmall), 2);
  // An engine's conventions (issue 21) are judged by vct compare, not split by the ladders.
  EXPECT_EQ(run_vct("attribute --set diffuse_cone_set=0,0,1,30,1 --out " + out.string() + kSmall), 2);
  EXPECT_EQ(run_vct("attribute --set indirect_diffuse_gain=0.15 --out " + out.string() + kSmall), 2);
  EXPECT_EQ(run_vct("attribute --set specular_aperture=rosseaux --out " + out.string() + kSmall), 2);
  EXPECT_EQ(run_vct("attribute --sweep specular_view=surface,origin --out " + out.string() + kSmall), 2);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace vct::test
