// `vct render` end to end through the real binary: the built-in scene renders with the run
// directory contract (final + run.json always, stages with --dump, the explained pixel), flags
// reach the settings, and bad input is one stderr line with exit 2.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../ref/gltf_test_doc.h"

namespace vct {
namespace {

struct Result {
  int exit_code = -1;
  std::string err;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

Result vct(const std::string& args) {
  const std::string out = (test::temp_dir() / "render_stdout.txt").string();
  const std::string err = (test::temp_dir() / "render_stderr.txt").string();
  const std::string cmd = std::string("'") + VCT_BINARY + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int status = std::system(cmd.c_str());
  Result r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = slurp(err);
  return r;
}

const char* kSmall = "--width 40 --height 32 --grid 16 --threads 2";

TEST(RenderCli, BuiltinSceneWritesTheRunDirectory) {
  const std::filesystem::path dir = test::temp_dir() / "render_builtin";
  const Result r = vct(std::string("render ") + kSmall + " --bounces 2 --aniso --dump --explain 20,20 --out '" +
                       dir.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"final.exr", "final.png", "run.json", "indirect_diffuse.exr", "diffuse_term.exr",
                        "diffuse_cone_0.exr", "multibounce_frame_1.nrrd", "explain_20_20.json", "explain_20_20.png"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  }
  const nlohmann::json run = nlohmann::json::parse(slurp((dir / "run.json").string()));
  EXPECT_EQ(run["settings"]["vct"]["grid"], 16);
  EXPECT_EQ(run["settings"]["vct"]["anisotropic"], true);
  EXPECT_EQ(run["multibounce_energy"]["ref"].size(), 2u);
  EXPECT_GT(run["timings_ms"]["ref"]["indirect_cones"].get<double>(), 0.0);
  const nlohmann::json ex = nlohmann::json::parse(slurp((dir / "explain_20_20.json").string()));
  ASSERT_TRUE(ex["covered"].get<bool>());
  EXPECT_GE(ex["cones"].size(), 6u);  // 5 diffuse + specular + one shadow cone per light
  EXPECT_EQ(ex["cones"][0]["kind"], "diffuse");
  EXPECT_FALSE(ex["cones"][0]["samples"].empty());
  // Each light as the pixel sees it (the Cornell box: its ceiling spot).
  ASSERT_EQ(ex["lights"].size(), 1u);
  EXPECT_EQ(ex["lights"][0]["kind"], "spot");
  const double vis = ex["lights"][0]["shadow_map_visibility"].get<double>();
  EXPECT_GE(vis, 0.0);
  EXPECT_LE(vis, 1.0);
}

TEST(RenderCli, ConeCountAndTiltReachDumpsAndExplain) {
  const std::filesystem::path dir = test::temp_dir() / "render_cones";
  const Result r = vct(std::string("render ") + kSmall + " --cone-count 9 --cone-tilt 60 --dump --explain 20,20 --out '" +
                       dir.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "diffuse_cone_8.exr"));
  EXPECT_FALSE(std::filesystem::exists(dir / "diffuse_cone_9.exr"));
  const nlohmann::json run = nlohmann::json::parse(slurp((dir / "run.json").string()));
  EXPECT_EQ(run["settings"]["vct"]["diffuse_cone_count"], 9);
  EXPECT_EQ(run["settings"]["vct"]["diffuse_cone_tilt_deg"], 60.0);
  const nlohmann::json ex = nlohmann::json::parse(slurp((dir / "explain_20_20.json").string()));
  ASSERT_TRUE(ex["covered"].get<bool>());
  int diffuse = 0;
  double weights = 0.0;
  for (const auto& c : ex["cones"]) {
    if (c["kind"] != "diffuse") continue;
    ++diffuse;
    weights += c["weight"].get<double>();
    const auto& d = c["direction"];
    const double len = std::sqrt(d[0].get<double>() * d[0].get<double>() + d[1].get<double>() * d[1].get<double>() +
                                 d[2].get<double>() * d[2].get<double>());
    EXPECT_NEAR(len, 1.0, 1e-5);
  }
  EXPECT_EQ(diffuse, 9);
  EXPECT_NEAR(weights, 1.0, 1e-6);  // cosine weights: 1/T and cos 60/T, T = 1 + 8 cos 60 = 5
  EXPECT_NEAR(ex["cones"][0]["weight"].get<double>(), 0.2, 1e-7);
  EXPECT_NEAR(ex["cones"][1]["weight"].get<double>(), 0.1, 1e-7);
}

// A dumped run is a stage set (compare/dump_manifest.h): its vct-stages.json lists the stages
// --stage-set writes, pointing at the dumped files, and `vct compare` judges it against another
// run. Two bounces, so the dumped base level (the marcher's mip level 0) is not the reduction's
// output the stage holds: that stage must come from stage_files/, byte for byte the --stage-set one.
TEST(RenderCli, DumpedRunIsAStageSetCompareReads) {
  namespace fs = std::filesystem;
  const fs::path dump = test::temp_dir() / "dumped_run", set = test::temp_dir() / "stage_set_run";
  const std::string args = std::string("render ") + kSmall + " --bounces 2 --out '";
  ASSERT_EQ(vct(args + dump.string() + "' --dump").exit_code, 0);
  ASSERT_EQ(vct(args + set.string() + "' --stage-set").exit_code, 0);
  const nlohmann::json dumped = nlohmann::json::parse(slurp((dump / "vct-stages.json").string()));
  const nlohmann::json written = nlohmann::json::parse(slurp((set / "stages" / "vct-stages.json").string()));
  ASSERT_EQ(dumped["stages"].size(), written["stages"].size());
  for (const auto& [name, e] : written["stages"].items()) {
    ASSERT_TRUE(dumped["stages"].contains(name)) << name;
    EXPECT_EQ(dumped["stages"][name]["kind"], e["kind"]) << name;
    EXPECT_TRUE(fs::exists(dump / dumped["stages"][name]["file"].get<std::string>())) << name;
  }
  EXPECT_EQ(dumped["backend"], "ref");
  EXPECT_EQ(dumped["stages"]["image.final"]["file"], "final.exr");  // the dump's own file
  EXPECT_EQ(dumped["stages"]["voxel.radiance"]["file"], "stage_files/voxel_radiance.nrrd");
  EXPECT_EQ(slurp((dump / "stage_files" / "voxel_radiance.nrrd").string()),
            slurp((set / "stages" / "voxel_radiance.nrrd").string()));
  // The same deterministic frame twice: every stage passes.
  const fs::path cmp = test::temp_dir() / "dumped_compare";
  const Result c = vct("compare '" + dump.string() + "' '" + (set / "stages").string() + "' --out '" + cmp.string() + "'");
  EXPECT_EQ(c.exit_code, 0) << c.err;
  const nlohmann::json verdicts = nlohmann::json::parse(slurp((cmp / "compare.json").string()))["verdicts"];
  EXPECT_EQ(verdicts["overall"], "pass");
  EXPECT_GE(verdicts["stages"].size(), 20u);
}

TEST(RenderCli, BadInputIsOneLineAndExitTwo) {
  const std::string out = " --out '" + (test::temp_dir() / "render_bad").string() + "'";
  for (const std::string& args : {std::string("render --explain 5") + out, std::string("render --light-model nope") + out,
                                 std::string("render --explain 9999,1 ") + kSmall + out,
                                 std::string("render /no/such/scene.gltf") + out,
                                 std::string("render --cone-count 17 ") + kSmall + out,
                                 std::string("render --cone-tilt 90 ") + kSmall + out}) {
    const Result r = vct(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  }
}

// What a backend refuses fails before the run directory is created (ref/io/run_dir.h): one line,
// exit 2, and no directory (no INCOMPLETE left to tell from a killed run). The GL refusals are
// found without a working driver (gl::check_gl_accepts, gl::check_gl_device_exists: a device
// name no EGL string matches is probed on each device, and a machine with none refuses it too).
TEST(RenderCli, WhatTheBackendRefusesLeavesNoRunDirectory) {
  const std::filesystem::path config = test::temp_dir() / "depth16.json";
  std::ofstream(config) << R"({"vct": {"shadow_depth_format": "depth16"}})";
  const std::string cfg = " --config '" + config.string() + "' ";
  struct Case {
    std::string args, needle;
  };
  const std::vector<Case> cases = {
      {"render --backend gl" + cfg, "settings: the GL backend runs the pcf_kernel square"},
      {"render --backend gl --set indirect_fresnel=schlick_roughness",
       "settings: the GL backend runs the oracle's composite Fresnel"},
      {"render --backend gl --set specular_view=origin", "settings: the GL backend runs the oracle's specular cone"},
      {"render --backend gl --set specular_aperture=rosseaux", "settings: the GL backend runs the oracle's specular cone"},
      {"render --backend gl --explain 1,1", "--explain: needs --backend ref"},
      {"render --backend gl --gl-device -1", "--gl-device: device index must be 0 or more"},
      {"render --backend gl --gl-fault nosuchfault", "unknown GL fault"},
      {"validate --no-report --spp 1" + cfg, "settings: the GL backend runs the pcf_kernel square"},
      {"validate --no-report --spp 1 --sweep shadow_depth_format=depth32f,depth16",
       "settings: the GL backend runs the pcf_kernel square"},
      // An engine's PCF variants (issue 39), each refused by validate with one line.
      {"validate --no-report --spp 1 --set shadow_border=shadowed", "settings: the GL backend runs one texel PCF kernel"},
      {"validate --no-report --spp 1 --set shadow_filter_order=filter_then_compare",
       "settings: the GL backend runs one texel PCF kernel"},
      {"validate --no-report --spp 1 --set pcf_tap_unit=uv", "settings: the GL backend runs one texel PCF kernel"},
      {"validate --no-report --spp 1 --set pcf_tap_scale=inv_w --set shadow_normal_offset=0",
       "settings: the GL backend runs one texel PCF kernel"},
      {"validate --no-report --spp 1 --set voxel_pcf_taps=0,0", "settings: the GL backend runs one texel PCF kernel"},
      // validate opens its GL context after the run directory exists: the device is checked first.
      {"validate --no-report --spp 1 --gl-device 99", "--gl-device: no EGL device 99"},
      {"validate --no-report --spp 1 --gl-device no-such-gpu", "--gl-device: no EGL device matches 'no-such-gpu'"},
      {"metamorphic --backend gl" + cfg, "settings: the GL backend runs the pcf_kernel square"},
  };
  bool no_gl_build = false;
  for (const Case& c : cases) {
    // Without GL, validate records the GL frame as unavailable and runs on: nothing refused.
    if (no_gl_build && c.args.rfind("validate", 0) == 0) continue;
    const std::filesystem::path out = test::temp_dir() / "refused_run";
    std::filesystem::remove_all(out);
    const Result r = vct(c.args + " " + kSmall + " --out '" + out.string() + "'");
    // A build without GL (VCT_BUILD_GL=OFF) refuses every GL frame as unavailable, exit 3.
    no_gl_build = no_gl_build || r.err.find("GL backend not built") != std::string::npos;
    EXPECT_EQ(r.exit_code, no_gl_build ? 3 : 2) << c.args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << c.args << ": " << r.err;
    if (!no_gl_build) {
      EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.args << ": " << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(out)) << c.args << " left its run directory behind";
  }
  // Taps per 1/w have no fixed footprint for the normal offset: refused by every backend.
  const Result inv_w = vct("render --backend ref --set pcf_tap_scale=inv_w " + std::string(kSmall) + " --out '" +
                           (test::temp_dir() / "refused_inv_w").string() + "'");
  EXPECT_EQ(inv_w.exit_code, 2) << inv_w.err;
  EXPECT_NE(inv_w.err.find("pcf_tap_scale = inv_w needs shadow_normal_offset = 0"), std::string::npos) << inv_w.err;
  // The reference runs the same setting.
  const std::filesystem::path out = test::temp_dir() / "ref_depth16";
  const Result ok = vct("render --backend ref" + cfg + kSmall + " --out '" + out.string() + "'");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(std::filesystem::exists(out / "final.exr"));
}

}  // namespace
}  // namespace vct
