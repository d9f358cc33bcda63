"""The first screen's verdict sentence and stage choice (report/vct_report/glance.py) on
hand-made verdicts: a fail names the first failing stage and the first clause of its note, ties
only are a match with the warning count, no stages say why GL was not compared; and every stage
name the pipeline dumps has docs and sources that exist in the repository."""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "report"))

from vct_report.glance import focus_stage, scene_warnings_line, verdict_sentence  # noqa: E402
from vct_report.registry import Registry  # noqa: E402


def stage(name, verdict, note=""):
    return {"stage": name, "verdict": verdict, "note": note}


def test_a_failure_names_the_first_failing_stage():
    v = {"first_failing": "voxel.radiance", "stages": [
        stage("gbuffer.depth", "pass"), stage("voxel.radiance", "fail", "11 of 5166 voxels beyond the bound; 3 ties"),
        stage("image.final", "fail")]}
    cls, text = verdict_sentence(v)
    assert cls == "fail"
    assert text == ("GL fails at voxel.radiance: 11 of 5166 voxels beyond the bound "
                    "(2 stages fail in all; later ones usually follow from it).")
    assert focus_stage(v)["stage"] == "voxel.radiance"


def test_ties_only_are_a_match_with_the_warning_count():
    v = {"first_failing": "", "stages": [stage("a", "pass"), stage("image.direct", "warn"), stage("b", "warn")]}
    assert verdict_sentence(v) == ("warn", "GL matches the CPU reference at every stage (3 compared); "
                                           "2 warnings are ties the tolerance models allow (first: image.direct).")
    assert focus_stage(v)["stage"] == "image.direct"


def test_all_pass_and_not_compared():
    v = {"first_failing": "", "stages": [stage("a", "pass"), stage("b", "pass")]}
    assert verdict_sentence(v) == ("pass", "GL matches the CPU reference at every stage (2 compared).")
    assert focus_stage(v) is None
    cls, text = verdict_sentence({"stages": [], "note": "gl unavailable: no EGL device"})
    assert cls == "missing" and "gl unavailable: no EGL device" in text


def test_the_registry_answers_for_family_members():
    rows = [{"name": "image.final", "family": None, "what": "the frame", "docs": "docs/pipeline.md § Final composite",
             "ref_source": "r", "gl_source": "g", "walkthrough_step": "final"},
            {"name": "mip.iso", "family": "mip_level", "what": "iso", "docs": "d", "ref_source": "r", "gl_source": "g",
             "walkthrough_step": "mips"}]
    for n in ("voxel.radiance", "voxel.conservative", "voxel.fragments", "voxel.occupancy", "voxel.holes"):
        rows.append({"name": n, "family": None, "what": n, "docs": "d", "ref_source": "r", "gl_source": "g",
                     "walkthrough_step": ""})
    reg = Registry(rows)
    assert reg.doc("mip.iso.3")[0] == "iso"
    assert reg.doc("mip.iso.x") is None and reg.doc("nope") is None
    assert reg.step_prefixes("mips") == ["mip.iso."]
    try:
        Registry(rows[1:])  # no image.final: the report's named stages must exist
        assert False
    except ValueError as e:
        assert "image.final" in str(e)


def test_scene_warnings_show_the_first_in_full_and_count_the_rest():
    assert scene_warnings_line({"scene": {"source": "a.gltf", "warnings": []}}) == ""
    assert scene_warnings_line({"scene": "a.gltf"}) == ""  # a path tracer run.json names the file only
    one = scene_warnings_line({"scene": {"warnings": ["mesh 0 primitive 1 has mode 1 (points or lines); skipped"]}})
    assert "id='glance-warnings'" in one and "Scene warning:" in one and "mode 1 (points or lines)" in one
    two = scene_warnings_line({"scene": {"warnings": ["a <b>", "c"]}})
    assert "Scene warnings:" in two and "a &lt;b&gt;" in two and "+1 more" in two
