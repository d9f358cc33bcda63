// The table of checked glTF properties and the walk that applies it (gltf_property_table.h).
#include "scene/gltf_property_table.h"

#include <cmath>
#include <limits>
#include <vector>

#include "core/error.h"
#include "io/bounded_json.h"

namespace vct::gltf {
namespace {

using nlohmann::json;

constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Kind { Index, Number, Integer, Boolean, Text, IntEnum, TextEnum, Numbers };

struct Rule {
  Kind kind = Kind::Number;
  const char* target = nullptr;  // Index: the array indexed, from the root or ("./...") the first element
  double lo = -kInf, hi = kInf;  // Number, Integer, Numbers: the closed range
  std::vector<int> ints;         // IntEnum
  std::vector<std::string> texts;  // TextEnum
  size_t length = 0;             // Numbers: the array's length (0 = any)
};

Rule rule(Kind kind, double lo = -kInf, double hi = kInf) {
  Rule r;
  r.kind = kind, r.lo = lo, r.hi = hi;
  return r;
}
Rule index(const char* target) {
  Rule r = rule(Kind::Index);
  r.target = target;
  return r;
}
Rule number(double lo = -kInf, double hi = kInf) { return rule(Kind::Number, lo, hi); }
Rule integer(double lo, double hi = kInf) { return rule(Kind::Integer, lo, hi); }
Rule boolean() { return rule(Kind::Boolean); }
Rule text() { return rule(Kind::Text); }
Rule one_of(std::vector<int> values) {
  Rule r = rule(Kind::IntEnum);
  r.ints = std::move(values);
  return r;
}
Rule one_of(std::vector<std::string> values) {
  Rule r = rule(Kind::TextEnum);
  r.texts = std::move(values);
  return r;
}
Rule numbers(size_t length, double lo = -kInf, double hi = kInf) {
  Rule r = rule(Kind::Numbers, lo, hi);
  r.length = length;
  return r;
}

/// One property: its path from the document root ("[]" visits every element of an array, "{}"
/// every value of an object) and its rule.
struct PropertyRow {
  std::string path;
  Rule rule;
};

constexpr const char* kLights = "extensions.KHR_lights_punctual.lights";

void add_texture_info(std::vector<PropertyRow>& rows, const std::string& slot) {
  rows.push_back({slot + ".index", index("textures")});
  rows.push_back({slot + ".texCoord", integer(0)});
  const std::string t = slot + ".extensions.KHR_texture_transform.";
  rows.push_back({t + "offset", numbers(2)});
  rows.push_back({t + "rotation", number()});
  rows.push_back({t + "scale", numbers(2)});
  rows.push_back({t + "texCoord", integer(0)});
}

// glTF 2.0's JSON schema for what the loader reads, and KHR_lights_punctual,
// KHR_materials_emissive_strength, KHR_materials_specular, KHR_texture_transform.
std::vector<PropertyRow> make_table() {
  std::vector<PropertyRow> rows = {
      {"asset.version", text()},
      {"scene", index("scenes")},
      {"scenes.[].nodes.[]", index("nodes")},
      {"nodes.[].children.[]", index("nodes")},
      {"nodes.[].mesh", index("meshes")},
      {"nodes.[].camera", index("cameras")},
      {"nodes.[].skin", index("skins")},
      {"nodes.[].extensions.KHR_lights_punctual.light", index(kLights)},
      {"nodes.[].matrix", numbers(16)},
      {"nodes.[].translation", numbers(3)},
      {"nodes.[].rotation", numbers(4)},
      {"nodes.[].scale", numbers(3)},
      {"nodes.[].weights", numbers(0)},
      {"meshes.[].weights", numbers(0)},
      {"meshes.[].primitives.[].attributes.{}", index("accessors")},
      {"meshes.[].primitives.[].indices", index("accessors")},
      {"meshes.[].primitives.[].material", index("materials")},
      {"meshes.[].primitives.[].targets.[].{}", index("accessors")},
      {"meshes.[].primitives.[].mode", one_of(std::vector<int>{0, 1, 2, 3, 4, 5, 6})},
      {"skins.[].joints.[]", index("nodes")},
      {"skins.[].skeleton", index("nodes")},
      {"skins.[].inverseBindMatrices", index("accessors")},
      {"animations.[].channels.[].sampler", index("./samplers")},
      {"animations.[].channels.[].target.node", index("nodes")},
      {"animations.[].samplers.[].input", index("accessors")},
      {"animations.[].samplers.[].output", index("accessors")},
      {"accessors.[].bufferView", index("bufferViews")},
      {"accessors.[].byteOffset", integer(0)},
      {"accessors.[].componentType", one_of(std::vector<int>{5120, 5121, 5122, 5123, 5125, 5126})},
      {"accessors.[].normalized", boolean()},
      {"accessors.[].count", integer(1)},
      {"accessors.[].type", one_of(std::vector<std::string>{"SCALAR", "VEC2", "VEC3", "VEC4", "MAT2", "MAT3", "MAT4"})},
      {"accessors.[].sparse.count", integer(1)},
      {"accessors.[].sparse.indices.bufferView", index("bufferViews")},
      {"accessors.[].sparse.indices.byteOffset", integer(0)},
      {"accessors.[].sparse.indices.componentType", one_of(std::vector<int>{5121, 5123, 5125})},
      {"accessors.[].sparse.values.bufferView", index("bufferViews")},
      {"accessors.[].sparse.values.byteOffset", integer(0)},
      {"bufferViews.[].buffer", index("buffers")},
      {"bufferViews.[].byteOffset", integer(0)},
      {"bufferViews.[].byteLength", integer(1)},
      {"bufferViews.[].byteStride", integer(4, 252)},
      {"buffers.[].byteLength", integer(1)},
      {"buffers.[].uri", text()},
      {"images.[].uri", text()},
      {"images.[].mimeType", text()},
      {"images.[].bufferView", index("bufferViews")},
      {"samplers.[].magFilter", one_of(std::vector<int>{9728, 9729})},
      {"samplers.[].minFilter", one_of(std::vector<int>{9728, 9729, 9984, 9985, 9986, 9987})},
      {"samplers.[].wrapS", one_of(std::vector<int>{33071, 33648, 10497})},
      {"samplers.[].wrapT", one_of(std::vector<int>{33071, 33648, 10497})},
      {"textures.[].source", index("images")},
      {"textures.[].sampler", index("samplers")},
      // Colours: >= 0 (glTF says <= 1 too; engines take brighter factors as given, so do we).
      {"materials.[].pbrMetallicRoughness.baseColorFactor", numbers(4, 0.0)},
      // metallic and roughness outside [0, 1] are clamped with a warning (gltf_materials.cpp).
      {"materials.[].pbrMetallicRoughness.metallicFactor", number()},
      {"materials.[].pbrMetallicRoughness.roughnessFactor", number()},
      {"materials.[].normalTexture.scale", number()},
      {"materials.[].occlusionTexture.strength", number(0.0, 1.0)},
      {"materials.[].emissiveFactor", numbers(3, 0.0)},
      {"materials.[].alphaMode", one_of(std::vector<std::string>{"OPAQUE", "MASK", "BLEND"})},
      {"materials.[].alphaCutoff", number(0.0)},
      {"materials.[].doubleSided", boolean()},
      {"materials.[].extensions.KHR_materials_emissive_strength.emissiveStrength", number(0.0)},
      {"materials.[].extensions.KHR_materials_specular.specularFactor", number(0.0)},
      {"materials.[].extensions.KHR_materials_specular.specularColorFactor", numbers(3, 0.0)},
      {"cameras.[].type", one_of(std::vector<std::string>{"perspective", "orthographic"})},
      {"cameras.[].perspective.yfov", number()},
      {"cameras.[].perspective.aspectRatio", number()},
      {"cameras.[].perspective.znear", number()},
      {"cameras.[].perspective.zfar", number()},
      {"cameras.[].orthographic.xmag", number()},
      {"cameras.[].orthographic.ymag", number()},
      {"cameras.[].orthographic.znear", number()},
      {"cameras.[].orthographic.zfar", number()},
      {std::string(kLights) + ".[].type", one_of(std::vector<std::string>{"directional", "point", "spot"})},
      {std::string(kLights) + ".[].color", numbers(3, 0.0)},
      {std::string(kLights) + ".[].intensity", number(0.0)},
      {std::string(kLights) + ".[].range", number(0.0)},
      {std::string(kLights) + ".[].spot.innerConeAngle", number()},
      {std::string(kLights) + ".[].spot.outerConeAngle", number()},
  };
  for (const char* slot : {"pbrMetallicRoughness.baseColorTexture", "pbrMetallicRoughness.metallicRoughnessTexture",
                           "normalTexture", "occlusionTexture", "emissiveTexture",
                           "extensions.KHR_materials_specular.specularTexture",
                           "extensions.KHR_materials_specular.specularColorTexture"}) {
    add_texture_info(rows, std::string("materials.[].") + slot);
  }
  return rows;
}

const std::vector<PropertyRow>& property_table() {
  static const std::vector<PropertyRow> rows = make_table();
  return rows;
}

std::vector<std::string> split(const std::string& path) {
  std::vector<std::string> out;
  size_t start = 0;
  for (size_t dot = path.find('.'); dot != std::string::npos; dot = path.find('.', start)) {
    out.push_back(path.substr(start, dot - start));
    start = dot + 1;
  }
  out.push_back(path.substr(start));
  return out;
}

// The size of the array `path` names from `from` (a missing step means an empty array).
size_t count_at(const json& from, const std::string& path) {
  const json* at = &from;
  for (const std::string& key : split(path)) {
    if (!at->is_object() || !at->contains(key)) return 0;
    at = &(*at)[key];
  }
  return at->is_array() ? at->size() : 0;
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

std::string range_text(const Rule& r) {
  if (r.lo == -kInf && r.hi == kInf) return "";
  auto num = [](double v) { return json(v == std::trunc(v) ? json(int64_t(v)) : json(v)).dump(); };
  if (r.hi == kInf) return " >= " + num(r.lo);
  return " in [" + num(r.lo) + ", " + num(r.hi) + "]";
}

// What a rule asks for, as the end of "... it must be <this>".
std::string wanted(const Rule& r) {
  switch (r.kind) {
    case Kind::Index: return "an index (a non-negative integer)";
    case Kind::Number: return "a number" + range_text(r);
    case Kind::Integer: return "an integer" + range_text(r);
    case Kind::Boolean: return "true or false";
    case Kind::Text: return "a string";
    case Kind::IntEnum: {
      std::vector<std::string> v;
      for (int i : r.ints) v.push_back(std::to_string(i));
      return "one of " + join(v);
    }
    case Kind::TextEnum: return "one of \"" + join(r.texts) + "\"";
    case Kind::Numbers:
      return "an array of " + (r.length ? std::to_string(r.length) + " " : "") + "numbers" + range_text(r);
  }
  return "";
}

bool in_range(const json& v, const Rule& r) {
  if (!v.is_number()) return false;
  const double d = v.get<double>();
  return d >= r.lo && d <= r.hi;
}

bool obeys(const json& v, const Rule& r) {
  switch (r.kind) {
    case Kind::Number: return in_range(v, r);
    case Kind::Integer: return (v.is_number_integer() || v.is_number_unsigned()) && in_range(v, r);
    case Kind::Boolean: return v.is_boolean();
    case Kind::Text: return v.is_string();
    case Kind::IntEnum:
      for (int i : r.ints)
        if ((v.is_number_integer() || v.is_number_unsigned()) && v.get<int64_t>() == i) return true;
      return false;
    case Kind::TextEnum:
      for (const std::string& t : r.texts)
        if (v.is_string() && v.get<std::string>() == t) return true;
      return false;
    case Kind::Numbers:
      if (!v.is_array() || (r.length && v.size() != r.length)) return false;
      for (const json& e : v)
        if (!in_range(e, r)) return false;
      return true;
    case Kind::Index: return true;  // checked by check_index
  }
  return false;
}

class PropertyWalk {
 public:
  PropertyWalk(const json& doc, const std::string& file) : doc_(doc), file_(file) {}

  void check(const PropertyRow& row) {
    rule_ = &row.rule;
    path_ = split(row.path);
    walk(doc_, 0, "", nullptr);
  }

 private:
  // `first` is the element of the first array on the path (for "./" index targets).
  void walk(const json& at, size_t step, const std::string& where, const json* first) {
    if (step == path_.size()) return check_value(at, where, first);
    const std::string& key = path_[step];
    if (key == "[]" || key == "{}") {
      const bool want_array = key == "[]";
      if (want_array ? !at.is_array() : !at.is_object()) {
        throw InputError(file_, where + " is not " + (want_array ? "an array" : "an object"));
      }
      size_t i = 0;
      for (auto it = at.begin(); it != at.end(); ++it, ++i) {
        const std::string inner = want_array ? where + "[" + std::to_string(i) + "]" : where + "." + it.key();
        walk(*it, step + 1, inner, first ? first : &*it);
      }
      return;
    }
    if (!at.is_object()) throw InputError(file_, where + " is not an object");
    if (!at.contains(key)) return;  // absent: nothing to check
    walk(at[key], step + 1, where.empty() ? key : where + "." + key, first);
  }

  void check_value(const json& v, const std::string& where, const json* first) const {
    if (rule_->kind == Kind::Index) return check_index(v, where, first);
    if (!obeys(v, *rule_)) throw InputError(file_, where + " is " + input_excerpt(v.dump(), 40) + "; it must be " + wanted(*rule_));
  }

  void check_index(const json& v, const std::string& where, const json* first) const {
    const std::string target = rule_->target;
    const bool local = target.rfind("./", 0) == 0;
    const size_t count = local ? (first ? count_at(*first, target.substr(2)) : 0) : count_at(doc_, target);
    const bool integer = v.is_number_unsigned() || (v.is_number_integer() && v.get<int64_t>() >= 0);
    if (!integer) {
      throw InputError(file_, where + " is " + input_excerpt(v.dump(), 40) + ", not an index (a non-negative integer) into " + target);
    }
    if (v.get<uint64_t>() >= count) {
      throw InputError(file_, where + " is " + v.dump() + ", but " + target + " has " + std::to_string(count) +
                                  (count == 1 ? " entry" : " entries") + " (index out of range)");
    }
  }

  const json& doc_;
  const std::string& file_;
  const Rule* rule_ = nullptr;
  std::vector<std::string> path_;
};

}  // namespace

void check_document_properties(const nlohmann::json& doc, const std::string& file) {
  PropertyWalk walk(doc, file);
  for (const PropertyRow& row : property_table()) walk.check(row);
}

}  // namespace vct::gltf
