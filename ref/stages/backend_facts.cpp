#include "stages/backend_facts.h"

#include <nlohmann/json.hpp>

#include "stages/raster.h"

namespace vct {

void to_json(nlohmann::json& j, const BackendFacts& f) {
  nlohmann::json positions = nlohmann::json::array();
  for (const vec2& p : f.sample_positions) positions.push_back({p.x, p.y});
  j = {{"msaa_samples", f.msaa_samples},
       {"msaa_samples_requested", f.msaa_samples_requested},
       {"sample_positions", positions},
       {"reduction", f.reduction},
       {"reduction_note", f.reduction_note},
       {"gl_fault", f.gl_fault},
       {"device", f.device},
       {"vendor", f.vendor},
       {"renderer", f.renderer},
       {"version", f.version},
       {"max_samples", f.max_samples},
       {"subpixel_bits", f.subpixel_bits},
       {"conservative_raster", f.conservative_raster},
       {"conservative_mode", f.conservative_mode},
       {"conservative_snap_bits", f.conservative_snap_bits},
       {"conservative_dilation", f.conservative_dilation},
       {"conservative_params", f.conservative_params},
       {"unreported", f.unreported}};
}

void from_json(const nlohmann::json& j, BackendFacts& f) {
  f = BackendFacts();
  if (!j.is_object()) throw nlohmann::json::type_error::create(302, "\"facts\" must be an object", &j);
  auto get = [&](const char* key, auto& member) {
    if (j.contains(key)) j.at(key).get_to(member);
  };
  get("msaa_samples", f.msaa_samples);
  get("msaa_samples_requested", f.msaa_samples_requested);
  if (j.contains("sample_positions"))
    for (const auto& p : j.at("sample_positions")) {
      if (!p.is_array() || p.size() != 2)
        throw nlohmann::json::type_error::create(302, "a sample position must be [x, y]", &p);
      f.sample_positions.emplace_back(p[0].get<float>(), p[1].get<float>());
    }
  get("reduction", f.reduction);
  get("reduction_note", f.reduction_note);
  get("gl_fault", f.gl_fault);
  get("device", f.device);
  get("vendor", f.vendor);
  get("renderer", f.renderer);
  get("version", f.version);
  get("max_samples", f.max_samples);
  get("subpixel_bits", f.subpixel_bits);
  get("conservative_raster", f.conservative_raster);
  get("conservative_mode", f.conservative_mode);
  get("conservative_snap_bits", f.conservative_snap_bits);
  get("conservative_dilation", f.conservative_dilation);
  get("conservative_params", f.conservative_params);
  get("unreported", f.unreported);
}

int cpu_subpixel_bits() { return kSubpixelBits; }

}  // namespace vct
