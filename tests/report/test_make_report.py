"""report/make_report.py on run.json shapes other than validate's."""
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "report"))

from make_report import backend_timings  # noqa: E402


def test_scalar_timings_of_other_commands_are_not_stages():
    # vct metamorphic writes {"total": 812.5, ...}: the performance section crashed on it
    j = {"timings_ms": {"total": 812.5, "ref": {"inject": 3.0}, "gl": {"inject": 1.5}}}
    assert backend_timings(j) == {"ref": {"inject": 3.0}, "gl": {"inject": 1.5}}
    assert backend_timings({"timings_ms": {"total": 1.0}}) == {}
    assert backend_timings({}) == {}


# ---------------------------------------------------------------- FLIP is opt-in (issue 16)
import json  # noqa: E402

import make_report  # noqa: E402
from vct_report.runio import Run  # noqa: E402


def run_dir(tmp_path, report_options=None):
    """A run directory holding only run.json with two bias rows (no images: no FLIP can run)."""
    row = {"available": True, "vct": "image.direct", "pt": "pt_direct", "component": "direct", "rel_mse": 0.1}
    j = {"bias": {"ref": [row, dict(row, vct="image.final", pt="pt_full", component="full")]}}
    if report_options is not None:
        j["report_options"] = report_options
    (tmp_path / "run.json").write_text(json.dumps(j))
    return Run(str(tmp_path))


def test_flip_mode_is_none_unless_the_run_or_the_environment_asks(tmp_path, monkeypatch):
    monkeypatch.delenv("VCT_REPORT_FLIP", raising=False)
    assert make_report.flip_mode(run_dir(tmp_path)) == "none"
    assert make_report.flip_mode(run_dir(tmp_path, {"flip": "full"})) == "full"
    assert make_report.flip_mode(run_dir(tmp_path, {"flip": "bogus"})) == "none"
    monkeypatch.setenv("VCT_REPORT_FLIP", "all")
    assert make_report.flip_mode(run_dir(tmp_path, {"flip": "full"})) == "all"


def test_flip_components_per_mode():
    direct, full = {"component": "direct"}, {"component": "full"}
    assert [make_report.flip_components("none", r) for r in (direct, full)] == [False, False]
    assert [make_report.flip_components("full", r) for r in (direct, full)] == [False, True]
    assert [make_report.flip_components("all", r) for r in (direct, full)] == [True, True]


def test_the_bias_section_says_flip_was_not_computed_and_how_to_get_it(tmp_path, monkeypatch):
    monkeypatch.delenv("VCT_REPORT_FLIP", raising=False)
    html = make_report.bias_section(make_report.Page(run_dir(tmp_path)))
    assert "FLIP: not computed: FLIP is opt-in" in html
    assert "vct validate --flip full" in html and "VCT_REPORT_FLIP=full" in html
    assert html.count("<td class=num>not computed</td>") == 2  # both rows' FLIP cells


def test_with_flip_full_only_the_full_row_is_asked_for(tmp_path, monkeypatch):
    monkeypatch.delenv("VCT_REPORT_FLIP", raising=False)
    html = make_report.bias_section(make_report.Page(run_dir(tmp_path, {"flip": "full"})))
    assert "HDR-FLIP of the full image against the path tracer" in html
    assert "not computed: FLIP is opt-in" not in html
    # direct was not asked for; full was, but this run has no images to compute it from
    assert html.count("<td class=num>not computed</td>") == 1
    assert html.count("<td class=num>n/a</td>") == 1


def test_part_times_keep_cpu_and_take_nested_flip_out_of_its_part(tmp_path):
    from vct_report.part_times import PartTimes, cpu_ms

    t = PartTimes()

    def spin():
        start = cpu_ms()
        while cpu_ms() - start < 20:  # at least 20 ms of CPU, however loaded the machine
            pass
        t.nested("FLIP", 5.0, 7.0)

    t.run("bias", spin)
    flip, bias = t.parts  # FLIP is listed when it ends, inside the part that asked for it
    assert flip == {"name": "FLIP", "ms": 5.0, "cpu_ms": 7.0}
    assert bias["name"] == "bias" and bias["cpu_ms"] >= 20 - 7.0
    t.write(str(tmp_path))
    written = json.loads((tmp_path / "part_times.json").read_text())
    assert [p["name"] for p in written["parts"]] == ["FLIP", "bias"]
    assert written["parts"][0]["cpu_ms"] == 7.0
