#!/usr/bin/env bash
# Validates every scenes/*.gltf (or the files given) with the Khronos glTF validator.
# Exit 0: no validator errors; 1: errors (listed); 77: node or the validator is not installed
# (ctest reports the test as skipped; scripts/setup.sh installs it into tools/gltf-validator).
#   scenes/validate_scenes.sh [--verbose] [FILE.gltf ...]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
modules="$root/tools/gltf-validator/node_modules"
if ! command -v node >/dev/null 2>&1; then
  echo "validate_scenes: node is not installed; skipping" >&2
  exit 77
fi
if [ ! -d "$modules/gltf-validator" ]; then
  echo "validate_scenes: gltf-validator not found in $modules (run scripts/setup.sh); skipping" >&2
  exit 77
fi
args=()
files=()
for a in "$@"; do
  if [ "$a" = --verbose ]; then args+=("$a"); else files+=("$a"); fi
done
if [ ${#files[@]} -eq 0 ]; then
  files=("$root"/scenes/*.gltf)
fi
NODE_PATH="$modules" exec node "$root/scenes/validate_gltf.js" "${args[@]}" "${files[@]}"
