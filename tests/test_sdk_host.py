"""`osdkc sdk host-test`: DJI's own host stack against `osdkc sim`.

Without a checkout of DJI's Onboard-SDK the tests here check what the
command does with trees it cannot use (exit 2 naming the reason), the
field-by-field comparison, and the simulator's broadcast log it compares
against, the refused-by-design and wire-ACK verdicts. With OSDK_SRC
pointing at a checkout of 2.3, 3.1.x, 3.2.x or 3.3 to 3.9 they also build
the SDK's host stack and run whole sessions (both baud rates, plain and
encrypted), and interrupt one.
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
needs_sdk = pytest.mark.skipif(not OSDK_SRC, reason="OSDK_SRC does not point at a checkout of DJI's Onboard-SDK "
                                                     "(2.3, 3.1.x, 3.2.x or 3.3 to 3.9)")

# Steps a release fails by its own defect, whatever the flight controller does, and
# what the step's detail then says: 2.3's CoreAPI::setBroadcastFreq turns every code
# of 5 or less into 0 before sending (lib/src/DJI_API.cpp:172-178).
KNOWN_SDK_FAILURES = {
    "2.3": {"frequencies": "CoreAPI::setBroadcastFreq sent codes 0,0,0,0,0,0,0,0,0,0,0,0 for the codes asked, 3,3,",
            "frequency_restore": "CoreAPI::setBroadcastFreq sent codes 0,0,0,0,0,0,0,0,0,0,0,0 for the codes asked"},
}


def fake_tree(root: Path, version: str = "3.1.9", leave_out: str | None = None,
              layout: sdk_host.Layout31 = sdk_host.LAYOUTS_31[0]) -> Path:
    """A directory with a 3.1.x layout's file names (no SDK code in it); the
    marks by which the core family tells 3.1.8 (lib/) and 3.2.2 apart."""
    extra = [f"{layout.inc}/DJICommonType.h"] if layout.inc.startswith("lib/") else []
    for rel in layout.required() + extra:
        if rel == leave_out:
            continue
        f = root / rel
        f.parent.mkdir(parents=True, exist_ok=True)
        f.write_text(f"/* @version {version} */\n"   # the SDK version constants of the two FW 3.1 profiles
                     "const Version versionM100_31 = (MAKE_VERSION(3, 1, 10, 0));\n"
                     "const Version versionA3_31 = (MAKE_VERSION(3, 1, 100, 0));\n"
                     + ("/* notifyCaller */\n" if rel.endswith("DJI_Link.cpp") else "")
                     + ("/* fwVersion */\n" if version == "3.2.2" and rel.endswith("DJI_Type.h") else ""))
    return root


def fake_tree_23(root: Path, leave_out: str | None = None, switches: tuple[str, ...] = ("SDK_VERSION_2_3",)) -> Path:
    """A directory with the file names of 2.3 (lib/, no DJICommonType.h, the
    command-line sample's serial driver) and a DJI_Config.h with `switches`."""
    for rel in [*sdk_host.REQUIRED_23, "lib/inc/DJI_API.h"]:
        if rel == leave_out:
            continue
        f = root / rel
        f.parent.mkdir(parents=True, exist_ok=True)
        f.write_text("/* file name only */\n")
    (root / "lib/inc/DJI_Config.h").write_text("//#define SDK_VERSION_3_1_M100\n"   # a switch left off
                                                + "".join(f"#define {name}\n" for name in switches))
    return root


def fake_vehicle_tree(root: Path, version: str = "3.9.0", leave_out: str | None = None) -> Path:
    """A directory with the file names of a 3.3 to 3.9 tree (Vehicle API) and
    the README heading by which the protocol family reads the release."""
    from osdk_conformance.sdk.families import protocol

    series = ".".join(version.split(".")[:2])
    (root / "README.md").parent.mkdir(parents=True, exist_ok=True)
    (root / "README.md").write_text(f"# DJI Onboard SDK (OSDK) {series}\n\nOSDK {version} was released\n")
    if series == "3.3":
        rels = protocol.SDK_SOURCES_33 + protocol.ADAPTER_HEADERS_33
    else:
        rels = protocol.SDK_SOURCES + protocol.ADAPTER_HEADERS
    for rel in {*rels, *sdk_host.VEHICLE_REQUIRED, "api/src/dji_control.cpp"}:
        if "osdk-core/" + rel == leave_out:
            continue
        f = root / "osdk-core" / rel
        f.parent.mkdir(parents=True, exist_ok=True)
        f.write_text("/* file name only */\n")
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
        assert f"missing {missing}" in err   # the family's or host-test's own message, naming the file


@pytest.mark.parametrize("version, from_aircraft", [("3.2.0", False), ("3.2.2", True)])
def test_32_releases_are_recognised_with_how_they_learn_the_version(tmp_path, version, from_aircraft):
    tree = fake_tree(tmp_path, version=version)
    inc = tmp_path / "osdk-core/inc"
    if version == "3.2.0":   # what the core family tells 3.2.0 by
        (inc / "DJI_Version.h").write_text((inc / "DJI_Version.h").read_text()
                                           + "const Version versionA3_32 = (MAKE_VERSION(3, 2, 0, 0));\n")
    else:                    # 3.2.1 and 3.2.2 take the firmware version from the version reply
        (inc / "DJI_API.h").write_text("Version getFwVersion() const;\n")
    found = sdk_host.detect(tree)
    assert (found.family, found.version, found.driver.name) == ("core", version, "driver31.cpp")
    assert found.profiles == ("m100-fw3.1", "a3-fw3.1")
    assert ("OSDKC_FW_FROM_AIRCRAFT" in found.defines) is from_aircraft
    assert found.sources[-1].name == "LinuxSerialDevice.cpp"


def test_23_is_recognised_with_the_samples_serial_driver(tmp_path):
    found = sdk_host.detect(fake_tree_23(tmp_path))
    assert (found.family, found.version, found.driver.name) == ("core", "2.3", "driver23.cpp")
    assert found.profiles == ("m100-fw2.3",)
    assert found.sources[-1] == tmp_path / sdk_host.SERIAL_23 / "DJIHardDriverManifold.cpp"
    assert tmp_path / sdk_host.SERIAL_23 in found.includes
    # built with DJI_Config.h's other switch, the tree speaks FW 3.1 on an M100
    assert sdk_host.detect(fake_tree_23(tmp_path / "31", switches=("SDK_VERSION_3_1_M100",))).profiles == ("m100-fw3.1",)


@pytest.mark.parametrize("switches, found", [
    ((), "it defines none"),
    (("SDK_VERSION_2_3", "SDK_VERSION_3_1_M100"), "it defines SDK_VERSION_2_3 (line 2), SDK_VERSION_3_1_M100 (line 3)"),
    (("SDK_VERSION_3_1_A3",), "it defines SDK_VERSION_3_1_A3 (line 2)"),
])
def test_23_config_without_one_usable_switch_is_exit_2(tmp_path, capsys, switches, found):
    code, err = host_test(capsys, "--osdk", str(fake_tree_23(tmp_path, switches=switches)))
    assert code == 2
    assert "lib/inc/DJI_Config.h must define exactly one of SDK_VERSION_2_3, SDK_VERSION_3_1_M100" in err
    assert found in err


def test_23_without_the_samples_serial_driver_is_exit_2(tmp_path, capsys):
    missing = f"{sdk_host.SERIAL_23}/DJIHardDriverManifold.cpp"
    code, err = host_test(capsys, "--osdk", str(fake_tree_23(tmp_path, leave_out=missing)))
    assert code == 2
    assert f"missing {missing}: the 2.3 host stack cannot be built (2.3's lib/ has no serial driver" in err


def test_23_version_reply_has_no_id_and_a_missing_verdict_is_not_flagged():
    name = "SDK-v1.0 BETA M100-02.03.01.00"
    s = sdk_host.Session(steps={"version": {"ok": True, "detail": "ACK code 0xFF01"}},
                         logs=[f"STATUS getVersionCallback,line 227: version name = {name}"], exit_code=1)
    steps = {st.name: st for st in sdk_host._verdicts("m100-fw2.3", s, sdk_host.Comparison(), {}, 500, [ack(0, 0, 0xFF01)])}
    assert steps["version"].verdict == "PASS", steps["version"].detail
    assert steps["version"].detail.startswith(f"SDK read ID None (sent None), name '{name}'")
    # the SDK's caller got no ACK in time: no verdict to weigh against the wire
    late = {"ok": False, "sdk_ok": None, "detail": "no ACK within 2 s"}
    ok, text, flagged = sdk_host.wire_check("frequencies", late, [ack(0, 0x10, 0)])
    assert ok and not flagged and "no ACK reached the SDK's caller within 2 s" in text


def test_32_version_is_checked_through_what_the_getters_read():
    ev = {"ok": True, "detail": "ACK code 0xFF01", "version_id": "SIM-000001", "hw_version": "A3",
          "fw_version": 0x03016400}
    s = sdk_host.Session(steps={"version": ev}, exit_code=1)
    steps = sdk_host._verdicts("a3-fw3.1", s, sdk_host.Comparison(), {}, 500, [ack(0, 0, 0xFF01)])
    assert steps[0].verdict == "PASS", steps[0].detail
    assert "hardware 'A3' and firmware 3.1.100.0 from the name 'SDK-v1.0 BETA A3-03.01.100.00'" in steps[0].detail
    s.steps["version"] = dict(ev, fw_version=0)   # the SDK could not parse the name
    assert sdk_host._verdicts("a3-fw3.1", s, sdk_host.Comparison(), {}, 500, [ack(0, 0, 0xFF01)])[0].verdict == "FAIL"


@pytest.mark.parametrize("version, can_encrypt", [("3.3.2", False), ("3.6.1", True), ("3.9.0", True)])
def test_vehicle_releases_are_recognised_with_what_they_can_do(tmp_path, version, can_encrypt):
    tree = fake_vehicle_tree(tmp_path, version)
    (tree / "osdk-core/api/inc/dji_vehicle.hpp").write_text("void setEncryption(bool);\n" if can_encrypt else "\n")
    found = sdk_host.detect(tree)
    assert found.family == "protocol" and found.driver.name == "driver_vehicle.cpp"
    assert found.version.startswith(version[:3]) and found.profiles == ("m100-fw3.1", "a3-fw3.1")
    assert found.can_encrypt is can_encrypt
    assert ("OSDKC_SET_ENCRYPTION" in found.defines) is can_encrypt
    assert set(found.refusals) == {"a3-fw3.1"}
    assert found.refusals["a3-fw3.1"].startswith("refused by design (osdk-core/api/src/dji_vehicle.cpp")
    assert all(p.suffix == ".cpp" for p in found.sources)


def test_refusal_is_located_in_the_tree(tmp_path):
    tree = fake_vehicle_tree(tmp_path)
    (tree / "osdk-core/api/src/dji_vehicle.cpp").write_text(
        "int\nsetup()\n{\n  if (this->getFwVersion() < extendedVersionBase &&\n    other)\n")
    assert "dji_vehicle.cpp:4:" in sdk_host.detect(tree).refusals["a3-fw3.1"]


def test_vehicle_tree_missing_a_file_is_exit_2_naming_it(tmp_path, capsys):
    tree = fake_vehicle_tree(tmp_path, leave_out="osdk-core/platform/linux/src/posix_thread.cpp")
    code, err = host_test(capsys, "--osdk", str(tree))
    assert code == 2 and "missing osdk-core/platform/linux/src/posix_thread.cpp" in err


def test_later_sdk_4x_is_exit_2(tmp_path, capsys):
    (tmp_path / "osdk-core" / "linker").mkdir(parents=True)
    code, err = host_test(capsys, "--osdk", str(tmp_path))
    assert code == 2 and "4.x is not supported" in err


def test_serial_rates_follow_the_two_tables_of_the_driver(tmp_path):
    # our own stand-in for the two tables a Linux serial driver pairs by index
    src = tmp_path / "serial.cpp"
    src.write_text("\n\nint st_baud[] = { B9600, B230400 };\nint std_rate[] = { 9600, 230400, 921600 };\n")
    rates = sdk_host.serial_rates(tmp_path, src)
    assert rates[230400] == ""
    assert rates[921600].startswith("serial.cpp:3: the release's Linux serial driver sets 9600, 230400 baud only")
    src.write_text("int st_baud[] = { B230400, B921600 };\nint std_rate[] = { 230400, 921600, 1000000 };\n")
    assert sdk_host.serial_rates(tmp_path, src) == {230400: "", 921600: ""}


def test_a_baud_rate_the_release_cannot_set_skips_every_step(tmp_path):
    tree = sdk_host.SdkTree(tmp_path, "3.1.9", ("m100-fw3.1",), [], [], tmp_path / "driver.cpp",
                            bauds={230400: "", 921600: "x.cpp:1: 230400 only"})
    args = type("Args", (), {"baud": 921600, "encrypt": False})()
    steps = sdk_host.run_profile(tmp_path / "driver", "m100-fw3.1", args, tmp_path, tree)
    assert [st.verdict for st in steps] == ["SKIP"] * len(sdk_host.STEPS)
    assert steps[0].detail == "x.cpp:1: 230400 only"


def ack(cmd_set: int, cmd_id: int, code: int, command: str = "00", encrypted: bool = False) -> dict:
    return {"set": cmd_set, "id": cmd_id, "session": 2, "seq": 1, "command": command,
            "value": code.to_bytes(2, "little").hex(), "encrypted": encrypted, "resent": False}


def test_refused_by_design_is_skip_with_the_place_not_fail():
    s = sdk_host.Session(steps={"version": {"ok": True, "detail": "SDK: success", "version_name": "x", "version_id": "y"},
                                "activation": {"ok": False, "refused": True, "detail": "SDK: error, ACK code 0xFFFF"}},
                         exit_code=1)
    steps = {st.name: st for st in sdk_host._verdicts("a3-fw3.1", s, sdk_host.Comparison(), {"frames_rejected": 0,
             "rx_bytes_discarded": {"not_a_frame": 0}, "commands_received": 2}, 500, [], "refused by design (f.cpp:9)")}
    assert steps["activation"].verdict == "SKIP" and steps["activation"].detail.startswith("refused by design (f.cpp:9)")
    for name in ("frequencies", "broadcast", "obtain_control", "movement", "release_control", "frequency_restore"):
        assert (steps[name].verdict, steps[name].detail) == ("SKIP", "refused by design (f.cpp:9)")
    assert steps["host_frames"].verdict == "PASS"
    # a refusal the release is not known for stays a failure
    plain = {st.name: st.verdict for st in sdk_host._verdicts("a3-fw3.1", s, sdk_host.Comparison(), {}, 500, [], None)}
    assert plain["activation"] == "FAIL"


def test_an_sdk_verdict_the_wire_does_not_support_is_flagged():
    # 3.9.0 keeps a control ACK in one byte: 0xFF01 (not activated) reads as 0x01, "release success"
    release = {"ok": True, "sdk_ok": True, "sdk_code": 0x01, "detail": "SDK: success, ACK code 0x0001"}
    ok, text, flagged = sdk_host.wire_check("release_control", release, [ack(1, 0, 0xFF01, "00")])
    assert not ok and flagged
    assert sdk_host.FLAG in text and "hands the caller 0x0001 for the wire's 0xFF01" in text
    # 3.3.2 calls the version query's 0xFF01 (answered, not activated yet) an error
    version = {"ok": True, "sdk_ok": False, "sdk_code": 0xFF01, "detail": "SDK: error"}
    ok, text, flagged = sdk_host.wire_check("version", version, [ack(0, 0, 0xFF01)])
    assert ok and flagged and "the SDK reports failure where the wire's 0xFF01 means success" in text
    # obtain: every ACK of the obtain requests, the last one decides
    obtain = {"ok": True, "sdk_ok": True, "sdk_code": 2, "detail": ""}
    ok, text, flagged = sdk_host.wire_check("obtain_control", obtain, [ack(1, 0, 3, "01", True), ack(1, 0, 2, "01", True),
                                                                      ack(1, 0, 1, "00", True)])
    assert ok and not flagged and "wire: ACK 0x0003, 0x0002 (2 of 2 encrypted)" in text
    ok, text, _ = sdk_host.wire_check("frequencies", obtain, [])
    assert not ok and text == "wire: no ACK sent"


def test_broadcasts_without_seq_are_matched_by_their_time_stamp(tmp_path):
    frames = sent_frames("m100-fw3.1", 6)
    # distinct time stamps, as the simulator's 400 Hz ticks are
    log = tmp_path / "sent.jsonl"
    values = []
    for seq, v in frames:
        b = bytearray(v)
        b[2:6] = (1000 + 8 * seq).to_bytes(4, "little")
        values.append((seq, bytes(b)))
    log.write_text("".join(json.dumps({"seq": s, "value": v.hex()}) + "\n" for s, v in values))
    decoded = [dict(decoded_as_sent("m100-fw3.1", s, v), seq=None, match="time_stamp.time") for s, v in values[2:]]
    del decoded[1]   # the SDK never reported the frame of SEQ 3
    exposed = [n for n in sdk_host.spec_fields("m100-fw3.1", values[0][1])[1] if n != "velocity.sensor_id"]
    c = sdk_host.compare("m100-fw3.1", log, decoded, exposed)
    assert (c.compared, c.mismatched_frames, c.lost, c.unknown) == (3, 0, 1, 0)
    assert c.unexposed == {"velocity.sensor_id"}


def test_not_a_checkout_and_no_checkout_are_exit_2(tmp_path, capsys, monkeypatch):
    code, err = host_test(capsys, "--osdk", str(tmp_path))
    assert code == 2 and "not a DJI Onboard-SDK checkout (looked for osdk-core/src/DJI_Codec.cpp" in err
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
@pytest.mark.parametrize("baud", sdk_host.BAUDS)
@pytest.mark.parametrize("encrypt", (False, True), ids=("plain", "encrypted"))
def test_sdk_host_stack_runs_a_whole_session_on_every_profile(tmp_path, baud, encrypt):
    tree = sdk_host.detect(Path(OSDK_SRC).resolve())
    proc = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "sdk", "host-test", "--osdk", OSDK_SRC,
                           "--out", str(tmp_path / "build"), "--baud", str(baud)] + (["--encrypt"] if encrypt else []),
                          capture_output=True, text=True, timeout=900)
    out = proc.stdout
    known = KNOWN_SDK_FAILURES.get(tree.version, {}) if not tree.bauds.get(baud) else {}
    assert proc.returncode == (1 if known else 0), out + proc.stderr
    ran = 0
    for profile in tree.profiles:
        rest = out.split(profile + "\n", 1)[1].splitlines()
        block = "\n".join(rest[:next((i for i, line in enumerate(rest) if not line.startswith("  ")), len(rest))])
        if tree.bauds.get(baud):   # the release's serial driver cannot set this rate
            assert all(f"SKIP  {step}" in block for step in sdk_host.STEPS)
            continue
        if profile in tree.refusals:
            assert "PASS  version" in block
            assert "SKIP  activation         refused by design (osdk-core/api/src/dji_vehicle.cpp:" in block
            continue
        ran += 1
        for step in sdk_host.STEPS:
            if step in known:   # the release's own defect, with its evidence
                line = next(x for x in block.splitlines() if x.startswith(f"  FAIL  {step} "))
                assert known[step] in line, line
                continue
            assert f"PASS  {step}" in block, block
        want_enc = 150 if encrypt and tree.can_encrypt else 0
        assert f"simulator received 150, {want_enc} of them encrypted" in block
        assert ": 0 with a mismatch, 0 lost, 0 unknown" in block
        assert "items acceleration, angular_rate, battery, control_info, flight_status, gimbal" in block
    assert ran or tree.bauds.get(baud)


@needs_sdk
@pytest.mark.slow
@pytest.mark.realtime
def test_through_the_tap_the_session_still_passes_and_the_tap_describes_it(tmp_path):
    tree = sdk_host.detect(Path(OSDK_SRC).resolve())
    profile = next((p for p in tree.profiles if p not in tree.refusals), None)
    if profile is None or KNOWN_SDK_FAILURES.get(tree.version):
        pytest.skip(f"SDK {tree.version}: no profile whose whole session passes to compare with")
    proc = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "sdk", "host-test", "--osdk", OSDK_SRC,
                           "--out", str(tmp_path / "build"), "--profile", profile, "--through-tap",
                           "--log-dir", str(tmp_path / "logs")], capture_output=True, text=True, timeout=900)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    for step in (*sdk_host.STEPS, "tap"):
        assert f"PASS  {step}" in proc.stdout, proc.stdout
    tap = json.loads((tmp_path / "logs" / f"{profile}.tap.json").read_text())
    assert tap["verdict"] == "PASS" and tap["host"]["movement commands"] == 150
    cadence = next(c for c in tap["checks"] if c["id"] == "host.cadence")
    assert cadence["status"] == "pass", cadence


def _control_device(log: Path, profile: str) -> int | None:
    lines = log.read_text().splitlines() if log.is_file() else []
    if not lines:
        return None
    try:
        rec = json.loads(lines[-1])
    except ValueError:   # caught mid-line
        return None
    fields = sdk_host.spec_fields(profile, bytes.fromhex(rec["value"]))[1]
    return fields.get("control_info.control_device")


@needs_sdk
@pytest.mark.slow
@pytest.mark.realtime
def test_ctrl_c_in_movement_releases_control_restores_frequencies_and_stops_everything(tmp_path):
    logs = tmp_path / "logs"
    tree = sdk_host.detect(Path(OSDK_SRC).resolve())
    profile = next(p for p in ("a3-fw3.1", "m100-fw3.1", "m100-fw2.3") if p in tree.profiles and p not in tree.refusals)
    restored = "FAIL" if "frequency_restore" in KNOWN_SDK_FAILURES.get(tree.version, {}) else "PASS"
    proc = subprocess.Popen([sys.executable, "-m", "osdk_conformance.cli", "sdk", "host-test", "--osdk", OSDK_SRC,
                             "--out", str(tmp_path / "build"), "--log-dir", str(logs), "--profile", profile,
                             "--frames", "20", "--moves", "5000"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        deadline = time.monotonic() + 240
        while _control_device(logs / f"{profile}.broadcast.jsonl", profile) != 2:   # the onboard computer flies
            assert proc.poll() is None and time.monotonic() < deadline, proc.stderr.read() if proc.poll() else ""
            time.sleep(0.2)
        os.killpg(proc.pid, signal.SIGINT)   # what Ctrl-C at the terminal does
        _, err = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
    assert proc.returncode == 130, err
    assert "interrupted; release_control PASS" in err
    assert f"interrupted; frequency_restore {restored}" in err
    assert (logs / f"{profile}.sim-stats.json").is_file()   # the simulator stopped cleanly
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
