"""Random textures and samplers for the scene generator: NPOT sizes, flat regions of dark,
saturated and mid values (where sRGB decode precision shows, issue 34), checkers, ramps, noise,
binary and ramped alpha; every glTF sampler mode, or no sampler at all."""
import numpy as np

NEAREST, LINEAR = 9728, 9729
MIN_FILTERS = [9728, 9729, 9984, 9985, 9986, 9987]  # NEAREST ... LINEAR_MIPMAP_LINEAR
WRAPS = [33071, 33648, 10497]  # CLAMP_TO_EDGE, MIRRORED_REPEAT, REPEAT
SIDES = [1, 2, 3, 5, 7, 8, 13, 16, 17, 31, 32, 33, 64, 100]

# Flat colours users' content is full of: near-black, saturated primaries, mid greys, white.
PALETTE = np.array([[0, 0, 0], [1, 1, 1], [3, 2, 5], [10, 10, 10], [15, 15, 15], [21, 30, 42],
                    [255, 0, 0], [0, 255, 0], [0, 0, 255], [255, 255, 0], [200, 20, 180], [128, 128, 128],
                    [188, 188, 188], [255, 255, 255], [64, 32, 16], [250, 128, 5]], np.uint8)


def sampler(rng):
    """A glTF sampler object; filters are sometimes absent (the implementation's choice)."""
    s = {"wrapS": int(rng.choice(WRAPS)), "wrapT": int(rng.choice(WRAPS))}
    if rng.random() < 0.85:
        s["magFilter"] = int(rng.choice([NEAREST, LINEAR]))
    if rng.random() < 0.85:
        s["minFilter"] = int(rng.choice(MIN_FILTERS))
    return s


def _pattern(rng, height, width):
    kind = rng.choice(["flat", "regions", "checker", "ramp", "noise"])
    if kind == "flat":
        return np.broadcast_to(PALETTE[rng.integers(len(PALETTE))], (height, width, 3)).copy()
    if kind == "regions":  # a few rectangles of palette colours over a palette background
        img = np.broadcast_to(PALETTE[rng.integers(len(PALETTE))], (height, width, 3)).copy()
        for _ in range(int(rng.integers(1, 5))):
            y0, x0 = rng.integers(0, height), rng.integers(0, width)
            y1, x1 = y0 + rng.integers(1, height + 1), x0 + rng.integers(1, width + 1)
            img[y0:y1, x0:x1] = PALETTE[rng.integers(len(PALETTE))]
        return img
    if kind == "checker":
        cell = int(rng.integers(1, max(2, min(height, width)) + 1))
        a, b = PALETTE[rng.integers(len(PALETTE), size=2)]
        yy, xx = np.meshgrid(np.arange(height), np.arange(width), indexing="ij")
        return np.where((((yy // cell) + (xx // cell)) % 2 == 0)[..., None], a, b).astype(np.uint8)
    if kind == "ramp":  # every value 0..255 along x (or a dark ramp 0..48)
        top = 255 if rng.random() < 0.5 else 48
        v = np.round(np.linspace(0, top, width)).astype(np.uint8)
        return np.broadcast_to(v[None, :, None], (height, width, 3)).copy()
    return rng.integers(0, 256, (height, width, 3), dtype=np.uint8)


def _alpha(rng, height, width):
    kind = rng.choice(["binary", "ramp", "opaque"])
    if kind == "opaque":
        return np.full((height, width, 1), 255, np.uint8)
    if kind == "ramp":
        v = np.round(np.linspace(0, 255, height)).astype(np.uint8)
        return np.broadcast_to(v[:, None, None], (height, width, 1)).copy()
    return (rng.random((height, width, 1)) < 0.5).astype(np.uint8) * 255


def texture(rng, with_alpha):
    """{'pixels': uint8 (h, w, 3|4), 'sampler': {...}}: an NPOT or power-of-two image."""
    height, width = int(rng.choice(SIDES)), int(rng.choice(SIDES))
    pixels = _pattern(rng, height, width)
    if with_alpha:
        pixels = np.concatenate([pixels, _alpha(rng, height, width)], axis=2)
    return {"pixels": pixels, "sampler": sampler(rng)}


def normal_map(rng):
    """A tangent-space normal map (linear): random unit normals in the +z hemisphere, or flat."""
    height, width = int(rng.choice(SIDES)), int(rng.choice(SIDES))
    n = rng.normal(size=(height, width, 3)) * [0.4, 0.4, 0.0] + [0.0, 0.0, 1.0]
    n /= np.linalg.norm(n, axis=2, keepdims=True)
    return {"pixels": np.round((n * 0.5 + 0.5) * 255).astype(np.uint8), "sampler": sampler(rng)}
