#!/usr/bin/env python3
"""Seed corpora for the fuzz targets, written into fuzz/corpus/.
gltf: the committed scenes (but tiny_triangles), minified, plus each as a .glb (buffer moved into the
BIN chunk), and inputs at the limits of issue 19 (nesting, a URI leaving the folder, a huge PNG header).
stage_set: a small run dir's manifest (two stages) + a NRRD + an EXR, joined as fuzz_inputs.h says.
scene_compare: whole stage sets of the built-in scene at the settings of scene_compare_steps.h
(scene_compare_seed_settings), the stages/ of two reference renders,
  vct render --backend ref --width 16 --height 16 --grid 16 --config C --set voxelizer=gpu
             --set reduction=fixed --stage-set --out ISO
with C = {"vct": {"shadow_map_size": 64}}, and again with "anisotropic": true added (ANISO) (not a
validate run's ref/: that emulates the GL driver's MSAA sample count, 4 on llvmpipe, where the
fixture renders the default 8), joined
as named files (fuzz_inputs.h: write_named_stage_set): the isotropic set exact (float volumes: its
frame is A's), the anisotropic one with uint8 (UNORM) volumes to stay small.
  fuzz/make_seeds.py [RUN_DIR/ref] [--scene-compare ISO/stages ANISO/stages]"""
import argparse, base64, json, pathlib, struct

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
    # The scene zoo but tiny_triangles (600 KB minified: over the fuzzer's -max_len).
    for name in ["plane_spot", "thin_wall", "cornell_box", "furnace_sphere", "demo_room"]:
        doc = json.loads((root / "scenes" / f"{name}.gltf").read_text())
        for image in doc.get("images", []):  # textures embedded: the fuzzer's folder has none
            if "uri" in image and not image["uri"].startswith("data:"):
                png = (root / "scenes" / image["uri"]).read_bytes()
                image["uri"] = "data:image/png;base64," + base64.b64encode(png).decode()
        (out / f"{name}.gltf").write_text(json.dumps(doc, separators=(",", ":")))
        if len(doc.get("buffers", [])) == 1:
            (out / f"{name}.glb").write_bytes(glb(doc))
    # Inputs at the limits of issue 19: nesting just under and over kMaxJsonNesting, an image URI
    # leaving the folder, a PNG whose header claims 100000 x 100000 pixels (as a data URI).
    plane = json.loads((root / "scenes" / "plane_spot.gltf").read_text())
    text = json.dumps(plane, separators=(",", ":"))
    # Seeds named refused_* must be refused (tests/ref/fuzz_regression_test.cpp), the others load.
    for depth, stem in ((127, "nesting_127"), (129, "refused_nesting_129")):
        (out / f"{stem}.gltf").write_text('{"extras":' + "[" * depth + "]" * depth + "," + text[1:])
    for name, uri in [("refused_uri_dotdot", "../../../../../../etc/passwd"),
                      ("refused_huge_png", "data:image/png;base64," + base64.b64encode(
                          b"\x89PNG\r\n\x1a\n" + struct.pack(">I", 13) + b"IHDR" +
                          struct.pack(">IIBBBBB", 100000, 100000, 8, 6, 0, 0, 0) + bytes(4)).decode())]:
        doc = json.loads(text)
        doc["images"] = [{"uri": uri}]
        doc["textures"] = [{"source": 0}]
        doc["materials"][0].setdefault("pbrMetallicRoughness", {})["baseColorTexture"] = {"index": 0}
        (out / f"{name}.gltf").write_text(json.dumps(doc, separators=(",", ":")))


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


# The stages kept: what --scene rebuilds the frame from, plus a few the A vs B judgement reads.
SCENE_COMPARE_STAGES = ["gbuffer.coverage", "gbuffer.depth", "gbuffer.position", "gbuffer.normal",
                        "gbuffer.albedo", "gbuffer.material", "gbuffer.specular_color", "gbuffer.emission",
                        "image.direct", "image.indirect_diffuse", "image.final", "shadow_map.0", "voxel.radiance"]


def nrrd_as_uint8(data):
    end = data.index(b"\n\n")
    header, body = data[:end].decode(), data[end + 2:]
    assert "type: float" in header and "encoding: raw" in header
    floats = struct.unpack(f"<{len(body) // 4}f", body[: len(body) // 4 * 4])
    return (header.replace("type: float", "type: uint8") + "\n\n").encode() + bytes(
        min(255, max(0, round(v * 255))) for v in floats)


def named_stage_set(dump, unorm_volumes):
    manifest = json.loads((dump / "vct-stages.json").read_text())
    keep = {n: e for n, e in manifest["stages"].items() if n in SCENE_COMPARE_STAGES or n.startswith("mip.")}
    manifest["stages"] = {n: {"file": e["file"], "kind": e["kind"]} for n, e in keep.items()}
    out = json.dumps(manifest, separators=(",", ":")).encode()
    for e in keep.values():
        data = (dump / e["file"]).read_bytes()
        if unorm_volumes and e["kind"] == "volume":
            data = nrrd_as_uint8(data)
        out += SEP + e["file"].encode() + b"\n" + data
    return out


def scene_compare_seeds(iso, aniso):
    out = corpus / "scene_compare"
    out.mkdir(parents=True, exist_ok=True)
    (out / "cornell_16_iso.bin").write_bytes(named_stage_set(iso, False))
    (out / "cornell_16_aniso_unorm.bin").write_bytes(named_stage_set(aniso, True))


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("run_dir", nargs="?", type=pathlib.Path, help="a validate run's ref/ (stage_set seeds)")
    ap.add_argument("--scene-compare", nargs=2, type=pathlib.Path, metavar=("ISO", "ANISO"))
    args = ap.parse_args()
    gltf_seeds()
    if args.run_dir:
        stage_set_seeds(args.run_dir)
    if args.scene_compare:
        scene_compare_seeds(*args.scene_compare)
