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

rm -rf "$work"
mkdir -p "$work/src" "$work/obj" "$work/run/dump"
cp -r "$src/src/." "$work/src/"
ln -s "$src/assets" "$work/assets"  # gidemo loads ../assets/... relative to its working directory
main="$work/src/main.cpp"

anchor() {  # anchor REGEX: the edit below needs this line of main.cpp
  grep -q "$1" "$main" || { echo "run.sh: anchor '$1' not in $main (another gidemo revision?)" >&2; exit 2; }
}
# 1. Our hook reads the voxel texture before fixopacity.comp, while alpha still counts fragments.
anchor '^Scene scene;'
sed -i '/^Scene scene;/i void vct_hook_before_fixopacity();' "$main"
anchor 'right now the opacity is used as a counter'
sed -i '/right now the opacity is used as a counter/i \\tvct_hook_before_fixopacity();' "$main"
# 2. Our one-frame main() (dump_hook.cpp) replaces the interactive loop and its GUI.
anchor '^int main() {'
sed -i '/^int main() {/,$d' "$main"
echo '#include "dump_hook.cpp"' >>"$main"

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
