// Stage sets survive the disk (vct-stages.json + EXR/NRRD) bit for bit, and bad manifests are
// InputErrors naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

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

}  // namespace
}  // namespace vct::cmp
