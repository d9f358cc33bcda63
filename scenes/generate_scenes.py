#!/usr/bin/env python3
"""Generates the procedural glTF 2.0 scenes in scenes/ (Python 3 standard library only).

    python3 scenes/generate_scenes.py          # rewrites every scene below
    python3 scenes/generate_scenes.py --check  # exits 1 if a committed file differs

Units are metres, +Y up, lights in glTF units (candela for spot and point lights, lux for a
directional light); see docs/scenes.md.
All buffers are embedded as base64 data URIs so each .gltf is one self-contained file (the
built-in scene is compiled into the binary); demo_room.gltf references its PNG textures in
scenes/textures/ to exercise external images. Output is deterministic (no randomness, fixed
float formatting), so regenerating gives byte-identical files.
"""
import base64
import json
import math
import os
import struct
import sys
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))

FLOAT, UINT8, UINT16, UINT32 = 5126, 5121, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
LAMBERT = {"KHR_materials_specular": {"specularFactor": 0.0}}


# ----------------------------------------------------------------------------- vector helpers
def add(a, b): return [a[i] + b[i] for i in range(3)]
def sub(a, b): return [a[i] - b[i] for i in range(3)]
def mul(a, s): return [a[i] * s for i in range(3)]
def dot(a, b): return sum(a[i] * b[i] for i in range(3))
def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
def normalize(a):
    n = math.sqrt(dot(a, a))
    return [x / n for x in a]


def quat_axis_angle(axis, angle):
    axis = normalize(axis)
    s = math.sin(angle / 2)
    return [round(axis[0] * s, 7), round(axis[1] * s, 7), round(axis[2] * s, 7), round(math.cos(angle / 2), 7)]


# Rotates the node's -Z (where glTF lights and cameras look) onto straight down (-Y).
POINT_DOWN = quat_axis_angle([1, 0, 0], -math.pi / 2)


def look_rotation(eye, target):
    """Quaternion turning -Z toward target-eye with +Y as up (for cameras and spot lights)."""
    f = normalize(sub(target, eye))
    r = normalize(cross(f, [0, 1, 0]))
    u = cross(r, f)
    # Rotation matrix columns: x = r, y = u, z = -f.
    m = [[r[0], u[0], -f[0]], [r[1], u[1], -f[1]], [r[2], u[2], -f[2]]]
    tr = m[0][0] + m[1][1] + m[2][2]
    if tr > 0:
        s = math.sqrt(tr + 1.0) * 2
        q = [(m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s, 0.25 * s]
    elif m[0][0] > m[1][1] and m[0][0] > m[2][2]:
        s = math.sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2
        q = [0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s, (m[2][1] - m[1][2]) / s]
    elif m[1][1] > m[2][2]:
        s = math.sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2
        q = [(m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s, (m[0][2] - m[2][0]) / s]
    else:
        s = math.sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2
        q = [(m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s, (m[1][0] - m[0][1]) / s]
    n = math.sqrt(sum(x * x for x in q))
    return [round(x / n, 7) for x in q]


# ----------------------------------------------------------------------------- meshes
class MeshData:
    """Triangle list with per-vertex position, normal and uv (normals/uvs may be None)."""

    def __init__(self, with_normals=True, with_uv=True, with_tangents=False):
        self.pos, self.nrm, self.uv, self.idx, self.tan = [], [], [], [], []
        self.with_normals, self.with_uv, self.with_tangents = with_normals, with_uv, with_tangents
        # COLOR_0 (linear RGBA in [0, 1], one per vertex) once set_colors is called; "float" writes
        # float VEC4, "ubyte" normalized unsigned bytes (what exporters write, glTF 2.0 3.7.2.1).
        self.colors, self.color_encoding = None, None

    def set_colors(self, color_of_position, encoding="float"):
        """Vertex colours from a function of the vertex position (call after the geometry)."""
        self.colors = [list(color_of_position(p)) for p in self.pos]
        self.color_encoding = encoding

    def vertex(self, p, n=None, uv=None):
        self.pos.append(p)
        if self.with_normals:
            self.nrm.append(n)
        if self.with_uv:
            self.uv.append(uv)
        return len(self.pos) - 1

    def tri(self, a, b, c):
        self.idx += [a, b, c]

    def quad(self, origin, du, dv, uv_scale=(1.0, 1.0), nu=1, nv=1):
        """Grid on origin + s*du + t*dv, s,t in [0,1]; front face (CCW) along du x dv.
        uv = (s*|du|, t*|dv|) * uv_scale, with t growing toward image rows below (glTF v)."""
        n = normalize(cross(du, dv))
        lu, lv = math.sqrt(dot(du, du)), math.sqrt(dot(dv, dv))
        base = len(self.pos)
        for j in range(nv + 1):
            for i in range(nu + 1):
                s, t = i / nu, j / nv
                p = add(origin, add(mul(du, s), mul(dv, t)))
                # v runs against dv so the image's top row sits at the far end of dv (image "up"
                # = +dv), the glTF convention for upright textures.
                self.vertex(p, n, [s * lu * uv_scale[0], (1.0 - t) * lv * uv_scale[1]])
                if self.with_tangents:
                    # +u along du; bitangent cross(N, T) * w = +dv = toward decreasing v: w = +1.
                    self.tan.append(normalize(du) + [1.0])
        for j in range(nv):
            for i in range(nu):
                a = base + j * (nu + 1) + i
                self.tri(a, a + 1, a + nu + 2)
                self.tri(a, a + nu + 2, a + nu + 1)

    def box(self, lo, hi, inward=False, uv_scale=(1.0, 1.0)):
        x0, y0, z0 = lo
        x1, y1, z1 = hi
        faces = [  # origin, du, dv with du x dv pointing outward
            ([x1, y0, z1], [0, 0, z0 - z1], [0, y1 - y0, 0]),  # +x
            ([x0, y0, z0], [0, 0, z1 - z0], [0, y1 - y0, 0]),  # -x
            ([x0, y1, z1], [x1 - x0, 0, 0], [0, 0, z0 - z1]),  # +y
            ([x0, y0, z0], [x1 - x0, 0, 0], [0, 0, z1 - z0]),  # -y
            ([x0, y0, z1], [x1 - x0, 0, 0], [0, y1 - y0, 0]),  # +z
            ([x1, y0, z0], [x0 - x1, 0, 0], [0, y1 - y0, 0]),  # -z
        ]
        for o, du, dv in faces:
            if inward:
                self.quad(add(o, du), mul(du, -1), dv, uv_scale)
            else:
                self.quad(o, du, dv, uv_scale)

    def sphere(self, center, radius, nlat, nlon, inward=False, displace=None):
        base = len(self.pos)
        for j in range(nlat + 1):
            theta = math.pi * j / nlat
            for i in range(nlon + 1):
                phi = 2 * math.pi * i / nlon
                d = [math.sin(theta) * math.cos(phi), math.cos(theta), -math.sin(theta) * math.sin(phi)]
                r = radius * (displace(theta, phi) if displace else 1.0)
                n = mul(d, -1.0) if inward else d
                self.vertex(add(center, mul(d, r)), n, [i / nlon, j / nlat])
        for j in range(nlat):
            for i in range(nlon):
                a = base + j * (nlon + 1) + i
                b, c, e = a + 1, a + nlon + 1, a + nlon + 2
                tris = []
                if j != 0:
                    tris.append((a, c, b))
                if j != nlat - 1:
                    tris.append((b, c, e))
                for t in tris:
                    self.tri(t[0], t[2], t[1]) if inward else self.tri(*t)
        if displace:
            self.recompute_normals(base)

    def cylinder(self, center, radius, height, n):
        """Open-ended side plus top cap, axis +Y from center (base) upward."""
        base = len(self.pos)
        for j in (0, 1):
            for i in range(n + 1):
                phi = 2 * math.pi * i / n
                d = [math.cos(phi), 0.0, -math.sin(phi)]
                self.vertex(add(center, [radius * d[0], height * j, radius * d[2]]), d,
                            [i / n * 2 * math.pi * radius, (1 - j) * height])
        for i in range(n):
            a = base + i
            self.tri(a, a + 1, a + n + 2)
            self.tri(a, a + n + 2, a + n + 1)
        top = add(center, [0, height, 0])
        c = self.vertex(top, [0, 1, 0], [0.5, 0.5])
        ring = [self.vertex(add(top, [radius * math.cos(2 * math.pi * i / n), 0, -radius * math.sin(2 * math.pi * i / n)]),
                            [0, 1, 0], [0.5 + 0.5 * math.cos(2 * math.pi * i / n), 0.5 + 0.5 * math.sin(2 * math.pi * i / n)])
                for i in range(n)]
        for i in range(n):
            self.tri(c, ring[i], ring[(i + 1) % n])

    def recompute_normals(self, start):
        acc = {k: [0.0, 0.0, 0.0] for k in range(start, len(self.pos))}
        # Vertices at the same position (sphere seams and poles) share their normal.
        key = {k: tuple(round(x, 6) for x in self.pos[k]) for k in acc}
        by_key = {}
        for t in range(0, len(self.idx), 3):
            a, b, c = self.idx[t:t + 3]
            if a < start:
                continue
            fn = cross(sub(self.pos[b], self.pos[a]), sub(self.pos[c], self.pos[a]))
            for v in (a, b, c):
                s = by_key.setdefault(key[v], [0.0, 0.0, 0.0])
                for i in range(3):
                    s[i] += fn[i]
        for k in acc:
            self.nrm[k] = normalize(by_key[key[k]])


# ----------------------------------------------------------------------------- PNG textures
def png_bytes(width, height, rows, channels=3):
    """rows: list of bytes objects (RGB or RGBA per texel). Row 0 is the top of the image."""
    def chunk(kind, data):
        c = kind + data
        return struct.pack(">I", len(data)) + c + struct.pack(">I", zlib.crc32(c) & 0xFFFFFFFF)
    color_type = {3: 2, 4: 6}[channels]
    raw = b"".join(b"\x00" + r for r in rows)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, color_type, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def hash01(i, j, seed):
    h = (i * 73856093) ^ (j * 19349663) ^ (seed * 83492791)
    h = (h ^ (h >> 13)) * 1274126177 & 0xFFFFFFFF
    return ((h ^ (h >> 16)) & 0xFFFF) / 65535.0


def brick_height(x, y, size):
    """Brick pattern on a size x size tile: 4 courses of 2 bricks, mortar 2 px, bevelled."""
    course = size // 4
    row = y // course
    xx = (x + (size // 4 if row % 2 else 0)) % size
    bx, by = xx % (size // 2), y % course
    d = min(bx, size // 2 - 1 - bx, by, course - 1 - by)  # distance to the mortar line
    return min(max(d - 1, 0) / 2.0, 1.0), (row, (xx // (size // 2)))


def brick_textures(size=64):
    albedo, normal = [], []
    h = [[brick_height(x, y, size)[0] for x in range(size)] for y in range(size)]
    for y in range(size):
        arow, nrow = bytearray(), bytearray()
        for x in range(size):
            height, brick = brick_height(x, y, size)
            if height == 0.0:
                c = (170, 165, 155)  # mortar
            else:
                v = 0.85 + 0.3 * hash01(brick[0], brick[1], 7)
                c = tuple(min(255, int(v * k)) for k in (150, 62, 45))
            arow += bytes(c)
            # Tangent-space normal from the height field: x right, y = up in the image
            # (toward row 0), z out of the surface (glTF / OpenGL convention).
            dhdx = (h[y][(x + 1) % size] - h[y][(x - 1) % size]) * 0.5
            dhdrow = (h[(y + 1) % size][x] - h[(y - 1) % size][x]) * 0.5
            n = normalize([-dhdx * 2.0, dhdrow * 2.0, 1.0])
            nrow += bytes(int(round((k * 0.5 + 0.5) * 255)) for k in n)
        albedo.append(bytes(arow))
        normal.append(bytes(nrow))
    return png_bytes(size, size, albedo), png_bytes(size, size, normal)


def tile_normal_two_channel(size=64):
    """Floor tiles as a two-channel normal map: R, G hold x, y; B is 0 (z is reconstructed)."""
    rows = []
    tile = size // 2
    for y in range(size):
        r = bytearray()
        for x in range(size):
            tx, ty = x % tile, y % tile
            nx = ny = 0.0
            if tx < 2: nx = -0.5
            elif tx >= tile - 2: nx = 0.5
            if ty < 2: ny = 0.5
            elif ty >= tile - 2: ny = -0.5
            r += bytes([int(round((nx * 0.5 + 0.5) * 255)), int(round((ny * 0.5 + 0.5) * 255)), 0])
        rows.append(bytes(r))
    return png_bytes(size, size, rows)


def leaf_card_texture(size=64):
    """RGBA leaves on a stem for alpha-masked foliage cards: alpha 255 on the plant, 0 elsewhere
    (hard edges, so the alpha test's edge is where bilinear alpha crosses the cutoff, half a texel
    from the plant's outline), and a transparent border of 2 texels so REPEAT never wraps the
    plant onto the opposite edge. Row 0 is the top of the image (the card's top)."""
    leaves = []  # centre x, centre y (texels), half-length, half-width, angle (radians)
    for k in range(6):
        side = 1 if k % 2 == 0 else -1
        y = 14 + 8 * k
        leaves.append((size / 2 + side * 10, y, 10.5, 4.0, side * math.radians(35)))
    leaves.append((size / 2, 9, 4.0, 7.0, 0.0))  # the top leaf, upright
    rows = []
    for y in range(size):
        r = bytearray()
        for x in range(size):
            px, py = x + 0.5, y + 0.5
            inside, vein = False, False
            if abs(px - size / 2) <= 1.0 and 6 <= py <= size - 2:
                inside, vein = True, True  # the stem
            for cx, cy, a, b, ang in leaves:
                # Leaf frame: u along the leaf (tilted up by ang), v across it.
                dx, dy = px - cx, -(py - cy)
                u = dx * math.cos(ang) + dy * math.sin(ang)
                v = -dx * math.sin(ang) + dy * math.cos(ang)
                if (u / a) ** 2 + (v / b) ** 2 <= 1.0:
                    inside = True
                    vein = vein or abs(v) < 0.6
            if not inside:
                r += bytes((40, 90, 30, 0))
                continue
            shade = 0.8 + 0.2 * hash01(x // 3, y // 3, 11)
            base = (55, 120, 40) if vein else (70, 160, 50)
            r += bytes(tuple(min(255, int(shade * c)) for c in base) + (255,))
        rows.append(bytes(r))
    return png_bytes(size, size, rows, channels=4)


def checker_albedo(size=256, square=32):
    """sRGB checker: squares of `square` texels, light (200, 190, 170) and dark (90, 80, 70)."""
    rows = []
    for y in range(size):
        r = bytearray()
        for x in range(size):
            light = ((x // square) + (y // square)) % 2 == 0
            r += bytes((200, 190, 170) if light else (90, 80, 70))
        rows.append(bytes(r))
    return png_bytes(size, size, rows)


def bump_normal(size=256, period=32):
    """Tangent-space normals of round bumps, one per `period` x `period` cell: a height field
    h = cos^2(pi r / (2 R)) inside radius R = 0.4 period (0 outside), differentiated centrally."""
    radius = 0.4 * period

    def height(x, y):
        cx, cy = (x % period) - period / 2 + 0.5, (y % period) - period / 2 + 0.5
        r = math.sqrt(cx * cx + cy * cy)
        return math.cos(math.pi * r / (2 * radius)) ** 2 if r < radius else 0.0

    rows = []
    for y in range(size):
        r = bytearray()
        for x in range(size):
            dhdx = (height(x + 1, y) - height(x - 1, y)) * 0.5 * 4.0
            dhdrow = (height(x, y + 1) - height(x, y - 1)) * 0.5 * 4.0
            # x right, y up in the image (toward row 0), z out of the surface (glTF convention).
            n = normalize([-dhdx, dhdrow, 1.0])
            r += bytes(int(round((k * 0.5 + 0.5) * 255)) for k in n)
        rows.append(bytes(r))
    return png_bytes(size, size, rows)


# ----------------------------------------------------------------------------- glTF writer
class Gltf:
    def __init__(self, generator_note):
        self.doc = {"asset": {"version": "2.0", "generator": "VCT Oracle scenes/generate_scenes.py (" + generator_note + ")"},
                    "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [], "materials": [],
                    "accessors": [], "bufferViews": [], "buffers": []}
        self.blob = bytearray()
        self.extensions = set()

    def _view(self, data, target=None):
        while len(self.blob) % 4:
            self.blob.append(0)
        view = {"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data)}
        if target:
            view["target"] = target
        self.blob += data
        self.doc["bufferViews"].append(view)
        return len(self.doc["bufferViews"]) - 1

    def _accessor(self, values, comps, ctype, target, minmax=False, normalized=False):
        fmt = {FLOAT: "f", UINT8: "B", UINT16: "H", UINT32: "I"}[ctype]
        flat = [x for v in values for x in (v if comps > 1 else [v])]
        view = self._view(struct.pack("<%d%s" % (len(flat), fmt), *flat), target)
        acc = {"bufferView": view, "componentType": ctype, "count": len(values),
               "type": {1: "SCALAR", 2: "VEC2", 3: "VEC3", 4: "VEC4"}[comps]}
        if normalized:
            acc["normalized"] = True
        if minmax:
            # min/max of the float32 values actually stored (the validator compares exactly).
            f32 = [struct.unpack("<f", struct.pack("<f", x))[0] for x in flat]
            acc["min"] = [min(f32[i::comps]) for i in range(comps)]
            acc["max"] = [max(f32[i::comps]) for i in range(comps)]
        self.doc["accessors"].append(acc)
        return len(self.doc["accessors"]) - 1

    def mesh(self, name, m, material):
        attrs = {"POSITION": self._accessor(m.pos, 3, FLOAT, ARRAY_BUFFER, minmax=True)}
        if m.with_normals:
            attrs["NORMAL"] = self._accessor(m.nrm, 3, FLOAT, ARRAY_BUFFER)
        if m.with_tangents:
            attrs["TANGENT"] = self._accessor(m.tan, 4, FLOAT, ARRAY_BUFFER)
        if m.with_uv:
            attrs["TEXCOORD_0"] = self._accessor(m.uv, 2, FLOAT, ARRAY_BUFFER)
        if m.colors is not None and m.color_encoding == "ubyte":
            bytes4 = [[int(round(min(max(c, 0.0), 1.0) * 255)) for c in v] for v in m.colors]
            attrs["COLOR_0"] = self._accessor(bytes4, 4, UINT8, ARRAY_BUFFER, normalized=True)
        elif m.colors is not None:
            attrs["COLOR_0"] = self._accessor(m.colors, 4, FLOAT, ARRAY_BUFFER)
        itype = UINT16 if len(m.pos) < 65536 else UINT32
        prim = {"attributes": attrs, "indices": self._accessor(m.idx, 1, itype, ELEMENT_ARRAY_BUFFER), "material": material}
        self.doc["meshes"].append({"name": name, "primitives": [prim]})
        return len(self.doc["meshes"]) - 1

    def material(self, name, color, metallic=0.0, roughness=1.0, lambert=False, emissive=None, strength=None,
                 extras=None, alpha_mode=None, alpha_cutoff=None, double_sided=False, **textures):
        mat = {"name": name, "pbrMetallicRoughness": {"baseColorFactor": list(color) + [1.0],
                                                      "metallicFactor": metallic, "roughnessFactor": roughness}}
        if alpha_mode:
            mat["alphaMode"] = alpha_mode
        if alpha_cutoff is not None:
            mat["alphaCutoff"] = alpha_cutoff
        if double_sided:
            mat["doubleSided"] = True
        ext = {}
        if lambert:
            ext.update(LAMBERT)
        if emissive:
            mat["emissiveFactor"] = list(emissive)
            if strength:
                ext["KHR_materials_emissive_strength"] = {"emissiveStrength": strength}
        if "base_color" in textures:
            mat["pbrMetallicRoughness"]["baseColorTexture"] = textures["base_color"]
        if "normal" in textures:
            mat["normalTexture"] = textures["normal"]
        if ext:
            mat["extensions"] = ext
            self.extensions.update(ext.keys())
        if extras:
            mat["extras"] = extras
        self.doc["materials"].append(mat)
        return len(self.doc["materials"]) - 1

    def texture(self, uri_or_png, name):
        """An image (a relative URI, or PNG bytes to embed) with a repeat/linear sampler."""
        self.doc.setdefault("samplers", [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}])
        images = self.doc.setdefault("images", [])
        if isinstance(uri_or_png, bytes):
            images.append({"name": name, "uri": "data:image/png;base64," + base64.b64encode(uri_or_png).decode()})
        else:
            images.append({"name": name, "uri": uri_or_png})
        textures = self.doc.setdefault("textures", [])
        textures.append({"name": name, "sampler": 0, "source": len(images) - 1})
        return len(textures) - 1

    def texture_info(self, texture, transform=None, **extra):
        info = {"index": texture}
        info.update(extra)
        if transform:
            info["extensions"] = {"KHR_texture_transform": transform}
            self.extensions.add("KHR_texture_transform")
        return info

    def node(self, name, root=True, **fields):
        node = {"name": name}
        node.update({k: v for k, v in fields.items() if v is not None})
        self.doc["nodes"].append(node)
        index = len(self.doc["nodes"]) - 1
        if root:
            self.doc["scenes"][0]["nodes"].append(index)
        return index

    def camera(self, eye, target, yfov, znear=0.05, zfar=100.0):
        self.doc.setdefault("cameras", []).append(
            {"type": "perspective", "perspective": {"yfov": yfov, "znear": znear, "zfar": zfar}})
        return self.node("camera", camera=len(self.doc["cameras"]) - 1, translation=list(eye),
                         rotation=look_rotation(eye, target))

    def spot(self, name, position, rotation, intensity, inner, outer, color=(1.0, 1.0, 1.0)):
        ext = self.doc.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {"lights": []})
        ext["lights"].append({"name": name, "type": "spot", "color": list(color), "intensity": intensity,
                              "spot": {"innerConeAngle": inner, "outerConeAngle": outer}})
        self.extensions.add("KHR_lights_punctual")
        return self.node(name, translation=list(position), rotation=rotation,
                         extensions={"KHR_lights_punctual": {"light": len(ext["lights"]) - 1}})

    def _light(self, name, light, position, rotation):
        ext = self.doc.setdefault("extensions", {}).setdefault("KHR_lights_punctual", {"lights": []})
        ext["lights"].append(light)
        self.extensions.add("KHR_lights_punctual")
        return self.node(name, translation=list(position), rotation=rotation,
                         extensions={"KHR_lights_punctual": {"light": len(ext["lights"]) - 1}})

    def point(self, name, position, intensity, color=(1.0, 1.0, 1.0), light_range=None):
        light = {"name": name, "type": "point", "color": list(color), "intensity": intensity}
        if light_range:
            light["range"] = light_range
        return self._light(name, light, position, None)

    def sun(self, name, direction, lux, color=(1.0, 1.0, 1.0)):
        """A directional light shining along `direction` (its node's -Z), intensity in lux."""
        light = {"name": name, "type": "directional", "color": list(color), "intensity": lux}
        return self._light(name, light, [0.0, 0.0, 0.0], look_rotation([0, 0, 0], direction))

    def write(self, filename):
        doc = self.doc
        doc["buffers"] = [{"byteLength": len(self.blob),
                           "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(self.blob)).decode()}]
        if self.extensions:
            doc["extensionsUsed"] = sorted(self.extensions)
        text = json.dumps(_rounded(doc), indent=1, sort_keys=False) + "\n"
        return filename, text.encode()


def _rounded(x):
    """Rounds floats in the JSON to 7 significant digits (deterministic, readable)."""
    if isinstance(x, float):
        return float("%.7g" % x)
    if isinstance(x, list):
        return [_rounded(v) for v in x]
    if isinstance(x, dict):
        # Accessor bounds stay exact: the validator compares them with the stored float32 data.
        return {k: (v if k in ("min", "max") else _rounded(v)) for k, v in x.items()}
    return x


# ----------------------------------------------------------------------------- scenes
def cornell_box():
    g = Gltf("Cornell box: the built-in default scene")
    white = g.material("white_wall", (0.73, 0.73, 0.73), lambert=True)
    red = g.material("red_wall", (0.63, 0.065, 0.05), lambert=True)
    green = g.material("green_wall", (0.14, 0.45, 0.091), lambert=True)
    panel = g.material("emissive_panel", (0.78, 0.78, 0.78), lambert=True, emissive=(1.0, 0.85, 0.6), strength=4.0)
    metal = g.material("rough_metal", (0.95, 0.64, 0.54), metallic=1.0, roughness=0.4)
    glossy = g.material("glossy_dielectric", (0.1, 0.25, 0.8), metallic=0.0, roughness=0.1)

    def add_quad_mesh(name, mat, origin, du, dv, n=4):
        m = MeshData()
        m.quad(origin, du, dv, nu=n, nv=n)
        g.node(name, mesh=g.mesh(name, m, mat))

    # The box spans x, z in [-1, 1], y in [0, 2]; open toward +z, where the camera stands.
    add_quad_mesh("floor", white, [-1, 0, 1], [2, 0, 0], [0, 0, -2])
    add_quad_mesh("ceiling", white, [-1, 2, -1], [2, 0, 0], [0, 0, 2])
    add_quad_mesh("back_wall", white, [-1, 0, -1], [2, 0, 0], [0, 2, 0])
    add_quad_mesh("left_wall", red, [-1, 0, 1], [0, 0, -2], [0, 2, 0])
    add_quad_mesh("right_wall", green, [1, 0, -1], [0, 0, 2], [0, 2, 0])
    # Emissive panel just below the ceiling, facing down, off-centre so the spot light's
    # housing position stays free.
    add_quad_mesh("emissive_panel", panel, [-0.25, 1.995, -0.55], [0.5, 0, 0], [0, 0, 0.3], n=1)

    box = MeshData()
    box.box([-0.3, 0.0, -0.3], [0.3, 1.2, 0.3])
    g.node("metal_box", mesh=g.mesh("metal_box", box, metal), translation=[-0.38, 0.0, -0.3],
           rotation=quat_axis_angle([0, 1, 0], math.radians(17)))
    sphere = MeshData()
    sphere.sphere([0, 0, 0], 1.0, 24, 48)
    g.node("glossy_sphere", mesh=g.mesh("glossy_sphere", sphere, glossy), translation=[0.42, 0.35, 0.3],
           scale=[0.35, 0.35, 0.35])

    g.spot("ceiling_spot", [0.0, 1.98, 0.1], POINT_DOWN, intensity=6.0, inner=0.45, outer=0.75)
    g.camera([0.0, 1.0, 3.6], [0.0, 1.0, 0.0], yfov=0.75)
    return g.write("cornell_box.gltf")


def statue_displacement(theta, phi):
    return 1.0 + 0.12 * math.sin(3 * theta) * math.cos(2 * phi) + 0.05 * math.sin(7 * phi) * math.sin(theta)


def demo_room():
    g = Gltf("demo room in the seed's spirit")
    brick_albedo, brick_normal = brick_textures()
    os.makedirs(os.path.join(HERE, "textures"), exist_ok=True)
    files = {"textures/brick_albedo.png": brick_albedo, "textures/brick_normal.png": brick_normal,
             "textures/tile_normal_rg.png": tile_normal_two_channel()}
    t_albedo = g.texture("textures/brick_albedo.png", "brick_albedo")
    t_normal = g.texture("textures/brick_normal.png", "brick_normal")
    t_tiles = g.texture("textures/tile_normal_rg.png", "tile_normal_rg")
    # One tile of the brick texture covers 1 m x 1 m; the transform halves it (2 tiles per m).
    tt = {"scale": [2.0, 2.0]}
    walls = g.material("brick_wall", (1.0, 1.0, 1.0), roughness=0.9,
                       base_color=g.texture_info(t_albedo, tt), normal=g.texture_info(t_normal, tt, scale=1.0))
    floor = g.material("tiled_floor", (0.55, 0.5, 0.45), roughness=0.6, extras={"vct_normal_two_channel": True},
                       normal=g.texture_info(t_tiles, scale=0.8))
    ceiling = g.material("ceiling", (0.8, 0.8, 0.8), lambert=True)
    gold = g.material("gold_pillar", (1.0, 0.78, 0.34), metallic=1.0, roughness=0.3)
    chrome = g.material("chrome_statue", (0.9, 0.9, 0.92), metallic=1.0, roughness=0.15)
    stone = g.material("stone", (0.5, 0.48, 0.45), roughness=0.8)
    coal = g.material("brazier", (0.05, 0.05, 0.05), metallic=1.0, roughness=0.5)

    def quad_mesh(name, mat, origin, du, dv):
        m = MeshData(with_tangents=mat in (walls, floor))
        m.quad(origin, du, dv)
        g.node(name, mesh=g.mesh(name, m, mat))

    # Room: x, z in [-4, 4], y in [0, 3.5], every surface facing inward.
    H = 3.5
    quad_mesh("floor", floor, [-4, 0, 4], [8, 0, 0], [0, 0, -8])
    quad_mesh("ceiling", ceiling, [-4, H, -4], [8, 0, 0], [0, 0, 8])
    quad_mesh("wall_back", walls, [-4, 0, -4], [8, 0, 0], [0, H, 0])
    quad_mesh("wall_front", walls, [4, 0, 4], [-8, 0, 0], [0, H, 0])
    quad_mesh("wall_left", walls, [-4, 0, 4], [0, 0, -8], [0, H, 0])
    quad_mesh("wall_right", walls, [4, 0, -4], [0, 0, 8], [0, H, 0])

    # Four pillars as children of one group node (exercises the hierarchy).
    pillar = MeshData()
    pillar.cylinder([0, 0, 0], 0.25, H, 24)
    pillar_mesh = g.mesh("pillar", pillar, gold)
    group = g.node("pillars")
    kids = [g.node("pillar_%d" % i, root=False, mesh=pillar_mesh, translation=[x, 0.0, z])
            for i, (x, z) in enumerate([(-2.5, -2.5), (2.5, -2.5), (-2.5, 2.5), (2.5, 2.5)])]
    g.doc["nodes"][group]["children"] = kids

    # Statue: pedestal + a deformed sphere body + a small head.
    pedestal = MeshData()
    pedestal.box([-0.5, 0.0, -0.5], [0.5, 0.8, 0.5])
    g.node("pedestal", mesh=g.mesh("pedestal", pedestal, stone))
    body = MeshData()
    body.sphere([0, 0, 0], 1.0, 32, 48, displace=statue_displacement)
    body_node = g.node("statue_body", mesh=g.mesh("statue_body", body, chrome), translation=[0.0, 1.45, 0.0],
                       scale=[0.45, 0.65, 0.45])
    head = MeshData()
    head.sphere([0, 0, 0], 1.0, 16, 24)
    head_node = g.node("statue_head", root=False, mesh=g.mesh("statue_head", head, chrome),
                       translation=[0.0, 1.25, 0.0], scale=[0.4, 0.28, 0.4])
    g.doc["nodes"][body_node]["children"] = [head_node]

    # Two braziers with fire particle emitters above them (schema: docs/scenes.md).
    brazier = MeshData()
    brazier.cylinder([0, 0, 0], 0.2, 0.5, 16)
    brazier_mesh = g.mesh("brazier", brazier, coal)
    for i, x in enumerate((-1.5, 1.5)):
        g.node("brazier_%d" % i, mesh=brazier_mesh, translation=[x, 0.0, -3.0])
        g.node("fire_%d" % i, translation=[x, 0.55, -3.0], extras={"vct_particles": {
            "count": 512, "lifetime": 1.2, "spawn_extent": [0.12, 0.02, 0.12],
            "velocity_min": [-0.1, 0.5, -0.1], "velocity_max": [0.1, 1.1, 0.1], "acceleration": [0.0, 0.4, 0.0],
            "color_start": [6.0, 2.6, 0.6], "color_end": [1.2, 0.15, 0.0], "size_start": 0.06, "size_end": 0.015}})

    g.spot("statue_spot", [2.5, 3.3, 2.0], look_rotation([2.5, 3.3, 2.0], [0.0, 1.2, 0.0]), intensity=40.0,
           inner=0.25, outer=0.45, color=(1.0, 0.95, 0.85))
    g.camera([0.0, 1.7, 3.6], [0.0, 1.2, -1.0], yfov=1.0)
    return [g.write("demo_room.gltf")] + [(name, data) for name, data in files.items()]


def furnace_sphere():
    """Closed Lambertian sphere (albedo 0.5, uniform emission 1) seen from its centre. The
    radiance everywhere is Le / (1 - albedo) = 2 (white furnace test)."""
    g = Gltf("furnace: closed sphere, albedo 0.5, emission 1, radiance 2 everywhere")
    mat = g.material("furnace_wall", (0.5, 0.5, 0.5), lambert=True, emissive=(1.0, 1.0, 1.0))
    m = MeshData()
    m.sphere([0, 0, 0], 1.0, 32, 64, inward=True)
    g.node("sphere", mesh=g.mesh("sphere", m, mat))
    g.camera([0.0, 0.0, 0.0], [0.0, 0.0, -1.0], yfov=1.2, znear=0.01, zfar=10.0)
    return g.write("furnace_sphere.gltf")


def plane_spot():
    """A 4 m x 4 m Lambertian plane (albedo 0.8) at y = 0 under a spot light 2 m above it,
    pointing straight down: E(r) = I cos^3(theta) / h^2 * cone(theta), theta = atan(r / h)."""
    g = Gltf("plane under a spot light: closed-form irradiance")
    mat = g.material("lambert_plane", (0.8, 0.8, 0.8), lambert=True)
    m = MeshData()
    m.quad([-2, 0, 2], [4, 0, 0], [0, 0, -4], nu=16, nv=16)
    g.node("plane", mesh=g.mesh("plane", m, mat))
    g.spot("spot", [0.0, 2.0, 0.0], POINT_DOWN, intensity=10.0, inner=0.3, outer=0.5)
    g.camera([0.0, 3.0, 3.0], [0.0, 0.0, 0.0], yfov=0.9)
    return g.write("plane_spot.gltf")


def tiny_triangles():
    """A 1 m x 1 m patch of 45,000 triangles (edges 6.7 mm, far below a voxel at grid 128 of
    this ~2.2 m volume, 17 mm) on a 2 m floor, lit by a spot light. Positions only: the loader
    generates flat normals and tangents."""
    g = Gltf("triangles much smaller than a voxel")
    floor_mat = g.material("floor", (0.7, 0.7, 0.7), lambert=True)
    patch_mat = g.material("patch", (0.9, 0.3, 0.2), lambert=True)
    floor = MeshData()
    floor.quad([-1, 0, 1], [2, 0, 0], [0, 0, -2])
    g.node("floor", mesh=g.mesh("floor", floor, floor_mat))
    n = 150
    patch = MeshData(with_normals=False, with_uv=False)
    patch.quad([-0.5, 0.0, 0.5], [1, 0, 0], [0, 0, -1], nu=n, nv=n)
    # Tilt the patch 30 degrees about x and lift it so it is not coplanar with the floor.
    g.node("patch", mesh=g.mesh("patch", patch, patch_mat), translation=[0.0, 0.6, 0.0],
           rotation=quat_axis_angle([1, 0, 0], math.radians(30)))
    g.spot("spot", [0.0, 2.0, 0.0], POINT_DOWN, intensity=8.0, inner=0.4, outer=0.7)
    g.camera([0.0, 1.6, 2.2], [0.0, 0.4, 0.0], yfov=0.8)
    return g.write("tiny_triangles.gltf")


def thin_wall():
    """Two closed rooms (x < 0 lit by a spot light, x > 0 dark) separated by a 2 cm wall, far
    thinner than a voxel (grid 64 over the 4.35 m volume: 68 mm). Any light seen in the dark
    room is leakage through the wall. The camera stands in the dark room, facing the wall."""
    g = Gltf("thin wall between a lit and a dark room")
    white = g.material("white", (0.75, 0.75, 0.75), lambert=True)
    wall_mat = g.material("thin_wall", (0.75, 0.75, 0.75), lambert=True)
    W = 0.01  # half thickness
    shell = MeshData()
    # Shared floor, ceiling, back and front over both rooms; outer side walls; all inward.
    shell.box([-2.0 - W, 0.0, -1.0], [2.0 + W, 2.0, 1.0], inward=True)
    g.node("shell", mesh=g.mesh("shell", shell, white))
    wall = MeshData()
    wall.box([-W, 0.0, -1.0], [W, 2.0, 1.0])
    g.node("thin_wall", mesh=g.mesh("thin_wall", wall, wall_mat))
    g.spot("lit_room_spot", [-1.0, 1.95, 0.0], POINT_DOWN, intensity=8.0, inner=0.6, outer=1.0)
    g.camera([1.9, 1.0, 0.0], [0.0, 1.0, 0.0], yfov=1.2, znear=0.02)
    return g.write("thin_wall.gltf")


def foliage():
    """Alpha-masked foliage: three plants of two crossed, double-sided 1 m x 1.4 m cards each, an
    RGBA leaf texture (alphaMode MASK, alphaCutoff 0.5), on a 3 m floor under a spot light from the
    front right that throws the leaves' shadows onto the floor behind them, with an emissive panel behind the plants seen
    through the gaps between the leaves (docs/scenes.md, "Alpha modes")."""
    g = Gltf("foliage cards with alpha masks")
    t_leaf = g.texture(leaf_card_texture(), "leaf_card")
    leaf = g.material("leaf_card", (1.0, 1.0, 1.0), roughness=0.7, alpha_mode="MASK", alpha_cutoff=0.5,
                      double_sided=True, base_color=g.texture_info(t_leaf))
    floor_mat = g.material("floor", (0.7, 0.68, 0.62), lambert=True)
    panel = g.material("emissive_panel", (0.8, 0.8, 0.8), lambert=True, emissive=(1.0, 0.9, 0.7), strength=3.0)
    floor = MeshData()
    floor.quad([-1.5, 0, 1.5], [3, 0, 0], [0, 0, -3], nu=4, nv=4)
    g.node("floor", mesh=g.mesh("floor", floor, floor_mat))
    back = MeshData()
    back.quad([-0.9, 0.2, -1.4], [1.8, 0, 0], [0, 0.9, 0])
    g.node("emissive_panel", mesh=g.mesh("emissive_panel", back, panel))
    W, H = 1.0, 1.4
    for i, (x, z, turn) in enumerate([(-0.75, -0.35, 25), (0.1, 0.25, 60), (0.8, -0.55, 80)]):
        card = MeshData()
        for a in (turn, turn + 90):
            d = [math.cos(math.radians(a)) * W, 0.0, -math.sin(math.radians(a)) * W]
            # uv in [0, 1]^2 over the card: the texture's top row at the card's top.
            card.quad(mul(d, -0.5), d, [0, H, 0], uv_scale=(1.0 / W, 1.0 / H))
        g.node("plant_%d" % i, mesh=g.mesh("plant_%d" % i, card, leaf), translation=[x, 0.0, z])
    g.spot("sun_spot", [1.4, 3.0, 1.6], look_rotation([1.4, 3.0, 1.6], [-0.2, 0.0, -0.6]), intensity=30.0,
           inner=0.45, outer=0.7, color=(1.0, 0.97, 0.9))
    g.camera([0.0, 1.4, 3.2], [0.0, 0.6, -0.2], yfov=0.85)
    return g.write("foliage.gltf")


def tiled_floor():
    """Issue 13's ordinary tiled floor: 4 m x 4 m, a 256^2 sRGB checker (32-texel squares) and a
    bump normal map (32-texel period), both repeated 4x (TEXCOORD_0 0..4), sampler
    LINEAR_MIPMAP_LINEAR / LINEAR / REPEAT, roughness 0.6; a closed room with a spot light and an
    emissive panel. Seen at a grazing angle the floor is strongly minified (mip levels 2-5)."""
    g = Gltf("tiled floor: mipmapped, repeated, normal-mapped textures")
    files = {"textures/checker_albedo.png": checker_albedo(), "textures/bump_normal.png": bump_normal()}
    t_albedo = g.texture("textures/checker_albedo.png", "checker_albedo")
    t_normal = g.texture("textures/bump_normal.png", "bump_normal")
    floor = g.material("tiled_floor", (1.0, 1.0, 1.0), roughness=0.6,
                       base_color=g.texture_info(t_albedo), normal=g.texture_info(t_normal, scale=1.0))
    walls = g.material("walls", (0.7, 0.7, 0.68), lambert=True)
    panel = g.material("panel", (0.0, 0.0, 0.0), lambert=True, emissive=(1.0, 0.9, 0.7), strength=3.0)
    m = MeshData(with_tangents=True)
    m.quad([-2, 0, 2], [4, 0, 0], [0, 0, -4])  # uv = (s * 4, (1 - t) * 4): TEXCOORD_0 0..4
    g.node("floor", mesh=g.mesh("floor", m, floor))
    room = MeshData()
    H = 2.5
    room.quad([-2, H, -2], [4, 0, 0], [0, 0, 4])    # ceiling
    room.quad([-2, 0, -2], [4, 0, 0], [0, H, 0])    # back wall
    room.quad([2, 0, 2], [-4, 0, 0], [0, H, 0])     # front wall
    room.quad([-2, 0, 2], [0, 0, -4], [0, H, 0])    # left wall
    room.quad([2, 0, -2], [0, 0, 4], [0, H, 0])     # right wall
    g.node("room", mesh=g.mesh("room", room, walls))
    lamp = MeshData()
    lamp.quad([-0.6, 1.0, -1.98], [1.2, 0, 0], [0, 0.6, 0])
    g.node("panel", mesh=g.mesh("panel", lamp, panel))
    g.spot("floor_spot", [0.5, 2.4, 0.5], look_rotation([0.5, 2.4, 0.5], [-0.3, 0.0, -0.6]), intensity=12.0,
           inner=0.35, outer=0.75)
    g.camera([0.0, 1.2, 1.9], [0.0, 0.2, -1.5], yfov=1.0)
    return [g.write("tiled_floor.gltf")] + [(name, data) for name, data in files.items()]


def sun_room():
    """A 5 x 3.8 x 5 m room lit by a high sun through a 1.2 x 1.2 m skylight and by two point lamps
    (one with a range), with a low platform across the room in the sun patch: every light kind but
    the spot, shadows from the sun's orthographic map and from both cubes.

    Placed so that no surface shows shadow acne under the constant depth bias at validate's 1024^2
    maps (docs/pipeline.md, "Shadow maps": a plane at distance h from a point light is acne-free
    when h > 3 near / (S bias) = 1.47 m here; every plane a lamp sees is >= 1.55 m from it, and the
    sun's 81 degree elevation keeps the floor's depth change under the bias)."""
    g = Gltf("room lit by a sun through a skylight and two point lamps")
    wall = g.material("plaster", (0.75, 0.73, 0.7), lambert=True)
    floor_mat = g.material("wood_floor", (0.55, 0.4, 0.28), roughness=0.6)
    platform_mat = g.material("platform", (0.3, 0.45, 0.6), roughness=0.5)

    def quad(name, mat, origin, du, dv, n=6):
        m = MeshData()
        m.quad(origin, du, dv, nu=n, nv=n)
        g.node(name, mesh=g.mesh(name, m, mat))

    # Inward-facing shell: x, z in [-2.5, 2.5], y in [0, 3.8]; a skylight in the ceiling at
    # x in [0.6, 1.8], z in [-0.6, 0.6].
    h = 3.8
    quad("floor", floor_mat, [-2.5, 0, 2.5], [5, 0, 0], [0, 0, -5])
    quad("back_wall", wall, [-2.5, 0, -2.5], [5, 0, 0], [0, h, 0])
    quad("front_wall", wall, [2.5, 0, 2.5], [-5, 0, 0], [0, h, 0])
    quad("left_wall", wall, [-2.5, 0, 2.5], [0, 0, -5], [0, h, 0])
    quad("right_wall", wall, [2.5, 0, -2.5], [0, 0, 5], [0, h, 0])
    quad("ceiling_left", wall, [-2.5, h, -2.5], [3.1, 0, 0], [0, 0, 5], n=4)
    quad("ceiling_right", wall, [1.8, h, -2.5], [0.7, 0, 0], [0, 0, 5], n=2)
    quad("ceiling_back", wall, [0.6, h, -2.5], [1.2, 0, 0], [0, 0, 1.9], n=2)
    quad("ceiling_front", wall, [0.6, h, 0.6], [1.2, 0, 0], [0, 0, 1.9], n=2)
    platform = MeshData()
    platform.box([0.9, 0.0, -2.4], [1.8, 0.35, 2.4])
    g.node("platform", mesh=g.mesh("platform", platform, platform_mat))

    g.sun("sun", normalize([-0.15, -1.0, 0.08]), lux=8.0, color=(1.0, 0.95, 0.85))
    g.point("lamp_back", [-0.7, 1.9, -0.8], intensity=4.0, color=(1.0, 0.8, 0.6))
    g.point("lamp_front", [-0.7, 1.9, 0.8], intensity=4.0, color=(1.0, 0.85, 0.7), light_range=6.0)
    g.camera([-2.2, 1.6, 2.2], [0.8, 0.6, -0.8], yfov=1.0)
    return g.write("sun_room.gltf")


def light_order():
    """Issue 34's zoo: what users' files have and the other scenes lacked. Every light kind in a
    mixed order (a point lamp, then a spot, then a sun, then a second point lamp: a spot and a sun
    after a point light, a point after a sun) and vertex colours: the floor carries float COLOR_0
    (a warm-to-cool gradient), the platform normalized-ubyte COLOR_0 (red to yellow) with alpha
    < 1 on an opaque material (alpha is ignored there, glTF 2.0 3.9.4). The shell, skylight, sun
    and lamps are sun_room's, placed clear of the constant bias's acne at validate's 1024^2 maps;
    the spot shines down onto the platform from 3.3 m (every plane it sees lies >= 1.6 m from it)."""
    g = Gltf("light kinds in a mixed order and vertex colours (COLOR_0)")
    wall = g.material("plaster", (0.75, 0.73, 0.7), lambert=True)
    floor_mat = g.material("painted_floor", (0.9, 0.9, 0.9), roughness=0.6)
    platform_mat = g.material("painted_platform", (1.0, 1.0, 1.0), roughness=0.5)
    h = 3.8

    def quad(name, mat, origin, du, dv, n=6, colors=None):
        m = MeshData()
        m.quad(origin, du, dv, nu=n, nv=n)
        if colors:
            m.set_colors(*colors)
        g.node(name, mesh=g.mesh(name, m, mat))

    gradient = (lambda p: (0.95 - 0.12 * (p[0] + 2.5), 0.55 + 0.05 * (p[2] + 2.5), 0.3 + 0.12 * (p[0] + 2.5), 1.0),
                "float")
    quad("floor", floor_mat, [-2.5, 0, 2.5], [5, 0, 0], [0, 0, -5], colors=gradient)
    quad("back_wall", wall, [-2.5, 0, -2.5], [5, 0, 0], [0, h, 0])
    quad("front_wall", wall, [2.5, 0, 2.5], [-5, 0, 0], [0, h, 0])
    quad("left_wall", wall, [-2.5, 0, 2.5], [0, 0, -5], [0, h, 0])
    quad("right_wall", wall, [2.5, 0, -2.5], [0, 0, 5], [0, h, 0])
    quad("ceiling_left", wall, [-2.5, h, -2.5], [3.1, 0, 0], [0, 0, 5], n=4)
    quad("ceiling_right", wall, [1.8, h, -2.5], [0.7, 0, 0], [0, 0, 5], n=2)
    quad("ceiling_back", wall, [0.6, h, -2.5], [1.2, 0, 0], [0, 0, 1.9], n=2)
    quad("ceiling_front", wall, [0.6, h, 0.6], [1.2, 0, 0], [0, 0, 1.9], n=2)
    platform = MeshData()
    platform.box([0.9, 0.0, -2.4], [1.8, 0.35, 2.4])
    # Saturated corners: red at the back end (z = -2.4), yellow at the front end, interpolated
    # along the box; alpha 0.5 (ignored: the material is opaque).
    platform.set_colors(lambda p: (1.0, 0.1, 0.1, 0.5) if p[2] < 0 else (1.0, 1.0, 0.1, 0.5), "ubyte")
    g.node("platform", mesh=g.mesh("platform", platform, platform_mat))

    g.point("lamp_back", [-0.7, 1.9, -0.8], intensity=4.0, color=(1.0, 0.8, 0.6))
    g.spot("platform_spot", [-0.6, 3.3, 0.4], look_rotation([-0.6, 3.3, 0.4], [1.35, 0.35, 0.0]), intensity=10.0,
           inner=0.3, outer=0.55, color=(0.9, 0.95, 1.0))
    g.sun("sun", normalize([-0.15, -1.0, 0.08]), lux=8.0, color=(1.0, 0.95, 0.85))
    g.point("lamp_front", [-0.7, 1.9, 0.8], intensity=4.0, color=(1.0, 0.85, 0.7), light_range=6.0)
    g.camera([-2.2, 1.6, 2.2], [0.8, 0.6, -0.8], yfov=1.0)
    return g.write("light_order.gltf")


def arch_mesh(m, center, inner, outer, depth, segments):
    """A semicircular arch in the x = const plane: a half annulus (radii inner..outer) about
    `center`, spanning z from -outer to +outer and y upward, extruded over x in +-depth/2. The
    faces: both sides (+x, -x), the intrados (facing the axis) and the extrados (facing away)."""
    cx, cy, cz = center
    h = depth / 2.0

    def ring(r, a):
        return [0.0, cy + r * math.sin(a), cz + r * math.cos(a)]

    for k in range(segments):
        a0, a1 = math.pi * k / segments, math.pi * (k + 1) / segments
        for side in (-1.0, 1.0):
            n = [side, 0.0, 0.0]
            p = [ring(inner, a0), ring(outer, a0), ring(outer, a1), ring(inner, a1)]
            v = [m.vertex([cx + side * h, q[1], q[2]], n, [q[2], q[1]]) for q in p]
            # CCW seen from +x for side +1, from -x for side -1.
            if side > 0:
                m.tri(v[0], v[3], v[2]); m.tri(v[0], v[2], v[1])
            else:
                m.tri(v[0], v[1], v[2]); m.tri(v[0], v[2], v[3])
        for r, sign in ((inner, -1.0), (outer, 1.0)):
            q0, q1 = ring(r, a0), ring(r, a1)
            am = 0.5 * (a0 + a1)
            n = [0.0, sign * math.sin(am), sign * math.cos(am)]
            v = [m.vertex([cx - h, q0[1], q0[2]], n, [0.0, a0 * r]), m.vertex([cx + h, q0[1], q0[2]], n, [depth, a0 * r]),
                 m.vertex([cx + h, q1[1], q1[2]], n, [depth, a1 * r]), m.vertex([cx - h, q1[1], q1[2]], n, [0.0, a1 * r])]
            if sign > 0:
                m.tri(v[0], v[3], v[2]); m.tri(v[0], v[2], v[1])
            else:
                m.tri(v[0], v[1], v[2]); m.tri(v[0], v[2], v[3])


def atrium():
    """Issue 13's zoo: a Sponza-like atrium of our own. An 8 x 8 m courtyard open to the sky, a
    mipmapped, tiled, normal-mapped floor (checker + bumps, 8 repeats, LINEAR_MIPMAP_LINEAR), brick
    walls (albedo + normal map, 4 repeats per wall), two arcades of four columns joined by
    semicircular arches, a high sun (80 degrees elevation, as in sun_room: no acne under the
    constant bias on the floor) and a warm lamp under the left arcade."""
    g = Gltf("atrium: mipmapped tiled normal-mapped floor, brick walls, columns and arches, sun and lamp")
    files = {"textures/checker_albedo.png": checker_albedo(), "textures/bump_normal.png": bump_normal()}
    brick_albedo, brick_normal = brick_textures()
    files.update({"textures/brick_albedo.png": brick_albedo, "textures/brick_normal.png": brick_normal})
    t_checker = g.texture("textures/checker_albedo.png", "checker_albedo")
    t_bump = g.texture("textures/bump_normal.png", "bump_normal")
    t_brick = g.texture("textures/brick_albedo.png", "brick_albedo")
    t_brick_n = g.texture("textures/brick_normal.png", "brick_normal")
    floor_mat = g.material("courtyard_floor", (1.0, 1.0, 1.0), roughness=0.7,
                           base_color=g.texture_info(t_checker), normal=g.texture_info(t_bump, scale=0.8))
    wall_mat = g.material("brick_wall", (1.0, 1.0, 1.0), roughness=0.9,
                          base_color=g.texture_info(t_brick), normal=g.texture_info(t_brick_n, scale=1.0))
    stone = g.material("column_stone", (0.72, 0.68, 0.6), roughness=0.8)
    S, H = 4.0, 4.0
    floor = MeshData(with_tangents=True)
    floor.quad([-S, 0, S], [2 * S, 0, 0], [0, 0, -2 * S], uv_scale=(1.0, 1.0))  # uv 0..8
    g.node("floor", mesh=g.mesh("floor", floor, floor_mat))
    walls = MeshData(with_tangents=True)
    for origin, du in (([-S, 0, -S], [2 * S, 0, 0]), ([S, 0, S], [-2 * S, 0, 0]),
                       ([-S, 0, S], [0, 0, -2 * S]), ([S, 0, -S], [0, 0, 2 * S])):
        walls.quad(origin, du, [0, H, 0], uv_scale=(0.5, 0.5), nu=2, nv=2)  # one brick tile per 2 m
    g.node("walls", mesh=g.mesh("walls", walls, wall_mat))
    column = MeshData()
    column.cylinder([0, 0, 0], 0.2, 2.2, 20)
    column_mesh = g.mesh("column", column, stone)
    arcade = MeshData()
    for z in (-3.0, -1.0, 1.0):  # arches between columns at z and z + 2, springing at y = 2.2
        arch_mesh(arcade, [0.0, 2.2, z + 1.0], 0.8, 1.0, 0.4, 12)
    arcade.box([-0.2, 3.2, -3.2], [0.2, 3.5, 3.2])  # the beam on top of the arches
    arcade_mesh = g.mesh("arcade", arcade, stone)
    for side, x in (("left", -2.2), ("right", 2.2)):
        for i, z in enumerate((-3.0, -1.0, 1.0, 3.0)):
            g.node("column_%s_%d" % (side, i), mesh=column_mesh, translation=[x, 0.0, z])
        g.node("arcade_" + side, mesh=arcade_mesh, translation=[x, 0.0, 0.0])
    g.sun("sun", normalize([0.12, -1.0, -0.1]), lux=6.0, color=(1.0, 0.96, 0.88))
    g.point("arcade_lamp", [-3.1, 1.6, 0.0], intensity=3.0, color=(1.0, 0.75, 0.5))
    g.camera([0.0, 1.8, 3.8], [0.0, 1.5, -2.0], yfov=1.25)
    return [g.write("atrium.gltf")] + [(name, data) for name, data in files.items()]


def scan_displacement(theta, phi):
    """A lumpy, scanned-looking surface: a few low-frequency lobes plus fine ridges."""
    return (1.0 + 0.15 * math.sin(2 * theta) * math.cos(3 * phi) + 0.06 * math.sin(9 * theta + 1.3) * math.cos(7 * phi)
            + 0.02 * math.sin(23 * theta) * math.sin(19 * phi + 0.7))


def scanned_statue():
    """Issue 13's zoo: a dense, scanned-like mesh: 29,800 small triangles (edges ~1-2 cm, below a
    grid-128 voxel of this ~3.2 m volume, 25 mm) on a pedestal in a small room, under a spot light."""
    g = Gltf("a dense scanned-like mesh (tens of thousands of triangles)")
    clay = g.material("clay", (0.7, 0.55, 0.42), roughness=0.65)
    wall = g.material("wall", (0.7, 0.7, 0.7), lambert=True)
    stone = g.material("pedestal", (0.45, 0.45, 0.47), roughness=0.8)
    room = MeshData(with_uv=False)
    room.box([-1.6, 0.0, -1.6], [1.6, 2.6, 1.6], inward=True)
    g.node("room", mesh=g.mesh("room", room, wall))
    pedestal = MeshData(with_uv=False)
    pedestal.box([-0.35, 0.0, -0.35], [0.35, 0.6, 0.35])
    g.node("pedestal", mesh=g.mesh("pedestal", pedestal, stone))
    statue = MeshData(with_uv=False)
    statue.sphere([0, 0, 0], 1.0, 100, 150, displace=scan_displacement)
    g.node("statue", mesh=g.mesh("statue", statue, clay), translation=[0.0, 1.1, 0.0], scale=[0.42, 0.5, 0.42])
    g.spot("key_light", [1.2, 2.5, 1.2], look_rotation([1.2, 2.5, 1.2], [0.0, 1.0, 0.0]), intensity=10.0,
           inner=0.3, outer=0.55)
    g.camera([0.9, 1.6, 1.5], [0.0, 1.0, 0.0], yfov=1.0)
    return g.write("scanned_statue.gltf")


def material_room():
    """Issue 13's zoo: a many-materials room. Two rows of four spheres (metals: gold, copper,
    iron, silver at roughness 0.1, 0.3, 0.55, 0.85; dielectrics: red, blue, white, green plastic
    at roughness 0.05, 0.25, 0.5, 0.9) on a grey floor, two emissive strips on the back wall and a
    spot light."""
    g = Gltf("many materials: metals and dielectrics of several roughnesses, emissive strips")
    wall = g.material("wall", (0.65, 0.65, 0.65), lambert=True)
    floor_mat = g.material("floor", (0.4, 0.4, 0.4), roughness=0.45)
    strip = g.material("strip", (0.0, 0.0, 0.0), lambert=True, emissive=(0.9, 0.95, 1.0), strength=4.0)
    metals = [("gold", (1.0, 0.78, 0.34), 0.1), ("copper", (0.95, 0.64, 0.54), 0.3),
              ("iron", (0.56, 0.57, 0.58), 0.55), ("silver", (0.97, 0.96, 0.91), 0.85)]
    plastics = [("red", (0.7, 0.1, 0.08), 0.05), ("blue", (0.1, 0.2, 0.7), 0.25),
                ("white", (0.8, 0.8, 0.8), 0.5), ("green", (0.15, 0.55, 0.15), 0.9)]
    room = MeshData(with_uv=False)
    room.box([-3.0, 0.0, -2.0], [3.0, 2.8, 2.0], inward=True)
    g.node("room", mesh=g.mesh("room", room, wall))
    floor = MeshData(with_uv=False)
    floor.quad([-2.9, 0.01, 1.9], [5.8, 0, 0], [0, 0, -3.8])
    g.node("floor", mesh=g.mesh("floor", floor, floor_mat))
    ball = MeshData(with_uv=False)
    ball.sphere([0, 0, 0], 0.3, 16, 24)
    for row, (z, entries, metal) in enumerate(((-1.3, metals, 1.0), (-0.3, plastics, 0.0))):
        for i, (name, color, rough) in enumerate(entries):
            mat = g.material("%s_r%g" % (name, rough), color, metallic=metal, roughness=rough)
            g.node("sphere_%s" % name, mesh=g.mesh("sphere_" + name, ball, mat),
                   translation=[-1.8 + 1.2 * i, 0.31, z])
    strips = MeshData(with_uv=False)
    for y in (1.4, 2.2):
        strips.quad([-2.4, y, -1.98], [4.8, 0, 0], [0, 0.08, 0])
    g.node("strips", mesh=g.mesh("strips", strips, strip))
    g.spot("spot", [0.0, 2.7, 1.2], look_rotation([0.0, 2.7, 1.2], [0.0, 0.0, -0.3]), intensity=14.0,
           inner=0.5, outer=0.8, color=(1.0, 0.97, 0.92))
    g.camera([0.0, 1.6, 1.9], [0.0, 0.6, -0.9], yfov=1.2)
    return g.write("material_room.gltf")


def main():
    outputs = []
    for make in (cornell_box, demo_room, furnace_sphere, plane_spot, tiny_triangles, thin_wall, foliage, tiled_floor,
                 sun_room, atrium, scanned_statue, material_room, light_order):
        result = make()
        outputs += result if isinstance(result, list) else [result]
    check = "--check" in sys.argv
    stale = []
    for name, data in outputs:
        path = os.path.join(HERE, name)
        old = open(path, "rb").read() if os.path.exists(path) else None
        if old != data:
            stale.append(name)
            if not check:
                os.makedirs(os.path.dirname(path), exist_ok=True)
                with open(path + ".tmp", "wb") as f:
                    f.write(data)
                os.replace(path + ".tmp", path)
        print("%-28s %8d bytes%s" % (name, len(data), " (changed)" if old != data else ""))
    if check and stale:
        print("stale: " + ", ".join(stale))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
