// Replays the crashers in fuzz/regressions/scene_compare/ (the fuzzer's oom-/crash- files and the
// crafted-* inputs written while reviewing the --scene path) through the same steps as the fuzz
// target (fuzz/scene_compare_steps.h): each must pass or throw InputError, never crash or throw
// anything else. The seeds must get as far as they were made to.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../../fuzz/scene_compare_steps.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

const fuzz::SceneCompareFixture& fixture() {
  static const fuzz::SceneCompareFixture f = fuzz::make_scene_compare_fixture();
  return f;
}

fs::path fuzz_dir(const std::string& sub) { return fs::path(VCT_SOURCE_DIR) / "fuzz" / sub; }

TEST(SceneCompareFuzzRegression, CrashersAreInputErrorsOrPass) {
  const fs::path dir = fuzz_dir("regressions/scene_compare");
  ASSERT_TRUE(fs::is_directory(dir));
  for (const auto& e : fs::directory_iterator(dir)) {
    if (!e.is_regular_file() || e.path().filename().string()[0] == '.') continue;
    SCOPED_TRACE(e.path().filename().string());
    EXPECT_NO_THROW(fuzz::run_scene_compare_steps(bytes_of(e.path()), fixture()));
  }
}

// The isotropic seed is the fixture's own frame written out: read, rebuilt and judged.
TEST(SceneCompareFuzzRegression, IsotropicSeedGoesAllTheWay) {
  EXPECT_EQ(fuzz::run_scene_compare_steps(bytes_of(fuzz_dir("corpus/scene_compare/cornell_16_iso.bin")), fixture()), 6);
  const cmp::StageSet b = cmp::read_stage_set((fuzz::scratch_dir() / "named_stage_set").string());
  EXPECT_EQ(b.volumes.at("mip.iso.4").nx, 1);
  EXPECT_EQ(b.images.at("gbuffer.coverage").width, 16);
  EXPECT_EQ(cmp::compare_stage_sets(fixture().reference, b).overall(), cmp::Verdict::Pass);
}

// The anisotropic seed (UNORM volumes) rebuilds its frame with the six directional chains.
TEST(SceneCompareFuzzRegression, AnisotropicSeedRebuildsItsFrame) {
  const int steps =
      fuzz::run_scene_compare_steps(bytes_of(fuzz_dir("corpus/scene_compare/cornell_16_aniso_unorm.bin")), fixture());
  EXPECT_EQ(steps & 3, 2);
  const cmp::StageSet b = cmp::read_stage_set((fuzz::scratch_dir() / "named_stage_set").string());
  const VctSettings s = app::settings_of_test_set(b, "");
  EXPECT_TRUE(s.anisotropic);
  const FrameResult f = cmp::frame_from_stage_set(b, fixture().scene, s);
  for (int d = 0; d < 6; ++d) EXPECT_EQ(f.mips.aniso[size_t(d)].size(), 4u);
}

// A name that would leave the scratch directory is not written; the others are, as given.
TEST(SceneCompareFuzzRegression, NamedFilesStayInTheScratchDirectory) {
  const std::string sep = fuzz::kFileSeparator;
  const std::string input = std::string(R"({"format":"vct-stages","stages":{"a":{"file":"x.exr"}}})") +
                            sep + "../escape.exr\nbytes" + sep + "x.exr\nnot an image";
  EXPECT_EQ(fuzz::run_scene_compare_steps(input, fixture()), 0);
  EXPECT_FALSE(fs::exists(fuzz::scratch_dir() / "escape.exr"));
  EXPECT_EQ(bytes_of(fuzz::scratch_dir() / "named_stage_set" / "x.exr"), "not an image");
}

}  // namespace
}  // namespace vct
