"""Supervise an implementation under test (a *testee*) speaking the JSON
Lines protocol of conformance/PROTOCOL.md.

The testee runs as a child process in its own session (so its whole
process group can be killed), with an address-space limit set through
RLIMIT_AS in the child before it executes (`memory_mb`, default 1 GiB; 0
for none) and core dumps disabled. `Testee.request(obj)` sends one JSON
line and reads one line back within `timeout` seconds. All pipe I/O goes
through one selector with non-blocking descriptors, so a testee that stops
reading, stops writing, floods standard error or writes an endless line can
never block the runner. Standard error is drained in the same loop into a
bounded buffer (the last `stderr_limit` bytes are kept).

A request that does not get a response object raises `TesteeFailure` with
one of four kinds:

- `testee_timeout`: no complete line within the timeout; the process group
  is killed.
- `testee_garbage`: a line that is not JSON, not a response object
  (`ok` true with a `result` object; `ok` false with an `error` string or
  `unsupported: true`), a response followed by more output, output nobody
  asked for, or a line longer than `max_line` bytes.
- `testee_oom`: the testee ended and either its standard error names
  memory exhaustion (Python's MemoryError, C++ std::bad_alloc, "out of
  memory", "Cannot allocate memory", Rust's "memory allocation of N bytes
  failed", ...) or it was killed by SIGKILL that the runner did not send,
  which on Linux is what the kernel's OOM killer does. A SIGSEGV or SIGABRT
  alone is a crash: with an address-space limit a failed allocation shows up
  as one of the messages above in every common runtime, and treating every
  segfault as memory exhaustion would hide real bugs.
- `testee_crash`: the testee ended (closed its output, exited, or was killed
  by a signal) in any other way.

After a failure the process is gone; the next request starts it again and
first asks it for its capabilities, with the start-up allowance, so the
start-up of a restarted testee on a busy machine is not charged to that
request.
When `max_restarts` restarts in a row (default 5) have not produced one
successful response, the next request that needs a restart raises
`TesteeGaveUp` instead. A testee that cannot be started at all raises
`TesteeStartError`. One that starts but gives no response to its first
request fails that request as above; `answered` tells the caller, and the
runner then reports it as not started (runner.start_error).

`close()` (also on garbage collection and at interpreter exit) closes the
testee's input, gives it a moment to exit, then kills its process group.
"""
from __future__ import annotations

import atexit
import json
import os
import re
import selectors
import shlex
import signal
import subprocess
import time
import weakref
from collections.abc import Sequence
from typing import Any

from osdk_conformance.core.priority import keep_priority

TESTEE_CRASH = "testee_crash"
TESTEE_TIMEOUT = "testee_timeout"
STARTUP_SECONDS = 10.0
"""Added to the timeout of the testee's very first request (its start-up)."""
TESTEE_GARBAGE = "testee_garbage"
TESTEE_OOM = "testee_oom"
FAILURE_KINDS = (TESTEE_CRASH, TESTEE_TIMEOUT, TESTEE_GARBAGE, TESTEE_OOM)

DEFAULT_TIMEOUT = 10.0
DEFAULT_MEMORY_MB = 1024
DEFAULT_MAX_RESTARTS = 5

_READ_SIZE = 1 << 20
_CAPABILITIES = b'{"op":"capabilities"}\n'

_EXIT_GRACE = 1.0  # seconds a testee gets to exit after its input is closed
_MEMORY_MESSAGES = re.compile(
    rb"MemoryError|out of memory|cannot allocate memory|bad_alloc|memory allocation of \d+ bytes failed"
    rb"|OutOfMemoryError|failed to allocate|allocation failed|ENOMEM",
    re.IGNORECASE,
)


class TesteeFailure(Exception):
    """One request got no valid response."""

    def __init__(self, kind: str, message: str, stderr: str = "") -> None:
        super().__init__(message)
        self.kind = kind
        self.message = message
        self.stderr = stderr  # the end of what the testee wrote to standard error

    def __str__(self) -> str:
        return f"{self.kind}: {self.message}"


class TesteeGaveUp(Exception):
    """Too many restarts in a row without a successful response."""


class TesteeStartError(Exception):
    """The testee command could not be started at all."""


def split_command(command: str | Sequence[str]) -> list[str]:
    """argv of a testee command: a shell-like string (shlex rules) or a list."""
    if isinstance(command, str):
        try:
            argv = shlex.split(command)
        except ValueError as e:
            raise TesteeStartError(f"cannot split the testee command {command!r}: {e}") from None
    else:
        argv = [str(a) for a in command]
    if not argv:
        raise TesteeStartError("the testee command is empty")
    return argv


def validate_response(obj: Any) -> str | None:
    """Why `obj` is not a protocol response object, or None when it is one."""
    if not isinstance(obj, dict):
        return f"a JSON {type(obj).__name__}, not an object"
    ok = obj.get("ok")
    if ok is True:
        if not isinstance(obj.get("result"), dict):
            return '"ok": true without a "result" object'
        return None
    if ok is False:
        if obj.get("unsupported") is True or isinstance(obj.get("error"), str):
            return None
        return '"ok": false with neither an "error" string nor "unsupported": true'
    return 'no "ok": true or "ok": false'


class _Tail:
    """The last `limit` bytes written to it, and how many were written in all."""

    def __init__(self, limit: int) -> None:
        self.limit = limit
        self.buf = bytearray()
        self.total = 0

    def add(self, data: bytes) -> None:
        self.total += len(data)
        self.buf += data
        if len(self.buf) > self.limit:
            del self.buf[: len(self.buf) - self.limit]

    def text(self, limit: int | None = None) -> str:
        data = bytes(self.buf if limit is None else self.buf[-limit:])
        prefix = "…" if self.total > len(data) else ""
        return prefix + data.decode("utf-8", "replace")


def _preexec(memory_bytes: int):
    def limit() -> None:  # runs in the child between fork and exec
        import resource

        if memory_bytes > 0:
            _, hard = resource.getrlimit(resource.RLIMIT_AS)
            soft = memory_bytes if hard == resource.RLIM_INFINITY else min(memory_bytes, hard)
            resource.setrlimit(resource.RLIMIT_AS, (soft, hard))
        try:
            resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
        except (ValueError, OSError):
            pass
        keep_priority()   # the testee has a session of its own

    return limit


_LIVE: "weakref.WeakSet[Testee]" = weakref.WeakSet()


def _kill_group(proc: subprocess.Popen) -> None:
    """SIGKILL the testee's process group. The testee is not reaped yet (at
    most a zombie), so its pid still names its group: this cannot hit an
    unrelated process."""
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


@atexit.register
def _kill_all() -> None:
    for t in list(_LIVE):
        t.kill()


class Testee:
    """One testee process at a time, restarted on demand after a failure."""

    def __init__(self, command: str | Sequence[str], *, timeout: float = DEFAULT_TIMEOUT,
                 memory_mb: int = DEFAULT_MEMORY_MB, max_restarts: int = DEFAULT_MAX_RESTARTS,
                 cwd: str | os.PathLike | None = None, env: dict[str, str] | None = None,
                 stderr_limit: int = 64 * 1024, max_line: int = 64 * 1024 * 1024) -> None:
        self.argv = split_command(command)
        self.timeout = float(timeout)
        self.memory_bytes = int(memory_mb) * 1024 * 1024
        self.max_restarts = max_restarts
        self.cwd = cwd
        self.env = env
        self.max_line = max_line
        self.stderr = _Tail(stderr_limit)
        self.starts = 0
        self.restarts_in_a_row = 0
        self._proc: subprocess.Popen | None = None
        self._sel: selectors.BaseSelector | None = None
        self._out = bytearray()
        self._killed_by_us = False
        self._stderr_at_start = 0
        self._answered = False   # a response came since the first start
        _LIVE.add(self)

    # ---- life cycle --------------------------------------------------------

    @property
    def running(self) -> bool:
        return self._proc is not None

    @property
    def answered(self) -> bool:
        """Whether any request got a response since the testee was first started."""
        return self._answered

    def start(self) -> None:
        if self._proc is not None:
            return
        try:
            proc = subprocess.Popen(
                self.argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                cwd=self.cwd, env=self.env, bufsize=0, start_new_session=True,
                preexec_fn=_preexec(self.memory_bytes),
            )
        except (OSError, subprocess.SubprocessError) as e:
            detail = e.strerror if isinstance(e, OSError) and e.strerror else str(e)
            raise TesteeStartError(f"cannot start testee {shlex.join(self.argv)}: {detail}") from None
        self.starts += 1
        self._proc = proc
        self._killed_by_us = False
        self._stderr_at_start = self.stderr.total
        self._out = bytearray()
        for f in (proc.stdin, proc.stdout, proc.stderr):
            os.set_blocking(f.fileno(), False)
        sel = selectors.DefaultSelector()
        sel.register(proc.stdout, selectors.EVENT_READ)
        sel.register(proc.stderr, selectors.EVENT_READ)
        self._sel = sel

    def close(self) -> None:
        """Close the testee's input, let it exit for a moment, kill what is left."""
        proc = self._proc
        if proc is None:
            return
        try:
            proc.stdin.close()
        except OSError:
            pass
        deadline = time.monotonic() + _EXIT_GRACE
        while time.monotonic() < deadline and not self._exited():
            self._drain_stderr(0.02)
        self.kill()

    def stop_from_another_thread(self) -> None:
        """Kill the testee's process group and leave the rest to the thread
        using the testee: its request in progress ends as a crash, and that
        thread reaps the process and closes the pipes (doing it here would
        pull them from under its feet)."""
        proc = self._proc
        if proc is None or proc.returncode is not None:
            return
        self._killed_by_us = True
        _kill_group(proc)

    def kill(self) -> None:
        """Kill the testee's process group now and reap the testee."""
        proc = self._proc
        if proc is None:
            return
        self._proc = None
        _kill_group(proc)
        try:
            proc.wait(timeout=5)
        except subprocess.TimeoutExpired:
            pass
        if self._sel is not None:
            self._sel.close()
            self._sel = None
        for f in (proc.stdin, proc.stdout, proc.stderr):
            try:
                f.close()
            except OSError:
                pass

    def __enter__(self) -> "Testee":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def __del__(self) -> None:
        try:
            self.kill()
        except Exception:
            pass

    # ---- requests ----------------------------------------------------------

    def request(self, obj: dict) -> dict:
        """Send one request, return the response object or raise."""
        restarted = False
        if self._proc is None:
            if self.starts:
                if self.restarts_in_a_row >= self.max_restarts:
                    raise TesteeGaveUp(f"the testee failed {self.restarts_in_a_row + 1} times in a row "
                                       f"({self.restarts_in_a_row} restarts without a successful response)")
                self.restarts_in_a_row += 1
                restarted = True
            self.start()
        # the first start, whether this call or the caller started the testee
        first_start = self.starts == 1 and not self._answered
        stderr_before = self.stderr.total
        try:
            if restarted:
                # A restarted testee is first asked for its capabilities with the
                # start-up allowance, so an interpreter or a JVM loading again on
                # a busy machine is not charged to the request that follows,
                # while a testee that keeps hanging on requests still costs the
                # timeout each time.
                try:
                    self._answer(self._exchange(_CAPABILITIES, STARTUP_SECONDS), stderr_before)
                except TesteeFailure as f:
                    f.message = f"restarted, it did not answer the capabilities request: {f.message}"
                    raise
            data = (json.dumps(obj, separators=(",", ":"), allow_nan=False) + "\n").encode()
            # the first request also waits for the start-up
            line = self._exchange(data, STARTUP_SECONDS if first_start else 0.0)
        except TesteeFailure as f:
            f.stderr = f.stderr or self._stderr_since(stderr_before)
            raise
        response = self._answer(line, stderr_before)
        self.restarts_in_a_row = 0
        self._answered = True
        return response

    def _answer(self, line: bytes, stderr_before: int) -> dict:
        """The response object in `line`, or TesteeFailure (garbage)."""
        try:
            response = json.loads(line)
        except (ValueError, RecursionError):
            self.kill()
            raise TesteeFailure(TESTEE_GARBAGE, f"the response is not JSON: {_show(line)}",
                                self._stderr_since(stderr_before)) from None
        problem = validate_response(response)
        if problem:
            self.kill()
            raise TesteeFailure(TESTEE_GARBAGE, f"the response is not a response object ({problem}): {_show(line)}",
                                self._stderr_since(stderr_before))
        return response

    def _stderr_since(self, total_before: int, limit: int = 4096) -> str:
        """What the testee wrote to standard error since `total_before` (its end, at most `limit` bytes)."""
        new = self.stderr.total - total_before
        if new <= 0:
            return ""
        keep = min(new, limit, len(self.stderr.buf))
        text = bytes(self.stderr.buf[-keep:]).decode("utf-8", "replace")
        return ("…" if keep < new else "") + text

    def _exchange(self, data: bytes, startup: float) -> bytes:
        proc, sel = self._proc, self._sel
        assert proc is not None and sel is not None
        deadline = time.monotonic() + self.timeout + startup
        # Output nobody asked for (a second line after the last response, or
        # chatter on stdout) would be taken for this request's answer.
        if self._out or any(key.fileobj is proc.stdout for key, _ in sel.select(0)):
            if not self._read_available(proc.stdout) and not self._out:
                raise self._ended()  # it exited after its last answer
            if self._out:
                extra = bytes(self._out)
                self.kill()
                raise TesteeFailure(TESTEE_GARBAGE, f"output before the request was sent: {_show(extra)}")
        pending = memoryview(data)
        try:
            n = os.write(proc.stdin.fileno(), pending)
            pending = pending[n:]
        except BlockingIOError:
            pass
        except (BrokenPipeError, ConnectionResetError):
            pending = memoryview(b"")  # it is gone; the read side below sees EOF
        if pending:
            sel.register(proc.stdin, selectors.EVENT_WRITE)
        try:
            while True:
                nl = self._out.find(b"\n")
                if nl >= 0:
                    line = bytes(self._out[:nl])
                    rest = bytes(self._out[nl + 1:])
                    del self._out[:nl + 1]
                    if rest.strip():
                        self.kill()
                        raise TesteeFailure(TESTEE_GARBAGE,
                                            f"more than one line in answer to one request: {_show(rest)}")
                    self._out.clear()
                    return line
                if len(self._out) > self.max_line:
                    self.kill()
                    raise TesteeFailure(TESTEE_GARBAGE, f"a response line longer than {self.max_line} bytes")
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    self._killed_by_us = True
                    self.kill()
                    raise TesteeFailure(TESTEE_TIMEOUT, f"no response within {self.timeout:g} s"
                                        + (f" (and {startup:g} s for its start-up)" if startup else ""))
                for key, _ in sel.select(remaining):
                    if key.fileobj is proc.stdin:
                        try:
                            n = os.write(proc.stdin.fileno(), pending)
                            pending = pending[n:]
                        except BlockingIOError:
                            continue
                        except (BrokenPipeError, ConnectionResetError):
                            pending = memoryview(b"")
                        if not pending:
                            sel.unregister(proc.stdin)
                    elif key.fileobj is proc.stdout:
                        if not self._read_available(proc.stdout):
                            raise self._ended()
                    else:
                        self._read_available(proc.stderr)
        finally:
            if self._sel is not None and pending:
                try:
                    self._sel.unregister(proc.stdin)
                except (KeyError, ValueError):
                    pass

    def _read_available(self, f) -> bool:
        """Read what is there; False at end of file."""
        try:
            chunk = os.read(f.fileno(), _READ_SIZE)
        except BlockingIOError:
            return True
        except OSError:
            chunk = b""
        if not chunk:
            if self._sel is not None:  # at end of file it would stay "readable" for ever
                try:
                    self._sel.unregister(f)
                except (KeyError, ValueError):
                    pass
            return False
        if f is self._proc.stdout:
            self._out += chunk
        else:
            self.stderr.add(chunk)
        return True

    def _exited(self) -> bool:
        proc = self._proc
        if proc is None:
            return True
        try:
            info = os.waitid(os.P_PID, proc.pid, os.WEXITED | os.WNOHANG | os.WNOWAIT)
        except ChildProcessError:
            return True
        return info is not None

    def _drain_stderr(self, wait: float) -> None:
        proc, sel = self._proc, self._sel
        if proc is None or sel is None:
            return
        for key, _ in sel.select(wait):
            if key.fileobj is proc.stderr:
                self._read_available(proc.stderr)
            elif key.fileobj is proc.stdout:
                self._read_available(proc.stdout)

    def _ended(self) -> TesteeFailure:
        """The testee closed its output: wait for it, then say how it ended."""
        proc = self._proc
        assert proc is not None
        deadline = time.monotonic() + _EXIT_GRACE
        while not self._exited() and time.monotonic() < deadline:
            self._drain_stderr(0.02)
        exited = self._exited()
        self._drain_stderr(0)
        self.kill()
        rc = proc.returncode
        own = self.stderr.total - self._stderr_at_start  # this process's, not an earlier one's
        err = bytes(self.stderr.buf[-own:]) if own > 0 else b""
        if not exited:
            return TesteeFailure(TESTEE_CRASH, "closed its standard output (killed after "
                                               f"{_EXIT_GRACE:g} s without exiting)")
        if rc is not None and rc < 0:
            try:
                name = signal.Signals(-rc).name
            except ValueError:
                name = f"signal {-rc}"
            if _MEMORY_MESSAGES.search(err):
                return TesteeFailure(TESTEE_OOM, f"killed by {name} after reporting memory exhaustion")
            if -rc == signal.SIGKILL and not self._killed_by_us:
                return TesteeFailure(TESTEE_OOM, "killed by SIGKILL that the runner did not send "
                                                 "(most likely the kernel's out-of-memory killer)")
            return TesteeFailure(TESTEE_CRASH, f"killed by {name}")
        if _MEMORY_MESSAGES.search(err):
            return TesteeFailure(TESTEE_OOM, f"exited with status {rc} after reporting memory exhaustion "
                                             f"(limit {self.memory_bytes >> 20} MiB of address space)")
        return TesteeFailure(TESTEE_CRASH, f"exited with status {rc} without answering")


def _show(data: bytes, limit: int = 200) -> str:
    text = data.decode("utf-8", "replace")
    return repr(text if len(text) <= limit else text[:limit] + "…")
