// vct import-capture: a RenderDoc frame capture of any engine -> a stage set, through a capture
// map that names each stage's texture and event and the engine's manifest conventions
// (docs/external_format.md, "From a RenderDoc capture"). Exit 0 written, 2 bad map or capture
// (one line, nothing written), 3 no RenderDoc replay on this machine.
#include <cstdio>

#include "commands.h"
#include "compare/capture_import.h"
#include "core/error.h"
#include "renderdoc_reader.h"

namespace vct::app {

void register_import_capture(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("import-capture", "Turn a RenderDoc capture into a stage set (vct compare reads it)");
  static std::string capture, map_file, out;
  cmd->add_option("capture", capture, "The frame capture (.rdc)")->required();
  cmd->add_option("--map", map_file, "The capture map (JSON: stage -> resource, event; the manifest's conventions)")->required();
  cmd->add_option("--out", out, "The stage set to write (a new or empty directory)")->required();
  cmd->callback([&exit_code] {
    const cmp::CaptureMap map = cmp::read_capture_map(map_file);  // checked before the capture is opened
    RenderDocReader reader;
    cmp::import_capture(capture, map, reader, out);
    std::printf("stage set written: %s (%zu stages)\n", out.c_str(), map.stages.size());
    exit_code = kExitOk;
  });
}

}  // namespace vct::app
