"""Mesh shapes for the random scene generator: each returns (positions, indices) in local space,
float64 (n, 3) and int64 (m, 3), counter-clockwise front faces. The shapes are the content users
bring that our own zoo lacked (issue 34): slivers, folds at nearly edge-on angles, thin walls,
heightfields from a handful to a million triangles, coplanar pairs.
"""
import numpy as np


def grid(nu, nv):
    """Triangles of an nu x nv quad grid over vertices numbered row by row ((nu + 1) per row)."""
    j, i = np.meshgrid(np.arange(nv), np.arange(nu), indexing="ij")
    a = (j * (nu + 1) + i).reshape(-1)
    b, c, d = a + 1, a + nu + 2, a + nu + 1
    return np.concatenate([np.stack([a, b, c], 1), np.stack([a, c, d], 1)]).astype(np.int64)


def plane(rng, size_class):
    n = int(rng.integers(1, 4 if size_class == "small" else 16))
    s, t = np.meshgrid(np.linspace(-0.5, 0.5, n + 1), np.linspace(-0.5, 0.5, n + 1))
    pos = np.stack([s.reshape(-1), np.zeros(s.size), -t.reshape(-1)], 1)
    return pos, grid(n, n)


def box(rng, size_class, thickness=None):
    """A closed box; `thickness` makes it a thin wall (a few millimetres to centimetres)."""
    half = np.array([0.5, 0.5, 0.5]) if thickness is None else np.array([0.5, 0.5, thickness / 2])
    corners = np.array([[x, y, z] for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)], float) * half
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    tris = [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]
    return corners, np.array(tris, np.int64)


def thin_wall(rng, size_class):
    return box(rng, size_class, thickness=float(rng.choice([0.002, 0.01, 0.03])))


def slivers(rng, size_class):
    """Needle triangles: two far vertices and a third within 1e-4..1e-2 of their segment."""
    count = int(rng.integers(1, 12 if size_class == "small" else 200))
    a = rng.uniform(-0.5, 0.5, (count, 3))
    b = rng.uniform(-0.5, 0.5, (count, 3))
    side = np.cross(b - a, rng.normal(size=(count, 3)))
    side /= np.linalg.norm(side, axis=1, keepdims=True)
    width = 10.0 ** rng.uniform(-4, -2, (count, 1))
    c = a + (b - a) * rng.uniform(0.2, 0.8, (count, 1)) + side * width
    pos = np.stack([a, b, c], 1).reshape(-1, 3)
    return pos, np.arange(3 * count, dtype=np.int64).reshape(-1, 3)


def fold(rng, size_class):
    """A zigzag sheet: strips whose fold angles reach almost 180 degrees, so some faces are seen
    nearly edge-on and neighbours nearly flip (issue 34's dense, folded mesh)."""
    folds = int(rng.integers(2, 8 if size_class == "small" else 64))
    xs = np.linspace(-0.5, 0.5, folds + 1)
    heights = rng.uniform(0.0, 0.5, folds + 1) * rng.choice([1.0, 8.0])
    heights[1::2] *= -1
    pos = np.array([[x, h, z] for x, h in zip(xs, heights) for z in (-0.5, 0.5)])
    tris = []
    for k in range(folds):
        a, b, c, d = 2 * k, 2 * k + 1, 2 * k + 3, 2 * k + 2
        tris += [(a, b, c), (a, c, d)]
    return pos, np.array(tris, np.int64)


HEIGHTFIELD_SIDE = {"small": (4, 24), "medium": (64, 160), "large": (360, 708)}


def heightfield(rng, size_class):
    """A terrain: n x n quads (2 n^2 triangles; 'large' reaches 1M), sum of random sines plus
    per-vertex noise, shared vertices (so shading normals vary smoothly, as exported terrains do)."""
    lo, hi = HEIGHTFIELD_SIDE[size_class]
    n = int(rng.integers(lo, hi + 1))
    s, t = np.meshgrid(np.linspace(-0.5, 0.5, n + 1), np.linspace(-0.5, 0.5, n + 1))
    h = np.zeros_like(s)
    for _ in range(3):
        f = rng.uniform(1, 12, 2)
        h += rng.uniform(0.01, 0.1) * np.sin(f[0] * s * 6.283 + rng.uniform(0, 6.283)) * np.cos(f[1] * t * 6.283)
    h += rng.uniform(0, 0.01) * rng.standard_normal(h.shape)
    pos = np.stack([s.reshape(-1), h.reshape(-1), -t.reshape(-1)], 1)
    return pos, grid(n, n)


def sphere(rng, size_class):
    nlat = int(rng.integers(3, 12 if size_class == "small" else 48))
    nlon = 2 * nlat
    theta, phi = np.meshgrid(np.linspace(0, np.pi, nlat + 1), np.linspace(0, 2 * np.pi, nlon + 1), indexing="ij")
    pos = 0.5 * np.stack([np.sin(theta) * np.cos(phi), np.cos(theta), -np.sin(theta) * np.sin(phi)], -1).reshape(-1, 3)
    quads = grid(nlon, nlat)  # rows = latitude rings; grid() winds them clockwise seen from outside
    return pos, quads[:, ::-1]


SHAPES = {"plane": plane, "box": box, "thin_wall": thin_wall, "slivers": slivers, "fold": fold,
          "heightfield": heightfield, "sphere": sphere}


def drop_degenerate(pos, tris):
    """Removes triangles of zero area in float32 (they have no normal; glTF validators flag them)."""
    p = pos.astype(np.float32).astype(np.float64)
    area2 = np.linalg.norm(np.cross(p[tris[:, 1]] - p[tris[:, 0]], p[tris[:, 2]] - p[tris[:, 0]]), axis=1)
    return tris[area2 > 1e-12]


def vertex_normals(pos, tris):
    """Area-weighted vertex normals of shared vertices; unit length (the validator checks it)."""
    face = np.cross(pos[tris[:, 1]] - pos[tris[:, 0]], pos[tris[:, 2]] - pos[tris[:, 0]])
    acc = np.zeros_like(pos)
    for k in range(3):
        np.add.at(acc, tris[:, k], face)
    length = np.linalg.norm(acc, axis=1, keepdims=True)
    fallback = np.tile([0.0, 1.0, 0.0], (len(pos), 1))
    return np.where(length > 1e-20, acc / np.maximum(length, 1e-30), fallback)


def unshare(pos, tris):
    """Flat shading: every triangle gets its own three vertices (and its face normal)."""
    p = pos[tris.reshape(-1)]
    return p, np.arange(len(p), dtype=np.int64).reshape(-1, 3)
