#include "scene/gltf_image_budget.h"

#include <climits>

#include "core/memory_budget.h"
#include "io/encoded_image_header.h"

namespace vct::gltf {

namespace {

constexpr uint64_t kDecodedChannels = 4;  // tinygltf asks stb_image for RGBA

uint64_t decoded_bytes(uint64_t width, uint64_t height, int bits) {
  return width * height * kDecodedChannels * (bits == 16 ? 2u : 1u);
}

std::string describe(const tinygltf::Image& image, int index, const EncodedImageHeader& h) {
  return "image " + std::to_string(index) + (image.uri.empty() ? "" : " '" + image.uri.substr(0, 200) + "'") + ": its " +
         h.format + " header says " + std::to_string(h.width) + " x " + std::to_string(h.height) + " pixels, " +
         std::to_string(h.channels) + " channel(s) of " + std::to_string(h.bits) + " bits";
}

/// The RGBA8 levels 1..q a mip chain adds (scene/texture_mips.h): below 1/3 of level 0 for a
/// square image, up to 1x for a one-texel-high strip. One chain per image; a texture that
/// materials read both as sRGB and as linear keeps a second one, not counted here.
uint64_t mip_chain_bytes(uint64_t width, uint64_t height) {
  uint64_t bytes = 0;
  while (width > 1 || height > 1) {
    width = width > 1 ? width / 2 : 1;
    height = height > 1 ? height / 2 : 1;
    bytes += width * height * 4;
  }
  return bytes;
}

}  // namespace

uint64_t image_decode_bytes(uint64_t width, uint64_t height, int bits) {
  return 2 * decoded_bytes(width, height, bits) + width * height * 4 +
         mip_chain_bytes(width, height);
}

uint64_t image_kept_bytes(uint64_t width, uint64_t height, int bits) {
  return decoded_bytes(width, height, bits) + width * height * 4 + mip_chain_bytes(width, height);
}

bool load_image_within_budget(tinygltf::Image* image, int index, std::string* err, std::string* warn, int req_width,
                              int req_height, const unsigned char* bytes, int size, void* user) {
  auto& budget = *static_cast<ImageBudget*>(user);
  const auto header = read_encoded_image_header(bytes, size > 0 ? size_t(size) : 0);
  if (header) {
    // Each factor is below 2^32, so the products below fit in 64 bits.
    const EncodedImageHeader& h = *header;
    if (h.width == 0 || h.height == 0) {
      budget.refusal = describe(*image, index, h) + ": an image needs at least one pixel";
      return false;
    }
    const uint64_t need = image_decode_bytes(h.width, h.height, h.bits);
    const uint64_t left = budget.available > budget.kept ? budget.available - budget.kept : 0;
    if (budget.available > 0 && need > left) {
      budget.refusal = describe(*image, index, h) + ": decoding it needs " + format_bytes(need) + ", but only " +
                       format_bytes(left) + " of the " + format_bytes(budget.available) +
                       " memory budget is left; refused before decoding (docs/scenes.md, \"Limits\")";
      return false;
    }
    if (decoded_bytes(h.width, h.height, h.bits) > uint64_t(INT_MAX)) {
      budget.refusal = describe(*image, index, h) + ": its decoded " + format_bytes(decoded_bytes(h.width, h.height, h.bits)) +
                       " are more than the 2 GiB per image the decoder (stb_image) handles; refused before decoding";
      return false;
    }
    // A 60-byte PNG claiming 16384 x 16384 decoded as a 3.5 GB black texture (issue 38). Deflate
    // expands at most 1032:1 (RFC 1951: a 258-byte match per ~2 bits), and a JPEG block of 64
    // pixels needs at least a few bits, so neither format can hold more than 1032 bytes per byte.
    const uint64_t claimed = h.width * h.height * uint64_t(h.channels) * uint64_t(h.bits) / 8;
    if ((h.format == "PNG" || h.format == "JPEG") && claimed / 1032 > uint64_t(size > 0 ? size : 0)) {
      budget.refusal = describe(*image, index, h) + ", but its " + std::to_string(size) +
                       " bytes cannot hold that many (at most 1032 decoded bytes per encoded byte): a truncated or forged header";
      return false;
    }
    budget.kept += image_kept_bytes(h.width, h.height, h.bits);
  }
  return tinygltf::LoadImageData(image, index, err, warn, req_width, req_height, bytes, size, nullptr);
}

}  // namespace vct::gltf
