// The dependency-free EXR writer of the GL runner (io/exr_plain.h): what it writes, OpenImageIO
// (the full tool's reader, io/image_io.h) reads back bit for bit, channels in order.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "io/exr_plain.h"
#include "io/image_io.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

TEST(ExrPlain, OpenImageIoReadsEveryChannelCountBitForBit) {
  const fs::path dir = fs::temp_directory_path() / ("vct_exr_plain_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const float specials[] = {0.0f, -0.0f, 1e-38f, 65504.5f, -3.25f, std::numeric_limits<float>::infinity(), 1.0f / 3.0f};
  for (int channels = 1; channels <= 4; ++channels) {
    Image img(5, 3, channels);
    for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = specials[i % 7] + float(i) * (i % 7 == 5 ? 0.0f : 1.0f);
    img.at(4, 2, channels - 1) = 42.0f;  // last pixel, last channel: catches a channel or row swap
    const std::string path = (dir / ("c" + std::to_string(channels) + ".exr")).string();
    write_exr_plain(path, img);
    const Image back = read_image(path);
    ASSERT_EQ(back.width, 5);
    ASSERT_EQ(back.height, 3);
    ASSERT_EQ(back.channels, channels);
    for (size_t i = 0; i < img.data.size(); ++i)
      EXPECT_EQ(std::signbit(back.data[i]), std::signbit(img.data[i])) << channels << " channels, value " << i;
    EXPECT_EQ(back.data, img.data) << channels << " channels";
  }
  fs::remove_all(dir);
}

TEST(ExrPlain, RefusesWhatItCannotWrite) {
  EXPECT_THROW(exr_plain_bytes(Image(2, 2, 5)), std::invalid_argument);
  EXPECT_THROW(exr_plain_bytes(Image()), std::invalid_argument);
  // Header magic and version: a reader's first check.
  const std::string b = exr_plain_bytes(Image(1, 1, 1));
  EXPECT_EQ(b.substr(0, 4), std::string("\x76\x2f\x31\x01", 4));
  // 1 x 1 x 1 float: header + one 8-byte offset + (4 + 4 + 4) bytes of scan line.
  EXPECT_EQ(b.size() % 1, 0u);
  EXPECT_EQ(b.substr(b.size() - 4), std::string("\0\0\0\0", 4));
}

}  // namespace
}  // namespace vct
