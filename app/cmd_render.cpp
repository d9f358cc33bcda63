// vct render: not built yet (see the open issues); registered so --help lists it.
#include <cstdio>

#include "commands.h"
#include "core/error.h"

namespace vct::app {

void register_render(CLI::App& app, int& exit_code) {
  CLI::App* cmd = app.add_subcommand("render", "(not built yet)");
  cmd->allow_extras();
  cmd->callback([&exit_code]() {
    std::fprintf(stderr, "vct render: not built yet\n");
    exit_code = kExitNoEnvironment;
  });
}

}  // namespace vct::app
