#include "compare/conventions.h"

#include <cmath>
#include <functional>
#include <vector>

#include "core/error.h"

namespace vct::cmp {

namespace {

// One row per convention key: how the manifest's value is read, and whether (and how) a set's
// conventions write it back. Adding a convention is adding a row (and its docs rows).
struct ConventionKey {
  const char* key;
  std::function<void(Conventions&, const std::string& manifest, const nlohmann::json&)> read;
  std::function<void(const Conventions&, nlohmann::json&)> write;
};

const std::vector<ConventionKey>& convention_keys() {
  static const std::vector<ConventionKey> keys = {
      {"mip_scale",
       [](Conventions& c, const std::string& manifest, const nlohmann::json& v) {
         if (!v.is_number() || !std::isfinite(v.get<double>()) || v.get<double>() <= 0.0)
           throw InputError(manifest, "conventions.mip_scale must be a positive number");
         c.mip_scale = v.get<double>();
       },
       [](const Conventions& c, nlohmann::json& j) {
         if (c.mip_scale != 1.0) j["mip_scale"] = c.mip_scale;
       }},
      {"display",
       [](Conventions& c, const std::string& manifest, const nlohmann::json& v) {
         c.display = read_display_transform(manifest, v);
       },
       [](const Conventions& c, nlohmann::json& j) {
         if (c.display.declared()) j["display"] = to_json(c.display);
       }},
  };
  return keys;
}

std::string known_keys() {
  std::string out;
  for (const ConventionKey& k : convention_keys()) out += (out.empty() ? "" : ", ") + std::string(k.key);
  return out;
}

}  // namespace

Conventions read_conventions(const std::string& manifest, const nlohmann::json& j) {
  if (!j.is_object()) throw InputError(manifest, "\"conventions\" must be an object (docs/external_format.md)");
  Conventions c;
  for (const auto& [key, value] : j.items()) {
    const ConventionKey* row = nullptr;
    for (const ConventionKey& k : convention_keys())
      if (key == k.key) row = &k;
    if (!row)
      throw InputError(manifest, "unknown convention '" + key + "' (known: " + known_keys() +
                                     "; reductions go in \"reduction\"; docs/external_format.md)");
    row->read(c, manifest, value);
  }
  return c;
}

nlohmann::json to_json(const Conventions& c) {
  nlohmann::json j = nlohmann::json::object();
  for (const ConventionKey& k : convention_keys()) k.write(c, j);
  return j;
}

}  // namespace vct::cmp
