"""`osdkc explain`: every control mode byte and every frame of the golden
vectors explained as the vectors decide them, every ACK code of the spec
with a meaning and a remedy, bad input in one line."""
from __future__ import annotations

import json
import re
import subprocess
import sys

import pytest

from osdk_conformance import cli
from osdk_conformance.core.deframe import HEADER_LEN, header_fields
from osdk_conformance.core.paths import SPEC
from osdk_conformance.core.rules import default_rules, profile_names
from osdk_conformance.explain import (DEFAULT_FRAME_PROFILE, ack_enums, explain_ack, explain_frame, explain_mode,
                                      header_layout)
from osdk_conformance.harness.vectors import VECTORS_DIR, load_cases

# Only the two files these tests read: all of vectors/ takes seconds to load.
CASES = load_cases([VECTORS_DIR / "control_mode.json", VECTORS_DIR / "frames.json"])
MODE_CASES = [c for c in CASES if c.operation == "classify_control_mode"]
FRAME_CASES = [c for c in CASES if c.operation == "decode_frame"]
WORKED = "aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba"  # PROTOCOL-FACTS' movement control


def osdkc(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "explain", *args], capture_output=True,
                          text=True, timeout=60)


# ---- the control mode byte


def test_every_mode_byte_of_the_vectors_gets_their_fields_classification_and_combination():
    assert len(MODE_CASES) == 768  # 256 bytes x 3 profiles
    for c in MODE_CASES:
        out = explain_mode(c.input["byte"], c.profile)
        got = out["profiles"][c.profile]
        assert (got["classification"], got["combination"]) == \
            (c.expected["classification"], c.expected["combination"]), c.id
        assert {f["field"]: {"value": f["value"], "name": f["name"]} for f in out["fields"]} == c.expected["fields"], c.id
        assert (got["ranges"] is not None) == (got["classification"] == "documented"), c.id


def test_a_documented_byte_shows_fields_frame_ranges_and_errata():
    out = explain_mode(0x4B)
    assert [f["name"] for f in out["fields"]] == ["hori_vel", "vert_vel", "yaw_rate", "body", "stable"]
    assert [f["bits"] for f in out["fields"]] == ["7:6", "5:4", "3", "2:1", "0"]
    assert set(out["profiles"]) == set(profile_names())
    assert "body frame" in out["frame"]
    a3 = out["profiles"]["a3-fw3.1"]
    assert a3["combination"] == 4
    assert a3["ranges"]["horizontal"] == {**a3["ranges"]["horizontal"], "axes": ["roll_or_x", "pitch_or_y"],
                                          "min": -10, "max": 10, "unit": "m/s"}
    assert out["profiles"]["m100-fw2.3"]["bit0"] == {"meaning": "yaw_frame", "name": "body"}   # errata E15
    titles = dict(re.findall(r"^## (E\d+): (.*)$", (SPEC / "ERRATA.md").read_text(encoding="utf-8"), re.M))
    assert {e["id"] for e in out["errata"]} >= {"E15", "E16"}
    assert all(e["title"] == titles[e["id"]] for e in out["errata"])


def test_yaw_angle_forces_the_ground_frame_and_profile_narrows():
    out = explain_mode(0x42, "a3-fw3.1")  # hori_vel, vert_vel, yaw_ang, body frame
    assert list(out["profiles"]) == ["a3-fw3.1"]
    assert "body frame" in out["frame"] and "ground frame" in out["frame"]


def test_an_undefined_byte_names_its_undefined_fields():
    out = explain_mode(0xFF)
    undefined = {f["field"]: f["undefined"] for f in out["fields"] if "undefined" in f}
    assert undefined == {"horizontal_logic": "later_firmware", "vertical_logic": "invalid", "horizontal_frame": "invalid"}
    assert all(p["classification"] == "invalid" and p["ranges"] is None for p in out["profiles"].values())


# ---- ACK codes


def test_the_ack_enums_are_read_from_the_payload_ksy():
    assert ack_enums() == {"version_query": "version_ack", "activation": "activation_result",
                           "set_frequency": "frequency_ack", "control_authority": "control_ack"}


@pytest.mark.parametrize("command", ["version_query", "activation", "set_frequency", "control_authority"])
def test_every_ack_code_of_the_spec_has_a_meaning_and_a_remedy(command):
    values = default_rules().data["enums"][ack_enums()[command]]["values"]
    for v in values:
        for text in (str(v["value"]), hex(v["value"])):
            out = explain_ack(command, text)
            assert out["name"] == v["name"] and out["meaning"] and out["remedy"] and out["remedy_source"], v


def test_the_facts_the_remedies_rest_on():
    new_app = explain_ack("0x00,0x01", "3")
    assert new_app["name"] == "new_app_id" and "DJI GO" in new_app["remedy"]
    assert "issues/379" in new_app["remedy_source"] and "issues/510" in new_app["remedy_source"]
    sdk = explain_ack("activation", "8", profile="m100-fw2.3")
    assert sdk["sdk_versions"] == {"m100-fw2.3": f"0x{default_rules().profile('m100-fw2.3').sdk_version:08X}"}
    assert "issues/88" in sdk["remedy_source"]
    assert "F" in explain_ack("control_authority", "0")["remedy"]
    assert "E26" in explain_ack("control_authority", "3")["remedy_source"]
    assert "activate" in explain_ack("version_query", "0xFF01")["remedy"]


def test_a_code_the_spec_does_not_name_is_said_so():
    out = explain_ack("control_authority", "7")
    assert out["name"] is None and "not defined by the spec" in out["meaning"]
    assert [d["value"] for d in out["defined"]] == [0, 1, 2, 3, 4, 0xC9]


# ---- a frame


def test_the_header_layout_read_from_the_ksy():
    ids = [f.id for f in header_layout()]
    assert ids == ["sof", "len", "ver", "session", "is_ack", "res0", "padding", "enc", "res1", "seq", "crc16"]


def test_every_frame_of_the_vectors_gets_their_verdict():
    assert FRAME_CASES
    for c in FRAME_CASES:
        raw = bytes.fromhex(c.input["hex"])
        out = explain_frame(raw, c.profile)
        if len(raw) >= HEADER_LEN:
            _check_header(out, raw, c.id)
        if c.result == "invalid":
            b = out["breaks_at"]
            assert out["verdict"] == "rejected" and b["error"] == c.expected["error"], c.id
            assert b["field"] and b["receiver"], c.id
        else:
            assert out["verdict"] == "valid" and out["breaks_at"] is None, c.id
            _check_valid(out, c.expected["frame"], c.id)


def _check_header(out: dict, raw: bytes, cid: str) -> None:
    """The header as explain reads it from the ksy is the header as the receiver reads it."""
    rows = {f["field"]: f for f in out["fields"]}
    for key, value in header_fields(raw[:HEADER_LEN]).items():
        shown = rows[key.upper()]["value"]
        assert (int(shown, 16) if isinstance(shown, str) else shown) == int(value), (cid, key)


def _check_valid(out: dict, frame: dict, cid: str) -> None:
    rows = {f["field"]: f for f in out["fields"]}
    assert rows["LEN"]["value"] == frame["len"] and rows["SEQ"]["value"] == frame["seq"], cid
    assert rows["SESSION"]["value"] == frame["session"] and rows["IS_ACK"]["value"] == int(frame["is_ack"]), cid
    assert rows["CRC16"]["value"] == f"0x{frame['crc16']:04X}" == rows["CRC16"]["computed"], cid
    if "crc32" in frame:
        assert rows["CRC32"]["value"] == f"0x{frame['crc32']:08X}" == rows["CRC32"]["computed"], cid
    data = frame.get("data")
    if isinstance(data, dict) and "cmd_id" in data:
        assert int(rows["CMD_SET"]["value"], 16) == data["cmd_set"]["value"], cid
        assert int(rows["CMD_ID"]["value"], 16) == data["cmd_id"], cid
        assert out["value"] == data["value"]["body"], cid


def test_where_a_frame_breaks_and_what_the_receiver_does():
    bad_crc16 = bytearray.fromhex(WORKED)
    bad_crc16[10] ^= 1
    out = explain_frame(bytes(bad_crc16), "a3-fw3.1")
    assert out["breaks_at"]["field"] == "CRC16" and "0xAA" in out["breaks_at"]["receiver"]
    assert "E21" in {e["id"] for e in out["breaks_at"]["errata"]}
    overlong = explain_frame(bytes.fromhex(WORKED + "00"), "a3-fw3.1")
    assert overlong["breaks_at"]["error"] == "length_mismatch" and "a valid frame" in overlong["breaks_at"]["receiver"]
    short = explain_frame(bytes.fromhex(WORKED[:40]), "a3-fw3.1")
    assert short["breaks_at"]["error"] == "truncated_frame" and "other 15 byte(s)" in short["breaks_at"]["receiver"]


def test_a_broadcast_without_a_profile_says_which_profile_explained_it():
    assert DEFAULT_FRAME_PROFILE in profile_names()
    broadcast = next(c for c in FRAME_CASES if c.result == "valid" and c.profile == DEFAULT_FRAME_PROFILE
                     and isinstance(c.expected["frame"].get("data"), dict)
                     and c.expected["frame"]["data"].get("cmd_set", {}).get("value") == 2)
    out = explain_frame(bytes.fromhex(broadcast.input["hex"]))
    assert out["command"] == "broadcast" and DEFAULT_FRAME_PROFILE in out["note"]


# ---- the command line


def test_the_command_line_as_a_process():
    mode = osdkc("0b01001011", "--json")
    assert mode.returncode == 0 and json.loads(mode.stdout)["hex"] == "0x4B"
    bad = osdkc("--hex", "abc")
    assert bad.returncode == 2 and bad.stderr.count("\n") == 1 and "Traceback" not in bad.stderr


def test_the_human_forms(capsys):
    assert cli.main(["explain", "--ack", "0x00,0x01", "3"]) == 0
    text = capsys.readouterr().out
    assert "new_app_id" in text and "DJI GO" in text
    assert cli.main(["explain", "--hex", "aa 16 00 00 00 00 00 00 07 00 1e de 02 00 00 18 03 57 69 c6 76 b2",
                     "--profile", "m100-fw2.3"]) == 0
    text = capsys.readouterr().out
    assert "REJECTED" in text and "reserved_bits" in text and "the receiver" in text
    assert cli.main(["explain", "--control-mode", "75", "--profile", "m100-fw2.3"]) == 0
    text = capsys.readouterr().out
    assert "m100-fw2.3: DOCUMENTED, combination 4" in text and "errata:" in text
    assert cli.main(["explain", "--hex", WORKED]) == 0
    text = capsys.readouterr().out
    assert "VALID, command movement_control" in text and "yaw" in text
    assert cli.main(["explain", "--ack", "control_authority", "7", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["name"] is None


@pytest.mark.parametrize("args, message", [
    (("0x100",), "out of range"), (("zz",), "not a number"), (("--ack", "broadcast", "1"), "no ACK codes"),
    (("--ack", "nope", "1"), "unknown command"), (("--ack", "activation", "0x10000"), "out of range"),
    (("--hex", "abc"), "not whole bytes"), (("--hex", "zz"), "not a hex string"), (("--hex", " "), "no bytes"),
    (("--hex", "aa" * 1024), "at most 1023"), ((), "give one thing"), (("0x4B", "--hex", "aa"), "give one thing"),
])
def test_bad_input_exits_2_in_one_line(capsys, args, message):
    assert cli.main(["explain", *args]) == 2
    err = capsys.readouterr().err
    assert message in err and err.count("\n") == 1, err
