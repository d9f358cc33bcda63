// Images on disk through OpenImageIO: EXR (linear float data) and PNG (tone-mapped sRGB preview).
#pragma once

#include <string>

#include "core/image.h"
#include "io/srgb.h"

namespace vct {

/// Linear float EXR (32-bit channels, so comparisons see exactly what was computed).
void write_exr(const std::string& path, const Image& img);

/// 8-bit sRGB PNG preview: exposure scale, then the chosen tone map, then the sRGB curve.
/// One-channel images are written grey; alpha (4th channel) is dropped.
// PNG previews' display transform (docs/report.md, "Display transform"): Khronos PBR Neutral by
// default (what the glTF Sample Viewer shows); the others for comparison with older runs.
enum class ToneMap { Clamp, Reinhard, Aces, KhronosPbrNeutral };
/// The display transform's name as the report shows it ("Khronos PBR Neutral").
const char* tone_map_name(ToneMap tm);
void write_png(const std::string& path, const Image& img, float exposure = 1.0f, ToneMap tm = ToneMap::KhronosPbrNeutral);

/// Writes a data image as PNG with values mapped linearly from [lo, hi] to [0, 255], no sRGB
/// (depth maps, masks, normals remapped by the caller).
void write_png_linear(const std::string& path, const Image& img, float lo, float hi);

/// Reads any image OpenImageIO can read into float channels; throws InputError on failure.
Image read_image(const std::string& path);

}  // namespace vct
