// Issue 38 item 9: SIGINT/SIGTERM end every command with one line and exit 4 (README.md), the
// run directory keeps INCOMPLETE, its lock goes with the process, and a child process the command
// started (the report generator) is stopped with it instead of writing on without the lock.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <thread>
#include <vector>

#include "../../app/interrupt.h"
#include "cli_run_util.h"

namespace vct {
namespace {

namespace fs = std::filesystem;
using test::spawn_vct;

bool wait_until(const std::function<bool()>& done, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

int exit_code_of(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

// A process that no longer runs: gone, or a zombie nobody has reaped yet.
bool stopped(pid_t pid) {
  const std::string stat = test::slurp("/proc/" + std::to_string(pid) + "/stat");
  const size_t paren = stat.rfind(')');
  return stat.empty() || (paren != std::string::npos && paren + 2 < stat.size() && stat[paren + 2] == 'Z');
}

TEST(InterruptCli, SigtermDuringValidateIsExitFourWithOneLineAndTheLockFree) {
  const fs::path dir = test::fresh_dir("interrupt_validate");
  const fs::path out = dir / "run", err = dir / "stderr.txt";
  // 1600 spp keep the path tracer busy for seconds: the signal lands mid-run.
  const pid_t pid = spawn_vct({"validate", "--width", "32", "--height", "32", "--grid", "16", "--spp", "1600",
                               "--threads", "2", "--no-report", "--out", out.string()},
                              err.string());
  ASSERT_TRUE(wait_until([&] { return fs::exists(out / "INCOMPLETE"); }, 60.0));
  ::kill(pid, SIGTERM);
  EXPECT_EQ(exit_code_of(pid), app::kExitInterrupted);
  const std::string text = test::slurp(err);
  EXPECT_NE(text.find("vct: interrupted (SIGTERM)"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
  EXPECT_EQ(text.find("interrupted"), text.rfind("interrupted")) << text;  // said once
  EXPECT_TRUE(fs::exists(out / "INCOMPLETE"));
  const int lock = ::open((out / ".vct-lock").c_str(), O_RDWR);
  ASSERT_GE(lock, 0);
  EXPECT_EQ(::flock(lock, LOCK_EX | LOCK_NB), 0) << "the lock outlived the interrupted command";
  ::close(lock);
}

// run_child's child (here a shell that records its pid, then sleeps) is stopped by the handler.
TEST(InterruptCli, ChildProcessIsStoppedWithTheCommand) {
  const fs::path dir = test::fresh_dir("interrupt_child");
  const fs::path pid_file = dir / "child.pid", err = dir / "stderr.txt";
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(e, 2);
    app::install_interrupt_handlers();
    app::run_child("echo $$ > '" + pid_file.string() + ".tmp' && mv '" + pid_file.string() + ".tmp' '" +
                   pid_file.string() + "' && exec sleep 60");
    ::_exit(0);  // reached only if the child ended by itself
  }
  ASSERT_TRUE(wait_until([&] { return fs::exists(pid_file); }, 20.0));
  const pid_t child = std::stoi(test::slurp(pid_file));
  ::kill(pid, SIGINT);
  EXPECT_EQ(exit_code_of(pid), app::kExitInterrupted);
  EXPECT_NE(test::slurp(err).find("vct: interrupted (SIGINT)"), std::string::npos);
  EXPECT_TRUE(wait_until([&] { return stopped(child); }, 10.0)) << "the child outlived the command";
}

}  // namespace
}  // namespace vct
