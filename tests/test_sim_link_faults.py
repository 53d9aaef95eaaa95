"""`osdkc sim`'s link faults, the ones `osdkc doctor` must tell apart: an FC
that never reads its RX line (--deaf), one that broadcasts nothing until
activated, a loopback line with no FC on it, and a different baud rate per
direction (--rx-baud), each over a real pseudo-terminal through pyserial."""
from __future__ import annotations

import json
import subprocess
import sys
import time

import pytest
import serial

from osdk_conformance.core.deframe import Frame, deframe
from osdk_conformance.core.rules import profile as load_profile
from osdk_conformance.core.wire import Opened, encode, open_frame
from osdk_conformance.sim.simulator import PtyTransport, SimConfig, Simulator, spawned
from osdk_conformance._construct.payload import osdk_payload

PROFILE = "a3-fw3.1"   # the simulator's default


def _version_query(seq: int) -> bytes:
    return encode(cmd_set=0, cmd_id=0, value=b"\x00", session=2, seq=seq)


def _activation(app_id: int, seq: int) -> bytes:
    value = osdk_payload(0, 1, False, PROFILE).build({"body": {
        "app_id": app_id, "api_level": 2, "sdk_version": load_profile(PROFILE).sdk_version, "bundle_id": bytes(32)}})
    return encode(cmd_set=0, cmd_id=1, value=value, session=2, seq=seq)


def _ack_code(cmd_id: int, ack: Opened) -> str:
    return str(osdk_payload(0, cmd_id, True, PROFILE).parse(ack.value).body.ack_code)


def _read(ser, seconds: float) -> bytes:
    end, data = time.monotonic() + seconds, b""
    while time.monotonic() < end:
        data += ser.read(4096)
    return data


def _frames(data: bytes) -> list[Opened]:
    """The CRC-valid frames in `data`, opened."""
    return [open_frame(ev.raw) for ev in deframe([data]) if isinstance(ev, Frame)]


def _broadcast(data: bytes) -> list[Opened]:
    return [op for op in _frames(data) if not op.is_ack and (op.cmd_set, op.cmd_id) == (2, 0)]


def _await_ack(ser, seq: int, seconds: float) -> tuple[Opened | None, bytes]:
    """The ACK to SEQ `seq` of session 2 once it came, or None after
    `seconds`; and all that was read meanwhile."""
    end, data = time.monotonic() + seconds, b""
    while time.monotonic() < end:
        data += ser.read(4096)
        for op in _frames(data):
            if op.is_ack and op.session == 2 and op.seq == seq:
                return op, data
    return None, data


@pytest.mark.realtime
def test_a_deaf_fc_broadcasts_and_answers_nothing(tmp_path):
    stats = tmp_path / "stats.json"
    query = _version_query(1)
    with spawned("--deaf", "--stats", str(stats)) as (url, _):
        with serial.serial_for_url(url, baudrate=230400, timeout=0.05) as ser:
            ser.write(query)
            ack, heard = _await_ack(ser, 1, 1.0)
    assert ack is None
    assert len(_broadcast(heard)) >= 20   # the broadcast goes on, 100 Hz here
    s = json.loads(stats.read_text())
    assert s["rx_bytes"] == len(query)
    assert s["rx_bytes_discarded"] == {"baud_mismatch": 0, "stalled": 0, "deaf": len(query), "not_a_frame": 0}
    assert s["commands_received"] == s["acks_sent"] == 0


@pytest.mark.realtime
def test_silent_until_activated_answers_and_starts_broadcasting_once_activated(tmp_path):
    stats = tmp_path / "stats.json"
    with spawned("--silent-until-activated", "--app-id", "11", "--stats", str(stats)) as (url, _):
        with serial.serial_for_url(url, baudrate=230400, timeout=0.05) as ser:
            assert _read(ser, 1.0) == b""
            ser.write(_version_query(1))
            ack, _ = _await_ack(ser, 1, 1.0)
            assert ack is not None and _ack_code(0, ack) == "not_activated"
            ser.write(_activation(12, seq=2))   # refused: another app id
            ack, heard = _await_ack(ser, 2, 1.0)
            assert ack is not None and _ack_code(1, ack) == "invalid_parameters"
            assert not _broadcast(heard + _read(ser, 0.3))
            ser.write(_activation(11, seq=3))
            ack, heard = _await_ack(ser, 3, 1.0)
            assert ack is not None and _ack_code(1, ack) == "success"
            assert len(_broadcast(heard + _read(ser, 0.5))) >= 20
    s = json.loads(stats.read_text())
    assert s["activated"] and s["activated_after_s"] >= 1.0 and s["acks_sent"] == 3


def test_a_restart_loses_the_activation_and_silences_it_again():
    t = PtyTransport()
    try:
        sim = Simulator(SimConfig(silent_until_activated=True), t)
        assert not sim._broadcasts()
        sim.on_frame(_activation(1, seq=1), time.monotonic())
        assert sim.activated and sim._broadcasts()
        sim._power_cycle(time.monotonic())
        assert not sim._broadcasts()
    finally:
        t.close()


def test_a_loopback_line_has_no_fc_to_start_broadcasting():
    t = PtyTransport()
    try:
        sim = Simulator(SimConfig(loopback=True), t)
        sim.broadcasting = True   # what SIGUSR1 does
        assert not sim._broadcasts()
    finally:
        t.close()


@pytest.mark.realtime
def test_a_loopback_line_returns_every_byte_written_and_nothing_else(tmp_path):
    stats = tmp_path / "stats.json"
    sent = _version_query(1) + bytes(range(256)) + b"\xaa" * 40   # a frame, every byte value, frame starts
    with spawned("--loopback", "--stats", str(stats)) as (url, _):
        with serial.serial_for_url(url, baudrate=230400, timeout=0.05) as ser:
            assert _read(ser, 0.5) == b""
            ser.write(sent)
            back = _read(ser, 0.5)
    assert back == sent
    s = json.loads(stats.read_text())
    assert s["bytes_echoed"] == s["rx_bytes"] == len(sent) and s["bytes_echo_lost"] == 0
    assert s["broadcast_frames"] == s["acks_sent"] == s["commands_received"] == 0
    assert set(s["rx_bytes_discarded"].values()) == {0}


@pytest.mark.realtime
def test_with_rx_baud_the_fc_hears_at_one_rate_and_sends_at_the_other(tmp_path):
    stats = tmp_path / "stats.json"
    unheard = _version_query(1)
    with spawned("--baud", "230400", "--rx-baud", "115200", "--stats", str(stats)) as (url, _):
        with serial.serial_for_url(url, baudrate=230400, timeout=0.05) as ser:
            ser.write(unheard)
            ack, heard = _await_ack(ser, 1, 0.5)
            assert ack is None
            assert len(_broadcast(heard)) >= 10   # what it sends arrives intact
            ser.baudrate = 115200
            # a pty has no line timing: the simulator looks at the speed on
            # each pass of its run loop, so it must have had one at 115200
            time.sleep(0.1)
            ser.write(_version_query(2))
            ser.flush()
            ser.baudrate = 230400   # before the answer comes, as a host reads it
            ack, _ = _await_ack(ser, 2, 1.0)
            assert ack is not None and _ack_code(0, ack) == "not_activated"
    s = json.loads(stats.read_text())
    assert s["rx_bytes_discarded"]["baud_mismatch"] == len(unheard)
    assert s["commands_received"] == s["acks_sent"] == 1


@pytest.mark.parametrize("args, message", [
    (("--rx-baud", "115200"), "--rx-baud goes with --baud"),
    (("--loopback", "--bug", "long-frame-hang"), "--loopback"),
    (("--loopback", "--baud", "115200", "--noise", "0.1"), "--baud, --noise"),
    (("--deaf", "--rx-baud", "115200", "--baud", "230400"), "--deaf"),
])
def test_options_that_make_no_sense_together_are_a_usage_error(args, message):
    proc = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "sim", *args, "--exit-after", "0"],
                          capture_output=True, text=True, timeout=30)
    assert proc.returncode == 2 and message in proc.stderr, proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1
