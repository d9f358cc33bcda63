#include "arrays.h"

#include <algorithm>

#include "core/error.h"

namespace vct::py {

FloatArray image_view(Image& image, nb::handle owner) {
  const size_t shape[3] = {size_t(image.height), size_t(image.width), size_t(image.channels)};
  return FloatArray(image.data.data(), 3, shape, owner);
}

FloatArray volume_view(Volume& volume, nb::handle owner) {
  const size_t shape[4] = {size_t(volume.nz), size_t(volume.ny), size_t(volume.nx), size_t(volume.channels)};
  return FloatArray(volume.data.data(), 4, shape, owner);
}

FloatArray image_array(Image&& image) {
  Image* owned = new Image(std::move(image));
  nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<Image*>(p); });
  return image_view(*owned, owner);
}

FloatArray volume_array(Volume&& volume) {
  Volume* owned = new Volume(std::move(volume));
  nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<Volume*>(p); });
  return volume_view(*owned, owner);
}

Image image_from_array(const InputArray& a, const std::string& what) {
  if (a.ndim() != 2 && a.ndim() != 3)
    throw InputError(what, "an image is H x W x C (or H x W), got " + std::to_string(a.ndim()) + " dimensions");
  const int channels = a.ndim() == 3 ? int(a.shape(2)) : 1;
  Image image(int(a.shape(1)), int(a.shape(0)), channels);
  std::copy(a.data(), a.data() + image.data.size(), image.data.begin());
  return image;
}

Volume volume_from_array(const InputArray& a, const std::string& what) {
  if (a.ndim() != 4)
    throw InputError(what, "a volume is D x H x W x C, got " + std::to_string(a.ndim()) + " dimensions");
  Volume volume(int(a.shape(2)), int(a.shape(1)), int(a.shape(0)), int(a.shape(3)));
  std::copy(a.data(), a.data() + volume.data.size(), volume.data.begin());
  return volume;
}

}  // namespace vct::py
