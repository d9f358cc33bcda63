// An engine's conventions stated as settings (issue 21: diffuse_cone_set, cone_tangent_frame,
// shadow_view_proj, shadow_ortho_box) through the real binary: the reference renders with them,
// malformed text is bad input (exit 2), and the GL backend, which runs the oracle's own cone set
// and light frusta, refuses each with exit 2 and no run directory left behind.
#include <gtest/gtest.h>

#include "cli_run_util.h"

namespace vct::test {
namespace {

const char* kSmall = "--width 16 --height 16 --grid 16 --set shadow_map_size=64";

TEST(EngineSettingsCli, ReferenceRendersTheSourceDesignsCones) {
  const fs::path dir = fresh_dir("engine_settings_ref");
  EXPECT_EQ(run_vct(std::string("render --backend ref ") + kSmall +
                    " --set 'diffuse_cone_set=0,0,1,30,1 1,0,1,30,1 -1,0,1,30,1 0,1,1,30,1 0,-1,1,30,1'"
                    " --set cone_tangent_frame=cross_hint --set cone_start=normal --set cone_offset_voxels=2"
                    " --set cone_axis_offset_voxels=2 --set cone_quality=0.7 --out '" +
                    (dir / "a").string() + "'"),
            0);
  EXPECT_EQ(run_vct(std::string("render --backend ref ") + kSmall + " --set 'diffuse_cone_set=0,0,1,30' --out '" +
                    (dir / "b").string() + "'"),
            2);
  EXPECT_EQ(run_vct(std::string("render --backend ref ") + kSmall + " --set 'shadow_view_proj=0:1,2' --out '" +
                    (dir / "c").string() + "'"),
            2);
  EXPECT_EQ(run_vct(std::string("render --backend ref ") + kSmall + " --set cone_axis_offset_voxels=2 --out '" +
                    (dir / "d").string() + "'"),
            2);  // needs cone_start = normal
  EXPECT_FALSE(fs::exists(dir / "b" / "run.json"));
}

TEST(EngineSettingsCli, GlRefusesTheEnginesConeSetAndMatrices) {
  const fs::path dir = fresh_dir("engine_settings_gl");
  const char* refused[] = {"'diffuse_cone_set=0,0,1,30,1'", "cone_tangent_frame=cross_hint",
                           "'shadow_view_proj=0:1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1'"};
  int k = 0;
  for (const char* setting : refused) {
    const fs::path out = dir / std::to_string(k++);
    const int rc = run_vct(std::string("render --backend gl ") + kSmall + " --set " + setting + " --out '" +
                           out.string() + "'");
    if (rc == 3) GTEST_SKIP() << "no GL context";
    EXPECT_EQ(rc, 2) << setting;
    EXPECT_FALSE(fs::exists(out / "run.json")) << setting;
  }
}

}  // namespace
}  // namespace vct::test
