"""Every regression case the hunt saved (scenes/regressions/*/) is complete: a scene that passes
the Khronos glTF validator, a settings file validate reads, and a case.json naming its seed, the
verdict line, the first failing stage and a cause field (docs/compare.md, "False-alarm hunt")."""
import glob
import json
import os
import subprocess

import pytest

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
CASES = sorted(glob.glob(os.path.join(ROOT, "scenes", "regressions", "*", "case.json")))


@pytest.mark.parametrize("case_path", CASES, ids=[os.path.basename(os.path.dirname(c)) for c in CASES])
def test_case_is_complete(case_path):
    folder = os.path.dirname(case_path)
    case = json.load(open(case_path))
    for key in ("seed", "size_class", "verdict_line", "first_failing_stage", "note", "minimal", "cause"):
        assert key in case, key
    assert case["first_failing_stage"] and "fail" in case["verdict_line"]
    settings = json.load(open(os.path.join(folder, "settings.json")))
    assert settings["vct"]["width"] == case["minimal"]["width"] and settings["vct"]["grid"] == case["minimal"]["grid"]
    proc = subprocess.run([os.path.join(ROOT, "scenes", "validate_scenes.sh"), os.path.join(folder, "scene.gltf")],
                          capture_output=True, text=True)
    if proc.returncode == 77:
        pytest.skip("no glTF validator")
    assert proc.returncode == 0 and " 0 errors" in proc.stdout, proc.stdout


def test_there_are_cases_to_check():
    assert CASES, "scenes/regressions holds no case"
