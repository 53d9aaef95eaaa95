"""Finding frames in a byte stream as the SDK's receiver does
(conformance/PROTOCOL.md, decode_stream): hunt for the start byte, check
the 12-byte header (a bad one covers one byte), wait for LEN bytes, check
the CRC-32 (a bad one covers the frame, and the search goes on from the
byte after its start). The events do not depend on how the input is cut
into chunks; memory is one frame plus the chunk being fed."""
from __future__ import annotations

from dataclasses import dataclass

from . import crc
from ._tables import CRC32, CRC32_FIELD, CRC_CLASSES, HEADER_LEN, SOF
from .decode import header_error, header_fields


@dataclass(frozen=True)
class Event:
    """kind "frame" (raw: the frame's bytes, for decode_frame), "error"
    (error_class, detail: bytes the receiver dropped) or "garbage" (bytes
    before a start byte). offset is absolute in the stream, length the
    bytes the event covers (later events may start inside a bad_crc32's)."""

    kind: str
    offset: int
    length: int
    raw: bytes = b""
    error_class: str | None = None
    detail: str = ""


class Deframer:
    """feed(chunk) -> events so far, finish() -> the rest at the end of the input."""

    def __init__(self) -> None:
        self._buf = bytearray()
        self._base = 0  # stream offset of _buf[0]
        self._garbage_start: int | None = None

    def feed(self, chunk: bytes) -> list[Event]:
        self._buf += chunk
        return self._scan(final=False)

    def finish(self) -> list[Event]:
        return self._scan(final=True)

    def _drop(self, n: int) -> None:
        del self._buf[:n]
        self._base += n

    def _scan(self, final: bool) -> list[Event]:
        out: list[Event] = []
        buf = self._buf
        while buf:
            if buf[0] != SOF:
                nxt = buf.find(SOF)
                if self._garbage_start is None:
                    self._garbage_start = self._base
                self._drop(len(buf) if nxt < 0 else nxt)
                continue
            self._flush_garbage(out)
            if len(buf) < HEADER_LEN:
                if not final:
                    break
                out.append(self._truncated("a header"))
                continue
            header = bytes(buf[:HEADER_LEN])
            problem = header_error(header)
            if problem:
                out.append(Event("error", self._base, 1, error_class=problem.error_class, detail=problem.detail))
                self._drop(1)
                continue
            length = header_fields(header)["len"]
            if len(buf) < length:
                if not final:
                    break
                out.append(self._truncated(f"LEN {length}"))
                continue
            raw = bytes(buf[:length])
            if length > HEADER_LEN:
                have, want = crc.stored(raw, CRC32), crc.computed(raw, CRC32)
                if have != want:
                    out.append(Event("error", self._base, length, error_class=CRC_CLASSES[CRC32_FIELD],
                                     detail=f"CRC-32 is 0x{have:08x}, expected 0x{want:08x}"))
                    self._drop(1)
                    continue
            out.append(Event("frame", self._base, length, raw=raw))
            self._drop(length)
        if final:
            self._flush_garbage(out)
        return out

    def _flush_garbage(self, out: list[Event]) -> None:
        if self._garbage_start is not None:
            out.append(Event("garbage", self._garbage_start, self._base - self._garbage_start))
            self._garbage_start = None

    def _truncated(self, want: str) -> Event:
        # the input ended inside a frame: report it, then search on after its
        # start byte, so a shorter frame inside it is still found
        have = len(self._buf)
        event = Event("error", self._base, have, error_class="truncated_frame",
                      detail=f"input ended after {have} byte(s) of {want}")
        self._drop(1)
        return event
