"""Wall and CPU time of each part of the report, written to REPORT_DIR/part_times.json so
`vct validate` can list them among its phases (app/phase_times.h). Parts do not overlap: time spent
in FLIP is taken out of the part that asked for it and listed as its own part. CPU time is this
process's plus its finished children's (FLIP runs in child processes), so on a shared machine a
part's work can be told from its waiting (docs/performance.md, "Where validate's time goes")."""
import json
import os
import resource
import time


def cpu_ms():
    """CPU time of this process and of its waited-for children, all threads, in ms."""
    c = resource.getrusage(resource.RUSAGE_CHILDREN)
    return 1000 * (time.process_time() + c.ru_utime + c.ru_stime)


class PartTimes:
    def __init__(self):
        self.parts = []
        self._nested = (0.0, 0.0)  # FLIP wall and CPU time inside the part now running

    def run(self, name, fn, *args):
        """fn(*args), timed as part `name` (less any time added by nested())."""
        t0, c0, self._nested = time.perf_counter(), cpu_ms(), (0.0, 0.0)
        try:
            return fn(*args)
        finally:
            self.parts.append({"name": name, "ms": 1000 * (time.perf_counter() - t0) - self._nested[0],
                               "cpu_ms": cpu_ms() - c0 - self._nested[1]})

    def nested(self, name, ms, cpu=0.0):
        """A sub-part (FLIP) already counted: listed on its own, taken out of the enclosing part."""
        self._nested = (self._nested[0] + ms, self._nested[1] + cpu)
        for p in self.parts:
            if p["name"] == name:
                p["ms"] += ms
                p["cpu_ms"] += cpu
                return
        self.parts.append({"name": name, "ms": ms, "cpu_ms": cpu})

    def write(self, out_dir):
        path = os.path.join(out_dir, "part_times.json")
        tmp = path + ".tmp"
        with open(tmp, "w") as f:
            json.dump({"parts": self.parts, "total_ms": sum(p["ms"] for p in self.parts)}, f, indent=1)
        os.replace(tmp, path)


TIMES = PartTimes()
