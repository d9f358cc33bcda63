"""Where tasks run: `none` (this process, in task order: the one-machine run), `local:N` (a Dask
LocalCluster of N worker processes) or `tcp://HOST:PORT` (a running Dask scheduler, e.g. one
that dask-jobqueue started on Slurm). Dask is imported here only, and only when asked for."""
import logging
import os

from .errors import VctInputError


class SerialExecutor:
    """Every task in this process, one after the other, in submission order."""

    workers = 1

    def __init__(self):
        self.threads_per_task = 0  # vct's default: every core of this machine

    def run(self, tasks, on_done):
        """tasks: [(key, fn, args)]; on_done(key, result) may return more tasks to run."""
        queue = list(tasks)
        while queue:
            key, fn, args = queue.pop(0)
            queue.extend(on_done(key, fn(*args)) or [])

    def close(self):
        pass


class DaskExecutor:
    """Tasks on Dask workers. A worker that dies mid-task has its task rerun on another worker by
    the scheduler (distributed's allowed-failures); an exception a task raises (bad input) is not
    retried: it is re-raised here as the task raised it."""

    def __init__(self, spec):
        try:
            from dask.distributed import Client, LocalCluster
        except ImportError:
            raise VctInputError("--scheduler: Dask is not installed (pip install dask distributed), "
                                "or use --scheduler none") from None
        self._cluster = None
        if spec.startswith("local:"):
            n = _positive_int(spec[len("local:"):], spec)
            cores = len(os.sched_getaffinity(0))
            self._cluster = LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                         dashboard_address=None, silence_logs=logging.ERROR)
            self.threads_per_task = max(1, cores // n)  # the machine's cores shared out
            self.workers = n
            self.client = Client(self._cluster)
        elif spec.startswith("tcp://") or spec.startswith("tls://"):
            try:
                self.client = Client(spec, timeout="20s")
            except OSError as e:
                raise VctInputError(f"--scheduler {spec}: no Dask scheduler answers ({e})") from None
            self.threads_per_task = 0  # each worker's vct uses every core of its machine
            self.workers = max(1, len(self.client.scheduler_info().get("workers", {})))
        else:
            raise VctInputError(f"--scheduler: expected none, local:N or tcp://HOST:PORT, got '{spec}'")

    def run(self, tasks, on_done):
        from dask.distributed import as_completed

        futures = as_completed()
        pending = []
        for key, fn, args in tasks:
            pending.append(self.client.submit(fn, *args, key=key, pure=False))
            futures.add(pending[-1])
        try:
            for fut in futures:
                for key, fn, args in on_done(fut.key, fut.result()) or []:
                    pending.append(self.client.submit(fn, *args, key=key, pure=False))
                    futures.add(pending[-1])
        except BaseException:
            self.client.cancel(pending)
            raise

    def close(self):
        self.client.close()
        if self._cluster is not None:
            self._cluster.close()


def _positive_int(text, spec):
    if not text.isdigit() or int(text) < 1:
        raise VctInputError(f"--scheduler: expected local:N with N >= 1, got '{spec}'")
    return int(text)


def check_scheduler_spec(spec):
    if spec != "none" and not spec.startswith(("local:", "tcp://", "tls://")):
        raise VctInputError(f"--scheduler: expected none, local:N or tcp://HOST:PORT, got '{spec}'")
    if spec.startswith("local:"):
        _positive_int(spec[len("local:"):], spec)


def make_executor(spec):
    check_scheduler_spec(spec)
    return SerialExecutor() if spec == "none" else DaskExecutor(spec)
