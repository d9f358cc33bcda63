// Stage outputs as NumPy arrays without copying: an Image is H x W x C float32 (row 0 = top), a
// Volume D x H x W x C (z, y, x, channel: x fastest, as stored; docs/pipeline.md). The array
// points into the C++ object's storage and keeps `owner` (the Python object holding it) alive.
#pragma once

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>

#include "core/image.h"
#include "core/volume.h"

namespace vct::py {

namespace nb = nanobind;
using FloatArray = nb::ndarray<nb::numpy, float>;
// What Python hands us: any float32 array of 3 (image) or 4 (volume) dimensions, C-contiguous.
using InputArray = nb::ndarray<const float, nb::c_contig, nb::device::cpu>;

FloatArray image_view(Image& image, nb::handle owner);
FloatArray volume_view(Volume& volume, nb::handle owner);

/// The array takes the storage over (moved, not copied); it frees it when Python drops it.
FloatArray image_array(Image&& image);
FloatArray volume_array(Volume&& volume);

/// Copies an H x W x C (or H x W) array into an Image; throws InputError on another shape.
Image image_from_array(const InputArray& a, const std::string& what);
/// Copies a D x H x W x C array into a Volume; throws InputError on another shape.
Volume volume_from_array(const InputArray& a, const std::string& what);

}  // namespace vct::py
