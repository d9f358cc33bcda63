#!/usr/bin/env bash
# Judges the gidemo dump of run.sh against our reference twice (docs/examples/gidemo.md):
#   BEFORE: the reference at gidemo's sizes only (grid 64, 128x128) and the dump's manifest with
#           its "conventions" removed -- what a new user gets without declaring anything;
#   AFTER:  the reference rendered with settings.json and gidemo's MSAA sample positions (--facts-from) (gidemo's light model, voxelizer, storage,
#           reduction, shadow frustum/PCF/depth format, cone set) and the manifest as dumped
#           (conventions mip_scale 1.9 and display reinhard/2.2/8 bits).
#   docs/examples/gidemo/compare.sh [DUMP_DIR] [OUT_DIR]
# and AFTER again with --scene (cone stages re-traced on gidemo's own depth, normals and mips).
# Exit status: that of the AFTER comparison (1: a stage FAILs -- expected, mip.iso.1).
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
vct="${VCT:-$root/build/bin/vct}"
dump="${1:-/work/gidemo-build/run/dump}"
out="${2:-/tmp/gidemo-compare}"
[ -f "$dump/vct-stages.json" ] || { echo "compare.sh: $dump: no vct-stages.json (run run.sh first)" >&2; exit 2; }
rm -rf "$out/before_dump" "$out/ref_before" "$out/ref_after" "$out/cmp_before" "$out/cmp_after" "$out/cmp_scene"
mkdir -p "$out/before_dump"
scene="$here/box.gltf"

# The same stage files, the manifest without its conventions.
for f in "$dump"/*; do ln -s "$f" "$out/before_dump/$(basename "$f")"; done
rm "$out/before_dump/vct-stages.json"
python3 -c 'import json,sys; m=json.load(open(sys.argv[1])); m.pop("conventions",None); json.dump(m,open(sys.argv[2],"w"),indent=2)' \
  "$dump/vct-stages.json" "$out/before_dump/vct-stages.json"

"$vct" render "$scene" --backend ref --dump --stage-set --set grid=64 --set width=128 --set height=128 \
  --out "$out/ref_before" >/dev/null
"$vct" render "$scene" --backend ref --dump --stage-set --config "$here/settings.json" --facts-from "$dump" \
  --out "$out/ref_after" >/dev/null

echo "== BEFORE (no conventions, reference at defaults)"
"$vct" compare "$out/ref_before/stages" "$out/before_dump" --out "$out/cmp_before"
echo "== AFTER (settings.json + the manifest's conventions)"
"$vct" compare "$out/ref_after/stages" "$dump" --out "$out/cmp_after"
rc=$?
echo "== AFTER, cone stages re-traced on gidemo's own depth, normals and mips (--scene)"
"$vct" compare "$out/ref_after/stages" "$dump" --scene "$scene" --config "$here/settings.json" --out "$out/cmp_scene"

# The verdict tables of docs/examples/gidemo.md, from each compare.json.
table() {
  python3 - "$1" <<'PY'
import json, sys
v = json.load(open(sys.argv[1]))["verdicts"]
print("| stage | verdict | what the judge says |\n| --- | --- | --- |")
for s in v["stages"]:
    if s.get("verdict") in (None, "missing"):
        continue
    note = s.get("note", "").split(" Driver fact")[0].replace("|", "/")
    print(f"| `{s['stage']}` | {s['verdict']} | {note} |")
PY
}
echo; echo "BEFORE table:"; table "$out/cmp_before/compare.json"
echo; echo "AFTER table:"; table "$out/cmp_after/compare.json"
echo; echo "AFTER --scene table:"; table "$out/cmp_scene/compare.json"
exit $rc
