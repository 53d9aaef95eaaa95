"""`osdkc sim` on its own: the motion model, fault injection reproducibility,
and the simulator answering over a real pseudo-terminal through pyserial."""
from __future__ import annotations

import errno
import json
import math
import os
import signal
import subprocess
import sys
import time

import pytest
import serial

from osdk_conformance.core.deframe import Frame, deframe
from osdk_conformance.core.rules import profile as load_profile
from osdk_conformance.core.wire import encode, open_frame
from osdk_conformance.sim.simulator import (PtyTransport, SimConfig, Simulator, Vehicle, euler_to_quaternion,
                                            quaternion_to_euler, spawned)
from osdk_conformance._construct.control import encode_movement_control
from osdk_conformance._construct.payload import osdk_payload

# Measures rates and timing of a live simulator: tools/run_tests.py runs the
# `realtime` tests one at a time, at a higher priority than the CPU-heavy rest.
pytestmark = pytest.mark.realtime


def fly(v: Vehicle, mode: int, x: float, y: float, z: float, yaw: float, seconds: float, dt: float = 0.01):
    t = 0.0
    while t < seconds:
        t += dt
        v.set_command(mode, x, y, z, yaw, t)
        v.step(dt, t)


def test_velocity_and_yaw_rate_commands_are_followed_within_the_seed_accuracy():
    v = Vehicle()
    fly(v, 0x48, 1.0, -0.5, 0.3, 10.0, 2.0)
    assert abs(v.vn - 1.0) <= 0.2 and abs(v.ve + 0.5) <= 0.2 and abs(v.vu - 0.3) <= 0.2
    assert abs(math.degrees(v.rates[2]) - 10.0) <= 0.5


def test_attitude_command_is_followed_within_half_a_degree():
    v = Vehicle()
    fly(v, 0x00, 5.0, -3.0, 0.0, 30.0, 2.0)
    roll, pitch, yaw = (math.degrees(a) for a in quaternion_to_euler(*euler_to_quaternion(v.roll, v.pitch, v.yaw)))
    assert abs(roll - 5.0) <= 0.5 and abs(pitch + 3.0) <= 0.5 and abs(yaw - 30.0) <= 0.5


def test_position_offset_and_height_commands_move_the_aircraft():
    v = Vehicle()
    v.set_command(0x90, 2.0, 1.0, 12.0, 0.0, 0.0)   # one offset, then the aircraft holds the target
    t = 0.0
    while t < 4.0:
        t += 0.01
        v.command_t = t
        v.step(0.01, t)
    assert math.hypot(v.n - 2.0, v.e - 1.0) < 0.1 and abs(v.height - 12.0) < 0.1


def test_without_commands_the_aircraft_hovers():
    v = Vehicle()
    fly(v, 0x48, 2.0, 0.0, 0.0, 0.0, 1.0)
    t = 1.0
    for _ in range(300):
        t += 0.01
        v.step(0.01, t)
    assert abs(v.vn) < 0.05 and abs(v.vu) < 0.05


def test_the_same_seed_injects_the_same_faults():
    frame = encode(cmd_set=2, cmd_id=0, value=b"\x00\x18\x03\x57", seq=1)
    outs = []
    for _ in range(2):
        t = PtyTransport()
        try:
            s = Simulator(SimConfig(seed=5, faults={"noise": 0.3, "bitflip": 0.3, "drop_bytes": 0.3,
                                                    "truncate": 0.3, "bad_crc": 0.3, "duplicate": 0.3}), t)
            outs.append([s._inject(frame) for _ in range(50)])
        finally:
            t.close()
    assert outs[0] == outs[1]
    assert sum(o != frame for o in outs[0]) > 10


def _start(*args):
    proc = subprocess.Popen([sys.executable, "-m", "osdk_conformance.cli", "sim", *args], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)
    return proc, proc.stdout.readline().strip()


def _exchange(ser, raw: bytes, seconds: float = 1.0):
    ser.write(raw)
    end, data = time.monotonic() + seconds, b""
    want = open_frame(raw)
    while time.monotonic() < end:
        data += ser.read(4096)
        for ev in deframe([data]):
            if isinstance(ev, Frame):
                op = open_frame(ev.raw)
                if op.is_ack and op.seq == want.seq and op.session == want.session:
                    return op.value
    return None


def test_sim_over_a_pty_broadcasts_answers_and_stops_cleanly_on_sigterm(tmp_path):
    stats = tmp_path / "stats.json"
    proc, url = _start("--profile", "m100-fw3.1", "--app-id", "11", "--stats", str(stats))
    try:
        ser = serial.serial_for_url(url, baudrate=230400, timeout=0.05)
        data, end = b"", time.monotonic() + 0.5
        while time.monotonic() < end:
            data += ser.read(4096)
        frames = [ev for ev in deframe([data]) if isinstance(ev, Frame)]
        assert len(frames) >= 30
        bcast = osdk_payload(2, 0, False, "m100-fw3.1")
        for f in frames[1:]:
            op = open_frame(f.raw)
            assert (op.cmd_set, op.cmd_id) == (2, 0)
            bcast.parse(op.value)

        def req(cmd_set, cmd_id, body, seq):
            value = osdk_payload(cmd_set, cmd_id, False, "m100-fw3.1").build({"body": body})
            ack = _exchange(ser, encode(cmd_set=cmd_set, cmd_id=cmd_id, value=value, session=2, seq=seq))
            assert ack is not None, (cmd_set, cmd_id)
            return osdk_payload(cmd_set, cmd_id, True, "m100-fw3.1").parse(ack).body

        assert str(req(0, 0, {"arbitrary": 0}, 10).ack_code) == "not_activated"
        assert int(req(1, 0, {"request": 1}, 11).ack_code) == 0xFF01     # not activated yet
        assert str(req(0, 1, {"app_id": 11, "api_level": 2, "sdk_version": 0x03010A00,
                              "bundle_id": bytes(32)}, 12).ack_code) == "success"
        assert [str(req(1, 0, {"request": 1}, s).ack_code) for s in (13, 14)] == ["obtain_in_progress", "obtained"]
        ser.write(encode(cmd_set=1, cmd_id=3, value=encode_movement_control(0x48, 3.0, 0, 0, 0), seq=15))
        assert str(req(0, 0x10, {"codes": [9] + [0] * 15}, 16).ack_code) == "parameter_error"
        assert [str(req(1, 0, {"request": 0}, s).ack_code) for s in (17, 18)] == ["release_in_progress", "released"]
        ser.close()
    finally:
        proc.send_signal(signal.SIGTERM)
        rc = proc.wait(timeout=10)
    assert rc == 143
    s = json.loads(stats.read_text())
    assert s["broadcast_frames"] > 30 and s["acks_sent"] == 8 and s["commands_received"] == 9


def test_sim_exits_cleanly_on_sigint_and_rejects_bad_arguments():
    proc, url = _start("--tcp", "0")
    assert url.startswith("socket://127.0.0.1:")
    time.sleep(0.3)
    proc.send_signal(signal.SIGINT)
    assert proc.wait(timeout=10) == 130   # as every osdkc command ends on Ctrl-C
    assert "Traceback" not in proc.stderr.read()
    bad = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "sim", "--noise", "2"],
                         capture_output=True, text=True, timeout=30)
    assert bad.returncode == 2 and "probability" in bad.stderr


@pytest.mark.parametrize("spec", ["battery=7", "nope=10"])
def test_sim_rate_option_is_checked(spec):
    proc = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "sim", "--rate", spec, "--exit-after", "0.2"],
                          capture_output=True, text=True, timeout=30)
    assert proc.returncode == 2 and "ITEM=HZ" in proc.stderr


@pytest.mark.parametrize(("profile", "ack_length"), [("m100-fw2.3", 38), ("m100-fw3.1", 49), ("a3-fw3.1", 49)])
def test_with_baud_the_first_command_after_open_is_answered(tmp_path, profile, ack_length):
    """A host that opens the port at the FC's speed and writes at once is heard,
    as a real UART hears it: the simulator looks at the line speed when bytes
    arrive, not on a timer. The answer has the profile's version-ACK layout
    (ERRATA E30: an 11-byte version ID on FW 3.1)."""
    stats = tmp_path / "stats.json"
    proc, url = _start("--profile", profile, "--baud", "115200", "--hold", "--stats", str(stats))
    try:
        time.sleep(0.3)   # the simulator has seen the port at its default speed before anyone opened it
        ser = serial.serial_for_url(url, baudrate=115200, timeout=0.05)
        value = osdk_payload(0, 0, False, profile).build({"body": {"arbitrary": 0}})
        ack = _exchange(ser, encode(cmd_set=0, cmd_id=0, value=value, session=2, seq=1))
        ser.close()
        assert ack is not None and len(ack) == ack_length
        body = osdk_payload(0, 0, True, profile).parse(ack).body
        assert bytes(body.version_name).rstrip(b"\0").decode() == load_profile(profile).version_name
        assert (body.version_id is None) == (profile == "m100-fw2.3")
    finally:
        proc.send_signal(signal.SIGTERM)
        assert proc.wait(timeout=10) == 143
    s = json.loads(stats.read_text())
    assert s["commands_received"] == 1 and s["acks_sent"] == 1
    assert s["rx_bytes_discarded"] == {"baud_mismatch": 0, "stalled": 0, "deaf": 0, "not_a_frame": 0}


def test_bytes_at_the_wrong_speed_are_counted_not_dropped_silently(tmp_path):
    stats = tmp_path / "stats.json"
    proc, url = _start("--baud", "115200", "--hold", "--stats", str(stats))
    try:
        ser = serial.serial_for_url(url, baudrate=9600, timeout=0.05)
        value = osdk_payload(0, 0, False, "a3-fw3.1").build({"body": {"arbitrary": 0}})
        frame = encode(cmd_set=0, cmd_id=0, value=value, session=2, seq=1)
        assert _exchange(ser, frame) is None
        ser.write(b"\x00" * 5)
        time.sleep(0.3)   # a pty has no line timing: let the simulator read these before the speed changes
        ser.baudrate = 115200   # stray bytes at the right speed: not frames, counted as such
        ser.write(b"\x00" * 5)
        time.sleep(0.3)
        ser.close()
    finally:
        proc.send_signal(signal.SIGTERM)
        assert proc.wait(timeout=10) == 143
    s = json.loads(stats.read_text())
    assert s["commands_received"] == 0
    assert s["rx_bytes"] == len(frame) + 10
    assert s["rx_bytes_discarded"] == {"baud_mismatch": len(frame) + 5, "stalled": 0, "deaf": 0,
                                         "not_a_frame": 5}


def _open_error(path) -> int | None:
    try:
        os.close(os.open(path, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK))
    except OSError as e:
        return e.errno
    return None


def test_an_unplugged_port_keeps_its_terminal_number_until_it_is_back(tmp_path):
    """Another program's new pseudo-terminal never gets the number of an
    unplugged one: a host reopening its port would reach that program."""
    link = tmp_path / "ttyFC"
    t = PtyTransport(str(link))
    others = []
    try:
        first = t.path
        assert os.path.realpath(link) == first
        t.unplug()
        assert _open_error(link) == errno.ENOENT and _open_error(first) == errno.ENOENT
        others.append(os.openpty())
        assert os.ttyname(others[-1][1]) != first
        t.replug()
        assert os.path.realpath(link) == t.path != first and _open_error(link) is None
    finally:
        t.close()
        for fds in others:
            for fd in fds:
                os.close(fd)
    assert not link.exists() and t.unplugged_slave == -1


def test_a_killed_simulator_s_terminal_number_is_not_given_away_while_it_is_spawned():
    with spawned("--profile", "a3-fw3.1") as (url, proc):
        proc.kill()
        proc.wait()
        assert _open_error(url) in (errno.ENOENT, errno.EIO)
        m, s = os.openpty()
        try:
            assert os.ttyname(s) != url
        finally:
            os.close(m)
            os.close(s)
