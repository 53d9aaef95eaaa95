"""Run one measured child process of `osdkc bench`: exit status, output,
wall time and resource usage, with a timeout.

Linux counts the RSS a process had before it called exec into its
ru_maxrss, so a child forked by this (large) Python process would report
this process's tens of MiB as its peak. With `peak_rss`, the child is
started by conformance/baseline's small osdk-peak-rss, which forks the
command itself and writes the command's own wait4 numbers to a file.
"""
from __future__ import annotations

import os
import subprocess
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.paths import ROOT
from osdk_conformance.core.priority import keep_priority

POLL = 0.02  # s between checks for the child's end; the measured numbers come from the child or from rusage
PEAK_RSS_BIN = ROOT / "conformance" / "baseline" / "build" / "osdk-peak-rss"


@dataclass
class Child:
    argv: list[str]
    code: int | None         # None: did not start or was killed at the timeout
    stdout: str
    stderr: str
    wall: float              # s, start to exit
    cpu: float               # s of user + system time, the child and the children it waited for
    maxrss_kib: int          # the largest resident set of the child or one of those children
    problem: str = ""        # why there is no usable exit status

    def stderr_line(self) -> str:
        """The last non-empty line of standard error, for a one-line report."""
        lines = [ln.strip() for ln in self.stderr.splitlines() if ln.strip()]
        return lines[-1] if lines else ""


def kill_group(proc: subprocess.Popen) -> None:
    """SIGKILL the process group `proc` leads (started with process_group=0 or a session
    of its own), so that its helpers go too (gcc's cc1 and as, make's compilers), and reap it."""
    try:
        os.killpg(proc.pid, 9)
    except ProcessLookupError:
        pass
    proc.wait()


def run(argv: list[str], timeout: float, peak_rss: bool = False, env: dict[str, str] | None = None,
        discard_stdout: bool = False) -> Child:
    """`argv` with no input, output to temporary files (no pipe can fill up), reaped with os.wait4.
    `env` is added to this process's environment; `discard_stdout` sends the output to /dev/null
    (a command whose output is the work, timed without keeping a gigabyte of it)."""
    if peak_rss and not PEAK_RSS_BIN.exists():
        raise UsageError(f"{PEAK_RSS_BIN} is missing; run `make setup` (it builds conformance/baseline)")
    with tempfile.TemporaryDirectory(prefix="osdkc-bench-") as tmp:
        usage_file = Path(tmp) / "usage"
        full = [str(PEAK_RSS_BIN), str(usage_file), *argv] if peak_rss else argv
        child = _run(full, timeout, Path(tmp), {**os.environ, **env} if env else None, discard_stdout)
        child.argv = argv
        if peak_rss and child.code is not None:
            try:
                code, rss, cpu = usage_file.read_text().split()
                child.code, child.maxrss_kib, child.cpu = int(code), int(rss), float(cpu)
            except (OSError, ValueError):
                child.problem = f"osdk-peak-rss left no usage ({child.stderr_line() or 'no message'})"
                child.code = None
    return child


def _run(argv: list[str], timeout: float, tmp: Path, env: dict[str, str] | None, discard_stdout: bool) -> Child:
    with open(tmp / "stdout", "w+b") as out, open(tmp / "stderr", "w+b") as err:
        start = time.monotonic()
        try:
            proc = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL if discard_stdout else out,
                                    stderr=err, cwd=ROOT, start_new_session=True, env=env,
                                    preexec_fn=keep_priority)
        except OSError as e:
            return Child(argv, None, "", "", 0.0, 0.0, 0, f"cannot start {argv[0]}: {e.strerror or e}")
        problem = ""
        while True:
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                break
            if time.monotonic() - start > timeout:
                try:
                    os.killpg(proc.pid, 9)   # its own session: the whole group, helpers included
                except ProcessLookupError:
                    pass
                pid, status, usage = os.wait4(proc.pid, 0)
                problem = f"no result within {timeout:g} s (killed)"
                break
            time.sleep(POLL)
        wall = time.monotonic() - start
        proc.returncode = os.waitstatus_to_exitcode(status)   # reaped here; Popen must not wait again
        out.seek(0)
        err.seek(0)
        text_out = out.read().decode("utf-8", "replace")
        text_err = err.read().decode("utf-8", "replace")
    return Child(argv, None if problem else proc.returncode, text_out, text_err, wall,
                 usage.ru_utime + usage.ru_stime, usage.ru_maxrss, problem)
