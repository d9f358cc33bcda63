// Core glTF features that change a still frame, through the real binary on variants of the
// Cornell box: an orthographic camera renders parallel in every engine and validates, and the
// loader's warnings reach stderr and run.json on the commands that render (docs/scenes.md).
#include <gtest/gtest.h>

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

json cornell_box() {
  std::ifstream in(std::string(VCT_SOURCE_DIR) + "/scenes/cornell_box.gltf");
  return json::parse(in);
}

std::string write_scene(const std::string& name, const json& doc) {
  const fs::path dir = test::fresh_dir(name);
  const fs::path file = dir / (name + ".gltf");
  std::ofstream(file) << doc.dump();
  return file.string();
}

json read_json(const fs::path& p) {
  std::ifstream in(p);
  return in.good() ? json::parse(in) : json::object();
}

// The box spans x in [-1, 1] (its side walls are the planes x = +-1). Seen orthographically along
// -z with half height ymag, it covers 2 / (2 ymag) of the image's height in columns, at any depth;
// a perspective view of the same box fills the whole 64x64 image.
TEST(SceneFeaturesCli, OrthographicCameraRendersParallelAndValidates) {
  json doc = cornell_box();
  const double ymag = 1.25;
  doc["cameras"][0] = {{"type", "orthographic"},
                       {"orthographic", {{"xmag", ymag}, {"ymag", ymag}, {"znear", 0.05}, {"zfar", 100.0}}}};
  const std::string scene = write_scene("ortho", doc);
  const fs::path out = test::fresh_dir("ortho_validate");
  const Result r = vct("validate '" + scene + "' --no-report --width 64 --height 64 --grid 32 --spp 4 --out '" +
                       out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;  // ref and gl agree stage by stage: no FAIL
  const json run = read_json(out / "run.json");
  EXPECT_EQ(run["verdicts"].value("first_failing", ""), "");

  const Image cov = read_image((out / "ref" / "gbuffer_coverage.exr").string());
  int lo = cov.width, hi = -1;
  for (int y = 0; y < cov.height; ++y)
    for (int x = 0; x < cov.width; ++x)
      if (cov.at(x, y, 0) > 0.0f) lo = std::min(lo, x), hi = std::max(hi, x);
  const double want = 64.0 * 2.0 / (2.0 * ymag);  // 51.2 columns, centred
  EXPECT_NEAR(double(hi - lo + 1), want, 1.0);
  EXPECT_NEAR(0.5 * double(lo + hi + 1), 32.0, 1.0);
}

// COLOR_0 (1, 1, 0) on every primitive: the base colour loses its blue in every engine, so every
// covered G-buffer albedo has b = 0 exactly on both backends (without vertex colours the white walls
// keep b = 0.73), and GL still matches the reference stage by stage.
TEST(SceneFeaturesCli, VertexColoursReachEveryEngine) {
  json doc = cornell_box();
  std::string bytes;
  std::map<int, int> accessor_of_count;  // one COLOR_0 accessor per vertex count
  for (json& mesh : doc["meshes"])
    for (json& prim : mesh["primitives"]) {
      const int count = doc["accessors"][prim["attributes"]["POSITION"].get<int>()]["count"];
      if (!accessor_of_count.count(count)) {
        const size_t at = bytes.size();
        for (int v = 0; v < count; ++v) bytes += std::string("\xff\xff\x00", 3);
        while (bytes.size() % 4) bytes += '\0';
        doc["bufferViews"].push_back({{"buffer", doc["buffers"].size()}, {"byteOffset", at}, {"byteLength", 3 * count}});
        doc["accessors"].push_back({{"bufferView", doc["bufferViews"].size() - 1},
                                    {"componentType", 5121},
                                    {"normalized", true},
                                    {"count", count},
                                    {"type", "VEC3"}});
        accessor_of_count[count] = int(doc["accessors"].size()) - 1;
      }
      prim["attributes"]["COLOR_0"] = accessor_of_count[count];
    }
  doc["buffers"].push_back({{"uri", "colours.bin"}, {"byteLength", bytes.size()}});
  const std::string scene = write_scene("coloured", doc);
  std::ofstream(fs::path(scene).parent_path() / "colours.bin", std::ios::binary) << bytes;
  const fs::path out = test::fresh_dir("coloured_validate");
  const Result r = vct("validate '" + scene + "' --no-report --width 32 --height 32 --grid 32 --spp 1 --out '" +
                       out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("COLOR_0"), std::string::npos) << r.err;
  for (const char* side : {"ref", "gl"}) {
    const Image cov = read_image((out / side / "gbuffer_coverage.exr").string());
    const Image albedo = read_image((out / side / "gbuffer_albedo.exr").string());
    int covered = 0, blue = 0;
    for (int y = 0; y < cov.height; ++y)
      for (int x = 0; x < cov.width; ++x) {
        if (cov.at(x, y, 0) <= 0.0f) continue;
        ++covered;
        blue += albedo.at(x, y, 2) != 0.0f;
      }
    EXPECT_GT(covered, 0) << side;
    EXPECT_EQ(blue, 0) << side;
  }
}

TEST(SceneFeaturesCli, LoadWarningsReachStderrAndRunJson) {
  json doc = cornell_box();
  for (json& n : doc["nodes"]) n.erase("extensions");  // the spot light's node keeps no light
  for (json& m : doc["materials"]) m.erase("emissiveFactor");
  const std::string scene = write_scene("unlit", doc);
  const fs::path out = test::fresh_dir("unlit_render");
  const Result r = vct("render '" + scene + "' --backend ref --width 16 --height 16 --grid 16 --out '" +
                       out.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("vct: warning: " + scene + ": the scene has no light"), std::string::npos) << r.err;
  const json run = read_json(out / "run.json");
  ASSERT_TRUE(run["scene"]["warnings"].is_array());
  ASSERT_EQ(run["scene"]["warnings"].size(), 1u);
  EXPECT_NE(run["scene"]["warnings"][0].get<std::string>().find("no light"), std::string::npos);

  const Result lit = vct("render --backend ref --width 16 --height 16 --grid 16 --out '" +
                         test::fresh_dir("lit_render").string() + "'");
  ASSERT_EQ(lit.exit_code, 0) << lit.err;
  EXPECT_EQ(lit.err.find("warning"), std::string::npos) << lit.err;  // the built-in scene has none
}

}  // namespace
}  // namespace vct
