// The GL runner's image I/O: the io/image_io.h and io/png_bytes.h functions the stage-set writer
// calls, without OpenImageIO (a GPU test machine may lack it, docs/gl_backend.md "GL runner").
// Data images are uncompressed float EXR (io/exr_plain.h), previews PNG through stb_image_write
// (Debian's libstb). Linked before vct_ref, these definitions keep io/image_io.cpp (and with it
// OpenImageIO) out of the runner.
#include <stb_image_write.h>

#include <stdexcept>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/exr_plain.h"
#include "io/image_io.h"
#include "io/png_bytes.h"

namespace vct {

void write_exr(const std::string& path, const Image& img) { write_exr_plain(path, img); }

void write_bytes_png(const std::string& path, int w, int h, int c, const std::vector<uint8_t>& bytes) {
  write_atomically(path, [&](const std::string& tmp) {
    if (!stbi_write_png(tmp.c_str(), w, h, c, bytes.data(), w * c)) throw std::runtime_error(path + ": cannot write PNG");
  });
}

Image read_image(const std::string& path) {
  throw EnvironmentError(path + ": the GL runner reads no images (judge its stage sets with the full vct)");
}

}  // namespace vct
