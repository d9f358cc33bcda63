// `vct import-capture` end to end: a bad map or capture is one line, exit 2, nothing written; and
// with RenderDoc installed (scripts/setup.sh: renderdoccmd, python3-renderdoc), a capture of our
// own GL frame, imported with tools/import_capture/vct_gl_map.json, holds exactly the stages
// `vct render --backend gl --dump` wrote. Skipped, with the reason, without RenderDoc or GL.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "cli_run_util.h"
#include "renderdoc_available.h"
#include "compare/stage_set.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

std::string gl_map() { return std::string(VCT_SOURCE_DIR) + "/tools/import_capture/vct_gl_map.json"; }

TEST(ImportCaptureCli, BadMapIsOneLineExit2AndWritesNothing) {
  const fs::path dir = test::fresh_dir("import_bad_map");
  const fs::path map = dir / "map.json", out = dir / "out";
  { std::ofstream(map) << R"({"format": "vct-capture-map", "version": 1, "stages": {"image.final": {"resourse": "x"}}})"; }
  { std::ofstream(dir / "frame.rdc") << "not a capture"; }
  const auto r = test::run_vct_captured("import-capture " + q(dir / "frame.rdc") + " --map " + q(map) + " --out " + q(out));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown key 'resourse' in stage 'image.final'"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
  // A missing capture: the map is fine, the file is not there.
  const auto missing = test::run_vct_captured("import-capture " + q(dir / "none.rdc") + " --map " + q(gl_map()) + " --out " + q(out));
  EXPECT_EQ(missing.exit_code, 2) << missing.err;
  EXPECT_NE(missing.err.find("no such capture file"), std::string::npos) << missing.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST(ImportCaptureCli, NotACaptureIsExit2) {
  if (const std::string why = test::renderdoc_missing(); !why.empty()) GTEST_SKIP() << why;
  const fs::path dir = test::fresh_dir("import_not_rdc");
  { std::ofstream(dir / "frame.rdc") << "not a capture"; }
  const auto r = test::run_vct_captured("import-capture " + q(dir / "frame.rdc") + " --map " + q(gl_map()) + " --out " + q(dir / "out"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("not a readable RenderDoc capture"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// The oracle's own settings for a GL run judged against the reference (app/validate_run.cpp: the
// GPU's coverage rule, the deterministic reduction); the map's mip chain is the 64^3 grid's.
const std::string kFrame = "--backend gl --width 64 --height 48 --grid 64 --shadow-map-size 256 --voxelizer gpu --reduction fixed ";

// Renders `render_args` under renderdoccmd into dir/run and imports dir/frame_capture.rdc into
// dir/imported; "" or why not.
std::string capture_and_import(const fs::path& dir, const std::string& render_args) {
  // One capture at a time across test processes (flock, util-linux): two captures at once share
  // RenderDoc's target-control port; a full ctest -j2 run, where both tests overlap, failed once.
  const fs::path lock = fs::temp_directory_path() / "vct-renderdoc-capture.lock";
  const std::string capture_cmd = "flock " + q(lock) + " renderdoccmd capture -w -d " + q(dir) + " -c " + q(dir / "frame") + " '" + std::string(VCT_BINARY) +
                                  "' render " + render_args + " --out " + q(dir / "run") + " > " + q(dir / "capture.log") + " 2>&1";
  // Not its exit code: renderdoccmd reports "Couldn't connect to target program" when a short run
  // exits before its target-control handshake, though the capture is written (the library is
  // preloaded into the program, which captures itself, gl_renderdoc.h).
  (void)std::system(capture_cmd.c_str());
  const fs::path rdc = dir / "frame_capture.rdc";  // RenderDoc appends "_capture" to the template
  if (!fs::exists(rdc)) return "no capture written: " + test::slurp(dir / "capture.log");
  const auto r = test::run_vct_captured("import-capture " + q(rdc) + " --map " + q(gl_map()) + " --out " + q(dir / "imported"));
  return r.exit_code == 0 ? "" : "import-capture: " + r.err;
}

TEST(ImportCaptureCli, OurGlFrameImportsToItsOwnDump) {
  if (const std::string why = test::capture_impossible(); !why.empty()) GTEST_SKIP() << why;
  const fs::path dir = test::fresh_dir("import_gl");
  if (test::run_vct("render " + kFrame + "--out " + q(dir / "probe")) == 3) GTEST_SKIP() << "no GL context";
  ASSERT_EQ(capture_and_import(dir, kFrame + "--dump"), "");
  const cmp::StageSet dumped = cmp::read_stage_set((dir / "run").string());
  const cmp::StageSet imported = cmp::read_stage_set((dir / "imported").string());
  EXPECT_EQ(imported.images.size() + imported.volumes.size(), 25u);
  for (const auto& [name, img] : imported.images) {
    ASSERT_TRUE(dumped.images.count(name)) << name;
    const Image& d = dumped.images.at(name);
    ASSERT_EQ(d.width, img.width) << name;
    ASSERT_EQ(d.channels, img.channels) << name;
    EXPECT_EQ(d.data, img.data) << name;  // the same texture, read by RenderDoc instead of glGetTextureImage
  }
  for (const auto& [name, vol] : imported.volumes) {
    ASSERT_TRUE(dumped.volumes.count(name)) << name;
    const Volume& d = dumped.volumes.at(name);
    ASSERT_EQ(d.channels, vol.channels) << name;
    EXPECT_EQ(d.data, vol.data) << name;
  }
}

// The docs' worked example (docs/external_format.md, "From a RenderDoc capture"): capture, import,
// render the reference with the run's facts, compare. A correct frame passes; a frame with a bug
// compiled in (gl_faults.h: iso mip l built from level l-2) fails first at mip.iso.2.
TEST(ImportCaptureCli, ACapturedFrameIsJudgedAndItsBugFoundAtItsStage) {
  if (const std::string why = test::capture_impossible(); !why.empty()) GTEST_SKIP() << why;
  const fs::path root = test::fresh_dir("import_judged");
  if (test::run_vct("render " + kFrame + "--out " + q(root / "probe")) == 3) GTEST_SKIP() << "no GL context";
  for (const std::string fault : {"", "wrong_mip"}) {
    const fs::path dir = root / (fault.empty() ? "clean" : fault);
    fs::create_directories(dir);
    ASSERT_EQ(capture_and_import(dir, kFrame + (fault.empty() ? "" : "--gl-fault " + fault)), "");
    const std::string ref_args = "render --backend ref --width 64 --height 48 --grid 64 --shadow-map-size 256 --voxelizer gpu "
                                 "--reduction fixed --dump --facts-from " + q(dir / "run" / "run.json") + " --out " + q(dir / "ref");
    ASSERT_EQ(test::run_vct(ref_args), 0);
    const auto verdict = test::run_vct_captured("compare " + q(dir / "ref") + " " + q(dir / "imported"));
    if (fault.empty()) {
      EXPECT_EQ(verdict.exit_code, 0) << verdict.out;
    } else {
      EXPECT_EQ(verdict.exit_code, 1) << verdict.out;
      EXPECT_NE(verdict.out.find("first failing stage: mip.iso.2"), std::string::npos) << verdict.out;
    }
  }
}

}  // namespace
}  // namespace vct
