// Textures and readback: creation with immutable storage, and reading levels back into the
// reference's Image (row 0 = top: GL's bottom-up rows are flipped) and Volume (x fastest, as GL).
#pragma once

#include "core/image.h"
#include "core/volume.h"
#include "gl_api.h"

namespace vct::gl {

GLuint make_texture_2d(GLenum internal_format, int w, int h);
GLuint make_texture_2d_array(GLenum internal_format, int w, int h, int layers);
/// 3D texture with `levels` mip levels, LINEAR_MIPMAP_LINEAR, CLAMP_TO_BORDER with border 0.
GLuint make_texture_3d(GLenum internal_format, int n, int levels);

/// Number of levels of a full chain from n down to 1.
int mip_count(int n);

/// Reads `channels` float channels of a 2D texture (or one layer of an array) into an Image,
/// flipping rows so row 0 is the top.
Image read_image(GLuint tex, int w, int h, int channels, int layer = -1);
/// Reads a depth texture (or array layer) as one float channel, flipped.
Image read_depth(GLuint tex, int w, int h, int layer = -1);
/// Reads one level of a 3D texture (float RGBA or R32UI) into a Volume.
Volume read_volume(GLuint tex, int level, int n, int channels);
Volume read_volume_uint(GLuint tex, int n);
/// Reads one level of an RGBA8 3D texture as bytes and converts with c / 255 (GL's definition; a
/// driver's own float readback may compute c * (1/255), one ulp away).
Volume read_volume_unorm8(GLuint tex, int level, int n);

}  // namespace vct::gl
