// validate's phase table (app/phase_times.h): wall and CPU time per phase, the report's parts with
// their CPU from part_times.json and the rest of the report child's CPU as "start-up and rest".
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../../app/phase_times.h"

namespace vct::app {
namespace {

namespace fs = std::filesystem;

TEST(PhaseTimes, APhaseRecordsTheCpuItBurnt) {
  PhaseTimes t;
  const int answer = t.time("spin", [] {
    const double start = process_cpu_ms();
    volatile double x = 0;
    while (process_cpu_ms() - start < 20.0) x = x + 1.0;  // at least 20 ms of CPU, however loaded
    return 42;
  });
  EXPECT_EQ(answer, 42);
  ASSERT_EQ(t.phases().size(), 1u);
  EXPECT_GE(t.phases()[0].cpu_ms, 20.0);
  EXPECT_GE(t.phases()[0].ms, 0.0);
  EXPECT_FALSE(t.phases()[0].render);
  EXPECT_DOUBLE_EQ(t.other_cpu_ms(), t.phases()[0].cpu_ms);
}

TEST(PhaseTimes, RenderAndOtherSplitsInWallAndCpu) {
  PhaseTimes t;
  t.add("render gl", 1000.0, true, 1500.0);
  t.add("render pt", 3000.0, true, 6000.0);
  t.add("write stage set ref", 400.0, false, 700.0);
  t.add("report: final images", 100.0);  // CPU not measured: counts 0, shown as "-"
  EXPECT_DOUBLE_EQ(t.render_ms(), 4000.0);
  EXPECT_DOUBLE_EQ(t.other_ms(), 500.0);
  EXPECT_DOUBLE_EQ(t.render_cpu_ms(), 7500.0);
  EXPECT_DOUBLE_EQ(t.other_cpu_ms(), 700.0);
  const nlohmann::json j = t.to_json();
  EXPECT_DOUBLE_EQ(j["other_cpu_ms"].get<double>(), 700.0);
  EXPECT_FALSE(j["phases"][3].contains("cpu_ms"));
  const std::string table = t.table();
  EXPECT_NE(table.find("      1.00 s    1.50 s  render gl  [render]"), std::string::npos) << table;
  EXPECT_NE(table.find("      0.10 s         -  report: final images"), std::string::npos) << table;
  EXPECT_NE(table.find("total: renders 4.00 s, everything else 0.50 s (12 % of the renders)"), std::string::npos)
      << table;
  EXPECT_NE(table.find("CPU time: renders 7.50 s, everything else 0.70 s (9 % of the renders)"), std::string::npos)
      << table;
}

TEST(PhaseTimes, AGroupCountsOnceAndItsTasksAreListedBesideIt) {
  PhaseTimes t;
  t.add("render ref", 2000.0, true, 3000.0);
  t.add("stage sets, comparison, bias (3 tasks on 2 threads)", 1500.0, false, 2800.0);
  t.add_concurrent("compare gl vs ref", 1400.0, 1300.0);
  t.add_concurrent("write stage set ref", 900.0, 850.0);
  t.add_concurrent("bias ref vs pt", 500.0, 480.0);
  EXPECT_DOUBLE_EQ(t.other_ms(), 1500.0);  // the tasks' overlapping times are not added again
  EXPECT_DOUBLE_EQ(t.other_cpu_ms(), 2800.0);
  const nlohmann::json j = t.to_json();
  EXPECT_TRUE(j["phases"][2]["concurrent"].get<bool>());
  EXPECT_FALSE(j["phases"][1].contains("concurrent"));
  const std::string table = t.table();
  EXPECT_NE(table.find("      0.90 s    0.85 s    | write stage set ref"), std::string::npos) << table;
  EXPECT_NE(table.find("total: renders 2.00 s, everything else 1.50 s (75 % of the renders)"), std::string::npos)
      << table;
}

TEST(PhaseTimes, ThreadCpuCountsTheCallingThread) {
  const double start = thread_cpu_ms();
  volatile double x = 0;
  while (thread_cpu_ms() - start < 10.0) x = x + 1.0;
  EXPECT_GE(thread_cpu_ms() - start, 10.0);
  EXPECT_GE(process_cpu_ms(), thread_cpu_ms());
}

std::string write_parts(const std::string& json) {
  const std::string path = (fs::temp_directory_path() / ("vct_part_times_" + std::to_string(::getpid()) + ".json")).string();
  std::ofstream(path) << json;
  return path;
}

TEST(PhaseTimes, ReportPartsAndTheRestOfTheChildsCpu) {
  const std::string path = write_parts(
      R"({"parts": [{"name": "final images", "ms": 300, "cpu_ms": 250}, {"name": "FLIP", "ms": 2000, "cpu_ms": 3900}]})");
  PhaseTimes t;
  EXPECT_TRUE(add_report_parts(t, path, 2600.0, 4500.0));
  ASSERT_EQ(t.phases().size(), 3u);
  EXPECT_EQ(t.phases()[1].name, "report: FLIP");
  EXPECT_DOUBLE_EQ(t.phases()[1].cpu_ms, 3900.0);
  EXPECT_EQ(t.phases()[2].name, "report: start-up and rest");
  EXPECT_DOUBLE_EQ(t.phases()[2].ms, 300.0);
  EXPECT_DOUBLE_EQ(t.phases()[2].cpu_ms, 350.0);
  fs::remove(path);
}

TEST(PhaseTimes, PartsWithoutCpuLeaveTheRestUnmeasured) {
  const std::string path = write_parts(R"({"parts": [{"name": "walkthrough", "ms": 100}]})");
  PhaseTimes t;
  EXPECT_TRUE(add_report_parts(t, path, 400.0, 900.0));
  ASSERT_EQ(t.phases().size(), 2u);
  EXPECT_LT(t.phases()[0].cpu_ms, 0.0);
  EXPECT_DOUBLE_EQ(t.phases()[1].ms, 300.0);
  EXPECT_LT(t.phases()[1].cpu_ms, 0.0);
  fs::remove(path);
  PhaseTimes missing;
  EXPECT_FALSE(add_report_parts(missing, path, 400.0, 900.0));
  ASSERT_EQ(missing.phases().size(), 1u);
  EXPECT_EQ(missing.phases()[0].name, "report");
  EXPECT_DOUBLE_EQ(missing.phases()[0].cpu_ms, 900.0);
}

}  // namespace
}  // namespace vct::app
