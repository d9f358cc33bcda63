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
#include "compare/stage_set.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

std::string gl_map() { return std::string(VCT_SOURCE_DIR) + "/tools/import_capture/vct_gl_map.json"; }

// Why RenderDoc cannot be used here ("" when it can).
std::string renderdoc_missing() {
  if (std::system("command -v renderdoccmd > /dev/null 2>&1") != 0) return "renderdoccmd not installed (apt-get install renderdoccmd)";
  if (std::system("/usr/bin/python3 -c 'import renderdoc' > /dev/null 2>&1") != 0)
    return "python3-renderdoc not installed for /usr/bin/python3 (apt-get install python3-renderdoc)";
  return "";
}

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
  if (const std::string why = renderdoc_missing(); !why.empty()) GTEST_SKIP() << why;
  const fs::path dir = test::fresh_dir("import_not_rdc");
  { std::ofstream(dir / "frame.rdc") << "not a capture"; }
  const auto r = test::run_vct_captured("import-capture " + q(dir / "frame.rdc") + " --map " + q(gl_map()) + " --out " + q(dir / "out"));
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("not a readable RenderDoc capture"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(ImportCaptureCli, OurGlFrameImportsToItsOwnDump) {
  if (const std::string why = renderdoc_missing(); !why.empty()) GTEST_SKIP() << why;
  const fs::path dir = test::fresh_dir("import_gl");
  // The map's mip chain is the 64^3 grid's (levels 1..6).
  const std::string render = "render --backend gl --width 64 --height 48 --grid 64 --shadow-map-size 256 --dump --out ";
  if (test::run_vct(render + q(dir / "probe")) == 3) GTEST_SKIP() << "no GL context";
  const std::string capture_cmd = "renderdoccmd capture -w -c " + q(dir / "frame") + " '" + std::string(VCT_BINARY) + "' " + render +
                                  q(dir / "run") + " > " + q(dir / "capture.log") + " 2>&1";
  ASSERT_EQ(std::system(capture_cmd.c_str()), 0) << test::slurp(dir / "capture.log");
  const fs::path rdc = dir / "frame_capture.rdc";  // RenderDoc appends "_capture" to the template
  ASSERT_TRUE(fs::exists(rdc)) << test::slurp(dir / "capture.log");
  const auto r = test::run_vct_captured("import-capture " + q(rdc) + " --map " + q(gl_map()) + " --out " + q(dir / "imported"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
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
  // And vct compare judges the pair identical.
  EXPECT_EQ(test::run_vct("compare " + q(dir / "run") + " " + q(dir / "imported")), 0);
}

}  // namespace
}  // namespace vct
