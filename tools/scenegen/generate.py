"""Random but valid glTF 2.0 scenes from a seed (issue 34, item 2): the scene spec.

A spec is a plain dict (numpy arrays for mesh and texture data) that gltf_writer.py turns into a
file and shrink.py makes smaller; `generate(seed, size_class)` is a pure function of its
arguments (numpy's PCG64 seeded with [seed, class index]), so a seed reproduces its scene exactly.
What is drawn, and why, is in docs/compare.md ("False-alarm hunt").
"""
import math

import numpy as np

import settings_draw
import shapes
import textures

SIZE_CLASSES = ["small", "medium", "large"]
IMAGE_SIDE = {"small": (8, 64), "medium": (32, 128), "large": (64, 256)}
GRIDS = {"small": [16, 32], "medium": [32, 64], "large": [64, 128]}
SHADOW_MAP_SIZES = {"small": [64, 128, 256, 512], "medium": [256, 512, 1024], "large": [1024, 2048]}
MESH_COUNT = {"small": (1, 4), "medium": (2, 6), "large": (1, 3)}
LIGHT_COUNT = {"small": (1, 3), "medium": (1, 5), "large": (1, 4)}


# ----------------------------------------------------------------------------- rotations
def quat_from_matrix(m):
    """Unit quaternion [x, y, z, w] of a rotation matrix (columns = rotated axes)."""
    tr = m[0, 0] + m[1, 1] + m[2, 2]
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        q = [(m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, 0.25 * s]
    elif m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = math.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2]) * 2
        q = [0.25 * s, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s, (m[2, 1] - m[1, 2]) / s]
    elif m[1, 1] > m[2, 2]:
        s = math.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2]) * 2
        q = [(m[0, 1] + m[1, 0]) / s, 0.25 * s, (m[1, 2] + m[2, 1]) / s, (m[0, 2] - m[2, 0]) / s]
    else:
        s = math.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1]) * 2
        q = [(m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, 0.25 * s, (m[1, 0] - m[0, 1]) / s]
    q = np.array(q)
    return q / np.linalg.norm(q)


def look_rotation(forward):
    """Quaternion turning the node's -Z (where cameras and lights look) onto `forward`."""
    f = np.asarray(forward, float) / np.linalg.norm(forward)
    up = np.array([0.0, 1.0, 0.0]) if abs(f[1]) < 0.99 else np.array([1.0, 0.0, 0.0])
    r = np.cross(f, up)
    r /= np.linalg.norm(r)
    u = np.cross(r, f)
    return quat_from_matrix(np.stack([r, u, -f], axis=1))


def quat_rotate(q, v):
    x, y, z, w = q
    u = np.array([x, y, z])
    return v + 2.0 * np.cross(u, np.cross(u, v) + w * v)


def random_quat(rng):
    q = rng.normal(size=4)
    return q / np.linalg.norm(q)


def world_points(mesh, points):
    p = points * np.asarray(mesh.get("scale") or [1, 1, 1])
    p = np.array([quat_rotate(mesh["rotation"], x) for x in p]) if mesh.get("rotation") is not None else p
    return p + np.asarray(mesh.get("translation") or [0, 0, 0])


# ----------------------------------------------------------------------------- meshes
def _attributes(rng, mesh, flat):
    """Normals (flat or smooth, sometimes none), planar UVs with an offset and scale that cross
    texture edges (so every wrap mode matters), COLOR_0 in a random encoding."""
    pos, tris = mesh["positions"], mesh["indices"]
    if flat:
        pos, tris = shapes.unshare(pos, tris)
        mesh["positions"], mesh["indices"] = pos, tris
    if rng.random() < 0.85:
        mesh["normals"] = shapes.vertex_normals(pos, tris)
    if rng.random() < 0.75:
        axes = rng.permutation(3)[:2]
        scale, offset = rng.uniform(0.3, 4.0, 2) * rng.choice([-1, 1], 2), rng.uniform(-1.5, 1.5, 2)
        mesh["uv"] = pos[:, axes] * scale + offset
    if rng.random() < 0.3:
        colors = rng.uniform(0, 1, (len(pos), 4))
        if rng.random() < 0.5:
            colors[:, 3] = 1.0
        mesh["colors"] = colors
        mesh["color_encoding"] = str(rng.choice(["float3", "float4", "ubyte4", "ushort4"]))


def _content_mesh(rng, spec, name, shape, extent):
    pos, tris = shapes.SHAPES[shape](rng, spec["size_class"])
    tris = shapes.drop_degenerate(pos, tris)
    mesh = {"name": name, "shape": shape, "positions": pos, "indices": tris}
    smooth = shape in ("heightfield", "sphere") and rng.random() < 0.8
    _attributes(rng, mesh, flat=not smooth)
    size = extent * rng.uniform(0.15, 0.7)
    scale = [size] * 3 if rng.random() < 0.7 else list(size * rng.uniform(0.3, 1.5, 3))
    if rng.random() < 0.05:
        scale[0] = -scale[0]  # a mirrored node (negative determinant: glTF flips the winding)
    mesh["scale"] = scale
    mesh["rotation"] = random_quat(rng) if rng.random() < 0.6 else None
    mesh["translation"] = list(rng.uniform(-0.3, 0.3, 3) * extent)
    return mesh


def _room(rng, extent):
    pos, tris = shapes.box(rng, "small")
    mesh = {"name": "room", "shape": "room", "positions": pos * extent, "indices": tris[:, ::-1].copy(),
            "translation": None, "rotation": None, "scale": None}
    _attributes(rng, mesh, flat=True)
    return mesh


def _edge_on_plane(camera, distance, extent):
    """A quad containing the camera's view ray: seen exactly edge-on from the eye."""
    forward = quat_rotate(camera["rotation"], np.array([0.0, 0.0, -1.0]))
    side = quat_rotate(camera["rotation"], np.array([1.0, 0.0, 0.0]))
    centre = np.asarray(camera["translation"]) + forward * distance
    half = extent * 0.2
    corners = np.array([centre - forward * half - side * 0.0, centre + forward * half])
    up = quat_rotate(camera["rotation"], np.array([0.0, 1.0, 0.0]))
    pos = np.array([corners[0] - up * half, corners[1] - up * half, corners[1] + up * half, corners[0] + up * half])
    mesh = {"name": "edge_on", "shape": "edge_on", "positions": pos, "indices": np.array([[0, 1, 2], [0, 2, 3]]),
            "translation": None, "rotation": None, "scale": None}
    mesh["normals"] = np.tile(side, (4, 1))
    return mesh


# ----------------------------------------------------------------------------- materials
def _base_color(rng):
    kind = rng.choice(["dark", "saturated", "grey", "random", "white"])
    if kind == "dark":
        rgb = rng.uniform(0.0, 0.05, 3)
    elif kind == "saturated":
        rgb = np.zeros(3)
        rgb[rng.integers(3)] = 1.0
    elif kind == "grey":
        rgb = np.full(3, rng.uniform(0.2, 0.8))
    elif kind == "white":
        rgb = np.ones(3)
    else:
        rgb = rng.uniform(0, 1, 3)
    return [float(v) for v in rgb]


def _material(rng, spec, name, mesh):
    mat = {"name": name, "base_color": _base_color(rng) + [1.0], "metallic": float(rng.choice([0.0, 0.0, 1.0, rng.uniform()])),
           "roughness": float(rng.uniform(0.05, 1.0)), "textures": {}, "lambert": bool(rng.random() < 0.3),
           "double_sided": bool(rng.random() < 0.3)}
    if rng.random() < 0.2:
        mat["alpha_mode"] = "MASK"
        mat["alpha_cutoff"] = float(rng.choice([0.5, rng.uniform(0.05, 0.95)])) if rng.random() < 0.8 else None
        mat["base_color"][3] = float(rng.choice([1.0, rng.uniform(0.3, 1.0)]))
    if rng.random() < 0.1:
        mat["emissive"] = [float(v) for v in rng.uniform(0, 1, 3)]
    if mesh.get("uv") is not None:
        _texture_slots(rng, spec, mat, mesh)
    return mat


def _texture_slots(rng, spec, mat, mesh):
    def add(tex):
        spec["textures"].append(tex)
        return len(spec["textures"]) - 1

    if rng.random() < 0.55:
        mat["textures"]["base_color"] = add(textures.texture(rng, with_alpha=mat.get("alpha_mode") == "MASK" or rng.random() < 0.2))
    if rng.random() < 0.15:
        mat["textures"]["metallic_roughness"] = add(textures.texture(rng, with_alpha=False))
    if rng.random() < 0.15 and mesh.get("normals") is not None:
        mat["textures"]["normal"] = add(textures.normal_map(rng))
    if rng.random() < 0.08:
        mat["textures"]["emissive"] = add(textures.texture(rng, with_alpha=False))
        mat["emissive"] = mat.get("emissive") or [1.0, 1.0, 1.0]


# ----------------------------------------------------------------------------- lights, camera
def _light(rng, kind, index, meshes, extent):
    color = [1.0, 1.0, 1.0] if rng.random() < 0.5 else [float(v) for v in rng.uniform(0.05, 1.0, 3)]
    light = {"name": "%s_%d" % (kind, index), "type": kind, "color": color, "translation": None, "rotation": None}
    if kind == "directional":
        d = rng.normal(size=3)
        d[1] = -abs(d[1]) if rng.random() < 0.8 else d[1]
        light["rotation"] = look_rotation(d)
        light["intensity"] = float(rng.uniform(0.5, 6.0))
        return light
    near_surface = rng.random() < 0.3 and meshes
    if near_surface:  # a lamp a few millimetres to centimetres off a surface
        mesh = meshes[int(rng.integers(len(meshes)))]
        k = int(rng.integers(len(mesh["positions"])))
        p = world_points(mesh, mesh["positions"][k:k + 1])[0]
        position = p + rng.normal(size=3) / math.sqrt(3) * 10.0 ** rng.uniform(-2.3, -1)
    else:
        position = rng.uniform(-0.45, 0.45, 3) * extent
    light["translation"] = [float(v) for v in position]
    light["intensity"] = float(rng.uniform(0.5, 5.0) * (extent / 2) ** 2)
    if rng.random() < 0.3:
        light["range"] = float(extent * rng.uniform(0.3, 2.0))
    if kind == "spot":
        light["outer"] = float(rng.uniform(0.1, 1.5))
        light["inner"] = float(light["outer"] * rng.uniform(0.0, 0.95))
        light["rotation"] = look_rotation(rng.uniform(-0.4, 0.4, 3) * extent - position)
    return light


def _lights(rng, spec, extent):
    lo, hi = LIGHT_COUNT[spec["size_class"]]
    count = int(rng.integers(lo, hi + 1))
    kinds = [str(k) for k in rng.choice(["point", "spot", "directional"], size=count)]
    if count >= 2 and rng.random() < 0.3:  # the orders our zoo lacked: a spot or sun after a point
        kinds[0], kinds[1] = "point", str(rng.choice(["spot", "directional"]))
    return [_light(rng, k, i, spec["meshes"], extent) for i, k in enumerate(kinds)]


def _camera(rng, spec, extent, inside):
    target_mesh = spec["meshes"][int(rng.integers(len(spec["meshes"])))]
    target = world_points(target_mesh, target_mesh["positions"].mean(axis=0, keepdims=True))[0]
    if inside:
        eye = rng.uniform(-0.45, 0.45, 3) * extent
    else:
        d = rng.normal(size=3)
        eye = target + d / np.linalg.norm(d) * extent * rng.uniform(0.8, 2.0)
    if np.linalg.norm(target - eye) < 1e-3:
        eye = eye + np.array([0.0, 0.0, 0.1 * extent])
    aspect = spec["width"] / spec["height"]
    cam = {"translation": [float(v) for v in eye], "rotation": look_rotation(target - eye), "scale": None}
    if rng.random() < 0.25:
        ymag = float(extent * rng.uniform(0.1, 0.7))
        xmag = ymag * aspect if rng.random() < 0.8 else ymag * rng.uniform(0.3, 3.0)
        cam.update(type="orthographic", ymag=ymag, xmag=float(xmag), znear=float(rng.uniform(0.0, 0.05)),
                   zfar=float(extent * 6))
    else:
        cam.update(type="perspective", yfov=float(rng.uniform(0.2, 2.0)), znear=float(10 ** rng.uniform(-2.5, -1)),
                   zfar=float(extent * rng.uniform(3, 10)) if rng.random() < 0.5 else None,
                   aspect=float(aspect) if rng.random() < 0.3 else None)
    return cam


# ----------------------------------------------------------------------------- the scene
def generate(seed, size_class="small"):
    """The spec of scene `seed` in `size_class` (small: <= 64^2 images, grid <= 32, a few hundred
    triangles; medium; large: heightfields up to 1M triangles)."""
    rng = np.random.default_rng([int(seed), SIZE_CLASSES.index(size_class)])
    spec = {"seed": int(seed), "size_class": size_class, "meshes": [], "materials": [], "textures": [], "lights": []}
    lo, hi = IMAGE_SIDE[size_class]
    spec["width"], spec["height"] = int(rng.integers(lo, hi + 1)), int(rng.integers(lo, hi + 1))
    spec["grid"] = int(rng.choice(GRIDS[size_class]))
    spec["shadow_map_size"] = int(rng.choice(SHADOW_MAP_SIZES[size_class]))
    extent = float(rng.uniform(1.5, 6.0))
    inside = rng.random() < 0.6
    if inside:
        spec["meshes"].append(_room(rng, extent))
    lo, hi = MESH_COUNT[size_class]
    names = list(shapes.SHAPES)
    for i in range(int(rng.integers(lo, hi + 1))):
        shape = "heightfield" if size_class == "large" and i == 0 else names[int(rng.integers(len(names)))]
        spec["meshes"].append(_content_mesh(rng, spec, "%s_%d" % (shape, i), shape, extent))
        if shape == "plane" and rng.random() < 0.4:  # a coplanar twin, shifted, other material
            twin = _content_mesh(rng, spec, "coplanar_%d" % i, "plane", extent)
            for key in ("scale", "rotation", "translation"):
                twin[key] = spec["meshes"][-1][key]
            twin["positions"] = twin["positions"] + [0.25, 0.0, 0.1]
            spec["meshes"].append(twin)
    spec["camera"] = _camera(rng, spec, extent, inside)
    if rng.random() < 0.3:
        spec["meshes"].append(_edge_on_plane(spec["camera"], extent * rng.uniform(0.2, 0.6), extent))
    for i, mesh in enumerate(spec["meshes"]):
        mesh["material"] = i
        spec["materials"].append(_material(rng, spec, "material_%d" % i, mesh))
    spec["lights"] = _lights(rng, spec, extent)
    spec["settings"] = settings_draw.draw(rng)
    return spec
