"""Frames packed field by field (PROTOCOL-FACTS section 1), independently
of the spec's own builder, and the edits that break them."""
from __future__ import annotations

import struct

from osdk_conformance.core.crc import crc16, crc32

from .scalars import le16

# The two worked frames of PROTOCOL-FACTS section 1, verbatim.
WORKED_MOVEMENT = "aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba"
WORKED_BROADCAST = "aa1600000000000007001ede02000018035769c676b2"
WORKED_MOVEMENT_VALUE = "4b0000803f000000c00000003f0000f041"
"""The value (mode 0x4B, x 1.0, y -2.0, z 0.5, yaw 30.0) of the worked movement control frame."""
WORKED_BROADCAST_VALUE = "00180357"
"""The value of the worked broadcast frame: flags 0x1800, flight status 3, battery 87."""
WORKED_BROADCAST_PROFILE = "a3-fw3.1"
"""The layout the worked broadcast frame is in (bits 11 and 12: flight status and battery)."""


def frame_bytes(*, cmd_set: int | None = None, cmd_id: int | None = None, value: bytes = b"", is_ack: bool = False,
                session: int = 0, seq: int = 0, enc: int = 0, padding: int = 0, ver: int = 0, res0: int = 0,
                res1: int = 0, length: int | None = None, data: bytes | None = None) -> bytes:
    """A frame packed field by field (PROTOCOL-FACTS section 1) with any header
    values, LEN computed unless given, and both CRCs right for what is there."""
    if data is None:
        data = value if cmd_set is None else bytes([cmd_set, cmd_id]) + value
    if length is None:
        length = 12 + (len(data) + 4 if data else 0)
    head = bytes([0xAA]) + le16((length & 0x3FF) | ver << 10) + bytes([session | is_ack << 5 | res0 << 6,
                                                                          padding | enc << 5])
    head += res1.to_bytes(3, "little") + le16(seq)
    head += le16(crc16(head))
    if not data:
        return head
    body = head + data
    return body + struct.pack("<I", crc32(body))


def flip(data: bytes, bit: int) -> bytes:
    """`data` with one bit inverted (bit 0 = least significant bit of byte 0)."""
    b = bytearray(data)
    b[bit // 8] ^= 1 << (bit % 8)
    return bytes(b)


def flip_last(data: bytes) -> bytes:
    return data[:-1] + bytes([data[-1] ^ 0x01])


def reseal(data: bytes) -> bytes:
    """Both CRCs recomputed over what is there, after a byte was edited."""
    b = bytearray(data)
    b[10:12] = le16(crc16(bytes(b[:10])))
    if len(b) > 12:
        b[-4:] = struct.pack("<I", crc32(bytes(b[:-4])))
    return bytes(b)


def crc16_wrong(data: bytes) -> bytes:
    """A bit of the stored CRC-16 flipped, the CRC-32 still right for the bytes."""
    b = flip(data, 80)
    return b[:-4] + struct.pack("<I", crc32(b[:-4])) if len(b) > 12 else b


def movement_hex(byte: int, x: int, y: int, z: int, yaw: int) -> str:
    """A movement control value (mode byte, then four float32 setpoints by their bits) as hex."""
    return (bytes([byte]) + struct.pack("<4I", x, y, z, yaw)).hex()


GOOD_FRAME = frame_bytes(cmd_set=1, cmd_id=0, value=b"\x01", seq=0x0203)
"""A small valid frame (control request, session 0) placed after or inside bad ones."""
