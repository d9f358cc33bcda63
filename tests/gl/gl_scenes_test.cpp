// Every scene in scenes/ renders on GL with finite, non-negative radiance everywhere (the issue's
// "works on every scene"), at the smallest useful sizes.
#include <dirent.h>

#include <cmath>
#include <vector>

#include "gl_test_util.h"

namespace vct::gl::test {

namespace {
std::vector<std::string> scene_files() {
  std::vector<std::string> out;
  const std::string dir = std::string(VCT_SOURCE_DIR) + "/scenes";
  if (DIR* d = opendir(dir.c_str())) {
    while (dirent* e = readdir(d)) {
      const std::string name = e->d_name;
      if (name.size() > 5 && name.compare(name.size() - 5, 5, ".gltf") == 0) out.push_back(dir + "/" + name);
    }
    closedir(d);
  }
  return out;
}

bool finite_non_negative(const Image& img) {
  for (float v : img.data)
    if (!std::isfinite(v) || v < 0.0f) return false;
  return true;
}
}  // namespace

TEST(GlScenes, EverySceneRenders) {
  VCT_REQUIRE_GL();
  const std::vector<std::string> files = scene_files();
  ASSERT_GE(files.size(), 3u);
  for (const std::string& f : files) {
    SCOPED_TRACE(f);
    const Scene scene = load_gltf_file(f);
    Settings s = small_settings(16, 32);
    s.vct.shadow_map_size = 128;
    const FrameResult r = render_gl_frame(*ctx, scene, s);
    EXPECT_TRUE(finite_non_negative(r.images.final_image));
    EXPECT_TRUE(finite_non_negative(r.images.direct));
    EXPECT_TRUE(finite_non_negative(r.images.indirect_diffuse));
    EXPECT_EQ(r.shadow_maps.size(), scene.lights.size());
    EXPECT_GT(std::stoll(r.info.at("covered_voxels")), 0);
  }
}

}  // namespace vct::gl::test
