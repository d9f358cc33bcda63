"""hunt.py's --time-limit: a validate run past it is stopped, its whole process group with it (the
GL runner validate starts), and recorded as "timeout", not as a verdict of the judge."""
import argparse
import os
import stat
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "tools", "scenegen"))
import hunt  # noqa: E402


def fake_vct(tmp_path, body):
    path = tmp_path / "vct"
    path.write_text("#!/bin/sh\n" + body)
    path.chmod(path.stat().st_mode | stat.S_IXUSR)
    return str(path)


def args_for(vct, limit):
    return argparse.Namespace(vct=vct, threads=1, time_limit=limit, keep_runs=False)


def test_a_run_past_the_limit_is_a_timeout_and_its_child_is_gone(tmp_path):
    pid_file = tmp_path / "child.pid"
    # A validate that starts a child (as it starts the GL runner) and never ends.
    vct = fake_vct(tmp_path, "sleep 600 &\necho $! > %s\necho started\nwait\n" % pid_file)
    start = time.time()
    r = hunt.run_validate(args_for(vct, 1.0), str(tmp_path))
    assert r["verdict"] == "timeout" and r["rc"] is None
    assert time.time() - start < 30
    child = int(pid_file.read_text())
    time.sleep(0.2)
    state = subprocess.run(["ps", "-o", "stat=", "-p", str(child)], capture_output=True, text=True).stdout.strip()
    assert state in ("", "Z"), state  # killed (a zombie at most, until init reaps it)


def test_a_run_within_the_limit_keeps_its_exit_code(tmp_path):
    vct = fake_vct(tmp_path, "echo 'GPU (gl) vs CPU reference: fail  (first failing stage: x)'\nexit 1\n")
    r = hunt.run_validate(args_for(vct, 30.0), str(tmp_path))
    assert r["verdict"] == "fail" and r["rc"] == 1
    assert r["line"].startswith("GPU (gl) vs CPU reference: fail")
    # No limit (0) behaves the same.
    assert hunt.run_validate(args_for(vct, 0), str(tmp_path))["verdict"] == "fail"
