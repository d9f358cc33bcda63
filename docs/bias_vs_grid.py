#!/usr/bin/env python3
"""Bias of voxel cone tracing against the path tracer as the voxel grid grows (docs/python.md).

Renders the CPU reference at each grid size, path-traces the same view once (the ground truth
does not depend on the grid), measures bias per component with the library's own metrics
(compare/bias.h) and plots relMSE and relative bias against grid size with matplotlib.

    .venv/bin/python docs/bias_vs_grid.py --grids 16,32,64,128 --size 128 --spp 64 --out bias.png
    .venv/bin/python docs/bias_vs_grid.py scenes/demo_room.gltf

The same numbers as `vct validate --sweep grid=...` (the report's sweep table), without files.
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")  # no display needed
import matplotlib.pyplot as plt  # noqa: E402

import vct  # noqa: E402

COMPONENTS = ["full", "direct", "indirect_diffuse", "indirect_specular"]


def measure(scene_path, grids, size, spp, threads):
    scene = vct.load_scene(scene_path)
    base = vct.validate_defaults()
    base["vct"].update(width=size, height=size)
    base["pt"].update(width=size, height=size, spp=spp)  # bias needs the same pixels on both sides
    base["threads"] = threads
    pt = vct.path_trace(scene, base)
    rows = []
    for g in grids:
        s = vct.sweep_settings(base, "grid", g)  # exactly what --sweep grid=g applies
        frame = vct.render_ref(scene, s)
        bias = {b["component"]: b for b in vct.bias(frame, pt) if b["available"]}
        rows.append((g, bias, frame.ms))
        print("grid %4d  %7.1f ms  %s" % (g, frame.ms, "  ".join(
            "%s relMSE %.4g bias %+.1f%%" % (c, bias[c]["rel_mse"], 100 * bias[c]["relative_bias"])
            for c in COMPONENTS if c in bias)), file=sys.stderr)
    return scene.source, rows


def plot(title, rows, out):
    fig, (ax_mse, ax_bias) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
    grids = [g for g, _, _ in rows]
    for c in COMPONENTS:
        if not all(c in b for _, b, _ in rows):
            continue
        ax_mse.plot(grids, [b[c]["rel_mse"] for _, b, _ in rows], "o-", label=c)
        ax_bias.plot(grids, [100 * b[c]["relative_bias"] for _, b, _ in rows], "o-", label=c)
    for ax in (ax_mse, ax_bias):
        ax.set_xscale("log", base=2)
        ax.set_xticks(grids, [str(g) for g in grids])
        ax.set_xlabel("voxel grid (N^3)")
        ax.grid(True, alpha=0.3)
    ax_mse.set_yscale("log")
    ax_mse.set_ylabel("relMSE against the path tracer (eps 0.01)")
    ax_bias.axhline(0, color="k", lw=0.8)
    ax_bias.set_ylabel("relative bias sum(VCT-PT)/sum(PT)  [%]")
    ax_bias.legend()
    fig.suptitle("VCT bias vs grid size: " + title)
    fig.savefig(out, dpi=90)
    print(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("scene", nargs="?", default="", help="glTF scene (default: the built-in Cornell box)")
    ap.add_argument("--grids", default="16,32,64,128", help="grid sizes, comma-separated")
    ap.add_argument("--size", type=int, default=128, help="image width and height")
    ap.add_argument("--spp", type=int, default=64, help="path tracer samples per pixel")
    ap.add_argument("--threads", type=int, default=0, help="worker threads (0 = all cores)")
    ap.add_argument("--out", default="bias_vs_grid.png", help="PNG to write")
    a = ap.parse_args()
    try:
        grids = [int(g) for g in a.grids.split(",")]
        title, rows = measure(a.scene, grids, a.size, a.spp, a.threads)
    except (ValueError, vct.InputError) as e:  # bad grid list or settings: one line, exit 2
        print("bias_vs_grid.py: %s" % e, file=sys.stderr)
        return 2
    plot(title, rows, a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
