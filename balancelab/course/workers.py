"""The grader's workers: one runner per notebook, forked from a server that imported everything once.

:func:`forked_runner` forks a runner (:func:`balancelab.course.runner.serve`) from a
:mod:`multiprocessing` forkserver that preloaded the runner, the checks and nbclient, reads its
report lines from a pipe only it holds, and kills its process group at the wall-clock limit.
Every runner alive is registered (:data:`ACTIVE`) so that a grader that is stopped kills them and
deletes their scratch folders (:func:`stop_on_signal`); :func:`clean_stale` deletes the scratch folders of
graders that were killed outright.
"""
from __future__ import annotations

import json
import os
import shutil
import signal
import sys
import tempfile
import threading
import time
from pathlib import Path

from .caps import Cgroup

__all__ = ["ACTIVE", "SCRATCH_PREFIX", "clean_stale", "forked_runner", "remove_tree", "scratch_root", "stop_on_signal"]

SCRATCH_PREFIX = "balancelab-grade-"
#: Runners and scratch folders alive now (killed and removed if the grader is stopped).
ACTIVE: dict[int, tuple[object, Path, Cgroup]] = {}
ACTIVE_LOCK = threading.Lock()


def scratch_root() -> Path:
    return Path(os.environ.get("BALANCELAB_SCRATCH") or tempfile.gettempdir())


def clean_stale(root: Path | None = None) -> list[Path]:
    """Delete the scratch folders of graders that no longer run (a grader killed with SIGKILL).

    Parameters
    ----------
    root : Path, optional
        Where scratch folders are made (``$BALANCELAB_SCRATCH`` or the temporary folder).

    Returns
    -------
    list of Path
        The folders deleted.

    Examples
    --------
    >>> isinstance(clean_stale(), list)
    True
    """
    gone = []
    for p in (root or scratch_root()).glob(SCRATCH_PREFIX + "*"):
        pid = p.name[len(SCRATCH_PREFIX):].split("-", 1)[0]
        if pid.isdigit() and not Path(f"/proc/{pid}").exists() and p.is_dir() and not p.is_symlink():
            remove_tree(p)
            gone.append(p)
    return gone


def remove_tree(folder: Path) -> None:
    """Delete a scratch folder (a process of the sandbox that is still dying may write for a moment)."""
    for _ in range(50):
        shutil.rmtree(folder, ignore_errors=True)
        if not folder.exists():
            return
        time.sleep(0.1)
    print(f"WARNING: could not delete the scratch folder {folder}", file=sys.stderr, flush=True)


def _kill(proc) -> None:
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


_CTX = None
_CTX_LOCK = threading.Lock()


def _context():
    """A forkserver that imported the runner, the checks, nbclient and the judges' sympy and scipy once:
    each runner (and each judge, forked from its runner) is forked from it."""
    global _CTX
    with _CTX_LOCK:
        if _CTX is None:
            import multiprocessing

            ctx = multiprocessing.get_context("forkserver")
            # sympy and scipy.optimize: the judges' own imports (a derive task's formula, task 3.1's root);
            # a judge is a child forked from the runner, so what it imports is imported again by the next
            ctx.set_forkserver_preload(["balancelab.course.runner", "balancelab.course.check", "nbclient",
                                        "jupyter_client.manager", "nbformat", "sympy", "scipy.optimize"])
            _CTX = ctx
        return _CTX


class _Forked:
    """A forked runner seen like a Popen (pid, kill, returncode) for :func:`stop_on_signal`."""

    def __init__(self, process):
        self.process, self.pid = process, process.pid


def forked_runner(job: dict, wall: float, cpu: int) -> tuple[list[dict], str, int | None]:
    """Grade one notebook in a runner forked from the warm server; report lines and how it ended."""
    from .runner import serve

    ctx = _context()
    recv, send = ctx.Pipe(duplex=False)
    proc = ctx.Process(target=serve, args=(job, send, cpu), daemon=False)
    proc.start()
    send.close()
    handle = _Forked(proc)
    with ACTIVE_LOCK:
        ACTIVE[proc.pid] = (handle, Path(job["scratch"]), Cgroup.attach(job.get("cgroup", {})))
    lines, ended, deadline = [], "", time.monotonic() + wall
    try:
        while True:
            left = deadline - time.monotonic()
            if left <= 0:
                ended = f"the grading of this notebook ran past its {wall:g} s limit and was stopped"
                break
            if recv.poll(min(left, 1.0)):
                try:
                    data = recv.recv_bytes(maxlength=64 * 2 ** 20)
                except (EOFError, OSError):
                    break
                try:
                    obj = json.loads(data)
                except (ValueError, RecursionError):
                    continue
                if isinstance(obj, dict):
                    lines.append(obj)
                    if obj.get("done"):
                        break
            elif not proc.is_alive() and not recv.poll(0):
                break
    finally:
        _kill(handle)
        proc.join(10)
        recv.close()
        with ACTIVE_LOCK:
            ACTIVE.pop(proc.pid, None)
    code = proc.exitcode
    if not ended and not any(x.get("done") for x in lines) and code:
        ended = (f"the runner was killed by signal {-code}" if code < 0 else f"the runner exited with code {code}")
    return lines, ended, code



def stop_on_signal(signum, frame):
    """The grader is stopped: kill every runner, delete every scratch folder, keep the rows written."""
    with ACTIVE_LOCK:
        active = list(ACTIVE.values())
    for proc, scratch, cgroup in active:
        _kill(proc)
        cgroup.remove()
        remove_tree(scratch)
    os._exit(128 + signum)
