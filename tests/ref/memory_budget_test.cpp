// The up-front memory check: hand-computed estimates and the refusal message.
#include <gtest/gtest.h>

#include "core/error.h"
#include "core/memory_budget.h"

namespace vct {
namespace {

TEST(MemoryBudget, EstimateMatchesHandCount) {
  Settings s;
  s.vct.grid = 64;
  s.vct.anisotropic = false;
  s.vct.bounces = 1;
  s.vct.reduction = Reduction::ExactMean;
  s.vct.width = s.vct.height = 100;
  s.vct.shadow_map_size = 50;
  s.pt.width = s.pt.height = 10;
  const MemoryEstimate e = estimate_memory(s);
  const uint64_t n3 = 64ull * 64 * 64;
  EXPECT_EQ(e.voxels, 52 * n3 + 16 * n3 / 7);
  EXPECT_EQ(e.images, 100ull * 100 * 46 * 4 + 50ull * 50 * 4);
  EXPECT_EQ(e.path_tracer, 100ull * 16 * 8);
  s.vct.anisotropic = true;
  s.vct.bounces = 2;
  EXPECT_EQ(estimate_memory(s).voxels, 52 * n3 + 2 * (16 * n3 / 7 + 96 * n3 / 7));
}

TEST(MemoryBudget, RefusesWithTheNeededAmount) {
  Settings s;
  s.vct.grid = 512;
  s.vct.anisotropic = true;
  const uint64_t need = estimate_memory(s).total();
  EXPECT_GT(need, 8ull << 30);  // 512^3 anisotropic is several GiB
  EXPECT_NO_THROW(check_memory_budget(s, need));
  try {
    check_memory_budget(s, 4ull << 30);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("need about " + format_bytes(need)), std::string::npos) << msg;
    EXPECT_NE(msg.find("has 4.0 GiB"), std::string::npos) << msg;
    EXPECT_NE(msg.find("grid 512^3 anisotropic"), std::string::npos) << msg;
  }
  EXPECT_NO_THROW(check_memory_budget(s, 0));  // unknown machine size: no check
}

TEST(MemoryBudget, ValidateSettingsRefusesHugeImagesOnThisMachine) {
  Settings s;
  s.vct.width = s.vct.height = 16384;
  s.pt.width = s.pt.height = 16384;
  // 16384^2 pixels * (184 + 128) B = 78 GiB: more than any machine these tests run on.
  ASSERT_GT(estimate_memory(s).total(), physical_memory_bytes());
  EXPECT_THROW(validate_settings(s), InputError);
  EXPECT_NO_THROW(validate_settings(Settings{}));
}

TEST(MemoryBudget, FormatsBytes) {
  EXPECT_EQ(format_bytes(1536), "1.5 KiB");
  EXPECT_EQ(format_bytes(300ull << 20), "300.0 MiB");
  EXPECT_EQ(format_bytes(3ull << 30), "3.0 GiB");
}

}  // namespace
}  // namespace vct
