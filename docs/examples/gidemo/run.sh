#!/usr/bin/env bash
# Builds the source design's renderer (righier/gidemo, no licence: it stays outside this repository)
# headless against Debian's glfw/glm/stb, renders its box scene for one frame under Xvfb + llvmpipe,
# and dumps its stages with our tools/vct_dump/vct_dump.h (docs/examples/gidemo.md).
#   docs/examples/gidemo/run.sh [GIDEMO_CHECKOUT] [WORK_DIR]
# Needs: g++, xvfb-run, libglfw3-dev, libglm-dev, libstb-dev, Mesa's llvmpipe. Leaves the stage set
# and box.gltf in WORK_DIR/run/dump/. Only our lines are here: each edit names its anchor line
# in gidemo's src/main.cpp and fails loudly when the anchor is not found.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
src="${1:-/work/gidemo}"
work="${2:-/work/gidemo-build}"
[ -f "$src/src/main.cpp" ] || { echo "run.sh: $src/src/main.cpp: not a gidemo checkout" >&2; exit 2; }

# Only what this script makes in WORK_DIR is removed (never WORK_DIR itself), and never inside
# this repository or the checkout.
w="$(realpath -m "$work")"
for keep in "$root" "$(realpath -m "$src")"; do
  case "$w/" in "$keep/"*) echo "run.sh: $work: refusing to build inside $keep" >&2; exit 2 ;; esac
done
rm -rf "$work/src" "$work/obj" "$work/run" "$work/assets" "$work/gidemo"
mkdir -p "$work/src" "$work/obj" "$work/run/dump"
cp -r "$src/src/." "$work/src/"
# gidemo loads ../assets/... relative to its working directory; shaders are copied (experiments edit them)
mkdir -p "$work/assets"
for a in "$src"/assets/*; do [ "$(basename "$a")" = shaders ] || ln -s "$a" "$work/assets/"; done
cp -r "$src/assets/shaders" "$work/assets/shaders"
main="$work/src/main.cpp"

anchor() {  # anchor REGEX: the edit below needs this line of main.cpp
  grep -q "$1" "$main" || { echo "run.sh: anchor '$1' not in $main (another gidemo revision?)" >&2; exit 2; }
}
# 1. Our hook reads the voxel texture before fixopacity.comp, while alpha still counts fragments.
anchor '^Scene scene;'
sed -i '/^Scene scene;/i void vct_hook_before_fixopacity();' "$main"
anchor 'right now the opacity is used as a counter'
sed -i '/right now the opacity is used as a counter/i \\tvct_hook_before_fixopacity();' "$main"
# 2. The camera passes draw into our single-sample target instead of the 4x MSAA window, so image
#    stages are pixel-centre values like the reference's (the voxelization pass keeps the window's
#    MSAA: it is gidemo's voxelizer). Only the Framebuffer::reset() of these two functions changes.
sed -i '/^Scene scene;/i void vct_hook_bind_frame_target();' "$main"
for fn in occlusionCulling voxelCone; do
  anchor "^void $fn(double time) {"
  sed -i "/^void $fn(double time) {/,/^}/ s/Framebuffer::reset();/vct_hook_bind_frame_target();/" "$main"
done
[ "$(grep -c 'vct_hook_bind_frame_target();' "$main")" = 3 ] || { echo "run.sh: frame target edit did not apply" >&2; exit 2; }
# 3. Our one-frame main() (dump_hook.cpp) replaces the interactive loop and its GUI.
anchor '^int main() {'
sed -i '/^int main() {/,$d' "$main"
echo '#include "dump_hook.cpp"' >>"$main"

# Experiment (GIDEMO_EXPERIMENT=unscaled_mips): mipmap.comp without its "* 1.9", to show what the
# scaling does downstream (docs/examples/gidemo.md). Not part of the worked example's verdicts.
if [ "${GIDEMO_EXPERIMENT:-}" = unscaled_mips ]; then
  mip="$work/assets/shaders/mipmap.comp"
  grep -q 'textureLod(u_src, pos, u_level) \* 1.9;' "$mip" || { echo "run.sh: anchor '* 1.9' not in $mip" >&2; exit 2; }
  sed -i 's/textureLod(u_src, pos, u_level) \* 1.9;/textureLod(u_src, pos, u_level);/' "$mip"
fi

flags=(-std=c++17 -O1 -DGLM_ENABLE_EXPERIMENTAL -w -I"$here" -I"$root/tools/vct_dump"
       -I"$src/libs/glad/include" -I/usr/include/stb -I"$work/src")
gcc -O1 -I"$src/libs/glad/include" -c "$src/libs/glad/src/glad.c" -o "$work/obj/glad.o"
for f in "$work"/src/*.cpp "$work"/src/imgui/*.cpp; do  # gidemo vendors Dear ImGui in src/imgui
  g++ "${flags[@]}" -c "$f" -o "$work/obj/$(basename "$f" .cpp).o"
done
g++ "$work"/obj/*.o -o "$work/gidemo" -lglfw -lGL -ldl -lpthread

# llvmpipe offers GL 4.5; gidemo asks for a 4.6 core context and #version 460 shaders.
cd "$work/run"
MESA_GL_VERSION_OVERRIDE=4.6 MESA_GLSL_VERSION_OVERRIDE=460 VCT_DUMP_DIR=dump/ \
  xvfb-run -a -s "-screen 0 640x480x24" "$work/gidemo"
echo "run.sh: stage set in $work/run/dump"
