// vct: the VCT Oracle command line. Exit codes: 0 ok / passed, 1 comparison failed,
// 2 bad input or usage, 3 environment missing, 4 interrupted (README.md).
#include <csignal>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <new>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "core/error.h"
#include "interrupt.h"

int main(int argc, char** argv) {
  using namespace vct;
  // Past a file-size limit (ulimit -f) the kernel sends SIGXFSZ, which kills the process with a
  // core dump by default; ignored, the write fails with EFBIG and write_atomically reports it as
  // one line, leaving no partial file (issue 19).
  std::signal(SIGXFSZ, SIG_IGN);
  // Ctrl-C / kill: one line, children stopped, exit 4 (interrupt.h).
  app::install_interrupt_handlers();
  CLI::App app{"VCT Oracle: CPU reference, GL build and path-traced ground truth for voxel cone tracing"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "vct 0.1.0");
  int exit_code = kExitOk;
  app::register_info(app, exit_code);
  app::register_render(app, exit_code);
  app::register_pathtrace(app, exit_code);
  app::register_compare(app, exit_code);
  app::register_validate(app, exit_code);
  app::register_bench(app, exit_code);
  app::register_settings(app, exit_code);
  app::register_stages(app, exit_code);
  app::register_metamorphic(app, exit_code);
  app::register_attribute(app, exit_code);
  app::register_import_capture(app, exit_code);
  app::register_config_from_manifest(app, exit_code);
  try {
    app.parse(argc, argv);
    return exit_code;
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "vct: %s (see 'vct --help')\n", e.what());
    return kExitBadInput;
  } catch (const InputError& e) {
    std::fprintf(stderr, "vct: %s\n", e.what());
    return kExitBadInput;
  } catch (const EnvironmentError& e) {
    std::fprintf(stderr, "vct: environment: %s\n", e.what());
    return kExitNoEnvironment;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "vct: out of memory (try a smaller --grid or image size)\n");
    return kExitBadInput;
  } catch (const std::filesystem::filesystem_error& e) {
    std::fprintf(stderr, "vct: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vct: internal error: %s\n", e.what());
    return kExitFailed;
  }
}
