"""decode_frame and decode_payload: conformance/PROTOCOL.md "The rule order",
steps 1-7, the first rule broken giving the one error."""
from __future__ import annotations

from io import BytesIO
from typing import Any, Callable

from kaitaistruct import KaitaiStream, KaitaiStructError

from . import crc
from ._tables import (CRC16, CRC32, CRC_CLASSES, CRC32_FIELD, DATA_FIELD, ERROR_BY_FIELD, HEADER_CHECKS,
                      CRC32_LEN, HEADER_FIELDS, HEADER_LEN, IMPOSSIBLE_LENGTHS, PROFILES, SOF)
from .errors import OsdkError, from_kaitai
from .osdk_frame import OsdkFrame
from .osdk_payload import OsdkPayload


def profile_value(profile: str) -> OsdkPayload.Profile:
    """The parsers' Profile of a profile id ("m100-fw2.3", "m100-fw3.1", "a3-fw3.1")."""
    if not isinstance(profile, str) or profile not in PROFILES:
        raise ValueError(f"unknown profile {profile!r} (one of {', '.join(PROFILES)})")
    return OsdkPayload.Profile(PROFILES[profile])


def as_bytes(data: Any, what: str = "data") -> bytes:
    if not isinstance(data, (bytes, bytearray, memoryview)):
        raise TypeError(f"{what} must be bytes, got {type(data).__name__}")
    return bytes(data)


def header_fields(header: bytes) -> dict[str, int]:
    """The 12-byte header's fields as plain numbers, checked or not."""
    word = int.from_bytes(header[:HEADER_LEN], "little")
    return {name: word >> (8 * byte + lsb) & ((1 << width) - 1)
            for name, (byte, lsb, width) in HEADER_FIELDS.items()}


def header_error(header: bytes) -> OsdkError | None:
    """The first of the receiver's header checks the 12 bytes break (step 2)."""
    fields = header_fields(header)
    for check in HEADER_CHECKS:
        if check == "sof":
            if fields["sof"] != SOF:
                return OsdkError(ERROR_BY_FIELD["sof"], "sof", f"first byte 0x{fields['sof']:02x} is not 0x{SOF:02x}")
        elif check in CRC_CLASSES:
            want = crc.computed(header, CRC16)
            if fields[check] != want:
                # when it fails the other header fields mean nothing
                return OsdkError(CRC_CLASSES[check], check, f"CRC-16 is 0x{fields[check]:04x}, expected 0x{want:04x}")
        elif check == "len":
            n = fields["len"]
            if any(lo <= n <= hi for lo, hi in IMPOSSIBLE_LENGTHS):
                return OsdkError(ERROR_BY_FIELD["len"], "len", f"LEN {n} is impossible")
        elif fields[check] != 0:
            # the other checked header fields are reserved or a version: 0 only
            return OsdkError(ERROR_BY_FIELD[check], check, f"{check} is {fields[check]}, must be 0")
    return None


def _short_header_field(have: int) -> str | None:
    """The header field the input ends in."""
    for name, (byte, lsb, width) in HEADER_FIELDS.items():
        if 8 * byte + lsb + width > 8 * have:
            return name
    return None


def parse(make: Callable[[KaitaiStream], Any], data: bytes, truncated: str = "truncated_payload") -> Any:
    """make(stream over data), a Kaitai exception turned into OsdkError."""
    try:
        return make(KaitaiStream(BytesIO(data)))
    except (KaitaiStructError, EOFError) as e:
        raise from_kaitai(e, truncated) from None


def frame_error(data: bytes) -> OsdkError | None:
    """Steps 1-4 on one frame's bytes: what a receiver checks before parsing."""
    if not data:
        return OsdkError("truncated_frame", "sof", "no bytes")
    if data[0] != SOF:
        return OsdkError(ERROR_BY_FIELD["sof"], "sof", f"first byte 0x{data[0]:02x} is not 0x{SOF:02x}")
    if len(data) < HEADER_LEN:
        return OsdkError("truncated_frame", _short_header_field(len(data)),
                         f"{len(data)} bytes, less than a {HEADER_LEN}-byte header")
    problem = header_error(data[:HEADER_LEN])
    if problem:
        return problem
    length = header_fields(data)["len"]
    if len(data) < length:
        field = DATA_FIELD if len(data) < length - CRC32_LEN else CRC32_FIELD
        return OsdkError("truncated_frame", field, f"{len(data)} bytes of a frame of LEN {length}")
    if len(data) > length:
        return OsdkError("length_mismatch", None, f"{len(data)} bytes for LEN {length}")
    if length > HEADER_LEN:
        have, want = crc.stored(data, CRC32), crc.computed(data, CRC32)
        if have != want:
            return OsdkError(CRC_CLASSES[CRC32_FIELD], CRC32_FIELD, f"CRC-32 is 0x{have:08x}, expected 0x{want:08x}")
    return None


def decode_frame(data: bytes, profile: str) -> OsdkFrame:
    """One frame's bytes (exactly one frame) as the parsed OsdkFrame for the
    profile id; OsdkError with the class of the first rule broken."""
    p = profile_value(profile)
    data = as_bytes(data)
    problem = frame_error(data)
    if problem:
        raise problem
    return parse(lambda io: OsdkFrame(p, io), data)


def decode_payload(data: bytes, cmd_set: int, cmd_id: int, is_ack: bool, profile: str) -> Any:
    """The body of a command's (or, is_ack, its ACK's) value (step 7)."""
    p = profile_value(profile)
    data = as_bytes(data)
    for name, v in (("cmd_set", cmd_set), ("cmd_id", cmd_id)):
        if isinstance(v, bool) or not isinstance(v, int) or not 0 <= v <= 0xFF:
            raise ValueError(f"{name} must be an int 0..255, got {v!r}")
    return parse(lambda io: OsdkPayload(cmd_set, cmd_id, bool(is_ack), p, io), data).body
