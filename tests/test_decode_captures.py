"""`osdkc decode` on captures as recordings make them: the end of a
recording cut inside a frame is noted, not an error (exit 0, the tail event
marked `"capture_end": true`), on both decoders and both directions, while a
frame the device cut short and a short --hex stay errors; a pcapng capture
cut inside a block is warned about; an input without a frame says so and
exits 1; a stream decoded with the wrong --profile names the profile it
decodes with. Captures are written with the kit's own CaptureWriter, frames
built with the spec (osdk_construct) and the API's broadcast encoder.
Runs osdkc in this process (cli.main), reading its output with capsys."""
from __future__ import annotations

import io
import json
import sys
from pathlib import Path

import pytest

from osdk_conformance import api, cli
from osdk_conformance.core.capture import CaptureWriter
from osdk_conformance.reference import values
from osdk_conformance.reference.decode import profiles_decoding
from osdk_conformance.reference.worked_examples import BROADCAST
from osdk_conformance._construct import build_frame

FRAME = bytes.fromhex(BROADCAST.hex)   # 22 bytes, a3-fw3.1
# A 21-byte broadcast with 0xAA at offsets 8 (its SEQ) and 16 (the battery):
# cut at 20 bytes, the receiver's rescan of it reports a bad_crc16 and two
# more truncated_frames, all inside the bytes the recording cut.
AA_INSIDE = api.encode_broadcast_frame("a3-fw3.1", {"battery": 0xAA}, seq=0xAA)
TAIL_NOTE = "osdkc decode: the input{} ends inside a frame ({} of {} bytes): the recording stopped there; " \
            "not counted as an error"


@pytest.fixture(params=["0", "1"], ids=["pure-python", "native"])
def decoder(request, monkeypatch):
    """Both decoders: the reference (Construct) and the native one (accel.py)."""
    monkeypatch.setenv("OSDKC_ACCEL", request.param)
    return request.param


def decode(capsys, *args: str) -> tuple[int, list[dict], list[str]]:
    """osdkc decode's exit status, its events and its lines on standard error."""
    status = cli.main(["decode", *args])
    out, err = capsys.readouterr()
    assert "Traceback" not in err
    return status, [json.loads(line) for line in out.splitlines()], err.strip().splitlines()


def capture(path: Path, *records: tuple[str, bytes]) -> Path:
    writer = CaptureWriter(path, {"profile": "a3-fw3.1"})
    for direction, data in records:
        (writer.rx if direction == "rx" else writer.tx)(data)
    writer.close()
    return path


# ---------------------------------------------------------------- the end of a recording


def test_a_capture_ending_one_byte_into_a_frame_exits_0_and_marks_the_tail(tmp_path, capsys, decoder):
    path = capture(tmp_path / "run.pcapng", ("rx", FRAME * 3), ("rx", FRAME[:1]))
    status, events, err = decode(capsys, "--profile", "a3-fw3.1", str(path))
    assert status == 0
    assert [e["kind"] for e in events] == ["frame"] * 3 + ["error"]
    tail = events[-1]
    assert (tail["offset"], tail["error"], tail["length"], tail["capture_end"]) == (66, "truncated_frame", 1, True)
    assert all("capture_end" not in e for e in events[:-1])
    assert err == [TAIL_NOTE.format("", 1, "12+")]


def test_the_rescan_of_the_cut_frame_is_part_of_the_tail(tmp_path, capsys, decoder):
    # raw bytes this time, from a file and from standard input alike
    data = AA_INSIDE + AA_INSIDE[:20]
    path = tmp_path / "run.bin"
    path.write_bytes(data)
    status, events, err = decode(capsys, "--profile", "a3-fw3.1", str(path))
    assert status == 0, events
    tail = events[1:]
    assert [(e["offset"], e.get("error") or e["kind"]) for e in tail] == [
        (21, "truncated_frame"), (22, "garbage"), (29, "bad_crc16"), (30, "garbage"), (37, "truncated_frame"),
        (38, "garbage")]
    assert [e.get("capture_end") for e in tail] == [True, None, True, None, True, None]
    assert err == [TAIL_NOTE.format("", 20, 21)]   # the header was whole: its LEN says 21
    sys_stdin = io.TextIOWrapper(io.BytesIO(data))
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(sys, "stdin", sys_stdin)
        assert decode(capsys, "--profile", "a3-fw3.1", "-") == (status, events, err)


def test_each_direction_of_a_capture_has_its_own_tail(tmp_path, capsys, decoder):
    path = capture(tmp_path / "run.pcapng", ("rx", FRAME * 2), ("tx", FRAME[:5]), ("rx", FRAME[:15]))
    status, events, err = decode(capsys, "--profile", "a3-fw3.1", "--direction", "both", str(path))
    assert status == 0
    marked = [(e["direction"], e["offset"], e["length"]) for e in events if e.get("capture_end")]
    assert marked == [("rx", 44, 15), ("tx", 0, 5)]
    assert err == [TAIL_NOTE.format(" (rx)", 15, 22), TAIL_NOTE.format(" (tx)", 5, "12+")]


def test_a_frame_the_device_cut_short_mid_stream_is_an_error(tmp_path, capsys, decoder):
    path = tmp_path / "run.bin"
    # cut at 15 bytes and followed by whole frames: its LEN takes bytes of the next one, CRC-32 fails
    path.write_bytes(FRAME + FRAME[:15] + FRAME * 2)
    status, events, err = decode(capsys, "--profile", "a3-fw3.1", str(path))
    assert status == 1 and err == []
    assert "bad_crc32" in [e.get("error") for e in events]
    assert not any(e.get("capture_end") for e in events)


def test_a_truncated_frame_followed_by_a_whole_frame_is_an_error(tmp_path, capsys, decoder):
    # A long frame cut short, then a whole frame, then the end of the input before
    # the long frame's LEN: the whole frame found in its rescan shows the device cut it.
    long = build_frame(cmd_set=1, cmd_id=3, value=bytes(100))
    path = capture(tmp_path / "run.pcapng", ("rx", long[:30] + FRAME))
    status, events, err = decode(capsys, "--profile", "a3-fw3.1", str(path))
    assert status == 1 and err == []
    assert events[0]["error"] == "truncated_frame" and "capture_end" not in events[0]
    assert events[-1]["kind"] == "frame" and events[-1]["offset"] == 30


def test_a_short_frame_given_with_hex_is_an_error(capsys, decoder):
    status, events, err = decode(capsys, "--profile", "a3-fw3.1", "--hex", FRAME[:15].hex())
    assert status == 1 and err == []
    assert events[0]["error"] == "truncated_frame" and not any(e.get("capture_end") for e in events)


def test_a_whole_capture_says_nothing_on_stderr(tmp_path, capsys):
    path = capture(tmp_path / "run.pcapng", ("rx", FRAME * 3))
    assert decode(capsys, "--profile", "a3-fw3.1", str(path))[::2] == (0, [])


# ---------------------------------------------------------------- a pcapng capture cut inside a block


def test_a_capture_cut_inside_a_block_is_warned_about(tmp_path, capsys):
    path = capture(tmp_path / "run.pcapng", ("rx", FRAME * 2), ("rx", FRAME))
    whole = path.read_bytes()
    path.write_bytes(whole[:-9])   # the writer killed in the middle of its last block
    status, events, err = decode(capsys, "--profile", "a3-fw3.1", str(path))
    assert status == 0
    assert [(e["kind"], e["offset"]) for e in events] == [("frame", 0), ("frame", 22)]
    (line,) = err
    block = 12 + 20 + 24 + 12          # the last EPB: 22 bytes padded to 24, epb_flags and the end of options
    assert line.startswith(f"osdkc decode: warning: the capture is cut inside a pcapng block after {block - 9} bytes")
    assert f"offset {len(whole) - block}" in line and line.endswith("the frames before it are decoded")


# ---------------------------------------------------------------- inputs without a frame


@pytest.mark.parametrize("what", ["empty", "pcapng header only", "text"])
def test_an_input_without_a_frame_says_so_and_exits_1(tmp_path, capsys, what):
    path = tmp_path / "input"
    if what == "empty":
        path.write_bytes(b"")
    elif what == "pcapng header only":
        capture(path)
    else:
        path.write_text("time,altitude\n" + "12.5,40.1\n" * 300)
    size = path.stat().st_size
    status, events, err = decode(capsys, "--profile", "a3-fw3.1", str(path))
    assert status == 1
    assert err[-1].startswith(f"osdkc decode: no frame found in {path} ({size} bytes")
    assert not any(e["kind"] == "error" for e in events)   # no start byte: one run of garbage at most
    assert len(events) <= 1


def test_empty_standard_input_has_no_frame_either(capsys, monkeypatch):
    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(b"")))
    assert decode(capsys, "--profile", "a3-fw3.1", "-") == (
        1, [], ["osdkc decode: no frame found in standard input (0 bytes)"])


# ---------------------------------------------------------------- the wrong profile


def m100_broadcasts(count: int) -> bytes:
    items = {item: None for item in values.items("m100-fw3.1")}   # every item, at rest
    return b"".join(api.encode_broadcast_frame("m100-fw3.1", items, seq=seq) for seq in range(count))


def test_the_wrong_profile_is_named_with_the_right_one(tmp_path, capsys, decoder):
    path = capture(tmp_path / "m100.pcapng", ("rx", m100_broadcasts(40)), ("rx", FRAME))
    status, events, err = decode(capsys, "--profile", "a3-fw3.1", str(path))
    assert status == 1 and len(events) == 41
    assert err == ["osdkc decode: 40 of 41 broadcast frames do not decode as a3-fw3.1; they decode as "
                   "m100-fw3.1: try --profile m100-fw3.1"]
    status, events, err = decode(capsys, "--profile", "m100-fw3.1", str(path))
    assert err == []  # one a3 frame among m100 ones is an error, not most of them


def test_device_and_decode_share_the_profile_guess():
    value = lambda profile: api.encode_broadcast(profile, {item: None for item in values.items(profile)})
    assert profiles_decoding([value("m100-fw3.1")], "a3-fw3.1") == ["m100-fw3.1"]
    assert profiles_decoding([value("a3-fw3.1")], "m100-fw3.1") == ["a3-fw3.1"]
    assert profiles_decoding([b"\xff"], "a3-fw3.1") == []
