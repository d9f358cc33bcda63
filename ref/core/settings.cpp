#include "core/settings.h"

#include <cmath>
#include <limits>
#include <set>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/memory_budget.h"
#include "core/declared_cones.h"
#include "core/light_matrices.h"
#include "core/pcf_taps.h"
#include "core/settings_table.h"
#include "io/bounded_json.h"

namespace vct {
namespace {

template <typename T>
bool fits(const nlohmann::json& v) {
  const double d = v.get<double>();  // exact for every integer an int can hold
  return std::isfinite(d) && d == std::trunc(d) && d >= double(std::numeric_limits<T>::min()) &&
         d <= double(std::numeric_limits<T>::max());
}

/// Reads the keys of `j` into fields; refuses keys nobody reads (typos must not pass silently).
class Reader {
 public:
  explicit Reader(const nlohmann::json& j, std::string scope) : j_(j), scope_(std::move(scope)) {
    if (!j.is_object()) throw InputError("", "settings '" + scope_ + "' must be a JSON object");
  }
  template <typename S>
  void table(const std::vector<SettingField<S>>& fields, S& out) {
    for (const auto& f : fields) {
      seen_.insert(f.key);
      if (j_.contains(f.key)) f.set(out, j_.at(f.key), scope_);
    }
  }
  template <typename T>
  void nested(const char* key, T& out) {
    seen_.insert(key);
    if (!j_.contains(key)) return;
    const nlohmann::json& v = j_.at(key);
    // {"threads": 2.7} must not become 2, nor 2^32 + 4 wrap to 4 (as the table's integer rows).
    if constexpr (std::is_integral_v<T>)
      if (v.is_number() && !fits<T>(v))
        throw InputError("", "setting '" + scope_ + key + "' = " + input_excerpt(v.dump()) + " is not an integer in range");
    try {
      out = v.get<T>();
    } catch (const nlohmann::json::exception&) {
      throw InputError("", "setting '" + scope_ + key + "' has the wrong type");
    }
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

template <typename S>
nlohmann::json table_to_json(const std::vector<SettingField<S>>& fields, const S& s) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& f : fields) j[f.key] = f.get(s);
  return j;
}

}  // namespace

void to_json(nlohmann::json& j, const VctSettings& s) { j = table_to_json(vct_setting_fields(), s); }

void from_json(const nlohmann::json& j, VctSettings& s) {
  Reader r(j, "vct.");
  r.table(vct_setting_fields(), s);
  r.finish();
}

void to_json(nlohmann::json& j, const PtSettings& s) { j = table_to_json(pt_setting_fields(), s); }

void from_json(const nlohmann::json& j, PtSettings& s) {
  Reader r(j, "pt.");
  r.table(pt_setting_fields(), s);
  r.finish();
}

void to_json(nlohmann::json& j, const Settings& s) {
  j = nlohmann::json{{"vct", s.vct}, {"pt", s.pt}, {"threads", s.threads}};
}

void from_json(const nlohmann::json& j, Settings& s) {
  Reader r(j, "");
  r.nested("vct", s.vct);
  r.nested("pt", s.pt);
  r.nested("threads", s.threads);
  r.finish();
}

Settings load_settings_file(const std::string& path, const Settings& base) {
  // Regular file, size and depth bounded, every parse error (1e999 too) one line (bounded_json.h).
  const nlohmann::json j = read_bounded_json_file(path, "settings file");
  if (!j.is_object()) throw InputError(path, "a settings file must hold a JSON object like {\"vct\": {\"grid\": 64}}");
  // Start from `base` so a config file only needs the keys it changes.
  nlohmann::json merged = base;
  merged.merge_patch(j);
  try {
    return merged.get<Settings>();
  } catch (const InputError& e) {
    throw InputError(path, e.what());
  } catch (const nlohmann::json::exception& e) {  // a type nlohmann refuses before our reader sees it
    throw InputError(path, input_excerpt(e.what(), 160));
  }
}

namespace {
void require(bool ok, const std::string& what) {
  if (!ok) throw InputError("", what);
}
}  // namespace

void validate_settings(const Settings& s) {
  for (const auto& f : vct_setting_fields()) check_setting_range(f, s.vct, "");
  for (const auto& f : pt_setting_fields()) check_setting_range(f, s.pt, "path tracer ");
  require(s.threads >= 0 && s.threads <= 1024, "threads must be in 0..1024");
  // A frustum with near >= far projects nothing (both given; 0 = the oracle's own rule).
  require(s.vct.shadow_near <= 0.0f || s.vct.shadow_far <= 0.0f || s.vct.shadow_near < s.vct.shadow_far,
          "shadow_near must be below shadow_far");
  (void)parse_pcf_taps(s.vct.pcf_taps);  // throws for a malformed tap list
  (void)parse_pcf_taps(s.vct.voxel_pcf_taps, "voxel_pcf_taps");
  require(s.vct.voxel_pcf == VoxelPcf::Same || s.vct.voxel_pcf_taps.empty(),
          "voxel_pcf_taps needs voxel_pcf = same (with oracle the voxelizer runs the pcf_kernel square)");
  // The normal offset is derived for a footprint fixed in texels (stages/shadow_map.h,
  // normal_offset_per_w); taps that shrink with 1/w have no such footprint.
  require(s.vct.pcf_tap_scale == PcfTapScale::None || s.vct.shadow_normal_offset == 0.0f,
          "pcf_tap_scale = inv_w needs shadow_normal_offset = 0 (the normal offset is derived for taps fixed in texels)");
  (void)parse_declared_cones(s.vct.diffuse_cone_set);
  (void)parse_light_matrices(s.vct.shadow_view_proj);
  (void)parse_ortho_boxes(s.vct.shadow_ortho_box);
  // The axis offset after the normal offset is the normal start's; the axis start has one offset.
  require(s.vct.cone_axis_offset_voxels == 0.0f || s.vct.cone_start == ConeStart::Normal,
          "cone_axis_offset_voxels needs cone_start = normal (with axis, cone_offset_voxels is the axis offset)");
  // A step of 0 would never end: 0 means "cone_quality", else the diffuse cones' own floor.
  require(s.vct.specular_quality == 0.0f || s.vct.specular_quality > 0.01f,
          "specular_quality must be 0 (= cone_quality) or in (0.01, 4]");
  check_memory_budget(s);  // a grid or image that would not fit: say how much it needs
}

}  // namespace vct
