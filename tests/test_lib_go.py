"""The generated Go library (generated/go) as a user's module sees it:
the examples built by `make -C examples/go build` (go.mod require +
replace) print what tests/library_examples.py expects, and bin/libcheck
answers the edge cases the examples do not reach (encoders against the
reference bit for bit, the error type, absent items) for the reference to
judge."""
from __future__ import annotations

import json
import shutil
import struct
import subprocess
from pathlib import Path

import pytest

from osdk_conformance import api

from library_examples import receive_expected, receive_stream, send_expected

ROOT = Path(__file__).resolve().parents[1]
BIN = ROOT / "examples" / "go" / "bin"
PROFILES = api.profiles()


def _bin(name: str) -> Path:
    path = BIN / name
    if not path.exists():
        if shutil.which("go") is None:
            pytest.skip("no Go toolchain and no built examples")
        pytest.fail(f"{path} is missing: run `make -C examples/go build`")
    return path


def _run(name: str, *args: str, stdin: bytes = b"") -> str:
    proc = subprocess.run([str(_bin(name)), *args], input=stdin, capture_output=True, timeout=30)
    assert proc.returncode == 0, proc.stderr.decode()
    return proc.stdout.decode()


def _check(requests: list[dict]) -> list[dict]:
    text = "".join(json.dumps(r) + "\n" for r in requests)
    lines = _run("libcheck", stdin=text.encode()).splitlines()
    assert len(lines) == len(requests)
    return [json.loads(line) for line in lines]


@pytest.mark.parametrize("profile", PROFILES)
def test_receive_example(profile):
    assert _run("receive", profile, stdin=receive_stream(profile)).splitlines() == receive_expected(profile)


def test_send_example():
    assert _run("send").splitlines() == send_expected()


def test_receive_rejects_an_unknown_profile():
    proc = subprocess.run([str(_bin("receive")), "no-such-profile"], capture_output=True, timeout=30)
    assert proc.returncode == 2
    assert len(proc.stderr.decode().strip().splitlines()) == 1 and b"Traceback" not in proc.stderr


EDGE_BITS = [
    (0x4B, [0x3F800000, 0xC0000000, 0x3F000000, 0x41F00000]),
    (0xFF, [0x7F800001, 0xFFBFFFFF, 0x80000000, 0x7FC12345]),   # signalling/quiet NaN payloads, -0.0
    (0x00, [0x7F7FFFFF, 0xFF800000, 0x00000001, 0x80000001]),   # max, -inf, denormals
]


def test_movement_control_encoder_is_bit_exact():
    answers = _check([{"op": "movement_control", "mode": m, "bits": b} for m, b in EDGE_BITS])
    for (mode, bits), got in zip(EDGE_BITS, answers):
        want = api.encode_movement_control(mode, *(api.F32(b) for b in bits)).hex()
        assert got == {"bits": want, "float": want}, (mode, [hex(b) for b in bits])


def test_value_encoders_at_their_limits():
    bundle = bytes(range(0xE0, 0x100))
    answers = _check([
        {"op": "activation", "app_id": 0xFFFFFFFF, "api_level": 0, "sdk_version": 0x80000001, "bundle_id": bundle.hex()},
        {"op": "set_frequency", "codes": [0xFF] * 15 + [0]},
        {"op": "version_query", "byte": 0xFF},
        {"op": "control_authority", "byte": 0xFF},
    ])
    want = [struct.pack("<III", 0xFFFFFFFF, 0, 0x80000001) + bundle, bytes([0xFF] * 15 + [0]), b"\xff", b"\xff"]
    assert [a["hex"] for a in answers] == [w.hex() for w in want]


def test_encode_frame_against_the_reference():
    longest = bytes(range(256)) * 3 + bytes(1005 - 768)        # LEN 1023 with cmd_set and cmd_id
    cases = [
        dict(cmd_set=0xFF, cmd_id=0xFF, is_ack=False, session=31, seq=0xFFFF, value=b"\x01"),
        dict(cmd_set=1, cmd_id=3, is_ack=False, session=0, seq=0, value=longest),
        dict(cmd_set=0, cmd_id=0, is_ack=True, session=5, seq=9, value=b""),      # header-only ACK
        dict(cmd_set=0, cmd_id=0, is_ack=True, session=1, seq=9, value=b"\x00\x00"),
        dict(cmd_set=2, cmd_id=0, is_ack=False, session=0, seq=7, value=b""),
    ]
    answers = _check([{"op": "frame", **{k: v for k, v in c.items() if k != "value"}, "hex": c["value"].hex()} for c in cases])
    for c, got in zip(cases, answers):
        cmd = {} if c["is_ack"] else {"cmd_set": c["cmd_set"], "cmd_id": c["cmd_id"]}
        want = api.encode_frame(**cmd, value=c["value"], is_ack=c["is_ack"], session=c["session"], seq=c["seq"])
        assert got == {"hex": want.hex()}


def test_encode_frame_errors():
    answers = _check([
        {"op": "frame", "cmd_set": 1, "cmd_id": 3, "session": 0, "seq": 0, "hex": "00" * 1006},
        {"op": "frame", "is_ack": True, "session": 0, "seq": 0, "hex": "00" * 2000},   # length before session
        {"op": "frame", "is_ack": True, "session": 0, "seq": 0, "hex": ""},
        {"op": "frame", "session": 32, "seq": 0, "hex": "00"},
    ])
    for got, cls in zip(answers, ["impossible_length", "impossible_length", "bad_session"]):
        assert got["is_error"] and got["class"] == cls and not got["eof"] and not got["argument"], got
    for value, is_ack in ((b"\x00" * 1006, False), (b"\x00" * 2000, True), (b"", True)):
        cmd = {} if is_ack else {"cmd_set": 1, "cmd_id": 3}
        with pytest.raises(api.InputError):
            api.encode_frame(**cmd, value=value, is_ack=is_ack, session=0)
    assert answers[3]["argument"] and not answers[3]["is_error"]


def _reference_error(raw: bytes, profile: str) -> str | None:
    events = api.decode(raw, profile)
    return events[0].error if len(events) == 1 and events[0].kind == "error" else None


def test_errors_name_class_and_field():
    profile = "a3-fw3.1"
    good = api.encode_broadcast_frame(profile, {"battery": 87, "flight_status": 0}, seq=1)
    # a broadcast whose flag word promises a battery byte the value lacks
    flags = 1 << api.broadcast_items(profile).index("battery")
    short_value = api.encode_frame(cmd_set=2, cmd_id=0, value=struct.pack("<H", flags), seq=2)
    reserved = api.encode_frame(cmd_set=2, cmd_id=0, value=struct.pack("<H", 1 << 15), seq=3)
    bad_crc16 = bytearray(good)
    bad_crc16[10] ^= 1
    cases = [
        (good[:16], "truncated_frame", "data", True),
        (good[:20], "truncated_frame", "crc32", True),
        (good[:5], "truncated_frame", "res1", True),
        (b"", "truncated_frame", "sof", True),
        (short_value, "truncated_payload", "battery", True),
        (bytes(bad_crc16), "bad_crc16", "crc16", False),
        (reserved, "reserved_bits", "reserved_flags", False),
        (good + b"\x00", "length_mismatch", "", False),
    ]
    answers = _check([{"op": "decode_frame", "hex": raw.hex(), "profile": profile} for raw, *_ in cases])
    for (raw, cls, field, eof), got in zip(cases, answers):
        assert (got["is_error"], got["class"], got["field"], got["eof"]) == (True, cls, field, eof), (raw.hex(), got)
    # the classes are the reference's (decode_frame's own checks for a cut or overlong frame)
    assert _reference_error(short_value, profile) == "truncated_payload"
    assert _reference_error(reserved, profile) == "reserved_bits"
    [unknown] = _check([{"op": "decode_frame", "hex": good.hex(), "profile": "no-such-profile"}])
    assert unknown["argument"] and not unknown["is_error"]


@pytest.mark.parametrize("profile", PROFILES)
def test_absent_items_are_nil(profile):
    items = api.broadcast_items(profile)
    raw = api.encode_broadcast_frame(profile, {"battery": 0, "time_stamp": {"time": 5}}, seq=1)
    [got] = _check([{"op": "decode_frame", "hex": raw.hex(), "profile": profile}])
    assert got["broadcast"] and got["battery"] == 0 and got["flight_status"] is None
    expected = {item: item in ("battery", "time_stamp") for item in got["items"]}
    assert got["items"] == expected
    assert set(items) <= set(got["items"])          # every profile's items have an accessor
    [not_broadcast] = _check([{"op": "decode_frame", "hex": send_expected()[-1].split()[1], "profile": profile}])
    assert not_broadcast == {"broadcast": False}
