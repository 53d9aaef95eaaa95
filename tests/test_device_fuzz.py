"""`osdkc fuzz --port`: malformed traffic at a flight controller (the
simulator over a real pseudo-terminal), a liveness check after each case.

The simulator is the test target: healthy, it survives every case and the
fuzzer reports no finding; with each planted firmware bug (sim/bugs.py) the
fuzzer finds it within a bounded number of cases, confirms it by replaying
the capture, and minimises it to the bytes that trigger the bug. Safety:
without --allow-motion nothing that moves the aircraft or takes control is
sent; with it, only zero setpoints in a velocity mode; a session ended by
SIGINT or SIGTERM hands control back and restores the rates.
"""
from __future__ import annotations

import itertools
import json
import os
import queue
import signal
import subprocess
import sys
import threading
import time
import xml.etree.ElementTree as ET
from collections import Counter
from pathlib import Path

import struct

import pytest

from osdk_conformance import api
from osdk_conformance.core.capture import TX, CaptureWriter, read_capture
from osdk_conformance.core.deframe import Deframer, Frame, frame_length
from osdk_conformance.core.wire import encode, open_frame
from osdk_conformance.device.active import Commander
from osdk_conformance.device.analysis import Analyzer
from osdk_conformance.device.fuzz_cases import KINDS, MOTION_KINDS, ZERO_VELOCITY_MODES, cases, safe
from osdk_conformance.device.fuzz_report import REPRO_FORMAT, results_of, write_findings
from osdk_conformance.device.fuzz_session import FuzzSession, SessionOptions
from osdk_conformance.device.hostload import HostClock, HostLoad
from osdk_conformance.device.liveness import SYMPTOMS, LivenessOptions
from osdk_conformance.device.port import Port
from osdk_conformance.sim.bugs import RECEIVE_BUFFER
from osdk_conformance.sim.simulator import SimConfig, Simulator, spawned
from osdk_conformance._construct.control import encode_movement_control

PROFILE = "a3-fw3.1"
DOCS = Path(__file__).resolve().parent.parent / "docs" / "DEVICE-FUZZING.md"
CLI = [sys.executable, "-m", "osdk_conformance.cli", "fuzz"]


# ---- the cases -------------------------------------------------------------


@pytest.mark.slow
def test_cases_are_reproducible_by_seed_and_every_kind_comes_early():
    first = list(itertools.islice(cases(PROFILE, 5), 300))
    assert first == list(itertools.islice(cases(PROFILE, 5), 300))
    assert first != list(itertools.islice(cases(PROFILE, 6), 300))
    assert len({c.id for c in first}) == len(first)
    # round-robin: every kind but movement control within the first round
    assert {c.kind for c in first[:len(KINDS)]} == set(KINDS) - MOTION_KINDS
    assert all(c.writes and all(c.writes) for c in first)


@pytest.mark.slow
def test_no_case_could_move_the_aircraft_or_take_control_without_allow_motion():
    withheld: dict[str, int] = {}
    sent = list(itertools.islice(cases(PROFILE, 1, withheld=withheld), 3000))
    assert withheld, "the vectors hold movement frames: some cases must be withheld"
    for c in sent:
        assert safe(c.data), c.id
        for i in range(len(c.data)):   # every start byte read as a frame
            if c.data[i] == 0xAA and len(c.data) > i + 13 and c.data[i + 12] == 0x01:
                assert c.data[i + 13] == 0x00 and (len(c.data) == i + 14 or c.data[i + 14] == 0), c.id


def test_the_safety_filter():
    zero = encode_movement_control(0x48, 0.0, -0.0, 0.0, 0.0)
    moving = encode_movement_control(0x48, 0.5, 0.0, 0.0, 0.0)
    movement = encode(cmd_set=1, cmd_id=3, value=zero)
    assert not safe(movement) and safe(movement, allow_motion=True)
    assert not safe(encode(cmd_set=1, cmd_id=3, value=moving), allow_motion=True)
    assert not safe(encode(cmd_set=1, cmd_id=3, value=encode_movement_control(0x40, 0, 0, 0, 0)), allow_motion=True)
    assert not safe(b"noise" + movement[:-1])   # inside garbage, CRC-32 cut off: still withheld
    assert safe(encode(cmd_set=1, cmd_id=0, value=b"\x00"))   # release
    assert not safe(encode(cmd_set=1, cmd_id=0, value=b"\x01"))   # obtain
    assert not safe(encode(cmd_set=1, cmd_id=0x1A, value=b"\x00"))   # another command of the control set
    motion = list(itertools.islice(cases(PROFILE, 1, allow_motion=True, kinds=("movement.zero",)), 200))
    assert motion and all(c.kind == "movement.zero" for c in motion)
    for c in motion:
        for ev in Deframer().feed(c.data):
            if isinstance(ev, Frame):
                op = open_frame(ev.raw)
                assert op.value[0] in ZERO_VELOCITY_MODES
                assert all(struct.unpack_from("<I", op.value.ljust(17, b"\0"), 1 + 4 * k)[0] & 0x7FFFFFFF == 0
                           for k in range(4))


def test_capture_blocks_carry_their_comment(tmp_path):
    cap = CaptureWriter(tmp_path / "c.pcapng")
    cap.tx(b"\xaa\x01", comment="garbage.7")
    cap.tx(b"\x00")
    cap.rx(b"\x01")
    cap.close()
    records = read_capture(tmp_path / "c.pcapng").records
    assert [(r.direction, r.data, r.comment) for r in records] == [
        (TX, b"\xaa\x01", "garbage.7"), (TX, b"\x00", ""), (0, b"\x01", "")]


def test_deframer_says_how_many_bytes_finish_the_frame_it_waits_for():
    d = Deframer()
    header = encode(seq=1)[:12]
    assert d.needs() == 0
    list(d.feed(b"\x00\xaa"))
    assert d.needs() == 11
    long = bytearray(header)
    long[1:3] = (400).to_bytes(2, "little")
    from osdk_conformance.core.crc import crc16
    long[10:12] = crc16(bytes(long[:10])).to_bytes(2, "little")
    d = Deframer()
    list(d.feed(bytes(long) + bytes(100)))
    assert d.needs() == 400 - 112
    list(d.feed(bytes(d.needs())))
    assert d.needs() == 0


def test_kinds_and_symptoms_are_documented_word_for_word():
    docs = DOCS.read_text()
    for kind, what in KINDS.items():
        assert f"| `{kind}` | {what} |" in docs, kind
    for name, what in SYMPTOMS.items():
        assert f"| `{name}` | {what} |" in docs, name


# ---- the command line: bad input -------------------------------------------


@pytest.mark.parametrize("args, message", [
    (["--port", "/dev/null", "--profile", PROFILE, "--impl", "construct"], "--impl: only for fuzzing implementations"),
    (["--port", "/dev/null"], "--port needs exactly one --profile"),
    (["--port", "/dev/null", "--profile", PROFILE, "--profile", "m100-fw3.1"], "exactly one --profile"),
    (["--replay", "x.json"], "--replay needs --port"),
    (["--port", "/nonexistent/tty", "--profile", PROFILE, "--no-capture"], "cannot open port /nonexistent/tty"),
])
def test_usage_errors_exit_2_with_one_line(args, message, tmp_path):
    done = subprocess.run(CLI + args, capture_output=True, text=True, cwd=tmp_path, timeout=60)
    assert done.returncode == 2, done.stderr
    assert message in done.stderr and "Traceback" not in done.stderr
    assert len(done.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "captures").exists()


@pytest.mark.parametrize("content, message", [
    ("{", "not a reproducer file (not JSON"),
    ('{"format": "other"}', "not a reproducer file"),
    (json.dumps({"format": REPRO_FORMAT, "profile": "m100-fw3.1", "cases": []}), "for profile m100-fw3.1"),
    (json.dumps({"format": REPRO_FORMAT, "profile": PROFILE, "cases": [{"id": 1}]}), "damaged reproducer"),
])
def test_a_bad_reproducer_is_refused_before_the_port_is_opened(content, message, tmp_path):
    (tmp_path / "r.json").write_text(content)
    done = subprocess.run(CLI + ["--port", "/nonexistent/tty", "--profile", PROFILE, "--replay", "r.json"],
                          capture_output=True, text=True, cwd=tmp_path, timeout=60)
    assert done.returncode == 2 and message in done.stderr and "Traceback" not in done.stderr


# ---- sessions against the simulator ----------------------------------------


def run_session(sim, tmp: Path, key: bytes | None = None, encrypt: bool = False, host: HostClock | None = None,
                rate_window: float = 1.0, **options):
    """A session in this process against `sim` over its pty, at 921600 baud."""
    an = Analyzer(PROFILE, key)
    port = Port(sim.url, 921600, an)
    port.open(start=False)
    cap = CaptureWriter(tmp / "fuzz.pcapng")
    port.start(cap)
    live = LivenessOptions(ack_timeout=0.3, stall_timeout=0.5, rate_window=rate_window)
    opts = SessionOptions(profile=PROFILE, seed=1, baud=921600, liveness=live, recover_timeout=3.0,
                          **options)

    def restart():
        try:
            sim.restart()
        except RuntimeError as e:
            return str(e)
        return None
    session = FuzzSession(port, an, opts, Commander(port, an, PROFILE, key, encrypt, ack_timeout=0.3), cap.path,
                          restart, host=host)
    try:
        out = session.run()
    finally:
        port.close()
        cap.close()
    return session, out


def sent_frames(path: Path) -> list:
    d = Deframer()
    return [open_frame(ev.raw) for r in read_capture(path).records if r.direction == TX
            for ev in d.feed(r.data) if isinstance(ev, Frame)]


@pytest.mark.realtime
def test_a_healthy_simulator_survives_every_kind_and_gives_no_finding(tmp_path):
    with api.simulator(PROFILE) as sim:
        session, out = run_session(sim, tmp_path, max_cases=400)
        stats, authority = sim.stats(), sim.authority()
    assert out.start_problem == "" and out.findings == [] and out.stopped == ""
    # one check per case, and one more when the last cases came within a rate window of a rate change
    assert sum(out.sent.values()) == 400 and out.checks in (400, 401)
    assert set(out.sent) == set(KINDS) - MOTION_KINDS
    assert stats["restarts"] == 0 and stats["movement_commands"] == 0
    assert authority["control"] == "rc" and authority["rates"] == authority["initial_rates"]
    # every case is in the capture under its id; the frequency cases were undone at the end too
    comments = Counter(r.comment for r in read_capture(tmp_path / "fuzz.pcapng").records if r.direction == TX)
    assert sum(1 for c in comments if c.count(".") and c.split(".")[0] in {k.split(".")[0] for k in KINDS}
               and not c.startswith(("liveness", "padding"))) == 400
    assert [r.id for r in session.cleanup.results] == ["active.control_release", "active.frequency_restore"]
    assert session.cleanup.results[1].status == "pass"
    assert not any(op.cmd_set == 1 and (op.cmd_id != 0 or op.value[:1] not in (b"", b"\0"))
                   for op in sent_frames(tmp_path / "fuzz.pcapng"))


@pytest.mark.realtime
@pytest.mark.parametrize("bug", [pytest.param("long-frame-hang", marks=pytest.mark.slow), "header-only-reset",
                                 "unknown-cmd-silence"])
def test_each_planted_bug_is_found_confirmed_and_minimised(bug, tmp_path):
    with api.simulator(PROFILE, bugs=[bug]) as sim:
        session, out = run_session(sim, tmp_path, max_cases=200, max_findings=1)
        stats = sim.stats()
    assert stats["bug_triggers"][bug] >= 2   # found, then triggered again by the replays
    [f] = out.findings
    assert f.confirmed is True and f.from_capture
    # the kinds take turns; the vector kinds reach a long frame later since the vectors grew (issue 25)
    assert sum(out.sent.values()) <= 6 * len(out.sent), "found within the first six rounds of the kinds"
    [case] = f.reproducer
    data = case.data
    if bug == "long-frame-hang":
        assert set(f.check.symptoms) >= {"no_ack", "broadcast_stopped"}
        assert len(data) == 12 and frame_length(data) > RECEIVE_BUFFER
    elif bug == "header-only-reset":
        assert "reset" in f.check.symptoms
        assert len(data) == 12 and frame_length(data) == 12
    else:
        assert f.check.symptoms == ["no_ack"]
        [frame] = [ev for ev in Deframer().feed(data) if isinstance(ev, Frame)]
        assert len(frame.raw) == len(data) and open_frame(frame.raw).cmd_set not in (0, 1, 2)
    paths = write_findings(out, tmp_path / "findings", PROFILE, 1, {})
    repro = json.loads(paths[1].read_text())
    assert repro["format"] == REPRO_FORMAT and repro["minimised"] and repro["cases"][0]["writes"] == [data.hex()]
    [vectors] = (tmp_path / "findings").glob("*.vectors.json")
    done = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "run", "--impl", "construct", "--vectors",
                           str(vectors)], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stdout + done.stderr


@pytest.mark.slow
@pytest.mark.realtime
def test_the_command_line_finds_replays_and_reports(tmp_path):
    """The whole command against `osdkc sim` processes: --restart-cmd with
    kill -HUP, reproducer, --replay against a buggy and a healthy simulator,
    JUnit and HTML."""
    with spawned("--bug", "long-frame-hang", "--link", str(tmp_path / "fc")) as (url, proc):
        done = subprocess.run(CLI + ["--port", url, "--profile", PROFILE, "--kind", "length", "--cases", "30",
                                     "--seed", "3", "--baud", "921600", "--ack-timeout", "0.3",
                                     "--restart-cmd", f"kill -HUP {proc.pid}", "--max-findings", "1",
                                     "--findings-dir", "found", "--capture", "f.pcapng", "--junit", "f.xml",
                                     "--html", "f.html"], capture_output=True, text=True, cwd=tmp_path, timeout=120)
    assert done.returncode == 1, done.stdout + done.stderr
    assert "FOUND 1: " in done.stdout and "minimised to 1 case(s), 12 byte(s)" in done.stdout
    [repro] = (tmp_path / "found").glob("*.repro.json")
    suite = ET.parse(tmp_path / "f.xml").getroot()
    failures = [tc.get("name") for tc in suite.iter("testcase") if tc.find("failure") is not None]
    assert "fuzz.finding.1" in failures and "fuzz.cases.length" in failures
    html = (tmp_path / "f.html").read_text()
    assert "Liveness timeline" in html and "<svg" in html
    comments = {r.comment for r in read_capture(tmp_path / "f.pcapng").records if r.direction == TX}
    assert "length.1" in comments and any(c.startswith("finding 1 trial") for c in comments)
    for bugs, status, word in (([], 0, "NOT REPRODUCED: "), (["--bug", "long-frame-hang"], 1, "REPRODUCED: ")):
        with spawned(*bugs) as (url, _):
            again = subprocess.run(CLI + ["--port", url, "--profile", PROFILE, "--replay", str(repro),
                                          "--ack-timeout", "0.3", "--no-capture"],
                                   capture_output=True, text=True, cwd=tmp_path, timeout=60)
        assert again.returncode == status and f"osdkc fuzz: {word}" in again.stdout, again.stdout + again.stderr


def _wait_for_a_movement_command(capture: Path, proc: subprocess.Popen, timeout: float = 30) -> None:
    """Until the capture being written holds a movement command sent (a fixed
    wait missed them on a loaded machine: none had gone out after 2 s)."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline and proc.poll() is None:
        try:
            if any((op.cmd_set, op.cmd_id) == (1, 3) for op in sent_frames(capture)):
                return
        except (OSError, ValueError):
            pass   # not written yet, or its last block still being written
        time.sleep(0.2)
    raise AssertionError(f"no movement command in {capture} after {timeout} s")


def _interrupt(tmp: Path, sig: int, extra: tuple[str, ...]) -> tuple[int, dict, str, list]:
    stats = tmp / "sim.json"
    with spawned("--stats", str(stats), "--app-id", "7") as (url, _):
        proc = subprocess.Popen(CLI + ["--port", url, "--profile", PROFILE, "--cases", "100000", "--seed", "2",
                                       "--capture", "f.pcapng", "--junit", "f.xml", "-q",
                                       *extra], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=tmp)
        q: queue.Queue = queue.Queue()
        threading.Thread(target=lambda: [q.put(line) for line in proc.stderr] + [q.put(None)], daemon=True).start()
        while True:
            line = q.get(timeout=30)
            assert line is not None, "the session ended before it could be interrupted"
            if "capturing to" in line:
                break
        _wait_for_a_movement_command(tmp / "f.pcapng", proc)   # the interrupt falls inside the motion session
        os.kill(proc.pid, sig)
        out, _ = proc.communicate(timeout=60)
    return proc.returncode, json.loads(stats.read_text()), out, sent_frames(tmp / "f.pcapng")


@pytest.mark.realtime
@pytest.mark.parametrize("sig, status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_an_interrupted_motion_session_releases_control_and_restores_the_rates(sig, status, tmp_path):
    code, stats, out, frames = _interrupt(tmp_path, sig, ("--allow-motion", "--yes", "--app-id", "7",
                                                          "--kind", "movement.zero", "--kind", "command.frequency",
                                                          "--kind", "generated.frame"))
    assert code == status, out
    assert f"INTERRUPTED by {signal.Signals(sig).name}" in out
    assert stats["control"] == "rc" and stats["rates"] == stats["initial_rates"]
    assert stats["movement_commands"] > 0
    # after the last movement command: release control, then the rates set back
    last_move = max(i for i, op in enumerate(frames) if (op.cmd_set, op.cmd_id) == (1, 3))
    tail = [(op.cmd_set, op.cmd_id, op.value[:1]) for op in frames[last_move + 1:]
            if not op.is_ack and op.cmd_set in (0, 1)]
    assert (1, 0, b"\x00") in tail and tail[-1][:2] == (0, 0x10)
    for op in frames:
        if (op.cmd_set, op.cmd_id) == (1, 3):
            assert op.value[0] in ZERO_VELOCITY_MODES
    suite = ET.parse(tmp_path / "f.xml").getroot()
    names = {tc.get("name"): tc for tc in suite.iter("testcase")}
    assert names["run.complete"].find("error") is not None
    assert names["active.control_release"].find("failure") is None


@pytest.mark.slow
@pytest.mark.realtime
def test_a_device_that_goes_away_mid_session_ends_it_with_a_finding_not_a_traceback(tmp_path):
    with spawned() as (url, sim):
        proc = subprocess.Popen(CLI + ["--port", url, "--profile", PROFILE, "--cases", "100000", "--seed", "4",
                                       "--capture", "f.pcapng", "--junit", "f.xml", "--recover-timeout", "1",
                                       "--ack-timeout", "0.3", "-q"],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=tmp_path)
        threading.Event().wait(2.5)
        sim.kill()
        out, err = proc.communicate(timeout=60)
    assert proc.returncode == 1, out + err
    assert "Traceback" not in err and ("the port went down" in out or "did not come back" in out), out
    suite = ET.parse(tmp_path / "f.xml").getroot()
    assert any(tc.find("failure") is not None for tc in suite.iter("testcase"))
    assert read_capture(tmp_path / "f.pcapng").records


@pytest.mark.slow
@pytest.mark.realtime
def test_a_fuzzer_stopped_by_its_host_makes_no_finding(tmp_path):
    """The fuzzer's process is stopped for 3 s (SIGSTOP, then SIGCONT: what a
    saturated host does to it, only longer) while a healthy simulator goes on
    broadcasting. Before, 2 sessions in 3 reported FOUND 1, "the broadcast
    slowed", NOT confirmed: the frames lost in the full pty meanwhile were
    counted as frames the FC did not send."""
    # at the default 230400 baud: at 921600 the simulator, beside the suite's other work, once read the cases
    # more slowly than the paced writes came, and a write timed out: a port error, not what this test is about
    with spawned() as (url, _):
        proc = subprocess.Popen(CLI + ["--port", url, "--profile", PROFILE, "--seconds", "7",
                                       "--seed", "1", "--no-capture", "-q"],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=tmp_path)
        time.sleep(2.5)   # started (about 0.5 s) and fuzzing
        os.kill(proc.pid, signal.SIGSTOP)
        time.sleep(3.0)
        os.kill(proc.pid, signal.SIGCONT)
        out, err = proc.communicate(timeout=120)
    assert proc.returncode in (0, 3), out + err
    assert "FAIL " not in out and "FOUND" not in out.replace("NOTHING FOUND", ""), out
    if proc.returncode == 3:
        assert "osdkc fuzz: INCONCLUSIVE: " in out and "host too busy: fuzz.host" in out, out


class FixedHost(HostClock):
    """A host whose load is given, not measured."""

    def __init__(self, load: HostLoad) -> None:
        super().__init__()
        self.fixed = load

    def load(self) -> HostLoad:
        return self.fixed


@pytest.mark.realtime
@pytest.mark.parametrize("load1", [0.2, 5.0], ids=("idle", "busy"))
def test_a_broadcast_slow_from_the_start_is_no_finding(load1, tmp_path):
    """The device broadcasts at 10 Hz where 100 are configured, before any
    case. On an idle host the fuzzer checks it with no case sent, finds it
    just as slow and ends the session: not a case's doing. On a busy host a
    live but slower broadcast is what a starved simulator shows, and is not
    judged."""
    # Only kinds that never carry a whole set frequency: after one the session restores the profile's
    # default rates, and the simulator no longer broadcasts at 10 Hz (on a fast machine such a case came
    # before the first 1 s rate window had passed, and the rate was never judged). These kinds have 118
    # cases, about 0.4 s: a rate window of 0.25 s (2 or 3 frames at 10 Hz, against 25 configured).
    kinds = ("header", "length", "garbage")
    with api.simulator(PROFILE, rates={item: 10 for item in api.broadcast_items(PROFILE)}) as sim:
        session, out = run_session(sim, tmp_path, kinds=kinds, rate_window=0.25, max_cases=60,
                                   host=FixedHost(HostLoad(cores=2, load1=load1, cpu_s=0.0, wall_s=1.0)))
    assert out.findings == [] and out.start_problem == ""
    results = {r.id: r for r in results_of(out, {})}
    stalls = session.port.port.state.host_stalls
    if load1 >= 2:
        assert out.unwell == "" and not any(j.replayed for j in out.not_judged)
        # every check found the slow broadcast and left it unjudged; or this test host, loaded on top of the
        # load it claims, left the reader unscheduled and the late frames' bursts looked fast enough (a CI run
        # sent all 60 cases that way, as the idle case below has too): no finding either way
        assert out.not_judged or stalls, out
        assert sum(out.sent.values()) == 60
        if out.not_judged:
            host = results["fuzz.host"]
            assert host.status == "skip" and host.kind == "host too busy"
            assert "load average 5.00 on 2 cores" in host.message
        else:
            assert "fuzz.host" not in results and results["fuzz.liveness"].status == "pass"
    elif out.not_judged or (not out.unwell and stalls):
        # the idle host was busy after all: this test host left the reader unscheduled for 0.5 s or more.
        # Frames read late arrive in a burst, so the slow broadcast may even have looked fast enough (a
        # lone-clone CI run sent all 60 cases that way): either way, no finding, which is what must hold
        assert stalls, out.not_judged
    else:
        assert "no case sent" in out.unwell
        assert out.unwell_host == "" or stalls   # (as above)
        health = results["fuzz.health"]
        assert health.status == ("skip" if out.unwell_host else "error") and "not a case's doing" in health.message
        # the session ended there; on a fast host every case went out within the first rate window, and the
        # session judged the rate once that window was full
        assert sum(out.sent.values()) < 60 or "a full rate window later" in out.unwell, out.unwell


@pytest.mark.realtime
@pytest.mark.parametrize("rate", [None, 10], ids=("healthy", "slow"))
def test_a_session_shorter_than_its_rate_window_still_judges_the_rate(rate, tmp_path):
    """Three cases go out in a few milliseconds, well within the 1 s rate
    window: the session waits for the window to fill and checks once more,
    so a slow broadcast is seen and a healthy one is passed on a rate it
    measured, not on none."""
    rates = {item: rate for item in api.broadcast_items(PROFILE)} if rate else None
    with api.simulator(PROFILE, rates=rates) as sim:
        session, out = run_session(sim, tmp_path, kinds=("header",), max_cases=3,
                                   host=FixedHost(HostLoad(cores=2, load1=0.2, cpu_s=0.0, wall_s=1.0)))
    assert sum(out.sent.values()) == 3 and out.findings == []
    if rate is None:
        assert out.checks == 4 and out.unwell == "" and out.seconds >= 1.0
        assert results_of(out, {})[-1].status == "pass"
    elif not session.port.port.state.host_stalls:   # (a reader left unscheduled may read a burst as fast)
        assert out.checks == 4 and out.unwell.startswith("after header.3: the broadcast slowed"), out.unwell
        assert "over 1 s" in out.unwell and "not a case's doing" in out.unwell


def test_the_analyzer_forgets_what_a_long_session_no_longer_needs():
    an = Analyzer(PROFILE)

    class Wire:   # the simulator's side of a port, in memory
        sent = bytearray()

        def connected(self):
            return True

        def write(self, data):
            self.sent += data
            return len(data)

        def pending_input(self):
            return 0

        def speed(self):
            return None
    s = Simulator(SimConfig(profile=PROFILE), Wire())
    for i in range(20):
        s.emit_broadcast(float(i))
    frames = [ev.raw for ev in Deframer().feed(bytes(s.t.sent)) if isinstance(ev, Frame)]
    for i, raw in enumerate(frames):
        an.feed_rx(100.0 + i, raw)
    an.feed_tx(100.0, encode(cmd_set=0, cmd_id=0, value=b"\0", session=2, seq=9))
    assert len(an.bcast) == 20 and an.sent
    assert an.forget_before(110.0) == 10
    assert len(an.bcast) == 10 and an.bcast[0][0] == 110.0 and not an.sent
    assert all(len(an.item_times[i]) == len(an.item_clock[i]) <= 10 for i in an.item_times)


def test_a_reproducer_that_could_move_the_aircraft_is_refused(tmp_path):
    movement = encode(cmd_set=1, cmd_id=3, value=encode_movement_control(0x48, 5.0, 0, 0, 0), session=0)
    obtain = encode(cmd_set=1, cmd_id=0, value=b"\x01", session=2, seq=3)
    for data, flags in ((movement, []), (obtain, []), (movement, ["--allow-motion"])):
        doc = {"format": REPRO_FORMAT, "profile": PROFILE, "cases": [{"id": "x.1", "kind": "x", "writes": [data.hex()]}]}
        (tmp_path / "r.json").write_text(json.dumps(doc))
        done = subprocess.run(CLI + ["--port", "/nonexistent/tty", "--profile", PROFILE, "--replay", "r.json", *flags],
                              capture_output=True, text=True, cwd=tmp_path, timeout=60)
        assert done.returncode == 2 and "could move the aircraft or take control" in done.stderr, done.stderr


@pytest.mark.parametrize("args, message", [
    (["--kind", "movement.zero"], "--kind movement.zero needs --allow-motion"),
    (["--app-id", "5"], "--app-id needs --allow-motion"),
])
def test_motion_options_need_allow_motion(args, message, tmp_path):
    done = subprocess.run(CLI + ["--port", "/nonexistent/tty", "--profile", PROFILE, *args],
                          capture_output=True, text=True, cwd=tmp_path, timeout=60)
    assert done.returncode == 2 and message in done.stderr, done.stderr


@pytest.mark.realtime
def test_movement_cases_alone_send_nothing_when_control_is_refused(tmp_path):
    with spawned("--app-id", "7") as (url, _):   # activation with another app id is refused
        done = subprocess.run(CLI + ["--port", url, "--profile", PROFILE, "--allow-motion", "--yes", "--app-id", "8",
                                     "--kind", "movement.zero", "--cases", "50", "--no-capture", "--ack-timeout",
                                     "0.3"], capture_output=True, text=True, cwd=tmp_path, timeout=60)
    assert done.returncode == 1 and "NOTHING FUZZED: 0 cases" in done.stdout, done.stdout
    assert "control authority was refused" in done.stderr and "no case kind left to send" in done.stdout


KEY = bytes(range(32))


@pytest.mark.realtime
def test_an_encrypted_link_is_fuzzed_with_the_key_and_refused_without_it(tmp_path):
    with api.simulator(PROFILE, key=KEY, encrypt=True) as sim:
        _, blind = run_session(sim, tmp_path, max_cases=20)
        session, out = run_session(sim, tmp_path, key=KEY, encrypt=True, max_cases=60)
    assert blind.start_problem.startswith("no broadcast frame") and not blind.sent
    assert out.start_problem == "" and out.findings == [] and sum(out.sent.values()) == 60
    probes = [op for op in sent_frames(tmp_path / "fuzz.pcapng") if op.encrypted]
    assert probes, "the probes and the session's commands go out encrypted"


@pytest.mark.parametrize("args, env, message", [
    (["--key-env", "OSDKC_TEST_KEY"], {"OSDKC_TEST_KEY": "zz"}, "the app key must be 64 hex characters"),
    (["--encrypt"], {}, "--encrypt needs --key-env"),
])
def test_a_bad_key_is_a_usage_error(args, env, message, tmp_path):
    done = subprocess.run(CLI + ["--port", "/nonexistent/tty", "--profile", PROFILE, *args], capture_output=True,
                          text=True, cwd=tmp_path, timeout=60, env={**os.environ, **env})
    assert done.returncode == 2 and message in done.stderr and "Traceback" not in done.stderr
