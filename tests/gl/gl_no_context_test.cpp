// Without a usable EGL (here: GLVND pointed at no vendor library) `vct render --backend gl` must
// fail with exit code 3 and one clear line, and nothing else may be affected.
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "gl_test_util.h"

namespace vct::gl::test {

TEST(GlNoContext, RenderExitsWithEnvironmentCode) {
  const std::string vct = VCT_BINARY;
  if (!std::ifstream(vct).good()) GTEST_SKIP() << "vct binary not built: " << vct;
  const std::string out = ::testing::TempDir() + "vct_gl_no_context";
  const std::string log = out + ".log";
  const std::string cmd = "__EGL_VENDOR_LIBRARY_FILENAMES=/nonexistent.json '" + vct + "' render '" +
                          std::string(VCT_SOURCE_DIR) + "/scenes/cornell_box.gltf' --backend gl --out '" + out +
                          "' > '" + log + "' 2>&1";
  const int status = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3);
  std::ifstream in(log);
  std::string text, line;
  while (std::getline(in, line)) text += line + "\n";
  EXPECT_NE(text.find("GL backend"), std::string::npos) << text;
}

}  // namespace vct::gl::test
