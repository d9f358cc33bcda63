// parallel_tasks (core/parallel_tasks.h): every task runs once whatever the thread count, and a
// throwing task's exception reaches the caller — the lowest index's, keeping its type — instead
// of leaving the OpenMP region (which would end the process).
#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/parallel.h"
#include "core/parallel_tasks.h"

namespace vct {
namespace {

class ParallelTasks : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override { set_thread_count(GetParam()); }
  void TearDown() override { set_thread_count(0); }
};

TEST_P(ParallelTasks, EveryTaskRunsOnceIntoItsOwnSlot) {
  std::vector<int> runs(37, 0);
  parallel_tasks(int64_t(runs.size()), [&](int64_t i) { runs[size_t(i)] += int(i) + 1; });
  for (size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i], int(i) + 1) << i;
}

TEST_P(ParallelTasks, TheLowestIndexErrorIsRethrownWithItsTypeAfterAllTasksRan) {
  std::atomic<int> ran{0};
  try {
    parallel_tasks(40, [&](int64_t i) {
      ++ran;
      if (i == 31) throw std::runtime_error("task 31");
      if (i == 7) throw InputError("file_7.exr", "task 7");
      if (i == 12) throw EnvironmentError("task 12");
    });
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("task 7"), std::string::npos) << e.what();
  }
  EXPECT_EQ(ran.load(), 40);  // the others still wrote their files
}

TEST_P(ParallelTasks, NoTasksIsNothing) {
  int calls = 0;
  parallel_tasks(0, [&](int64_t) { ++calls; });
  EXPECT_EQ(calls, 0);
}

INSTANTIATE_TEST_SUITE_P(Threads, ParallelTasks, ::testing::Values(1, 2, 8));

}  // namespace
}  // namespace vct
