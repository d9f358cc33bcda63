#!/usr/bin/env python3
"""Verdicts of two scripts/validate_matrix.sh output folders (--out), run by run: overall, first
failing stage, and per stage verdict, checked, out_of_bound, allowed. Prints every difference and
exits 1 when there is one. Used to show a judge change decides the same (docs/compare.md).
   scripts/diff_verdicts.py BEFORE_DIR AFTER_DIR"""
import json, os, sys
a, b = sys.argv[1], sys.argv[2]
diffs, runs = 0, 0
for name in sorted(os.listdir(a)):
    ra, rb = os.path.join(a, name, "run.json"), os.path.join(b, name, "run.json")
    if not os.path.exists(ra):
        continue
    if not os.path.exists(rb):
        print("missing after:", name); diffs += 1; continue
    va = json.load(open(ra)).get("verdicts") or {}
    vb = json.load(open(rb)).get("verdicts") or {}
    runs += 1
    for k in ("overall", "first_failing"):
        if va.get(k) != vb.get(k):
            print(name, k, va.get(k), "->", vb.get(k)); diffs += 1
    sa = {s["stage"]: s for s in va.get("stages", [])}
    sb = {s["stage"]: s for s in vb.get("stages", [])}
    for st in sorted(set(sa) | set(sb)):
        x, y = sa.get(st, {}), sb.get(st, {})
        for k in ("verdict", "checked", "out_of_bound", "allowed"):
            if x.get(k) != y.get(k):
                print(name, st, k, x.get(k), "->", y.get(k)); diffs += 1
print("runs compared:", runs, "differences:", diffs)
sys.exit(1 if diffs else 0)
