#!/usr/bin/env python3
"""Our path tracer against Mitsuba 3 on one Cornell box with a spot and an area light (issues 16
and 37; derivation of the test's bound in docs/compare.md, "Path tracer against Mitsuba 3";
figures in docs/performance.md).

  bench/mitsuba_compare.py [--glossy] [--size 128] [--spp 256] [--depth 64] [--threads 2]
                           [--variant llvm_ad_rgb|scalar_rgb] [--estimand centres|box]
                           [--pt-sampler sobol,independent] [--mitsuba-samplers independent,stratified,multijitter]
                           [--ref-parts 16] [--seeds 2] [--vct build/bin/vct] [--work DIR]
      benchmark, run by hand: efficiency 1 / (MSE x CPU seconds of the render itself), ours over
      Mitsuba's, each MSE against a converged reference (Mitsuba's independent sampler at
      ref-parts x spp through pixel centres, its own variance subtracted), --seeds renders each (default 2), at
      equal spp and at equal CPU time (Mitsuba's spp scaled to our CPU time); prints RATIO lines
      and the load average. Each Mitsuba render runs in a worker process of its own
      (--mitsuba-worker); on llvm_ad_rgb it is rendered twice and the second timed (no kernel
      compilation counted), with Dr.Jit's pool at --threads. --estimand centres (default): Mitsuba's
      camera rays through pixel centres as ours; box: mi.render with a box filter (another image).
      Ours: pt.sampler (default sobol: scrambled Sobol replicates, docs/pathtracer.md), its CPU
      time from run.json pathtrace.render_cpu_seconds. Not ldsampler: biased here (docs/performance.md).
      --work DIR keeps every render there (default: a temporary directory), the reference as ref.npy
      with its variance in ref.json, so that our images can be scored again without Mitsuba.
  bench/mitsuba_compare.py --test [--size 32] [--spp 64]
      correctness (ctest pt_mitsuba_agreement): the image means of the two renderers (Mitsuba
      scalar_rgb, pixel centres) agree per channel within 4 standard errors; exit 0 pass, 1 fail,
      77 skipped (no mitsuba in the venv).
  bench/mitsuba_compare.py --test --glossy
      the same with the scene's glossy metal box and glossy dielectric sphere kept, Mitsuba shading
      them with our Cook–Torrance as a Python BSDF (bench/mitsuba_cook_torrance.py; ctest
      pt_mitsuba_glossy_agreement); the benchmark's --glossy is the built-in scene's materials.

The LLVM variant needs LLVM >= 17 for drjit 1.5: Debian's libllvm19 (scripts/setup.sh), found
through DRJIT_LIBLLVM_PATH (set for the worker when unset).

The scene is scenes/cornell_box.gltf with flat normals, the camera moved off its symmetry plane
(cornell_scene says why), its two glossy objects made Lambertian (kept with --glossy) and its spot made
hard-edged (inner 0.75 rad, outer 0.7505 rad): glTF's cone falloff (KHR_lights_punctual) and
Mitsuba's (linear in angle) differ inside the transition, so the transition is made 0.5 mrad wide.
Both renderers get the same triangles, albedos, emission (front faces only), camera and light
(radiant intensity in W/sr; glTF candela are read as such by ref/pt). Our path tracer shoots every
camera ray through the pixel centre (so its pixels are the VCT frame's), so the test and the
benchmark trace Mitsuba's camera rays through pixel centres too (--estimand box: mi.render).
"""
import argparse
import base64
import contextlib
import json
import math
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
INNER, OUTER = 0.75, 0.7505
CAMERA_SHIFT = (0.0123, 0.0071, 0.0)  # off the box's symmetry: see cornell_scene


# ------------------------------------------------------------------ the scene, both ways
def cornell_scene(path, glossy):
    """Writes the benchmark scene (a glTF) and returns its parsed form for Mitsuba: Lambertian
    unless glossy. Two changes keep the comparison free of ties that are not the physics:
    - NORMAL is dropped (glTF's flat-normal rule in ours, face_normals in Mitsuba): the sphere's
      smooth normals would otherwise meet Mitsuba's flat ones (up to 80 % per pixel, 0.3 % of the mean);
    - the camera moves off the box's symmetry plane: from (0, 1, 3.6) the floor–wall edges project
      exactly onto the image diagonals, so pixel-centre rays hit an edge shared by two surfaces and
      which one either renderer reports is a tie (measured: 13 pixels, 2 % of the image mean)."""
    with open(os.path.join(ROOT, "scenes", "cornell_box.gltf")) as f:
        g = json.load(f)
    for m in g["materials"]:
        if glossy:
            continue
        pbr = m["pbrMetallicRoughness"]
        pbr["metallicFactor"], pbr["roughnessFactor"] = 0.0, 1.0
        m.setdefault("extensions", {})["KHR_materials_specular"] = {"specularFactor": 0.0}
    for mesh in g["meshes"]:
        for prim in mesh["primitives"]:
            prim["attributes"].pop("NORMAL", None)
    for node in g["nodes"]:
        if "camera" in node:
            node["translation"] = [t + d for t, d in zip(node["translation"], CAMERA_SHIFT)]
    spot = g["extensions"]["KHR_lights_punctual"]["lights"][0]
    spot["spot"] = {"innerConeAngle": INNER, "outerConeAngle": OUTER}
    with open(path, "w") as f:
        json.dump(g, f)
    return g


def quat_rotate(q, v):
    x, y, z, w = q
    u = np.array([x, y, z])
    v = np.asarray(v, dtype=np.float64)
    return v + 2.0 * np.cross(u, np.cross(u, v) + w * v)


def accessor(g, blob, index):
    """One glTF accessor as an (count, width) array (tightly packed views, as the generator writes)."""
    a = g["accessors"][index]
    view = g["bufferViews"][a["bufferView"]]
    dtype = np.dtype({5126: "<f4", 5125: "<u4", 5123: "<u2", 5121: "u1"}[a["componentType"]])
    width = {"SCALAR": 1, "VEC2": 2, "VEC3": 3, "VEC4": 4}[a["type"]]
    if view.get("byteStride", dtype.itemsize * width) != dtype.itemsize * width:
        raise SystemExit("mitsuba_compare: interleaved glTF buffers are not supported")
    start = view.get("byteOffset", 0) + a.get("byteOffset", 0)
    return np.frombuffer(blob, dtype=dtype, count=a["count"] * width, offset=start).reshape(a["count"], width)


def write_ply(path, vertices, faces):
    with open(path, "wb") as f:
        f.write(("ply\nformat binary_little_endian 1.0\nelement vertex %d\nproperty float x\nproperty float y\n"
                 "property float z\nelement face %d\nproperty list uchar int vertex_indices\nend_header\n"
                 % (len(vertices), len(faces))).encode())
        f.write(np.asarray(vertices, dtype="<f4").tobytes())
        rows = np.zeros(len(faces), dtype=[("n", "u1"), ("i", "<i4", 3)])
        rows["n"], rows["i"] = 3, faces
        f.write(rows.tobytes())


def mitsuba_bsdf(material):
    """Mitsuba's diffuse BSDF where the material is Lambertian (specularFactor 0, not metallic),
    else our Cook–Torrance as a Python plugin (bench/mitsuba_cook_torrance.py)."""
    pbr = material["pbrMetallicRoughness"]
    albedo = pbr.get("baseColorFactor", [1, 1, 1, 1])[:3]
    specular = material.get("extensions", {}).get("KHR_materials_specular", {}).get("specularFactor", 1.0)
    metallic = pbr.get("metallicFactor", 1.0)
    if specular == 0.0 and metallic == 0.0:
        return {"type": "diffuse", "reflectance": {"type": "rgb", "value": albedo}}
    return {"type": "vct_cook_torrance", "albedo_r": albedo[0], "albedo_g": albedo[1], "albedo_b": albedo[2],
            "metallic": metallic, "roughness": pbr.get("roughnessFactor", 1.0), "specular_factor": specular}


def mitsuba_scene(g, work, size, spp, depth, seed, sampler="independent"):
    import mitsuba as mi
    T = mi.ScalarTransform4f
    blob = base64.b64decode(g["buffers"][0]["uri"].split(",", 1)[1])
    scene = {"type": "scene",
             "integrator": {"type": "path", "max_depth": depth + 1}}  # Mitsuba counts the camera segment
    for n, node in enumerate(g["nodes"]):
        if "mesh" in node:
            t = np.array(node.get("translation", [0, 0, 0]), dtype=np.float64)
            q = node.get("rotation", [0, 0, 0, 1])
            s = np.array(node.get("scale", [1, 1, 1]), dtype=np.float64)
            for k, prim in enumerate(g["meshes"][node["mesh"]]["primitives"]):
                p = accessor(g, blob, prim["attributes"]["POSITION"]).astype(np.float64) * s
                p = np.array([quat_rotate(q, v) for v in p]) + t
                idx = accessor(g, blob, prim["indices"]).reshape(-1, 3).astype(np.int32)
                ply = os.path.join(work, "mesh_%d_%d.ply" % (n, k))
                write_ply(ply, p, idx)
                m = g["materials"][prim["material"]]
                shape = {"type": "ply", "filename": ply, "face_normals": True, "bsdf": mitsuba_bsdf(m)}
                if "emissiveFactor" in m:
                    strength = m.get("extensions", {}).get("KHR_materials_emissive_strength", {}).get("emissiveStrength", 1.0)
                    shape["emitter"] = {"type": "area", "radiance": {"type": "rgb",
                                                                     "value": [c * strength for c in m["emissiveFactor"]]}}
                scene["shape_%d_%d" % (n, k)] = shape
        if "camera" in node:
            cam = g["cameras"][node["camera"]]["perspective"]
            eye = np.array(node["translation"], dtype=np.float64)
            q = node.get("rotation", [0, 0, 0, 1])
            scene["sensor"] = {
                "type": "perspective", "fov_axis": "y", "fov": math.degrees(cam["yfov"]), "near_clip": cam.get("znear", 0.05),
                "to_world": T().look_at(origin=eye.tolist(), target=(eye + quat_rotate(q, [0, 0, -1])).tolist(),
                                        up=quat_rotate(q, [0, 1, 0]).tolist()),
                "film": {"type": "hdrfilm", "width": size, "height": size, "rfilter": {"type": "box"}, "pixel_format": "rgb"},
                "sampler": {"type": sampler, "sample_count": spp, "seed": seed}}
        if "extensions" in node:
            light = g["extensions"]["KHR_lights_punctual"]["lights"][node["extensions"]["KHR_lights_punctual"]["light"]]
            pos = np.array(node["translation"], dtype=np.float64)
            q = node.get("rotation", [0, 0, 0, 1])
            d = quat_rotate(q, [0, 0, -1])
            up = quat_rotate(q, [0, 1, 0])
            scene["spot"] = {"type": "spot", "to_world": T().look_at(origin=pos.tolist(), target=(pos + d).tolist(), up=up.tolist()),
                             "intensity": {"type": "rgb", "value": [c * light["intensity"] for c in light["color"]]},
                             "cutoff_angle": math.degrees(OUTER), "beam_width": math.degrees(INNER)}
    return scene


LLVM_CANDIDATES = ("/usr/lib/x86_64-linux-gnu/libLLVM-19.so", "/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1",
                   "/usr/lib/llvm-19/lib/libLLVM.so")


def mitsuba_env(variant):
    """The worker's environment: Dr.Jit's LLVM backend needs LLVM >= 17 (drjit 1.5 aborts on 15/16,
    "Cannot select: fminimum"); Debian 12's libllvm19 (scripts/setup.sh) is pointed at unless
    DRJIT_LIBLLVM_PATH is already set. Mesa's LLVM 15 never loads in that process (docs/performance.md)."""
    env = dict(os.environ)
    if variant.startswith("llvm") and "DRJIT_LIBLLVM_PATH" not in env:
        found = [p for p in LLVM_CANDIDATES if os.path.exists(p)]
        if found:
            env["DRJIT_LIBLLVM_PATH"] = found[0]
    return env


def render_mitsuba(g, work, size, spp, depth, seed, centres=False, sampler="independent", variant="scalar_rgb",
                   warm=False, threads=0):
    """Mitsuba's image, wall and CPU seconds of the render alone, rendered in a worker process of its
    own (`--mitsuba-worker`: Dr.Jit's libLLVM and its thread pool apart from everything else).
    centres=True: every camera ray through the pixel centre, as ref/pt/camera_ray.cpp shoots them
    (the same estimand as ours); else mi.render with a box pixel filter. warm=True (LLVM): the
    render runs twice and the second is timed, so Dr.Jit's kernel compilation is not counted."""
    spec = {"scene": g, "work": work, "size": size, "spp": spp, "depth": depth, "seed": seed, "centres": centres,
            "sampler": sampler, "variant": variant, "warm": warm,
            "threads": threads}
    tag = "%s_%s_%d_%d_%d" % (variant, sampler, spp, seed, int(centres))
    spec_path, out = os.path.join(work, "mi_%s.json" % tag), os.path.join(work, "mi_%s" % tag)
    with open(spec_path, "w") as f:
        json.dump(spec, f)
    subprocess.run([sys.executable, os.path.abspath(__file__), "--mitsuba-worker", spec_path, out], check=True,
                   env=mitsuba_env(variant))
    with open(out + ".json") as f:
        t = json.load(f)
    return np.load(out + ".npy"), t["wall"], t["cpu"]


def mitsuba_worker(spec_path, out):
    """One Mitsuba render (see render_mitsuba), image to OUT.npy, times to OUT.json."""
    import mitsuba as mi
    with open(spec_path) as f:
        s = json.load(f)
    mi.set_variant(s["variant"])
    if s.get("threads") and not s["variant"].startswith("scalar"):
        import drjit as dr
        dr.set_thread_count(s["threads"])  # Dr.Jit's pool (nanothread); default: every core
    import mitsuba_cook_torrance
    mitsuba_cook_torrance.register()
    scene = mi.load_dict(mitsuba_scene(s["scene"], s["work"], s["size"], s["spp"], s["depth"], s["seed"], s["sampler"]))
    draw = render_centres if s["centres"] else render_box
    if s["warm"]:
        draw(mi, scene, s["size"], s["spp"], s["seed"])
    t0, c0 = time.perf_counter(), time.process_time()  # process_time: every thread of this process
    img = draw(mi, scene, s["size"], s["spp"], s["seed"])
    times = {"wall": time.perf_counter() - t0, "cpu": time.process_time() - c0}
    np.save(out + ".npy", img)
    with open(out + ".json", "w") as f:
        json.dump(times, f)


def render_box(mi, scene, size, spp, seed):
    return np.array(mi.render(scene, seed=seed), dtype=np.float64)[:, :, :3]


def render_centres(mi, scene, size, spp, seed):
    """Pixel-centre camera rays: per ray in Python on scalar variants (small images only), one
    wavefront of size² × spp rays on the vectorised ones (pixel-major, spp consecutive lanes per
    pixel, as mi.render lays them out, so stratified samplers stratify per pixel)."""
    sensor, integrator = scene.sensors()[0], scene.integrator()
    sampler = sensor.sampler().clone()
    if mi.variant().startswith("scalar"):
        return centres_scalar(mi, scene, sensor, integrator, sampler, size, spp, seed)
    import drjit as dr
    # The sampler's own count: stratified and multijitter round a requested count (412 -> 441), and
    # lanes laid out by the requested one would straddle its per-pixel strata (each pixel's lanes no
    # longer one stratified set): the equal-time renders of issue 37's first table did that.
    spp = sampler.sample_count()
    n = size * size * spp
    sampler.seed(seed, n)
    pixel = dr.arange(mi.UInt32, n) // spp
    x, y = mi.Float(pixel % size), mi.Float(pixel // size)
    ray, weight = sensor.sample_ray(0.0, 0.5, mi.Point2f((x + 0.5) / size, (y + 0.5) / size), mi.Point2f(0.5, 0.5))
    spec = integrator.sample(scene, sampler, ray)[0] * weight
    dr.eval(spec)  # one kernel for the three channels: block_sum evaluates its input, channel by channel
    channels = [np.array(dr.block_sum(spec[c], spp), dtype=np.float64) / spp for c in range(3)]
    return np.stack(channels, axis=-1).reshape(size, size, 3)


def centres_scalar(mi, scene, sensor, integrator, sampler, size, spp, seed):
    sampler.seed(seed, 1)
    img = np.zeros((size, size, 3))
    for y in range(size):
        for x in range(size):
            acc = [0.0, 0.0, 0.0]
            centre = mi.Point2f((x + 0.5) / size, (y + 0.5) / size)
            for _ in range(spp):
                ray, weight = sensor.sample_ray(0.0, 0.5, centre, mi.Point2f(0.5, 0.5))
                spec = integrator.sample(scene, sampler, ray)[0]
                for c in range(3):
                    acc[c] += spec[c] * weight[c]
                sampler.advance()
            img[y, x] = np.array(acc) / spp
    return img


def render_ours(vct, scene_path, work, size, spp, depth, seed, threads, sampler=None):
    out = os.path.join(work, "ours_%s_%d_%d" % (sampler, spp, seed))  # a fresh run dir (no resume)
    cfg = out + ".json"
    with open(cfg, "w") as f:
        json.dump({"pt": {"seed": seed, **({"sampler": sampler} if sampler else {})}}, f)
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([vct, "pathtrace", scene_path, "--config", cfg, "--width", str(size), "--height", str(size),
                    "--spp", str(spp), "--max-depth", str(depth), "--threads", str(threads), "--quiet", "--out", out],
                   check=True, stdout=subprocess.DEVNULL)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.path.join(out, "run.json")) as f:
        pt = json.load(f)["pathtrace"]
    # CPU time of the passes alone (run.json); older binaries: the whole child (load and BVH included).
    cpu = pt.get("render_cpu_seconds", (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime))
    seconds = pt["render_seconds"]
    import mitsuba as mi
    mi.set_variant("scalar_rgb")
    img = np.array(mi.Bitmap(os.path.join(out, "pt_full.exr")), dtype=np.float64)[:, :, :3]
    return img, seconds, cpu


# ------------------------------------------------------------------ statistics
def pair_stats(a, b):
    """Two independent renders of one image: their mean image's per-channel mean, the standard
    error of that mean, and the per-pixel variance of one render (docs/compare.md)."""
    d = a - b
    pixels = a.shape[0] * a.shape[1]
    per_pixel_var = (d * d / 2.0).reshape(-1, 3)  # E[(a-b)^2] / 2 = Var of one render, per pixel
    mean = ((a + b) / 2.0).reshape(-1, 3).mean(axis=0)
    se = np.sqrt(per_pixel_var.sum(axis=0) / pixels ** 2 / 2.0)  # Var(mean of P pixels of (a+b)/2)
    return mean, se, float(per_pixel_var.mean())




def mse(img, ref):
    """Mean over pixels and channels of (img - ref)^2 (docs/performance.md: efficiency)."""
    return float(((img - ref) ** 2).mean())


def reference(g, work, size, spp, depth, variant, parts):
    """A converged pixel-centre image: Mitsuba's independent sampler, `parts` renders of spp with
    seeds 1000.., averaged; and the per-pixel variance of that average (from its parts), which
    every MSE against it carries and which is subtracted from the MSEs below."""
    imgs = [render_mitsuba(g, work, size, spp, depth, 1000 + k, True, "independent", variant)[0] for k in range(parts)]
    stack = np.stack(imgs)
    ref, ref_var = stack.mean(axis=0), float(stack.var(axis=0, ddof=1).mean() / parts)
    np.save(os.path.join(work, "ref.npy"), ref)
    with open(os.path.join(work, "ref.json"), "w") as f:
        json.dump({"variance": ref_var, "parts": parts, "spp": spp, "variant": variant}, f)
    return ref, ref_var


def benchmark(a, g, scene_path, work, size, spp):
    """Efficiency 1 / (MSE x CPU seconds of the render), ours over Mitsuba's, each MSE against a
    converged reference (its own variance subtracted), --seeds renders each; at equal spp and at equal
    CPU time (Mitsuba's spp scaled to our CPU time)."""
    centres = a.estimand == "centres"
    ours_samplers = a.pt_sampler.split(",")
    seeds = range(1, a.seeds + 1)
    ref, ref_var = reference(g, work, size, spp, a.depth, a.variant, a.ref_parts)
    print("  reference: mitsuba %s independent, pixel centres, %d x %d spp; its own per-pixel variance %.3g "
          "(subtracted from each MSE)" % (a.variant, a.ref_parts, spp, ref_var))

    def stats(runs):
        err = np.mean([mse(r[0], ref) for r in runs]) - ref_var
        return err, min(r[1] for r in runs), min(r[2] for r in runs), np.mean([r[0].mean() for r in runs])

    ours = {n: stats([render_ours(a.vct, scene_path, work, size, spp, a.depth, seed, a.threads, n) for seed in seeds])
            for n in ours_samplers}
    theirs = {n: stats([render_mitsuba(g, work, size, spp, a.depth, seed, centres, n, a.variant, warm=True,
                                       threads=a.threads)
                        for seed in seeds]) for n in a.mitsuba_samplers.split(",")}
    print("  ref image mean %.5f" % ref.mean())
    for name, (err, wall, cpu, mean) in list(ours.items()) + [("mitsuba " + k, v) for k, v in theirs.items()]:
        print("  %-28s %d spp: MSE %.4g  wall %.2f s  CPU %.2f s  image mean %.5f  efficiency 1/(MSE*CPU) %.4g"
              % (name, spp, err, wall, cpu, mean, 1.0 / (err * cpu)))
    for on, (oerr, owall, ocpu, _) in ours.items():
        for mn, (merr, mwall, mcpu, _) in theirs.items():
            print("  RATIO equal spp: ours %s / mitsuba %s %s: efficiency %.2f by CPU, %.2f by wall"
                  % (on, a.variant, mn, (merr * mcpu) / (oerr * ocpu), (merr * mwall) / (oerr * owall)))
    # Equal time: Mitsuba's spp scaled so its CPU time matches ours (its render time is linear in spp).
    on, (oerr, owall, ocpu, _) = next(iter(ours.items()))
    for mn, (merr, mwall, mcpu, _) in theirs.items():
        spp_eq = max(1, int(round(spp * ocpu / mcpu)))
        err, wall, cpu, _ = stats([render_mitsuba(g, work, size, spp_eq, a.depth, seed, centres, mn, a.variant, warm=True,
                                                  threads=a.threads)
                                   for seed in seeds])
        print("  RATIO equal time: mitsuba %s %s at %d spp (CPU %.2f s vs ours %.2f s): MSE mitsuba / ours %.2f, "
              "efficiency ours/mitsuba %.2f by CPU" % (a.variant, mn, spp_eq, cpu, ocpu, err / oerr,
                                                       (err * cpu) / (oerr * ocpu)))


def main(argv):
    if argv[:1] == ["--mitsuba-worker"]:
        sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
        mitsuba_worker(argv[1], argv[2])
        return 0
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--test", action="store_true")
    ap.add_argument("--glossy", action="store_true", help="keep the glossy objects (our Cook-Torrance in Mitsuba)")
    ap.add_argument("--size", type=int)
    ap.add_argument("--spp", type=int)
    ap.add_argument("--depth", type=int, default=64)
    ap.add_argument("--threads", type=int, default=2,
                    help="ours, and Dr.Jit's pool on the LLVM variant (1: no worker waits, the steadiest CPU times)")
    ap.add_argument("--vct", default=os.environ.get("VCT_BINARY", os.path.join(ROOT, "build", "bin", "vct")))
    ap.add_argument("--k", type=float, default=4.0, help="--test bound in standard errors")
    ap.add_argument("--pt-sampler", default="sobol",
                    help="ours: pt.sampler (sobol or independent; the benchmark takes a comma-separated list, "
                         "the test the first)")
    ap.add_argument("--variant", default="llvm_ad_rgb", help="benchmark: Mitsuba variant (llvm_ad_rgb, scalar_rgb)")
    ap.add_argument("--mitsuba-samplers", default="independent,stratified,multijitter",
                    help="benchmark: comma-separated Mitsuba samplers (independent, stratified, multijitter, "
                         "orthogonal; not ldsampler: biased here, docs/performance.md)")
    ap.add_argument("--estimand", choices=("centres", "box"), default="centres",
                    help="benchmark: Mitsuba's camera rays through pixel centres (ours' estimand) or its box filter")
    ap.add_argument("--ref-parts", type=int, default=16, help="benchmark: reference = this many x spp")
    ap.add_argument("--seeds", type=int, default=2,
                    help="benchmark: renders per renderer and sampler, MSEs averaged (the glossy scene's are heavy-tailed)")
    ap.add_argument("--work", help="keep the renders and the reference (ref.npy) in this directory")
    a = ap.parse_args(argv)
    size = a.size or (32 if a.test else 128)
    spp = a.spp or (64 if a.test else 256)
    try:
        import mitsuba  # noqa: F401
    except ImportError:
        print("mitsuba_compare: mitsuba is not installed in this Python (scripts/setup.sh puts it in .venv)")
        return 77 if a.test else 3
    if a.work:
        os.makedirs(a.work, exist_ok=True)
    with (contextlib.nullcontext(a.work) if a.work else tempfile.TemporaryDirectory(prefix="vct-mitsuba-")) as work:
        scene_path = os.path.join(work, "cornell_glossy.gltf" if a.glossy else "cornell_lambert.gltf")
        g = cornell_scene(scene_path, a.glossy)
        print("%s Cornell box, spot + area light, %d^2, %d spp, depth %d, load average %s"
              % ("Glossy (our Cook-Torrance in Mitsuba)" if a.glossy else "Lambertian", size, spp, a.depth,
                 " ".join("%.2f" % x for x in os.getloadavg())))
        if not a.test:
            benchmark(a, g, scene_path, work, size, spp)
            print("  load average after: %s" % " ".join("%.2f" % x for x in os.getloadavg()))
            return 0
        sampler = a.pt_sampler.split(",")[0]
        ours = [render_ours(a.vct, scene_path, work, size, spp, a.depth, seed, a.threads, sampler) for seed in (1, 2)]
        theirs = [render_mitsuba(g, work, size, spp, a.depth, seed, True, "independent", "scalar_rgb")
                  for seed in (1, 2)]
    om, ose, _ = pair_stats(ours[0][0], ours[1][0])
    mm, mse_, _ = pair_stats(theirs[0][0], theirs[1][0])
    z = (om - mm) / np.sqrt(ose ** 2 + mse_ ** 2)
    print("  ours     mean RGB %s  +- %s (1 s.e.)" % (np.round(om, 5), np.round(ose, 5)))
    print("  mitsuba  mean RGB %s  +- %s" % (np.round(mm, 5), np.round(mse_, 5)))
    print("  z per channel %s  (bound |z| <= %.1f)" % (np.round(z, 2), a.k))
    ok = bool(np.all(np.abs(z) <= a.k)) and bool(np.all(om > 0))
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
