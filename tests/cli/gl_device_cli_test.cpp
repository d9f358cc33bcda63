// `vct validate --gl-device` on Mesa's EGL device platform (its software device: the path that
// opens an NVIDIA, AMD or Intel device elsewhere), the driver's facts in run.json, the reference
// emulating the driver's sample positions, and bad device / fault names as exit 2.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_run_util.h"

namespace vct::test {
namespace {

nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

// Index of Mesa's software device from `vct info --gl --json`, or "" when there is none.
std::string software_device(const fs::path& dir) {
  const std::string cmd = std::string("'") + VCT_BINARY + "' info --gl --json > '" + (dir / "gl.json").string() + "' 2>/dev/null";
  const int rc = std::system(cmd.c_str());
  if (rc != 0) {
    std::printf("vct info --gl: status %d\n", rc);
    return "";
  }
  const nlohmann::json list = read_json(dir / "gl.json");
  for (const auto& d : list["devices"])
    if (d["kind"] == "software" && d["status"] == "ok") return d["spec"].get<std::string>();
  return "";
}

TEST(GlDeviceCli, ValidateRunsOnTheEglDevicePlatformAndMirrorsTheDriversFacts) {
  const fs::path dir = fresh_dir("gl_device_cli");
  const std::string dev = software_device(dir);
  if (dev.empty()) GTEST_SKIP() << "no EGL software device (not Mesa's EGL, or no GL)";
  const fs::path out = dir / "validate";
  const int rc = run_vct("validate --no-report --width 32 --height 32 --grid 16 --spp 1 --gl-device " + dev +
                         " --out '" + out.string() + "'");
  EXPECT_EQ(rc, 0);
  const nlohmann::json run = read_json(out / "run.json");
  ASSERT_EQ(run["backends"]["gl"]["status"], "ok");
  const nlohmann::json& gl = run["backends"]["gl"]["facts"];
  EXPECT_EQ(gl["device"].get<std::string>().rfind("egl device " + dev, 0), 0u) << gl.dump();
  EXPECT_FALSE(gl["renderer"].get<std::string>().empty());
  EXPECT_EQ(gl["sample_positions"].size(), gl["msaa_samples"].get<size_t>());
  // The reference's GPU-rule voxelizer sampled where the driver does.
  EXPECT_EQ(run["backends"]["ref"]["facts"]["sample_positions"], gl["sample_positions"]);
  // And the stage set says so, typed.
  EXPECT_EQ(read_json(out / "gl" / "vct-stages.json")["facts"]["device"], gl["device"]);
}

TEST(GlDeviceCli, UnknownDevicesAndFaultsAreBadInput) {
  const fs::path dir = fresh_dir("gl_device_cli_bad");
  EXPECT_EQ(run_vct("render --backend gl --width 16 --height 16 --grid 16 --gl-device 99 --out '" + (dir / "a").string() + "'"), 2);
  EXPECT_EQ(run_vct("render --backend gl --width 16 --height 16 --grid 16 --gl-device no-such-gpu --out '" + (dir / "b").string() + "'"), 2);
  EXPECT_EQ(run_vct("render --backend gl --width 16 --height 16 --grid 16 --gl-fault nope --out '" + (dir / "c").string() + "'"), 2);
  EXPECT_FALSE(fs::exists(dir / "a" / "run.json"));
  EXPECT_FALSE(fs::exists(dir / "c" / "run.json"));
  EXPECT_EQ(run_vct("render --backend ref --facts-from '" + (dir / "missing").string() + "' --out '" + (dir / "d").string() + "'"), 2);
}

}  // namespace
}  // namespace vct::test
