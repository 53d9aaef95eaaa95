"""The bug classes the golden vectors close, and the tables that show it.

An implementation written independently from the documents can pass every
rule-level count of `osdkc vectors coverage` and still be wrong in ways no
vector exercises: an error class that never appears inside a stream, a
pair of frame rules whose precedence no frame tests, a header bit never set
in a frame the receiver accepts, an ACK situation no stream shows. This
module names those classes once, for both sides:

- tools/gen_vectors.py generates the cases from these lists (every frame
  error class, every pair of FRAME_RULES, every header bit, every command
  kind and ACK situation) and checks its expectations against them;
- `osdkc vectors coverage` prints one table per class, computed from the
  vectors' bytes and expected events alone (never from ids or flags), and
  marks every cell with no case as a HOLE.

Everything here reads the vectors as data: `broken_rules` evaluates each
frame rule on its own over the bytes, so a table counts what the bytes
really exercise, whatever a case's comment says.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Iterator

from osdk_conformance.core.commands import COMMANDS, command_name
from osdk_conformance.core.crc import crc16, crc32
from osdk_conformance.core.deframe import HEADER_LEN, header_fields
from osdk_conformance.core.deframe import frame_length, header_problem
from osdk_conformance.core.paths import ROOT
from osdk_conformance.core.rules import classify_control_mode, input_ranges
from osdk_conformance.reference.codec import AXIS_RANGE, _out_of_range, answer
from osdk_conformance._construct import frame, payload

VALUE_MODEL = ROOT / "docs" / "VALUE-MODEL.md"

# ============================================================== frame error classes


def frame_error_classes() -> tuple[str, ...]:
    """The error classes of docs/VALUE-MODEL.md ("Error classes" table), in its order."""
    text = VALUE_MODEL.read_text(encoding="utf-8")
    table = text.split("Error classes:", 1)[1]
    return tuple(re.findall(r"^\| `([a-z0-9_]+)` \|", table, flags=re.M))


NOT_IN_STREAMS = {
    "bad_sof": "a stream reports bytes before a start byte as garbage, never as an error",
    "undecodable": "a conforming decoder never produces it",
    "undefined_mode": "a check_movement_control answer, not a frame's",
    "out_of_range": "a check_movement_control answer, not a frame's",
    "bad_request": "an answer of the testee protocol about the request",
    "internal_error": "an answer of the testee protocol about the testee",
}
"""Error classes of docs/VALUE-MODEL.md a decode_stream event cannot carry,
and why; every other class must appear in stream vectors (the generator
stops when a new class has neither a stream vector nor a reason here)."""


def stream_error_classes() -> tuple[str, ...]:
    """Every class a decode_stream error event can carry."""
    return tuple(c for c in frame_error_classes() if c not in NOT_IN_STREAMS)


# ============================================================== frame rules and their precedence


@dataclass(frozen=True)
class FrameRule:
    name: str
    classes: tuple[str, ...]  # the error class(es) it reports
    contexts: tuple[str, ...]  # where it can fire: decode_frame, decode_stream


BOTH = ("decode_frame", "decode_stream")
FRAME_RULES: tuple[FrameRule, ...] = (
    FrameRule("sof", ("bad_sof",), ("decode_frame",)),
    FrameRule("crc16", ("bad_crc16",), BOTH),
    FrameRule("ver", ("bad_version",), BOTH),
    FrameRule("res0", ("reserved_bits",), BOTH),
    FrameRule("res1", ("reserved_bits",), BOTH),
    FrameRule("len", ("impossible_length",), BOTH),
    FrameRule("size", ("truncated_frame", "length_mismatch"), ("decode_frame",)),
    FrameRule("crc32", ("bad_crc32",), BOTH),
    FrameRule("session", ("bad_session",), BOTH),
    FrameRule("enc", ("bad_encryption",), BOTH),
    FrameRule("value", ("truncated_payload", "length_mismatch", "reserved_bits"), BOTH),
)
"""Every rule the frame layer checks, in precedence order (the reference's
order, docs/VALUE-MODEL.md): when a frame breaks several, the first one's
class is reported. `size` is decode_frame's byte count against LEN (in a
stream the bytes after a frame belong to the next one); `sof` exists only
for decode_frame (a stream skips to the next start byte)."""

RULE_BY_NAME = {r.name: r for r in FRAME_RULES}

IMPOSSIBLE_PAIRS = {
    frozenset({"len", "crc32"}): "an impossible LEN leaves no CRC-32 to check",
    frozenset({"len", "value"}): "an impossible LEN leaves no value to decode",
    frozenset({"session", "value"}): "only an ACK can be in the wrong session, and an ACK frame's value stays raw",
}
"""Pairs of rules no single frame can break together, and why."""


def rule_pairs(context: str) -> list[tuple[str, str]]:
    """Every pair of rules that can fire on one frame in `context`, in precedence order."""
    names = [r.name for r in FRAME_RULES if context in r.contexts]
    return [(a, b) for i, a in enumerate(names) for b in names[i + 1:] if frozenset({a, b}) not in IMPOSSIBLE_PAIRS]


def _enc_broken(f: dict) -> bool:
    if f["enc"] == 0:
        return f["padding"] != 0
    return not (f["enc"] == 1 and 1 <= f["padding"] <= 16 and f["len"] > 16 and (f["len"] - 16) % 16 == 0)


def _value_broken(data: bytes, f: dict, profile: str) -> bool:
    if f["is_ack"] or f["enc"] != 0 or f["len"] < 17 or len(data) < f["len"]:
        return False
    body = data[HEADER_LEN:f["len"] - 4]
    if len(body) < 2:
        return True
    res = answer("decode_payload", profile, {"hex": body[2:].hex(), "cmd_set": body[0], "cmd_id": body[1],
                                             "is_ack": False})
    return not res["ok"]


def broken_rules(data: bytes, profile: str, context: str) -> set[str]:
    """The FRAME_RULES `data` (one frame's bytes) breaks, each judged on its own."""
    out: set[str] = set()
    if context == "decode_frame" and (not data or data[0] != 0xAA):
        out.add("sof")
    if len(data) < HEADER_LEN:
        return out
    f = header_fields(data[:HEADER_LEN])
    length = f["len"]
    checks = {
        "crc16": crc16(data[:10]) != f["crc16"],
        "ver": f["ver"] != 0,
        "res0": f["res0"] != 0,
        "res1": f["res1"] != 0,
        "len": length < HEADER_LEN or HEADER_LEN < length <= HEADER_LEN + 4,
        "size": context == "decode_frame" and len(data) != length,
        "crc32": length > HEADER_LEN + 4 and len(data) >= length and crc32(data[:length]) != 0,
        "session": f["is_ack"] and f["session"] == 0,
        "enc": _enc_broken(f),
    }
    out.update(name for name, broken in checks.items() if broken)
    if _value_broken(data, f, profile):
        out.add("value")
    return out


# ============================================================== header bits


def header_bits() -> list[tuple[str, int, int]]:
    """(field, bit within the field, bit within the 12-byte header) of every
    header bit after the start byte, from the Construct layout of the spec."""

    _, fields, _ = frame._header_bits._layout()
    out, pos = [], 8
    for name, _, width, _ in fields:
        out += [(name, k, pos + k) for k in range(width)]
        pos += width
    for name, width in (("seq", 16), ("crc16", 16)):
        out += [(name, k, pos + k) for k in range(width)]
        pos += width
    return out


# ============================================================== ACK situations


ACK_SITUATIONS = {
    "matched": "the command, then its ACK: decoded as that command's ACK",
    "session1_ack": "the same in session 1 (ACK optional, ERRATA E24, E32): the ACK is not matched",
    "matched_bad_value": "the command, then an ACK whose value does not fit the ACK layout: error with ack_of",
    "repeated_ack": "a second ACK with the same session and SEQ after a matched one: not matched",
    "ack_before_command": "the ACK arrives before its command: not matched",
    "other_session": "an ACK with the command's SEQ in another session: not matched",
    "other_seq": "an ACK in the command's session with another SEQ: not matched",
    "session0_command": "the command was in session 0 (no ACK wanted): a later ACK with its SEQ is not matched",
    "rejected_command": "the command frame was rejected (its value does not decode): a later ACK is not matched",
    "retransmitted_command": "the command sent twice with the same session and SEQ: one ACK matches, the next not",
    "replaced_command": "another command took the same session and SEQ: the ACK is matched to the later one",
    "superseded_command": "a second command in the same session with another SEQ takes the session's slot: "
                          "an ACK with the first command's SEQ is not matched (ERRATA E32)",
    "interleaved": "two commands in sessions 2 and 3 answered in reverse order: both matched",
    "header_only_ack": "a header-only ACK matches and consumes the command (its empty value decoded as the "
                       "command's ACK): a later full ACK is not matched (ERRATA E32)",
}
"""What a stream decoder must get right about ACKs, per command kind."""

NO_LAYOUT_SITUATIONS = frozenset({"matched_bad_value"})
"""Situations impossible for a command without a decoded ACK layout (any ACK value is raw)."""

NO_VALUE_ERROR_KINDS = frozenset({"unknown"})
"""Command kinds whose value cannot fail to decode (kept raw)."""


def command_kinds() -> list[str]:
    """Every command the spec names, then `unknown`."""
    return [*COMMANDS.values(), "unknown"]


def has_ack_layout(kind: str) -> bool:
    keys = [k for k, name in COMMANDS.items() if name == kind]
    return bool(keys) and payload.key(*keys[0], True) in payload.BODY_BY_KEY


def feasible_situation(kind: str, situation: str) -> bool:
    if situation in NO_LAYOUT_SITUATIONS and not has_ack_layout(kind):
        return False
    return not (situation == "rejected_command" and kind in NO_VALUE_ERROR_KINDS)


VALUE_ERRORS = ("truncated_payload", "length_mismatch", "reserved_bits")


def _events_with_bytes(hex_input: str, events: list[dict]) -> Iterator[tuple[dict, bytes]]:
    """Each event with the bytes it judged: a frame's LEN bytes, and for an
    error at least the frame its header announces (a rejected header's
    event covers one byte, the byte the receiver drops)."""
    data = bytes.fromhex(hex_input)
    for ev in events:
        if ev["kind"] == "frame":
            size = ev["frame"]["len"]
        else:
            size = ev["length"]
            if ev["kind"] == "error" and len(data) - ev["offset"] >= HEADER_LEN:
                size = max(size, header_fields(data[ev["offset"]:ev["offset"] + HEADER_LEN])["len"], HEADER_LEN)
        yield ev, data[ev["offset"]:ev["offset"] + size]


def _events(case) -> list[dict]:
    """The expected events of a decode_stream case (none when it expects an error)."""
    if case.result == "invalid":
        return []
    return (case.expected.get("value") if case.result == "acceptable" else case.expected).get("events", [])


@dataclass
class _AckModel:
    """What a stream has shown so far, for reading ACK situations off it
    (one slot per session 2..31, PROTOCOL.md "ACK matching")."""

    slots: dict = field(default_factory=dict)  # session -> (seq, kinds sent with that SEQ since it took the slot, order)
    answered: dict = field(default_factory=dict)  # (session, seq) -> kind of the command last answered
    header_only: dict = field(default_factory=dict)  # (session, seq) -> kind a header-only ACK was matched to
    superseded: dict = field(default_factory=dict)  # (session, seq) -> kind whose slot a command with another SEQ took
    rejected: dict = field(default_factory=dict)  # (session, seq) -> kind of a command whose value did not decode
    session0: dict = field(default_factory=dict)  # seq -> kind of a session-0 command
    session1: dict = field(default_factory=dict)  # seq -> kind of a session-1 command
    sent: int = 0

    def command(self, ev: dict, key: tuple[int, int], kind: str) -> None:
        session, seq = key
        if ev["kind"] == "error":
            if ev["error"] in VALUE_ERRORS and session:
                self.rejected[key] = kind
        elif session == 0:
            self.session0[seq] = kind
        elif session == 1:
            self.session1[seq] = kind
        elif session <= 31:
            self.sent += 1
            old = self.slots.get(session)
            if old is not None and old[0] == seq:
                self.slots[session] = (seq, [*old[1], kind], old[2])
            else:
                if old is not None:
                    self.superseded[(session, old[0])] = old[1][-1]
                self.slots[session] = (seq, [kind], self.sent)
            self.answered.pop(key, None)
            self.header_only.pop(key, None)
            self.superseded.pop(key, None)

    def matched(self, ev: dict, key: tuple[int, int], header_only: bool) -> set[tuple[str, str]]:
        kind = ev["ack_of"]
        slot = self.slots.pop(key[0], None)
        kinds = slot[1] if slot is not None and slot[0] == key[1] else [kind]
        self.answered[key] = kind
        if header_only:
            self.header_only[key] = kind  # the situation shows when a later full ACK is not matched
            return set()
        out = {(kind, "matched" if ev["kind"] == "frame" else "matched_bad_value")}
        if slot is not None and any(other[2] < slot[2] for other in self.slots.values()):
            out.add((kind, "interleaved"))  # a command sent earlier, in another session, is still waiting
        if len(kinds) > 1:
            out.add((kind, "retransmitted_command" if len(set(kinds)) == 1 else "replaced_command"))
        return out

    def unmatched(self, key: tuple[int, int], later: list[str]) -> set[tuple[str, str]]:
        """Why an ACK was not matched (`later`: kinds of commands with its key after it)."""
        waiting = [((session, seq), kinds[-1]) for session, (seq, kinds, _) in self.slots.items()]
        same_seq = [kind for k, kind in waiting if k[1] == key[1]]
        same_session = [kind for k, kind in waiting if k[0] == key[0]]
        reasons = ((self.header_only.get(key), "header_only_ack"),
                   (self.answered.get(key), "repeated_ack"),
                   (later[0] if later else None, "ack_before_command"),
                   (self.rejected.get(key), "rejected_command"),
                   (self.session1.get(key[1]) if key[0] == 1 else None, "session1_ack"),
                   (self.session0.get(key[1]), "session0_command"),
                   (self.superseded.get(key), "superseded_command"),
                   (same_seq[-1] if same_seq else None, "other_session"),
                   (same_session[-1] if same_session else None, "other_seq"))
        return next(({(kind, situation)} for kind, situation in reasons if kind), set())


def ack_situations(case) -> set[tuple[str, str]]:
    """(command kind, situation) pairs a decode_stream case shows, read from
    its bytes and expected events by a model of ACK matching of its own."""
    out: set[tuple[str, str]] = set()
    events = [(ev, raw, header_fields(raw[:HEADER_LEN])) for ev, raw in _events_with_bytes(case.input["hex"], _events(case))
              if ev["kind"] != "garbage" and len(raw) >= HEADER_LEN and crc16(raw[:10]) == raw[10] | raw[11] << 8]
    model = _AckModel()
    for i, (ev, raw, f) in enumerate(events):
        key = (f["session"], f["seq"])
        plain_data = f["enc"] == 0 and f["len"] > HEADER_LEN
        if not f["is_ack"]:
            if plain_data and len(raw) >= 14:
                model.command(ev, key, command_name(raw[12], raw[13]))
        elif "ack_of" in ev:
            out |= model.matched(ev, key, f["len"] == HEADER_LEN)
        elif plain_data and ev["kind"] == "frame":
            later = [command_name(r[12], r[13]) for e, r, g in events[i + 1:]
                     if not g["is_ack"] and e["kind"] == "frame" and (g["session"], g["seq"]) == key and len(r) > 14]
            out |= model.unmatched(key, later)
    return out


# ============================================================== check_movement_control precedence


MODE_CLASSES = ("invalid", "later_firmware", "undocumented", "documented")
MOVEMENT_PAIRS = (("length", "mode"), ("range", "mode"), ("length", "range"))
"""Pairs of check_movement_control checks one value can fail together. The
reference checks the length first (the value must parse), then the mode
byte, then the ranges; the generator pins that order for every pair."""


def movement_checks(data: bytes, profile: str) -> tuple[str | None, set[str]]:
    """(classification of the mode byte or None, the checks `data` fails:
    length, mode, range), each judged on its own; a setpoint of an
    undefined mode counts as out of range when it is not finite (no range
    admits it)."""
    import math
    import struct

    failed: set[str] = set()
    if len(data) != 17:
        failed.add("length")
    if not data:
        return None, failed
    cls = classify_control_mode(data[0], profile)["classification"]
    if cls != "documented":
        failed.add("mode")
    floats = [struct.unpack("<f", data[1 + 4 * i:5 + 4 * i])[0] for i in range(min(4, (len(data) - 1) // 4))]
    ranges = input_ranges(data[0], profile) if cls == "documented" else None
    for axis, value in zip(AXIS_RANGE, floats):
        if (_out_of_range(value, ranges[AXIS_RANGE[axis]]) if ranges else not math.isfinite(value)):
            failed.add("range")
    return cls, failed


# ============================================================== the tables


@dataclass
class Table:
    title: str
    columns: tuple[str, ...]
    rows: list[tuple[str, tuple[int | None, ...]]]  # None: impossible (n/a)
    minimum: int = 1
    """Fewer cases than this in a cell is a hole."""

    @property
    def holes(self) -> list[str]:
        return [f"{label} x {col}" for label, cells in self.rows for col, n in zip(self.columns, cells)
                if n is not None and n < self.minimum]

    def lines(self) -> list[str]:
        width = max([len(self.title)] + [len(label) for label, _ in self.rows]) + 2
        cw = [max(len(c), 6) for c in self.columns]
        out = [self.title.ljust(width) + "  ".join(c.rjust(w) for c, w in zip(self.columns, cw))]
        for label, cells in self.rows:
            text = "  ".join(("n/a" if n is None else str(n)).rjust(w) for n, w in zip(cells, cw))
            hole = [c for c, n in zip(self.columns, cells) if n is not None and n < self.minimum]
            out.append(label.ljust(width) + text + (f"   HOLE: {', '.join(hole)}" if hole else ""))
        return out


def stream_error_table(cases) -> Table:
    """Per stream error class: cases with it, followed by a good frame, and
    with a good frame found inside its bytes (where scanning resumes)."""
    counts = {c: [0, 0, 0] for c in stream_error_classes()}
    for case in cases:
        if case.operation != "decode_stream":
            continue
        events = _events(case)
        judged = [raw for _, raw in _events_with_bytes(case.input["hex"], events)]
        seen: dict[str, list[bool]] = {}
        for i, ev in enumerate(events):
            if ev["kind"] != "error" or ev["error"] not in counts:
                continue
            frames_after = [e for e in events[i + 1:] if e["kind"] == "frame"]
            inside = _hides_a_frame(judged[i])
            flags = seen.setdefault(ev["error"], [True, False, False])
            flags[1] |= bool(frames_after)
            flags[2] |= inside
        for cls, flags in seen.items():
            for k in range(3):
                counts[cls][k] += flags[k]
    # A rejected header's event covers the header alone, and an impossible
    # LEN announces no DATA: no whole frame fits inside, wherever scanning resumes.
    rows = [(cls, (n[0], n[1], None if cls == "impossible_length" else n[2])) for cls, n in counts.items()]
    return Table("stream error class", ("cases", "then a good frame", "a good frame inside"), rows)


def _hides_a_frame(raw: bytes) -> bool:
    """Whether a whole good frame starts inside `raw` after its first byte:
    found when scanning resumes after the start byte, skipped when it
    resumes after the frame."""

    for p in range(1, len(raw) - HEADER_LEN + 1):
        if raw[p] != 0xAA or header_problem(raw[p:p + HEADER_LEN]):
            continue
        length = frame_length(raw[p:p + HEADER_LEN])
        if p + length <= len(raw) and (length == HEADER_LEN or crc32(raw[p:p + length]) == 0):
            return True
    return False


def rule_pair_table(cases) -> Table:
    counts: dict[tuple[str, str], dict[str, int]] = {}
    for context in BOTH:
        for pair in rule_pairs(context):
            counts.setdefault(pair, {})[context] = 0
    for case in cases:
        for context, raw in _judged_frames(case):
            broken = broken_rules(raw, case.profile, context)
            for pair in counts:
                if context in counts[pair] and set(pair) <= broken:
                    counts[pair][context] += 1
    rows = [(f"{a} + {b}", tuple(c.get(ctx) for ctx in BOTH)) for (a, b), c in counts.items()]
    return Table("frame rule pair", BOTH, rows)


def _judged_frames(case) -> Iterator[tuple[str, bytes]]:
    """(context, bytes) of every frame a case asks a decoder to judge: the
    input of decode_frame, the bytes of each decode_stream event but garbage."""
    if case.operation == "decode_frame":
        yield "decode_frame", bytes.fromhex(case.input["hex"])
    elif case.operation == "decode_stream":
        for ev, raw in _events_with_bytes(case.input["hex"], _events(case)):
            if ev["kind"] != "garbage":
                yield "decode_stream", raw


VALID_HEADER_VALUES = {"ver": (0,), "res0": (0,), "res1": (0,), "enc": (0, 1)}
"""Header fields whose valid values are few (spec/rules.yaml#/frame: ver,
reserved_zero, enc.values): a bit none of them has never appears in a
frame that decodes, so its "set, decodes" cell is n/a."""


def header_bit_table(cases) -> Table:
    """Per header bit: cases in which a frame the receiver reads (CRC-16
    right) has it set, and those in which that frame decodes."""
    bits = header_bits()
    counts = {pos: [0, 0] for _, _, pos in bits}
    for case in cases:
        seen: dict[int, list[bool]] = {}
        for context, raw in _judged_frames(case):
            if len(raw) < HEADER_LEN or raw[0] != 0xAA or crc16(raw[:10]) != raw[10] | raw[11] << 8:
                continue
            valid = not broken_rules(raw, case.profile, context) and (context == "decode_stream" or case.result == "valid")
            for _, _, pos in bits:
                if raw[pos // 8] >> (pos % 8) & 1:
                    flags = seen.setdefault(pos, [True, False])
                    flags[1] |= valid
        for pos, flags in seen.items():
            counts[pos][0] += flags[0]
            counts[pos][1] += flags[1]
    rows = []
    for name, k, pos in bits:
        n, valid = counts[pos]
        possible = name not in VALID_HEADER_VALUES or any(v >> k & 1 for v in VALID_HEADER_VALUES[name])
        rows.append((f"{name} bit {k} (byte {pos // 8}, bit {pos % 8})", (n, valid if possible else None)))
    # One frame per profile is a handful: a decoder reading the field one bit
    # wrong would fail that few cases, so a hole is fewer than two per profile.
    return Table("header field bit", ("set", "set, decodes"), rows, minimum=6)


def ack_table(cases) -> Table:
    counts = {(k, s): 0 for k in command_kinds() for s in ACK_SITUATIONS}
    for case in cases:
        if case.operation == "decode_stream":
            for pair in ack_situations(case):
                if pair in counts:
                    counts[pair] += 1
    rows = [(kind, tuple(counts[(kind, s)] if feasible_situation(kind, s) else None for s in ACK_SITUATIONS))
            for kind in command_kinds()]
    return Table("command kind \\ ACK situation", tuple(ACK_SITUATIONS), rows)


def movement_table(cases) -> Table:
    counts = {(cls, pair): 0 for cls in MODE_CLASSES for pair in MOVEMENT_PAIRS}
    for case in cases:
        if case.operation != "check_movement_control":
            continue
        cls, failed = movement_checks(bytes.fromhex(case.input["hex"]), case.profile)
        for pair in MOVEMENT_PAIRS:
            if cls and set(pair) <= failed:
                counts[(cls, pair)] += 1
    # "mode" pairs need an undefined mode; "length + range" is judged with a documented one.
    rows = [(cls, tuple(counts[(cls, pair)] if (cls == "documented") != ("mode" in pair) else None
                        for pair in MOVEMENT_PAIRS)) for cls in MODE_CLASSES]
    return Table("mode byte class", tuple(" + ".join(p) for p in MOVEMENT_PAIRS), rows)


def tables(cases) -> list[Table]:
    cases = list(cases)
    return [stream_error_table(cases), rule_pair_table(cases), header_bit_table(cases), ack_table(cases),
            movement_table(cases)]
