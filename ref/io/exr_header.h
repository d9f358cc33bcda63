// A look at an OpenEXR file's header before OpenImageIO opens it. OpenEXR allocates its line or
// tile buffers from the header's data window, tile size and channel list while the file is
// opened, before read_image can see the size (a 16.7 M x 1 pixel EXR made the open allocate about
// 1 GB and the read ask for 17 GB: fuzz/regressions/scene_compare/), so those fields are judged
// here against io/image_limits.h.
#pragma once

#include <string>

namespace vct {

/// Throws InputError when `bytes` (the whole file at `path`) is an OpenEXR file whose header
/// (every part of a multi-part file) states a data window beyond kMaxImageSide per side or
/// kMaxImageValues, more than kMaxImageChannels channels, or a tile side beyond kMaxExrTileSide.
/// Other files, and headers too broken to walk (OpenEXR refuses those itself), pass.
void check_exr_header_sizes(const std::string& path, const std::string& bytes);

}  // namespace vct
