"""A Y-cable stand-in for the passive tap: `python -m
osdk_conformance.bench.ycable FC_PORT BAUD` opens the flight controller's port,
makes a port for the host and two RX-only ports (one hears the host's TX
line, one the flight controller's), prints them as one JSON line and moves
bytes until its stdin closes (exit 0) or it gets SIGINT or SIGTERM (130,
143); then it prints how many bytes each port did not take in time (a line
does not wait).

A real Y-cable is copper and two USB adapters: it never stalls the line
between host and flight controller, whatever the tap's machine does. So the
stand-in is a process of its own, which the bench and the tests raise above
their busy loops as they raise the simulator (bench/stand_in.favour); a
thread inside a busy test process let the simulator's writes block, and the
tap rightly saw a flight controller that broadcast slowly."""
from __future__ import annotations

import json
import os
import select
import signal
import subprocess
import sys
import tty

import serial

from osdk_conformance.bench.stand_in import favour


def raw_pty() -> tuple[int, int, str]:
    master, slave = os.openpty()
    tty.setraw(slave)
    return master, slave, os.ttyname(slave)


def _offer(fd: int, data: bytes) -> int:
    """Write what the port takes now and return how many bytes it did not:
    a line does not wait for a reader, what nobody takes in time is lost."""
    try:
        return len(data) - os.write(fd, data)
    except OSError:   # BlockingIOError (full), or nobody holds that port yet
        return len(data)


def run(fc_path: str, baud: int) -> int:
    stopped = []
    for sig in (signal.SIGINT, signal.SIGTERM):
        signal.signal(sig, lambda s, _f: stopped.append(s))
    port = serial.Serial(fc_path, baud, timeout=0)   # the cable's end at the flight controller's rate
    fc = port.fileno()
    host, host_slave, host_path = raw_pty()
    taps = {line: raw_pty() for line in ("host_tx", "fc_tx")}
    # where what is read from each end goes: the other end, then the RX-only port of that line
    routes = {fc: (host, taps["fc_tx"][0]), host: (fc, taps["host_tx"][0])}
    names = {fc: "flight controller", host: "host", taps["fc_tx"][0]: "fc_tx tap", taps["host_tx"][0]: "host_tx tap"}
    lost = dict.fromkeys(names.values(), 0)
    for fd in names:
        os.set_blocking(fd, False)
    print(json.dumps({"host": host_path, "host_tx": taps["host_tx"][2], "fc_tx": taps["fc_tx"][2]}), flush=True)
    stdin = sys.stdin.fileno()
    while not stopped:
        try:
            ready, _, _ = select.select([fc, host, stdin], [], [], 0.2)
        except InterruptedError:
            continue
        for fd in ready:
            try:
                data = os.read(fd, 65536)
            except OSError:   # a side not open yet (EIO on a pty nobody holds): nothing crossed
                continue
            if fd == stdin:
                if not data:
                    stopped.append("EOF")
                continue
            for to in routes[fd]:
                lost[names[to]] += _offer(to, data)
    # what each port did not take, for the caller to tell a lossy run from a clean one
    print(json.dumps({"lost bytes": lost}), flush=True)
    # stdin closed is the caller's usual stop; a signal gives 128 + its number, as every osdkc command does
    return 128 + stopped[0] if isinstance(stopped[0], int) else 0


def spawn(fc_path: str, baud: int) -> tuple[subprocess.Popen, dict]:
    """The stand-in on `fc_path`, raised where this user may, and its ports
    {"host", "host_tx", "fc_tx"}. Close its stdin (or terminate it) to stop it."""
    proc = subprocess.Popen([sys.executable, "-m", "osdk_conformance.bench.ycable", fc_path, str(baud)],
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    favour(proc.pid)
    line = proc.stdout.readline()
    if not line:
        proc.wait()
        raise RuntimeError(f"the Y-cable stand-in did not start: {proc.stderr.read().strip()}")
    return proc, json.loads(line)


def stop(proc: subprocess.Popen) -> dict:
    """Stop the stand-in; how many bytes each port did not take ({} if it said nothing)."""
    try:
        out = proc.communicate(timeout=5)[0]   # closes its stdin first: the stand-in's cue
    except (OSError, subprocess.TimeoutExpired):
        proc.kill()
        proc.wait()
        return {}
    try:
        return json.loads(out.strip().splitlines()[-1])["lost bytes"]
    except (ValueError, IndexError, KeyError):
        return {}


if __name__ == "__main__":
    if len(sys.argv) != 3 or not sys.argv[2].isdigit():
        print("usage: python -m osdk_conformance.bench.ycable FC_PORT BAUD", file=sys.stderr)
        sys.exit(2)
    try:
        sys.exit(run(sys.argv[1], int(sys.argv[2])))
    except (OSError, serial.SerialException) as e:
        print(f"ycable: {sys.argv[1]}: {e.strerror or e}", file=sys.stderr)
        sys.exit(1)
