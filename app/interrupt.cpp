#include "interrupt.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>

namespace vct::app {
namespace {

// Process groups of the running children (0 = free slot); read by the handler.
constexpr int kMaxChildren = 8;
volatile std::sig_atomic_t g_children[kMaxChildren] = {};

extern "C" void vct_exit_on_interrupt(int sig) {
  for (int i = 0; i < kMaxChildren; ++i)
    if (g_children[i] > 0) ::kill(-pid_t(g_children[i]), SIGTERM);
  // Only async-signal-safe calls here: write(2) of a constant line, then _exit.
  static const char kInt[] = "vct: interrupted (SIGINT); the run directory keeps INCOMPLETE: rerun the command to finish it\n";
  static const char kTerm[] = "vct: interrupted (SIGTERM); the run directory keeps INCOMPLETE: rerun the command to finish it\n";
  const bool is_int = sig == SIGINT;
  ssize_t ignored = ::write(2, is_int ? kInt : kTerm, (is_int ? sizeof kInt : sizeof kTerm) - 1);
  (void)ignored;
  ::_exit(kExitInterrupted);
}

sigset_t interrupt_signals() {
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  return set;
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction sa {};
  sa.sa_handler = vct_exit_on_interrupt;
  sigemptyset(&sa.sa_mask);
  sigaddset(&sa.sa_mask, SIGINT);  // one handler at a time: a second signal waits for _exit
  sigaddset(&sa.sa_mask, SIGTERM);
  ::sigaction(SIGINT, &sa, nullptr);
  ::sigaction(SIGTERM, &sa, nullptr);
}

int run_child(const std::string& shell_command) {
  // Signals wait until the child is registered, so the handler cannot miss it.
  const sigset_t block = interrupt_signals();
  sigset_t old;
  ::pthread_sigmask(SIG_BLOCK, &block, &old);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setpgid(0, 0);
    ::signal(SIGINT, SIG_DFL);
    ::signal(SIGTERM, SIG_DFL);
    ::pthread_sigmask(SIG_SETMASK, &old, nullptr);
    ::execl("/bin/sh", "sh", "-c", shell_command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int slot = -1;
  if (pid > 0) {
    ::setpgid(pid, pid);  // also here: whichever of parent and child runs first
    for (int i = 0; i < kMaxChildren && slot < 0; ++i)
      if (g_children[i] == 0) slot = i;
    if (slot >= 0) g_children[slot] = pid;
  }
  ::pthread_sigmask(SIG_SETMASK, &old, nullptr);
  if (pid < 0) return -1;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (slot >= 0) g_children[slot] = 0;
  return status;
}

}  // namespace vct::app
