// dump_hook.cpp -- our headless driver for the source design's renderer (righier/gidemo), the worked
// example of docs/examples/gidemo.md. It is NOT compiled into VCT Oracle: run.sh appends
// `#include "dump_hook.cpp"` to a copy of gidemo's src/main.cpp in place of its interactive
// main(), so this file sees gidemo's globals (scene, cam, voxelTexture, shadowMap, ...) and calls
// its own pass functions (renderShadowMap, voxelize, occlusionCulling, voxelCone) once.
// Everything here is ours; none of gidemo's lines are copied.
//
// Output (directory VCT_DUMP_DIR, default "dump/"): a stage set written with our
// tools/vct_dump/vct_dump.h, and box.gltf, the same scene with the positions gidemo's vertex
// shader computes (u_transform * p in float) baked in (docs/external_format.md, "The scene as
// glTF with the same vertex positions").
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "vct_dump.h"

namespace vct_hook {

constexpr int kGrid = 64;        // issue 21's run: a 64^3 grid (gidemo's default is 128)
constexpr int kImageSide = 128;  // a 128^2 window (gidemo's default is 1280x720)

std::vector<float> g_fragments;  // per-voxel fragment counts, read before fixopacity.comp

std::string dump_dir() {
  const char* d = std::getenv("VCT_DUMP_DIR");
  return d ? d : "dump/";
}

void get_texture_image(unsigned tex, int level, unsigned format, unsigned type, int size, void* pixels) {
  glGetTextureImage(tex, level, format, type, size, pixels);
}

// voxelize.frag's running mean keeps the fragment count in alpha as n/255 (val.a = 1/255 added per
// fragment, rounded to the RGBA16F storage each step) until fixopacity.comp sets alpha to 0/1.
void read_fragment_counts() {
  std::vector<float> rgba(size_t(kGrid) * kGrid * kGrid * 4);
  glGetTextureImage(voxelTexture->id, 0, GL_RGBA, GL_FLOAT, int(rgba.size() * sizeof(float)), rgba.data());
  g_fragments.resize(rgba.size() / 4);
  for (size_t i = 0; i < g_fragments.size(); ++i) g_fragments[i] = std::round(rgba[i * 4 + 3] * 255.0f);
}

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const unsigned v = (unsigned(bytes[i]) << 16) | (i + 1 < bytes.size() ? unsigned(bytes[i + 1]) << 8 : 0u) |
                       (i + 2 < bytes.size() ? unsigned(bytes[i + 2]) : 0u);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[v & 63] : '=';
  }
  return out;
}

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", v);
  return b;
}

std::string vec3_json(const glm::vec3& v) { return "[" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + "]"; }

// One mesh and one material per gidemo Object, world positions baked as its vertex shaders compute
// them (u_transform * vec4(p, 1), float), normals by the inverse transpose (voxelize.vert).
void write_gltf(const std::string& path) {
  std::vector<unsigned char> buffer;
  auto append = [&buffer](const void* p, size_t n) {
    const auto* c = static_cast<const unsigned char*>(p);
    buffer.insert(buffer.end(), c, c + n);
  };
  std::string meshes, materials, nodes, accessors, views;
  int node_count = 0;
  for (size_t o = 0; o < scene.objects.size(); ++o) {
    Object& obj = scene.objects[o];
    const mat4 m = obj.genMatrix();
    const mat3 nm = mat3(transpose(inverse(m)));
    glm::vec3 lo(1e30f), hi(-1e30f);
    std::vector<float> pos, nrm;
    for (const Vertex& v : obj.mesh->vertices) {
      const glm::vec3 p = glm::vec3(m * glm::vec4(v.p, 1.0f));
      const glm::vec3 n = glm::normalize(nm * v.n);
      lo = glm::min(lo, p), hi = glm::max(hi, p);
      pos.insert(pos.end(), {p.x, p.y, p.z});
      nrm.insert(nrm.end(), {n.x, n.y, n.z});
    }
    const std::vector<uint32_t>& idx = obj.mesh->indices;
    const size_t count = obj.mesh->vertices.size();
    const int base_view = int(o) * 3;
    auto view = [&](const void* data, size_t bytes, const char* target) {
      views += std::string(views.empty() ? "" : ",\n    ") + "{\"buffer\": 0, \"byteOffset\": " +
               std::to_string(buffer.size()) + ", \"byteLength\": " + std::to_string(bytes) + ", \"target\": " + target + "}";
      append(data, bytes);
    };
    view(pos.data(), pos.size() * 4, "34962");
    view(nrm.data(), nrm.size() * 4, "34962");
    view(idx.data(), idx.size() * 4, "34963");
    accessors += std::string(accessors.empty() ? "" : ",\n    ") +
                 "{\"bufferView\": " + std::to_string(base_view) + ", \"componentType\": 5126, \"count\": " +
                 std::to_string(count) + ", \"type\": \"VEC3\", \"min\": " + vec3_json(lo) + ", \"max\": " + vec3_json(hi) +
                 "},\n    {\"bufferView\": " + std::to_string(base_view + 1) + ", \"componentType\": 5126, \"count\": " +
                 std::to_string(count) + ", \"type\": \"VEC3\"},\n    {\"bufferView\": " + std::to_string(base_view + 2) +
                 ", \"componentType\": 5125, \"count\": " + std::to_string(idx.size()) + ", \"type\": \"SCALAR\"}";
    // voxelize.frag and voxelcone.frag linearise the editor colour: albedo = pow(u_diffuse, 2.2).
    const glm::vec3 albedo = glm::pow(obj.mat.diffuse, glm::vec3(2.2f));
    materials += std::string(materials.empty() ? "" : ",\n    ") + "{\"name\": \"" + obj.name +
                 "\", \"pbrMetallicRoughness\": {\"baseColorFactor\": [" + num(albedo.x) + ", " + num(albedo.y) + ", " +
                 num(albedo.z) + ", 1], \"metallicFactor\": " + num(obj.mat.metal) + ", \"roughnessFactor\": " +
                 num(obj.mat.rough) + "}}";
    meshes += std::string(meshes.empty() ? "" : ",\n    ") + "{\"name\": \"" + obj.name +
              "\", \"primitives\": [{\"attributes\": {\"POSITION\": " + std::to_string(base_view) + ", \"NORMAL\": " +
              std::to_string(base_view + 1) + "}, \"indices\": " + std::to_string(base_view + 2) + ", \"material\": " +
              std::to_string(o) + "}]}";
    nodes += std::string(nodes.empty() ? "" : ",\n    ") + "{\"name\": \"" + obj.name + "\", \"mesh\": " + std::to_string(o) + "}";
    ++node_count;
  }
  // The camera: gidemo's view is rotate(-vrot, x) rotate(-hrot, y) translate(-pos); in our run
  // hrot = vrot = 0, so the camera node is a translation and looks along -Z like a glTF camera.
  nodes += ",\n    {\"name\": \"camera\", \"camera\": 0, \"translation\": " + vec3_json(cam.pos) + "}";
  // The spot: its node frame is the one light.h's lookAt builds, so the reference's shadow map
  // (node -Z forward, node +Y up) has gidemo's orientation: f = dir, up = normalize(cross(dir + z, dir)),
  // right = cross(f, up) (glm::lookAt's s), true up = cross(s, f).
  const glm::vec3 f = glm::normalize(scene.light.dir);
  const glm::vec3 up0 = glm::normalize(glm::cross(scene.light.dir + glm::vec3(0, 0, 1), scene.light.dir));
  const glm::vec3 s = glm::normalize(glm::cross(f, up0));
  const glm::vec3 u = glm::cross(s, f);
  const glm::vec3 p = scene.light.pos;
  nodes += ",\n    {\"name\": \"spot\", \"extensions\": {\"KHR_lights_punctual\": {\"light\": 0}}, \"matrix\": [" +
           num(s.x) + ", " + num(s.y) + ", " + num(s.z) + ", 0, " + num(u.x) + ", " + num(u.y) + ", " + num(u.z) + ", 0, " +
           num(-f.x) + ", " + num(-f.y) + ", " + num(-f.z) + ", 0, " + num(p.x) + ", " + num(p.y) + ", " + num(p.z) + ", 1]}";
  // light.h: outer cos = cos(angle/2), inner cos = cos((angle - smooth)/2), smoothstep between them,
  // falloff 1/(1 + d): our `light_model: seed` reads the same numbers (docs/scenes.md).
  const float kPi = 3.14159265358979f;
  const std::string light = "{\"type\": \"spot\", \"color\": [1, 1, 1], \"intensity\": " + num(scene.light.color.x) +
                            ", \"spot\": {\"innerConeAngle\": " + num((scene.light.angle - scene.light.smooth) * 0.5f * kPi / 180.0f) +
                            ", \"outerConeAngle\": " + num(scene.light.angle * 0.5f * kPi / 180.0f) + "}}";
  std::string scene_nodes;
  for (int i = 0; i < node_count + 2; ++i) scene_nodes += (i ? ", " : "") + std::to_string(i);
  std::ostringstream j;
  // gidemo's voxel cube is [-1, 1]^3 (voxelize.geom projects world x, y, z as clip coordinates;
  // toVoxel() = pos * 0.5 + 0.5): stated as our vct_volume override (docs/scenes.md).
  j << "{\n  \"asset\": {\"version\": \"2.0\", \"generator\": \"VCT Oracle docs/examples/gidemo/dump_hook.cpp\", "
    << "\"extras\": {\"vct_volume\": {\"origin\": [-1, -1, -1], \"size\": 2}}},\n"
    << "  \"extensionsUsed\": [\"KHR_lights_punctual\"],\n"
    << "  \"extensions\": {\"KHR_lights_punctual\": {\"lights\": [" << light << "]}},\n"
    << "  \"scene\": 0,\n  \"scenes\": [{\"nodes\": [" << scene_nodes << "]}],\n"
    << "  \"nodes\": [\n    " << nodes << "\n  ],\n"
    << "  \"cameras\": [{\"type\": \"perspective\", \"perspective\": {\"yfov\": " << num(cam.fov) << ", \"aspectRatio\": "
    << num(cam.ratio) << ", \"znear\": " << num(cam.near) << ", \"zfar\": " << num(cam.far) << "}}],\n"
    << "  \"meshes\": [\n    " << meshes << "\n  ],\n"
    << "  \"materials\": [\n    " << materials << "\n  ],\n"
    << "  \"accessors\": [\n    " << accessors << "\n  ],\n"
    << "  \"bufferViews\": [\n    " << views << "\n  ],\n"
    << "  \"buffers\": [{\"byteLength\": " << buffer.size() << ", \"uri\": \"data:application/octet-stream;base64,"
    << base64(buffer) << "\"}]\n}\n";
  std::ofstream(path) << j.str();
}

// The camera passes' target (run.sh points occlusionCulling() and voxelCone() here): RGBA8 like
// the window's 8-bit colour, one sample per pixel, so each pixel is the shading at its centre;
// the window itself is 4x MSAA, whose resolve would average the samples of edge pixels.
GLuint g_frame_fbo = 0, g_frame_colour = 0;

GLuint frame_target() {
  if (g_frame_fbo) return g_frame_fbo;
  GLuint depth = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &g_frame_colour);
  glTextureStorage2D(g_frame_colour, 1, GL_RGBA8, kImageSide, kImageSide);
  glCreateTextures(GL_TEXTURE_2D, 1, &depth);
  glTextureStorage2D(depth, 1, GL_DEPTH_COMPONENT24, kImageSide, kImageSide);  // the window's depth bits
  glCreateFramebuffers(1, &g_frame_fbo);
  glNamedFramebufferTexture(g_frame_fbo, GL_COLOR_ATTACHMENT0, g_frame_colour, 0);
  glNamedFramebufferTexture(g_frame_fbo, GL_DEPTH_ATTACHMENT, depth, 0);
  return g_frame_fbo;
}

void read_frame(vct_dump::StageSetWriter& w, const std::string& stage) {
  vct_dump::image_from_gl(w, stage, get_texture_image, g_frame_colour, kImageSide, kImageSide, /*depth=*/false);
}

// gbuffer.normal: gidemo has no G-buffer, so a pass of ours draws its objects (their meshes and
// u_transform, through gidemo's Object::draw) with the normal its shaders shade with:
// mat3(transpose(inverse(u_transform))) * i_normal, normalised (voxelcone.vert / .frag).
GLuint compile_normal_program() {
  const char* vs = R"(#version 450 core
layout(location = 0) in vec3 i_position;
layout(location = 2) in vec3 i_normal;
uniform mat4 u_project;
uniform mat4 u_transform;
out vec3 v_normal;
void main() {
  v_normal = mat3(transpose(inverse(u_transform))) * i_normal;
  gl_Position = u_project * (u_transform * vec4(i_position, 1.0));
})";
  const char* fs = R"(#version 450 core
in vec3 v_normal;
layout(location = 0) out vec4 o_normal;
void main() { o_normal = vec4(normalize(v_normal), 1.0); })";
  GLuint program = glCreateProgram();
  for (auto [type, text] : {std::pair<GLenum, const char*>{GL_VERTEX_SHADER, vs}, {GL_FRAGMENT_SHADER, fs}}) {
    GLuint sh = glCreateShader(type);
    glShaderSource(sh, 1, &text, nullptr);
    glCompileShader(sh);
    glAttachShader(program, sh);
  }
  glLinkProgram(program);
  return program;
}

void dump_normal(vct_dump::StageSetWriter& w) {
  GLuint fbo = 0, colour = 0, depth = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &colour);
  glTextureStorage2D(colour, 1, GL_RGBA32F, kImageSide, kImageSide);
  glCreateTextures(GL_TEXTURE_2D, 1, &depth);
  glTextureStorage2D(depth, 1, GL_DEPTH_COMPONENT32F, kImageSide, kImageSide);
  glCreateFramebuffers(1, &fbo);
  glNamedFramebufferTexture(fbo, GL_COLOR_ATTACHMENT0, colour, 0);
  glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, depth, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, kImageSide, kImageSide);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);  // gidemo's frame passes' test: at an exact depth tie the last drawn wins
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  const float zero[4] = {0, 0, 0, 0};
  glClearBufferfv(GL_COLOR, 0, zero);
  glClear(GL_DEPTH_BUFFER_BIT);
  Shader normal_shader;  // gidemo's wrapper around our program, so Object::draw sets u_transform
  normal_shader.id = int(compile_normal_program());
  normal_shader.bind();
  normal_shader.set("u_project", cam.final);
  scene.drawObjects(0.0, &normal_shader, false);
  glFinish();
  vct_dump::image_from_gl(w, "gbuffer.normal", get_texture_image, colour, kImageSide, kImageSide, /*depth=*/false);
  Framebuffer::reset();
}

// gidemo's render modes (main.cpp renderModeText) are its frame components, each tone-mapped like
// the final: 0 direct light only, 1 indirect diffuse (restitution x the sum of its 5 cones, no
// albedo), 2 indirect specular (the raw cone), 3 the composite.
void render_frame(int mode) {
  renderMode = mode;
  glBindFramebuffer(GL_FRAMEBUFFER, frame_target());
  glViewport(0, 0, kImageSide, kImageSide);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearColor(0.f, 0.f, 0.f, 1.f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  occlusionCulling(0.0);
  voxelCone(0.0);
  glFinish();
}

void dump_frames(vct_dump::StageSetWriter& w) {
  const char* stages[4] = {"image.direct", "image.indirect_diffuse", "image.indirect_specular", "image.final"};
  for (int mode = 0; mode < 4; ++mode) {
    render_frame(mode);
    read_frame(w, stages[mode]);
  }
}

// gbuffer.depth at pixel centres: gidemo's own depth pre-pass (shadowShader with the camera's
// matrix, as occlusionCulling() draws it) into a single-sample DEPTH32F target of ours. The
// window's depth buffer is 4x multisampled and its read-back resolves to a sample, not the centre.
void dump_depth(vct_dump::StageSetWriter& w) {
  GLuint fbo = 0, tex = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &tex);
  glTextureStorage2D(tex, 1, GL_DEPTH_COMPONENT32F, kImageSide, kImageSide);
  glCreateFramebuffers(1, &fbo);
  glNamedFramebufferTexture(fbo, GL_DEPTH_ATTACHMENT, tex, 0);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glViewport(0, 0, kImageSide, kImageSide);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);  // gidemo's frame passes' test: at an exact depth tie the last drawn wins
  glEnable(GL_CULL_FACE);
  glCullFace(GL_BACK);
  glClear(GL_DEPTH_BUFFER_BIT);
  shadowShader->bind();
  shadowShader->set("u_project", cam.final);
  scene.drawObjects(0.0, shadowShader, false);
  glFinish();
  vct_dump::image_from_gl(w, "gbuffer.depth", get_texture_image, tex, kImageSide, kImageSide, /*depth=*/true);
  Framebuffer::reset();
}

void record_facts(vct_dump::StageSetWriter& w) {
  GLint samples = 0, depth_bits = 0;
  glGetIntegerv(GL_SAMPLES, &samples);
  w.set_fact("msaa_samples", int(samples));
  // Where the voxelization pass samples (it draws into this window): GL_SAMPLE_POSITION in pixel
  // units, lower-left origin (GL 4.5 §14.3.1), which `vct render --facts-from` makes the reference use.
  std::vector<std::vector<double>> positions;
  for (GLint i = 0; i < samples; ++i) {
    GLfloat xy[2] = {0, 0};
    glGetMultisamplefv(GL_SAMPLE_POSITION, GLuint(i), xy);
    positions.push_back({double(xy[0]), double(xy[1])});
  }
  if (!positions.empty()) w.set_fact("sample_positions", positions);
  GLint subpixel_bits = 0;
  glGetIntegerv(GL_SUBPIXEL_BITS, &subpixel_bits);
  w.set_fact("subpixel_bits", int(subpixel_bits));
  w.set_fact("renderer", std::string(reinterpret_cast<const char*>(glGetString(GL_RENDERER))));
  w.set_fact("vendor", std::string(reinterpret_cast<const char*>(glGetString(GL_VENDOR))));
  w.set_fact("version", std::string(reinterpret_cast<const char*>(glGetString(GL_VERSION))));
  glGetTextureLevelParameteriv(shadowMap->t->id, 0, GL_TEXTURE_DEPTH_SIZE, &depth_bits);
  // shadowMap is an unsized GL_DEPTH_COMPONENT texture (assets.h): the driver picks its depth
  // (llvmpipe: 24 bits), which our setting shadow_depth_format states.
  if (depth_bits == 16 || depth_bits == 24) w.set_setting("shadow_depth_format", "depth" + std::to_string(depth_bits));
  std::printf("vct_hook: GL_SAMPLES %d, shadow depth bits %d, %s\n", samples, depth_bits, glGetString(GL_RENDERER));
}

// What gidemo ran, in our settings keys (docs/settings.md), so `vct compare --scene` and a reader of
// the manifest see the run's parameters.
void record_settings(vct_dump::StageSetWriter& w) {
  w.set_setting("grid", kGrid);
  w.set_setting("width", kImageSide);
  w.set_setting("height", kImageSide);
  w.set_setting("voxelizer", "gpu");
  w.set_setting("light_model", "seed");
  w.set_setting("shadow_map_size", 2048);
  w.set_setting("shadow_fov_deg", double(scene.light.angle));  // light.h: perspective(radians(angle), 1, 0.01, 3)
  w.set_setting("shadow_near", 0.01);
  w.set_setting("shadow_far", 3.0);
  w.set_setting("shadow_bias", double(shadowBias));
  w.set_setting("bounces", 1);
  // u_restitution multiplies render mode 1 (image.indirect_diffuse) and the composite alike
  // (voxelcone.frag: indirectDiffuse *= u_restitution): our indirect_diffuse_gain.
  w.set_setting("indirect_diffuse_gain", double(restitution));
}

void dump_all() {
  vct_dump::StageSetWriter w(dump_dir(), "gidemo");
  w.set_storage("rgba16f");          // Texture::init3D with hdrVoxels = true
  w.set_reduction("running_mean");   // voxelize.frag: imageLoad, weighted mean, imageStore, no atomics
  record_settings(w);
  record_facts(w);
  w.set_convention("mip_scale", 1.9);  // mipmap.comp: textureLod(...) * 1.9
  vct_dump::Object display;            // voxelcone.frag: Reinhard, gamma 2.2, 8-bit window
  display.set("operator", "reinhard");
  display.set("gamma", 2.2);
  display.set("bits", 8);
  display.set("stages", std::vector<std::string>{"image.direct", "image.indirect_diffuse", "image.indirect_specular", "image.final"});
  w.set_convention("display", display);
  for (int level = 0, n = kGrid; n >= 1; ++level, n /= 2)
    vct_dump::volume_from_gl(w, level == 0 ? "voxel.radiance" : "mip.iso." + std::to_string(level), get_texture_image,
                             voxelTexture->id, level, n, n, n);
  w.volume("voxel.fragments", kGrid, kGrid, kGrid, 1, g_fragments.data());
  vct_dump::image_from_gl(w, "shadow_map.0", get_texture_image, shadowMap->t->id, 2048, 2048, /*depth=*/true);
  dump_frames(w);
  dump_depth(w);
  dump_normal(w);
  if (!w.finish()) std::fprintf(stderr, "vct_dump: %s\n", w.error().c_str());
  write_gltf(dump_dir() + "box.gltf");
}

}  // namespace vct_hook

// Replaces Framebuffer::reset() in gidemo's occlusionCulling() and voxelCone() (run.sh).
void vct_hook_bind_frame_target() { glBindFramebuffer(GL_FRAMEBUFFER, vct_hook::frame_target()); }

// Inserted by run.sh into gidemo's voxelize(), before fixopacity.comp turns the count into 0/1.
void vct_hook_before_fixopacity() {
  glMemoryBarrier(GL_ALL_BARRIER_BITS);
  vct_hook::read_fragment_counts();
}

int main() {
  System::init(4, 6);  // what gidemo asks for (run.sh sets MESA_GL_VERSION_OVERRIDE=4.6 for llvmpipe)
  Window::create(vct_hook::kImageSide, vct_hook::kImageSide, "gidemo headless", Window::WINDOWED, false);
  Window::update();
  voxelCount = vct_hook::kGrid;
  temporalMultibounce = false;  // one frame: nothing to bounce yet (the seed model)
  addDiffuseNoise = false;      // deterministic cone frames in image.final
  cam = Camera(glm::radians(60.f), 1.0f, .1f, 100.f);
  cam.pos = vec3(0.f, 0.f, 3.f);
  cam.update();
  loadAssets();
  addCornellBox(false);  // main.cpp's box: five planes, one spot (issue 21's "box scene")
  initVoxelize();
  // Experiment knob (docs/examples/gidemo.md): gidemo's "Diffuse restitution" slider, the gain of
  // its indirect diffuse (addCornellBox sets 0.15); the manifest records it as indirect_diffuse_gain.
  if (const char* r = std::getenv("VCT_HOOK_RESTITUTION")) restitution = float(std::atof(r));
  renderShadowMap(0.0);
  voxelize(0.0);
  vct_hook::dump_all();
  System::exit(0);
}
