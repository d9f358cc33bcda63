"""Writes a scene spec (tools/scenegen/generate.py) as one self-contained glTF 2.0 file.

Every buffer and PNG is embedded as a base64 data URI, so a regression case is one .gltf plus its
settings.json. Output is a pure function of the spec (fixed float formatting, no timestamps): the
seed reproduces the file byte for byte (docs/compare.md, "False-alarm hunt").
"""
import base64
import json
import struct
import zlib

import numpy as np

FLOAT, UBYTE, USHORT, UINT = 5126, 5121, 5123, 5125
ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER = 34962, 34963
TYPE_OF_WIDTH = {1: "SCALAR", 2: "VEC2", 3: "VEC3", 4: "VEC4"}


def png_bytes(pixels):
    """pixels: uint8 array (height, width, 3 or 4); row 0 is the top of the image (glTF v = 0)."""
    height, width, channels = pixels.shape
    color_type = {3: 2, 4: 6}[channels]

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    raw = b"".join(b"\x00" + pixels[y].tobytes() for y in range(height))
    header = struct.pack(">IIBBBBB", width, height, 8, color_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 6)) +
            chunk(b"IEND", b""))


class _Writer:
    def __init__(self):
        self.blob = bytearray()
        self.views, self.accessors = [], []

    def view(self, data, target):
        while len(self.blob) % 4:
            self.blob.append(0)
        self.views.append({"buffer": 0, "byteOffset": len(self.blob), "byteLength": len(data),
                           "target": target})
        self.blob += data
        return len(self.views) - 1

    def accessor(self, array, ctype, target, normalized=False, minmax=False):
        """array: (count, width) or (count,) numpy array already in the component type."""
        count = array.shape[0]
        width = 1 if array.ndim == 1 else array.shape[1]
        acc = {"bufferView": self.view(np.ascontiguousarray(array).tobytes(), target),
               "componentType": ctype, "count": int(count), "type": TYPE_OF_WIDTH[width]}
        if normalized:
            acc["normalized"] = True
        if minmax:  # the stored float32 values, exactly (the validator compares them bit for bit)
            acc["min"] = [float(v) for v in array.reshape(count, width).min(axis=0)]
            acc["max"] = [float(v) for v in array.reshape(count, width).max(axis=0)]
        self.accessors.append(acc)
        return len(self.accessors) - 1


def _color_accessor(w, colors, encoding):
    """COLOR_0 in one of the encodings glTF allows: float VEC3/VEC4, normalized ubyte/ushort VEC4
    (VEC4 keeps every element 4-byte aligned without a byteStride, glTF 2.0 §3.6.2.4)."""
    c = np.clip(colors, 0.0, 1.0)
    if encoding == "float3":
        return w.accessor(c[:, :3].astype(np.float32), FLOAT, ARRAY_BUFFER)
    if encoding == "float4":
        return w.accessor(c.astype(np.float32), FLOAT, ARRAY_BUFFER)
    if encoding == "ubyte4":
        return w.accessor(np.round(c * 255).astype(np.uint8), UBYTE, ARRAY_BUFFER, normalized=True)
    return w.accessor(np.round(c * 65535).astype(np.uint16), USHORT, ARRAY_BUFFER, normalized=True)


def _primitive(w, mesh):
    attrs = {"POSITION": w.accessor(mesh["positions"].astype(np.float32), FLOAT, ARRAY_BUFFER, minmax=True)}
    if mesh.get("normals") is not None:
        attrs["NORMAL"] = w.accessor(mesh["normals"].astype(np.float32), FLOAT, ARRAY_BUFFER)
    if mesh.get("uv") is not None:
        attrs["TEXCOORD_0"] = w.accessor(mesh["uv"].astype(np.float32), FLOAT, ARRAY_BUFFER)
    if mesh.get("colors") is not None:
        attrs["COLOR_0"] = _color_accessor(w, mesh["colors"], mesh.get("color_encoding", "float4"))
    flat = mesh["indices"].reshape(-1)
    wide = len(mesh["positions"]) >= 65536
    indices = w.accessor(flat.astype(np.uint32 if wide else np.uint16), UINT if wide else USHORT,
                         ELEMENT_ARRAY_BUFFER)
    return {"attributes": attrs, "indices": indices, "material": mesh["material"]}


def _material(mat, extensions):
    pbr = {"baseColorFactor": list(mat["base_color"]), "metallicFactor": mat["metallic"],
           "roughnessFactor": mat["roughness"]}
    out = {"name": mat["name"], "pbrMetallicRoughness": pbr}
    slots = mat.get("textures", {})
    if "base_color" in slots:
        pbr["baseColorTexture"] = {"index": slots["base_color"]}
    if "metallic_roughness" in slots:
        pbr["metallicRoughnessTexture"] = {"index": slots["metallic_roughness"]}
    if "normal" in slots:
        out["normalTexture"] = {"index": slots["normal"]}
    if "emissive" in slots:
        out["emissiveTexture"] = {"index": slots["emissive"]}
    if mat.get("emissive"):
        out["emissiveFactor"] = list(mat["emissive"])
    if mat.get("alpha_mode"):
        out["alphaMode"] = mat["alpha_mode"]
        if mat.get("alpha_cutoff") is not None:
            out["alphaCutoff"] = mat["alpha_cutoff"]
    if mat.get("double_sided"):
        out["doubleSided"] = True
    if mat.get("lambert"):
        out["extensions"] = {"KHR_materials_specular": {"specularFactor": 0.0}}
        extensions.add("KHR_materials_specular")
    return out


def _light(light):
    out = {"name": light["name"], "type": light["type"], "color": list(light["color"]),
           "intensity": light["intensity"]}
    if light.get("range"):
        out["range"] = light["range"]
    if light["type"] == "spot":
        out["spot"] = {"innerConeAngle": light["inner"], "outerConeAngle": light["outer"]}
    return out


def _camera(cam):
    if cam["type"] == "orthographic":
        return {"type": "orthographic", "orthographic": {"xmag": cam["xmag"], "ymag": cam["ymag"],
                                                          "znear": cam["znear"], "zfar": cam["zfar"]}}
    persp = {"yfov": cam["yfov"], "znear": cam["znear"]}
    if cam.get("zfar"):
        persp["zfar"] = cam["zfar"]
    if cam.get("aspect"):
        persp["aspectRatio"] = cam["aspect"]
    return {"type": "perspective", "perspective": persp}


def _node(name, transform, **fields):
    node = {"name": name}
    for key in ("translation", "rotation", "scale"):
        if transform.get(key) is not None:
            node[key] = [float(v) for v in transform[key]]
    node.update(fields)
    return node


def gltf_document(spec):
    """The glTF JSON document (dict) of a spec, buffers embedded."""
    w = _Writer()
    extensions = set()
    doc = {"asset": {"version": "2.0", "generator": "VCT Oracle tools/scenegen (seed %s)" % spec["seed"]},
           "scene": 0, "scenes": [{"nodes": []}], "nodes": [], "meshes": [], "accessors": w.accessors,
           "bufferViews": w.views}
    doc["materials"] = [_material(m, extensions) for m in spec["materials"]]
    if spec["textures"]:
        doc["samplers"] = [t["sampler"] for t in spec["textures"]]
        doc["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(png_bytes(t["pixels"])).decode()}
                         for t in spec["textures"]]
        doc["textures"] = [{"sampler": i, "source": i} for i in range(len(spec["textures"]))]
    for mesh in spec["meshes"]:
        doc["meshes"].append({"name": mesh["name"], "primitives": [_primitive(w, mesh)]})
        doc["nodes"].append(_node(mesh["name"], mesh, mesh=len(doc["meshes"]) - 1))
    if spec["lights"]:
        extensions.add("KHR_lights_punctual")
        doc["extensions"] = {"KHR_lights_punctual": {"lights": [_light(l) for l in spec["lights"]]}}
        for i, light in enumerate(spec["lights"]):
            doc["nodes"].append(_node(light["name"], light, extensions={"KHR_lights_punctual": {"light": i}}))
    doc["cameras"] = [_camera(spec["camera"])]
    doc["nodes"].append(_node("camera", spec["camera"], camera=0))
    doc["scenes"][0]["nodes"] = list(range(len(doc["nodes"])))
    doc["buffers"] = [{"byteLength": len(w.blob),
                       "uri": "data:application/octet-stream;base64," + base64.b64encode(bytes(w.blob)).decode()}]
    if extensions:
        doc["extensionsUsed"] = sorted(extensions)
    for key in ("materials", "meshes", "accessors", "bufferViews"):
        if not doc[key]:
            del doc[key]
    return doc


def gltf_bytes(spec):
    return (json.dumps(_rounded(gltf_document(spec)), indent=1) + "\n").encode()


def _rounded(x):
    """Floats to 9 significant digits (float32 round-trips); accessor bounds stay exact."""
    if isinstance(x, float):
        return float("%.9g" % x)
    if isinstance(x, list):
        return [_rounded(v) for v in x]
    if isinstance(x, dict):
        return {k: (v if k in ("min", "max") else _rounded(v)) for k, v in x.items()}
    return x
