// sRGB transfer functions (IEC 61966-2-1), shared by textures and previews. Their own file, so
// code that decodes textures (scene/surface.cpp) links without the image I/O library: the GL
// runner has no OpenImageIO (docs/gl_backend.md, "GL runner").
#pragma once

namespace vct {

float srgb_to_linear(float c);
float linear_to_srgb(float c);

}  // namespace vct
