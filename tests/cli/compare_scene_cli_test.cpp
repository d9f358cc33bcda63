// `vct compare A B --scene SCENE` through the real binary: cone stages judged on B's own inputs
// give exactly validate's isolated verdicts, a correct marcher on different voxels passes where
// the end-to-end judgement fails, a wrong cone image still fails, and bad input is one line,
// exit 2, no compare.json. Small sizes (64x64, 64^3) keep every run under a few seconds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "cli_run_util.h"
#include "core/image.h"
#include "io/image_io.h"

namespace vct {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using Result = test::VctOutput;

Result vct(const std::string& args) { return test::run_vct_captured(args); }

json read_json(const fs::path& p) {
  std::ifstream in(p);
  EXPECT_TRUE(in.good()) << p;
  return in.good() ? json::parse(in) : json::object();
}

std::string scene(const std::string& name) { return std::string(VCT_SOURCE_DIR) + "/scenes/" + name; }

// `vct validate` at 64x64, 64^3, 1 spp; writes ref/ (and gl/ when there is a GL context).
json validate(const std::string& scene_file, const fs::path& out, const std::string& vct_json) {
  std::string config;
  if (!vct_json.empty()) {
    config = (out.string() + ".json");
    std::ofstream(config) << R"({"vct": )" << vct_json << "}";
    config = " --config '" + config + "'";
  }
  const Result r = vct("validate '" + scene_file + "' --no-report --width 64 --height 64 --grid 64 --spp 1" + config +
                       " --out '" + out.string() + "'");
  EXPECT_NE(r.exit_code, 2) << r.err;
  return read_json(out / "run.json");
}

std::map<std::string, json> by_stage(const json& verdicts) {
  std::map<std::string, json> m;
  for (json s : verdicts["stages"]) {
    s.erase("mask");  // validate writes masks under compare/, compare under masks/
    m[s["stage"].get<std::string>()] = s;
  }
  return m;
}

// Two CPU-reference stage sets of tiny_triangles that differ only in the voxels: the GPU rule
// (reference, A) and the conservative voxelizer (test, B). Both marchers are the same correct code,
// so B's cone images differ end to end (420 extra voxels) but not on B's own voxels.
class CompareScene : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(test::fresh_dir("compare_scene"));
    validate(scene("tiny_triangles.gltf"), *dir_ / "gpu", R"({"voxelizer": "gpu", "msaa_samples": 4})");
    validate(scene("tiny_triangles.gltf"), *dir_ / "cons", R"({"voxelizer": "conservative", "msaa_samples": 4})");
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string a() { return (*dir_ / "gpu" / "ref").string(); }
  static std::string b() { return (*dir_ / "cons" / "ref").string(); }
  static fs::path* dir_;
};
fs::path* CompareScene::dir_ = nullptr;

TEST_F(CompareScene, CorrectMarcherOnOtherVoxelsPassesIsolatedAndFailsEndToEnd) {
  const fs::path e2e = *dir_ / "out_e2e", iso = *dir_ / "out_iso";
  const Result r0 = vct("compare '" + a() + "' '" + b() + "' --out '" + e2e.string() + "'");
  EXPECT_EQ(r0.exit_code, 1) << r0.err;  // voxel.occupancy fails either way: 420 extra voxels
  EXPECT_NE(r0.out.find("--scene SCENE judges them on B's own inputs"), std::string::npos) << r0.out;
  const Result r1 = vct("compare '" + a() + "' '" + b() + "' --scene '" + scene("tiny_triangles.gltf") + "' --out '" +
                        iso.string() + "'");
  EXPECT_EQ(r1.exit_code, 1) << r1.err;
  const json j0 = read_json(e2e / "compare.json"), j1 = read_json(iso / "compare.json");
  EXPECT_EQ(j0["cone_stages"], "end_to_end");
  EXPECT_EQ(j1["cone_stages"], "isolated");
  const auto s0 = by_stage(j0["verdicts"]), s1 = by_stage(j1["verdicts"]);
  EXPECT_EQ(s0.at("voxel.occupancy"), s1.at("voxel.occupancy"));  // upstream stages untouched
  for (const char* stage : {"image.indirect_diffuse", "image.indirect_specular", "image.diffuse_term", "image.final"}) {
    // End to end the conservative voxels change a quarter of the indirect pixels (2444 of 4096
    // for indirect_diffuse when measured); on B's own voxels the reference re-traces B's images
    // bit for bit.
    EXPECT_EQ(s0.at(stage)["verdict"], "fail") << stage;
    EXPECT_GT(s0.at(stage)["out_of_bound"].get<int>(), 100) << stage;
    EXPECT_EQ(s1.at(stage)["verdict"], "warn") << stage;  // isolated pass, end to end not: warn
    EXPECT_EQ(s1.at(stage)["max_abs"].get<double>(), 0.0) << stage;
    EXPECT_EQ(s1.at(stage)["out_of_bound"].get<int>(), 0) << stage;
    EXPECT_EQ(s1.at(stage)["extra"]["end_to_end"]["verdict"], "fail") << stage;
    EXPECT_EQ(s1.at(stage)["extra"]["end_to_end"]["max_abs"], s0.at(stage)["max_abs"]) << stage;
  }
}

TEST_F(CompareScene, WrongConeImageStillFailsIsolated) {
  // A marcher bug: B's indirect diffuse 50 % too bright in a 16x16 block.
  const fs::path broken = *dir_ / "broken";
  fs::remove_all(broken);
  fs::copy(b(), broken, fs::copy_options::recursive);
  Image img = read_image((broken / "image_indirect_diffuse.exr").string());
  for (int y = 24; y < 40; ++y)
    for (int x = 24; x < 40; ++x) img.set_rgb(x, y, img.rgb(x, y) * 1.5f);
  write_exr((broken / "image_indirect_diffuse.exr").string(), img);
  const fs::path out = *dir_ / "out_broken";
  const Result r = vct("compare '" + b() + "' '" + broken.string() + "' --scene '" + scene("tiny_triangles.gltf") +
                       "' --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const auto s = by_stage(read_json(out / "compare.json")["verdicts"]);
  EXPECT_EQ(s.at("image.indirect_diffuse")["verdict"], "fail");
  EXPECT_EQ(s.at("image.indirect_diffuse")["extra"]["end_to_end"]["verdict"], "fail");
  EXPECT_EQ(s.at("image.indirect_specular")["verdict"], "pass");  // B against itself, untouched
}

void expect_bad_input(const std::string& args, const fs::path& out, const std::string& names) {
  const Result r = vct(args + " --out '" + out.string() + "'");
  EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
  EXPECT_NE(r.err.find(names), std::string::npos) << args << ": " << r.err;
  EXPECT_FALSE(fs::exists(out / "compare.json")) << args;
  EXPECT_FALSE(fs::exists(out / "masks")) << args;
}

TEST_F(CompareScene, BadInputIsOneLineExitTwoAndWritesNothing) {
  const std::string ab = "compare '" + a() + "' '" + b() + "'";
  const fs::path out = *dir_ / "out_bad";
  expect_bad_input(ab + " --scene /no/such/scene.gltf", out, "/no/such/scene.gltf");
  // B without its mip chain: nothing to re-trace the cones in.
  const fs::path no_mips = *dir_ / "no_mips";
  fs::remove_all(no_mips);
  fs::copy(b(), no_mips, fs::copy_options::recursive);
  json m = read_json(no_mips / "vct-stages.json");
  for (auto it = m["stages"].begin(); it != m["stages"].end();)
    it = it.key().rfind("mip.", 0) == 0 ? m["stages"].erase(it) : std::next(it);
  std::ofstream(no_mips / "vct-stages.json") << m.dump(1);
  const std::string tiny = " --scene '" + scene("tiny_triangles.gltf") + "'";
  expect_bad_input("compare '" + a() + "' '" + no_mips.string() + "'" + tiny, out, "stage 'mip.iso.1' is missing");
  // The Cornell box's camera does not see tiny_triangles' G-buffer.
  expect_bad_input(ab + " --scene '" + scene("cornell_box.gltf") + "'", out, "wrong --scene");
  // Settings that describe another grid than B's voxels.
  std::ofstream(*dir_ / "grid128.json") << R"({"vct": {"grid": 128}})";
  expect_bad_input(ab + tiny + " --config '" + (*dir_ / "grid128.json").string() + "'", out, "grid = 128");
  expect_bad_input(ab + " --config '" + (*dir_ / "grid128.json").string() + "'", out, "only used with --scene");
}

// With a GL context: `vct compare RUN RUN --scene` on a validate run directory reproduces
// validate's verdicts stage for stage (isolated cone stages included), and without --scene the
// cone stages are validate's recorded end-to-end verdicts.
TEST(CompareSceneGl, SameVerdictsAsValidate) {
  const fs::path dir = test::fresh_dir("compare_scene_gl");
  const json run = validate(scene("tiny_triangles.gltf"), dir / "run", "");
  if (run["backends"]["gl"]["status"] != "ok") GTEST_SKIP() << "no GL: " << run["backends"]["gl"]["status"];
  const std::string rr = "compare '" + (dir / "run").string() + "' '" + (dir / "run").string() + "'";
  const Result r1 = vct(rr + " --scene '" + scene("tiny_triangles.gltf") + "' --out '" + (dir / "iso").string() + "'");
  ASSERT_NE(r1.exit_code, 2) << r1.err;
  EXPECT_EQ(r1.exit_code, run["exit_code"].get<int>());
  const json iso = read_json(dir / "iso" / "compare.json")["verdicts"];
  EXPECT_EQ(iso["overall"], run["verdicts"]["overall"]);
  EXPECT_EQ(iso["first_failing"], run["verdicts"]["first_failing"]);
  const auto v = by_stage(run["verdicts"]), c = by_stage(iso);
  ASSERT_EQ(v.size(), c.size());
  int isolated = 0;
  for (const auto& [stage, verdict] : v) {
    EXPECT_EQ(c.at(stage), verdict) << stage;
    isolated += verdict["extra"].contains("end_to_end");
  }
  // indirect_diffuse, indirect_specular, diffuse_term, specular_term, final; direct and emission
  // (on the test's own G-buffer and shadow maps). voxel.radiance is re-injected through the
  // test's own shadow maps only where end to end it counted shading ties (none here).
  EXPECT_EQ(isolated, 7);
  const Result r0 = vct(rr + " --out '" + (dir / "e2e").string() + "'");
  ASSERT_NE(r0.exit_code, 2) << r0.err;
  const auto e = by_stage(read_json(dir / "e2e" / "compare.json")["verdicts"]);
  for (const auto& [stage, verdict] : v) {
    if (!verdict["extra"].contains("end_to_end")) continue;
    const json& recorded = verdict["extra"]["end_to_end"];
    EXPECT_EQ(e.at(stage)["verdict"], recorded["verdict"]) << stage;
    EXPECT_EQ(e.at(stage)["rms"], recorded["rms"]) << stage;
    EXPECT_EQ(e.at(stage)["max_abs"], recorded["max_abs"]) << stage;
  }
}

}  // namespace
}  // namespace vct
