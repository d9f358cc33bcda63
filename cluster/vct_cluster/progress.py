"""One line on a terminal: tasks done/total, samples per second, ETA (nothing when piped)."""
import sys
import time


class Progress:
    def __init__(self, label, total_tasks, total_samples, enabled=None, unit="samples"):
        self.label = label
        self.unit = unit
        self.total_tasks = total_tasks
        self.total_samples = total_samples
        self.done_tasks = 0
        self.done_samples = 0
        self.start = time.monotonic()
        self.enabled = sys.stderr.isatty() if enabled is None else enabled

    def task_done(self, samples, reused=False):
        """samples: pixel samples the task holds; reused tasks count as done but not as speed."""
        self.done_tasks += 1
        if reused:
            self.total_samples -= samples
        else:
            self.done_samples += samples
        self.show()

    def line(self):
        elapsed = max(time.monotonic() - self.start, 1e-9)
        rate = self.done_samples / elapsed
        left = self.total_samples - self.done_samples
        eta = f"{left / rate:.0f} s" if rate > 0 else "?"
        return (f"{self.label}: tasks {self.done_tasks}/{self.total_tasks}, "
                f"{rate:.3g} {self.unit}/s, ETA {eta}")

    def show(self):
        if self.enabled:
            sys.stderr.write("\r" + self.line() + "\033[K")
            sys.stderr.flush()

    def finish(self):
        if self.enabled:
            sys.stderr.write("\r\033[K")
            sys.stderr.flush()
