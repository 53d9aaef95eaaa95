"""Bug class "header field bit" (osdk_conformance.harness.vector_tables):
every bit of every header field set in a valid frame, so that a decoder
reading a field one bit too wide, too narrow or shifted misreads one."""
from __future__ import annotations

from typing import Callable

from osdk_conformance.harness import vector_tables as vt

from .builder import GenerationError, R
from .wire import GOOD_FRAME, frame_bytes

FIELD_RULES = {"len": "frame.len", "session": "frame.session", "padding": "frame.enc", "seq": "frame.data",
               "res1": "frame.reserved"}


def header_bit_frames(field: str, k: int) -> list[tuple[str, dict]]:
    """Valid frames with bit k of a header field set (or, for LEN, also
    every other bit set), as frame_bytes arguments; [] for a field whose
    bits only appear in invalid frames, which the frames suite already has
    for every value (VER, RES0, ENC 2..7) or which are set here (RES1)."""
    if field == "len":
        out = []
        for tag, length in (("set", 17 | 1 << k), ("all_but", 0x3FF & ~(1 << k))):
            if length == 17:  # the one DATA byte of a LEN 17 frame is an ACK's value
                out.append((tag, {"is_ack": True, "session": 1, "value": b"\x00", "seq": 0x0607}))
            else:
                out.append((tag, {"cmd_set": 0, "cmd_id": 0x7F, "value": bytes(length - 18), "seq": 0x0607}))
        return out
    if field == "session":
        return [("command", {"cmd_set": 1, "cmd_id": 0, "value": b"\x01", "session": 1 << k, "seq": 0x0607}),
                ("ack", {"is_ack": True, "value": b"\x02\x00", "session": 1 << k, "seq": 0x0607})]
    if field == "padding":
        return [("aes", {"data": bytes(range(32)), "enc": 1, "padding": 1 << k, "seq": 0x0607})]
    if field == "seq":
        return [("command", {"cmd_set": 1, "cmd_id": 0, "value": b"\x01", "seq": 1 << k})]
    if field == "res1":
        return [("set", {"cmd_set": 1, "cmd_id": 0, "value": b"\x01", "res1": 1 << k})]
    return []


def describe_bit(field: str, k: int, tag: str, kw: dict, data: bytes) -> str:
    """How a case comment names the frame. Keyed on the tag alone, so the
    RES1 frames (tag "set") are named by their LEN, not by the RES1 value;
    changing that would change the vectors."""
    if tag == "set":
        return f"LEN {len(data)} (bit {k} set)"
    if tag == "all_but":
        return f"LEN {len(data)} (every bit but {k} set)"
    value = kw.get("session") or kw.get("padding") or kw.get("seq")
    return f"{field} {value} (bit {k} set), {tag}"


def add_header_bits(add: Callable[..., None], stream: bool) -> None:
    """Every bit of every header field (vt.header_bits, from the spec's
    layout) set in a frame. In streams, LEN bits only (LEN decides where
    the next frame starts), each frame followed by a good one."""
    for field, k, pos in vt.header_bits():
        if stream and field != "len":
            continue
        for tag, kw in header_bit_frames(field, k):
            if stream and tag != "set":
                continue
            data = frame_bytes(**kw)
            if bool(data[pos // 8] >> (pos % 8) & 1) != (tag != "all_but"):
                raise GenerationError(f"header bit {field}.{k} is not as {tag} says in its frame")
            what = describe_bit(field, k, tag, kw, data)
            flags = R(FIELD_RULES[field])
            if stream:
                add(f"header_bits.{field}.bit{k}", "stream.header_bits",
                    f"a frame with {what}, then a good frame: LEN decides where the next frame starts",
                    data + GOOD_FRAME, flags + R("stream.resync"))
            else:
                add(f"header_bits.{field}.bit{k}.{tag}", "frame.header_bits",
                    f"header bit {pos} (byte {pos // 8}, bit {pos % 8}) is bit {k} of {field}: {what}",
                    data, flags)
