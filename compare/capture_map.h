// The mapping file of `vct import-capture` (docs/external_format.md, "From a RenderDoc capture"):
// which texture of a frame capture holds each stage, after which event to read it, and the
// manifest conventions of the engine that rendered it. Parsed and checked before the capture is
// opened, so a bad map is one line and exit 2 with nothing written.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vct::cmp {

/// Where in the capture a stage is read: resource by debug label (glObjectLabel, vkSetDebugUtils
/// ObjectNameEXT) or by RenderDoc resource id, after an event.
struct CaptureStage {
  std::string name;      // canonical stage name ("voxel.radiance", "mip.iso.2", ...)
  std::string kind;      // "image" | "volume"
  std::string resource;  // debug label, or "ResourceId::N" / "N" for an id
  // "end" (the end of the capture), an event id as decimal digits, or the name of a debug group
  // / action: the read happens after the last event inside the first one of that name.
  std::string event = "end";
  int mip = 0;
  int slice = 0;   // array layer, cube face (layer·6 + face) or, for an image from a 3D texture, z
  int sample = 0;  // multisample index
  std::vector<int> channels;  // the texture's channels to keep, in order; empty = all
  bool bottom_first = true;   // rows as GL stores them (row 0 = bottom): flipped to row 0 = top
};

struct CaptureMap {
  std::string path;  // the map file (for messages)
  nlohmann::json manifest = nlohmann::json::object();  // backend, storage, reduction, settings, facts, conventions, info
  std::vector<CaptureStage> stages;
};

/// Parses and checks a map document; throws InputError(path, ...) naming the first problem.
CaptureMap parse_capture_map(const nlohmann::json& doc, const std::string& path);
/// read_bounded_json_file then parse_capture_map.
CaptureMap read_capture_map(const std::string& path);

}  // namespace vct::cmp
