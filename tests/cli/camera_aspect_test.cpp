// The image takes the camera's aspect ratio (issue 35; docs/scenes.md, "Camera"): width from the
// height, height from --width alone, both forced: kept with a warning. And the frame is the author's:
// the edge of the 16:9 frustum lands on the image's edge.
#include <gtest/gtest.h>

#include <cmath>

#include "../../app/camera_aspect.h"

namespace vct::app {
namespace {

Scene camera_scene(float aspect) {
  Scene s;
  s.source = "test.gltf";
  s.camera.yfov = 0.8f;
  s.camera.aspect_ratio = aspect;
  return s;
}

TEST(CameraAspect, WidthFollowsTheHeight) {
  Settings s;
  s.vct.height = s.pt.height = 64;
  std::string warning;
  const Settings out = fit_image_to_camera(s, camera_scene(16.0f / 9.0f), CommonOptions{}, warning);
  EXPECT_EQ(out.vct.width, 114);  // round(64 x 1.7778) = round(113.78)
  EXPECT_EQ(out.vct.height, 64);
  EXPECT_EQ(out.pt.width, 114);
  EXPECT_TRUE(warning.empty());
}

TEST(CameraAspect, HeightFollowsAWidthGivenAlone) {
  CommonOptions o;
  o.width = 128;
  Settings s;
  s.vct.width = s.pt.width = 128;
  std::string warning;
  const Settings out = fit_image_to_camera(s, camera_scene(16.0f / 9.0f), o, warning);
  EXPECT_EQ(out.vct.height, 72);
  EXPECT_EQ(out.pt.height, 72);
}

TEST(CameraAspect, BothForcedAreKeptWithAWarningWhenTheFramingChanges) {
  CommonOptions o;
  o.width = o.height = 64;
  Settings s;
  s.vct.width = s.vct.height = s.pt.width = s.pt.height = 64;
  std::string warning;
  const Settings out = fit_image_to_camera(s, camera_scene(16.0f / 9.0f), o, warning);
  EXPECT_EQ(out.vct.width, 64);
  EXPECT_EQ(warning,
            "the camera's aspectRatio is 1.778 but --width 64 --height 64 make 1: the framing changes (same vertical "
            "field of view, narrower than the author framed it); give only --height or --width to keep it");
  o.width = 114;  // what the camera asks, to the pixel: nothing to say
  fit_image_to_camera(s, camera_scene(16.0f / 9.0f), o, warning);
  EXPECT_TRUE(warning.empty());
  // Without aspectRatio the size is the settings' own.
  const Settings same = fit_image_to_camera(s, camera_scene(0.0f), CommonOptions{}, warning);
  EXPECT_EQ(same.vct.width, 64);
  EXPECT_TRUE(warning.empty());
}

// The author's frame: a point on the 16:9 frustum's right edge (horizontal half-angle
// atan(aspect tan(yfov / 2))) projects to the image's right edge within half a pixel.
TEST(CameraAspect, TheAuthorsFrustumEdgeIsTheImageEdge) {
  const Scene scene = camera_scene(16.0f / 9.0f);
  Settings s;
  s.vct.height = 64;
  std::string warning;
  const Settings out = fit_image_to_camera(s, scene, CommonOptions{}, warning);
  const float aspect = float(out.vct.width) / float(out.vct.height);
  const float tan_half_x = scene.camera.aspect_ratio * std::tan(0.5f * scene.camera.yfov);
  const vec4 clip = scene.camera.projection(aspect) * scene.camera.view() * vec4(tan_half_x * 5.0f, 0.0f, -5.0f, 1.0f);
  EXPECT_NEAR(clip.x / clip.w, 1.0f, 1.0f / float(out.vct.width));
}

}  // namespace
}  // namespace vct::app
