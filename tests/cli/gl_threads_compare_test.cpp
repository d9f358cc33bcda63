// A correct GL run passes against itself under different llvmpipe thread counts (issue 7 item 6):
// two `vct validate` runs with LP_NUM_THREADS=1 and 4, then `vct compare` of their gl/ stage sets
// must pass (fixed-point voxels: bit-exact). Skipped when there is no GL context.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

namespace {

namespace fs = std::filesystem;

int sh(const std::string& cmd) {
  const int rc = std::system((cmd + " > /dev/null 2>&1").c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

TEST(GlThreads, GlAgainstItselfPassesAcrossLlvmpipeThreadCounts) {
  const fs::path dir = fs::temp_directory_path() / ("vct_gl_threads_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string vct = VCT_BINARY;
  const std::string common = " validate --no-report --width 64 --height 64 --grid 16 --spp 2 --out ";
  for (const char* t : {"1", "4"})
    sh(std::string("LP_NUM_THREADS=") + t + " " + vct + common + (dir / t).string());
  std::ifstream in(dir / "1" / "run.json");
  ASSERT_TRUE(in.good());
  const nlohmann::json j = nlohmann::json::parse(in);
  if (j["backends"]["gl"]["status"] != "ok") {
    fs::remove_all(dir);
    GTEST_SKIP() << "no GL: " << j["backends"]["gl"]["status"];
  }
  EXPECT_EQ(sh(vct + " compare " + (dir / "1" / "gl").string() + " " + (dir / "4" / "gl").string()), 0);
  fs::remove_all(dir);
}

}  // namespace
