#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "core/settings.h"

namespace vct {

TEST(Settings, JsonRoundTripKeepsEveryField) {
  Settings s;
  s.vct.grid = 64;
  s.vct.light_model = LightModel::Seed;
  s.vct.reduction = Reduction::CasRgba8;
  s.pt.spp = 17;
  const nlohmann::json j = s;
  const Settings back = j.get<Settings>();
  EXPECT_EQ(back.vct.grid, 64);
  EXPECT_EQ(back.vct.light_model, LightModel::Seed);
  EXPECT_EQ(back.vct.reduction, Reduction::CasRgba8);
  EXPECT_EQ(back.pt.spp, 17);
  EXPECT_EQ(nlohmann::json(back), j);
}

TEST(Settings, UnknownKeyIsRefused) {
  nlohmann::json j = {{"vct", {{"gird", 64}}}};
  EXPECT_THROW(j.get<Settings>(), InputError);
}

// A number an int field cannot hold must not convert (undefined for 1e300) or wrap: 2^32 + 16
// would become grid 16 and pass validation. An integral float is still an integer.
TEST(Settings, IntegerFieldsRefuseNumbersTheyCannotHold) {
  for (const nlohmann::json& bad : {nlohmann::json(1e300), nlohmann::json(-1e300), nlohmann::json(4294967312LL),
                                    nlohmann::json(-2147483649LL), nlohmann::json(16.5),
                                    nlohmann::json(18446744073709551615ULL)}) {
    SCOPED_TRACE(bad.dump());
    EXPECT_THROW((nlohmann::json{{"vct", {{"grid", bad}}}}.get<Settings>()), InputError);
  }
  EXPECT_THROW((nlohmann::json{{"pt", {{"seed", -1}}}}.get<Settings>()), InputError);  // uint32_t
  EXPECT_EQ((nlohmann::json{{"vct", {{"grid", 64.0}}}}.get<Settings>().vct.grid), 64);
  EXPECT_EQ((nlohmann::json{{"pt", {{"seed", 4294967295ULL}}}}.get<Settings>().pt.seed), 4294967295u);
  EXPECT_EQ((nlohmann::json{{"vct", {{"frame", -2147483648LL}}}}.get<Settings>().vct.frame), -2147483648LL);
}

TEST(Settings, BadEnumNamesTheAllowedValues) {
  nlohmann::json j = {{"vct", {{"light_model", "sun"}}}};
  try {
    (void)j.get<Settings>();
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gltf|seed"), std::string::npos) << e.what();
  }
}

// GL faults are no setting (gl/gl_faults.h, --gl-fault): the old key is an unknown key.
TEST(Settings, GlFaultIsNotASetting) {
  nlohmann::json j = {{"vct", {{"gl_fault", "wrong_mip"}}}};
  try {
    (void)j.get<Settings>();
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gl_fault"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(nlohmann::json(Settings())["vct"].contains("gl_fault"));
}

TEST(Settings, ValidationRejectsNonPowerOfTwoGrid) {
  Settings s;
  s.vct.grid = 100;
  EXPECT_THROW(validate_settings(s), InputError);
  s.vct.grid = 128;
  EXPECT_NO_THROW(validate_settings(s));
}

TEST(Settings, DiffuseConeSetRoundTripsAndIsRangeChecked) {
  Settings s;
  EXPECT_EQ(s.vct.diffuse_cone_count, 5);  // the seed's set
  EXPECT_EQ(s.vct.diffuse_cone_tilt_deg, 45.0f);
  s.vct.diffuse_cone_count = 9;
  s.vct.diffuse_cone_tilt_deg = 60.0f;
  const Settings back = nlohmann::json(s).get<Settings>();
  EXPECT_EQ(back.vct.diffuse_cone_count, 9);
  EXPECT_EQ(back.vct.diffuse_cone_tilt_deg, 60.0f);
  EXPECT_NO_THROW(validate_settings(back));
  const auto refused = [](int count, float tilt, const char* key) {
    Settings bad;
    bad.vct.diffuse_cone_count = count;
    bad.vct.diffuse_cone_tilt_deg = tilt;
    try {
      validate_settings(bad);
      ADD_FAILURE() << "expected InputError for " << count << " cones at " << tilt;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  refused(0, 45.0f, "diffuse_cone_count");
  refused(17, 45.0f, "diffuse_cone_count");
  refused(5, 0.0f, "diffuse_cone_tilt_deg");
  refused(5, 90.0f, "diffuse_cone_tilt_deg");
  refused(5, std::nanf(""), "diffuse_cone_tilt_deg");
  for (int count : {1, 16}) {
    Settings ok;
    ok.vct.diffuse_cone_count = count;
    ok.vct.diffuse_cone_tilt_deg = 89.5f;
    EXPECT_NO_THROW(validate_settings(ok)) << count;
  }
}

}  // namespace vct
