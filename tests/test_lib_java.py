"""The generated Java library (generated/java) as a user's project sees it:
the examples built by `make -C examples/java build` (the library installed
with `mvn install`, the examples depending on the artifact) print what
tests/library_examples.py expects, and the jar's `check` mode answers the
edge cases the examples do not reach (encoders against the reference bit
for bit, OsdkException's class and field, absent items) for the reference
to judge. One JVM per program run; nothing is built here."""
from __future__ import annotations

import shutil
import struct
import subprocess
from pathlib import Path

import pytest

from osdk_conformance import api

from library_examples import receive_expected, receive_stream, send_expected

ROOT = Path(__file__).resolve().parents[1]
JAR = ROOT / "examples" / "java" / "target" / "osdk-examples.jar"
PROFILES = api.profiles()


def _jar() -> Path:
    if not JAR.exists():
        if shutil.which("java") is None or shutil.which("mvn") is None:
            pytest.skip("no JDK/Maven and no built examples")
        pytest.fail(f"{JAR} is missing: run `make -C examples/java build`")
    return JAR


def _run(*args: str, stdin: bytes = b"") -> str:
    proc = subprocess.run(["java", "-jar", str(_jar()), *args], input=stdin, capture_output=True, timeout=60)
    assert proc.returncode == 0, proc.stderr.decode()
    return proc.stdout.decode()


def _check(requests: list[str]) -> list[str]:
    lines = _run("check", stdin="".join(r + "\n" for r in requests).encode()).splitlines()
    assert len(lines) == len(requests)
    return lines


def _ref_error(frame: bytes, profile: str) -> str:
    """The reference's error class for one frame with a good header and CRC-32."""
    [event] = api.decode(frame, profile)
    assert event.kind == "error"
    return event.error


@pytest.mark.parametrize("profile", PROFILES)
def test_receive_example(profile):
    assert _run("receive", profile, stdin=receive_stream(profile)).splitlines() == receive_expected(profile)


def test_send_example():
    assert _run("send").splitlines() == send_expected()


def test_examples_reject_bad_arguments():
    for args in (["receive", "no-such-profile"], ["nothing"]):
        proc = subprocess.run(["java", "-jar", str(_jar()), *args], capture_output=True, timeout=60)
        assert proc.returncode == 2
        assert len(proc.stderr.decode().strip().splitlines()) == 1 and b"Exception" not in proc.stderr


# float bits the encoders must keep: signalling and quiet NaNs with payloads, -0.0, infinities, subnormals
BITS = [0x7F800001, 0x7FC12345, 0xFFFFFFFF, 0xFFA00001, 0x80000000, 0x00000000, 0x7F800000, 0xFF800000,
        0x00000001, 0x807FFFFF, 0x7F7FFFFF, 0x3F800000]


def _signalling(bits: int) -> bool:
    return (bits & 0x7F800000) == 0x7F800000 and bits & 0x7FFFFF and not bits & 0x400000


def test_encode_movement_control_bit_exact():
    cases = []
    for i, x in enumerate(BITS):
        mode = (0x4B, 0x00, 0xFF)[i % 3]
        y, z, yaw = BITS[(i + 1) % len(BITS)], BITS[(i + 5) % len(BITS)], BITS[(i + 7) % len(BITS)]
        cases.append((mode, x, y, z, yaw))
    answers = _check([f"movement {m:x} {x:x} {y:x} {z:x} {w:x}" for m, x, y, z, w in cases])
    for (mode, *bits), answer in zip(cases, answers):
        expected = api.encode_movement_control(mode, *(api.F32(b) for b in bits)).hex()
        from_bits, from_floats = answer.split()
        assert from_bits == expected
        if not any(_signalling(b) for b in bits):  # Java may quiet a signalling NaN float
            assert from_floats == expected


def test_encode_frame_against_the_reference():
    cases = [  # (cmd_set, cmd_id, is_ack, session, seq, value)
        (1, 3, False, 0, 0x1234, bytes(17)),
        (0, 0, True, 5, 7, b"\x00\x00"),
        (0, 0, True, 3, 0xFFFF, b""),  # header-only
        (2, 0, False, 31, 1, bytes(1023 - 18)),  # the longest frame
    ]
    answers = _check([f"frame {c:x} {i:x} {int(a)} {s:x} {q:x} {v.hex() or '-'}" for c, i, a, s, q, v in cases])
    for (cmd_set, cmd_id, is_ack, session, seq, value), answer in zip(cases, answers):
        ids = {} if is_ack else {"cmd_set": cmd_set, "cmd_id": cmd_id}
        assert answer == api.encode_frame(**ids, value=value, is_ack=is_ack, session=session, seq=seq).hex()


def test_encode_frame_errors():
    assert _check([
        "frame 0 0 1 0 1 0000",  # an ACK in session 0
        f"frame 2 0 0 1 1 {'00' * (1023 - 17)}",  # one byte too long
        f"frame 0 0 1 0 1 {'00' * 1100}",  # too long and session 0: the length first
        "frame 0 0 0 20 1 00",  # session 32
        "frame 100 0 0 1 1 00",  # cmd_set 256
    ]) == ["error bad_session is_ack", "error impossible_length len", "error impossible_length len",
           "argument", "argument"]


def _flags(profile: str, *items: str) -> bytes:
    order = api.broadcast_items(profile)
    return struct.pack("<H", sum(1 << order.index(i) for i in items))


@pytest.mark.parametrize("profile", PROFILES)
def test_errors_name_class_and_field(profile):
    good = api.encode_frame(cmd_set=1, cmd_id=0, value=b"\x01", session=1, seq=2)
    bad_crc = good[:-1] + bytes([good[-1] ^ 1])

    def broadcast(value: bytes) -> bytes:
        return api.encode_frame(cmd_set=2, cmd_id=0, value=value, seq=9)

    frames = [  # (frame, class, field): the class is the reference's too
        (broadcast(_flags(profile, "battery")), "truncated_payload", "battery"),
        (broadcast(_flags(profile, "time_stamp") + b"\x00\x00"), "truncated_payload", "time"),
        (broadcast(struct.pack("<H", 1 << 15)), "reserved_bits", "reserved_flags"),
        (broadcast(_flags(profile, "battery") + b"\x01\x02"), "length_mismatch", "trailing"),
        (api.encode_frame(cmd_set=1, cmd_id=0, value=b"\x01\x00", seq=3), "length_mismatch", "trailing"),
    ]
    requests, expected = [], []
    for frame, cls, fld in frames:
        assert _ref_error(frame, profile) == cls
        requests.append(f"decode {profile} {frame.hex()}")
        expected.append(f"error {cls} {fld}")
    for raw, line in [
        (b"", "error truncated_frame sof"),
        (b"\x55" + good[1:], "error bad_sof sof"),
        (good[:5], "error truncated_frame res1"),
        (good[:-2], "error truncated_frame crc32"),
        (good + b"\x00", "error length_mismatch len"),
        (bad_crc, "error bad_crc32 crc32"),
        (good, "ok"),
    ]:
        requests.append(f"decode {profile} {raw.hex() or '-'}")
        expected.append(line)
    movement = api.encode_movement_control(0x4B, 1.0, 2.0, 3.0, 4.0)
    requests += [f"payload {profile} 1 3 0 {movement[:-1].hex()}", f"payload {profile} 1 3 0 {movement.hex()}00",
                 f"payload {profile} 1 3 0 {movement.hex()}", f"payload no-such-profile 1 3 0 {movement.hex()}"]
    expected += ["error truncated_payload yaw", "error length_mismatch trailing", "ok", "argument"]
    assert _check(requests) == expected


def test_absent_items_are_null():
    full_a3 = api.encode_broadcast_frame("a3-fw3.1", {i: None for i in api.broadcast_items("a3-fw3.1")}, seq=1)
    some_m100 = api.encode_broadcast_frame("m100-fw3.1", {"battery": 3}, seq=1)
    control = api.encode_frame(cmd_set=1, cmd_id=0, value=bytes([1]))
    a3, m100, command = _check([f"items a3-fw3.1 {full_a3.hex()}", f"items m100-fw3.1 {some_m100.hex()}",
                                f"items m100-fw3.1 {control.hex()}"])
    assert "=null" not in a3 and a3.endswith("gps_detail()=set")
    every = {i for p in PROFILES for i in api.broadcast_items(p)}
    *items, gps = m100.split()
    assert gps == "gps_detail()=null"  # a3-fw3.1's item, not m100-fw3.1's: absent too
    assert sorted(items) == sorted(f"{i}={'set' if i == 'battery' else 'null'}" for i in every)
    assert command == "not a broadcast"
