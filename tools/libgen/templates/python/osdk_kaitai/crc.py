"""CRC-16 and CRC-32 of the frame (both reflected; parameters and 256-entry
tables from the spec's tables, spec/rules.yaml `crc`)."""
from __future__ import annotations

from ._tables import CRC16, CRC16_TABLE, CRC32, CRC32_TABLE


def _crc(data: bytes, table: tuple[int, ...], init: int, xorout: int) -> int:
    crc = init
    for b in data:
        crc = table[(crc ^ b) & 0xFF] ^ (crc >> 8)
    return crc ^ xorout


def crc16(data: bytes) -> int:
    """The header's CRC-16 of `data`."""
    return _crc(data, CRC16_TABLE, CRC16["init"], CRC16["xorout"])


def crc32(data: bytes) -> int:
    """The frame's CRC-32 of `data`."""
    return _crc(data, CRC32_TABLE, CRC32["init"], CRC32["xorout"])


def span(data: bytes, where: tuple[int, int]) -> bytes:
    """The bytes of an inclusive (first, last) position pair, negative from the end."""
    first, last = (p if p >= 0 else len(data) + p for p in where)
    return data[first:last + 1]


def stored(data: bytes, params: dict) -> int:
    return int.from_bytes(span(data, params["stored_at"]), "little")


def computed(data: bytes, params: dict) -> int:
    fn = crc16 if params is CRC16 else crc32
    return fn(span(data, params["covers"]))


# A wrong table would make every frame fail its CRC: refuse to load instead.
for _fn, _params in ((crc16, CRC16), (crc32, CRC32)):
    if _fn(b"123456789") != _params["check"]:
        raise ImportError(f"osdk_kaitai: {_fn.__name__} fails its check value")
