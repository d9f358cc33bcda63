#include "io/nrrd.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include <zlib.h>

#include "core/error.h"
#include "core/image.h"
#include "io/atomic_file.h"
#include "io/image_io.h"

namespace vct {

namespace {

// Deflate's largest ratio (RFC 1951: a 258-byte match in at least 2 bits): a gzip payload that
// decodes to more than this many bytes per compressed byte is not one any writer made.
constexpr size_t kMaxDeflateRatio = 1032;

// `size` bytes at `data` as one gzip member (RFC 1952). Z_RLE finds only runs (distance 1): a
// volume is mostly empty voxels, whose zero runs it codes as well as level 6 does, at the speed
// of level 1 (~0.35 s for a 256^3 RGBA float volume; docs/performance.md, "Validate at grid 256").
// zlib writes mtime 0 and a fixed OS byte: the same volume gives the same bytes.
std::string gzip_bytes(const void* data, size_t size, const std::string& path) {
  z_stream z{};
  if (deflateInit2(&z, 1, Z_DEFLATED, 15 + 16, 8, Z_RLE) != Z_OK) throw std::runtime_error(path + ": deflateInit2 failed");
  std::string out;
  const auto* in = static_cast<const unsigned char*>(data);
  constexpr size_t kChunk = size_t(1) << 20;
  size_t done = 0;
  int rc = Z_OK;
  do {
    const size_t take = std::min(kChunk, size - done);
    z.next_in = const_cast<unsigned char*>(in + done);
    z.avail_in = uInt(take);
    done += take;
    const int flush = done == size ? Z_FINISH : Z_NO_FLUSH;
    do {
      const size_t at = out.size();
      out.resize(at + kChunk / 4);
      z.next_out = reinterpret_cast<unsigned char*>(&out[at]);
      z.avail_out = uInt(kChunk / 4);
      rc = deflate(&z, flush);
      out.resize(at + kChunk / 4 - z.avail_out);
    } while (z.avail_out == 0);
  } while (done < size);
  deflateEnd(&z);
  if (rc != Z_STREAM_END) throw std::runtime_error(path + ": deflate did not finish");
  return out;
}

// The gzip payload `data` decoded into exactly `need` bytes; anything else is bad input.
std::string gunzip_exactly(const std::string& path, const char* data, size_t size, size_t need) {
  if (need / kMaxDeflateRatio > size + 64)
    throw InputError(path, "NRRD gzip data is short: " + std::to_string(size) + " bytes cannot decode to the " +
                               std::to_string(need) + " the sizes need");
  std::string out(need, '\0');
  z_stream z{};
  if (inflateInit2(&z, 15 + 16) != Z_OK) throw InputError(path, "NRRD gzip: inflateInit2 failed");
  // zlib counts in uInt: fed and drained in pieces of at most 1 GiB.
  constexpr size_t kPiece = size_t(1) << 30;
  const auto* in = reinterpret_cast<const unsigned char*>(data);
  size_t in_fed = 0, out_given = 0;
  int rc = Z_OK;
  while (rc == Z_OK) {
    if (z.avail_in == 0 && in_fed < size) {
      z.next_in = const_cast<unsigned char*>(in + in_fed);
      z.avail_in = uInt(std::min(kPiece, size - in_fed));
      in_fed += z.avail_in;
    }
    if (z.avail_out == 0 && out_given < need) {
      z.next_out = reinterpret_cast<unsigned char*>(out.data() + out_given);
      z.avail_out = uInt(std::min(kPiece, need - out_given));
      out_given += z.avail_out;
    }
    rc = inflate(&z, Z_NO_FLUSH);  // Z_BUF_ERROR once no progress is possible (input or room used up)
  }
  const size_t out_done = out_given - z.avail_out;
  inflateEnd(&z);
  if (rc != Z_STREAM_END)
    throw InputError(path, "NRRD gzip data is corrupt or longer than the sizes (" + std::to_string(need) + " bytes)");
  if (out_done != need)
    throw InputError(path, "NRRD data is short: need " + std::to_string(need) + " bytes, gzip decodes to " +
                               std::to_string(out_done));
  return out;
}

}  // namespace

void write_nrrd(const std::string& path, const Volume& vol, float spacing) {
  std::ostringstream h;
  const bool multi = vol.channels > 1;
  h << "NRRD0004\n# written by vct (VCT Oracle)\n";
  h << "type: float\n";
  h << "dimension: " << (multi ? 4 : 3) << "\n";
  h << "sizes: ";
  if (multi) h << vol.channels << " ";
  h << vol.nx << " " << vol.ny << " " << vol.nz << "\n";
  h << "kinds: " << (multi ? (vol.channels == 4 ? "RGBA-color " : "vector ") : "") << "domain domain domain\n";
  h << "space dimension: 3\n";
  h << "space directions: " << (multi ? "none " : "") << "(" << spacing << ",0,0) (0," << spacing << ",0) (0,0,"
    << spacing << ")\n";
  // gzip is one of NRRD 0004's standard encodings (teem's nrrd format): what every NRRD reader
  // decodes. A raw 256^3 radiance volume is 268 MB, gzip-encoded ~2 MB.
  h << "endian: little\nencoding: gzip\n\n";
  write_text_atomically(path, h.str() + gzip_bytes(vol.data.data(), vol.data.size() * sizeof(float), path));
}

namespace {

size_t element_size(const std::string& type) {
  if (type == "float") return 4;
  if (type == "uint8" || type == "uchar" || type == "unsigned char") return 1;
  if (type == "uint16" || type == "ushort" || type == "unsigned short") return 2;
  if (type == "int32" || type == "int" || type == "signed int") return 4;
  return 0;
}

float element_value(const std::string& type, const char* p) {
  if (type == "float") {
    float f;
    std::memcpy(&f, p, 4);
    return f;
  }
  if (element_size(type) == 1) return float(uint8_t(*p)) / 255.0f;
  if (element_size(type) == 2) {
    uint16_t u;
    std::memcpy(&u, p, 2);
    return float(u) / 65535.0f;
  }
  int32_t i;
  std::memcpy(&i, p, 4);
  return float(i);
}

}  // namespace

Volume read_nrrd(const std::string& path) {
  const std::string bytes = read_file(path);
  if (bytes.rfind("NRRD000", 0) != 0) throw InputError(path, "not a NRRD file (missing NRRD000x magic)");
  const size_t end = bytes.find("\n\n");
  if (end == std::string::npos) throw InputError(path, "NRRD header is not terminated by a blank line");
  std::istringstream header(bytes.substr(0, end));
  std::string line, type, encoding = "raw", endian = "little";
  std::vector<long long> sizes;
  int dimension = 0;
  while (std::getline(header, line)) {
    if (line.empty() || line[0] == '#') continue;
    const size_t colon = line.find(": ");
    if (colon == std::string::npos) continue;
    const std::string key = line.substr(0, colon), value = line.substr(colon + 2);
    std::istringstream vs(value);
    if (key == "type") type = value;
    else if (key == "dimension") vs >> dimension;
    else if (key == "encoding") encoding = value;
    else if (key == "endian") endian = value;
    else if (key == "sizes") {
      long long s;
      while (vs >> s) sizes.push_back(s);
    }
  }
  if (element_size(type) == 0) throw InputError(path, "unsupported NRRD type '" + type + "'");
  const bool gzip = encoding == "gzip" || encoding == "gz";
  if (encoding != "raw" && !gzip)
    throw InputError(path, "unsupported NRRD encoding '" + encoding + "' (raw or gzip)");
  if (endian != "little" && element_size(type) > 1) throw InputError(path, "big-endian NRRD not supported");
  if ((dimension != 3 && dimension != 4) || int(sizes.size()) != dimension)
    throw InputError(path, "NRRD must have dimension 3 or 4 with matching sizes");
  for (long long s : sizes)
    if (s <= 0 || s > 4096) throw InputError(path, "NRRD size out of range");
  const int channels = dimension == 4 ? int(sizes[0]) : 1;
  const int off = dimension == 4 ? 1 : 0;
  if (channels > 16) throw InputError(path, "NRRD has too many channels");
  // Sizes are checked against the bytes present before allocating: a header alone may claim
  // 16 x 4096^3 values.
  size_t need = element_size(type);
  for (long long s : sizes) need *= size_t(s);
  const char* data = bytes.data() + end + 2;
  const size_t have = bytes.size() - (end + 2);
  if (!gzip && have < need)
    throw InputError(path, "NRRD data is short: need " + std::to_string(need) + " bytes, have " + std::to_string(have));
  const std::string decoded = gzip ? gunzip_exactly(path, data, have, need) : std::string();
  Volume vol(int(sizes[off]), int(sizes[off + 1]), int(sizes[off + 2]), channels);
  const char* p = gzip ? decoded.data() : data;
  for (size_t i = 0; i < vol.data.size(); ++i) vol.data[i] = element_value(type, p + i * element_size(type));
  return vol;
}

void write_volume_montage(const std::string& path, const Volume& vol, int max_slices, float exposure) {
  const int step = std::max(1, (vol.nz + max_slices - 1) / max_slices);
  const int slices = (vol.nz + step - 1) / step;
  const int cols = int(std::ceil(std::sqrt(double(slices))));
  const int rows = (slices + cols - 1) / cols;
  const int gap = 1;
  const bool rgb = vol.channels >= 3;
  Image img((vol.nx + gap) * cols, (vol.ny + gap) * rows, rgb ? 3 : 1, 0.0f);
  for (int s = 0; s < slices; ++s) {
    const int z = s * step, ox = (s % cols) * (vol.nx + gap), oy = (s / cols) * (vol.ny + gap);
    for (int y = 0; y < vol.ny; ++y)
      for (int x = 0; x < vol.nx; ++x)
        for (int c = 0; c < img.channels; ++c)
          // Flip y so +y points up in the picture, as in a viewer.
          img.at(ox + x, oy + (vol.ny - 1 - y), c) = vol.voxel(x, y, z)[c];
  }
  if (rgb) write_png(path, img, exposure);
  else write_png_linear(path, img, 0.0f, 1.0f);
}

}  // namespace vct
