// Issue 38 item 8: whole files or none. After a disk-full stop, validate left 23-69 PNG/EXR files
// of 0 bytes under their final names: OpenImageIO did not report every failed write. Images are
// now encoded in memory and written with checked write(2)s (io/atomic_file.h). Here a file-size
// limit (RLIMIT_FSIZE) makes every write past 4 KiB fail midway, as a full
// disk does: each writer must throw, and leave neither its final name nor a temporary behind.
#include <gtest/gtest.h>

#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <functional>

#include "core/error.h"
#include "core/image.h"
#include "core/volume.h"
#include "gltf_test_doc.h"
#include "io/image_io.h"
#include "io/nrrd.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

// Noise does not compress: every encoded file is far above the 4 KiB limit.
Image noise(int w, int h) {
  Image img(w, h, 4);
  uint32_t x = 12345;
  for (float& v : img.data) {
    x = x * 1664525u + 1013904223u;
    v = float(x >> 8) / float(1u << 24);
  }
  return img;
}

// Runs `write` under a 4 KiB soft file-size limit (this process, restored after; no fork: a
// child of a process whose other threads hold locks can deadlock). 0 when the write threw
// EnvironmentError ("cannot write: File too large"), 1 when it returned, 2 for another error.
int write_under_limit(const std::function<void()>& write) {
  rlimit old{};
  ::getrlimit(RLIMIT_FSIZE, &old);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);  // as vct's main: the write fails with EFBIG
  rlimit limit = old;
  limit.rlim_cur = 4096;
  ::setrlimit(RLIMIT_FSIZE, &limit);
  int result = 1;
  try {
    write();
  } catch (const EnvironmentError&) {
    result = 0;
  } catch (...) {
    result = 2;
  }
  ::setrlimit(RLIMIT_FSIZE, &old);
  std::signal(SIGXFSZ, old_handler);
  return result;
}

void expect_nothing_left(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir)) ADD_FAILURE() << "left behind: " << e.path();
}

TEST(WholeFileWrites, PngExrAndNrrdPastAFileSizeLimitLeaveNothing) {
  const fs::path dir = test::temp_dir() / "whole_files";
  fs::create_directories(dir);
  const Image img = noise(128, 128);
  EXPECT_EQ(write_under_limit([&] { write_png((dir / "preview.png").string(), img, 1.0f, ToneMap::Clamp); }), 0);
  EXPECT_EQ(write_under_limit([&] { write_exr((dir / "data.exr").string(), img); }), 0);
  Volume vol(16, 16, 16, 4);  // noise: gzip-encoded still far above the limit
  vol.data.assign(img.data.begin(), img.data.begin() + long(vol.data.size()));
  EXPECT_EQ(write_under_limit([&] { write_nrrd((dir / "volume.nrrd").string(), vol); }), 0);
  expect_nothing_left(dir);
}

TEST(WholeFileWrites, TheSameWritesWithoutALimitGiveReadableFiles) {
  const fs::path dir = test::temp_dir() / "whole_files_ok";
  fs::create_directories(dir);
  const Image img = noise(128, 128);
  write_exr((dir / "data.exr").string(), img);
  const Image back = read_image((dir / "data.exr").string());
  ASSERT_EQ(back.data.size(), img.data.size());
  EXPECT_EQ(back.data, img.data);  // float EXR: bit for bit
  write_png((dir / "preview.png").string(), img, 1.0f, ToneMap::Clamp);
  EXPECT_EQ(read_image((dir / "preview.png").string()).width, 128);
}

}  // namespace
}  // namespace vct
