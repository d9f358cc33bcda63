// The table of glTF index properties and the walk that checks them (gltf_index_table.h).
#include "scene/gltf_index_table.h"

#include <vector>

#include "core/error.h"

namespace vct::gltf {
namespace {

using nlohmann::json;

/// One index property: where it sits (a path from each element of `owner`, "[]" visits every
/// element of an array, "{}" every value of an object) and the array it indexes (a path from the
/// document root, or from the owning element when it starts with "./").
struct IndexRow {
  const char* owner;   // top-level array whose elements hold the index; "" = the document itself
  const char* path;    // dot-separated
  const char* target;  // dot-separated
};

constexpr const char* kLights = "extensions.KHR_lights_punctual.lights";

const std::vector<IndexRow>& index_table() {
  static const std::vector<IndexRow> rows = {
      {"", "scene", "scenes"},
      {"scenes", "nodes.[]", "nodes"},
      {"nodes", "children.[]", "nodes"},
      {"nodes", "mesh", "meshes"},
      {"nodes", "camera", "cameras"},
      {"nodes", "skin", "skins"},
      {"nodes", "extensions.KHR_lights_punctual.light", kLights},
      {"meshes", "primitives.[].attributes.{}", "accessors"},
      {"meshes", "primitives.[].indices", "accessors"},
      {"meshes", "primitives.[].material", "materials"},
      {"meshes", "primitives.[].targets.[].{}", "accessors"},
      {"skins", "joints.[]", "nodes"},
      {"skins", "skeleton", "nodes"},
      {"skins", "inverseBindMatrices", "accessors"},
      {"animations", "channels.[].sampler", "./samplers"},
      {"animations", "channels.[].target.node", "nodes"},
      {"animations", "samplers.[].input", "accessors"},
      {"animations", "samplers.[].output", "accessors"},
      {"accessors", "bufferView", "bufferViews"},
      {"accessors", "sparse.indices.bufferView", "bufferViews"},
      {"accessors", "sparse.values.bufferView", "bufferViews"},
      {"bufferViews", "buffer", "buffers"},
      {"images", "bufferView", "bufferViews"},
      {"textures", "source", "images"},
      {"textures", "sampler", "samplers"},
      {"materials", "pbrMetallicRoughness.baseColorTexture.index", "textures"},
      {"materials", "pbrMetallicRoughness.metallicRoughnessTexture.index", "textures"},
      {"materials", "normalTexture.index", "textures"},
      {"materials", "occlusionTexture.index", "textures"},
      {"materials", "emissiveTexture.index", "textures"},
      {"materials", "extensions.KHR_materials_specular.specularTexture.index", "textures"},
      {"materials", "extensions.KHR_materials_specular.specularColorTexture.index", "textures"},
  };
  return rows;
}

std::vector<std::string> split(const char* path) {
  std::vector<std::string> out;
  std::string part;
  for (const char* c = path; *c; ++c) {
    if (*c == '.') {
      out.push_back(part);
      part.clear();
    } else {
      part += *c;
    }
  }
  if (!part.empty()) out.push_back(part);
  return out;
}

// The array `path` names from `from` (a missing step means an empty array).
size_t count_at(const json& from, const std::vector<std::string>& path) {
  const json* at = &from;
  for (const std::string& key : path) {
    if (!at->is_object() || !at->contains(key)) return 0;
    at = &(*at)[key];
  }
  return at->is_array() ? at->size() : 0;
}

class IndexWalk {
 public:
  IndexWalk(const json& doc, const std::string& file) : doc_(doc), file_(file) {}

  void check(const IndexRow& row, const json& element, const std::string& where) {
    const std::string target = row.target;
    const bool local = target.rfind("./", 0) == 0;
    const size_t count = count_at(local ? element : doc_, split(local ? row.target + 2 : row.target));
    walk(element, split(row.path), 0, where, target, count);
  }

 private:
  void walk(const json& at, const std::vector<std::string>& path, size_t step, const std::string& where,
            const std::string& target, size_t count) {
    if (step == path.size()) return check_index(at, where, target, count);
    const std::string& key = path[step];
    if (key == "[]" || key == "{}") {
      const bool want_array = key == "[]";
      if (want_array ? !at.is_array() : !at.is_object()) {
        throw InputError(file_, where + " is not " + (want_array ? "an array" : "an object"));
      }
      size_t i = 0;
      for (auto it = at.begin(); it != at.end(); ++it, ++i) {
        const std::string inner = want_array ? where + "[" + std::to_string(i) + "]" : where + "." + it.key();
        walk(*it, path, step + 1, inner, target, count);
      }
      return;
    }
    if (!at.is_object()) throw InputError(file_, where + " is not an object");
    if (!at.contains(key)) return;  // absent: nothing to check
    walk(at[key], path, step + 1, where.empty() ? key : where + "." + key, target, count);
  }

  void check_index(const json& v, const std::string& where, const std::string& target, size_t count) const {
    const bool integer = v.is_number_unsigned() || (v.is_number_integer() && v.get<int64_t>() >= 0);
    if (!integer) {
      throw InputError(file_, where + " is " + excerpt(v) + ", not an index (a non-negative integer) into " + target);
    }
    if (v.get<uint64_t>() >= count) {
      throw InputError(file_, where + " is " + v.dump() + ", but " + target + " has " + std::to_string(count) +
                                  (count == 1 ? " entry" : " entries") + " (index out of range)");
    }
  }

  // A value in a message: at most 40 characters of it.
  static std::string excerpt(const json& v) {
    std::string s = v.dump();
    return s.size() > 40 ? s.substr(0, 37) + "..." : s;
  }

  const json& doc_;
  const std::string& file_;
};

}  // namespace

void check_document_indices(const nlohmann::json& doc, const std::string& file) {
  IndexWalk walk(doc, file);
  for (const IndexRow& row : index_table()) {
    const std::string owner = row.owner;
    if (owner.empty()) {
      walk.check(row, doc, "");
      continue;
    }
    if (!doc.contains(owner)) continue;
    const json& list = doc[owner];
    if (!list.is_array()) throw InputError(file, owner + " is not an array");
    for (size_t i = 0; i < list.size(); ++i) walk.check(row, list[i], owner + "[" + std::to_string(i) + "]");
  }
}

}  // namespace vct::gltf
