// A Blender user's export through the CLI (issue 35; docs/scenes.md, "Blender exports"): the
// Standard (photometric) file is auto-exposed by whole stops and says so, the Unitless one keeps
// scale 1, both take the 16:9 camera's width from the height, and forcing both sizes warns.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_run_util.h"

namespace vct {
namespace {

using nlohmann::json;

std::string blender(const std::string& mode) {
  return "'" + std::string(VCT_SOURCE_DIR) + "/scenes/blender/blender_room_" + mode + ".gltf'";
}

json render(const std::string& mode, const std::string& size, test::VctOutput& r) {
  const auto out = test::fresh_dir("blender_" + mode);
  r = test::run_vct_captured("render " + blender(mode) + " --backend ref " + size + " --grid 16 --set shadow_map_size=128 --out '" +
                             out.string() + "'");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return json::parse(test::slurp(out / "run.json"));
}

TEST(BlenderExportCli, StandardIsAutoExposedAndUnitlessIsNot) {
  test::VctOutput r;
  const json standard = render("standard", "--height 18", r);
  // Meter 2100 lx at the centre (the hard spot aimed away from it counts by its flux share):
  // EV100 9.71, scale 2.08 / 2100 = 2^-9.97 -> -10 stops.
  EXPECT_EQ(standard["exposure"]["stops"], -10);
  EXPECT_EQ(standard["exposure"]["scale"].get<double>(), std::ldexp(1.0, -10));
  EXPECT_NE(r.err.find("vct: exposure: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("material 4 'Glass': KHR_materials_transmission ignored, rendered opaque with its base colour"),
            std::string::npos);
  EXPECT_EQ(standard["settings"]["vct"]["width"], 32);  // round(18 x 16/9)
  const json unitless = render("unitless", "--height 18", r);
  EXPECT_EQ(unitless["exposure"]["stops"], 0);  // 683x less light: inside the dead band
  EXPECT_EQ(unitless["exposure"]["scale"], 1.0);
  EXPECT_EQ(r.err.find("vct: exposure: "), std::string::npos) << r.err;
}

// `validate --sweep exposure=...` re-exposes the scene per value (docs/scenes.md, "Light units and
// exposure"): each row records its own exposure, and the path tracer's AOVs are scaled with it, so
// the direct light's relative bias is the same at -10 stops and unexposed.
TEST(BlenderExportCli, AnExposureSweepReExposesEachRow) {
  const auto out = test::fresh_dir("blender_sweep");
  const test::VctOutput r = test::run_vct_captured("validate " + blender("standard") +
                                                   " --height 18 --grid 16 --spp 2 --no-report --set shadow_map_size=128"
                                                   " --sweep exposure=auto,none --out '" + out.string() + "'");
  ASSERT_NE(r.exit_code, 2) << r.err;
  const json run = json::parse(test::slurp(out / "run.json"));
  const json& rows = run["sweeps"][0]["rows"];
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0]["exposure"]["scale"].get<double>(), std::ldexp(1.0, -10));
  EXPECT_EQ(rows[1]["exposure"]["mode"], "none");
  EXPECT_EQ(rows[1]["exposure"]["scale"].get<double>(), 1.0);
  for (const json& b : rows[1]["bias"])
    if (b["component"] == "direct") {
      for (const json& a : rows[0]["bias"]) {
        if (a["component"] == "direct") {
          EXPECT_NEAR(b["relative_bias"].get<double>(), a["relative_bias"].get<double>(), 1e-3);
        }
      }
    }
}

TEST(BlenderExportCli, ForcingBothSizesWarnsThatTheFramingChanges) {
  test::VctOutput r;
  const json run = render("unitless", "--width 16 --height 16", r);
  EXPECT_EQ(run["settings"]["vct"]["width"], 16);
  EXPECT_NE(r.err.find("the framing changes"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vct
