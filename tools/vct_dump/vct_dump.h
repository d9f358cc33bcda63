// vct_dump.h -- header-only helper an engine includes to write its textures and facts as a VCT
// Oracle stage set (docs/external_format.md, "For engine developers"): vct-stages.json plus one
// NRRD per volume and one PFM (1 or 3 channels) or uncompressed OpenEXR (2 or 4 channels) per
// image, readable by `vct compare REF DIR`.
//
// C++17, the standard library only. It takes plain CPU buffers; for GL, volume_from_gl /
// image_from_gl take the engine's own glGetTextureImage pointer (no GL header needed). Vulkan or
// D3D engines read their textures back into CPU buffers and call the same writer.
//
//   vct_dump::StageSetWriter w("dump/", "my-engine");
//   w.set_storage("rgba16f"); w.set_reduction("running_mean");
//   w.set_setting("grid", 128); w.set_fact("msaa_samples", 4); w.set_convention("mip_scale", 1.9);
//   w.set_convention("display", vct_dump::Object().set("operator", "reinhard").set("gamma", 2.2).set("bits", 8));
//   w.volume("voxel.radiance", n, n, n, 4, rgba);          // x fastest, then y, then z
//   w.volume("voxel.fragments", n, n, n, 1, counts);       // the cheapest decisive stage
//   w.image("shadow_map.0", size, size, 1, depth, vct_dump::Rows::BottomFirst);  // a GL read-back
//   if (!w.finish()) fprintf(stderr, "%s\n", w.error().c_str());
//
// Every file is written to a temporary name and renamed, the manifest last, so a crashed dump
// never looks complete.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace vct_dump {

enum class Rows { TopFirst, BottomFirst };  // GL read-backs are bottom row first

class Object;

// JSON text of the values a manifest holds: numbers, booleans, strings, lists of them, and
// objects (Object) for nested entries such as conventions.display.
namespace detail {
inline std::string quote(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\', o += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char b[8];
      std::snprintf(b, sizeof b, "\\u%04x", c);
      o += b;
    } else o += c;
  }
  return o + "\"";
}
inline std::string json_value(const std::string& v) { return quote(v); }
inline std::string json_value(const char* v) { return quote(v); }
// Any arithmetic type (bool, int, size_t, float, double, ...): no overload ambiguity for the
// integer types an engine happens to hold its sizes in.
template <typename T, std::enable_if_t<std::is_arithmetic_v<T>, int> = 0>
std::string json_value(T v) {
  if constexpr (std::is_same_v<T, bool>) {
    return v ? "true" : "false";
  } else if constexpr (std::is_integral_v<T>) {
    return std::to_string(v);
  } else {
    if (!std::isfinite(double(v))) return "null";
    char b[32];
    std::snprintf(b, sizeof b, "%.17g", double(v));
    return b;
  }
}
std::string json_value(const Object& v);
template <typename T>
std::string json_value(const std::vector<T>& list) {
  std::string o = "[";
  for (size_t i = 0; i < list.size(); ++i) o += (i ? ", " : "") + json_value(list[i]);
  return o + "]";
}
inline std::string object(const std::map<std::string, std::string>& m) {
  std::string o = "{";
  const char* sep = "";
  for (const auto& [k, v] : m) o += sep + quote(k) + ": " + v, sep = ", ";
  return o + "}";
}
}  // namespace detail

/// A nested JSON object for a manifest entry, e.g. conventions.display (docs/external_format.md):
///   vct_dump::Object().set("operator", "reinhard").set("gamma", 2.2).set("bits", 8)
///                     .set("stages", std::vector<std::string>{"image.final"})
class Object {
 public:
  template <typename T>
  Object& set(const std::string& key, const T& v) {
    members_[key] = detail::json_value(v);
    return *this;
  }
  std::string json() const { return detail::object(members_); }

 private:
  std::map<std::string, std::string> members_;
};

inline std::string detail::json_value(const Object& v) { return v.json(); }

class StageSetWriter {
 public:
  StageSetWriter(std::string dir, std::string backend) : dir_(std::move(dir)), backend_(std::move(backend)) {
    if (!dir_.empty() && dir_.back() != '/') dir_ += '/';
  }

  // "rgba8" | "rgba16f" | "rgba32f"; "exact_mean" | "fixed_point" | "cas_rgba8" | "running_mean".
  void set_storage(const std::string& s) { storage_ = s; }
  void set_reduction(const std::string& r) { reduction_ = r; }
  // Free-form "settings" (VCT settings keys are used by `vct compare --scene`), typed "facts",
  // "conventions" (docs/external_format.md). Numbers, booleans, strings, std::vector lists of
  // them, and Object for nested entries (conventions.display).
  template <typename T>
  void set_setting(const std::string& key, const T& v) { settings_[key] = detail::json_value(v); }
  template <typename T>
  void set_fact(const std::string& key, const T& v) { facts_[key] = detail::json_value(v); }
  template <typename T>
  void set_convention(const std::string& key, const T& v) { conventions_[key] = detail::json_value(v); }

  /// A float image of 1 to 4 channels, channels interleaved: 1 or 3 as PFM, 2 or 4 (e.g.
  /// gbuffer.material) as an uncompressed OpenEXR, which PFM cannot hold.
  bool image(const std::string& stage, int width, int height, int channels, const float* data, Rows rows) {
    if (channels < 1 || channels > 4) return fail(stage + ": images hold 1 to 4 channels, not " + std::to_string(channels));
    if (width <= 0 || height <= 0 || !data) return fail(stage + ": empty image");
    if (channels == 2 || channels == 4) return add(stage, file_stem(stage) + ".exr", "image", exr_bytes(width, height, channels, data, rows), {});
    // PFM stores the bottom row first (negative scale = little endian).
    std::string head = std::string(channels == 3 ? "PF" : "Pf") + "\n" + std::to_string(width) + " " +
                       std::to_string(height) + "\n-1.0\n";
    std::vector<float> body(size_t(width) * size_t(height) * size_t(channels));
    const size_t row = size_t(width) * size_t(channels);
    for (int y = 0; y < height; ++y) {
      const int src = rows == Rows::BottomFirst ? y : height - 1 - y;  // y-th row from the bottom
      std::memcpy(&body[size_t(y) * row], data + size_t(src) * row, row * sizeof(float));
    }
    return add(stage, file_stem(stage) + ".pfm", "image", head, body);
  }

  /// A float volume, channels interleaved, then x fastest, then y, then z (glGetTexImage's layout).
  bool volume(const std::string& stage, int nx, int ny, int nz, int channels, const float* data) {
    if (nx <= 0 || ny <= 0 || nz <= 0 || channels <= 0 || !data) return fail(stage + ": empty volume");
    std::string head = "NRRD0004\ntype: float\n";
    head += channels > 1 ? "dimension: 4\nsizes: " + std::to_string(channels) + " " : "dimension: 3\nsizes: ";
    head += std::to_string(nx) + " " + std::to_string(ny) + " " + std::to_string(nz) + "\nendian: little\nencoding: raw\n\n";
    const std::vector<float> body(data, data + size_t(nx) * size_t(ny) * size_t(nz) * size_t(channels));
    return add(stage, file_stem(stage) + ".nrrd", "volume", head, body);
  }

  /// Writes vct-stages.json. False (see error()) when any stage failed or the file cannot be written.
  bool finish() {
    if (!error_.empty()) return false;
    std::string j = "{\n  \"format\": \"vct-stages\",\n  \"version\": 1,\n  \"backend\": " + detail::quote(backend_) +
                    ",\n  \"storage\": " + detail::quote(storage_) + ",\n  \"reduction\": " + detail::quote(reduction_) + ",\n";
    j += "  \"settings\": " + detail::object(settings_) + ",\n  \"facts\": " + detail::object(facts_) + ",\n";
    if (!conventions_.empty()) j += "  \"conventions\": " + detail::object(conventions_) + ",\n";
    j += "  \"stages\": {";
    const char* sep = "\n";
    for (const auto& [stage, entry] : stages_) {
      j += sep + std::string("    ") + detail::quote(stage) + ": {\"file\": " + detail::quote(entry.first) + ", \"kind\": " + detail::quote(entry.second) + "}";
      sep = ",\n";
    }
    j += "\n  }\n}\n";
    return write_file("vct-stages.json", j, {});
  }

  const std::string& error() const { return error_; }

 private:
  static std::string file_stem(std::string s) {
    for (char& c : s)
      if (c == '.') c = '_';
    return s;
  }
  // A single-part scan-line OpenEXR, NO_COMPRESSION, 32-bit float channels (openexr.com, "OpenEXR
  // File Layout"; the layout ref/io/exr_plain.cpp writes): channels stored in alphabetical name
  // order (A, B, G, R), which readers return as R, G, B, A; rows top first (INCREASING_Y).
  static std::string exr_bytes(int width, int height, int channels, const float* data, Rows rows) {
    auto u32 = [](std::string& o, uint32_t v) {
      for (int i = 0; i < 4; ++i) o.push_back(char((v >> (8 * i)) & 0xffu));
    };
    auto f32 = [&u32](std::string& o, float f) {
      uint32_t u = 0;
      std::memcpy(&u, &f, 4);
      u32(o, u);
    };
    auto attribute = [&u32](std::string& o, const char* name, const char* type, const std::string& value) {
      o += name, o.push_back('\0'), o += type, o.push_back('\0');
      u32(o, uint32_t(value.size()));
      o += value;
    };
    const char* names[4] = {"R", "G", "B", "A"};
    std::vector<int> order;  // image channel of each file channel
    for (int c : {3, 2, 1, 0})
      if (c < channels) order.push_back(c);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return std::strcmp(names[a], names[b]) < 0; });
    std::string out, chlist, box, one, centre;
    u32(out, 20000630u), u32(out, 2u);  // magic, version 2 (single-part scan lines)
    for (int c : order) {
      chlist += names[c], chlist.push_back('\0');
      u32(chlist, 2u), chlist += std::string(4, '\0'), u32(chlist, 1u), u32(chlist, 1u);  // FLOAT, pLinear, sampling 1x1
    }
    chlist.push_back('\0');
    for (uint32_t v : {0u, 0u, uint32_t(width - 1), uint32_t(height - 1)}) u32(box, v);
    f32(one, 1.0f), f32(centre, 0.0f), f32(centre, 0.0f);
    attribute(out, "channels", "chlist", chlist);
    attribute(out, "compression", "compression", std::string(1, '\0'));
    attribute(out, "dataWindow", "box2i", box);
    attribute(out, "displayWindow", "box2i", box);
    attribute(out, "lineOrder", "lineOrder", std::string(1, '\0'));
    attribute(out, "pixelAspectRatio", "float", one);
    attribute(out, "screenWindowCenter", "v2f", centre);
    attribute(out, "screenWindowWidth", "float", one);
    out.push_back('\0');
    const uint64_t line_bytes = uint64_t(width) * uint64_t(channels) * 4u;
    const uint64_t first = uint64_t(out.size()) + 8u * uint64_t(height);
    for (int y = 0; y < height; ++y) {
      const uint64_t offset = first + uint64_t(y) * (8u + line_bytes);
      u32(out, uint32_t(offset & 0xffffffffu)), u32(out, uint32_t(offset >> 32));
    }
    for (int y = 0; y < height; ++y) {
      const int src = rows == Rows::TopFirst ? y : height - 1 - y;  // y-th row from the top
      u32(out, uint32_t(y)), u32(out, uint32_t(line_bytes));
      for (int c : order)
        for (int x = 0; x < width; ++x) f32(out, data[(size_t(src) * size_t(width) + size_t(x)) * size_t(channels) + size_t(c)]);
    }
    return out;
  }
  bool fail(const std::string& e) {
    if (error_.empty()) error_ = e;
    return false;
  }
  bool add(const std::string& stage, const std::string& file, const char* kind, const std::string& head,
           const std::vector<float>& body) {
    if (!write_file(file, head, body)) return false;
    stages_[stage] = {file, kind};
    return true;
  }
  // The host must be little endian (the files say so; every GPU host today is).
  bool write_file(const std::string& name, const std::string& head, const std::vector<float>& body) {
    const std::string path = dir_ + name, tmp = path + ".tmp";
    std::FILE* f = std::fopen(tmp.c_str(), "wb");
    if (!f) return fail(path + ": cannot open for writing");
    bool ok = std::fwrite(head.data(), 1, head.size(), f) == head.size();
    if (ok && !body.empty()) ok = std::fwrite(body.data(), sizeof(float), body.size(), f) == body.size();
    ok = (std::fclose(f) == 0) && ok;
    if (!ok || std::rename(tmp.c_str(), path.c_str()) != 0) {
      std::remove(tmp.c_str());
      return fail(path + ": write failed");
    }
    return true;
  }

  std::string dir_, backend_, storage_ = "rgba32f", reduction_ = "exact_mean";
  std::map<std::string, std::string> settings_, facts_, conventions_;
  std::map<std::string, std::pair<std::string, std::string>> stages_;  // stage -> file, kind
  std::string error_;
};

// GL enums by value, so no GL header is needed (GL 4.5 core, table 8.3 / 8.2).
constexpr unsigned kGlRed = 0x1903, kGlRg = 0x8227, kGlRgb = 0x1907, kGlRgba = 0x1908, kGlDepthComponent = 0x1902,
                   kGlFloat = 0x1406;

/// Reads level `level` of a 3D texture with the engine's glGetTextureImage (GL 4.5 §8.11.4:
/// (texture, level, format, type, bufSize, pixels)) as RGBA float and writes it as `stage`.
template <typename GetTextureImage>
bool volume_from_gl(StageSetWriter& w, const std::string& stage, GetTextureImage get_texture_image, unsigned texture,
                    int level, int nx, int ny, int nz) {
  std::vector<float> buf(size_t(nx) * size_t(ny) * size_t(nz) * 4);
  get_texture_image(texture, level, kGlRgba, kGlFloat, int(buf.size() * sizeof(float)), buf.data());
  return w.volume(stage, nx, ny, nz, 4, buf.data());
}

/// Reads a 2D texture (a depth texture: format GL_DEPTH_COMPONENT, 1 channel; colour: GL_RGB, 3)
/// and writes it as `stage`, flipping GL's bottom-first rows.
template <typename GetTextureImage>
bool image_from_gl(StageSetWriter& w, const std::string& stage, GetTextureImage get_texture_image, unsigned texture,
                   int width, int height, bool depth) {
  const int channels = depth ? 1 : 3;
  std::vector<float> buf(size_t(width) * size_t(height) * size_t(channels));
  get_texture_image(texture, 0, depth ? kGlDepthComponent : kGlRgb, kGlFloat, int(buf.size() * sizeof(float)), buf.data());
  return w.image(stage, width, height, channels, buf.data(), Rows::BottomFirst);
}

/// Reads the first `channels` (1 to 4: GL_RED, GL_RG, GL_RGB, GL_RGBA) of a colour texture, e.g.
/// a 4-channel `gbuffer.material`, and writes it as `stage`, flipping GL's bottom-first rows.
template <typename GetTextureImage>
bool colour_image_from_gl(StageSetWriter& w, const std::string& stage, GetTextureImage get_texture_image,
                          unsigned texture, int width, int height, int channels) {
  constexpr unsigned kFormat[4] = {kGlRed, kGlRg, kGlRgb, kGlRgba};
  if (channels < 1 || channels > 4) return w.image(stage, width, height, channels, nullptr, Rows::BottomFirst);
  std::vector<float> buf(size_t(width) * size_t(height) * size_t(channels));
  get_texture_image(texture, 0, kFormat[channels - 1], kGlFloat, int(buf.size() * sizeof(float)), buf.data());
  return w.image(stage, width, height, channels, buf.data(), Rows::BottomFirst);
}

}  // namespace vct_dump
