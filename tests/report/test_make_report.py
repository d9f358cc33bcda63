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
