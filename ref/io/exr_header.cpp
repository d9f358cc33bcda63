#include "io/exr_header.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>

#include "core/error.h"
#include "io/image_limits.h"

namespace vct {

namespace {

// OpenEXR file layout: magic, version + flags, then headers of attributes "name\0type\0" int32
// size, value; a header ends with an empty name, a multi-part file's list of headers with an
// empty header. Integers are little endian.
constexpr unsigned char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr uint32_t kMultiPartFlag = 0x1000;

class Cursor {
 public:
  explicit Cursor(const std::string& b) : b_(b) {}
  bool at_end() const { return p_ >= b_.size(); }
  std::optional<std::string> name() {  // attribute and type names: at most 255 characters
    const size_t end = b_.find('\0', p_);
    if (end == std::string::npos || end - p_ > 255) return std::nullopt;
    std::string s = b_.substr(p_, end - p_);
    p_ = end + 1;
    return s;
  }
  std::optional<int64_t> i32() {
    if (b_.size() - p_ < 4) return std::nullopt;
    uint32_t v = 0;
    std::memcpy(&v, b_.data() + p_, 4);  // little-endian hosts only, as the rest of io/
    p_ += 4;
    return int64_t(int32_t(v));
  }
  std::optional<std::string> bytes(int64_t n) {
    if (n < 0 || uint64_t(n) > b_.size() - p_) return std::nullopt;
    std::string s = b_.substr(p_, size_t(n));
    p_ += size_t(n);
    return s;
  }

 private:
  const std::string& b_;
  size_t p_ = 0;
};

int64_t le32(const std::string& v, size_t at) {
  uint32_t x = 0;
  std::memcpy(&x, v.data() + at, 4);
  return int64_t(int32_t(x));
}

// chlist: per channel "name\0", pixel type, pLinear + 3 reserved bytes, x and y sampling; "\0" ends.
int64_t channel_count(const std::string& v) {
  int64_t n = 0;
  for (size_t p = 0; p < v.size() && v[p] != '\0'; ++n) {
    const size_t end = v.find('\0', p);
    if (end == std::string::npos) break;
    p = end + 1 + 16;
  }
  return n;
}

void refuse(const std::string& path, const std::string& what) {
  throw InputError(path, "OpenEXR header: " + what + " (vct reads images up to 16384 per side, 16384 x 16384 x 4 "
                                                     "values, 64 channels, tiles up to 4096 per side)");
}

void check_attribute(const std::string& path, const std::string& name, const std::string& type, const std::string& v,
                     int64_t& channels, int64_t& width, int64_t& height) {
  if (type == "box2i" && name == "dataWindow" && v.size() >= 16) {
    width = le32(v, 8) - le32(v, 0) + 1;  // int64: a [-2^31, 2^31) window does not overflow
    height = le32(v, 12) - le32(v, 4) + 1;
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide)
      refuse(path, "data window " + std::to_string(width) + " x " + std::to_string(height));
  } else if (type == "tiledesc" && v.size() >= 8) {
    const int64_t tx = int64_t(uint32_t(le32(v, 0))), ty = int64_t(uint32_t(le32(v, 4)));
    if (tx < 1 || ty < 1 || tx > kMaxExrTileSide || ty > kMaxExrTileSide)
      refuse(path, "tile size " + std::to_string(tx) + " x " + std::to_string(ty));
  } else if (type == "chlist") {
    channels = channel_count(v);
    if (channels > kMaxImageChannels) refuse(path, std::to_string(channels) + " channels");
  }
}

// One header; false at the empty header that ends a multi-part list, or where the bytes stop
// making sense.
bool check_header(const std::string& path, Cursor& c) {
  int64_t channels = 0, width = 0, height = 0;
  for (;;) {
    const auto name = c.name();
    if (!name) return false;
    if (name->empty()) break;
    const auto type = c.name();
    const auto size = type ? c.i32() : std::nullopt;
    const auto value = size ? c.bytes(*size) : std::nullopt;
    if (!value) return false;
    check_attribute(path, *name, *type, *value, channels, width, height);
  }
  if (width * height * std::max<int64_t>(channels, 1) > kMaxImageValues)
    refuse(path, std::to_string(width) + " x " + std::to_string(height) + " x " + std::to_string(channels) + " values");
  return width > 0;  // an empty header (no attributes) ends the list
}

}  // namespace

void check_exr_header_sizes(const std::string& path, const std::string& bytes) {
  if (bytes.size() < 8 || std::memcmp(bytes.data(), kMagic, 4) != 0) return;
  const uint32_t flags = uint32_t(le32(bytes, 4));
  Cursor c(bytes);
  c.bytes(8);
  if (!(flags & kMultiPartFlag)) {
    check_header(path, c);
    return;
  }
  while (!c.at_end() && check_header(path, c)) {
  }
}

}  // namespace vct
