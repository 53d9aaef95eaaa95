"""The serial port of a live acceptance run: a reader thread that feeds the
analyzer and the capture, reopening after the device goes away, and a
writer that records before it sends."""
from __future__ import annotations

import contextlib
import threading
import time
from dataclasses import dataclass, field

import serial

from osdk_conformance.core.errors import UsageError, one_line



# A reader loop that came round this much later than its read timeout was not
# scheduled: bytes may have piled up, and been lost, in buffers on this host.
HOST_STALL_S = 0.5
WRITE_TIMEOUT_S = 1.0


@dataclass
class LinkState:
    t_open: float = 0.0
    t_end: float = 0.0
    disconnects: list = field(default_factory=list)   # [t_lost, t_back or None, why]
    host_stalls: list = field(default_factory=list)   # (t, seconds) the reader was not scheduled


class PortDown(Exception):
    pass


class Port:
    """The serial port, a reader thread that feeds the analyzer and the
    capture, reopening after the device goes away, and a writer."""

    def __init__(self, url: str, baud: int, analyzer, capture=None) -> None:
        self.url, self.baud, self.an, self.cap = url, baud, analyzer, capture
        self.state = LinkState()
        self.ser = None
        self.failed = None   # the serial object a write last failed on (the reader replaces it when it reopens)
        self.stop = threading.Event()
        self.wlock = threading.Lock()
        self.thread: threading.Thread | None = None
        # a section no signal exception may interrupt (Interrupts.critical in a live run)
        self.critical = contextlib.nullcontext

    def _open(self):
        return serial.serial_for_url(self.url, baudrate=self.baud, timeout=0.05, write_timeout=WRITE_TIMEOUT_S)

    def open(self, start: bool = True) -> None:
        """Open the port and (unless `start` is False) start reading."""
        try:
            self.ser = self._open()
        except Exception as e:  # SerialException, ValueError (bad URL), OSError
            raise UsageError(f"cannot open port {self.url}: {one_line(e)}") from None
        if start:
            self.start(self.cap)

    def start(self, capture) -> None:
        """Attach the capture, then start reading: the capture holds every byte the analyzer counts."""
        with self.critical():   # a signal here leaves either no reader or a started one
            self.cap = capture
            self.state.t_open = time.time()
            self.thread = threading.Thread(target=self._reader, name="osdkc-reader", daemon=True)
            self.thread.start()

    def _reader(self) -> None:
        last = time.monotonic()
        while not self.stop.is_set():
            now = time.monotonic()
            if now - last > HOST_STALL_S:
                self.state.host_stalls.append((time.time() - (now - last), now - last))
            last = now
            ser = self.ser
            if ser is None:
                try:
                    ser = self._open()
                except Exception:
                    self.stop.wait(0.25)
                    last = time.monotonic()   # a wait of its own, not a stall
                    continue
                self.ser = ser
                self.state.disconnects[-1][1] = time.time()
            try:
                waiting = ser.in_waiting
                data = ser.read(min(65536, waiting) if waiting else 1)
            except Exception as e:
                t = time.time()
                self.state.disconnects.append([t, None, one_line(e)])
                with self.wlock:
                    try:
                        ser.close()
                    except Exception:
                        pass
                    self.ser = None
                continue
            if data:
                ts = time.time_ns()
                if self.cap:
                    self.cap.rx(data, ts)
                self.an.feed_rx(ts / 1e9, data)

    def write(self, data: bytes, comment: str | None = None) -> None:
        """Record and register the bytes, then send them. In that order: an ACK
        that comes back at once finds its command (else it is dropped and the
        command sent again), and the capture keeps the order the device saw.
        Bytes a failing write may have sent in part stay recorded. `comment`
        goes into the capture with them (a fuzz case's id)."""
        with self.critical(), self.wlock:
            if self.ser is None:
                raise PortDown("the port is down")
            ts = time.time_ns()
            if self.cap:
                self.cap.tx(data, ts, comment)
            self.an.feed_tx(ts / 1e9, data)
            t0 = time.monotonic()
            try:
                self.ser.write(data)
            except Exception as e:
                late = time.monotonic() - t0 - WRITE_TIMEOUT_S
                if isinstance(e, serial.SerialTimeoutException) and late > HOST_STALL_S:
                    # pyserial writes, then finds its deadline gone: this process was not scheduled for longer
                    # than the time-out, and the bytes went out meanwhile. A stall of this host, not of the port.
                    self.state.host_stalls.append((time.time() - (time.monotonic() - t0), late))
                    return
                if not isinstance(e, serial.SerialTimeoutException):   # a slow reader is not a lost port
                    self.failed = self.ser
                raise PortDown(one_line(e)) from None

    def wait_back(self, timeout: float) -> bool:
        """Wait up to `timeout` s for a port to write to: one the reader has
        (re)opened, not the one a write last failed on (the reader may not
        have noticed that loss yet). True when there is one."""
        end = time.monotonic() + timeout
        while True:
            ser = self.ser
            if ser is not None and ser is not self.failed:
                return True
            if time.monotonic() >= end or self.stop.is_set():
                return False
            time.sleep(0.05)

    def close(self) -> None:
        self.stop.set()
        if self.thread and self.thread.ident is not None:
            self.thread.join(2.0)
        self.state.t_end = time.time()
        with self.wlock:
            if self.ser is not None:
                try:
                    self.ser.close()
                except Exception:
                    pass


