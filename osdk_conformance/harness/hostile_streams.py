"""Byte streams built to make a receiver work hard or hold on to memory.

Every kind is produced in blocks, cut to an exact total length, so that a
stream of any size (a gibibyte and more) can be written to a testee's
bench mode (`<testee> --bench - --profile P`, conformance/PROTOCOL.md)
without being held in memory here either. The same kind, length and seed
always give the same bytes.

- `random`: seeded pseudo-random bytes. About one byte in 256 is a start
  byte, and nearly every header it starts fails its CRC-16.
- `max_len_headers`: headers that pass every header check and claim the
  maximum LEN (1023), back to back. Each one makes the receiver hold a
  partial frame of 1023 bytes across reads and then fail its CRC-32 (the
  next headers are inside it) and rescan from the byte after its start:
  1023 bytes of CRC-32 work for every 12 bytes of input.
- `truncated_headers`: headers that never complete. The first 1, 2, ...,
  11 bytes of a valid header, each cut short by the start byte of the next,
  so every start byte begins a header that fails its CRC-16.
- `max_len_frames`: valid 1023-byte frames back to back, every one of which
  deframes and decodes.
"""
from __future__ import annotations

import random
from typing import Iterator

from osdk_conformance._construct import build_frame
from osdk_conformance._construct.frame import CRC32_LEN, HEADER_LEN, MAX_LEN

BLOCK = 1 << 20
KINDS = ("random", "max_len_headers", "truncated_headers", "max_len_frames")

# A command with no payload layout in the spec: its value is carried raw,
# so a frame of any length decodes.
_RAW_COMMAND = {"cmd_set": 0x00, "cmd_id": 0x7F}


def max_len_frame(seed: int = 0, seq: int = 0) -> bytes:
    """A valid frame of the maximum length, LEN 1023."""
    value = random.Random(seed).randbytes(MAX_LEN - HEADER_LEN - CRC32_LEN - 2)
    return build_frame(**_RAW_COMMAND, value=value, seq=seq)


def max_len_header(seq: int = 0) -> bytes:
    """12 bytes that pass every header check and claim LEN 1023."""
    return max_len_frame(seq=seq)[:HEADER_LEN]


def _period(kind: str, seed: int) -> bytes:
    if kind == "max_len_headers":
        return max_len_header()
    if kind == "truncated_headers":
        header = max_len_header()
        return b"".join(header[:n] for n in range(1, HEADER_LEN))
    if kind == "max_len_frames":
        return max_len_frame(seed)
    raise ValueError(f"unknown hostile stream kind {kind!r} (known: {', '.join(KINDS)})")


def blocks(kind: str, total: int, *, seed: int = 0, block: int = BLOCK) -> Iterator[bytes]:
    """The stream of `kind`, exactly `total` bytes, in blocks of at most `block` bytes.
    The bytes depend on `kind`, `total` and `seed` only."""
    if total < 0 or block <= 0:
        raise ValueError("total must be >= 0 and block > 0")
    if not total:
        return
    left = total
    for piece in _pieces(kind, seed):
        piece = piece[:left]
        for at in range(0, len(piece), block):
            yield piece[at:at + block]
        left -= len(piece)
        if not left:
            return


def _pieces(kind: str, seed: int) -> Iterator[bytes]:
    """The endless stream of `kind` in pieces of about BLOCK bytes."""
    if kind == "random":
        rng = random.Random(seed)
        while True:
            yield rng.randbytes(BLOCK)
    period = _period(kind, seed)
    # Whole periods per piece, so that each piece goes on where the last one ended.
    unit = period * max(1, BLOCK // len(period))
    while True:
        yield unit
