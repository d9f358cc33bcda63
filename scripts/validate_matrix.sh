#!/usr/bin/env bash
# Runs `vct validate` over every scene in scenes/ (and the built-in one) across image sizes,
# grids and pipeline options, and prints one line per run: verdict and first failing stage.
# A FAIL on a correct build is a bug of a tolerance model or of the emulation (docs/compare.md).
#   scripts/validate_matrix.sh [--quick] [--cross] [--sizes 64,128] [--grids 32,64] [--variants A,B] [--out DIR] [--threads N]
#   --quick: 64^2 and grid 32 only, the option variants on the built-in scene (minutes, not hours)
#   --cross: every combination of the four pipeline options (reduction, bounces, soft shadows,
#            anisotropic mips: 16 variants) instead of one at a time. Thread count is not crossed:
#            every stage's bytes are the same for any thread count (the Determinism tests), so a
#            verdict cannot depend on it.
#   --sizes / --grids: a part of the full matrix (every scene, every variant, these sizes only)
#   --variants: only these variants by name (e.g. default,cas-b3-soft-aniso)
# Exit 1 when any run fails.
set -uo pipefail
cd "$(dirname "$0")/.."
VCT=${VCT:-build/bin/vct}
OUT=runs/matrix
QUICK=0
CROSS=0
THREADS=2
SIZES=""
GRIDS=""
VARIANTS=""
while (($#)); do
  case $1 in
    --quick) QUICK=1 ;;
    --cross) CROSS=1 ;;
    --sizes) SIZES=$2; shift ;;
    --grids) GRIDS=$2; shift ;;
    --variants) VARIANTS=",$2," ; shift ;;
    --out) OUT=$2; shift ;;
    --threads) THREADS=$2; shift ;;
    *) echo "validate_matrix.sh: unknown argument $1" >&2; exit 2 ;;
  esac
  shift
done
scenes=("" scenes/*.gltf)
if ((QUICK)); then sizes=(64); grids=(32); else sizes=(64 128 256); grids=(32 64 128); fi
[ -n "$SIZES" ] && IFS=, read -r -a sizes <<<"$SIZES"
[ -n "$GRIDS" ] && IFS=, read -r -a grids <<<"$GRIDS"
# name | extra flags (every run also uses its size, grid and --spp 4)
variants=(
  "default|"
  "cas|--set reduction=cas"
  "bounces3|--set bounces=3"
  "soft|--set soft_shadows=true"
  "aniso|--set anisotropic=true"
  "threads1|"
)
if ((CROSS)); then
  variants=()
  for red in fixed cas; do
    for b in 1 3; do
      for soft in false true; do
        for an in false true; do
          variants+=("${red}-b${b}$([ $soft = true ] && echo -soft)$([ $an = true ] && echo -aniso)|--set reduction=$red --set bounces=$b --set soft_shadows=$soft --set anisotropic=$an")
        done
      done
    done
  done
fi
fails=0
run_one() {
  local scene=$1 size=$2 grid=$3 name=$4 flags=$5
  local tag
  tag="$(basename "${scene:-builtin}" .gltf)-${size}-g${grid}-${name}"
  local log="$OUT/$tag.log" threads=$THREADS
  [ "$name" = threads1 ] && threads=1  # determinism is tested elsewhere; here: no FAIL at 1 thread
  # shellcheck disable=SC2086
  "$VCT" validate $scene --width "$size" --height "$size" --grid "$grid" --spp 4 --threads "$threads" \
    --no-report --flip none --out "$OUT/$tag" $flags >"$log" 2>&1
  local rc=$?
  local verdict
  verdict=$(grep -m1 -o 'GPU (gl) vs CPU reference: [a-z]*\( *(first failing stage: [^)]*)\)\?' "$log" | sed 's/GPU (gl) vs CPU reference: //')
  printf '%-48s rc=%d  %s\n' "$tag" "$rc" "${verdict:-see $log}"
  ((rc == 1)) && fails=$((fails + 1))
}
mkdir -p "$OUT"
for scene in "${scenes[@]}"; do
  for size in "${sizes[@]}"; do
    for grid in "${grids[@]}"; do
      for v in "${variants[@]}"; do
        name=${v%%|*}
        flags=${v#*|}
        # --quick: the variants on the built-in scene, the default on every other scene
        if ((QUICK)) && [ -n "$scene" ] && [ "$name" != default ]; then continue; fi
        if [ -n "$VARIANTS" ] && [[ $VARIANTS != *",$name,"* ]]; then continue; fi
        run_one "$scene" "$size" "$grid" "$name" "$flags"
      done
    done
  done
done
echo "validate_matrix: $fails failing run(s)"
((fails == 0))
