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
  // Meter 8150 lx at the centre: EV100 11.67, scale 2.08 / 8150 = 2^-11.93 -> -12 stops.
  EXPECT_EQ(standard["exposure"]["stops"], -12);
  EXPECT_EQ(standard["exposure"]["scale"].get<double>(), std::ldexp(1.0, -12));
  EXPECT_NE(r.err.find("vct: exposure: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("material 4 'Glass': KHR_materials_transmission ignored, rendered opaque with its base colour"),
            std::string::npos);
  EXPECT_EQ(standard["settings"]["vct"]["width"], 32);  // round(18 x 16/9)
  const json unitless = render("unitless", "--height 18", r);
  EXPECT_EQ(unitless["exposure"]["stops"], 0);  // 683x less light: inside the dead band
  EXPECT_EQ(unitless["exposure"]["scale"], 1.0);
  EXPECT_EQ(r.err.find("vct: exposure: "), std::string::npos) << r.err;
}

TEST(BlenderExportCli, ForcingBothSizesWarnsThatTheFramingChanges) {
  test::VctOutput r;
  const json run = render("unitless", "--width 16 --height 16", r);
  EXPECT_EQ(run["settings"]["vct"]["width"], 16);
  EXPECT_NE(r.err.find("the framing changes"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vct
