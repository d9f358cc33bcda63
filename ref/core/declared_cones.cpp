#include "core/declared_cones.h"

#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/settings.h"

namespace vct {

namespace {

[[noreturn]] void bad(const std::string& entry, const std::string& why) {
  throw InputError("", "diffuse_cone_set: '" + entry + "' " + why);
}

std::vector<float> numbers(const std::string& entry) {
  std::vector<float> out;
  std::istringstream in(entry);
  std::string item;
  while (std::getline(in, item, ',')) {
    size_t used = 0;
    float v = 0.0f;
    try {
      v = std::stof(item, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size() || !std::isfinite(v)) bad(entry, "is not x,y,z,aperture_deg,weight");
    out.push_back(v);
  }
  return out;
}

}  // namespace

std::vector<DeclaredCone> parse_declared_cones(const std::string& text) {
  std::vector<DeclaredCone> cones;
  std::istringstream in(text);
  std::string entry;
  while (in >> entry) {
    const std::vector<float> v = numbers(entry);
    if (v.size() != 5) bad(entry, "is not x,y,z,aperture_deg,weight");
    const vec3 d(v[0], v[1], v[2]);
    const float length = glm::length(d);
    // A cone below the tangent plane looks into the surface it shades.
    if (!(length > 0.0f) || d.z < 0.0f) bad(entry, "has no direction above the tangent plane (z >= 0, not 0,0,0)");
    if (!(v[3] > 0.0f && v[3] < 180.0f)) bad(entry, "has an aperture outside (0, 180) degrees");
    if (v[4] < 0.0f) bad(entry, "has a negative weight");
    cones.push_back({d / length, v[3], v[4]});
  }
  if (cones.size() > size_t(kMaxDiffuseConeCount))
    throw InputError("", "diffuse_cone_set: more than " + std::to_string(kMaxDiffuseConeCount) + " cones");
  return cones;
}

}  // namespace vct
