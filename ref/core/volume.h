// A dense 3D float volume, x fastest then y then z (the layout of a GL 3D texture and of NRRD).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/math.h"

namespace vct {

struct Volume {
  int nx = 0, ny = 0, nz = 0;
  int channels = 0;
  std::vector<float> data;
  std::vector<std::string> channel_names;

  Volume() = default;
  Volume(int x, int y, int z, int c, float fill = 0.0f)
      : nx(x), ny(y), nz(z), channels(c), data(size_t(x) * size_t(y) * size_t(z) * size_t(c), fill) {}

  size_t voxel_count() const { return size_t(nx) * size_t(ny) * size_t(nz); }
  size_t index(int x, int y, int z) const {
    return ((size_t(z) * size_t(ny) + size_t(y)) * size_t(nx) + size_t(x)) * size_t(channels);
  }
  bool contains(int x, int y, int z) const {
    return x >= 0 && y >= 0 && z >= 0 && x < nx && y < ny && z < nz;
  }
  float* voxel(int x, int y, int z) { return &data[index(x, y, z)]; }
  const float* voxel(int x, int y, int z) const { return &data[index(x, y, z)]; }
  vec4 rgba(int x, int y, int z) const {
    const float* p = voxel(x, y, z);
    vec4 v(0.0f);
    for (int c = 0; c < channels && c < 4; ++c) v[c] = p[c];
    return v;
  }
  void set_rgba(int x, int y, int z, const vec4& v) {
    float* p = voxel(x, y, z);
    for (int c = 0; c < channels && c < 4; ++c) p[c] = v[c];
  }
  size_t bytes() const { return data.size() * sizeof(float); }
};

}  // namespace vct
