#include "compare/conventions.h"

#include <cmath>

#include "core/error.h"

namespace vct::cmp {

Conventions read_conventions(const std::string& manifest, const nlohmann::json& j) {
  if (!j.is_object()) throw InputError(manifest, "\"conventions\" must be an object (docs/external_format.md)");
  Conventions c;
  for (const auto& [key, value] : j.items()) {
    if (key == "mip_scale") {
      if (!value.is_number() || !std::isfinite(value.get<double>()) || value.get<double>() <= 0.0)
        throw InputError(manifest, "conventions.mip_scale must be a positive number");
      c.mip_scale = value.get<double>();
    } else {
      throw InputError(manifest, "unknown convention '" + key +
                                     "' (known: mip_scale; reductions go in \"reduction\"; docs/external_format.md)");
    }
  }
  return c;
}

nlohmann::json to_json(const Conventions& c) {
  nlohmann::json j = nlohmann::json::object();
  if (c.mip_scale != 1.0) j["mip_scale"] = c.mip_scale;
  return j;
}

}  // namespace vct::cmp
