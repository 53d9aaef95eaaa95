"""`osdkc run`: replay the golden vectors against an implementation under test.

In the manner of protobuf's conformance runner: the implementation (the
*testee*) runs as a child process speaking conformance/PROTOCOL.md, one JSON
request line, one JSON response line, strictly in turn (osdk_conformance.harness.testee
supervises it). The runner asks for its capabilities, replays every vector
whose operation and profile it supports (the others are skipped), judges each
response with `osdk_conformance.harness.vectors.compare`, applies the failure list,
and reports: a summary table on stdout, optionally JUnit XML and HTML
(osdk_conformance.harness.report).

Failure list: a text file with one case id per line, `#` starts a comment.
A listed case that fails is ignored (xfail); a listed case that passes fails
the run (xpass: remove it from the list); a listed id that names no vector is
an error.

Every run prints its coverage: for each operation and profile, how many of
the available cases (those the vector files, --profile and --filter select)
ran and why the others were skipped (operation or profile not claimed,
answered `unsupported`, run aborted or interrupted). The verdict never
claims more than ran (conformance/PROTOCOL.md, "Verdicts and coverage"):

  CONFORMS                       every available case ran and passed    exit 0
  CONFORMS for OPS: N of M cases some were skipped, all that ran passed exit 0
  DOES NOT CONFORM               a case failed, errored or xpassed      exit 1
  (usage or I/O error, or a testee that did not start)                  exit 2
  INTERRUPTED                    SIGINT or SIGTERM; partial reports     exit 130 or 143
  NOTHING RAN                    no case ran at all: no verdict         exit 4

`--vectors` files are validated exactly as `osdkc vectors check` validates
vector files (vectors.load_checked_cases): schema, numberOfTests, ids
unique across every file given, known flags.
"""
from __future__ import annotations

import argparse
import gc
import json
import os
import re
import shlex
import signal
import sys
import threading
import time
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Sequence, TextIO

from osdk_conformance.core.errors import UsageError, cannot_read, exit_status_of_signal
from osdk_conformance.core.options import DEFAULT_JOBS, non_negative_int, positive_float, positive_int
from osdk_conformance.core.paths import CHECKOUT, REPORTS, ROOT, needs_checkout
from osdk_conformance.harness import report, response_schema, vectors
from osdk_conformance.harness.report import ERROR, FAIL, PASS, SKIP, STATUSES, XFAIL, XPASS, Result
from osdk_conformance.reference import accel
from osdk_conformance.harness.testee import DEFAULT_MAX_RESTARTS, DEFAULT_MEMORY_MB, DEFAULT_TIMEOUT, TESTEE_OOM, Testee, TesteeFailure, TesteeGaveUp, TesteeStartError, validate_response

TESTEES = ROOT / "conformance" / "testees"

# The implementations this kit bundles, by the name `--impl` takes: the
# command that starts each (relative paths from the repository root). The
# compiled ones are built by `make setup` (conformance/testees/<lang>/Makefile).
BUNDLED_IMPLS: dict[str, list[str]] = {
    "construct": [sys.executable, str(TESTEES / "construct_testee.py")],
    "kaitai-python": [sys.executable, str(TESTEES / "kaitai_python_testee.py")],
    "js": ["node", str(TESTEES / "javascript" / "testee.js")],
    "java": ["java", "-Xss8m", "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1", "-Xmx256m",
             "-XX:ReservedCodeCacheSize=64m", "-XX:CompressedClassSpaceSize=64m", "-XX:MaxMetaspaceSize=128m",
             "-jar", str(TESTEES / "java" / "target" / "osdk-java-testee.jar")],
    "go": [str(TESTEES / "go" / "bin" / "osdk-go-testee")],
    "c": [str(TESTEES / "c" / "build" / "osdk-c-testee")],
    # the same generated C decoder inside Python: the accelerator `osdkc decode` and the API use
    "accel": [sys.executable, str(TESTEES / "accel_testee.py")],
}
# Implementations on a microcontroller, reached over its UART: the generated
# C library on QEMU's Cortex-M4 (docs/ON-TARGET.md). `--impl c-target` runs
# it; `all` means the host implementations above (a replay over the
# emulated UART takes minutes; the kit runs this one on its own).
BRIDGE = [sys.executable, "-m", "osdk_conformance.board.bridge"]   # a testee on a board's UART
TARGET_IMPLS: dict[str, list[str]] = {
    "c-target": [*BRIDGE, "--qemu", str(TESTEES / "c-target" / "build" / "mps2-an386" / "osdk-c-target.elf")],
}
KNOWN_IMPLS = {**BUNDLED_IMPLS, **TARGET_IMPLS}
ALL = "all"
FAILURE_LISTS = ROOT / "conformance" / "failure_lists"
# What a built implementation needs on disk, and how to get it.
BUILD_HINT = "run `make setup` (it builds every bundled testee)"


def impl_argv(name: str) -> list[str]:
    """The command that runs a bundled implementation."""
    try:
        argv = list(KNOWN_IMPLS[name])
    except KeyError:
        raise UsageError(f"no bundled implementation {name!r} (known: {', '.join(KNOWN_IMPLS)})") from None
    for part in argv[1:] if argv[0] in (sys.executable, "node", "java") else argv[:1]:
        if part.startswith("/") and not Path(part).exists():
            why = needs_checkout(f"the bundled implementation {name!r}")
            why = (f"{why}: clone the repository, run `make setup` there (it builds every bundled testee with "
                   f"its language's toolchain) and `osdkc run --impl {name}` in it, or run your own build with "
                   "`osdkc run --testee CMD`") if why else \
                f"bundled implementation {name!r} is not built ({part} is missing); {BUILD_HINT}"
            raise UsageError(why)
    return argv


def select_cases(cases: Sequence[Any], profiles: Sequence[str] | None, id_part: str | None) -> list[Any]:
    """The cases of `profiles` (all when none; a profile-free case always) whose id contains `id_part`."""
    return [c for c in cases if (not profiles or c.profile is None or c.profile in profiles)
            and (not id_part or id_part in c.id)]


def available_impls() -> tuple[list[str], dict[str, str]]:
    """(implementations to run, {implementation absent: why}). A checkout runs
    every bundled one (a missing build is its failure); an installed package
    has only the Python testees, and the accelerator's only when it was
    compiled at install, and says so rather than failing the others."""
    if CHECKOUT:
        return list(BUNDLED_IMPLS), {}
    absent = {i: needs_checkout("it") for i, argv in BUNDLED_IMPLS.items() if argv[0] != sys.executable}
    if not accel.available():
        absent["accel"] = "the native decoder was not compiled when the package was installed (no C compiler?)"
    return [i for i in BUNDLED_IMPLS if i not in absent], absent


# ---- failure list ----------------------------------------------------------------

def default_failure_list(impl: str) -> Path:
    """A bundled implementation's reviewed failure list, used when present
    (protobuf style: every line names a case and says why it fails)."""
    return FAILURE_LISTS / f"{impl}.txt"


def read_failure_list(path: str | os.PathLike) -> dict[str, int]:
    """case id -> line number, from a failure list file."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as e:
        raise UsageError(cannot_read(path, e, "the failure list")) from None
    out: dict[str, int] = {}
    for n, line in enumerate(text.splitlines(), 1):
        case_id = line.split("#", 1)[0].strip()
        if case_id:
            out.setdefault(case_id, n)
    return out


# ---- progress ----------------------------------------------------------------------

class Progress:
    """A bar on a terminal; otherwise one line per tenth of the run."""

    def __init__(self, total: int, stream: TextIO | None) -> None:
        self.total = max(total, 1)
        self.stream = stream
        self.tty = bool(stream is not None and stream.isatty())
        self.start = time.monotonic()
        self._last_draw = 0.0
        self._next_tenth = 1

    def update(self, done: int, failed: int) -> None:
        if self.stream is None:
            return
        now = time.monotonic()
        if self.tty:
            if now - self._last_draw < 0.1 and done < self.total:
                return
            self._last_draw = now
            width = 30
            fill = int(width * done / self.total)
            self.stream.write(f"\r[{'#' * fill}{'.' * (width - fill)}] {done}/{self.total} "
                              f"{failed} failed  {now - self.start:5.1f} s")
            self.stream.flush()
        elif done * 10 >= self._next_tenth * self.total:
            while done * 10 >= self._next_tenth * self.total:
                self._next_tenth += 1
            self.stream.write(f"osdkc run: {done}/{self.total} cases ({100 * done // self.total}%), "
                              f"{failed} failed, {now - self.start:.1f} s\n")
            self.stream.flush()

    def finish(self) -> None:
        if self.stream is not None and self.tty:
            self.stream.write("\n")
            self.stream.flush()


# ---- one run -----------------------------------------------------------------------

@dataclass
class Capabilities:
    name: str
    operations: frozenset[str]
    profiles: frozenset[str]


def parse_capabilities(response: dict) -> Capabilities:
    """Capabilities from a response, or ValueError saying what is wrong."""
    problem = validate_response(response)
    if problem:
        raise ValueError(problem)
    if response["ok"] is not True:
        raise ValueError(f"capabilities refused: {json.dumps(response)[:200]}")
    res = response["result"]
    ops, profiles = res.get("operations"), res.get("profiles")
    if not (isinstance(ops, list) and all(isinstance(o, str) for o in ops)):
        raise ValueError('"operations" is not a list of strings')
    if not (isinstance(profiles, list) and all(isinstance(p, str) for p in profiles)):
        raise ValueError('"profiles" is not a list of strings')
    return Capabilities(str(res.get("name", "")), frozenset(ops), frozenset(profiles))


def request_of(case: Any) -> dict:
    """The protocol request for a case: op, id, profile (when it has one), then its input."""
    req: dict[str, Any] = {"op": case.operation, "id": case.id}
    if case.profile is not None:
        req["profile"] = case.profile
    req.update(case.input)
    return req


def _case_details(case: Any) -> dict[str, Any]:
    d: dict[str, Any] = {}
    if isinstance(case.input, dict) and isinstance(case.input.get("hex"), str):
        d["hex"] = case.input["hex"]
    others = {k: v for k, v in case.input.items() if k != "hex"} if isinstance(case.input, dict) else case.input
    d["operation"] = case.operation + (f" ({case.profile})" if case.profile else "")
    if others:
        d["input"] = others
    d["expected result"] = case.result
    d["expected"] = case.expected
    return d


def compared_answers(r: Result) -> tuple[Any, Any] | None:
    """For the HTML report: a failed case's expected answer and the testee's,
    as compare() saw them, from the details _case_details and judge wrote
    ("operation" reads "OP (PROFILE)"); None for a case without an answer."""
    d = r.details
    if "expected" not in d or not isinstance(d.get("expected"), dict) or "actual" not in d:
        return None
    operation = str(d.get("operation", "")).split(" ")[0]
    return vectors.compared_answers(operation, str(d.get("expected result")), d["expected"], d["actual"])


def _trailer(case: Any) -> dict[str, Any]:
    d: dict[str, Any] = {}
    if getattr(case, "comment", None):
        d["comment"] = case.comment
    d["flags"] = list(getattr(case, "flags", None) or [])
    if getattr(case, "file", None):
        d["file"] = str(case.file)
    return d


@dataclass
class RunOutcome:
    results: list[Result]
    capabilities: Capabilities | None
    aborted: str | None
    seconds: float
    testee_stderr: str
    interrupted: str | None = None  # the signal that ended the run early ("SIGINT", "SIGTERM")


# Result.kind of a skipped case: why it did not run (the coverage table's words).
NOT_CLAIMED_OP, NOT_CLAIMED_PROFILE, UNSUPPORTED, INTERRUPTED, ABORTED = (
    "op_not_claimed", "profile_not_claimed", "unsupported", "interrupted", "aborted")
SKIP_REASONS = {NOT_CLAIMED_OP: "operation not claimed", NOT_CLAIMED_PROFILE: "profile not claimed",
                UNSUPPORTED: "answered unsupported", INTERRUPTED: "interrupted", ABORTED: "run aborted",
                "no_capabilities": "no capabilities"}
RAN = frozenset({PASS, FAIL, XFAIL, XPASS})  # statuses of a case the testee answered (or failed to)


class Interrupted(BaseException):
    """SIGINT or SIGTERM during a run (raised by SignalStop). A BaseException,
    like KeyboardInterrupt, so that no `except Exception` on the way swallows it."""

    def __init__(self, signame: str) -> None:
        super().__init__(signame)
        self.signame = signame


class SignalStop:
    """While armed, the first SIGINT or SIGTERM raises Interrupted in the main
    thread; later ones (and any after `disarm`) are only noted, so that the
    partial reports get written and the testee's process group is killed
    instead of the runner dying with the testee left behind. Does nothing
    outside the main thread (signal handlers can only be set there)."""

    SIGNALS = (signal.SIGINT, signal.SIGTERM)

    def __init__(self, raises: bool = True) -> None:
        # raises=False: the signal is only noted, for a caller that polls `received`; an exception raised
        # at any point of the main thread could leave a lock of concurrent.futures held (a hang)
        self.raises = raises
        self.armed = False
        self.received: str | None = None
        self._old: dict[int, Any] = {}

    def __enter__(self) -> "SignalStop":
        if threading.current_thread() is threading.main_thread():
            self._old = {s: signal.signal(s, self._handle) for s in self.SIGNALS}
            self.armed = True
        return self

    def _handle(self, signum: int, frame: Any) -> None:
        name = signal.Signals(signum).name
        self.received = self.received or name
        if self.armed and self.raises:
            self.armed = False
            raise Interrupted(name)

    def disarm(self) -> None:
        self.armed = False

    def __exit__(self, *exc: object) -> None:
        self.armed = False
        for s, old in self._old.items():
            signal.signal(s, old)


def _not_run(case: Any, kind: str, why: str) -> Result:
    """A case that did not run: skipped when nothing is known against the
    testee (interrupted), an error when the testee stopped the run (aborted)."""
    return Result(case.category, case.id, ERROR if kind == ABORTED else SKIP, f"not run: {why}", kind=kind)


def judge(case: Any, response: dict, compare: Callable[[Any, dict], tuple[bool, str]], seconds: float) -> Result:
    """The result of one answered case."""
    if response.get("ok") is False and response.get("unsupported") is True:
        return Result(case.category, case.id, SKIP, "the testee answered unsupported", kind=UNSUPPORTED,
                      seconds=seconds)
    try:
        passed, reason = compare(case, response)
    except Exception as e:  # a judge that chokes on an answer is a failed case, not a crash
        passed, reason = False, f"the response could not be compared ({type(e).__name__}: {e})"
    problem = response_schema.case_violation(case, response, passed)
    if passed and problem is None:
        return Result(case.category, case.id, PASS, seconds=seconds)
    details = _case_details(case)
    details["actual"] = response
    details.update(_trailer(case))
    if problem is not None:  # its own failure class: the response breaks conformance/schemas/
        reason = f"schema violation at {problem}" + ("" if passed else f" (and: {reason})")
        return Result(case.category, case.id, FAIL, reason, details, kind=response_schema.SCHEMA_VIOLATION,
                      seconds=seconds)
    return Result(case.category, case.id, FAIL, reason, details, kind="mismatch", seconds=seconds)


def run_one(testee: Testee, case: Any, compare: Callable[[Any, dict], tuple[bool, str]]) -> Result:
    """Send one case, judge the answer; TesteeGaveUp passes through."""
    t0 = time.perf_counter()
    try:
        response = testee.request(request_of(case))
    except TesteeFailure as f:
        details = _case_details(case)
        details["actual"] = str(f)
        if f.stderr:
            details["stderr"] = f.stderr
        details.update(_trailer(case))
        return Result(case.category, case.id, FAIL, f.message, details, kind=f.kind,
                      seconds=time.perf_counter() - t0)
    return judge(case, response, compare, time.perf_counter() - t0)


def unclaimed(case: Any, caps: Capabilities) -> Result | None:
    """The skip result of a case whose operation or profile the testee does not claim."""
    if case.operation not in caps.operations:
        return Result(case.category, case.id, SKIP, f"the testee does not support {case.operation}",
                      kind=NOT_CLAIMED_OP)
    if case.profile is not None and case.profile not in caps.profiles:
        return Result(case.category, case.id, SKIP, f"the testee does not support profile {case.profile}",
                      kind=NOT_CLAIMED_PROFILE)
    return None


# What a JVM writes (to standard output) when it cannot reserve its heap or
# code cache under the address-space limit; it exits with status 1, which
# alone says nothing of memory.
_JVM_RESERVE = re.compile(r"Error occurred during initialization of VM|Could not reserve enough space"
                          r"|insufficient memory for the Java Runtime")
_STDERR_LINES = 3    # the end of a traceback: the failing line and the exception
_STDERR_CHARS = 400


def start_error(testee: Testee, f: TesteeFailure) -> TesteeStartError:
    """The one-line error for a testee that gave no response to its first
    request (it exited, hung or wrote something else): it did not start (a
    missing module, a bad path, a VM that could not reserve its memory), and
    nothing can be said of its conformance."""
    lines = [line.strip() for line in f.stderr.splitlines() if line.strip()][-_STDERR_LINES:]
    tail = " | ".join(lines)
    if len(tail) > _STDERR_CHARS:
        tail = "…" + tail[-_STDERR_CHARS:]
    said = f"; its standard error ends: {tail}" if tail else "; it wrote nothing to standard error"
    jvm = bool(_JVM_RESERVE.search(f.message) or _JVM_RESERVE.search(f.stderr))
    hint = ""
    if testee.memory_bytes and (f.kind == TESTEE_OOM or jvm):
        hint = (f" (it runs with a limit of {testee.memory_bytes >> 20} MiB of address space"
                + (", less than this JVM reserves at start" if jvm else "")
                + ": try a larger --memory-mb, or 0 for no limit)")
    return TesteeStartError(f"testee {shlex.join(testee.argv)} did not start: no response to its first request "
                            f"(capabilities): {f.message}{hint}{said}")


def ask_capabilities(testee: Testee) -> tuple[Capabilities | None, Result | None]:
    """The testee's capabilities, or the failed result saying why there are
    none; usable capabilities in a response that breaks its schema come with
    a failed result of kind schema_violation (the run goes on). A testee
    that has never given a response raises TesteeStartError (start_error)."""
    try:
        response = testee.request({"op": "capabilities"})
        caps = parse_capabilities(response)
        problem = response_schema.violation("capabilities", None, response)
        return caps, (Result("capabilities", "capabilities", FAIL, f"schema violation at {problem}",
                             {"actual": response}, kind=response_schema.SCHEMA_VIOLATION) if problem else None)
    except TesteeFailure as f:
        if not testee.answered:
            raise start_error(testee, f) from None
        return None, Result("capabilities", "capabilities", FAIL, f"the testee did not answer capabilities: {f}",
                            {"stderr": f.stderr} if f.stderr else {}, kind=f.kind)
    except ValueError as e:
        return None, Result("capabilities", "capabilities", FAIL, f"the capabilities answer is not usable: {e}",
                            kind="testee_garbage")


def run_cases(testee: Testee, cases: Sequence[Any], compare: Callable[[Any, dict], tuple[bool, str]],
              progress: Progress | None = None) -> RunOutcome:
    """Ask for capabilities, then replay `cases` (without failure-list
    handling). `cases` is iterated once, in order. An Interrupted raised
    while it runs (SignalStop) ends the run: every case not yet judged is
    recorded as skipped, kind "interrupted", and the outcome names the
    signal."""
    start = time.monotonic()
    results: list[Result] = []
    aborted: str | None = None
    interrupted: str | None = None
    caps: Capabilities | None = None
    pending = iter(cases)
    case = None
    try:
        caps, problem = ask_capabilities(testee)
        if caps is None:
            results.append(problem)
            return RunOutcome(results, None, problem.message, time.monotonic() - start, testee.stderr.text())
        if problem is not None:
            results.append(problem)
        failed = 0
        for n, case in enumerate(pending):
            result = _not_run(case, ABORTED, aborted) if aborted is not None else unclaimed(case, caps)
            if result is None:
                try:
                    result = run_one(testee, case, compare)
                except TesteeGaveUp as g:
                    aborted = str(g)
                    result = _not_run(case, ABORTED, aborted)
            results.append(result)  # the one append per case: an interrupt lands before or after it
            if result.status == FAIL:
                failed += 1
            if progress is not None and result.kind not in (NOT_CLAIMED_OP, NOT_CLAIMED_PROFILE, ABORTED):
                progress.update(n + 1, failed)
    except Interrupted as i:
        interrupted = i.signame
        if case is not None and (not results or results[-1].id != case.id):
            results.append(_not_run(case, INTERRUPTED, f"interrupted ({interrupted})"))
        results += [_not_run(c, INTERRUPTED, f"interrupted ({interrupted})") for c in pending]
    if progress is not None:
        progress.finish()
    return RunOutcome(results, caps, aborted, time.monotonic() - start, testee.stderr.text(4096), interrupted)


def apply_failure_list(results: list[Result], listed: dict[str, int], known_ids: set[str],
                       list_name: str) -> list[Result]:
    """xfail/xpass for listed cases, and an error for every listed id that is no vector."""
    out = []
    for r in results:
        if r.id in listed and r.status == FAIL:
            r = Result(r.category, r.id, XFAIL, r.message, r.details, r.kind, r.seconds)
        elif r.id in listed and r.status == PASS:
            r = Result(r.category, r.id, XPASS,
                       f"passes, but is listed in the failure list ({list_name} line {listed[r.id]}): "
                       "remove it from the list", kind="unexpected_pass", seconds=r.seconds)
        out.append(r)
    for case_id, line in listed.items():
        if case_id not in known_ids:
            out.append(Result("failure_list", case_id, ERROR,
                              f"{list_name} line {line}: {case_id!r} is not the id of any vector",
                              kind="unknown_id"))
    return out


# ---- coverage and verdict ------------------------------------------------------------

EXIT_NOTHING_RAN = 4  # no case ran, so there is nothing to base a verdict on


@dataclass
class CoverageRow:
    """The available cases of one operation and profile, and what became of them."""
    operation: str
    profile: str | None
    available: int = 0
    ran: int = 0
    skipped: Counter = field(default_factory=Counter)  # why (SKIP_REASONS words) -> cases

    def as_json(self) -> dict:
        return {"operation": self.operation, "profile": self.profile, "available": self.available,
                "ran": self.ran, "skipped": dict(sorted(self.skipped.items()))}


def coverage(cases: Sequence[Any], results: Sequence[Result], no_result: str) -> list[CoverageRow]:
    """Cases run / available by operation and profile. A case that ran is one
    the testee was asked and answered or failed to answer (pass, fail, xfail,
    xpass); `no_result` is why a case without any result did not run."""
    by_id = {r.id: r for r in results}
    rows: dict[tuple[str, str], CoverageRow] = {}
    for case in cases:
        row = rows.setdefault((case.operation, case.profile or ""), CoverageRow(case.operation, case.profile))
        row.available += 1
        r = by_id.get(case.id)
        if r is not None and r.status in RAN:
            row.ran += 1
        else:
            row.skipped[no_result if r is None else SKIP_REASONS.get(r.kind, r.kind or r.status)] += 1
    return [rows[k] for k in sorted(rows)]


def coverage_table(rows: Sequence[CoverageRow]) -> str:
    """operation x profile: run / available (skipped why), and the total."""
    op_w = max([len("operation"), *(len(r.operation) for r in rows)])
    pr_w = max([len("profile"), *(len(r.profile or "-") for r in rows)])
    ran, available = sum(r.ran for r in rows), sum(r.available for r in rows)
    num_w = len(f"{available:,}")
    head = f"{'operation':<{op_w}}  {'profile':<{pr_w}}  {'ran':>{num_w}} / {'available':<{max(num_w, 9)}}  skipped"
    lines = [head, "-" * len(head)]
    for r in rows:
        why = ", ".join(f"{n:,} {reason}" for reason, n in sorted(r.skipped.items()))
        lines.append(f"{r.operation:<{op_w}}  {r.profile or '-':<{pr_w}}  {r.ran:>{num_w},} / "
                     f"{r.available:<{max(num_w, 9)},}  {why}".rstrip())
    lines.append("-" * len(head))
    lines.append(f"{'total':<{op_w}}  {'':<{pr_w}}  {ran:>{num_w},} / {available:<{max(num_w, 9)},}".rstrip())
    return "\n".join(lines)


def coverage_html(rows: Sequence[CoverageRow]) -> str:
    import html

    out = ["<h2>Coverage: cases run out of cases available</h2><table><thead><tr><th>operation</th>"
           "<th>profile</th><th>ran</th><th>available</th><th>skipped (why)</th></tr></thead><tbody>"]
    for r in rows:
        why = ", ".join(f"{n:,} {reason}" for reason, n in sorted(r.skipped.items()))
        cls = ' class="good"' if r.ran == r.available else (' class="bad"' if not r.ran else "")
        out.append(f"<tr><td>{html.escape(r.operation)}</td><td>{html.escape(r.profile or '-')}</td>"
                   f"<td{cls}>{r.ran:,}</td><td>{r.available:,}</td><td>{html.escape(why)}</td></tr>")
    out.append(f"<tr><td>total</td><td></td><td>{sum(r.ran for r in rows):,}</td>"
               f"<td>{sum(r.available for r in rows):,}</td><td></td></tr></tbody></table>")
    return "".join(out)


@dataclass
class Verdict:
    word: str       # CONFORMS, DOES NOT CONFORM, INTERRUPTED or NOTHING RAN
    line: str       # the word and what it covers, as printed
    exit: int
    conforms: bool  # all that ran passed (every available case, or some: see `complete`)
    complete: bool  # every available case ran


def verdict_of(results: Sequence[Result], rows: Sequence[CoverageRow], interrupted: str | None) -> Verdict:
    """The verdict, never claiming more than ran (PROTOCOL.md, "Verdicts and coverage")."""
    ran, available = sum(r.ran for r in rows), sum(r.available for r in rows)
    complete = ran == available
    failed = sum(r.status in report.BAD and r.kind != ABORTED for r in results)  # not-run cases are no failures
    known = sum(r.status == XFAIL for r in results)
    of = f"{ran:,} of {available:,} cases ran"
    if interrupted:
        line = f"INTERRUPTED by {interrupted}: no verdict ({of}" + (f"; {failed:,} failed so far)" if failed else ")")
        return Verdict("INTERRUPTED", line, exit_status_of_signal(interrupted), False, False)
    if not report.conforms(results):
        return Verdict("DOES NOT CONFORM", f"DOES NOT CONFORM ({failed:,} failed; {of})", 1, False, complete)
    if ran == 0:
        return Verdict("NOTHING RAN", f"NOTHING RAN: no verdict ({of}; see the coverage table)",
                       EXIT_NOTHING_RAN, False, False)
    listed = f", {known:,} known failures in the failure list" if known else ""
    if complete:
        return Verdict("CONFORMS", f"CONFORMS: all {available:,} cases{listed}", 0, True, True)
    by_op: dict[str, list[int]] = {}
    for r in rows:
        counts = by_op.setdefault(r.operation, [0, 0])
        counts[0] += r.ran
        counts[1] += r.available
    scope = ", ".join(op if n == a else f"{op} ({n:,} of {a:,})" for op, (n, a) in by_op.items() if n)
    return Verdict("CONFORMS", f"CONFORMS for {scope}: {ran:,} of {available:,} cases{listed}", 0, True, False)


def no_result_reason(outcome: RunOutcome) -> str:
    """Why a case has no result at all (the run ended before the cases)."""
    if outcome.interrupted:
        return SKIP_REASONS[INTERRUPTED]
    return SKIP_REASONS["no_capabilities"] if outcome.capabilities is None else SKIP_REASONS[ABORTED]


# ---- the command -------------------------------------------------------------------

def _check_writable(path: str | None, option: str) -> None:
    if path is None:
        return
    parent = Path(path).resolve().parent
    if not parent.is_dir():
        raise UsageError(f"{option} {path}: directory {parent} does not exist")
    if Path(path).is_dir():
        raise UsageError(f"{option} {path}: is a directory")
    if not os.access(parent, os.W_OK):
        raise UsageError(f"{option} {path}: directory {parent} is not writable")


def _load_cases(paths: list[str] | None):
    """The cases, validated (vectors.load_checked_cases), and the judge."""
    try:
        cases = vectors.load_checked_cases(paths or None)
    except UsageError:
        raise
    except Exception as e:  # a bad vector file is the user's input, not our crash
        raise UsageError(f"cannot load the vectors: {type(e).__name__}: {e}") from None
    # The vectors are millions of objects that live as long as the run. Each
    # full collection of the cyclic GC would walk them all again (a Ctrl-C's
    # 35,000 skipped results alone set off enough of them to take 0.3 s):
    # frozen, the collector leaves them out. Freezing only hides them from
    # the cycle collector: they hold no cycles, and reference counting frees
    # them when the run (or the kit's next run) lets go of them.
    gc.freeze()
    return cases, vectors.compare


def _print_failures(results: Sequence[Result], out: TextIO, limit: int = 30) -> None:
    bad = [r for r in results if r.status in report.BAD and r.kind != "aborted"]
    for r in bad[:limit]:
        first = r.message.splitlines()[0] if r.message else ""
        kind = f" [{r.kind}]" if r.kind and r.kind not in ("mismatch",) else ""
        out.write(f"  {r.status.upper():5} {r.id}{kind}: {first[:300]}\n")
    if len(bad) > limit:
        out.write(f"  … and {len(bad) - limit} more (see --junit / --html reports)\n")


def replay(argv: list[str], cases: Sequence[Any], compare, timeout: float, memory_mb: int,
           progress: Progress | None, max_restarts: int = DEFAULT_MAX_RESTARTS) -> tuple[RunOutcome, list[str]]:
    """Start the testee and run the cases; SIGINT or SIGTERM end the run early
    (recorded in the outcome) and the testee's process group is killed
    whatever happens. Returns the outcome and the testee's argv."""
    try:
        testee = Testee(argv, timeout=timeout, memory_mb=memory_mb, max_restarts=max_restarts)
    except TesteeStartError as e:
        raise UsageError(str(e)) from None
    outcome: RunOutcome | None = None
    with SignalStop() as stop:
        try:
            try:
                testee.start()
                outcome = run_cases(testee, cases, compare, progress)
            except TesteeStartError as e:
                raise UsageError(str(e)) from None
        except Interrupted as i:  # before the first request (nothing ran) or just after the last
            outcome = outcome or RunOutcome([], None, None, 0.0, "", i.signame)
        finally:
            stop.disarm()  # from here on a signal is only noted: the reports get written
            testee.close()
        if outcome.interrupted is None and stop.received:
            outcome.interrupted = stop.received  # it came after the last case
    return outcome, testee.argv


def run_command(args: argparse.Namespace) -> int:
    _check_writable(args.junit, "--junit")
    _check_writable(args.html, "--html")
    if args.impl and (len(args.impl) > 1 or ALL in args.impl):
        return run_all(args, [i for i in KNOWN_IMPLS if (ALL in args.impl and i in BUNDLED_IMPLS) or i in args.impl])
    args.impl = args.impl[0] if args.impl else None
    _check_writable(args.summary_json, "--summary-json")
    if args.testee_port:
        argv = [*BRIDGE, "--port", args.testee_port, "--baud", str(args.baud)]
    else:
        argv = impl_argv(args.impl) if args.impl else args.testee
    if args.failure_list is None and args.impl and default_failure_list(args.impl).exists():
        args.failure_list = str(default_failure_list(args.impl))
    listed = read_failure_list(args.failure_list) if args.failure_list else {}

    all_cases, compare = _load_cases(args.vectors)
    known_ids = {c.id for c in all_cases}
    cases = select_cases(all_cases, args.profile, args.filter)
    if not cases:
        raise UsageError("no vector matches the --profile / --filter selection")

    timeout = args.timeout if args.timeout is not None else DEFAULT_TIMEOUT
    memory_mb = args.memory_mb if args.memory_mb is not None else DEFAULT_MEMORY_MB
    progress = Progress(len(cases), None if args.no_progress else sys.stderr)
    outcome, testee_argv = replay(argv, cases, compare, timeout, memory_mb, progress)

    list_name = str(args.failure_list) if args.failure_list else "failure list"
    results = apply_failure_list(outcome.results, listed, known_ids, list_name)
    name = outcome.capabilities.name if outcome.capabilities and outcome.capabilities.name else " ".join(
        testee_argv)
    rows = coverage(cases, results, no_result_reason(outcome))
    verdict = verdict_of(results, rows, outcome.interrupted)

    out = sys.stdout
    out.write(f"osdkc run: {name}: {len(cases):,} cases in {outcome.seconds:.1f} s\n\n")
    out.write(report.summary_table(results) + "\n\n")
    out.write("coverage (cases run / available):\n" + coverage_table(rows) + "\n\n")
    kinds: dict[str, int] = {}
    for r in results:
        if r.status in (FAIL, XFAIL) and r.kind and r.kind != "mismatch":
            kinds[r.kind] = kinds.get(r.kind, 0) + 1
    if kinds:
        out.write("testee failures: " + ", ".join(f"{k} {v}" for k, v in sorted(kinds.items())) + "\n")
    if outcome.aborted:
        out.write(f"run aborted: {outcome.aborted}\n")
    if not report.conforms(results):
        _print_failures(results, out)
    meta = {
        "testee": name,
        "command": " ".join(testee_argv),
        "verdict": verdict.line,
        "cases": str(len(cases)),
        "coverage": f"{sum(r.ran for r in rows):,} of {sum(r.available for r in rows):,} cases ran",
        "duration": f"{outcome.seconds:.1f} s",
        "timeout per request": f"{timeout:g} s",
        "memory limit": f"{memory_mb} MiB" if memory_mb else "none",
    }
    if args.failure_list:
        meta["failure list"] = f"{args.failure_list} ({len(listed)} ids)"
    if args.filter or args.profile:
        meta["selection"] = " ".join(filter(None, [f"--filter {args.filter}" if args.filter else "",
                                                   *(f"--profile {p}" for p in args.profile or [])]))
    if outcome.aborted:
        meta["aborted"] = outcome.aborted
    if outcome.interrupted:
        meta["interrupted"] = f"by {outcome.interrupted}: the reports are partial"
    try:
        if args.junit:
            per_row = {f"coverage {r.operation} {r.profile or '-'}":
                       f"{r.ran} / {r.available}" + "".join(f"; {n} {why}" for why, n in sorted(r.skipped.items()))
                       for r in rows}
            report.write_junit(args.junit, results, f"osdkc run: {name}", properties={**meta, **per_row})
        if args.html:
            appendix = {"testee standard error (end)": outcome.testee_stderr} if outcome.testee_stderr else None
            report.write_html(args.html, results, f"OPEN protocol conformance: {name}", meta, appendix=appendix,
                              extra_html=coverage_html(rows), verdict=(verdict.line, verdict.conforms),
                              diff=compared_answers)
        if args.summary_json:
            summary = {"impl": args.impl, "testee": name, "command": " ".join(testee_argv),
                       "cases": len(cases), "seconds": round(outcome.seconds, 1),
                       "statuses": {st: sum(r.status == st for r in results) for st in STATUSES},
                       "failure_list": args.failure_list, "conforms": verdict.conforms,
                       "complete": verdict.complete, "verdict": verdict.word, "verdict_line": verdict.line,
                       "interrupted": outcome.interrupted,
                       "coverage": {"ran": sum(r.ran for r in rows), "available": sum(r.available for r in rows),
                                    "rows": [r.as_json() for r in rows]}}
            Path(args.summary_json).write_text(json.dumps(summary, indent=1) + "\n")
    except OSError as e:
        raise UsageError(f"cannot write a report: {e.strerror or e}") from None
    out.write(f"{verdict.line}\n")
    out.flush()
    return verdict.exit


RUN_EPILOG = """\
Every run prints its coverage (cases run / available by operation and
profile, and why the others were skipped) and one verdict line:
  CONFORMS: all M cases                  every available case ran and passed
  CONFORMS for OPS: N of M cases         some were skipped; all that ran passed
  DOES NOT CONFORM (...)                 a case failed, or an error
  NOTHING RAN: no verdict (...)          no case ran (nothing claimed, or all unsupported)
  INTERRUPTED by SIG...: no verdict      SIGINT/SIGTERM: partial reports written
Exit status: 0 CONFORMS (all or some), 1 DOES NOT CONFORM, 2 usage or I/O
error, or a testee that did not start (no response to its first request: it
exited, hung or wrote something else), 4 NOTHING RAN, 130 interrupted by
SIGINT, 143 by SIGTERM.
--vectors files are validated as `osdkc vectors check` does (schema,
numberOfTests, ids unique across the files, known flags).
See conformance/PROTOCOL.md, "Verdicts and coverage"."""


def add_arguments(p: argparse.ArgumentParser, profiles: Sequence[str]) -> None:
    p.epilog = RUN_EPILOG
    p.formatter_class = argparse.RawDescriptionHelpFormatter
    which = p.add_mutually_exclusive_group(required=True)
    which.add_argument("--testee", metavar="COMMAND",
                       help="command that starts the implementation under test (split like a shell does)")
    which.add_argument("--impl", action="append", choices=[*KNOWN_IMPLS, ALL], metavar="IMPL",
                       help=f"a bundled implementation ({', '.join(BUNDLED_IMPLS)}; on an emulated board: "
                            f"{', '.join(TARGET_IMPLS)}), or {ALL} for every one on this host; "
                            "repeatable: more than one run side by side, reports in --report-dir")
    which.add_argument("--testee-port", metavar="PORT",
                       help="a board on this serial port running the on-target testee (docs/ON-TARGET.md)")
    p.add_argument("--profile", action="append", choices=profiles, metavar="PROFILE",
                   help=f"only this profile (repeatable; one of {', '.join(profiles)}); "
                        "cases without a profile always run")
    p.add_argument("--failure-list", metavar="FILE",
                   help="case ids expected to fail, one per line, # comments")
    p.add_argument("--junit", metavar="FILE", help="write a JUnit XML report")
    p.add_argument("--html", metavar="FILE", help="write a self-contained HTML report")
    p.add_argument("--timeout", type=positive_float, metavar="S", help=f"seconds per request (default {DEFAULT_TIMEOUT:g})")
    p.add_argument("--memory-mb", type=non_negative_int, metavar="N",
                   help=f"address-space limit of the testee in MiB (default {DEFAULT_MEMORY_MB}; 0 for none; "
                        "a JVM needs more than the default)")
    p.add_argument("--filter", metavar="SUBSTRING", help="only cases whose id contains SUBSTRING")
    p.add_argument("--vectors", action="append", metavar="FILE",
                   help="vector file(s) to use instead of vectors/*.json (repeatable)")
    p.add_argument("-q", "--quiet", dest="no_progress", action="store_true",
                   help="no progress output on stderr")
    # the former spelling, still accepted; -q/--quiet is the one every command shares
    p.add_argument("--no-progress", dest="no_progress", action="store_true", help=argparse.SUPPRESS)
    p.add_argument("--summary-json", metavar="FILE", help="write the run's counts and verdict as JSON")
    p.add_argument("--report-dir", metavar="DIR", default=str(REPORTS),
                   help="with --impl all: where each implementation's JUnit, HTML, log and summary go, "
                        "and conformance.json (default: reports/)")
    p.add_argument("--baud", type=positive_int, metavar="B", default=115200,
                   help="with --testee-port: the port's rate (default 115200)")
    p.add_argument("--jobs", type=positive_int, metavar="N", default=DEFAULT_JOBS,
                   help="with --impl all: implementations run at once (default: the number of CPUs)")


# ---- every bundled implementation ---------------------------------------------------

def _forwarded(args: argparse.Namespace) -> list[str]:
    """The options of this run that each per-implementation run repeats."""
    out: list[str] = []
    for p in args.profile or []:
        out += ["--profile", p]
    for v in args.vectors or []:
        out += ["--vectors", v]
    if args.filter:
        out += ["--filter", args.filter]
    if args.timeout is not None:
        out += ["--timeout", str(args.timeout)]
    if args.memory_mb is not None:
        out += ["--memory-mb", str(args.memory_mb)]
    return out


def status_table(summaries: list[dict]) -> str:
    cols = ("pass", "fail", "xfail", "xpass", "skip", "error")
    head = f"{'implementation':<15} {'cases':>6} " + " ".join(f"{c:>6}" for c in cols) + f" {'seconds':>8}  verdict"
    lines = [head, "-" * len(head)]
    for s in summaries:
        st = s.get("statuses") or {}
        verdict = s.get("problem") or s.get("verdict") or "DOES NOT CONFORM"
        cov = s.get("coverage") or {}
        if s.get("conforms") and not s.get("complete") and cov:
            verdict += f" for {cov['ran']:,} of {cov['available']:,} cases"
        lines.append(f"{s['impl']:<15} {s.get('cases', 0):>6} " + " ".join(f"{st.get(c, 0):>6}" for c in cols)
                     + f" {s.get('seconds', 0):>8.1f}  {verdict}")
    return "\n".join(lines)


_PROGRESS_LINE = re.compile(r"osdkc run: ([\d,]+)/([\d,]+) cases")


PROGRESS_EVERY_ENV = "OSDKC_PROGRESS_EVERY"


def progress_every(default: float = 10.0) -> float:
    """Seconds between progress lines off a terminal: OSDKC_PROGRESS_EVERY
    where a CI log wants them closer or further apart, else `default`."""
    try:
        every = float(os.environ.get(PROGRESS_EVERY_ENV, default))
    except ValueError:
        return default
    return every if every > 0 else default


class StatusLine:
    """A progress line: rewritten in place on a terminal (at most twice a
    second), otherwise written as a new line when something changed or at
    least every `every` seconds (progress_every()); nothing without a stream."""

    def __init__(self, stream: TextIO | None, every: float | None = None) -> None:
        self.stream, self.every = stream, progress_every() if every is None else every
        self.tty = bool(stream is not None and stream.isatty())
        self.start = self.last = time.monotonic()

    def due(self, changed: bool = False, final: bool = False) -> bool:
        if self.stream is None:
            return False
        since = time.monotonic() - self.last
        return final or changed or since >= (0.5 if self.tty else self.every)

    def write(self, line: str, final: bool = False) -> None:
        assert self.stream is not None
        self.last = time.monotonic()
        if self.tty:
            self.stream.write("\r\x1b[K" + line[:200] + ("\n" if final else ""))
        else:
            self.stream.write(line + "\n")
        self.stream.flush()

    def seconds(self) -> float:
        return time.monotonic() - self.start


class _Heartbeat:
    """What `run --impl all` is doing: the implementations done, and the cases
    done by each running one (the last progress line in its log), on a
    StatusLine (also when one finishes)."""

    def __init__(self, out_dir: Path, impls: Sequence[str], stream: TextIO | None) -> None:
        self.out_dir, self.impls = out_dir, impls
        self.line = StatusLine(stream)
        self.done_before = 0
        self.final = False

    def _cases(self, impl: str) -> str:
        try:
            text = (self.out_dir / f"{impl}.log").read_text(errors="replace")
        except OSError:
            return "starting"
        found = _PROGRESS_LINE.findall(text)
        return f"{found[-1][0]}/{found[-1][1]}" if found else "starting"

    def show(self, done: dict[str, bool], final: bool = False) -> None:
        self.final = self.final or final
        finished = sum(done.values())
        if not self.line.due(changed=finished != self.done_before, final=final):
            return
        self.done_before = finished
        running = ", ".join(f"{impl} {self._cases(impl)}" for impl in self.impls if not done[impl])
        self.line.write(f"osdkc run: {finished}/{len(self.impls)} implementations done, {self.line.seconds():.0f} s"
                        + (f"; running: {running}" if running else ""), final)


def run_all(args: argparse.Namespace, chosen: Sequence[str]) -> int:
    """The `chosen` bundled implementations (--impl all: every one), `--jobs` at a time, each in its own
    `osdkc run` process (the runner's judging is CPU-bound Python, so
    processes, not threads, use the cores). One table at the end; each
    run's JUnit, HTML, log and summary in --report-dir, and
    conformance.json with every summary (generated/README.md's status is
    rendered from it)."""
    if args.testee or args.failure_list or args.junit or args.html or args.summary_json:
        raise UsageError("more than one --impl (or all) writes its reports to --report-dir; --failure-list, "
                         "--junit, --html and --summary-json apply to a single implementation")
    if args.jobs < 1:
        raise UsageError("--jobs must be at least 1")
    out_dir = Path(args.report_dir)
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise UsageError(f"--report-dir {out_dir}: {e.strerror or e}") from None
    import subprocess
    from concurrent.futures import ThreadPoolExecutor, wait

    lock = threading.Lock()
    live: dict[str, subprocess.Popen] = {}
    stopping: list[str] = []  # the signal that ended the run, once one has

    def one(impl: str) -> dict:
        summary_path = out_dir / f"{impl}.json"
        summary_path.unlink(missing_ok=True)
        # its progress lines (a tenth of the run each) go to its log, where the heartbeat below reads them
        cmd = [sys.executable, "-m", "osdk_conformance.cli", "run", "--impl", impl,
               "--junit", str(out_dir / f"{impl}.xml"), "--html", str(out_dir / f"{impl}.html"),
               "--summary-json", str(summary_path), *_forwarded(args)]
        with open(out_dir / f"{impl}.log", "w", encoding="utf-8") as log:
            with lock:  # no new run once a signal is being passed on
                if stopping:
                    return {"impl": impl, "conforms": False, "problem": f"not run: interrupted by {stopping[0]}"}
                live[impl] = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
            code = live[impl].wait()
        try:
            summary = json.loads(summary_path.read_text())
        except (OSError, ValueError):
            last = (out_dir / f"{impl}.log").read_text(errors="replace").strip().splitlines()[-1:]
            summary = {"impl": impl, "conforms": False, "problem": f"exit {code}: {last[0] if last else 'no output'}"}
        summary["exit"] = code
        return summary

    present, absent = available_impls()
    impls = [i for i in present if i in chosen]
    absent = {i: why for i, why in absent.items() if i in chosen}
    start = time.monotonic()
    print(f"osdkc run: {len(impls)} implementations, {args.jobs} at a time", flush=True)
    for name, why in absent.items():
        print(f"not run: {name}: {why}", flush=True)
    with SignalStop() as stop, ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = []
        try:
            futures += [pool.submit(one, impl) for impl in impls]
            beat = _Heartbeat(out_dir, impls, sys.stderr if not args.no_progress else None)
            while (pending := wait(futures, timeout=0.5).not_done) or not beat.final:
                beat.show({impl: f.done() for impl, f in zip(impls, futures)}, final=not pending)
        except Interrupted as i:
            # Each run writes its partial reports and kills its testee on the same signal.
            with lock:
                stopping.append(i.signame)
                for proc in live.values():
                    if proc.poll() is None:
                        proc.send_signal(signal.Signals[i.signame])
        finally:
            stop.disarm()
        summaries = [f.result() for f in futures]
    seconds = time.monotonic() - start
    ok = not stopping and all(s.get("conforms") and s.get("exit") == 0 for s in summaries)
    print(status_table(summaries))
    for s in summaries:
        if not (s.get("conforms") and s.get("exit") == 0):
            print(f"{s['impl']}: see {out_dir / (s['impl'] + '.log')}")
    selection = " ".join(_forwarded(args)) or None
    (out_dir / "conformance.json").write_text(json.dumps(
        {"seconds": round(seconds, 1), "jobs": args.jobs, "selection": selection,
         "interrupted": stopping[0] if stopping else None, "implementations": summaries}, indent=1) + "\n")
    print(f"\nreports: {out_dir}/  ({seconds:.1f} s)")
    if stopping:
        print(f"INTERRUPTED by {stopping[0]}: no verdict (partial reports)")
        return exit_status_of_signal(stopping[0])
    verdict = "ALL CONFORM" if ok else "NOT ALL CONFORM"
    print(f"{verdict} ({len(impls)} of {len(chosen)} implementations ran)" if absent else verdict)
    return 0 if ok else 1
