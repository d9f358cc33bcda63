#!/usr/bin/env bash
# The sanitizer part of CI (.ci/run calls it after scripts/test.sh):
#  1. ASan + UBSan build (-DVCT_SANITIZE=ON) in build-asan, the whole ctest suite there (LSan on);
#  2. TSan build (-DVCT_TSAN=ON, parallel_for on std::thread so TSan sees every sync) in
#     build-tsan, the CPU reference and path tracer test binaries (ref_tests, pt_tests).
# Prints the wall time of each part. Assumes scripts/setup.sh has installed the packages.
#   scripts/sanitize.sh [asan|tsan]   (default: both)
set -euo pipefail
cd "$(dirname "$0")/.."
JOBS=$(nproc)
what=${1:-all}
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1"

configure() {  # dir, extra cmake args...
  local dir=$1
  shift
  [ -f "$dir/build.ninja" ] || cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DVCT_BUILD_BENCH=OFF "$@"
}

timed() {  # label, command...
  local label=$1 t0=$SECONDS
  shift
  "$@"
  echo "sanitize: $label took $((SECONDS - t0)) s"
}

asan() {
  configure build-asan -DVCT_SANITIZE=ON
  timed "ASan+UBSan build" cmake --build build-asan -j "$JOBS"
  # Everything, LeakSanitizer on (GL tests included: Mesa llvmpipe passes it too).
  timed "ASan+UBSan tests" env ASAN_OPTIONS="detect_leaks=1" \
    ctest --test-dir build-asan --output-on-failure -j "$JOBS"
}

tsan() {
  configure build-tsan -DVCT_TSAN=ON -DVCT_BUILD_GL=OFF
  timed "TSan build" cmake --build build-tsan -j "$JOBS" --target ref_tests pt_tests
  timed "TSan ref_tests" build-tsan/bin/ref_tests --gtest_brief=1
  timed "TSan pt_tests" build-tsan/bin/pt_tests --gtest_brief=1
}

case $what in
  asan) asan ;;
  tsan) tsan ;;
  all) asan && tsan ;;
  *) echo "usage: scripts/sanitize.sh [asan|tsan]" >&2; exit 2 ;;
esac
