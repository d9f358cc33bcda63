// `vct import-capture`'s packed depth formats (tools/import_capture/rdc_read.py to_floats): a GL
// program (tests/capture/depth_formats_frame.cpp) writes a GL_DEPTH24_STENCIL8 and a
// GL_DEPTH32F_STENCIL8 texture with depth (x + 4 y + 1) / 10 at texel (x, y) (y up) and stencil
// 0xA5; captured with RenderDoc and imported with tests/capture/depth_formats_map.json, every
// texel's depth comes back -- the 24-bit one within one UNORM step (GL 4.5 section 2.3.5.2: either
// neighbour), the float one within one float ulp (the clear's depth goes through the driver's
// ClearDepth path, GL 4.5 section 17.4.3.1, in double on Mesa: llvmpipe stores some of these one
// ulp low) -- in the stage's row order (row 0 = top). A decoder that read
// the stencil bits as depth, or the padding, would miss by far more. Skipped, with the reason,
// without RenderDoc, GL, or under a sanitizer (import_capture_cli_test.cpp says why).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "cli_run_util.h"
#include "renderdoc_available.h"
#include "compare/stage_set.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

TEST(ImportCaptureDepth, PackedDepthStencilTexturesDecodeToTheirDepths) {
  if (const std::string why = test::capture_impossible(); !why.empty()) GTEST_SKIP() << why;
  const fs::path program = fs::path(VCT_BINARY).parent_path() / "depth_formats_frame";
  if (!fs::exists(program)) GTEST_SKIP() << "depth_formats_frame not built (a build without GL)";
  const fs::path dir = test::fresh_dir("import_depth_formats");
  if (std::system((q(program) + " > /dev/null 2>&1").c_str()) != 0) GTEST_SKIP() << "no GL 4.5 context";
  // One capture at a time across test processes (import_capture_cli_test.cpp's lock).
  const fs::path lock = fs::temp_directory_path() / "vct-renderdoc-capture.lock";
  const std::string capture = "flock " + q(lock) + " renderdoccmd capture -w -d " + q(dir) + " -c " + q(dir / "frame") +
                              " " + q(program) + " > " + q(dir / "capture.log") + " 2>&1";
  (void)std::system(capture.c_str());  // its exit code: see import_capture_cli_test.cpp
  const fs::path rdc = dir / "frame_capture.rdc";
  ASSERT_TRUE(fs::exists(rdc)) << test::slurp(dir / "capture.log");
  const std::string map = std::string(VCT_SOURCE_DIR) + "/tests/capture/depth_formats_map.json";
  const auto r = test::run_vct_captured("import-capture " + q(rdc) + " --map " + q(map) + " --out " + q(dir / "imported"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const cmp::StageSet set = cmp::read_stage_set((dir / "imported").string());
  const double q24 = 1.0 / 16777215.0;
  const double float_ulp = std::ldexp(1.0, -24);  // of values in [0.5, 1); below, half that or less
  for (const auto& [stage, step] : {std::pair<std::string, double>{"shadow_map.0", q24}, {"shadow_map.1", float_ulp}}) {
    ASSERT_TRUE(set.images.count(stage)) << stage;
    const Image& img = set.images.at(stage);
    ASSERT_EQ(img.width, 4) << stage;
    ASSERT_EQ(img.height, 2) << stage;
    ASSERT_EQ(img.channels, 1) << stage;
    for (int row = 0; row < 2; ++row)
      for (int x = 0; x < 4; ++x) {
        const int y = 1 - row;  // the stage's row 0 is the texture's top row
        const float written = float(x + 4 * y + 1) / 10.0f;
        EXPECT_NEAR(double(img.at(x, row, 0)), double(written), step) << stage << " texel " << x << "," << y;
      }
  }
}

}  // namespace
}  // namespace vct
