#!/usr/bin/env bash
# One-step set-up on a fresh Debian 12 machine: installs missing Debian packages, makes the
# Python venv the report tooling uses, configures and builds. Idempotent; quick when all is there.
#   scripts/setup.sh            Release build in build/
#   BUILD_DIR=build-asan CMAKE_ARGS="-DVCT_SANITIZE=ON" scripts/setup.sh
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
BUILD_TYPE=${BUILD_TYPE:-Release}
# ccache keys on relative paths under the checkout, so clones in other folders (CI) hit it too.
export CCACHE_BASEDIR="$PWD"

APT_PACKAGES=(
  build-essential cmake ninja-build pkg-config git python3 python3-venv
  libembree-dev libopenimageio-dev openimageio-tools libtinygltf-dev nlohmann-json3-dev libstb-dev
  libglm-dev libgtest-dev libgmock-dev libbenchmark-dev libcli11-dev libfmt-dev
  libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri
  chromium ccache
  # Dr.Jit's LLVM backend (Mitsuba's llvm_ad_rgb in bench/mitsuba_compare.py) needs LLVM >= 17;
  # Mesa keeps its own LLVM 15. A library only: nothing links against it.
  libllvm19
)

missing=()
for p in "${APT_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# Optional: RenderDoc (`vct import-capture`, docs/external_format.md "From a RenderDoc capture"):
# renderdoccmd captures, python3-renderdoc replays under the system python3, and
# renderdoc_app.h lets the GL backend capture its own frame. A machine without them (an older
# Debian, a mirror lacking them) still builds and passes: the import test skips.
OPTIONAL_APT_PACKAGES=(renderdoccmd python3-renderdoc librenderdoc-dev)
optional_missing=()
for p in "${OPTIONAL_APT_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || optional_missing+=("$p")
done
if ((${#optional_missing[@]})); then
  echo "setup: installing (optional) ${optional_missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${optional_missing[@]}" ||
    echo "setup: optional packages ${optional_missing[*]} unavailable; vct import-capture will say so"
fi

# Python venv for the report, image metrics (FLIP) and the `import vct` module's build and tests
# (nanobind, pytest, matplotlib). Rebuilt only when requirements change.
if [ ! -f .venv/.requirements-done ] || ! cmp -s report/requirements.txt .venv/.requirements-done; then
  echo "setup: making .venv"
  python3 -m venv .venv
  .venv/bin/pip install -q --disable-pip-version-check -r report/requirements.txt
  cp report/requirements.txt .venv/.requirements-done
fi

# Khronos glTF validator (npm), used by scenes/validate_scenes.sh and its ctest. Node from
# Debian if there is none; the package goes into tools/gltf-validator (git-ignored node_modules).
if ! command -v npm >/dev/null 2>&1; then
  echo "setup: installing nodejs npm"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends nodejs npm
fi
if [ ! -d tools/gltf-validator/node_modules/gltf-validator ]; then
  echo "setup: installing gltf-validator into tools/gltf-validator"
  npm ci --silent --no-audit --no-fund --prefix tools/gltf-validator
fi

# The Python module (docs/python.md) is built against the venv's Python and nanobind; a build
# directory configured before it existed is switched on here (once).
PY_ARGS=(-DVCT_PYTHON=ON "-DPython_EXECUTABLE=$PWD/.venv/bin/python")
if [ ! -f "$BUILD_DIR/build.ninja" ]; then
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE="$BUILD_TYPE" -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
    "${PY_ARGS[@]}" ${CMAKE_ARGS:-}
elif ! grep -q '^VCT_PYTHON:BOOL=ON' "$BUILD_DIR/CMakeCache.txt"; then
  cmake -S . -B "$BUILD_DIR" "${PY_ARGS[@]}"
fi
cmake --build "$BUILD_DIR" -j "$(nproc)"
echo "setup: built $BUILD_DIR/bin/vct"

# `import vct` in the venv: a .pth file puts the build's package folder on its path, so every
# rebuild is what `.venv/bin/python` imports (sanitizer builds have no module: VCT_PYTHON is off).
if [ -d "$BUILD_DIR/python/vct" ]; then
  site=$(.venv/bin/python -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')
  echo "$PWD/$BUILD_DIR/python" > "$site/vct_oracle.pth"
  echo "setup: import vct -> $BUILD_DIR/python/vct"
fi

# vct-cluster (docs/cluster.md): a launcher in .venv/bin for the package in cluster/, run by the
# venv's Python (Dask is in its requirements) with this build's vct; like `import vct`, only for
# the build that has the Python module (not a sanitizer build).
if [ -d "$BUILD_DIR/python/vct" ]; then
  printf '#!/bin/sh\nexport VCT_BIN="${VCT_BIN:-%s}"\nexport PYTHONPATH="%s${PYTHONPATH:+:$PYTHONPATH}"\nexec "%s" -m vct_cluster "$@"\n' \
    "$(cd "$BUILD_DIR" && pwd)/bin/vct" "$PWD/cluster" "$PWD/.venv/bin/python" > .venv/bin/vct-cluster
  chmod +x .venv/bin/vct-cluster
  echo "setup: .venv/bin/vct-cluster"
fi
