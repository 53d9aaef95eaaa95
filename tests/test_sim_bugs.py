"""Planted firmware bugs (`osdkc sim --bug NAME`, sim/bugs.py): each one
triggers on its malformed frame and has its effect over a real
pseudo-terminal, the same frame leaves a healthy simulator answering and
broadcasting, and the trigger is in the stats."""
from __future__ import annotations

import argparse
import contextlib
import json
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
import serial

from osdk_conformance import api
from osdk_conformance.core.crc import crc16
from osdk_conformance.core.deframe import Deframer, Frame, frame_length
from osdk_conformance.core.rules import profile as load_profile, profile_names
from osdk_conformance.core.wire import encode, open_frame
from osdk_conformance.sim.bugs import BUGS, REBOOT_PAUSE_S
from osdk_conformance.sim.simulator import PtyTransport, SimConfig, Simulator, add_arguments, spawned
from osdk_conformance._construct.payload import osdk_payload

PROFILE = "a3-fw3.1"
DOCS = Path(__file__).resolve().parent.parent / "docs" / "ACCEPTANCE.md"
LONG = encode(cmd_set=0, cmd_id=0, value=bytes(400 - 18), seq=2)   # a version query with LEN 400
UNKNOWN_SET = encode(cmd_set=0x7E, cmd_id=0x01, value=b"\x00", session=2, seq=2)
HEADER_ONLY = encode(seq=4)


def with_crc16(covered: bytes) -> bytes:
    return covered + crc16(covered).to_bytes(2, "little")


def version_query(seq: int) -> bytes:
    value = osdk_payload(0, 0, False, PROFILE).build({"body": {"arbitrary": 0}})
    return encode(cmd_set=0, cmd_id=0, value=value, session=2, seq=seq)


def command(cmd_set: int, cmd_id: int, body: dict, seq: int) -> bytes:
    value = osdk_payload(cmd_set, cmd_id, False, PROFILE).build({"body": body})
    return encode(cmd_set=cmd_set, cmd_id=cmd_id, value=value, session=2, seq=seq)


def activation(seq: int) -> bytes:
    return command(0, 1, {"app_id": 1, "api_level": 2, "sdk_version": load_profile(PROFILE).sdk_version,
                          "bundle_id": bytes(32)}, seq)


def ack_code(cmd_set: int, cmd_id: int, ack: bytes) -> str:
    return str(osdk_payload(cmd_set, cmd_id, True, PROFILE).parse(ack).body.ack_code)


def test_the_frames_used_are_the_triggers_they_are_meant_to_be():
    assert frame_length(LONG) == 400 and len(LONG) == 400
    assert len(HEADER_ONLY) == 12 and frame_length(HEADER_ONLY) == 12
    assert open_frame(UNKNOWN_SET).cmd_set == 0x7E


# ---- the BUGS table is the one definition ----------------------------------


def test_every_bug_is_in_the_help_and_documented_word_for_word():
    ap = argparse.ArgumentParser(prog="osdkc sim")
    add_arguments(ap, tuple(profile_names()))
    help_text = " ".join(ap.format_help().split())
    docs = DOCS.read_text()
    assert "### Planted firmware bugs" in docs
    for name, what in BUGS.items():
        assert f"| `--bug {name}` | {what} |" in docs, name
        assert f"{name}: {' '.join(what.split())}" in help_text.replace("- ", "-"), name
    assert ap.parse_args(["--bug", "long-frame-hang", "--bug", "unknown-cmd-silence"]).bug == [
        "long-frame-hang", "unknown-cmd-silence"]
    assert ap.parse_args([]).bug == []


def test_an_unknown_bug_is_refused(capsys):
    ap = argparse.ArgumentParser(prog="osdkc sim")
    add_arguments(ap, tuple(profile_names()))
    with pytest.raises(SystemExit):
        ap.parse_args(["--bug", "nope"])
    assert "invalid choice: 'nope'" in capsys.readouterr().err
    with pytest.raises(ValueError, match="unknown planted bug nope"):
        Simulator(SimConfig(bugs=("nope",)), Wire())


# ---- in process: where each trigger is recognised ---------------------------


class Wire:
    """The simulator's side of a port, in memory: what it sends is kept."""

    def __init__(self) -> None:
        self.sent = bytearray()

    def connected(self) -> bool:
        return True

    def write(self, data: bytes) -> int:
        self.sent += data
        return len(data)

    def pending_input(self) -> int:
        return 0

    def speed(self) -> None:
        return None


def fed(bugs: tuple[str, ...], *reads: bytes) -> Simulator:
    sim = Simulator(SimConfig(profile=PROFILE, bugs=bugs), Wire())
    for data in reads:
        sim.on_received(data, time.monotonic(), False)
    return sim


def acks(sim: Simulator) -> list:
    return [op for ev in Deframer().feed(bytes(sim.t.sent)) if isinstance(ev, Frame)
            for op in [open_frame(ev.raw)] if op.is_ack]


@pytest.mark.parametrize("reads", [
    [LONG[:12]],                                   # the header alone: the rest never comes
    [LONG[:5], LONG[5:9], LONG[9:12]],             # a header split across reads
    [LONG],                                        # the whole frame in one read
    [LONG[:-1] + bytes([LONG[-1] ^ 1])],           # the whole frame, bad CRC-32
    [b"\x00garbage", LONG[:12]],                   # after garbage
    [LONG[:11] + b"\x00", LONG[:12]],              # after a header with a bad CRC-16
    [version_query(1) + LONG[:20]],                # after a good frame in the same read
], ids=["header-only", "split", "whole", "bad-crc32", "after-garbage", "after-bad-header", "after-frame"])
def test_long_frame_hang_triggers_wherever_the_receiver_takes_a_long_header(reads):
    sim = fed(("long-frame-hang",), *reads)
    assert sim.bugs.halted(time.monotonic())
    assert sim.stats["bug_triggers"] == {"long-frame-hang": 1}
    [event] = sim.stats["bug_events"]
    assert event["bug"] == "long-frame-hang" and "LEN 400 > 300" in event["trigger"]
    assert event["header"] == LONG[:12].hex()
    accounted = sim.rx_accounting()
    assert sum(accounted["rx_bytes_discarded"].values()) + sim._rx_frame_bytes == accounted["rx_bytes"]


@pytest.mark.parametrize("data", [
    encode(cmd_set=0, cmd_id=0, value=bytes(300 - 18), seq=2),        # LEN 300 fits the buffer
    with_crc16(LONG[:2] + bytes([LONG[2] | 0x04]) + LONG[3:10]),        # LEN 400, VER 1: rejected
    encode(cmd_set=0, cmd_id=0x7F, value=LONG[:12] + bytes(8), seq=3),  # a long header inside a good frame's body
], ids=["len-300", "rejected-header", "inside-a-frame"])
def test_long_frame_hang_ignores_headers_the_receiver_does_not_take(data):
    sim = fed(("long-frame-hang",), data, version_query(5))
    assert not sim.bugs.halted(time.monotonic())
    assert sim.stats["bug_triggers"] == {"long-frame-hang": 0} and sim.stats["bug_events"] == []
    assert [op.seq for op in acks(sim)] == [5]


def test_header_only_reset_loses_seq_clock_activation_control_and_rates():
    sim = fed(("header-only-reset",), activation(1), command(1, 0, {"request": 1}, 2),
              command(1, 0, {"request": 1}, 3), command(0, 0x10, {"codes": [1] * 16}, 4))
    assert sim.activated and sim.control == "onboard" and set(sim.rates.values()) == {1}
    sim.seq = 1234
    now = time.monotonic()
    sim.on_received(HEADER_ONLY + version_query(6), now, False)
    assert sim.seq == 0 and not sim.activated and sim.control == "rc" and not sim.onboard_requested
    assert sim.rates == load_profile(PROFILE).default_rates_hz
    assert sim.bugs.halted(now) and not sim.bugs.halted(now + REBOOT_PAUSE_S)
    assert sim.boot == pytest.approx(now + REBOOT_PAUSE_S)
    assert [op.seq for op in acks(sim)] == [1, 2, 3, 4]   # the query after the reset in the same read is lost
    assert sim.stats["rx_bytes_discarded"]["stalled"] == len(version_query(6))
    [event] = sim.stats["bug_events"]
    assert event["bug"] == "header-only-reset" and event["trigger"] == "12-byte header-only frame, SEQ 4"


def test_unknown_cmd_silence_wedges_every_command_after_the_unknown_set():
    sim = fed(("unknown-cmd-silence",), version_query(1), version_query(2),
              UNKNOWN_SET, activation(3), version_query(4))
    assert [op.seq for op in acks(sim)] == [1, 2]
    assert not sim.activated   # not executed either
    assert sim.stats["bug_triggers"] == {"unknown-cmd-silence": 1}
    assert "command set 0x7e id 0x01" in sim.stats["bug_events"][0]["trigger"]
    assert not sim.bugs.halted(time.monotonic())   # it goes on broadcasting


def test_without_bugs_the_triggers_change_nothing_and_the_stats_have_no_bug_keys():
    sim = fed((), LONG[:12], LONG[12:], HEADER_ONLY, UNKNOWN_SET, version_query(7))
    assert sim.bugs is None and [op.seq for op in acks(sim)] == [7]
    assert not {"bugs", "bug_triggers", "bug_events"} & set(sim.stats)


# ---- over a pseudo-terminal -------------------------------------------------


class Link:
    """A pyserial client of `osdkc sim`: every frame it receives, with its arrival time."""

    def __init__(self, url: str) -> None:
        self.ser = serial.serial_for_url(url, baudrate=230400, timeout=0.02)
        self.deframer = Deframer()
        self.frames: list[tuple[float, object]] = []

    def pump(self, seconds: float, until=None):
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            data = self.ser.read(4096)
            now = time.monotonic()
            for ev in self.deframer.feed(data):
                if isinstance(ev, Frame):
                    op = open_frame(ev.raw)
                    self.frames.append((now, op))
                    if until is not None and until(op):
                        return op
        return None

    def ask(self, raw: bytes, seconds: float = 1.0) -> bytes | None:
        """The ACK value to this command, or None when none came within `seconds`."""
        want = open_frame(raw)
        self.ser.write(raw)
        op = self.pump(seconds, lambda op: op.is_ack and op.seq == want.seq and op.session == want.session)
        return None if op is None else op.value

    def broadcasts(self, since: float = 0.0) -> list[tuple[float, int, int | None]]:
        """(arrival, SEQ, time stamp ticks) of every broadcast received since `since`."""
        out = []
        for t, op in self.frames:
            if t >= since and not op.is_ack and (op.cmd_set, op.cmd_id) == (2, 0):
                stamp = osdk_payload(2, 0, False, PROFILE).parse(op.value).body.data.time_stamp
                out.append((t, op.seq, None if stamp is None else int(stamp.time)))
        return out

    def acks_since(self, since: float) -> int:
        return sum(1 for t, op in self.frames if t >= since and op.is_ack)


class Sim:
    """`osdkc sim` in a child process on a pty, its --stats read when it has stopped."""

    def __init__(self, tmp_path: Path, bugs: tuple[str, ...]) -> None:
        self.stats_file = tmp_path / "stats.json"
        args = ["--profile", PROFILE, "--stats", str(self.stats_file)]
        for name in bugs:
            args += ["--bug", name]
        self.proc = subprocess.Popen([sys.executable, "-m", "osdk_conformance.cli", "sim", *args],
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        self.link = Link(self.proc.stdout.readline().strip())

    def stop(self) -> dict:
        self.link.ser.close()
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
        assert self.proc.wait(timeout=10) in (0, 143)   # 0 when it had ended by itself (--exit-after)
        return json.loads(self.stats_file.read_text())


@pytest.fixture
def start(tmp_path):
    sims = []

    def run(planted: bool, bug: str) -> Sim:
        sims.append(Sim(tmp_path, (bug,) if planted else ()))
        return sims[-1]

    yield run
    for sim in sims:
        if sim.proc.poll() is None:
            sim.proc.kill()
            sim.proc.wait()


@pytest.mark.realtime
@pytest.mark.parametrize("planted", [True, False], ids=["planted", "healthy"])
def test_long_frame_hang_over_a_pty(start, planted):
    sim = start(planted, "long-frame-hang")
    link = sim.link
    assert link.ask(version_query(1)) is not None
    link.ser.write(LONG[:12])
    link.pump(0.2)   # the header alone is the trigger; the rest of the frame follows later
    link.ser.write(LONG[12:])
    after = time.monotonic()
    ack = link.ask(version_query(3), 1.0)
    link.pump(0.5)
    stats = sim.stop()
    if planted:
        assert ack is None and link.broadcasts(after) == []
        [event] = stats["bug_events"]
        assert event["bug"] == "long-frame-hang" and event["header"] == LONG[:12].hex()
        assert stats["bug_triggers"] == {"long-frame-hang": 1} and stats["acks_sent"] == 1
    else:
        assert ack is not None and len(link.broadcasts(after)) >= 20
        assert "bug_events" not in stats and stats["acks_sent"] == 2


@pytest.mark.realtime
@pytest.mark.parametrize("planted", [True, False], ids=["planted", "healthy"])
def test_header_only_reset_over_a_pty(start, planted):
    sim = start(planted, "header-only-reset")
    link = sim.link
    assert ack_code(0, 1, link.ask(activation(1))) == "success"
    assert [ack_code(1, 0, link.ask(command(1, 0, {"request": 1}, s))) for s in (2, 3)] == [
        "obtain_in_progress", "obtained"]
    link.pump(0.2)
    trigger = time.monotonic()
    link.ser.write(HEADER_ONLY)
    link.pump(0.3 + REBOOT_PAUSE_S)
    answer = link.ask(version_query(5), 1.0)
    stats = sim.stop()
    frames = link.broadcasts()
    assert frames and all(stamp is not None for _, _, stamp in frames)   # every frame carries the time stamp
    restarts = [i for i in range(1, len(frames)) if frames[i][1] != (frames[i - 1][1] + 1) & 0xFFFF]
    gap = max(b[0] - a[0] for a, b in zip(frames, frames[1:]))
    if planted:
        [i] = restarts
        assert frames[i - 1][1] > 20 and frames[i - 1][0] < trigger + 0.5   # broadcasting a while, then the trigger
        assert frames[i][1] == 0 and frames[i][2] < 0.1 * 400 < frames[i - 1][2]   # SEQ and time stamp restart
        assert REBOOT_PAUSE_S - 0.05 <= frames[i][0] - frames[i - 1][0] < 1.0
        assert frames[i][0] >= trigger + REBOOT_PAUSE_S - 0.05
        assert ack_code(0, 0, answer) == "not_activated"
        assert stats["activated"] is False and stats["control"] == "rc"
        [event] = stats["bug_events"]
        assert event["bug"] == "header-only-reset" and event["header"] == HEADER_ONLY.hex()
    else:
        assert restarts == [] and gap < REBOOT_PAUSE_S - 0.05
        assert ack_code(0, 0, answer) == "activated"
        assert stats["activated"] is True and stats["control"] == "onboard" and "bug_events" not in stats


@pytest.mark.realtime
@pytest.mark.parametrize("planted", [True, False], ids=["planted", "healthy"])
def test_unknown_cmd_silence_over_a_pty(start, planted):
    sim = start(planted, "unknown-cmd-silence")
    link = sim.link
    assert link.ask(version_query(1)) is not None
    link.ser.write(UNKNOWN_SET)
    link.pump(0.2)
    after = time.monotonic()
    ack = link.ask(version_query(3), 1.0)
    link.pump(0.5)
    stats = sim.stop()
    assert len(link.broadcasts(after)) >= 20   # the broadcast goes on either way
    if planted:
        assert ack is None and link.acks_since(after) == 0
        [event] = stats["bug_events"]
        assert event["bug"] == "unknown-cmd-silence" and "command set 0x7e" in event["trigger"]
        assert stats["acks_sent"] == 1
    else:
        assert ack is not None and "bug_events" not in stats and stats["acks_sent"] == 2


# ---- a restart (a power cycle: SIGHUP, RunningSimulator.restart) -------------


class Stepper(Wire):
    """A port that lets the simulator's run loop go round once: the loop
    stops when it next looks for its ports to wait on."""

    def __init__(self) -> None:
        super().__init__()
        self.sim: Simulator | None = None

    def read_fds(self) -> list[int]:
        self.sim.running = False
        return []


def stepped(bugs: tuple[str, ...], *reads: bytes) -> Simulator:
    """A simulator that has received `reads`, whose run loop can be stepped."""
    sim = Simulator(SimConfig(profile=PROFILE, bugs=bugs), Stepper())
    sim.t.sim = sim
    for data in reads:
        heard(sim, data, time.monotonic())
    return sim


def heard(sim: Simulator, data: bytes, now: float) -> None:
    """Bytes arriving at `now`, deaf while halted as in the run loop."""
    sim.on_received(data, now, sim._halted(now))


def restarted(sim: Simulator) -> float:
    """Request a restart and let the run loop perform it; when it resumes."""
    sim.request_restart()
    sim.running = True
    sim.run()
    assert sim.restart_requests_done == sim.restart_requests
    return sim.resume_at


def test_a_restart_brings_a_simulator_hung_by_a_long_frame_back():
    sim = stepped(("long-frame-hang",), version_query(1), LONG[:12])
    heard(sim, version_query(2), time.monotonic())
    assert sim._halted(time.monotonic()) and [op.seq for op in acks(sim)] == [1]
    resume = restarted(sim)
    assert not sim.bugs.hung and sim.bugs.pending.tail == bytearray() and sim.bugs.received == 0
    heard(sim, version_query(3), resume - 0.01)             # deaf while it boots
    heard(sim, LONG[12:] + version_query(4), resume + 0.01)  # the rest of the long frame is garbage now
    assert [op.seq for op in acks(sim)] == [1, 4]
    assert sim.stats["restarts"] == 1 and sim.stats["bug_triggers"] == {"long-frame-hang": 1}
    assert len(sim.stats["bug_events"]) == 1


def test_a_restart_unwedges_the_command_handler():
    sim = stepped(("unknown-cmd-silence",), UNKNOWN_SET, version_query(3))
    assert sim.bugs.silent and acks(sim) == []
    resume = restarted(sim)
    assert not sim.bugs.silent
    heard(sim, version_query(4), resume + 0.01)
    assert [op.seq for op in acks(sim)] == [4]
    assert sim.stats["bug_triggers"] == {"unknown-cmd-silence": 1} and sim.stats["restarts"] == 1


@pytest.mark.parametrize("bugs", [(), tuple(BUGS)], ids=["healthy", "all-bugs"])
def test_a_restart_loses_what_a_reboot_loses_and_is_no_bug_trigger(bugs):
    sim = stepped(bugs, activation(1), command(1, 0, {"request": 1}, 2), command(1, 0, {"request": 1}, 3),
                  command(0, 0x10, {"codes": [1] * 16}, 4))
    assert sim.activated and sim.control == "onboard" and set(sim.rates.values()) == {1}
    assert sim.stats["restarts"] == 0 and sim.last_ack
    sim.seq, sim.frame_index, sim.pending = 1234, 7, "release"
    sim.vehicle.command = {"h": 1}
    sim.outbuf += b"not yet sent"
    before = time.monotonic()
    resume = restarted(sim)
    assert sim.seq == 0 and sim.frame_index == 0 and not sim.activated and sim.control == "rc"
    assert sim.pending is None and not sim.onboard_requested and sim.vehicle.command is None
    assert sim.rates == load_profile(PROFILE).default_rates_hz and sim.last_ack == {} and sim.outbuf == b""
    assert before + REBOOT_PAUSE_S <= resume == sim.boot <= time.monotonic() + REBOOT_PAUSE_S
    assert sim._halted(resume - 0.01) and not sim._halted(resume)
    stalled = sim.stats["rx_bytes_discarded"]["stalled"]
    heard(sim, version_query(5), resume - 0.01)
    assert sim.stats["rx_bytes_discarded"]["stalled"] == stalled + len(version_query(5))
    assert sim.stats["restarts"] == 1
    if bugs:
        assert sim.stats["bug_triggers"] == {name: 0 for name in BUGS} and sim.stats["bug_events"] == []
    else:
        assert not {"bugs", "bug_triggers", "bug_events"} & set(sim.stats)
    # requests made before the loop gets to them are one restart
    assert sim.request_restart() + 1 == sim.request_restart()
    restarted(sim)
    assert sim.stats["restarts"] == 2


@pytest.mark.realtime
def test_sighup_restarts_a_hung_simulator_over_a_pty(tmp_path):
    stats_file = tmp_path / "stats.json"
    with spawned("--pty", "--profile", PROFILE, "--bug", "long-frame-hang", "--stats", str(stats_file)) as (url, proc):
        link = Link(url)
        assert link.ask(version_query(1)) is not None
        link.ser.write(LONG)
        assert link.ask(version_query(3), 0.3) is None
        hup = time.monotonic()
        proc.send_signal(signal.SIGHUP)
        # deaf while it boots: a query is worth sending once the broadcast is back
        assert link.pump(1.0, lambda op: not op.is_ack) is not None
        assert ack_code(0, 0, link.ask(version_query(4))) == "not_activated"
        proc.send_signal(signal.SIGTERM)
        end = time.monotonic() + 10
        with contextlib.suppress(serial.SerialException):   # the port goes away when it stops
            while proc.poll() is None and time.monotonic() < end:
                link.pump(0.05)   # read on, so that it drains at once
        link.ser.close()
    stats = json.loads(stats_file.read_text())
    assert stats["restarts"] == 1 and stats["bug_triggers"] == {"long-frame-hang": 1}
    assert stats["acks_sent"] == 2
    after = link.broadcasts(hup)
    assert after and after[0][1] == 0 and after[0][0] >= hup + REBOOT_PAUSE_S - 0.05


def test_running_simulator_restart_brings_a_hung_one_back():
    with api.simulator(PROFILE, bugs=["long-frame-hang"]) as sim:
        link = Link(sim.url)
        try:
            assert link.ask(version_query(1)) is not None
            link.ser.write(LONG[:12])
            assert link.ask(version_query(3), 0.3) is None
            sim.restart()
            assert sim.stats()["restarts"] == 1
            assert link.pump(1.0, lambda op: not op.is_ack) is not None   # booted
            assert link.ask(version_query(4)) is not None
            assert sim.stats()["bug_triggers"] == {"long-frame-hang": 1}
        finally:
            link.ser.close()


def test_running_simulator_restart_of_a_stopped_one_fails_in_time():
    port = PtyTransport()
    try:
        stopped = api.RunningSimulator(Simulator(SimConfig(profile=PROFILE), port), port, PROFILE)
        start = time.monotonic()
        with pytest.raises(RuntimeError, match="did not restart within 0.1 s"):
            stopped.restart(timeout=0.1)
        assert time.monotonic() - start < 0.5
        for bad in (0, -1.0, True, "1", float("nan")):
            with pytest.raises(api.InputError, match="timeout must be"):
                stopped.restart(timeout=bad)
    finally:
        port.close()
