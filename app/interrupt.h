// Ctrl-C and kill for every command (issue 38): one line on stderr, the child processes a command
// started (the report generator, bench's validate run) stopped with it, and an exit code of its
// own. The run directory keeps its INCOMPLETE marker and its lock (an flock) goes with the
// process, so rerunning the command finishes the run (README.md, "Exit codes").
#pragma once

#include <string>

namespace vct::app {

/// The exit code of a command stopped by SIGINT or SIGTERM (0-3 are README.md's other codes).
inline constexpr int kExitInterrupted = 4;

/// Installs the SIGINT/SIGTERM handler every command runs under (main.cpp). `vct pathtrace` puts
/// its own in place while it renders, to stop after a pass with a checkpoint.
void install_interrupt_handlers();

/// As std::system(shell_command), but the child runs in its own process group, which the
/// interrupt handler stops (SIGTERM) before the parent exits; while it runs the parent still
/// answers Ctrl-C (std::system ignores SIGINT in the parent). Returns the wait status.
int run_child(const std::string& shell_command);

}  // namespace vct::app
