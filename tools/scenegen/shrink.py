"""Shrinks a failing scene spec to a minimal one that still fails the same way (GraphicsFuzz's
reduction, greedy): each pass proposes smaller specs (drop a setting, a light, a mesh, a texture
slot, vertex colours, an alpha mask; remove chunks of triangles, ddmin-style; halve the image,
the grid, the shadow map, a texture) and keeps the first one for which `still_fails` holds, until
no pass makes progress or the budget of predicate calls is spent. The predicate is all it knows
of `vct`: tests/scenegen/test_shrink.py drives it with a synthetic one."""
import copy

import numpy as np


def _without(items, k):
    return items[:k] + items[k + 1:]


def drop_settings(spec):
    for key in list(spec["settings"]):
        s = copy.deepcopy(spec)
        del s["settings"][key]
        yield "setting %s" % key, s


def drop_lights(spec):
    for k in range(len(spec["lights"])):
        s = copy.deepcopy(spec)
        s["lights"] = _without(s["lights"], k)
        yield "light %s" % spec["lights"][k]["name"], s


def drop_meshes(spec):
    """Removes a mesh (its material stays: an unused material is still valid glTF)."""
    for k in range(len(spec["meshes"])):
        s = copy.deepcopy(spec)
        s["meshes"] = _without(s["meshes"], k)
        yield "mesh %s" % spec["meshes"][k]["name"], s


def drop_material_features(spec):
    for k, mat in enumerate(spec["materials"]):
        for slot in list(mat.get("textures", {})):
            s = copy.deepcopy(spec)
            del s["materials"][k]["textures"][slot]
            yield "%s texture of %s" % (slot, mat["name"]), s
        for key in ("alpha_mode", "emissive", "double_sided", "lambert"):
            if mat.get(key):
                s = copy.deepcopy(spec)
                s["materials"][k][key] = None
                yield "%s of %s" % (key, mat["name"]), s
    for k, mesh in enumerate(spec["meshes"]):
        for key in ("colors", "normals", "uv"):
            if mesh.get(key) is not None and not (key == "uv" and _textured(spec, mesh)):
                s = copy.deepcopy(spec)
                s["meshes"][k][key] = None
                yield "%s of %s" % (key, mesh["name"]), s


def prune_unused(spec):
    """Drops materials no mesh uses and textures no material uses (indices renumbered)."""
    used_mats = sorted({m["material"] for m in spec["meshes"]})
    used_tex = sorted({t for k in used_mats for t in spec["materials"][k].get("textures", {}).values()})
    if len(used_mats) == len(spec["materials"]) and len(used_tex) == len(spec["textures"]):
        return
    s = copy.deepcopy(spec)
    mat_of = {old: new for new, old in enumerate(used_mats)}
    tex_of = {old: new for new, old in enumerate(used_tex)}
    s["materials"] = [s["materials"][k] for k in used_mats]
    s["textures"] = [s["textures"][k] for k in used_tex]
    for mesh in s["meshes"]:
        mesh["material"] = mat_of[mesh["material"]]
    for mat in s["materials"]:
        mat["textures"] = {slot: tex_of[t] for slot, t in mat.get("textures", {}).items()}
    yield "unused materials and textures", s


def _textured(spec, mesh):
    return bool(spec["materials"][mesh["material"]].get("textures"))


def drop_triangles(spec):
    """ddmin over each mesh's triangles: remove one of n equal chunks, n = 2, 4, 8, ... (a chunk
    of one triangle at the finest). Unreferenced vertices are compacted away."""
    for k, mesh in enumerate(spec["meshes"]):
        count = len(mesh["indices"])
        n = 2
        while count > 1 and n <= 2 * count:
            bounds = np.linspace(0, count, min(n, count) + 1).astype(int)
            for lo, hi in zip(bounds[:-1], bounds[1:]):
                if hi > lo and hi - lo < count:
                    s = copy.deepcopy(spec)
                    keep = np.concatenate([mesh["indices"][:lo], mesh["indices"][hi:]])
                    _set_triangles(s["meshes"][k], keep)
                    yield "triangles %d..%d of %s" % (lo, hi, mesh["name"]), s
            n *= 2


def _set_triangles(mesh, tris):
    used, remap = np.unique(tris.reshape(-1), return_inverse=True)
    mesh["indices"] = remap.reshape(-1, 3)
    for key in ("positions", "normals", "uv", "colors"):
        if mesh.get(key) is not None:
            mesh[key] = mesh[key][used]


def halve_sizes(spec):
    for key, floor in (("width", 8), ("height", 8), ("grid", 16), ("shadow_map_size", 64)):
        if spec[key] // 2 >= floor:
            s = copy.deepcopy(spec)
            s[key] = spec[key] // 2
            yield "%s %d" % (key, s[key]), s
    for k, tex in enumerate(spec["textures"]):
        h, w = tex["pixels"].shape[:2]
        if h > 1 or w > 1:
            s = copy.deepcopy(spec)
            s["textures"][k]["pixels"] = tex["pixels"][::2 if h > 1 else 1, ::2 if w > 1 else 1].copy()
            yield "texture %d to %dx%d" % (k, (w + 1) // 2, (h + 1) // 2), s


PASSES = [drop_settings, drop_lights, drop_meshes, prune_unused, drop_material_features, halve_sizes, drop_triangles]


def shrink(spec, still_fails, budget=200, log=None):
    """The smallest spec the passes reach for which still_fails(spec) is true, and the number of
    predicate calls made. `spec` itself is assumed to fail (it is not re-checked)."""
    calls = 0
    progress = True
    while progress and calls < budget:
        progress = False
        for make in PASSES:
            accepted = True
            while accepted and calls < budget:
                accepted = False
                for what, candidate in make(spec):
                    calls += 1
                    if still_fails(candidate):
                        spec, accepted, progress = candidate, True, True
                        if log:
                            log("  shrink: dropped %s (call %d)" % (what, calls))
                        break
                    if calls >= budget:
                        break
    return spec, calls
