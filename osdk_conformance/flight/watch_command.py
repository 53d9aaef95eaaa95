"""`osdkc watch`: its command line; the view itself is watch.py, which
needs the optional `flight` extra (numpy)."""
from __future__ import annotations

import argparse
from typing import Sequence

from osdk_conformance.core.options import baud_rate, positive_float
from osdk_conformance.flight import extra, live


def add_arguments(p: argparse.ArgumentParser, profiles: Sequence[str]) -> None:
    src = p.add_mutually_exclusive_group(required=True)
    src.add_argument("--port", help="the flight controller's serial port (a path or a pyserial URL)")
    src.add_argument("--capture", metavar="FILE", help="a capture file (pcapng or raw), followed as it grows")
    p.add_argument("--baud", type=baud_rate, default=live.DEFAULT_BAUD, help=f"baud rate (default {live.DEFAULT_BAUD})")
    p.add_argument("--profile", required=True, choices=profiles, help="broadcast wire profile of the flight controller")
    p.add_argument("--interval", type=positive_float, default=0.5, metavar="S", help="seconds between updates (0.5)")
    p.add_argument("--duration", type=positive_float, metavar="S", help="stop after S seconds (scripts)")


def run_watch(args: argparse.Namespace) -> int:
    watch, = extra.load("watch")
    return watch.run(args)
