// glTF entry points: reading the file, the container checks tinygltf leaves to us (GLB header
// and chunk lengths, JSON syntax, asset version), then tinygltf's parse, our structural checks
// (gltf_validate.cpp) and the conversion into the flat Scene.
#include "scene/gltf_loader.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>

#include <nlohmann/json.hpp>

#include "core/memory_budget.h"
#include "io/bounded_file.h"
#include "io/bounded_json.h"
#include "scene/embedded_scenes.h"
#include "scene/gltf_file_access.h"
#include "scene/gltf_image_budget.h"
#include "scene/gltf_internal.h"
#include "scene/gltf_property_table.h"
#include "scene/scene_finite.h"
#include "scene/texture_mips.h"

namespace vct {
namespace gltf {

void fail(const Context& ctx, const std::string& message) { throw InputError(ctx.file, message); }

const std::vector<std::string>& supported_extensions() {
  static const std::vector<std::string> list = {"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                                "KHR_materials_specular", "KHR_texture_transform"};
  return list;
}

}  // namespace gltf

namespace {

namespace fs = std::filesystem;

// tinygltf reports several lines and parsers echo raw file bytes (a corrupt base64 buffer came
// back whole, 4 MB in one line); we report one printable line quoting at most 300 characters.
std::string one_line(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  std::string out;
  for (char c : s) {
    if (c == '\n') out += "; ";
    else if (c != '\r') out += c;
  }
  return input_excerpt(out, 300);
}

std::string read_bytes(const std::string& path) {
  std::string bytes = read_regular_file(path, kMaxSceneFileBytes, "glTF file");
  if (bytes.empty()) throw InputError(path, "empty file");
  return bytes;
}

// The checks tinygltf would report unclearly or not at all: JSON syntax, asset.version,
// required extensions. Warns about used-but-unsupported extensions.
nlohmann::json precheck_json(const std::string& text, const std::string& name, std::vector<std::string>& warnings) {
  const size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos || text[first] != '{') {
    throw InputError(name, "not a glTF file (neither a JSON object nor a GLB container)");
  }
  // The one bounded reader (io/bounded_json.h): tinygltf converts the JSON by recursion, and a
  // deep enough document would end the process with a stack overflow.
  nlohmann::json j = parse_bounded_json(text, name);
  if (!j.is_object() || !j.contains("asset") || !j["asset"].is_object()) {
    throw InputError(name, "not a glTF file (no \"asset\" object)");
  }
  const auto& asset = j["asset"];
  if (!asset.contains("version") || !asset["version"].is_string()) {
    throw InputError(name, "asset.version is missing; only glTF 2.0 is supported");
  }
  const std::string version = asset["version"];
  if (version.rfind("2.", 0) != 0) throw InputError(name, "glTF version " + version + " is not supported (need 2.0)");
  if (asset.contains("minVersion") && asset["minVersion"].is_string() && asset["minVersion"] != "2.0") {
    throw InputError(name, "asset.minVersion " + asset["minVersion"].get<std::string>() + " is newer than 2.0");
  }
  const auto& ok = gltf::supported_extensions();
  auto supported = [&](const std::string& e) { return std::find(ok.begin(), ok.end(), e) != ok.end(); };
  if (j.contains("extensionsRequired") && j["extensionsRequired"].is_array()) {
    for (const auto& e : j["extensionsRequired"]) {
      if (!e.is_string() || !supported(e.get<std::string>())) {
        throw InputError(name, "requires extension " + e.dump() + ", which is not supported (docs/scenes.md lists the supported ones)");
      }
    }
  }
  if (j.contains("extensionsUsed") && j["extensionsUsed"].is_array()) {
    for (const auto& e : j["extensionsUsed"]) {
      // KHR_materials_* are said per material, with what is rendered instead (gltf_material_extensions.cpp).
      if (e.is_string() && !supported(e.get<std::string>()) && e.get<std::string>().rfind("KHR_materials_", 0) != 0)
        warnings.push_back("extension " + e.get<std::string>() + " is ignored");
    }
  }
  return j;
}

// tinygltf names images by index ("image[3]"); add the file name so the user knows which one.
std::string name_image(const std::string& message, const nlohmann::json& doc) {
  const size_t at = message.find("image[");
  if (at == std::string::npos) return message;
  const size_t index = std::strtoul(message.c_str() + at + 6, nullptr, 10);
  if (!doc.contains("images") || !doc["images"].is_array() || index >= doc["images"].size()) return message;
  const auto& img = doc["images"][index];
  if (!img.contains("uri") || !img["uri"].is_string()) return message + " (image stored in a bufferView)";
  const std::string uri = img["uri"];
  return message + (uri.rfind("data:", 0) == 0 ? " (embedded data URI)" : " (uri '" + uri + "')");
}

uint32_t u32_at(const std::string& b, size_t at) {
  uint32_t v;
  std::memcpy(&v, b.data() + at, 4);
  return v;  // GLB is little-endian, as is every platform we build on
}

// GLB container (glTF 2.0 §4.4): 12-byte header, a JSON chunk, an optional BIN chunk.
std::string check_glb(const std::string& b, const std::string& name) {
  if (b.size() < 12) throw InputError(name, "GLB file is shorter than its 12-byte header");
  const uint32_t version = u32_at(b, 4), length = u32_at(b, 8);
  if (version != 2) throw InputError(name, "GLB container version " + std::to_string(version) + " is not supported (need 2)");
  if (length != b.size()) {
    throw InputError(name, "GLB header says " + std::to_string(length) + " bytes but the file has " +
                               std::to_string(b.size()) + (length > b.size() ? " (truncated?)" : ""));
  }
  if (b.size() < 20) throw InputError(name, "GLB file has no JSON chunk");
  const uint64_t json_len = u32_at(b, 12);
  if (u32_at(b, 16) != 0x4E4F534Au) throw InputError(name, "first GLB chunk is not JSON");
  if (20 + json_len > b.size()) throw InputError(name, "GLB JSON chunk length " + std::to_string(json_len) + " runs past the end of the file");
  const uint64_t bin_at = 20 + json_len;
  if (bin_at + 8 <= b.size()) {
    const uint64_t bin_len = u32_at(b, size_t(bin_at));
    if (bin_at + 8 + bin_len > b.size()) throw InputError(name, "GLB BIN chunk length " + std::to_string(bin_len) + " runs past the end of the file");
  } else if (bin_at != b.size()) {
    throw InputError(name, "GLB file has " + std::to_string(b.size() - bin_at) + " stray bytes after the JSON chunk");
  }
  return b.substr(20, size_t(json_len));
}

// A scene without any light renders black in every engine; say so rather than exit 0 in silence.
void warn_if_unlit(Scene& scene) {
  const bool emissive = std::any_of(scene.triangle_material.begin(), scene.triangle_material.end(),
                                    [&](uint32_t m) { return scene.materials[m].is_emissive(); });
  if (scene.lights.empty() && scene.emitters.empty() && !emissive) {
    scene.stats.warnings.push_back("the scene has no light (no punctual light, no emissive surface, no particles): "
                                   "every image will be black");
  }
}

Scene convert(const tinygltf::Model& model, const std::string& name, std::vector<std::string> warnings) {
  const gltf::Context ctx{model, name};
  gltf::validate_model(ctx);
  gltf::validate_lights(ctx);
  Scene scene;
  scene.source = name;
  scene.stats.warnings = std::move(warnings);
  gltf::warn_hard_spots(ctx, scene.stats.warnings);
  gltf::convert_textures(ctx, scene);
  gltf::convert_materials(ctx, scene);
  build_texture_mips(scene);  // once, for the encodings the materials read
  gltf::convert_nodes(ctx, scene);
  if (scene.triangles.empty()) gltf::fail(ctx, "the scene contains no triangles to render");
  warn_if_unlit(scene);
  if (scene.materials.empty()) {
    Material d;
    d.name = "default";
    scene.materials.push_back(d);
  }
  if (!gltf::read_volume_override(ctx, scene.volume)) scene.volume = fit_volume(scene.bounds);
  if (!scene.camera.from_file) {
    scene.camera = default_camera(scene.bounds);
  } else if (scene.camera.zfar == 0.0f) {
    // glTF's infinite projection: far enough to see the whole scene from the camera.
    const float reach = glm::length(scene.bounds.center() - scene.camera.position) + glm::length(scene.bounds.extent());
    scene.camera.zfar = std::max(2.0f * reach, scene.camera.znear * 10.0f);
  }
  check_scene_finite(scene, name);  // lights, camera and emitters as the renderers will read them
  return scene;
}

Scene parse(const std::string& bytes, bool glb, const std::string& name, const std::string& base_dir,
            const SceneLoadOptions& options) {
  std::vector<std::string> warnings;
  const nlohmann::json doc = precheck_json(glb ? check_glb(bytes, name) : bytes, name, warnings);
  gltf::check_document_properties(doc, name);  // before tinygltf turns bad values into defaults
  // The policy is checked on every URI before tinygltf opens any file, and tinygltf opens files
  // only through the policy's callbacks (gltf_file_access.h).
  const gltf::FileAccess access(base_dir, options.allow_outside_scene_dir);
  gltf::check_document_uris(doc, name, access);
  gltf::ImageBudget budget;
  budget.available = options.image_memory_budget ? options.image_memory_budget : physical_memory_bytes();
  tinygltf::TinyGLTF loader;
  loader.SetFsCallbacks(access.callbacks());
  loader.SetImageLoader(&gltf::load_image_within_budget, &budget);
  tinygltf::Model model;
  std::string err, warn;
  bool ok = false;
  try {
    if (glb) {
      ok = loader.LoadBinaryFromMemory(&model, &err, &warn, reinterpret_cast<const unsigned char*>(bytes.data()),
                                       static_cast<unsigned int>(bytes.size()), base_dir);
    } else {
      ok = loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), static_cast<unsigned int>(bytes.size()), base_dir);
    }
  } catch (const std::exception& e) {
    throw InputError(name, std::string("glTF parse failed: ") + e.what());
  }
  if (!budget.refusal.empty()) throw InputError(name, budget.refusal);
  if (!ok) throw InputError(name, "tinygltf: " + name_image(one_line(err.empty() ? "parse failed" : err), doc));
  std::istringstream lines(warn);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty()) warnings.push_back(line);
  }
  return convert(model, name, std::move(warnings));
}

}  // namespace

Scene load_gltf_file(const std::string& path, const SceneLoadOptions& options) {
  const std::string bytes = read_bytes(path);
  const std::string base_dir = fs::path(path).parent_path().string();
  const bool glb = bytes.size() >= 4 && bytes.compare(0, 4, "glTF") == 0;
  if (!glb && fs::path(path).extension() == ".glb") throw InputError(path, "not a GLB file (bad magic, expected \"glTF\")");
  return parse(bytes, glb, path, base_dir.empty() ? "." : base_dir, options);
}

Scene load_gltf_text(const std::string& json_text, const std::string& name, const std::string& base_dir,
                     const SceneLoadOptions& options) {
  if (json_text.empty()) throw InputError(name, "empty file");
  return parse(json_text, false, name, base_dir, options);
}

Scene load_scene(const std::string& path_or_empty, const SceneLoadOptions& options) {
  if (!path_or_empty.empty()) return load_gltf_file(path_or_empty, options);
  const std::string& text = embedded_scene("cornell_box.gltf");
  if (text.empty()) throw InputError(kBuiltinSceneName, "the built-in scene is missing from this build");
  return load_gltf_text(text, kBuiltinSceneName, "", options);
}

}  // namespace vct
