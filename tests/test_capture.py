"""pcapng captures: the block layout Wireshark expects, crash safety (a
SIGKILLed device run leaves a readable capture that replays), and
`osdkc decode` reading a capture like a raw byte file."""
from __future__ import annotations

import signal
import struct
import subprocess
import sys
import time

import pytest

from osdk_conformance.capture import (EPB_TYPE, IDB_TYPE, LINKTYPE_USER0, RX, SHB_TYPE, TX, CaptureWriter,
                                      read_capture)
from osdk_conformance.sim import spawned
from osdk_conformance.worked_examples import BROADCAST, MOVEMENT

# Measures rates and timing of a live simulator: run alone, never beside
# CPU-heavy tests (the Makefile runs the `realtime` tests after the rest).
pytestmark = pytest.mark.realtime


def blocks(data: bytes):
    pos = 0
    while pos < len(data):
        btype, total = struct.unpack_from("<II", data, pos)
        assert total % 4 == 0 and struct.unpack_from("<I", data, pos + total - 4)[0] == total
        yield btype, data[pos + 8:pos + total - 4]
        pos += total


def test_layout_is_shb_two_idbs_then_epbs_with_direction_flags(tmp_path):
    path = tmp_path / "c.pcapng"
    w = CaptureWriter(path, {"profile": "a3-fw3.1"})
    w.rx(b"\xaa\x01\x02", ts_ns=1_700_000_000_123_456_789)
    w.tx(b"\xaa" * 5, ts_ns=1_700_000_000_223_456_789)
    w.close()
    bl = list(blocks(path.read_bytes()))
    assert [b[0] for b in bl] == [SHB_TYPE, IDB_TYPE, IDB_TYPE, EPB_TYPE, EPB_TYPE]
    magic, major, minor, section_len = struct.unpack_from("<IHHq", bl[0][1])
    assert (magic, major, minor, section_len) == (0x1A2B3C4D, 1, 0, -1)
    for _, body in bl[1:3]:
        assert struct.unpack_from("<H", body)[0] == LINKTYPE_USER0
        assert b"\x09\x00\x01\x00\x09" in body          # if_tsresol = 9 (nanoseconds)
    iface, hi, lo, caplen, orig = struct.unpack_from("<IIIII", bl[3][1])
    assert (iface, hi << 32 | lo, caplen, orig) == (0, 1_700_000_000_123_456_789, 3, 3)
    assert bl[3][1].endswith(struct.pack("<HHI", 2, 4, 1) + b"\0\0\0\0")   # epb_flags inbound
    assert bl[4][1].endswith(struct.pack("<HHI", 2, 4, 2) + b"\0\0\0\0")   # epb_flags outbound
    cap = read_capture(path)
    assert cap.comment == {"profile": "a3-fw3.1"} and cap.partial_tail == 0
    assert [(r.direction, r.data, r.ts_ns) for r in cap.records] == [
        (RX, b"\xaa\x01\x02", 1_700_000_000_123_456_789), (TX, b"\xaa" * 5, 1_700_000_000_223_456_789)]


def test_a_partial_last_block_is_reported_and_the_rest_read(tmp_path):
    path = tmp_path / "c.pcapng"
    w = CaptureWriter(path)
    for i in range(10):
        w.rx(bytes([i]) * 7)
    w.close()
    data = path.read_bytes()
    path.write_bytes(data[:-9])
    cap = read_capture(path)
    assert len(cap.records) == 9 and cap.partial_tail > 0
    assert [r.data for r in cap.records] == [bytes([i]) * 7 for i in range(9)]


def test_decode_reads_a_capture_like_the_bytes_it_received(tmp_path):
    rx = b"\x00" + bytes.fromhex(MOVEMENT.hex) + bytes.fromhex(BROADCAST.hex)
    path = tmp_path / "c.pcapng"
    w = CaptureWriter(path)
    w.rx(rx[:10])
    w.tx(b"\xaa\xbb\xcc")               # sent bytes are not part of the received stream
    w.rx(rx[10:])
    w.close()
    raw = tmp_path / "raw.bin"
    raw.write_bytes(rx)
    run = lambda f: subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "decode", "--profile", "a3-fw3.1",
                                    str(f)], capture_output=True, timeout=60)
    a, b = run(path), run(raw)
    assert a.returncode == b.returncode == 0
    assert a.stdout == b.stdout and a.stdout.count(b'"kind": "frame"') == 2


def test_sigkilled_device_run_leaves_a_capture_that_replays(tmp_path):
    cap = tmp_path / "killed.pcapng"
    with spawned("--profile", "m100-fw2.3") as (url, _):
        dev = subprocess.Popen([sys.executable, "-m", "osdk_conformance.cli", "device", "--port", url, "--profile",
                                "m100-fw2.3", "--duration", "30", "--capture", str(cap)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        time.sleep(3.0)
        dev.send_signal(signal.SIGKILL)
        dev.wait(timeout=10)
    c = read_capture(cap)
    assert c.comment["profile"] == "m100-fw2.3" and c.comment["port"] == url
    assert sum(len(r.data) for r in c.records if r.direction == RX) > 5000
    html = tmp_path / "replay.html"
    rep = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "device", "--replay", str(cap), "--profile",
                          "m100-fw2.3", "--html", str(html), "--max-jitter-ms", "150"],
                         capture_output=True, text=True, timeout=60)
    assert rep.returncode == 0, rep.stdout + rep.stderr
    assert "PASS  stream.rates" in rep.stdout and "PASS  values.time_stamp" in rep.stdout
    assert "<svg" in html.read_text()
    wrong = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "device", "--replay", str(cap), "--profile",
                            "a3-fw3.1"], capture_output=True, text=True, timeout=60)
    assert wrong.returncode == 1 and "FAIL  decode.profile" in wrong.stdout


def test_replay_of_something_that_is_not_a_capture_is_a_usage_error(tmp_path):
    f = tmp_path / "x.bin"
    f.write_bytes(b"hello")
    p = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "device", "--replay", str(f), "--profile",
                        "a3-fw3.1"], capture_output=True, text=True, timeout=60)
    assert p.returncode == 2 and "not a pcapng" in p.stderr
