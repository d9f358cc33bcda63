#!/usr/bin/env python3
"""Seed corpora for the fuzz targets, written into fuzz/corpus/ (run by scripts/fuzz.sh).
gltf: the small committed scenes, minified, plus each as a .glb (buffer moved into the BIN chunk).
stage_set: a small run dir's manifest (two stages) + a NRRD + an EXR, joined as fuzz_inputs.h says."""
import base64, json, pathlib, struct, sys

root = pathlib.Path(__file__).resolve().parent.parent
corpus = root / "fuzz" / "corpus"
SEP = b"\n--VCT-FUZZ-FILE--\n"


def glb(doc):
    doc = json.loads(json.dumps(doc))
    buf = doc["buffers"][0]
    data = base64.b64decode(buf.pop("uri").split(",", 1)[1])
    data += b"\0" * (-len(data) % 4)
    buf["byteLength"] = len(data)
    js = json.dumps(doc, separators=(",", ":")).encode()
    js += b" " * (-len(js) % 4)
    body = struct.pack("<II", len(js), 0x4E4F534A) + js + struct.pack("<II", len(data), 0x004E4942) + data
    return b"glTF" + struct.pack("<II", 2, 12 + len(body)) + body


def gltf_seeds():
    out = corpus / "gltf"
    out.mkdir(parents=True, exist_ok=True)
    for name in ["plane_spot", "thin_wall", "cornell_box", "furnace_sphere"]:
        doc = json.loads((root / "scenes" / f"{name}.gltf").read_text())
        (out / f"{name}.gltf").write_text(json.dumps(doc, separators=(",", ":")))
        if len(doc.get("buffers", [])) == 1:
            (out / f"{name}.glb").write_bytes(glb(doc))


def stage_set_seeds(run_dir):
    out = corpus / "stage_set"
    out.mkdir(parents=True, exist_ok=True)
    manifest = json.loads((run_dir / "vct-stages.json").read_text())
    nrrd = (run_dir / "mip_iso_3.nrrd").read_bytes()
    exr = (run_dir / "gbuffer_depth.exr").read_bytes()
    small = dict(manifest)
    small["stages"] = {
        "mip.iso.3": {"file": "v.nrrd", "kind": "volume"},
        "gbuffer.depth": {"file": "i.exr", "kind": "image"},
    }
    (out / "run_dir.bin").write_bytes(json.dumps(small, indent=1).encode() + SEP + nrrd + SEP + exr)
    (out / "manifest_only.bin").write_bytes(json.dumps(small).encode())


if __name__ == "__main__":
    gltf_seeds()
    if len(sys.argv) > 1:
        stage_set_seeds(pathlib.Path(sys.argv[1]))
