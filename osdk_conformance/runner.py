"""`osdkc run`: replay the golden vectors against an implementation under test.

In the manner of protobuf's conformance runner: the implementation (the
*testee*) runs as a child process speaking conformance/PROTOCOL.md, one JSON
request line, one JSON response line, strictly in turn (osdk_conformance.testee
supervises it). The runner asks for its capabilities, replays every vector
whose operation and profile it supports (the others are skipped), judges each
response with `osdk_conformance.vectors.compare`, applies the failure list,
and reports: a summary table on stdout, optionally JUnit XML and HTML
(osdk_conformance.report).

Failure list: a text file with one case id per line, `#` starts a comment.
A listed case that fails is ignored (xfail); a listed case that passes fails
the run (xpass: remove it from the list); a listed id that names no vector is
an error. Exit status: 0 the testee conforms, 1 it does not, 2 usage or I/O
error.
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable, Sequence, TextIO

from . import report
from .errors import UsageError
from .paths import ROOT
from .report import ERROR, FAIL, PASS, SKIP, STATUSES, XFAIL, XPASS, Result
from .testee import (
    DEFAULT_MEMORY_MB, DEFAULT_TIMEOUT, Testee, TesteeFailure, TesteeGaveUp, TesteeStartError, validate_response,
)

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
}
ALL = "all"
FAILURE_LISTS = ROOT / "conformance" / "failure_lists"
# What a built implementation needs on disk, and how to get it.
BUILD_HINT = "run `make setup` (it builds every bundled testee)"


def impl_argv(name: str) -> list[str]:
    """The command that runs a bundled implementation."""
    try:
        argv = list(BUNDLED_IMPLS[name])
    except KeyError:
        raise UsageError(f"no bundled implementation {name!r} (known: {', '.join(BUNDLED_IMPLS)})") from None
    for part in argv[1:] if argv[0] in (sys.executable, "node", "java") else argv[:1]:
        if part.startswith("/") and not Path(part).exists():
            raise UsageError(f"bundled implementation {name!r} is not built ({part} is missing); {BUILD_HINT}")
    return argv


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
        raise UsageError(f"cannot read the failure list {path}: {getattr(e, 'strerror', None) or e}") from None
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


def run_cases(testee: Testee, cases: Sequence[Any], compare: Callable[[Any, dict], tuple[bool, str]],
              progress: Progress | None = None) -> RunOutcome:
    """Ask for capabilities, then replay `cases` (without failure-list handling)."""
    start = time.monotonic()
    results: list[Result] = []
    caps: Capabilities | None = None
    try:
        response = testee.request({"op": "capabilities"})
        caps = parse_capabilities(response)
    except TesteeFailure as f:
        reason = f"the testee did not answer capabilities: {f}"
        if f.kind != "testee_timeout" and testee.memory_bytes:
            reason += (f" (it runs with a limit of {testee.memory_bytes >> 20} MiB of address space; runtimes such as "
                       "the JVM reserve more than that at start: try a larger --memory-mb, or 0 for no limit)")
        results.append(Result("capabilities", "capabilities", FAIL, reason, {"stderr": f.stderr} if f.stderr else {},
                              kind=f.kind))
    except ValueError as e:
        results.append(Result("capabilities", "capabilities", FAIL,
                              f"the capabilities answer is not usable: {e}", kind="testee_garbage"))
    if caps is None:
        return RunOutcome(results, None, results[0].message, time.monotonic() - start, testee.stderr.text())

    aborted: str | None = None
    failed = 0
    for n, case in enumerate(cases):
        if aborted is not None:
            results.append(Result(case.category, case.id, ERROR, f"not run: {aborted}", kind="aborted"))
            continue
        if case.operation not in caps.operations or (case.profile is not None and case.profile not in caps.profiles):
            what = case.operation if case.operation not in caps.operations else f"profile {case.profile}"
            results.append(Result(case.category, case.id, SKIP, f"the testee does not support {what}"))
            continue
        t0 = time.perf_counter()
        try:
            response = testee.request(request_of(case))
        except TesteeFailure as f:
            details = _case_details(case)
            details["actual"] = str(f)
            if f.stderr:
                details["stderr"] = f.stderr
            details.update(_trailer(case))
            results.append(Result(case.category, case.id, FAIL, f.message, details, kind=f.kind,
                                  seconds=time.perf_counter() - t0))
            failed += 1
        except TesteeGaveUp as g:
            aborted = str(g)
            results.append(Result(case.category, case.id, ERROR, f"not run: {aborted}", kind="aborted"))
        else:
            seconds = time.perf_counter() - t0
            if response.get("ok") is False and response.get("unsupported") is True:
                results.append(Result(case.category, case.id, SKIP, "the testee answered unsupported",
                                      seconds=seconds))
            else:
                try:
                    passed, reason = compare(case, response)
                except Exception as e:  # a judge that chokes on an answer is a failed case, not a crash
                    passed, reason = False, f"the response could not be compared ({type(e).__name__}: {e})"
                if passed:
                    results.append(Result(case.category, case.id, PASS, seconds=seconds))
                else:
                    details = _case_details(case)
                    details["actual"] = response
                    details.update(_trailer(case))
                    results.append(Result(case.category, case.id, FAIL, reason, details, kind="mismatch",
                                          seconds=seconds))
                    failed += 1
        if progress is not None:
            progress.update(n + 1, failed)
    if progress is not None:
        progress.finish()
    return RunOutcome(results, caps, aborted, time.monotonic() - start, testee.stderr.text(4096))


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
    try:
        from . import vectors
    except ImportError as e:
        raise UsageError(f"the golden vectors are not available ({e})") from None
    try:
        cases = vectors.load_cases(paths or None)
    except UsageError:
        raise
    except Exception as e:  # a bad vector file is the user's input, not our crash
        raise UsageError(f"cannot load the vectors: {type(e).__name__}: {e}") from None
    return cases, vectors.compare


def _print_failures(results: Sequence[Result], out: TextIO, limit: int = 30) -> None:
    bad = [r for r in results if r.status in report.BAD and r.kind != "aborted"]
    for r in bad[:limit]:
        first = r.message.splitlines()[0] if r.message else ""
        kind = f" [{r.kind}]" if r.kind and r.kind not in ("mismatch",) else ""
        out.write(f"  {r.status.upper():5} {r.id}{kind}: {first[:300]}\n")
    if len(bad) > limit:
        out.write(f"  … and {len(bad) - limit} more (see --junit / --html reports)\n")


def run_command(args: argparse.Namespace) -> int:
    if args.timeout is not None and not args.timeout > 0:
        raise UsageError("--timeout must be a positive number of seconds")
    if args.memory_mb is not None and args.memory_mb < 0:
        raise UsageError("--memory-mb must be 0 (no limit) or a positive number of MiB")
    _check_writable(args.junit, "--junit")
    _check_writable(args.html, "--html")
    if args.impl == ALL:
        return run_all(args)
    _check_writable(args.summary_json, "--summary-json")
    argv = impl_argv(args.impl) if args.impl else args.testee
    if args.failure_list is None and args.impl and default_failure_list(args.impl).exists():
        args.failure_list = str(default_failure_list(args.impl))
    listed = read_failure_list(args.failure_list) if args.failure_list else {}

    all_cases, compare = _load_cases(args.vectors)
    known_ids = {c.id for c in all_cases}
    cases = [c for c in all_cases
             if (not args.profile or c.profile is None or c.profile in args.profile)
             and (not args.filter or args.filter in c.id)]
    if not cases:
        raise UsageError("no vector matches the --profile / --filter selection")

    timeout = args.timeout if args.timeout is not None else DEFAULT_TIMEOUT
    memory_mb = args.memory_mb if args.memory_mb is not None else DEFAULT_MEMORY_MB
    try:
        testee = Testee(argv, timeout=timeout, memory_mb=memory_mb)
        testee.start()
    except TesteeStartError as e:
        raise UsageError(str(e)) from None
    progress = Progress(len(cases), None if args.no_progress else sys.stderr)
    try:
        outcome = run_cases(testee, cases, compare, progress)
    finally:
        testee.close()

    list_name = str(args.failure_list) if args.failure_list else "failure list"
    results = apply_failure_list(outcome.results, listed, known_ids, list_name)
    name = outcome.capabilities.name if outcome.capabilities and outcome.capabilities.name else " ".join(
        testee.argv)
    ok = report.conforms(results)

    out = sys.stdout
    out.write(f"osdkc run: {name}: {len(cases)} cases in {outcome.seconds:.1f} s\n\n")
    out.write(report.summary_table(results) + "\n\n")
    kinds: dict[str, int] = {}
    for r in results:
        if r.status in (FAIL, XFAIL) and r.kind and r.kind != "mismatch":
            kinds[r.kind] = kinds.get(r.kind, 0) + 1
    if kinds:
        out.write("testee failures: " + ", ".join(f"{k} {v}" for k, v in sorted(kinds.items())) + "\n")
    if outcome.capabilities and not any(r.status != SKIP for r in outcome.results):
        out.write("note: no case applies to the operations and profiles the testee claims\n")
    if outcome.aborted:
        out.write(f"run aborted: {outcome.aborted}\n")
    if not ok:
        _print_failures(results, out)
    meta = {
        "testee": name,
        "command": " ".join(testee.argv),
        "cases": str(len(cases)),
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
    try:
        if args.junit:
            report.write_junit(args.junit, results, f"osdkc run: {name}", properties=meta)
        if args.html:
            appendix = {"testee standard error (end)": outcome.testee_stderr} if outcome.testee_stderr else None
            report.write_html(args.html, results, f"OPEN protocol conformance: {name}", meta, appendix=appendix)
        if args.summary_json:
            summary = {"impl": args.impl, "testee": name, "command": " ".join(testee.argv),
                       "cases": len(cases), "seconds": round(outcome.seconds, 1),
                       "statuses": {st: sum(r.status == st for r in results) for st in STATUSES},
                       "failure_list": args.failure_list, "conforms": ok}
            Path(args.summary_json).write_text(json.dumps(summary, indent=1) + "\n")
    except OSError as e:
        raise UsageError(f"cannot write a report: {e.strerror or e}") from None
    verdict = "CONFORMS" if ok else "DOES NOT CONFORM"
    out.write(f"{verdict}\n")
    out.flush()
    return 0 if ok else 1


def add_arguments(p: argparse.ArgumentParser, profiles: Sequence[str]) -> None:
    which = p.add_mutually_exclusive_group(required=True)
    which.add_argument("--testee", metavar="COMMAND",
                       help="command that starts the implementation under test (split like a shell does)")
    which.add_argument("--impl", choices=[*BUNDLED_IMPLS, ALL], metavar="IMPL",
                       help=f"a bundled implementation ({', '.join(BUNDLED_IMPLS)}), or {ALL} for every one "
                            "(reports in --report-dir)")
    p.add_argument("--profile", action="append", choices=profiles, metavar="PROFILE",
                   help=f"only this profile (repeatable; one of {', '.join(profiles)}); "
                        "cases without a profile always run")
    p.add_argument("--failure-list", metavar="FILE",
                   help="case ids expected to fail, one per line, # comments")
    p.add_argument("--junit", metavar="FILE", help="write a JUnit XML report")
    p.add_argument("--html", metavar="FILE", help="write a self-contained HTML report")
    p.add_argument("--timeout", type=float, metavar="S", help=f"seconds per request (default {DEFAULT_TIMEOUT:g})")
    p.add_argument("--memory-mb", type=int, metavar="N",
                   help=f"address-space limit of the testee in MiB (default {DEFAULT_MEMORY_MB}; 0 for none; "
                        "a JVM needs more than the default)")
    p.add_argument("--filter", metavar="SUBSTRING", help="only cases whose id contains SUBSTRING")
    p.add_argument("--vectors", action="append", metavar="FILE",
                   help="vector file(s) to use instead of vectors/*.json (repeatable)")
    p.add_argument("--no-progress", action="store_true", help="no progress output on stderr")
    p.add_argument("--summary-json", metavar="FILE", help="write the run's counts and verdict as JSON")
    p.add_argument("--report-dir", metavar="DIR", default=str(ROOT / "reports"),
                   help="with --impl all: where each implementation's JUnit, HTML, log and summary go, "
                        "and conformance.json (default: reports/)")
    p.add_argument("--jobs", type=int, metavar="N", default=os.cpu_count() or 1,
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
        verdict = "CONFORMS" if s.get("conforms") else s.get("problem") or "DOES NOT CONFORM"
        lines.append(f"{s['impl']:<15} {s.get('cases', 0):>6} " + " ".join(f"{st.get(c, 0):>6}" for c in cols)
                     + f" {s.get('seconds', 0):>8.1f}  {verdict}")
    return "\n".join(lines)


def run_all(args: argparse.Namespace) -> int:
    """Every bundled implementation, `--jobs` at a time, each in its own
    `osdkc run` process (the runner's judging is CPU-bound Python, so
    processes, not threads, use the cores). One table at the end; each
    run's JUnit, HTML, log and summary in --report-dir, and
    conformance.json with every summary (generated/README.md's status is
    rendered from it)."""
    if args.testee or args.failure_list or args.junit or args.html or args.summary_json:
        raise UsageError("--impl all writes its reports to --report-dir; --failure-list, --junit, --html and "
                         "--summary-json apply to a single implementation")
    if args.jobs < 1:
        raise UsageError("--jobs must be at least 1")
    out_dir = Path(args.report_dir)
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise UsageError(f"--report-dir {out_dir}: {e.strerror or e}") from None
    import subprocess
    from concurrent.futures import ThreadPoolExecutor

    def one(impl: str) -> dict:
        summary_path = out_dir / f"{impl}.json"
        summary_path.unlink(missing_ok=True)
        cmd = [sys.executable, "-m", "osdk_conformance.cli", "run", "--impl", impl, "--no-progress",
               "--junit", str(out_dir / f"{impl}.xml"), "--html", str(out_dir / f"{impl}.html"),
               "--summary-json", str(summary_path), *_forwarded(args)]
        with open(out_dir / f"{impl}.log", "w", encoding="utf-8") as log:
            code = subprocess.run(cmd, stdout=log, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL).returncode
        try:
            summary = json.loads(summary_path.read_text())
        except (OSError, ValueError):
            last = (out_dir / f"{impl}.log").read_text(errors="replace").strip().splitlines()[-1:]
            summary = {"impl": impl, "conforms": False, "problem": f"exit {code}: {last[0] if last else 'no output'}"}
        summary["exit"] = code
        return summary

    start = time.monotonic()
    print(f"osdkc run --impl all: {len(BUNDLED_IMPLS)} implementations, {args.jobs} at a time", flush=True)
    with ThreadPoolExecutor(max_workers=args.jobs) as pool:
        summaries = list(pool.map(one, BUNDLED_IMPLS))
    seconds = time.monotonic() - start
    ok = all(s.get("conforms") and s.get("exit") == 0 for s in summaries)
    print(status_table(summaries))
    for s in summaries:
        if not (s.get("conforms") and s.get("exit") == 0):
            print(f"{s['impl']}: see {out_dir / (s['impl'] + '.log')}")
    selection = " ".join(_forwarded(args)) or None
    (out_dir / "conformance.json").write_text(json.dumps(
        {"seconds": round(seconds, 1), "jobs": args.jobs, "selection": selection, "implementations": summaries},
        indent=1) + "\n")
    print(f"\nreports: {out_dir}/  ({seconds:.1f} s)")
    print("ALL CONFORM" if ok else "NOT ALL CONFORM")
    return 0 if ok else 1
