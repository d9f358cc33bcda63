#include "io/run_dir.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/utsname.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>
#include <map>
#include <mutex>

#include <OpenImageIO/oiioversion.h>
#include <embree3/rtcore_config.h>
#include <filesystem>
#include <fstream>
#include <glm/detail/setup.hpp>

#include "core/error.h"
#include "core/parallel.h"
#include "io/atomic_file.h"
#include "io/bounded_json.h"
#include "io/image_io.h"
#include "io/nrrd.h"

namespace vct {

namespace fs = std::filesystem;

// An exclusive flock on <run>/.vct-lock, held while this process writes the run. flock locks die
// with the process (kill -9 included), so a stale lock file never blocks a rerun. The file is
// removed when the lock is released; a process that locked a file just removed (its inode no
// longer the one under the name) tries again.
class RunLock {
 public:
  explicit RunLock(const std::string& dir) : path_((fs::path(dir) / kRunLockFile).string()) {
    for (int attempt = 0; attempt < 10; ++attempt) {
      fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
      if (fd_ < 0) {
        const int err = errno;
        if (err == EACCES || err == EPERM || err == EROFS)
          throw InputError(dir, std::string("cannot write in this run directory: ") + std::strerror(err));
        throw_write_error(path_, err);
      }
      if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        const std::string holder = read_holder();
        ::close(fd_);
        fd_ = -1;
        throw InputError(dir, "another vct process" + (holder.empty() ? std::string() : " (pid " + holder + ")") +
                                  " is writing this run directory; wait for it to finish or use another --out");
      }
      struct stat held {}, named {};
      if (::fstat(fd_, &held) == 0 && ::stat(path_.c_str(), &named) == 0 && held.st_ino == named.st_ino) break;
      ::close(fd_);
      fd_ = -1;
    }
    if (fd_ < 0) throw InputError(dir, "cannot lock this run directory (its lock file keeps changing)");
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {
      // The pid is only for the message another process prints; the lock holds without it.
    }
  }
  ~RunLock() {
    ::unlink(path_.c_str());
    ::close(fd_);
  }
  RunLock(const RunLock&) = delete;
  RunLock& operator=(const RunLock&) = delete;

  /// One lock per directory and process: a command that opens its run twice shares it (two
  /// flocks of one process on two descriptors would refuse each other).
  static std::shared_ptr<RunLock> acquire(const std::string& dir) {
    static std::mutex mutex;
    static std::map<std::string, std::weak_ptr<RunLock>> held;
    std::error_code ec;
    const std::string key = fs::weakly_canonical(fs::absolute(dir), ec).string();
    std::lock_guard<std::mutex> guard(mutex);
    if (auto existing = held[key].lock()) return existing;
    auto lock = std::make_shared<RunLock>(dir);
    held[key] = lock;
    return lock;
  }

 private:
  std::string read_holder() const {
    char buf[32] = {};
    const ssize_t n = ::pread(fd_, buf, sizeof buf - 1, 0);
    std::string s(buf, n > 0 ? size_t(n) : 0);
    while (!s.empty() && (s.back() == '\n' || s.back() < '0' || s.back() > '9')) s.pop_back();
    return s;
  }
  std::string path_;
  int fd_ = -1;
};

namespace {
// Temporaries of write_atomically (".tmp-<pid>-<name>") that a killed writer left behind. Only
// called while holding the run directory's lock, so no live writer owns any of them.
void remove_stale_temporaries(const std::string& dir) {
  std::error_code ec;
  std::vector<fs::path> stale;
  for (fs::recursive_directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec) && it->path().filename().string().rfind(".tmp-", 0) == 0) stale.push_back(it->path());
  for (const fs::path& p : stale) fs::remove(p, ec);
}
}  // namespace

RunDir::RunDir(std::string path, RunRole role) : path_(std::move(path)), role_(role) {
  std::error_code ec;
  if (fs::exists(path_, ec) && !fs::is_directory(path_, ec))
    throw InputError(path_, "exists and is not a directory; cannot use it as a run directory");
  fs::create_directories(path_, ec);
  if (ec) throw InputError(path_, "cannot create run directory: " + ec.message());
  json_["format"] = "vct-run/1";
  if (role_ != RunRole::Run) return;
  lock_ = RunLock::acquire(path_);
  remove_stale_temporaries(path_);
  const std::time_t now = std::time(nullptr);
  char when[64] = {};
  std::strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  write_text_atomically(file(kIncompleteMarker),
                        std::string("A vct command started writing this run directory at ") + when + " (pid " +
                            std::to_string(::getpid()) +
                            ") and has not finished. Rerun the same command to complete it.\n");
}

RunDir::~RunDir() = default;

void RunDir::finish() {
  if (role_ != RunRole::Run) return;
  finished_ = true;
  save();
  std::error_code ignored;
  fs::remove(file(kIncompleteMarker), ignored);
}

void RunDir::keep_existing_json() {
  if (!fs::exists(file("run.json"))) return;
  try {
    nlohmann::json old = read_bounded_json_file(file("run.json"), "run.json");
    if (old.is_object()) json_.merge_patch(old);
  } catch (const InputError&) {
    // Replaced by this command's run.json.
  }
}

std::string RunDir::file(const std::string& relative) const { return (fs::path(path_) / relative).string(); }

void RunDir::write_color(const std::string& name, const Image& img, float exposure) {
  write_exr(file(name + ".exr"), img);
  write_png(file(name + ".png"), img, exposure);
}

void RunDir::write_data(const std::string& name, const Image& img, float lo, float hi) {
  write_exr(file(name + ".exr"), img);
  write_png_linear(file(name + ".png"), img, lo, hi);
}

void RunDir::write_volume(const std::string& name, const Volume& vol, float spacing, float exposure) {
  write_nrrd(file(name + ".nrrd"), vol, spacing);
  write_volume_montage(file(name + ".png"), vol, 64, exposure);
}

void RunDir::add_timing(const std::string& backend, const std::string& stage, double ms) {
  json_["timings_ms"][backend][stage] = ms;
}

void RunDir::save() const {
  if (role_ != RunRole::Run) {
    write_text_atomically(file("run.json"), json_.dump(2) + "\n");
    return;
  }
  nlohmann::json j = json_;
  j["status"] = finished_ ? "complete" : "incomplete";
  write_text_atomically(file("run.json"), j.dump(2) + "\n");
}

namespace {
std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
  return "unknown";
}
}  // namespace

nlohmann::json environment_info() {
  utsname u{};
  uname(&u);
  return {{"vct_version", "0.1.0"},
          {"os", std::string(u.sysname) + " " + u.release},
          {"cpu", cpu_model()},
          {"cores", int(sysconf(_SC_NPROCESSORS_ONLN))},
          {"threads", thread_count()},
          {"compiler", std::string("gcc ") + __VERSION__},
          {"openimageio", OIIO_VERSION_STRING},
          {"embree", RTC_VERSION_STRING},
          {"glm", GLM_VERSION}};
}

}  // namespace vct
