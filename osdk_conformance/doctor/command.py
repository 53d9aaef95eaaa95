"""`osdkc doctor`: diagnose a serial link to a flight controller that does not work.

    osdkc doctor --port /dev/ttyUSB0
    osdkc doctor --port /dev/ttyTHS1 --profile a3-fw3.1 --app-id 1234567 --key-env OSDK_KEY --json

It only listens, then sends version queries (and, with --app-id, one
activation): never control authority, never movement. Exit status: 0 the
link works, 1 a problem was found (or the link could not be checked to
the end), 2 a usage error, 130/143 interrupted (what was found so far is printed).
"""
from __future__ import annotations

import argparse
import signal
import sys

from osdk_conformance.core.errors import UsageError, exit_status_of_signal
from osdk_conformance.core.options import baud_rate, uint32
from osdk_conformance.core.wire import KeyError_, key_from_env
from osdk_conformance.doctor.diagnose import Doctor, Options


def add_arguments(ap: argparse.ArgumentParser, profiles: tuple[str, ...]) -> None:
    ap.description = __doc__.split("\n\n")[0]
    ap.add_argument("--port", required=True, help="serial device or pyserial URL (socket://, rfc2217://)")
    ap.add_argument("--baud", type=baud_rate,
                    help="the baud rate you configured (default: find it among 230400, 115200, 460800, 921600, 1000000)")
    ap.add_argument("--profile", choices=profiles, help="the wire profile you expect (default: find it)")
    ap.add_argument("--app-id", type=uint32, help="also try activation with this app id")
    ap.add_argument("--key-env", metavar="VAR", help="environment variable holding the app key (64 hex digits)")
    ap.add_argument("--json", action="store_true", help="the diagnosis as JSON on standard output")
    ap.add_argument("-v", "--verbose", action="store_true", help="show the evidence of every finding")


class _Stopped(KeyboardInterrupt):
    def __init__(self, signame: str) -> None:
        super().__init__(signame)
        self.signame = signame


def _raise(signum, frame) -> None:
    # Only what is safe was sent (queries, one activation): stopping at once leaves the FC as it was.
    raise _Stopped(signal.Signals(signum).name)


def run_doctor(args: argparse.Namespace) -> int:
    if not args.port.strip():
        raise UsageError("--port: empty (a serial device such as /dev/ttyUSB0, or a pyserial URL)")
    try:
        key = key_from_env(args.key_env)
    except KeyError_ as e:
        raise UsageError(str(e)) from None
    say = (lambda text: None) if args.json else (lambda text: print(f"osdkc doctor: {text}", file=sys.stderr,
                                                                     flush=True))
    doctor = Doctor(Options(args.port, args.baud, args.profile, key, args.app_id, say))
    previous = {s: signal.signal(s, _raise) for s in (signal.SIGINT, signal.SIGTERM)}
    status = None
    try:
        try:
            diagnosis = doctor.run()
        except _Stopped as stop:
            diagnosis = doctor.d
            diagnosis.interrupted = stop.signame
            status = exit_status_of_signal(stop.signame)
        for s, h in previous.items():
            signal.signal(s, h)
    except _Stopped as stop:   # a second signal while the first was handled
        return exit_status_of_signal(stop.signame)
    if args.json:
        diagnosis.write_json(sys.stdout)
    else:
        diagnosis.write_text(sys.stdout, args.verbose)
    if status is not None:
        return status
    return 0 if diagnosis.link_works else 1
