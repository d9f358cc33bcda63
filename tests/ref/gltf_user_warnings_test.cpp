// What a Blender user's file gets (issue 35; docs/scenes.md, "Warnings"): warnings that name the
// object and say what is rendered instead, hard spots accepted with a warning, generated tangents
// said once per mesh, and the camera's aspectRatio kept.
#include <gtest/gtest.h>

#include <algorithm>

#include "gltf_test_doc.h"
#include "scene/gltf_loader.h"

namespace vct {
namespace {

using test::quad_doc;

Scene load(const test::GltfDoc& d) { return load_gltf_text(d.text(), "test.gltf", test::temp_dir().string()); }

// A lit quad (emissive, so "the scene has no light" does not join the warnings).
test::GltfDoc lit_quad() {
  auto d = quad_doc();
  d.j["materials"][0]["emissiveFactor"] = {1, 1, 1};
  return d;
}

std::vector<std::string> containing(const Scene& s, const std::string& part) {
  std::vector<std::string> out;
  for (const std::string& w : s.stats.warnings)
    if (w.find(part) != std::string::npos) out.push_back(w);
  return out;
}

TEST(GltfUserWarnings, IgnoredMaterialExtensionsNameTheMaterialAndWhatIsRenderedInstead) {
  auto d = lit_quad();
  d.j["materials"][0]["name"] = "Glass";
  d.j["materials"][0]["extensions"] = {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                                       {"KHR_materials_clearcoat", {{"clearcoatFactor", 1.0}}},
                                       {"KHR_materials_sheen", nlohmann::json::object()}};
  d.j["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_clearcoat", "KHR_materials_sheen"};
  const Scene s = load(d);
  ASSERT_EQ(s.stats.warnings.size(), 3u);  // one per extension, none by extension name alone
  EXPECT_EQ(containing(s, "KHR_materials_transmission").at(0),
            "material 0 'Glass': KHR_materials_transmission ignored, rendered opaque with its base colour");
  EXPECT_EQ(containing(s, "KHR_materials_clearcoat").at(0),
            "material 0 'Glass': KHR_materials_clearcoat ignored, rendered without its clear coat (base layer only)");
  EXPECT_EQ(containing(s, "KHR_materials_sheen").at(0), "material 0 'Glass': KHR_materials_sheen ignored, rendered without sheen");
}

TEST(GltfUserWarnings, HardSpotIsAcceptedWithAWarning) {
  auto d = lit_quad();
  d.j["extensions"] = {{"KHR_lights_punctual",
                        {{"lights", {{{"name", "HardSpot"}, {"type", "spot"},
                                      {"spot", {{"innerConeAngle", 0.349}, {"outerConeAngle", 0.349}}}}}}}}};
  d.j["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  d.j["scenes"][0]["nodes"].push_back(1);
  const Scene s = load(d);
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.lights[0].inner_cone_angle, s.lights[0].outer_cone_angle);
  ASSERT_EQ(s.stats.warnings.size(), 1u);
  EXPECT_EQ(s.stats.warnings[0],
            "light 0 'HardSpot': innerConeAngle == outerConeAngle (a hard spot; the Khronos validator flags it): "
            "rendered as a step, lit strictly inside the outer cone, in every engine");
}

TEST(GltfUserWarnings, GeneratedTangentsAreSaidOncePerNormalMappedMesh) {
  auto d = lit_quad();
  d.j["meshes"][0]["name"] = "Wall";
  d.j["materials"][0]["name"] = "Brick";
  d.j["images"] = {{{"uri", "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAADUlEQVR42mP4z8DwHwAFAAH/q842iQAAAABJRU5ErkJggg=="}}};
  d.j["textures"] = {{{"source", 0}}};
  d.j["materials"][0]["normalTexture"] = {{"index", 0}};
  // The same primitive twice in mesh 0, and the mesh instanced by two nodes: still one warning.
  d.j["meshes"][0]["primitives"].push_back(d.j["meshes"][0]["primitives"][0]);
  d.j["nodes"].push_back({{"mesh", 0}, {"translation", {0, 0, 1}}});
  d.j["scenes"][0]["nodes"].push_back(1);
  const Scene s = load(d);
  const auto w = containing(s, "tangents generated");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0], "mesh 0 'Wall': no TANGENT for material 'Brick' (normal-mapped); tangents generated from its UVs "
                  "(not MikkTSpace: baked normal maps may differ at UV seams)");
  auto plain = lit_quad();  // no normal map: tangents do not matter, nothing said
  EXPECT_TRUE(containing(load(plain), "TANGENT").empty());
}

TEST(GltfUserWarnings, PerspectiveAspectRatioIsKept) {
  auto d = lit_quad();
  d.j["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}, {"aspectRatio", 1.7777778}}}}};
  d.j["nodes"].push_back({{"camera", 0}, {"translation", {0.5, 0.5, 3}}});
  d.j["scenes"][0]["nodes"].push_back(1);
  EXPECT_FLOAT_EQ(load(d).camera.aspect_ratio, 1.7777778f);
  d.j["cameras"][0]["perspective"].erase("aspectRatio");
  EXPECT_EQ(load(d).camera.aspect_ratio, 0.0f);
}

}  // namespace
}  // namespace vct
