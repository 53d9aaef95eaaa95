"""`osdkc selftest`: mutation testing of the golden vectors.

Every mutant of osdk_conformance.harness.mutants (the reference implementation with
one deliberate fault) is run against the full vector suite through the real
runner machinery: a child process (conformance/testees/mutant_testee.py)
supervised by osdk_conformance.harness.testee, cases replayed by
runner.run_cases, answers judged by vectors.compare. A mutant is *killed*
when at least one vector fails for it, including a crash or a timeout of
the mutant process (recorded as testee_crash / testee_timeout, like any
testee's). The suite bites when every mutant is killed: the command prints
one row per mutant and the mutation score (killed / total) and exits 0 only
at 100 %.

To stay fast:

- cases are replayed interleaved (round robin over groups of the same
  category, operation and profile, each group in file order), so every kind
  of case comes early and a mutant meets the cases that kill it after a
  few hundred requests instead of after the 25,000 broadcast flag subsets;
- a mutant's run stops after `--max-failures` failing cases (default 3;
  0 replays every vector and counts all failures exactly); a surviving
  mutant always replays the whole suite;
- each request has a short timeout (`--timeout`, default 2 s) so the
  hanging mutant costs seconds;
- mutants run in parallel (`--jobs`, default 2), one testee process each.

A baseline run of the same harness without a fault (mutant "none") replays
every vector first, in parallel with the mutants; it must pass every case,
or no kill would mean anything (the selftest then fails). `--no-baseline`
skips it.
"""
from __future__ import annotations

import argparse
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor, wait
from dataclasses import dataclass, field
from typing import Any, Iterable, Iterator, Sequence, TextIO

from osdk_conformance.core.errors import UsageError, exit_status_of_signal
from osdk_conformance.core.options import DEFAULT_JOBS, non_negative_int, positive_float, positive_int
from osdk_conformance.core.paths import ROOT
from osdk_conformance.harness import mutants
from osdk_conformance.harness.report import FAIL
from osdk_conformance.harness.runner import SignalStop, StatusLine, run_cases
from osdk_conformance.harness.testee import Testee, TesteeStartError
from osdk_conformance.harness.vectors import compare, load_cases

MUTANT_TESTEE = ROOT / "conformance" / "testees" / "mutant_testee.py"
DEFAULT_MAX_FAILURES = 3
DEFAULT_TIMEOUT = 2.0


def interleave(cases: Sequence[Any]) -> list[Any]:
    """Cases round robin over their (category, operation, profile) groups,
    groups in order of first appearance, each group in file order."""
    groups: dict[tuple, list[Any]] = {}
    for c in cases:
        groups.setdefault((c.category, c.operation, c.profile), []).append(c)
    queues = list(groups.values())
    out: list[Any] = []
    i = 0
    while queues:
        queues = [q for q in queues if len(q) > i]
        out.extend(q[i] for q in queues)
        i += 1
    return out


class _StopAfter:
    """The cases of one run, handed out until `limit` of them have failed.

    It is both the case source and the progress object of
    runner.run_cases, which calls update(done, failed) after each case and
    takes the next case only afterwards, so the source knows the failure
    count before it hands out the next case."""

    def __init__(self, cases: Sequence[Any], limit: int, stopping: threading.Event | None = None) -> None:
        self.cases = cases
        self.limit = limit
        self.failed = 0
        self.stopped = False
        self.stopping = stopping
        self.done = 0

    def __iter__(self) -> Iterator[Any]:
        for case in self.cases:
            if self.limit and self.failed >= self.limit:
                self.stopped = True
                return
            if self.stopping is not None and self.stopping.is_set():
                return
            yield case

    def __len__(self) -> int:
        return len(self.cases)

    def update(self, done: int, failed: int) -> None:
        self.failed = failed
        self.done = done

    def finish(self) -> None:
        pass


@dataclass
class MutantRun:
    name: str
    description: str
    violates: tuple[str, ...]
    expect: str
    cases_run: int = 0
    failures: int = 0
    stopped_early: bool = False
    first_id: str = ""
    first_category: str = ""
    first_kind: str = ""
    first_message: str = ""
    kinds: dict[str, int] = field(default_factory=dict)
    problem: str = ""  # the run itself went wrong (could not start, no capabilities, aborted)
    seconds: float = 0.0

    @property
    def killed(self) -> bool:
        return self.failures > 0 and not self.problem


class _Running:
    """The runs in progress, so that an interrupt can stop them: each run's
    case source stops handing out cases and its testee is killed."""

    def __init__(self) -> None:
        self.stopping = threading.Event()
        self.lock = threading.Lock()
        self.testees: dict[str, Testee] = {}
        self.sources: dict[str, _StopAfter] = {}

    def stop(self) -> None:
        self.stopping.set()
        with self.lock:
            testees = list(self.testees.values())
        for t in testees:
            t.stop_from_another_thread()


def run_mutant(name: str, cases: Sequence[Any], *, max_failures: int = DEFAULT_MAX_FAILURES,
               timeout: float = DEFAULT_TIMEOUT, description: str = "", violates: tuple[str, ...] = (),
               expect: str = "mismatch", running: _Running | None = None) -> MutantRun:
    """Replay `cases` (in the given order) against mutant `name` ("none" for
    the unmutated harness) through the runner; stop after `max_failures`
    failing cases (0: never), or when `running` is stopped."""

    run = MutantRun(name, description, violates, expect)
    t0 = time.monotonic()
    running = running or _Running()
    if running.stopping.is_set():
        run.problem = "interrupted"
        return run
    try:
        testee = Testee([sys.executable, str(MUTANT_TESTEE), name], timeout=timeout)
        testee.start()
    except TesteeStartError as e:
        run.problem = str(e)
        return run
    source = _StopAfter(cases, max_failures, running.stopping)
    with running.lock:
        running.testees[name], running.sources[name] = testee, source
    try:
        outcome = run_cases(testee, source, compare, source)  # type: ignore[arg-type]
    except TesteeStartError as e:
        run.problem = str(e)
        return run
    finally:
        testee.close()
        with running.lock:
            running.testees.pop(name, None)
    if running.stopping.is_set():
        run.problem = "interrupted"
    run.seconds = time.monotonic() - t0
    results = outcome.results
    if run.problem:
        return run
    if outcome.capabilities is None:
        run.problem = outcome.aborted or "no capabilities"
        return run
    if outcome.aborted:
        run.problem = f"run aborted: {outcome.aborted}"
    failed = [r for r in results if r.status == FAIL]
    run.cases_run = len(results)
    run.failures = len(failed)
    run.stopped_early = source.stopped
    for r in failed:
        run.kinds[r.kind or "mismatch"] = run.kinds.get(r.kind or "mismatch", 0) + 1
    if failed:
        first = failed[0]
        run.first_id, run.first_category = first.id, first.category
        run.first_kind = first.kind or "mismatch"
        run.first_message = (first.message or "").splitlines()[0] if first.message else ""
    return run


@dataclass
class SelftestOutcome:
    runs: list[MutantRun]
    baseline: MutantRun | None
    cases: int
    seconds: float
    interrupted: str | None = None  # the signal that ended the selftest early
    planned: int = 0                # mutants asked for (runs holds those that finished)

    @property
    def killed(self) -> int:
        return sum(r.killed for r in self.runs)

    @property
    def score(self) -> float:
        return self.killed / len(self.runs) if self.runs else 0.0

    @property
    def ok(self) -> bool:
        if self.interrupted:
            return False
        baseline_ok = self.baseline is None or (not self.baseline.failures and not self.baseline.problem)
        return baseline_ok and bool(self.runs) and self.killed == len(self.runs)


class _Progress:
    """Mutants finished and killed so far, and the baseline's cases, on a StatusLine."""

    def __init__(self, total: int, stream: TextIO | None) -> None:
        self.total = total
        self.line = StatusLine(stream)

    def show(self, runs: Sequence[MutantRun], base: _StopAfter | None, final: bool = False) -> None:
        if not self.line.due(final=final):
            return
        done = [r for r in runs if r.problem != "interrupted"]
        self.line.write(f"osdkc selftest: {len(done)}/{self.total} mutants done, {sum(r.killed for r in done)} killed"
                        + (f"; baseline {base.done:,}/{len(base):,} cases" if base is not None else "")
                        + f", {self.line.seconds():.0f} s", final)


def selftest(names: Iterable[str] | None = None, *, jobs: int = DEFAULT_JOBS,
             max_failures: int = DEFAULT_MAX_FAILURES, timeout: float = DEFAULT_TIMEOUT,
             baseline: bool = True, vector_files: Sequence[str] | None = None,
             progress: TextIO | None = None) -> SelftestOutcome:
    """Run the mutants (default: all) against the vectors; see the module doc.
    SIGINT or SIGTERM (in the main thread) stop every run within moments: the
    outcome holds the mutants that finished and names the signal."""

    chosen = list(names) if names else list(mutants.MUTANTS)
    unknown = [n for n in chosen if n not in mutants.MUTANTS]
    if unknown:
        raise UsageError(f"no mutant {', '.join(map(repr, unknown))} (known: {', '.join(mutants.MUTANTS)})")
    t0 = time.monotonic()
    cases = load_cases(list(vector_files) if vector_files else None)
    ordered = interleave(cases)
    running = _Running()
    shown = _Progress(len(chosen), progress)
    interrupted: str | None = None
    pool = ThreadPoolExecutor(max_workers=max(1, jobs))
    with SignalStop(raises=False) as stop:
        try:
            base = pool.submit(run_mutant, mutants.NONE, ordered, max_failures=0, timeout=max(timeout, 10.0),
                               description="no fault (the harness itself)", running=running) if baseline else None
            futures = [pool.submit(run_mutant, n, ordered, max_failures=max_failures, timeout=timeout,
                                   description=mutants.MUTANTS[n].description, violates=mutants.MUTANTS[n].violates,
                                   expect=mutants.MUTANTS[n].expect, running=running) for n in chosen]
            everything = futures + ([base] if base is not None else [])
            # Waiting in short slices notices a signal within moments (the
            # handler only notes it: raised inside wait() it could leave a
            # future's lock held and the pool hung) and gives the progress line its beat.
            while wait(everything, timeout=0.2).not_done and not stop.received:
                shown.show([f.result() for f in futures if f.done()], running.sources.get(mutants.NONE))
        finally:
            stop.disarm()  # from here on a signal is only noted
            if interrupted or stop.received:
                interrupted = interrupted or stop.received
                running.stop()
            pool.shutdown(wait=True, cancel_futures=True)
    runs = [f.result() for f in futures if f.done() and not f.cancelled()]
    base_run = base.result() if base is not None and base.done() and not base.cancelled() else None
    if interrupted:
        runs = [r for r in runs if r.problem != "interrupted"]
        if base_run is not None and base_run.problem == "interrupted":
            base_run = None
    else:
        shown.show(runs, None, final=True)
    return SelftestOutcome(runs, base_run, len(cases), time.monotonic() - t0, interrupted, len(chosen))


# ---- output ------------------------------------------------------------------------


def _clip(text: str, width: int) -> str:
    return text if len(text) <= width else text[: width - 1] + "…"


def format_table(outcome: SelftestOutcome, max_failures: int) -> str:
    rows = [("mutant", "killed", "failing", "first failing vector [category]", "description")]
    for r in outcome.runs:
        if r.problem and not r.failures:
            killed, failing, first = "ERROR", "-", _clip(r.problem, 70)
        else:
            killed = "yes" if r.killed else "NO"
            failing = f"{r.failures}{'+' if r.stopped_early else ''}"
            kind = "" if r.first_kind in ("", "mismatch") else f" {r.first_kind}"
            first = f"{r.first_id} [{r.first_category}]{kind}" if r.failures else "-"
        rows.append((r.name, killed, failing, first, r.description))
    widths = [max(len(row[i]) for row in rows) for i in range(4)]
    lines = []
    for n, row in enumerate(rows):
        lines.append("  ".join(cell.ljust(widths[i]) for i, cell in enumerate(row[:4])) + "  " + row[4])
        if n == 0:
            lines.append("-" * (sum(widths) + 8 + len(row[4])))
    return "\n".join(lines)


def report(outcome: SelftestOutcome, max_failures: int, out: TextIO) -> None:
    limit = f"stop after {max_failures} failing vectors per mutant" if max_failures else "every vector"
    out.write(f"osdkc selftest: {len(outcome.runs)} mutants against {outcome.cases} vectors ({limit})\n")
    b = outcome.baseline
    if b is not None:
        state = "OK" if not b.failures and not b.problem else "FAILS"
        out.write(f"baseline (no fault): {b.cases_run} cases, {b.failures} failing, {b.seconds:.1f} s: {state}\n")
        if b.failures:
            out.write(f"  first: {b.first_id} [{b.first_category}]: {b.first_message[:200]}\n")
        if b.problem:
            out.write(f"  {b.problem}\n")
    out.write("\n" + format_table(outcome, max_failures) + "\n\n")
    wrong_kind = [r for r in outcome.runs if r.killed and r.expect != "mismatch" and r.expect not in r.kinds]
    for r in wrong_kind:
        out.write(f"note: {r.name} was killed, but not as {r.expect} ({', '.join(sorted(r.kinds))})\n")
    survivors = [r for r in outcome.runs if not r.killed]
    for r in survivors:
        why = r.problem or f"passed all {r.cases_run} vectors"
        out.write(f"SURVIVED: {r.name}: {why} (violates {', '.join(r.violates)})\n")
    if outcome.interrupted:
        # no score: the mutants that did not finish were neither killed nor survived
        out.write(f"INTERRUPTED by {outcome.interrupted} after {outcome.seconds:.1f} s: no verdict "
                  f"({len(outcome.runs)} of {outcome.planned} mutants finished, {outcome.killed} of them killed"
                  + ("; the baseline did not finish" if b is None else "") + ")\n")
        out.flush()
        return
    out.write(f"mutation score: {outcome.killed}/{len(outcome.runs)} killed "
              f"({100 * outcome.score:.1f}%) in {outcome.seconds:.1f} s\n")
    if b is not None and (b.failures or b.problem):
        out.write("SELFTEST FAILED: the unmutated harness does not pass the vectors\n")
    else:
        out.write("SELFTEST PASSED\n" if outcome.ok else "SELFTEST FAILED\n")
    out.flush()


# ---- the command ------------------------------------------------------------------


def add_arguments(p: argparse.ArgumentParser, profiles: Sequence[str] = ()) -> None:
    p.add_argument("--mutant", action="append", metavar="NAME", help="only this mutant (repeatable; default: all)")
    p.add_argument("--jobs", type=positive_int, default=DEFAULT_JOBS, metavar="N",
                   help="mutants run in parallel (default: the number of CPUs)")
    p.add_argument("--max-failures", type=non_negative_int, default=DEFAULT_MAX_FAILURES, metavar="N",
                   help=f"stop a mutant's run after N failing vectors (default {DEFAULT_MAX_FAILURES}; "
                        "0: replay every vector and count all failures)")
    p.add_argument("--timeout", type=positive_float, default=DEFAULT_TIMEOUT, metavar="S",
                   help=f"seconds per request (default {DEFAULT_TIMEOUT:g}; the hanging mutant waits this long)")
    p.add_argument("--no-baseline", action="store_true", help="skip the run of the harness without a fault")
    p.add_argument("--vectors", action="append", metavar="FILE",
                   help="vector file(s) to use instead of vectors/*.json (repeatable)")
    p.add_argument("--list", action="store_true", help="list the mutants and what they violate, then exit")
    p.add_argument("-q", "--quiet", action="store_true",
                   help="no progress on standard error (mutants done and killed so far)")


def run_selftest(args: argparse.Namespace) -> int:
    if args.list:
        for m in mutants.MUTANTS.values():
            print(f"{m.name:30} {', '.join(m.violates):45} {m.description}")
        return 0
    outcome = selftest(args.mutant, jobs=args.jobs, max_failures=args.max_failures, timeout=args.timeout,
                       baseline=not args.no_baseline, vector_files=args.vectors,
                       progress=None if args.quiet else sys.stderr)
    report(outcome, args.max_failures, sys.stdout)
    if outcome.interrupted:
        return exit_status_of_signal(outcome.interrupted)
    return 0 if outcome.ok else 1
