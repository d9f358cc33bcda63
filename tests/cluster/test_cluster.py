"""vct-cluster on a LocalCluster of 2 worker processes (docs/cluster.md): the distributed path
tracer's bytes equal the one-machine run's, also with a worker killed mid-task or the client
killed and rerun; bad input fails with its one line; a sweep of 2 scenes x 2 grids gathers the
table of the single-machine sweeps. 32x32 images, few spp: ~25 CPU-seconds in all (63-109 s wall
measured at load average 11-17 on 2 cores; a LocalCluster start is ~3-7 s of it)."""
import json
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

pytest.importorskip("distributed")

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "cluster"))

from vct_cluster.errors import VctInputError  # noqa: E402
from vct_cluster.executors import DaskExecutor, SerialExecutor  # noqa: E402
from vct_cluster.pathtrace_job import PathtraceJob, render_range  # noqa: E402
from vct_cluster.sweep_job import run_sweep_job  # noqa: E402
from vct_cluster.vct_process import find_vct  # noqa: E402

VCT = find_vct(os.environ.get("VCT_BIN"))
SCENES = ROOT / "scenes"
SMALL = ["--width", "32", "--height", "32"]
OUTPUTS = ["pt_checkpoint.bin"] + [f"pt_{a}{v}.png" for a in ("full", "direct", "emission", "indirect_diffuse",
                                                               "indirect_specular", "particles") for v in ("", "_var")]


@pytest.fixture(scope="module")
def cluster():
    ex = DaskExecutor("local:2")
    yield ex
    ex.close()


def outputs(d):
    return {f: (Path(d) / f).read_bytes() for f in OUTPUTS}


def pathtrace(executor, out, spp, task_spp, scene=None):
    args = ([str(scene)] if scene else []) + SMALL + ["--spp", str(spp)]
    return PathtraceJob(VCT, args, spp, task_spp, str(out)).run(executor, progress_enabled=False)


class ReversedSerial(SerialExecutor):
    """Tasks finish in the opposite order: the merge must not care."""

    def run(self, tasks, on_done):
        super().run(list(reversed(tasks)), on_done)


SPP, TASK_SPP = 16, 4  # four tasks


@pytest.fixture(scope="module")
def one_machine(tmp_path_factory):
    """The same job on one machine, its tasks run in this process in reverse order."""
    out = tmp_path_factory.mktemp("one_machine")
    pathtrace(ReversedSerial(), out, SPP, TASK_SPP)
    return outputs(out)


def test_distributed_pathtrace_equals_one_machine(cluster, one_machine, tmp_path):
    pathtrace(cluster, tmp_path / "dask", SPP, TASK_SPP)
    assert outputs(tmp_path / "dask") == one_machine
    run = json.loads((tmp_path / "dask" / "run.json").read_text())["pathtrace"]
    assert run["spp"] == SPP and [(t["first"], t["end"]) for t in run["tasks"]] == [(0, 4), (4, 8), (8, 12), (12, 16)]
    assert all(t["host"] and t["seconds"] > 0 for t in run["tasks"])
    # One task holding every sample is `vct pathtrace` itself, byte for byte.
    pathtrace(cluster, tmp_path / "one_task", 6, 6)
    subprocess.run([VCT, "pathtrace"] + SMALL + ["--spp", "6", "--quiet", "--out", str(tmp_path / "plain")],
                   check=True, capture_output=True)
    assert outputs(tmp_path / "one_task") == outputs(tmp_path / "plain")


def _children(pid):
    kids = []
    for p in Path("/proc").iterdir():
        if p.name.isdigit():
            try:
                stat = (p / "stat").read_text()
                cmd = (p / "cmdline").read_bytes().split(b"\0")
            except OSError:
                continue
            if int(stat.rsplit(")", 1)[1].split()[1]) == pid and b"--sample-range" in cmd:
                kids.append(int(p.name))
    return kids


def _running(pid):
    """Alive and not a zombie (an init that reaps slowly leaves the entry a while)."""
    try:
        return (Path("/proc") / str(pid) / "stat").read_text().rsplit(")", 1)[1].split()[0] != "Z"
    except OSError:
        return False


def _kill_a_worker_mid_task(workers, killed):
    deadline = time.monotonic() + 60
    while time.monotonic() < deadline and not killed:
        for w in workers:
            kids = _children(w)
            if kids:
                os.kill(w, signal.SIGKILL)
                killed.append((w, kids[0]))
                return
        time.sleep(0.005)


def test_worker_killed_mid_task_changes_nothing(cluster, one_machine, tmp_path):
    workers = list(cluster.client.run(os.getpid).values())
    killed = []
    watcher = threading.Thread(target=_kill_a_worker_mid_task, args=(workers, killed))
    watcher.start()
    pathtrace(cluster, tmp_path / "dask", SPP, TASK_SPP)
    watcher.join()
    assert killed, "no worker was caught running vct"
    time.sleep(0.2)
    assert not _running(killed[0][1]), "the killed worker's vct kept running"
    assert outputs(tmp_path / "dask") == one_machine


def test_client_killed_rerun_reuses_finished_tasks(one_machine, tmp_path):
    out = tmp_path / "run"
    cmd = [sys.executable, "-m", "vct_cluster", "pathtrace", *SMALL, "--spp", str(SPP), "--task-spp", str(TASK_SPP),
           "--scheduler", "none", "--vct", VCT, "--quiet", "--out", str(out)]
    env = dict(os.environ, PYTHONPATH=str(ROOT / "cluster"))
    client = subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    while client.poll() is None and not list((out / "pt_tasks").glob("*.ptpart")):
        time.sleep(0.005)
    client.kill()
    client.wait()
    finished = len(list((out / "pt_tasks").glob("*.ptpart")))
    assert 1 <= finished < 4
    subprocess.run(cmd, env=env, check=True, capture_output=True)
    assert json.loads((out / "cluster.json").read_text())["reused"] == finished
    assert outputs(out) == one_machine


def test_bad_input_fails_with_its_line(cluster, tmp_path):
    missing = str(tmp_path / "missing.gltf")
    with pytest.raises(VctInputError, match="missing.gltf: file not found"):  # raised on a worker
        cluster.run([("bad", render_range, (VCT, [missing] + SMALL, 0, 2, 1))], lambda k, r: [])
    r = subprocess.run([sys.executable, "-m", "vct_cluster", "pathtrace", missing, "--spp", "4", "--scheduler",
                        "none", "--vct", VCT, "--out", str(tmp_path / "out")],
                       env=dict(os.environ, PYTHONPATH=str(ROOT / "cluster")), capture_output=True, text=True)
    assert r.returncode == 2
    assert r.stderr.strip().splitlines() == [f"vct-cluster: {missing}: file not found"]
    assert not (tmp_path / "out").exists()


def _without_times(x):
    if isinstance(x, dict):
        return {k: _without_times(v) for k, v in x.items() if not (k == "ms" or k.endswith("_ms"))}
    if isinstance(x, list):
        return [_without_times(v) for v in x]
    return x


def test_sweep_gathers_the_single_machine_table(cluster, tmp_path):
    scenes = [str(SCENES / "cornell_box.gltf"), str(SCENES / "plane_spot.gltf")]
    args = SMALL + ["--spp", "4", "--grid", "32"]
    code = run_sweep_job(VCT, scenes, args, ["grid=16,32"], str(tmp_path / "dask"), cluster, report=False,
                         progress_enabled=False)
    assert code == 0
    for s in scenes:
        one = tmp_path / ("one_" + Path(s).stem)
        subprocess.run([VCT, "validate", s] + args + ["--sweep", "grid=16,32", "--no-report", "--out", str(one)],
                       check=True, capture_output=True)
        want = json.loads((one / "run.json").read_text())["sweeps"]
        got = json.loads((tmp_path / "dask" / Path(s).stem / "run.json").read_text())["sweeps"]
        assert [r["value"] for r in got[0]["rows"]] == ["16", "32"]
        assert all(len(r["bias"]) > 0 for r in got[0]["rows"])
        assert _without_times(got) == _without_times(want)
