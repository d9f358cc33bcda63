"""Running the vct binary as a task: its own process, killed with the worker that started it."""
import ctypes
import os
import signal
import socket
import subprocess
import time
from pathlib import Path

from .errors import VctInputError, VctTaskError

_PR_SET_PDEATHSIG = 1


def _die_with_parent():
    # A worker killed mid-task (kill -9, a lost node) must not leave its vct rendering on: the
    # task is retried elsewhere and an orphan would only steal that machine's cores.
    try:
        ctypes.CDLL("libc.so.6", use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)
    except OSError:
        pass


def find_vct(explicit=None):
    """--vct, else $VCT_BIN, else build/bin/vct of the checkout this package lives in."""
    candidates = [explicit, os.environ.get("VCT_BIN"),
                  str(Path(__file__).resolve().parents[2] / "build" / "bin" / "vct")]
    for c in candidates:
        if c and os.access(c, os.X_OK):
            return os.path.abspath(c)
    raise VctInputError(f"{candidates[0] or candidates[-1]}: no vct binary (build it, or pass --vct PATH)")


def run_vct(vct, args, threads=0, cwd=None, ok_codes=(0,)):
    """Runs vct with `args` (and --threads when threads > 0); returns stdout, host and seconds.
    Exit 2 raises VctInputError with vct's own line, any other code not in ok_codes VctTaskError."""
    cmd = [vct] + list(args) + (["--threads", str(threads)] if threads > 0 else [])
    start = time.monotonic()
    proc = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, preexec_fn=_die_with_parent)
    seconds = time.monotonic() - start
    if proc.returncode not in ok_codes:
        lines = [ln for ln in proc.stderr.splitlines() if ln.strip()]
        last = lines[-1] if lines else f"vct exited {proc.returncode}"
        if last.startswith("vct: "):
            last = last[len("vct: "):]
        if proc.returncode == 2:
            raise VctInputError(last)
        raise VctTaskError(f"{last} (exit {proc.returncode} on {socket.gethostname()})")
    return proc.stdout, socket.gethostname(), seconds, proc.returncode
