// A dependency-free OpenEXR writer: one part, scan lines, no compression, 32-bit float channels
// (the OpenEXR file layout: openexr.com "OpenEXR File Layout"). The GL runner writes its stage
// images with it (no OpenImageIO there); any EXR reader, ours included (io/image_io.h), reads them.
// Channels are named R, G, B, A (Y for one channel), which readers return in that order.
#pragma once

#include <string>

#include "core/image.h"

namespace vct {

/// The whole file's bytes for `img` (row 0 = top, as the file stores it). At most 4 channels.
std::string exr_plain_bytes(const Image& img);

/// Writes exr_plain_bytes(img) to `path` atomically (io/atomic_file.h).
void write_exr_plain(const std::string& path, const Image& img);

}  // namespace vct
