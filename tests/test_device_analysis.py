"""The acceptance receiver (device/analysis.py) decodes with the native
decoder when it is installed and with Construct otherwise (OSDKC_ACCEL):
either way a stream gives the same findings, the same decode errors and the
same values in `latest`, the traces and `on_broadcast`, in the value model."""
from __future__ import annotations

import dataclasses
import functools
import math

import pytest

from osdk_conformance.core.wire import encode
from osdk_conformance.device.analysis import Analyzer
from osdk_conformance.reference import accel
from osdk_conformance.sim.simulator import SimConfig, Simulator

PROFILES = ("a3-fw3.1", "m100-fw2.3")   # with and without cur_mov_control_mode in control_info
T0 = 100.0


def _value(profile: str, implausible: bool = False, **vehicle) -> bytes:
    """A broadcast value carrying every item of the profile."""
    sim = Simulator(SimConfig(profile=profile, implausible=implausible), transport=None)
    for name, v in vehicle.items():
        setattr(sim.vehicle, name, v)
    return sim.broadcast_value(list(sim.profile.flag_bits), sim.start)


@functools.lru_cache(maxsize=None)   # one stream for both runs: the time stamp item carries the host's clock
def _stream(profile: str) -> tuple[bytes, ...]:
    """Plausible frames, implausible ones, non-finite floats, payloads that do
    not decode (broadcast and other commands) and noise between frames."""
    moving = _value(profile, roll=0.1, pitch=-0.05, yaw=0.3, vn=1.1, ve=-0.7, height=12.345)
    bad = _value(profile, implausible=True)
    odd = _value(profile, vn=math.nan, accel=(math.inf, 0.0, -math.inf))
    reserved = moving[:1] + bytes([moving[1] | 0x80]) + moving[2:]   # a reserved flag bit
    frames = [encode(cmd_set=2, cmd_id=0, value=v, seq=s)
              for s, v in enumerate([moving, moving, bad, moving, odd, moving[:1], moving + b"\0", reserved, bad])]
    frames.insert(3, encode(cmd_set=1, cmd_id=3, value=b"\x48\x00", seq=50))       # movement control cut short
    frames.insert(5, b"\x01\x02\x03")                                               # noise
    frames.insert(7, encode(cmd_set=0, cmd_id=0x10, value=bytes(17), seq=51))      # set frequency, a byte too many
    return tuple(frames)


def _run(monkeypatch, profile: str, setting: str) -> tuple[Analyzer, list]:
    monkeypatch.setenv(accel.ENV, setting)
    an = Analyzer(profile)
    seen: list = []
    an.on_broadcast = lambda t, data: seen.append((t, data))
    for k, frame in enumerate(_stream(profile)):
        an.feed_rx(T0 + k / 100, frame)
    an.finish()
    return an, seen


def _kept(an: Analyzer, seen: list) -> dict:
    return {
        "findings": {rule: dataclasses.asdict(f) for rule, f in an.findings.items()},
        # the class of each failure; its detail is worded by whichever decoder ran
        "decode_errors": an.decode_errors,
        "decode_classes": [e.split(":", 1)[0] for e in an.decode_examples],
        "undecoded": an.undecoded_broadcasts, "frames": an.cmd_frames, "incidents": an.incidents,
        "bcast": an.bcast, "item_clock": an.item_clock,
        "latest": an.latest, "traces": an.traces, "on_broadcast": seen,
    }


@pytest.mark.skipif(not accel.available(), reason="the native decoder is not built here")
@pytest.mark.parametrize("profile", PROFILES)
def test_native_and_pure_python_decoding_keep_the_same_values(monkeypatch, profile):
    native, native_seen = _run(monkeypatch, profile, "1")
    python, python_seen = _run(monkeypatch, profile, "0")
    # repr: NaN is not equal to itself, and 0.0 == -0.0 would hide a sign
    assert repr(_kept(native, native_seen)) == repr(_kept(python, python_seen))

    an = python
    f = {rule: (x.samples, x.count) for rule, x in an.findings.items()}
    assert f["quaternion_norm"] == (6, 2) and f["gps_health"] == (6, 2) and f["battery"] == (6, 2)
    assert f["rc_channels"] == (6, 2) and f["flight_status"] == (6, 2) and f["control_info"] == (6, 2)
    assert f["finite"] == (30, 2) and f["time_stamp"] == (5, 1)
    assert an.decode_errors == {"truncated_payload": 2, "length_mismatch": 2, "reserved_bits": 1}
    assert len(an.undecoded_broadcasts) == 3
    assert [i[1:] for i in an.incidents] == [("noise", 3, "3 byte(s) outside any frame")]
    finite = an.findings["finite"].examples
    assert finite[0].endswith(": acceleration [inf, 0.0, -inf]") and finite[1].endswith(": velocity [nan, 0.0, 0.0]")
    assert an.findings["quaternion_norm"].examples[0].endswith(": |q| = 2")
    assert an.findings["control_info"].examples[0].endswith(": control device 5 not defined")

    # the values kept are the value model; the last frame decoded is an implausible one
    ci = an.latest["control_info"][1]
    assert ci["control_device"] == {"value": 5, "name": None}
    assert ("cur_mov_control_mode" in ci) == (profile == "a3-fw3.1")
    assert an.latest["rc"][1]["mode"] == 1234
    assert an.latest["time_stamp"][1]["time"] == 0x7FFFFFFF
    data = python_seen[0][1]
    assert data["battery"] == 90 and data["velocity"]["x"] == {"f32": "0x3f8ccccd", "value": 1.100000023841858}
    assert python_seen[4][1]["velocity"]["x"]["value"] == "NaN"


@pytest.mark.parametrize("cut", [1, 11, 12, 60])
def test_a_run_that_ends_inside_a_frame_counts_no_incident(cut):
    # the last read stopped inside a frame: its start is no error of the device, nor are the rest of its bytes,
    # which the receiver scans again as garbage (0xAA nowhere in them, as an encrypted frame's often are not)
    value = bytes(range(1, 100))
    frames = [encode(cmd_set=2, cmd_id=0x7F, value=value, seq=s) for s in range(3)]
    assert 0xAA not in frames[-1][1:cut]
    an = Analyzer("m100-fw3.1")
    an.feed_rx(T0, b"".join(frames[:-1]) + frames[-1][:cut])
    an.finish()
    assert an.incidents == [] and an.frames == 2, an.incidents
