// `vct import-capture`: a frame capture's textures, named by a capture map (capture_map.h), turned
// into a stage set (docs/external_format.md, "From a RenderDoc capture"). The capture is read
// through a CaptureReader (the real one replays a RenderDoc capture, app/renderdoc_reader.h; tests
// give a fake one), so everything but the replay is tested without RenderDoc.
#pragma once

#include <string>
#include <vector>

#include "compare/capture_map.h"
#include "compare/stage_set.h"

namespace vct::cmp {

/// One texture subresource as the reader found it, converted to float (UNORM / 255, depth in
/// [0,1], half and float as stored, integers as their value): texel-major with channels fastest,
/// then x, then y in the API's own row order (row 0 = the first row in memory), then z.
struct CapturedTexture {
  int width = 0, height = 0, depth = 1, channels = 0;
  std::vector<float> data;
  std::string format;  // the texture's format as the capture names it (for messages)
};

class CaptureReader {
 public:
  virtual ~CaptureReader() = default;
  /// One texture per stage, in the map's order. Throws InputError for a capture that cannot be
  /// opened or a resource / event / subresource that is not in it, EnvironmentError when the
  /// machine cannot replay.
  virtual std::vector<CapturedTexture> read(const std::string& capture, const std::vector<CaptureStage>& stages) = 0;
};

/// The stage set the map describes, from the textures read for its stages (in the map's order).
/// Throws InputError naming the stage when a texture does not fit it (a 3D texture as an image,
/// a channel the texture lacks, a data size that disagrees with its dimensions).
StageSet stage_set_from_capture(const CaptureMap& map, const std::vector<CapturedTexture>& textures);

/// Reads the capture, builds the stage set and writes it to `out_dir`, all or nothing: the set is
/// written beside it under a temporary name, read back by read_stage_set (the manifest checks of
/// `vct compare`) and only then renamed to `out_dir`. An `out_dir` that exists and is not empty
/// is refused.
void import_capture(const std::string& capture, const CaptureMap& map, CaptureReader& reader, const std::string& out_dir);

}  // namespace vct::cmp
