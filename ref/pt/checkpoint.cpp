#include "pt/checkpoint.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "io/atomic_file.h"

namespace vct::pt {

namespace {

constexpr char kMagic[8] = {'V', 'C', 'T', 'P', 'T', 'C', 'K', '1'};

class Fnv {
 public:
  void bytes(const void* p, size_t n) {
    const auto* b = static_cast<const uint8_t*>(p);
    for (size_t i = 0; i < n; ++i) h_ = (h_ ^ b[i]) * 0x100000001B3ull;
  }
  template <class T>
  void pod(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof(T));
  }
  template <class T>
  void vec(const std::vector<T>& v) {
    pod(uint64_t(v.size()));
    if (!v.empty()) bytes(v.data(), v.size() * sizeof(T));
  }
  void str(const std::string& s) {
    pod(uint64_t(s.size()));
    bytes(s.data(), s.size());
  }
  void tex_ref(const TextureRef& t) {
    pod(t.texture);
    pod(t.texcoord);
    pod(t.transform.offset);
    pod(t.transform.rotation);
    pod(t.transform.scale);
  }
  uint64_t value() const { return h_; }

 private:
  uint64_t h_ = 0xCBF29CE484222325ull;
};

}  // namespace

uint64_t hash_scene(const Scene& s) {
  Fnv h;
  h.vec(s.positions);
  h.vec(s.normals);
  h.vec(s.tangents);
  h.vec(s.uv0);
  h.vec(s.uv1);
  h.vec(s.triangles);
  h.vec(s.triangle_material);
  for (const Material& m : s.materials) {
    h.pod(m.base_color_factor);
    h.tex_ref(m.base_color_texture);
    h.pod(m.metallic_factor);
    h.pod(m.roughness_factor);
    h.tex_ref(m.metallic_roughness_texture);
    h.tex_ref(m.normal_texture);
    h.pod(m.normal_scale);
    h.pod(m.normal_two_channel);
    h.pod(m.emissive_factor);
    h.tex_ref(m.emissive_texture);
    h.pod(m.emissive_strength);
    h.pod(m.specular_factor);
    h.pod(m.specular_color_factor);
    h.pod(m.double_sided);
  }
  for (const Texture& t : s.textures) {
    h.pod(t.width);
    h.pod(t.height);
    h.vec(t.rgba8);
    h.pod(int(t.wrap_s));
    h.pod(int(t.wrap_t));
    h.pod(int(t.mag_filter));
    h.pod(int(
        t.min_filter));  // the primary hit's ray-cone lookup reads the mip chain (pt/ray_cone.h)
  }
  for (const Light& l : s.lights) {
    h.pod(int(l.kind));
    h.pod(l.position);
    h.pod(l.direction);
    h.pod(l.color);
    h.pod(l.intensity);
    h.pod(l.inner_cone_angle);
    h.pod(l.outer_cone_angle);
    h.pod(l.range);
  }
  for (const ParticleEmitter& e : s.emitters) {
    h.pod(e.origin);
    h.pod(e.count);
    h.pod(e.lifetime);
    h.pod(e.spawn_extent);
    h.pod(e.velocity_min);
    h.pod(e.velocity_max);
    h.pod(e.acceleration);
    h.pod(e.color_start);
    h.pod(e.color_end);
    h.pod(e.size_start);
    h.pod(e.size_end);
  }
  const Camera& c = s.camera;
  h.pod(c.position);
  h.pod(c.forward);
  h.pod(c.up);
  h.pod(c.yfov);
  h.pod(c.znear);
  h.pod(c.zfar);
  if (c.orthographic) h.pod(c.ymag);  // perspective hashes stay as before, so their checkpoints resume
  return h.value();
}

uint64_t hash_pt_settings(const PtSettings& s) {
  nlohmann::json j = s;
  j.erase("spp");
  j.erase("checkpoint_seconds");
  Fnv h;
  h.str(j.dump());
  return h.value();
}

uint64_t hash_render_settings(const PtSettings& s, const ParticleOptions& p) {
  Fnv h;
  h.pod(hash_pt_settings(s));
  h.pod(p.enabled);
  h.pod(p.enabled ? p.time : 0.0f);
  return h.value();
}

void save_checkpoint(const std::string& path, const CheckpointKey& key, const Accumulator& acc) {
  write_atomically(path, [&](const std::string& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    const int32_t w = acc.width(), hgt = acc.height();
    const uint32_t spp = acc.samples(), values = Accumulator::kValuesPerPixel;
    out.write(kMagic, sizeof kMagic);
    out.write(reinterpret_cast<const char*>(&key.scene_hash), 8);
    out.write(reinterpret_cast<const char*>(&key.settings_hash), 8);
    out.write(reinterpret_cast<const char*>(&w), 4);
    out.write(reinterpret_cast<const char*>(&hgt), 4);
    out.write(reinterpret_cast<const char*>(&spp), 4);
    out.write(reinterpret_cast<const char*>(&values), 4);
    out.write(reinterpret_cast<const char*>(acc.sums().data()), std::streamsize(acc.sums().size() * sizeof(double)));
    out.close();
    if (!out) throw InputError(tmp, "cannot write checkpoint");
  });
}

bool load_checkpoint(const std::string& path, const CheckpointKey& key, int width, int height, Accumulator& acc,
                     std::string& why) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) {
    why = "no checkpoint";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  char magic[8];
  CheckpointKey k;
  int32_t w = 0, hgt = 0;
  uint32_t spp = 0, values = 0;
  in.read(magic, 8);
  in.read(reinterpret_cast<char*>(&k.scene_hash), 8);
  in.read(reinterpret_cast<char*>(&k.settings_hash), 8);
  in.read(reinterpret_cast<char*>(&w), 4);
  in.read(reinterpret_cast<char*>(&hgt), 4);
  in.read(reinterpret_cast<char*>(&spp), 4);
  in.read(reinterpret_cast<char*>(&values), 4);
  if (!in || std::memcmp(magic, kMagic, 8) != 0 || values != uint32_t(Accumulator::kValuesPerPixel)) {
    why = "not a checkpoint of this format";
    return false;
  }
  if (k.scene_hash != key.scene_hash) {
    why = "checkpoint belongs to a different scene";
    return false;
  }
  if (k.settings_hash != key.settings_hash || w != width || hgt != height) {
    why = "checkpoint was made with different path tracer settings";
    return false;
  }
  Accumulator loaded(width, height);
  in.read(reinterpret_cast<char*>(loaded.sums().data()), std::streamsize(loaded.sums().size() * sizeof(double)));
  if (!in || in.peek() != std::char_traits<char>::eof()) {
    why = "checkpoint is truncated or has trailing bytes";
    return false;
  }
  loaded.set_samples(spp);
  acc = std::move(loaded);
  return true;
}

}  // namespace vct::pt
