// vct config-from-manifest STAGESET: the reference's --config for a stage set (manifest_config.h),
// printed or written with --out; notes on stderr. Exit 0, 2 bad stage set or settings.
#include <cstdio>

#include "commands.h"
#include "compare/stage_set.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "manifest_config.h"

namespace vct::app {

void register_config_from_manifest(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("config-from-manifest",
                                 "Turn a stage set's manifest into the reference's settings (a --config file)");
  static std::string stage_set, out;
  cmd->add_option("stage_set", stage_set, "A stage set directory or its vct-stages.json")->required();
  cmd->add_option("--out", out, "Write the settings JSON here (default: print it)");
  cmd->callback([&exit_code] {
    std::vector<std::string> notes;
    const nlohmann::json config = config_from_manifest(cmp::read_stage_set(stage_set), notes);
    for (const std::string& n : notes) std::fprintf(stderr, "note: %s\n", n.c_str());
    if (out.empty()) std::printf("%s\n", config.dump(2).c_str());
    else write_text_atomically(out, config.dump(2) + "\n");
    exit_code = kExitOk;
  });
}

}  // namespace vct::app
