"""pcapng captures: the block layout Wireshark expects, crash safety (a
SIGKILLed device run leaves a readable capture that replays), damage reported
with the file name and offset, reading block by block in bounded memory, and
`osdkc decode` reading a capture like a raw byte file, either direction."""
from __future__ import annotations

import json
import signal
import struct
import subprocess
import sys
import time
import tracemalloc

import pytest

from osdk_conformance.core.capture import (EPB_TYPE, IDB_TYPE, LINKTYPE_USER0, RX, SHB_TYPE, TX, CaptureError,
                                      CaptureReader, CaptureWriter, read_capture)
from osdk_conformance.reference.decode import received_bytes
from osdk_conformance.core.deframe import split_chunks
from osdk_conformance.sim.simulator import spawned
from osdk_conformance.reference.worked_examples import BROADCAST, MOVEMENT
from osdk_conformance._construct import build_frame


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


# Measures rates and timing of a live simulator: tools/run_tests.py runs the
# `realtime` tests one at a time, at a higher priority than the CPU-heavy rest.
@pytest.mark.realtime
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


def osdkc(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "osdk_conformance.cli", *args], capture_output=True, text=True,
                          timeout=60)


def ten_records(path) -> list[int]:
    """A capture of ten rx records of 7 bytes; the byte offset of each record's block."""
    w = CaptureWriter(path)
    for i in range(10):
        w.rx(bytes([i]) * 7)
    w.close()
    data = path.read_bytes()
    first = len(data) - 10 * 52  # an EPB of 7 bytes: 12 + 20 + 8 (data, padded) + 12 (epb_flags and end)
    assert struct.unpack_from("<II", data, first) == (EPB_TYPE, 52)
    return [first + 52 * i for i in range(10)]


def damage(path, offset: int, value: int) -> None:
    data = bytearray(path.read_bytes())
    struct.pack_into("<I", data, offset, value)
    path.write_bytes(bytes(data))


@pytest.mark.parametrize("field, value, what", [
    # one word too long: where its trailing copy should be, the next block starts
    (4, 56, "block length 56 does not match its trailing copy 6"),
    (4, 50, "bad block length 50 for block type 0x00000006"),          # not a multiple of 4
    (4, 28, "bad block length 28 for block type 0x00000006"),          # shorter than a packet block
    (4, 0x7FFFFFF0, "bad block length 2147483632 for block type 0x00000006"),  # far past the end
    (0, 0x12345678, "unknown block type 0x12345678"),
    (8, 5, "packet of interface 5, but the section describes 2"),
    (20, 4096, "packet of 4096 bytes in a block of 52"),               # captured length past the block
])
def test_a_damaged_block_in_the_middle_is_reported_with_file_and_offset(tmp_path, field, value, what):
    path = tmp_path / "damaged.pcapng"
    offsets = ten_records(path)
    damage(path, offsets[4] + field, value)
    with pytest.raises(CaptureError) as e:
        read_capture(path)
    assert str(e.value) == f"{path}: damaged capture at offset {offsets[4]}: {what}"


def test_decode_and_replay_blame_the_capture_not_the_device(tmp_path):
    path = tmp_path / "damaged.pcapng"
    offsets = ten_records(path)
    damage(path, offsets[4] + 4, 56)
    what = "block length 56 does not match its trailing copy 6"
    for argv in (["decode", "--profile", "a3-fw3.1", str(path)],
                 ["device", "--replay", str(path), "--profile", "a3-fw3.1"]):
        proc = osdkc(*argv)
        assert proc.returncode == 2 and "Traceback" not in proc.stderr
        assert proc.stderr.strip().splitlines()[-1] == f"osdkc: {path}: damaged capture at offset {offsets[4]}: {what}"


def test_reading_in_pieces_of_any_size_gives_the_same_records(tmp_path):
    path = tmp_path / "c.pcapng"
    ten_records(path)
    data = path.read_bytes()[:-9]  # and a partial last block
    whole = read_capture(path)  # unchanged file: nothing partial
    for size in (1, 7, 44, 1000):
        reader = CaptureReader(split_chunks(data, [size] * (len(data) // size)), "pieces")
        records = list(reader)
        assert [r.data for r in records] == [r.data for r in whole.records[:9]]
        assert reader.partial_tail == 52 - 9 and reader.count == 9


def test_reading_a_capture_keeps_one_block_in_memory(tmp_path):
    path = tmp_path / "big.pcapng"
    w = CaptureWriter(path, fsync_interval=60)
    for i in range(256):
        w.rx(bytes([i]) * 65536)  # the writer's largest record: one read() of 64 KiB
    w.close()
    tracemalloc.start()
    try:
        with path.open("rb") as fh:
            total = sum(len(chunk) for chunk in received_bytes(iter(lambda: fh.read(65536), b"")))
        peak = tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()
    assert total == 256 * 65536
    assert peak < 1 << 20, f"{peak} bytes for a {path.stat().st_size}-byte capture"


def test_decode_shows_the_sent_direction_too(tmp_path):
    cmd = build_frame(cmd_set=1, cmd_id=0, value=b"\x01", session=2, seq=40)
    ack = build_frame(is_ack=True, value=b"\x03\x00", session=2, seq=40)
    path = tmp_path / "c.pcapng"
    w = CaptureWriter(path)
    w.tx(cmd[:5])                        # a command split over two writes,
    w.rx(bytes.fromhex(BROADCAST.hex))   # a broadcast received in between,
    w.tx(cmd[5:])
    w.rx(ack)                            # and the flight controller's answer
    w.close()
    decode = lambda direction: osdkc("decode", "--profile", "a3-fw3.1", "--direction", direction, str(path))
    rx, tx, both = decode("rx"), decode("tx"), decode("both")
    assert rx.returncode == tx.returncode == both.returncode == 0, rx.stderr + tx.stderr + both.stderr
    assert osdkc("decode", "--profile", "a3-fw3.1", str(path)).stdout == rx.stdout   # rx is the default
    events = lambda proc: [json.loads(line) for line in proc.stdout.splitlines()]
    assert [(e["offset"], e.get("command")) for e in events(rx)] == [(0, "broadcast"), (22, "ack")]
    assert [(e["offset"], e["command"]) for e in events(tx)] == [(0, "control_authority")]
    assert [(e["direction"], e["offset"], e.get("command") or e.get("ack_of")) for e in events(both)] == [
        ("rx", 0, "broadcast"), ("tx", 0, "control_authority"), ("rx", 22, "control_authority")]
    assert events(both)[2]["ack"] == {"ack_code": {"value": 3, "name": "obtain_in_progress"}}


def test_direction_tx_of_raw_bytes_is_a_usage_error(tmp_path):
    raw = tmp_path / "raw.bin"
    raw.write_bytes(bytes.fromhex(BROADCAST.hex))
    proc = osdkc("decode", "--profile", "a3-fw3.1", "--direction", "tx", str(raw))
    assert proc.returncode == 2 and proc.stdout == ""
    (line,) = proc.stderr.strip().splitlines()
    assert line.startswith(f"osdkc: {raw}: raw bytes hold only what was received")
