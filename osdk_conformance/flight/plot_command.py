"""`osdkc plot CAPTURE --profile P --items battery,attitude -o flight.html`:
the broadcasts of a capture drawn as the acceptance report draws its
series (plot.py); HTML or SVG by the output's suffix."""
from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Sequence

from osdk_conformance.core.errors import UsageError, cannot_read
from osdk_conformance.flight import extra, output

SUFFIXES = (".html", ".svg")
DEFAULT_ITEMS = "battery,attitude,velocity"


def add_arguments(p: argparse.ArgumentParser, profiles: Sequence[str]) -> None:
    p.add_argument("capture", help="a pcapng capture (osdkc device, tap, sim) or a file of raw received bytes")
    p.add_argument("--profile", required=True, choices=profiles, help="broadcast wire profile of the flight controller")
    p.add_argument("--items", default=DEFAULT_ITEMS, metavar="ITEM,...",
                   help=f"what to draw (default {DEFAULT_ITEMS}): broadcast items, item.field, or attitude "
                        "(roll, pitch, yaw in degrees from the quaternion)")
    p.add_argument("-o", "--output", required=True, metavar="FILE",
                   help="the page to write: .html (self-contained, works offline) or .svg")


def run_plot(args: argparse.Namespace) -> int:
    out = Path(args.output)
    if out.suffix.lower() not in SUFFIXES:
        raise UsageError(f"{args.output}: the output is .html or .svg (PNG: open the HTML or SVG in a browser "
                         "and save it)")
    items = [i.strip() for i in args.items.split(",") if i.strip()]
    if not items:
        raise UsageError("--items names nothing to draw")
    columns, plot = extra.load("columns", "plot")
    try:
        data = columns.read(args.capture, args.profile)
    except OSError as e:
        raise UsageError(cannot_read(args.capture, e)) from None
    text = plot.svg(data, items) if out.suffix.lower() == ".svg" else plot.page(data, items)
    try:
        output.write_replacing(out, lambda fh: fh.write(text.encode("utf-8")))
    except OSError as e:
        raise UsageError(f"cannot write {out}: {e.strerror or e}") from None
    print(f"osdkc plot: {data.rows:,} broadcast frames of {args.capture} drawn to {out}", file=sys.stderr)
    return 0
