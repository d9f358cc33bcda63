"""`vct-cluster sweep`: per scene one base task (`vct validate` without sweeps: GL, CPU reference,
path tracer, comparisons) and then one task per sweep row (`vct validate --sweep KEY=V
--sweep-rows` against the base run's path tracer images); the client gathers the rows in
`--sweep` and value order into the base run's run.json "sweeps" and builds the report, so each
scene's run directory is what `vct validate SCENE --sweep ...` writes (docs/cluster.md)."""
import io
import json
import os
import shutil
import subprocess
import sys
import tarfile
import tempfile
import uuid
from pathlib import Path

from .errors import VctInputError
from .files import read_json, write_json_atomically
from .progress import Progress
from .vct_process import run_vct

# vct validate: 0 passed, 1 a GPU stage failed (still a complete run with its sweep rows).
_VALIDATE_DONE = (0, 1)


def _tar(root, names=None):
    buf = io.BytesIO()
    with tarfile.open(fileobj=buf, mode="w") as t:
        for name in names if names is not None else sorted(os.listdir(root)):
            t.add(os.path.join(root, name), arcname=name)
    return buf.getvalue()


def _untar(data, dest):
    with tarfile.open(fileobj=io.BytesIO(data)) as t:
        t.extractall(dest, filter="data")


def validate_base(vct, scene_args, args, threads):
    """On a worker: the base validate run (no sweeps, no report), returned as a tar."""
    with tempfile.TemporaryDirectory(prefix="vct-sweep-") as tmp:
        run = os.path.join(tmp, "run")
        _, host, seconds, code = run_vct(vct, ["validate"] + scene_args + args + ["--no-report", "--out", run],
                                         threads, ok_codes=_VALIDATE_DONE)
        return {"data": _tar(run), "host": host, "seconds": seconds, "exit_code": code}


def sweep_row(vct, scene_args, args, key, value, base_blob, threads):
    """On a worker: one row, against the base run's path tracer (run.json + pt/*.exr)."""
    with tempfile.TemporaryDirectory(prefix="vct-row-") as tmp:
        base = os.path.join(tmp, "base")
        _untar(base_blob, base)
        rows = os.path.join(tmp, "rows.json")
        _, host, seconds, _ = run_vct(vct, ["validate"] + scene_args + args + [
            "--sweep", f"{key}={value}", "--pt-from", base, "--sweep-rows", rows], threads)
        with open(rows) as f:
            sweep = json.load(f)[0]
        return {"key": sweep["key"], "value": sweep["values"][0], "row": sweep["rows"][0], "host": host,
                "seconds": seconds}


def parse_sweep(spec):
    key, eq, values = spec.partition("=")
    if not eq or not key or not values:
        raise VctInputError(f"--sweep: expected KEY=V1,V2,... (e.g. grid=64,128,256), got '{spec}'")
    return key, values.split(",")


class SceneSweep:
    """One scene's run directory: out/<scene stem>, bookkeeping in its cluster_sweep/."""

    def __init__(self, scene, out, args, sweeps):
        self.scene_args = [os.path.abspath(scene)] if scene else []
        self.dir = os.path.join(out, Path(scene).stem if scene else "default")
        self.state = os.path.join(self.dir, "cluster_sweep")
        self.args = args
        self.sweeps = [parse_sweep(s) for s in sweeps]
        self.signature = {"scene": self.scene_args, "args": args, "sweeps": sweeps}

    def rows(self):
        return [(i, j, key, v) for i, (key, values) in enumerate(self.sweeps) for j, v in enumerate(values)]

    def row_file(self, i, j):
        return os.path.join(self.state, f"row_{i:03d}_{j:04d}.json")

    def base_done(self):
        """A finished base run of the same command (a rerun after a killed client reuses it)."""
        return (read_json(os.path.join(self.state, "job.json")) == self.signature
                and read_json(os.path.join(self.state, "base.json")) is not None
                and (read_json(os.path.join(self.dir, "run.json")) or {}).get("status") == "complete")

    def reset(self):
        if os.path.isdir(self.dir):
            shutil.rmtree(self.dir)
        os.makedirs(self.state)
        write_json_atomically(os.path.join(self.state, "job.json"), self.signature)

    def store_base(self, result):
        tmp = self.dir + ".incoming"
        shutil.rmtree(tmp, ignore_errors=True)
        _untar(result["data"], tmp)
        os.makedirs(os.path.join(tmp, "cluster_sweep"), exist_ok=True)
        shutil.copy(os.path.join(self.state, "job.json"), os.path.join(tmp, "cluster_sweep", "job.json"))
        shutil.rmtree(self.dir)
        os.replace(tmp, self.dir)
        write_json_atomically(os.path.join(self.state, "base.json"),
                              {k: result[k] for k in ("host", "seconds", "exit_code")})

    def base_blob(self):
        names = ["run.json"] + [os.path.join("pt", f) for f in sorted(os.listdir(os.path.join(self.dir, "pt")))
                                if f.endswith(".exr")]
        return _tar(self.dir, names)

    def gather(self, report):
        """The rows into run.json "sweeps" (validate's layout), then the report."""
        run_json = os.path.join(self.dir, "run.json")
        run = read_json(run_json)
        sweeps = []
        for i, (key, values) in enumerate(self.sweeps):
            got = [read_json(self.row_file(i, j)) for j in range(len(values))]
            sweeps.append({"key": got[0]["key"], "values": [g["value"] for g in got], "rows": [g["row"] for g in got]})
        run["sweeps"] = sweeps
        run["cluster_tasks"] = {"base": read_json(os.path.join(self.state, "base.json")),
                                "rows": [{k: g[k] for k in ("key", "value", "host", "seconds")}
                                         for i, (_, values) in enumerate(self.sweeps)
                                         for g in [read_json(self.row_file(i, j)) for j in range(len(values))]]}
        write_json_atomically(run_json, run)
        if report:
            make_report(self.dir)
        return read_json(os.path.join(self.state, "base.json"))["exit_code"]


def make_report(run_dir):
    script = Path(__file__).resolve().parents[2] / "report" / "make_report.py"
    env = dict(os.environ, VCT_REPORT_FLIP=os.environ.get("VCT_REPORT_FLIP", "none"))
    with open(os.path.join(run_dir, "report.log"), "w") as log:
        subprocess.run([sys.executable, str(script), run_dir], env=env, stdout=log, stderr=log, check=False)


def check_sweep_inputs(vct, scenes, args, sweeps):
    """Bad scenes, settings and sweep values fail here, on the client, before any task."""
    jobs = [SceneSweep(s, "", args, sweeps) for s in scenes]
    if len({j.dir for j in jobs}) != len(jobs):
        raise VctInputError("sweep: two scenes share a file name (their run directories would collide)")
    for j in jobs:
        run_vct(vct, ["validate"] + j.scene_args + args + [a for s in sweeps for a in ("--sweep", s)]
                + ["--check-input"])


def run_sweep_job(vct, scenes, args, sweeps, out, executor, report=True, progress_enabled=None):
    jobs = [SceneSweep(s, out, args, sweeps) for s in scenes]
    run_id = uuid.uuid4().hex[:8]  # task keys unique to this run (see pathtrace_job.py)
    total = sum(1 + len(j.rows()) for j in jobs)
    bar = Progress("vct-cluster sweep", total, total, progress_enabled, unit="tasks")
    tasks = []
    by_key = {}

    def row_tasks(j, idx):
        blob = j.base_blob()  # in each row task's arguments: no shared file system needed
        out_tasks = []
        for i, r, key, value in j.rows():
            if os.path.exists(j.row_file(i, r)):
                bar.task_done(1, reused=True)
                continue
            k = f"vct-row-{idx}-{i}-{r}-{run_id}"
            by_key[k] = ("row", j, (i, r))
            out_tasks.append((k, sweep_row, (vct, j.scene_args, args, key, value, blob, executor.threads_per_task)))
        return out_tasks

    for idx, j in enumerate(jobs):
        os.makedirs(out, exist_ok=True)
        if j.base_done():
            bar.task_done(1, reused=True)
            tasks += row_tasks(j, idx)
        else:
            j.reset()
            k = f"vct-base-{idx}-{run_id}"
            by_key[k] = ("base", j, idx)
            tasks.append((k, validate_base, (vct, j.scene_args, args, executor.threads_per_task)))

    def done(key, result):
        kind, j, where = by_key[key]
        bar.task_done(1)
        if kind == "base":  # its rows can start now
            j.store_base(result)
            return row_tasks(j, where)
        write_json_atomically(j.row_file(*where), result)
        return []

    executor.run(tasks, done)
    bar.finish()
    return max(j.gather(report) for j in jobs)
