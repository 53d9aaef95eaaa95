"""One serial frame of the OPEN protocol, and an encoder that fills it in.

Mirrors spec/osdk_frame.ksy: the 12-byte header (start byte, LEN/VER,
session/ACK/RES0, PADDING/ENC, RES1, SEQ, CRC16), then, unless the frame
is header-only (LEN = 12), DATA and a CRC32. Plain DATA is decoded (command
set, id and the value by osdk_payload; or an ACK's raw value); encrypted
DATA stays ciphertext. The `valid` rules of the ksy hold in both directions:
VER, RES0, RES1 = 0, LEN = 12 or >= 17, PADDING = 0 when plain, 1..16
with whole 16-byte blocks when AES-256, and no ACK in session 0.

Like the Kaitai description, `osdk_frame(profile)` does not check the CRCs; it
reads and writes them as plain integers, so a test can build a frame with a
wrong CRC on purpose. `build_frame` is the encoder for correct frames: it
computes LEN and both CRCs (osdk_conformance.core.crc, parameters from
spec/rules.yaml).
"""
from __future__ import annotations

import functools
import struct

from construct import (
    BitsInteger, Bytes, Check, Const, Enum, Flag, GreedyBytes, Int8ul, Int16ul, Int32ul, Struct,
    this,
)

from osdk_conformance.core.crc import crc16, crc32

from . import compiled
from .bitfields import lsb_first, record
from .combinators import Call, Cond, ExactSize, when
from .enums import COMMAND_SET, ENCRYPTION, enum_int, profile_value
from .payload import osdk_payload

__all__ = [
    "HEADER_LEN", "CRC32_LEN", "MAX_LEN", "header", "osdk_frame", "frame", "frame_data", "parse_frame", "build_frame",
]

HEADER_LEN = 12
CRC32_LEN = 4
MAX_LEN = 0x3FF  # LEN is 10 bits


def _len_valid(this) -> bool:
    return this.len == HEADER_LEN or this.len >= HEADER_LEN + CRC32_LEN + 1


def _enc_valid(this) -> bool:
    # ERRATA E23: plain DATA has no padding; AES DATA is whole 16-byte
    # blocks and PADDING is 1..16.
    enc = enum_int(this.enc, ENCRYPTION)
    if enc == ENCRYPTION["plain"]:
        return this.padding == 0
    return (enc == ENCRYPTION["aes256"] and 1 <= this.padding <= 16
            and this.len > HEADER_LEN + CRC32_LEN and (this.len - HEADER_LEN - CRC32_LEN) % 16 == 0)


def _session_valid(this) -> bool:
    # ERRATA E24: a session-0 command wants no ACK, so no ACK is in session 0.
    return not this.is_ack or this.session != 0


_sof = "sof" / Const(b"\xaa")

_header_bits = lsb_first(
    "len" / BitsInteger(10),
    "ver" / Const(0, BitsInteger(6)),
    "session" / BitsInteger(5),
    "is_ack" / Flag,
    "res0" / Const(0, BitsInteger(2)),
    "padding" / BitsInteger(5),
    "enc" / Enum(BitsInteger(3), **ENCRYPTION),
    "res1" / Const(0, BitsInteger(24)),
    # Named so that a failure's path says which rule failed; in wire order,
    # so that a header breaking several rules reports the first, as the
    # .ksy (checked field by field) does.
    checks=("_valid_len" / Check(_len_valid), "_valid_session" / Check(_session_valid),
            "_valid_enc" / Check(_enc_valid)),
)

_crc16_covered = record(_sof, _header_bits, "seq" / Int16ul)
"""Bytes 0-9, the part of the header CRC16 covers."""

header = record(_sof, _header_bits, "seq" / Int16ul, "crc16" / Int16ul)
"""The 12-byte header alone (every frame starts with it)."""


def _is_command(this) -> bool:
    return not this._.is_ack


def _is_ack(this) -> bool:
    return bool(this._.is_ack)


@functools.cache
def frame_data(profile: int):
    """osdk_frame::frame_data: plain DATA of a command frame or an ACK frame."""
    return Struct(
        "cmd_set" / when(_is_command, Enum(Int8ul, **COMMAND_SET)),
        "cmd_id" / when(_is_command, Int8ul),
        "value" / when(_is_command, Call(osdk_payload, this.cmd_set, this.cmd_id, False, profile)),
        "ack_value" / when(_is_ack, GreedyBytes),
    )


def _has_data(this) -> bool:
    return this.len > HEADER_LEN


def _is_plain(this) -> bool:
    return enum_int(this.enc, ENCRYPTION) == ENCRYPTION["plain"]


def _data_len(this) -> int:
    return this.len - HEADER_LEN - CRC32_LEN


@functools.cache
def _frame(profile: int):
    return record(
        _sof,
        _header_bits,
        "seq" / Int16ul,
        "crc16" / Int16ul,
        "data" / when(_has_data, Cond(_is_plain, ExactSize(_data_len, frame_data(profile)), Bytes(_data_len))),
        "crc32" / when(_has_data, Int32ul),
    )


def osdk_frame(profile):
    """osdk_frame(profile): profile as value, ksy name or profile id."""
    return _frame(profile_value(profile))


frame = osdk_frame
"""Short name within this module (osdk_conformance._construct.frame.frame)."""


def parse_frame(data: bytes, profile):
    """Parse one frame from the start of `data` (bytes after it are ignored,
    as a stream parser would leave them for the next frame). Compiled where
    that is safe (compiled.py); values and errors are the interpreter's."""
    return compiled.parse(osdk_frame(profile), data)


def build_frame(*, cmd_set=None, cmd_id=None, value: bytes = b"", is_ack: bool = False,
                session: int = 0, seq: int = 0, enc: int = 0, padding: int = 0) -> bytes:
    """Encode a frame with LEN, CRC16 and CRC32 filled in.

    DATA is [cmd_set, cmd_id] + value for a command frame, value alone for
    an ACK frame (is_ack, no cmd_set/cmd_id) or for encrypted DATA (enc=1:
    give the ciphertext as value, no cmd_set/cmd_id). With no DATA at all the
    frame is the 12-byte header alone. Raises on anything the spec forbids
    (LEN over 1023, PADDING/ENC mismatch, fields out of range).
    """
    if (cmd_set is None) != (cmd_id is None):
        raise ValueError("give both cmd_set and cmd_id, or neither")
    if cmd_set is not None and is_ack:
        raise ValueError("an ACK frame carries no command set and id")
    data = bytes(value)
    if cmd_set is not None:
        data = bytes([enum_int(cmd_set, COMMAND_SET), cmd_id]) + data
    length = HEADER_LEN + (len(data) + CRC32_LEN if data else 0)
    if length > MAX_LEN:
        raise ValueError(f"frame of {length} bytes exceeds the {MAX_LEN}-byte maximum of LEN")
    for name, v, top in (("session", session, 31), ("seq", seq, 0xFFFF), ("padding", padding, 31), ("enc", enc, 7)):
        if not isinstance(v, int) or not 0 <= v <= top:
            raise ValueError(f"{name} must be an integer 0..{top}, got {v!r}")
    covered = _crc16_covered.build(
        {"len": length, "session": session, "is_ack": bool(is_ack), "padding": padding, "enc": enc, "seq": seq}
    )
    out = covered + struct.pack("<H", crc16(covered))
    if data:
        out += data
        out += struct.pack("<I", crc32(out))
    return out
