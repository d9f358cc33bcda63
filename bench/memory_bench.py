#!/usr/bin/env python3
"""Predicted memory against the peak RSS of `vct render` or `vct validate` (issue 37, Deliver 3
and 4): prints predicted / peak for the built-in Cornell box with each triangle split into n²
(2 382 to ~1 M triangles) at grids 64–256, and for validate its non-render / renders ratio (wall
and CPU time). A benchmark, run by hand; figures in docs/performance.md ("Scale: memory predicted
and measured", "Validate at grid 256").

  bench/memory_bench.py [--command render|gl|validate] [--splits 1,4,8,20] [--grids 64,128,256]
                        [--size 128 (render) / 256 (validate)] [--vct build/bin/vct]

`--command gl` measures `vct render --backend gl` (llvmpipe's textures, buffers and the frame it
reads back: estimate_gl_memory). `vct render` and `vct validate` write memory.predicted_bytes (estimate_memory /
estimate_validate_memory, ref/core/memory_budget.cpp) and memory.peak_rss_bytes (getrusage) into
run.json; both are read back here.
"""
import argparse
import base64
import json
import os
import struct
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
COMPONENTS = {5126: ("<f4", 4), 5125: ("<u4", 4), 5123: ("<u2", 2), 5121: ("u1", 1)}
WIDTHS = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}


def read_accessor(g, blob, index):
    a = g["accessors"][index]
    view = g["bufferViews"][a["bufferView"]]
    dtype, size = COMPONENTS[a["componentType"]]
    width = WIDTHS[a["type"]]
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    return np.frombuffer(blob, dtype=dtype, count=a["count"] * width, offset=start).reshape(a["count"], width)


def split_pattern(n):
    """Barycentric weights (wb, wc) of the (n+1)(n+2)/2 grid points of a triangle split into n²,
    and the n² sub-triangles as index triples into them (the parent's winding)."""
    pts = [(i, j) for j in range(n + 1) for i in range(n + 1 - j)]
    at = {p: k for k, p in enumerate(pts)}
    tris = []
    for j in range(n):
        for i in range(n - j):
            tris.append((at[(i, j)], at[(i + 1, j)], at[(i, j + 1)]))
            if i + j < n - 1:
                tris.append((at[(i + 1, j)], at[(i + 1, j + 1)], at[(i, j + 1)]))
    w = np.array(pts, dtype=np.float64) / n
    return w, np.array(tris, dtype=np.uint32)


def split_scene(n, path):
    """scenes/cornell_box.gltf with every triangle split into n² (vertex attributes interpolated),
    written with an external .bin buffer; returns the triangle count."""
    with open(os.path.join(ROOT, "scenes", "cornell_box.gltf")) as f:
        g = json.load(f)
    blob = base64.b64decode(g["buffers"][0]["uri"].split(",", 1)[1])
    w, sub = split_pattern(n)
    out, accessors, views, triangles = bytearray(), [], [], 0

    def add(array, gl_type, component, target):
        data = np.ascontiguousarray(array).tobytes()
        views.append({"buffer": 0, "byteOffset": len(out), "byteLength": len(data), "target": target})
        out.extend(data)
        out.extend(b"\0" * (-len(out) % 4))
        acc = {"bufferView": len(views) - 1, "componentType": component, "count": len(array), "type": gl_type}
        if gl_type == "VEC3" and component == 5126:
            acc["min"], acc["max"] = array.min(axis=0).tolist(), array.max(axis=0).tolist()
        accessors.append(acc)
        return len(accessors) - 1

    for mesh in g["meshes"]:
        for prim in mesh["primitives"]:
            idx = read_accessor(g, blob, prim["indices"]).reshape(-1, 3).astype(np.int64)
            attrs = {}
            for name, a in prim["attributes"].items():
                v = read_accessor(g, blob, a).astype(np.float64)[idx]  # (tris, 3, width)
                p = v[:, :1] + w[None, :, :1] * (v[:, 1:2] - v[:, :1]) + w[None, :, 1:] * (v[:, 2:3] - v[:, :1])
                p = p.reshape(-1, v.shape[2]).astype(np.float32)
                if name == "NORMAL":
                    p /= np.maximum(np.linalg.norm(p, axis=1, keepdims=True), 1e-12)
                attrs[name] = add(p, {2: "VEC2", 3: "VEC3", 4: "VEC4"}[v.shape[2]], 5126, 34962)
            base = (np.arange(len(idx), dtype=np.uint32) * np.uint32(len(w)))[:, None, None]
            tris = (base + sub[None]).reshape(-1)
            triangles += len(tris) // 3
            prim["attributes"], prim["indices"] = attrs, add(tris, "SCALAR", 5125, 34963)
    g["accessors"], g["bufferViews"] = accessors, views
    bin_name = os.path.basename(path)[:-5] + ".bin"
    g["buffers"] = [{"uri": bin_name, "byteLength": len(out)}]
    with open(os.path.join(os.path.dirname(path), bin_name), "wb") as f:
        f.write(out)
    with open(path, "w") as f:
        json.dump(g, f)
    return triangles


def measure(vct, command, scene, grid, size, out):
    """(predicted bytes, peak RSS bytes, run.json) of one `vct render --backend ref` (or gl) or one
    `vct validate --no-report` (its default 64 spp: the path tracer's time counts in its renders)."""
    if command in ("render", "gl"):
        args = [vct, "render", scene, "--backend", "ref" if command == "render" else "gl"]
    else:
        args = [vct, "validate", scene, "--no-report"]
    subprocess.run(args + ["--grid", str(grid), "--width", str(size), "--height", str(size), "--out", out],
                   check=command != "validate", stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "run.json")) as f:
        run = json.load(f)
    return run["memory"]["predicted_bytes"], run["memory"]["peak_rss_bytes"], run


def non_render_ratio(run):
    """validate's everything-else / renders, wall and CPU (app/phase_times.h: run.json "phases")."""
    p = run.get("phases", {})
    wall = p.get("other_ms", 0.0) / max(p.get("render_ms", 0.0), 1e-9)
    cpu = p.get("other_cpu_ms", 0.0) / max(p.get("render_cpu_ms", 0.0), 1e-9)
    return wall, cpu


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--splits", default="1,4,8,20", help="each triangle into n^2 (2382 n^2 triangles)")
    ap.add_argument("--grids", default="64,128,256")
    ap.add_argument("--size", type=int, default=128)
    ap.add_argument("--vct", default=os.environ.get("VCT_BINARY", os.path.join(ROOT, "build", "bin", "vct")))
    ap.add_argument("--command", choices=("render", "gl", "validate"), default="render",
                    help="gl: vct render --backend gl; validate: its predicted/peak and its non-render/renders "
                    "ratio (wall, CPU) per row")
    a = ap.parse_args(argv)
    if a.command == "validate" and a.size == 128 and "--size" not in argv:
        a.size = 256  # validate's default image
    mib = 1024.0 * 1024.0
    print("load average %s" % " ".join("%.2f" % x for x in os.getloadavg()))
    extra = " validate non-render / renders (wall, CPU) |" if a.command == "validate" else ""
    print("| triangles | grid | predicted MiB | peak RSS MiB | predicted / peak |" + extra)
    print("| --- | --- | --- | --- | --- |" + (" --- |" if extra else ""))
    with tempfile.TemporaryDirectory(prefix="vct-memory-") as work:
        for n in (int(s) for s in a.splits.split(",")):
            scene = os.path.join(work, "split_%d.gltf" % n)
            tris = split_scene(n, scene)
            for grid in (int(s) for s in a.grids.split(",")):
                pred, peak, run = measure(a.vct, a.command, scene, grid, a.size,
                                          os.path.join(work, "run_%d_%d" % (n, grid)))
                row = "| %d | %d | %.0f | %.0f | %.2f |" % (tris, grid, pred / mib, peak / mib, pred / peak)
                if a.command == "validate":
                    row += " %.2f, %.2f |" % non_render_ratio(run)
                print(row)
                sys.stdout.flush()
    print("load average %s" % " ".join("%.2f" % x for x in os.getloadavg()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
