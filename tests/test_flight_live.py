"""Flight data as it arrives: `osdkc watch` in a real pseudo-terminal against
a simulated flight controller, quitting on q, Ctrl-C and SIGTERM; `osdkc
decode --port` and `--follow`; `osdkc watch --capture` on a growing file;
and what they say to arguments they cannot use."""
from __future__ import annotations

import fcntl
import json
import os
import pty
import re
import select
import signal
import struct
import subprocess
import termios
import sys
import threading
import time
from pathlib import Path

import pytest

from osdk_conformance import api
from osdk_conformance.core.capture import CaptureWriter

pytestmark = pytest.mark.realtime

ROOT = Path(__file__).resolve().parents[1]
A3 = "a3-fw3.1"
OSDKC = [sys.executable, "-m", "osdk_conformance"]


class Terminal:
    """A command on the slave side of a pseudo-terminal of 120 x 40; the screen text read from the master."""

    def __init__(self, *args: str) -> None:
        self.master, slave = pty.openpty()
        os.set_blocking(self.master, False)
        fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 40, 120, 0, 0))
        self.proc = subprocess.Popen([*OSDKC, *args], stdin=slave, stdout=slave, stderr=slave, cwd=ROOT,
                                     start_new_session=True)
        os.close(slave)
        self.text = ""

    def read_until(self, pattern: str, timeout: float = 15.0) -> str:
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if re.search(pattern, self.text, re.S):
                return self.text
            ready, _, _ = select.select([self.master], [], [], 0.1)
            if ready:
                try:
                    self.text += os.read(self.master, 65536).decode(errors="replace")
                except OSError:   # the slave closed: the command ended
                    break
        raise AssertionError(f"no {pattern!r} on the screen within {timeout} s:\n{self.text[-3000:]}")

    def last_screen(self) -> str:
        """The last screen drawn whole (from cursor home to erase-below)."""
        return [s for s in self.text.split("\x1b[H") if "\x1b[J" in s][-1]

    def ended_within(self, seconds: float) -> int:
        t0 = time.monotonic()
        code = self.proc.wait(timeout=10)
        assert time.monotonic() - t0 < seconds, f"took {time.monotonic() - t0:.1f} s to end"
        try:
            self.text += os.read(self.master, 65536).decode(errors="replace")
        except OSError:
            pass
        return code

    def close(self) -> None:
        if self.proc.poll() is None:
            self.proc.kill()
            self.proc.wait()
        os.close(self.master)


@pytest.fixture
def sim():
    with api.simulator(A3, seed=3) as running:
        yield running


def test_watch_shows_each_items_rate_and_values_in_place_and_quits_on_q(sim) -> None:
    term = Terminal("watch", "--port", sim.url, "--profile", A3, "--interval", "0.25")
    try:
        term.read_until(r"\nbattery +[\d.]+ +1  \d+\x1b\[K.*\x1b\[H")   # the 1 Hz battery has come, and a later screen
        term.read_until(r"\x1b\[H.*attitude \(deg\)[^\n]*\n\x1b\[J")
        screen = term.last_screen()
        rows = {m.group(1): (float(m.group(2)), int(m.group(3))) for m in
                re.finditer(r"^(\w+) +([\d.]+) +(\d+)  ", screen, re.M)}
        assert set(rows) >= {"time_stamp", "quaternion", "battery", "control_info"}, screen
        assert rows["time_stamp"][1] == 100 and rows["battery"][1] == 1   # the profile's defaults beside
        assert rows["time_stamp"][0] > 20, screen                           # and measured: frames arrive
        assert re.search(r"^battery .* \d+\x1b\[K", screen, re.M)            # its latest value
        assert "frames/s" in screen and "errors/s" in screen
        assert screen.count("\n") < 40                                       # it fits the terminal, in place
        os.write(term.master, b"q")
        assert term.ended_within(2.0) == 0
        assert "\x1b[?25h" in term.text                                      # the cursor is given back
    finally:
        term.close()


@pytest.mark.parametrize("signum, status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_watch_stops_on_a_signal_within_2_s(sim, signum, status) -> None:
    term = Terminal("watch", "--port", sim.url, "--profile", A3)
    try:
        term.read_until(r"battery")
        os.killpg(term.proc.pid, signum)
        assert term.ended_within(2.0) == status
        assert "\x1b[?25h" in term.text and "Traceback" not in term.text
    finally:
        term.close()


def test_watch_without_a_terminal_prints_a_line_per_update(sim) -> None:
    done = subprocess.run([*OSDKC, "watch", "--port", sim.url, "--profile", A3, "--duration", "1.6",
                           "--interval", "0.5"], capture_output=True, text=True, timeout=30, cwd=ROOT)
    assert done.returncode == 0, done.stderr
    lines = done.stdout.splitlines()
    assert 3 <= len(lines) <= 6 and "\x1b" not in done.stdout
    assert re.search(r"frames/s, [\d.]+ errors/s; Hz: time_stamp [\d.]+", lines[-1]), lines[-1]
    assert done.stderr.startswith("osdkc watch: ")


def test_decode_port_prints_frames_as_they_arrive_until_ctrl_c(sim) -> None:
    proc = subprocess.Popen([*OSDKC, "decode", "--profile", A3, "--port", sim.url], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, cwd=ROOT, text=True)
    try:
        lines = []
        deadline = time.monotonic() + 15
        while len(lines) < 20 and time.monotonic() < deadline:
            lines.append(proc.stdout.readline())   # each line comes as its frame does: no buffering to the end
        events = [json.loads(line) for line in lines]
        assert sum(ev.get("command") == "broadcast" for ev in events) >= 15
        proc.send_signal(signal.SIGINT)
        t0 = time.monotonic()
        proc.wait(timeout=10)
        assert time.monotonic() - t0 < 2.0 and proc.returncode == 130
        assert "Traceback" not in proc.stderr.read()
    finally:
        if proc.poll() is None:
            proc.kill()
        proc.stdout.close()
        proc.stderr.close()


def test_decode_follow_and_watch_capture_read_a_capture_as_it_is_written(tmp_path) -> None:
    path = tmp_path / "growing.pcapng"
    writer = CaptureWriter(str(path))
    stop = threading.Event()

    def write() -> None:
        seq = 0
        while not stop.is_set():
            writer.rx(api.encode_broadcast_frame(A3, {"time_stamp": {"time": seq}, "battery": 77}, seq=seq))
            seq += 1
            time.sleep(0.01)

    thread = threading.Thread(target=write, daemon=True)
    thread.start()
    try:
        follow = subprocess.Popen([*OSDKC, "decode", "--profile", A3, "--follow", str(path)], stdout=subprocess.PIPE,
                                  stderr=subprocess.PIPE, cwd=ROOT, text=True)
        first = [json.loads(follow.stdout.readline()) for _ in range(10)]
        assert [ev["frame"]["data"]["value"]["body"]["data"]["battery"] for ev in first] == [77] * 10
        follow.send_signal(signal.SIGINT)
        assert follow.wait(timeout=10) == 130
        follow.stdout.close()
        follow.stderr.close()
        watched = subprocess.run([*OSDKC, "watch", "--capture", str(path), "--profile", A3, "--duration", "1.2",
                                  "--interval", "0.4"], capture_output=True, text=True, timeout=30, cwd=ROOT)
        assert watched.returncode == 0, watched.stderr
        assert re.search(r"battery [\d.]+", watched.stdout)
    finally:
        stop.set()
        thread.join()
        writer.close()


@pytest.mark.parametrize("args, words", [
    (["watch", "--port", "/dev/osdkc-no-such-port", "--profile", A3], "cannot open port /dev/osdkc-no-such-port"),
    (["watch", "--capture", "/tmp/osdkc-no-such-capture", "--profile", A3], "no such file"),
    (["watch", "--profile", A3], "one of the arguments --port --capture is required"),
    (["decode", "--profile", A3, "--follow", "-"], "--follow is for a FILE"),
    (["decode", "--profile", A3, "--port", "/dev/null", "--format", "csv"], "--port and --follow give JSON lines"),
    (["decode", "--profile", A3, "--port", "/dev/osdkc-no-such-port"], "cannot open port"),
])
def test_bad_live_arguments_are_one_line_and_exit_2(args, words) -> None:
    done = subprocess.run([*OSDKC, *args], capture_output=True, text=True, timeout=30, cwd=ROOT,
                          stdin=subprocess.DEVNULL)
    assert done.returncode == 2 and words in done.stderr, done.stderr
    assert "Traceback" not in done.stderr and len(done.stderr.strip().splitlines()) == 1
