"""The generated JavaScript library (generated/javascript, npm package
osdk-kaitai) as a user installs it: examples/javascript's receive and send
(built by `make -C examples/javascript build`) print what
tests/library_examples.py computes from the reference, and the encoders,
errors and absent items hold at the edges, checked by one node script run
against the same installed package."""
from __future__ import annotations

import json
import math
import shutil
import struct
import subprocess

import pytest
from library_examples import receive_expected, receive_stream, send_expected

from osdk_conformance import api
from osdk_conformance.core import crc
from osdk_conformance.core.paths import ROOT
from osdk_conformance._construct import F32
from osdk_conformance._construct import payload as construct_payload

EXAMPLES = ROOT / "examples" / "javascript"
NODE = shutil.which("node")

pytestmark = pytest.mark.skipif(
    NODE is None or not (EXAMPLES / "node_modules" / "osdk-kaitai").is_dir(),
    reason="node or the built examples missing (make -C examples/javascript build)")


def node(args: list[str], stdin: bytes = b"") -> str:
    proc = subprocess.run([NODE, *args], input=stdin, cwd=EXAMPLES, capture_output=True, timeout=60)
    assert proc.returncode == 0, proc.stderr.decode()
    return proc.stdout.decode()


@pytest.mark.parametrize("profile", api.profiles())
def test_receive_prints_the_reference_events(profile):
    assert node(["receive.js", profile], receive_stream(profile)).splitlines() == receive_expected(profile)


def test_send_prints_the_reference_frames():
    assert node(["send.js"]).splitlines() == send_expected()


def test_receive_refuses_an_unknown_profile():
    proc = subprocess.run([NODE, "receive.js", "m100"], cwd=EXAMPLES, capture_output=True, timeout=60)
    assert proc.returncode == 2 and proc.stderr.decode().count("\n") == 1


# One node run: each case is [operation, args], answered with the library's
# result as hex or the error's name, class and field.
SCRIPT = r"""
const osdk = require('osdk-kaitai');
const cases = JSON.parse(require('fs').readFileSync(0, 'utf8'));
const hex = (b) => Buffer.from(b).toString('hex');
const arg = (v) => (v !== null && typeof v === 'object' && 'bits' in v ? osdk.f32Bits(v.bits)
  : v !== null && typeof v === 'object' && 'hex' in v ? Buffer.from(v.hex, 'hex')
  : v === '-0' ? -0 : v === 'NaN' ? NaN : v);
const run = ([op, args]) => {
  try {
    if (op === 'absent') {
      const bc = osdk.broadcastOf(osdk.decodeFrame(Buffer.from(args[0], 'hex'), args[1]));
      return { items: Object.fromEntries(args[2].map((i) => [i, bc.item(i) === null ? null : 'value'])),
               battery: bc.battery, gpsDetail: bc.gpsDetail, timeStamp: bc.timeStamp };
    }
    if (op === 'broadcastOf') return { value: osdk.broadcastOf(osdk.decodeFrame(Buffer.from(args[0], 'hex'), args[1])) };
    const out = osdk[op](...args.map(arg));
    return { hex: hex(op === 'decodeFrame' || op === 'decodePayload' ? [] : out) };
  } catch (err) {
    return { name: err.constructor.name, errorClass: err.errorClass, field: err.field === undefined ? 'undefined' : err.field,
             isOsdkError: err instanceof osdk.OsdkError, isError: err instanceof Error };
  }
};
process.stdout.write(JSON.stringify(cases.map(run)));
"""


def run_cases(cases: list[list]) -> list[dict]:
    return json.loads(node(["-e", SCRIPT], json.dumps(cases).encode()))


def f32(bits: int) -> dict:
    return {"bits": bits}


def test_encoders_match_the_reference_at_the_edges():
    ints = {"version_query": [0, 0xFF], "control_authority": [0, 1, 0xFF]}
    cases, expected = [], []
    for name, values in ints.items():
        op = "encodeVersionQuery" if name == "version_query" else "encodeControlAuthority"
        build = construct_payload.version_query if name == "version_query" else construct_payload.control_request
        key = "arbitrary" if name == "version_query" else "request"
        for v in values:
            cases.append([op, [v]])
            expected.append(build.build({key: v}).hex())
    for app_id, level, version, bundle in ((0, 0, 0, bytes(32)), (0xFFFFFFFF, 0xFFFFFFFF, 0xFFFFFFFF, b"\xff" * 32),
                                           (1000001, 2, 0x03016400, bytes(range(32)))):
        cases.append(["encodeActivation", [app_id, level, version, {"hex": bundle.hex()}]])
        expected.append(construct_payload.activation_request.build(
            {"app_id": app_id, "api_level": level, "sdk_version": version, "bundle_id": bundle}).hex())
    for codes in ([0] * 16, [0xFF] * 16, list(range(16))):
        cases.append(["encodeSetFrequency", [codes]])
        expected.append(construct_payload.frequency_request.build({"codes": codes}).hex())
    # NaN payloads (signalling, quiet, negative), -0.0, infinities, the largest float32
    bit_sets = ((0x7F800001, 0xFFC00001, 0x80000000, 0x7FBFFFFF), (0x7F800000, 0xFF800000, 0x7F7FFFFF, 0x00000001),
                (0, 0, 0, 0))
    for mode in (0, 0x4B, 0xFF):
        for bits in bit_sets:
            cases.append(["encodeMovementControl", [mode, *map(f32, bits)]])
            expected.append(api.encode_movement_control(mode, *map(F32, bits)).hex())
    # numbers: -0.0 stays negative, NaN is the quiet NaN a float32 cast gives
    cases.append(["encodeMovementControl", [0x4B, "-0", 1.0, -2.0, 0.1]])
    expected.append(api.encode_movement_control(0x4B, -0.0, 1.0, -2.0, 0.1).hex())
    cases.append(["encodeMovementControl", [0x4B, "NaN", 3.4028235e38, -1e-45, 30.0]])
    expected.append(api.encode_movement_control(0x4B, math.nan, 3.4028235e38, -1e-45, 30.0).hex())
    for cmd, is_ack, session, seq, value in (((0, 0), False, 0, 0, b"\x00"), ((0xFF, 0xFF), False, 31, 0xFFFF, b""),
                                             (None, True, 31, 0xFFFF, b"\x01\x02"), (None, True, 1, 0, b""),
                                             (None, False, 0, 7, b""), ((1, 3), False, 5, 9, bytes(1005))):
        cmd_set, cmd_id = cmd or (None, None)
        cases.append(["encodeFrame", [cmd_set, cmd_id, is_ack, session, seq, {"hex": value.hex()}]])
        expected.append(api.encode_frame(cmd_set=cmd_set, cmd_id=cmd_id, value=value, is_ack=is_ack,
                                         session=session, seq=seq).hex())
    got = run_cases(cases)
    assert [g.get("hex", g) for g in got] == expected


def test_frame_rules_and_argument_errors():
    frame = api.encode_frame(cmd_set=1, cmd_id=3, value=bytes.fromhex("4b0000803f000000c00000003f0000f041"), seq=1)
    bad_crc = bytearray(frame)
    bad_crc[-1] ^= 1
    bad_header = bytearray(frame)
    bad_header[5] = 1  # RES1, CRC-16 then fixed up
    bad_header[10:12] = struct.pack("<H", crc.crc16(bytes(bad_header[:10])))
    short_value = api.encode_frame(cmd_set=1, cmd_id=3, value=bytes(5), seq=1)
    reserved = api.encode_frame(cmd_set=2, cmd_id=0, value=struct.pack("<H", 1 << 15), seq=1)
    cases = [
        ["decodeFrame", [{"hex": ""}, "a3-fw3.1"]],
        ["decodeFrame", [{"hex": "ab"}, "a3-fw3.1"]],
        ["decodeFrame", [{"hex": frame[:5].hex()}, "a3-fw3.1"]],
        ["decodeFrame", [{"hex": frame[:-2].hex()}, "a3-fw3.1"]],
        ["decodeFrame", [{"hex": frame[:14].hex()}, "a3-fw3.1"]],
        ["decodeFrame", [{"hex": (frame + b"\x00").hex()}, "a3-fw3.1"]],
        ["decodeFrame", [{"hex": bytes(bad_crc).hex()}, "a3-fw3.1"]],
        ["decodeFrame", [{"hex": bytes(bad_header).hex()}, "a3-fw3.1"]],
        ["decodeFrame", [{"hex": short_value.hex()}, "a3-fw3.1"]],
        ["decodeFrame", [{"hex": reserved.hex()}, "m100-fw3.1"]],
        ["decodePayload", [{"hex": "0100"}, 2, 0, False, "a3-fw3.1"]],
        ["decodePayload", [{"hex": "0100"}, 0, 0, False, "a3-fw3.1"]],
        ["encodeFrame", [None, None, True, 0, 1, {"hex": ""}]],
        ["encodeFrame", [None, None, True, 0, 1, {"hex": "00" * 1008}]],
        ["encodeFrame", [1, 3, False, 32, 1, {"hex": ""}]],
        ["encodeActivation", [1, 2, 3, {"hex": "00" * 31}]],
        ["encodeMovementControl", [0, 1e39, 0, 0, 0]],
        ["encodeMovementControl", [256, 0, 0, 0, 0]],
        ["decodeFrame", [{"hex": frame.hex()}, "m100"]],
    ]
    got = [(g.get("name"), g.get("errorClass"), g.get("field")) for g in run_cases(cases)]
    assert got == [
        ("OsdkError", "truncated_frame", "sof"),
        ("OsdkError", "bad_sof", "sof"),
        ("OsdkError", "truncated_frame", "res1"),
        ("OsdkError", "truncated_frame", "crc32"),
        ("OsdkError", "truncated_frame", "data"),
        ("OsdkError", "length_mismatch", None),
        ("OsdkError", "bad_crc32", "crc32"),
        ("OsdkError", "reserved_bits", "res1"),
        ("OsdkError", "truncated_payload", "y"),
        ("OsdkError", "reserved_bits", "reserved_flags"),
        ("OsdkError", "truncated_payload", "time"),
        ("OsdkError", "length_mismatch", "trailing"),
        ("OsdkError", "bad_session", "is_ack"),
        ("OsdkError", "impossible_length", "len"),
        ("RangeError", None, "undefined"),
        ("RangeError", None, "undefined"),
        ("RangeError", None, "undefined"),
        ("RangeError", None, "undefined"),
        ("RangeError", None, "undefined"),
    ]


def test_absent_items_are_null():
    profile = "m100-fw3.1"
    items = list(api.broadcast_items(profile))
    frame = api.encode_broadcast_frame(profile, {"battery": 12}, seq=2)
    (got,) = run_cases([["absent", [frame.hex(), profile, items]]])
    assert got["items"] == {i: ("value" if i == "battery" else None) for i in items}
    # gps_detail is no item of m100-fw3.1: null as well, never undefined
    assert got["battery"] == 12 and got["gpsDetail"] is None and got["timeStamp"] is None
    command = api.encode_frame(cmd_set=1, cmd_id=0, value=b"\x01", session=1, seq=3)
    (not_broadcast,) = run_cases([["broadcastOf", [command.hex(), profile]]])
    assert not_broadcast == {"value": None}
