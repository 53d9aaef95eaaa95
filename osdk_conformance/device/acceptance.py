"""`osdkc device`: acceptance suite for a flight controller on a serial port.

    osdkc device --port /dev/ttyUSB0 --baud 230400 --profile a3-fw3.1 --duration 10
    osdkc device --port socket://127.0.0.1:5760 --profile m100-fw3.1 --active --app-id 1234567 --key-env OSDK_KEY
    osdkc device --replay captures/device-....pcapng --profile a3-fw3.1

Passive checks listen to the broadcast; `--active` adds the command
exchange (version, activation, frequencies, control authority) and, only
with `--allow-motion`, movement control (asked for at the terminal first:
`confirm_motion`; `--yes` for scripts). Every received and sent byte is
recorded in a pcapng capture (core/capture.py) that `--replay` checks offline.
Each check is a named Result (category = check group, id = check name), so
the reports are those of `osdkc run`. docs/ACCEPTANCE.md lists every check.

Exit status: EXIT_STATUS below (also the --help epilog and docs/ACCEPTANCE.md).
An active run always ends through ActiveRun.clean_up (active.py). A run
PASSES, FAILS or was INTERRUPTED (device/verdict.py): the same word at the
terminal, in the HTML banner and in the JUnit property `verdict`.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from osdk_conformance.core.capture import CaptureError, CaptureWriter, RX, default_capture_path, open_capture
from osdk_conformance.core.errors import EXIT_INCONCLUSIVE, UsageError, cannot_read
from osdk_conformance.core.options import baud_rate, fraction, non_negative_float, positive_float, uint32
from osdk_conformance.core.rules import RulesError, default_rules
from osdk_conformance.core.wire import key_option
from osdk_conformance.device.active import (ActiveRun, Commander, EXIT_BY_SIGNAL, Interrupts, not_reached,
                                             to_the_end)
from osdk_conformance.device.analysis import Analyzer
from osdk_conformance.device.checks import Options, passive_results
from osdk_conformance.device.hostload import HOST_TOO_BUSY, HostClock, withheld
from osdk_conformance.device.plots import checks_html, plots_html
from osdk_conformance.device.port import Port
from osdk_conformance.device.verdict import acceptance_word, counts
from osdk_conformance.harness.report import ERROR, PASS, SKIP, Result, conforms, summary_table, write_html, write_junit

EXIT_STATUS = ("exit status: 0 every check passed (PASS), 1 a check failed or errored (FAIL), 2 usage or port "
               "error, or movement control not confirmed, 3 nothing failed but this host was too busy to read the "
               "port in time for some checks, which were not judged (INCONCLUSIVE: run again on a quieter host), 130 interrupted by SIGINT (also at the --allow-motion "
               "question), 143 by SIGTERM (INTERRUPTED: an interrupted run releases control, restores the rates "
               "it changed and still writes its reports; a second SIGINT cuts that clean-up short)")

MOTION_WARNING = """\
!!! WARNING: --allow-motion sends MOVEMENT CONTROL commands. On a real flight
!!! controller this MOVES THE AIRCRAFT (attitude, velocity, position and height
!!! changes of several metres). Remove the propellers or use the DJI simulator,
!!! keep the RC in hand and be ready to take over."""
ANSWERS_YES = ("yes", "y")


# --------------------------------------------------------------------------
# Command line


def add_arguments(ap: argparse.ArgumentParser, profiles: tuple[str, ...]) -> None:
    src = ap.add_mutually_exclusive_group(required=True)
    src.add_argument("--port", metavar="URL", help="serial port: /dev/ttyUSB0, a pty path, socket://HOST:PORT, rfc2217://...")
    src.add_argument("--replay", metavar="FILE", help="run the passive checks on a pcapng capture instead")
    ap.add_argument("--baud", type=baud_rate, default=230400, help="baud rate (default 230400)")
    ap.add_argument("--profile", required=True, choices=profiles, help="broadcast wire profile of the flight controller")
    ap.add_argument("--duration", type=positive_float, default=10.0, metavar="S", help="seconds of passive listening (default 10)")
    ap.add_argument("--active", action="store_true", help="also send commands: version, activation, frequency, control")
    ap.add_argument("--allow-motion", action="store_true",
                    help="with --active: send movement control (MOVES THE AIRCRAFT); asks for confirmation first")
    ap.add_argument("--yes", action="store_true",
                    help="with --allow-motion: do not ask (for scripts; needed when standard input is not a terminal)")
    ap.add_argument("--app-id", type=uint32, help="app id for activation (with --active)")
    ap.add_argument("--key-env", metavar="VAR", help="environment variable holding the app key (64 hex characters)")
    ap.add_argument("--encrypt", action="store_true", help="AES-256 encrypt the commands sent (needs --key-env)")
    ap.add_argument("--capture", metavar="FILE", help="pcapng capture file (default captures/device-<time>-<pid>.pcapng)")
    ap.add_argument("--no-capture", action="store_true", help="do not record a capture")
    ap.add_argument("--junit", metavar="FILE", help="write a JUnit XML report")
    ap.add_argument("--html", metavar="FILE", help="write a self-contained HTML report with plots")
    ap.add_argument("--rate-tolerance", type=fraction, default=0.10, metavar="FRAC", help="allowed rate error (default 0.10)")
    ap.add_argument("--max-link-errors", type=non_negative_float, default=0.001, metavar="FRAC",
                    help="allowed link incidents per frame, per kind (default 0.001)")
    ap.add_argument("--max-jitter-ms", type=positive_float, default=25.0, metavar="MS", help="allowed arrival spread (default 25)")
    ap.add_argument("--stall-timeout", type=positive_float, default=1.0, metavar="S", help="longest silence allowed (default 1)")
    ap.add_argument("--flight-status-enum", choices=("old", "new"), help="override the profile's flight status enum")
    ap.add_argument("--expect-rate", action="append", default=[], metavar="ITEM=HZ",
                    help="a rate the FC is configured for, when not the profile default (repeatable)")
    ap.add_argument("--active-window", type=positive_float, default=2.0, metavar="S",
                    help="seconds to measure rates after setting frequencies (default 2)")
    ap.add_argument("--motion-seconds", type=positive_float, default=1.5, metavar="S",
                    help="seconds each movement command is held (default 1.5; position 5/3 of it)")
    ap.add_argument("-q", "--quiet", action="store_true", help="print only the summary and the failures")
    ap.epilog = EXIT_STATUS


def expect_rates(profile: str, specs: list[str]) -> dict[str, int] | None:
    """The --expect-rate ITEM=HZ options (also `osdkc fuzz --port`'s)."""
    prof = default_rules().profile(profile)
    rates = {}
    for spec in specs:
        item, _, hz = spec.partition("=")
        if item not in prof.flag_bits or not hz.isdigit():
            raise UsageError(f"--expect-rate {spec}: want ITEM=HZ, ITEM one of {', '.join(prof.flag_bits)}")
        rates[item] = int(hz)
    return rates or None


def _options(args) -> Options:
    rates = expect_rates(args.profile, args.expect_rate)
    try:
        if args.flight_status_enum:
            default_rules().flight_status_enum(args.profile, args.flight_status_enum)
    except RulesError as e:
        raise UsageError(str(e)) from None
    return Options(profile=args.profile, duration=args.duration, rate_tolerance=args.rate_tolerance,
                   max_link_errors=args.max_link_errors, max_jitter_ms=args.max_jitter_ms,
                   stall_timeout=args.stall_timeout, flight_status_enum=args.flight_status_enum,
                   expect_rates=rates or None)


def motion_plan(seconds: float) -> str:
    """What `movement_check` (active.py) commands, and for how long."""
    steps = ((seconds, "attitude: roll 5 deg, pitch -3 deg, yaw 20 deg from the heading"),
             (seconds, "velocity: 1 m/s north, 0.5 m/s west, climb 0.3 m/s, yaw at 10 deg/s"),
             (seconds * 5 / 3, "position: to 2 m north, 1 m east, 1 m higher"),
             (0.5, "hover: zero velocity"))
    return (f"movement control, once control authority is obtained, for about {sum(t for t, _ in steps):.1f} s in "
            f"all (--motion-seconds {seconds:g}):\n" + "\n".join(f"  {t:4.1f} s  {what}" for t, what in steps))


def confirm_motion(tool: str, plan: str, yes: bool, stdin=None, stderr=None) -> int | None:
    """Ask before anything moves: None to go on, else the exit status (2
    refused or no answer, 130 Ctrl-C). With `yes` nothing is asked; when
    standard input is not a terminal nobody could answer: a usage error
    that says to add --yes (a script must not block on a question)."""
    if yes:
        return None
    stdin, stderr = stdin or sys.stdin, stderr or sys.stderr
    try:
        interactive = stdin.isatty()
    except (AttributeError, ValueError, OSError):
        interactive = False
    if not interactive:
        raise UsageError("--allow-motion: standard input is not a terminal, so nobody can confirm that the aircraft "
                         "may move; add --yes to send movement control without asking (nothing was sent)")
    try:   # from the prompt on: a Ctrl-C that comes as soon as the question shows is an answer too
        stderr.write(f"{tool}: about to send {plan}\n{tool}: type yes to go on (anything else aborts): ")
        stderr.flush()
        answer = stdin.readline()
    except KeyboardInterrupt:
        stderr.write(f"\n{tool}: interrupted at the question: nothing was sent\n")
        stderr.flush()
        return 130
    except OSError:   # the terminal went away
        answer = ""
    if answer.strip().lower() in ANSWERS_YES:
        return None
    why = f'the answer was "{answer.strip()}", not yes' if answer.strip() else (
        "no answer (end of input)" if not answer else "the answer was empty, not yes")
    stderr.write(("" if answer.endswith("\n") else "\n") + f"{tool}: movement control not confirmed ({why}): "
                 "nothing was sent\n")
    stderr.flush()
    return 2


def print_results(results: list[Result], quiet: bool, stream=None) -> None:
    stream = stream or sys.stdout
    for r in results:
        if quiet and r.status in (PASS, SKIP):
            continue
        stream.write(f"{r.status.upper():5} {r.id:28} {r.message}\n")
    stream.write("\n" + summary_table(results) + "\n")


def write_reports(args, results: list[Result], an, meta: dict, verdict: tuple[str, bool]) -> None:
    """JUnit and HTML, both with the terminal's verdict line (`verdict`: it
    and whether it is good): the property `verdict` and the banner."""
    meta = {"verdict": verdict[0], **meta}
    if args.junit:
        write_junit(args.junit, results, "osdkc device", meta)
    if args.html:
        write_html(args.html, results, f"OPEN protocol acceptance run: {meta.get('profile')}", meta,
                   lead_html=plots_html(an), extra_html=checks_html(results), verdict=verdict, noun="check")


def run_device(args: argparse.Namespace) -> int:
    opts = _options(args)
    key = key_option(args.key_env, args.encrypt)
    if args.allow_motion and not args.active:
        raise UsageError("--allow-motion needs --active")
    an = Analyzer(args.profile, key, opts.expect_rates, opts.flight_status_enum)
    if args.replay:
        return _replay(args, an, opts)

    if args.allow_motion:
        print(MOTION_WARNING, file=sys.stderr, flush=True)
        refused = confirm_motion("osdkc device", motion_plan(args.motion_seconds), args.yes)
        if refused is not None:
            return refused
    port = Port(args.port, args.baud, an)
    port.open(start=False)   # before the capture: a port that cannot be opened leaves no file behind
    interrupts = Interrupts()
    interrupts.install()
    try:
        cap = _open_capture(args, port)
        port.critical = interrupts.critical
        return _live(args, opts, an, port, cap, key, interrupts)
    finally:
        interrupts.uninstall()


def _open_capture(args, port: Port):
    if args.no_capture:
        return None
    path = Path(args.capture) if args.capture else default_capture_path()
    meta_c = {"tool": "osdkc device", "profile": args.profile, "port": args.port, "baud": args.baud,
              "started": time.strftime("%Y-%m-%dT%H:%M:%S%z")}
    try:
        cap = CaptureWriter(path, meta_c)
    except OSError as e:
        port.close()
        raise UsageError(f"cannot write the capture {path}: {e.strerror or e}") from None
    return cap


def _live(args, opts: Options, an, port: Port, cap, key, interrupts) -> int:
    """Listen, run the active checks (which clean up after themselves however
    they end), then report every result measured, whatever ended the run."""

    results: list[Result] = [Result("link", "link.open", PASS, f"opened {args.port} at {args.baud} baud")]
    run: ActiveRun | None = None
    host = HostClock()
    started = time.monotonic()   # from the first byte read on: the run's actual duration
    with to_the_end(interrupts, port, an, cap) as ending:
        if cap:
            print(f"osdkc device: capturing to {cap.path}", file=sys.stderr, flush=True)
        port.start(cap)
        started = time.monotonic()
        end = started + args.duration
        while time.monotonic() < end:
            time.sleep(min(0.1, max(0.0, end - time.monotonic())))
        if args.active and port.ser is None:
            results.append(Result("active", "active.version", ERROR, "port down: active checks not run"))
        elif args.active:
            run = ActiveRun(Commander(port, an, args.profile, key, args.encrypt), an, opts, args.app_id,
                            args.allow_motion, args.active_window, args.motion_seconds, interrupts)
            run.run()
    error = ending.error
    ran_s = time.monotonic() - started
    opts.host = host.load()
    with an.lock:
        results += passive_results(an, opts, port.state)
    signame = interrupts.first
    phase = interrupts.first_phase if signame else (run.stopped_in or run.phase) if run else "passive"
    if run:
        results += run.results
    if args.active and (signame or error):
        why = f"interrupted by {signame}" if signame else "stopped by an error"
        results += not_reached(results, f"the run was {why} during phase {phase}")
    cleanup = (run.cleanup_cut if run and run.cleanup_cut else "complete") if run else "nothing to undo"
    if signame:
        results.append(Result("run", "run.complete", ERROR, f"interrupted by {signame} during phase {phase}; "
                              f"clean-up: {cleanup}", {"signals": interrupts.signals, "phase": phase,
                                                       "clean-up": cleanup}, kind="interrupted"))
    elif error:
        results.append(Result("run", "run.complete", ERROR, f"the run stopped on an internal error during phase "
                              f"{phase}: {error}; clean-up: {cleanup}", {"phase": phase, "clean-up": cleanup},
                              kind="exception"))
    results = withheld(results, port.state.host_stalls, opts.host)
    ok = conforms(results)
    host_busy = any(r.kind == HOST_TOO_BUSY for r in results)
    word = acceptance_word(ok, signame, host_busy)
    how = f" by {signame} during phase {phase} after {ran_s:.1f} s, clean-up {cleanup}" if signame else ""
    line = f"{word}{how}: {counts(results)}"
    meta = {"profile": args.profile, "port": args.port, "baud": args.baud,
            "duration": f"{ran_s:.1f} s" + (f" (interrupted; {args.duration:g} s of listening planned)" if signame
                                            else f" ({args.duration:g} s of listening)"),
            "capture": str(cap.path) if cap else "none", "active": args.active,
            "movement control": "allowed" if args.allow_motion else "not allowed",
            "interrupted": f"{signame} during phase {phase}" if signame else "no", "clean-up": cleanup}
    print_results(results, args.quiet)
    write_reports(args, results, an, meta, (line, ok and not signame and not host_busy))
    print(f"\nosdkc device: {line}; {'' if signame else f'{ran_s:.1f} s, '}{args.profile} on {args.port}")
    if signame:
        return EXIT_BY_SIGNAL.get(signame, 130)
    return (EXIT_INCONCLUSIVE if host_busy else 0) if ok else 1


def _replay(args, an, opts: Options) -> int:
    try:
        with open_capture(args.replay) as capf:  # block by block: memory does not grow with the file
            for rec in capf:
                (an.feed_rx if rec.direction == RX else an.feed_tx)(rec.t, rec.data)
    except OSError as e:
        raise UsageError(cannot_read(args.replay, e, "capture")) from None
    except CaptureError as e:  # names the file and the offset of the damage
        raise UsageError(str(e)) from None
    an.finish()
    results = passive_results(an, opts, None)
    meta = {"profile": args.profile, "replay": args.replay, "records": capf.count,
            "incomplete last block bytes": capf.partial_tail, **{f"capture {k}": v for k, v in capf.comment.items()}}
    if capf.partial_tail:
        print(f"osdkc device: {args.replay} ends in an incomplete block ({capf.partial_tail} bytes; "
              "the recording process was killed): replaying the complete blocks", file=sys.stderr)
    ok = conforms(results)
    line = f"{acceptance_word(ok, None)}: {counts(results)}"
    print_results(results, args.quiet)
    write_reports(args, results, an, meta, (line, ok))
    print(f"\nosdkc device: {line}; {args.profile}, replay of {args.replay}")
    return 0 if ok else 1
