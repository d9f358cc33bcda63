"""Wall time of each part of the report, written to REPORT_DIR/part_times.json so `vct validate`
can list them among its phases (app/phase_times.h). Parts do not overlap: time spent in FLIP is
taken out of the part that asked for it and listed as its own part."""
import json
import os
import time


class PartTimes:
    def __init__(self):
        self.parts = []
        self._nested = 0.0  # FLIP time inside the part now running

    def run(self, name, fn, *args):
        """fn(*args), timed as part `name` (less any time added by nested())."""
        t0, self._nested = time.perf_counter(), 0.0
        try:
            return fn(*args)
        finally:
            self.parts.append({"name": name, "ms": 1000 * (time.perf_counter() - t0) - self._nested})

    def nested(self, name, ms):
        """A sub-part (FLIP) already counted: listed on its own, taken out of the enclosing part."""
        self._nested += ms
        for p in self.parts:
            if p["name"] == name:
                p["ms"] += ms
                return
        self.parts.append({"name": name, "ms": ms})

    def write(self, out_dir):
        path = os.path.join(out_dir, "part_times.json")
        tmp = path + ".tmp"
        with open(tmp, "w") as f:
            json.dump({"parts": self.parts, "total_ms": sum(p["ms"] for p in self.parts)}, f, indent=1)
        os.replace(tmp, path)


TIMES = PartTimes()
