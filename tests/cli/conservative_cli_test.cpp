// `vct render --backend gl` with a hardware conservative voxelization mode the driver lacks
// (llvmpipe has neither GL_NV_conservative_raster nor GL_INTEL_conservative_rasterization): exit 3,
// one line naming the extension, no run directory left behind (docs/gl_backend.md, "Conservative
// voxelization"; DESIGN §5). Skipped where there is no GL at all or the driver has the extension.
#include <gtest/gtest.h>

#include <algorithm>

#include "cli_run_util.h"

namespace vct::test {
namespace {

TEST(ConservativeCli, HardwareModeWithoutTheExtensionExits3AndWritesNothing) {
  for (const char* mode : {"nv", "intel"}) {
    const fs::path out = scratch_root() / (std::string("cons_") + mode);
    fs::remove_all(out);
    const VctOutput r = run_vct_captured(std::string("render ") + VCT_SOURCE_DIR +
                                         "/scenes/cornell_box.gltf --backend gl --width 16 --height 16 --grid 16 "
                                         "--set conservative_raster=" + mode + " --out '" + out.string() + "'");
    if (r.exit_code == 0) GTEST_SKIP() << "this driver has the " << mode << " extension";
    if (r.err.find("conservative_raster") == std::string::npos && r.exit_code == 3)
      GTEST_SKIP() << "no GL context: " << r.err;
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(std::string("conservative_raster = ") + mode), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << "a refused render left " << out;
  }
}

// `vct validate --set conservative_raster=gs` judges the GL voxels against the exact voxelizer by
// itself (validate's default reference voxelizer is the sample rule); a --set voxelizer=gpu that
// asks for the sample rule keeps it, and the occupancy judge then fails with its own reason.
TEST(ConservativeCli, ValidateWithTheGsModeUsesTheExactVoxelizer) {
  const std::string args = "validate --width 16 --height 16 --grid 16 --spp 1 --no-report --flip none "
                           "--set conservative_raster=gs --out '";
  const VctOutput r = run_vct_captured(args + (scratch_root() / "cons_validate").string() + "'");
  if (r.exit_code == 3) GTEST_SKIP() << "no GL context: " << r.err;
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("pass voxel.occupancy"), std::string::npos) << r.out;
  const VctOutput asked = run_vct_captured(args + (scratch_root() / "cons_validate_gpu").string() +
                                           "' --set voxelizer=gpu");
  EXPECT_EQ(asked.exit_code, 1) << asked.out << asked.err;
  EXPECT_NE(asked.out.find("the reference must voxelize exactly"), std::string::npos) << asked.out;
}

}  // namespace
}  // namespace vct::test
