// Replays the fuzzers' saved crashers (fuzz/regressions/<target>/) through the same entry points
// the fuzz targets use (fuzz/fuzz_inputs.h): each must load or throw InputError, never crash or
// throw anything else. The seed corpora (fuzz/corpus/) are replayed too and must load (but the
// refused_* seeds, which must be refused).
// The run-dir manifest half of stage_set inputs is replayed in tests/compare (it needs vct_compare).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../../fuzz/fuzz_inputs.h"
#include "core/error.h"
#include "io/image_io.h"
#include "io/nrrd.h"
#include "scene/gltf_loader.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> files_in(const std::string& sub) {
  std::vector<fs::path> out;
  const fs::path dir = fs::path(VCT_SOURCE_DIR) / "fuzz" / sub;
  if (fs::is_directory(dir))
    for (const auto& e : fs::directory_iterator(dir))
      if (e.is_regular_file() && e.path().filename().string()[0] != '.') out.push_back(e.path());
  return out;
}

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// What gltf_fuzz does with an input; returns true if it loaded, false on InputError.
bool load_like_the_fuzzer(const std::string& b) {
  try {
    if (fuzz::is_glb(b.data(), b.size()))
      load_gltf_file(fuzz::write_scratch("fuzz.glb", b.data(), b.size()));
    else
      load_gltf_text(b, "fuzz.gltf", fuzz::scratch_dir().string());
    return true;
  } catch (const InputError&) {
    return false;
  }
}

TEST(FuzzRegression, GltfCrashersAreInputErrorsOrLoad) {
  for (const fs::path& p : files_in("regressions/gltf")) {
    SCOPED_TRACE(p.filename().string());
    EXPECT_NO_FATAL_FAILURE(load_like_the_fuzzer(bytes_of(p)));
  }
}

TEST(FuzzRegression, GltfSeedCorpusLoads) {
  const auto seeds = files_in("corpus/gltf");
  ASSERT_GE(seeds.size(), 4u);
  int glb = 0;
  for (const fs::path& p : seeds) {
    const std::string b = bytes_of(p);
    glb += fuzz::is_glb(b.data(), b.size());
    // refused_*: inputs at the limits of issue 19 (fuzz/make_seeds.py), refused by design.
    const bool refused = p.filename().string().rfind("refused_", 0) == 0;
    EXPECT_EQ(load_like_the_fuzzer(b), !refused) << p.filename();
  }
  EXPECT_GE(glb, 2);  // both paths of the fuzz target are seeded
}

TEST(FuzzRegression, DumpFilesOfStageSetInputsAreInputErrorsOrRead) {
  auto replay = [](const fs::path& p, bool must_read) {
    SCOPED_TRACE(p.filename().string());
    fuzz::write_stage_set_files(bytes_of(p));
    int read = 0;
    try {
      read_nrrd((fuzz::scratch_dir() / "v.nrrd").string());
      ++read;
    } catch (const InputError&) {
    }
    try {
      read_image((fuzz::scratch_dir() / "i.exr").string());
      ++read;
    } catch (const InputError&) {
    }
    if (must_read) {
      EXPECT_EQ(read, 2);
    }
  };
  for (const fs::path& p : files_in("regressions/stage_set")) replay(p, false);
  replay(fs::path(VCT_SOURCE_DIR) / "fuzz/corpus/stage_set/run_dir.bin", true);
}

}  // namespace
}  // namespace vct
