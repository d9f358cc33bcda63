// A structure-aware mutator for glTF JSON (issue 19 item 4). Byte mutations of a 20-700 KB scene
// seldom keep it valid JSON, so they stop at the parser; this one parses the document and changes
// its structure, so the loader's checks behind the parser (indices, counts, types, the nesting
// limit, URIs) see inputs that are almost right:
//   - duplicate, delete or swap array elements and object members, copy a subtree elsewhere;
//   - replace a value by one of another type;
//   - set numbers to edge values (0, -1, 2^31, 2^32, huge, tiny) and raw tokens JSON has not
//     (NaN, Infinity, 1e999), or the string "NaN";
//   - set index fields (glTF 2.0 spec §3.7: an index names an element of a top-level array) to the
//     array's size, -1 or beyond 2^31;
//   - rewire the accessor/index graph: set an index field to another *valid* index of its array
//     (a NORMAL to a VEC2 accessor, a morph target to one of another count, a texture to another
//     image), so the checks behind the index range (types, counts, component types) are reached
//     (issue 38);
//   - set URIs to what the file-access policy judges (docs/scenes.md, "File access");
//   - nest a value 127-20 000 levels deep (ref/io/bounded_json.h refuses beyond 128).
// Raw tokens and deep nesting are spliced into the text after serialization: nlohmann's dump
// recurses, and JSON has no NaN. Used by fuzz/gltf_fuzz.cpp (LLVMFuzzerCustomMutator) and by
// tests/ref/gltf_mutator_test.cpp; header-only, so the fuzz build and the tests share it.
#pragma once

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/bounded_json.h"

namespace vct::fuzz {

namespace gltf_mutator_detail {

using Json = nlohmann::json;
using Rng = std::minstd_rand;

// A quoted string the serializer writes verbatim, later replaced by raw text (a token JSON does
// not have, or nesting too deep to build as a tree). \u0001 never occurs in a glTF we mutate.
inline const std::string kPlaceholder = "\x01vct-splice\x01";

struct Node {
  Json* value;
  std::string key;  // the member name in its parent object, "" for array elements and the root
  Json* parent;
};

inline size_t pick(Rng& rng, size_t n) { return n == 0 ? 0 : size_t(rng() % n); }

// Every value of the document, parents before children; iterative, so a deep input cannot
// exhaust the mutator's stack (inputs are checked against a nesting bound before parsing anyway).
inline std::vector<Node> collect(Json& root) {
  std::vector<Node> nodes{{&root, "", nullptr}};
  for (size_t i = 0; i < nodes.size(); ++i) {
    Json* v = nodes[i].value;
    if (v->is_object())
      for (auto it = v->begin(); it != v->end(); ++it) nodes.push_back({&it.value(), it.key(), v});
    else if (v->is_array())
      for (Json& e : *v) nodes.push_back({&e, "", v});
  }
  return nodes;
}

// glTF index fields and the top-level array each one indexes (glTF 2.0 spec §5).
inline const char* indexed_array(const std::string& key) {
  static const std::pair<const char*, const char*> kIndexFields[] = {
      {"bufferView", "bufferViews"}, {"buffer", "buffers"},   {"indices", "accessors"}, {"POSITION", "accessors"},
      {"NORMAL", "accessors"},       {"TANGENT", "accessors"}, {"TEXCOORD_0", "accessors"}, {"TEXCOORD_1", "accessors"},
      {"COLOR_0", "accessors"},      {"material", "materials"}, {"mesh", "meshes"},      {"camera", "cameras"},
      {"children", "nodes"},         {"nodes", "nodes"},       {"scene", "scenes"},      {"source", "images"},
      {"sampler", "samplers"},       {"index", "textures"},    {"light", "lights"},      {"skin", "skins"},
      {"input", "accessors"},        {"output", "accessors"},  {"node", "nodes"},        {"texCoord", ""}};
  for (const auto& [field, array] : kIndexFields)
    if (key == field) return array;
  return nullptr;
}

inline int64_t edge_index(Rng& rng, const Json& root, const char* array) {
  int64_t count = 0;
  if (*array && root.contains(array) && root[array].is_array()) count = int64_t(root[array].size());
  const int64_t edges[] = {count, count + 1, -1, 2147483647LL, 2147483648LL, 4294967296LL, int64_t(1) << 53};
  return edges[pick(rng, std::size(edges))];
}

// Raw number tokens: JSON's edge cases and what it has not (JSON has no NaN or Infinity).
inline const std::vector<std::string>& edge_tokens() {
  static const std::vector<std::string> tokens = {
      "0",           "-1",          "-0",       "2147483647",           "2147483648",  "4294967295",
      "4294967296",  "9007199254740993", "18446744073709551616", "1e308", "-1e308",  "1e999",
      "1e-45",       "1e-400",      "NaN",      "Infinity",             "-Infinity",   "0.5"};
  return tokens;
}

inline Json edge_string(Rng& rng) {
  static const char* kStrings[] = {"",
                                   "NaN",
                                   "../../../../../../etc/passwd",
                                   "/etc/passwd",
                                   "file:///etc/passwd",
                                   "data:application/octet-stream;base64,",
                                   "data:application/octet-stream;base64,AAAA",
                                   "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mNk",
                                   "textures/../../outside.png",
                                   "%2e%2e/%2e%2e/etc/passwd",
                                   "SCALAR",
                                   "MAT4",
                                   "KHR_lights_punctual"};
  if (pick(rng, 8) == 0) return std::string(size_t(1) << (10 + pick(rng, 8)), 'A');  // 1 KiB .. 128 KiB
  return kStrings[pick(rng, std::size(kStrings))];
}

inline Json other_type(Rng& rng, const Json& v) {
  switch (pick(rng, 7)) {
    case 0: return v.is_string() ? Json(0) : Json(v.dump(-1, ' ', false, Json::error_handler_t::replace));
    case 1: return nullptr;
    case 2: return Json::array({v});
    case 3: return Json::object({{"value", v}});
    case 4: return !v.is_boolean();
    case 5: return Json::array();
    default: return Json::object();
  }
}

// One structural change; raw text to splice in for the placeholder is returned in `splice`.
inline void mutate_once(Rng& rng, Json& root, std::string& splice) {
  std::vector<Node> nodes = collect(root);
  Node& n = nodes[pick(rng, nodes.size())];
  Json& v = *n.value;
  switch (pick(rng, 10)) {
    case 0:  // duplicate an element or member
      if (v.is_array() && !v.empty()) v.insert(v.begin() + long(pick(rng, v.size() + 1)), v[pick(rng, v.size())]);
      else if (v.is_object() && !v.empty()) v[std::next(v.begin(), long(pick(rng, v.size()))).key() + "_"] = v.front();
      break;
    case 1:  // delete
      if (v.is_array() && !v.empty()) v.erase(v.begin() + long(pick(rng, v.size())));
      else if (v.is_object() && !v.empty()) v.erase(std::next(v.begin(), long(pick(rng, v.size()))));
      break;
    case 2:  // swap two elements, or two members' values
      if ((v.is_array() || v.is_object()) && v.size() >= 2) std::swap(*std::next(v.begin(), long(pick(rng, v.size()))),
                                                                     *std::next(v.begin(), long(pick(rng, v.size()))));
      break;
    case 3:  // another type
      if (n.parent) v = other_type(rng, v);
      break;
    case 4:  // an edge number (or raw token), spliced as text
      if (n.parent && splice.empty()) {
        splice = edge_tokens()[pick(rng, edge_tokens().size())];
        v = kPlaceholder;
      } else if (n.parent) {
        v = -1;
      }
      break;
    case 5: {  // an index field out of range
      const char* array = indexed_array(n.key);
      if (array && v.is_number()) v = edge_index(rng, root, array);
      else if (array && v.is_array() && !v.empty()) v[pick(rng, v.size())] = edge_index(rng, root, array);
      else if (n.parent && n.parent->is_object()) {
        // No index here: give an index field to the parent instead.
        static const char* kFields[] = {"bufferView", "accessor", "material", "mesh", "source", "sampler", "index"};
        const char* field = kFields[pick(rng, std::size(kFields))];
        (*n.parent)[field] = edge_index(rng, root, indexed_array(field) ? indexed_array(field) : "");
      }
      break;
    }
    case 8: {  // rewire: another valid index of the same array
      const char* array = indexed_array(n.key);
      const int64_t count = array && *array && root.contains(array) && root[array].is_array()
                                ? int64_t(root[array].size()) : 0;
      if (count == 0) break;
      if (v.is_number()) v = int64_t(pick(rng, size_t(count)));
      else if (v.is_array() && !v.empty()) v[pick(rng, v.size())] = int64_t(pick(rng, size_t(count)));
      break;
    }
    case 6:  // a string the loader judges (URIs, types), or a very long one
      if (n.parent && (v.is_string() || pick(rng, 4) == 0)) v = edge_string(rng);
      break;
    case 7: {  // copy a subtree somewhere else
      const Json copy = *nodes[pick(rng, nodes.size())].value;
      if (v.is_array()) v.push_back(copy);
      else if (v.is_object()) v["extras"] = copy;
      break;
    }
    default:  // nest a value deeply, around the limit or far past it
      if (n.parent && splice.empty()) {
        static const size_t kDepths[] = {100, 126, 127, 128, 129, 1000, 20000};
        const size_t depth = kDepths[pick(rng, std::size(kDepths))];
        const bool objects = pick(rng, 2) == 0;
        std::string text;
        for (size_t i = 0; i < depth; ++i) text += objects ? "{\"a\":" : "[";
        text += "0";
        for (size_t i = 0; i < depth; ++i) text += objects ? "}" : "]";
        splice = std::move(text);
        v = kPlaceholder;
      }
      break;
  }
}

}  // namespace gltf_mutator_detail

/// Parses `text` as JSON and applies 1-4 structural mutations chosen by `seed`. nullopt when the
/// text is not JSON we can take apart (not JSON, nested deeper than 4 x kMaxJsonNesting, or a
/// result longer than max_size): the caller falls back to byte mutation.
inline std::optional<std::string> mutate_gltf_json(const std::string& text, uint32_t seed, size_t max_size) {
  using namespace gltf_mutator_detail;
  if (scan_json_nesting(text, 4 * kMaxJsonNesting).exceeded) return std::nullopt;
  Json root = Json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (root.is_discarded() || !root.is_object()) return std::nullopt;
  Rng rng(seed ? seed : 1);
  std::string splice, out;
  try {
    const size_t count = 1 + pick(rng, 4);
    for (size_t i = 0; i < count; ++i) mutate_once(rng, root, splice);
    out = root.dump(-1, ' ', false, Json::error_handler_t::replace);
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;  // a mutation nlohmann refuses (none known): byte mutation instead
  }
  if (!splice.empty()) {
    const std::string quoted = Json(kPlaceholder).dump();
    const size_t at = out.find(quoted);
    if (at != std::string::npos) out.replace(at, quoted.size(), splice);
  }
  if (out.size() > max_size || out == text) return std::nullopt;
  return out;
}

}  // namespace vct::fuzz
