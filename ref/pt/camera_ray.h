// Primary rays through pixel centres with the pipelines' camera (Camera::view/projection):
// row 0 = top, aspect = width/height, and the ray limited to the view frustum's depth range
// [znear, zfar] so the path tracer sees exactly what the rasterised G-buffer can see.
#pragma once

#include "core/math.h"
#include "scene/scene.h"

namespace vct::pt {

struct Ray {
  vec3 org{0.0f};
  vec3 dir{0.0f, 0.0f, -1.0f};  // unit
  float tnear = 0.0f;
  float tfar = 0.0f;
};

/// The ray through the image point (px, py) in pixel units (pixel centre = x + 0.5).
Ray camera_ray(const Camera& cam, int width, int height, float px, float py);

}  // namespace vct::pt
