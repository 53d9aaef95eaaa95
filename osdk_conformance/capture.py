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
                         for rx, 2 outbound for tx).

Every block is written whole and flushed at once; the file is fsynced at
most `fsync_interval` seconds apart and on close. A process killed at any
moment leaves complete blocks followed by at most one partial block, and
`read_capture` reads every complete block and reports the partial one.
Wireshark opens the file (the payload shows as "User 0" data; a dissector is
not needed to see the bytes and their times).
"""
from __future__ import annotations

import json
import os
import struct
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Iterator

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

    def record(self, direction: int, data: bytes, ts_ns: int | None = None) -> None:
        if not data:
            return
        ts = time.time_ns() if ts_ns is None else ts_ns
        body = struct.pack("<IIIII", direction, ts >> 32, ts & 0xFFFFFFFF, len(data), len(data))
        body += data + bytes((-len(data)) % 4)
        body += _options(_option(2, struct.pack("<I", DIRECTION_FLAGS[direction])))
        with self._lock:
            if self._fh.closed:
                return
            self._write(_block(EPB_TYPE, body))
            self.records += 1

    def rx(self, data: bytes, ts_ns: int | None = None) -> None:
        self.record(RX, data, ts_ns)

    def tx(self, data: bytes, ts_ns: int | None = None) -> None:
        self.record(TX, data, ts_ns)

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

    @property
    def t(self) -> float:
        return self.ts_ns / 1e9


@dataclass
class Capture:
    comment: dict = field(default_factory=dict)
    records: list[Record] = field(default_factory=list)
    partial_tail: int = 0          # bytes of an incomplete last block (a killed writer)
    interfaces: list[dict] = field(default_factory=list)

    def received(self) -> Iterator[bytes]:
        for r in self.records:
            if r.direction == RX:
                yield r.data


class CaptureError(ValueError):
    pass


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


def read_capture(path: str | Path) -> Capture:
    """Every complete block of a capture this module wrote (any single-section
    pcapng with EPBs on byte-stream interfaces reads the same way)."""
    return parse_capture(Path(path).read_bytes(), str(path))


def parse_capture(data: bytes, path: str = "capture") -> Capture:
    """`read_capture` over bytes already read."""
    if not is_pcapng(data):
        raise CaptureError(f"{path}: not a pcapng file (no Section Header Block)")
    cap = Capture()
    pos, e = 0, "<"
    tsres: list[int] = []
    while pos < len(data):
        if pos + 12 > len(data):
            cap.partial_tail = len(data) - pos
            break
        if data[pos:pos + 4] == SHB_MAGIC_BYTES:
            magic = data[pos + 8:pos + 12]
            e = "<" if magic == struct.pack("<I", BYTE_ORDER_MAGIC) else ">"
            if magic not in (struct.pack("<I", BYTE_ORDER_MAGIC), struct.pack(">I", BYTE_ORDER_MAGIC)):
                raise CaptureError(f"{path}: bad byte-order magic at offset {pos}")
        btype, total = struct.unpack_from(e + "II", data, pos)
        if total < 12 or total % 4:
            raise CaptureError(f"{path}: bad block length {total} at offset {pos}")
        if pos + total > len(data):
            cap.partial_tail = len(data) - pos
            break
        body = data[pos + 8:pos + total - 4]
        if btype == SHB_TYPE:
            opts = _parse_options(body[16:], e)
            if 1 in opts:
                try:
                    cap.comment = json.loads(opts[1].decode())
                except (ValueError, UnicodeDecodeError):
                    cap.comment = {"text": opts[1].decode("utf-8", "replace")}
        elif btype == IDB_TYPE:
            linktype = struct.unpack_from(e + "H", body, 0)[0]
            opts = _parse_options(body[8:], e)
            res = opts.get(9, bytes([6]))[0]
            tsres.append(10 ** (res & 0x7F) if not res & 0x80 else 2 ** (res & 0x7F))
            cap.interfaces.append({"linktype": linktype, "name": opts.get(2, b"").decode("utf-8", "replace")})
        elif btype == EPB_TYPE:
            iface, hi, lo, caplen, _orig = struct.unpack_from(e + "IIIII", body, 0)
            payload = body[20:20 + caplen]
            units = hi << 32 | lo
            per_s = tsres[iface] if iface < len(tsres) else 1_000_000
            ts_ns = units * 1_000_000_000 // per_s
            opts = _parse_options(body[20 + caplen + (-caplen) % 4:], e)
            direction = iface
            if 2 in opts and len(opts[2]) == 4:
                flags = struct.unpack(e + "I", opts[2])[0] & 3
                direction = {1: RX, 2: TX}.get(flags, iface)
            cap.records.append(Record(ts_ns, direction, payload))
        pos += total
    return cap


def default_capture_path(root: str | Path = "captures") -> Path:
    stamp = time.strftime("%Y%m%d-%H%M%S")
    return Path(root) / f"device-{stamp}-{os.getpid()}.pcapng"
