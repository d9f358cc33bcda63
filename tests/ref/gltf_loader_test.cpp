// The loader's conversion into the flat Scene: transforms, generated normals and tangents,
// materials and extensions, lights, particles, camera, volume, degenerate/skipped primitives.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "gltf_test_doc.h"
#include "scene/alpha_mask.h"
#include "scene/gltf_loader.h"
#include "scene/surface.h"

namespace vct {
namespace {

using test::quad_doc;
using nlohmann::json;

Scene load(const test::GltfDoc& d) { return load_gltf_text(d.text(), "test.gltf", test::temp_dir().string()); }

void expect_vec(const vec3& got, const vec3& want, float tol = 1e-5f) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

vec3 geometric_normal(const Scene& s, size_t t) {
  const uvec3 i = s.triangles[t];
  return glm::normalize(glm::cross(s.positions[i.y] - s.positions[i.x], s.positions[i.z] - s.positions[i.x]));
}

TEST(GltfLoader, QuadGetsFlatNormalsAndBounds) {
  const Scene s = load(quad_doc());
  ASSERT_EQ(s.triangle_count(), 2u);
  EXPECT_EQ(s.positions.size(), 6u);  // unwelded for flat normals (glTF: no NORMAL = flat)
  for (const vec3& n : s.normals) expect_vec(n, vec3(0, 0, 1));
  expect_vec(s.bounds.lo, vec3(0, 0, 0));
  expect_vec(s.bounds.hi, vec3(1, 1, 0));
  EXPECT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].name, "white");
  EXPECT_EQ(s.materials[0].metallic_factor, 0.0f);
  EXPECT_TRUE(s.uv1.empty());
  EXPECT_FALSE(s.camera.from_file);
  EXPECT_FALSE(s.volume.overridden);
  // fit_volume: largest extent 1 -> size 1*1.02 + 1/16, centred on (0.5, 0.5, 0).
  EXPECT_NEAR(s.volume.size, 1.02f + 1.0f / 16.0f, 1e-6f);
  expect_vec(s.volume.origin + vec3(s.volume.size * 0.5f), vec3(0.5f, 0.5f, 0.0f));
}

TEST(GltfLoader, GeneratedTangentsFollowUAndPointBitangentToImageUp) {
  const Scene s = load(quad_doc());
  for (size_t v = 0; v < s.positions.size(); ++v) {
    const vec4 t = s.tangents[v];
    EXPECT_NEAR(glm::dot(vec3(t), s.normals[v]), 0.0f, 1e-6f);
    expect_vec(vec3(t), vec3(1, 0, 0));  // u grows along +x
    // v decreases along +y, so "up in the image" is +y: bitangent = cross(N, T) * w = +y.
    expect_vec(glm::cross(s.normals[v], vec3(t)) * t.w, vec3(0, 1, 0));
  }
}

TEST(GltfLoader, NodeHierarchyComposesTrsTransforms) {
  auto d = quad_doc();
  // Parent: translate (1,2,3) * rotate 90 deg about z * scale 2; child: translate (1,0,0).
  const float h = std::sqrt(0.5f);
  d.j["nodes"] = {{{"name", "parent"}, {"children", {1}}, {"translation", {1, 2, 3}}, {"rotation", {0, 0, h, h}},
                   {"scale", {2, 2, 2}}},
                  {{"name", "child"}, {"mesh", 0}, {"translation", {1, 0, 0}}}};
  const Scene s = load(d);
  ASSERT_EQ(s.triangle_count(), 2u);
  // Vertex (1,0,0): child -> (2,0,0), scale -> (4,0,0), rotate -> (0,4,0), translate -> (1,6,3).
  // Vertex (0,0,0): -> (1,0,0) -> (2,0,0) -> (0,2,0) -> (1,4,3). Vertex (1,1,0) -> (-1,6,3).
  const uvec3 t0 = s.triangles[0];
  expect_vec(s.positions[t0.x], vec3(1, 4, 3));
  expect_vec(s.positions[t0.y], vec3(1, 6, 3));
  expect_vec(s.positions[t0.z], vec3(-1, 6, 3));
  expect_vec(s.normals[t0.x], vec3(0, 0, 1));
  expect_vec(vec3(s.tangents[t0.x]), vec3(0, 1, 0));  // +x rotated to +y
}

TEST(GltfLoader, MatrixTransformIsColumnMajor) {
  auto d = quad_doc();
  d.j["nodes"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1};
  const Scene s = load(d);
  expect_vec(s.bounds.lo, vec3(5, 6, 7));
  expect_vec(s.bounds.hi, vec3(6, 7, 7));
}

TEST(GltfLoader, NegativeScaleFlipsWindingAndHandedness) {
  auto d = quad_doc();
  // Given normals (+z) this time, so winding and vertex normals are tested independently.
  test::append<float>(d.bin, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
  d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 92}, {"byteLength", 48}});
  d.j["accessors"].push_back({{"bufferView", 3}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
  d.j["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 3;
  d.j["nodes"][0]["scale"] = {-1, 1, 1};
  const Scene s = load(d);
  ASSERT_EQ(s.triangle_count(), 2u);
  EXPECT_EQ(s.positions.size(), 4u);  // normals given: vertices stay shared
  for (size_t t = 0; t < 2; ++t) expect_vec(geometric_normal(s, t), vec3(0, 0, 1));
  for (size_t v = 0; v < 4; ++v) {
    expect_vec(s.normals[v], vec3(0, 0, 1));
    expect_vec(vec3(s.tangents[v]), vec3(-1, 0, 0));  // u now grows along -x
    EXPECT_EQ(s.tangents[v].w, -1.0f);                // mirrored: left-handed frame
    expect_vec(glm::cross(s.normals[v], vec3(s.tangents[v])) * s.tangents[v].w, vec3(0, 1, 0));
  }
}

TEST(GltfLoader, GivenTangentsAreTransformedAndMirrored) {
  auto d = quad_doc();
  test::append<float>(d.bin, {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
  test::append<float>(d.bin, {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1});
  d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 92}, {"byteLength", 48}});
  d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 140}, {"byteLength", 64}});
  d.j["accessors"].push_back({{"bufferView", 3}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
  d.j["accessors"].push_back({{"bufferView", 4}, {"componentType", 5126}, {"count", 4}, {"type", "VEC4"}});
  d.j["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 3;
  d.j["meshes"][0]["primitives"][0]["attributes"]["TANGENT"] = 4;
  d.j["nodes"][0]["scale"] = {-2, 1, 1};
  const Scene s = load(d);
  for (size_t v = 0; v < 4; ++v) {
    expect_vec(vec3(s.tangents[v]), vec3(-1, 0, 0));
    EXPECT_EQ(s.tangents[v].w, -1.0f);
  }
}

TEST(GltfLoader, MaterialExtensionsAndTextureTransform) {
  auto d = quad_doc();
  // A 2x1 PNG (red, green) as a data URI, used by every texture slot.
  static const unsigned char kPng[] = {
      0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d,
      0x49, 0x48, 0x44, 0x52, 0x00, 0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x01,
      0x08, 0x02, 0x00, 0x00, 0x00, 0x7b, 0x40, 0xe8, 0xdd, 0x00, 0x00, 0x00,
      0x0f, 0x49, 0x44, 0x41, 0x54, 0x78, 0xda, 0x63, 0xf8, 0xcf, 0xc0, 0xc0,
      0xf0, 0x9f, 0x01, 0x00, 0x07, 0xff, 0x01, 0xff, 0xb8, 0x04, 0x35, 0xe0,
      0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
  };
  const std::string png(reinterpret_cast<const char*>(kPng), sizeof(kPng));
  d.j["images"] = {{{"uri", "data:image/png;base64," + test::base64(png)}}};
  d.j["samplers"] = {{{"magFilter", 9728}, {"wrapS", 33071}, {"wrapT", 33648}}};
  d.j["textures"] = {{{"source", 0}, {"sampler", 0}}};
  const json xf = {{"KHR_texture_transform", {{"offset", {0.5, 0.25}}, {"rotation", 0.3}, {"scale", {2, 3}}}}};
  d.j["materials"][0] = {
      {"name", "fancy"},
      {"pbrMetallicRoughness",
       {{"baseColorFactor", {0.5, 0.6, 0.7, 1.0}}, {"baseColorTexture", {{"index", 0}, {"extensions", xf}}},
        {"metallicFactor", 0.25}, {"roughnessFactor", 0.75}, {"metallicRoughnessTexture", {{"index", 0}}}}},
      {"normalTexture", {{"index", 0}, {"scale", 0.5}}},
      {"emissiveTexture", {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"texCoord", 1}}}}}}},
      {"emissiveFactor", {1.0, 0.5, 0.25}},
      {"doubleSided", true},
      {"extras", {{"vct_normal_two_channel", true}}},
      {"extensions",
       {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}},
        {"KHR_materials_specular", {{"specularFactor", 0.0}, {"specularColorFactor", {0.9, 0.8, 0.7}}}}}}};
  d.j["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_emissive_strength", "KHR_materials_specular"};
  const Scene s = load(d);
  ASSERT_EQ(s.textures.size(), 1u);
  const Texture& t = s.textures[0];
  EXPECT_EQ(t.width, 2);
  EXPECT_EQ(t.height, 1);
  ASSERT_EQ(t.rgba8.size(), 8u);
  EXPECT_EQ(t.rgba8[0], 255);  // red texel
  EXPECT_EQ(t.rgba8[1], 0);
  EXPECT_EQ(t.rgba8[3], 255);  // opaque (RGB file)
  EXPECT_EQ(t.rgba8[5], 255);  // green texel
  EXPECT_EQ(t.wrap_s, Wrap::ClampToEdge);
  EXPECT_EQ(t.wrap_t, Wrap::MirroredRepeat);
  EXPECT_EQ(t.mag_filter, Filter::Nearest);
  // No minFilter in the sampler: ours, LINEAR_MIPMAP_LINEAR (docs/scenes.md, "Textures"). The
  // 2x1 image is read as sRGB (base colour, emissive) and linear (metallic-roughness, normal):
  // one 1x1 level 1 per encoding.
  EXPECT_EQ(t.min_filter, MinFilter::LinearMipmapLinear);
  ASSERT_EQ(t.mips[0].size(), 1u);
  ASSERT_EQ(t.mips[1].size(), 1u);
  EXPECT_EQ(t.mips[0][0].rgba8,
            (std::vector<uint8_t>{128, 128, 0, 255}));  // (255 + 0 + 1) / 2 rounded
  EXPECT_EQ(t.mips[1][0].rgba8,
            (std::vector<uint8_t>{188, 188, 0, 255}));  // linear 0.5 -> sRGB 187.5
  const Material& m = s.materials[0];
  EXPECT_EQ(m.base_color_factor, vec4(0.5f, 0.6f, 0.7f, 1.0f));
  EXPECT_EQ(m.base_color_texture.texture, 0);
  EXPECT_EQ(m.base_color_texture.transform.offset, vec2(0.5f, 0.25f));
  EXPECT_FLOAT_EQ(m.base_color_texture.transform.rotation, 0.3f);
  EXPECT_EQ(m.base_color_texture.transform.scale, vec2(2.0f, 3.0f));
  EXPECT_TRUE(m.metallic_roughness_texture.transform.is_identity());
  EXPECT_EQ(m.metallic_factor, 0.25f);
  EXPECT_EQ(m.roughness_factor, 0.75f);
  EXPECT_EQ(m.normal_texture.texture, 0);
  EXPECT_EQ(m.normal_scale, 0.5f);
  EXPECT_TRUE(m.normal_two_channel);
  EXPECT_EQ(m.emission(), vec3(4.0f, 2.0f, 1.0f));
  EXPECT_EQ(m.specular_factor, 0.0f);
  EXPECT_EQ(m.specular_color_factor, vec3(0.9f, 0.8f, 0.7f));
  EXPECT_TRUE(m.double_sided);
  // The transform's texCoord overrides the slot's; the quad has no TEXCOORD_1, which is a warning.
  EXPECT_EQ(m.emissive_texture.texcoord, 1);
  EXPECT_EQ(m.base_color_texture.texcoord, 0);
  // ... and the normal-mapped quad without TANGENT gets generated tangents, said once (issue 35).
  ASSERT_EQ(s.stats.warnings.size(), 2u);
  EXPECT_NE(s.stats.warnings[0].find("TEXCOORD_1"), std::string::npos);
  EXPECT_NE(s.stats.warnings[1].find("tangents generated"), std::string::npos);
  d.j["materials"][0]["emissiveTexture"]["extensions"]["KHR_texture_transform"]["texCoord"] = 2;
  EXPECT_THROW(load(d), InputError);
}

TEST(GltfLoader, SpotLightTakesPositionAndMinusZFromItsNode) {
  auto d = quad_doc();
  const float h = std::sqrt(0.5f);
  d.j["extensions"] = {{"KHR_lights_punctual",
                        {{"lights", {{{"name", "s"}, {"type", "spot"}, {"intensity", 12.5}, {"color", {1, 0.5, 0.25}},
                                      {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}}}}}}}};
  d.j["nodes"].push_back({{"translation", {0, 3, 0}}, {"rotation", {-h, 0, 0, h}},
                          {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  d.j["scenes"][0]["nodes"].push_back(1);
  const Scene s = load(d);
  ASSERT_EQ(s.lights.size(), 1u);
  const Light& l = s.lights[0];
  expect_vec(l.position, vec3(0, 3, 0));
  expect_vec(l.direction, vec3(0, -1, 0));
  EXPECT_EQ(l.intensity, 12.5f);
  EXPECT_EQ(l.color, vec3(1.0f, 0.5f, 0.25f));
  EXPECT_FLOAT_EQ(l.inner_cone_angle, 0.2f);
  EXPECT_FLOAT_EQ(l.outer_cone_angle, 0.6f);
}

TEST(GltfLoader, PointAndDirectionalLightsLoadWithTheirKind) {
  auto d = quad_doc();
  const float h = std::sqrt(0.5f);
  d.j["extensions"] = {{"KHR_lights_punctual",
                        {{"lights", {{{"name", "lamp"}, {"type", "point"}, {"intensity", 7.0}, {"range", 4.0}},
                                     {{"name", "sun"}, {"type", "directional"}, {"intensity", 3.0}, {"color", {1, 0.9, 0.8}}}}}}}};
  d.j["nodes"].push_back({{"translation", {1, 2, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
  d.j["nodes"].push_back({{"translation", {5, 5, 5}}, {"rotation", {-h, 0, 0, h}},
                          {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
  d.j["scenes"][0]["nodes"].push_back(1);
  d.j["scenes"][0]["nodes"].push_back(2);
  const Scene s = load(d);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].kind, LightKind::Point);
  EXPECT_EQ(s.lights[0].name, "lamp");
  expect_vec(s.lights[0].position, vec3(1, 2, 3));
  EXPECT_EQ(s.lights[0].intensity, 7.0f);
  EXPECT_EQ(s.lights[0].range, 4.0f);
  EXPECT_EQ(s.lights[1].kind, LightKind::Directional);
  expect_vec(s.lights[1].direction, vec3(0, -1, 0));  // the node's -Z turned straight down
  EXPECT_EQ(s.lights[1].intensity, 3.0f);
  EXPECT_EQ(s.lights[1].color, vec3(1.0f, 0.9f, 0.8f));
  EXPECT_EQ(s.lights[1].range, 0.0f);
  EXPECT_STREQ(light_kind_name(s.lights[1].kind), "directional");
}

TEST(GltfLoader, UnknownLightTypeIsRefused) {
  auto d = quad_doc();
  d.j["extensions"] = {{"KHR_lights_punctual", {{"lights", {{{"type", "area"}}}}}}};
  try {
    (void)load(d);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("lights[0].type is \"area\"; it must be one of \"directional, point, spot\""), std::string::npos) << e.what();
  }
}

TEST(GltfLoader, CameraComesFromTheFirstCameraNode) {
  auto d = quad_doc();
  d.j["cameras"] = {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"zfar", 50}}}},
                    {{"type", "perspective"}, {"perspective", {{"yfov", 0.9}, {"znear", 0.1}}}}};
  const float h = std::sqrt(0.5f);
  // Node 1 (camera 0) is nested under node 2, which comes later in the scene's roots; node 3
  // (camera 1) is an earlier root, so pre-order traversal finds camera 1 first.
  d.j["nodes"].push_back({{"camera", 0}});
  d.j["nodes"].push_back({{"children", {1}}});
  d.j["nodes"].push_back({{"camera", 1}, {"translation", {0, 0, 5}}, {"rotation", {0, h, 0, h}}});
  d.j["scenes"][0]["nodes"] = {0, 3, 2};
  const Scene s = load(d);
  EXPECT_TRUE(s.camera.from_file);
  EXPECT_FLOAT_EQ(s.camera.yfov, 0.9f);
  expect_vec(s.camera.position, vec3(0, 0, 5));
  expect_vec(s.camera.forward, vec3(-1, 0, 0));  // -z turned 90 deg about +y
  EXPECT_GT(s.camera.zfar, s.camera.znear);      // zfar absent (infinite) -> finite from bounds
}

TEST(GltfLoader, ParticleEmittersFromNodeExtras) {
  auto d = quad_doc();
  d.j["nodes"].push_back({{"name", "fire"}, {"translation", {1, 2, 3}},
                          {"extras", {{"vct_particles", {{"count", 100}, {"lifetime", 2.0}, {"size_start", 0.2},
                                                         {"color_start", {5, 2, 1}}}}}}});
  d.j["scenes"][0]["nodes"].push_back(1);
  const Scene s = load(d);
  ASSERT_EQ(s.emitters.size(), 1u);
  const ParticleEmitter& e = s.emitters[0];
  EXPECT_EQ(e.name, "fire");
  expect_vec(e.origin, vec3(1, 2, 3));
  EXPECT_EQ(e.count, 100);
  EXPECT_EQ(e.lifetime, 2.0f);
  EXPECT_EQ(e.size_start, 0.2f);
  EXPECT_EQ(e.color_start, vec3(5, 2, 1));
  EXPECT_EQ(e.size_end, ParticleEmitter{}.size_end);  // absent keys keep the documented defaults

  d.j["nodes"][1]["extras"]["vct_particles"]["colour"] = {1, 1, 1};
  EXPECT_THROW(load(d), InputError);
  d.j["nodes"][1]["extras"]["vct_particles"].erase("colour");
  d.j["nodes"][1]["extras"]["vct_particles"]["count"] = -3;
  EXPECT_THROW(load(d), InputError);
}

TEST(GltfLoader, VolumeOverrideFromAssetExtras) {
  auto d = quad_doc();
  d.j["asset"]["extras"] = {{"vct_volume", {{"origin", {-1, -2, -3}}, {"size", 8}}}};
  const Scene s = load(d);
  EXPECT_TRUE(s.volume.overridden);
  EXPECT_EQ(s.volume.origin, vec3(-1, -2, -3));
  EXPECT_EQ(s.volume.size, 8.0f);
  d.j["asset"]["extras"]["vct_volume"]["size"] = 0;
  EXPECT_THROW(load(d), InputError);
}

TEST(GltfLoader, DegenerateTrianglesAreDroppedAndCounted) {
  auto d = quad_doc();
  // Indices: the quad, then a repeated-vertex triangle and a zero-area (collinear) one.
  // Vertices 0,1 and a new vertex 4 at (2,0,0) are collinear.
  d.bin.resize(48);
  test::append<float>(d.bin, {2, 0, 0});  // 5th vertex, positions now 60 bytes
  test::append<float>(d.bin, {0, 1, 1, 1, 1, 0, 0, 0, 2, 1});
  test::append<uint16_t>(d.bin, {0, 1, 2, 0, 2, 3, 1, 1, 2, 0, 1, 4});
  d.j["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 60}},
                        {{"buffer", 0}, {"byteOffset", 60}, {"byteLength", 40}},
                        {{"buffer", 0}, {"byteOffset", 100}, {"byteLength", 24}}};
  d.j["accessors"][0]["count"] = 5;
  d.j["accessors"][0]["max"] = {2, 1, 0};
  d.j["accessors"][1]["count"] = 5;
  d.j["accessors"][2]["count"] = 12;
  const Scene s = load(d);
  EXPECT_EQ(s.triangle_count(), 2u);
  EXPECT_EQ(s.stats.degenerate_triangles_dropped, 2);
}

TEST(GltfLoader, LinePrimitivesAreSkippedWithAWarning) {
  auto d = quad_doc();
  auto lines = d.j["meshes"][0]["primitives"][0];
  lines["mode"] = 1;
  d.j["meshes"][0]["primitives"].push_back(lines);
  const Scene s = load(d);
  EXPECT_EQ(s.triangle_count(), 2u);
  EXPECT_EQ(s.stats.non_triangle_primitives_skipped, 1);
  ASSERT_FALSE(s.stats.warnings.empty());
  EXPECT_NE(s.stats.warnings.front().find("skipped"), std::string::npos);
}

TEST(GltfLoader, TriangleStripAndFanAreTriangulated) {
  // Strip 0,1,3,2 and fan 0,1,2,3 both cover the quad with two +z-facing triangles (glTF's
  // strip rule swaps the order of every odd triangle).
  for (int mode : {5, 6}) {
    auto d = quad_doc();
    d.bin.resize(80);
    if (mode == 5) test::append<uint16_t>(d.bin, {0, 1, 3, 2});
    else test::append<uint16_t>(d.bin, {0, 1, 2, 3});
    d.j["bufferViews"][2]["byteLength"] = 8;
    d.j["accessors"][2]["count"] = 4;
    d.j["meshes"][0]["primitives"][0]["mode"] = mode;
    const Scene s = load(d);
    ASSERT_EQ(s.triangle_count(), 2u) << mode;
    for (size_t t = 0; t < 2; ++t) expect_vec(geometric_normal(s, t), vec3(0, 0, 1));
  }
}

TEST(GltfLoader, PrimitiveWithoutMaterialGetsTheDefault) {
  auto d = quad_doc();
  d.j["meshes"][0]["primitives"][0].erase("material");
  d.j.erase("materials");
  const Scene s = load(d);
  ASSERT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.materials[0].name, "default");
  EXPECT_EQ(s.materials[0].base_color_factor, vec4(1.0f));
  EXPECT_EQ(s.materials[0].metallic_factor, 1.0f);
  EXPECT_EQ(s.triangle_material[0], 0u);
}

TEST(GltfLoader, GlbContainerLoads) {
  const std::string path = test::write_file("quad.glb", quad_doc().glb());
  const Scene s = load_gltf_file(path);
  EXPECT_EQ(s.triangle_count(), 2u);
  EXPECT_EQ(s.source, path);
}

TEST(GltfLoader, ExternalBufferAndImageResolveNextToTheFile) {
  auto d = quad_doc();
  test::write_file("quad.bin", d.bin);
  d.j["buffers"][0] = {{"uri", "quad.bin"}, {"byteLength", d.bin.size()}};
  const std::string path = test::write_file("external.gltf", d.text());
  EXPECT_EQ(load_gltf_file(path).triangle_count(), 2u);
}

// glTF 2.0 §3.6.2.3: a sparse accessor is its bufferView's data (or zeros) with `count` elements
// replaced. Here vertex 2 of the quad, (1, 1, 0), becomes (1, 1, 2), and an accessor without a
// bufferView starts from zeros.
TEST(GltfLoader, SparseAccessorsSubstituteTheirElements) {
  auto d = quad_doc();
  const size_t at = d.bin.size();
  test::append<uint8_t>(d.bin, {2, 0, 0, 0});  // one UNSIGNED_BYTE index, padded to 4
  test::append<float>(d.bin, {1, 1, 2});
  d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", 1}});
  d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at + 4}, {"byteLength", 12}});
  d.j["accessors"][0]["sparse"] = {{"count", 1},
                                   {"indices", {{"bufferView", 3}, {"componentType", 5121}}},
                                   {"values", {{"bufferView", 4}}}};
  d.j["accessors"][0]["max"] = {1, 1, 2};
  const Scene s = load(d);
  EXPECT_FLOAT_EQ(s.bounds.hi.z, 2.0f);
  int raised = 0;
  for (const vec3& p : s.positions) raised += p == vec3(1, 1, 2) ? 1 : 0;
  EXPECT_EQ(raised, 2);  // vertex 2 is in both triangles; flat normals unweld it into two copies

  auto z = quad_doc();  // TEXCOORD_0 without a bufferView: zeros, then one substitution
  const size_t at2 = z.bin.size();
  test::append<uint8_t>(z.bin, {3, 0, 0, 0});
  test::append<float>(z.bin, {0.25f, 0.75f});
  z.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at2}, {"byteLength", 1}});
  z.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at2 + 4}, {"byteLength", 8}});
  z.j["accessors"][1].erase("bufferView");
  z.j["accessors"][1]["sparse"] = {{"count", 1},
                                   {"indices", {{"bufferView", 3}, {"componentType", 5121}}},
                                   {"values", {{"bufferView", 4}}}};
  const Scene t = load(z);
  for (size_t v = 0; v < t.positions.size(); ++v) {
    const vec2 want = t.positions[v] == vec3(0, 1, 0) ? vec2(0.25f, 0.75f) : vec2(0.0f);
    EXPECT_EQ(t.uv0[v], want) << "vertex " << v;
  }
}

// glTF 2.0 §3.7.2.2: a still frame shows base + sum of weight * target; the node's weights win
// over the mesh's. Target 0 lifts vertex 2 by (0, 0, 1), target 1 moves vertex 0 by (-1, 0, 0).
TEST(GltfLoader, MorphTargetsAreAppliedAtTheirDefaultWeights) {
  auto d = quad_doc();
  const size_t at = d.bin.size();
  test::append<float>(d.bin, {0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0});
  test::append<float>(d.bin, {-1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", 96}});
  d.j["accessors"].push_back({{"bufferView", 3}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
  d.j["accessors"].push_back(
      {{"bufferView", 3}, {"byteOffset", 48}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
  d.j["meshes"][0]["primitives"][0]["targets"] = {{{"POSITION", 3}}, {{"POSITION", 4}}};
  d.j["meshes"][0]["weights"] = {0.5, 0.0};
  const Scene mesh_weights = load(d);
  EXPECT_FLOAT_EQ(mesh_weights.bounds.hi.z, 0.5f);
  EXPECT_FLOAT_EQ(mesh_weights.bounds.lo.x, 0.0f);

  d.j["nodes"][0]["weights"] = {1.0, 0.25};
  const Scene node_weights = load(d);
  EXPECT_FLOAT_EQ(node_weights.bounds.hi.z, 1.0f);
  EXPECT_FLOAT_EQ(node_weights.bounds.lo.x, -0.25f);

  d.j["nodes"][0]["weights"] = {1.0, 0.25, 1.0};  // more weights than targets
  EXPECT_THROW(load(d), InputError);
}

// glTF 2.0 §3.10.3: ymag is half the view's height; the width follows the image (docs/scenes.md).
TEST(GltfLoader, OrthographicCameraProjectsParallel) {
  auto d = quad_doc();
  d.j["cameras"] = {{{"type", "orthographic"}, {"orthographic", {{"xmag", 2.0}, {"ymag", 1.0}, {"znear", 0.5}, {"zfar", 10}}}}};
  d.j["nodes"].push_back({{"camera", 0}, {"translation", {0.5, 0.5, 3}}});
  d.j["scenes"][0]["nodes"] = {0, 1};
  const Scene s = load(d);
  ASSERT_TRUE(s.camera.orthographic);
  EXPECT_FLOAT_EQ(s.camera.ymag, 1.0f);
  const mat4 vp = s.camera.projection(2.0f) * s.camera.view();
  // A point 1 above the camera's axis is at the top of clip space, 2 to its right at the right edge,
  // whatever its depth.
  for (float z : {0.0f, -5.0f}) {
    const vec4 top = vp * vec4(0.5f, 1.5f, z, 1.0f), right = vp * vec4(2.5f, 0.5f, z, 1.0f);
    EXPECT_NEAR(top.y / top.w, 1.0f, 1e-6f);
    EXPECT_NEAR(right.x / right.w, 1.0f, 1e-6f);
  }
  expect_vec(s.camera.to_eye(vec3(7, -3, 0)), vec3(0, 0, 1));  // every point sees the eye along +z

  d.j["cameras"][0]["orthographic"]["ymag"] = -1.0;
  EXPECT_THROW(load(d), InputError);
}

TEST(GltfLoader, ASceneWithoutAnyLightIsWarnedAbout) {
  const Scene s = load(quad_doc());  // a white quad, no light, no emission
  ASSERT_EQ(s.stats.warnings.size(), 1u);
  EXPECT_NE(s.stats.warnings[0].find("the scene has no light"), std::string::npos);
  auto lit = quad_doc();
  lit.j["materials"][0]["emissiveFactor"] = {1, 1, 1};
  EXPECT_TRUE(load(lit).stats.warnings.empty());
}

// glTF 2.0 §3.9.2: COLOR_0 multiplies the base colour, alpha included (normalized unsigned bytes
// here); with alphaMode MASK its alpha enters the test (§3.9.4).
TEST(GltfLoader, VertexColoursMultiplyTheBaseColourAndItsAlpha) {
  auto d = quad_doc();
  const size_t at = d.bin.size();
  test::append<uint8_t>(d.bin, {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 0, 255, 255, 255, 128});
  d.j["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", at}, {"byteLength", 16}});
  d.j["accessors"].push_back(
      {{"bufferView", 3}, {"componentType", 5121}, {"normalized", true}, {"count", 4}, {"type", "VEC4"}});
  d.j["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 3;
  d.j["materials"][0]["pbrMetallicRoughness"]["baseColorFactor"] = {0.5, 0.5, 0.5, 1.0};
  d.j["materials"][0]["alphaMode"] = "MASK";
  d.j["materials"][0]["emissiveFactor"] = {1, 1, 1};  // lit, so the only warning would be COLOR_0's
  const Scene s = load(d);
  EXPECT_TRUE(s.stats.warnings.empty()) << s.stats.warnings.front();
  ASSERT_EQ(s.colors.size(), s.positions.size());
  for (size_t v = 0; v < s.positions.size(); ++v) {  // flat normals unweld: find each corner by position
    const vec3 p = s.positions[v];
    const vec4 want = p == vec3(0, 0, 0)   ? vec4(1, 0, 0, 1)
                      : p == vec3(1, 0, 0) ? vec4(0, 1, 0, 1)
                      : p == vec3(1, 1, 0) ? vec4(0, 0, 1, 0)
                                           : vec4(1, 1, 1, 128.0f / 255.0f);
    EXPECT_EQ(s.colors[v], want) << "vertex " << v;
  }
  // Triangle 0 is corners (0, 1, 2): at its centroid the colour is the mean of three.
  const SurfacePoint c = interpolate_surface(s, 0, 1.0f / 3.0f, 1.0f / 3.0f);
  const SurfaceMaterial m = evaluate_material(s, c);
  EXPECT_NEAR(m.albedo.r, 0.5f / 3.0f, 1e-6f);
  EXPECT_NEAR(m.albedo.g, 0.5f / 3.0f, 1e-6f);
  EXPECT_NEAR(m.albedo.b, 0.5f / 3.0f, 1e-6f);
  EXPECT_NEAR(base_color_alpha(s, 0, 1.0f / 3.0f, 1.0f / 3.0f), 2.0f / 3.0f, 1e-6f);
  EXPECT_FALSE(surface_masked(s, 0, 0.0f, 0.0f));  // corner 0: alpha 1
  EXPECT_TRUE(surface_masked(s, 0, 0.0f, 1.0f));   // corner 2: COLOR_0 alpha 0 < 0.5
}

}  // namespace
}  // namespace vct
