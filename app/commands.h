// Each subcommand lives in its own cmd_<name>.cpp and registers itself here. A command's
// callback stores its exit code in `exit_code`; errors are thrown (InputError -> 2,
// EnvironmentError -> 3) and reported by main as one line.
#pragma once

#include <CLI/CLI.hpp>

namespace vct::app {

void register_info(CLI::App& app, int& exit_code);
void register_render(CLI::App& app, int& exit_code);
void register_pathtrace(CLI::App& app, int& exit_code);
void register_compare(CLI::App& app, int& exit_code);
void register_validate(CLI::App& app, int& exit_code);
void register_bench(CLI::App& app, int& exit_code);
void register_settings(CLI::App& app, int& exit_code);
void register_stages(CLI::App& app, int& exit_code);
void register_metamorphic(CLI::App& app, int& exit_code);
void register_attribute(CLI::App& app, int& exit_code);
void register_import_capture(CLI::App& app, int& exit_code);
void register_config_from_manifest(CLI::App& app, int& exit_code);

}  // namespace vct::app
