#!/usr/bin/env bash
# The GL runner bundle end to end (docs/gl_backend.md "GL runner", "GPU check"): the bundle is
# built by one script and fits 60 MiB, the bundled runner runs from a bare environment with only
# LD_LIBRARY_PATH (its libraries resolve inside the bundle, the driver's libEGL outside), a small
# gpu_check matrix renders and its judging step prints the table with every row as expected, and
# bad input exits 2 writing nothing. Exit 77 (skipped) without a GL context.
# Usage: gl_runner_bundle_test.sh SOURCE_DIR BUILD_DIR WORK_DIR
set -euo pipefail
src="$1" build="$2" work="$3"
rm -rf "$work"
mkdir -p "$work"
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

"$src/scripts/bundle_gl_runner.sh" "$work/bundle" --build-dir "$build" --no-build
bytes=$(du -sb "$work/bundle" | cut -f1)
[ "$bytes" -le $((60 * 1024 * 1024)) ] || fail "bundle is $bytes bytes"
for lib in libEGL libOpenGL libGLdispatch libOpenImageIO libembree libc.so; do
  if compgen -G "$work/bundle/lib/$lib*" > /dev/null; then fail "bundle carries $lib"; fi
done
# Every non-system library resolves inside the bundle.
resolved=$(LD_LIBRARY_PATH="$work/bundle/lib" ldd "$work/bundle/bin/vct_gl_runner")
# (here-strings, not `echo | grep -q`: grep -q exits at the first match and pipefail would then
# report echo's SIGPIPE as a failure)
grep -q "libstdc++.so.6 => $work/bundle/lib/" <<< "$resolved" || fail "libstdc++ not taken from the bundle: $resolved"
if grep -q "not found" <<< "$resolved"; then fail "unresolved library: $resolved"; fi

# A bare environment: only PATH and what run_gl_runner.sh sets.
set +e
env -i PATH=/usr/bin:/bin "$work/bundle/run_gl_runner.sh" "$work/bundle/scenes/cornell_box.gltf" \
  --out "$work/probe" --width 32 --height 32 --grid 16 --shadow-map-size 128 > "$work/probe.log" 2>&1
rc=$?
set -e
if [ "$rc" = 3 ]; then echo "skipped: no GL context: $(cat "$work/probe.log")"; exit 77; fi
[ "$rc" = 0 ] || fail "bundled runner exit $rc: $(cat "$work/probe.log")"
[ -f "$work/probe/vct-stages.json" ] || fail "no stage set written"

# Bad input: exit 2, one line, nothing written.
set +e
"$work/bundle/run_gl_runner.sh" "$work/bundle/scenes/cornell_box.gltf" --out "$work/bad" --gl-fault nope 2> "$work/bad.err"
rc=$?
set -e
[ "$rc" = 2 ] || fail "unknown fault: exit $rc"
[ "$(wc -l < "$work/bad.err")" = 1 ] || fail "unknown fault: $(cat "$work/bad.err")"
[ ! -e "$work/bad" ] || fail "unknown fault wrote $work/bad"

# A small matrix: one scene (8 sets), its conservative GS row (the hardware rows are skipped on a
# driver without the extensions) and two faults (one caught, one llvmpipe cannot show).
"$work/bundle/gpu_check.sh" render --out "$work/res" --reduced --scenes cornell_box \
  --faults wrong_mip,missing_barrier --no-timings > "$work/render.log" 2>&1 || fail "render: $(cat "$work/render.log")"
[ "$(ls "$work/res/sets" | wc -l)" = 11 ] || fail "expected 11 stage sets: $(ls "$work/res/sets")"
"$src/scripts/gpu_check.sh" judge "$work/res" --vct "$build/bin/vct" > "$work/judge.txt" || fail "judge: $(cat "$work/judge.txt")"
cat "$work/judge.txt"
grep -q "^fault.wrong_mip.fixed .* fail .*mip.iso.2 .* yes$" "$work/judge.txt" || fail "wrong_mip not blamed on mip.iso.2"
grep -q "^11 sets, 0 not as expected" "$work/judge.txt" || fail "unexpected rows"
grep -q "^cornell_box.cons_gs .* pass .*conservative: yes, within its bound: yes$" "$work/judge.txt" ||
  fail "no conservative line for the GS row"
if ! grep -q "GL_NV_conservative_raster" <<< "$("$build/bin/vct" info --gl 2>/dev/null)"; then
  grep -q "^cornell_box.cons_nv: skipped" "$work/judge.txt" || fail "the nv row neither ran nor says skipped"
fi
echo "ok"
