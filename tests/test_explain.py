"""`osdkc explain`: every control mode byte and every frame of the golden
vectors explained as the vectors decide them, every ACK code of the spec
with a meaning and a remedy, bad input in one line."""
from __future__ import annotations

import json
import subprocess
import sys

import pytest

from osdk_conformance.core.rules import default_rules
from osdk_conformance.explain import ACK_ENUMS, explain_ack, explain_frame, explain_mode
from osdk_conformance.harness.vectors import load_cases

CASES = load_cases()


def osdkc(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "explain", *args], capture_output=True,
                          text=True, timeout=60)


def test_every_mode_byte_of_the_vectors_gets_their_classification_and_combination():
    cases = [c for c in CASES if c.operation == "classify_control_mode"]
    assert len(cases) == 768
    for c in cases:
        got = explain_mode(c.input["byte"], c.profile)["profiles"][c.profile]
        assert (got["classification"], got["combination"]) == \
            (c.expected["classification"], c.expected["combination"]), c.id


def test_a_documented_byte_shows_fields_ranges_and_errata():
    out = explain_mode(0x4B)
    assert [f["name"] for f in out["fields"]] == ["hori_vel", "vert_vel", "yaw_rate", "body", "stable"]
    assert set(out["profiles"]) == {"m100-fw2.3", "m100-fw3.1", "a3-fw3.1"}
    a3 = out["profiles"]["a3-fw3.1"]
    assert a3["combination"] == 4 and a3["ranges"]["horizontal"]["unit"] == "m/s"
    assert out["profiles"]["m100-fw2.3"]["bit0"]["meaning"] == "yaw_frame"   # errata E15
    assert {e["id"] for e in out["errata"]} >= {"E15"} and all(e["title"] for e in out["errata"])


def test_every_frame_of_the_vectors_gets_their_verdict():
    cases = [c for c in CASES if c.operation == "decode_frame"]
    for c in cases:
        out = explain_frame(bytes.fromhex(c.input["hex"]), c.profile)
        if c.result == "invalid":
            assert out["verdict"] == "rejected" and out["breaks_at"]["error"] == c.expected["error"], c.id
            assert out["breaks_at"]["receiver"]
        else:
            assert out["verdict"] == "valid", c.id
        if len(c.input["hex"]) >= 24:
            assert [f["field"] for f in out["fields"]][:3] == ["SOF", "LEN", "VER"]


@pytest.mark.parametrize("command", list(ACK_ENUMS))
def test_every_ack_code_of_the_spec_has_a_meaning_and_a_remedy(command):
    for v in default_rules().data["enums"][ACK_ENUMS[command]]["values"]:
        out = explain_ack(command, str(v["value"]))
        assert out["name"] == v["name"] and out["meaning"] and out["remedy"] and out["remedy_source"]


def test_the_command_line_forms():
    mode = osdkc("0b01001011", "--json")
    assert mode.returncode == 0 and json.loads(mode.stdout)["hex"] == "0x4B"
    ack = osdkc("--ack", "0x00,0x01", "3")
    assert ack.returncode == 0 and "new_app_id" in ack.stdout and "DJI GO" in ack.stdout
    frame = osdkc("--hex", "aa 16 00 00 00 00 00 00 07 00 1e de 02 00 00 18 03 57 69 c6 76 b2", "--profile",
                  "m100-fw2.3")
    assert frame.returncode == 0 and "REJECTED" in frame.stdout and "reserved_bits" in frame.stdout
    undefined = osdkc("--ack", "control_authority", "7")
    assert undefined.returncode == 0 and "not defined by the spec" in undefined.stdout


@pytest.mark.parametrize("args, message", [
    (("0x100",), "out of range"), (("zz",), "not a number"), (("--ack", "broadcast", "1"), "no ACK codes"),
    (("--ack", "nope", "1"), "unknown command"), (("--hex", "abc"), "not a hex string"), ((), "give one thing"),
    (("0x4B", "--hex", "aa"), "give one thing"),
])
def test_bad_input_exits_2_in_one_line(args, message):
    proc = osdkc(*args)
    assert proc.returncode == 2 and message in proc.stderr, proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1 and "Traceback" not in proc.stderr
