"""`osdkc tap`: judge the host a user brings, between it and the flight controller.

    osdkc tap --fc /dev/ttyUSB0 --baud 230400 --profile m100-fw3.1          # prints the host's pty first
    osdkc tap --fc /dev/ttyUSB0 --host /dev/ttyUSB1 --profile a3-fw3.1 --duration 60
    osdkc tap --listen-host-tx /dev/ttyUSB0 --listen-fc-tx /dev/ttyUSB1 --profile a3-fw3.1
    osdkc tap --replay captures/tap-....pcapng --profile a3-fw3.1

Relay mode forwards every byte both ways, unchanged (tap/relay.py); passive
mode only listens to the two RX taps of a Y-cable. Both record a pcapng with
the host's bytes as "tx" (sent to the flight controller) and the FC's as
"rx", the acceptance suite's own capture format, so `osdkc device --replay`,
`osdkc decode --direction both` and the Wireshark dissector read it too.
The checks are tap/checks.py's; docs/TAP.md lists them and says how to wire
a tap.

Exit status: EXIT_STATUS below.
"""
from __future__ import annotations

import argparse
import json
import math
import signal
import sys
import threading
import time
from pathlib import Path

from osdk_conformance.core.capture import CaptureError, CaptureWriter, default_capture_path
from osdk_conformance.core.errors import EXIT_INCONCLUSIVE, UsageError, cannot_read
from osdk_conformance.core.options import baud_rate, non_negative_float, positive_float, positive_int
from osdk_conformance.core.wire import key_option
from osdk_conformance.device.acceptance import expect_rates, print_results
from osdk_conformance.core.stats import percentile
from osdk_conformance.device.analysis import Analyzer
from osdk_conformance.device.checks import Options
from osdk_conformance.device.hostload import HOST_TOO_BUSY, HostClock, withheld
from osdk_conformance.device.plots import checks_html, plots_html
from osdk_conformance.device.verdict import acceptance_word, counts
from osdk_conformance.harness.report import Result, conforms, write_html, write_junit
from osdk_conformance.tap.checks import TapOptions, tap_results
from osdk_conformance.tap.judge import REORDER_S, HostJudge
from osdk_conformance.tap.plots import host_plots_html
from osdk_conformance.tap.relay import FC, HOST, Link, PtyEnd, SerialEnd
from osdk_conformance.tap.replay import judge_capture

TOOL = "osdkc tap"
EXIT_STATUS = ("exit status: 0 every check passed (PASS), 1 a check failed (FAIL), 2 usage or port error, 3 nothing "
               "failed but this machine was too busy to judge some checks (INCONCLUSIVE), 130 stopped by SIGINT, "
               "143 by SIGTERM (every report is still written; the verdict of a stopped relay is about what it saw)")
SIGNAL_EXIT = {"SIGINT": 130, "SIGTERM": 143}


def add_arguments(ap: argparse.ArgumentParser, profiles: tuple[str, ...]) -> None:
    mode = ap.add_argument_group("where the tap sits: --fc (relay), --listen-host-tx and --listen-fc-tx (passive), "
                                 "or --replay")
    mode.add_argument("--fc", metavar="PORT", help="relay: the flight controller's serial port")
    mode.add_argument("--host", metavar="PORT", help="relay: the host's serial port (two adapters); without it the "
                                                     "tap opens a pseudo-terminal for the host and prints its path "
                                                     "as the first line")
    mode.add_argument("--link", metavar="PATH",
                      help="relay without --host: a symlink naming the host's pseudo-terminal")
    mode.add_argument("--listen-host-tx", metavar="PORT", help="passive: an RX-only port wired to the host's TX line")
    mode.add_argument("--listen-fc-tx", metavar="PORT", help="passive: an RX-only port wired to the FC's TX line")
    mode.add_argument("--replay", metavar="FILE", help="judge a recorded session (a tap or device capture) again")
    ap.add_argument("--profile", required=True, choices=profiles, help="broadcast wire profile of the flight controller")
    ap.add_argument("--baud", type=baud_rate, default=230400, help="line speed (default 230400)")
    ap.add_argument("--host-baud", type=baud_rate, help="the host side's speed when it differs (default --baud)")
    ap.add_argument("--duration", type=positive_float, metavar="S", help="stop after S seconds (default: at Ctrl-C)")
    ap.add_argument("--key-env", metavar="VAR",
                    help="environment variable holding the app key (64 hex characters): judge encrypted commands too")
    ap.add_argument("--capture", metavar="FILE", help="pcapng capture file (default captures/tap-<time>-<pid>.pcapng)")
    ap.add_argument("--no-capture", action="store_true", help="do not record a capture")
    ap.add_argument("--junit", metavar="FILE", help="write a JUnit XML report")
    ap.add_argument("--html", metavar="FILE", help="write a self-contained HTML report with plots")
    ap.add_argument("--summary-json", metavar="FILE", help="write the verdict, the counts and every check as JSON")
    lim = ap.add_argument_group("limits of the host checks")
    lim.add_argument("--min-movement-hz", type=positive_float, default=10.0, metavar="HZ",
                     help="least rate of movement commands under control (default 10; DJI's users report "
                          "commands ignored below about 10 to 50 Hz)")
    lim.add_argument("--max-movement-gap", type=positive_float, default=0.5, metavar="S",
                     help="longest gap between movement commands under control (default 0.5)")
    lim.add_argument("--max-tries", type=positive_int, default=5, metavar="N",
                     help="transmissions of one command before it is a retry storm (default 5)")
    lim.add_argument("--min-resend-ms", type=non_negative_float, default=50.0, metavar="MS",
                     help="a resend sooner than this after the last one is a retry storm (default 50)")
    lim.add_argument("--ack-timeout", type=positive_float, default=1.0, metavar="S",
                     help="an ACK later than this after the last transmission is late (default 1)")
    lim.add_argument("--expect-rate", action="append", default=[], metavar="ITEM=HZ",
                     help="a broadcast rate the FC is configured for, when not the profile default (repeatable)")
    ap.add_argument("-q", "--quiet", action="store_true", help="print only the summary and the failures")
    ap.epilog = EXIT_STATUS


def _check_mode(args) -> str:
    relay, passive = args.fc is not None, args.listen_host_tx is not None or args.listen_fc_tx is not None
    if sum((relay, passive, args.replay is not None)) != 1:
        raise UsageError("say where the tap sits: --fc PORT (relay), --listen-host-tx PORT --listen-fc-tx PORT "
                         "(passive), or --replay FILE")
    if passive and not (args.listen_host_tx and args.listen_fc_tx):
        raise UsageError("passive mode needs both --listen-host-tx and --listen-fc-tx")
    if (args.host or args.link) and not relay:
        raise UsageError("--host and --link belong to relay mode (--fc)")
    if args.host and args.link:
        raise UsageError("--link names the pseudo-terminal the tap opens; with --host there is none")
    if args.replay and (args.duration or args.capture or args.no_capture):
        raise UsageError("--duration, --capture and --no-capture belong to a live tap, not --replay")
    return "relay" if relay else "passive" if passive else "replay"


def _tap_options(args) -> TapOptions:
    device = Options(profile=args.profile, duration=args.duration or 1.0,
                     expect_rates=expect_rates(args.profile, args.expect_rate))
    return TapOptions(device=device, min_movement_hz=args.min_movement_hz, max_movement_gap=args.max_movement_gap,
                      max_tries=args.max_tries, min_resend_s=args.min_resend_ms / 1000.0,
                      ack_timeout=args.ack_timeout)


def run_tap(args: argparse.Namespace) -> int:
    mode = _check_mode(args)
    key = key_option(args.key_env, False)
    opts = _tap_options(args)
    if mode == "replay":
        return _replay(args, opts, key)
    an = Analyzer(args.profile, key, opts.device.expect_rates, ack_reorder_s=REORDER_S)
    return _live(args, mode, an, HostJudge(an, args.profile, two_lines=(mode == "passive")), opts)


# ---- live --------------------------------------------------------------------------


def _ends(args, mode: str):
    if mode == "passive":
        host = SerialEnd(HOST, args.listen_host_tx, args.host_baud or args.baud)
        try:
            return SerialEnd(FC, args.listen_fc_tx, args.baud), host
        except UsageError:
            host.close()
            raise
    fc = SerialEnd(FC, args.fc, args.baud)
    try:
        host = SerialEnd(HOST, args.host, args.host_baud or args.baud) if args.host else PtyEnd(HOST, args.link)
    except UsageError:
        fc.close()
        raise
    return fc, host


def _live(args, mode: str, an, judge, opts: TapOptions) -> int:
    stopped: list[str] = []
    woken = threading.Event()

    def on_signal(signum, frame):
        stopped.append(signal.Signals(signum).name)
        woken.set()

    old = {s: signal.signal(s, on_signal) for s in (signal.SIGINT, signal.SIGTERM)}
    try:
        fc, host = _ends(args, mode)
        cap = None
        if not args.no_capture:
            path = Path(args.capture) if args.capture else default_capture_path(tool="tap")
            try:
                cap = CaptureWriter(path, {"tool": TOOL, "mode": mode, "profile": args.profile, "fc": fc.label,
                                           "host": host.label, "baud": args.baud,
                                           "started": time.strftime("%Y-%m-%dT%H:%M:%S%z")})
            except OSError as e:
                fc.close()
                host.close()
                raise UsageError(f"cannot write the capture {path}: {e.strerror or e}") from None
        # the GIL passes between the mover and the analysing thread every 0.5 ms, not 5: a
        # forwarded byte waits at most that long for a decoding broadcast frame
        sys.setswitchinterval(0.0005)
        link = Link(fc, host, judge, cap, forward=(mode == "relay"))
        if mode == "relay" and not args.host:
            print(host.label, flush=True)   # the first line: where the host connects (as osdkc sim prints)
        print(f"{TOOL}: {mode}: flight controller {fc.label}, host {host.label}, {args.profile}"
              + (f"; capturing to {cap.path}" if cap else ""), file=sys.stderr, flush=True)
        clock = HostClock()
        started = time.monotonic()
        link.start()
        end = started + args.duration if args.duration else math.inf
        while not stopped and link.alive:
            woken.wait(min(0.2, max(0.0, end - time.monotonic())))
            if time.monotonic() >= end:
                break
        link.close()
        ran_s = time.monotonic() - started
        judge.finish(link.state.t_end)
        if cap:
            cap.close()
    finally:
        for s, h in old.items():
            signal.signal(s, h)
    opts.stalls = list(link.late)
    opts.device.host = clock.load()
    opts.device.duration = ran_s
    with an.lock:
        results = tap_results(judge, opts, link.state)
    results = withheld(results, link.state.host_stalls, opts.device.host)
    for err in link.errors[:3]:
        results.append(Result("tap", "tap.link", "error", err, kind="port"))
    signame = stopped[0] if stopped else None
    meta = {"mode": mode, "profile": args.profile, "flight controller": fc.label, "host": host.label,
            "baud": args.baud, "duration": f"{ran_s:.1f} s" + (f" (stopped by {signame})" if signame else ""),
            "capture": str(cap.path) if cap else "none", **_moved(link)}
    return _finish(args, results, an, judge, meta, signame, f"{mode} {fc.label} <-> {host.label}")


def _moved(link: Link) -> dict:
    """What crossed the tap, and what forwarding added to it."""
    out = {}
    for name, who in ((HOST, "host to FC"), (FC, "FC to host")):
        m = link.moved[name]
        out[f"{who} bytes"] = m.bytes
        if m.undelivered:
            out[f"{who} bytes not delivered (the other end did not read)"] = m.undelivered
        if m.delays:
            out[f"{who} forwarding delay p99 (ms)"] = round(1000 * percentile(m.delays, 99), 3)
    return out


# ---- replay -------------------------------------------------------------------------


def _replay(args, opts: TapOptions, key: bytes | None) -> int:
    try:
        judged = judge_capture(args.replay, opts, key)
    except OSError as e:
        raise UsageError(cannot_read(args.replay, e, "capture")) from None
    except CaptureError as e:
        raise UsageError(str(e)) from None
    if judged.partial_tail:
        print(f"{TOOL}: {args.replay} ends in an incomplete block ({judged.partial_tail} bytes; the recording "
              "process was killed): judging the complete blocks", file=sys.stderr)
    meta = {"replay": args.replay, "profile": args.profile, "records": judged.records,
            **{f"capture {k}": v for k, v in judged.comment.items()}}
    return _finish(args, judged.results, judged.judge.an, judged.judge, meta, None, f"replay of {args.replay}")


# ---- the end ------------------------------------------------------------------------


def _finish(args, results: list[Result], an, judge, meta: dict, signame: str | None, where: str) -> int:
    ok = conforms(results)
    busy = any(r.kind == HOST_TOO_BUSY for r in results)
    # a tap's usual end is a Ctrl-C: the verdict is on what it saw, and says how it stopped
    word = acceptance_word(ok, None, busy)
    line = f"{word}: {counts(results)}" + (f"; stopped by {signame}" if signame else "")
    print_results(results, args.quiet)
    meta = {"verdict": line, **meta}
    if args.junit:
        write_junit(args.junit, results, TOOL, meta)
    if args.html:
        write_html(args.html, results, f"OPEN protocol tap: the host and the flight controller ({args.profile})",
                   meta, lead_html=host_plots_html(judge) + plots_html(an), extra_html=checks_html(results),
                   verdict=(line, ok and not busy), noun="check")
    if args.summary_json:
        Path(args.summary_json).write_text(json.dumps(summary(results, word, line, meta, judge), indent=2) + "\n")
    print(f"\n{TOOL}: {line}; {args.profile}, {where}")
    if signame:
        return SIGNAL_EXIT.get(signame, 130)
    return (EXIT_INCONCLUSIVE if busy else 0) if ok else 1


def summary(results: list[Result], word: str, line: str, meta: dict, judge: HostJudge) -> dict:
    """The machine-readable report: verdict, counts, every check, and what the host did."""
    modes: dict[str, int] = {}
    for m in judge.moves:
        modes[f"{m.mode:#04x}"] = modes.get(f"{m.mode:#04x}", 0) + 1
    return {"tool": TOOL, "verdict": word, "summary": line, "meta": {k: v for k, v in meta.items() if k != "verdict"},
            "host": {"frames": judge.frames, "commands": [c.name for c in judge.commands],
                     "movement commands": len(judge.moves), "mode bytes": modes},
            "checks": [{"id": r.id, "category": r.category, "status": r.status, "message": r.message,
                        **({"kind": r.kind} if r.kind else {})} for r in results]}
