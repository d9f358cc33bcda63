"""vct-cluster's overheads on this machine (docs/performance.md, "Path tracing on a cluster").

Times one reference three ways: `vct pathtrace` in one process, the same job's tasks in one
process without Dask (--scheduler none) and on a LocalCluster of N workers, and the parts of a
task's cost the throughput model needs: the fixed cost of one task (process start, scene load,
BVH), a Dask task's round trip, moving one partial-sums file through Dask, the merge. Prints
ratios; run it on an otherwise idle machine (it prints the load average it saw).

  .venv/bin/python bench/cluster_overheads.py [--size 256] [--spp 128] [--task-spp 16] [--workers 2]
"""
import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "cluster"))

from vct_cluster.executors import DaskExecutor, SerialExecutor  # noqa: E402
from vct_cluster.pathtrace_job import PathtraceJob  # noqa: E402
from vct_cluster.vct_process import find_vct  # noqa: E402


def cpu_seconds():
    """CPU time of this process and of every child waited for (vct runs, LocalCluster workers
    and their vct runs once the cluster is closed): robust where wall time is not on a busy machine."""
    s, c = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return s.ru_utime + s.ru_stime + c.ru_utime + c.ru_stime


def timed(fn):
    start = time.monotonic()
    out = fn()
    return time.monotonic() - start, out


def echo(data):
    return data


def dask_costs(ex, nbytes, repeats=20):
    """Mean round trip of an empty task, and of a task returning nbytes."""
    client = ex.client
    empty, _ = timed(lambda: [client.submit(echo, i, pure=False).result() for i in range(repeats)])
    blob = os.urandom(nbytes)
    moved, _ = timed(lambda: [client.submit(len, blob, pure=False).result() for _ in range(3)])
    back = client.submit(os.urandom, nbytes, pure=False)
    back.result()
    fetch, _ = timed(lambda: [client.submit(os.urandom, nbytes, pure=False).result() for _ in range(3)])
    return empty / repeats, fetch / 3


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--spp", type=int, default=128)
    ap.add_argument("--task-spp", type=int, default=16)
    ap.add_argument("--workers", type=int, default=2)
    a = ap.parse_args()
    vct = find_vct(os.environ.get("VCT_BIN"))
    size = ["--width", str(a.size), "--height", str(a.size)]
    load0 = os.getloadavg()[0]
    with tempfile.TemporaryDirectory(prefix="vct-cluster-bench-") as tmp:
        cpu0 = cpu_seconds()
        one, _ = timed(lambda: subprocess.run([vct, "pathtrace", *size, "--spp", str(a.spp), "--quiet", "--out",
                                               f"{tmp}/one"], check=True, capture_output=True))
        cpu1 = cpu_seconds()
        # A task's fixed cost: process start, scene load, BVH, writing its file (an 8x8 image, 1 spp).
        fixed, _ = timed(lambda: subprocess.run([vct, "pathtrace", "--width", "8", "--height", "8", "--spp", "1",
                                                 "--sample-range", "0:1",
                                                 "--partial", f"{tmp}/fixed.ptpart", "--quiet"],
                                                check=True, capture_output=True))
        args = size + ["--spp", str(a.spp)]
        cpu_s0 = cpu_seconds()
        serial, r_serial = timed(lambda: PathtraceJob(vct, args, a.spp, a.task_spp, f"{tmp}/none").run(
            SerialExecutor(), progress_enabled=False))
        cpu2 = cpu_seconds()
        start_cluster, ex = timed(lambda: DaskExecutor(f"local:{a.workers}"))
        try:
            dask_t, r_dask = timed(lambda: PathtraceJob(vct, args, a.spp, a.task_spp, f"{tmp}/dask").run(
                ex, progress_enabled=False))
        finally:
            ex.close()
        time.sleep(1.0)  # the workers' exit is waited for asynchronously
        cpu3 = cpu_seconds()
        part_bytes = r_dask["bytes"] // r_dask["tasks"]
        ex = DaskExecutor(f"local:{a.workers}")  # the micro costs on a cluster of their own
        try:
            empty_task, fetch = dask_costs(ex, part_bytes)
        finally:
            ex.close()
        same = Path(f"{tmp}/none/pt_checkpoint.bin").read_bytes() == Path(f"{tmp}/dask/pt_checkpoint.bin").read_bytes()
    load1 = os.getloadavg()[0]
    tasks = r_dask["tasks"]
    print(json.dumps({
        "image": f"{a.size}x{a.size}", "spp": a.spp, "task_spp": a.task_spp, "tasks": tasks, "workers": a.workers,
        "cores": len(os.sched_getaffinity(0)), "load_average_before_after": [round(load0, 2), round(load1, 2)],
        "one_process_s": round(one, 2), "serial_tasks_s": round(serial, 2), "dask_s": round(dask_t, 2),
        "cluster_start_s": round(start_cluster, 2),
        "ratio_serial_tasks_vs_one_process": round(serial / one, 3),
        "ratio_dask_vs_one_process": round(dask_t / one, 3),
        "ratio_dask_with_cluster_start_vs_one_process": round((dask_t + start_cluster) / one, 3),
        "cpu_one_process_s": round(cpu1 - cpu0, 2),
        "cpu_ratio_serial_tasks_vs_one_process": round((cpu2 - cpu_s0) / (cpu1 - cpu0), 3),
        "cpu_ratio_dask_vs_one_process": round((cpu3 - cpu2) / (cpu1 - cpu0), 3),
        "fixed_cost_per_task_s": round(fixed, 3), "merge_s": round(r_dask["merge_s"], 3),
        "dask_empty_task_round_trip_s": round(empty_task, 4), "partial_bytes": part_bytes,
        "dask_fetch_one_partial_s": round(fetch, 4), "dask_equals_serial_bytes": same}, indent=1))


if __name__ == "__main__":
    main()
