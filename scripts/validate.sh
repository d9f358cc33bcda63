#!/usr/bin/env bash
# Sets up and runs the main job: `vct validate` on the built-in default scene.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
exec build/bin/vct validate "$@"
