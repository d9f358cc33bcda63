// Issue 38 through the real binary: deep JSON in --config and in a stage-set manifest, a --config
// that is a directory or holds 1e999, a FIFO or /dev/zero as the scene, non-finite and fractional
// settings. Each is exit 2 with one stderr line (never a stack overflow, a hang or "internal error").
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <fstream>

#include "../ref/gltf_test_doc.h"
#include "cli_run_util.h"

namespace vct {
namespace {

namespace fs = std::filesystem;
using test::run_vct_captured;

std::string deep_json(size_t levels) { return std::string(levels, '[') + std::string(levels, ']'); }

fs::path write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

// Exit 2, one line on stderr that contains `expected`.
void expect_refused(const std::string& args, const std::string& expected) {
  const test::VctOutput r = run_vct_captured(args);
  EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err.substr(0, 500);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err.substr(0, 500);
  EXPECT_NE(r.err.find(expected), std::string::npos) << args << "\n" << r.err.substr(0, 500);
}

TEST(HostileInputCli, DeepConfigIsExitTwo) {
  const fs::path dir = test::fresh_dir("deep_config");
  const fs::path config = write(dir / "deep.json", "{\"vct\": " + deep_json(300000) + "}");
  expect_refused("render --out '" + (dir / "out").string() + "' --config '" + config.string() + "'",
                 "nests deeper than 128 levels");
}

TEST(HostileInputCli, ConfigThatIsADirectoryOrHoldsAHugeNumberIsExitTwo) {
  const fs::path dir = test::fresh_dir("config_kinds");
  expect_refused("render --out '" + (dir / "out").string() + "' --config '" + dir.string() + "'",
                 "is a directory, not a settings file");
  const fs::path big = write(dir / "big.json", "{\"vct\": {\"shadow_bias\": 1e999}}");
  expect_refused("render --out '" + (dir / "out").string() + "' --config '" + big.string() + "'", "broken JSON");
}

TEST(HostileInputCli, DeepStageSetManifestIsExitTwo) {
  const fs::path dir = test::fresh_dir("deep_manifest");
  fs::create_directories(dir / "ext");
  write(dir / "ext" / "vct-stages.json", "{\"format\": \"vct-stages\", \"info\": " + deep_json(300000) + "}");
  const std::string ext = (dir / "ext").string();
  expect_refused("compare '" + ext + "' '" + ext + "'", "nests deeper than 128 levels");
}

TEST(HostileInputCli, FifoAndDeviceAsSceneAreRefusedAtOnce) {
  const fs::path dir = test::fresh_dir("fifo_scene");
  const fs::path pipe = dir / "scene.gltf";
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  expect_refused("info '" + pipe.string() + "'", "is not a regular file");
  expect_refused("info /dev/zero", "/dev/zero: is not a regular file");
}

TEST(HostileInputCli, NonFiniteAndFractionalSettingsAreExitTwo) {
  const fs::path dir = test::fresh_dir("bad_settings");
  const std::string out = " --out '" + (dir / "out").string() + "'";
  expect_refused("render --time nan" + out, "vct.time' is not a finite number");
  expect_refused("render --offset inf" + out, "vct.cone_offset_voxels' is not a finite number");
  const fs::path threads = write(dir / "threads.json", "{\"threads\": 2.7}");
  expect_refused("render --config '" + threads.string() + "'" + out, "'threads' = 2.7 is not an integer");
  const fs::path huge = write(dir / "huge.json", "{\"vct\": {\"shadow_bias\": 1e39}}");
  expect_refused("render --config '" + huge.string() + "'" + out, "vct.shadow_bias' is not a finite number");
  EXPECT_FALSE(fs::exists(dir / "out"));  // refused before the run directory is created
}

// A voxel.radiance with 1 of its 4 channels passed `vct compare` (issue 38): the set is refused.
TEST(HostileInputCli, StageWithFewerChannelsThanItsRowIsExitTwo) {
  const fs::path dir = test::fresh_dir("one_channel");
  fs::create_directories(dir / "ext");
  std::string nrrd = "NRRD0004\ntype: float\ndimension: 3\nsizes: 2 2 2\nendian: little\nencoding: raw\n\n";
  nrrd += std::string(8 * sizeof(float), '\0');
  write(dir / "ext" / "radiance.nrrd", nrrd);
  write(dir / "ext" / "vct-stages.json",
        R"({"format": "vct-stages", "stages": {"voxel.radiance": {"file": "radiance.nrrd", "kind": "volume"}}})");
  const std::string ext = (dir / "ext").string();
  expect_refused("compare '" + ext + "' '" + ext + "'", "stage 'voxel.radiance' has 1 channel(s), but it needs 4");
}

}  // namespace
}  // namespace vct
