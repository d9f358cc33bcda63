#include "io/exr_plain.h"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.h"

namespace vct {
namespace {

// Little-endian scalars, as every OpenEXR field is stored.
void put_u32(std::string& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(char((v >> (8 * i)) & 0xffu));
}
void put_u64(std::string& out, uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(char((v >> (8 * i)) & 0xffu));
}
void put_f32(std::string& out, float f) {
  uint32_t u = 0;
  std::memcpy(&u, &f, 4);
  put_u32(out, u);
}

// One header attribute: name, type name, size, value.
void attribute(std::string& out, const char* name, const char* type, const std::string& value) {
  out += name;
  out.push_back('\0');
  out += type;
  out.push_back('\0');
  put_u32(out, uint32_t(value.size()));
  out += value;
}

std::string box2i(int w, int h) {
  std::string v;
  for (uint32_t x : {0u, 0u, uint32_t(w - 1), uint32_t(h - 1)}) put_u32(v, x);
  return v;
}

// Channel names in the file's (alphabetical) order, and which image channel each holds.
std::vector<std::pair<std::string, int>> channels_in_file_order(int channels) {
  if (channels == 1) return {{"Y", 0}};
  std::vector<std::pair<std::string, int>> named = {{"A", 3}, {"B", 2}, {"G", 1}, {"R", 0}};
  std::vector<std::pair<std::string, int>> out;
  for (const auto& n : named)
    if (n.second < channels) out.push_back(n);
  return out;
}

}  // namespace

std::string exr_plain_bytes(const Image& img) {
  if (img.channels < 1 || img.channels > 4 || img.width < 1 || img.height < 1)
    throw std::invalid_argument("exr_plain_bytes: 1 to 4 channels and a non-empty image");
  const auto order = channels_in_file_order(img.channels);
  std::string out;
  put_u32(out, 20000630u);  // magic number
  put_u32(out, 2u);         // version 2, single-part scan-line file
  std::string chlist;
  for (const auto& c : order) {
    chlist += c.first;
    chlist.push_back('\0');
    put_u32(chlist, 2u);              // pixel type FLOAT
    chlist += std::string(4, '\0');   // pLinear + 3 reserved bytes
    put_u32(chlist, 1u);              // x sampling
    put_u32(chlist, 1u);              // y sampling
  }
  chlist.push_back('\0');
  attribute(out, "channels", "chlist", chlist);
  attribute(out, "compression", "compression", std::string(1, '\0'));  // NO_COMPRESSION
  attribute(out, "dataWindow", "box2i", box2i(img.width, img.height));
  attribute(out, "displayWindow", "box2i", box2i(img.width, img.height));
  attribute(out, "lineOrder", "lineOrder", std::string(1, '\0'));  // INCREASING_Y
  std::string one, centre;
  put_f32(one, 1.0f);
  put_f32(centre, 0.0f);
  put_f32(centre, 0.0f);
  attribute(out, "pixelAspectRatio", "float", one);
  attribute(out, "screenWindowCenter", "v2f", centre);
  attribute(out, "screenWindowWidth", "float", one);
  out.push_back('\0');  // end of header
  // Offset table (one scan line per block), then the blocks: y, byte count, channel by channel.
  const uint64_t line_bytes = uint64_t(img.width) * uint64_t(order.size()) * 4u;
  const uint64_t first = uint64_t(out.size()) + 8u * uint64_t(img.height);
  for (int y = 0; y < img.height; ++y) put_u64(out, first + uint64_t(y) * (8u + line_bytes));
  for (int y = 0; y < img.height; ++y) {
    put_u32(out, uint32_t(y));
    put_u32(out, uint32_t(line_bytes));
    for (const auto& c : order)
      for (int x = 0; x < img.width; ++x) put_f32(out, img.at(x, y, c.second));
  }
  return out;
}

void write_exr_plain(const std::string& path, const Image& img) {
  const std::string bytes = exr_plain_bytes(img);
  write_text_atomically(path, bytes);
}

}  // namespace vct
