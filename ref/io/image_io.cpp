#include "io/image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/exr_header.h"
#include "io/image_limits.h"
#include "io/png_bytes.h"

namespace vct {

namespace {

// Encoded in memory, then written by write_bytes_checked: OpenImageIO's PNG and EXR writers did
// not report every failed write on a full disk, and 0-byte or truncated files were renamed into
// place (issue 38). Whole files or none: the bytes reach the disk only through checked writes.
void write_with_oiio(const std::string& tmp, const OIIO::ImageSpec& spec, const void* pixels,
                     const std::string& final_path) {
  auto out = OIIO::ImageOutput::create(tmp);
  if (!out) throw std::runtime_error(final_path + ": no image writer: " + OIIO::geterror());
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput memory(encoded);
  if (!out->supports("ioproxy") || !out->set_ioproxy(&memory))
    throw std::runtime_error(final_path + ": the image writer cannot encode to memory");
  if (!out->open(tmp, spec) || !out->write_image(spec.format, pixels) || !out->close())
    throw std::runtime_error(final_path + ": cannot encode image: " + out->geterror());
  write_bytes_checked(tmp, encoded.data(), encoded.size());
}

}  // namespace

void write_bytes_png(const std::string& path, int w, int h, int c, const std::vector<uint8_t>& bytes) {
  write_atomically(path, [&](const std::string& tmp) {
    OIIO::ImageSpec spec(w, h, c, OIIO::TypeDesc::UINT8);
    // Previews are for looking: zlib level 1 and the "sub" row filter encode 3-5x faster than the
    // defaults (level 6, every filter tried per row) for files ~1.3x larger (docs/performance.md,
    // "Where validate's time goes").
    spec.attribute("png:compressionLevel", 1);
    spec.attribute("png:filter", 0x10);  // PNG_FILTER_SUB
    write_with_oiio(tmp, spec, bytes.data(), path);
  });
}

void write_exr(const std::string& path, const Image& img) {
  write_atomically(path, [&](const std::string& tmp) {
    OIIO::ImageSpec spec(img.width, img.height, img.channels, OIIO::TypeDesc::FLOAT);
    if (int(img.channel_names.size()) == img.channels) spec.channelnames = img.channel_names;
    // zlib level 1: the float data's mantissas hardly compress at any level, and level 1 costs
    // ~15% less time than the default (docs/performance.md, "Where validate's time goes").
    spec.attribute("compression", "zip:1");
    // OIIO stamps the current time otherwise; fixed so equal images are equal files (the run's
    // date is in run.json), which the byte-level determinism tests rely on.
    spec.attribute("DateTime", "");
    write_with_oiio(tmp, spec, img.data.data(), path);
  });
}

namespace {
// A header may claim far more than its compressed bytes hold, and OpenImageIO allocates from it
// when reading (a 16.7 M x 1 EXR made it ask for 17 GB: fuzz/regressions/scene_compare/), so the
// size is judged first (io/image_limits.h).
void check_image_size(const std::string& path, const OIIO::ImageSpec& spec) {
  const long long w = spec.width, h = spec.height, c = spec.nchannels;
  if (w < 1 || h < 1 || c < 1 || w > kMaxImageSide || h > kMaxImageSide || c > kMaxImageChannels ||
      w * h * c > kMaxImageValues)
    throw InputError(path, std::to_string(w) + " x " + std::to_string(h) + " x " + std::to_string(c) +
                               " channel(s): vct reads images up to 16384 per side, 64 channels and 16384 x "
                               "16384 x 4 values");
}
}  // namespace

Image read_image(const std::string& path) {
  // read_file: uniform "missing / directory" errors; then what OpenEXR would allocate at open.
  check_exr_header_sizes(path, read_file(path));
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw InputError(path, "not a readable image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  check_image_size(path, spec);
  Image img(spec.width, spec.height, spec.nchannels);
  img.channel_names = spec.channelnames;
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, img.data.data()))
    throw InputError(path, "cannot decode image: " + in->geterror());
  return img;
}

}  // namespace vct
