// `vct bench` end to end at a tiny size: bench.json holds every CPU stage time, the stage groups
// (ratio = CPU / GL when GL ran, or a note when it did not) and the path tracer beside raw Embree.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include "cli_run_util.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

TEST(BenchCli, WritesBenchJsonWithRatios) {
  const auto dir = test::fresh_dir("bench");
  ASSERT_EQ(test::run_vct("bench --grid 16 --width 32 --height 24 --repeat 1 --pt-spp 1 --raw-rays 100000 --threads 2 "
                          "--validate-spp 4 --validate-grid 32 --out '" +
                          dir.string() + "'"),
            0);
  const nlohmann::json j = nlohmann::json::parse(test::slurp(dir / "bench.json"));
  // --out is a finished run directory (ref/io/run_dir.h): run.json complete, no marker, no lock.
  const nlohmann::json run = nlohmann::json::parse(test::slurp(dir / "run.json"));
  EXPECT_EQ(run["command"], "bench");
  EXPECT_EQ(run["status"], "complete");
  EXPECT_FALSE(fs::exists(dir / "INCOMPLETE"));
  EXPECT_FALSE(fs::exists(dir / ".vct-lock"));
  EXPECT_EQ(j["settings"]["vct"]["grid"], 16);
  const double total = j["ref"]["total"].get<double>();
  EXPECT_GT(total, 0.0);
  EXPECT_GT(j["ref"]["indirect_cones"].get<double>(), 0.0);
  EXPECT_LE(j["ref"]["indirect_cones"].get<double>(), total);
  ASSERT_EQ(j["groups"].size(), 9u);
  const auto& last = j["groups"][8];
  EXPECT_EQ(last["name"], "total");
  EXPECT_DOUBLE_EQ(last["ref_ms"].get<double>(), total);
  // The oracle's own extras (no GL counterpart, so no ratio) and the frame without them.
  const auto& extras = j["groups"][6];
  const auto& vct_work = j["groups"][7];
  EXPECT_EQ(extras["name"], "oracle extras (ref only)");
  EXPECT_GT(extras["ref_ms"].get<double>(), 0.0);
  EXPECT_EQ(vct_work["name"], "total, VCT work");
  EXPECT_NEAR(vct_work["ref_ms"].get<double>() + extras["ref_ms"].get<double>(), total, 1e-6 * total);
  if (!j["gl"].is_null()) {
    EXPECT_TRUE(extras["ref_over_gl"].is_null());
  }
  if (j["gl"].is_null()) {
    EXPECT_TRUE(j.contains("gl_note"));
  } else {
    EXPECT_NEAR(last["ref_over_gl"].get<double>(), total / j["gl"]["total"].get<double>(), 1e-9);
  }
  // The validate row: a whole validate at the bench's sizes, its phases summing to its parts.
  const auto& v = j["validate"];
  ASSERT_TRUE(v.contains("phases")) << v.dump();
  EXPECT_EQ(v["settings"]["width"], 32);
  EXPECT_EQ(v["settings"]["spp"], 4);
  EXPECT_EQ(v["settings"]["grid"], 32);  // --validate-grid, not the bench's own grid
  // validate's own memory prediction beside its peak (docs/performance.md, "Validate's memory").
  EXPECT_GT(v["memory"]["predicted_bytes"].get<double>(), 100.0 * (1 << 20));
  EXPECT_GT(v["memory"]["peak_rss_bytes"].get<double>(), 100.0 * (1 << 20));
  double render = 0.0, other = 0.0;
  // A group's member tasks ran side by side inside the group's time: counted once, as the group.
  for (const auto& ph : v["phases"]["phases"])
    if (!ph.value("concurrent", false)) (ph["render"].get<bool>() ? render : other) += ph["ms"].get<double>();
  EXPECT_GT(render, 0.0);
  EXPECT_NEAR(v["phases"]["render_ms"].get<double>(), render, 1e-6);
  EXPECT_NEAR(v["phases"]["other_ms"].get<double>(), other, 1e-6);
  EXPECT_LE(render + other, v["wall_ms"].get<double>());  // the phases happen inside the child's wall time
  const auto& pt = j["path_tracer"];
  EXPECT_EQ(pt["raw_rays"], 100000);
  EXPECT_GT(pt["raw_intersect_rays_per_second"].get<double>(), 0.0);
  EXPECT_EQ(pt["primary_only"]["primary"], 32 * 24);  // one camera ray per pixel and pass
  EXPECT_EQ(pt["primary_only"]["secondary"], 0);      // max_depth 0: no continuation rays
  const double f = pt["full_paths"]["fraction_of_raw_intersect"].get<double>();
  EXPECT_GT(f, 0.0);
  EXPECT_NEAR(f, pt["full_paths"]["rays_per_second"].get<double>() / pt["raw_intersect_rays_per_second"].get<double>(),
              1e-9);
}

// A second writer of the same --out is refused before any measurement, with the holder's pid.
// The holder is this test, locking as a vct process does, so the timing cannot race.
TEST(BenchCli, LockedOutIsRefusedBeforeMeasuring) {
  const auto dir = test::fresh_dir("bench_locked");
  const int fd = ::open((dir / ".vct-lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const std::string pid = std::to_string(::getpid());
  ASSERT_EQ(::write(fd, pid.data(), pid.size()), ssize_t(pid.size()));
  const test::VctOutput r = test::run_vct_captured("bench --no-gl --no-pt --no-validate --grid 16 --width 32 --height 24 "
                                                   "--repeat 1 --threads 1 --out '" + dir.string() + "'");
  ::close(fd);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_NE(r.err.find("another vct process (pid " + pid + ") is writing this run directory"), std::string::npos)
      << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;  // refused before the first frame was timed
  EXPECT_FALSE(fs::exists(dir / "bench.json"));
}

}  // namespace
}  // namespace vct
