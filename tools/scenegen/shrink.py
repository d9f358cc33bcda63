"""Shrinks a failing scene spec to a minimal one that still fails the same way (GraphicsFuzz's
reduction, greedy): each pass proposes smaller specs (drop a setting, a light, a mesh, a texture
slot, vertex colours, an alpha mask; remove chunks of triangles, ddmin-style; halve the image,
the grid, the shadow map, a texture) and keeps the first one for which `still_fails` holds, until
no pass makes progress or the budget of predicate calls is spent. The predicate is all it knows
of `vct`: tests/scenegen/test_shrink.py drives it with a synthetic one.

With `pin_bounds`, the triangles that hold the scene's extreme vertices (world space, per axis) are
never dropped, so the scene's bounds stay as they were, and with them everything the loader and the
renderers fit to them: the voxel volume (hence every voxel's place), an infinite camera's far
plane and the spot lights' shadow depth ranges (docs/compare.md, "False-alarm hunt"). Without it a
voxel failure moves with the grid as triangles go, and cannot be shrunk."""
import copy

import numpy as np

from generate import world_points


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
    """Removes a mesh (its material stays: an unused material is still valid glTF); not one that
    holds a pinned triangle."""
    for k in range(len(spec["meshes"])):
        if _pinned(spec["meshes"][k]).any():
            continue
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
    of one triangle at the finest), pinned triangles excepted. Unreferenced vertices are compacted
    away."""
    for k, mesh in enumerate(spec["meshes"]):
        count = len(mesh["indices"])
        pinned = _pinned(mesh)
        n = 2
        while count > 1 and n <= 2 * count:
            bounds = np.linspace(0, count, min(n, count) + 1).astype(int)
            for lo, hi in zip(bounds[:-1], bounds[1:]):
                keep = np.ones(count, dtype=bool)
                keep[lo:hi] = False
                keep |= pinned
                if hi > lo and hi - lo < count and not keep.all():
                    s = copy.deepcopy(spec)
                    _set_triangles(s["meshes"][k], keep)
                    yield "triangles %d..%d of %s" % (lo, hi, mesh["name"]), s
            n *= 2


def _set_triangles(mesh, keep):
    """Keeps the triangles where `keep` is true (a mask over mesh["indices"])."""
    if mesh.get("pinned") is not None:
        mesh["pinned"] = mesh["pinned"][keep]
    used, remap = np.unique(mesh["indices"][keep].reshape(-1), return_inverse=True)
    mesh["indices"] = remap.reshape(-1, 3)
    for key in ("positions", "normals", "uv", "colors"):
        if mesh.get(key) is not None:
            mesh[key] = mesh[key][used]


def _pinned(mesh):
    pinned = mesh.get("pinned")
    return pinned if pinned is not None else np.zeros(len(mesh["indices"]), dtype=bool)


def pin_bounds(spec):
    """A copy of spec whose meshes mark ("pinned") one triangle for each of the six extreme
    vertices of the whole scene in world space (min and max per axis; the first in mesh and index
    order where several share the extreme)."""
    s = copy.deepcopy(spec)
    best = {}  # (axis, side) -> (value, mesh, triangle)
    for k, mesh in enumerate(s["meshes"]):
        mesh["pinned"] = np.zeros(len(mesh["indices"]), dtype=bool)
        if len(mesh["indices"]) == 0:
            continue
        corners = world_points(mesh, mesh["positions"])[mesh["indices"]]  # triangles x 3 x 3
        for axis in range(3):
            for side, pick in ((0, np.argmin), (1, np.argmax)):
                flat = pick(corners[:, :, axis])
                value = corners[:, :, axis].reshape(-1)[flat]
                old = best.get((axis, side))
                if old is None or (value < old[0] if side == 0 else value > old[0]):
                    best[(axis, side)] = (value, k, flat // 3)
    for _, k, tri in best.values():
        s["meshes"][k]["pinned"][tri] = True
    return s


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


def shrink(spec, still_fails, budget=200, log=None, pin=False):
    """The smallest spec the passes reach for which still_fails(spec) is true, and the number of
    predicate calls made. `spec` itself is assumed to fail (it is not re-checked). pin: keep the
    scene's bounds (pin_bounds)."""
    if pin:
        spec = pin_bounds(spec)
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
