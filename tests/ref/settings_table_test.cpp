// The settings table: ranges as declared (closed, open, powers of two, lists), text parsed by
// the field's type, unknown keys and malformed values refused with the key in the message.
#include "core/settings_table.h"

#include <gtest/gtest.h>

#include "core/error.h"

namespace vct {
namespace {

std::string error_of(const Settings& s) {
  try {
    validate_settings(s);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SettingsTable, RangesAreTheDeclaredOnes) {
  Settings s;
  s.vct.grid = 48;
  EXPECT_EQ(error_of(s), "grid must be a power of two in 16..512 (got 48)");
  s.vct.grid = 64;
  s.vct.diffuse_aperture_deg = 180.0f;  // open at both ends
  EXPECT_EQ(error_of(s), "diffuse_aperture_deg must be in (0, 180) (got 180)");
  s.vct.diffuse_aperture_deg = 30.0f;
  s.vct.cone_quality = 4.0f;  // (0.01, 4]: 4 is allowed
  EXPECT_EQ(error_of(s), "");
  s.vct.msaa_samples = 2;
  EXPECT_EQ(error_of(s), "msaa_samples must be 1, 4 or 8 (got 2)");
  s.vct.msaa_samples = 4;
  s.pt.spp = 0;
  EXPECT_EQ(error_of(s), "path tracer spp must be >= 1 (got 0)");
}

TEST(SettingsTable, TextIsParsedByTheFieldsType) {
  const Settings base;
  EXPECT_EQ(with_setting(base, "grid", "32", "--set").vct.grid, 32);
  EXPECT_EQ(with_setting(base, "vct.anisotropic", "true", "--set").vct.anisotropic, true);
  EXPECT_EQ(with_setting(base, "reduction", "cas", "--set").vct.reduction, Reduction::CasRgba8);
  EXPECT_EQ(with_setting(base, "pt.spp", "9", "--set").pt.spp, 9);
  EXPECT_FLOAT_EQ(with_setting(base, "cone_quality", "0.25", "--set").vct.cone_quality, 0.25f);
  EXPECT_THROW(with_setting(base, "grid", "32.5", "--set"), InputError);   // not an integer
  EXPECT_THROW(with_setting(base, "anisotropic", "1", "--set"), InputError);  // not a boolean
  EXPECT_THROW(with_setting(base, "reduction", "mean", "--set"), InputError);
  try {
    with_setting(base, "gird", "32", "--set");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--set: unknown setting 'gird' (vct settings lists them)");
  }
}

TEST(SettingsTable, ValuesPrintAsPeopleWriteThem) {
  EXPECT_EQ(value_text(nlohmann::json(0.0005f)), "0.0005");
  EXPECT_EQ(value_text(nlohmann::json(1.7320508f)), "1.7320508");
  EXPECT_EQ(value_text(nlohmann::json("gltf")), "gltf");
  EXPECT_EQ(value_text(nlohmann::json(64)), "64");
}

}  // namespace
}  // namespace vct
