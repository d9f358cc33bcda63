// The one place an 8-bit PNG reaches the disk (atomically). The full tool writes it through
// OpenImageIO (io/image_io.cpp); the GL runner links its own, dependency-free version
// (gl/runner/runner_image_io.cpp) so it needs no OpenImageIO.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vct {

/// Writes w x h pixels of c interleaved 8-bit channels (row 0 = top) as PNG at `path`.
void write_bytes_png(const std::string& path, int w, int h, int c, const std::vector<uint8_t>& bytes);

}  // namespace vct
