"""What a host sent a flight controller, judged against the spec.

`HostJudge` hangs on an `Analyzer` (device/analysis.py), the acceptance
suite's own receiver: the analyzer deframes both directions, opens frames
and decodes the broadcast; through its `on_tx` and `on_rx_frame` hooks the
judge sees every event of the host's byte stream (frames, and bytes the
receiver dropped) and every frame of the flight controller's. From them it
keeps the host's session: its commands with their retransmissions and
ACKs, control authority as the ACKs grant it and as the broadcast's control
info shows it, and every movement control command with its mode byte and
setpoints. `tap/checks.py` turns this into Results.

The ACK of a command is matched the way DJI's receivers match it (errata
E32, conformance/PROTOCOL.md "ACK matching"): in sessions 1..31, against the
one command waiting in that session, when the SEQ is the same.
"""
from __future__ import annotations

import math
import struct
from collections import deque
from dataclasses import dataclass, field
from typing import Any

from osdk_conformance.core.commands import command_name
from osdk_conformance.core.deframe import Frame, Garbage
from osdk_conformance.core.rules import default_rules
from osdk_conformance.core.wire import Opened
from osdk_conformance.device.analysis import Finding
from osdk_conformance.reference.decode import payload_body

# Commands whose outcome a host only learns from the ACK: sent in session 0
# (no ACK wanted, facts §1) the host cannot know whether they took effect.
NEEDS_ACK = ("version_query", "activation", "set_frequency", "control_authority")
# Sent by the flight controller only: a host that sends them sends nonsense.
FC_ONLY = ("broadcast", "lost_control")
CONTROL_ONBOARD = 2                 # control_device enum: onboard_device
OBTAINED, RELEASED = 2, 1            # control_ack codes
MOVEMENT = struct.Struct("<B4f")     # mode byte, roll-or-x, pitch-or-y, throttle-or-z, yaw (facts §2 row 0x01/0x03)
# After this long without an ACK a host may go on in the session: the
# acceptance suite's own Commander waits 1 s per try (device/active.py).
ACK_PATIENCE_S = 1.0
# Two USB adapters on a Y-cable: how much sooner than its command an ACK may be read
# (an FTDI adapter's latency timer is 16 ms by default; twice that and then some).
REORDER_S = 0.05


@dataclass
class Command:
    """One command the host sent (its first transmission), its resends and its ACK."""

    t: float
    session: int
    seq: int
    name: str
    cmd_set: int
    cmd_id: int
    value: bytes
    raw: bytes
    resent: list[float] = field(default_factory=list)
    ack_t: float | None = None
    ack_value: bytes | None = None
    superseded: bool = False     # another command took its session before its ACK came

    @property
    def last_sent(self) -> float:
        return self.resent[-1] if self.resent else self.t

    def ack_code(self) -> int | None:
        v = self.ack_value
        return None if v is None or len(v) < 2 else int.from_bytes(v[:2], "little")


@dataclass
class Move:
    """One movement control command: when, its mode byte, its four setpoints
    and whether the host held control authority (by the ACKs) when it came."""

    t: float
    mode: int
    setpoints: tuple[float, float, float, float]
    under_control: bool


class HostJudge:
    """Judges the host by what the tap read both ways. `two_lines` (a
    Y-cable: each line through its own adapter) holds the host's bytes back
    for the analyser's ack_reorder_s before judging them, so that an ACK
    read up to that much later than the host's next command is judged
    before it: the FC's line may lag the host's by that much either way,
    and the order of two frames that close is not known (a relay reads both
    ends itself and knows it)."""

    def __init__(self, analyzer, profile: str, two_lines: bool = False) -> None:
        self.an, self.profile = analyzer, profile
        self._hold_s = analyzer.ack_reorder_s if two_lines else 0.0
        self._held: deque[tuple[float, bytes]] = deque()   # the host's bytes not yet judged
        self.rules = default_rules()
        self._body = payload_body(profile)
        self.frames = 0
        self.t0: float | None = None           # the first byte the tap read, either way
        self.first_t: float | None = None      # the host's first and last byte
        self.last_t: float | None = None
        self.leading_bytes = 0                 # before the first good frame: a tap that joined mid-frame
        # each a Finding (device/analysis.py): how many, and the first examples
        self.malformed = Finding()             # bytes the receiver dropped, after the first good frame
        self.malformed_bytes = 0
        self._in_gap = False
        self.unopened = Finding()              # frames whose DATA could not be opened (encryption)
        self.encrypted_without_key = 0
        self.unknown = Finding()               # commands the spec does not have, or that only an FC sends
        self.bad_values = Finding()            # known commands whose value does not decode
        self.host_acks = 0                     # ACKs the host sent (to lost_control)
        self.commands: list[Command] = []
        self.waiting: dict[int, Command] = {}  # session -> the command waiting for its ACK there
        self.last_in: dict[int, Command] = {}  # session -> the last command sent in it
        self.session_clash = Finding()         # a new command in a session whose command still waits
        self.seq_reuse = Finding()             # a SEQ reused for other content while its command waits
        self.stray_acks = Finding()            # FC ACKs that answer no command of the host's
        self.repeated_acks = 0                 # FC ACKs to a retransmission of a command already answered
        self.early: dict[int, list] = {}       # session -> ACKs read before any command they answer: (t, frame)
        self.moves: list[Move] = []
        self.frequency_requests: list[tuple[float, list[int]]] = []
        # control authority by the ACKs: (t, True obtained / False released)
        self.authority: list[tuple[float, bool]] = []
        self.activated_at: float | None = None
        self.version_at: float | None = None
        self.control_asked_before_activation = Finding()
        # the broadcast's view: (t, control device) changes, and lost_control frames
        self.device_changes: list[tuple[float, int]] = []
        self.lost_control: list[float] = []
        analyzer.on_tx = self._tx
        analyzer.on_rx_frame = self._rx
        self._next_broadcast = analyzer.on_broadcast
        analyzer.on_broadcast = self._broadcast

    # ---- input: what the tap read, in order ----------------------------------

    def feed_rx(self, t: float, data: bytes) -> None:
        """Bytes from the flight controller."""
        if self.t0 is None:
            self.t0 = t
        self._release(t)
        self.an.feed_rx(t, data)

    def feed_tx(self, t: float, data: bytes) -> None:
        """Bytes from the host."""
        if self.t0 is None:
            self.t0 = t
        if self._hold_s:
            self._release(t)
            self._held.append((t, data))
        else:
            self.an.feed_tx(t, data)

    def _release(self, now: float) -> None:
        while self._held and self._held[0][0] + self._hold_s <= now:
            self.an.feed_tx(*self._held.popleft())

    def finish(self, t: float | None = None) -> None:
        """The end of the input: the host's bytes still held back are judged, then the analyser finishes."""
        self._release(math.inf)
        self.an.finish(t)

    def at(self, t: float) -> str:
        """A time as the reports write it: seconds from the first byte the tap read, either way."""
        return f"t={t - (self.t0 or 0.0):.3f}"

    # ---- the host's bytes ----------------------------------------------------

    def _seen(self, t: float) -> None:
        if self.first_t is None:
            self.first_t = t
        self.last_t = t

    def _tx(self, t: float, ev, op: Opened | None) -> None:
        self._seen(t)
        if not isinstance(ev, Frame):
            n = ev.length
            if self.frames == 0:
                self.leading_bytes += n
                return
            self.malformed_bytes += n
            if not self._in_gap:   # one incident per run of dropped bytes, named by its first rejection
                self._keep(self.malformed, t, f"{n} byte(s) outside any frame" if isinstance(ev, Garbage)
                           else f"{ev.error}: {ev.detail}")
            self._in_gap = True
            return
        self._in_gap = False
        self.frames += 1
        if op.problem:
            if op.encrypted and "no key" in op.problem:
                self.encrypted_without_key += 1
            else:
                self._keep(self.unopened, t, f"session {op.session} seq {op.seq}: {op.problem}")
            return
        if op.is_ack:
            self.host_acks += 1
            return
        name = command_name(op.cmd_set, op.cmd_id)
        if name == "unknown" or name in FC_ONLY:
            why = "a command the spec does not have" if name == "unknown" else "a frame only a flight controller sends"
            self._keep(self.unknown, t, f"command {op.cmd_set:#04x}/{op.cmd_id:#04x} ({why})")
            return
        try:
            self._body(op.value, op.cmd_set, op.cmd_id, False)
        except Exception as e:   # DecodeFailure, or anything the decoder raises on a bad value
            self._keep(self.bad_values, t, f"{name} value {op.value.hex()}: {getattr(e, 'detail', e)}")
            return
        if name == "movement_control":
            self._movement(t, op.value)
            return
        self._command(t, op, name, ev.raw)

    def _keep(self, into: Finding, t: float, what: str) -> None:
        into.add(False, lambda: f"{self.at(t)}: {what}")

    def _command(self, t: float, op: Opened, name: str, raw: bytes) -> None:
        last = self.last_in.get(op.session)
        if last is not None and last.seq == op.seq and last.raw == raw:
            last.resent.append(t)   # the same frame again, answered or not: a retransmission
            return
        waiting = self.waiting.get(op.session) if op.session > 0 else None
        if waiting is not None:
            if waiting.seq == op.seq:
                self._keep(self.seq_reuse, t, f"session {op.session} seq {op.seq}: {name} reuses the SEQ of "
                                              f"{waiting.name} sent at {self.at(waiting.t)}, still unanswered")
            elif t - waiting.last_sent < ACK_PATIENCE_S:
                self._keep(self.session_clash, t, f"session {op.session}: {name} (seq {op.seq}) sent while "
                                                  f"{waiting.name} (seq {waiting.seq}, {1000 * (t - waiting.last_sent):.0f} ms "
                                                  "earlier) still waits for its ACK")
            waiting.superseded = True
        cmd = Command(t, op.session, op.seq, name, op.cmd_set, op.cmd_id, op.value, raw)
        self.commands.append(cmd)
        self.last_in[op.session] = cmd
        if op.session > 0:
            self.waiting[op.session] = cmd
            self._early_answer(cmd)
        if name == "version_query" and self.version_at is None:
            self.version_at = t
        elif name == "set_frequency":
            self.frequency_requests.append((t, list(op.value[:16])))
        elif name == "control_authority" and self.activated_at is None:
            what = "obtain" if op.value[:1] == bytes([1]) else "release"
            self._keep(self.control_asked_before_activation, t,
                       f"control authority {what} asked for (seq {op.seq}) before an activation succeeded")

    def _early_answer(self, cmd: Command) -> None:
        """An ACK read up to the analyser's ack_reorder_s (REORDER_S for a
        tap) before its command answers it: two adapters of a Y-cable deliver
        their lines with latencies of their own, so the FC's answer can reach
        the tap first."""
        early = self.early.get(cmd.session, [])
        for t, op in list(early):
            if cmd.t - t > self.an.ack_reorder_s:
                early.remove((t, op))
                self._keep(self.stray_acks, t, f"ACK in session {op.session} seq {op.seq} answers no command "
                                               "of the host's")
            elif op.seq == cmd.seq:
                early.remove((t, op))
                self._answer(cmd, t, op)
                # more ACKs of this SEQ read as early: the FC answered retransmissions still held back
                again = [(t2, op2) for t2, op2 in early if op2.seq == cmd.seq]
                for e in again:
                    early.remove(e)
                self.repeated_acks += len(again)
                return

    def settle(self) -> None:
        """At the end: ACKs still waiting for a command answer none."""
        for early in self.early.values():
            for t, op in early:
                self._keep(self.stray_acks, t, f"ACK in session {op.session} seq {op.seq} answers no command "
                                               "of the host's")
            early.clear()

    def _movement(self, t: float, value: bytes) -> None:
        mode, *sp = MOVEMENT.unpack_from(value)
        self.moves.append(Move(t, mode, tuple(sp), self.in_control()))

    def in_control(self) -> bool:
        """Whether the host holds control authority by the ACKs it got so far."""
        return bool(self.authority) and self.authority[-1][1]

    # ---- the flight controller's frames ----------------------------------------

    def _rx(self, t: float, op: Opened) -> None:
        if op.is_ack:
            cmd = self.waiting.get(op.session) if op.session > 0 else None
            if cmd is None or cmd.seq != op.seq:
                last = self.last_in.get(op.session)
                if last is not None and last.seq == op.seq:
                    self.repeated_acks += 1   # the FC answered a retransmission of an answered command again
                else:
                    self.early.setdefault(op.session, []).append((t, op))
                return
            self._answer(cmd, t, op)
            return
        if (op.cmd_set, op.cmd_id) == (0x02, 0x01):
            self.lost_control.append(t)

    def _answer(self, cmd: Command, t: float, op: Opened) -> None:
        t = max(t, cmd.t)   # an ACK read before its command (a Y-cable) came after it
        cmd.ack_t, cmd.ack_value = t, op.value
        del self.waiting[cmd.session]
        code = cmd.ack_code()
        if cmd.name == "activation" and code == 0 and self.activated_at is None:
            self.activated_at = t
        elif cmd.name == "version_query" and code == 0 and self.activated_at is None:
            self.activated_at = t   # the FC says an app is already activated
        elif cmd.name == "control_authority" and code in (OBTAINED, RELEASED):
            self.authority.append((t, code == OBTAINED))

    def _broadcast(self, t: float, data: Any) -> None:
        ci = data.get("control_info")
        if ci is not None:
            dev = ci["control_device"]["value"]
            if not self.device_changes or self.device_changes[-1][1] != dev:
                self.device_changes.append((t, dev))
        if self._next_broadcast:
            self._next_broadcast(t, data)

    # ---- questions the checks ask ------------------------------------------------

    def control_spans(self, end: float) -> list[tuple[float, float]]:
        """Spans of time in which the host held control authority by the ACKs."""
        spans, since = [], None
        for t, held in self.authority:
            if held and since is None:
                since = t
            elif not held and since is not None:
                spans.append((since, t))
                since = None
        if since is not None:
            spans.append((since, end))
        return spans

    def fc_took_control(self) -> list[tuple[float, int]]:
        """When the broadcast's control device left the onboard computer
        while the host held control by the ACKs: (t, device)."""
        out = []
        prev = None
        for t, dev in self.device_changes:
            if prev == CONTROL_ONBOARD and dev != CONTROL_ONBOARD and self._held_at(t):
                out.append((t, dev))
            prev = dev
        return out

    def _held_at(self, t: float) -> bool:
        held = False
        for ta, h in self.authority:
            if ta > t:
                break
            held = h
        return held

    def mode_meaning(self, mode: int) -> dict[str, Any]:
        return self.rules.classify_control_mode(mode, self.profile)

    def ranges(self, mode: int) -> dict[str, dict] | None:
        return self.rules.input_ranges(mode, self.profile)
