// vct validate [SCENE]: ref + gl + pt + comparisons + report. Grows as the engines land.
#include <cstdio>

#include "commands.h"
#include "core/error.h"

namespace vct::app {

void register_validate(CLI::App& app, int& exit_code) {
  CLI::App* cmd = app.add_subcommand("validate", "(not built yet)");
  cmd->allow_extras();
  cmd->callback([&exit_code]() {
    std::fprintf(stderr, "vct validate: not built yet\n");
    exit_code = kExitNoEnvironment;
  });
}

}  // namespace vct::app
