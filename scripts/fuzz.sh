#!/usr/bin/env bash
# Builds and runs the libFuzzer targets (fuzz/): installs clang-14, libclang-rt-14-dev (libFuzzer)
# and libomp-14-dev (OpenMP for clang) if missing, builds with ASan+UBSan in build-fuzz, and runs
# each target for SECONDS (default 600) on a working copy of its committed seed corpus.
# Crashes are written to fuzz/regressions/<target>/ (replayed by the test suite).
# stdout is closed in the targets (-close_fd_mask=1): `vct compare --scene` prints notes per input.
#   scripts/fuzz.sh [SECONDS] [gltf|stage_set|scene_compare]
set -euo pipefail
cd "$(dirname "$0")/.."
SECS=${1:-600}
ONLY=${2:-}
missing=()
for p in clang-14 libclang-rt-14-dev libomp-14-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
if [ ! -f build-fuzz/build.ninja ]; then
  CC=clang-14 CXX=clang++-14 cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DVCT_FUZZ=ON -DVCT_SANITIZE=ON -DVCT_BUILD_GL=OFF \
    -DVCT_BUILD_TESTS=OFF -DVCT_BUILD_BENCH=OFF
fi
cmake --build build-fuzz -j "$(nproc)" --target gltf_fuzz stage_set_fuzz scene_compare_fuzz

# Seeds: fuzz/corpus/ (committed; fuzz/make_seeds.py regenerates them, its docstring says from what),
# and for gltf the whole scene zoo (scenes/*.gltf), copied in at each run so new scenes join.
# -max_len: gltf 1 MiB, the largest zoo scene (scanned_statue.gltf, 715 KiB) whole plus room for
# the mutator's nesting (fuzz/gltf_mutator.h: 20 000 levels take 40-100 KB); the other targets
# 200000 (their largest seed, a stage set, is far smaller). gltf_fuzz mutates structure
# (LLVMFuzzerCustomMutator, fuzz/gltf_mutator.h) three times in four, bytes otherwise.
export ASAN_OPTIONS="detect_leaks=0:allocator_may_return_null=1"  # leaks: process-lifetime caches only
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
for t in gltf stage_set scene_compare; do
  [ -z "$ONLY" ] || [ "$ONLY" = "$t" ] || continue
  work=build-fuzz/corpus_$t
  mkdir -p "$work" "fuzz/regressions/$t"
  cp -n fuzz/corpus/$t/* "$work/" 2>/dev/null || true
  max_len=200000
  if [ "$t" = gltf ]; then
    cp -n scenes/*.gltf "$work/"
    max_len=1048576
  fi
  dict=()
  [ ! -f "fuzz/$t.dict" ] || dict=(-dict="fuzz/$t.dict")
  echo "fuzz: $t for $SECS s"
  build-fuzz/bin/${t}_fuzz "${dict[@]}" "$work" -max_total_time="$SECS" -max_len="$max_len" -rss_limit_mb=4096 -timeout=20 \
    -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 -artifact_prefix="fuzz/regressions/$t/" \
    -close_fd_mask=1 -print_final_stats=1 2>&1 | tee "build-fuzz/fuzz_$t.log" | grep -E "^#[0-9]+: cov|DONE|crash-|oom-|timeout-|stat::" | tail -30
done
