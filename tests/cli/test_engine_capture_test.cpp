// The issue 39 "Done when": a small engine with its own conventions (tests/capture/test_engine.cpp:
// |n.v|, its own box-filter mips, a Reinhard + gamma 2.2 display in RGBA8) captured with RenderDoc,
// imported with the map it writes, its manifest turned into the reference's settings
// (config-from-manifest) and judged: no FAIL with its conventions declared (its own frame PCF --
// UV taps off centre, the driver's filtered depth compared once, a shadowed border -- passes
// image.direct); its PCF left undeclared
// FAILs image.direct first; with a bug injected (each mip level x1.9, VCT_TEST_ENGINE_MIP_SCALE)
// it FAILs first at mip.iso.1. Skipped, with the
// reason, without RenderDoc, GL, or under a sanitizer (import_capture_cli_test.cpp says why).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli_run_util.h"
#include "renderdoc_available.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

// Captures the engine (with `env` before it) into dir and judges it; the verdict's output.
test::VctOutput capture_and_judge(const fs::path& program, const fs::path& dir, const std::string& env) {
  const fs::path lock = fs::temp_directory_path() / "vct-renderdoc-capture.lock";  // one capture at a time
  const std::string capture = env + " flock " + q(lock) + " renderdoccmd capture -w -d " + q(dir) + " -c " +
                              q(dir / "frame") + " " + q(program) + " " + q(dir / "map.json") + " > " +
                              q(dir / "capture.log") + " 2>&1";
  (void)std::system(capture.c_str());  // its exit code: see import_capture_cli_test.cpp
  const fs::path rdc = dir / "frame_capture.rdc";
  if (!fs::exists(rdc) || !fs::exists(dir / "map.json")) return {-1, "", "no capture: " + test::slurp(dir / "capture.log")};
  const auto imported = test::run_vct_captured("import-capture " + q(rdc) + " --map " + q(dir / "map.json") + " --out " +
                                               q(dir / "imported"));
  if (imported.exit_code != 0) return {-1, "", "import-capture: " + imported.err};
  const auto config = test::run_vct_captured("config-from-manifest " + q(dir / "imported") + " --out " + q(dir / "config.json"));
  if (config.exit_code != 0) return {-1, "", "config-from-manifest: " + config.err};
  const auto ref = test::run_vct_captured("render --backend ref --config " + q(dir / "config.json") + " --facts-from " +
                                          q(dir / "imported") + " --dump --out " + q(dir / "ref"));
  if (ref.exit_code != 0) return {-1, "", "render: " + ref.err};
  return test::run_vct_captured("compare " + q(dir / "ref") + " " + q(dir / "imported"));
}

// The same capture judged against a reference rendered without the engine's PCF settings.
test::VctOutput judge_without_pcf(const fs::path& dir) {
  nlohmann::json config;
  std::ifstream(dir / "config.json") >> config;
  for (const char* key : {"pcf_taps", "pcf_tap_unit", "shadow_compare", "shadow_filter_order", "shadow_border", "voxel_pcf"})
    config["vct"].erase(key);
  std::ofstream(dir / "config_no_pcf.json") << config.dump();
  const auto ref = test::run_vct_captured("render --backend ref --config " + q(dir / "config_no_pcf.json") +
                                          " --facts-from " + q(dir / "imported") + " --dump --out " + q(dir / "ref_no_pcf"));
  if (ref.exit_code != 0) return {-1, "", "render: " + ref.err};
  return test::run_vct_captured("compare " + q(dir / "ref_no_pcf") + " " + q(dir / "imported"));
}

TEST(TestEngineCapture, DeclaredConventionsPassAndAMipBugFailsAtMipIso1) {
  if (const std::string why = test::capture_impossible(); !why.empty()) GTEST_SKIP() << why;
  const fs::path program = fs::path(VCT_BINARY).parent_path() / "test_engine";
  if (!fs::exists(program)) GTEST_SKIP() << "test_engine not built (a build without GL)";
  const fs::path root = test::fresh_dir("test_engine");
  if (std::system((q(program) + " " + q(root / "probe.json") + " > /dev/null 2>&1").c_str()) != 0)
    GTEST_SKIP() << "no GL 4.5 context";
  fs::create_directories(root / "clean");
  const auto clean = capture_and_judge(program, root / "clean", "");
  ASSERT_NE(clean.exit_code, -1) << clean.err;
  EXPECT_EQ(clean.exit_code, 0) << clean.out;
  EXPECT_NE(clean.out.find("pass image.direct"), std::string::npos) << clean.out;
  const auto undeclared = judge_without_pcf(root / "clean");
  ASSERT_NE(undeclared.exit_code, -1) << undeclared.err;
  EXPECT_EQ(undeclared.exit_code, 1) << undeclared.out;
  EXPECT_NE(undeclared.out.find("first failing stage: image.direct"), std::string::npos) << undeclared.out;
  fs::create_directories(root / "mip19");
  const auto bug = capture_and_judge(program, root / "mip19", "VCT_TEST_ENGINE_MIP_SCALE=1.9");
  ASSERT_NE(bug.exit_code, -1) << bug.err;
  EXPECT_EQ(bug.exit_code, 1) << bug.out;
  EXPECT_NE(bug.out.find("first failing stage: mip.iso.1"), std::string::npos) << bug.out;
}

}  // namespace
}  // namespace vct
