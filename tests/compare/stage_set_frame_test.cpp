// The frame behind a stage set (what `vct compare --scene` re-traces): rebuilt from the stage set
// of a reference frame it reproduces that frame's cone images bit for bit, isotropic and
// anisotropic, with PCF or cone-traced shadows; missing or mis-sized inputs are InputErrors.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "compare/isolated_stages.h"
#include "compare/stage_set_frame.h"
#include "core/error.h"
#include "scene/gltf_loader.h"
#include "freedoms/reference_frame.h"

namespace vct::cmp {
namespace {

Settings small(bool anisotropic, bool soft_shadows) {
  Settings s;
  s.vct.width = s.vct.height = 32;
  s.vct.grid = 16;
  s.vct.shadow_map_size = 128;
  s.vct.anisotropic = anisotropic;
  s.vct.soft_shadows = soft_shadows;
  return s;
}

void expect_round_trip(bool anisotropic, bool soft_shadows) {
  const Scene scene = load_scene("");
  const Settings s = small(anisotropic, soft_shadows);
  const FrameResult ref = render_ref_frame(scene, s);
  const FrameResult rebuilt = frame_from_stage_set(stage_set_from_frame(ref, s.vct), scene, s.vct);
  const FrameResult traced = reference_on_test_inputs(scene, rebuilt, s.vct);
  EXPECT_EQ(traced.images.indirect_diffuse.data, ref.images.indirect_diffuse.data);
  EXPECT_EQ(traced.images.indirect_specular.data, ref.images.indirect_specular.data);
  EXPECT_EQ(traced.images.direct.data, ref.images.direct.data);
  EXPECT_EQ(traced.images.final_image.data, ref.images.final_image.data);
  EXPECT_EQ(rebuilt.mips.iso.size(), anisotropic ? ref.mips.iso.size() : 5u);  // 16, 8, 4, 2, 1
  for (int d = 0; d < 6; ++d) EXPECT_EQ(rebuilt.mips.aniso[size_t(d)].size(), anisotropic ? 4u : 0u);
}

TEST(StageSetFrame, RebuiltFrameRetracesTheSameImages) {
  expect_round_trip(false, false);
  expect_round_trip(true, false);
  expect_round_trip(false, true);
}

TEST(StageSetFrame, ConeInputsFollowTheSettings) {
  const Scene scene = load_scene("");
  auto has = [](const std::vector<std::string>& v, const std::string& s) {
    return std::find(v.begin(), v.end(), s) != v.end();
  };
  const auto iso = cone_input_stages(scene, small(false, false).vct);
  EXPECT_TRUE(has(iso, "gbuffer.specular_color") && has(iso, "image.direct") && has(iso, "voxel.radiance"));
  EXPECT_TRUE(has(iso, "mip.iso.4"));  // 16^3: levels 1..4 down to 1^3
  EXPECT_FALSE(has(iso, "mip.iso.5") || has(iso, "mip.posx.1") || has(iso, "gbuffer.depth"));
  EXPECT_FALSE(has(iso, "image.particles"));  // the Cornell box has no emitters
  const auto aniso = cone_input_stages(scene, small(true, true).vct);
  EXPECT_TRUE(has(aniso, "mip.negz.4") && !has(aniso, "mip.iso.1"));
  EXPECT_FALSE(has(aniso, "image.direct"));  // cone-traced shadows re-trace direct light
  EXPECT_EQ(aniso.size(), 7u + 1u + 24u);  // G-buffer, voxel.radiance, 6 directions x 4 levels
}

TEST(StageSetFrame, MissingOrMisSizedInputsAreInputErrors) {
  const Scene scene = load_scene("");
  const Settings s = small(false, false);
  const StageSet full = stage_set_from_frame(render_ref_frame(scene, s), s.vct);
  StageSet set = full;
  set.volumes.erase("mip.iso.3");
  EXPECT_THROW(frame_from_stage_set(set, scene, s.vct), InputError);
  set = full;
  set.volumes["mip.iso.2"] = Volume(2, 2, 2, 4);  // level 2 of 16^3 is 4^3
  EXPECT_THROW(frame_from_stage_set(set, scene, s.vct), InputError);
  set = full;
  set.images["gbuffer.normal"] = Image(16, 32, 3);
  EXPECT_THROW(frame_from_stage_set(set, scene, s.vct), InputError);
  // RGBA files for RGB stages are fine: the extra channel is dropped.
  set = full;
  Image rgba(32, 32, 4, 1.0f);
  const Image& pos = full.images.at("gbuffer.position");
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) rgba.set_rgb(x, y, pos.rgb(x, y));
  set.images["gbuffer.position"] = rgba;
  EXPECT_EQ(frame_from_stage_set(set, scene, s.vct).gbuffer.position.data, pos.data);
  // A scene whose camera does not see these positions.
  Scene moved = scene;
  moved.camera.yfov *= 1.25f;  // every pixel but the centre moves by more than 1 px
  EXPECT_THROW(frame_from_stage_set(full, moved, s.vct), InputError);
}

// Shadow maps name their light: a point light's cube faces rebuild against a scene whose light N
// is a point light, and the same set is refused (wrong --scene) when light N is a spot or when the
// scene has another number of lights.
TEST(StageSetFrame, ShadowMapsMustMatchTheScenesLightKinds) {
  Scene scene = load_scene("");
  ASSERT_EQ(scene.lights.size(), 1u);
  Light lamp;
  lamp.kind = LightKind::Point;
  lamp.position = vec3(0.3f, 1.5f, 0.2f);
  lamp.intensity = 2.0f;
  scene.lights.push_back(lamp);
  const Settings s = small(false, false);
  const StageSet set = stage_set_from_frame(render_ref_frame(scene, s), s.vct);
  EXPECT_EQ(set.images.count("shadow_map.0"), 1u);
  EXPECT_EQ(set.images.count("shadow_map.1"), 0u);
  for (int f = 0; f < 6; ++f) EXPECT_EQ(set.images.count("shadow_map_cube." + std::to_string(6 + f)), 1u) << f;
  const FrameResult rebuilt = frame_from_stage_set(set, scene, s.vct);
  ASSERT_EQ(rebuilt.shadow_maps.size(), 2u);
  EXPECT_TRUE(rebuilt.shadow_maps[1].is_cube());
  Scene spots = scene;
  spots.lights[1].kind = LightKind::Spot;
  EXPECT_THROW(frame_from_stage_set(set, spots, s.vct), InputError);
  Scene one = scene;
  one.lights.pop_back();
  EXPECT_THROW(frame_from_stage_set(set, one, s.vct), InputError);
}

// An input of the wrong kind is missing, not an empty slot whose pixels are indexed, and an info
// list that is not all numbers is kept as text (info is free-form).
TEST(StageSetFrame, InputsOfTheWrongKindAreMissingAndInfoStaysFreeForm) {
  const Scene scene = load_scene("");
  const Settings s = small(false, false);
  const StageSet full = stage_set_from_frame(render_ref_frame(scene, s), s.vct);
  StageSet set = full;
  set.images.erase("gbuffer.position");
  set.volumes["gbuffer.position"] = Volume(4, 4, 4, 4);
  try {
    frame_from_stage_set(set, scene, s.vct);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'gbuffer.position' is missing"), std::string::npos) << e.what();
  }
  set = full;
  set.info["multibounce_energy"] = {"x", 2};
  const FrameResult f = frame_from_stage_set(set, scene, s.vct);
  EXPECT_TRUE(f.multibounce_energy.empty());
  EXPECT_EQ(f.info.at("multibounce_energy"), R"(["x",2])");
}

}  // namespace
}  // namespace vct::cmp
