// `vct info` end to end through the real binary: every committed scene prints, the built-in
// scene is the default, --json parses, and bad input is exactly one stderr line with exit 2.
#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <cstring>
#include <limits>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "../ref/gltf_test_doc.h"

namespace vct {
namespace {

struct Result {
  int exit_code = -1;
  std::string out, err;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Runs `vct <args>` with stdout and stderr captured to files (args are quoted by the caller).
Result vct(const std::string& args) {
  const std::string out = (test::temp_dir() / "stdout.txt").string(), err = (test::temp_dir() / "stderr.txt").string();
  const std::string cmd = std::string("'") + VCT_BINARY + "' " + args + " >'" + out + "' 2>'" + err + "'";
  const int status = std::system(cmd.c_str());
  Result r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

std::string scene(const std::string& name) { return std::string("'") + VCT_SOURCE_DIR + "/scenes/" + name + "'"; }

size_t lines(const std::string& s) {
  size_t n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

TEST(CliInfo, BuiltInSceneWhenNoArgument) {
  const Result r = vct("info");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("scene: builtin:cornell_box"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("triangles: 2382"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("'ceiling_spot'"), std::string::npos);
  EXPECT_NE(r.out.find("voxel volume: origin"), std::string::npos);
  EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST(CliInfo, PrintsEveryCommittedScene) {
  const std::pair<const char*, const char*> expected[] = {
      {"cornell_box.gltf", "triangles: 2382"},   {"demo_room.gltf", "particle emitters: 2"},
      {"furnace_sphere.gltf", "triangles: 3968"}, {"plane_spot.gltf", "intensity 10 cd"},
      {"tiny_triangles.gltf", "triangles: 45002"}, {"thin_wall.gltf", "triangles: 24"},
      {"sun_room.gltf", "'sun' directional: direction"}, {"sun_room.gltf", "'lamp_front' point: position"}};
  for (const auto& [file, text] : expected) {
    const Result r = vct("info " + scene(file));
    ASSERT_EQ(r.exit_code, 0) << file << ": " << r.err;
    EXPECT_NE(r.out.find(text), std::string::npos) << file << "\n" << r.out;
    EXPECT_NE(r.out.find("camera (from file)"), std::string::npos) << file;
  }
}

TEST(CliInfo, JsonSummaryParses) {
  const Result r = vct("info --json " + scene("demo_room.gltf"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["triangles"], 4104);
  EXPECT_EQ(j["textures"].size(), 3u);
  EXPECT_EQ(j["particle_emitters"].size(), 2u);
  EXPECT_EQ(j["materials"][1]["normal_two_channel"], true);
  EXPECT_EQ(j["volume"]["default_grid"], 128);
}

TEST(CliInfo, BadInputIsOneLineAndExitCode2) {
  test::GltfDoc cycle = test::quad_doc();
  cycle.j["nodes"].push_back({{"children", {2}}});
  cycle.j["nodes"].push_back({{"children", {1}}});
  test::GltfDoc nan = test::quad_doc();
  const float qnan = std::numeric_limits<float>::quiet_NaN();
  std::memcpy(&nan.bin[0], &qnan, 4);
  const std::string files[] = {
      (test::temp_dir() / "nope.gltf").string(),
      test::temp_dir().string(),
      test::write_file("empty.gltf", ""),
      test::write_file("broken.gltf", "{\"asset\": {"),
      test::write_file("v1.gltf", "{\"asset\": {\"version\": \"1.0\"}}"),
      test::write_file("bad.glb", "glTF\x01\x00\x00\x00\x10\x00\x00\x00"),
      test::write_file("cycle.gltf", cycle.text()),
      test::write_file("nan.gltf", nan.text()),
  };
  for (const std::string& f : files) {
    const Result r = vct("info '" + f + "'");
    EXPECT_EQ(r.exit_code, 2) << f;
    EXPECT_EQ(lines(r.err), 1u) << r.err;
    EXPECT_NE(r.err.find(f + ": "), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

}  // namespace
}  // namespace vct
