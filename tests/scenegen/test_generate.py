"""The random scene generator (tools/scenegen): a seed reproduces its file byte for byte; the
drawn content covers what issue 34 lists; every drawn setting is a row of the settings table;
a sample passes the Khronos glTF validator. VCT=path/to/vct names the binary (ctest sets it)."""
import collections
import json
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np
import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools", "scenegen"))
import generate  # noqa: E402
import gltf_writer  # noqa: E402
import settings_draw  # noqa: E402
import textures  # noqa: E402

SEEDS = range(60)


def test_a_seed_reproduces_its_scene():
    for seed in (0, 7, 123):
        assert gltf_writer.gltf_bytes(generate.generate(seed)) == gltf_writer.gltf_bytes(generate.generate(seed))
    assert gltf_writer.gltf_bytes(generate.generate(1)) != gltf_writer.gltf_bytes(generate.generate(2))
    assert gltf_writer.gltf_bytes(generate.generate(1, "medium")) != gltf_writer.gltf_bytes(generate.generate(1))


def test_the_draws_cover_the_issue_list():
    seen = collections.Counter()
    for seed in SEEDS:
        spec = generate.generate(seed)
        docs = gltf_writer.gltf_document(spec)
        seen.update("shape:" + m["shape"] for m in spec["meshes"])
        kinds = [l["type"] for l in spec["lights"]]
        seen.update("light:" + k for k in kinds)
        if "point" in kinds and any(k != "point" for k in kinds[kinds.index("point") + 1:]):
            seen["spot or sun after a point"] += 1
        seen["camera:" + spec["camera"]["type"]] += 1
        seen.update("color:" + m.get("color_encoding", "") for m in spec["meshes"] if m.get("colors") is not None)
        seen.update("mask" for m in spec["materials"] if m.get("alpha_mode") == "MASK")
        for t in spec["textures"]:
            h, w = t["pixels"].shape[:2]
            seen["npot" if (w & (w - 1)) or (h & (h - 1)) else "pot"] += 1
            seen.update("sampler:%s" % v for v in t["sampler"].values())
        seen.update("slot:" + s for m in docs["materials"] for s in ("normalTexture", "emissiveTexture") if s in m)
        seen.update("slot:" + s for m in docs["materials"] for s in m["pbrMetallicRoughness"] if s.endswith("Texture"))
        seen["aspect>2"] += max(spec["width"], spec["height"]) > 2 * min(spec["width"], spec["height"])
        seen.update("setting:" + k for k in spec["settings"])
    wanted = (["shape:" + s for s in ("plane", "box", "thin_wall", "slivers", "fold", "heightfield", "sphere",
                                      "room", "edge_on")] + ["light:point", "light:spot", "light:directional",
               "spot or sun after a point", "camera:perspective", "camera:orthographic", "mask", "npot", "pot",
               "aspect>2", "slot:baseColorTexture", "slot:metallicRoughnessTexture", "slot:normalTexture",
               "slot:emissiveTexture"] + ["color:" + e for e in ("float3", "float4", "ubyte4", "ushort4")]
              + ["sampler:%d" % v for v in textures.WRAPS + textures.MIN_FILTERS])
    missing = [w for w in wanted if not seen[w]]
    assert not missing, missing
    assert len([k for k in seen if k.startswith("setting:")]) >= len(settings_draw.CHOICES) // 2


def test_heightfields_reach_a_million_triangles_in_the_large_class():
    lo, hi = generate.shapes.HEIGHTFIELD_SIDE["large"]
    assert 2 * hi * hi >= 1_000_000 and 2 * lo * lo >= 250_000
    rng = np.random.default_rng(0)
    pos, tris = generate.shapes.heightfield(rng, "small")
    assert len(tris) == 2 * (round(len(pos) ** 0.5) - 1) ** 2


def test_every_drawn_setting_is_in_the_settings_table():
    vct = os.environ.get("VCT", os.path.join(ROOT, "build", "bin", "vct"))
    if not os.path.exists(vct):
        pytest.skip("no vct binary at " + vct)
    table = subprocess.run([vct, "settings", "--markdown"], capture_output=True, text=True, check=True).stdout
    for key in list(settings_draw.CHOICES) + ["shadow_map_size", "width", "height", "grid"]:
        assert "`vct.%s`" % key in table, key


def test_a_sample_passes_the_khronos_validator():
    script = os.path.join(ROOT, "scenes", "validate_scenes.sh")
    work = tempfile.mkdtemp()
    try:
        files = []
        for seed in range(0, 60, 3):
            path = os.path.join(work, "seed_%d.gltf" % seed)
            with open(path, "wb") as f:
                f.write(gltf_writer.gltf_bytes(generate.generate(seed)))
            files.append(path)
        proc = subprocess.run([script] + files, capture_output=True, text=True)
        if proc.returncode == 77:
            pytest.skip("no glTF validator: " + proc.stderr.strip())
        assert proc.returncode == 0, proc.stdout
        assert proc.stdout.count(" 0 errors") == len(files)
    finally:
        shutil.rmtree(work)


def test_settings_file_carries_sizes_and_spp():
    sys.path.insert(0, os.path.join(ROOT, "tools", "scenegen"))
    import hunt
    spec = generate.generate(3)
    doc = hunt.settings_document(spec)
    assert doc["pt"] == {"spp": 4}
    assert (doc["vct"]["width"], doc["vct"]["height"], doc["vct"]["grid"]) == (spec["width"], spec["height"], spec["grid"])
    assert doc["vct"]["shadow_map_size"] == spec["shadow_map_size"]
    json.dumps(doc)
