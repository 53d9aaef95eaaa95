"""The deframer finds frames as the SDK's receiver does, and says why it
dropped everything it dropped."""
from __future__ import annotations

from hypothesis import given, strategies as st

from osdk_conformance.core.crc import crc16, crc32
from osdk_conformance.core.deframe import Frame, Garbage, Rejected, deframe, header_fields
from osdk_conformance.reference.worked_examples import BROADCAST, MOVEMENT
from osdk_conformance._construct import build_frame

MOVE = bytes.fromhex(MOVEMENT.hex)
BCAST = bytes.fromhex(BROADCAST.hex)


def events(data: bytes, chunk: int | None = None):
    chunks = [data] if chunk is None else [data[i:i + chunk] for i in range(0, len(data), chunk)]
    return list(deframe(chunks))


def frames(evs):
    return [(e.offset, e.raw) for e in evs if isinstance(e, Frame)]


def errors(evs):
    return [(e.offset, e.error) for e in evs if isinstance(e, Rejected)]


def with_header(frame: bytes, **changes) -> bytes:
    """The frame with header bytes changed and both CRCs made right again."""
    b = bytearray(frame)
    for index, value in changes.items():
        b[int(index[1:])] = value
    b[10:12] = crc16(bytes(b[:10])).to_bytes(2, "little")
    if len(b) > 12:
        b[-4:] = crc32(bytes(b[:-4])).to_bytes(4, "little")
    return bytes(b)


def test_worked_frames_back_to_back():
    evs = events(MOVE + BCAST)
    assert frames(evs) == [(0, MOVE), (len(MOVE), BCAST)]
    assert errors(evs) == []


def test_garbage_between_frames_is_reported_as_runs():
    evs = events(b"\x00\x01\x02" + MOVE + b"\x55" * 7 + BCAST + b"\x10")
    assert frames(evs) == [(3, MOVE), (3 + len(MOVE) + 7, BCAST)]
    assert [(e.offset, e.length) for e in evs if isinstance(e, Garbage)] == [
        (0, 3), (3 + len(MOVE), 7), (3 + len(MOVE) + 7 + len(BCAST), 1)]


def test_bad_crc16_drops_one_byte_and_rescans():
    bad = bytearray(MOVE)
    bad[10] ^= 0x01
    evs = events(bytes(bad) + BCAST)
    assert errors(evs)[0] == (0, "bad_crc16")
    assert frames(evs) == [(len(MOVE), BCAST)]


def test_bad_crc32_rescans_and_finds_a_frame_hidden_inside():
    # A frame whose DATA carries a whole valid frame, then a broken CRC-32:
    # the receiver must rescan after the outer start byte and find the inner one.
    outer = bytearray(build_frame(cmd_set=0x05, cmd_id=0x01, value=BCAST))
    outer[-1] ^= 0xFF
    evs = events(bytes(outer))
    assert errors(evs)[0] == (0, "bad_crc32")
    assert frames(evs) == [(14, BCAST)]


def test_reserved_and_version_fields_are_header_errors():
    assert errors(events(with_header(MOVE, b3=MOVE[3] | 0x40)))[0] == (0, "reserved_bits")
    assert errors(events(with_header(MOVE, b6=1)))[0] == (0, "reserved_bits")
    assert errors(events(with_header(MOVE, b2=MOVE[2] | 0x04)))[0] == (0, "bad_version")


def test_impossible_lengths():
    for length in (0, 11, 13, 14, 15, 16):
        word = length.to_bytes(2, "little")
        evs = events(with_header(MOVE[:12], b1=word[0], b2=word[1]) + MOVE[12:])
        assert errors(evs)[0] == (0, "impossible_length"), length


def test_header_only_frame():
    raw = build_frame(session=2, seq=3)
    assert len(raw) == 12
    assert frames(events(raw)) == [(0, raw)]


def test_truncation_at_every_byte_is_reported_never_a_frame():
    for cut in range(1, len(MOVE)):
        evs = events(MOVE[:cut])
        assert frames(evs) == []
        assert (0, "truncated_frame") in errors(evs), cut


@given(st.integers(min_value=1, max_value=40))
def test_split_reads_give_the_same_events(chunk):
    data = b"\x01\xaa\x02" + MOVE + b"\xaa" + BCAST + MOVE[:20]
    assert events(data, chunk) == events(data)


_no_sof = st.binary(max_size=64).map(lambda b: b.replace(b"\xaa", b"\xab"))


@given(st.lists(st.tuples(_no_sof, st.sampled_from([MOVE, BCAST])), max_size=6), _no_sof,
       st.integers(min_value=1, max_value=64))
def test_every_intact_frame_is_found_whatever_surrounds_it(parts, tail, chunk):
    data, expect = b"", []
    for garbage, frame in parts:
        data += garbage
        expect.append((len(data), frame))
        data += frame
    data += tail
    assert frames(events(data, chunk)) == expect


@given(st.binary(max_size=300), st.integers(min_value=1, max_value=64))
def test_random_bytes_are_fully_accounted_for(data, chunk):
    """Every input byte is inside a frame, a garbage run, or starts a rejection."""
    evs = events(data, chunk)
    covered = set()
    for e in evs:
        if isinstance(e, Frame):
            covered.update(range(e.offset, e.offset + len(e.raw)))
        elif isinstance(e, Garbage):
            covered.update(range(e.offset, e.offset + e.length))
        else:
            covered.add(e.offset)
    assert covered == set(range(len(data)))


def test_header_fields_of_any_header():
    h = header_fields(MOVE[:12])
    assert h == {"len": 35, "ver": 0, "session": 0, "is_ack": False, "res0": 0, "padding": 0, "enc": 0,
                 "res1": 0, "seq": 0x1234, "crc16": 0x72E1}
