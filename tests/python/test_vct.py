"""`import vct` (docs/python.md) against the CLI and against itself, on the built-in Cornell box at
small sizes: the reference frame equals `vct render --dump`'s files bit for bit (and at another
thread count), a set compared with itself passes, a changed pixel fails at exactly its stage,
settings round-trip and bad ones raise, arrays are views that keep their owner alive, GL agrees
with the reference, the path tracer's emission matches VCT's (both see the same emitters)."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

import vct

VCT_BINARY = os.environ.get("VCT_BINARY")


def small_settings(**vct_keys):
    s = vct.default_settings()
    s["vct"].update(width=32, height=32, grid=16, shadow_map_size=256, **vct_keys)
    s["pt"].update(width=32, height=32, spp=4)
    s["threads"] = 1
    return s


@pytest.fixture(scope="module")
def scene():
    return vct.load_scene()


@pytest.fixture(scope="module")
def ref(scene):
    return vct.render_ref(scene, small_settings())


def test_scene_is_the_builtin_cornell_box(scene):
    assert scene.source == "builtin:cornell_box"
    assert scene.triangle_count == 2382  # docs/pipeline.md, "Measured"
    assert scene.spot_light_count == 1
    assert scene.light_count == 1
    assert scene.light_kinds == ["spot"]


def test_shapes_follow_the_settings(ref):
    assert ref["image.final"].shape == (32, 32, 3)
    assert ref["image.final"].dtype == np.float32
    assert ref["shadow_map.0"].shape == (256, 256, 1)
    assert ref["voxel.radiance"].shape == (16, 16, 16, 4)  # D x H x W x C
    assert ref["mip.iso.1"].shape == (8, 8, 8, 4)
    alpha = ref["voxel.radiance"][..., 3]
    assert set(np.unique(alpha)) <= {0.0, 1.0}  # level 0 opacity is 0 or 1 (stage_types.h)
    assert 0 < alpha.sum() < alpha.size
    assert "image.final" in ref and "no.such.stage" not in ref
    with pytest.raises(KeyError):
        ref["no.such.stage"]


def test_arrays_are_views_that_keep_the_set_alive(scene):
    s = vct.render_ref(scene, small_settings())
    a, b = s["image.final"], s["image.final"]
    assert np.shares_memory(a, b)
    expected = a.copy()
    del s
    np.testing.assert_array_equal(a, expected)  # still valid: the array owns a reference to the set


def test_reference_equals_the_cli_dump_bit_for_bit(scene, ref, tmp_path):
    if not VCT_BINARY:
        pytest.skip("VCT_BINARY not set (ctest sets it)")
    config = tmp_path / "settings.json"
    config.write_text(json.dumps(small_settings()))
    out = tmp_path / "dump"
    # Two threads here, one in the Python render: the bytes may not depend on the thread count.
    subprocess.run([VCT_BINARY, "render", "--backend", "ref", "--dump", "--config", str(config), "--threads", "2",
                    "--out", str(out)], check=True, capture_output=True)
    pairs = [("image.final", "final.exr"), ("image.direct", "direct.exr"), ("gbuffer.normal", "gbuffer_normal.exr"),
             ("shadow_map.0", "shadow_map_0.exr")]
    for stage, name in pairs:
        np.testing.assert_array_equal(ref[stage], vct.read_image(str(out / name)), err_msg=stage)
    np.testing.assert_array_equal(ref["voxel.radiance"], vct.read_volume(str(out / "voxels_radiance_L0.nrrd")))
    np.testing.assert_array_equal(ref["mip.iso.2"], vct.read_volume(str(out / "voxels_radiance_L2.nrrd")))


def test_a_set_compared_with_itself_passes(ref):
    report = vct.compare(ref, ref)
    assert report["overall"] == "pass"
    assert report["first_failing"] == ""
    assert len(report["stages"]) >= 20
    assert all(s["verdict"] == "pass" and s["max_abs"] == 0 for s in report["stages"])


def test_a_changed_albedo_fails_at_that_stage(scene, ref):
    test = vct.render_ref(scene, small_settings())
    albedo = test["gbuffer.albedo"]
    y, x = np.argwhere(test["gbuffer.coverage"][..., 0] > 0)[0]
    albedo[y, x, :] += 0.5  # writes into the set: the array is a view
    report = vct.compare(ref, test)
    assert report["overall"] == "fail"
    assert report["first_failing"] == "gbuffer.albedo"
    stage = next(s for s in report["stages"] if s["stage"] == "gbuffer.albedo")
    assert stage["out_of_bound"] == 1
    assert stage["worst"][0]["at"][:2] == [int(x), int(y)]
    assert stage["max_abs"] == pytest.approx(0.5, abs=1e-6)


def test_settings_round_trip():
    d = vct.default_settings()
    assert vct.check_settings(d) == d
    changed = vct.copy_settings(d)
    changed["vct"]["grid"] = 32
    changed["vct"]["light_model"] = "seed"
    back = vct.check_settings(changed)
    assert back["vct"]["grid"] == 32 and back["vct"]["light_model"] == "seed"
    assert vct.check_settings({"vct": {"grid": 32}}) == dict(d, vct=dict(d["vct"], grid=32))
    assert vct.sweep_settings(d, "cones", "0")["vct"]["diffuse_cones"] is False
    assert vct.sweep_settings(d, "aperture", "45")["vct"]["diffuse_aperture_deg"] == 45
    v = vct.validate_defaults()
    assert v["vct"]["grid"] == 64 and v["vct"]["reduction"] == "fixed"


@pytest.mark.parametrize("bad, words", [
    ({"vct": {"grid": 7}}, "grid"),
    ({"vct": {"gird": 64}}, "vct.gird"),
    ({"vct": {"grid": "large"}}, "vct.grid"),
    ({"vct": {"light_model": "sun"}}, "light_model"),
    ({"pt": {"spp": -1}}, "spp"),
    ([1, 2], "dict"),
    ({"threads": 2.7}, "threads"),  # issue 38: not truncated to 2
    ({"vct": {"time": float("nan")}}, "broken JSON"),  # json.dumps writes NaN, which JSON lacks
    ({"vct": {"shadow_bias": 1e39}}, "shadow_bias"),  # beyond float: Inf
    (json.loads('{"vct": ' + '{"a": ' * 200 + "1" + "}" * 200 + "}"), "nests deeper than 128"),
])
def test_bad_settings_raise_naming_the_key(scene, bad, words):
    with pytest.raises(vct.InputError, match=words):
        vct.check_settings(bad)
    with pytest.raises(ValueError):  # InputError is a ValueError
        vct.render_ref(scene, bad)


def test_bad_scene_index_raises_instead_of_crashing(tmp_path):
    """Issue 38: a morph target naming accessor 1000000 read out of bounds and killed Python."""
    root = os.environ.get("VCT_SOURCE_DIR") or os.path.join(os.path.dirname(__file__), "..", "..")
    with open(os.path.join(root, "scenes", "cornell_box.gltf")) as f:
        doc = json.load(f)
    doc["meshes"][0]["primitives"][0]["targets"] = [{"POSITION": 1000000}]
    (tmp_path / "bad.gltf").write_text(json.dumps(doc))
    with pytest.raises(vct.InputError, match=r"targets\[0\]\.POSITION is 1000000, but accessors has"):
        vct.load_scene(str(tmp_path / "bad.gltf"))


def test_deep_stage_set_manifest_raises(tmp_path):
    (tmp_path / "vct-stages.json").write_text('{"format": "vct-stages", "info": ' + "[" * 300000 + "]" * 300000 + "}")
    with pytest.raises(vct.InputError, match="nests deeper than 128"):
        vct.read_stage_set(str(tmp_path))


def test_stage_set_written_and_read_back(ref, tmp_path):
    vct.write_stage_set(str(tmp_path / "set"), ref)
    back = vct.read_stage_set(str(tmp_path / "set"))
    assert sorted(back.image_names) == sorted(ref.image_names)
    for name in ("image.final", "voxel.radiance", "gbuffer.depth"):
        np.testing.assert_array_equal(back[name], ref[name], err_msg=name)
    assert vct.compare(ref, back)["overall"] == "pass"


def test_a_set_built_from_arrays(ref):
    s = vct.StageSet()
    s.backend = "mine"
    s.set_image("image.final", np.ascontiguousarray(ref["image.final"]))
    with pytest.raises(vct.InputError, match="already"):
        s.set_image("image.final", ref["image.final"])
    with pytest.raises(vct.InputError, match="D x H x W x C"):
        s.set_volume("voxel.radiance", ref["image.final"])
    np.testing.assert_array_equal(s["image.final"], ref["image.final"])


def test_gl_matches_the_reference(scene):
    s = vct.validate_defaults()
    s["vct"].update(width=64, height=64, grid=16, shadow_map_size=256)
    s["threads"] = 1
    try:
        gl = vct.render_gl(scene, s)
    except vct.EnvironmentUnavailable as e:
        pytest.skip(str(e))
    assert vct.facts(gl).get("renderer")
    ref = vct.render_ref(scene, vct.settings_as_run_by_gl(s, gl))
    report = vct.compare(ref, gl)
    assert report["overall"] in ("pass", "warn"), report["first_failing"]
    assert report["first_failing"] == ""


def test_path_tracer_and_bias(scene, ref):
    pt = vct.path_trace(scene, small_settings())
    assert pt.spp == 4
    assert pt["pt_full"].shape == (32, 32, 3)
    assert "pt_full_var" in pt.names
    rows = {r["component"]: r for r in vct.bias(ref, pt)}
    assert rows["full"]["available"] and rows["full"]["rel_mse"] > 0
    # Emission is seen directly by both: no bias beyond float rounding.
    assert rows["emission"]["available"]
    assert abs(rows["emission"]["relative_bias"]) < 1e-4


def test_the_docs_example_plots_a_sweep(tmp_path):
    """docs/bias_vs_grid.py at a tiny size: it runs, prints one line per grid, writes the plot."""
    root = os.environ.get("VCT_SOURCE_DIR") or os.path.join(os.path.dirname(__file__), "..", "..")
    out = tmp_path / "bias.png"
    r = subprocess.run([sys.executable, os.path.join(root, "docs", "bias_vs_grid.py"), "--grids", "16,32", "--size", "32",
                        "--spp", "2", "--threads", "1", "--out", str(out)], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    assert [line.split()[1] for line in r.stderr.splitlines() if line.startswith("grid")] == ["16", "32"]
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    bad = subprocess.run([sys.executable, os.path.join(root, "docs", "bias_vs_grid.py"), "--grids", "7"],
                         capture_output=True, text=True)
    assert bad.returncode == 2 and "grid" in bad.stderr and "Traceback" not in bad.stderr
