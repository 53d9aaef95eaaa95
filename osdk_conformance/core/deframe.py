"""Find frames in a byte stream the way the SDK's receiver does.

The receiver hunts for 0xAA, checks the 12-byte header (VER = 0,
RES0 = 0, RES1 = 0, a possible LEN, CRC-16) and on any failure drops that
ONE byte and hunts again. With a good header it waits for LEN bytes and
checks the CRC-32; on failure it rescans from the byte after the rejected
start, so a valid frame hidden inside a corrupt one is still found.
(PROTOCOL-FACTS section 1; SDK 3.1.9 byteHandler/verifyHead/verifyData.)

Unlike the SDK, every rejection is reported: a conformance tool has to say
why bytes were dropped, not only that they were. Memory is bounded by one
maximum-length frame plus the read size, whatever the input.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Iterable, Iterator

from osdk_conformance.core.crc import crc16, crc32

SOF = 0xAA
HEADER_LEN = 12
CRC32_LEN = 4
MAX_LEN = 0x3FF


@dataclass(frozen=True)
class Frame:
    offset: int
    raw: bytes


@dataclass(frozen=True)
class Rejected:
    """Bytes the receiver dropped, and why."""

    offset: int
    error: str
    detail: str
    length: int = 1  # how many bytes this rejection accounts for


@dataclass(frozen=True)
class Garbage:
    """A run of bytes before any start-of-frame byte."""

    offset: int
    length: int


Event = Frame | Rejected | Garbage


def header_problem(header: bytes) -> tuple[str, str] | None:
    """(error class, detail) of the first thing wrong with a 12-byte
    header, or None. CRC-16 is checked first: when it fails, the values of
    the other fields mean nothing."""
    stored = header[10] | header[11] << 8
    computed = crc16(header[:10])
    if computed != stored:
        return "bad_crc16", f"CRC-16 is 0x{stored:04x}, expected 0x{computed:04x}"
    word = header[1] | header[2] << 8
    length, ver = word & 0x3FF, word >> 10
    if ver != 0:
        return "bad_version", f"header version {ver}, must be 0"
    if header[3] >> 6:
        return "reserved_bits", f"RES0 is {header[3] >> 6}, must be 0"
    if any(header[5:8]):
        return "reserved_bits", f"RES1 is 0x{header[7]:02x}{header[6]:02x}{header[5]:02x}, must be 0"
    if length < HEADER_LEN or HEADER_LEN < length <= HEADER_LEN + CRC32_LEN:
        return "impossible_length", f"LEN {length} is impossible (12, or 17 to {MAX_LEN})"
    return None


def header_fields(header: bytes) -> dict:
    """The header's fields as plain numbers, valid or not: what an error
    report shows about a frame whose value did not decode."""
    word = header[1] | header[2] << 8
    return {
        "len": word & 0x3FF, "ver": word >> 10,
        "session": header[3] & 0x1F, "is_ack": bool(header[3] >> 5 & 1), "res0": header[3] >> 6,
        "padding": header[4] & 0x1F, "enc": header[4] >> 5,
        "res1": int.from_bytes(header[5:8], "little"),
        "seq": header[8] | header[9] << 8, "crc16": header[10] | header[11] << 8,
    }


def frame_length(header: bytes) -> int:
    return (header[1] | header[2] << 8) & 0x3FF


class Deframer:
    """Incremental: feed() any chunks, then finish(). Offsets are absolute."""

    def __init__(self) -> None:
        self._buf = bytearray()
        self._base = 0  # absolute offset of _buf[0]
        self._garbage_start: int | None = None

    def feed(self, chunk: bytes) -> Iterator[Event]:
        self._buf += chunk
        yield from self._scan(final=False)

    def finish(self) -> Iterator[Event]:
        yield from self._scan(final=True)

    def needs(self) -> int:
        """How many more bytes the frame it waits for needs (0: it waits for
        none): what a sender pads with so that the next frame it sends is
        heard from its first byte."""
        buf = self._buf
        if not buf or buf[0] != SOF:
            return 0
        if len(buf) < HEADER_LEN:
            return HEADER_LEN - len(buf)
        return max(frame_length(bytes(buf[:HEADER_LEN])) - len(buf), 1)

    def _drop(self, n: int) -> None:
        del self._buf[:n]
        self._base += n

    def _flush_garbage(self) -> Iterator[Event]:
        if self._garbage_start is not None:
            yield Garbage(self._garbage_start, self._base - self._garbage_start)
            self._garbage_start = None

    def _scan(self, final: bool) -> Iterator[Event]:
        buf = self._buf
        while buf:
            if buf[0] != SOF:
                nxt = buf.find(SOF)
                n = len(buf) if nxt < 0 else nxt
                if self._garbage_start is None:
                    self._garbage_start = self._base
                self._drop(n)
                continue
            if self._garbage_start is not None:
                yield from self._flush_garbage()
            if len(buf) < HEADER_LEN:
                if not final:
                    break
                yield self._truncated()
                continue
            header = bytes(buf[:HEADER_LEN])
            problem = header_problem(header)
            if problem:
                yield Rejected(self._base, *problem)
                self._drop(1)
                continue
            length = frame_length(header)  # looked up at call time: a selftest mutant misreads LEN here
            if len(buf) < length:
                if not final:
                    break
                yield self._truncated(length)
                continue
            raw = bytes(buf[:length])
            if length > HEADER_LEN and crc32(raw) != 0:
                stored = int.from_bytes(raw[-4:], "little")
                yield Rejected(self._base, "bad_crc32",
                               f"CRC-32 is 0x{stored:08x}, expected 0x{crc32(raw[:-4]):08x}", length)
                self._drop(1)
                continue
            yield Frame(self._base, raw)
            self._drop(length)
        if final:
            yield from self._flush_garbage()

    def _truncated(self, length: int | None = None) -> Rejected:
        # At the end of the input a started frame can no longer complete.
        # Report it, then rescan after its start byte like any rejection, so
        # a shorter frame inside it is still found.
        have = len(self._buf)
        want = f"LEN {length}" if length else "a 12-byte header"
        event = Rejected(self._base, "truncated_frame", f"input ended after {have} byte(s) of {want}", have)
        self._drop(1)
        return event


def split_chunks(data: bytes, sizes: list[int]) -> list[bytes]:
    """`data` cut into reads of the given sizes; what they leave over is one last read."""
    out, pos = [], 0
    for size in sizes:
        out.append(data[pos:pos + size])
        pos += size
    if pos < len(data):
        out.append(data[pos:])
    return out


def deframe(chunks: Iterable[bytes]) -> Iterator[Event]:
    d = Deframer()
    for chunk in chunks:
        yield from d.feed(chunk)
    yield from d.finish()
