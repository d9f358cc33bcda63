// A run directory reopened for writing (the rerun after a kill -9) starts clean: temporaries a
// killed writer left (write_atomically's ".tmp-<pid>-<name>", anywhere below) are removed once
// the lock is held, so the finished run holds exactly the files an uninterrupted one does.
#include "io/run_dir.h"

#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>

namespace vct {
namespace {

namespace fs = std::filesystem;

TEST(RunDir, RerunRemovesTemporariesOfAKilledWriter) {
  const fs::path dir = fs::temp_directory_path() / ("vct-run-dir-test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "explain");
  std::ofstream(dir / "explain" / ".tmp-17344-explain.png") << "half";
  std::ofstream(dir / "explain" / "explain.png") << "whole";
  std::ofstream(dir / "notes.txt") << "kept";
  {
    RunDir run(dir.string(), RunRole::Run);
    EXPECT_FALSE(fs::exists(dir / "explain" / ".tmp-17344-explain.png"));
    EXPECT_TRUE(fs::exists(dir / "explain" / "explain.png"));
    EXPECT_TRUE(fs::exists(dir / "notes.txt"));
    run.finish();
  }
  // A directory opened to read or as a part of a run is left as it is.
  std::ofstream(dir / ".tmp-1-x") << "x";
  { RunDir part(dir.string()); }
  EXPECT_TRUE(fs::exists(dir / ".tmp-1-x"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace vct
