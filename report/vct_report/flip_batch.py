"""All of a report's FLIP maps at once: each pair still runs in its own child process (see
flip_one.py: flip-evaluator's core may call exit()), but up to one per core at a time, so the
report's largest part runs on every core instead of one (docs/performance.md)."""
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))


def workers():
    """$VCT_REPORT_JOBS, else the cores this process may use."""
    try:
        return max(1, int(os.environ.get("VCT_REPORT_JOBS", "0")) or len(os.sched_getaffinity(0)))
    except (ValueError, AttributeError):
        return os.cpu_count() or 1


def run_all(jobs, timeout=180):
    """jobs: [(pt_exr, vct_exr, out_png)]. Returns {out_png: mean FLIP or None}."""
    results, pending, running = {}, list(jobs), []
    limit = workers()
    while pending or running:
        while pending and len(running) < limit:
            ref, test, png = pending.pop(0)
            proc = subprocess.Popen([sys.executable, os.path.join(HERE, "flip_one.py"), ref, test, png],
                                    stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
            running.append((proc, png, time.monotonic()))
        still = []
        for proc, png, start in running:
            if proc.poll() is None and time.monotonic() - start < timeout:
                still.append((proc, png, start))
                continue
            if proc.poll() is None:
                proc.kill()
            out = proc.communicate()[0] or ""
            try:
                results[png] = float(out.strip().splitlines()[-1]) if proc.returncode == 0 and out.strip() else None
            except (ValueError, IndexError):
                results[png] = None
        running = still
        if running:
            time.sleep(0.01)
    return results
