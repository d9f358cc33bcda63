// `vct config-from-manifest` (issue 39 item 5): a stage set's manifest -> the reference's --config.
// The manifest's reduction in its own spelling becomes the settings' (core/reduction_names.h), its
// VCT settings keys and MSAA fact carry over, the files' sizes win, other keys are noted; the
// config loads in `vct render --config`. Both spellings of a reduction are read everywhere.
#include <gtest/gtest.h>

#include <algorithm>

#include <nlohmann/json.hpp>

#include "cli_run_util.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

TEST(ConfigFromManifestCli, TurnsAManifestIntoSettingsTheReferenceLoads) {
  const fs::path dir = test::fresh_dir("config_from_manifest");
  ASSERT_EQ(test::run_vct("render --backend ref --width 24 --height 16 --grid 16 --dump --out " + q(dir / "run")), 0);
  nlohmann::json m = nlohmann::json::parse(test::slurp(dir / "run" / "vct-stages.json"));
  m["reduction"] = "fixed_point";
  m["storage"] = "rgba8";
  m["settings"] = {{"cone_quality", 0.7}, {"grid", 16}, {"engine_flag", 1}};
  m["facts"] = {{"msaa_samples", 4}};
  { std::ofstream(dir / "run" / "vct-stages.json") << m.dump(); }
  const auto r = test::run_vct_captured("config-from-manifest " + q(dir / "run"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json vct = nlohmann::json::parse(r.out)["vct"];
  EXPECT_EQ(vct["reduction"], "fixed");  // the manifest's fixed_point in the settings' spelling
  EXPECT_EQ(vct["storage"], "rgba8");
  EXPECT_EQ(vct["cone_quality"], 0.7);
  EXPECT_EQ(vct["msaa_samples"], 4);
  EXPECT_EQ(vct["width"], 24);
  EXPECT_EQ(vct["height"], 16);
  EXPECT_FALSE(vct.contains("engine_flag"));
  EXPECT_NE(r.err.find("settings.engine_flag: not a VCT setting"), std::string::npos) << r.err;
  { std::ofstream(dir / "config.json") << r.out; }
  EXPECT_EQ(test::run_vct("render --backend ref --config " + q(dir / "config.json") + " --out " + q(dir / "again")), 0);
  // One vocabulary: the manifest's name is a valid --set value, and a manifest may use the settings'.
  EXPECT_EQ(test::run_vct("render --backend ref --width 8 --height 8 --grid 16 --set reduction=cas_rgba8 --out " + q(dir / "alias")), 0);
  m["reduction"] = "fixed";
  { std::ofstream(dir / "run" / "vct-stages.json") << m.dump(); }
  EXPECT_EQ(test::run_vct("compare " + q(dir / "run") + " " + q(dir / "run")), 0);
}

TEST(ConfigFromManifestCli, SettingsTheReferenceCannotRunAreExit2) {
  const fs::path dir = test::fresh_dir("config_from_manifest_bad");
  ASSERT_EQ(test::run_vct("render --backend ref --width 8 --height 8 --grid 16 --dump --out " + q(dir / "run")), 0);
  nlohmann::json m = nlohmann::json::parse(test::slurp(dir / "run" / "vct-stages.json"));
  m["settings"] = {{"cone_quality", -3}};
  { std::ofstream(dir / "run" / "vct-stages.json") << m.dump(); }
  const auto r = test::run_vct_captured("config-from-manifest " + q(dir / "run"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("not valid reference settings"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

}  // namespace
}  // namespace vct
