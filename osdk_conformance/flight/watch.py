"""`osdkc watch` (watch_command.py): a live view of a flight controller's broadcast, in the
manner of the MAVLink Inspector: per item its measured rate beside the
profile's default, its latest values, and the link's frames, errors and
garbage per second, updated in place on a terminal (plain ANSI: works over
SSH, in tmux, in any terminal emulator). `q` or Ctrl-C quits.

The source is a serial port (`--port`, reopened when it goes away), or a
capture file followed as it grows (`--capture`, e.g. the one `osdkc device
--capture` is writing). Rates are measured on the host's clock over the
last RATE_WINDOW_S: what arrived, including the host's own delays, which a
busy host turns into jitter; `osdkc device` judges the flight controller's
timing on its own clock. When standard output is not a terminal, a line
per update is printed instead, for logs.

Exit status: 0 after `q` or --duration, 130/143 on SIGINT/SIGTERM, 2 for
arguments that cannot be used or a port that cannot be opened.
"""
from __future__ import annotations

import argparse
import collections
import os
import queue
import select
import shutil
import sys
import termios
import threading
import time
import tty

import numpy as np

from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.rules import profile as load_profile
from osdk_conformance.flight import columns, live
from osdk_conformance.flight.records import attitude_of, int_enum

RATE_WINDOW_S = 2.0


class Stats:
    """What the view shows, from the rows and counts of each batch."""

    def __init__(self, profile: str, schema: tuple[columns.Column, ...]) -> None:
        self.schema = schema
        self.items = tuple(dict.fromkeys(c.item for c in schema))
        self.defaults = dict(load_profile(profile).default_rates_hz)
        # one entry per batch: (start of its interval, {item: frames}, frames, errors, garbage bytes, bytes)
        self.window: collections.deque = collections.deque()
        self.latest: dict[str, object] = {}                     # column -> its latest value
        self.totals = collections.Counter()
        self.started = self.last = time.monotonic()

    def add(self, data: columns.FlightData, nbytes: int) -> None:
        now = time.monotonic()
        per_item = {item: int(np.count_nonzero(data.present(item))) for item in self.items}
        for c in self.schema:
            where = np.flatnonzero(data.valid(c.name))
            if len(where):
                self.latest[c.name] = data.values(c.name)[where[-1]].item()
        c = data.counts
        self.window.append((self.last, per_item, c["frames"], c["errors"], c["garbage_bytes"], nbytes))
        self.last = now
        self.totals.update({"frames": c["frames"], "errors": c["errors"], "garbage_bytes": c["garbage_bytes"],
                            "broadcasts": data.rows, "bytes": nbytes})
        while len(self.window) > 1 and now - self.window[1][0] >= RATE_WINDOW_S:
            self.window.popleft()

    def span(self) -> float:
        """The time the batches in the window cover: from the start of the oldest to the last."""
        return max(1e-9, self.last - self.window[0][0]) if self.window else 1e-9

    def rate(self, index: int) -> float:
        return sum(w[index] for w in self.window) / self.span()

    def item_rate(self, item: str) -> float:
        return sum(w[1].get(item, 0) for w in self.window) / self.span()

    def values_of(self, item: str) -> str:
        parts = []
        for c in self.schema:
            if c.item != item or c.name not in self.latest or c.field == "reserved":
                continue
            v = self.latest[c.name]
            if c.enum and (members := int_enum(c.enum)) is not None and v in members._value2member_map_:
                v = members(v).name
            elif isinstance(v, float):
                v = f"{v:.6g}"
            parts.append(f"{c.field}={v}" if c.name != item else str(v))
        return " ".join(parts)

    def attitude(self) -> str:
        q = [self.latest.get(f"quaternion.q{i}") for i in range(4)]
        if any(v is None for v in q):
            return ""
        a = attitude_of(*q)  # type: ignore[arg-type]
        return f"roll={a.roll:.2f} pitch={a.pitch:.2f} yaw={a.yaw:.2f}"


def screen(stats: Stats, title: str, state: str, width: int) -> list[str]:
    elapsed = time.monotonic() - stats.started
    lines = [f"osdkc watch  {title}  {state}  {elapsed:.1f} s   (q or Ctrl-C quits)",
             f"link: {stats.rate(5) / 1000:.1f} kB/s  {stats.rate(2):.1f} frames/s  {stats.rate(3):.1f} errors/s  "
             f"{stats.rate(4):.0f} garbage B/s   totals: {stats.totals['frames']:,} frames, "
             f"{stats.totals['errors']:,} errors",
             "",
             f"{'item':<15}{'Hz':>8}{'default':>9}  latest"]
    for item in stats.items:
        lines.append(f"{item:<15}{stats.item_rate(item):>8.1f}{stats.defaults.get(item, 0):>9}  {stats.values_of(item)}")
    if att := stats.attitude():
        lines.append(f"{'attitude (deg)':<15}{'':>8}{'':>9}  {att}")
    return [line[:width] for line in lines]


def summary(stats: Stats) -> str:
    rates = ", ".join(f"{i} {stats.item_rate(i):.1f}" for i in stats.items if stats.item_rate(i))
    return (f"{time.monotonic() - stats.started:.1f} s: {stats.rate(2):.1f} frames/s, {stats.rate(3):.1f} errors/s"
            + (f"; Hz: {rates}" if rates else "; no broadcast"))


class _Keys:
    """q from a terminal's keyboard without Enter; nothing when stdin is not a terminal."""

    def __init__(self) -> None:
        self.fd = sys.stdin.fileno() if sys.stdin is not None and sys.stdin.isatty() else None
        self.saved = None

    def __enter__(self) -> "_Keys":
        if self.fd is not None:
            self.saved = termios.tcgetattr(self.fd)
            tty.setcbreak(self.fd)
        return self

    def __exit__(self, *exc) -> None:
        if self.saved is not None:
            termios.tcsetattr(self.fd, termios.TCSADRAIN, self.saved)

    def quit_within(self, seconds: float) -> bool:
        """Waits up to `seconds`; True when q was pressed."""
        if self.fd is None:
            time.sleep(seconds)
            return False
        ready, _, _ = select.select([self.fd], [], [], seconds)
        return bool(ready) and os.read(self.fd, 64).lower().find(b"q") >= 0


def _width(out) -> int:
    # the terminal's own size (it may be resized while watching), not $COLUMNS
    try:
        return os.get_terminal_size(out.fileno()).columns
    except OSError:
        return shutil.get_terminal_size((100, 24)).columns


def run(args: argparse.Namespace) -> int:
    stop = threading.Event()
    status: dict = {}
    if args.port:
        ser = live.open_port(args.port, args.baud)
        source = live.port_pieces(ser, args.port, args.baud, stop, status)
        title = f"{args.port} @ {args.baud} baud  {args.profile}"
    else:
        if not os.path.exists(args.capture):
            raise UsageError(f"cannot read {args.capture}: no such file")
        source = live.follow_pieces(args.capture, stop)
        status["port"] = "following"
        title = f"{args.capture}  {args.profile}"
    pieces: queue.Queue = queue.Queue()

    def read() -> None:
        try:
            for piece in source:
                pieces.put(piece)
        except UsageError as e:
            pieces.put(e)

    reader = threading.Thread(target=read, name="osdkc-watch-reader", daemon=True)
    filler = columns.open_filler(args.profile)
    stats = Stats(args.profile, columns.schema_of(filler))
    out = sys.stdout
    terminal = out.isatty()
    deadline = time.monotonic() + args.duration if args.duration else None
    reader.start()
    if terminal:
        out.write("\x1b[?25l\x1b[2J")   # hide the cursor, clear the screen once
    try:
        with _Keys() as keys:
            while True:
                nbytes = 0
                while True:
                    try:
                        piece = pieces.get_nowait()
                    except queue.Empty:
                        break
                    if isinstance(piece, UsageError):
                        raise piece
                    data, ts = piece
                    nbytes += len(data)
                    columns.feed(filler, data, ts)
                stats.add(columns.take(filler, args.profile, stats.schema), nbytes)
                if terminal:
                    width = _width(out)
                    body = "".join(f"{line}\x1b[K\n" for line in screen(stats, title, status.get("port", ""), width))
                    out.write("\x1b[H" + body + "\x1b[J")
                else:
                    out.write(summary(stats) + "\n")
                out.flush()
                if deadline is not None and time.monotonic() >= deadline:
                    break
                wait = args.interval if deadline is None else max(0.0, min(args.interval, deadline - time.monotonic()))
                if keys.quit_within(wait):
                    break
    finally:
        stop.set()
        if terminal:
            out.write("\x1b[?25h")
        out.flush()
        reader.join(timeout=1.0)
    print(f"osdkc watch: {summary(stats)}", file=sys.stderr)
    return 0
