"""vct-cluster pathtrace|sweep: the command line (docs/cluster.md). Exit codes as vct's: 0 done,
1 a task failed or a validate comparison failed, 2 bad input (one line naming what is wrong)."""
import argparse
import os
import sys
import time
from pathlib import Path

from .errors import VctInputError, VctTaskError
from .executors import check_scheduler_spec, make_executor
from .files import write_json_atomically
from .pathtrace_job import PathtraceJob
from .sweep_job import check_sweep_inputs, run_sweep_job
from .vct_process import find_vct


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit 2, as vct's own usage errors
        sys.stderr.write(f"vct-cluster: {message}\n")
        sys.exit(2)


def _common(p):
    p.add_argument("--scheduler", default="local:2",
                   help="none (this process, tasks in order), local:N (LocalCluster of N worker processes) "
                        "or tcp://HOST:PORT (a running Dask scheduler); default local:2")
    p.add_argument("--out", required=True, help="output directory (rerun the command to reuse finished tasks)")
    p.add_argument("--vct", help="vct binary (default: $VCT_BIN, else build/bin/vct of this checkout); "
                                 "the same path must work on every worker")
    p.add_argument("--width", type=int)
    p.add_argument("--height", type=int)
    p.add_argument("--spp", type=int)
    p.add_argument("--config", help="settings JSON (vct --config)")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="any settings-table key")
    p.add_argument("--quiet", action="store_true", help="no progress line")


def _parser():
    top = _Parser(prog="vct-cluster", description=__doc__)
    sub = top.add_subparsers(dest="command", required=True, parser_class=_Parser)
    sub.add_parser("scheduler", help="a Dask scheduler (dask scheduler's options) that knows vct-cluster's tasks")
    sub.add_parser("worker", help="a Dask worker (dask worker SCHEDULER and its options) that runs them")
    pt = sub.add_parser("pathtrace", help="a path-traced reference split into sample ranges")
    pt.add_argument("scene", nargs="?", default="", help="glTF scene (default: the built-in Cornell box)")
    _common(pt)
    pt.add_argument("--task-spp", type=int, default=16,
                    help="samples per task: fixes the task boundaries, and so the result's bytes (default 16)")
    pt.add_argument("--max-depth", type=int)
    pt.add_argument("--light-model", choices=["gltf", "seed"])
    sw = sub.add_parser("sweep", help="vct validate --sweep over scenes, one task per row")
    sw.add_argument("scenes", nargs="*", default=[""], help="glTF scenes (default: the built-in Cornell box)")
    _common(sw)
    sw.add_argument("--sweep", action="append", required=True, metavar="KEY=V1,V2,...")
    sw.add_argument("--grid", type=int)
    sw.add_argument("--no-report", action="store_true")
    return top


def _vct_args(a):
    args = []
    for flag in ("width", "height", "spp", "grid", "max_depth", "light_model"):
        v = getattr(a, flag, None)
        if v is not None:
            args += ["--" + flag.replace("_", "-"), str(v)]
    if a.config:
        args += ["--config", os.path.abspath(a.config)]
    for kv in a.set:
        args += ["--set", kv]
    return args


def _pathtrace(a, vct, start_executor):
    if a.spp is None or a.spp < 1 or a.task_spp < 1:
        raise VctInputError("pathtrace: --spp N and --task-spp K must be at least 1")
    scene = [os.path.abspath(a.scene)] if a.scene else []
    job = PathtraceJob(vct, scene + _vct_args(a), a.spp, a.task_spp, a.out)  # checks the input
    executor = start_executor()
    start = time.monotonic()
    r = job.run(executor, False if a.quiet else None)
    r.update(wall_s=time.monotonic() - start, scheduler=a.scheduler, workers=executor.workers,
             threads_per_task=executor.threads_per_task, task_spp=a.task_spp, spp=a.spp)
    write_json_atomically(os.path.join(a.out, "cluster.json"), r)
    print(f"vct-cluster pathtrace: {a.spp} spp in {r['tasks']} tasks ({r['reused']} reused) on {executor.workers} "
          f"workers, {r['wall_s']:.2f} s (tasks {r['task_seconds']:.2f} s summed, merge {r['merge_s']:.2f} s) "
          f"-> {a.out}")
    return 0


def _sweep(a, vct, start_executor):
    check_sweep_inputs(vct, a.scenes, _vct_args(a), a.sweep)
    executor = start_executor()
    code = run_sweep_job(vct, a.scenes, _vct_args(a), a.sweep, a.out, executor, report=not a.no_report,
                         progress_enabled=False if a.quiet else None)
    print(f"vct-cluster sweep: {len(a.scenes)} scene(s) x {', '.join(a.sweep)} -> {a.out}")
    return code


def _serve(role, argv):
    """`vct-cluster scheduler|worker ...`: Dask's own scheduler or worker, with this package on
    the Python path of it and of its worker processes (they unpickle the tasks' functions)."""
    here = str(Path(__file__).resolve().parents[1])
    os.environ["PYTHONPATH"] = here + (os.pathsep + os.environ["PYTHONPATH"] if os.environ.get("PYTHONPATH") else "")
    module = {"scheduler": "distributed.cli.dask_scheduler", "worker": "distributed.cli.dask_worker"}[role]
    os.execv(sys.executable, [sys.executable, "-m", module] + list(argv))


def _one_line(e):
    first = (str(e).strip().splitlines() or [""])[0].split(". ")[0].rstrip(".")
    if "deserializ" in first:  # a scheduler or worker that cannot import this package
        first += " (start them with `vct-cluster scheduler` / `vct-cluster worker`, docs/cluster.md)"
    return f"{type(e).__name__}: {first}"


def main(argv=None):
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv and argv[0] in ("scheduler", "worker"):
        _serve(argv[0], argv[1:])
    a = _parser().parse_args(argv)
    started = []

    def start_executor():  # after the input is checked: a LocalCluster takes seconds to start
        started.append(make_executor(a.scheduler))
        return started[-1]

    try:
        check_scheduler_spec(a.scheduler)
        vct = find_vct(a.vct)
        return (_pathtrace if a.command == "pathtrace" else _sweep)(a, vct, start_executor)
    except VctInputError as e:
        sys.stderr.write(f"vct-cluster: {e}\n")
        return 2
    except VctTaskError as e:
        sys.stderr.write(f"vct-cluster: {e}\n")
        return 1
    except KeyboardInterrupt:
        sys.stderr.write("vct-cluster: interrupted; finished tasks are kept, rerun the command to go on\n")
        return 1
    except Exception as e:  # a Dask or environment failure: one line, no traceback
        sys.stderr.write(f"vct-cluster: {_one_line(e)}; finished tasks are kept, rerun to go on\n")
        return 1
    finally:
        for executor in started:
            executor.close()
