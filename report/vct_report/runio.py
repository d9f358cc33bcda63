"""Reading a run directory: run.json, stage manifests, NRRD volumes, EXR images (through
flip_evaluator's loader), and a tiny PNG writer. Everything tolerates missing files: a missing
part is returned as None and shown as missing by the page."""
import base64
import json
import os
import struct
import zlib

import numpy as np


def load_json(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def read_nrrd(path):
    """Little-endian NRRD, raw or gzip (vct writes gzip), as most tools write it: returns array [z, y, x, c]."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError:
        return None
    end = data.find(b"\n\n")
    if end < 0:
        return None
    header = {}
    for line in data[:end].decode("latin-1").splitlines()[1:]:
        if line.startswith("#") or ":" not in line:
            continue
        k, v = line.split(":", 1)
        header[k.strip()] = v.strip()
    encoding = header.get("encoding", "raw")
    if encoding not in ("raw", "gzip", "gz"):
        return None
    dtype = {"float": "<f4", "uint8": "u1", "unsigned char": "u1", "uint16": "<u2", "int32": "<i4"}.get(
        header.get("type", "float"))
    if dtype is None:
        return None
    sizes = [int(s) for s in header["sizes"].split()]
    payload = data[end + 2:]
    if encoding != "raw":  # vct writes gzip (ref/io/nrrd.cpp); wbits 31 = one gzip member
        try:
            payload = zlib.decompress(payload, 31)
        except zlib.error:
            return None
    arr = np.frombuffer(payload, dtype=dtype).astype(np.float32)
    if len(sizes) == 3:
        sizes = [1] + sizes
    c, nx, ny, nz = sizes
    return arr[: c * nx * ny * nz].reshape(nz, ny, nx, c)


def read_exr(path):
    """HxWxC float32 via flip_evaluator (tinyexr); None when unavailable."""
    if not os.path.exists(path):
        return None
    try:
        import flip_evaluator
        img = flip_evaluator.load(path)
        return np.asarray(img, dtype=np.float32)
    except Exception:  # noqa: BLE001 - the page shows the image as missing instead
        return None


def write_png(path, rgb):
    """rgb: HxWx3 float in [0,1] or uint8."""
    a = rgb if rgb.dtype == np.uint8 else (np.clip(rgb, 0, 1) * 255 + 0.5).astype(np.uint8)
    h, w = a.shape[:2]
    raw = b"".join(b"\x00" + a[y].tobytes() for y in range(h))

    def chunk(tag, body):
        return struct.pack(">I", len(body)) + tag + body + struct.pack(">I", zlib.crc32(tag + body) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b"")
    tmp = path + ".tmp"
    with open(tmp, "wb") as f:
        f.write(png)
    os.replace(tmp, path)


def half_b64(img, max_side=256):
    """Float image as base64 float16 (row 0 = top), downsampled by striding to <= max_side."""
    step = max(1, int(np.ceil(max(img.shape[0], img.shape[1]) / max_side)))
    small = img[::step, ::step, :3]
    if small.shape[2] == 1:
        small = np.repeat(small, 3, axis=2)
    small = np.ascontiguousarray(np.nan_to_num(small, nan=0, posinf=65000).clip(0, 65000).astype("<f2"))
    return {"w": int(small.shape[1]), "h": int(small.shape[0]), "data": base64.b64encode(small.tobytes()).decode()}


class Run:
    """One run directory: run.json plus the stage sets under ref/ and gl/ (or an external set)."""

    def __init__(self, path):
        self.path = os.path.abspath(path)
        self.json = load_json(os.path.join(self.path, "run.json")) or {}
        self.sets = {}
        for side in ("ref", "gl"):
            m = load_json(os.path.join(self.path, side, "vct-stages.json"))
            if m:
                self.sets[side] = m
        own = load_json(os.path.join(self.path, "vct-stages.json"))
        if own:  # an external stage directory on its own
            self.sets[own.get("backend", "external")] = own
            for side in list(self.sets):
                if side != own.get("backend", "external"):
                    continue

    def file(self, *parts):
        p = os.path.join(self.path, *parts)
        return p if os.path.exists(p) else None

    def stage_dir(self, side):
        if side in self.sets and os.path.isdir(os.path.join(self.path, side)):
            return os.path.join(self.path, side)
        return self.path

    def stage_file(self, side, stage, preview=True):
        m = self.sets.get(side)
        if not m or stage not in m.get("stages", {}):
            return None
        e = m["stages"][stage]
        name = e.get("preview") if preview else e.get("file")
        if not name:
            return None
        p = os.path.join(self.stage_dir(side), name)
        return p if os.path.exists(p) else None

    def stages(self, side):
        return list(self.sets.get(side, {}).get("stages", {}).keys())
