// Scale (issue 9): a scene of a million triangles, generated here as a .glb (never committed),
// loads through the real loader and voxelizes; the count of covered voxels is checked against the
// hand-computed footprint of the flat sheet it is.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gltf_test_doc.h"
#include "scene/gltf_loader.h"
#include "stages/voxelize.h"

namespace vct {
namespace {

// A Q x Q grid of quads (2 Q^2 triangles) covering x, z in [0.01, 1.99] at height y0.
std::string sheet_glb(int q, float y0) {
  std::vector<float> pos;
  std::vector<uint32_t> idx;
  for (int j = 0; j <= q; ++j)
    for (int i = 0; i <= q; ++i) {
      pos.insert(pos.end(), {0.01f + 1.98f * float(i) / float(q), y0, 0.01f + 1.98f * float(j) / float(q)});
    }
  for (int j = 0; j < q; ++j)
    for (int i = 0; i < q; ++i) {
      const uint32_t a = uint32_t(j * (q + 1) + i), b = a + 1, c = a + uint32_t(q + 1), d = c + 1;
      idx.insert(idx.end(), {a, c, b, b, c, d});
    }
  const size_t pos_bytes = pos.size() * 4, idx_bytes = idx.size() * 4;
  std::string bin(pos_bytes + idx_bytes, '\0');
  std::memcpy(&bin[0], pos.data(), pos_bytes);
  std::memcpy(&bin[pos_bytes], idx.data(), idx_bytes);
  const nlohmann::json doc = {
      {"asset", {{"version", "2.0"}}},
      {"scene", 0},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
      {"buffers", {{{"byteLength", bin.size()}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", pos_bytes}, {"target", 34962}},
        {{"buffer", 0}, {"byteOffset", pos_bytes}, {"byteLength", idx_bytes}, {"target", 34963}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", pos.size() / 3}, {"type", "VEC3"},
         {"min", {0.01f, y0, 0.01f}}, {"max", {1.99f, y0, 1.99f}}},
        {{"bufferView", 1}, {"componentType", 5125}, {"count", idx.size()}, {"type", "SCALAR"}}}}};
  std::string json = doc.dump();
  json.append((4 - json.size() % 4) % 4, ' ');
  auto u32 = [](uint32_t v) { return std::string(reinterpret_cast<const char*>(&v), 4); };
  const std::string body = u32(uint32_t(json.size())) + "JSON" + json + u32(uint32_t(bin.size())) + "BIN" +
                           std::string(1, '\0') + bin;
  return "glTF" + u32(2) + u32(uint32_t(12 + body.size())) + body;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(Scale, MillionTriangleSheetLoadsAndVoxelizes) {
  const int q = 708;  // 2 * 708^2 = 1,002,528 triangles
  const float y0 = 1.03125f;
  const std::string path = test::write_file("million.glb", sheet_glb(q, y0));
  auto t0 = std::chrono::steady_clock::now();
  Scene scene = load_gltf_file(path);
  const double load_s = seconds_since(t0);
  ASSERT_EQ(scene.triangle_count(), size_t(2 * q * q));
  // Cube [-1, 3]^3 at 64^3 (voxel 1/16): the sheet lies mid-layer (y index 32.5) and covers x, z
  // voxel indices 16.16 .. 47.84, i.e. columns 16..47: exactly 32 x 32 voxels in one layer.
  scene.volume.origin = vec3(-1.0f);
  scene.volume.size = 4.0f;
  scene.volume.overridden = true;
  t0 = std::chrono::steady_clock::now();
  const Voxelization v = voxelize_conservative(scene, 64);
  const double vox_s = seconds_since(t0);
  EXPECT_EQ(v.covered, 32 * 32);
  EXPECT_EQ(v.occupancy.voxel(16, 32, 16)[0], 1.0f);
  EXPECT_EQ(v.occupancy.voxel(47, 32, 47)[0], 1.0f);
  EXPECT_EQ(v.occupancy.voxel(16, 31, 16)[0], 0.0f);
  EXPECT_GE(v.fragments.size(), scene.triangle_count());  // every triangle lands in >= 1 voxel
  std::printf("1,002,528 triangles: load %.2f s, conservative voxelization 64^3 %.2f s, %zu fragments\n", load_s,
              vox_s, v.fragments.size());
}

}  // namespace
}  // namespace vct
