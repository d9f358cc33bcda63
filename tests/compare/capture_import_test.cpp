// vct import-capture without RenderDoc (compare/capture_map.h, capture_import.h): the map's
// checks, and the stage set written from a fake reader's textures (rows, channels, manifest,
// all-or-nothing output). The RenderDoc replay itself: tests/cli/import_capture_cli_test.cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "compare/capture_import.h"
#include "core/error.h"

namespace vct::cmp {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

json good_map() {
  return json::parse(R"({
    "format": "vct-capture-map", "version": 1,
    "manifest": {"backend": "tiny", "reduction": "running_mean", "storage": "rgba16f",
                 "settings": {"grid": 2}, "facts": {"msaa_samples": 4},
                 "conventions": {"mip_scale": 1.5}},
    "stages": {
      "gbuffer.coverage": {"resource": "frame.colour", "channels": [3], "event": "Lighting"},
      "image.final": {"resource": "frame.colour", "channels": [0, 1, 2]},
      "voxel.radiance": {"resource": 17, "event": 42},
      "shadow_map.0": {"resource": "ResourceId::9", "slice": 1, "rows": "top_first"}
    }})");
}

std::string problem_of(const json& doc) {
  try {
    parse_capture_map(doc, "map.json");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CaptureMap, ReadsStagesInNameOrder) {
  const CaptureMap map = parse_capture_map(good_map(), "map.json");
  ASSERT_EQ(map.stages.size(), 4u);
  const CaptureStage& coverage = map.stages[0];
  EXPECT_EQ(coverage.name, "gbuffer.coverage");
  EXPECT_EQ(coverage.kind, "image");
  EXPECT_EQ(coverage.event, "Lighting");
  EXPECT_EQ(coverage.channels, std::vector<int>{3});
  EXPECT_TRUE(coverage.bottom_first);
  const CaptureStage& shadow = map.stages[2];
  EXPECT_EQ(shadow.name, "shadow_map.0");
  EXPECT_EQ(shadow.resource, "ResourceId::9");
  EXPECT_EQ(shadow.slice, 1);
  EXPECT_FALSE(shadow.bottom_first);
  const CaptureStage& voxels = map.stages[3];
  EXPECT_EQ(voxels.kind, "volume");
  EXPECT_EQ(voxels.resource, "17");
  EXPECT_EQ(voxels.event, "42");
  EXPECT_EQ(map.stages[1].event, "end");
}

TEST(CaptureMap, RefusesWhatItCannotRead) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"/format", "\"format\" must be \"vct-capture-map\""},
      {"/stages/image.final/resource", "needs a \"resource\""},
  };
  for (const auto& [pointer, expected] : cases) {
    json doc = good_map();
    const json::json_pointer p(pointer);
    doc[p.parent_pointer()].erase(p.back());
    EXPECT_NE(problem_of(doc).find(expected), std::string::npos) << pointer << ": " << problem_of(doc);
  }
  const std::vector<std::pair<std::string, json>> bad = {
      {"unknown key 'colour'", json{{"colour", 1}}},
      {"\"mip\" must be an integer", json{{"mip", -1}}},
      {"\"channels\" entries must be 0..3", json{{"channels", {4}}}},
      {"\"rows\" must be", json{{"rows", "upside_down"}}},
      {"must be an image", json{{"kind", "volume"}}},
      {"\"event\" must be", json{{"event", ""}}},
  };
  for (const auto& [expected, patch] : bad) {
    json doc = good_map();
    doc["stages"]["image.final"].update(patch);
    EXPECT_NE(problem_of(doc).find(expected), std::string::npos) << patch.dump() << ": " << problem_of(doc);
  }
  json no_kind = good_map();
  no_kind["stages"]["my.debug"] = {{"resource", "x"}};
  EXPECT_NE(problem_of(no_kind).find("say \"kind\""), std::string::npos);
  json bad_reduction = good_map();
  bad_reduction["manifest"]["reduction"] = "exactly";
  EXPECT_NE(problem_of(bad_reduction).find("unknown reduction 'exactly'"), std::string::npos);
  json bad_convention = good_map();
  bad_convention["manifest"]["conventions"]["mip_scael"] = 2;
  EXPECT_NE(problem_of(bad_convention).find("mip_scael"), std::string::npos) << problem_of(bad_convention);
  json wrong_type = good_map();
  wrong_type["manifest"]["storage"] = 3;
  EXPECT_NE(problem_of(wrong_type).find("bad capture map"), std::string::npos);
}

// Stands in for the RenderDoc replay: texture i of the map's order is the one given.
class FakeReader : public CaptureReader {
 public:
  explicit FakeReader(std::vector<CapturedTexture> textures) : textures_(std::move(textures)) {}
  std::vector<CapturedTexture> read(const std::string&, const std::vector<CaptureStage>& stages) override {
    asked = stages.size();
    return textures_;
  }
  size_t asked = 0;

 private:
  std::vector<CapturedTexture> textures_;
};

// A 2x2 RGBA texture, value = 10·texel + channel, texels in memory order.
CapturedTexture colour_2x2() {
  CapturedTexture t{2, 2, 1, 4, {}, "R32G32B32A32_FLOAT"};
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 4; ++c) t.data.push_back(float(10 * i + c));
  return t;
}

CapturedTexture depth_2x2() { return {2, 2, 1, 1, {0.1f, 0.2f, 0.3f, 0.4f}, "D32_FLOAT"}; }

CapturedTexture volume_2() {
  CapturedTexture t{2, 2, 2, 4, {}, "R16G16B16A16_FLOAT"};
  for (int i = 0; i < 32; ++i) t.data.push_back(float(i) / 32.0f);
  return t;
}

std::vector<CapturedTexture> textures_for_good_map() { return {colour_2x2(), colour_2x2(), depth_2x2(), volume_2()}; }

TEST(CaptureImport, FlipsGlRowsKeepsChannelsAndCarriesTheManifest) {
  const StageSet set = stage_set_from_capture(parse_capture_map(good_map(), "map.json"), textures_for_good_map());
  EXPECT_EQ(set.backend, "tiny");
  EXPECT_EQ(set.reduction, "running_mean");
  EXPECT_EQ(set.storage, "rgba16f");
  EXPECT_FLOAT_EQ(set.conventions.mip_scale, 1.5f);
  EXPECT_EQ(set.facts.msaa_samples, 4);
  const Image& coverage = set.images.at("gbuffer.coverage");
  ASSERT_EQ(coverage.channels, 1);
  // bottom_first: memory row 1 (texels 2, 3) is the picture's top row.
  EXPECT_EQ(coverage.at(0, 0, 0), 23.0f);
  EXPECT_EQ(coverage.at(1, 0, 0), 33.0f);
  EXPECT_EQ(coverage.at(0, 1, 0), 3.0f);
  const Image& final_image = set.images.at("image.final");
  ASSERT_EQ(final_image.channels, 3);
  EXPECT_EQ(final_image.at(1, 1, 2), 12.0f);
  // top_first: memory order is kept.
  const Image& shadow = set.images.at("shadow_map.0");
  EXPECT_EQ(shadow.at(0, 0, 0), 0.1f);
  EXPECT_EQ(shadow.channel_names, std::vector<std::string>{"Z"});
  // The settings' spelling of a reduction is read too and written in the manifest's.
  json settings_spelling = good_map();
  settings_spelling["manifest"]["reduction"] = "fixed";
  EXPECT_EQ(stage_set_from_capture(parse_capture_map(settings_spelling, "map.json"), textures_for_good_map()).reduction,
            "fixed_point");
  // Volumes keep the API's order (voxel coordinates, every API).
  const Volume& v = set.volumes.at("voxel.radiance");
  ASSERT_EQ(v.data.size(), 32u);
  EXPECT_EQ(v.data[31], 31.0f / 32.0f);
}

TEST(CaptureImport, RefusesATextureThatDoesNotFitItsStage) {
  const CaptureMap map = parse_capture_map(good_map(), "map.json");
  auto problem = [&](std::vector<CapturedTexture> t) {
    try {
      stage_set_from_capture(map, t);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  std::vector<CapturedTexture> deep = textures_for_good_map();
  deep[1] = volume_2();  // image.final from a 3D texture
  EXPECT_NE(problem(deep).find("is 2 deep"), std::string::npos) << problem(deep);
  std::vector<CapturedTexture> narrow = textures_for_good_map();
  narrow[0] = depth_2x2();  // channel 3 of a one-channel texture
  EXPECT_NE(problem(narrow).find("channel 3 asked"), std::string::npos) << problem(narrow);
  std::vector<CapturedTexture> short_data = textures_for_good_map();
  short_data[3].data.pop_back();
  EXPECT_NE(problem(short_data).find("returned 31 values"), std::string::npos) << problem(short_data);
  EXPECT_NE(problem({colour_2x2()}).find("1 textures for 4 stages"), std::string::npos);
}

fs::path scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("vct_capture_import_" + std::to_string(getpid())) / name;
  fs::remove_all(p);
  fs::create_directories(p.parent_path());
  return p;
}

TEST(CaptureImport, WritesAStageSetVctCompareReads) {
  const fs::path out = scratch("ok");
  FakeReader reader(textures_for_good_map());
  import_capture("frame.rdc", parse_capture_map(good_map(), "map.json"), reader, out.string());
  EXPECT_EQ(reader.asked, 4u);
  const StageSet back = read_stage_set(out.string());
  EXPECT_EQ(back.backend, "tiny");
  EXPECT_EQ(back.info["capture"].get<std::string>(), "frame.rdc");
  EXPECT_EQ(back.images.at("gbuffer.coverage").at(0, 0, 0), 23.0f);
  EXPECT_EQ(back.volumes.at("voxel.radiance").data[5], 5.0f / 32.0f);
  for (const auto& e : fs::directory_iterator(out.parent_path()))
    EXPECT_EQ(e.path().filename().string().find(".importing-"), std::string::npos) << e.path();
  fs::remove_all(out.parent_path());
}

TEST(CaptureImport, LeavesNothingBehindWhenTheSetIsRefused) {
  // voxel.radiance with 2 of its 4 channels: read_stage_set's channel check refuses the set after
  // it is written, so the temporary directory is removed and --out never appears.
  const fs::path out = scratch("refused");
  json doc = good_map();
  doc["stages"]["voxel.radiance"]["channels"] = {0, 1};
  FakeReader reader(textures_for_good_map());
  EXPECT_THROW(import_capture("frame.rdc", parse_capture_map(doc, "map.json"), reader, out.string()), InputError);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_TRUE(fs::is_empty(out.parent_path()));
  // An existing, non-empty --out is refused before anything is read.
  fs::create_directories(out);
  { std::ofstream(out / "keep.txt") << "mine"; }
  FakeReader unused(textures_for_good_map());
  EXPECT_THROW(import_capture("frame.rdc", parse_capture_map(good_map(), "map.json"), unused, out.string()), InputError);
  EXPECT_EQ(unused.asked, 0u);
  EXPECT_TRUE(fs::exists(out / "keep.txt"));
  fs::remove_all(out.parent_path());
}

}  // namespace
}  // namespace vct::cmp
