"""Captures of a serial session in pcapng, written so that a crash loses nothing.

File layout (pcapng, little-endian, one section):
  Section Header Block   shb_userappl "osdkc", opt_comment = JSON with what the
                         run was (profile, port, baud, started)
  Interface Description  interface 0 "rx": bytes the host received from the
  Blocks (two)           flight controller; interface 1 "tx": bytes the host
                         sent. LINKTYPE_USER0 (147), nanosecond time stamps
                         (if_tsresol 9).
  Enhanced Packet Blocks one per read() or write(): the bytes exactly as they
                         crossed the port, with epb_flags direction (1 inbound
                         for rx, 2 outbound for tx) and, where the writer
                         says what the bytes were (`osdkc fuzz --port`: the
                         case id), an opt_comment.

Every block is written whole and flushed at once; the file is fsynced at
most `fsync_interval` seconds apart and on close. A process killed at any
moment leaves complete blocks followed by at most one partial block, and
`CaptureReader` reads every complete block and reports the partial one.
Wireshark opens the file (the payload shows as "User 0" data; a dissector is
not needed to see the bytes and their times).
"""
from __future__ import annotations

import json
import os
import struct
import threading
import time
from contextlib import contextmanager
from dataclasses import dataclass, field
from functools import partial
from pathlib import Path
from typing import Iterable, Iterator

SHB_TYPE = 0x0A0D0D0A
IDB_TYPE = 0x00000001
EPB_TYPE = 0x00000006
BYTE_ORDER_MAGIC = 0x1A2B3C4D
LINKTYPE_USER0 = 147
SHB_MAGIC_BYTES = struct.pack("<I", SHB_TYPE)  # the same 4 bytes in either byte order

RX, TX = 0, 1
DIRECTION_FLAGS = {RX: 1, TX: 2}  # epb_flags bits 0-1: 01 inbound, 10 outbound
NAMES = {RX: "rx", TX: "tx"}


def _option(code: int, value: bytes) -> bytes:
    pad = (-len(value)) % 4
    return struct.pack("<HH", code, len(value)) + value + bytes(pad)


def _options(*opts: bytes) -> bytes:
    return b"".join(opts) + struct.pack("<HH", 0, 0) if opts else b""


def _block(btype: int, body: bytes) -> bytes:
    total = 12 + len(body)
    return struct.pack("<II", btype, total) + body + struct.pack("<I", total)


def is_pcapng(head: bytes) -> bool:
    """True when `head` (the first bytes of a file) starts a pcapng section."""
    return len(head) >= 4 and head[:4] == SHB_MAGIC_BYTES


class CaptureWriter:
    """Appends rx/tx records to a pcapng file; thread-safe."""

    def __init__(self, path: str | Path, comment: dict | None = None, fsync_interval: float = 0.2) -> None:
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._fh = open(self.path, "wb", buffering=0)
        self._lock = threading.Lock()
        self._fsync_interval = fsync_interval
        self._last_sync = 0.0
        self.records = 0
        shb_opts = [_option(4, b"osdkc")]
        if comment:
            shb_opts.insert(0, _option(1, json.dumps(comment, sort_keys=True).encode()))
        shb = struct.pack("<IHHq", BYTE_ORDER_MAGIC, 1, 0, -1) + _options(*shb_opts)
        out = _block(SHB_TYPE, shb)
        for iface in (RX, TX):
            desc = ("bytes received from the flight controller" if iface == RX
                    else "bytes sent to the flight controller")
            body = struct.pack("<HHI", LINKTYPE_USER0, 0, 0) + _options(
                _option(2, NAMES[iface].encode()), _option(3, desc.encode()), _option(9, bytes([9])))
            out += _block(IDB_TYPE, body)
        self._write(out, force_sync=True)

    def _write(self, data: bytes, force_sync: bool = False) -> None:
        self._fh.write(data)  # unbuffered: one write() per whole block
        now = time.monotonic()
        if force_sync or now - self._last_sync >= self._fsync_interval:
            os.fsync(self._fh.fileno())
            self._last_sync = now

    def record(self, direction: int, data: bytes, ts_ns: int | None = None, comment: str | None = None) -> None:
        if not data:
            return
        ts = time.time_ns() if ts_ns is None else ts_ns
        body = struct.pack("<IIIII", direction, ts >> 32, ts & 0xFFFFFFFF, len(data), len(data))
        body += data + bytes((-len(data)) % 4)
        opts = [_option(2, struct.pack("<I", DIRECTION_FLAGS[direction]))]
        if comment:
            opts.insert(0, _option(1, comment.encode()))
        body += _options(*opts)
        with self._lock:
            if self._fh.closed:
                return
            self._write(_block(EPB_TYPE, body))
            self.records += 1

    def rx(self, data: bytes, ts_ns: int | None = None) -> None:
        self.record(RX, data, ts_ns)

    def tx(self, data: bytes, ts_ns: int | None = None, comment: str | None = None) -> None:
        self.record(TX, data, ts_ns, comment)

    def close(self) -> None:
        with self._lock:
            if not self._fh.closed:
                os.fsync(self._fh.fileno())
                self._fh.close()


@dataclass
class Record:
    ts_ns: int
    direction: int   # RX or TX
    data: bytes
    comment: str = ""   # the block's opt_comment, when it has one

    @property
    def t(self) -> float:
        return self.ts_ns / 1e9


@dataclass
class Capture:
    """A whole capture in memory (small captures, tests); CaptureReader streams."""
    comment: dict = field(default_factory=dict)
    records: list[Record] = field(default_factory=list)
    partial_tail: int = 0          # bytes of an incomplete last block (a killed writer)
    interfaces: list[dict] = field(default_factory=list)


class CaptureError(ValueError):
    pass


READ_SIZE = 64 * 1024
# The longest block accepted. The writer's blocks hold one read() of at most
# 64 KiB; a length beyond this is corruption, and reading it whole would make
# memory depend on a damaged length field.
MAX_BLOCK_LENGTH = 16 << 20
# Standard block types (pcapng, IETF draft, section 11.1) that carry nothing
# a capture of a serial link needs: skipped. Any other type is corruption.
SKIPPED_BLOCK_TYPES = frozenset({0x2, 0x3, 0x4, 0x5, 0x7, 0x8, 0x9, 0xA, 0xBAD, 0x40000BAD})
MIN_BLOCK_LENGTH = {SHB_TYPE: 28, IDB_TYPE: 20, EPB_TYPE: 32}  # 12 + the fixed fields of each


def _parse_options(buf: bytes, e: str) -> dict[int, bytes]:
    out: dict[int, bytes] = {}
    pos = 0
    while pos + 4 <= len(buf):
        code, length = struct.unpack_from(e + "HH", buf, pos)
        pos += 4
        if code == 0:
            break
        out.setdefault(code, buf[pos:pos + length])
        pos += length + (-length) % 4
    return out


class CaptureReader:
    """The records of a pcapng capture, read block by block from `chunks`
    (the file's bytes in pieces of any size), so memory stays bounded by the
    longest block whatever the file's size. Block lengths, types and
    interface ids are checked; damage raises CaptureError naming the file and
    the byte offset of the block. A capture that ends inside a block (its
    writer was killed) ends the iteration, with `partial_tail` bytes left
    over. `comment` and `interfaces` fill in as their blocks are read;
    `count` is the number of records read."""

    def __init__(self, chunks: Iterable[bytes], name: str = "capture") -> None:
        self.name = name
        self.comment: dict = {}
        self.interfaces: list[dict] = []
        self.partial_tail = 0
        self.count = 0
        self._chunks = iter(chunks)
        self._buf = b""
        self._pos = 0        # the next unread byte in _buf
        self._offset = 0     # file offset of _buf[0]
        self._order = "<"
        self._per_s: list[int] = []  # time stamp units per second, by interface id

    def _fill(self, n: int) -> bool:
        """At least n unread bytes in the buffer; False when the input ends first."""
        have = len(self._buf) - self._pos
        if have >= n:
            return True
        parts = [self._buf[self._pos:]]
        while have < n:
            chunk = next(self._chunks, None)
            if chunk is None:
                break
            parts.append(chunk)
            have += len(chunk)
        self._offset += self._pos
        self._buf, self._pos = b"".join(parts), 0
        return have >= n

    def _error(self, offset: int, what: str) -> CaptureError:
        return CaptureError(f"{self.name}: damaged capture at offset {offset}: {what}")

    def __iter__(self) -> Iterator[Record]:
        while True:
            offset = self._offset + self._pos
            if not self._fill(12):
                self.partial_tail = len(self._buf) - self._pos
                if offset == 0 and not is_pcapng(self._buf):
                    raise CaptureError(f"{self.name}: not a pcapng file (no Section Header Block)")
                return
            btype, total = self._header(offset)
            if not self._fill(total):
                self.partial_tail = len(self._buf) - self._pos
                return
            block = self._buf[self._pos:self._pos + total]
            self._pos += total
            trailer = struct.unpack_from(self._order + "I", block, total - 4)[0]
            if trailer != total:
                raise self._error(offset, f"block length {total} does not match its trailing copy {trailer}")
            record = self._block(btype, block[8:-4], offset)
            if record is not None:
                self.count += 1
                yield record

    def _header(self, offset: int) -> tuple[int, int]:
        head = self._buf[self._pos:self._pos + 12]
        if head[:4] == SHB_MAGIC_BYTES:
            magic = head[8:12]
            if magic == struct.pack("<I", BYTE_ORDER_MAGIC):
                self._order = "<"
            elif magic == struct.pack(">I", BYTE_ORDER_MAGIC):
                self._order = ">"
            else:
                raise self._error(offset, "bad byte-order magic")
        elif offset == 0:
            raise CaptureError(f"{self.name}: not a pcapng file (no Section Header Block)")
        btype, total = struct.unpack_from(self._order + "II", head)
        if btype not in MIN_BLOCK_LENGTH and btype not in SKIPPED_BLOCK_TYPES and not btype & 0x80000000:
            raise self._error(offset, f"unknown block type 0x{btype:08x}")
        if total % 4 or not MIN_BLOCK_LENGTH.get(btype, 12) <= total <= MAX_BLOCK_LENGTH:
            raise self._error(offset, f"bad block length {total} for block type 0x{btype:08x}")
        return btype, total

    def _block(self, btype: int, body: bytes, offset: int) -> Record | None:
        e = self._order
        if btype == SHB_TYPE:
            self.interfaces, self._per_s = [], []  # interface ids count from 0 in each section
            opts = _parse_options(body[16:], e)
            if 1 in opts:
                try:
                    self.comment = json.loads(opts[1].decode())
                except (ValueError, UnicodeDecodeError):
                    self.comment = {"text": opts[1].decode("utf-8", "replace")}
        elif btype == IDB_TYPE:
            linktype = struct.unpack_from(e + "H", body, 0)[0]
            opts = _parse_options(body[8:], e)
            res = (opts.get(9) or bytes([6]))[0]  # microseconds unless said otherwise
            self._per_s.append(10 ** (res & 0x7F) if not res & 0x80 else 2 ** (res & 0x7F))
            self.interfaces.append({"linktype": linktype, "name": opts.get(2, b"").decode("utf-8", "replace")})
        elif btype == EPB_TYPE:
            return self._packet(body, offset)
        return None

    def _packet(self, body: bytes, offset: int) -> Record:
        e = self._order
        iface, hi, lo, caplen, _orig = struct.unpack_from(e + "IIIII", body, 0)
        if iface >= len(self._per_s):
            raise self._error(offset, f"packet of interface {iface}, but the section describes {len(self._per_s)}")
        if 20 + caplen > len(body):
            raise self._error(offset, f"packet of {caplen} bytes in a block of {len(body) + 12}")
        ts_ns = (hi << 32 | lo) * 1_000_000_000 // self._per_s[iface]
        opts = _parse_options(body[20 + caplen + (-caplen) % 4:], e)
        direction = iface
        if 2 in opts and len(opts[2]) == 4:
            flags = struct.unpack(e + "I", opts[2])[0] & 3
            direction = {1: RX, 2: TX}.get(flags, iface)
        comment = opts[1].decode("utf-8", "replace") if 1 in opts else ""
        return Record(ts_ns, direction, body[20:20 + caplen], comment)


@contextmanager
def open_capture(path: str | Path) -> Iterator[CaptureReader]:
    """A CaptureReader over a file (OSError when it cannot be opened)."""
    with open(path, "rb") as fh:
        yield CaptureReader(iter(partial(fh.read, READ_SIZE), b""), str(path))


def read_capture(path: str | Path) -> Capture:
    """Every complete block of a capture this module wrote (any single-section
    pcapng with EPBs on byte-stream interfaces reads the same way), in memory."""
    with open_capture(path) as reader:
        records = list(reader)
    return Capture(reader.comment, records, reader.partial_tail, reader.interfaces)


def default_capture_path(root: str | Path = "captures", tool: str = "device") -> Path:
    stamp = time.strftime("%Y%m%d-%H%M%S")
    return Path(root) / f"{tool}-{stamp}-{os.getpid()}.pcapng"
