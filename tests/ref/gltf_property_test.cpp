// Issue 38 items 1 and 7: every glTF index is checked before anything reads it (one case per kind:
// morph target accessors, node light/camera/mesh/skin, material/texture/sampler/image, negative
// and wrongly typed indices), and every property the loader reads has its type, enum or range
// checked: an InputError naming the property, never a crash or a silently substituted default.
#include <gtest/gtest.h>

#include <functional>

#include "core/error.h"
#include "gltf_test_doc.h"
#include "scene/gltf_loader.h"

namespace vct {
namespace {

using nlohmann::json;
using test::GltfDoc;

struct IndexCase {
  const char* name;
  const char* expected;  // substring of the message
  std::function<void(GltfDoc&)> edit;
};

void add_texture(GltfDoc& d) {
  d.j["images"] = {{{"uri", "albedo.png"}}};
  d.j["samplers"] = json::array({json::object()});
  d.j["textures"] = {{{"source", 0}, {"sampler", 0}}};
}

void add_light(GltfDoc& d) {
  d.j["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", 1.0}}}}}}};
}

const std::vector<IndexCase>& index_cases() {
  static const std::vector<IndexCase> cases = {
      {"morph_target_accessor", "meshes[0].primitives[0].targets[0].POSITION is 1000000, but accessors has 3 entries",
       [](GltfDoc& d) {
         d.j["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", 1000000}}};
         d.j["meshes"][0]["weights"] = {1.0};
       }},
      {"morph_target_small_index", "targets[0].NORMAL is 3, but accessors has 3 entries",
       [](GltfDoc& d) { d.j["meshes"][0]["primitives"][0]["targets"] = {{{"NORMAL", 3}}}; }},
      {"node_light_negative", "nodes[0].extensions.KHR_lights_punctual.light is -1, not an index",
       [](GltfDoc& d) {
         add_light(d);
         d.j["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", -1}}}};
       }},
      {"node_light_out_of_range", "KHR_lights_punctual.light is 1, but extensions.KHR_lights_punctual.lights has 1 entry",
       [](GltfDoc& d) {
         add_light(d);
         d.j["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 1}}}};
       }},
      {"node_light_no_lights", "lights has 0 entries",
       [](GltfDoc& d) { d.j["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 0}}}}; }},
      {"node_camera", "nodes[0].camera is 2, but cameras has 0 entries", [](GltfDoc& d) { d.j["nodes"][0]["camera"] = 2; }},
      {"node_camera_negative", "nodes[0].camera is -1, not an index", [](GltfDoc& d) { d.j["nodes"][0]["camera"] = -1; }},
      {"node_mesh", "nodes[0].mesh is 7, but meshes has 1 entry", [](GltfDoc& d) { d.j["nodes"][0]["mesh"] = 7; }},
      {"node_mesh_string", "nodes[0].mesh is \"0\", not an index", [](GltfDoc& d) { d.j["nodes"][0]["mesh"] = "0"; }},
      {"node_mesh_fraction", "nodes[0].mesh is 0.5, not an index", [](GltfDoc& d) { d.j["nodes"][0]["mesh"] = 0.5; }},
      {"node_skin", "nodes[0].skin is 0, but skins has 0 entries", [](GltfDoc& d) { d.j["nodes"][0]["skin"] = 0; }},
      {"node_child", "nodes[0].children[0] is 5, but nodes has 1 entry", [](GltfDoc& d) { d.j["nodes"][0]["children"] = {5}; }},
      {"scene_root", "scenes[0].nodes[0] is -3, not an index", [](GltfDoc& d) { d.j["scenes"][0]["nodes"] = {-3}; }},
      {"default_scene", "scene is 4, but scenes has 1 entry", [](GltfDoc& d) { d.j["scene"] = 4; }},
      {"primitive_material", "primitives[0].material is 9, but materials has 1 entry",
       [](GltfDoc& d) { d.j["meshes"][0]["primitives"][0]["material"] = 9; }},
      {"primitive_indices_negative", "primitives[0].indices is -2, not an index",
       [](GltfDoc& d) { d.j["meshes"][0]["primitives"][0]["indices"] = -2; }},
      {"material_texture", "materials[0].pbrMetallicRoughness.baseColorTexture.index is 1, but textures has 1 entry",
       [](GltfDoc& d) {
         add_texture(d);
         d.j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 1}};
       }},
      {"material_normal_texture_negative", "materials[0].normalTexture.index is -1, not an index",
       [](GltfDoc& d) { d.j["materials"][0]["normalTexture"] = {{"index", -1}}; }},
      {"texture_sampler", "textures[0].sampler is 3, but samplers has 1 entry",
       [](GltfDoc& d) {
         add_texture(d);
         d.j["textures"][0]["sampler"] = 3;
       }},
      {"texture_image", "textures[0].source is 1, but images has 1 entry",
       [](GltfDoc& d) {
         add_texture(d);
         d.j["textures"][0]["source"] = 1;
       }},
      {"image_buffer_view", "images[0].bufferView is 10, but bufferViews has 3 entries",
       [](GltfDoc& d) {
         add_texture(d);
         d.j["images"][0] = {{"bufferView", 10}, {"mimeType", "image/png"}};
       }},
      {"accessor_buffer_view", "accessors[1].bufferView is -5, not an index",
       [](GltfDoc& d) { d.j["accessors"][1]["bufferView"] = -5; }},
      {"buffer_view_buffer", "bufferViews[2].buffer is 1, but buffers has 1 entry",
       [](GltfDoc& d) { d.j["bufferViews"][2]["buffer"] = 1; }},
      {"children_not_array", "nodes[0].children is not an array", [](GltfDoc& d) { d.j["nodes"][0]["children"] = 1; }},
  };
  return cases;
}

// What tinygltf replaced by its default in silence (issue 38, "Silent substitutions").
const std::vector<IndexCase>& property_cases() {
  static const std::vector<IndexCase> cases = {
      {"sampler_wrap_42", "samplers[0].wrapS is 42; it must be one of 33071, 33648, 10497",
       [](GltfDoc& d) {
         add_texture(d);
         d.j["samplers"][0]["wrapS"] = 42;
       }},
      {"sampler_mag_filter_mipmap", "samplers[0].magFilter is 9987; it must be one of 9728, 9729",
       [](GltfDoc& d) {
         add_texture(d);
         d.j["samplers"][0]["magFilter"] = 9987;
       }},
      {"sampler_filter_string", "samplers[0].minFilter is \"LINEAR\"; it must be one of",
       [](GltfDoc& d) {
         add_texture(d);
         d.j["samplers"][0]["minFilter"] = "LINEAR";
       }},
      {"light_intensity_string", "lights[0].intensity is \"10\"; it must be a number >= 0",
       [](GltfDoc& d) {
         add_light(d);
         d.j["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = "10";
       }},
      {"alpha_mode_number", "materials[0].alphaMode is 1; it must be one of \"OPAQUE, MASK, BLEND\"",
       [](GltfDoc& d) { d.j["materials"][0]["alphaMode"] = 1; }},
      {"alpha_cutoff_string", "materials[0].alphaCutoff is \"0.5\"; it must be a number >= 0",
       [](GltfDoc& d) { d.j["materials"][0]["alphaCutoff"] = "0.5"; }},
      {"texture_transform_rotation_string",
       "baseColorTexture.extensions.KHR_texture_transform.rotation is \"abc\"; it must be a number",
       [](GltfDoc& d) {
         add_texture(d);
         d.j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {
             {"index", 0}, {"extensions", {{"KHR_texture_transform", {{"rotation", "abc"}}}}}};
       }},
      {"emissive_strength_string", "KHR_materials_emissive_strength.emissiveStrength is \"abc\"; it must be a number",
       [](GltfDoc& d) {
         d.j["materials"][0]["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", "abc"}}}};
       }},
      {"morph_weights_string", "meshes[0].weights is [\"a\"]; it must be an array of numbers",
       [](GltfDoc& d) { d.j["meshes"][0]["weights"] = {"a"}; }},
      {"accessor_negative_byte_offset", "accessors[0].byteOffset is -4; it must be an integer >= 0",
       [](GltfDoc& d) { d.j["accessors"][0]["byteOffset"] = -4; }},
      {"buffer_view_offset_2_to_64", "bufferViews[0].byteOffset is 1.8446744073709552e+19; it must be an integer >= 0",
       [](GltfDoc& d) { d.j["bufferViews"][0]["byteOffset"] = 18446744073709551616.0; }},
      {"matrix_of_15_numbers", "nodes[0].matrix is [1,0,0,0,0,1,0,0,0,0,1,0,0,0,1]; it must be an array of 16 numbers",
       [](GltfDoc& d) { d.j["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1}; }},
      {"base_color_factor_of_3", "baseColorFactor is [1,0.5,0.5]; it must be an array of 4 numbers >= 0",
       [](GltfDoc& d) { d.j["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {1, 0.5, 0.5}; }},
  };
  return cases;
}

class BadProperty : public ::testing::TestWithParam<size_t> {};

TEST_P(BadProperty, IsRefusedNamingThePropertyAndTheRule) {
  const IndexCase& c = property_cases()[GetParam()];
  GltfDoc d = test::quad_doc();
  c.edit(d);
  try {
    (void)load_gltf_text(d.text(), std::string(c.name) + ".gltf", ".");
    FAIL() << c.name << ": loaded without error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(c.expected), std::string::npos) << c.name << ": " << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(AllKinds, BadProperty, ::testing::Range<size_t>(0, property_cases().size()),
                         [](const ::testing::TestParamInfo<size_t>& p) { return std::string(property_cases()[p.param].name); });

// metallic and roughness outside [0, 1] are clamped as engines do, with a warning naming both values.
TEST(BadProperty, MetallicAndRoughnessOutsideTheUnitRangeAreClampedWithAWarning) {
  GltfDoc d = test::quad_doc();
  d.j["materials"][0]["pbrMetallicRoughness"] = {{"metallicFactor", -1.0}, {"roughnessFactor", 5.0}};
  const Scene s = load_gltf_text(d.text(), "clamp.gltf", ".");
  ASSERT_FALSE(s.materials.empty());
  EXPECT_EQ(s.materials[0].metallic_factor, 0.0f);
  EXPECT_EQ(s.materials[0].roughness_factor, 1.0f);
  std::string all;
  for (const std::string& w : s.stats.warnings) all += w + "\n";
  EXPECT_NE(all.find("material 0 'white' metallicFactor -1.000000 is outside [0, 1]; using 0"), std::string::npos) << all;
  EXPECT_NE(all.find("material 0 'white' roughnessFactor 5.000000 is outside [0, 1]; using 1"), std::string::npos) << all;
}

class BadIndex : public ::testing::TestWithParam<size_t> {};

TEST_P(BadIndex, IsRefusedNamingTheProperty) {
  const IndexCase& c = index_cases()[GetParam()];
  GltfDoc d = test::quad_doc();
  c.edit(d);
  const std::string path = test::write_file(std::string(c.name) + ".gltf", d.text());
  try {
    (void)load_gltf_file(path);
    FAIL() << c.name << ": loaded without error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
    EXPECT_NE(msg.find(c.expected), std::string::npos) << c.name << ": " << msg;
  }
}

INSTANTIATE_TEST_SUITE_P(AllKinds, BadIndex, ::testing::Range<size_t>(0, index_cases().size()),
                         [](const ::testing::TestParamInfo<size_t>& p) { return std::string(index_cases()[p.param].name); });

// The same document with valid indices loads: the cases above fail for their one edit alone.
TEST(BadIndex, ValidIndicesLoad) {
  GltfDoc d = test::quad_doc();
  add_light(d);
  d.j["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 0}}}};
  const Scene s = load_gltf_text(d.text(), "valid.gltf", ".");
  ASSERT_EQ(s.lights.size(), 1u);
  EXPECT_EQ(s.triangles.size(), 2u);
}

// Issue 38 "garbage out": values finite in the file's doubles but not as the renderers' floats, or
// not after the node transforms, are refused before rendering, naming the object.
std::string load_message(const GltfDoc& d) {
  try {
    (void)load_gltf_text(d.text(), "garbage.gltf", ".");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GarbageOut, LightIntensityBeyondFloatIsRefusedNamingTheLight) {
  GltfDoc d = test::quad_doc();
  add_light(d);
  d.j["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = 1e39;
  d.j["extensions"]["KHR_lights_punctual"]["lights"][0]["name"] = "lamp";
  d.j["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 0}}}};
  EXPECT_NE(load_message(d).find("point light 'lamp': intensity inf x colour is not a finite float"), std::string::npos)
      << load_message(d);
  d.j["extensions"]["KHR_lights_punctual"]["lights"][0]["intensity"] = 3e38;  // finite, but x colour 2 is not
  d.j["extensions"]["KHR_lights_punctual"]["lights"][0]["color"] = {2.0, 1.0, 1.0};
  EXPECT_NE(load_message(d).find("point light 'lamp': intensity"), std::string::npos) << load_message(d);
}

TEST(GarbageOut, WorldTransformOverflowingFloatIsRefusedNamingTheNode) {
  GltfDoc d = test::quad_doc();
  // Each local scale is a finite float; their product (1e40) is not.
  d.j["nodes"] = {{{"children", {1}}, {"scale", {1e20, 1e20, 1e20}}}, {{"mesh", 0}, {"scale", {1e20, 1e20, 1e20}}}};
  EXPECT_NE(load_message(d).find("node 1: its world transform"), std::string::npos) << load_message(d);
}

// Accessor 3: 4 VEC2 of 3e38 (a TEXCOORD_0 morph target); with weight 2 every UV overflows.
GltfDoc uv_morph_doc(double weight) {
  GltfDoc d = test::quad_doc();
  const size_t at = d.bin.size();
  test::append<float>(d.bin, {3e38f, 0, 3e38f, 0, 3e38f, 0, 3e38f, 0});
  d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", 32}});
  d.j["accessors"].push_back({{"bufferView", 3}, {"componentType", 5126}, {"count", 4}, {"type", "VEC2"}});
  d.j["meshes"][0]["primitives"][0]["targets"] = {{{"TEXCOORD_0", 3}}};
  d.j["meshes"][0]["weights"] = {weight};
  return d;
}

TEST(GarbageOut, MorphTargetOverflowingTheUvsIsRefused) {
  EXPECT_NE(load_message(uv_morph_doc(2.0)).find("morph target 0 TEXCOORD_0 (weight 2.000000) makes element 0"),
            std::string::npos)
      << load_message(uv_morph_doc(2.0));
  EXPECT_NE(load_message(uv_morph_doc(1e39)).find("node 0 (mesh 0) morph weight 0 is not a finite float"),
            std::string::npos)
      << load_message(uv_morph_doc(1e39));
  EXPECT_EQ(load_message(uv_morph_doc(0.0)), "");  // the same file at weight 0 loads
}

TEST(GarbageOut, Uint32ColorIsRefused) {
  GltfDoc d = test::quad_doc();
  const size_t at = d.bin.size();
  test::append<uint32_t>(d.bin, {4000000000u, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", 48}});
  d.j["accessors"].push_back({{"bufferView", 3}, {"componentType", 5125}, {"count", 4}, {"type", "VEC3"}});
  d.j["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 3;
  EXPECT_NE(load_message(d).find("COLOR_0 (accessor 3) must be FLOAT or normalized UNSIGNED_BYTE/UNSIGNED_SHORT"),
            std::string::npos)
      << load_message(d);
}

// A chain of nodes (each the only child of the one before) is a tree however long; closing it
// into a ring is a cycle. The check walks each node once (docs/scenes.md, "Limits").
std::string chain_doc(size_t nodes, bool ring) {
  GltfDoc d = test::quad_doc();
  json list = json::array();
  for (size_t i = 0; i < nodes; ++i) {
    json n = json::object();
    if (i + 1 < nodes) n["children"] = {i + 1};
    else if (ring) n["children"] = {0};
    list.push_back(std::move(n));
  }
  list[nodes - 1]["mesh"] = 0;
  d.j["nodes"] = std::move(list);
  return d.text();
}

TEST(NodeChain, LongChainLoadsAndItsRingIsRefused) {
  constexpr size_t kNodes = 100000;
  const Scene s = load_gltf_text(chain_doc(kNodes, false), "chain.gltf", ".");
  EXPECT_EQ(s.triangles.size(), 2u);
  try {
    (void)load_gltf_text(chain_doc(kNodes, true), "ring.gltf", ".");
    FAIL() << "a ring of nodes loaded";
  } catch (const InputError& e) {
    // Every node has one parent, and none reaches a root: the first node walked is named.
    EXPECT_NE(std::string(e.what()).find("node graph has a cycle through node 0"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace vct
