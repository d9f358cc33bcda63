// A small engine with its own conventions, for judging a real program through a RenderDoc capture
// (issue 39, tests/cli/test_engine_capture_test.cpp). It drives our GL frame (gl/gl_pipeline.h)
// where our GL runs its conventions -- |n.v| in the direct light (n_dot_v = abs) -- and its own
// passes where it differs: its own isotropic mips, a plain box filter of the 2x2x2 children
// (x 1; VCT_TEST_ENGINE_MIP_SCALE=s multiplies each level by s, the injected bug of the source
// design's x1.9), and its own display transform, Reinhard x/(1+x) then gamma 2.2 into RGBA8.
// Everything is one capture (the engine brackets it, GlOptions::renderdoc_capture = false).
// It writes the capture map for `vct import-capture` beside its output: the GL stages by their
// labels, its own mips and display image, and the manifest that declares its conventions and the
// driver's facts (the sample positions its voxelization used).
//
// Usage: test_engine MAP.json. Exit 0 written, 1 failed, 3 no GL 4.5 context.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "gl/gl_api.h"
#include "gl/gl_context.h"
#include "gl/gl_pipeline.h"
#include "gl/gl_program.h"
#include "gl/gl_renderdoc.h"
#include "scene/gltf_loader.h"

namespace {

using vct::gl::Program;
using vct::gl::ShaderSource;

// The engine's frame: the built-in box at the sizes of our own capture test, |n.v|.
vct::Settings engine_settings() {
  vct::Settings s;
  s.vct.width = 64;
  s.vct.height = 48;
  s.vct.grid = 64;
  s.vct.shadow_map_size = 256;
  s.vct.voxelizer = vct::Voxelizer::GpuEmulation;
  s.vct.reduction = vct::Reduction::FixedPoint;
  s.vct.n_dot_v = vct::NdotV::Abs;
  return s;
}

Program compute(const char* name, const std::string& body) {
  return Program({ShaderSource{GL_COMPUTE_SHADER, name, "#version 450\n" + body}});
}

// Level L = s x the mean of the eight children of level L - 1, stored by imageStore (the driver's
// float -> half conversion).
const char* const kMipShader = R"(
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
layout(binding = 0, rgba16f) uniform readonly image3D u_child;
layout(binding = 1, rgba16f) uniform writeonly image3D u_parent;
uniform float u_scale;
void main() {
  ivec3 p = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(p, imageSize(u_parent)))) return;
  vec4 sum = vec4(0.0);
  for (int k = 0; k < 8; ++k) sum += imageLoad(u_child, 2 * p + ivec3(k & 1, (k >> 1) & 1, k >> 2));
  imageStore(u_parent, p, sum * 0.125 * u_scale);
}
)";

// Reinhard, then gamma 2.2, stored as RGBA8 UNORM.
const char* const kDisplayShader = R"(
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D u_linear;
layout(binding = 1, rgba8) uniform writeonly image2D u_display;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_display)))) return;
  vec3 c = max(texelFetch(u_linear, p, 0).rgb, vec3(0.0));
  c = pow(c / (1.0 + c), vec3(1.0 / 2.2));
  imageStore(u_display, p, vec4(c, 1.0));
}
)";

// The engine's voxel texture: level 0 from our GL frame's, its mips built by kMipShader.
void engine_mips(const vct::Volume& level0, float scale) {
  const int n = level0.nx;
  int levels = 1;
  while ((n >> levels) > 0) ++levels;
  GLuint tex = 0;
  glCreateTextures(GL_TEXTURE_3D, 1, &tex);
  glTextureStorage3D(tex, levels, GL_RGBA16F, n, n, n);
  glObjectLabel(GL_TEXTURE, tex, -1, "engine.voxels");
  glTextureSubImage3D(tex, 0, 0, 0, 0, n, n, n, GL_RGBA, GL_FLOAT, level0.data.data());
  const Program mip = compute("engine_mip.comp", kMipShader);
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 2, -1, "engine.mips");
  mip.use();
  mip.set("u_scale", scale);
  for (int level = 1; level < levels; ++level) {
    glBindImageTexture(0, tex, level - 1, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA16F);
    glBindImageTexture(1, tex, level, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    const GLuint groups = GLuint(std::max(1, (n >> level) / 4));
    glDispatchCompute(groups, groups, groups);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  glPopDebugGroup();
}

// The engine's display image of our frame's linear final colour (uploaded bottom row first, GL's
// order; the frame's images have row 0 at the top).
void engine_display(const vct::Image& final_linear) {
  const int w = final_linear.width, h = final_linear.height;
  std::vector<float> rows(size_t(w) * size_t(h) * 4, 1.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) rows[(size_t(y) * size_t(w) + size_t(x)) * 4 + size_t(c)] = final_linear.at(x, h - 1 - y, c);
  GLuint linear = 0, display = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &linear);
  glTextureStorage2D(linear, 1, GL_RGBA32F, w, h);
  glObjectLabel(GL_TEXTURE, linear, -1, "engine.final_linear");
  glTextureSubImage2D(linear, 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, rows.data());
  glCreateTextures(GL_TEXTURE_2D, 1, &display);
  glTextureStorage2D(display, 1, GL_RGBA8, w, h);
  glObjectLabel(GL_TEXTURE, display, -1, "engine.display");
  const Program prog = compute("engine_display.comp", kDisplayShader);
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 3, -1, "engine.display");
  prog.use();
  glBindTextureUnit(0, linear);
  glBindImageTexture(1, display, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glDispatchCompute(GLuint((w + 7) / 8), GLuint((h + 7) / 8), 1);
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  glPopDebugGroup();
}

nlohmann::json rgb(const char* resource) { return {{"resource", resource}, {"channels", {0, 1, 2}}}; }

// The capture map: our GL frame's stages by their labels (tools/import_capture/vct_gl_map.json),
// the engine's mips and display image, its conventions and the driver's facts.
nlohmann::json capture_map(const vct::FrameResult& r, const vct::Settings& s, int levels) {
  nlohmann::json stages = {
      {"shadow_map.0", {{"resource", "vct.shadow_maps"}, {"slice", 0}}},
      {"gbuffer.position", rgb("vct.gbuffer.position")},
      {"gbuffer.normal", rgb("vct.gbuffer.normal")},
      {"gbuffer.albedo", rgb("vct.gbuffer.albedo")},
      {"gbuffer.depth", {{"resource", "vct.gbuffer.depth"}}},
      {"voxel.radiance", {{"resource", "vct.radiance"}, {"mip", 0}}},
      {"voxel.fragments", {{"resource", "vct.fragments"}}},
      {"image.final", rgb("engine.display")},
  };
  for (int level = 1; level < levels; ++level)
    stages["mip.iso." + std::to_string(level)] = {{"resource", "engine.voxels"}, {"mip", level}, {"event", "engine.mips"}};
  const nlohmann::json settings = {{"n_dot_v", "abs"}, {"voxelizer", "gpu"}, {"shadow_map_size", s.vct.shadow_map_size}};
  return {{"format", "vct-capture-map"},
          {"version", 1},
          {"rows", "bottom_first"},
          {"manifest",
           {{"backend", "test-engine"},
            {"storage", "rgba16f"},
            {"reduction", "fixed_point"},
            {"settings", settings},
            {"facts", r.facts},
            {"conventions", {{"display", {{"operator", "reinhard"}, {"gamma", 2.2}, {"bits", 8}}}}}}},
          {"stages", stages}};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: test_engine MAP.json\n");
    return 1;
  }
  try {
    const char* scale_text = std::getenv("VCT_TEST_ENGINE_MIP_SCALE");
    const float scale = scale_text ? std::strtof(scale_text, nullptr) : 1.0f;
    vct::gl::GlContext context;
    const vct::Scene scene = vct::load_scene("");
    const vct::Settings s = engine_settings();
    vct::gl::GlOptions options;
    options.renderdoc_capture = false;  // one capture for our frame and the engine's passes
    vct::gl::RenderDocFrame capture;
    const vct::FrameResult r = vct::gl::render_gl_frame(context, scene, s, options);
    engine_mips(r.voxels.radiance, scale);
    engine_display(r.images.final_image);
    glFinish();
    capture.end();
    int levels = 1;
    while ((s.vct.grid >> levels) > 0) ++levels;
    std::ofstream(argv[1]) << capture_map(r, s, levels).dump(1) << "\n";
  } catch (const vct::EnvironmentError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
