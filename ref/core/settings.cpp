#include "core/settings.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/memory_budget.h"

namespace vct {
namespace {

template <typename Enum>
struct EnumNames;
template <>
struct EnumNames<LightModel> {
  static const std::map<LightModel, std::string>& get() {
    static const std::map<LightModel, std::string> m{{LightModel::Gltf, "gltf"}, {LightModel::Seed, "seed"}};
    return m;
  }
};
template <>
struct EnumNames<Voxelizer> {
  static const std::map<Voxelizer, std::string>& get() {
    static const std::map<Voxelizer, std::string> m{{Voxelizer::Conservative, "conservative"},
                                                    {Voxelizer::GpuEmulation, "gpu"}};
    return m;
  }
};
template <>
struct EnumNames<VoxelStorage> {
  static const std::map<VoxelStorage, std::string>& get() {
    static const std::map<VoxelStorage, std::string> m{{VoxelStorage::Rgba8, "rgba8"},
                                                       {VoxelStorage::Rgba16f, "rgba16f"}};
    return m;
  }
};
template <>
struct EnumNames<Reduction> {
  static const std::map<Reduction, std::string>& get() {
    static const std::map<Reduction, std::string> m{{Reduction::ExactMean, "exact"},
                                                    {Reduction::FixedPoint, "fixed"},
                                                    {Reduction::CasRgba8, "cas"}};
    return m;
  }
};
template <>
struct EnumNames<DiffuseWeighting> {
  static const std::map<DiffuseWeighting, std::string>& get() {
    static const std::map<DiffuseWeighting, std::string> m{{DiffuseWeighting::Cosine, "cosine"},
                                                           {DiffuseWeighting::SeedSum, "seed"}};
    return m;
  }
};

template <typename Enum>
std::string enum_name(Enum e) {
  return EnumNames<Enum>::get().at(e);
}

template <typename Enum>
Enum enum_from(const nlohmann::json& j, const std::string& key) {
  const std::string name = j.get<std::string>();
  for (const auto& [value, n] : EnumNames<Enum>::get())
    if (n == name) return value;
  std::string allowed;
  for (const auto& [value, n] : EnumNames<Enum>::get()) allowed += (allowed.empty() ? "" : "|") + n;
  throw InputError("", "setting '" + key + "' is '" + name + "', expected one of " + allowed);
}

// An integer setting given a number it cannot hold (1e300, 2^32 + 16, 16.5) is bad input: the
// plain conversion would be undefined (float) or wrap silently to a value that may validate
// (reachable from an external stage set's manifest "settings": fuzz/regressions/scene_compare/).
template <typename T>
bool fits_integer(const nlohmann::json& v) {
  using L = std::numeric_limits<T>;
  if (v.is_number_unsigned()) return v.get<uint64_t>() <= uint64_t(L::max());
  if (v.is_number_integer()) return v.get<int64_t>() >= int64_t(L::min()) && v.get<int64_t>() <= int64_t(L::max());
  const double d = v.get<double>();
  return std::isfinite(d) && d == std::trunc(d) && d >= double(L::min()) && d <= double(L::max());
}

/// Reads the keys of `j` into fields; refuses keys nobody reads (typos must not pass silently).
class Reader {
 public:
  explicit Reader(const nlohmann::json& j, std::string scope) : j_(j), scope_(std::move(scope)) {
    if (!j.is_object()) throw InputError("", "settings '" + scope_ + "' must be a JSON object");
  }
  template <typename T>
  void field(const char* key, T& out) {
    seen_.insert(key);
    if (!j_.contains(key)) return;
    if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>)
      if (j_.at(key).is_number() && !fits_integer<T>(j_.at(key)))
        throw InputError("", "setting '" + scope_ + key + "' = " + j_.at(key).dump() + " is not an integer in range");
    try {
      out = j_.at(key).get<T>();
    } catch (const nlohmann::json::exception&) {
      throw InputError("", "setting '" + scope_ + key + "' has the wrong type");
    }
  }
  template <typename Enum>
  void enumeration(const char* key, Enum& out) {
    seen_.insert(key);
    if (!j_.contains(key)) return;
    if (!j_.at(key).is_string()) throw InputError("", "setting '" + scope_ + key + "' must be a string");
    out = enum_from<Enum>(j_.at(key), scope_ + key);
  }
  void finish() const {
    for (const auto& item : j_.items())
      if (!seen_.count(item.key())) throw InputError("", "unknown setting '" + scope_ + item.key() + "'");
  }

 private:
  const nlohmann::json& j_;
  std::string scope_;
  std::set<std::string> seen_;
};

}  // namespace

std::string to_string(LightModel m) { return enum_name(m); }
std::string to_string(Voxelizer v) { return enum_name(v); }
std::string to_string(VoxelStorage v) { return enum_name(v); }
std::string to_string(Reduction r) { return enum_name(r); }
std::string to_string(DiffuseWeighting w) { return enum_name(w); }

void to_json(nlohmann::json& j, const VctSettings& s) {
  j = nlohmann::json{{"width", s.width},
                     {"height", s.height},
                     {"shadow_map_size", s.shadow_map_size},
                     {"pcf_kernel", s.pcf_kernel},
                     {"shadow_bias", s.shadow_bias},
                     {"light_model", enum_name(s.light_model)},
                     {"grid", s.grid},
                     {"voxelizer", enum_name(s.voxelizer)},
                     {"msaa_samples", s.msaa_samples},
                     {"storage", enum_name(s.storage)},
                     {"reduction", enum_name(s.reduction)},
                     {"anisotropic", s.anisotropic},
                     {"diffuse_cones", s.diffuse_cones},
                     {"specular_cones", s.specular_cones},
                     {"soft_shadows", s.soft_shadows},
                     {"diffuse_aperture_deg", s.diffuse_aperture_deg},
                     {"diffuse_cone_count", s.diffuse_cone_count},
                     {"diffuse_cone_tilt_deg", s.diffuse_cone_tilt_deg},
                     {"diffuse_weighting", enum_name(s.diffuse_weighting)},
                     {"random_rotation", s.random_rotation},
                     {"cone_quality", s.cone_quality},
                     {"cone_offset_voxels", s.cone_offset_voxels},
                     {"max_distance", s.max_distance},
                     {"soft_shadow_aperture_deg", s.soft_shadow_aperture_deg},
                     {"bounces", s.bounces},
                     {"restitution", s.restitution},
                     {"convergence_tolerance", s.convergence_tolerance},
                     {"time", s.time},
                     {"frame", s.frame},
                     {"particles", s.particles},
                     {"depth_prepass", s.depth_prepass}};
}

void from_json(const nlohmann::json& j, VctSettings& s) {
  Reader r(j, "vct.");
  r.field("width", s.width);
  r.field("height", s.height);
  r.field("shadow_map_size", s.shadow_map_size);
  r.field("pcf_kernel", s.pcf_kernel);
  r.field("shadow_bias", s.shadow_bias);
  r.enumeration("light_model", s.light_model);
  r.field("grid", s.grid);
  r.enumeration("voxelizer", s.voxelizer);
  r.field("msaa_samples", s.msaa_samples);
  r.enumeration("storage", s.storage);
  r.enumeration("reduction", s.reduction);
  r.field("anisotropic", s.anisotropic);
  r.field("diffuse_cones", s.diffuse_cones);
  r.field("specular_cones", s.specular_cones);
  r.field("soft_shadows", s.soft_shadows);
  r.field("diffuse_aperture_deg", s.diffuse_aperture_deg);
  r.field("diffuse_cone_count", s.diffuse_cone_count);
  r.field("diffuse_cone_tilt_deg", s.diffuse_cone_tilt_deg);
  r.enumeration("diffuse_weighting", s.diffuse_weighting);
  r.field("random_rotation", s.random_rotation);
  r.field("cone_quality", s.cone_quality);
  r.field("cone_offset_voxels", s.cone_offset_voxels);
  r.field("max_distance", s.max_distance);
  r.field("soft_shadow_aperture_deg", s.soft_shadow_aperture_deg);
  r.field("bounces", s.bounces);
  r.field("restitution", s.restitution);
  r.field("convergence_tolerance", s.convergence_tolerance);
  r.field("time", s.time);
  r.field("frame", s.frame);
  r.field("particles", s.particles);
  r.field("depth_prepass", s.depth_prepass);
  r.finish();
}

void to_json(nlohmann::json& j, const PtSettings& s) {
  j = nlohmann::json{{"width", s.width},
                     {"height", s.height},
                     {"spp", s.spp},
                     {"max_depth", s.max_depth},
                     {"rr_start_depth", s.rr_start_depth},
                     {"seed", s.seed},
                     {"checkpoint_seconds", s.checkpoint_seconds},
                     {"light_model", enum_name(s.light_model)}};
}

void from_json(const nlohmann::json& j, PtSettings& s) {
  Reader r(j, "pt.");
  r.field("width", s.width);
  r.field("height", s.height);
  r.field("spp", s.spp);
  r.field("max_depth", s.max_depth);
  r.field("rr_start_depth", s.rr_start_depth);
  r.field("seed", s.seed);
  r.field("checkpoint_seconds", s.checkpoint_seconds);
  r.enumeration("light_model", s.light_model);
  r.finish();
}

void to_json(nlohmann::json& j, const Settings& s) {
  j = nlohmann::json{{"vct", s.vct}, {"pt", s.pt}, {"threads", s.threads}};
}

void from_json(const nlohmann::json& j, Settings& s) {
  Reader r(j, "");
  r.field("vct", s.vct);
  r.field("pt", s.pt);
  r.field("threads", s.threads);
  r.finish();
}

Settings load_settings_file(const std::string& path, const Settings& base) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "cannot open settings file");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(path, std::string("broken JSON: ") + e.what());
  }
  // Start from `base` so a config file only needs the keys it changes.
  nlohmann::json merged = base;
  merged.merge_patch(j);
  try {
    return merged.get<Settings>();
  } catch (const InputError& e) {
    throw InputError(path, e.what());
  }
}

namespace {
void require(bool ok, const std::string& what) {
  if (!ok) throw InputError("", what);
}
std::string shortest(float v) {  // 90 rather than std::to_string's 90.000000
  std::ostringstream o;
  o << v;
  return o.str();
}
}  // namespace

void validate_settings(const Settings& s) {
  const VctSettings& v = s.vct;
  require(v.width > 0 && v.height > 0 && v.width <= 16384 && v.height <= 16384,
          "image size must be within 1..16384 per side");
  require(v.grid >= 16 && v.grid <= 512 && (v.grid & (v.grid - 1)) == 0,
          "grid must be a power of two in 16..512 (got " + std::to_string(v.grid) + ")");
  require(v.shadow_map_size >= 16 && v.shadow_map_size <= 16384, "shadow_map_size must be in 16..16384");
  require(v.pcf_kernel >= 1 && v.pcf_kernel <= 9, "pcf_kernel must be in 1..9");
  require(v.msaa_samples == 1 || v.msaa_samples == 4 || v.msaa_samples == 8, "msaa_samples must be 1, 4 or 8");
  require(v.cone_quality > 0.01f && v.cone_quality <= 4.0f, "cone_quality must be in (0.01, 4]");
  require(v.diffuse_aperture_deg > 0.0f && v.diffuse_aperture_deg < 180.0f, "diffuse_aperture_deg must be in (0, 180)");
  require(v.diffuse_cone_count >= 1 && v.diffuse_cone_count <= kMaxDiffuseConeCount,
          "diffuse_cone_count must be in 1.." + std::to_string(kMaxDiffuseConeCount) + " (got " +
              std::to_string(v.diffuse_cone_count) + ")");
  require(v.diffuse_cone_tilt_deg > 0.0f && v.diffuse_cone_tilt_deg < 90.0f,
          "diffuse_cone_tilt_deg must be in (0, 90) (got " + shortest(v.diffuse_cone_tilt_deg) + ")");
  require(v.bounces >= 1 && v.bounces <= 64, "bounces must be in 1..64");
  require(v.restitution >= 0.0f && v.restitution <= 1.0f, "restitution must be in [0, 1]");
  const PtSettings& p = s.pt;
  require(p.width > 0 && p.height > 0 && p.width <= 16384 && p.height <= 16384,
          "path tracer image size must be within 1..16384 per side");
  require(p.spp >= 1, "spp must be >= 1");
  require(p.max_depth >= 1 && p.max_depth <= 1024, "max_depth must be in 1..1024");
  require(s.threads >= 0 && s.threads <= 1024, "threads must be in 0..1024");
  check_memory_budget(s);  // a grid or image that would not fit: say how much it needs
}

}  // namespace vct
