"""Resource caps for one submission: what the platform can enforce, and which cap was hit.

A submission runs as a process tree (its kernel and whatever that starts) inside the sandbox.
Its caps (:class:`Caps`) are enforced with what the platform gives:

* **memory of the whole tree** and **process count**: a cgroup of its own (cgroup v2, or the
  v1 ``memory`` and ``pids`` controllers) when the grader may create one (usually as root, or
  in a delegated cgroup); otherwise per-process limits only (``RLIMIT_AS`` for each process,
  ``RLIMIT_NPROC`` counted inside the sandbox's own user namespace), and :func:`probe` says so;
* **sizes of the in-memory folders** (``/tmp``, ``/dev/shm``, the working folder): bubblewrap's
  ``--size`` for each tmpfs (their pages also count towards the cgroup's memory);
* **disk**: the submission writes only to those tmpfs folders; the one folder shared with the
  grader (the kernel's sockets) is made read-only once the kernel is up (as root);
* **file size** and **CPU time**: ``RLIMIT_FSIZE`` and ``RLIMIT_CPU`` of every process;
* **output kept**: the runner keeps at most :attr:`Caps.output` bytes of a notebook's output.

:class:`Cgroup` creates, joins, reads and removes the cgroup of one submission;
:func:`measure_folders` reads how full the in-memory folders are from outside the kernel, and
:func:`cap_notes` turns every cap hit into a row note (a cap note is always the grader's own
measurement, never the notebook's word).
"""
from __future__ import annotations

import os
import signal
import time
import uuid
from dataclasses import dataclass
from pathlib import Path

__all__ = ["WORK", "Caps", "Cgroup", "probe", "LIMITER", "measure_folders", "cap_notes"]

#: The sandbox's working folder and home (a tmpfs of its own; the sandbox mounts it, the caps size it).
WORK = "/home/student"

MB = 2 ** 20
_ROOT = Path("/sys/fs/cgroup")


@dataclass(frozen=True)
class Caps:
    """The caps of one submission (bytes, counts, seconds).

    Attributes
    ----------
    memory : int
        Memory of the submission's whole process tree (cgroup), or of each process without one.
    processes : int
        Processes and threads alive at once.
    tmp, shm, work : int
        Sizes of the sandbox's ``/tmp``, ``/dev/shm`` and working folder (tmpfs).
    file_size : int
        Largest file a process may write.
    output : int
        Output (stdout, stderr, displays) kept from one notebook; the rest is dropped.
    runner_memory : int
        Address space of the trusted runner and judge process.
    judge_seconds : float
        Time for judging one task.

    Examples
    --------
    >>> Caps().processes
    64
    """

    memory: int = 2048 * MB
    processes: int = 64
    tmp: int = 256 * MB
    shm: int = 64 * MB
    work: int = 256 * MB
    file_size: int = 128 * MB
    output: int = 2 * MB
    runner_memory: int = 4096 * MB
    judge_seconds: float = 20.0


def _own_path(controller: str) -> str | None:
    """This process's cgroup path for a v1 controller ("" for the v2 unified line)."""
    try:
        lines = Path("/proc/self/cgroup").read_text().splitlines()
    except OSError:
        return None
    for line in lines:
        _, names, path = line.split(":", 2)
        if (controller == "" and names == "") or controller in names.split(","):
            return path
    return None


def _v2() -> bool:
    return (_ROOT / "cgroup.controllers").exists()


def _parents() -> dict[str, Path] | None:
    """Folders in which a child cgroup would be created: v2 ``{"": dir}``, v1 ``{"memory", "pids"}``."""
    if _v2():
        own = _own_path("")
        return {"": _ROOT / own.lstrip("/")} if own is not None else None
    found = {}
    for c in ("memory", "pids"):
        own = _own_path(c)
        if own is None or not (_ROOT / c).is_dir():
            return None
        found[c] = _ROOT / c / own.lstrip("/")
    return found


class Cgroup:
    """The cgroup of one submission (memory and process caps), or nothing when none can be made.

    Parameters
    ----------
    caps : Caps
        Its ``memory`` and ``processes`` are written to the cgroup.

    Attributes
    ----------
    dirs : dict
        Controller -> folder (empty when no cgroup could be created).

    Examples
    --------
    >>> cg = Cgroup(Caps())
    >>> cg.join_command(["true"])[-1]
    'true'
    >>> cg.remove()
    """

    def __init__(self, caps: Caps) -> None:
        self.dirs: dict[str, Path] = {}
        parents = _parents()
        if not parents:
            return
        name = f"balancelab-{os.getpid()}-{uuid.uuid4().hex[:12]}"
        try:
            for c, parent in parents.items():
                d = parent / name
                d.mkdir()
                self.dirs[c] = d
            if "" in self.dirs:
                d = self.dirs[""]
                (d / "memory.max").write_text(str(caps.memory))
                (d / "pids.max").write_text(str(caps.processes))
                _try_write(d / "memory.swap.max", "0")
            else:
                (self.dirs["memory"] / "memory.limit_in_bytes").write_text(str(caps.memory))
                _try_write(self.dirs["memory"] / "memory.memsw.limit_in_bytes", str(caps.memory))
                (self.dirs["pids"] / "pids.max").write_text(str(caps.processes))
        except OSError:
            self.remove()

    @classmethod
    def attach(cls, dirs: dict) -> Cgroup:
        """The cgroup whose folders another process created (controller -> folder)."""
        cg = cls.__new__(cls)
        cg.dirs = {str(k): Path(v) for k, v in dirs.items()}
        return cg

    @staticmethod
    def clean_stale() -> int:
        """Remove the cgroups left by graders that no longer run (killed with SIGKILL); how many.

        Examples
        --------
        >>> Cgroup.clean_stale() >= 0
        True
        """
        gone = 0
        for parent in (_parents() or {}).values():
            for d in parent.glob("balancelab-*"):
                pid = d.name.split("-")[1]
                if pid.isdigit() and not Path(f"/proc/{pid}").exists():
                    cg = Cgroup.attach({"": d})
                    cg.remove()
                    gone += 1
        return gone

    def join_command(self, cmd: list[str]) -> list[str]:
        """``cmd`` prefixed by a shell that moves itself into the cgroup first.

        Parameters
        ----------
        cmd : list of str

        Returns
        -------
        list of str
        """
        if not self.dirs:
            return list(cmd)
        procs = [str(d / "cgroup.procs") for d in self.dirs.values()]
        script = "".join(f'echo $$ > "${i + 1}" || exit 97; ' for i in range(len(procs)))
        return ["/bin/sh", "-c", script + f"shift {len(procs)}; exec \"$@\"", "sh", *procs, *cmd]

    def peak(self) -> int | None:
        """Peak memory of the tree (bytes), if the cgroup records it."""
        for d, f in ((self.dirs.get(""), "memory.peak"), (self.dirs.get("memory"), "memory.max_usage_in_bytes")):
            if d is not None:
                try:
                    return int((d / f).read_text().split()[0])
                except (OSError, ValueError, IndexError):
                    return None
        return None

    def hits(self) -> list[str]:
        """Which caps the tree reached (``"memory"``, ``"processes"``)."""
        out = []
        mem, pids = self.dirs.get("") or self.dirs.get("memory"), self.dirs.get("") or self.dirs.get("pids")
        if mem is not None:
            events = _keyed(mem / ("memory.events" if "" in self.dirs else "memory.oom_control"))
            failcnt = _int(mem / "memory.failcnt") if "" not in self.dirs else 0
            if events.get("oom_kill", 0) > 0 or events.get("max", 0) > 0 or failcnt > 0:
                out.append("memory")
        if pids is not None and _keyed(pids / "pids.events").get("max", 0) > 0:
            out.append("processes")
        return out

    def kill(self) -> None:
        """SIGKILL every process still in the cgroup or in any cgroup below it (a submission may have
        made child cgroups and moved processes there)."""
        for _ in range(20):
            alive = False
            for d in self.dirs.values():
                for pid in (p for sub in _tree(d) for p in _pids(sub)):
                    alive = True
                    try:
                        os.kill(pid, signal.SIGKILL)
                    except (ProcessLookupError, PermissionError):
                        pass
            if not alive:
                return
            time.sleep(0.05)

    def remove(self) -> None:
        """Kill what is left and delete the cgroup with every cgroup below it (deepest first)."""
        self.kill()
        for top in list(self.dirs.values()):
            for d in reversed(_tree(top)):
                for _ in range(40):
                    try:
                        d.rmdir()
                        break
                    except FileNotFoundError:
                        break
                    except OSError:
                        time.sleep(0.05)
        self.dirs = {}


def _tree(d: Path) -> list[Path]:
    """``d`` and every cgroup folder below it, parents before children (links are not followed)."""
    out, todo = [], [d]
    while todo:
        cur = todo.pop()
        out.append(cur)
        try:
            todo += sorted(p for p in cur.iterdir() if p.is_dir() and not p.is_symlink())
        except OSError:
            pass
    return out


def _pids(d: Path) -> list[int]:
    try:
        return [int(x) for x in (d / "cgroup.procs").read_text().split()]
    except (OSError, ValueError):
        return []


def _try_write(path: Path, text: str) -> None:
    try:
        path.write_text(text)
    except OSError:
        pass


def _int(path: Path) -> int:
    try:
        return int(path.read_text().split()[0])
    except (OSError, ValueError, IndexError):
        return 0


def _keyed(path: Path) -> dict[str, int]:
    out = {}
    try:
        for line in path.read_text().splitlines():
            parts = line.split()
            if len(parts) == 2 and parts[1].lstrip("-").isdigit():
                out[parts[0]] = int(parts[1])
    except OSError:
        pass
    return out


def probe() -> dict[str, str]:
    """How each cap is enforced here (cap -> ``"cgroup"``, ``"rlimit"``, ``"tmpfs"``, ...).

    Returns
    -------
    dict
        ``memory`` and ``processes`` say ``"cgroup"`` when a cgroup of the submission's own can
        be made, else ``"per process"``.

    Examples
    --------
    >>> sorted(probe())
    ['cpu', 'disk', 'file size', 'memory', 'output', 'processes', 'shm', 'tmp']
    """
    cg = Cgroup(Caps())
    tree = "cgroup" if cg.dirs else "per process"
    cg.remove()
    return {"memory": tree, "processes": tree if tree == "cgroup" else "per user namespace (RLIMIT_NPROC)",
            "tmp": "tmpfs size", "shm": "tmpfs size", "disk": "tmpfs sizes", "file size": "rlimit",
            "cpu": "rlimit", "output": "runner"}


#: A tiny program that sets resource limits and then becomes the command (``argv``: cpu seconds,
#: file size, address space, process count, then the command). No ``preexec_fn``: the grader
#: runs several jobs in threads.
LIMITER = ("import os, resource, sys\n"
           "for name, value in (('RLIMIT_CPU', int(sys.argv[1])), ('RLIMIT_FSIZE', int(sys.argv[2])),\n"
           "                    ('RLIMIT_AS', int(sys.argv[3])), ('RLIMIT_NPROC', int(sys.argv[4])),\n"
           "                    ('RLIMIT_CORE', 0)):\n"
           "    if value >= 0:\n"
           "        try:\n"
           "            resource.setrlimit(getattr(resource, name), (value, value))\n"
           "        except (ValueError, OSError):\n"
           "            pass\n"
           "os.execvp(sys.argv[5], sys.argv[5:])\n")


def _descendants(pid: int) -> list[int]:
    """``pid`` and every process below it, parents first (read from ``/proc``)."""
    out: list[int] = []
    todo = [pid]
    while todo and len(out) < 4096:
        p = todo.pop(0)
        out.append(p)
        try:
            tasks = os.listdir(f"/proc/{p}/task")
        except OSError:
            continue
        for t in tasks:
            try:
                todo += [int(c) for c in Path(f"/proc/{p}/task/{t}/children").read_text().split()]
            except (OSError, ValueError):
                pass
    return out


def measure_folders(pid: int | None, full: dict) -> None:
    """How full the sandbox's in-memory folders are, read from outside the kernel (into ``full``).

    The runner looks at the folders through ``/proc/PID/root`` of the deepest process under the
    sandbox's first process ``pid`` (it sees the sandbox's mounts); the kernel's code cannot
    change this reading (a note about a cap must not be the notebook's word). Nothing is recorded
    where ``/proc`` does not let the runner look (then no folder note is given).

    Parameters
    ----------
    pid : int or None
        The sandbox's first process (None: nothing is measured).
    full : dict
        Folder -> the largest used fraction seen so far; updated in place.

    Examples
    --------
    >>> full = {}
    >>> measure_folders(os.getpid(), full)  # no sandbox below this process: the host's root
    >>> full
    {}
    """
    if not isinstance(pid, int):
        return
    for p in reversed(_descendants(pid)):
        try:
            stats = {f: os.statvfs(f"/proc/{p}/root{f}") for f in ("/tmp", "/dev/shm", WORK)}
        except OSError:
            continue
        if os.stat(f"/proc/{p}/root/").st_ino == os.stat("/").st_ino and os.stat(f"/proc/{p}/root/").st_dev \
                == os.stat("/").st_dev:
            return  # the host's own root (the sandbox's tree is gone): nothing of the sandbox to read
        for f, st in stats.items():
            if st.f_blocks:
                full[f] = max(full.get(f, 0.0), 1 - st.f_bavail / st.f_blocks)
        return


def cap_notes(caps: Caps, full: dict, hits: list, notes: list) -> None:
    """Add a row note (and a hit) for every cap the submission reached.

    Parameters
    ----------
    caps : Caps
    full : dict
        Folder -> the largest used fraction :func:`measure_folders` saw.
    hits : list
        The caps hit (``"memory"``, ``"processes"``, ...); folders that reached their cap are added.
    notes : list
        The row's notes; one is added per cap hit.

    Examples
    --------
    >>> hits, notes = ["processes"], []
    >>> cap_notes(Caps(), {"/tmp": 0.99}, hits, notes)
    >>> notes
    ['the in-memory folder /tmp reached its cap (256 MB)', 'the process cap (64 at once) was reached']
    """
    sizes = {"/tmp": caps.tmp, "/dev/shm": caps.shm, WORK: caps.work}
    for p, used in sorted(full.items()):
        if used >= 0.98 and p in sizes:
            hits.append(p)
            notes.append(f"the in-memory folder {p} reached its cap ({sizes[p] // 2 ** 20} MB)")
    if "memory" in hits:
        notes.append(f"the memory cap of the notebook's processes ({caps.memory // 2 ** 20} MB) was reached")
    if "processes" in hits:
        notes.append(f"the process cap ({caps.processes} at once) was reached")
