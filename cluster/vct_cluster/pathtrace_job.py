"""`vct-cluster pathtrace`: fixed sample ranges as tasks, partial sums merged in range order.

The ranges depend only on --spp and --task-spp, each task's sums are those samples accumulated
from zero (vct pathtrace --sample-range), and `vct pathtrace --merge` adds them in range order:
the result's bytes do not depend on workers, finishing order or retries (docs/cluster.md)."""
import json
import os
import struct
import tempfile
import time
import uuid

from .errors import VctInputError
from .files import read_json, write_bytes_atomically, write_json_atomically
from .progress import Progress
from .vct_process import run_vct

# ref/pt/partial_sums.cpp: magic, scene hash, settings hash, width, height, first, end, values
# per pixel, rays (primary, secondary, shadow, non-finite samples).
HEADER = struct.Struct("<8sQQiiIII4Q")
MAGIC = b"VCTPTPS1"


def read_header(data):
    if len(data) < HEADER.size:
        return None
    f = HEADER.unpack_from(data)
    if f[0] != MAGIC:
        return None
    return {"scene_hash": f[1], "settings_hash": f[2], "width": f[3], "height": f[4], "first": f[5],
            "end": f[6], "rays": {"primary": f[8], "secondary": f[9], "shadow": f[10]}}


def plan_ranges(spp, task_spp):
    """Fixed task boundaries: [0, k), [k, 2k), ... up to spp (the last one may be shorter)."""
    return [(a, min(a + task_spp, spp)) for a in range(0, spp, task_spp)]


def render_range(vct, args, first, end, threads):
    """One task, on a worker: samples first..end-1 into a partial-sums file, returned as bytes
    (no file system shared with the client needed)."""
    with tempfile.TemporaryDirectory(prefix="vct-pt-") as tmp:
        part = os.path.join(tmp, "range.ptpart")
        _, host, seconds, _ = run_vct(vct, ["pathtrace"] + args + [
            "--sample-range", f"{first}:{end}", "--partial", part, "--quiet"], threads)
        with open(part, "rb") as f:
            data = f.read()
    return {"data": data, "host": host, "seconds": seconds}


class PathtraceJob:
    def __init__(self, vct, args, spp, task_spp, out):
        self.vct, self.args, self.spp, self.out = vct, args, spp, out
        self.tasks_dir = os.path.join(out, "pt_tasks")
        self.ranges = plan_ranges(spp, task_spp)
        # Loads the scene and checks the settings here, before any task: bad input fails at once.
        stdout, _, _, _ = run_vct(vct, ["pathtrace"] + args + ["--job-key"])
        self.key = json.loads(stdout)

    def _name(self, first, end):
        return os.path.join(self.tasks_dir, f"samples_{first:09d}_{end:09d}")

    def _matches(self, header, first, end):
        k = self.key
        return (header is not None and header["first"] == first and header["end"] == end
                and all(header[f] == k[f] for f in ("scene_hash", "settings_hash", "width", "height")))

    def _reusable(self, first, end):
        try:
            with open(self._name(first, end) + ".ptpart", "rb") as f:
                return self._matches(read_header(f.read(HEADER.size)), first, end)
        except OSError:
            return False

    def _drop_stale_files(self):
        """Partial sums of other ranges (another --task-spp) would overlap in the merge."""
        wanted = {os.path.basename(self._name(a, b)) + ".ptpart" for a, b in self.ranges}
        for f in os.listdir(self.tasks_dir):
            if f.endswith(".ptpart") and f not in wanted:
                os.remove(os.path.join(self.tasks_dir, f))

    def _store(self, first, end, result, pixels):
        header = read_header(result["data"])
        if not self._matches(header, first, end):
            raise VctInputError(f"samples {first}..{end}: the worker's vct or scene differs from the client's "
                                f"(scene/settings hash mismatch: same files and build on every machine?)")
        name = self._name(first, end)
        write_bytes_atomically(name + ".ptpart", result["data"])
        write_json_atomically(name + ".json", {"first": first, "end": end, "host": result["host"],
                                               "seconds": round(result["seconds"], 4),
                                               "samples": (end - first) * pixels,
                                               "bytes": len(result["data"])})

    def run(self, executor, progress_enabled=None):
        os.makedirs(self.tasks_dir, exist_ok=True)
        self._drop_stale_files()
        pixels = self.key["width"] * self.key["height"]
        todo = [(a, b) for a, b in self.ranges if not self._reusable(a, b)]
        reused = len(self.ranges) - len(todo)
        bar = Progress("vct-cluster pathtrace", len(self.ranges), self.spp * pixels, progress_enabled)
        for a, b in set(self.ranges) - set(todo):
            bar.task_done((b - a) * pixels, reused=True)
        bar.show()
        # Keys unique to this run: a scheduler must not hand back a result it still holds from an
        # earlier job (another --out may want the task rendered again).
        tag = f"{self.key['scene_hash']:x}-{self.key['settings_hash']:x}-{uuid.uuid4().hex[:8]}"
        tasks = [(f"vct-pt-{tag}-{a}-{b}", render_range, (self.vct, self.args, a, b, executor.threads_per_task))
                 for a, b in todo]
        by_key = {t[0]: t[2][2:4] for t in tasks}
        start = time.monotonic()

        def done(key, result):
            a, b = by_key[key]
            self._store(a, b, result, pixels)
            bar.task_done((b - a) * pixels)

        executor.run(tasks, done)
        bar.finish()
        render_wall = time.monotonic() - start
        return self._merge(reused, render_wall)

    def _merge(self, reused, render_wall):
        table = [read_json(self._name(a, b) + ".json", {"first": a, "end": b}) for a, b in self.ranges]
        write_json_atomically(os.path.join(self.tasks_dir, "tasks.json"), table)
        start = time.monotonic()
        run_vct(self.vct, ["pathtrace"] + self.args + ["--merge", self.tasks_dir, "--out", self.out, "--quiet"])
        merge_s = time.monotonic() - start
        return {"tasks": len(self.ranges), "reused": reused, "render_wall_s": render_wall, "merge_s": merge_s,
                "task_seconds": sum(t.get("seconds", 0.0) for t in table),
                "bytes": sum(t.get("bytes", 0) for t in table)}
