"""Bytes as they arrive, for `osdkc decode --port/--follow` and `osdkc watch`:
a serial port read until stopped, or a capture file followed as it grows
(`tail -f` for `osdkc device --capture`, raw or pcapng).

`port_pieces(url, baud, stop)` yields (bytes, capture time ns) read from
the port, reopening it when it goes away (a USB adapter pulled out and put
back); `follow_pieces(path, stop)` yields (bytes, time ns) of a growing
file: the pcapng records' own times, or for raw bytes the time they were
read. Both end when `stop` is set, within POLL_S.
"""
from __future__ import annotations

import threading
import time
from typing import Iterator

import serial

from osdk_conformance.core.errors import UsageError, cannot_read, one_line
from osdk_conformance.reference.decode import timed_pieces

DEFAULT_BAUD = 230400   # osdkc device's default too
POLL_S = 0.1        # how often a quiet port or file is looked at again
READ_MAX = 65536


def open_port(url: str, baud: int):
    """The serial port (a path or a pyserial URL), open; UsageError when it cannot be."""
    try:
        return serial.serial_for_url(url, baudrate=baud, timeout=POLL_S)
    except Exception as e:  # SerialException, ValueError (a bad URL), OSError
        raise UsageError(f"cannot open port {url}: {one_line(e)}") from None


def port_pieces(ser, url: str, baud: int, stop: threading.Event, status: dict | None = None) -> Iterator[tuple[bytes, int]]:
    """Bytes from an open port with the time they were read. A lost port is
    reopened; `status["port"]` says which state it is in."""
    status = status if status is not None else {}
    status["port"] = "open"
    try:
        while not stop.is_set():
            if ser is None:
                try:
                    ser = serial.serial_for_url(url, baudrate=baud, timeout=POLL_S)
                    status["port"] = "open"
                except Exception:
                    stop.wait(0.25)
                    continue
            try:
                waiting = ser.in_waiting
                data = ser.read(min(READ_MAX, waiting) if waiting else 1)
            except Exception as e:
                status["port"] = f"lost ({one_line(e)}), reopening"
                try:
                    ser.close()
                except Exception:
                    pass
                ser = None
                continue
            if data:
                yield data, time.time_ns()
    finally:
        if ser is not None:
            ser.close()


def _growing(fh, stop: threading.Event) -> Iterator[bytes]:
    while not stop.is_set():
        data = fh.read(READ_MAX)
        if data:
            yield data
        else:
            stop.wait(POLL_S)


def follow_pieces(path: str, stop: threading.Event) -> Iterator[tuple[bytes, int]]:
    """The received bytes of a file that is still being written, from its
    start: read as `osdkc decode` reads a file (reference/decode.py,
    timed_pieces), its end only where `stop` is set."""
    try:
        fh = open(path, "rb")
    except OSError as e:
        raise UsageError(cannot_read(path, e)) from None
    with fh:
        for _, data, ts_ns in timed_pieces(_magic_first(_growing(fh, stop)), frozenset({"rx"}), path):
            yield data, time.time_ns() if ts_ns is None else ts_ns


def _magic_first(chunks: Iterator[bytes]) -> Iterator[bytes]:
    # a capture just created may not hold its 4-byte magic yet: hold the start back until it does
    first = b""
    for chunk in chunks:
        first += chunk
        if len(first) >= 4:
            break
    if first:
        yield first
    yield from chunks
