// A 2D float image, row-major, row 0 = top of the picture (as written to files).
// GL framebuffers have row 0 at the bottom; stages that mirror GL say so where they flip.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "core/math.h"

namespace vct {

struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<float> data;
  /// Channel names, e.g. {"R","G","B"} or {"Z"}; used as EXR channel names.
  std::vector<std::string> channel_names;

  Image() = default;
  Image(int w, int h, int c, float fill = 0.0f)
      : width(w), height(h), channels(c), data(size_t(w) * size_t(h) * size_t(c), fill) {}

  size_t index(int x, int y) const { return (size_t(y) * size_t(width) + size_t(x)) * size_t(channels); }
  float& at(int x, int y, int c) { return data[index(x, y) + size_t(c)]; }
  float at(int x, int y, int c) const { return data[index(x, y) + size_t(c)]; }
  float* pixel(int x, int y) { return &data[index(x, y)]; }
  const float* pixel(int x, int y) const { return &data[index(x, y)]; }
  bool empty() const { return data.empty(); }

  vec3 rgb(int x, int y) const {
    const float* p = pixel(x, y);
    return channels >= 3 ? vec3(p[0], p[1], p[2]) : vec3(p[0]);
  }
  void set_rgb(int x, int y, const vec3& v) {
    float* p = pixel(x, y);
    for (int c = 0; c < 3 && c < channels; ++c) p[c] = v[c];
  }
};

}  // namespace vct
