"""`osdkc sdk host-test`: DJI's own host stack against `osdkc sim`.

Without a checkout of DJI's Onboard-SDK the tests here check what the
command does with trees it cannot use (exit 2 naming the reason), the
field-by-field comparison, and the simulator's broadcast log it compares
against. With OSDK_SRC pointing at a 3.1.x checkout they also build the
SDK's host stack and run whole sessions, and interrupt one.
"""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest
import serial

from osdk_conformance import cli
from osdk_conformance.sdk import host as sdk_host
from osdk_conformance.core.deframe import Frame, deframe
from osdk_conformance.core.wire import open_frame
from osdk_conformance.sim.simulator import spawned

OSDK_SRC = os.environ.get("OSDK_SRC")
needs_sdk = pytest.mark.skipif(not OSDK_SRC, reason="OSDK_SRC does not point at a checkout of DJI's Onboard-SDK 3.1.x")


def fake_tree(root: Path, version: str = "3.1.9", leave_out: str | None = None,
              layout: sdk_host.Layout31 = sdk_host.LAYOUTS_31[0]) -> Path:
    """A directory with a 3.1.x layout's file names (no SDK code in it)."""
    for rel in layout.required():
        if rel == leave_out:
            continue
        f = root / rel
        f.parent.mkdir(parents=True, exist_ok=True)
        f.write_text(f"/* @version {version} */\n"   # the SDK version constants of the two FW 3.1 profiles
                     "const Version versionM100_31 = (MAKE_VERSION(3, 1, 10, 0));\n"
                     "const Version versionA3_31 = (MAKE_VERSION(3, 1, 100, 0));\n")
    return root


def host_test(capsys, *args: str) -> tuple[int, str]:
    code = cli.main(["sdk", "host-test", *args])
    return code, capsys.readouterr().err


@pytest.mark.parametrize("layout", sdk_host.LAYOUTS_31, ids=("3.1.9", "3.1.8"))
def test_missing_file_is_exit_2_naming_it(tmp_path, capsys, layout):
    for missing in (f"{layout.serial}/LinuxSerialDevice.cpp", f"{layout.src}/DJI_Link.cpp"):
        tree = fake_tree(tmp_path / missing.replace("/", "_"), leave_out=missing, layout=layout)
        code, err = host_test(capsys, "--osdk", str(tree))
        assert code == 2
        assert f"missing {missing}: the 3.1.x host stack cannot be built" in err


def test_unsupported_3_1_layout_version_is_exit_2(tmp_path, capsys):
    code, err = host_test(capsys, "--osdk", str(fake_tree(tmp_path, version="3.2.2")))
    assert code == 2
    assert "Onboard-SDK 3.2.2 is not supported" in err and "3.1.x" in err


def test_later_sdk_layout_is_exit_2_with_its_version(tmp_path, capsys):
    f = tmp_path / sdk_host.NEW_LAYOUT_MARK
    f.parent.mkdir(parents=True)
    f.write_text("/** @version 3.9 */\n")
    code, err = host_test(capsys, "--osdk", str(tmp_path))
    assert code == 2
    assert "Onboard-SDK 3.9 (osdk-core/api layout) is not supported" in err


def test_not_a_checkout_and_no_checkout_are_exit_2(tmp_path, capsys, monkeypatch):
    code, err = host_test(capsys, "--osdk", str(tmp_path))
    assert code == 2 and "not a DJI Onboard-SDK checkout: missing osdk-core/inc/DJI_Version.h" in err
    code, err = host_test(capsys, "--osdk", str(tmp_path / "nowhere"))
    assert code == 2 and "no such directory" in err
    monkeypatch.delenv("OSDK_SRC", raising=False)
    code, err = host_test(capsys)
    assert code == 2 and "needs --osdk DIR" in err


def test_profile_the_sdk_cannot_speak_is_exit_2(tmp_path, capsys):
    code, err = host_test(capsys, "--osdk", str(fake_tree(tmp_path)), "--profile", "m100-fw2.3")
    assert code == 2 and "supports m100-fw3.1, a3-fw3.1" in err


def test_build_error_is_exit_2_with_the_compiler_output(tmp_path, capsys):
    # the fake tree's "sources" are not C++: the compiler's complaint is the message
    code, err = host_test(capsys, "--osdk", str(fake_tree(tmp_path / "sdk")), "--out", str(tmp_path / "out"))
    assert code == 2
    assert "failed (" in err and "error" in err


def sent_frames(profile: str, count: int) -> list[tuple[int, bytes]]:
    """SEQ and value of broadcast frames built the way the simulator builds them."""
    from osdk_conformance.sim.simulator import SimConfig, Simulator

    class Nowhere:
        def connected(self) -> bool:
            return False

    sim = Simulator(SimConfig(profile=profile), Nowhere())
    items = list(sim.profile.flag_bits)
    return [(seq, sim.broadcast_value(items, time.monotonic())) for seq in range(count)]


def decoded_as_sent(profile: str, seq: int, value: bytes) -> dict:
    flags, fields = sdk_host.spec_fields(profile, value)
    return {"ev": "bc", "seq": seq, "flags": flags, "f": dict(fields)}


def test_comparison_finds_a_flipped_bit_a_lost_frame_and_an_unknown_one(tmp_path):
    frames = sent_frames("a3-fw3.1", 5)
    log = tmp_path / "sent.jsonl"
    log.write_text("".join(json.dumps({"seq": s, "value": v.hex()}) + "\n" for s, v in frames))
    decoded = [decoded_as_sent("a3-fw3.1", s, v) for s, v in frames]
    clean = sdk_host.compare("a3-fw3.1", log, decoded)
    assert (clean.compared, clean.mismatched_frames, clean.lost, clean.unknown) == (5, 0, 0, 0)
    assert {"gps_detail", "rtk_detail", "control_info"} <= clean.items

    decoded[1]["f"]["rtk_detail.latitude"] ^= 1          # lowest mantissa bit of a double
    decoded[3]["f"]["gimbal.pitch"] ^= 1 << 31           # sign of a float
    decoded[4]["f"].pop("control_info.control_device")   # a field the SDK did not decode
    del decoded[2]
    decoded.append(dict(decoded[0], seq=99))
    bad = sdk_host.compare("a3-fw3.1", log, decoded)
    assert (bad.compared, bad.mismatched_frames, bad.lost, bad.unknown) == (4, 3, 1, 1)
    text = " | ".join(bad.mismatches)
    assert "SEQ 1: rtk_detail.latitude" in text and "SEQ 3: gimbal.pitch" in text
    assert "control_info.control_device: sent 0, SDK nothing" in text


def test_a_session_that_stops_early_fails_every_later_step_with_the_reason():
    s = sdk_host.Session(steps={"open": {"step": "open", "ok": False, "detail": "could not open /dev/nothing"}},
                         exit_code=1)
    steps = sdk_host._verdicts("a3-fw3.1", s, sdk_host.Comparison(), {}, 500)
    verdicts = {st.name: (st.verdict, st.detail) for st in steps}
    assert [st.name for st in steps] == list(sdk_host.STEPS)
    assert verdicts["version"] == ("FAIL", "not reached: could not open /dev/nothing")
    assert verdicts["release_control"] == ("FAIL", "not reached: could not open /dev/nothing")
    refused = sdk_host.Session(steps={"obtain_control": {"ok": False, "detail": "ACK codes 0x0000"}}, exit_code=1)
    verdicts = {st.name: st.verdict for st in sdk_host._verdicts("a3-fw3.1", refused, sdk_host.Comparison(), {}, 500)}
    assert verdicts["obtain_control"] == "FAIL" and verdicts["movement"] == verdicts["release_control"] == "SKIP"
    assert verdicts["host_frames"] == "FAIL"   # the simulator heard nothing
    crashed = sdk_host._verdicts("a3-fw3.1", sdk_host.Session(exit_code=-11), sdk_host.Comparison(), {}, 500)
    assert crashed[0].detail == "not reached: the driver was killed by signal 11 (SIGSEGV)"


@pytest.mark.realtime
def test_broadcast_log_holds_every_frame_the_simulator_sent(tmp_path):
    log = tmp_path / "sent.jsonl"
    with spawned("--profile", "a3-fw3.1", "--log-broadcast", str(log)) as (port, _proc):
        with serial.Serial(port, timeout=0.1) as ser:
            data = b""
            end = time.monotonic() + 1.0
            while time.monotonic() < end:
                data += ser.read(4096)
    on_wire = {}
    for ev in deframe([data]):
        if isinstance(ev, Frame):
            op = open_frame(ev.raw)
            if (op.cmd_set, op.cmd_id) == (2, 0):
                on_wire[op.seq] = op.value
    logged = {r["seq"]: bytes.fromhex(r["value"]) for r in map(json.loads, log.read_text().splitlines())}
    assert len(on_wire) >= 20
    assert all(logged[seq] == value for seq, value in on_wire.items())


def test_unwritable_broadcast_log_is_exit_2(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "sim", "--log-broadcast",
                           str(tmp_path / "no" / "such" / "dir.jsonl")], capture_output=True, text=True, timeout=30)
    assert proc.returncode == 2 and "--log-broadcast: cannot write" in proc.stderr


# --------------------------------------------------------------------------
# With DJI's SDK


@needs_sdk
@pytest.mark.slow
@pytest.mark.realtime
def test_sdk_host_stack_runs_a_whole_session_on_every_fw31_profile(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "sdk", "host-test", "--osdk", OSDK_SRC,
                           "--out", str(tmp_path / "build")], capture_output=True, text=True, timeout=600)
    out = proc.stdout
    assert proc.returncode == 0, out + proc.stderr
    for profile in ("m100-fw3.1", "a3-fw3.1"):
        block = out.split(profile + "\n", 1)[1]
        for step in sdk_host.STEPS:
            assert f"PASS  {step}" in block
    assert out.count(": 0 with a mismatch, 0 lost, 0 unknown") == 2
    assert "items acceleration, angular_rate, battery, control_info, flight_status, gimbal, gps_detail" in out
    assert out.count("simulator received 150, 150 of them encrypted") == 2


def _control_device(log: Path) -> int | None:
    lines = log.read_text().splitlines() if log.is_file() else []
    if not lines:
        return None
    try:
        rec = json.loads(lines[-1])
    except ValueError:   # caught mid-line
        return None
    fields = sdk_host.spec_fields("a3-fw3.1", bytes.fromhex(rec["value"]))[1]
    return fields.get("control_info.control_device")


@needs_sdk
@pytest.mark.slow
@pytest.mark.realtime
def test_ctrl_c_in_movement_releases_control_restores_frequencies_and_stops_everything(tmp_path):
    logs = tmp_path / "logs"
    proc = subprocess.Popen([sys.executable, "-m", "osdk_conformance.cli", "sdk", "host-test", "--osdk", OSDK_SRC,
                             "--out", str(tmp_path / "build"), "--log-dir", str(logs), "--profile", "a3-fw3.1",
                             "--frames", "20", "--moves", "5000"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        deadline = time.monotonic() + 240
        while _control_device(logs / "a3-fw3.1.broadcast.jsonl") != 2:   # the onboard computer flies
            assert proc.poll() is None and time.monotonic() < deadline, proc.stderr.read() if proc.poll() else ""
            time.sleep(0.2)
        os.killpg(proc.pid, signal.SIGINT)   # what Ctrl-C at the terminal does
        _, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
    assert proc.returncode == 130, err
    assert "interrupted; release_control PASS" in err
    assert "interrupted; frequency_restore PASS" in err
    assert (logs / "a3-fw3.1.sim-stats.json").is_file()   # the simulator stopped cleanly
    assert not processes_mentioning(str(tmp_path))   # neither the driver nor the simulator is left


def processes_mentioning(text: str) -> list[int]:
    found = []
    for p in Path("/proc").glob("[0-9]*"):
        try:
            if text.encode() in (p / "cmdline").read_bytes():
                found.append(int(p.name))
        except OSError:   # it ended while we looked
            pass
    return found
