"""Planted firmware bugs for `osdkc sim --bug NAME`.

A healthy simulator is our model of a correct flight controller; a device
fuzzer has to be shown to find the receive-path bugs real firmware has. Each
bug here models one known class of them and is off unless named. When one
triggers, the simulator's stats record it (which bug, when, on what bytes),
so a test or a fuzzer's report can confirm that a finding is the planted bug.
"""
from __future__ import annotations

import time

from osdk_conformance._construct.enums import COMMAND_SET

from osdk_conformance.core.deframe import (HEADER_LEN, SOF, Event, Frame, Garbage, Rejected, frame_length,
                                           header_problem)
from osdk_conformance.core.wire import Opened

BUGS: dict[str, str] = {
    "long-frame-hang": "a header the receiver accepts (CRC-16 good) with LEN over 300, whether or not the rest "
                       "arrives, overruns a 300-byte receive buffer: no ACK and no broadcast until restarted",
    "header-only-reset": "a 12-byte header-only frame reboots it: broadcast SEQ and time stamp restart at 0, "
                         "activation, control authority and rates are lost, the broadcast resumes 0.3 s later",
    "unknown-cmd-silence": "a valid command frame with a command set it does not know wedges its command "
                           "handler: no command is executed or ACKed any more, the broadcast goes on",
}
"""Bug name -> what it does, one line each: `osdkc sim --help`, docs/ACCEPTANCE.md
("Planted firmware bugs") and tests/test_sim_bugs.py read the names from here."""

RECEIVE_BUFFER = 300
"""Bytes in DJI's SDK receive buffer: a longer frame overruns it."""

REBOOT_PAUSE_S = 0.3
"""How long a reboot (a planted reset or a restart) keeps the simulator deaf and silent."""

KNOWN_COMMAND_SETS = frozenset(COMMAND_SET.values())

EVENTS_KEPT = 64
"""Trigger records kept in the stats: a fuzzer can trigger a reset thousands
of times; `bug_triggers` still counts every one."""


def event_end(ev: Event) -> int:
    """Where the receiver's pending bytes start after this event: a frame is
    consumed whole, garbage up to the next start byte, a rejection drops one
    byte and rescans (core.deframe)."""
    if isinstance(ev, Frame):
        return ev.offset + len(ev.raw)
    if isinstance(ev, Garbage):
        return ev.offset + ev.length
    return ev.offset + 1


class PendingBytes:
    """The bytes the receiver holds back while it waits for the rest of a
    frame, followed from its events, so that a long header is seen as soon
    as it has arrived, not only when (or if) the rest of its frame does. A
    header inside the body of a good frame is never looked at, as in the
    receiver itself."""

    def __init__(self) -> None:
        self.tail = bytearray()
        self.base = 0   # stream offset of tail[0], in the deframer's offsets

    def fed(self, data: bytes) -> None:
        self.tail += data

    def consumed(self, end: int) -> None:
        n = end - self.base
        if n > 0:
            del self.tail[:n]
            self.base = end

    def header(self) -> bytes | None:
        """The 12-byte header of the frame the receiver waits for, if any."""
        start = self.tail.find(SOF)
        # bytes before a start byte are garbage the receiver has dropped
        self.consumed(self.base + (len(self.tail) if start < 0 else start))
        return bytes(self.tail[:HEADER_LEN]) if len(self.tail) >= HEADER_LEN else None


def overruns(header: bytes) -> bool:
    """A header the receiver accepts and whose frame does not fit its buffer."""
    return header_problem(header) is None and frame_length(header) > RECEIVE_BUFFER


class PlantedBugs:
    """The state of the planted bugs of one simulator run, and their record
    in its stats (`bugs`, `bug_triggers`, `bug_events`)."""

    def __init__(self, names: tuple[str, ...], stats: dict, start: float) -> None:
        unknown = [n for n in names if n not in BUGS]
        if unknown:
            raise ValueError(f"unknown planted bug {', '.join(unknown)}: known are {', '.join(BUGS)}")
        self.names = frozenset(names)
        self.stats = stats
        self.start = start
        self.hung = False
        self.silent = False
        self.resume_at: float | None = None
        self.pending = PendingBytes() if "long-frame-hang" in self.names else None
        self.received = 0   # bytes fed to the receiver (the deframer's offsets)
        stats["bugs"] = [n for n in BUGS if n in self.names]
        stats["bug_triggers"] = {n: 0 for n in stats["bugs"]}
        stats["bug_events"] = []

    def halted(self, now: float) -> bool:
        """Deaf and silent: hung for good, or rebooting."""
        return self.hung or (self.resume_at is not None and now < self.resume_at)

    # ---- the receiver ----------------------------------------------------

    def fed(self, data: bytes) -> None:
        """Bytes about to be fed to the simulator's receiver (its deframer)."""
        self.received += len(data)
        if self.pending is not None:
            self.pending.fed(data)

    def consumed(self, ev: Event) -> None:
        if self.pending is not None:
            self.pending.consumed(event_end(ev))

    def received_after(self, ev: Event) -> int:
        """Bytes received after this event's end: lost when it halted the simulator."""
        return max(0, self.received - event_end(ev))

    def rebooted(self) -> None:
        """The simulator restarts with a new, empty receiver and a command handler no longer wedged."""
        self.received = 0
        self.silent = False
        if self.pending is not None:
            self.pending = PendingBytes()

    def power_cycled(self) -> None:
        """The simulator was restarted from outside (Simulator.request_restart):
        a reboot that a hang does not survive either. The pause that follows is
        the simulator's own, so a planted reset's pause still running ends here.
        Nothing is recorded: a restart is not a bug's doing."""
        self.hung = False
        self.resume_at = None
        self.rebooted()

    def _record(self, name: str, now: float, trigger: str, raw: bytes) -> None:
        self.stats["bug_triggers"][name] += 1
        if len(self.stats["bug_events"]) < EVENTS_KEPT:
            # a new list, not an append: api.RunningSimulator.stats() copies from another thread
            self.stats["bug_events"] = [*self.stats["bug_events"], {
                "bug": name, "t": round(now - self.start, 3), "wall": round(time.time(), 3),
                "trigger": trigger, "header": raw[:HEADER_LEN].hex()}]

    # ---- long-frame-hang --------------------------------------------------

    def overrun_by(self, ev: Event, now: float) -> bool:
        """Whether this receiver event is a whole long frame (good or bad
        CRC-32) that arrived in one read; hangs when it is."""
        if self.pending is None:
            return False
        if isinstance(ev, Frame):
            raw, how = ev.raw, "a whole frame"
        elif isinstance(ev, Rejected) and ev.error == "bad_crc32":
            start = ev.offset - self.pending.base
            raw, how = bytes(self.pending.tail[start:start + HEADER_LEN]), "a frame with a bad CRC-32"
        else:
            return False
        if len(raw) < HEADER_LEN or not overruns(raw):
            return False
        self._hang(now, f"header with LEN {frame_length(raw)} > {RECEIVE_BUFFER}, {how}", raw)
        return True

    def overrun_pending(self, now: float) -> bool:
        """Whether the frame the receiver now waits for overruns its buffer; hangs when it does."""
        header = self.pending.header() if self.pending is not None else None
        if header is None or not overruns(header):
            return False
        self._hang(now, f"header with LEN {frame_length(header)} > {RECEIVE_BUFFER}, "
                        f"{len(self.pending.tail)} byte(s) of the frame received", header)
        return True

    def _hang(self, now: float, trigger: str, raw: bytes) -> None:
        self.hung = True
        self._record("long-frame-hang", now, trigger, raw)

    # ---- header-only-reset ------------------------------------------------

    def resets_on(self, raw: bytes, now: float) -> bool:
        """Whether this frame reboots the simulator; starts the reboot's pause when it does."""
        if "header-only-reset" not in self.names or len(raw) != HEADER_LEN:
            return False
        self.resume_at = now + REBOOT_PAUSE_S
        self._record("header-only-reset", now, f"12-byte header-only frame, SEQ {raw[8] | raw[9] << 8}", raw)
        return True

    # ---- unknown-cmd-silence ----------------------------------------------

    def wedged_by(self, op: Opened, raw: bytes, now: float) -> bool:
        """Whether the command handler ignores this command: it is wedged
        already, or this command's unknown set wedges it now."""
        if self.silent:
            return True
        if "unknown-cmd-silence" not in self.names or op.cmd_set in KNOWN_COMMAND_SETS:
            return False
        self.silent = True
        self._record("unknown-cmd-silence", now,
                     f"command set 0x{op.cmd_set:02x} id 0x{op.cmd_id:02x}, SEQ {op.seq}", raw)
        return True
