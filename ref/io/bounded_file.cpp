#include "io/bounded_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"

namespace vct {
namespace {

struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

std::string open_problem(int error) {
  if (error == ENOENT || error == ENOTDIR) return "file not found";
  if (error == EACCES || error == EPERM) return "permission denied";
  return std::string("cannot open: ") + std::strerror(error);
}

}  // namespace

std::string read_regular_file(const std::string& path, uint64_t max_bytes, const std::string& kind) {
  // O_NONBLOCK: opening a FIFO must not wait for a writer; fstat on the open descriptor then
  // decides, so the file cannot be swapped between the check and the read.
  const Fd f{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC)};
  if (f.fd < 0) throw InputError(path, open_problem(errno));
  struct stat st {};
  if (::fstat(f.fd, &st) != 0) throw InputError(path, std::string("cannot stat: ") + std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw InputError(path, "is a directory, not a " + kind);
  if (!S_ISREG(st.st_mode)) {
    throw InputError(path, "is not a regular file (a FIFO, device or socket); a " + kind + " must be a regular file");
  }
  const auto too_large = [&](uint64_t bytes) {
    return InputError(path, "is " + std::to_string(bytes) + " bytes; a " + kind + " may have at most " +
                                std::to_string(max_bytes) + " (docs/scenes.md, \"Limits\")");
  };
  if (uint64_t(st.st_size) > max_bytes) throw too_large(uint64_t(st.st_size));
  std::string bytes(size_t(st.st_size), '\0');
  size_t have = 0;
  for (;;) {
    if (have == bytes.size()) bytes.resize(have + 65536);  // the file grew since fstat
    const ssize_t n = ::read(f.fd, &bytes[have], bytes.size() - have);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(path, std::string("read error: ") + std::strerror(errno));
    if (n == 0) break;
    have += size_t(n);
    if (have > max_bytes) throw too_large(have);
  }
  bytes.resize(have);
  return bytes;
}

}  // namespace vct
