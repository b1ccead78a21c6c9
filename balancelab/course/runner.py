"""Run one submitted notebook and judge its answers: the trusted runner, one process per notebook.

``python -m balancelab.course.runner NOTEBOOK --lab lab2 --student s123 --scratch DIR`` is
started by :mod:`balancelab.course.grading` with a memory and CPU limit and a wall-clock limit.
It runs **outside** the sandbox; only the kernel runs inside it
(:func:`~balancelab.course.sandbox.sandbox_command`, launched by :class:`SandboxKernelManager`),
talking to the runner over the Jupyter protocol on unix sockets in a folder of the scratch
folder (made read-only once the kernel is up). So code in the notebook

* cannot write to the runner's output: the runner keeps its report channel on a private file
  descriptor and gives the kernel ``/dev/null`` as output; the kernel cannot see the runner's
  processes (its own PID namespace) nor signal or trace them;
* reaches the runner only as protocol messages, whose outputs are kept up to
  :attr:`~balancelab.course.caps.Caps.output` bytes;
* cannot choose a status, a note or a score: the runner decides the status itself and sends
  only the answer variables' **data**, which it judges itself (:mod:`balancelab.course.check`,
  each task under a time limit) after the kernel is gone.

After every code cell the runner executes an export cell (:func:`export_source`) whose output
line carries a fresh random nonce; only that line is read. The report, written on the private
descriptor, is one JSON object per line: ``{"run": ...}`` when the notebook has run, then one
``{"task": ...}`` per judged task, then ``{"done": true}``. A runner that dies before its
``run`` line yields status ``error`` and no points (the grader never reads a file the kernel
could have written).
"""
from __future__ import annotations

import argparse
import inspect
import json
import os
import secrets
import signal
import sys
import time
from typing import Any
from pathlib import Path

from .caps import Caps, Cgroup, cap_notes, measure_folders
from .check.data import encode_answer
from .sanitize import excerpt
from .sandbox import (KERNEL_START, NOBODY, SHARE, WORK, assume_kernel_user, kernel_runs_as_nobody, limited,
                      sandbox_command)

__all__ = ["export_source", "SandboxKernelManager", "run_notebook", "judge_tasks", "serve", "main"]

# jsonschema (imported by nbformat) builds an IRI grammar for 4 s on import; nothing here validates an IRI
sys.modules.setdefault("rfc3987_syntax", None)  # type: ignore[arg-type]  # None blocks the import on purpose

#: Largest export (bytes of answer data after one cell).
EXPORT_CAP = 4 * 2 ** 20
#: Seconds a cell may keep running after the interrupt at its time limit.
INTERRUPT_GRACE = 2.0
#: The encoder's source, read once when this module is imported (the code that is running).
_ENCODER_SOURCE = inspect.getsource(encode_answer).replace("encode_answer", "_bl_encode_answer")
#: A serializer the export defines afresh each time (a notebook that patches ``json.dumps`` or
#: ``print`` does not change what is exported).
_SERIALIZER = '''
def _bl_ser(x):
    if x is None:
        return "null"
    if x is True or x is False:
        return "true" if x else "false"
    if type(x) in (int, float):
        return repr(x) if x == x and abs(x) != float("inf") else '"nan"'
    if type(x) is str:
        return '"' + "".join(c if (c.isascii() and c.isprintable() and c not in '"\\\\') else
                             "\\\\u%04x" % ord(c) if ord(c) < 0x10000 else "?" for c in x) + '"'
    if type(x) in (list, tuple):
        return "[" + ",".join(_bl_ser(v) for v in x) + "]"
    if type(x) is dict:
        return "{" + ",".join(_bl_ser(str(k)) + ":" + _bl_ser(v) for k, v in x.items()) + "}"
    return '"?"'
'''


def export_source(variables: list[str], nonce: str) -> str:
    """The code the kernel runs after each cell: write ``nonce`` and the answers' data on one line.

    Parameters
    ----------
    variables : list of str
        The answer variables of the lab.
    nonce : str
        A fresh random token (the runner reads only the line that starts with it).

    Returns
    -------
    str

    Examples
    --------
    >>> import contextlib, io
    >>> ns, buf = {"answer": 2.5, "other": "x"}, io.StringIO()
    >>> with contextlib.redirect_stdout(buf):
    ...     exec(export_source(["answer", "missing"], "N0NCE"), ns)
    >>> nonce, line = buf.getvalue().split(" ", 1)
    >>> nonce, json.loads(line)["answer"], "missing" in json.loads(line)
    ('N0NCE', {'num': '2.5'}, False)
    """
    return (_ENCODER_SOURCE + _SERIALIZER +
            "def _bl_export(_g):\n"
            "    import sys as _s\n"
            f"    _d = {{_v: _bl_encode_answer(_g[_v]) for _v in {list(variables)!r} if _v in _g}}\n"
            "    _c = getattr(_s.modules.get('balancelab.course.check.core'), 'ATTEMPTS', None)\n"
            "    if type(_c) is dict:\n"
            "        _d['__attempts__'] = {str(k): v for k, v in _c.items() if type(v) is int}\n"
            f"    type(_s.stdout).write(_s.stdout, {nonce!r} + ' ' + _bl_ser(_d) + '\\n')\n"
            "try:\n"
            "    _bl_export(globals())\n"
            "finally:\n"
            "    del _bl_export, _bl_ser, _bl_encode_answer\n")


def _kernel_manager_class():
    from jupyter_client.kernelspec import KernelSpec
    from jupyter_client.manager import AsyncKernelManager

    class SandboxKernelManager(AsyncKernelManager):
        """A kernel started inside the sandbox, reached over unix sockets in ``share``."""

        def setup(self, share: Path, caps: Caps, cgroup: Cgroup, sandbox: bool, fonts=None) -> None:
            # relative socket paths (this process works in ``share``): a unix socket path has at most 107 bytes
            self.transport, self.ip, self.sandboxed = "ipc", "k", sandbox
            self.connection_file = str(share / "kernel.json")
            kernel = [sys.executable, "-c", KERNEL_START, "-f", "{connection_file}", "--HistoryManager.enabled=False"]
            env = {"MPLBACKEND": "Agg", "PYTHONDONTWRITEBYTECODE": "1", "PYTHONNOUSERSITE": "1",
                   "IPYTHONDIR": f"{WORK}/.ipython", "MPLCONFIGDIR": f"{WORK}/.mpl",
                   "JUPYTER_RUNTIME_DIR": f"{WORK}/.runtime", "PYDEVD_DISABLE_FILE_VALIDATION": "1"}
            pkg = Path(__file__).resolve().parents[1]
            if sandbox and (pkg.parent / "pyproject.toml").is_file():
                # a checkout (this grader's balancelab, bound alone at its own path): the kernel imports
                # that one, not the one an editable install's finder may name elsewhere (unbound there)
                env["PYTHONPATH"] = str(pkg.parent)
            if sandbox and fonts:  # the grader's font list (a name and its text), read by the kernel at start
                (share / Path(fonts[0]).name).write_text(fonts[1], encoding="utf-8")
                env["BALANCELAB_FONTS"] = f"{SHARE}/{Path(fonts[0]).name}"
            cpu = 24 * 3600
            # with a cgroup the tree's memory is capped there; a process's address space (libraries and
            # thread arenas reserve far more than they use) then only needs a loose limit
            space = 4 * caps.memory if cgroup.dirs else caps.memory
            if sandbox:
                inner = limited(kernel, cpu, caps.file_size, space, caps.processes)
                argv = cgroup.join_command(sandbox_command(inner, share, caps, env))
            else:
                argv = cgroup.join_command(limited(kernel, cpu, caps.file_size, space))
            self._kernel_spec = KernelSpec(argv=argv, display_name="sandbox", language="python",
                                           interrupt_mode="message", env={} if sandbox else env)

        def format_kernel_cmd(self, extra_arguments=None):
            conn = self.connection_file
            if self.sandboxed:  # the kernel's copy names its sockets where it sees the folder
                info = json.loads(Path(conn).read_text())
                info["ip"] = f"{SHARE}/k"
                mine = Path(conn).with_name("kernel-sandbox.json")
                mine.write_text(json.dumps(info))
                if kernel_runs_as_nobody():  # its reader, alone (the scratch folder is the grader's)
                    os.chown(mine, NOBODY, NOBODY)
                conn = f"{SHARE}/kernel-sandbox.json"
            assert self.kernel_spec is not None  # set in __init__
            return [a.replace("{connection_file}", conn) for a in self.kernel_spec.argv]

    return SandboxKernelManager


SandboxKernelManager = None  # the class is built on first use (jupyter_client is imported lazily)


def _client_class(budget: int):
    from nbclient import NotebookClient
    from nbclient.exceptions import CellTimeoutError

    class _Client(NotebookClient):
        """Interrupt at the cell limit, give up after a short grace; keep at most ``budget`` bytes."""

        kept, dropped = 0, 0

        def process_message(self, msg, cell, cell_index):
            if msg.get("msg_type") not in ("status", "execute_input"):
                size = len(repr(msg.get("content", "")))
                if cell.get("metadata", {}).get("export"):   # the export has a budget of its own
                    if size + sum(len(str(o.get("text", ""))) for o in cell.get("outputs", [])) > EXPORT_CAP:
                        return None
                    return super().process_message(msg, cell, cell_index)
                if self.kept + size > budget:
                    self.dropped += size
                    return None
                self.kept += size
            return super().process_message(msg, cell, cell_index)

        async def _async_handle_timeout(self, timeout, cell=None):
            import asyncio
            from queue import Empty

            from jupyter_core.utils import ensure_async

            assert self.km is not None and self.kc is not None  # a cell runs: the kernel is up
            await ensure_async(self.km.interrupt_kernel())
            loop_end = asyncio.get_event_loop().time() + INTERRUPT_GRACE
            while (left := loop_end - asyncio.get_event_loop().time()) > 0:
                try:
                    msg = await ensure_async(self.kc.shell_channel.get_msg(timeout=left))
                except Empty:
                    break
                if msg.get("msg_type") == "execute_reply":
                    return msg
            raise CellTimeoutError.error_from_timeout_and_cell("Cell did not stop", timeout, cell)

    return _Client


def _exported(cell, nonce: str) -> dict | None:
    found = None
    for o in cell.get("outputs", []):
        if o.get("output_type") != "stream":
            continue
        for line in str(o.get("text", "")).splitlines():
            if line.startswith(nonce + " "):
                try:
                    data = json.loads(line[len(nonce) + 1:])
                except (ValueError, RecursionError):  # a forged line nested too deep is no export
                    return None
                found = data if isinstance(data, dict) else None
    return found


def _reported_error(i: int, output: dict) -> str:
    """The note of an error output of cell ``i``: the kernel's own words (any code can raise any
    exception with any text, or send an error output), quoted and marked as the submission's, with
    no ``;`` that would read as a note of the grader's."""
    said = excerpt(output.get("ename"), 40) + (f": {excerpt(output.get('evalue'), 60)}" if output.get("evalue") else "")
    return f'cell {i} raised an error (reported by the submission: "{said.replace(";", ",").replace(chr(34), chr(39))}")'


def _lock(share: Path) -> bool:
    """Make the socket folder read-only for the kernel (its sockets exist by now): no disk there."""
    try:
        for p in [*share.iterdir(), share]:
            os.chown(p, 65533, 65533, follow_symlinks=False)
        share.chmod(0o555)
        return True
    except OSError:
        return False


def _run_cells(client, nb, cells: list, variables: list[str], cell_timeout: int, cgroup: Cgroup,
               errors: list, notes: list, full: dict, budget: float | None = None) -> tuple[dict, str]:
    """Run the code cells one by one, each followed by the export probe with a fresh nonce; returns the
    last exported answers and the status (``graded``, ``timeout``, ``kernel died`` or ``error``).
    ``budget`` (s) is the notebook limit: no cell starts once it is spent, and a cell that runs
    into it is interrupted like one that reaches the cell limit."""
    import nbformat
    from nbclient.exceptions import CellTimeoutError, DeadKernelError

    answers, status = {}, "graded"
    deadline = None if budget is None else time.monotonic() + budget
    for i, cell in enumerate(cells):
        if cell.cell_type != "code":
            continue
        left = None if deadline is None else deadline - time.monotonic()
        if left is not None and left <= 0:
            status = "timeout"
            notes.append(f"the notebook ran past its {budget:g} s limit before cell {i}: the cells from "
                         "there on did not run; the answers given before are graded")
            break
        client.timeout = cell_timeout if left is None else max(1, min(cell_timeout, int(left) + 1))
        nonce = secrets.token_hex(16)
        probe = nbformat.v4.new_code_cell(export_source(variables, nonce), metadata={"export": True})
        try:
            nb.cells[0] = cell
            client.execute_cell(cell, 0)
            errors += [_reported_error(i, o) for o in cell.get("outputs", []) if o.get("output_type") == "error"][:5]
            cell.outputs = []
            nb.cells[0] = probe
            client.timeout = cell_timeout  # the probe exports what the cell left, even past the budget
            client.execute_cell(probe, 0)
        except CellTimeoutError:
            status = "timeout"
            notes.append(f"cell {i} ran past the {cell_timeout} s cell limit and did not stop within "
                         f"{INTERRUPT_GRACE:g} s of the interrupt (a loop that ignores interrupts, or a "
                         "long computation in compiled code): its kernel was killed; the answers given "
                         "before it are graded")
            break
        except DeadKernelError:
            status = "kernel died"
            hit = cgroup.hits()
            notes.append(f"the kernel died in cell {i}" + (f" at the {' and '.join(hit)} cap" if hit else "")
                         + "; the answers given before it are graded")
            break
        except Exception as e:  # the kernel sent what the runner cannot read (a patched kernel)
            status = "error"
            notes.append(f"the kernel stopped answering the runner in cell {i} ({type(e).__name__}): "
                         "the answers given before it are graded")
            break
        if getattr(client.km, "sandboxed", False):  # the runner's own reading, never the kernel's word
            measure_folders(getattr(client.km.provisioner, "pid", None), full)
        found = _exported(probe, nonce)
        if found is not None:
            answers = found
    return answers, status


def run_notebook(path: str | Path, variables: list[str], share: str | Path, cell_timeout: int = 60,
                 caps: Caps | None = None, sandbox: bool = True, cgroup: Cgroup | None = None,
                 notebook_timeout: float | None = None, fonts: tuple[str, str] | None = None) -> dict:
    """Execute a notebook cell by cell in a sandboxed kernel, exporting the answers after each cell.

    Parameters
    ----------
    path : str or Path
        The notebook (a copy the runner reads; the kernel never sees the file).
    variables : list of str
        The answer variables to export.
    share : str or Path
        An empty folder for the kernel's sockets.
    cell_timeout : int
        Per-cell limit (s).
    caps : Caps, optional
        The submission's caps.
    sandbox : bool
        Run the kernel in bubblewrap (False: only with resource limits).
    cgroup : Cgroup, optional
        The submission's cgroup (made, read and removed by the caller); none by default.
    notebook_timeout : float, optional
        Limit of the whole notebook's cells (s): no cell starts after it, a cell that runs into it
        is interrupted; the status is then ``timeout`` and the answers given before are kept.
    fonts : (str, str), optional
        matplotlib's font list for a sandboxed kernel (:func:`~balancelab.course.sandbox.font_list`).

    Returns
    -------
    dict
        ``{"status", "answers", "attempts", "errors", "notes", "peak", "hits"}``.
    """
    import nbformat

    global SandboxKernelManager
    SandboxKernelManager = SandboxKernelManager or _kernel_manager_class()
    caps, share, path = caps or Caps(), Path(share).resolve(), Path(path).resolve()
    os.chdir(share)
    if sandbox and kernel_runs_as_nobody():  # the kernel (uid 65534) makes its sockets here
        os.chown(share, NOBODY, NOBODY)
    nb = nbformat.read(path, as_version=4)
    cells = [c for c in nb.cells]
    nb.cells = [nbformat.v4.new_code_cell("")]
    cgroup = cgroup or Cgroup.attach({})
    km = SandboxKernelManager()
    km.setup(share, caps, cgroup, sandbox, fonts)
    client = _client_class(caps.output)(nb, km=km, timeout=cell_timeout, allow_errors=True,
                                        interrupt_on_timeout=True, shutdown_kernel="immediate",
                                        startup_timeout=120)
    answers: dict[str, Any] = {}
    errors: list[str] = []
    notes: list[str] = []
    full: dict[str, Any] = {}
    status = "error"
    if not cgroup.dirs:
        notes.append("caps: the memory of the process tree and the process count are enforced per process "
                     "only (no cgroup here)")
    try:
        with client.setup_kernel(stdout=open(os.devnull, "wb"), stderr=open(os.devnull, "wb")):
            if sandbox and not _lock(share):
                notes.append("caps: the socket folder stays writable (not root): disk use there is capped per file only")
            answers, status = _run_cells(client, nb, cells, variables, cell_timeout, cgroup, errors, notes, full,
                                         notebook_timeout)
    finally:
        peak, hits = cgroup.peak(), cgroup.hits()
        cgroup.kill()
    if peak is None:
        import resource

        peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024
    attempts = answers.pop("__attempts__", {}) if isinstance(answers, dict) else {}
    if client.dropped:
        hits.append("output")
        notes.append(f"output cap: {client.dropped / 2 ** 20:.1f} MB of output beyond {caps.output / 2 ** 20:g} MB "
                     "were dropped")
    cap_notes(caps, full, hits, notes)
    return dict(status=status, answers=answers, attempts=attempts if isinstance(attempts, dict) else {},
                errors=errors, notes=notes, peak=peak, hits=hits)


def _judge_one(task_id: str, data, student: str, seconds: float) -> dict:
    """One task's verdict, computed in a forked child that is killed after ``seconds`` of CPU time (a
    judge stuck in compiled code, which no alarm interrupts, or one that runs out of memory, costs
    only its task)."""
    from . import check as _check

    r, w = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: judge, write the verdict, leave without cleaning up the parent's state
        code = 0
        try:
            import resource

            os.close(r)
            cpu = max(1, int(seconds))  # CPU seconds: a limit that a loaded machine does not shorten
            resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 1))
            v = _check.check_data(task_id, data, student)
            os.write(w, json.dumps(dict(correct=bool(v.correct), message=v.message, score=float(v.score))).encode())
        except MemoryError:
            code = 3
        except BaseException:
            code = 4
        finally:
            os._exit(code)
    os.close(w)
    chunks, deadline = [], time.monotonic() + 4 * seconds + 10.0  # wall: a backstop for a judge that sleeps
    import select

    while (left := deadline - time.monotonic()) > 0:
        ready, _, _ = select.select([r], [], [], left)
        if not ready:
            break
        chunk = os.read(r, 1 << 16)
        if not chunk:
            break
        chunks.append(chunk)
    os.close(r)
    try:
        os.kill(pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    _, status = os.waitpid(pid, 0)
    try:
        return json.loads(b"".join(chunks))
    except (ValueError, RecursionError):
        exit_code = os.WEXITSTATUS(status) if os.WIFEXITED(status) else None
        if exit_code == 3:
            return dict(correct=False, score=0.0, message="the answer needed more memory than the checker "
                                                          "allows: not graded")
        return dict(correct=False, score=0.0, message=f"the answer took more than {seconds:g} s to check: not graded")


def judge_tasks(answers: dict, lab: str, student: str, seconds: float, report) -> None:
    """Judge every task of ``lab`` on the exported data, each in a child stopped at ``seconds``.

    Parameters
    ----------
    answers : dict
        Variable -> encoded answer (untrusted data).
    lab : str
        The lab.
    student : str
        Whose personal numbers the tasks are judged with.
    seconds : float
        Time for one task; past it the task scores 0 with a message.
    report : callable
        Called with ``{"id", "score", "points", "correct", "message"}`` per task.

    Examples
    --------
    >>> out = []
    >>> judge_tasks({"k_lamp": {"num": "1.0"}}, "lab2", "", 10, out.append)
    >>> out[0]["id"], out[0]["correct"], out[1]["message"]
    ('2.1', False, 'no answer: variable `lever_conditions` is not defined')
    """
    from . import check as _check

    for t in _check.tasks(lab):
        row = dict(id=t.id, score=0.0, points=float(t.points), correct=False)
        if not isinstance(answers, dict) or t.variable not in answers:
            report({**row, "message": f"no answer: variable `{t.variable}` is not defined"})
            continue
        v = _judge_one(t.id, answers[t.variable], student, seconds)
        ok = v.get("correct") is True
        raw = v.get("score")
        score = raw if isinstance(raw, float) else 0.0
        row.update(correct=ok, message=str(v.get("message", "")),
                   score=min(max(score, 0.0), float(t.points)) if ok else 0.0)
        report(row)


def _die_with_parent() -> None:
    """Ask Linux to kill this runner when the grader dies (the kernel then dies with it)."""
    try:
        import ctypes

        ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGKILL)  # PR_SET_PDEATHSIG
    except (OSError, AttributeError):
        pass


def _private_channel():
    """A writer on a duplicate of fd 1 that no child inherits; fd 1 and 2 then go to /dev/null."""
    fd = os.dup(1)  # non-inheritable
    null = os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, 1)
    os.dup2(null, 2)
    os.close(null)
    out = os.fdopen(fd, "w", encoding="utf-8")
    sys.stdout = sys.stderr = open(os.devnull, "w")
    return out


def _fonts(value) -> tuple[str, str] | None:
    """The job's font list as ``(name, text)``, or None."""
    ok = isinstance(value, (list, tuple)) and len(value) == 2 and all(isinstance(v, str) for v in value)
    return (value[0], value[1]) if ok else None


def _grade(job: dict, emit) -> None:
    """Run and judge one notebook (``job``: the command line's options as a dict), reporting by ``emit``."""
    from . import check as _check  # the grader's own checks

    caps = Caps(**job.get("caps", {}))
    if "as_nobody" in job:  # the grader probed the sandbox once for all its runners
        assume_kernel_user(bool(job["as_nobody"]))
    variables = [t.variable for t in _check.tasks(job["lab"])] + ["STUDENT_ID"]
    start = time.monotonic()
    try:
        res = run_notebook(job["notebook"], variables, job["share"], int(job.get("cell_timeout", 60)), caps,
                           not job.get("no_sandbox", False), Cgroup.attach(job.get("cgroup", {})),
                           job.get("notebook_timeout"), _fonts(job.get("fonts")))
    except Exception as e:  # the kernel could not start, the notebook could not be read
        res = dict(status="error", answers={}, attempts={}, errors=[], peak=None, hits=[],
                   notes=[f"the notebook could not be run ({type(e).__name__})"])
    res["seconds"] = round(time.monotonic() - start, 2)
    answers = res.pop("answers")
    declared = answers.pop("STUDENT_ID", None) if isinstance(answers, dict) else None
    res["declared"] = declared.get("str") if isinstance(declared, dict) and isinstance(declared.get("str"), str) \
        else None if declared is None else "(not a string)"
    emit({"run": res})
    judge_tasks(answers, job["lab"], job.get("student", ""), caps.judge_seconds, lambda row: emit({"task": row}))
    emit({"done": True})


def serve(job: dict, conn, cpu_seconds: int) -> None:
    """The runner forked from a pre-imported server (:mod:`multiprocessing` forkserver): limits itself,
    grades ``job`` and sends each report line on ``conn`` (the only channel to the grader).

    Parameters
    ----------
    job : dict
        As :func:`main`'s options.
    conn : multiprocessing.connection.Connection
        Write end of a pipe to the grader.
    cpu_seconds : int
        CPU limit of this process.
    """
    import resource

    os.setsid()
    _die_with_parent()
    caps = Caps(**job.get("caps", {}))
    for name, value in (("RLIMIT_AS", caps.runner_memory), ("RLIMIT_CPU", cpu_seconds),
                        ("RLIMIT_FSIZE", caps.file_size), ("RLIMIT_CORE", 0)):
        try:
            resource.setrlimit(getattr(resource, name), (value, value))
        except (ValueError, OSError):
            pass
    null = os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, 1)
    os.dup2(null, 2)
    os.close(null)
    _grade(job, lambda obj: conn.send_bytes(json.dumps(obj).encode()))
    conn.close()


def main(argv: list[str] | None = None) -> int:
    """Command line (see the module docstring).

    Parameters
    ----------
    argv : list of str, optional

    Returns
    -------
    int
        0 when a report was written.
    """
    ap = argparse.ArgumentParser(prog="python -m balancelab.course.runner")
    ap.add_argument("notebook")
    ap.add_argument("--lab", required=True)
    ap.add_argument("--student", default="")
    ap.add_argument("--share", required=True)
    ap.add_argument("--cell-timeout", type=int, default=60)
    ap.add_argument("--caps", default="{}")
    ap.add_argument("--cgroup", default="{}")
    ap.add_argument("--no-sandbox", action="store_true")
    args = ap.parse_args(argv)
    out = _private_channel()
    _die_with_parent()

    def emit(obj):
        out.write(json.dumps(obj) + "\n")
        out.flush()

    _grade(dict(notebook=args.notebook, lab=args.lab, student=args.student, share=args.share,
                cell_timeout=args.cell_timeout, caps=json.loads(args.caps), cgroup=json.loads(args.cgroup),
                no_sandbox=args.no_sandbox), emit)
    return 0


if __name__ == "__main__":
    sys.exit(main())
