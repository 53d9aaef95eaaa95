"""The generated Python library (generated/python, package osdk_kaitai):
pip installs it, the examples built against the installed package
(examples/python, `make -C examples/python build`) print what
tests/library_examples.py expects, its encoders give the reference's bytes
at the edges, its errors carry the class and the field, and an absent
broadcast item is None.
"""
from __future__ import annotations

import filecmp
import os
import shutil
import struct
import subprocess
import sys
from pathlib import Path

import pytest

from osdk_conformance import _construct as osdk_construct
import osdk_kaitai
from osdk_conformance import api
from osdk_conformance.core import crc
from osdk_kaitai import Float32Bits, OsdkError

import library_examples

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples" / "python"
SITE = EXAMPLES / "build" / "site"
PROFILES = ("m100-fw2.3", "m100-fw3.1", "a3-fw3.1")
PIP = [sys.executable, "-m", "pip", "install", "--quiet", "--disable-pip-version-check", "--no-deps", "--no-compile"]


def _stale(site: Path) -> bool:
    installed, source = site / "osdk_kaitai", ROOT / "generated" / "python" / "osdk_kaitai"
    if not installed.is_dir():
        return True
    names = sorted(p.name for p in source.glob("*.py"))
    _, differ, missing = filecmp.cmpfiles(source, installed, names, shallow=False)
    return bool(differ or missing)


@pytest.fixture(scope="module")
def site() -> Path:
    """The package as `make -C examples/python build` installed it, built
    again when generated/python changed since."""
    if _stale(SITE):
        proc = subprocess.run(["make", "-s", "-C", str(EXAMPLES), "build"], capture_output=True, text=True,
                              timeout=300)
        assert proc.returncode == 0, proc.stdout + proc.stderr
    return SITE


def _run(site: Path, args: list[str], stdin: bytes = b"") -> subprocess.CompletedProcess:
    # the installed package first on the path, not the checkout's generated/python
    env = {**os.environ, "PYTHONPATH": str(site)}
    return subprocess.run([sys.executable, *args], input=stdin, capture_output=True, env=env, timeout=60)


@pytest.mark.slow
def test_pip_installs_the_package(tmp_path: Path) -> None:
    src = tmp_path / "src"
    shutil.copytree(ROOT / "generated" / "python", src, ignore=shutil.ignore_patterns("__pycache__"))
    proc = subprocess.run([*PIP, "--target", str(tmp_path / "site"), str(src)], capture_output=True, text=True,
                          timeout=300)
    assert proc.returncode == 0, proc.stderr
    probe = ("import importlib.metadata as m, osdk_kaitai; "
             "print(osdk_kaitai.__file__); print(m.version('osdk-kaitai')); print(m.requires('osdk-kaitai'))")
    out = _run(tmp_path / "site", ["-c", probe])
    assert out.returncode == 0, out.stderr
    where, version, requires = out.stdout.decode().splitlines()
    assert Path(where).is_relative_to(tmp_path / "site")
    assert version and requires == "['kaitaistruct==0.11']"


def test_the_examples_use_the_installed_package(site: Path) -> None:
    out = _run(site, ["-c", "import osdk_kaitai; print(osdk_kaitai.__file__)"])
    assert Path(out.stdout.decode().strip()).is_relative_to(site)


@pytest.mark.parametrize("profile", PROFILES)
def test_receive_example(site: Path, profile: str) -> None:
    proc = _run(site, [str(EXAMPLES / "receive.py"), profile], library_examples.receive_stream(profile))
    assert proc.returncode == 0, proc.stderr.decode()
    assert proc.stdout.decode().splitlines() == library_examples.receive_expected(profile)


def test_send_example(site: Path) -> None:
    proc = _run(site, [str(EXAMPLES / "send.py")])
    assert proc.returncode == 0, proc.stderr.decode()
    assert proc.stdout.decode().splitlines() == library_examples.send_expected()


def test_examples_refuse_bad_arguments(site: Path) -> None:
    for args in (["receive.py"], ["receive.py", "x9-fw9.9"], ["send.py", "extra"]):
        proc = _run(site, [str(EXAMPLES / args[0]), *args[1:]])
        assert proc.returncode == 2 and b"Traceback" not in proc.stderr
        assert len(proc.stderr.decode().strip().splitlines()) == 1


# ---- encoders against the reference ------------------------------------------------

F32_EDGES = (0x00000000, 0x80000000, 0x7F800000, 0xFF800000, 0x7F7FFFFF, 0x00000001,
             0x7FC00000, 0x7FA00001, 0xFFC12345, 0x7F800001, 0xFFFFFFFF)


@pytest.mark.parametrize("bits", F32_EDGES)
@pytest.mark.parametrize("mode", (0x00, 0x4B, 0xFF))
def test_movement_control_bits_are_the_references(mode: int, bits: int) -> None:
    args = (bits, bits ^ 0x80000000, 0x3F800000, bits)
    ours = osdk_kaitai.encode_movement_control(mode, *(Float32Bits(b) for b in args))
    assert ours == api.encode_movement_control(mode, *(api.F32(b) for b in args))
    assert ours == osdk_construct.encode_movement_control(mode, *(osdk_construct.F32(b) for b in args))
    assert ours[1:5] == bits.to_bytes(4, "little")


@pytest.mark.parametrize("value", (0.0, -0.0, float("inf"), float("-inf"), 1.0e-45, 3.4028234663852886e38, 30.000002))
def test_movement_control_floats_are_the_references(value: float) -> None:
    ours = osdk_kaitai.encode_movement_control(0x4B, value, -value, value, 1)
    assert ours == api.encode_movement_control(0x4B, value, -value, value, 1)
    assert ours[1:5] == struct.pack("<f", value)  # -0.0 keeps its sign


@pytest.mark.parametrize("kw", [
    dict(cmd_set=0, cmd_id=0, value=b""),
    dict(cmd_set=255, cmd_id=255, value=b"\xff" * 1005, session=31, seq=0xFFFF),
    dict(cmd_set=1, cmd_id=3, value=b"\x00" * 17, session=0, seq=0),
    dict(is_ack=True, value=b"", session=1, seq=7),
    dict(is_ack=True, value=b"\x00" * 1007, session=31, seq=0xFFFF),
])
def test_frames_are_the_references(kw: dict) -> None:
    full = {"cmd_set": None, "cmd_id": None, "is_ack": False, "session": 0, "seq": 0} | kw
    ours = osdk_kaitai.encode_frame(full["cmd_set"], full["cmd_id"], full["is_ack"], full["session"], full["seq"],
                                    full["value"])
    assert ours == api.encode_frame(**kw)
    assert ours == osdk_construct.build_frame(**kw)


def test_frame_rules_are_errors_in_the_decoders_order() -> None:
    with pytest.raises(OsdkError) as e:
        osdk_kaitai.encode_frame(1, 3, False, 0, 0, b"\x00" * 1006)
    assert (e.value.error_class, e.value.field) == ("impossible_length", "len")
    with pytest.raises(OsdkError) as e:
        osdk_kaitai.encode_frame(None, None, True, 0, 0, b"\x00\x00")
    assert (e.value.error_class, e.value.field) == ("bad_session", "is_ack")
    with pytest.raises(OsdkError) as e:  # LEN first, as decoding checks it first
        osdk_kaitai.encode_frame(None, None, True, 0, 0, b"\x00" * 1008)
    assert e.value.error_class == "impossible_length"


def test_command_encoders_at_their_limits() -> None:
    assert osdk_kaitai.encode_version_query(arbitrary=0xFF) == b"\xff"
    assert osdk_kaitai.encode_activation(0xFFFFFFFF, 0, 0xFFFFFFFF, bytes(range(32))) == \
        struct.pack("<III", 0xFFFFFFFF, 0, 0xFFFFFFFF) + bytes(range(32))
    assert osdk_kaitai.encode_set_frequency([7] * 16) == b"\x07" * 16
    assert osdk_kaitai.encode_control_authority(osdk_kaitai.OsdkPayload.ControlRequestCode.obtain) == b"\x01"


@pytest.mark.parametrize("call", [
    lambda: osdk_kaitai.encode_activation(1, 2, 3, b"x" * 31),
    lambda: osdk_kaitai.encode_activation(1 << 32, 2, 3, b"x" * 32),
    lambda: osdk_kaitai.encode_set_frequency([0] * 15),
    lambda: osdk_kaitai.encode_control_authority(256),
    lambda: osdk_kaitai.encode_movement_control(0, 1e300, 0, 0, 0),
    lambda: Float32Bits(1 << 32),
    lambda: osdk_kaitai.encode_frame(1, 3, False, 32, 0, b""),
    lambda: osdk_kaitai.encode_frame(1, 3, False, 0, 1 << 16, b""),
    lambda: osdk_kaitai.encode_frame(None, 3, False, 0, 0, b""),
    lambda: osdk_kaitai.decode_frame(bytes.fromhex(library_examples.WORKED_FRAME), "x9-fw9.9"),
])
def test_bad_arguments_are_argument_errors(call) -> None:
    with pytest.raises((ValueError, TypeError)) as e:
        call()
    assert not isinstance(e.value, OsdkError)


# ---- errors: class and field ----------------------------------------------------------

WORKED = bytes.fromhex(library_examples.WORKED_FRAME)


def _refresh_crcs(frame: bytearray) -> bytes:
    frame[10:12] = osdk_kaitai.crc16(bytes(frame[:10])).to_bytes(2, "little")
    frame[-4:] = osdk_kaitai.crc32(bytes(frame[:-4])).to_bytes(4, "little")
    return bytes(frame)


def _ack_in_session_0() -> bytes:
    frame = bytearray(api.encode_frame(is_ack=True, session=1, seq=5, value=b"\x00\x00"))
    frame[3] &= ~0x1F
    return _refresh_crcs(frame)


def _broadcast(profile: str, flags: int, value: bytes = b"") -> bytes:
    return api.encode_frame(cmd_set=2, cmd_id=0, value=struct.pack("<H", flags) + value, seq=1)


BATTERY_BIT_A3 = 1 << api.broadcast_items("a3-fw3.1").index("battery")


@pytest.mark.parametrize("data, error, field", [
    (b"", "truncated_frame", "sof"),
    (b"\x55" + WORKED[1:], "bad_sof", "sof"),
    (WORKED[:5], "truncated_frame", "res1"),
    (WORKED[:9], "truncated_frame", "seq"),
    (WORKED[:30], "truncated_frame", "data"),
    (WORKED[:-1], "truncated_frame", "crc32"),
    (WORKED + b"\x00", "length_mismatch", None),
    (WORKED[:10] + b"\x00\x00" + WORKED[12:], "bad_crc16", "crc16"),
    (WORKED[:-1] + bytes([WORKED[-1] ^ 1]), "bad_crc32", "crc32"),
    (_ack_in_session_0(), "bad_session", "is_ack"),
    (_broadcast("a3-fw3.1", BATTERY_BIT_A3), "truncated_payload", "battery"),
    (_broadcast("a3-fw3.1", 1 << 15), "reserved_bits", "reserved_flags"),
    (_broadcast("a3-fw3.1", 1, b"\x00\x00"), "truncated_payload", "time"),
    (api.encode_frame(cmd_set=1, cmd_id=3, value=WORKED[14:30]), "truncated_payload", "yaw"),
    (api.encode_frame(cmd_set=1, cmd_id=3, value=WORKED[14:31] + b"\x00"), "length_mismatch", "trailing"),
    (api.encode_frame(cmd_set=1, cmd_id=0, value=b""), "truncated_payload", "request"),
])
def test_decode_frame_errors_name_class_and_field(data: bytes, error: str, field: str | None) -> None:
    with pytest.raises(OsdkError) as e:
        osdk_kaitai.decode_frame(data, "a3-fw3.1")
    assert (e.value.error_class, e.value.field) == (error, field)
    assert isinstance(e.value, ValueError) and e.value.detail and "\n" not in e.value.detail


def test_decode_payload_errors() -> None:
    with pytest.raises(OsdkError) as e:
        osdk_kaitai.decode_payload(b"\x01\x00", 0, 1, False, "m100-fw3.1")
    assert (e.value.error_class, e.value.field) == ("truncated_payload", "app_id")
    assert osdk_kaitai.decode_payload(b"\x07", 9, 9, False, "m100-fw3.1").raw == b"\x07"


# ---- absent is None ---------------------------------------------------------------------

@pytest.mark.parametrize("profile", PROFILES)
def test_absent_items_are_none(profile: str) -> None:
    items = api.broadcast_items(profile)
    frame = osdk_kaitai.decode_frame(api.encode_broadcast_frame(profile, {"battery": 0}, seq=2), profile)
    bc = osdk_kaitai.broadcast_of(frame)
    assert bc.battery == 0  # present and zero is not absent
    for item in set(osdk_kaitai.BROADCAST_ITEMS["a3-fw3.1"]) | set(items):
        if item != "battery":
            assert getattr(bc, item) is None, item
    full = osdk_kaitai.decode_frame(api.encode_broadcast_frame(profile, {i: None for i in items}, seq=3), profile)
    bc = osdk_kaitai.broadcast_of(full)
    assert all(getattr(bc, i) is not None for i in items)
    assert bc.gps_detail is None if "gps_detail" not in items else bc.gps_detail is not None


def test_not_a_broadcast_is_none() -> None:
    for frame in (WORKED, api.encode_frame(session=0, seq=7), api.encode_frame(is_ack=True, session=1, value=b"\0")):
        assert osdk_kaitai.broadcast_of(osdk_kaitai.decode_frame(frame, "a3-fw3.1")) is None


def test_crcs_and_tables() -> None:
    assert osdk_kaitai.crc16(b"123456789") == crc.crc16(b"123456789")
    assert osdk_kaitai.crc32(b"123456789") == crc.crc32(b"123456789")
    assert tuple(osdk_kaitai.BROADCAST_ITEMS[p] for p in PROFILES) == tuple(api.broadcast_items(p) for p in PROFILES)

