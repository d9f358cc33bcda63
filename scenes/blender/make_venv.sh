#!/usr/bin/env bash
# Makes scenes/blender/.venv-blender with bpy (Blender as a Python module) from PyPI: a test-data
# generator only (docs/scenes.md, "Blender exports"), never a runtime dependency of vct and not part
# of scripts/setup.sh. bpy 4.5 is Blender 4.5 LTS, built for CPython 3.11 (Debian 12's python3).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
venv="$here/.venv-blender"
python3 -m venv "$venv"
"$venv/bin/pip" install --quiet --upgrade pip
"$venv/bin/pip" install --quiet "bpy==4.5.*"
"$venv/bin/python" -c "import bpy; print('bpy', bpy.app.version_string)"
