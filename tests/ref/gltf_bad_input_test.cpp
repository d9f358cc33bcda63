// Every kind of bad input of issue 2 item 5: refused with an InputError that is one line,
// starts with the file name and says what is wrong. Never a crash.
#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <limits>

#include "core/error.h"
#include "gltf_test_doc.h"
#include "scene/gltf_loader.h"

namespace vct {
namespace {

using nlohmann::json;
using test::GltfDoc;
using test::quad_doc;

struct BadCase {
  const char* name;      // test case and file stem
  const char* expected;  // substring of the message
  std::function<std::string()> make;  // returns the path to load
};

std::string doc_file(const char* name, const std::function<void(GltfDoc&)>& edit) {
  GltfDoc d = quad_doc();
  edit(d);
  return test::write_file(std::string(name) + ".gltf", d.text());
}

// Gives accessor 0 (POSITION) two sparse substitutions at element indices i0, i1 (uint16, view 3)
// with values (0, 0, 0) and (1, 0, 0) (view 4).
void add_sparse(GltfDoc& d, uint16_t i0, uint16_t i1) {
  const size_t at = d.bin.size();
  test::append<uint16_t>(d.bin, {i0, i1});
  test::append<float>(d.bin, {0, 0, 0, 1, 0, 0});
  d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", 4}});
  d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at + 4}, {"byteLength", 24}});
  d.j["accessors"][0]["sparse"] = {{"count", 2},
                                   {"indices", {{"bufferView", 3}, {"componentType", 5123}}},
                                   {"values", {{"bufferView", 4}}}};
}

std::string glb_file(const char* name, const std::function<void(std::string&)>& edit) {
  std::string bytes = quad_doc().glb();
  edit(bytes);
  return test::write_file(std::string(name) + ".glb", bytes);
}

void put_u32(std::string& b, size_t at, uint32_t v) { std::memcpy(&b[at], &v, 4); }

const std::vector<BadCase>& bad_cases() {
  static const std::vector<BadCase> cases = {
      {"missing_file", "file not found", [] { return (test::temp_dir() / "does_not_exist.gltf").string(); }},
      {"directory", "is a directory", [] { return test::temp_dir().string(); }},
      {"empty_file", "empty file", [] { return test::write_file("empty.gltf", ""); }},
      {"not_gltf", "not a glTF file", [] { return test::write_file("not_gltf.gltf", "\x89PNG\r\n\x1a\nbinary"); }},
      {"json_without_asset", "no \"asset\"", [] { return test::write_file("no_asset.gltf", "{\"scenes\": []}"); }},
      {"version_1", "version 1.0 is not supported",
       [] { return doc_file("version_1", [](GltfDoc& d) { d.j["asset"]["version"] = "1.0"; }); }},
      {"broken_json", "broken JSON",
       [] {
         std::string t = quad_doc().text();
         return test::write_file("broken_json.gltf", t.substr(0, t.size() / 2));
       }},
      {"glb_bad_magic", "bad magic", [] { return glb_file("glb_bad_magic", [](std::string& b) { b[0] = 'X'; }); }},
      {"glb_truncated", "GLB header says",
       [] { return glb_file("glb_truncated", [](std::string& b) { b.resize(b.size() - 8); }); }},
      {"glb_version", "container version 1",
       [] { return glb_file("glb_version", [](std::string& b) { put_u32(b, 4, 1); }); }},
      {"glb_json_chunk_length", "JSON chunk length",
       [] { return glb_file("glb_json_chunk_length", [](std::string& b) { put_u32(b, 12, 1u << 20); }); }},
      {"glb_short_header", "shorter than its 12-byte header",
       [] { return test::write_file("glb_short_header.glb", "glTF\x02"); }},
      {"missing_buffer", "buffers[0] uri 'missing.bin': file not found (searched /",
       [] {
         return doc_file("missing_buffer", [](GltfDoc& d) { d.j["buffers"][0] = {{"uri", "missing.bin"}, {"byteLength", 92}}; });
       }},
      {"short_buffer_file", "short.bin",
       [] {
         test::write_file("short.bin", quad_doc().bin.substr(0, 40));
         return doc_file("short_buffer_file", [](GltfDoc& d) { d.j["buffers"][0] = {{"uri", "short.bin"}, {"byteLength", 92}}; });
       }},
      {"short_buffer_data", "short buffer",
       [] {
         return doc_file("short_buffer_data", [](GltfDoc& d) {
           d.bin.resize(60);
           d.j["buffers"][0]["byteLength"] = 60;
         });
       }},
      {"buffer_view_out_of_range", "bufferView 2 covers bytes",
       [] { return doc_file("buffer_view_out_of_range", [](GltfDoc& d) { d.j["bufferViews"][2]["byteLength"] = 400; }); }},
      {"accessor_out_of_range", "accessor out of range",
       [] { return doc_file("accessor_out_of_range", [](GltfDoc& d) { d.j["accessors"][0]["count"] = 10; }); }},
      {"index_out_of_range", "index out of range",
       [] { return doc_file("index_out_of_range", [](GltfDoc& d) { d.bin[80 + 4] = 9; }); }},
      // Sparse accessors (glTF 2.0 §3.6.2.3): substitutions must stay inside their views and the
      // accessor, indices strictly increasing.
      {"sparse_index_out_of_range", "accessor 0 sparse index 0 (4) is out of range or not strictly increasing",
       [] { return doc_file("sparse_index_out_of_range", [](GltfDoc& d) { add_sparse(d, 4, 5); }); }},
      {"sparse_indices_not_increasing", "sparse index 1 (1) is out of range or not strictly increasing",
       [] { return doc_file("sparse_indices_not_increasing", [](GltfDoc& d) { add_sparse(d, 1, 1); }); }},
      {"sparse_values_out_of_view", "accessor 0 sparse values need 24 bytes at offset 8",
       [] {
         return doc_file("sparse_values_out_of_view", [](GltfDoc& d) {
           add_sparse(d, 0, 1);
           d.j["accessors"][0]["sparse"]["values"]["byteOffset"] = 8;
         });
       }},
      {"sparse_count_too_large", "accessor 0 sparse count 5 must be 1..4",
       [] {
         return doc_file("sparse_count_too_large", [](GltfDoc& d) {
           add_sparse(d, 0, 1);
           d.j["accessors"][0]["sparse"]["count"] = 5;
         });
       }},
      {"dangling_buffer_view", "accessors[1].bufferView is 7, but bufferViews has 3 entries",
       [] { return doc_file("dangling_buffer_view", [](GltfDoc& d) { d.j["accessors"][1]["bufferView"] = 7; }); }},
      {"dangling_mesh", "nodes[0].mesh is 5, but meshes has 1 entry",
       [] { return doc_file("dangling_mesh", [](GltfDoc& d) { d.j["nodes"][0]["mesh"] = 5; }); }},
      {"dangling_material", "primitives[0].material is 3, but materials has 1 entry",
       [] { return doc_file("dangling_material", [](GltfDoc& d) { d.j["meshes"][0]["primitives"][0]["material"] = 3; }); }},
      {"unknown_alpha_mode", "materials[0].alphaMode is \"CUTOUT\"; it must be one of \"OPAQUE, MASK, BLEND\"",
       [] { return doc_file("unknown_alpha_mode", [](GltfDoc& d) { d.j["materials"][0]["alphaMode"] = "CUTOUT"; }); }},
      {"negative_alpha_cutoff", "materials[0].alphaCutoff is -0.25; it must be a number >= 0",
       [] {
         return doc_file("negative_alpha_cutoff", [](GltfDoc& d) {
           d.j["materials"][0]["alphaMode"] = "MASK";
           d.j["materials"][0]["alphaCutoff"] = -0.25;
         });
       }},
      {"dangling_texture", "baseColorTexture.index is 2, but textures has 0 entries",
       [] {
         return doc_file("dangling_texture", [](GltfDoc& d) {
           d.j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 2}};
         });
       }},
      {"dangling_light", "KHR_lights_punctual.light is 0, but extensions.KHR_lights_punctual.lights has 0 entries",
       [] {
         return doc_file("dangling_light", [](GltfDoc& d) {
           d.j["nodes"][0]["extensions"] = {{"KHR_lights_punctual", {{"light", 0}}}};
         });
       }},
      {"dangling_child_node", "nodes[0].children[0] is 9, but nodes has 1 entry",
       [] { return doc_file("dangling_child_node", [](GltfDoc& d) { d.j["nodes"][0]["children"] = {9}; }); }},
      {"dangling_scene_node", "scenes[0].nodes[0] is 4, but nodes has 1 entry",
       [] { return doc_file("dangling_scene_node", [](GltfDoc& d) { d.j["scenes"][0]["nodes"] = {4}; }); }},
      {"node_cycle", "cycle",
       [] {
         return doc_file("node_cycle", [](GltfDoc& d) {
           // Nodes 1 and 2 are each other's child (and no scene lists them).
           d.j["nodes"].push_back({{"children", {2}}});
           d.j["nodes"].push_back({{"children", {1}}});
         });
       }},
      {"node_self_child", "its own child",
       [] { return doc_file("node_self_child", [](GltfDoc& d) { d.j["nodes"][0]["children"] = {0}; }); }},
      {"node_two_parents", "two parents",
       [] {
         return doc_file("node_two_parents", [](GltfDoc& d) {
           d.j["nodes"].push_back({{"children", {0}}});
           d.j["nodes"].push_back({{"children", {0}}});
           d.j["scenes"][0]["nodes"] = {1, 2};
         });
       }},
      {"unsupported_required_extension", "requires extension \"KHR_draco_mesh_compression\"",
       [] {
         return doc_file("unsupported_required_extension", [](GltfDoc& d) {
           d.j["extensionsUsed"] = {"KHR_draco_mesh_compression"};
           d.j["extensionsRequired"] = {"KHR_draco_mesh_compression"};
         });
       }},
      {"nan_position", "POSITION (accessor 0) element 2 is not a finite number",
       [] {
         return doc_file("nan_position", [](GltfDoc& d) {
           const float nan = std::numeric_limits<float>::quiet_NaN();
           std::memcpy(&d.bin[24 + 4], &nan, 4);
         });
       }},
      {"inf_texcoord", "TEXCOORD_0 (accessor 1) element 0 is not a finite number",
       [] {
         return doc_file("inf_texcoord", [](GltfDoc& d) {
           const float inf = std::numeric_limits<float>::infinity();
           std::memcpy(&d.bin[48], &inf, 4);
         });
       }},
      {"missing_image", "missing.png",
       [] {
         return doc_file("missing_image", [](GltfDoc& d) {
           d.j["images"] = {{{"uri", "missing.png"}}};
           d.j["textures"] = {{{"source", 0}}};
           d.j["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
         });
       }},
      {"undecodable_image", "not_an_image.png",
       [] {
         test::write_file("not_an_image.png", "this is not a PNG");
         return doc_file("undecodable_image", [](GltfDoc& d) {
           d.j["images"] = {{{"uri", "not_an_image.png"}}};
           d.j["textures"] = {{{"source", 0}}};
         });
       }},
      {"no_triangles", "no triangles",
       [] { return doc_file("no_triangles", [](GltfDoc& d) { d.j["meshes"][0]["primitives"][0]["mode"] = 1; }); }},
      {"zero_quaternion", "zero rotation quaternion",
       [] { return doc_file("zero_quaternion", [](GltfDoc& d) { d.j["nodes"][0]["rotation"] = {0, 0, 0, 0}; }); }},
      {"bad_spot_cone", "innerConeAngle <= outerConeAngle",
       [] {
         return doc_file("bad_spot_cone", [](GltfDoc& d) {
           d.j["extensions"] = {{"KHR_lights_punctual",
                                 {{"lights", {{{"type", "spot"}, {"spot", {{"innerConeAngle", 1.0}, {"outerConeAngle", 0.5}}}}}}}}};
         });
       }},
  };
  return cases;
}

class BadInput : public ::testing::TestWithParam<size_t> {};

TEST_P(BadInput, IsRefusedWithOneLineNamingTheFile) {
  const BadCase& c = bad_cases()[GetParam()];
  const std::string path = c.make();
  try {
    (void)load_gltf_file(path);
    FAIL() << c.name << ": loaded without error";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path + ": ", 0), 0u) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_NE(msg.find(c.expected), std::string::npos) << c.name << ": " << msg;
  }
}

INSTANTIATE_TEST_SUITE_P(AllCases, BadInput, ::testing::Range<size_t>(0, bad_cases().size()),
                         [](const ::testing::TestParamInfo<size_t>& p) { return std::string(bad_cases()[p.param].name); });

TEST(BadInputText, InMemoryTextNamesItsSource) {
  try {
    (void)load_gltf_text("{\"asset\": {\"version\": \"2.0\"}", "memory.gltf", ".");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("memory.gltf: broken JSON", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace vct
