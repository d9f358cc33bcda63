#include "io/nrrd.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

#include "core/error.h"
#include "core/image.h"
#include "io/atomic_file.h"
#include "io/image_io.h"

namespace vct {

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
  h << "endian: little\nencoding: raw\n\n";
  std::string bytes = h.str();
  const size_t header = bytes.size();
  bytes.resize(header + vol.data.size() * sizeof(float));
  std::memcpy(&bytes[header], vol.data.data(), vol.data.size() * sizeof(float));
  write_text_atomically(path, bytes);
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
  if (encoding != "raw") throw InputError(path, "unsupported NRRD encoding '" + encoding + "' (only raw)");
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
  if (bytes.size() - (end + 2) < need)
    throw InputError(path, "NRRD data is short: need " + std::to_string(need) + " bytes, have " +
                               std::to_string(bytes.size() - end - 2));
  Volume vol(int(sizes[off]), int(sizes[off + 1]), int(sizes[off + 2]), channels);
  const char* p = bytes.data() + end + 2;
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
