// Primary rays against the rasterizers' camera: every ray passes through the point that
// Camera::view/projection maps to its pixel (unprojected with GLM, an independent route), for a
// perspective and an orthographic camera; orthographic rays are parallel and start on the near plane.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "pt/camera_ray.h"

namespace vct::pt {
namespace {

Camera tilted(bool orthographic) {
  Camera c;
  c.position = vec3(0.3f, 1.2f, 4.0f);
  c.forward = glm::normalize(vec3(-0.1f, -0.2f, -1.0f));
  c.up = vec3(0.0f, 1.0f, 0.0f);
  c.orthographic = orthographic;
  c.yfov = 0.7f;
  c.ymag = 1.5f;
  c.znear = 0.5f;
  c.zfar = 20.0f;
  return c;
}

void expect_rays_hit_their_pixels(const Camera& c) {
  const int w = 48, h = 32;
  const mat4 view = c.view(), proj = c.projection(float(w) / float(h));
  for (int y : {0, 7, 31})
    for (int x : {0, 20, 47}) {
      const Ray r = camera_ray(c, w, h, float(x) + 0.5f, float(y) + 0.5f);
      // Window point at mid depth on the same pixel (GL windows: row 0 at the bottom).
      const vec3 target = glm::unProject(vec3(float(x) + 0.5f, float(h - y) - 0.5f, 0.5f), view, proj,
                                         vec4(0, 0, w, h));
      const vec3 to = target - r.org;
      const float along = glm::dot(to, r.dir);
      EXPECT_LT(glm::length(to - along * r.dir), 1e-4f * (1.0f + along)) << x << "," << y;
      EXPECT_GT(along, 0.0f);
    }
}

TEST(CameraRay, PerspectiveRaysPassThroughTheirPixels) { expect_rays_hit_their_pixels(tilted(false)); }

TEST(CameraRay, OrthographicRaysPassThroughTheirPixelsInParallel) {
  const Camera c = tilted(true);
  expect_rays_hit_their_pixels(c);
  const Ray a = camera_ray(c, 48, 32, 0.5f, 0.5f), b = camera_ray(c, 48, 32, 47.5f, 31.5f);
  EXPECT_EQ(a.dir, b.dir);
  EXPECT_NEAR(glm::dot(a.dir, c.forward), 1.0f, 1e-6f);
  // Corner to corner: 2 ymag (aspect 1.5) by 2 ymag, less one pixel, on the image plane.
  const vec3 span = b.org - a.org;
  EXPECT_NEAR(glm::length(span), std::hypot(2.0f * 1.5f * 1.5f * 47.0f / 48.0f, 2.0f * 1.5f * 31.0f / 32.0f), 1e-4f);
  EXPECT_NEAR(glm::dot(span, c.forward), 0.0f, 1e-5f);
  EXPECT_FLOAT_EQ(a.tnear, c.znear);
  EXPECT_FLOAT_EQ(a.tfar, c.zfar);
}

}  // namespace
}  // namespace vct::pt
