#!/usr/bin/env bash
# Packs vct_gl_runner into a folder that runs on a GPU machine without the project's packages:
#   OUT/bin/vct_gl_runner   the runner (stripped)
#   OUT/lib/                its shared libraries from `ldd`, except the driver's (libEGL, libGL*,
#                           libOpenGL, libGLdispatch: glvnd dispatches to the machine's own driver)
#                           and the C library's (libc, libm, ld-linux: the target's glibc must be
#                           at least this machine's, Debian 12 = 2.36)
#   OUT/run_gl_runner.sh    sets LD_LIBRARY_PATH=OUT/lib and runs the runner
#   OUT/scenes/, OUT/gpu_check.sh   what scripts/gpu_check.sh renders, and the script itself
#   OUT/BUNDLE.txt          commit, libraries, size
# Fails (exit 1) when the folder exceeds 60 MiB. docs/gl_backend.md, "GL runner".
# Usage: scripts/bundle_gl_runner.sh OUT [--build-dir DIR] [--no-build]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out=""
build="$root/build"
do_build=1
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build="$2"; shift 2 ;;
    --no-build) do_build=0; shift ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    -*) echo "bundle_gl_runner.sh: unknown option $1" >&2; exit 2 ;;
    *) out="$1"; shift ;;
  esac
done
[ -n "$out" ] || { echo "bundle_gl_runner.sh: usage: bundle_gl_runner.sh OUT [--build-dir DIR] [--no-build]" >&2; exit 2; }
limit=$((60 * 1024 * 1024))

if [ "$do_build" = 1 ]; then
  cmake --build "$build" -j2 --target vct_gl_runner >/dev/null
fi
runner="$build/bin/vct_gl_runner"
[ -x "$runner" ] || { echo "bundle_gl_runner.sh: $runner: not built (cmake --build build --target vct_gl_runner)" >&2; exit 2; }

# Built next to OUT and renamed at the end, so a failed run leaves no half bundle.
tmp="$(dirname "$out")/.tmp-bundle-$$"
rm -rf "$tmp"
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/bin" "$tmp/lib"
cp "$runner" "$tmp/bin/vct_gl_runner"
strip --strip-unneeded "$tmp/bin/vct_gl_runner" 2>/dev/null || true

# Driver and C-library objects stay the target machine's own.
is_system() {
  case "$1" in
    libEGL.so*|libGL.so*|libGLX*|libOpenGL.so*|libGLdispatch.so*|libGLESv*) return 0 ;;
    libc.so*|libm.so*|libdl.so*|librt.so*|libpthread.so*|ld-linux*|linux-vdso*) return 0 ;;
  esac
  return 1
}
libs=()
while read -r name arrow path _; do
  [ "$arrow" = "=>" ] || continue
  [ -f "$path" ] || { echo "bundle_gl_runner.sh: $name: not found by ldd" >&2; exit 1; }
  if is_system "$name"; then continue; fi
  cp -L "$path" "$tmp/lib/$name"
  strip --strip-unneeded "$tmp/lib/$name" 2>/dev/null || true
  libs+=("$name")
done < <(ldd "$runner")

cat > "$tmp/run_gl_runner.sh" <<'RUN'
#!/usr/bin/env bash
# Runs the bundled vct_gl_runner with its libraries (the driver's libEGL comes from the system).
here="$(cd "$(dirname "$0")" && pwd)"
LD_LIBRARY_PATH="$here/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" exec "$here/bin/vct_gl_runner" "$@"
RUN
chmod +x "$tmp/run_gl_runner.sh"
mkdir -p "$tmp/scenes"
cp -r "$root"/scenes/*.gltf "$root/scenes/textures" "$tmp/scenes/"
cp "$root/scripts/gpu_check.sh" "$tmp/gpu_check.sh"

bytes=$(du -sb "$tmp" | cut -f1)
{
  echo "vct_gl_runner bundle"
  echo "commit: $(git -C "$root" rev-parse --short HEAD 2>/dev/null || echo unknown)"
  echo "built on: $(uname -srm), $(ldd --version | head -1)"
  echo "bundled libraries: ${libs[*]}"
  echo "size: $bytes bytes (limit $limit)"
} > "$tmp/BUNDLE.txt"
if [ "$bytes" -gt "$limit" ]; then
  echo "bundle_gl_runner.sh: bundle is $bytes bytes, over the 60 MiB limit" >&2
  exit 1
fi
rm -rf "$out"
mv "$tmp" "$out"
trap - EXIT
echo "bundle_gl_runner.sh: $out ($((bytes / 1024)) KiB; ${#libs[@]} libraries: ${libs[*]})"
