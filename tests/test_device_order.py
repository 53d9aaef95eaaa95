"""Order on the wire and in the capture, where a race made healthy runs fail.

- A device that answers at once: the ACK must find its command registered
  (else it is dropped and the command goes out again) and the capture must
  hold the command before its ACK (else a replay repeats the false FAIL).
  The device here is a thread on the master side of a real pseudo-terminal
  that answers each command the moment it has read it.
- The capture is attached before the first read: a live run and the replay
  of its capture count the same bytes and frames.
- A frame at the new rates that arrives in the very read that brings the set
  frequency ACK does not count against the old rates.
"""
from __future__ import annotations

import functools
import os
import re
import subprocess
import sys
import threading
import tty

import pytest

from osdk_conformance.core.capture import RX, TX, CaptureWriter, read_capture
from osdk_conformance.core.deframe import Deframer, Frame
from osdk_conformance.device.checks import Options, stream_checks
from osdk_conformance.device.port import Port
from osdk_conformance.device.active import Commander
from osdk_conformance.device.analysis import Analyzer
from osdk_conformance.core.wire import encode, open_frame
from osdk_conformance.sim.simulator import spawned

PROFILE = "a3-fw3.1"
REQUESTS = 1000


def _ack_value(cmd_set: int, cmd_id: int) -> bytes:
    """The ACK of set frequency (the only command the device here answers)."""
    from osdk_conformance._construct.payload import osdk_payload

    assert (cmd_set, cmd_id) == (0, 0x10)
    return osdk_payload(0, 0x10, True, PROFILE).build({"body": {"ack_code": "success"}})


class InstantDevice(threading.Thread):
    """Answers every command on the pty master with its ACK as soon as it is read."""

    def __init__(self, master: int) -> None:
        super().__init__(daemon=True)
        self.master, self.commands, self.stop = master, 0, threading.Event()

    def run(self) -> None:
        import select

        deframer = Deframer()
        while not self.stop.is_set():
            if not select.select([self.master], [], [], 0.05)[0]:
                continue
            for ev in deframer.feed(os.read(self.master, 4096)):
                if isinstance(ev, Frame):
                    op = open_frame(ev.raw)
                    self.commands += 1
                    os.write(self.master, encode(value=_ack_value(op.cmd_set, op.cmd_id), is_ack=True,
                                                 session=op.session, seq=op.seq))


@pytest.mark.realtime   # a reader thread starved for 0.5 s would also make a command go out again
def test_an_ack_that_comes_back_at_once_finds_its_command(tmp_path):
    master, slave = os.openpty()
    tty.setraw(slave)
    device = InstantDevice(master)
    device.start()
    an = Analyzer(PROFILE)
    port = Port(os.ttyname(slave), 230400, an)
    port.open(start=False)
    cap = CaptureWriter(tmp_path / "c.pcapng")
    port.start(cap)
    try:
        cmd = Commander(port, an, PROFILE, None, False, ack_timeout=0.5)
        keep_all = {"codes": [5] * 16}   # set frequency, every item "keep as is"
        answered = [cmd.request(0, 0x10, keep_all, tries=2)[0] is not None for _ in range(REQUESTS)]
    finally:
        port.close()
        cap.close()
        device.stop.set()
        device.join()
        os.close(master)
        os.close(slave)
    assert all(answered)
    assert device.commands == REQUESTS, f"{device.commands - REQUESTS} commands sent again: their ACK was dropped"
    # in the capture every ACK comes after its command
    tx_seen, rx_deframer, tx_deframer = set(), Deframer(), Deframer()
    for rec in read_capture(tmp_path / "c.pcapng").records:
        deframer = tx_deframer if rec.direction == TX else rx_deframer
        for ev in deframer.feed(rec.data):
            if isinstance(ev, Frame):
                op = open_frame(ev.raw)
                if rec.direction == TX:
                    tx_seen.add(op.seq)
                else:
                    assert op.is_ack and op.seq in tx_seen, f"ACK {op.seq} recorded before its command"


LINE = re.compile(r"^(PASS|FAIL|SKIP|ERROR)\s+(\S+)\s+(.*)$", re.M)


def _checks(out: str) -> dict[str, str]:
    return {m[2]: m[3] for m in LINE.finditer(out)}


@pytest.mark.realtime
def test_the_capture_holds_every_byte_the_live_run_counted(tmp_path):
    cap = tmp_path / "run.pcapng"
    dev = [sys.executable, "-m", "osdk_conformance.cli", "device", "--profile", PROFILE]
    # the simulator broadcasts before the device opens the port: bytes are waiting at the first read
    with spawned("--profile", PROFILE) as (url, _):
        live = subprocess.run([*dev, "--port", url, "--capture", str(cap), "--duration", "1"], capture_output=True,
                              text=True, timeout=60)
    replay = subprocess.run([*dev, "--replay", str(cap)], capture_output=True, text=True, timeout=60)
    live_checks, replay_checks = _checks(live.stdout), _checks(replay.stdout)
    for cid in ("link.data", "link.baud", "decode.frames"):
        assert live_checks[cid] == replay_checks[cid], cid
    rx = sum(len(r.data) for r in read_capture(cap).records if r.direction == RX)
    assert live_checks["link.data"] == f"{rx} bytes received"


@functools.lru_cache(maxsize=1)
def _sim():
    from osdk_conformance.sim.simulator import SimConfig, Simulator

    return Simulator(SimConfig(profile=PROFILE), transport=None)


def _broadcast(seq: int, rates: dict[str, int], fc_time: float = 0.0) -> bytes:
    """A broadcast frame carrying the items with a non-zero rate (values from a
    simulator at rest), its time stamp item `fc_time` s after the simulator's start."""
    sim = _sim()
    items = [i for i in sim.profile.flag_bits if rates.get(i)]
    return encode(cmd_set=2, cmd_id=0, value=sim.broadcast_value(items, sim.start + fc_time), seq=seq)


@pytest.mark.parametrize("fc_hz,arrival,expected", [
    (100, lambda k: max(k / 100, 0.12), 100.0),   # the host did not read for 120 ms, then read a burst
    (125, lambda k: k / 125, 125.0),              # the device is 25 % fast by both clocks: rate drift
])
def test_rates_are_measured_on_the_flight_controllers_clock(fc_hz, arrival, expected):
    an = Analyzer(PROFILE)
    for k in range(100):
        an.feed_rx(1000.0 + arrival(k), _broadcast(k, {"time_stamp": 100}, k / fc_hz))
    m = an.measure_rates({"time_stamp": 100}, 1000.0, 1002.0)["time_stamp"]
    assert m["clock"] == "flight controller time stamp"
    assert m["measured_hz"] == pytest.approx(expected, abs=0.5)   # ticks of 2.5 ms over a 1 s window
    # on the arrival clock the pause alone would read 114 Hz: more than the 10 % tolerance


def _paused_run(pause_at: int, pause: float, fc_hz: float = 100, frames: int = 300) -> Analyzer:
    """A run at `fc_hz` whose host did not read for `pause` s before frame
    `pause_at`, then read the frames it owed in one burst."""
    an = Analyzer(PROFILE)
    for k in range(frames):
        t = k / fc_hz
        if pause_at <= k and t < pause_at / fc_hz + pause:
            t = pause_at / fc_hz + pause
        an.feed_rx(1000.0 + t, _broadcast(k, {"time_stamp": 100, "quaternion": 100}, k / fc_hz))
    return an


def test_a_window_with_a_host_pause_is_measured_on_the_fc_clock_the_run_vouches_for():
    # reliability bench, healthy-active-0074 and -0076: windows beside a pause
    # of the host read 169 Hz and 66 Hz for 100, on the arrival clock, because
    # the FC's clock was trusted only where it agreed with the arrivals
    an = _paused_run(pause_at=150, pause=0.15)
    assert an.fc_clock_trusted()
    m = an.measure_rates({"time_stamp": 100}, 1001.6, 1002.0)["time_stamp"]   # opens with the burst
    assert m["clock"] == "flight controller time stamp"
    assert m["measured_hz"] == pytest.approx(100.0, abs=3)


def test_a_time_stamp_clock_in_the_wrong_unit_is_not_trusted():
    an = Analyzer(PROFILE)
    for k in range(300):   # an FC counting milliseconds in the 1/400 s field: 2.5 times too fast
        an.feed_rx(1000.0 + k / 100, _broadcast(k, {"time_stamp": 100}, 2.5 * k / 100))
    assert not an.fc_clock_trusted()
    m = an.measure_rates({"time_stamp": 100}, 1000.0, 1003.0)["time_stamp"]
    assert m["clock"] == "arrival" and m["measured_hz"] == pytest.approx(100.0, abs=1)


def test_the_yaw_rate_span_is_on_the_fc_clock():
    # reliability bench, healthy-active-0078: yaw rate 12.2 deg/s for 10 when
    # the attitude samples' span was taken on the arrival clock across a pause
    # the window opens with the burst: its first sample was built 0.15 s before it came
    an = _paused_run(pause_at=150, pause=0.15)
    att = [s for s in an.traces["attitude"] if s[0] >= 1001.6]
    assert att[-1][0] - att[0][0] == pytest.approx(1.34, abs=0.005)   # arrival: 10 % short
    assert an.sample_span(att) == pytest.approx(1.49, abs=0.005)       # the FC's clock


def test_a_frame_at_the_new_rates_in_the_read_of_the_ack_is_not_held_against_the_old_rates():
    from osdk_conformance.device.active import rate_codes
    from osdk_conformance.core.rules import profile

    prof = profile(PROFILE)
    an = Analyzer(PROFILE)
    old, new = dict(prof.default_rates_hz), {i: 0 for i in prof.flag_bits}
    new.update(control_info=100, time_stamp=100)
    t, seq = 100.0, 0
    for seq in range(300):   # 3 s of frames at the default rates: every item at each one's rate
        items = {i: hz for i, hz in old.items() if hz and seq % round(100 / hz) == 0}
        an.feed_rx(t + seq / 100, _broadcast(seq, items))
    t_req = t + 3.0
    request = encode(cmd_set=0, cmd_id=0x10, value=bytes(rate_codes(prof, new)), session=2, seq=7)
    an.feed_tx(t_req, request)
    ack = encode(value=_ack_value(0, 0x10), is_ack=True, session=2, seq=7)
    an.feed_rx(t_req + 0.01, ack + _broadcast(seq + 1, new))   # one read: the ACK and a frame at the new rates
    an.finish()
    assert len(an.epochs) == 2
    stream = {r.id: r for r in stream_checks(an, Options(PROFILE))}
    assert stream["stream.rates"].status == "pass", stream["stream.rates"].message
    assert stream["stream.flags"].status == "pass", stream["stream.flags"].message
