// vct compare's exit codes on real files: 0 pass, 1 fail, 2 bad input (README.md).
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/image.h"
#include "io/image_io.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

int run_vct(const std::string& args) {
  const std::string cmd = std::string(VCT_BINARY) + " " + args + " > /dev/null 2>&1";
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

class CompareCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("vct_compare_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    Image a(32, 32, 3);
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x) a.set_rgb(x, y, vec3(0.25f + 0.01f * float(x), 0.5f, 0.1f));
    write_exr(p("a.exr"), a);
    Image b = a;
    for (int y = 10; y < 20; ++y)
      for (int x = 10; x < 20; ++x) b.set_rgb(x, y, a.rgb(x, y) * 1.5f);  // a block 50% too bright
    write_exr(p("b.exr"), b);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string p(const std::string& f) const { return (dir_ / f).string(); }
  fs::path dir_;
};

TEST_F(CompareCli, IdenticalImagesPass) { EXPECT_EQ(run_vct("compare " + p("a.exr") + " " + p("a.exr")), 0); }

TEST_F(CompareCli, BrightBlockFailsAndWritesMask) {
  EXPECT_EQ(run_vct("compare " + p("a.exr") + " " + p("b.exr") + " --out " + p("out")), 1);
  EXPECT_TRUE(fs::exists(p("out/compare.json")));
  EXPECT_TRUE(fs::exists(p("out/masks/image_final_mask.png")));
}

TEST_F(CompareCli, BadInputIsExitTwo) {
  EXPECT_EQ(run_vct("compare " + p("a.exr") + " " + p("nope.exr")), 2);
  fs::create_directories(p("ext"));
  std::ofstream(p("ext/vct-stages.json")) << R"({"format":"vct-stages","stages":{"image.final":{"file":"gone.exr"}}})";
  EXPECT_EQ(run_vct("compare " + p("ext") + " " + p("ext")), 2);
}

TEST_F(CompareCli, ExternalManifestAgainstItselfPasses) {
  fs::create_directories(p("ext"));
  fs::copy_file(p("a.exr"), p("ext/final.exr"));
  std::ofstream(p("ext/vct-stages.json")) << R"({"format":"vct-stages","backend":"engine","stages":{"image.final":{"file":"final.exr"}}})";
  EXPECT_EQ(run_vct("compare " + p("ext") + " " + p("ext")), 0);
}

}  // namespace
}  // namespace vct

namespace vct {
namespace {

TEST(ValidateCli, BadSweepIsExitTwoBeforeRendering) {
  const std::string out = (std::filesystem::temp_directory_path() / "vct_bad_sweep").string();
  EXPECT_EQ(run_vct("validate --no-report --out " + out + " --sweep grid"), 2);
  EXPECT_FALSE(std::filesystem::exists(out + "/run.json"));
  EXPECT_EQ(run_vct("validate --no-report --out " + out + " --sweep nosuchkey=1,2"), 2);
  EXPECT_EQ(run_vct("validate --no-report --out " + out + " --sweep grid=64,7"), 2);  // 7 is not a valid grid
  EXPECT_FALSE(std::filesystem::exists(out + "/run.json"));
  std::filesystem::remove_all(out);
}

}  // namespace
}  // namespace vct
