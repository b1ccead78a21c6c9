"""Run an untrusted command in a sandbox with limits: what the grader does with each submission.

On Linux with bubblewrap (``bwrap``; Debian: ``apt-get install bubblewrap``) the command runs
as the unprivileged user ``nobody`` in new user, PID, IPC, UTS, cgroup and network namespaces
and sees only what a Python kernel needs (:func:`kernel_binds`): the system's programs and
libraries, this Python and its packages read-only, the ``balancelab`` package folder alone
(not the checkout around it: no solutions, tests or book), a minimal ``/dev``, its own
``/proc``, and size-capped in-memory ``/tmp``, ``/dev/shm`` and working folder. No home, no
submissions, no host ``/tmp`` or its sockets, no network (only a loopback of its own), no
environment variable of the grader; one host folder may be shared (the kernel's sockets).
When the command ends or is killed every process it started dies with its PID namespace
(a detached child included). It may not make user namespaces of its own (``--disable-userns``):
without one it cannot mount anything (a cgroup file system to raise its own caps included).
Run by root, bubblewrap alone would map ``nobody`` to the host's root user (without capabilities);
so a root grader uses two steps (:func:`kernel_runs_as_nobody`): the kernel is then the host's uid
65534. Where that cannot work (no ``setpriv``, no unprivileged user namespaces, a Python only root
may read) the one-step sandbox stays, its kernel root without any capability.

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

from . import caps

__all__ = ["bwrap_path", "sandbox_available", "sandbox_command", "RunResult", "run_limited", "kernel_runs_as_nobody", "NOBODY",
           "assume_kernel_user",
           "NO_SANDBOX_WARNING", "kernel_binds", "limited", "precompile_package", "font_list", "KERNEL_START", "WORK",
           "SHARE"]

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
        r = subprocess.run(sandbox_command(["true"]), capture_output=True, timeout=30)
    except (OSError, subprocess.TimeoutExpired):
        return False
    return r.returncode == 0


def _python_roots() -> list[str]:
    """Folders this Python needs: its prefixes, its standard library and its site-packages (never
    ``sys.path`` as such: ``python -m`` puts the working folder first there, and the grader's
    working folder may hold the solutions or the grades, but the folders of installed distributions it
    names, see :func:`_site_folders_on_path`), minus the checkout, if the package sits in one (an editable install's
    repository root would show the solutions, tests and book: only the package folder itself is
    bound, see :func:`kernel_binds`), the home folder, the working folder and their parents."""
    import site
    import sysconfig

    around = Path(__file__).resolve().parents[2]
    # a checkout has the build files; from a wheel, the folder around the package is site-packages
    checkout = around if (around / "pyproject.toml").is_file() else None
    prefixes = [sys.prefix, sys.base_prefix, sys.exec_prefix, sys.base_exec_prefix]
    libs = [sysconfig.get_paths().get(k) for k in ("stdlib", "platstdlib", "purelib", "platlib")]
    libs += site.getsitepackages() if hasattr(site, "getsitepackages") else []
    libs += _site_folders_on_path()
    never = {Path("/"), Path.cwd().resolve(), Path.home().resolve()} | ({checkout} if checkout else set())
    found = set()
    for entry in prefixes + libs:
        if not entry:
            continue
        path = Path(entry).resolve()
        inside = checkout is not None and (checkout in path.parents or path in checkout.parents)
        near = any(path == n or path in n.parents for n in never)  # the cwd, home or a folder above them
        if not path.is_dir() or near or (inside and entry not in prefixes):
            continue
        found.add(path)
    outer = [p for p in found if not any(q in p.parents for q in found)]
    return sorted(str(p) for p in outer)


def _site_folders_on_path() -> list[str]:
    """Folders of installed distributions that ``sys.path`` names besides the site folders (added by a
    ``.pth`` file or ``PYTHONPATH``): a folder counts when it holds a ``*.dist-info``."""
    out = []
    for entry in sys.path:
        path = Path(entry or ".")
        if entry and path.is_absolute() and path.is_dir() and next(path.glob("*.dist-info"), None) is not None:
            out.append(entry)
    return out


#: Files of ``/etc`` a Python kernel reads (the dynamic linker's cache, fonts for plots, the time zone).
_ETC = ("/etc/ld.so.cache", "/etc/ld.so.conf", "/etc/ld.so.conf.d", "/etc/fonts", "/etc/localtime",
        "/etc/mime.types", "/etc/matplotlibrc")


def kernel_binds() -> list[str]:
    """The read-only binds of the sandbox: the system's programs and libraries, this Python, its
    packages and the ``balancelab`` package folder alone (never the checkout around it).

    Returns
    -------
    list of str
        bubblewrap arguments.

    Examples
    --------
    >>> args = kernel_binds()
    >>> import balancelab, pathlib
    >>> str(pathlib.Path(balancelab.__file__).resolve().parent) in args
    True
    >>> "/home" in args or "/root" in args
    False
    """
    out: list[str] = ["--ro-bind", "/usr", "/usr"]
    for top in ("/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"):
        p = Path(top)
        if p.is_symlink():
            out += ["--symlink", os.readlink(top), top]
        elif p.is_dir():
            out += ["--ro-bind", top, top]
    for f in _ETC:
        out += ["--ro-bind-try", f, f]
    for root in _python_roots():
        if not root.startswith("/usr/"):
            out += ["--ro-bind", root, root]
    pkg = str(Path(__file__).resolve().parents[1])  # the balancelab package folder
    return out + ["--ro-bind", pkg, pkg]


@functools.lru_cache(maxsize=1)
def precompile_package() -> bool:
    """Byte-compile the ``balancelab`` package folder once, before the kernels start.

    Every kernel imports ``balancelab`` from a read-only bind and may not write byte code
    (``PYTHONDONTWRITEBYTECODE``); a package without ``__pycache__`` (an editable install, a
    checkout run with ``PYTHONDONTWRITEBYTECODE`` set) is then compiled again by every kernel,
    about a second of CPU per notebook. The grader compiles it here, once per process, as pip
    does for an installed package; files already compiled are only checked.

    Returns
    -------
    bool
        True when the folder is compiled (False: it cannot be written, nothing changed).

    Examples
    --------
    >>> precompile_package() in (True, False)
    True
    """
    import compileall

    pkg = Path(__file__).resolve().parents[1]
    if not os.access(pkg, os.W_OK):
        return False
    try:
        return bool(compileall.compile_dir(str(pkg), quiet=2, workers=1))
    except OSError:
        return False


@functools.lru_cache(maxsize=1)
def font_list() -> tuple[str, str] | None:
    """matplotlib's font list, built once per grader for every kernel to start from.

    Each kernel's matplotlib folder is a fresh in-memory folder, so its first figure scanned the
    fonts again (0.2–0.3 s of CPU per notebook). The grader builds the list here, once, with the
    kernels' own Python and the fonts they see (``/usr`` and matplotlib's own, bound read-only at
    the same paths); each runner hands the file to its kernel, which copies it into its own
    folder (:data:`KERNEL_START`). A plain JSON file of font names and
    paths, the same for every submission and written by the grader: nothing of one submission
    reaches another.

    Returns
    -------
    (str, str) or None
        The file's name (``fontlist-vNNN.json``) and text; None when matplotlib cannot build it.

    Examples
    --------
    >>> found = font_list()
    >>> found is None or (found[0].startswith("fontlist-") and found[1].startswith("{"))
    True
    """
    import tempfile

    with tempfile.TemporaryDirectory(prefix="balancelab-fonts-") as folder:
        env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONSTARTUP")}
        try:
            subprocess.run([sys.executable, "-I", "-c", "import matplotlib.font_manager"], timeout=120,
                           capture_output=True, env={**env, "MPLCONFIGDIR": folder, "MPLBACKEND": "Agg"})
            found = sorted(Path(folder).glob("fontlist-v*.json"))
            return (found[0].name, found[0].read_text(encoding="utf-8")) if found else None
        except (OSError, subprocess.SubprocessError, UnicodeError):
            return None


#: How the kernel starts: as ``python -m ipykernel_launcher`` (the working folder off ``sys.path``), but
#: with ``debugpy`` blocked (ipykernel imports it at start-up for a debugger that grading never uses),
#: and with matplotlib's font list copied from the one the grader built
#: (:func:`font_list`) into the kernel's own matplotlib folder.
KERNEL_START = ("import os, sys\n"
                "if sys.path[:1] == ['']:\n"
                "    del sys.path[0]\n"
                "sys.modules['debugpy'] = None\n"
                "_f = os.environ.pop('BALANCELAB_FONTS', '')\n"
                "if _f and os.environ.get('MPLCONFIGDIR'):\n"
                "    try:\n"
                "        os.makedirs(os.environ['MPLCONFIGDIR'], exist_ok=True)\n"
                "        with open(_f, 'rb') as _i, open(os.path.join(os.environ['MPLCONFIGDIR'], "
                "os.path.basename(_f)), 'wb') as _o:\n"
                "            _o.write(_i.read())\n"
                "    except OSError:\n"
                "        pass\n"
                "from ipykernel.kernelapp import launch_new_instance\n"
                "launch_new_instance()\n")
WORK = caps.WORK  # the sandbox's working folder and home (a tmpfs of its own)
#: Where the shared folder (the kernel's sockets) appears inside the sandbox (a short path: a unix
#: socket's path has at most 107 bytes).
SHARE = "/run/balancelab"


def sandbox_command(cmd: list[str], share: str | Path | None = None, caps=None,
                    env: dict | None = None) -> list[str]:
    """The bubblewrap command line that runs ``cmd`` with nothing of the host but what a kernel needs.

    The command sees the system's programs and libraries, this Python and its packages
    (read-only, the ``balancelab`` package without the checkout around it), a minimal ``/dev``,
    its own ``/proc``, and size-capped in-memory folders: ``/tmp``, ``/dev/shm`` and its working
    folder and home :data:`WORK`. Nothing else: no home, no other ``/tmp``, no submissions,
    no network (a loopback of its own), no host sockets except those in ``share``.

    Parameters
    ----------
    cmd : list of str
        The command.
    share : str or Path, optional
        A host folder bound read-write at :data:`SHARE` (the kernel's sockets).
    caps : Caps, optional
        Sizes of the in-memory folders (:class:`~balancelab.course.caps.Caps`).
    env : dict, optional
        The command's whole environment (nothing of the grader's is passed on).

    Returns
    -------
    list of str

    Examples
    --------
    >>> sandbox_command(["true"])[-1]
    'true'
    """
    from .caps import Caps

    caps = caps or Caps()
    env = {"PATH": "/usr/local/bin:/usr/bin:/bin", "HOME": WORK, "LANG": "C.UTF-8", **(env or {})}
    shared = []
    if share is not None:
        shared = ["--bind", str(Path(share).resolve()), SHARE]
    setenv = [x for k, v in env.items() for x in ("--setenv", k, str(v))]
    if kernel_runs_as_nobody():
        return _nobody_command(list(cmd), shared, caps, setenv)
    return [bwrap_path() or "bwrap", "--dev", "/dev", "--proc", "/proc",
            "--size", str(caps.tmp), "--tmpfs", "/tmp", "--size", str(caps.shm), "--tmpfs", "/dev/shm",
            "--size", str(caps.work), "--tmpfs", WORK, *kernel_binds(), *shared,
            "--unshare-all", "--unshare-user", "--uid", "65534", "--gid", "65534", "--hostname", "sandbox",
            "--disable-userns", "--cap-drop", "ALL", "--die-with-parent", "--new-session", "--clearenv", *setenv,
            "--chdir", WORK, "--"] + list(cmd)


#: The host user and group the kernel runs as when the grader is root.
NOBODY = 65534
#: Drop from root to :data:`NOBODY` for good: no groups, no capability in any set, no new privileges.
_SETPRIV = ["--reuid", str(NOBODY), "--regid", str(NOBODY), "--clear-groups", "--inh-caps=-all",
            "--bounding-set=-all", "--no-new-privs", "--"]


def kernel_runs_as_nobody() -> bool:
    """Whether the kernel runs as the host's unprivileged user ``nobody`` (65534) in two steps.

    As root, bubblewrap's own user namespace would map the kernel to the host's root user (without
    capabilities, but the owner of every root file). So a root grader builds the sandbox's file
    system as root (outside any user namespace: the Python under a home of mode 700 can still be
    bound, and the folders above each bind are made readable), drops to uid and gid 65534 for good
    (``setpriv``), and only then a second, unprivileged bubblewrap makes the user namespace (with
    ``--disable-userns``). Needs ``setpriv`` (Debian: util-linux) and unprivileged user namespaces.

    Returns
    -------
    bool
        True when the grader is root and the two-step sandbox works here: a Python in it, as uid
        65534, can import ``balancelab`` and ``ipykernel`` (a Python or a package folder that only
        root may read, such as one under a folder of mode 700, keeps the one-step sandbox, whose
        kernel is root without capabilities).

    Examples
    --------
    >>> kernel_runs_as_nobody() in (True, False)
    True
    """
    if os.geteuid() != 0:
        return False
    binds = tuple(kernel_binds())
    if binds not in _TWO_STEP:
        _TWO_STEP[binds] = _two_step_works(binds)
    return _TWO_STEP[binds]


#: Whether the two-step sandbox works, per set of binds (probed once; a grader passes its answer to
#: the runners it forks with :func:`assume_kernel_user`, so that no runner pays for the probe).
_TWO_STEP: dict[tuple, bool] = {}


def assume_kernel_user(as_nobody: bool) -> None:
    """Take the grader's answer of :func:`kernel_runs_as_nobody` for this process's binds (no probe).

    Parameters
    ----------
    as_nobody : bool
        What :func:`kernel_runs_as_nobody` said in the grader.

    Examples
    --------
    >>> assume_kernel_user(kernel_runs_as_nobody())
    """
    _TWO_STEP[tuple(kernel_binds())] = bool(as_nobody)


def _two_step_works(binds: tuple) -> bool:
    if bwrap_path() is None or shutil.which("setpriv") is None:
        return False
    roots = [binds[i + 2] for i, a in enumerate(binds) if a == "--ro-bind"]
    pkg = Path(__file__).resolve().parents[1]
    # from a checkout the kernel imports this very package (runner: PYTHONPATH), so the probe does too
    first = f"import sys\nsys.path.insert(0, {str(pkg.parent)!r})\n" if (pkg.parent / "pyproject.toml").is_file() else ""
    probe = [sys.executable, "-I", "-c",
             first + f"import os, balancelab.course.check, ipykernel\nfor p in {roots!r}: os.listdir(p)"]
    try:
        r = subprocess.run(_nobody_command(probe, [], None, []), capture_output=True, timeout=120)
    except (OSError, subprocess.TimeoutExpired):
        return False
    return r.returncode == 0


def _made_readable(binds: list[str], held: list[str]) -> list[str]:
    """``--dir`` with mode 755 for every folder above a bind's destination that no earlier bind holds
    (bubblewrap would make them 700, owned by root: out of reach of uid 65534).

    ``held`` are folders the sandbox makes itself (an empty ``/tmp``): they exist, but what lies
    below them does not (a checkout under ``/tmp/x`` needs ``/tmp/x`` made readable)."""
    out: list[str] = []
    made = {Path(h) for h in held}
    bound: list[Path] = []
    for i, arg in enumerate(binds):
        if arg not in ("--ro-bind", "--ro-bind-try", "--bind", "--symlink"):
            continue
        dest = Path(binds[i + 2])
        for parent in reversed(dest.parents):
            if parent == Path("/") or parent in made or any(parent == b or b in parent.parents for b in bound):
                continue
            out += ["--perms", "0755", "--dir", str(parent)]
            made.add(parent)
        bound.append(dest)
    return out


def _nobody_command(cmd: list[str], shared: list[str], caps, setenv: list[str]) -> list[str]:
    """The two-step sandbox of :func:`kernel_runs_as_nobody` (the grader is root)."""
    from .caps import Caps

    caps = caps or Caps()
    exe = bwrap_path() or "bwrap"
    binds = kernel_binds() + shared
    # /tmp and /dev/shm for everyone (sticky) under the binds (a Python under /tmp stays visible); the
    # working folder is made by the unprivileged step, so that it belongs to uid 65534
    tmpfs = ["--perms", "01777", "--size", str(caps.tmp), "--tmpfs", "/tmp",
             "--perms", "01777", "--size", str(caps.shm), "--tmpfs", "/dev/shm"]
    dirs = [x for d in (str(Path(WORK).parent), WORK) for x in ("--perms", "0755", "--dir", d)]
    outer = [exe, "--dev", "/dev", "--proc", "/proc", *tmpfs, *dirs, *_made_readable(binds, ["/tmp", "/dev"]),
             *binds, "--unshare-pid", "--unshare-ipc", "--unshare-uts", "--unshare-net", "--unshare-cgroup",
             "--hostname", "sandbox", "--die-with-parent", "--new-session", "--clearenv", *setenv, "--chdir", "/", "--"]
    inner = [exe, "--bind", "/", "/", "--size", str(caps.work), "--tmpfs", WORK, "--unshare-user", "--disable-userns",
             "--uid", str(NOBODY), "--gid", str(NOBODY), "--cap-drop", "ALL", "--die-with-parent", "--chdir", WORK,
             "--"]
    return outer + [shutil.which("setpriv") or "setpriv", *_SETPRIV] + inner + list(cmd)


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


def limited(cmd: list[str], cpu_seconds: int, file_size: int = FILE_LIMIT, memory: int = MEMORY_LIMIT,
            processes: int = -1) -> list[str]:
    """``cmd`` run under resource limits (:data:`~balancelab.course.caps.LIMITER`; -1: unchanged).

    Parameters
    ----------
    cmd : list of str
    cpu_seconds, file_size, memory, processes : int
        ``RLIMIT_CPU``, ``RLIMIT_FSIZE``, ``RLIMIT_AS`` and ``RLIMIT_NPROC``.

    Returns
    -------
    list of str

    Examples
    --------
    >>> limited(["true"], 10)[-1]
    'true'
    """
    from .caps import LIMITER

    return [sys.executable, "-c", LIMITER, str(cpu_seconds), str(file_size), str(memory), str(processes)] + list(cmd)


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
    lim = limited(cmd, int(timeout) + 30)
    full = sandbox_command(lim, env=env) if use else lim
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
