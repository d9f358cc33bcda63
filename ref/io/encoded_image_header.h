// The size an encoded image (PNG, JPEG, or another format stb_image knows) claims in its header,
// read without decoding anything, so a texture is judged against the memory budget before a
// decoder allocates from a header that may claim far more than the file holds (issue 19: a PNG
// claiming 100 000 x 100 000 pixels was refused only as "Unknown image format").
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace vct {

struct EncodedImageHeader {
  std::string format;   // "PNG", "JPEG", or "image" (another stb_image format)
  uint64_t width = 0;
  uint64_t height = 0;
  int channels = 0;     // channels stored in the file (a PNG palette counts as RGB(A))
  int bits = 8;         // per channel: 8, or 16 for 16-bit PNG
};

/// PNG: the IHDR chunk (PNG spec §11.2.2); JPEG: the first SOFn segment (ITU T.81 §B.2.2);
/// others: stb_image's header reader. Empty when no header can be read (the decoder then reports
/// why). PNG and JPEG are read by hand because stb_image's reader refuses the very headers worth
/// reporting (it fails as "too large" before telling the size).
std::optional<EncodedImageHeader> read_encoded_image_header(const unsigned char* bytes, size_t size);

}  // namespace vct
