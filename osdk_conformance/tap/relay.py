"""The bytes between a host and a flight controller: forwarded, and heard.

A `Link` has two ends, the flight controller's and the host's. In relay
mode both are written: what one end sends goes to the other at once. In
passive mode the ends are the two RX-only taps of a Y-cable (one hears the
host's TX line, the other the FC's) and nothing is written anywhere.

One thread moves the bytes: it waits on both ends with select(), reads what
is there, writes it to the other end and only then hands (time, direction,
bytes) to a queue. A second thread takes them from the queue in order,
records them in the capture and feeds the analyzer: decoding and the disk
never delay a forwarded byte. What was read is kept even when the other end
cannot take it (a host that does not read its port): such bytes are
counted as not delivered, as a UART overrun would lose them.
"""
from __future__ import annotations

import errno
import os
import queue
import select
import sys
import threading
import time
from dataclasses import dataclass, field

import serial

from osdk_conformance.core.capture import RX, TX
from osdk_conformance.core.errors import UsageError, one_line
from osdk_conformance.device.port import HOST_STALL_S, LinkState
from osdk_conformance.sim.simulator import PtyTransport

READ_SIZE = 65536
POLL_S = 0.05          # how often the mover looks at its stop flag (a Ctrl-C ends it within this)
LATE_S = 2 * POLL_S    # a round of the mover this much longer than its poll: it was kept from running
MAX_BACKLOG = 8192     # bytes held for an end that does not take them; beyond that they are dropped
FC, HOST = "fc", "host"


class End:
    """One end: a file descriptor to select on, read and (in relay mode) write."""

    name: str
    label: str

    def fileno(self) -> int:
        raise NotImplementedError

    def read(self) -> bytes:
        try:
            return os.read(self.fileno(), READ_SIZE)
        except BlockingIOError:
            return b""

    def write(self, data: bytes) -> int:
        try:
            return os.write(self.fileno(), data)
        except BlockingIOError:
            return 0

    def close(self) -> None:
        raise NotImplementedError


class SerialEnd(End):
    """A serial port (a USB adapter, a UART, another program's pty) by pyserial."""

    def __init__(self, name: str, url: str, baud: int) -> None:
        self.name, self.label = name, url
        try:
            self.ser = serial.serial_for_url(url, baudrate=baud, timeout=0)
        except Exception as e:  # SerialException, ValueError (bad URL), OSError
            raise UsageError(f"cannot open port {url}: {one_line(e)}") from None
        if not hasattr(self.ser, "fd"):
            self.ser.close()
            raise UsageError(f"{url}: the tap needs a serial port or pseudo-terminal (a device path), "
                             "not a network URL")
        os.set_blocking(self.ser.fd, False)

    def fileno(self) -> int:
        return self.ser.fd

    def read(self) -> bytes:
        try:
            data = os.read(self.fileno(), READ_SIZE)
        except BlockingIOError:
            return b""
        if not data:   # end of file on a terminal: the device is gone (a USB adapter pulled)
            raise OSError(errno.ENODEV, "the device reports data and returns none (disconnected)")
        return data

    def close(self) -> None:
        try:
            self.ser.close()
        except Exception:
            pass


class PtyEnd(End):
    """A pseudo-terminal for the host to open, as `osdkc sim` offers one."""

    def __init__(self, name: str, link: str | None = None) -> None:
        try:
            self.pty = PtyTransport(link)
        except OSError as e:
            raise UsageError(f"cannot open a pseudo-terminal: {e.strerror or e}") from None
        self.name, self.label = name, self.pty.url

    def fileno(self) -> int:
        return self.pty.master

    def read(self) -> bytes:
        return self.pty.on_readable(self.pty.master)

    def write(self, data: bytes) -> int:
        return self.pty.write(data)

    def close(self) -> None:
        self.pty.close()


@dataclass
class Moved:
    """What crossed the tap in one direction."""

    chunks: int = 0
    bytes: int = 0
    undelivered: int = 0                                   # read, but the other end did not take them
    delays: list[float] = field(default_factory=list)      # s from read() returning to the bytes written


class Link:
    """Moves bytes between `fc` and `host` (relay) or only hears them
    (passive: `forward` False), feeding `sink` (its feed_rx: bytes from the
    FC, feed_tx: from the host; tap/judge.HostJudge) and `capture` from a
    thread of its own."""

    def __init__(self, fc: End, host: End, sink, capture=None, forward: bool = True) -> None:
        self.ends = {FC: fc, HOST: host}
        self.sink, self.cap, self.forward = sink, capture, forward
        self.state = LinkState()
        self.late: list[tuple[float, float]] = []   # (t, s) the mover was not scheduled for LATE_S or more
        self.moved = {FC: Moved(), HOST: Moved()}
        self.stop = threading.Event()
        self.errors: list[str] = []
        self._q: queue.SimpleQueue = queue.SimpleQueue()
        self._backlog = {FC: bytearray(), HOST: bytearray()}   # what waits to be written to that end
        self._mover = threading.Thread(target=self._move, name="osdkc-tap-mover", daemon=True)
        self._tee = threading.Thread(target=self._record, name="osdkc-tap-tee", daemon=True)

    def start(self) -> None:
        self.state.t_open = time.time()
        self._tee.start()
        self._mover.start()

    # ---- moving ------------------------------------------------------------------

    def _move(self) -> None:
        other = {FC: HOST, HOST: FC}
        by_fd = {end.fileno(): name for name, end in self.ends.items()}
        last = time.monotonic()
        while not self.stop.is_set():
            now = time.monotonic()
            if now - last > LATE_S:
                # not scheduled: what arrived meanwhile is read late, and its gaps are this machine's
                self.late.append((time.time() - (now - last), now - last))
                if now - last > HOST_STALL_S + POLL_S:   # long enough for a UART's buffers to overflow
                    self.state.host_stalls.append(self.late[-1])
            last = now
            wfds = [self.ends[n].fileno() for n, b in self._backlog.items() if b] if self.forward else []
            try:
                readable, writable, _ = select.select(list(by_fd), wfds, [], POLL_S)
            except (OSError, ValueError) as e:
                self._fail(f"select: {one_line(e)}")
                return
            for fd in writable:
                self._flush(by_fd[fd])
            for fd in readable:
                name = by_fd[fd]
                try:
                    data = self.ends[name].read()
                except OSError as e:
                    if e.errno in (errno.EIO, errno.ENXIO, errno.ENODEV):
                        whose = "flight controller's" if name == FC else "host's"
                        if name == FC:   # what the acceptance suite's link.connection reports
                            self.state.disconnects.append([time.time(), None, one_line(e)])
                        self._fail(f"the {whose} port {self.ends[name].label} went away: {one_line(e)}")
                        return
                    raise
                if not data:
                    continue
                ts = time.time_ns()
                if self.forward:
                    dest = other[name]
                    self._backlog[dest] += data
                    self._flush(dest)
                    self.moved[name].delays.append(time.time_ns() / 1e9 - ts / 1e9)
                m = self.moved[name]
                m.chunks += 1
                m.bytes += len(data)
                self._q.put((ts, name, data))
        self._q.put(None)

    def _flush(self, dest: str) -> None:
        buf = self._backlog[dest]
        try:
            n = self.ends[dest].write(bytes(buf))
        except OSError as e:
            n = 0
            self.errors.append(f"writing to the {dest} port: {one_line(e)}")
        del buf[:n]
        if len(buf) > MAX_BACKLOG:   # the end is not reading: the oldest bytes are lost, as on a UART
            source = FC if dest == HOST else HOST
            self.moved[source].undelivered += len(buf) - MAX_BACKLOG
            del buf[:len(buf) - MAX_BACKLOG]

    def _fail(self, why: str) -> None:
        self.errors.append(why)
        self.stop.set()
        self._q.put(None)

    # ---- hearing -------------------------------------------------------------------

    def _record(self) -> None:
        while True:
            item = self._q.get()
            if item is None:
                return
            ts, name, data = item
            direction = RX if name == FC else TX
            try:
                if self.cap:
                    self.cap.record(direction, data, ts)
                (self.sink.feed_rx if direction == RX else self.sink.feed_tx)(ts / 1e9, data)
            except Exception as e:   # a bug of ours must not stop the forwarding, nor lose the capture
                self.errors.append(f"analysing: {one_line(e)}")
                print(f"osdkc tap: internal error while analysing ({one_line(e)}); still forwarding and "
                      "recording", file=sys.stderr, flush=True)

    def close(self) -> None:
        """Stop moving, then record and analyse everything already read."""
        self.stop.set()
        if self._mover.ident is not None:
            self._mover.join(2.0)
        if self._tee.ident is not None:
            self._tee.join(10.0)
        self.state.t_end = time.time()
        for end in self.ends.values():
            end.close()

    @property
    def alive(self) -> bool:
        return self._mover.is_alive()
