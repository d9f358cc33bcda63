// Stage sets survive the disk (vct-stages.json + EXR/NRRD) bit for bit, and bad manifests are
// InputErrors naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "compare/stage_compare.h"
#include "compare/stage_set.h"
#include "core/error.h"

namespace vct::cmp {
namespace {

namespace fs = std::filesystem;

TEST(StageSetIo, RoundTripIsExactAndComparesAsPass) {
  StageSet s;
  s.backend = "gl";
  s.storage = "rgba16f";
  s.reduction = "fixed_point";
  Image img(8, 4, 3);
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = 0.1f * float(i) + 1e-7f;
  s.images["image.final"] = img;
  Volume v(4, 4, 4, 4);
  v.set_rgba(1, 2, 3, vec4(0.25f, 0.5f, 0.75f, 1.0f));
  s.volumes["voxel.radiance"] = v;
  const std::string dir = (fs::temp_directory_path() / ("vct_stage_set_" + std::to_string(::getpid()))).string();
  write_stage_set(dir, s);
  const StageSet r = read_stage_set(dir);
  EXPECT_EQ(r.backend, "gl");
  EXPECT_EQ(r.reduction, "fixed_point");
  ASSERT_TRUE(r.images.count("image.final") && r.volumes.count("voxel.radiance"));
  EXPECT_EQ(r.images.at("image.final").data, img.data);
  EXPECT_EQ(r.volumes.at("voxel.radiance").data, v.data);
  EXPECT_EQ(compare_stage_sets(s, r).overall(), Verdict::Pass);
  fs::remove_all(dir);
}

// The manifest carries the backend's typed facts ("facts") and a reduction the backend
// substituted comes from them, not from prose in "info".
TEST(StageSetIo, FactsRoundTripTypedAndSetTheReduction) {
  FrameResult f;
  f.backend = "gl";
  f.facts.renderer = "llvmpipe";
  f.facts.msaa_samples = 4;
  f.facts.sample_positions = {{0.375f, 0.125f}, {0.875f, 0.375f}, {0.125f, 0.625f}, {0.625f, 0.875f}};
  f.facts.reduction = "fixed_point";
  f.facts.unreported = {"texture filtering sub-texel precision: no query"};
  f.info["note"] = "free-form";
  f.images.final_image = Image(2, 2, 3);
  VctSettings vs;
  vs.reduction = Reduction::ExactMean;
  StageSet s = stage_set_from_frame(f, vs);
  EXPECT_EQ(s.reduction, "fixed_point");
  const std::string dir = (fs::temp_directory_path() / ("vct_stage_set_facts_" + std::to_string(::getpid()))).string();
  write_stage_set(dir, s);
  const StageSet r = read_stage_set(dir);
  EXPECT_EQ(r.facts.renderer, "llvmpipe");
  EXPECT_EQ(r.facts.sample_positions, f.facts.sample_positions);
  EXPECT_EQ(r.facts.unreported, f.facts.unreported);
  EXPECT_EQ(r.reduction, "fixed_point");
  EXPECT_EQ(r.info["note"], "free-form");
  // A facts object of the wrong shape is bad input naming the manifest.
  nlohmann::json m;
  {
    std::ifstream in(dir + "/vct-stages.json");
    m = nlohmann::json::parse(in);
  }
  m["facts"]["sample_positions"] = "everywhere";
  {
    std::ofstream out(dir + "/vct-stages.json");
    out << m.dump();
  }
  EXPECT_THROW(read_stage_set(dir), InputError);
  fs::remove_all(dir);
}

TEST(StageSetIo, BadManifestsAreInputErrors) {
  const fs::path dir = fs::temp_directory_path() / ("vct_bad_manifest_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  EXPECT_THROW(read_stage_set(dir.string()), InputError);  // no manifest
  std::ofstream(dir / "vct-stages.json") << "{\"format\":\"other\",\"stages\":{}}";
  EXPECT_THROW(read_stage_set(dir.string()), InputError);
  std::ofstream(dir / "vct-stages.json") << "{\"format\":\"vct-stages\",\"storage\":\"rgb9e5\",\"stages\":{}}";
  EXPECT_THROW(read_stage_set(dir.string()), InputError);
  std::ofstream(dir / "vct-stages.json") << "{not json";
  EXPECT_THROW(read_stage_set(dir.string()), InputError);
  fs::remove_all(dir);
}

// Canonical names have one kind (docs/external_format.md): an image listed as mip.iso.2 is refused
// when read, not looked up among the volumes later; names outside the table may be either.
TEST(StageSetIo, CanonicalNamesOfTheWrongKindAreInputErrors) {
  const fs::path dir = fs::temp_directory_path() / ("vct_kind_manifest_" + std::to_string(::getpid()));
  StageSet s;
  s.images["image.final"] = Image(2, 2, 3, 0.5f);
  s.volumes["voxel.radiance"] = Volume(2, 2, 2, 4);
  write_stage_set(dir.string(), s);
  const std::string exr = s.files.at("image.final"), nrrd = s.files.at("voxel.radiance");
  auto manifest_with = [&](const std::string& stages) {
    std::ofstream(dir / "vct-stages.json") << R"({"format":"vct-stages","stages":{)" << stages << "}}";
  };
  manifest_with(R"("mip.iso.2":{"file":")" + exr + R"(","kind":"image"})");
  try {
    read_stage_set(dir.string());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'mip.iso.2' must be a volume"), std::string::npos) << e.what();
  }
  manifest_with(R"("gbuffer.position":{"file":")" + nrrd + R"("})");  // kind from .nrrd: volume
  EXPECT_THROW(read_stage_set(dir.string()), InputError);
  manifest_with(R"("my.extra":{"file":")" + nrrd + R"("},"other":{"file":")" + exr + R"("})");
  const StageSet r = read_stage_set(dir.string());
  EXPECT_TRUE(r.volumes.count("my.extra") && r.images.count("other"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vct::cmp
