"""`osdkc fuzz`: implementations against each other (harness/fuzz.py), or,
with `--port`, malformed traffic at a flight controller with a liveness
check after every case (device/fuzz_session.py).

    osdkc fuzz --port /dev/ttyUSB0 --baud 230400 --profile a3-fw3.1 --seconds 600
    osdkc fuzz --port /dev/ttyUSB0 --profile a3-fw3.1 --cases 2000 --seed 7 --restart-cmd ./power-cycle.sh
    osdkc fuzz --port /dev/ttyUSB0 --profile a3-fw3.1 --replay findings/.../finding-1-....repro.json

docs/DEVICE-FUZZING.md says what is sent, what is checked and what is safe.
A session FOUND n findings or found NOTHING (NOTHING FOUND), or was
INTERRUPTED; a replay REPRODUCED its finding or did not: the same word at
the terminal, in the HTML banner and in the JUnit property `verdict`, with
how many checks ran, passed, failed and were skipped (device/verdict.py).
`--allow-motion` asks for confirmation at a terminal first (`--yes` for
scripts), as `osdkc device` does.
"""
from __future__ import annotations

import argparse
import json
import os
import random
import shlex
import subprocess
import sys
import time
from pathlib import Path
from typing import Callable, Sequence

from osdk_conformance.core.capture import CaptureWriter
from osdk_conformance.core.errors import EXIT_INCONCLUSIVE, UsageError, cannot_read, one_line
from osdk_conformance.core.options import baud_rate, fraction, positive_float, positive_int, uint32
from osdk_conformance.core.wire import key_option
from osdk_conformance.device.acceptance import MOTION_WARNING, confirm_motion, expect_rates
from osdk_conformance.device.active import EXIT_BY_SIGNAL, Commander, Interrupts, to_the_end
from osdk_conformance.device.analysis import Analyzer
from osdk_conformance.device.fuzz_cases import KINDS, MOTION_KINDS, FuzzCase, safe
from osdk_conformance.device.fuzz_report import REPRO_FORMAT, results_of, timeline_html, write_findings
from osdk_conformance.device.fuzz_session import FuzzSession, SessionOptions, SessionOutcome
from osdk_conformance.device.liveness import LivenessOptions
from osdk_conformance.device.plots import checks_html
from osdk_conformance.device.port import Port
from osdk_conformance.device.verdict import FOUND, INCONCLUSIVE, INTERRUPTED, NOTHING_FOUND, counts
from osdk_conformance.harness import fuzz as differential
from osdk_conformance.harness.report import Result, conforms, write_html, write_junit

DIFFERENTIAL_ONLY = ("testee", "impl", "max_examples", "out", "op", "timeout")
EXIT_STATUS = ("exit status with --port: 0 NOTHING FOUND, 1 FOUND n (or the device was not live before the first "
               "case, or no case was sent, or it failed its check with no case sent: STOPPED; with --replay: the finding "
               "REPRODUCED, or the reproducer was not sent), 3 INCONCLUSIVE (no finding, but checks failed on timing "
               "while this host was busy: not judged), 2 usage or port error, or movement control not confirmed, 130 interrupted by SIGINT (also at the "
               "--allow-motion question), 143 by SIGTERM (INTERRUPTED: an interrupted session releases control, "
               "restores the rates it changed and still writes its reports)")


def add_arguments(p: argparse.ArgumentParser, profiles: Sequence[str]) -> None:
    differential.add_arguments(p, profiles)
    d = p.add_argument_group("a flight controller on a serial port (--port; docs/DEVICE-FUZZING.md)")
    d.add_argument("--port", metavar="URL", help="fuzz the device on this port: /dev/ttyUSB0, a pty, socket://...")
    d.add_argument("--baud", type=baud_rate, default=230400, help="baud rate (default 230400); bytes are paced to it")
    d.add_argument("--cases", type=positive_int, metavar="N", help="stop after N cases")
    d.add_argument("--kind", action="append", choices=tuple(KINDS), metavar="KIND",
                   help=f"only cases of this kind (repeatable; {', '.join(KINDS)})")
    d.add_argument("--allow-motion", action="store_true",
                   help="obtain control and send movement control with zero setpoints in a velocity mode; asks for "
                        "confirmation first")
    d.add_argument("--yes", action="store_true",
                   help="with --allow-motion: do not ask (for scripts; needed when standard input is not a terminal)")
    d.add_argument("--app-id", type=uint32, help="with --allow-motion: activate this app id before obtaining control")
    d.add_argument("--key-env", metavar="VAR",
                   help="environment variable holding the app key (64 hex characters): reads an encrypted broadcast")
    d.add_argument("--encrypt", action="store_true",
                   help="AES-256 encrypt the probes and the session's own commands (needs --key-env; cases are sent "
                        "as generated)")
    d.add_argument("--restart-cmd", metavar="CMD",
                   help="command that restarts the device (power cycle), run between a finding's replays")
    d.add_argument("--recover-timeout", type=positive_float, default=5.0, metavar="S",
                   help="seconds a device has to be live again after a finding (default 5)")
    d.add_argument("--ack-timeout", type=positive_float, default=1.0, metavar="S",
                   help="seconds the liveness probe waits for its ACK (default 1; it tries twice)")
    d.add_argument("--stall-timeout", type=positive_float, default=1.0, metavar="S",
                   help="longest broadcast silence a check allows (default 1)")
    d.add_argument("--rate-tolerance", type=fraction, default=0.5, metavar="FRAC",
                   help="how far below its configured rate the broadcast may fall (default 0.5)")
    d.add_argument("--expect-rate", action="append", default=[], metavar="ITEM=HZ",
                   help="a rate the FC is configured for, when not the profile default (repeatable)")
    d.add_argument("--max-findings", type=positive_int, default=5, metavar="N", help="stop after N findings (default 5)")
    d.add_argument("--minimise-trials", type=positive_int, default=40, metavar="N",
                   help="replays allowed per finding to confirm and minimise it (default 40)")
    d.add_argument("--findings-dir", metavar="DIR",
                   help="where reproducers and vector files go (default findings/fuzz-<time>-<pid>)")
    d.add_argument("--capture", metavar="FILE", help="pcapng capture (default captures/fuzz-<time>-<pid>.pcapng)")
    d.add_argument("--no-capture", action="store_true", help="no capture (findings are then replayed from memory)")
    d.add_argument("--junit", metavar="FILE", help="write a JUnit XML report")
    d.add_argument("--html", metavar="FILE", help="write an HTML report with the liveness timeline")
    d.add_argument("--replay", metavar="FILE", help="send a reproducer file's cases once and check liveness")
    d.add_argument("-q", "--quiet", action="store_true", help="print only the failures and the summary")
    p.epilog = EXIT_STATUS


def run_fuzz(args: argparse.Namespace) -> int:
    if args.port is None:
        if args.replay:
            raise UsageError("--replay needs --port")
        return differential.run_fuzz(args)
    given = [f"--{n.replace('_', '-')}" for n in DIFFERENTIAL_ONLY if getattr(args, n) not in (None, [], False)]
    if given:
        raise UsageError(f"{', '.join(given)}: only for fuzzing implementations, not with --port")
    if not args.profile or len(args.profile) != 1:
        raise UsageError("--port needs exactly one --profile: the flight controller's wire profile")
    profile = args.profile[0]
    args.profile = profile
    if not args.allow_motion:
        motion = [k for k in args.kind or () if k in MOTION_KINDS]
        if motion or args.app_id is not None:
            raise UsageError(f"{'--kind ' + motion[0] if motion else '--app-id'} needs --allow-motion")
    replay = _read_reproducer(args.replay, profile, args.allow_motion) if args.replay else None
    seed = args.seed if args.seed is not None else random.SystemRandom().randrange(1 << 32)
    seconds = args.seconds if args.seconds is not None else (None if args.cases or replay else 60.0)
    key = key_option(args.key_env, args.encrypt)
    an = Analyzer(profile, key, expect_rates(profile, args.expect_rate), None)
    sopts = SessionOptions(profile=profile, seed=seed, seconds=seconds, max_cases=args.cases,
                           allow_motion=args.allow_motion, app_id=args.app_id, baud=args.baud,
                           liveness=LivenessOptions(args.ack_timeout, args.stall_timeout,
                                                    rate_tolerance=args.rate_tolerance),
                           recover_timeout=args.recover_timeout, minimise_trials=args.minimise_trials,
                           max_findings=args.max_findings, kinds=tuple(args.kind) if args.kind else None)
    stamp = f"{time.strftime('%Y%m%d-%H%M%S')}-{os.getpid()}"
    findings_dir = Path(args.findings_dir or f"findings/fuzz-{stamp}")
    if args.allow_motion:
        print(MOTION_WARNING.replace("MOVEMENT CONTROL commands", "MOVEMENT CONTROL commands (zero setpoints)"),
              file=sys.stderr, flush=True)
        refused = confirm_motion("osdkc fuzz", _motion_plan(args, sopts, replay), args.yes)
        if refused is not None:
            return refused
    port = Port(args.port, args.baud, an)
    port.open(start=False)   # a port that cannot be opened leaves no file behind
    interrupts = Interrupts("osdkc fuzz")
    interrupts.install()
    try:
        cap = None
        if not args.no_capture:
            path = Path(args.capture or f"captures/fuzz-{stamp}.pcapng")
            try:
                cap = CaptureWriter(path, {"tool": "osdkc fuzz", "profile": profile, "port": args.port,
                                           "baud": args.baud, "seed": seed,
                                           "started": time.strftime("%Y-%m-%dT%H:%M:%S%z")})
            except OSError as e:
                port.close()
                raise UsageError(f"cannot write the capture {path}: {e.strerror or e}") from None
            print(f"osdkc fuzz: capturing to {cap.path}", file=sys.stderr, flush=True)
        port.critical = interrupts.critical
        return _session(args, profile, seed, an, port, cap, sopts, findings_dir, interrupts, replay, key)
    finally:
        interrupts.uninstall()


def _motion_plan(args, sopts: SessionOptions, replay: list[FuzzCase] | None) -> str:
    """What --allow-motion makes the session send, and for how long."""
    control = ("control authority obtained (after activating app id " + str(args.app_id) + ")"
               if args.app_id is not None else "control authority obtained")
    if replay is not None:
        return (f"the {len(replay)} case(s) of {args.replay} with {control}, and released once they are checked")
    budget = " or ".join(filter(None, [f"{sopts.seconds:g} s" if sopts.seconds else "",
                                       f"{sopts.max_cases} cases" if sopts.max_cases else ""]))
    cases = ("" if sopts.kinds is not None and not set(sopts.kinds) & MOTION_KINDS else
             " and movement control with zero setpoints (velocity modes 0x48 to 0x4F) among the cases")
    return (f"fuzz cases with {control} for the whole session{cases}: up to {budget}"
            + (", whichever ends first" if " or " in budget else "") + ", then control released")


def _restart_command(cmd: str | None) -> Callable[[], str | None] | None:
    if not cmd:
        return None
    argv = shlex.split(cmd)

    def restart() -> str | None:
        try:
            done = subprocess.run(argv, capture_output=True, text=True, timeout=60)
        except (OSError, subprocess.TimeoutExpired) as e:
            return one_line(e)
        return None if done.returncode == 0 else f"exit status {done.returncode}: {one_line(done.stderr) or '-'}"
    return restart


def _read_reproducer(path: str, profile: str, allow_motion: bool) -> list[FuzzCase]:
    try:
        doc = json.loads(Path(path).read_text(encoding="utf-8"))
    except OSError as e:
        raise UsageError(cannot_read(path, e, "reproducer")) from None
    except ValueError as e:
        raise UsageError(f"{path}: not a reproducer file (not JSON: {one_line(e)})") from None
    if not isinstance(doc, dict) or doc.get("format") != REPRO_FORMAT:
        raise UsageError(f"{path}: not a reproducer file (want \"format\": \"{REPRO_FORMAT}\")")
    if doc.get("profile") != profile:
        raise UsageError(f"{path}: a reproducer for profile {doc.get('profile')}, not {profile}")
    try:
        cases = [FuzzCase.from_json(c) for c in doc["cases"]]
    except (KeyError, TypeError, ValueError, AttributeError) as e:
        raise UsageError(f"{path}: damaged reproducer: {one_line(e)}") from None
    if not cases:
        raise UsageError(f"{path}: the reproducer holds no case")
    unsafe = [c.id for c in cases if not safe(c.data, allow_motion)]
    if unsafe:   # the same filter as the session's own cases: a file is not trusted more than a generator
        raise UsageError(f"{path}: case {unsafe[0]} could move the aircraft or take control"
                         + ("" if allow_motion else " (movement control needs --allow-motion, and then only "
                                                    "zero setpoints in a velocity mode)"))
    return cases


def _session(args, profile: str, seed: int, an, port, cap, sopts: SessionOptions, findings_dir: Path,
             interrupts: Interrupts, replay: list[FuzzCase] | None, key: bytes | None) -> int:
    cmd = Commander(port, an, profile, key, args.encrypt, ack_timeout=sopts.liveness.ack_timeout)
    session = FuzzSession(port, an, sopts, cmd, cap.path if cap else None, _restart_command(args.restart_cmd),
                          interrupts, progress=lambda text: print(f"osdkc fuzz: {text}", file=sys.stderr, flush=True))
    out: SessionOutcome = session.out
    with to_the_end(interrupts, port, an, cap) as ending:
        port.start(cap)
        out = session.replay(replay) if replay is not None else session.run()
    error = ending.error
    sent = sum(out.sent.values())
    meta = {"profile": profile, "port": args.port, "baud": args.baud, "seed": seed,
            "capture": str(cap.path) if cap else "none", "seconds": round(out.seconds, 1),
            "cases": sent, "cases per s": round(sent / out.case_seconds, 1) if out.case_seconds else 0,
            "bytes per case": round(out.bytes_sent / sent, 1) if sent else 0,
            "motion": out.motion, "restart": args.restart_cmd or "none (waits for recovery)"}
    if replay is None:
        results = results_of(out, write_findings(out, findings_dir, profile, seed, meta), sopts.kinds)
    else:
        meta.pop("seed")
        results = _replay_results(out, args.replay)
    results += session.cleanup.results
    signame = interrupts.first
    if signame or error:
        why = f"interrupted by {signame}" if signame else f"stopped by an internal error: {error}"
        cut = session.cleanup.cleanup_cut or "complete"
        results.append(Result("run", "run.complete", "error", f"{why}; clean-up: {cut}", kind="interrupted"))
    elif out.stopped and replay is None:
        results.append(Result("run", "run.complete", "skip", f"stopped before the budget: {out.stopped}",
                              kind="stopped before the budget"))
    _print(results, args.quiet)
    line, status = _verdict(args, results, out, sent, seed, profile, findings_dir, replay, signame, error)
    title = f"Device fuzzing: {profile} on {args.port}"
    meta = {"verdict": line, **meta}
    if args.junit:
        write_junit(args.junit, results, "osdkc fuzz --port", meta)
    if args.html:
        write_html(args.html, results, title, meta, verdict=(line, status == 0), noun="check",
                   lead_html=timeline_html(session.live, out), extra_html=checks_html(results))
    if args.allow_motion:
        print(f"osdkc fuzz: movement control {out.motion}", file=sys.stderr, flush=True)
    print(f"\nosdkc fuzz: {line}")
    return status


def _verdict(args, results: list[Result], out: SessionOutcome, total: int, seed: int, profile: str,
             findings_dir: Path, replay: list[FuzzCase] | None, signame: str | None, error: str) -> tuple[str, int]:
    """The summary line (also the HTML banner and the JUnit property) and the exit status."""
    checks = counts(results)
    interrupted = f"{INTERRUPTED} by {signame}" if signame else ""
    if replay is not None:
        status = 1 if out.findings or out.start_problem or out.stopped or signame or error else 0
        word = ("REPRODUCED" if out.findings else interrupted or ("NOT RUN" if not total else "STOPPED" if error
                                                                  else "NOT REPRODUCED"))
        return (f"{word}: {len(replay)} case(s) of {args.replay}, {profile} on {args.port}; {checks}",
                EXIT_BY_SIGNAL.get(signame, 130) if signame else status)
    rate = total / out.case_seconds if out.case_seconds else 0.0
    per_case = f", {out.bytes_sent / total:.1f} bytes/case" if total else ""
    tail = (f"{total} cases in {out.seconds:.1f} s ({rate:.1f} cases/s at {args.baud} baud{per_case}), "
            f"seed {seed}, {profile} on {args.port}; {checks}")
    if signame:
        return f"{interrupted}: {tail}", EXIT_BY_SIGNAL.get(signame, 130)
    if out.findings:
        return f"{FOUND} {len(out.findings)}: {tail}; reproducers in {findings_dir}", 1
    if not total:   # no case sent is no verdict
        return f"NOTHING FUZZED: {tail}", 1
    if out.unwell and not out.unwell_host:   # not a case's doing: no finding, and the cases after it were never sent
        return f"STOPPED: {tail}", 1
    if not conforms(results):   # no finding, but the session did not end well
        return f"{'STOPPED' if error or out.port_lost else 'CLEAN-UP FAILED'}: {tail}", 1
    if out.unwell or out.not_judged:   # no finding, but this host kept checks from being judged
        return f"{INCONCLUSIVE}: {tail}", EXIT_INCONCLUSIVE
    return f"{NOTHING_FOUND}: {tail}", 0


def _replay_results(out: SessionOutcome, path: str) -> list[Result]:
    if out.start_problem:
        return [Result("fuzz", "fuzz.start", "error", f"the device was not live before the replay: "
                       f"{out.start_problem}", kind="not_live")]
    if out.stopped:
        return [Result("findings", "fuzz.replay", "error", out.stopped, kind="not_run")]
    if out.findings:
        f = out.findings[0]
        return [Result("findings", "fuzz.replay", "fail", f"REPRODUCED: {f.check.describe()} after the cases of "
                       f"{path}", {"symptoms": f.check.symptoms}, kind="+".join(f.check.symptoms))]
    return [Result("findings", "fuzz.replay", "pass", f"not reproduced: the device stayed live after the cases of "
                   f"{path}")]


def _print(results: list[Result], quiet: bool) -> None:
    for r in results:
        if quiet and r.status in ("pass", "skip"):
            continue
        print(f"{r.status.upper():5} {r.id:32} {r.message}")
