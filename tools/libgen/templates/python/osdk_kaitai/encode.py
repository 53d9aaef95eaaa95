"""The values of the commands an onboard computer sends, and whole frames
(conformance/PROTOCOL.md "encode_movement_control and encode_frame").
The encoders are generated from the commands' layouts in spec/osdk_payload.ksy."""
from __future__ import annotations

import struct
from typing import Any, Callable, Sequence

from . import crc
from ._tables import CRC16, CRC32, CRC32_LEN, ERROR_BY_FIELD, HEADER_FIELDS, HEADER_LEN, MAX_LEN, SOF
from .decode import as_bytes
from .errors import OsdkError


class Float32Bits:
    """A float32 given by its 32 IEEE bits, sent exactly as they are: the
    way to send a NaN with a payload (a Python float cannot carry a
    signalling NaN through float32 conversion). -0.0 and infinities also
    go out exactly as Python floats."""

    __slots__ = ("bits",)

    def __init__(self, bits: int) -> None:
        if isinstance(bits, bool) or not isinstance(bits, int) or not 0 <= bits <= 0xFFFFFFFF:
            raise ValueError(f"float32 bits must be an int 0..0xFFFFFFFF, got {bits!r}")
        self.bits = bits

    def __repr__(self) -> str:
        return f"Float32Bits(0x{self.bits:08x})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Float32Bits) and other.bits == self.bits

    def __hash__(self) -> int:
        return hash(self.bits)


def _uint(value: Any, name: str, size: int) -> bytes:
    if isinstance(value, bool) or not isinstance(value, int):
        raise TypeError(f"{name} must be an int, got {type(value).__name__}")
    if not 0 <= value < 1 << (8 * size):
        raise ValueError(f"{name} must be 0..{(1 << 8 * size) - 1}, got {value}")
    return int(value).to_bytes(size, "little")


def _u1(value: Any, name: str) -> bytes:
    return _uint(value, name, 1)


def _u2(value: Any, name: str) -> bytes:
    return _uint(value, name, 2)


def _u4(value: Any, name: str) -> bytes:
    return _uint(value, name, 4)


def _f4(value: Any, name: str) -> bytes:
    if isinstance(value, Float32Bits):
        return value.bits.to_bytes(4, "little")
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise TypeError(f"{name} must be a float or Float32Bits, got {type(value).__name__}")
    try:
        return struct.pack("<f", value)
    except OverflowError:
        raise ValueError(f"{name} = {value!r} is beyond the float32 range") from None


def _bytes(value: Any, size: int, name: str) -> bytes:
    value = as_bytes(value, name)
    if len(value) != size:
        raise ValueError(f"{name} must be {size} bytes, got {len(value)}")
    return value


def _repeat(values: Any, count: int, name: str, write: Callable[[Any, str], bytes]) -> bytes:
    values = list(values)
    if len(values) != count:
        raise ValueError(f"{name} must have {count} elements, got {len(values)}")
    return b"".join(write(v, f"{name}[{i}]") for i, v in enumerate(values))


def _sized(value: bytes, size: int, name: str) -> bytes:
    assert len(value) == size, f"{name}: {len(value)} bytes, the layout says {size}"
    return value


${encoders}

def _header(fields: dict[str, int]) -> bytes:
    word = 0
    for name, value in fields.items():
        byte, lsb, width = HEADER_FIELDS[name]
        word |= (value & ((1 << width) - 1)) << (8 * byte + lsb)
    return word.to_bytes(HEADER_LEN, "little")


def encode_frame(cmd_set: int | None, cmd_id: int | None, is_ack: bool, session: int, seq: int,
                 value: bytes = b"") -> bytes:
    """A whole plain frame: DATA is cmd_set, cmd_id and the value for a
    command, the value alone for an ACK (cmd_set and cmd_id are then not
    used and may be None); LEN, both CRCs; the reserved fields 0. OsdkError
    impossible_length (longer than the 10-bit LEN), then bad_session (an
    ACK in session 0); ValueError/TypeError for arguments out of range."""
    value = as_bytes(value, "value")
    is_ack = bool(is_ack)
    _u1(session, "session")
    if not 0 <= session <= (1 << HEADER_FIELDS["session"][2]) - 1:
        raise ValueError(f"session must be 0..{(1 << HEADER_FIELDS['session'][2]) - 1}, got {session}")
    _u2(seq, "seq")
    data = value if is_ack else _u1(cmd_set, "cmd_set") + _u1(cmd_id, "cmd_id") + value
    length = HEADER_LEN + len(data) + CRC32_LEN if data else HEADER_LEN
    if length > MAX_LEN:
        raise OsdkError(ERROR_BY_FIELD["len"], "len", f"a frame of {length} bytes is longer than {MAX_LEN}")
    if is_ack and session == 0:
        raise OsdkError(ERROR_BY_FIELD["is_ack"], "is_ack", "an ACK frame is never in session 0")
    fields = {"sof": SOF, "len": length, "session": session, "is_ack": int(is_ack), "seq": seq}
    header = _header(fields)
    header = _header({**fields, "crc16": crc.computed(header, CRC16)})
    if not data:
        return header
    frame = header + data + bytes(CRC32_LEN)
    return frame[:-CRC32_LEN] + crc.computed(frame, CRC32).to_bytes(CRC32_LEN, "little")
