// Exposure (docs/scenes.md, "Exposure"): KHR_lights_punctual's photometric units read as the
// extension defines them (a point lamp of N cd gives E = N cos / d^2 lux), the auto meter's closed
// form, whole-stop pre-exposure, and the committed scenes left at scale 1.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "scene/exposure.h"
#include "scene/gltf_loader.h"
#include "stage_test_scene.h"
#include "stages/direct.h"
#include "stages/gbuffer.h"
#include "stages/shadow_map.h"

namespace vct {
namespace {

// Blender's exporter in "Standard" mode: a 1000 W point lamp is 1000 / (4 pi) x 683 = 54351 cd.
constexpr float kBlenderStandardCandela = 54351.4f;

Scene lamp_over_floor(float candela, float height) {
  Scene s;
  const uint32_t m = test::add_material(s, vec3(0.5f));
  s.materials[m].specular_factor = 0.0f;  // pure Lambertian: L = albedo / pi x E
  test::add_quad(s, {-2, 0, -2}, {2, 0, -2}, {2, 0, 2}, {-2, 0, 2}, {0, 1, 0}, m);
  Light l;
  l.kind = LightKind::Point;
  l.position = vec3(0.0f, height, 0.0f);
  l.intensity = candela;
  s.lights.push_back(l);
  s.volume = fit_volume(s.bounds);
  test::top_camera(s);
  return s;
}

TEST(Exposure, MeterReadsCandelaOverDistanceSquared) {
  // The bounds' centre is (0, 0, 0); the lamp 2 m above it: E = N / 4 (white light, luminance 1).
  const Scene s = lamp_over_floor(kBlenderStandardCandela, 2.0f);
  EXPECT_NEAR(key_illuminance(s), double(kBlenderStandardCandela) / 4.0, 1e-3);
}

TEST(Exposure, MeterCountsASpotByItsConeAtTheCentreButAtLeastItsFlux) {
  // A hard 20 degree spot 2 m above the centre: aimed at it, E = N / 4 (the cone is 1 there);
  // aimed sideways (the centre outside its cone), its flux over the sphere, N (1 - cos 20 deg) / 2 / 4.
  Scene s = lamp_over_floor(kBlenderStandardCandela, 2.0f);
  Light& l = s.lights[0];
  l.kind = LightKind::Spot;
  l.inner_cone_angle = l.outer_cone_angle = 20.0f * kPi / 180.0f;
  l.direction = vec3(0.0f, -1.0f, 0.0f);
  EXPECT_NEAR(key_illuminance(s), double(kBlenderStandardCandela) / 4.0, 1e-3);
  l.direction = vec3(1.0f, 0.0f, 0.0f);
  EXPECT_NEAR(spot_flux_share(l), (1.0 - std::cos(20.0 * M_PI / 180.0)) / 2.0, 1e-6);
  EXPECT_NEAR(key_illuminance(s), double(kBlenderStandardCandela) * (1.0 - std::cos(20.0 * M_PI / 180.0)) / 2.0 / 4.0, 1e-2);
}

TEST(Exposure, AutoPreExposesAPhotometricExportByWholeStops) {
  Scene s = lamp_over_floor(kBlenderStandardCandela, 2.0f);
  const ExposureApplied e = resolve_exposure(s, ExposureMode::Auto, 0.0f);
  // E = 13587.85 lx; EV100 = log2(E x 100 / 250) = 12.408; scale 1 / (1.2 x 2^12.408) = 2^-12.671:
  // outside the +-4 stop dead band, rounded to -13.
  EXPECT_NEAR(e.ev100, 12.408, 1e-3);
  EXPECT_EQ(e.stops, -13);
  EXPECT_EQ(e.scale, std::ldexp(1.0f, -13));
  pre_expose(s, e);
  EXPECT_EQ(s.lights[0].intensity, kBlenderStandardCandela * std::ldexp(1.0f, -13));  // exact: a power of two
  EXPECT_EQ(s.exposure.stops, -13);
}

TEST(Exposure, AutoKeepsScaleOneInsideTheDeadBand) {
  // 10 cd at 2 m: E = 2.5 lx, meter scale 2.083 / 2.5 = 2^-0.26: kept at 1.
  const ExposureApplied e = resolve_exposure(lamp_over_floor(10.0f, 2.0f), ExposureMode::Auto, 0.0f);
  EXPECT_EQ(e.stops, 0);
  EXPECT_EQ(e.scale, 1.0f);
  // No light and no emission: nothing to meter, scale 1.
  Scene dark = lamp_over_floor(10.0f, 2.0f);
  dark.lights.clear();
  EXPECT_EQ(resolve_exposure(dark, ExposureMode::Auto, 0.0f).scale, 1.0f);
}

TEST(Exposure, Ev100AndNoneScales) {
  const Scene s = lamp_over_floor(10.0f, 2.0f);
  EXPECT_FLOAT_EQ(resolve_exposure(s, ExposureMode::Ev100, 0.0f).scale, 1.0f / 1.2f);
  EXPECT_FLOAT_EQ(resolve_exposure(s, ExposureMode::Ev100, 10.0f).scale, 1.0f / (1.2f * 1024.0f));
  EXPECT_EQ(resolve_exposure(s, ExposureMode::None, 0.0f).scale, 1.0f);
}

// The closed form through the reference's direct stage: L = albedo / pi x N cos / d^2 x 2^stops.
TEST(Exposure, PreExposedPhotometricLampIsTheClosedFormInImageDirect) {
  Scene s = lamp_over_floor(kBlenderStandardCandela, 1.0f);
  pre_expose(s, resolve_exposure(s, ExposureMode::Auto, 0.0f));
  ASSERT_LT(s.exposure.stops, -4);
  VctSettings st;
  st.width = st.height = 48;
  st.shadow_map_size = 256;
  const auto maps = render_shadow_maps(s, st);
  const GBuffer g = render_gbuffer(s, st);
  const Image img = shade_direct(s, g, maps, st);
  int checked = 0;
  for (int y = 0; y < st.height; ++y)
    for (int x = 0; x < st.width; ++x) {
      if (g.coverage.at(x, y, 0) == 0.0f) continue;
      const vec3 p = g.position.rgb(x, y);
      if (std::abs(p.x) > 0.9f || std::abs(p.z) > 0.9f) continue;  // PCF taps stay on the cube's -y face
      const float d = glm::length(vec3(0, 1, 0) - p), cos_t = 1.0f / d;
      const float expected = 0.5f / kPi * kBlenderStandardCandela * cos_t / (d * d) * s.exposure.scale;
      EXPECT_NEAR(img.at(x, y, 0), expected, 1e-5f * expected) << x << "," << y;
      ++checked;
    }
  EXPECT_GT(checked, 600);
}

// Every committed scene is authored in renderer-style units (a few cd, lux and nits): auto leaves
// them exactly as they were (scale 1), so their tests and validate runs do not move.
TEST(Exposure, AutoLeavesEveryCommittedSceneAtScaleOne) {
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(VCT_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".gltf") continue;
    const Scene s = load_gltf_file(entry.path().string());
    const ExposureApplied e = resolve_exposure(s, ExposureMode::Auto, 0.0f);
    EXPECT_EQ(e.scale, 1.0f) << entry.path() << ": " << e.key_illuminance << " lx";
    ++scenes;
  }
  EXPECT_GE(scenes, 10);
}

}  // namespace
}  // namespace vct
