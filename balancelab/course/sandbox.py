"""Run an untrusted command in a sandbox with limits: what the grader does with each submission.

On Linux with bubblewrap (``bwrap``; Debian: ``apt-get install bubblewrap``) the command runs
as the unprivileged user ``nobody`` in new user, PID, IPC, UTS and network namespaces: the
whole file system is read-only except its scratch folder (and a private, empty ``/tmp``, into
which the grader's own Python and package are bound back read-only when they live there),
there is no network (only a loopback of its own), and when the command ends or is killed
every process it started dies with its PID namespace (a detached child included).

Without bubblewrap the command runs in a process group of its own with resource limits
(CPU time, file size, address space), and :func:`run_limited` warns once that submissions
can then write wherever the grader can; the process group is killed at the end.
"""
from __future__ import annotations

import functools
import os
import shutil
import signal
import subprocess
import sys
import warnings
from dataclasses import dataclass
from pathlib import Path

__all__ = ["bwrap_path", "sandbox_available", "sandbox_command", "RunResult", "run_limited",
           "NO_SANDBOX_WARNING"]

NO_SANDBOX_WARNING = ("no sandbox: bubblewrap (bwrap) is missing, does not work here or was turned off, so "
                      "submissions run as the grader's user with resource limits only and can read and write the grader's files; install it "
                      "(Debian: apt-get install bubblewrap) before grading untrusted work")
#: Largest file a submission may write (bytes) and address space of each of its processes (bytes).
FILE_LIMIT = 200 * 2 ** 20
MEMORY_LIMIT = 6 * 2 ** 30


def bwrap_path() -> str | None:
    """Path of the ``bwrap`` executable, or None.

    Returns
    -------
    str or None

    Examples
    --------
    >>> bwrap_path() is None or bwrap_path().endswith("bwrap")
    True
    """
    return shutil.which("bwrap")


@functools.lru_cache(maxsize=1)
def sandbox_available() -> bool:
    """Whether bubblewrap works here (it is installed and may create namespaces).

    Returns
    -------
    bool

    Examples
    --------
    >>> isinstance(sandbox_available(), bool)
    True
    """
    exe = bwrap_path()
    if exe is None:
        return False
    try:
        r = subprocess.run(sandbox_command(["true"], Path("/tmp")), capture_output=True, timeout=30)
    except (OSError, subprocess.TimeoutExpired):
        return False
    return r.returncode == 0


def _python_paths_in_tmp() -> list[str]:
    """Folders under ``/tmp`` that this Python needs (its prefixes, its import path), outermost only.

    The sandbox gives the command an empty ``/tmp`` of its own; a grader whose virtual
    environment or checkout lives under ``/tmp`` (a CI runner's clone, say) is bound back
    read-only so that the same interpreter and the same pristine package run inside.
    """
    tmp = Path("/tmp").resolve()
    found = set()
    for entry in [sys.prefix, sys.base_prefix, sys.exec_prefix, os.path.dirname(sys.executable),
                  str(Path(__file__).resolve().parents[2]), *sys.path]:
        if not entry:
            continue
        path = Path(entry).resolve()
        if path != tmp and tmp in path.parents and path.exists():
            found.add(path)
    outer = [p for p in found if not any(q in p.parents for q in found)]
    return sorted(str(p) for p in outer)


def sandbox_command(cmd: list[str], scratch: str | Path) -> list[str]:
    """The bubblewrap command line that runs ``cmd`` with only ``scratch`` writable and no network.

    Parameters
    ----------
    cmd : list of str
        The command.
    scratch : str or Path
        The only folder the command may write to (also its working folder and ``HOME``).

    Returns
    -------
    list of str

    Examples
    --------
    >>> sandbox_command(["true"], "/tmp/x")[-1]
    'true'
    """
    scratch = str(Path(scratch).resolve())
    keep: list[str] = []
    for path in _python_paths_in_tmp():          # a grader installed under /tmp must stay visible
        keep += ["--ro-bind", path, path]
    return [bwrap_path() or "bwrap", "--ro-bind", "/", "/", "--dev", "/dev", "--proc", "/proc",
            "--tmpfs", "/tmp", *keep, "--bind", scratch, scratch, "--unshare-all", "--unshare-user",
            "--uid", "65534", "--gid", "65534", "--cap-drop", "ALL", "--die-with-parent", "--new-session",
            "--chdir", scratch, "--setenv", "HOME", scratch, "--"] + list(cmd)


@dataclass
class RunResult:
    """What a limited run gave.

    Attributes
    ----------
    returncode : int or None
        None when the run was killed at the time limit.
    stdout, stderr : str
        The command's output (at most 10 MB each are kept).
    timed_out : bool
        Whether the time limit killed it.
    sandboxed : bool
        Whether bubblewrap was used.

    Examples
    --------
    >>> RunResult(0, "", "", False, True).timed_out
    False
    """

    returncode: int | None
    stdout: str
    stderr: str
    timed_out: bool
    sandboxed: bool


#: A tiny program that sets the resource limits and then becomes the command (no ``preexec_fn``,
#: which is not safe when the grader runs several jobs in threads).
_LIMITED = ("import os, resource, sys\n"
            "for name, value in (('RLIMIT_CPU', int(sys.argv[1])), ('RLIMIT_FSIZE', int(sys.argv[2])),\n"
            "                    ('RLIMIT_AS', int(sys.argv[3])), ('RLIMIT_CORE', 0)):\n"
            "    try:\n"
            "        resource.setrlimit(getattr(resource, name), (value, value))\n"
            "    except (ValueError, OSError):\n"
            "        pass\n"
            "os.execvp(sys.argv[4], sys.argv[4:])\n")


def _limited(cmd: list[str], cpu_seconds: int) -> list[str]:
    return [sys.executable, "-c", _LIMITED, str(cpu_seconds), str(FILE_LIMIT), str(MEMORY_LIMIT)] + list(cmd)


def _kill_group(pgid: int) -> None:
    try:
        os.killpg(pgid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def run_limited(cmd: list[str], scratch: str | Path, timeout: float, env: dict | None = None,
                sandbox: bool | None = None) -> RunResult:
    """Run ``cmd`` in the sandbox (or with limits only) and kill its whole process group at ``timeout``.

    Parameters
    ----------
    cmd : list of str
        The command.
    scratch : str or Path
        Its working folder, the only one it may write to in the sandbox.
    timeout : float
        Wall-clock limit (s); the CPU limit of each process is a little above it.
    env : dict, optional
        Environment (default: the grader's).
    sandbox : bool, optional
        Force the sandbox on or off; by default it is used when :func:`sandbox_available`.

    Returns
    -------
    RunResult

    Examples
    --------
    >>> import tempfile
    >>> run_limited([sys.executable, "-c", "print(6 * 7)"], tempfile.mkdtemp(), 60).stdout
    '42\\n'
    """
    use = sandbox_available() if sandbox is None else sandbox
    if not use:
        warnings.warn(NO_SANDBOX_WARNING, RuntimeWarning, stacklevel=2)
    limited = _limited(cmd, int(timeout) + 30)
    full = sandbox_command(limited, scratch) if use else limited
    proc = subprocess.Popen(full, cwd=str(scratch), env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, start_new_session=True, text=True, errors="replace")
    timed_out = False
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        timed_out = True
        _kill_group(proc.pid)
        try:
            out, err = proc.communicate(timeout=10)
        except subprocess.TimeoutExpired:  # a process that left the group still holds the pipes
            proc.kill()
            out, err = "", "the process group was killed; its output was lost"
    finally:
        _kill_group(proc.pid)  # whatever is left of the group (the sandbox's PID namespace is gone already)
    return RunResult(None if timed_out else proc.returncode, out[-10 ** 7:], err[-10 ** 7:], timed_out, use)


if __name__ == "__main__":  # pragma: no cover - a manual probe
    print("sandbox available:", sandbox_available(), file=sys.stderr)
