"""`osdkc sdk test`: the golden vectors against DJI's Onboard-SDK itself.

Builds the two variants of the SDK's testee (`osdkc sdk build`, plain and
with AddressSanitizer/UndefinedBehaviorSanitizer) and replays the selected
vectors against each with the runner of `osdkc run` (harness/runner.py:
capabilities, then every case the adapter claims; the others are skipped and
counted). Each variant gets its verdict line, which never claims more than
ran, and its own reports: --junit F and --html F for the plain variant,
F with `-asan` before the suffix for the other.

The adapter claims only the operations and profiles the SDK performs. Where
the SDK rejects input without saying why, the adapter derives the error class
from what the SDK did; the Recipe says how (`derivations`), and the terminal
summary, the JUnit properties and the HTML report repeat it.

A sanitizer error ends the testee: the case shows as testee_crash, and the
report names the sanitizer's finding (`heap-buffer-overflow in F file:line`),
read from what the testee wrote to standard error, or from the case replayed
alone when the runner kept too little of it.

Exit status: 0 both variants conform (for what they claim), 1 one does not,
2 the tree cannot be used or a bad command line, 4 nothing ran, 130 (143)
interrupted by SIGINT (SIGTERM) after reporting what ran.
"""
from __future__ import annotations

import argparse
import html
import json
import os
import re
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Sequence

from osdk_conformance.core.errors import UsageError, exit_status_of_signal
from osdk_conformance.core.options import positive_float
from osdk_conformance.core.priority import keep_priority
from osdk_conformance.harness import report, runner, vectors
from osdk_conformance.harness.report import FAIL, Result
from osdk_conformance.harness.runner import (EXIT_NOTHING_RAN, Progress, RunOutcome, compared_answers, coverage,
                                             coverage_html, coverage_table, no_result_reason, request_of,
                                             select_cases, verdict_of)
from osdk_conformance.harness.testee import DEFAULT_MEMORY_MB, DEFAULT_TIMEOUT, TESTEE_CRASH, TESTEE_OOM
from osdk_conformance.sdk.family import Recipe
from osdk_conformance.sdk.testee_build import Built, add_osdk_arguments, build, describe, recipe_of

# A testee that crashes on many cases in a row is the SDK under test doing
# what it does, not a testee that cannot run: keep restarting it (the
# runner's default gives up after 5), so that every claimed case is judged.
MAX_RESTARTS = 100_000
# Cases replayed alone to read a sanitizer report the runner kept only the end of.
MAX_REPLAYS = 200


# --------------------------------------------------------------------------
# Sanitizer reports


_ASAN_ERROR = re.compile(r"ERROR: (AddressSanitizer|LeakSanitizer): ([\w-]+)")
_FRAME = re.compile(r"^\s*#\d+ 0x[0-9a-f]+ in (.+?) (/\S+?:\d+)(?::\d+)?\s*$")
_UBSAN = re.compile(r"^(\S+?:\d+)(?::\d+)?: runtime error: (.+)$")
_SUMMARY = re.compile(r"SUMMARY: (\w+Sanitizer): ([\w-]+)(?: (\S+?:\d+)(?::\d+)?)?(?: in (.+))?")
_RUNTIME = ("libsanitizer", "compiler-rt", "sanitizer_common", "/asan/", "/ubsan/")


def _short_path(path: str, root: Path | None) -> str:
    if root is not None:
        try:
            return str(Path(path).relative_to(root))
        except ValueError:
            pass
    return path


def _function(signature: str) -> str:
    """A frame's function without its parameter list (C++ signatures are long)."""
    depth, out = 0, []
    for ch in signature:
        if ch == "(" and depth == 0 and out:
            break
        depth += ch == "<"
        depth -= ch == ">"
        out.append(ch)
    return "".join(out).strip() or signature


def sanitizer_finding(stderr: str, root: Path | None = None) -> str | None:
    """`heap-buffer-overflow in F file:line` from a sanitizer's report: the
    error, and the first frame of the faulting access's stack that is not
    the sanitizer's own (an intercepted memcpy is reported where it was
    called). Only the error's name when the text lacks the start of the
    report and its summary names no place of ours; None when it holds no
    report at all."""
    lines = stderr.splitlines()
    for line in lines:
        m = _UBSAN.match(line.strip())
        if m:
            what = re.sub(r"0x[0-9a-f]{5,}", "0x…", m.group(2).strip())   # addresses differ per process
            return f"undefined behaviour ({what}) at {_short_path(m.group(1), root)}"
    start = next((n for n, line in enumerate(lines) if _ASAN_ERROR.search(line)), None)
    summary = next((m for m in map(_SUMMARY.search, lines) if m), None)
    if start is None and summary is None:
        return None
    if start is not None:
        kind = _ASAN_ERROR.search(lines[start]).group(2)
        for line in lines[start + 1:]:
            if any(w in line for w in ("is located", "allocated by", "freed by", "SUMMARY:")):
                break   # past the stack of the faulting access
            m = _FRAME.match(line)
            if m and not any(r in m.group(2) for r in _RUNTIME):
                return f"{kind} in {_function(m.group(1))} {_short_path(m.group(2), root)}"
    else:
        kind = summary.group(2)
    if summary is not None and summary.group(3) and not any(r in summary.group(3) for r in _RUNTIME):
        where = f" in {_function(summary.group(4))}" if summary.group(4) else ""
        return f"{kind}{where} {_short_path(summary.group(3), root)}"
    return kind


def located(finding: str | None) -> bool:
    """Whether a finding names a file and line."""
    return finding is not None and re.search(r":\d+$", finding) is not None


def _replay_alone(exe: Path, case: Any, timeout: float) -> str:
    """What the testee writes to standard error when given this one case."""
    line = json.dumps(request_of(case), separators=(",", ":")) + "\n"
    try:
        proc = subprocess.run([str(exe)], input=line.encode(), capture_output=True, timeout=timeout,
                              start_new_session=True, preexec_fn=keep_priority)
    except (OSError, subprocess.SubprocessError):
        return ""
    return proc.stderr.decode("utf-8", "replace")


def annotate_crashes(results: list[Result], cases_by_id: dict[str, Any], exe: Path, root: Path | None,
                     timeout: float) -> dict[str, list[str]]:
    """Put the sanitizer's finding into each crashed case's details; returns
    finding -> case ids. A case whose kept standard error holds only the end
    of a report is replayed alone (at most MAX_REPLAYS of them)."""
    found: dict[str, list[str]] = {}
    replays = 0
    for i, r in enumerate(results):
        if r.kind not in (TESTEE_CRASH, TESTEE_OOM):
            continue
        finding = sanitizer_finding(str(r.details.get("stderr", "")), root)
        # a report cut short (the runner keeps the end of standard error): read it whole
        if finding is not None and not located(finding) and r.id in cases_by_id and replays < MAX_REPLAYS:
            replays += 1
            finding = sanitizer_finding(_replay_alone(exe, cases_by_id[r.id], timeout), root) or finding
        if finding is None:
            continue
        results[i] = Result(r.category, r.id, r.status, r.message, {"sanitizer": finding, **r.details}, r.kind,
                            r.seconds)
        found.setdefault(finding, []).append(r.id)
    return found


# --------------------------------------------------------------------------
# One variant


@dataclass
class VariantRun:
    built: Built
    outcome: RunOutcome
    results: list[Result]
    rows: list
    verdict: Any
    findings: dict[str, list[str]] = field(default_factory=dict)
    overclaimed: list[str] = field(default_factory=list)


def replay(built: Built, cases: Sequence[Any], compare, timeout: float, progress: Progress | None) -> RunOutcome:
    """`osdkc run --testee` for one variant: the same supervisor and run loop;
    the sanitizer variant runs without an address-space limit (ASan reserves
    terabytes of it), and a crashing SDK is restarted as often as it takes."""
    memory_mb = 0 if built.asan else DEFAULT_MEMORY_MB
    return runner.replay([str(built.exe)], cases, compare, timeout, memory_mb, progress, MAX_RESTARTS)[0]


def _overclaimed(recipe: Recipe, outcome: RunOutcome) -> list[str]:
    """What the adapter claims beyond the Recipe (it must claim only what the SDK performs)."""
    caps = outcome.capabilities
    if caps is None:
        return []
    return sorted(caps.operations - set(recipe.operations)) + sorted(caps.profiles - set(recipe.profiles))


def run_variant(built: Built, root: Path, cases: Sequence[Any], compare, timeout: float,
                progress: Progress | None) -> VariantRun:
    outcome = replay(built, cases, compare, timeout, progress)
    results = list(outcome.results)
    findings: dict[str, list[str]] = {}
    if not outcome.interrupted:
        try:
            findings = annotate_crashes(results, {c.id: c for c in cases}, built.exe, root, timeout)
        except KeyboardInterrupt:
            outcome.interrupted = "SIGINT"
    rows = coverage(cases, results, no_result_reason(outcome))
    return VariantRun(built, outcome, results, rows, verdict_of(results, rows, outcome.interrupted), findings,
                      _overclaimed(built.recipe, outcome))


# --------------------------------------------------------------------------
# Reports


def variant_path(path: str, asan: bool) -> str:
    """F for the plain variant, F with -asan before its suffix for the other."""
    if not asan:
        return path
    p = Path(path)
    return str(p.with_name(f"{p.stem}-asan{p.suffix}"))


def _check_writable(path: str | None, option: str) -> None:
    if path is None:
        return
    for f in (variant_path(path, False), variant_path(path, True)):
        parent = Path(f).absolute().parent
        if not parent.is_dir():
            raise UsageError(f"{option} {path}: directory {parent} does not exist")
        if Path(f).is_dir():
            raise UsageError(f"{option} {path}: {f} is a directory")
        if not os.access(parent, os.W_OK):
            raise UsageError(f"{option} {path}: directory {parent} is not writable")


def _claimed(run: VariantRun) -> str:
    caps = run.outcome.capabilities
    if caps is None:
        return "claimed: nothing (no capabilities answer)"
    return (f"claimed: {', '.join(sorted(caps.operations)) or 'no operation'}; "
            f"profiles {', '.join(sorted(caps.profiles)) or 'none'}")


def _skipped(run: VariantRun) -> str:
    ran, available = sum(r.ran for r in run.rows), sum(r.available for r in run.rows)
    why: dict[str, int] = {}
    for r in run.rows:
        for reason, n in r.skipped.items():
            why[reason] = why.get(reason, 0) + n
    skipped = ", ".join(f"{n:,} {reason}" for reason, n in sorted(why.items()))
    return f"ran {ran:,} of {available:,} cases" + (f"; skipped: {skipped}" if skipped else "")


def _meta(recipe: Recipe, root: Path, run: VariantRun, args: argparse.Namespace, timeout: float) -> dict[str, str]:
    meta = {
        "SDK": f"DJI Onboard-SDK {recipe.version} (family {recipe.family}) at {root}",
        "variant": "ASan/UBSan" if run.built.asan else "plain",
        "testee": run.built.command,
        "verdict": run.verdict.line,
        "claimed": _claimed(run).removeprefix("claimed: "),
        "coverage": _skipped(run),
        "duration": f"{run.outcome.seconds:.1f} s",
        "timeout per request": f"{timeout:g} s",
        "memory limit": "none" if run.built.asan else f"{DEFAULT_MEMORY_MB} MiB",
    }
    if args.filter or args.profile:
        meta["selection"] = " ".join(filter(None, [f"--filter {args.filter}" if args.filter else "",
                                                   *(f"--profile {p}" for p in args.profile or [])]))
    if run.overclaimed:
        meta["adapter claims beyond the recipe"] = ", ".join(run.overclaimed)
    if run.outcome.aborted:
        meta["aborted"] = run.outcome.aborted
    if run.outcome.interrupted:
        meta["interrupted"] = f"by {run.outcome.interrupted}: the report is partial"
    return meta


def _derivations_html(recipe: Recipe) -> str:
    if not recipe.derivations:
        return ""
    rows = "".join(f"<tr><td>{html.escape(k)}</td><td>{html.escape(v)}</td></tr>"
                   for k, v in sorted(recipe.derivations.items()))
    return ("<h2>How error classes were derived</h2><p>Where the SDK rejects input without saying why, "
            "the adapter derives the class from what the SDK did:</p><table class=\"meta\"><thead><tr>"
            f"<th>error class</th><th>derived from</th></tr></thead><tbody>{rows}</tbody></table>")


def _findings_html(findings: dict[str, list[str]]) -> str:
    if not findings:
        return ""
    rows = "".join(f"<tr><td>{html.escape(f)}</td><td>{len(ids)}</td><td>{html.escape(', '.join(ids[:20]))}"
                   f"{' …' if len(ids) > 20 else ''}</td></tr>" for f, ids in findings.items())
    return ("<h2>Sanitizer findings</h2><table class=\"meta\"><thead><tr><th>finding</th><th>cases</th>"
            f"<th>case ids</th></tr></thead><tbody>{rows}</tbody></table>")


def write_reports(run: VariantRun, recipe: Recipe, root: Path, args: argparse.Namespace, timeout: float) -> None:
    meta = _meta(recipe, root, run, args, timeout)
    title = f"DJI Onboard-SDK {recipe.version} ({meta['variant']})"
    try:
        if args.junit:
            props = dict(meta)
            props.update({f"derivation {k}": v for k, v in sorted(recipe.derivations.items())})
            props.update({f"coverage {r.operation} {r.profile or '-'}":
                          f"{r.ran} / {r.available}" + "".join(f"; {n} {why}" for why, n in sorted(r.skipped.items()))
                          for r in run.rows})
            props.update({f"sanitizer {f}": ", ".join(ids) for f, ids in run.findings.items()})
            report.write_junit(variant_path(args.junit, run.built.asan), run.results, f"osdkc sdk test: {title}",
                               properties=props)
        if args.html:
            stderr = run.outcome.testee_stderr
            report.write_html(variant_path(args.html, run.built.asan), run.results,
                              f"OPEN protocol conformance: {title}", meta,
                              appendix={"testee standard error (end)": stderr} if stderr else None,
                              lead_html=_findings_html(run.findings),
                              extra_html=_derivations_html(recipe) + coverage_html(run.rows),
                              verdict=(run.verdict.line, run.verdict.conforms), diff=compared_answers)
    except OSError as e:
        raise UsageError(f"cannot write a report: {e.strerror or e}") from None


def print_variant(run: VariantRun, out=None, limit: int = 20) -> None:
    out = out or sys.stdout
    name = "ASan/UBSan" if run.built.asan else "plain"
    out.write(f"\n== {name}: {run.built.command} ({run.outcome.seconds:.1f} s)\n")
    out.write(_claimed(run) + "\n")
    if run.overclaimed:
        out.write(f"warning: the adapter claims {', '.join(run.overclaimed)}, which the recipe does not list\n")
    out.write(_skipped(run) + "\n")
    out.write("coverage (cases run / available):\n" + coverage_table(run.rows) + "\n")
    kinds: dict[str, int] = {}
    for r in run.results:
        if r.status == FAIL and r.kind and r.kind != "mismatch":
            kinds[r.kind] = kinds.get(r.kind, 0) + 1
    if kinds:
        out.write("testee failures: " + ", ".join(f"{k} {v:,}" for k, v in sorted(kinds.items())) + "\n")
    for finding, ids in run.findings.items():
        shown = ", ".join(ids[:5]) + (f" and {len(ids) - 5:,} more" if len(ids) > 5 else "")
        out.write(f"sanitizer: {finding}: {len(ids):,} case(s): {shown}\n")
    if run.outcome.aborted:
        out.write(f"run aborted: {run.outcome.aborted}\n")
    bad = [r for r in run.results if r.status in report.BAD and r.kind != "aborted"]
    for r in bad[:limit]:
        first = r.message.splitlines()[0] if r.message else ""
        kind = f" [{r.kind}]" if r.kind and r.kind != "mismatch" else ""
        out.write(f"  {r.status.upper():5} {r.id}{kind}: {first[:200]}\n")
    if len(bad) > limit:
        out.write(f"  … and {len(bad) - limit:,} more (see the --junit / --html reports)\n")
    out.write(f"{name}: {run.verdict.line}\n")
    out.flush()


# --------------------------------------------------------------------------
# Command line


EPILOG = """\
Builds the plain and the ASan/UBSan testee (as `osdkc sdk build` does) and
replays the vectors against each with the runner of `osdkc run`. Reports:
--junit F and --html F for the plain variant, F-asan.xml / F-asan.html (the
suffix kept) for the sanitizer one.
Exit status: 0 both conform (for what the SDK does: the verdict names what
ran), 1 one does not conform, 2 the tree cannot be used or a bad command
line, 4 nothing ran, 130 interrupted (what ran is reported).
See docs/SDK-TESTING.md."""


def add_arguments(ap: argparse.ArgumentParser, profiles: tuple[str, ...]) -> None:
    ap.epilog = EPILOG
    ap.formatter_class = argparse.RawDescriptionHelpFormatter
    add_osdk_arguments(ap)
    ap.add_argument("--junit", metavar="FILE", help="JUnit XML of the plain variant (and FILE-asan of the other)")
    ap.add_argument("--html", metavar="FILE", help="HTML report of the plain variant (and FILE-asan of the other)")
    ap.add_argument("--profile", action="append", choices=profiles, metavar="PROFILE",
                    help="only this profile (repeatable); it must be one the SDK supports")
    ap.add_argument("--filter", metavar="REGEX", help="only cases whose id matches REGEX (re.search)")
    ap.add_argument("--timeout", type=positive_float, metavar="S",
                    help=f"seconds per request (default {DEFAULT_TIMEOUT:g})")
    ap.add_argument("-q", "--quiet", dest="no_progress", action="store_true",
                   help="no progress output on stderr")
    # the former spelling, still accepted; -q/--quiet is the one every command shares
    ap.add_argument("--no-progress", dest="no_progress", action="store_true", help=argparse.SUPPRESS)


def _pattern(args: argparse.Namespace) -> re.Pattern | None:
    if not args.filter:
        return None
    try:
        return re.compile(args.filter)
    except re.error as e:
        raise UsageError(f"--filter {args.filter!r}: not a regular expression ({e})") from None


def _cases(args: argparse.Namespace, recipe: Recipe, pattern: re.Pattern | None) -> tuple[list[Any], Any]:
    for p in args.profile or ():
        if p not in recipe.profiles:
            raise UsageError(f"--profile {p}: the SDK {recipe.version} supports "
                             f"{', '.join(recipe.profiles) or 'no profile'}")
    try:
        all_cases = vectors.load_checked_cases(None)
    except UsageError:
        raise
    except Exception as e:  # a damaged vector file in the kit is not the user's command line
        raise UsageError(f"cannot load the vectors: {type(e).__name__}: {e}") from None
    cases = [c for c in select_cases(all_cases, args.profile, None) if pattern is None or pattern.search(c.id)]
    if not cases:
        raise UsageError("no vector matches the --profile / --filter selection")
    return cases, vectors.compare


def _osdk_root(args: argparse.Namespace) -> Path:
    return Path(args.osdk).expanduser().absolute()


def run_sdk_test(args: argparse.Namespace) -> int:
    _check_writable(args.junit, "--junit")
    _check_writable(args.html, "--html")
    pattern = _pattern(args)
    recipe, out = recipe_of(args, "sdk test")
    root = _osdk_root(args)
    cases, compare = _cases(args, recipe, pattern)
    timeout = args.timeout if args.timeout is not None else DEFAULT_TIMEOUT
    # both built before anything runs: a tree that cannot be built is exit 2 at once
    builds = [build(recipe, out, asan=False), build(recipe, out, asan=True)]

    stdout = sys.stdout
    stdout.write(f"osdkc sdk test: {describe(recipe)[0]} at {root}: {len(cases):,} cases, 2 variants\n")
    stdout.write(describe(recipe)[1] + "\n")
    if recipe.derivations:
        stdout.write("how error classes were derived (the SDK rejects silently; the class is the adapter's):\n")
        for k, v in sorted(recipe.derivations.items()):
            stdout.write(f"  {k}: {v}\n")
    stdout.flush()

    runs: list[VariantRun] = []
    for built in builds:
        progress = None if args.no_progress else Progress(len(cases), sys.stderr)
        run = run_variant(built, root, cases, compare, timeout, progress)
        runs.append(run)
        print_variant(run)
        write_reports(run, recipe, root, args, timeout)
        if run.outcome.interrupted:
            for rest in builds[len(runs):]:
                stdout.write(f"\n== {'ASan/UBSan' if rest.asan else 'plain'}: not run (interrupted)\n")
            stdout.write(f"INTERRUPTED by {run.outcome.interrupted}: no verdict for the SDK\n")
            stdout.flush()
            return exit_status_of_signal(run.outcome.interrupted)

    exits = [r.verdict.exit for r in runs]
    if 1 in exits:
        word, code = "DOES NOT CONFORM", 1
    elif EXIT_NOTHING_RAN in exits:
        word, code = "NOTHING RAN: no verdict", EXIT_NOTHING_RAN
    else:
        word, code = "CONFORMS (for what the verdict lines name)", 0
    stdout.write(f"\nDJI Onboard-SDK {recipe.version}: {word}\n")
    stdout.flush()
    return code
