#!/usr/bin/env python3
"""`make prove`: Frama-C's WP proves units of the generated C library free of
runtime errors, against the ACSL contracts tools/cgen emits.

For each unit (one generated .c file, every function in it) Frama-C's RTE
plugin turns every operation C leaves undefined into a goal (a memory access
out of its object, pointer arithmetic outside an object, a signed overflow,
a shift out of range, a division by zero) and WP proves those goals, the
contracts (`requires` met at every call, `assigns` the only writes) and the
loops' invariants and variants (termination) with z3 and cvc4. A unit is
proved when every goal is; one goal not proved fails the run (exit 1).

WP's cache (`-wp-cache update`, in .cache/prove/ of the checkout) keeps each
prover's answer per goal: a second run asks the provers only about goals
that changed. Per unit it prints goals, proved, time, and what WP assumed
about memory (its "memory model hypotheses": that two regions do not
overlap); docs/VERIFICATION.md says what the proof covers and what not.

`--mutants` then plants bounds bugs (MUTANTS), each in a copy of the
library, and checks that the proof of the function fails on the goal the
bug breaks: `make prove` runs them all.

Exit status: 0 every goal proved (and every mutant caught), 1 a goal not
proved or a mutant not caught, 2 Frama-C missing, a unit that does not
parse, or bad arguments.
"""
from __future__ import annotations

import argparse
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SOURCE = ROOT / "generated" / "c"
CACHE = ROOT / ".cache" / "prove"

# What is proved today (docs/VERIFICATION.md), unit -> which of its functions:
# None for every one, or the names (regular expressions) to prove, or to leave
# out, of the functions the unit defines.
UNITS: dict[str, dict | None] = {
    "osdk_crc.c": None,
    "osdk_acks.c": None,
    "osdk_encode.c": None,
    "osdk_decoder.c": {"except": [], "also": ["osdk_kdiv", "osdk_kmod"]},   # with the header's inline helpers
    "osdk_broadcast.c": None,
    # the three that call the user's callback with its model (osdk_event_model) as the callback
    "osdk_deframer.c": None,
}
# A function definition as the generators write it: the name, then `{` on the next line.
DEFINITION = re.compile(r"^(?:static\s+)?(?:inline\s+)?[A-Za-z_][\w \*]*?\b([A-Za-z_]\w*)\([^;{]*\)\s*\n\{", re.M)


def _split(unit: str, source: Path) -> tuple[list[str] | None, list[str]]:
    """The functions of `unit` to prove (None: all of them) and those it defines but leaves out."""
    rule = UNITS.get(unit)
    if rule is None:
        return None, []
    defined = DEFINITION.findall((source / unit).read_text(encoding="utf-8"))
    if "only" in rule:
        chosen = [f for f in defined if any(re.fullmatch(r, f) for r in rule["only"])] + rule.get("also", [])
    else:
        chosen = [f for f in defined if not any(re.fullmatch(r, f) for r in rule["except"])] + rule.get("also", [])
    return chosen, [f for f in defined if f not in chosen]


def selected(unit: str, source: Path) -> list[str] | None:
    """The functions of `unit` to prove (None: all of them)."""
    return _split(unit, source)[0]


def left_out(unit: str, source: Path) -> list[str]:
    """The functions `unit` defines that are not proved."""
    return _split(unit, source)[1]


# Planted bugs, each in a copy of the library: the proof of the function must
# then fail, on the goal named (a proof that cannot fail shows nothing).
# name -> (unit, function, the line as generated, the line with the bug, the goal WP can no longer prove)
MUTANTS = {
    "crc-reads-one-past-the-end": ("osdk_crc.c", "osdk_crc16", "for (i = 0; i < len; i++) {",
                                   "for (i = 0; i <= len; i++) {", "osdk_crc16_assert_rte_mem_access"),
    "acks-session-check-missing": ("osdk_acks.c", "osdk_acks_command",
                                   "if (session < OSDK_ACK_FIRST_SESSION || session >= OSDK_ACK_SESSIONS) return;",
                                   "if (session < OSDK_ACK_FIRST_SESSION) return;",
                                   "osdk_acks_command_assert_rte_pointer_value"),
    "encode-copies-one-byte-too-many": ("osdk_encode.c", "osdk_encode_frame",
                                        "for (i = 0; i < len; i++) out[at++] = value[i];",
                                        "for (i = 0; i <= len; i++) out[at++] = value[i];",
                                        "osdk_encode_frame_assert_rte_mem_access"),
    "encode-room-check-one-short": ("osdk_encode.c", "osdk_encode_frame",
                                    "if (out == NULL || cap < frame_len) return OSDK_ENCODE_BUFFER_TOO_SMALL;",
                                    "if (out == NULL || cap + 1u < frame_len) return OSDK_ENCODE_BUFFER_TOO_SMALL;",
                                    "osdk_encode_frame_assert_rte_mem_access"),
    "deframer-window-overrun": ("osdk_deframer.c", "take", "k = len < space ? len : space;",
                                "k = len < space ? len : space + 1u;", "take_assert_rte_mem_access"),
    "feed-steps-past-what-it-took": ("osdk_deframer.c", "osdk_deframer_feed", "data += k;", "data += k + 1u;",
                                     "osdk_deframer_feed_assert_rte_pointer_value"),
    "stream-reads-one-past-the-end": ("osdk_decoder.c", "osdk_read_uint",
                                      "if (nbytes > 8 || io->size - io->pos < nbytes) return false;",
                                      "if (nbytes > 8 || io->size - io->pos + 1u < nbytes) return false;",
                                      "osdk_read_uint_assert_rte_mem_access"),
    "frame-checks-a-byte-it-did-not-read": ("osdk_decoder.c", "osdk_frame__read_sof",
                                            "if (!osdk_read_bytes(io, 1, &self->sof))",
                                            "if (!osdk_read_bytes(io, 0, &self->sof))",
                                            "osdk_frame_read_sof_assert_rte_mem_access"),   # WP names the goals of `a__b` as `a_b`
}
# A planted bug's goal cannot be proved, so it uses each prover's whole timeout: every goal of the
# proved units takes well under a second, 1 s is ample
MUTANT_TIMEOUT_S = 1
# per goal and prover; the longest proved goal, a postcondition of osdk_frame_frame_data__read_value, takes
# cvc4 about 20 s on an idle 2-core machine
TIMEOUT_S = 60
# -rte-no-pointer-call: WP 25 has no \valid_function, so the goal that a call
# through a pointer reaches a function of its type could never be proved.
# The one such call in the proved units is the deframer's callback, whose
# target the contracts fix (fn == &osdk_event_model, a declared function of
# that type).
WP = ["-wp", "-wp-rte", "-rte-no-pointer-call", "-warn-invalid-pointer", "-wp-prover", "z3,cvc4"]
HYPOTHESES = re.compile(r"Memory model hypotheses for function '([^']+)':\s*/\*@\s*behavior wp_typed:\s*"
                        r"requires (.*?);\s*\*/", re.S)


@dataclass
class Unit:
    name: str
    seconds: float = 0.0
    goals: int = 0
    proved: int = 0
    functions: dict[str, tuple[int, int]] = field(default_factory=dict)   # name -> (goals, proved)
    unproved: list[str] = field(default_factory=list)                     # property names
    assumed: dict[str, str] = field(default_factory=dict)                 # function -> WP's hypothesis
    problem: str = ""                                                      # Frama-C did not run through


class Stopped(Exception):
    def __init__(self, signum: int) -> None:
        super().__init__(signum)
        self.signum, self.name = signum, signal.Signals(signum).name


def _stopped(signum: int, frame) -> None:
    raise Stopped(signum)


def why3_config() -> Path:
    """WP reaches z3 and cvc4 through Why3, which finds them only in its
    configuration: one of our own, detected once, not the user's ~/.why3.conf."""
    conf = CACHE / "why3.conf"
    if not conf.is_file():
        CACHE.mkdir(parents=True, exist_ok=True)
        partial = conf.with_suffix(".part")
        subprocess.run(["why3", "-C", str(partial), "config", "detect"], capture_output=True, check=False)
        if partial.is_file():
            partial.replace(conf)
    return conf


# the Frama-C runs under way (their process groups), for a stop to end them
_RUNNING: set[subprocess.Popen] = set()
_RUNNING_LOCK = threading.Lock()


def _kill(proc: subprocess.Popen) -> None:
    if proc.poll() is None:
        try:
            os.killpg(proc.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
        proc.wait()


def prove(unit: str, source: Path, jobs: int, cache: Path | None, timeout: int = TIMEOUT_S,
          functions: list[str] | None = None) -> Unit:
    """Prove `functions` of `unit` (None: all). With several jobs and
    functions, as many Frama-C runs side by side, each proving a share of
    them: WP builds and simplifies its goals on one core, and for the
    decoder that, not the provers, is most of the time."""
    if not functions or jobs <= 1 or len(functions) == 1:
        return _prove_run(unit, source, jobs, cache, timeout, functions)
    shares = [functions[k::jobs] for k in range(min(jobs, len(functions)))]
    out = Unit(unit)
    t0 = time.monotonic()
    pool = ThreadPoolExecutor(len(shares))
    try:
        futures = [pool.submit(_prove_run, unit, source, 1, cache, timeout, share) for share in shares]
        runs = [f.result() for f in futures]
    except Stopped:   # the runs' Frama-C would go on: end them, so that the threads end too
        with _RUNNING_LOCK:
            for proc in _RUNNING:
                _kill(proc)
        raise
    finally:
        pool.shutdown(wait=True)
    out.seconds = time.monotonic() - t0
    for r in runs:
        out.goals += r.goals
        out.proved += r.proved
        out.functions.update(r.functions)
        out.unproved += r.unproved
        out.assumed.update(r.assumed)
        out.problem = out.problem or r.problem
    return out


def _prove_run(unit: str, source: Path, jobs: int, cache: Path | None, timeout: int,
               functions: list[str] | None) -> Unit:
    out = Unit(unit)
    with tempfile.TemporaryDirectory(prefix="osdk-prove-") as tmp:
        report = Path(tmp) / "report.json"
        cmd = ["frama-c", f"-cpp-extra-args=-I{source}", str(source / unit), *WP, "-wp-timeout", str(timeout), "-wp-par", str(jobs),
               "-wp-report-json", str(report)]
        if functions:
            cmd += ["-wp-fct", ",".join(functions)]
        if cache is not None:
            cache.mkdir(parents=True, exist_ok=True)
            cmd += ["-wp-cache", "update", "-wp-cache-dir", str(cache)]
        t0 = time.monotonic()
        # its own session, so that a stop ends Frama-C and every prover it started, not Frama-C alone
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, cwd=tmp,
                                start_new_session=True, env={**os.environ, "WHY3CONFIG": str(why3_config())})
        with _RUNNING_LOCK:
            _RUNNING.add(proc)
        try:
            log = proc.communicate()[0]
        finally:
            _kill(proc)
            with _RUNNING_LOCK:
                _RUNNING.discard(proc)
        out.seconds = time.monotonic() - t0
        if proc.returncode != 0 or not report.is_file():
            errors = [line for line in log.splitlines() if "error" in line.lower()] or log.strip().splitlines()[-3:]
            out.problem = "Frama-C stopped: " + " | ".join(errors[:3])
            return out
        functions = dict(json.loads(report.read_text())).get("wp:functions", {})
    for fn, props in functions.items():
        goals = proved = 0
        for prop, by in props.items():
            if prop == "wp:section":   # the function's own total of the properties below
                continue
            main = by.get("wp:main", {})
            goals += main.get("total", 0)
            proved += main.get("valid", 0)
            if main.get("valid", 0) < main.get("total", 0):
                out.unproved.append(prop)
        out.functions[fn] = (goals, proved)
        out.goals += goals
        out.proved += proved
    out.assumed = {fn: " ".join(req.split()) for fn, req in HYPOTHESES.findall(log)}
    if not out.goals:
        out.problem = "WP made no goal (no function, or none with a contract)"
    return out


def check_mutant(name: str, source: Path, jobs: int) -> tuple[bool, str]:
    """Plant mutant `name` in a copy of `source` and prove its function:
    (the proof failed on the goal it must, what happened)."""
    unit, fn, good, bad, goal = MUTANTS[name]
    text = (source / unit).read_text(encoding="utf-8")
    if good not in text:   # the first occurrence is in `fn`
        return False, f"{unit} no longer has {good!r}: update the mutant"
    with tempfile.TemporaryDirectory(prefix="osdk-mutant-") as tmp:
        copy = Path(tmp) / "c"
        shutil.copytree(source, copy)
        (copy / unit).write_text(text.replace(good, bad, 1), encoding="utf-8")
        u = prove(unit, copy, jobs, None, MUTANT_TIMEOUT_S, [fn])
    if u.problem:
        return False, u.problem
    hit = [p for p in u.unproved if p.startswith(goal)]
    if not hit:
        return False, f"the proof did not fail on {goal} (not proved: {', '.join(u.unproved) or 'nothing'})"
    return True, f"{u.goals - u.proved} of {u.goals} goals of {fn} not proved, {hit[0]} among them ({u.seconds:.1f} s)"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("units", nargs="*", metavar="UNIT", help=f"units to prove (default all: {', '.join(UNITS)})")
    ap.add_argument("--source", type=Path, default=SOURCE, help="the generated C library (default generated/c)")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1, help="goals proved at once (default: cores)")
    ap.add_argument("--no-cache", action="store_true", help="ask the provers about every goal again")
    ap.add_argument("--timeout", type=int, default=TIMEOUT_S, metavar="S",
                    help=f"seconds each prover gets for a goal (default {TIMEOUT_S}); a goal not proved in time "
                         "is not proved")
    ap.add_argument("--function", action="append", metavar="FN",
                    help="prove only the functions of the units this regular expression matches (repeatable; "
                         "the others' contracts are assumed)")
    ap.add_argument("--mutants", nargs="*", metavar="NAME", choices=list(MUTANTS),
                    help="after the proof, plant each bug (default all: " + ", ".join(MUTANTS) + ") in a copy "
                         "and check that the proof fails on it; no unit is proved when only mutants are named "
                         "and no UNIT is")
    ap.add_argument("--json", action="store_true", help="one JSON object per unit instead of the table")
    ap.add_argument("-v", "--verbose", action="store_true", help="goals per function")
    args = ap.parse_args(argv)
    for sig in (signal.SIGINT, signal.SIGTERM):   # also where the caller left SIGINT ignored (a background job)
        signal.signal(sig, _stopped)
    only_mutants = args.mutants is not None and len(args.mutants) > 0 and not args.units
    units = [] if only_mutants else args.units or list(UNITS)
    unknown = [u for u in units if not (args.source / u).is_file()]
    if unknown:
        print(f"prove: no such unit in {args.source}: {', '.join(unknown)}", file=sys.stderr)
        return 2
    missing = [tool for tool in ("frama-c", "why3", "z3", "cvc4") if shutil.which(tool) is None]
    if missing:
        print(f"prove: {', '.join(missing)} not installed; `make setup` installs them (tools/apt-packages.sh)",
              file=sys.stderr)
        return 2
    cache = None if args.no_cache else CACHE / "wp"
    failed = broken = False
    try:
        if not args.json and units:
            print(f"{'unit':16} {'goals':>6} {'proved':>7} {'seconds':>8}")
        for name in units:
            chosen = selected(name, args.source)
            if args.function:
                everything = chosen if chosen is not None else DEFINITION.findall(
                    (args.source / name).read_text(encoding="utf-8"))
                chosen = [f for f in everything if any(re.fullmatch(r, f) for r in args.function)]
                if not chosen:
                    print(f"prove: no function of {name} matches {', '.join(args.function)}", file=sys.stderr)
                    return 2
            u = prove(name, args.source, max(1, args.jobs), cache, max(1, args.timeout), chosen)
            broken |= bool(u.problem)
            failed |= u.proved < u.goals
            if args.json:
                print(json.dumps(u.__dict__, sort_keys=True))
                continue
            print(f"{u.name:16} {u.goals:>6} {u.proved:>7} {u.seconds:>8.1f}"
                  + (f"  {u.problem}" if u.problem else "  PROVED" if u.proved == u.goals else "  NOT PROVED"))
            for prop in u.unproved:
                print(f"    not proved: {prop}")
            left = left_out(name, args.source) if not args.function else []
            if left:
                print(f"    left out ({len(left)} functions, docs/VERIFICATION.md): "
                      + (", ".join(left) if len(left) <= 6 else ", ".join(left[:6]) + ", ..."))
            if args.verbose:
                for fn, (goals, proved) in u.functions.items():
                    print(f"    {fn:40} {goals:>4} {proved:>4}")
            for fn, req in u.assumed.items():
                print(f"    assumed by WP for {fn}: {req}")
        if args.mutants is not None:
            for name in args.mutants or list(MUTANTS):
                caught, what = check_mutant(name, args.source, max(1, args.jobs))
                failed |= not caught
                print(f"mutant {name}: " + ("the proof fails, as it must: " if caught else "NOT CAUGHT: ") + what)
    except Stopped as e:
        print(f"prove: stopped by {e.name}; the units above were proved, the rest not", file=sys.stderr)
        return 128 + e.signum
    if broken:
        return 2
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
