"""A testee on a board: conformance/PROTOCOL.md's request lines from
standard input to the board's UART, the board's answer lines back.

`osdkc run --impl c-target` starts this with `--qemu`: the firmware of
conformance/testees/c-target in qemu-system-arm, its UART on a
pseudo-terminal opened through pyserial as a real board's would be.
`osdkc run --testee-port PORT --baud B` starts it with `--port`.

The board's own lines start with '#' and are never answers: `#start
BOARD` when it (re)starts, `#fault` when it faulted. A start or a fault
while a request waits, the board's port going away or QEMU ending, all end
this process with status 3 and a message on standard error: the runner
then reports the request as a crash of the testee and starts this bridge
again, as it does for a host testee that dies.
"""
from __future__ import annotations

import argparse
import os
import re
import select
import signal
import subprocess
import sys
import time
from pathlib import Path

import serial

from osdk_conformance.core.errors import one_line

QEMU = "qemu-system-arm"
MACHINE = "mps2-an386"
DEFAULT_BAUD = 115200
# Until the firmware has said `#start` (QEMU's start-up on a busy host included).
START_TIMEOUT_S = 30.0
PTY_LINE = re.compile(rb"char device redirected to (/dev/\S+) \(label serial0\)")
CRASH = 3


class BoardGone(Exception):
    """The board restarted, faulted or went away: this testee has crashed."""


def qemu_command(elf: Path, machine: str) -> list[str]:
    # -S and the monitor on stdin: the guest starts only once the pty is
    # open (QEMU drops what a guest writes to a pty nobody holds).
    # -no-reboot: a fault's reset ends QEMU, and with it this testee.
    # tb-size: TCG's translation cache, 1 GiB by default, would not fit the
    # runner's address-space limit.
    return [QEMU, "-machine", machine, "-display", "none", "-monitor", "stdio", "-serial", "pty",
            "-S", "-no-reboot", "-accel", "tcg,tb-size=32", "-kernel", str(elf)]


class Board:
    """The UART, line by line; a QEMU process behind it when emulated."""

    def __init__(self, ser: serial.Serial, qemu: subprocess.Popen | None = None) -> None:
        self.ser, self.qemu = ser, qemu
        self.buf = bytearray()

    @classmethod
    def emulated(cls, elf: Path, machine: str) -> "Board":
        if not elf.is_file():
            raise SystemExit(f"c-target: no firmware at {elf}; build it with "
                             f"`make -C conformance/testees/c-target` (docs/ON-TARGET.md)")
        try:
            qemu = subprocess.Popen(qemu_command(elf, machine), stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                    stderr=subprocess.STDOUT, bufsize=0)
        except OSError as e:
            raise SystemExit(f"c-target: cannot start {QEMU}: {e.strerror} (make setup installs it)") from None
        out = bytearray()
        deadline = time.monotonic() + START_TIMEOUT_S
        while not (m := PTY_LINE.search(out)):
            ready, _, _ = select.select([qemu.stdout], [], [], max(0.0, deadline - time.monotonic()))
            chunk = os.read(qemu.stdout.fileno(), 4096) if ready else b""
            if not chunk:
                qemu.kill()
                raise SystemExit(f"c-target: {QEMU} gave no serial port: {out.decode(errors='replace').strip()[-300:]}")
            out += chunk
        try:
            ser = serial.Serial(m[1].decode(), DEFAULT_BAUD, timeout=0)
        except serial.SerialException as e:
            qemu.kill()
            raise SystemExit(f"c-target: cannot open QEMU's serial port {m[1].decode()}: {one_line(e)}") from None
        board = cls(ser, qemu)
        qemu.stdin.write(b"cont\n")
        try:
            line = board.line(deadline)
        except BoardGone as e:
            board.close()   # the caller has no board to close yet
            raise SystemExit(f"c-target: the firmware did not start: {e}") from None
        if not line.startswith(b"#start"):
            board.close()
            raise SystemExit(f"c-target: the firmware did not start (first line {line[:80]!r})")
        return board

    @classmethod
    def on_port(cls, url: str, baud: int) -> "Board":
        try:
            ser = serial.serial_for_url(url, baudrate=baud, timeout=0)
        except (serial.SerialException, ValueError) as e:
            raise SystemExit(f"c-target: cannot open {url}: {one_line(e)}") from None
        board = cls(ser)
        # A line an earlier run left half-sent ends here, and whatever the
        # board answers to it is dropped with the rest of the input.
        ser.write(b"\n")
        time.sleep(0.3)
        ser.reset_input_buffer()
        return board

    def line(self, deadline: float | None = None) -> bytes:
        """The board's next line (without its newline)."""
        while (end := self.buf.find(b"\n")) < 0:
            if self.qemu is not None and self.qemu.poll() is not None:
                raise BoardGone(f"QEMU ended (exit {self.qemu.returncode})")
            wait = 0.2 if deadline is None else min(0.2, deadline - time.monotonic())
            if wait <= 0:
                raise BoardGone("the board said nothing in time")
            try:
                ready, _, _ = select.select([self.ser.fileno()], [], [], wait)
                if ready:
                    self.buf += self.ser.read(self.ser.in_waiting or 1)
            except (serial.SerialException, OSError) as e:
                raise BoardGone(f"the board's port went away: {one_line(e)}") from None
        line = bytes(self.buf[:end])
        del self.buf[:end + 1]
        return line

    def ask(self, request: bytes) -> bytes:
        """One request line out, its answer line back; the board's own lines reported."""
        try:
            self.ser.write(request + b"\n")
        except (serial.SerialException, OSError) as e:
            raise BoardGone(f"the board's port went away: {one_line(e)}") from None
        while True:
            line = self.line()
            # anywhere in the line: a reset can cut an answer short, and the
            # start line then follows the half of it that was sent
            if b"#start " in line:
                raise BoardGone("the board restarted while a request waited (a reset, or power lost)")
            if line.startswith(b"#fault"):
                raise BoardGone("the board faulted (a HardFault or bus fault) while a request waited")
            if line.startswith(b"#"):
                print(f"c-target: board: {line.decode(errors='replace')}", file=sys.stderr, flush=True)
                continue
            return line

    def close(self) -> None:
        try:
            self.ser.close()
        except Exception:
            pass
        if self.qemu is not None and self.qemu.poll() is None:
            self.qemu.kill()
            self.qemu.wait()


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m osdk_conformance.board.bridge",
                                 description="A testee on a board's UART (docs/ON-TARGET.md).")
    where = ap.add_mutually_exclusive_group(required=True)
    where.add_argument("--qemu", metavar="ELF", type=Path, help="run this firmware in qemu-system-arm")
    where.add_argument("--port", metavar="PORT", help="a board on this serial port (or pyserial URL)")
    ap.add_argument("--machine", default=MACHINE, help=f"QEMU's machine (default {MACHINE})")
    ap.add_argument("--baud", type=int, default=DEFAULT_BAUD, help=f"the port's rate (default {DEFAULT_BAUD})")
    args = ap.parse_args(argv)
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(128 + signal.SIGTERM))
    board = None
    try:
        board = Board.emulated(args.qemu, args.machine) if args.qemu else Board.on_port(args.port, args.baud)
        for request in sys.stdin.buffer:
            request = request.rstrip(b"\r\n")
            if not request.strip():
                continue
            sys.stdout.buffer.write(board.ask(request) + b"\n")
            sys.stdout.buffer.flush()
        return 0
    except BoardGone as e:
        print(f"c-target: {e}", file=sys.stderr, flush=True)
        return CRASH
    except KeyboardInterrupt:
        return 128 + signal.SIGINT
    except BrokenPipeError:
        return 0
    finally:
        if board is not None:
            board.close()


if __name__ == "__main__":
    sys.exit(main())
