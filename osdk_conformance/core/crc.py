"""The two frame checksums of the OPEN protocol, from one small CRC engine.

A frame carries a CRC-16 over its first ten bytes and, when it has DATA, a
CRC-32 over every byte before the last four. Both are ordinary table-driven
CRCs that differ only in their parameter block, so this module has one
engine (`Crc`) and reads the two parameter blocks from spec/rules.yaml
(through `osdk_conformance.core.rules.crc_params`), which is where the spec keeps
them; nothing here repeats the numbers.

How `init` is read. The DJI SDK starts its right-shifting (reflected)
register at 0x3AA3 for both CRCs, and the check values in rules.yaml
(0x2752 and 0xE4D9DC14 over b"123456789") only come out that way. So
`init` here is the value the engine's own register starts with, in the
engine's shift direction. Catalogues in the Rocksoft/reveng style give the
init of a reflected CRC in unreflected form; in those terms these two CRCs
would have init reflect(0x3AA3). The engine does not reflect `init`.

A parameter block with zlib's polynomial and reflection (the frame CRC-32
among them) is computed by zlib.crc32, with init and xorout mapped onto
zlib's complemented register; every other block by the table.

The engine supports both shift directions (reflect_in true: bytes enter
least significant bit first; false: most significant bit first) so that it
can be tested against well-known CRCs of either kind, and a reflect_out
that differs from reflect_in reverses the register at the end.
"""
from __future__ import annotations

import functools
import zlib
from dataclasses import dataclass
from osdk_conformance.core.rules import crc_params

ZLIB_POLY = 0x04C11DB7  # the CRC-32 polynomial zlib.crc32 computes (reflected, normal form given)


@dataclass(frozen=True)
class CrcSpec:
    """The parameters the engine needs (a subset of rules.CrcParams)."""

    width: int
    poly: int  # normal (unreflected) form, without the top bit
    init: int  # the register's start value, in the engine's shift direction
    reflect_in: bool
    reflect_out: bool
    xorout: int


def reflect(value: int, width: int) -> int:
    """`value` with its lowest `width` bits in reverse order."""
    out = 0
    for _ in range(width):
        out = (out << 1) | (value & 1)
        value >>= 1
    return out


class Crc:
    """A table-driven CRC for one parameter block; zlib.crc32 computes the
    blocks with zlib's polynomial and reflection, whatever init and xorout."""

    def __init__(self, spec: CrcSpec) -> None:
        if spec.width < 8 or spec.width % 8:
            raise ValueError(f"CRC width {spec.width}: only whole bytes of at least 8 bits are supported")
        self.spec = spec
        self.mask = (1 << spec.width) - 1
        self.table = self._make_table()
        zlib_computes_it = (spec.width, spec.poly, spec.reflect_in, spec.reflect_out) == (32, ZLIB_POLY, True, True)
        self._run = self._zlib if zlib_computes_it else self._table_driven
        # zlib complements the register on the way in and on the way out
        self._zlib_in = (spec.init & self.mask) ^ 0xFFFFFFFF
        self._zlib_out = 0xFFFFFFFF ^ spec.xorout

    def _make_table(self) -> tuple[int, ...]:
        s = self.spec
        table = []
        if s.reflect_in:
            poly = reflect(s.poly, s.width)
            for byte in range(256):
                reg = byte
                for _ in range(8):
                    reg = (reg >> 1) ^ poly if reg & 1 else reg >> 1
                table.append(reg)
        else:
            top = 1 << (s.width - 1)
            for byte in range(256):
                reg = byte << (s.width - 8)
                for _ in range(8):
                    reg = ((reg << 1) ^ s.poly) & self.mask if reg & top else (reg << 1) & self.mask
                table.append(reg)
        return tuple(table)

    def __call__(self, data: bytes) -> int:
        return self._run(data)

    def _zlib(self, data: bytes) -> int:
        # The same register in C: the receivers check every frame, and the
        # table loop below costs about 0.1 us a byte.
        return zlib.crc32(data, self._zlib_in) ^ self._zlib_out

    def _table_driven(self, data: bytes) -> int:
        s, table = self.spec, self.table
        reg = s.init & self.mask
        if s.reflect_in:
            for byte in data:
                reg = (reg >> 8) ^ table[(reg ^ byte) & 0xFF]
        else:
            shift = s.width - 8
            for byte in data:
                reg = ((reg << 8) & self.mask) ^ table[((reg >> shift) ^ byte) & 0xFF]
        if s.reflect_out != s.reflect_in:
            reg = reflect(reg, s.width)
        return reg ^ s.xorout


@functools.cache
def engine(name: str) -> Crc:
    """The engine for "crc16" or "crc32", parameters from spec/rules.yaml."""

    p = crc_params(name)
    return Crc(CrcSpec(width=p.width, poly=p.poly, init=p.init, reflect_in=p.reflect_in,
                       reflect_out=p.reflect_out, xorout=p.xorout))


def crc16(data: bytes) -> int:
    """Frame header checksum (over bytes 0-9), stored little-endian at bytes 10-11."""
    return engine("crc16")(data)


def crc32(data: bytes) -> int:
    """Frame checksum over every byte before it, stored little-endian in the last 4 bytes."""
    return engine("crc32")(data)
