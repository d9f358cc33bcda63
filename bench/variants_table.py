#!/usr/bin/env python3
"""Issue 17's artifact fixes measured with `vct validate --sweep` (docs/compare.md, "Artifact fixes:
what each removes and what it costs").

For each scene: one validate run per base (isotropic, anisotropic) sweeping each variant alone
against the defaults, and one with every fix on. Prints a Markdown table per scene: indirect
diffuse (image.diffuse_term vs pt_indirect_diffuse) relative bias and relMSE from validate's bias
block, the GL verdict, and the ref / GL frame times of the sweep row (wall clock, this machine,
noisy: compare within a table). The per-term budget of `vct attribute` is not used here.

  bench/variants_table.py --vct build/bin/vct --scenes builtin,scenes/demo_room.gltf \
      --out /tmp/variants --size 128 --grid 64 --spp 64
"""
import argparse
import json
import os
import subprocess
import sys

SWEEPS = [("solid_voxelization", ["false", "true"]),
          ("surface_thickening_voxels", ["0", "1", "2", "4"]),
          ("opacity_step_correction", ["false", "true"])]
ALL_FIXES = ["solid_voxelization=true", "surface_thickening_voxels=2", "opacity_step_correction=true"]


def validate(args, scene, out, sets, sweeps):
    if args.reuse and os.path.exists(os.path.join(out, "run.json")):
        with open(os.path.join(out, "run.json")) as f:
            return json.load(f)
    cmd = [args.vct, "validate"] + ([] if scene == "builtin" else [scene])
    cmd += ["--no-report", "--width", str(args.size), "--height", str(args.size), "--grid", str(args.grid),
            "--spp", str(args.spp), "--out", out]
    for s in sets:
        cmd += ["--set", s]
    for key, values in sweeps:
        cmd += ["--sweep", key + "=" + ",".join(values)]
    r = subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if r.returncode not in (0, 1):
        sys.exit("validate failed (%d): %s" % (r.returncode, r.stderr[-2000:]))
    with open(os.path.join(out, "run.json")) as f:
        return json.load(f)


def diffuse(row):
    for b in row["bias"]:
        if b["component"] == "indirect_diffuse":
            return b
    return None


def rows(run, base_label):
    out = []
    for sweep in run["sweeps"]:
        for row in sweep["rows"]:
            b = diffuse(row)
            label = "%s, %s=%s" % (base_label, row["key"], row["value"])
            out.append((label, b["mean_vct"], b["mean_pt"], b["relative_bias"], b["rel_mse"], b["ssim"],
                        row["gl_verdict"], row["gl_first_failing"], row["ref_ms"], row["gl_ms"],
                        row["gl_timings_ms"].get("voxel_fill", 0.0), row["ref_timings_ms"].get("inject", 0.0)))
    return out


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--vct", required=True)
    p.add_argument("--scenes", default="builtin")
    p.add_argument("--out", required=True)
    p.add_argument("--size", type=int, default=128)
    p.add_argument("--grid", type=int, default=64)
    p.add_argument("--spp", type=int, default=64)
    p.add_argument("--reuse", action="store_true", help="read run.json where --out already has one")
    args = p.parse_args()
    for scene in args.scenes.split(","):
        stem = "builtin" if scene == "builtin" else os.path.splitext(os.path.basename(scene))[0]
        table = []
        iso = validate(args, scene, os.path.join(args.out, stem, "iso"), [],
                       SWEEPS + [("anisotropic", ["true"])])
        table += rows(iso, "iso")
        aniso = validate(args, scene, os.path.join(args.out, stem, "aniso"), ["anisotropic=true"], SWEEPS)
        table += rows(aniso, "aniso")
        fixes = validate(args, scene, os.path.join(args.out, stem, "all"), ALL_FIXES,
                         [("anisotropic", ["false", "true"])])
        table += [(("all fixes, " + r[0].split(", ", 1)[1]),) + r[1:] for r in rows(fixes, "")]
        print("\n%s (%dx%d, grid %d, pt %d spp)\n" % (stem, args.size, args.size, args.grid, args.spp))
        print("| setting | mean VCT / PT | bias | relMSE | SSIM | GL verdict | ref ms (inject) | GL ms (fill pass) |")
        print("| --- | --- | --- | --- | --- | --- | --- | --- |")
        seen = set()
        for label, vct, pt, bias, rel_mse, ssim, verdict, first, ref_ms, gl_ms, gl_fill, ref_inject in table:
            if label in seen:
                continue
            seen.add(label)
            v = verdict + (" (" + first + ")" if first else "")
            # PT mean 0 (a dark room: everything VCT shows there is leakage): no relative bias.
            b = "%+.1f %%" % (100 * bias) if pt > 0 else "n/a (PT 0)"
            print("| %s | %.5f / %.5f | %s | %.3f | %.3f | %s | %.0f (%.0f) | %.0f (%.1f) |" %
                  (label, vct, pt, b, rel_mse, ssim, v, ref_ms, ref_inject, gl_ms, gl_fill))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
