#include "io/encoded_image_header.h"

#include <stb/stb_image.h>

#include <climits>
#include <cstring>

namespace vct {

namespace {

uint32_t be32(const unsigned char* p) { return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | p[3]; }
uint32_t be16(const unsigned char* p) { return uint32_t(p[0]) << 8 | p[1]; }

// Signature (8 bytes), then the IHDR chunk: length, "IHDR", width, height, bit depth, colour type.
std::optional<EncodedImageHeader> png_header(const unsigned char* b, size_t size) {
  static const unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size < 26 || std::memcmp(b, kSignature, 8) != 0 || std::memcmp(b + 12, "IHDR", 4) != 0) return std::nullopt;
  EncodedImageHeader h;
  h.format = "PNG";
  h.width = be32(b + 16);
  h.height = be32(b + 20);
  h.bits = b[24] == 16 ? 16 : 8;
  switch (b[25]) {  // colour type (PNG spec table 11.1)
    case 0: h.channels = 1; break;  // grey
    case 2: h.channels = 3; break;  // RGB
    case 3: h.channels = 4; break;  // palette: up to RGBA once expanded
    case 4: h.channels = 2; break;  // grey + alpha
    case 6: h.channels = 4; break;  // RGBA
    default: return std::nullopt;
  }
  return h;
}

// SOI, then marker segments (FF xx, 2-byte length including itself) up to the first start of
// frame: precision, height, width, component count. SOF markers are C0..CF except C4 (DHT),
// C8 (JPG) and CC (DAC).
std::optional<EncodedImageHeader> jpeg_header(const unsigned char* b, size_t size) {
  if (size < 4 || b[0] != 0xFF || b[1] != 0xD8) return std::nullopt;
  size_t at = 2;
  while (at + 4 <= size) {
    if (b[at] != 0xFF) return std::nullopt;
    const unsigned char marker = b[at + 1];
    if (marker == 0xFF) {  // fill byte
      ++at;
      continue;
    }
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7)) {  // no length field
      at += 2;
      continue;
    }
    const size_t length = be16(b + at + 2);
    if (length < 2) return std::nullopt;
    const bool sof = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (sof) {
      if (at + 10 > size) return std::nullopt;
      EncodedImageHeader h;
      h.format = "JPEG";
      h.height = be16(b + at + 5);
      h.width = be16(b + at + 7);
      h.channels = b[at + 9];
      return h;
    }
    if (marker == 0xDA || marker == 0xD9) return std::nullopt;  // scan data or end before a frame
    at += 2 + length;
  }
  return std::nullopt;
}

}  // namespace

std::optional<EncodedImageHeader> read_encoded_image_header(const unsigned char* bytes, size_t size) {
  if (auto h = png_header(bytes, size)) return h;
  if (auto h = jpeg_header(bytes, size)) return h;
  if (size > size_t(INT_MAX)) return std::nullopt;
  int w = 0, h = 0, c = 0;
  if (!stbi_info_from_memory(bytes, int(size), &w, &h, &c)) return std::nullopt;
  EncodedImageHeader out;
  out.format = "image";
  out.width = uint64_t(w);
  out.height = uint64_t(h);
  out.channels = c;
  out.bits = stbi_is_16_bit_from_memory(bytes, int(size)) ? 16 : 8;
  return out;
}

}  // namespace vct
