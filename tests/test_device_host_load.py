"""A busy host never turns a healthy flight controller red (issue 26): the
passive checks that arrival times can fool judge the FC on its own time
stamps, and say what the host did instead of blaming the FC.

Streams here are built frame by frame: the FC's time stamps on a steady
100 Hz clock (or not), and arrival times as a host delivers them (on time,
in a late burst after it was not scheduled, or not at all for a while)."""
from __future__ import annotations

import pytest

from osdk_conformance.core.wire import encode
from osdk_conformance.device.analysis import Analyzer
from osdk_conformance.device.checks import Options, passive_results
from osdk_conformance.device.hostload import HostLoad
from osdk_conformance.device.port import LinkState
from osdk_conformance.sim.simulator import SimConfig, Simulator

PROFILE = "a3-fw3.1"
PERIOD = 0.01
FRAMES = 500
IDLE = HostLoad(cores=2, load1=0.3, cpu_s=0.4, wall_s=5.0)
BUSY = HostLoad(cores=2, load1=4.2, cpu_s=0.9, wall_s=5.0)


def run_checks(stamps: list[float], arrivals: list[float], host: HostLoad | None,
               items: tuple[str, ...] | None = None) -> dict[str, tuple[str, str]]:
    """The passive results of frames whose time stamp items say `stamps` and
    which the host read at `arrivals` (all frames at 100 Hz)."""
    sim = Simulator(SimConfig(profile=PROFILE), transport=None)
    items = list(items or sim.profile.flag_bits)
    rates = {i: (100 if i in items else 0) for i in sim.profile.flag_bits}
    an = Analyzer(PROFILE, expect_rates=rates)
    for seq, (stamp, t) in enumerate(zip(stamps, arrivals)):
        an.feed_rx(t, encode(cmd_set=2, cmd_id=0, value=sim.broadcast_value(items, stamp, stamp), seq=seq))
    an.finish()
    link = LinkState(t_open=arrivals[0] - 0.05, t_end=arrivals[-1] + 0.02)
    opts = Options(PROFILE, duration=arrivals[-1] - arrivals[0], host=host)
    return {r.id: (r.status, r.message) for r in passive_results(an, opts, link)}


def steady(n: int = FRAMES, t0: float = 100.0) -> list[float]:
    return [t0 + k * PERIOD for k in range(n)]


def host_paused(pause: float, at: int = 250) -> list[float]:
    """Arrival times of a host that was not scheduled for `pause` s: the
    frames sent meanwhile are read in one burst when it runs again."""
    out = steady()
    resume = out[at] + pause
    return [max(t, resume) if k >= at and t < resume else t for k, t in enumerate(out)]


@pytest.mark.parametrize("host", [BUSY, IDLE, None], ids=("busy", "idle", "replay"))
def test_a_host_that_was_not_scheduled_does_not_fail_the_fc(host):
    checks = run_checks(steady(), host_paused(0.3), host)
    assert checks["stream.jitter"][0] == "pass", checks["stream.jitter"]
    assert "FC time stamps spread" in checks["stream.jitter"][1]
    assert "not the flight controller" in checks["stream.jitter"][1]
    if host is not None:
        assert f"load average {host.load1:.2f}" in checks["stream.jitter"][1]
    assert checks["stream.rates"][0] == "pass", checks["stream.rates"]


def test_a_silence_of_the_host_is_not_a_stall_of_the_fc():
    checks = run_checks(steady(), host_paused(1.6), BUSY)
    assert checks["link.stall"][0] == "pass", checks["link.stall"]
    assert "the host read nothing for 1.6" in checks["link.stall"][1]
    assert "kept sending" in checks["link.stall"][1]


def test_an_fc_that_stops_sending_is_still_a_stall():
    stamps = steady()
    stamps = stamps[:250] + [t + 1.6 for t in stamps[250:]]   # its own clock shows the silence too
    checks = run_checks(stamps, stamps, IDLE)
    assert checks["link.stall"][0] == "fail" and "stalled" in checks["link.stall"][1]


def test_an_fc_whose_own_time_stamps_jitter_fails_on_any_host():
    stamps = [t + (0.04 if k % 7 == 3 else 0.0) for k, t in enumerate(steady())]
    for host in (BUSY, IDLE):
        checks = run_checks(stamps, stamps, host)
        assert checks["stream.jitter"][0] == "fail", checks["stream.jitter"]
        assert "the flight controller's own time stamps spread" in checks["stream.jitter"][1]


def test_without_time_stamps_arrival_spread_is_judged_only_on_an_idle_host():
    items = tuple(i for i in Simulator(SimConfig(profile=PROFILE), None).profile.flag_bits if i != "time_stamp")
    arrivals = host_paused(0.3)
    busy = run_checks(steady(), arrivals, BUSY, items)["stream.jitter"]
    assert busy[0] == "skip" and "cannot be told from the host's" in busy[1] and "load average 4.20" in busy[1]
    assert run_checks(steady(), arrivals, None, items)["stream.jitter"][0] == "skip"
    idle = run_checks(steady(), arrivals, IDLE, items)["stream.jitter"]
    assert idle[0] == "fail" and "on an idle host" in idle[1]
    assert run_checks(steady(), steady(), BUSY, items)["stream.jitter"][0] == "pass"


def test_a_reader_that_was_not_scheduled_withholds_the_timed_checks_only():
    from osdk_conformance.device.hostload import HOST_TOO_BUSY, withheld
    from osdk_conformance.device.verdict import INCONCLUSIVE, PASSED, acceptance_word, counts
    from osdk_conformance.harness.report import FAIL, PASS, SKIP, Result

    results = [Result("stream", "stream.sequence", FAIL, "2 SEQ gaps (148 frames missing)"),
               Result("link", "link.crc", FAIL, "3 frames with a bad CRC"),
               Result("stream", "stream.flags", PASS, "every flag word as configured")]
    assert withheld(results, [], BUSY) == results
    out = withheld(results, [(1000.0, 1.9), (1003.0, 0.6)], BUSY)
    assert [r.status for r in out] == [SKIP, FAIL, PASS]
    assert out[0].kind == HOST_TOO_BUSY
    assert out[0].message.startswith("not judged: this host did not read the port for up to 1.9 s (2 time(s); "
                                     "load average 4.20 on 2 cores")
    assert out[0].message.endswith("Measured: 2 SEQ gaps (148 frames missing)")
    only_timed = withheld(results[:1] + results[2:], [(1000.0, 1.9)], BUSY)
    assert acceptance_word(True, None, any(r.kind == HOST_TOO_BUSY for r in only_timed)) == INCONCLUSIVE
    assert acceptance_word(True, None, False) == PASSED
    assert "1 skipped (host too busy: sequence)" in counts(only_timed)


@pytest.mark.realtime
def test_a_judge_stopped_by_its_host_is_inconclusive_not_a_failing_fc(tmp_path):
    """The judge's process is stopped for 3 s (SIGSTOP, then SIGCONT: what a
    saturated host does to it, only longer) while a healthy simulator goes on
    sending: the pty fills, the frames after are lost on this host, and the
    SEQ gap and the rates that follow are not the FC's. Before, the run
    FAILED stream.sequence and stream.rates; now it is INCONCLUSIVE, exit 3,
    and says why."""
    import os
    import signal
    import subprocess
    import sys
    import time

    from osdk_conformance.sim.simulator import spawned

    with spawned("--profile", PROFILE, "--seed", "5") as (url, _):
        proc = subprocess.Popen([sys.executable, "-m", "osdk_conformance.cli", "device", "--port", url, "--profile",
                                 PROFILE, "--duration", "6", "--no-capture", "-q"],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        time.sleep(2.5)   # started (about 0.5 s) and listening
        os.kill(proc.pid, signal.SIGSTOP)
        time.sleep(3.0)   # the pty holds about 1.6 s of this stream
        os.kill(proc.pid, signal.SIGCONT)
        out, err = proc.communicate(timeout=60)
    assert proc.returncode == 3, out + err
    assert "osdkc device: INCONCLUSIVE: " in out and "host too busy" in out
    assert "FAIL " not in out, out


# ---- the fuzzer's liveness check (device/liveness.py) ---------------------------------------------


def liveness_rate(stamps: list[float], arrivals: list[float], seqs: list[int] | None = None,
                  items: tuple[str, ...] | None = None):
    """The broadcast half of `osdkc fuzz --port`'s check, made just after the
    last of these frames arrived (arrival times end now, on the wall clock)."""
    import time

    from osdk_conformance.device.liveness import Check, Liveness, LivenessOptions

    sim = Simulator(SimConfig(profile=PROFILE), transport=None)
    items = list(items or sim.profile.flag_bits)
    an = Analyzer(PROFILE, expect_rates={i: 100 for i in sim.profile.flag_bits})
    frames = [encode(cmd_set=2, cmd_id=0, value=sim.broadcast_value(items, stamp, stamp), seq=seq)
              for seq, stamp in zip(seqs or range(len(stamps)), stamps)]
    shift = time.time() - arrivals[-1] - 0.01
    for t, frame in zip(arrivals, frames):
        an.feed_rx(t + shift, frame)
    # the rate alone: however long this busy test host took to get here, no frame is overdue
    live = Liveness(an, lambda data, comment: None, PROFILE, LivenessOptions(rate_window=2.0, stall_timeout=60.0))
    live.window_start = arrivals[0] + shift
    check = Check(time.time(), "a case")
    live.broadcast(check)
    return check


def test_frames_a_busy_host_lost_are_no_slower_broadcast():
    """A steady 100 Hz FC; the host read only every third frame of the last
    two seconds (the rest were lost in a full buffer while its reader waited):
    on arrival that is 33 frames/s, on the FC's SEQ and clock 100."""
    stamps = steady()
    keep = [k for k in range(FRAMES) if k < 300 or k % 3 == 0]
    check = liveness_rate([stamps[k] for k in keep], [stamps[k] for k in keep], seqs=keep)
    assert "broadcast_slow" not in check.symptoms, check.describe()
    assert check.details["rate_hz"] == pytest.approx(100, abs=1)


def test_a_late_burst_is_no_slower_broadcast():
    """The last second of a steady 100 Hz stream read in one burst at the end."""
    stamps = steady()
    check = liveness_rate(stamps, host_paused(1.0, at=400))
    assert check.ok, check.describe()


def test_an_fc_that_slows_down_is_slow_on_its_own_clock():
    stamps = steady(300) + [steady()[299] + (k + 1) * 0.025 for k in range(80)]   # then 40 Hz
    check = liveness_rate(stamps, stamps)
    assert check.symptoms == ["broadcast_slow"]
    assert "on the flight controller time stamp clock" in check.details["broadcast_slow"]


def test_without_time_stamps_a_slow_arrival_is_a_slow_broadcast():
    keep = [k for k in range(FRAMES) if k < 300 or k % 3 == 0]
    arrivals = [steady()[k] for k in keep]
    items = tuple(i for i in Simulator(SimConfig(profile=PROFILE), transport=None).profile.flag_bits
                  if i != "time_stamp")
    check = liveness_rate(arrivals, arrivals, seqs=keep, items=items)
    assert check.symptoms == ["broadcast_slow"]
    assert "on the arrival clock" in check.details["broadcast_slow"]
