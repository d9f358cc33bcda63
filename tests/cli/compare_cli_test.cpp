// vct compare's exit codes on real files: 0 pass, 1 fail, 2 bad input (README.md).
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "cli_run_util.h"
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

// Rerunning into the same --out leaves only this comparison's masks: a mask of another stage from
// an earlier run would be read as part of this verdict.
TEST_F(CompareCli, RerunIntoTheSameOutKeepsNoStaleMasks) {
  EXPECT_EQ(run_vct("compare " + p("a.exr") + " " + p("b.exr") + " --stage image.direct --out " + p("out")), 1);
  ASSERT_TRUE(fs::exists(p("out/masks/image_direct_mask.png")));
  EXPECT_EQ(run_vct("compare " + p("a.exr") + " " + p("a.exr") + " --out " + p("out")), 0);
  EXPECT_TRUE(fs::exists(p("out/masks/image_final_mask.png")));
  EXPECT_FALSE(fs::exists(p("out/masks/image_direct_mask.png")));
}

// --out is a run directory like every command's (ref/io/run_dir.h): finished, it holds a
// complete run.json and neither the INCOMPLETE marker nor the lock.
TEST_F(CompareCli, OutIsAFinishedRunDirectory) {
  EXPECT_EQ(run_vct("compare " + p("a.exr") + " " + p("b.exr") + " --out " + p("out")), 1);
  const nlohmann::json run = nlohmann::json::parse(test::slurp(p("out/run.json")));
  EXPECT_EQ(run["command"], "compare");
  EXPECT_EQ(run["status"], "complete");
  EXPECT_EQ(run["compare"]["overall"], "fail");
  EXPECT_EQ(run["compare"]["file"], "compare.json");
  EXPECT_FALSE(fs::exists(p("out/INCOMPLETE")));
  EXPECT_FALSE(fs::exists(p("out/.vct-lock")));
}

// A second writer of the same --out is refused with one line naming the holder; it writes
// nothing there. The holder is this test, locking as a vct process does, so nothing races.
TEST_F(CompareCli, LockedOutIsRefused) {
  fs::create_directories(p("locked"));
  const int fd = ::open(p("locked/.vct-lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const std::string pid = std::to_string(::getpid());
  ASSERT_EQ(::write(fd, pid.data(), pid.size()), ssize_t(pid.size()));
  const test::VctOutput r = test::run_vct_captured("compare " + p("a.exr") + " " + p("b.exr") + " --out " + p("locked"));
  ::close(fd);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "vct: " + p("locked") + ": another vct process (pid " + pid +
                       ") is writing this run directory; wait for it to finish or use another --out\n");
  EXPECT_FALSE(fs::exists(p("locked/compare.json")));
  EXPECT_FALSE(fs::exists(p("locked/masks")));
  EXPECT_FALSE(fs::exists(p("locked/INCOMPLETE")));  // the holder's directory is left alone
}

// Bad input is found before --out is opened: no directory, no INCOMPLETE left behind.
TEST_F(CompareCli, BadInputCreatesNoOutDirectory) {
  EXPECT_EQ(run_vct("compare " + p("a.exr") + " " + p("nope.exr") + " --out " + p("bad1")), 2);
  EXPECT_FALSE(fs::exists(p("bad1")));
  write_exr(p("small.exr"), Image(16, 16, 3));
  EXPECT_EQ(run_vct("compare " + p("a.exr") + " " + p("small.exr") + " --out " + p("bad2")), 2);
  EXPECT_FALSE(fs::exists(p("bad2")));
}

// compare --out into another command's run keeps that run's run.json sections.
TEST_F(CompareCli, OutIntoAnotherRunKeepsItsRunJson) {
  fs::create_directories(p("validate_run"));
  std::ofstream(p("validate_run/run.json")) << R"({"command": "validate", "verdicts": {"overall": "pass"}})";
  EXPECT_EQ(run_vct("compare " + p("a.exr") + " " + p("a.exr") + " --out " + p("validate_run")), 0);
  const nlohmann::json run = nlohmann::json::parse(test::slurp(p("validate_run/run.json")));
  EXPECT_EQ(run["command"], "validate");
  EXPECT_EQ(run["verdicts"]["overall"], "pass");
  EXPECT_EQ(run["compare"]["overall"], "pass");
  EXPECT_EQ(run["status"], "complete");
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
