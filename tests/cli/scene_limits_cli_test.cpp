// The three inputs of issue 19 through the real binary: each is refused with one stderr line and
// exit 2 (20 000-deep nesting used to end `vct info` with SIGSEGV, exit 139), and every command
// that loads a scene takes --allow-outside-scene-dir.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <fstream>

#include "../ref/gltf_test_doc.h"
#include "cli_run_util.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

struct Result {
  int exit_code = -1;
  std::string out, err;
};

Result vct(const std::string& args) {
  const fs::path out = test::scratch_root() / "stdout.txt", err = test::scratch_root() / "stderr.txt";
  fs::create_directories(test::scratch_root());
  const std::string cmd = std::string("'") + VCT_BINARY + "' " + args + " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::slurp(out), test::slurp(err)};
}

// scene/<name>.gltf: the test quad with one texture `uri`.
fs::path textured(const fs::path& dir, const std::string& name, const std::string& uri) {
  test::GltfDoc d = test::quad_doc();
  d.j["images"] = {{{"uri", uri}}};
  d.j["textures"] = {{{"source", 0}}};
  d.j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
  const fs::path p = dir / (name + ".gltf");
  std::ofstream(p, std::ios::binary) << d.text();
  return p;
}

void expect_refused(const Result& r, const std::string& needle) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
}

TEST(SceneLimitsCli, TwentyThousandDeepNestingExitsTwoNotSigsegv) {
  const fs::path dir = test::fresh_dir("deep");
  const std::string text = test::quad_doc().text();
  std::ofstream(dir / "deep.gltf") << "{\"extras\":" << std::string(20000, '[') << std::string(20000, ']') << ","
                                   << text.substr(1);
  expect_refused(vct("info '" + (dir / "deep.gltf").string() + "'"), "JSON nests deeper than 128 levels");
}

TEST(SceneLimitsCli, EtcPasswdUriIsRefusedNamingTheUri) {
  const fs::path dir = test::fresh_dir("passwd");
  const fs::path scene = textured(dir, "passwd", "../../../../../../etc/passwd");
  expect_refused(vct("info '" + scene.string() + "'"), "images[0] uri '../../../../../../etc/passwd' is refused");
}

TEST(SceneLimitsCli, HugePngHeaderIsRefusedWithItsSize) {
  const fs::path dir = test::fresh_dir("huge");
  std::string png("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\x01\x86\xa0\0\x01\x86\xa0\x08\x06\0\0\0\0\0\0\0", 33);
  std::ofstream(dir / "huge.png", std::ios::binary) << png;
  expect_refused(vct("info '" + textured(dir, "huge", "huge.png").string() + "'"),
                 "its PNG header says 100000 x 100000 pixels");
}

TEST(SceneLimitsCli, AllowOutsideSceneDirReadsTheFileOutside) {
  const fs::path dir = test::fresh_dir("outside");
  fs::create_directories(dir / "scene");
  // A real texture beside the scene's folder: refused by default, read with the flag.
  fs::copy_file(fs::path(VCT_SOURCE_DIR) / "scenes" / "textures" / "brick_albedo.png", dir / "brick.png");
  const fs::path scene = textured(dir / "scene", "out", "../brick.png");
  expect_refused(vct("info '" + scene.string() + "'"), "uri '../brick.png' is refused");
  const Result ok = vct("info --allow-outside-scene-dir --json '" + scene.string() + "'");
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_NE(ok.out.find("\"width\": 64"), std::string::npos) << ok.out;  // the 64 x 64 brick texture
}

TEST(SceneLimitsCli, EveryCommandThatLoadsASceneTakesTheFlag) {
  for (const char* cmd : {"info", "render", "pathtrace", "validate", "bench", "compare"}) {
    const Result r = vct(std::string(cmd) + " --help");
    EXPECT_EQ(r.exit_code, 0) << cmd;
    EXPECT_NE(r.out.find("--allow-outside-scene-dir"), std::string::npos) << cmd << " --help:\n" << r.out;
  }
}

}  // namespace
}  // namespace vct
