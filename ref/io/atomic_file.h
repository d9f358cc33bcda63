// Outputs are written to "<name>.tmp-<pid>" and renamed into place, so an interrupted run never
// leaves a half-written file under the final name (rename is atomic on POSIX file systems).
#pragma once

#include <functional>
#include <string>

namespace vct {

/// Calls write(tmp_path), then renames tmp_path to `path`. On any exception the temporary is
/// removed and the exception propagates.
void write_atomically(const std::string& path, const std::function<void(const std::string& tmp_path)>& write);

/// Writes `text` to `path` atomically.
void write_text_atomically(const std::string& path, const std::string& text);

/// Reads a whole file; throws InputError(path, ...) if it is missing, a directory or unreadable.
std::string read_file(const std::string& path);

}  // namespace vct
