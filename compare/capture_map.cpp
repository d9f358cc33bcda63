#include "compare/capture_map.h"

#include <set>

#include "compare/conventions.h"
#include "core/error.h"
#include "core/reduction_names.h"
#include "io/bounded_json.h"
#include "stages/backend_facts.h"
#include "stages/stage_registry.h"

namespace vct::cmp {
namespace {

using nlohmann::json;

// The keys each object of the map may hold (docs/external_format.md, "From a RenderDoc capture").
const std::set<std::string> kTopKeys = {"format", "version", "rows", "manifest", "stages"};
const std::set<std::string> kManifestKeys = {"backend", "storage", "reduction", "settings", "facts", "conventions", "info"};
const std::set<std::string> kStageKeys = {"resource", "event", "mip", "slice", "sample", "channels", "rows", "kind"};
const std::set<std::string> kStorages = {"rgba8", "rgba16f", "rgba32f"};

void check_keys(const json& j, const std::set<std::string>& allowed, const std::string& where, const std::string& path) {
  if (!j.is_object()) throw InputError(path, where + " must be an object");
  for (const auto& [key, value] : j.items())
    if (!allowed.count(key)) throw InputError(path, "unknown key '" + key + "' in " + where);
}

bool rows_bottom_first(const json& j, const std::string& where, const std::string& path) {
  const std::string rows = j.get<std::string>();
  if (rows != "bottom_first" && rows != "top_first")
    throw InputError(path, where + ": \"rows\" must be \"bottom_first\" (GL) or \"top_first\" (Vulkan, D3D), not '" + rows + "'");
  return rows == "bottom_first";
}

int small_index(const json& j, const std::string& key, const std::string& where, const std::string& path) {
  if (!j.contains(key)) return 0;
  if (!j[key].is_number_integer() || j[key].get<int64_t>() < 0 || j[key].get<int64_t>() > 65535)
    throw InputError(path, where + ": \"" + key + "\" must be an integer in [0, 65535]");
  return j[key].get<int>();
}

std::string resource_of(const json& j, const std::string& where, const std::string& path) {
  if (!j.contains("resource")) throw InputError(path, where + " needs a \"resource\" (debug label or resource id)");
  const json& r = j["resource"];
  if (r.is_number_unsigned()) return std::to_string(r.get<uint64_t>());
  if (!r.is_string() || r.get<std::string>().empty())
    throw InputError(path, where + ": \"resource\" must be a non-empty label or a resource id");
  return r.get<std::string>();
}

std::string event_of(const json& j, const std::string& where, const std::string& path) {
  if (!j.contains("event")) return "end";
  const json& e = j["event"];
  if (e.is_number_unsigned()) return std::to_string(e.get<uint64_t>());
  if (!e.is_string() || e.get<std::string>().empty())
    throw InputError(path, where + ": \"event\" must be an event id, \"end\" or a debug group name");
  return e.get<std::string>();
}

std::vector<int> channels_of(const json& j, const std::string& where, const std::string& path) {
  std::vector<int> out;
  if (!j.contains("channels")) return out;
  const json& c = j["channels"];
  if (!c.is_array() || c.empty() || c.size() > 4)
    throw InputError(path, where + ": \"channels\" must be a list of 1 to 4 channel indices");
  for (const json& i : c) {
    if (!i.is_number_integer() || i.get<int64_t>() < 0 || i.get<int64_t>() > 3)
      throw InputError(path, where + ": \"channels\" entries must be 0..3");
    out.push_back(i.get<int>());
  }
  return out;
}

std::string kind_of(const json& j, const std::string& name, const std::string& where, const std::string& path) {
  const auto expected = namespace_kind(name);
  std::string kind = expected ? (*expected == StageKind::Image ? "image" : "volume") : "";
  if (j.contains("kind")) {
    const std::string given = j["kind"].get<std::string>();
    if (given != "image" && given != "volume") throw InputError(path, where + ": \"kind\" must be \"image\" or \"volume\"");
    if (!kind.empty() && given != kind)
      throw InputError(path, where + ": stage '" + name + "' must be " + (kind == "image" ? "an image" : "a volume") +
                                 " (docs/external_format.md, Stage names)");
    kind = given;
  }
  if (kind.empty()) throw InputError(path, where + ": say \"kind\" (\"image\" or \"volume\") for a stage outside the known namespaces");
  return kind;
}

// The manifest half is checked as the stage-set reader will check it, before any capture is read.
void check_manifest(const json& m, const std::string& path) {
  check_keys(m, kManifestKeys, "\"manifest\"", path);
  if (m.contains("storage") && !kStorages.count(m["storage"].get<std::string>()))
    throw InputError(path, "unknown storage '" + m["storage"].get<std::string>() + "' (rgba8, rgba16f, rgba32f)");
  if (m.contains("reduction") && !reduction_from_name(m["reduction"].get<std::string>()))
    throw InputError(path, "unknown reduction '" + m["reduction"].get<std::string>() +
                               "' (exact_mean | fixed_point | cas_rgba8 | running_mean, or the settings' exact | fixed | cas)");
  for (const char* key : {"settings", "info"})
    if (m.contains(key) && !m[key].is_object()) throw InputError(path, std::string("\"manifest\".\"") + key + "\" must be an object");
  if (m.contains("facts")) (void)m["facts"].get<BackendFacts>();
  if (m.contains("conventions")) (void)read_conventions(path, m["conventions"]);
}

CaptureMap parse_unguarded(const json& doc, const std::string& path) {
  check_keys(doc, kTopKeys, "the map", path);
  if (doc.value("format", "") != "vct-capture-map") throw InputError(path, "\"format\" must be \"vct-capture-map\"");
  if (doc.value("version", 0) != 1) throw InputError(path, "\"version\" must be 1");
  CaptureMap map;
  map.path = path;
  if (doc.contains("manifest")) {
    check_manifest(doc["manifest"], path);
    map.manifest = doc["manifest"];
  }
  const bool bottom_first = doc.contains("rows") ? rows_bottom_first(doc["rows"], "the map", path) : true;
  if (!doc.contains("stages") || !doc["stages"].is_object() || doc["stages"].empty())
    throw InputError(path, "\"stages\" must be a non-empty object of stage name -> {resource, event, ...}");
  for (const auto& [name, j] : doc["stages"].items()) {
    const std::string where = "stage '" + name + "'";
    check_keys(j, kStageKeys, where, path);
    CaptureStage s;
    s.name = name;
    s.kind = kind_of(j, name, where, path);
    s.resource = resource_of(j, where, path);
    s.event = event_of(j, where, path);
    s.mip = small_index(j, "mip", where, path);
    s.slice = small_index(j, "slice", where, path);
    s.sample = small_index(j, "sample", where, path);
    s.channels = channels_of(j, where, path);
    s.bottom_first = j.contains("rows") ? rows_bottom_first(j["rows"], where, path) : bottom_first;
    map.stages.push_back(std::move(s));
  }
  return map;
}

}  // namespace

CaptureMap parse_capture_map(const json& doc, const std::string& path) {
  try {
    return parse_unguarded(doc, path);
  } catch (const json::exception& e) {
    // A field of the wrong JSON type ("mip": "2", "storage": 3): one line like any bad input.
    throw InputError(path, std::string("bad capture map: ") + e.what());
  }
}

CaptureMap read_capture_map(const std::string& path) {
  return parse_capture_map(read_bounded_json_file(path, "capture map"), path);
}

}  // namespace vct::cmp
