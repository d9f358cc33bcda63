// Small glTF documents built in code for loader tests: a unit quad (4 vertices, 2 triangles)
// whose JSON and binary buffer tests can break in one specific way each.
#pragma once

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

#include <nlohmann/json.hpp>

namespace vct::test {

inline std::string base64(const std::string& in) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const uint32_t v = uint32_t(uint8_t(in[i])) << 16 | uint32_t(uint8_t(in[i + 1])) << 8 | uint8_t(in[i + 2]);
    out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], t[v & 63]};
  }
  if (i + 1 == in.size()) {
    const uint32_t v = uint32_t(uint8_t(in[i])) << 16;
    out += {t[v >> 18], t[(v >> 12) & 63], '=', '='};
  } else if (i + 2 == in.size()) {
    const uint32_t v = uint32_t(uint8_t(in[i])) << 16 | uint32_t(uint8_t(in[i + 1])) << 8;
    out += {t[v >> 18], t[(v >> 12) & 63], t[(v >> 6) & 63], '='};
  }
  return out;
}

template <typename T>
void append(std::string& bin, std::initializer_list<T> values) {
  for (T v : values) bin.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

struct GltfDoc {
  nlohmann::json j;
  std::string bin;

  /// The document with buffer 0 embedded as a data URI (unless the test set uri/byteLength).
  std::string text() const {
    nlohmann::json d = j;
    auto& b = d["buffers"][0];
    if (!b.contains("uri")) b["uri"] = "data:application/octet-stream;base64," + base64(bin);
    if (!b.contains("byteLength")) b["byteLength"] = bin.size();
    return d.dump();
  }

  /// The document as a GLB container with buffer 0 in the BIN chunk.
  std::string glb() const {
    nlohmann::json d = j;
    d["buffers"][0] = {{"byteLength", bin.size()}};
    std::string json = d.dump();
    while (json.size() % 4) json += ' ';
    std::string body = bin;
    while (body.size() % 4) body += '\0';
    std::string out = "glTF";
    append<uint32_t>(out, {2u, uint32_t(12 + 8 + json.size() + 8 + body.size())});
    append<uint32_t>(out, {uint32_t(json.size()), 0x4E4F534Au});
    out += json;
    append<uint32_t>(out, {uint32_t(body.size()), 0x004E4942u});
    out += body;
    return out;
  }
};

/// Unit quad in the z=0 plane, front face +z: positions (view 0, 48 bytes), TEXCOORD_0 (view 1,
/// 32 bytes, u along +x, v decreasing with y), uint16 indices (view 2, 12 bytes). No normals:
/// the loader generates flat ones. One node (node 0) holds mesh 0; material 0 is white.
inline GltfDoc quad_doc() {
  GltfDoc d;
  append<float>(d.bin, {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0});
  append<float>(d.bin, {0, 1, 1, 1, 1, 0, 0, 0});
  append<uint16_t>(d.bin, {0, 1, 2, 0, 2, 3});
  d.j = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"name", "quad"}, {"mesh", 0}}}},
      {"meshes",
       {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 1}}}, {"indices", 2}, {"material", 0}}}}}}},
      {"materials", {{{"name", "white"}, {"pbrMetallicRoughness", {{"metallicFactor", 0.0}}}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"},
         {"min", {0, 0, 0}}, {"max", {1, 1, 0}}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}},
        {{"bufferView", 2}, {"componentType", 5123}, {"count", 6}, {"type", "SCALAR"}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 48}},
        {{"buffer", 0}, {"byteOffset", 48}, {"byteLength", 32}},
        {{"buffer", 0}, {"byteOffset", 80}, {"byteLength", 12}}}},
      {"buffers", {nlohmann::json::object()}},
  };
  return d;
}

/// A fresh directory per test process for files the tests write.
/// Removed when the test process exits.
inline std::filesystem::path temp_dir() {
  struct Dir {
    std::filesystem::path path;
    ~Dir() {
      std::error_code ec;
      std::filesystem::remove_all(path, ec);
    }
  };
  static const Dir dir = [] {
    auto p = std::filesystem::temp_directory_path() / ("vct_loader_test_" + std::to_string(::getpid()));
    std::filesystem::create_directories(p);
    return Dir{p};
  }();
  return dir.path;
}

inline std::string slurp_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline std::string write_file(const std::string& name, const std::string& bytes) {
  const auto path = temp_dir() / name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path.string();
}

}  // namespace vct::test
