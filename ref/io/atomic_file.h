// Outputs are written to "<name>.tmp-<pid>" and renamed into place, so an interrupted run never
// leaves a half-written file under the final name (rename is atomic on POSIX file systems).
#pragma once

#include <functional>
#include <string>

namespace vct {

/// Calls write(tmp_path), then renames tmp_path to `path`. On any exception the temporary is
/// removed and the exception propagates; one that a full disk or a file-size limit caused (errno
/// ENOSPC, EDQUOT, EFBIG) becomes an EnvironmentError, a read-only place (EACCES, EPERM, EROFS)
/// an InputError, both naming `path` and the system's reason (issue 19).
void write_atomically(const std::string& path, const std::function<void(const std::string& tmp_path)>& write);

/// The one-line error for a failed write of `path` with errno `err`, as write_atomically throws it.
[[noreturn]] void throw_write_error(const std::string& path, int err);

/// Writes `size` bytes to the new file `tmp`, checking every write(2) and the close: on failure it
/// throws with errno kept, for write_atomically to report (a library that ignores a failed fwrite
/// must not produce the bytes it writes: issue 38's 0-byte PNG/EXR files after a full disk).
void write_bytes_checked(const std::string& tmp, const void* data, size_t size);

/// Writes `text` to `path` atomically.
void write_text_atomically(const std::string& path, const std::string& text);

/// The largest image or volume file vct reads: what it writes is at most a 512^3 RGBA float volume
/// (2 GiB) or a 16384^2 RGBA float image (4 GiB); 16 GiB leaves room and still bounds the read.
inline constexpr unsigned long long kMaxInputFileBytes = 16ull << 30;

/// Reads a whole file; throws InputError(path, ...) if it is missing, a directory, not a regular
/// file, larger than kMaxInputFileBytes or unreadable (io/bounded_file.h).
std::string read_file(const std::string& path);

}  // namespace vct
