#include "io/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <cstdio>
#include <filesystem>

#include "core/error.h"
#include "io/bounded_file.h"

namespace vct {

namespace fs = std::filesystem;

namespace {
// The errno values that mean "this place cannot take the file", as opposed to a bug.
bool is_write_error(int err) {
  return err == ENOSPC || err == EDQUOT || err == EFBIG || err == EIO || err == EACCES || err == EPERM ||
         err == EROFS;
}
}  // namespace

void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  const fs::path target(path);
  if (target.has_parent_path()) fs::create_directories(target.parent_path());
  // Keep the extension last: OpenImageIO picks the format from it.
  const std::string tmp = (target.parent_path() / (".tmp-" + std::to_string(::getpid()) + "-" +
                                                   target.filename().string()))
                              .string();
  try {
    errno = 0;  // so a failure below is judged by its own errno, not an old one
    write(tmp);
    fs::rename(tmp, target);
  } catch (const std::exception&) {
    const int err = errno;
    std::error_code ignored;
    fs::remove(tmp, ignored);
    if (is_write_error(err)) throw_write_error(path, err);
    throw;
  }
}

void throw_write_error(const std::string& path, int err) {
  const std::string why = std::strerror(err);
  if (err == EACCES || err == EPERM || err == EROFS) throw InputError(path, "cannot write: " + why);
  throw EnvironmentError(path + ": cannot write: " + why +
                         (err == EFBIG ? " (a file-size limit, ulimit -f?)" : err == EIO ? "" : " (disk full?)") +
                         "; nothing was left under this name");
}

void write_bytes_checked(const std::string& tmp, const void* data, size_t size) {
  const auto fail = [&](const char* what) {
    const int err = errno;
    std::runtime_error e(tmp + ": " + what + ": " + std::strerror(err));
    errno = err;  // write_atomically judges the failure by errno
    throw e;
  };
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("cannot create");
  const auto* p = static_cast<const char*>(data);
  for (size_t done = 0; done < size;) {
    const ssize_t n = ::write(fd, p + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      if (n == 0) errno = ENOSPC;  // no progress: the device took nothing
      const int err = errno;
      ::close(fd);
      errno = err;
      fail("cannot write");
    }
    done += size_t(n);
  }
  if (::close(fd) != 0) fail("cannot write");
}

void write_text_atomically(const std::string& path, const std::string& text) {
  write_atomically(path, [&](const std::string& tmp) { write_bytes_checked(tmp, text.data(), text.size()); });
}

std::string read_file(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path, "no such file");
  if (fs::is_directory(path, ec)) throw InputError(path, "is a directory, expected a file");
  // Regular files only (a FIFO would block, /dev/zero never end), bounded (issue 38).
  return read_regular_file(path, kMaxInputFileBytes, "stage file");
}

}  // namespace vct
