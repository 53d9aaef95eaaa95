"""`osdkc bench`: how fast the implementations and the kit's own commands are.

Sections (`--only`, default all, in this order):

- decode: every bundled implementation and the SDK-style C baseline
  (conformance/baseline/) decode each corpus (corpus.py) in their bench
  mode; frames/s, MB/s, peak RSS and the ratio to the baseline of the same
  run; the counts each reports must be the corpus's (bench_decode).
- api: the one-hour a3-fw3.1 corpus decoded into Python values through
  the public API, and by `osdkc decode` into JSON lines, with the native
  accelerator and with pure Python (api_decode.py).
- run: wall and CPU time of `osdkc run --impl all`.
- fuzz: executions per second of `osdkc fuzz --impl all` (fixed examples and seed).
- acceptance: CPU use of the acceptance receiver at 100 Hz (`osdkc soak --json`).
- device_fuzz: cases per second of `osdkc fuzz --port` against a healthy
  `osdkc sim` over a pty at 921600 and 230400 baud (fixed cases and seed),
  beside what the line could carry of the bytes a case takes.
- footprint: text, data and bss of the C library (generated/c) per
  feature and the deepest stack of each public function, on x86-64 (gcc)
  and Cortex-M4 (clang-14), compile only (footprint.py); then the library
  linked into one small Cortex-M4 program per feature, with flash, RAM,
  a stack bound and instructions per frame in QEMU (board_footprint.py);
  with --markdown it rewrites its own block of the file, so `--only
  footprint` leaves the other numbers alone.
- reliability (only when named in --only: about an hour and a half on 2
  cores, of which the fuzz sessions took 31 minutes):
  healthy active runs of `osdkc device` that must all pass, and seeded runs
  of every simulator fault that must all be detected (reliability.py); healthy
  `osdkc fuzz --port` sessions that must find nothing, and seeded sessions
  against each planted bug that must find it (fuzz_reliability.py).
- doctor (only when named in --only: about ten minutes at 20 runs): seeded
  diagnoses of `osdkc doctor` against each link fault it must tell apart;
  each must name that fault and no other (doctor_faults.py, docs/DOCTOR.md).
- tap (only when named in --only: about 22 minutes at 20 runs): seeded
  sessions of `osdkc host` through `osdkc tap` beside busy loops, relaying
  and (five of the hosts) passive on a Y-cable: a healthy host must pass,
  each planted host bug must fail the one check it names (tap_hosts.py,
  docs/TAP.md).

Nothing here asserts a speed: the numbers are printed, written as JSON
(--json) and as the Markdown block of docs/PERFORMANCE.md (--markdown), with
a verdict on each target of the issue. Exit status: 0 when every section ran
and every check held (counts, conformance, no disagreement, no frame lost),
1 otherwise, 2 for bad arguments.
"""
from __future__ import annotations

import argparse
import datetime
import json
import os
import sys
import time
from pathlib import Path

from osdk_conformance.bench import api_decode as bench_api, flight_data as bench_flight, corpus as bench_corpus, decode as bench_decode, footprint as bench_footprint, reliability as bench_reliability, doctor_faults as bench_doctor, tap_hosts as bench_tap, report as bench_report, sections as bench_sections
from osdk_conformance.bench.corpus import CORPORA
from osdk_conformance.bench.decode import impl_names
from osdk_conformance.bench.reliability import FAULT_CASES
from osdk_conformance.bench.report import HOUR_CORPUS
from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.options import non_negative_int, positive_float, positive_int

SECTIONS = ("decode", "api", "run", "fuzz", "acceptance", "device_fuzz", "footprint", "reliability", "doctor", "tap")
DEFAULT_SECTIONS = SECTIONS[:7]
QUICK_CORPUS_SECONDS = 60.0
DEFAULTS = {  # (full, --quick)
    "fuzz_examples": (2000, 200),
    "soak_seconds": (60.0, 30.0),
    "device_fuzz_cases": (2000, 200),
}
FUZZ_SEED = 1
REPEATS, BUDGET, TIMEOUT = 3, 120.0, 1800.0
RELIABILITY_RUNS, FAULT_RUNS, BUSY_PER_CORE, FUZZ_RUNS, BUG_RUNS, DOCTOR_RUNS, TAP_RUNS = 200, 20, 2, 40, 20, 20, 20


def add_arguments(ap: argparse.ArgumentParser, profiles: tuple[str, ...]) -> None:
    ap.add_argument("--only", metavar="SECTIONS",
                    help=f"comma-separated sections to run ({', '.join(SECTIONS)}; default all but reliability, doctor and tap)")
    ap.add_argument("--quick", action="store_true",
                    help=f"a fast check: corpora of {QUICK_CORPUS_SECONDS:g} s, "
                         f"{DEFAULTS['fuzz_examples'][1]} fuzz examples, {DEFAULTS['soak_seconds'][1]:g} s of soak, "
                         f"{DEFAULTS['device_fuzz_cases'][1]} device fuzzing cases per baud rate")
    ap.add_argument("--corpora", metavar="NAMES",
                    help=f"comma-separated corpora (default all: {', '.join(CORPORA)})")
    ap.add_argument("--corpus-seconds", type=positive_float, metavar="S", help="make every corpus S seconds of traffic long")
    ap.add_argument("--input", metavar="FILE",
                    help="decode this capture (raw bytes) instead of the corpora; needs --profile")
    ap.add_argument("--profile", choices=profiles, help="the wire profile of --input")
    ap.add_argument("--impl", action="append", metavar="IMPL",
                    help=f"an implementation to decode with (repeatable; default all: {', '.join(impl_names())})")
    ap.add_argument("--repeats", type=positive_int, default=REPEATS, metavar="N",
                    help=f"runs per implementation and corpus; the best counts (default {REPEATS})")
    ap.add_argument("--budget", type=positive_float, default=BUDGET, metavar="S",
                    help="no further runs of an implementation on a corpus once its runs took S seconds "
                         f"(default {BUDGET:g})")
    ap.add_argument("--timeout", type=positive_float, default=TIMEOUT, metavar="S",
                    help=f"seconds one run (of any section) may take (default {TIMEOUT:g})")
    ap.add_argument("--fuzz-examples", type=positive_int, metavar="N",
                    help="examples of the fuzz section (default %d, quick %d)" % DEFAULTS["fuzz_examples"])
    ap.add_argument("--soak-seconds", type=positive_float, metavar="S",
                    help="seconds of the acceptance section (default %g, quick %g)" % DEFAULTS["soak_seconds"])
    ap.add_argument("--device-fuzz-cases", type=positive_int, metavar="N",
                    help="cases of the device_fuzz section at each baud rate (default %d, quick %d)"
                         % DEFAULTS["device_fuzz_cases"])
    ap.add_argument("--runs", type=non_negative_int, default=RELIABILITY_RUNS, metavar="N",
                    help=f"reliability: healthy runs, active and passive in turn (default {RELIABILITY_RUNS})")
    ap.add_argument("--fault-runs", type=non_negative_int, default=FAULT_RUNS, metavar="N",
                    help=f"reliability: seeded runs of each simulator fault (default {FAULT_RUNS})")
    ap.add_argument("--fuzz-runs", type=non_negative_int, default=FUZZ_RUNS, metavar="N",
                    help=f"reliability: healthy sessions of osdkc fuzz --port (default {FUZZ_RUNS})")
    ap.add_argument("--bug-runs", type=non_negative_int, default=BUG_RUNS, metavar="N",
                    help=f"reliability: seeded fuzz sessions against each planted simulator bug (default {BUG_RUNS})")
    ap.add_argument("--busy-per-core", type=non_negative_int, default=BUSY_PER_CORE, metavar="N",
                    help=f"reliability: busy-loop processes per core for the whole measurement (default "
                         f"{BUSY_PER_CORE}: the machine saturated; 0: idle)")
    ap.add_argument("--fault-kinds", metavar="KINDS",
                    help="reliability: comma-separated simulator faults to run (default all)")
    ap.add_argument("--parallel", type=positive_int, default=1, metavar="N",
                    help="reliability: runs at a time (default 1)")
    ap.add_argument("--doctor-runs", type=positive_int, default=DOCTOR_RUNS, metavar="N",
                    help=f"doctor: seeded diagnoses of each link fault (default {DOCTOR_RUNS})")
    ap.add_argument("--tap-runs", type=non_negative_int, default=TAP_RUNS, metavar="N",
                    help=f"tap: seeded sessions of a healthy host and of each planted host bug through osdkc tap, "
                         f"beside --busy-per-core busy loops per core (default {TAP_RUNS}; 0: only the latency "
                         "the tap adds, idle and saturated)")
    ap.add_argument("--json", action="store_true",
                    help="print every number as one JSON object instead of the tables (as every --json does)")
    ap.add_argument("--markdown", metavar="FILE",
                    help="write the tables, command and machine as Markdown; in a file with a bench block "
                         "(docs/PERFORMANCE.md) only that block is replaced")


def _names(text: str | None, known, what: str) -> list[str]:
    if text is None:
        return list(known)
    names = [n.strip() for n in text.split(",") if n.strip()]
    unknown = [n for n in names if n not in known]
    if unknown or not names:
        given = ", ".join(map(repr, unknown)) or "(none given)"
        raise UsageError(f"unknown {what} {given} (known: {', '.join(known)})")
    return list(dict.fromkeys(names))


def _writable(path: str | None, option: str) -> Path | None:
    if path is None:
        return None
    p = Path(path)
    if not p.resolve().parent.is_dir():
        raise UsageError(f"{option} {path}: directory {p.resolve().parent} does not exist")
    if p.is_dir():
        raise UsageError(f"{option} {path} is a directory")
    return p


def command_line(args: argparse.Namespace) -> str:
    """The options of this run as a command someone can repeat."""
    parts = ["osdkc", "bench"]
    for opt in ("only", "corpora", "corpus_seconds", "input", "profile", "impl", "fuzz_examples", "soak_seconds",
                "device_fuzz_cases", "fault_kinds"):
        v = getattr(args, opt)
        if v is not None:
            parts += [f"--{opt.replace('_', '-')}", f"{v:g}" if isinstance(v, float) else str(v)]
    if "doctor" in (args.only or ""):
        parts += ["--doctor-runs", str(args.doctor_runs)]
    if "tap" in (args.only or ""):
        parts += ["--tap-runs", str(args.tap_runs)]
    if args.quick:
        parts.append("--quick")
    for opt, default in (("repeats", REPEATS), ("budget", BUDGET), ("timeout", TIMEOUT), ("runs", RELIABILITY_RUNS),
                         ("fault_runs", FAULT_RUNS), ("fuzz_runs", FUZZ_RUNS), ("bug_runs", BUG_RUNS),
                         ("busy_per_core", BUSY_PER_CORE), ("parallel", 1)):
        if getattr(args, opt) != default:
            parts += [f"--{opt.replace('_', '-')}", f"{getattr(args, opt):g}"]
    return " ".join(parts)


def run_bench(args: argparse.Namespace) -> int:
    sections = _names(args.only, SECTIONS, "section") if args.only else list(DEFAULT_SECTIONS)
    kinds = _names(args.fault_kinds, tuple(FAULT_CASES), "fault kind")
    impls = _names(",".join(args.impl) if args.impl else None, bench_decode.impl_names(), "implementation")
    if (args.input is None) != (args.profile is None):
        raise UsageError("--input and --profile go together")
    if args.input is not None and (args.corpora or args.corpus_seconds):
        raise UsageError("--input replaces the corpora: no --corpora or --corpus-seconds with it")
    md_path = _writable(args.markdown, "--markdown")
    pick = 1 if args.quick else 0
    fuzz_examples = args.fuzz_examples or DEFAULTS["fuzz_examples"][pick]
    soak_seconds = args.soak_seconds or DEFAULTS["soak_seconds"][pick]
    device_fuzz_cases = args.device_fuzz_cases or DEFAULTS["device_fuzz_cases"][pick]

    corpora = []
    if "decode" in sections:
        if args.input is not None:
            corpora = [bench_corpus.user_input(args.input, args.profile)]
        else:
            seconds = args.corpus_seconds or (QUICK_CORPUS_SECONDS if args.quick else None)
            for name in _names(args.corpora, bench_corpus.CORPORA, "corpus"):
                _log(f"corpus {name}: generating or loading from {bench_corpus.CACHE_DIR}")
                corpora.append(bench_corpus.corpus(name, seconds))

    started = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    t0 = time.monotonic()
    result: dict = {"command": command_line(args), "started": started, "machine": bench_sections.machine()}
    if "decode" in sections:
        _log(f"decode: {len(corpora)} corpora x {len(impls)} implementations, up to {args.repeats} runs each")
        result["decode"] = bench_decode.measure(corpora, impls, args.repeats, args.timeout, args.budget)
    if "api" in sections:
        hour = next((c for c in corpora if c.name == HOUR_CORPUS), None) if "decode" in sections else None
        if hour is None:
            hour = bench_corpus.corpus(HOUR_CORPUS, args.corpus_seconds or (QUICK_CORPUS_SECONDS if args.quick else None))
        _log(f"api: {hour.name} through the Python API and osdkc decode, native and pure Python")
        result["api"] = bench_api.measure(hour, args.timeout)
        _log(f"api: {hour.name} into an Arrow table, typed records and osdkc decode --format csv")
        flight = bench_flight.measure(hour, args.timeout)
        result["api"]["flight"] = flight
        result["api"]["ok"] = result["api"]["ok"] and flight["ok"]
    if "run" in sections:
        _log("run: osdkc run --impl all")
        result["run"] = bench_sections.conformance_run(args.timeout)
    if "fuzz" in sections:
        _log(f"fuzz: osdkc fuzz --impl all, {fuzz_examples} examples")
        result["fuzz"] = bench_sections.fuzz(fuzz_examples, FUZZ_SEED, args.timeout)
    if "acceptance" in sections:
        _log(f"acceptance: osdkc soak, {soak_seconds:g} s")
        result["acceptance"] = bench_sections.acceptance(soak_seconds, args.timeout + soak_seconds)
    if "device_fuzz" in sections:
        _log(f"device_fuzz: osdkc fuzz --port against osdkc sim over a pty, {device_fuzz_cases} cases at each of "
             + " and ".join(map(str, bench_sections.DEVICE_FUZZ_BAUDS)) + " baud")
        result["device_fuzz"] = bench_sections.device_fuzz(device_fuzz_cases, FUZZ_SEED, args.timeout)
    if "reliability" in sections:
        _log(f"reliability: {args.runs} healthy active runs, {args.fault_runs} seeded runs of each fault")
        result["reliability"] = bench_reliability.measure(args.runs, args.fault_runs, args.busy_per_core, args.parallel,
                                                          kinds, args.fuzz_runs, args.bug_runs)
        result["reliability"]["command"] = command_line(args)
    if "doctor" in sections:
        _log(f"doctor: {args.doctor_runs} seeded diagnoses of each of {len(bench_doctor.FAULTS)} link faults")
        result["doctor"] = bench_doctor.measure(args.doctor_runs, _log)
        result["doctor"]["command"] = command_line(args)
    if "tap" in sections:
        _log(f"tap: {args.tap_runs} seeded sessions of each of {len(bench_tap.CASES)} hosts relayed and "
             f"{len(bench_tap.PASSIVE_CASES)} passive, {args.busy_per_core} busy loops per core")
        result["tap"] = bench_tap.measure(args.tap_runs, _log, args.busy_per_core)
        result["tap"]["command"] = command_line(args)
    if "footprint" in sections:
        _log("footprint: generated/c on x86-64 (gcc -Os) and Cortex-M4 (clang-14 -Os), compile only; linked for "
             f"{bench_footprint.board_footprint.BOARD} and run in QEMU")
        result["footprint"] = bench_footprint.measure()
    result["total_seconds"] = round(time.monotonic() - t0, 1)
    result["machine"]["load_average_at_end"] = " ".join(f"{x:.2f}" for x in os.getloadavg())
    result["targets"] = bench_report.targets(result)
    result["ok"] = _ok(result)

    text = bench_report.terminal(result)
    if "footprint" in result:
        text += "\n\n" + bench_footprint.terminal(result["footprint"])
    if "doctor" in result:
        text += "\n\nosdkc doctor, seeded diagnoses of each link fault:\n" + bench_doctor.markdown(result["doctor"])
    if "tap" in result:
        text += "\n\nosdkc tap, seeded host sessions:\n" + bench_tap.markdown(result["tap"])
    print(json.dumps(result, indent=1) if args.json else text)
    try:
        if md_path and sections != ["footprint"]:
            bench_report.write_markdown(md_path, bench_report.markdown(result))
        if md_path and "footprint" in result:
            bench_footprint.write_markdown(md_path, bench_footprint.markdown(result["footprint"], result["command"]))
    except OSError as e:
        raise UsageError(f"cannot write the report: {e.strerror or e}") from None
    return 0 if result["ok"] else 1


def _ok(result: dict) -> bool:
    decode = result.get("decode")
    if decode and (decode["mismatches"] or not all(r["ok"] for c in decode["corpora"] for r in c["results"])):
        return False
    return all(result[s]["ok"] for s in ("api", "run", "fuzz", "acceptance", "device_fuzz", "footprint", "reliability", "doctor",
                                         "tap") if s in result)


def _log(text: str) -> None:
    print(f"osdkc bench: {text}", file=sys.stderr, flush=True)
