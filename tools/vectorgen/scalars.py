"""Numbers as the wire carries them: float bit patterns, little-endian
words, and the value model of floats and enums that hand-written
expectations are written in."""
from __future__ import annotations

import struct

from osdk_conformance.core import model


def f32(value: float) -> int:
    """The float32 bits of `value`."""
    return struct.unpack("<I", struct.pack("<f", value))[0]


def f64(value: float) -> int:
    """The float64 bits of `value`."""
    return struct.unpack("<Q", struct.pack("<d", value))[0]


def f32_value(bits: int) -> float:
    return struct.unpack("<f", struct.pack("<I", bits))[0]


def f32_model(bits: int) -> dict:
    """A float32 as the value model writes it (bits and value)."""
    return model.float_model(bits, 32)


def f32_next_up(bits: int) -> int:
    """The bits of the smallest float32 above this finite one."""
    if bits == 0x80000000:
        return 0x00000001
    return bits - 1 if bits & 0x80000000 else bits + 1


def f32_next_down(bits: int) -> int:
    """The bits of the largest float32 below this finite one."""
    if bits == 0x00000000:
        return 0x80000001
    return bits + 1 if bits & 0x80000000 else bits - 1


F32_SPECIALS = {
    "qnan": 0x7FC00000, "snan": 0x7F800001, "nan_payload": 0x7FC12345, "neg_nan": 0xFFC00000,
    "inf": 0x7F800000, "neg_inf": 0xFF800000, "neg_zero": 0x80000000, "denormal_min": 0x00000001,
    "neg_denormal_max": 0x807FFFFF, "f32_max": 0x7F7FFFFF,
}
F64_SPECIALS = {
    "qnan": 0x7FF8000000000000, "snan": 0x7FF0000000000001, "neg_inf": 0xFFF0000000000000,
    "neg_zero": 0x8000000000000000, "denormal_min": 0x0000000000000001,
}
NON_FINITE = {"qnan", "snan", "nan_payload", "neg_nan", "inf", "neg_inf"}


def le16(v: int) -> bytes:
    return struct.pack("<H", v)


def enum(value: int, name: str | None) -> dict:
    """An enum field as the value model writes it (name null when unnamed)."""
    return {"value": value, "name": name}
