// Replays stage_set_fuzz's saved crashers (fuzz/regressions/stage_set/) through read_stage_set as
// the fuzz target does: InputError or success, never a crash. The seed run dir must read.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../../fuzz/fuzz_inputs.h"
#include "compare/stage_set.h"
#include "core/error.h"

namespace vct::cmp {
namespace {

namespace fs = std::filesystem;

bool read_like_the_fuzzer(const fs::path& input) {
  std::ifstream in(input, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  fuzz::write_stage_set_files(ss.str());
  try {
    read_stage_set(fuzz::scratch_dir().string());
    return true;
  } catch (const InputError&) {
    return false;
  }
}

TEST(StageSetFuzzRegression, CrashersAreInputErrorsOrRead) {
  const fs::path dir = fs::path(VCT_SOURCE_DIR) / "fuzz/regressions/stage_set";
  if (!fs::is_directory(dir)) return;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (!e.is_regular_file() || e.path().filename().string()[0] == '.') continue;
    SCOPED_TRACE(e.path().filename().string());
    EXPECT_NO_FATAL_FAILURE(read_like_the_fuzzer(e.path()));
  }
}

TEST(StageSetFuzzRegression, SeedRunDirReadsWithItsTwoStages) {
  ASSERT_TRUE(read_like_the_fuzzer(fs::path(VCT_SOURCE_DIR) / "fuzz/corpus/stage_set/run_dir.bin"));
  const StageSet s = read_stage_set(fuzz::scratch_dir().string());
  EXPECT_TRUE(s.has("mip.iso.3"));
  EXPECT_TRUE(s.has("gbuffer.depth"));
  EXPECT_EQ(s.volumes.at("mip.iso.3").nx, 2);
}

}  // namespace
}  // namespace vct::cmp
