#include "gl_resources.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "gl_context.h"

namespace vct::gl {

GLuint make_texture_2d(GLenum internal_format, int w, int h) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, 1, internal_format, w, h);
  glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return t;
}

GLuint make_texture_2d_array(GLenum internal_format, int w, int h, int layers) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &t);
  glTextureStorage3D(t, 1, internal_format, w, h, std::max(layers, 1));
  glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return t;
}

int mip_count(int n) {
  int levels = 1;
  while (n > 1) {
    n /= 2;
    ++levels;
  }
  return levels;
}

GLuint make_texture_3d(GLenum internal_format, int n, int levels) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_3D, 1, &t);
  glTextureStorage3D(t, levels, internal_format, n, n, n);
  const bool integer = internal_format == GL_R32UI;
  glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, integer ? GL_NEAREST : GL_LINEAR_MIPMAP_LINEAR);
  glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, integer ? GL_NEAREST : GL_LINEAR);
  for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
    glTextureParameteri(t, wrap, GL_CLAMP_TO_BORDER);
  const float border[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  glTextureParameterfv(t, GL_TEXTURE_BORDER_COLOR, border);
  return t;
}

namespace {
GLenum format_of(int channels) {
  switch (channels) {
    case 1: return GL_RED;
    case 2: return GL_RG;
    case 3: return GL_RGB;
    default: return GL_RGBA;
  }
}

Image flip_rows(Image img) {
  const size_t row = size_t(img.width) * size_t(img.channels);
  for (int y = 0; y < img.height / 2; ++y)
    std::swap_ranges(img.data.begin() + long(size_t(y) * row), img.data.begin() + long(size_t(y + 1) * row),
                     img.data.begin() + long(size_t(img.height - 1 - y) * row));
  return img;
}

Image read_any(GLuint tex, int w, int h, int channels, GLenum format, int layer) {
  Image img(w, h, channels);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  const GLsizei bytes = GLsizei(img.data.size() * sizeof(float));
  if (layer < 0) {
    glGetTextureImage(tex, 0, format, GL_FLOAT, bytes, img.data.data());
  } else {
    glGetTextureSubImage(tex, 0, 0, 0, layer, w, h, 1, format, GL_FLOAT, bytes, img.data.data());
  }
  check_gl("texture readback");
  return flip_rows(std::move(img));
}
}  // namespace

Image read_image(GLuint tex, int w, int h, int channels, int layer) {
  return read_any(tex, w, h, channels, format_of(channels), layer);
}

Image read_depth(GLuint tex, int w, int h, int layer) {
  Image img = read_any(tex, w, h, 1, GL_DEPTH_COMPONENT, layer);
  img.channel_names = {"Z"};
  return img;
}

Volume read_volume(GLuint tex, int level, int n, int channels) {
  Volume v(n, n, n, channels);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(tex, level, format_of(channels), GL_FLOAT, GLsizei(v.data.size() * sizeof(float)), v.data.data());
  check_gl("volume readback");
  if (channels == 4) v.channel_names = {"R", "G", "B", "A"};
  return v;
}

Volume read_volume_unorm8(GLuint tex, int level, int n) {
  std::vector<uint8_t> raw(size_t(n) * size_t(n) * size_t(n) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(tex, level, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(raw.size()), raw.data());
  check_gl("volume readback (unorm8)");
  Volume v(n, n, n, 4);
  for (size_t i = 0; i < raw.size(); ++i) v.data[i] = float(raw[i]) / 255.0f;
  v.channel_names = {"R", "G", "B", "A"};
  return v;
}

Volume read_volume_uint(GLuint tex, int n) {
  std::vector<uint32_t> raw(size_t(n) * size_t(n) * size_t(n));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(tex, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(raw.size() * 4), raw.data());
  check_gl("volume readback (uint)");
  Volume v(n, n, n, 1);
  for (size_t i = 0; i < raw.size(); ++i) v.data[i] = float(raw[i]);
  return v;
}

}  // namespace vct::gl
