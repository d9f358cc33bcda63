// vct_dump.h -- header-only helper an engine includes to write its textures and facts as a VCT
// Oracle stage set (docs/external_format.md, "For engine developers"): vct-stages.json plus one
// NRRD per volume and one PFM per image, readable by `vct compare REF DIR`.
//
// C++17, the standard library only. It takes plain CPU buffers; for GL, volume_from_gl /
// image_from_gl take the engine's own glGetTextureImage pointer (no GL header needed). Vulkan or
// D3D engines read their textures back into CPU buffers and call the same writer.
//
//   vct_dump::StageSetWriter w("dump/", "my-engine");
//   w.set_storage("rgba16f"); w.set_reduction("running_mean");
//   w.set_setting("grid", 128); w.set_fact("msaa_samples", 4); w.set_convention("mip_scale", 1.9);
//   w.volume("voxel.radiance", n, n, n, 4, rgba);          // x fastest, then y, then z
//   w.volume("voxel.fragments", n, n, n, 1, counts);       // the cheapest decisive stage
//   w.image("shadow_map.0", size, size, 1, depth, vct_dump::Rows::BottomFirst);  // a GL read-back
//   if (!w.finish()) fprintf(stderr, "%s\n", w.error().c_str());
//
// Every file is written to a temporary name and renamed, the manifest last, so a crashed dump
// never looks complete.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace vct_dump {

enum class Rows { TopFirst, BottomFirst };  // GL read-backs are bottom row first

class StageSetWriter {
 public:
  StageSetWriter(std::string dir, std::string backend) : dir_(std::move(dir)), backend_(std::move(backend)) {
    if (!dir_.empty() && dir_.back() != '/') dir_ += '/';
  }

  // "rgba8" | "rgba16f" | "rgba32f"; "exact_mean" | "fixed_point" | "cas_rgba8" | "running_mean".
  void set_storage(const std::string& s) { storage_ = s; }
  void set_reduction(const std::string& r) { reduction_ = r; }
  // Free-form "settings" (VCT settings keys are used by `vct compare --scene`), typed "facts",
  // "conventions" (docs/external_format.md). Numbers, booleans and strings.
  template <typename T>
  void set_setting(const std::string& key, const T& v) { settings_[key] = json_value(v); }
  template <typename T>
  void set_fact(const std::string& key, const T& v) { facts_[key] = json_value(v); }
  template <typename T>
  void set_convention(const std::string& key, const T& v) { conventions_[key] = json_value(v); }

  /// A 1- or 3-channel float image (PFM holds no other channel count), channels interleaved.
  bool image(const std::string& stage, int width, int height, int channels, const float* data, Rows rows) {
    if (channels != 1 && channels != 3) return fail(stage + ": PFM images hold 1 or 3 channels, not " + std::to_string(channels));
    if (width <= 0 || height <= 0 || !data) return fail(stage + ": empty image");
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
    std::string j = "{\n  \"format\": \"vct-stages\",\n  \"version\": 1,\n  \"backend\": " + quote(backend_) +
                    ",\n  \"storage\": " + quote(storage_) + ",\n  \"reduction\": " + quote(reduction_) + ",\n";
    j += "  \"settings\": " + object(settings_) + ",\n  \"facts\": " + object(facts_) + ",\n";
    if (!conventions_.empty()) j += "  \"conventions\": " + object(conventions_) + ",\n";
    j += "  \"stages\": {";
    const char* sep = "\n";
    for (const auto& [stage, entry] : stages_) {
      j += sep + std::string("    ") + quote(stage) + ": {\"file\": " + quote(entry.first) + ", \"kind\": " + quote(entry.second) + "}";
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
  static std::string quote(const std::string& s) {
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
  static std::string json_value(const std::string& v) { return quote(v); }
  static std::string json_value(const char* v) { return quote(v); }
  static std::string json_value(bool v) { return v ? "true" : "false"; }
  static std::string json_value(int v) { return std::to_string(v); }
  static std::string json_value(double v) {
    if (!std::isfinite(v)) return "null";
    char b[32];
    std::snprintf(b, sizeof b, "%.17g", v);
    return b;
  }
  static std::string object(const std::map<std::string, std::string>& m) {
    std::string o = "{";
    const char* sep = "";
    for (const auto& [k, v] : m) o += sep + quote(k) + ": " + v, sep = ", ";
    return o + "}";
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
constexpr unsigned kGlRgb = 0x1907, kGlRgba = 0x1908, kGlDepthComponent = 0x1902, kGlFloat = 0x1406;

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

}  // namespace vct_dump
