"""`osdkc decode`: the value model's JSON lines (reference/decode.py), or,
with `--format csv|parquet`, the broadcasts as a table (tables.py).

The JSON lines are every event, exactly as they have always been; a table
holds the broadcast frames only, one row each, and what else the input held
is said on standard error: frames of other commands, errors, garbage bytes,
the frame a recording stopped inside. The exit status means what it means
for the JSON lines: 1 when an error was counted or a recording holds no
frame at all, 2 for input that cannot be read or arguments that are wrong.
"""
from __future__ import annotations

import argparse
import os
import sys
import threading
from typing import Sequence

from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.options import baud_rate
from osdk_conformance.flight import extra, live, output
from osdk_conformance.reference import decode as json_lines

FORMATS = ("jsonl", "csv", "parquet")


def add_arguments(d: argparse.ArgumentParser, profiles: Sequence[str]) -> None:
    sources = json_lines.add_arguments(d, profiles)
    sources.add_argument("--port", help="decode a serial port as the bytes arrive (a path or a pyserial URL), until "
                                        "Ctrl-C")
    d.add_argument("--baud", type=baud_rate, default=live.DEFAULT_BAUD, help=f"with --port: the baud rate ({live.DEFAULT_BAUD})")
    d.add_argument("--follow", action="store_true",
                   help="with FILE: keep reading as the file grows (a capture being written), until Ctrl-C")
    d.add_argument("--format", choices=FORMATS, default="jsonl",
                   help="jsonl (default): every event in the value model; csv or parquet: the broadcast frames as "
                        "a table, one column per field (needs the optional dependencies: pip install "
                        "'osdk-conformance[flight]')")
    d.add_argument("--items", metavar="ITEM,...",
                   help="with csv or parquet: only these broadcast items (or item.field), e.g. battery,quaternion")
    d.add_argument("-o", "--output", metavar="FILE",
                   help="write the table to FILE instead of standard output (parquet needs a FILE)")


def run_decode(args: argparse.Namespace) -> int:
    if args.follow and not args.file or args.follow and args.file == "-":
        raise UsageError("--follow is for a FILE that is being written")
    if args.port or args.follow:
        if args.format != "jsonl":
            raise UsageError("--port and --follow give JSON lines as frames arrive (a table is written when its "
                             "input ends: record with `osdkc device --capture`, then --format it)")
        return _run_live(args)
    if args.format == "jsonl":
        for option, given in (("--items", args.items), ("--output", args.output)):
            if given is not None:
                raise UsageError(f"{option} is for --format csv or parquet; the JSON lines hold every event")
        return json_lines.run_decode(args)
    return _run_table(args)


def _run_live(args: argparse.Namespace) -> int:
    stop = threading.Event()
    if args.port:
        ser = live.open_port(args.port, args.baud)
        name, pieces = args.port, live.port_pieces(ser, args.port, args.baud, stop)
    else:
        if not os.path.exists(args.file):
            raise UsageError(f"cannot read {args.file}: no such file")
        name, pieces = args.file, live.follow_pieces(args.file, stop)
    try:
        return json_lines.run_decode(args, (name, (data for data, _ in pieces), None), live=True)
    finally:
        stop.set()


def _items(text: str | None) -> list[str] | None:
    if text is None:
        return None
    items = [i.strip() for i in text.split(",") if i.strip()]
    if not items:
        raise UsageError("--items names no item")
    return items


def _run_table(args: argparse.Namespace) -> int:
    if args.direction != "rx":
        raise UsageError("a table holds the broadcasts the flight controller sent: --direction rx only")
    if args.format == "parquet" and not args.output:
        raise UsageError("parquet is a binary format: give -o FILE")
    if args.pretty:
        raise UsageError("--pretty is for the JSON lines")
    items = _items(args.items)
    columns, tables = extra.load("columns", "tables")   # the optional extra: only when a table is asked for
    name, chunks, close = json_lines.open_input(args)
    try:
        data = columns.read_chunks_of(chunks, args.profile, name)
    except OSError as e:
        raise UsageError(f"reading failed: {e.strerror or e}") from None
    finally:
        if close:
            close.close()
    table = tables.to_arrow(data, items)
    _write(table, tables, args)
    for line in notes(data, name, recording=args.hex is None):
        print(f"osdkc decode: {line}", file=sys.stderr)
    return status(data, recording=args.hex is None)


def _write(table, tables, args: argparse.Namespace) -> None:
    if not args.output:
        tables.write(table, args.format, sys.stdout.buffer)
        sys.stdout.flush()
        return
    try:
        output.write_replacing(args.output, lambda out: tables.write(table, args.format, out))
    except OSError as e:
        raise UsageError(f"cannot write {args.output}: {e.strerror or e}") from None


def notes(data, name: str, recording: bool) -> list[str]:
    c = data.counts
    out = [f"{data.rows:,} broadcast frames in the table; "
           + ", ".join(f"{c[k]:,} {label}" for k, label in (
               ("other_frames", "frames of other commands"), ("encrypted_frames", "encrypted frames"),
               ("errors", "errors"), ("garbage_bytes", "garbage bytes")))
           + ("" if data.has_capture_time else "; raw bytes carry no capture time (no time column)")]
    if data.seen.cut_block:
        out.append(json_lines.cut_block_note(data.seen, "in the table"))
    if c["capture_end_events"] and recording:
        out.append("the input ends inside a frame: the recording stopped there; not counted as an error")
    if recording and not c["frames"] and not c["errors"]:
        out.append(f"no frame found in {name}")
    elif c["broadcasts"] == 0 and c["errors"]:
        out.append(f"no broadcast decoded as {data.profile}: is it the profile of this flight controller? "
                   "(`osdkc decode` without --format names the one the frames fit)")
    return out


def status(data, recording: bool) -> int:
    errors = data.counts["errors"] + (0 if recording else data.counts["capture_end_events"])
    return 1 if errors or (recording and not data.counts["frames"]) else 0
