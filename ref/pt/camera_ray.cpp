#include "pt/camera_ray.h"

#include <cmath>

namespace vct::pt {

Ray camera_ray(const Camera& cam, int width, int height, float px, float py) {
  // The same basis glm::lookAt builds for Camera::view().
  const vec3 f = glm::normalize(cam.forward);
  const vec3 r = glm::normalize(glm::cross(f, cam.up));
  const vec3 u = glm::cross(r, f);
  const float aspect = float(width) / float(height);
  const float ndc_x = 2.0f * px / float(width) - 1.0f;
  const float ndc_y = 1.0f - 2.0f * py / float(height);
  if (cam.orthographic) {  // parallel rays from the image rectangle, as Camera::projection's glm::ortho
    Ray ray;
    ray.org = cam.position + r * (ndc_x * cam.ymag * aspect) + u * (ndc_y * cam.ymag);
    ray.dir = f;
    ray.tnear = cam.znear;
    ray.tfar = cam.zfar;
    return ray;
  }
  const float tan_half = std::tan(0.5f * cam.yfov);
  const vec3 d = r * (ndc_x * tan_half * aspect) + u * (ndc_y * tan_half) + f;
  const float len = glm::length(d);  // view-space depth of a point at distance t is t / len
  Ray ray;
  ray.org = cam.position;
  ray.dir = d / len;
  ray.tnear = cam.znear * len;
  ray.tfar = cam.zfar * len;
  return ray;
}

}  // namespace vct::pt
