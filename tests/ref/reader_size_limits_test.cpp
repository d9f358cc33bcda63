// The file readers judge a size field before allocating from it (io/image_limits.h): an image past
// the largest frame vct renders (16384 per side, 64 channels, 16384 x 16384 x 4 values), an
// OpenEXR header claiming such a size, and a NRRD whose header claims more bytes than the file
// holds are InputErrors; the files at the limits still read.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/error.h"
#include "core/image.h"
#include "core/volume.h"
#include "io/image_io.h"
#include "io/nrrd.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "vct_reader_size_limits";
  fs::create_directories(dir);
  return dir / name;
}

TEST(ReaderSizeLimits, ImageWiderThan16384IsRefusedAndTheLimitReads) {
  const std::string wide = scratch("wide.exr").string(), edge = scratch("edge.exr").string();
  write_exr(wide, Image(16385, 1, 1, 0.5f));
  write_exr(edge, Image(16384, 1, 1, 0.5f));
  EXPECT_THROW(read_image(wide), InputError);
  const Image back = read_image(edge);
  EXPECT_EQ(back.width, 16384);
  EXPECT_EQ(back.at(16383, 0, 0), 0.5f);
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// OpenEXR sizes its line buffers from the header's data window when the file is opened, so a
// header claiming a 16.7 M pixel wide window is refused before OpenImageIO opens it.
TEST(ReaderSizeLimits, ExrHeaderClaimingAHugeDataWindowIsRefusedBeforeOpening) {
  const std::string path = scratch("window.exr").string();
  write_exr(path, Image(16, 16, 1, 0.5f));
  std::string b = bytes_of(path);
  const size_t at = b.find(std::string("dataWindow\0box2i\0", 17));
  ASSERT_NE(at, std::string::npos);
  const int32_t x_max = 16777215;  // box2i: xMin, yMin, xMax, yMax after the int32 size
  std::memcpy(&b[at + 17 + 4 + 8], &x_max, 4);
  std::ofstream(path, std::ios::binary | std::ios::trunc) << b;
  try {
    read_image(path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("OpenEXR header: data window 16777216 x 16"), std::string::npos) << e.what();
  }
}

TEST(ReaderSizeLimits, MoreThanSixtyFourChannelsAreRefused) {
  const std::string path = scratch("channels.exr").string();
  write_exr(path, Image(2, 2, 65, 0.5f));
  EXPECT_THROW(read_image(path), InputError);
  write_exr(path, Image(2, 2, 64, 0.5f));
  EXPECT_EQ(read_image(path).channels, 64);
}

TEST(ReaderSizeLimits, NrrdHeaderClaimingMoreThanItsBytesIsRefused) {
  const std::string path = scratch("claims.nrrd").string();
  std::ofstream(path, std::ios::binary) << "NRRD0004\ntype: float\ndimension: 4\nsizes: 16 4096 4096 4096\n"
                                           "endian: little\nencoding: raw\n\n";
  try {
    read_nrrd(path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    // 16 x 4096^3 floats: the message gives the claim, nothing was allocated for it.
    EXPECT_NE(std::string(e.what()).find("need 4398046511104 bytes, have 0"), std::string::npos) << e.what();
  }
  const std::string ok = scratch("ok.nrrd").string();
  Volume v(2, 2, 2, 4, 0.25f);
  write_nrrd(ok, v);
  EXPECT_EQ(read_nrrd(ok).data, v.data);
}

}  // namespace
}  // namespace vct
