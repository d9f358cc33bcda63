// Shader build errors name the shader file and carry the driver's log; every embedded shader
// compiles with the shared header prepended.
#include "gl_test_util.h"
#include "gl/gl_program.h"

namespace vct::gl::test {

TEST(GlShader, CompileErrorNamesTheShader) {
  VCT_REQUIRE_GL();
  const ShaderSource bad{GL_FRAGMENT_SHADER, "broken_test.frag",
                         "#version 450\nout vec4 c;\nvoid main() { c = undefined_symbol; }\n"};
  try {
    Program p({bad});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("broken_test.frag"), std::string::npos) << msg;
    EXPECT_NE(msg.find("compile failed"), std::string::npos) << msg;
    EXPECT_NE(msg.find("undefined_symbol"), std::string::npos) << msg;  // the driver's log
  }
}

TEST(GlShader, LinkErrorNamesThePrograms) {
  VCT_REQUIRE_GL();
  // A vertex shader output the fragment shader reads with another type: a link error.
  const ShaderSource vs{GL_VERTEX_SHADER, "mismatch.vert", "#version 450\nout vec3 v;\nvoid main() { v = vec3(0); gl_Position = vec4(0); }\n"};
  const ShaderSource fs{GL_FRAGMENT_SHADER, "mismatch.frag", "#version 450\nin vec2 v;\nout vec4 c;\nvoid main() { c = vec4(v, 0, 1); }\n"};
  try {
    Program p({vs, fs});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("mismatch.vert + mismatch.frag"), std::string::npos) << e.what();
  }
}

TEST(GlShader, EveryEmbeddedProgramBuilds) {
  VCT_REQUIRE_GL();
  const std::vector<std::vector<std::string>> programs = {
      {"scene.vert", "depth_only.frag"},     {"scene.vert", "gbuffer.frag"},
      {"voxelize.vert", "voxelize.geom", "voxelize.frag"},
      {"voxel_resolve.comp"},                {"mip_iso.comp"},
      {"mip_aniso.comp"},                    {"fullscreen.vert", "direct.frag"},
      {"fullscreen.vert", "indirect.frag"},  {"particles.vert", "particles.frag"},
      {"particles_voxel.comp"}};
  for (const auto& files : programs) EXPECT_NO_THROW(Program::from_files(files)) << files.back();
  EXPECT_THROW(Program::from_files({"no_such_shader.frag"}), std::runtime_error);
}

}  // namespace vct::gl::test
