// The glTF fuzz target's structure-aware mutator (fuzz/gltf_mutator.h), run here as a small
// fuzzer in the ordinary build: mutations of a zoo scene keep mostly to valid JSON, reach the
// loader's limits (nesting, edge numbers, out-of-range indices, URIs outside the scene), and every
// result loads or is refused with InputError, nothing else.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../../fuzz/fuzz_inputs.h"
#include "../../fuzz/gltf_mutator.h"
#include "core/error.h"
#include "scene/gltf_loader.h"
#include "io/bounded_json.h"

namespace vct {
namespace {

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

constexpr size_t kMaxLen = 1 << 20;  // scripts/fuzz.sh -max_len for gltf

TEST(GltfMutator, IsDeterministicAndLeavesNonJsonToByteMutation) {
  const std::string doc = R"({"asset":{"version":"2.0"},"nodes":[{"mesh":0}],"meshes":[]})";
  const auto a = fuzz::mutate_gltf_json(doc, 7, kMaxLen), b = fuzz::mutate_gltf_json(doc, 7, kMaxLen);
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(*a, *b);
  EXPECT_NE(*a, doc);
  EXPECT_FALSE(fuzz::mutate_gltf_json("glTF\x02\0\0\0", 7, kMaxLen).has_value());
  EXPECT_FALSE(fuzz::mutate_gltf_json("{\"asset\": ", 7, kMaxLen).has_value());
  EXPECT_FALSE(fuzz::mutate_gltf_json(std::string(600, '[') + std::string(600, ']'), 7, kMaxLen).has_value());
  EXPECT_FALSE(fuzz::mutate_gltf_json(doc, 7, 10).has_value());  // longer than max_size
}

// 400 mutations of plane_spot.gltf (19 KB): each loads or throws InputError (a crash or another
// exception fails the test); the mix reaches the limits the mutator is for.
TEST(GltfMutator, MutatedZooSceneLoadsOrIsRefused) {
  const std::string seed = read_text(std::filesystem::path(VCT_SOURCE_DIR) / "scenes" / "plane_spot.gltf");
  ASSERT_FALSE(seed.empty());
  int produced = 0, still_json = 0, too_deep = 0, loaded = 0, refused = 0;
  for (uint32_t s = 1; s <= 400; ++s) {
    const auto m = fuzz::mutate_gltf_json(seed, s, kMaxLen);
    if (!m) continue;
    ++produced;
    if (!nlohmann::json::parse(*m, nullptr, false).is_discarded()) ++still_json;
    if (scan_json_nesting(*m).exceeded) ++too_deep;
    try {
      load_gltf_text(*m, "mutated.gltf", fuzz::scratch_dir().string());
      ++loaded;
    } catch (const InputError&) {
      ++refused;
    }
  }
  std::printf("mutated %d of 400: %d still JSON, %d nested past the limit, %d loaded, %d refused\n", produced,
              still_json, too_deep, loaded, refused);
  // Seeds only fail to produce when a mutation changes nothing (a delete on an empty array ...).
  EXPECT_GE(produced, 300);
  EXPECT_EQ(loaded + refused, produced);
  // Raw tokens (NaN, 1e999 ...) are the only syntax the mutator breaks: about 1 in 9 mutations,
  // 1-4 per input, at most one spliced per input.
  EXPECT_GE(still_json, produced / 2);
  EXPECT_GE(too_deep, 5);   // nesting past kMaxJsonNesting: about 1 in 9 x 3/7 of the depths
  EXPECT_GE(loaded, 20);    // some mutations leave a loadable scene ...
  EXPECT_GE(refused, 100);  // ... most do not
}

// The accessor/index graph rewired (indices kept in range, fuzz/gltf_mutator.h case 8) over every
// committed scene: each mutation loads or is refused with InputError, never a crash (issue 38's
// morph targets, light and COLOR_0 cases were of this kind). 25 seeds per scene keep it short;
// VCT_MUTATOR_SEEDS=N runs a longer campaign (docs/performance.md, "Hostile input, bounded").
TEST(GltfMutator, EveryZooSceneMutatedLoadsOrIsRefused) {
  const char* seeds_env = std::getenv("VCT_MUTATOR_SEEDS");
  const uint32_t seeds = seeds_env ? uint32_t(std::strtoul(seeds_env, nullptr, 10)) : 25u;
  int produced = 0, loaded = 0, refused = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(VCT_SOURCE_DIR) / "scenes")) {
    if (e.path().extension() != ".gltf") continue;
    const std::string seed = read_text(e.path());
    for (uint32_t s = 1; s <= seeds; ++s) {
      const auto m = fuzz::mutate_gltf_json(seed, s * 7919u, kMaxLen);
      if (!m) continue;
      ++produced;
      try {
        load_gltf_text(*m, e.path().filename().string(), fuzz::scratch_dir().string());
        ++loaded;
      } catch (const InputError&) {
        ++refused;
      }
    }
  }
  std::printf("zoo: mutated %d inputs: %d loaded, %d refused\n", produced, loaded, refused);
  EXPECT_EQ(loaded + refused, produced);
  EXPECT_GE(produced, 100);
}

}  // namespace
}  // namespace vct
