// Outputs under faults (issue 19 item 3): a file-size limit, a full disk, a read-only --out and a
// second process writing the same --out. Each ends with one line naming the file and the
// system's reason, leaves no file under a final name that is not complete, leaves INCOMPLETE in
// the run directory, and a rerun without the fault finishes it. (kill -9 of `vct validate`:
// kill_resume_test.cpp.)
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <functional>
#include <thread>
#include <vector>

#include "cli_run_util.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

struct Child {
  int exit_code = -1;  // -1: killed by a signal
  std::string err;     // stderr
};

// Runs `vct args...`, stdout to /dev/null, stderr captured; `in_child` runs after fork, before exec.
Child run_child(const std::vector<std::string>& args, const std::function<void()>& in_child = {}) {
  const fs::path err_file = test::scratch_root() / ("stderr_" + std::to_string(::getpid()) + ".txt");
  fs::create_directories(test::scratch_root());
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    const int err = ::open(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(null, 1);
    ::dup2(err, 2);
    if (in_child) in_child();
    std::vector<char*> argv{const_cast<char*>(VCT_BINARY)};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(VCT_BINARY, argv.data());
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  Child c;
  c.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  c.err = test::slurp(err_file);
  return c;
}

std::vector<std::string> render_args(const fs::path& out) {
  return {"render", "--backend", "ref", "--width", "64", "--height", "64", "--grid", "16", "--threads", "1",
          "--out", out.string()};
}

// One line on stderr, "vct: " + what the caller expects to find in it.
void expect_one_line(const Child& c, const std::string& needle) {
  EXPECT_EQ(c.err.find('\n'), c.err.size() - 1) << c.err;
  EXPECT_EQ(c.err.rfind("vct: ", 0), 0u) << c.err;
  EXPECT_NE(c.err.find(needle), std::string::npos) << c.err;
}

// The run directory after a failed write: it says it is incomplete, and holds no temporary and
// no output under its final name (the first output, final.exr, is the one that failed).
void expect_incomplete_and_clean(const fs::path& out) {
  EXPECT_TRUE(fs::exists(out / "INCOMPLETE"));
  for (const auto& e : fs::directory_iterator(out)) {
    const std::string name = e.path().filename().string();
    EXPECT_TRUE(name == "INCOMPLETE") << "left behind: " << name;
  }
}

// Rerun without the fault: finishes, INCOMPLETE is gone, run.json says complete.
void expect_rerun_finishes(const fs::path& out) {
  const Child again = run_child(render_args(out));
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_FALSE(fs::exists(out / "INCOMPLETE"));
  EXPECT_FALSE(fs::exists(out / ".vct-lock"));
  EXPECT_TRUE(fs::exists(out / "final.exr"));
  EXPECT_NE(test::slurp(out / "run.json").find("\"status\": \"complete\""), std::string::npos);
}

TEST(OutputFaults, FileSizeLimitEndsWithOneLineAndNoPartialFile) {
  const fs::path out = test::fresh_dir("fsize") / "run";
  // 8 KiB: INCOMPLETE (150 B) fits, the 64 x 64 float EXR (about 30 KiB) does not. vct ignores
  // SIGXFSZ, so the write fails with EFBIG instead of the signal killing it.
  const Child c = run_child(render_args(out), [] {
    const rlimit limit{8192, 8192};
    ::setrlimit(RLIMIT_FSIZE, &limit);
  });
  EXPECT_EQ(c.exit_code, 3);
  expect_one_line(c, (out / "final.exr").string() + ": cannot write: File too large");
  expect_incomplete_and_clean(out);
  expect_rerun_finishes(out);
}

// A full disk: a 24 KiB tmpfs mounted in a private mount namespace of the child (`unshare
// --mount`, needs root; skipped otherwise, the file-size limit above then stands in for it).
TEST(OutputFaults, FullDiskEndsWithOneLineAndNoPartialFile) {
  const fs::path dir = test::fresh_dir("full_disk");
  const fs::path mnt = dir / "mnt", listing = dir / "listing.txt", err = dir / "stderr.txt";
  fs::create_directories(mnt);
  std::string args;
  for (const auto& a : render_args(mnt / "run")) args += "'" + a + "' ";
  const fs::path script = dir / "full_disk.sh";
  std::ofstream(script) << "mount -t tmpfs -o size=24k tmpfs '" << mnt.string() << "' || exit 77\n'" << VCT_BINARY
                        << "' " << args << " >/dev/null 2>'" << err.string() << "'\nrc=$?\nls -A '"
                        << (mnt / "run").string() << "' > '" << listing.string() << "'\nexit $rc\n";
  const int status = std::system(("unshare --mount sh '" + script.string() + "' 2>/dev/null").c_str());
  const int rc = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (rc == 77 || (rc == 1 && !fs::exists(err))) GTEST_SKIP() << "cannot mount a tmpfs here (not root?)";
  EXPECT_EQ(rc, 3);
  Child c;
  c.err = test::slurp(err);
  expect_one_line(c, (mnt / "run" / "final.exr").string() + ": cannot write: No space left on device");
  EXPECT_EQ(test::slurp(listing), "INCOMPLETE\n");  // no partial final.exr, no temporary
}

TEST(OutputFaults, ReadOnlyOutIsRefusedBeforeAnyWork) {
  const fs::path out = test::fresh_dir("read_only") / "run";
  fs::create_directories(out);
  ::chmod(out.c_str(), 0555);
  // Root writes anywhere, so as root the child drops to nobody (the scratch folders are 0755).
  const Child c = run_child(render_args(out), [] {
    if (::geteuid() == 0 && (::setgid(65534) != 0 || ::setuid(65534) != 0)) ::_exit(126);
  });
  ::chmod(out.c_str(), 0755);
  ASSERT_NE(c.exit_code, 126) << "could not drop to uid 65534";
  EXPECT_EQ(c.exit_code, 2);
  expect_one_line(c, out.string() + ": cannot write in this run directory: Permission denied");
  EXPECT_TRUE(fs::is_empty(out));
}

// The second writer is refused with the first one's pid. Here the first writer is this test,
// holding the lock as a vct process does (ref/io/run_dir.cpp), so the timing cannot race.
TEST(OutputFaults, SecondWriterOfTheSameOutIsRefused) {
  const fs::path out = test::fresh_dir("second_writer") / "run";
  fs::create_directories(out);
  const int fd = ::open((out / ".vct-lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const std::string pid = std::to_string(::getpid());
  ASSERT_EQ(::write(fd, pid.data(), pid.size()), ssize_t(pid.size()));
  const Child c = run_child(render_args(out));
  EXPECT_EQ(c.exit_code, 2);
  expect_one_line(c, out.string() + ": another vct process (pid " + pid + ") is writing this run directory");
  EXPECT_FALSE(fs::exists(out / "final.exr"));
  EXPECT_FALSE(fs::exists(out / "INCOMPLETE"));  // the first writer's files are left alone
  ::close(fd);
  expect_rerun_finishes(out);  // the lock is gone with its holder
}

// Two real processes: a long path trace holds --out; a render to it is refused while it runs.
TEST(OutputFaults, RenderIntoARunningPathTraceIsRefused) {
  const fs::path out = test::fresh_dir("two_processes") / "run";
  const pid_t pt = ::fork();
  if (pt == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, 1);
    ::dup2(null, 2);
    const std::string o = out.string();
    ::execl(VCT_BINARY, VCT_BINARY, "pathtrace", "--quiet", "--width", "32", "--height", "32", "--spp", "1000000",
            "--threads", "1", "--out", o.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  bool locked = false;
  for (int i = 0; i < 3000 && !locked; ++i) {
    locked = fs::exists(out / "INCOMPLETE");  // written right after the lock is taken
    if (!locked) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const Child c = locked ? run_child(render_args(out)) : Child{};
  ::kill(pt, SIGKILL);
  ::waitpid(pt, nullptr, 0);
  ASSERT_TRUE(locked) << "vct pathtrace did not start within 60 s";
  EXPECT_EQ(c.exit_code, 2);
  expect_one_line(c, "another vct process (pid " + std::to_string(pt) + ") is writing this run directory");
  EXPECT_FALSE(fs::exists(out / "final.exr"));
}

}  // namespace
}  // namespace vct
