// A small engine with its own conventions, for judging a real program through a RenderDoc capture
// (issue 39, tests/cli/test_engine_capture_test.cpp). It drives our GL frame (gl/gl_pipeline.h)
// for what it shares with it -- shadow map, G-buffer, voxelization and light injection with the
// oracle's 3x3 PCF -- and runs its own passes after it (GlOptions::extra_passes) where it differs:
//  - its own direct light: |n.v| in the BRDF (sh::view_cosine NV_ABS) and its own frame PCF, 4x4
//    taps off centre at {-3, -2, -1, 0} texels given as UV offsets, each the map's depth filtered
//    by the driver (GL_LINEAR on a plain sampler2DArray, CLAMP_TO_BORDER with border depth 0) and
//    compared once (filter then compare, a shadowed border);
//  - its own isotropic mips, a plain box filter of the 2x2x2 children (x 1;
//    VCT_TEST_ENGINE_MIP_SCALE=s multiplies each level by s, the source design's x1.9 bug);
//  - its own composite and display: our final with its direct light in place of ours, then
//    Reinhard x/(1+x) and gamma 2.2 into RGBA8.
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
#include "gl/gl_frame.h"
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

// The engine's direct light on our G-buffer, lights and shadow map (lights.glsl, gbuffer_read.glsl).
// Its PCF: the lookup point moved by our normal offset with its own taps' reach (u_pcf_kernel 8:
// 4 texels, the reference's pcf_reach of linear taps up to 3 texels away), then 16 taps at uv + o,
// each the driver's bilinear blend of the four depths around it (the sampler object bound to unit
// 4) compared once with the point's depth; outside the frustum lit.
const char* const kDirectShader = R"(
#include "lights.glsl"
#include "gbuffer_read.glsl"
uniform vec2 u_engine_taps[16];
layout(location = 0) out vec4 o_direct;

float engine_visibility(int i, vec3 p, vec3 n) {
  if (u_light_kind[i] == LIGHT_KIND_POINT) return surface_visibility(i, p, n);
  int layer = u_light_layer[i];
  vec4 clip = u_shadow_view_proj[layer] * vec4(shadow_lookup_point(i, p, n), 1.0f);
  if (clip.w <= 0.0f) return 1.0f;
  vec3 ndc = clip.xyz / clip.w;
  if (abs(ndc.x) > 1.0f || abs(ndc.y) > 1.0f || abs(ndc.z) > 1.0f) return 1.0f;
  float z = ndc.z * 0.5f + 0.5f;
  vec2 uv = ndc.xy * 0.5f + 0.5f;
  int lit = 0;
  for (int k = 0; k < 16; ++k)
    if (z <= texture(u_shadow_maps, vec3(uv + u_engine_taps[k], float(layer))).r + u_shadow_bias) ++lit;
  return float(lit) / 16.0f;
}

void main() {
  GSample g = read_gbuffer(ivec2(gl_FragCoord.xy));
  o_direct = vec4(0.0f);
  if (!g.covered) return;
  vec3 v = to_eye(g.position);
  vec3 sum = vec3(0.0f);
  for (int i = 0; i < u_light_count; ++i) {
    vec3 l = light_vector(i, g.position);
    float n_dot_l = dot(g.normal, l);
    float vis = engine_visibility(i, g.position, g.normal);
    if (n_dot_l <= 0.0f) continue;
    sum += cook_torrance_nv(g.pbr, g.normal, v, l, NV_ABS) * light_irradiance(i, g.position) * n_dot_l * vis;
  }
  o_direct = vec4(sum, 0.0f);
}
)";

// Its composite and display: our final with its direct light in place of ours, Reinhard, then
// gamma 2.2, stored as RGBA8 UNORM.
const char* const kDisplayShader = R"(
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D u_final;
layout(binding = 1) uniform sampler2D u_our_direct;
layout(binding = 2) uniform sampler2D u_engine_direct;
layout(binding = 3, rgba8) uniform writeonly image2D u_display;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, imageSize(u_display)))) return;
  vec3 c = texelFetch(u_final, p, 0).rgb - texelFetch(u_our_direct, p, 0).rgb + texelFetch(u_engine_direct, p, 0).rgb;
  c = max(c, vec3(0.0));
  c = pow(c / (1.0 + c), vec3(1.0 / 2.2));
  imageStore(u_display, p, vec4(c, 1.0));
}
)";

// The engine's frame taps in UV: {-3, -2, -1, 0} texels of a 256^2 map per axis.
constexpr float kTapUv[4] = {-3.0f / 256.0f, -2.0f / 256.0f, -1.0f / 256.0f, 0.0f};

// A float as a decimal that reads back to it (9 significant digits).
std::string exact(float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", double(v));
  return buf;
}

// "dx,dy dx,dy ..." (pcf_taps) of the `count` first values per axis, x fastest.
std::string tap_list(const float* per_axis, int count) {
  std::string out;
  for (int j = 0; j < count; ++j)
    for (int i = 0; i < count; ++i) out += (out.empty() ? "" : " ") + exact(per_axis[i]) + "," + exact(per_axis[j]);
  return out;
}

GLuint texture_2d(GLenum format, int w, int h, const char* label) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, 1, format, w, h);
  glObjectLabel(GL_TEXTURE, t, -1, label);
  return t;
}

// The engine's voxel texture: level 0 copied from our frame's, its mips built by kMipShader.
void engine_mips(const vct::gl::GlFrame& f, float scale) {
  const int n = f.s.grid;
  GLuint tex = 0;
  glCreateTextures(GL_TEXTURE_3D, 1, &tex);
  glTextureStorage3D(tex, f.levels, GL_RGBA16F, n, n, n);
  glObjectLabel(GL_TEXTURE, tex, -1, "engine.voxels");
  glCopyImageSubData(f.radiance, GL_TEXTURE_3D, 0, 0, 0, 0, tex, GL_TEXTURE_3D, 0, 0, 0, 0, n, n, n);
  const Program mip = compute("engine_mip.comp", kMipShader);
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 2, -1, "engine.mips");
  mip.use();
  mip.set("u_scale", scale);
  for (int level = 1; level < f.levels; ++level) {
    glBindImageTexture(0, tex, level - 1, GL_TRUE, 0, GL_READ_ONLY, GL_RGBA16F);
    glBindImageTexture(1, tex, level, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    const GLuint groups = GLuint(std::max(1, (n >> level) / 4));
    glDispatchCompute(groups, groups, groups);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  glPopDebugGroup();
}

// The engine's direct light (kDirectShader) into "engine.direct".
GLuint engine_direct(vct::gl::GlFrame& f) {
  const GLuint out = texture_2d(GL_RGBA32F, f.s.width, f.s.height, "engine.direct");
  const Program prog({vct::gl::shader_file("fullscreen.vert"),
                      ShaderSource{GL_FRAGMENT_SHADER, "engine_direct.frag",
                                   vct::gl::assemble_source("engine_direct.frag", kDirectShader)}});
  GLuint fbo = 0;
  glCreateFramebuffers(1, &fbo);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, out, 0);
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 4, -1, "engine.direct");
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, f.s.width, f.s.height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  prog.use();
  f.geo.set_lights(prog, f.s, f.layer_view_proj, f.light_layer);
  prog.set("u_pcf_kernel", 8);  // the normal offset's reach: 4 texels, its linear taps'
  for (int k = 0; k < 16; ++k) prog.set(("u_engine_taps[" + std::to_string(k) + "]").c_str(), vct::vec2(kTapUv[k % 4], kTapUv[k / 4]));
  glBindTextureUnit(4, f.shadow_maps);
  // Its sampler: depths filtered bilinearly (no compare), a border of depth 0 read as shadowed.
  GLuint sampler = 0;
  glCreateSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
  glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  const float border[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glSamplerParameterfv(sampler, GL_TEXTURE_BORDER_COLOR, border);
  glBindSampler(4, sampler);
  for (GLuint i = 0; i < 6; ++i) glBindTextureUnit(12 + i, f.gbuffer[i]);
  prog.set("u_camera_position", f.scene.camera.position);
  prog.set("u_camera_forward", glm::normalize(f.scene.camera.forward));
  prog.set("u_camera_orthographic", f.scene.camera.orthographic ? 1 : 0);
  prog.set("u_volume_origin", f.scene.volume.origin);
  prog.set("u_volume_size", f.scene.volume.size);
  glBindVertexArray(f.empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glBindSampler(4, 0);
  glPopDebugGroup();
  return out;
}

// The engine's composite and display image (kDisplayShader) into "engine.display".
void engine_display(const vct::gl::GlFrame& f, GLuint direct) {
  const GLuint display = texture_2d(GL_RGBA8, f.s.width, f.s.height, "engine.display");
  const Program prog = compute("engine_display.comp", kDisplayShader);
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 3, -1, "engine.display");
  prog.use();
  glBindTextureUnit(0, f.shading[4]);
  glBindTextureUnit(1, f.direct);
  glBindTextureUnit(2, direct);
  glBindImageTexture(3, display, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA8);
  glDispatchCompute(GLuint((f.s.width + 7) / 8), GLuint((f.s.height + 7) / 8), 1);
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
      {"image.direct", rgb("engine.direct")},
      {"image.final", rgb("engine.display")},
  };
  for (int level = 1; level < levels; ++level)
    stages["mip.iso." + std::to_string(level)] = {{"resource", "engine.voxels"}, {"mip", level}, {"event", "engine.mips"}};
  // Its conventions as settings: |n.v|; the frame's PCF; the voxelizer's is the oracle's (our GL
  // frame injects with it).
  const nlohmann::json settings = {{"n_dot_v", "abs"},
                                   {"voxelizer", "gpu"},
                                   {"shadow_map_size", s.vct.shadow_map_size},
                                   {"shadow_compare", "linear"},
                                   {"shadow_filter_order", "filter_then_compare"},
                                   {"pcf_tap_unit", "uv"},
                                   {"pcf_taps", tap_list(kTapUv, 4)},
                                   {"shadow_border", "shadowed"},
                                   {"voxel_pcf", "oracle"}};
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
    int levels = 1;
    options.extra_passes = [&](vct::gl::GlFrame& f) {
      engine_mips(f, scale);
      engine_display(f, engine_direct(f));
      levels = f.levels;
    };
    vct::gl::RenderDocFrame capture;
    const vct::FrameResult r = vct::gl::render_gl_frame(context, scene, s, options);
    glFinish();
    capture.end();
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
