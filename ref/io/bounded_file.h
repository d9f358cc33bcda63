// Reading a whole input file with a bound (issue 38): only regular files are read, so a FIFO
// cannot block the tool and /dev/zero cannot fill memory, and a file larger than the caller's cap
// is refused before its bytes are read. Scenes, the files their URIs name and every JSON input
// (bounded_json.h) come through here.
#pragma once

#include <cstdint>
#include <string>

namespace vct {

/// Throws InputError(path, ...) when `path` is missing, unreadable, a directory, not a regular
/// file (FIFO, device, socket) or larger than `max_bytes`. `kind` names the file in messages
/// ("glTF file", "settings file").
std::string read_regular_file(const std::string& path, uint64_t max_bytes, const std::string& kind);

}  // namespace vct
