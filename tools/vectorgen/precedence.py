"""Bug class "frame rule pair" (osdk_conformance.harness.vector_tables):
every pair of frame rules broken on one frame, in every way that takes a
different path through a decoder; the class reported is the first rule's
in the spec's precedence."""
from __future__ import annotations

from typing import Any, Callable

from osdk_conformance.harness import vector_tables as vt
from osdk_conformance.reference import codec as reference

from .builder import GenerationError, R
from .wire import GOOD_FRAME, crc16_wrong, flip_last, frame_bytes, reseal

PAIR_BASE = {"cmd_set": 1, "cmd_id": 0, "value": b"\x01", "session": 2, "seq": 0x0102}
"""The frame every pair of broken rules starts from: a control request in session 2."""

# How each rule of vt.FRAME_RULES is broken, in every way that takes a
# different path through a decoder (variant tag -> header values for
# frame_bytes, and an edit of the finished bytes at a stage: 0 before both
# CRCs are recomputed, 1 after, 2 last).
Breaker = tuple[dict, int, Callable[[bytes], bytes] | None]
BREAKERS: dict[str, dict[str, Breaker]] = {
    "sof": {"": ({}, 0, lambda d: b"\x55" + d[1:])},
    "crc16": {"": ({}, 1, crc16_wrong)},
    "ver": {"": ({"ver": 1}, 0, None)},
    "res0": {"": ({"res0": 1}, 0, None)},
    "res1": {"": ({"res1": 0x000001}, 0, None)},  # its lowest bit alone: a decoder reading ENC one bit wide sees 0
    "len": {"below12": ({"length": 3}, 0, None), "13to16": ({"length": 14}, 0, None)},
    "size": {"extra": ({}, 2, lambda d: d + b"\x00"), "short": ({}, 2, lambda d: d[:-1])},
    "crc32": {"": ({}, 1, flip_last)},
    "session": {"": ({"is_ack": True, "session": 0, "cmd_set": None, "cmd_id": None, "value": b"\x02\x00"}, 0, None)},
    # plain DATA with padding (the value is still decoded), an undefined ENC, AES without padding
    "enc": {"plain_padding": ({"padding": 1}, 0, None), "enc2": ({"enc": 2}, 0, None),
            "aes_padding0": ({"enc": 1}, 0, None)},
    "value": {"trailing": ({"value": b"\x01\x00"}, 0, None), "short": ({"value": b""}, 0, None)},
}
RULE_FLAGS = {"sof": "frame.sof", "crc16": "frame.crc16", "ver": "frame.ver", "res0": "frame.reserved",
              "res1": "frame.reserved", "len": "frame.len", "size": "frame.extra_bytes", "crc32": "frame.crc32",
              "session": "frame.session", "enc": "frame.enc", "value": "payload.trailing",
              "size-short": "frame.truncation", "value-short": "payload.truncated"}
"""The rule flag of each breaker ("rule" or "rule-variant")."""


def broken_frame(breakers: list[Breaker]) -> bytes | None:
    """PAIR_BASE with every breaker applied, or None when two of them need
    the same header value to differ."""
    wanted: dict[str, Any] = {}
    for fields, _, _ in breakers:
        for k, v in fields.items():
            if k in wanted and wanted[k] != v:
                return None
            wanted[k] = v
    data = frame_bytes(**{**PAIR_BASE, **wanted})
    for stage in (0, 1, 2):
        edits = [edit for _, at, edit in breakers if at == stage and edit]
        for edit in edits:
            data = edit(data)
        if stage == 0 and edits:
            data = reseal(data)
    return data


def first_rule(broken: set[str], context: str) -> vt.FrameRule:
    return next(r for r in vt.FRAME_RULES if r.name in broken and context in r.contexts)


def variant_pairs(a: str, b: str, profile: str, context: str) -> list[tuple[str, bytes, set[str], list[str]]]:
    """(id part, frame bytes, rules it breaks, rule flags) for every way of
    breaking both a and b together; GenerationError when there is none."""
    out = []
    for ta, ba in BREAKERS[a].items():
        for tb, bb in BREAKERS[b].items():
            data = broken_frame([ba, bb])
            broken = vt.broken_rules(data, profile, context) if data else set()
            if {a, b} <= broken:
                names = [f"{n}-{t}" if t else n for n, t in ((a, ta), (b, tb))]
                flags = R(*{RULE_FLAGS.get(name, RULE_FLAGS[name.split("-")[0]]) for name in names})
                out.append((".".join(names), data, broken, flags))
    if not out:
        raise GenerationError(f"rules {a} and {b} cannot be broken together; list the pair in "
                              f"vector_tables.IMPOSSIBLE_PAIRS with the reason")
    return out


def add_rule_pairs(profile: str, context: str, prefix: str, add: Callable[..., None]) -> None:
    """One case per pair of frame rules that can fire on one frame
    (vt.rule_pairs) and per way of breaking each: the frame alone
    (decode_frame) or followed by GOOD_FRAME (decode_stream)."""
    for a, b in vt.rule_pairs(context):
        for name, data, broken, flags in variant_pairs(a, b, profile, context):
            add_rule_pair(profile, context, f"{prefix}.{name}", a, b, data, broken, flags, add)


def add_rule_pair(profile: str, context: str, id: str, a: str, b: str, data: bytes, broken: set[str],
                  flags: list[str], add: Callable[..., None]) -> None:
    """The case of one way of breaking a and b; the reference must answer
    what the precedence of the first broken rule says."""
    first = first_rule(broken, context)
    also = sorted(broken - {a, b}, key=[r.name for r in vt.FRAME_RULES].index)
    what = f"{a} and {b} broken on one frame{' (and ' + ', '.join(also) + ')' if also else ''}"
    if context == "decode_frame":
        ref = reference.answer("decode_frame", profile, {"hex": data.hex()})
        if ref["ok"] or ref["error"] not in first.classes:
            raise GenerationError(f"{id}: the reference answers {ref}, precedence says {first.name}")
        add(id, "frame.precedence", f"{what}: {first.name} comes first, {ref['error']}", data, flags,
            error=ref["error"])
        return
    events = reference.answer("decode_stream", profile, {"hex": (data + GOOD_FRAME).hex(),
                                                         "chunks": [len(data) + len(GOOD_FRAME)]})
    ev = events["result"]["events"][0]
    if ev["kind"] != "error" or ev["offset"] != 0 or ev["error"] not in first.classes:
        raise GenerationError(f"{id} in a stream: first event {ev}, precedence says {first.name}")
    add(id, "stream.precedence", f"{what}, then a good frame: {first.name} comes first ({ev['error']} covering "
        f"{ev['length']} byte(s)), and scanning resumes where that class says", data + GOOD_FRAME,
        flags + R("stream.resync"))
