"""Every long command stops on the first SIGINT or SIGTERM: the kit, the
selftest and the simulator, each run as a real child process and sent a
real signal in the middle of its work. Each exits 130 or 143 (the shell's
128 + signal number, as every osdkc command does), says what it had not
finished, leaves no child process behind and does not go on to later steps.

The time from the signal to the exit is printed (pytest -s shows it); the
bound asserted here is only a guard against the former behaviour (minutes,
or never), since the suite runs beside other tests on a loaded machine.
"""
from __future__ import annotations

import json
import os
import queue
import signal
import subprocess
import sys
import threading
import time
import uuid
from pathlib import Path

import pytest

# the kit and selftest interrupted mid-run: `make quick` leaves it out
pytestmark = pytest.mark.slow

from osdk_conformance.core.paths import ROOT

GUARD_S = 30.0   # the former kit went on for 70 s after a SIGTERM; the selftest for minutes


def _reader(stream, q: queue.Queue) -> None:
    for line in stream:
        q.put(line)
    q.put(None)


class Child:
    """An `osdkc` child process, its output read line by line in the background,
    marked (in its environment) so that the processes it leaves can be found."""

    def __init__(self, *args: str) -> None:
        self.mark = uuid.uuid4().hex
        self.proc = subprocess.Popen([sys.executable, "-m", "osdk_conformance.cli", *args], cwd=ROOT,
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                     # progress every second: the tests wait for the first line
                                     env=dict(os.environ, OSDKC_TEST_MARK=self.mark, OSDKC_PROGRESS_EVERY="1"),
                                     # a pytest-xdist worker ignores SIGINT, and an ignored signal stays
                                     # ignored across exec: give the child the disposition a shell gives
                                     preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
        self.out: queue.Queue = queue.Queue()
        self.err: queue.Queue = queue.Queue()
        self.seen: list[str] = []
        threading.Thread(target=_reader, args=(self.proc.stdout, self.out), daemon=True).start()
        threading.Thread(target=_reader, args=(self.proc.stderr, self.err), daemon=True).start()

    def wait_for(self, text: str, stream: str = "out", timeout: float = 120) -> None:
        q = self.out if stream == "out" else self.err
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            try:
                line = q.get(timeout=0.5)
            except queue.Empty:
                continue
            assert line is not None, f"ended before {text!r}: {''.join(self.seen)}"
            self.seen.append(line)
            if text in line:
                return
        raise AssertionError(f"no {text!r} within {timeout} s: {''.join(self.seen)}")

    def interrupt(self, sig: int) -> tuple[int, str, str, float]:
        """Send `sig`; wait for the exit; (status, stdout, stderr, seconds to exit)."""
        t0 = time.monotonic()
        self.proc.send_signal(sig)
        try:
            self.proc.wait(timeout=120)
        finally:
            if self.proc.poll() is None:
                self.proc.kill()
        seconds = time.monotonic() - t0
        print(f"exit {self.proc.returncode} {seconds:.2f} s after {signal.Signals(sig).name}")
        return self.proc.returncode, self._rest(self.out), self._rest(self.err), seconds

    def _rest(self, q: queue.Queue) -> str:
        lines = []
        deadline = time.monotonic() + 10
        while time.monotonic() < deadline:
            line = q.get(timeout=10)
            if line is None:
                break
            lines.append(line)
        return "".join(self.seen + lines) if q is self.out else "".join(lines)

    def left_behind(self) -> list[str]:
        """Processes still alive that this child started (by the mark in their environment)."""
        found = []
        time.sleep(0.5)  # a killed group is reaped by init a moment later
        for env in Path("/proc").glob("[0-9]*/environ"):
            try:
                if f"OSDKC_TEST_MARK={self.mark}".encode() in env.read_bytes().split(b"\0"):
                    stat = (env.parent / "stat").read_text()
                    if stat.rsplit(")", 1)[1].split()[0] != "Z":
                        found.append((env.parent / "cmdline").read_bytes().replace(b"\0", b" ").decode())
            except OSError:
                continue
        return found


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM], ids=["SIGINT", "SIGTERM"])
def test_sim_ends_on_a_signal_like_every_command_after_writing_its_stats(tmp_path, sig):
    stats = tmp_path / "stats.json"
    child = Child("sim", "--profile", "a3-fw3.1", "--stats", str(stats))
    child.wait_for("osdkc sim:", stream="err", timeout=60)
    code, out, err, seconds = child.interrupt(sig)
    assert code == 128 + sig, err
    assert f"stopped by {signal.Signals(sig).name}" in err and "Traceback" not in err
    assert json.loads(stats.read_text())["profile"] == "a3-fw3.1"
    assert seconds < GUARD_S


def test_sim_exit_after_is_a_normal_end(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "sim", "--profile", "m100-fw3.1",
                           "--exit-after", "0.5"], cwd=ROOT, capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    assert "stopped;" in proc.stderr


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM], ids=["SIGINT", "SIGTERM"])
def test_selftest_stops_every_mutant_and_claims_no_score(sig):
    # the baseline replays every vector: a run long enough to be interrupted in the middle
    child = Child("selftest", "--jobs", "2")
    child.wait_for("osdkc selftest:", stream="err", timeout=120)   # the first progress line (1 s in)
    code, out, err, seconds = child.interrupt(sig)
    assert code == 128 + sig, out + err
    assert f"INTERRUPTED by {signal.Signals(sig).name}" in out and "no verdict" in out
    assert "mutation score" not in out and "SELFTEST PASSED" not in out and "Traceback" not in err
    assert child.left_behind() == []
    assert seconds < GUARD_S


def test_kit_stops_at_the_interrupted_step_and_runs_no_later_one(tmp_path):
    reports = tmp_path / "reports"
    reports.mkdir()
    # a finished report a later step would overwrite: it must stay as it was
    (reports / "device.html").write_text("complete")
    child = Child("kit", "--report-dir", str(reports))
    child.wait_for("== osdkc run", timeout=300)
    # the implementations are running (the heartbeat comes 1 s in, once every run has been started)
    child.wait_for("implementations done", stream="err", timeout=180)
    code, out, err, seconds = child.interrupt(signal.SIGINT)
    assert code == 130, out + err
    assert "kit: INTERRUPTED by SIGINT during run" in out and "not run: run c-target, selftest, device, fuzz, doctor, tap" in out
    assert "== osdkc selftest" not in out and "== osdkc sim" not in out and "Traceback" not in err
    assert (reports / "device.html").read_text() == "complete"
    summary = json.loads((reports / "conformance.json").read_text())
    assert summary["interrupted"] == "SIGINT"
    assert child.left_behind() == []
    assert seconds < GUARD_S


@pytest.mark.parametrize("sig,status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)], ids=["SIGINT", "SIGTERM"])
def test_a_command_without_handlers_of_its_own_ends_as_every_command_does(sig, status):
    # `osdkc bench --only footprint` sets no signal handler: the command line's own is what answers here,
    # while QEMU runs the firmware, and QEMU goes with it
    child = Child("bench", "--only", "footprint")
    child.wait_for("linked for", stream="err")
    time.sleep(1.5)
    code, out, err, seconds = child.interrupt(sig)
    assert code == status, err
    assert "Traceback" not in err and err.rstrip().endswith("interrupted" if sig == signal.SIGINT else "terminated")
    assert seconds < GUARD_S
    assert child.left_behind() == []

