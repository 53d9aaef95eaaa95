"""Property: the receiver never loses a valid frame that is intact in the
stream, whatever garbage surrounds it and however the bytes are split into
reads; checked on the Python deframer directly and on every bundled
implementation through its decode_stream operation.

When the property holds, and why it needs a precondition. The receiver
(the SDK's rule, osdk_conformance/core/deframe.py) only ever looks for a frame at
the position where its scan stands, and the scan moves forward in three
ways: past bytes that are not a start byte (it stops at the next 0xAA), by
ONE byte after any rejection (bad header, bad CRC-32, or a frame cut short
at the end of the input), and by LEN bytes after accepting a frame. The
first two cannot step over the valid frame's start byte at offset p; only
accepting a frame that starts before p and ends after p can. So:

    If no offset q < p starts bytes the receiver would accept as a frame
    (header checks and CRC-16 pass, all LEN bytes present, CRC-32 passes
    when LEN > 12) that end after p, then the frame at p comes out as a
    frame event at p with its exact bytes, for every split into reads.

The end of the input changes nothing: finish() reports a frame cut short
and rescans one byte later, like any rejection, so it still reaches p.

The precondition cannot be dropped: garbage can itself be a complete frame
that passes both CRCs and overlaps the valid one, and then the receiver
takes it and never looks at p (test_a_frame_that_covers_the_start_hides_it).
Garbage made of arbitrary bytes, 0xAA-rich bytes, truncated frames, headers
whose CRC-16 passes and whose LEN runs into or past the valid frame,
headers whose CRC-16 passes and whose other fields are anything, frames
with a broken CRC-32, and whole valid frames glued on meets it except by
coincidence; `covering_frame` states it and the tests `assume` it, so the
property checked is exactly the one above. (Hypothesis does find such
coincidences: the first 11 bytes of a header-only frame whose CRC-16 has
the high byte 0xAA, followed by the valid frame, make a whole header-only
frame that takes the valid frame's start byte.)

For decode_stream the frame event also needs its frame to decode, and an
ACK's event depends on the commands before it (ACK matching by session and
SEQ). The valid frame is drawn from frames that decode on their own (SEQ
0..0x7FFF); every frame in the garbage has SEQ 0x8000..0xFFFF, so it is
never a command the valid frame answers.
"""
from __future__ import annotations

import random
from functools import cache

import pytest
from hypothesis import HealthCheck, assume, given, note, settings, strategies as st

from osdk_conformance.core.crc import crc16, crc32
from osdk_conformance.core.deframe import (HEADER_LEN, MAX_LEN, SOF, Frame, deframe, frame_length, header_problem,
                                      split_chunks)
from osdk_conformance.reference.codec import PROFILES, answer
from osdk_conformance.core.rules import profile as rules_profile
from osdk_conformance.harness.vectors import VECTORS_DIR, difference, load_cases
from osdk_conformance._construct import build_frame
from osdk_conformance._construct.frame import CRC32_LEN

SEQ_OF_FRAME = (0, 0x7FFF)
SEQ_OF_GARBAGE = (0x8000, 0xFFFF)
MAX_VALUE = MAX_LEN - HEADER_LEN - CRC32_LEN - 2  # value bytes of a maximum-length command frame


def covering_frame(data: bytes, p: int) -> int | None:
    """The first offset q < p at which the receiver could accept a frame
    that ends after p (the precondition's counterexample), or None."""
    for q in range(p):
        if data[q] != SOF or q + HEADER_LEN > len(data):
            continue
        header = data[q:q + HEADER_LEN]
        if header_problem(header):
            continue
        end = q + frame_length(header)
        if end > p and end <= len(data) and (end == q + HEADER_LEN or crc32(data[q:end]) == 0):
            return q
    return None


# ---------------------------------------------------------------- frames


@cache
def payload_cases() -> dict[str, list[tuple[int, int, bool, bytes]]]:
    """Valid command and ACK values of the golden vectors, by profile."""
    out: dict[str, list] = {p: [] for p in PROFILES}
    for c in load_cases([VECTORS_DIR / "payloads.json"]):
        if c.operation == "decode_payload" and c.result == "valid":
            i = c.input
            out[c.profile].append((i["cmd_set"], i["cmd_id"], i["is_ack"], bytes.fromhex(i["hex"])))
    return out


@st.composite
def frames(draw, profile: str, seqs: tuple[int, int]) -> bytes:
    """A plain (not encrypted) frame that decodes for `profile`: a command
    or ACK value from the vectors, a broadcast with random item bytes, a
    command the spec has no layout for (any length up to the maximum), or
    a header-only frame."""
    seq = draw(st.integers(*seqs))
    session = draw(st.integers(0, 31))
    shape = draw(st.sampled_from(("vector", "broadcast", "raw", "header_only")))
    if shape == "vector":
        cmd_set, cmd_id, is_ack, value = draw(st.sampled_from(payload_cases()[profile]))
        if is_ack:  # an ACK in session 0 is a bad_session error
            return build_frame(value=value, is_ack=True, session=max(session, 1), seq=seq)
        return build_frame(cmd_set=cmd_set, cmd_id=cmd_id, value=value, session=session, seq=seq)
    if shape == "broadcast":
        layout = rules_profile(profile)
        flags = draw(st.integers(0, layout.all_flags))
        items = draw(st.binary(min_size=layout.payload_size(flags), max_size=layout.payload_size(flags)))
        return build_frame(cmd_set=0x02, cmd_id=0x00, value=flags.to_bytes(2, "little") + items, session=session,
                           seq=seq)
    if shape == "raw":
        # a short value hypothesis can shrink, or one of the maximum length
        value = draw(st.one_of(st.binary(max_size=64),
                               st.integers(0, 2**32 - 1).map(lambda s: random.Random(s).randbytes(MAX_VALUE))))
        return build_frame(cmd_set=0x00, cmd_id=0x7F, value=value, session=session, seq=seq)
    is_ack = draw(st.booleans())
    return build_frame(is_ack=is_ack, session=max(session, int(is_ack)), seq=seq)


def header_claiming(length: int, seq: int) -> bytes:
    """A header that passes every check and claims LEN `length` (17..1023)."""
    value = bytes(length - HEADER_LEN - CRC32_LEN)  # an ACK: DATA is the value alone
    return build_frame(value=value, is_ack=True, session=1, seq=seq)[:HEADER_LEN]


def with_crc16(fields: bytes) -> bytes:
    """A start byte, nine header bytes as given (any VER, LEN, reserved
    bits, session) and their right CRC-16: the checks behind the CRC-16
    decide, and LEN can run anywhere."""
    header = bytes([SOF]) + fields
    return header + crc16(header).to_bytes(2, "little")


def garbage(profile: str):
    """Bytes around the valid frame, in pieces (see the module doc)."""
    glued = frames(profile, SEQ_OF_GARBAGE)
    piece = st.one_of(
        st.binary(min_size=1, max_size=48),
        st.lists(st.one_of(st.just(SOF), st.integers(0, 255)), min_size=1, max_size=48).map(bytes),
        st.tuples(glued, st.integers(1, MAX_LEN)).map(lambda t: t[0][:max(1, min(t[1], len(t[0]) - 1))]),
        st.tuples(st.integers(HEADER_LEN + CRC32_LEN + 1, MAX_LEN), st.integers(*SEQ_OF_GARBAGE))
          .map(lambda t: header_claiming(*t)),
        st.binary(min_size=9, max_size=9).map(with_crc16),
        glued.map(lambda f: f[:-1] + bytes([f[-1] ^ 0xFF]) if len(f) > HEADER_LEN else f),
        glued,
    )
    return st.lists(piece, max_size=5).map(b"".join)


@st.composite
def framed_streams(draw, max_chunk: int):
    """(profile, valid frame, its offset, the whole stream, read sizes)."""
    profile = draw(st.sampled_from(PROFILES))
    valid = draw(frames(profile, SEQ_OF_FRAME))
    before, after = draw(garbage(profile)), draw(garbage(profile))
    chunks = draw(st.lists(st.integers(0, max_chunk), max_size=24))
    return profile, valid, len(before), before + valid + after, chunks


# ---------------------------------------------------------------- the Python deframer


@pytest.mark.slow
@settings(max_examples=min(settings.default.max_examples, 3000))
@given(framed_streams(max_chunk=400))
def test_python_deframer_finds_every_intact_frame(example):
    profile, valid, p, data, chunks = example
    assume(covering_frame(data, p) is None)
    note(f"stream {data.hex()}, frame at {p}, reads {chunks}")
    events = list(deframe(split_chunks(data, chunks)))
    assert Frame(p, valid) in events


def test_a_frame_that_covers_the_start_hides_it():
    """The precondition is needed: a frame that passes both CRCs and ends
    inside (or after) the valid one is accepted, and the scan jumps past
    the valid frame's start."""
    valid = build_frame(cmd_set=0x01, cmd_id=0x03, value=bytes(17), seq=7)
    # 1. the valid frame is the DATA of a longer valid frame
    outer = build_frame(cmd_set=0x00, cmd_id=0x7F, value=valid, seq=8)
    p = outer.index(valid)
    assert covering_frame(outer, p) == 0
    assert [e for e in deframe([outer]) if isinstance(e, Frame)] == [Frame(0, outer)]
    # 2. only garbage BEFORE it: a header-only frame whose CRC-16 is the
    # valid frame's first two bytes (the SEQ that gives it, found by search)
    def header(seq: int) -> bytes:
        return build_frame(seq=seq)[:10]

    seq = next(s for s in range(1 << 16) if crc16(header(s)) == valid[0] | valid[1] << 8)
    data = header(seq) + valid
    assert covering_frame(data, 10) == 0
    found = [e for e in deframe([data]) if isinstance(e, Frame)]
    assert found == [Frame(0, data[:HEADER_LEN])]


# ---------------------------------------------------------------- every implementation


@pytest.fixture(scope="module")
def implementations():
    """Every bundled implementation, started once for the module."""
    from osdk_conformance.harness.fuzz import start_fuzzees, stop_fuzzees
    from osdk_conformance.harness.runner import BUNDLED_IMPLS, impl_argv

    started = start_fuzzees([(name, impl_argv(name)) for name in BUNDLED_IMPLS])
    yield started
    stop_fuzzees(started)


@pytest.mark.slow
@settings(max_examples=min(settings.default.max_examples, 500),
          suppress_health_check=[HealthCheck.too_slow])
@given(example=framed_streams(max_chunk=64))
def test_every_implementation_finds_every_intact_frame(implementations, example):
    profile, valid, p, data, chunks = example
    assume(covering_frame(data, p) is None)
    expected = answer("decode_frame", profile, {"hex": valid.hex()})
    assert expected["ok"], expected  # the strategy draws frames that decode
    request = {"op": "decode_stream", "id": "stream-property", "profile": profile, "hex": data.hex(),
               "chunks": chunks}
    note(f"request {request}, frame at {p}")
    for impl in implementations:
        response = impl.testee.request(request)
        assert response.get("ok") is True, (impl.label, response)
        at_p = [e for e in response["result"]["events"] if e.get("offset") == p and e.get("kind") == "frame"]
        assert len(at_p) == 1, (impl.label, response["result"]["events"])
        assert difference(expected["result"]["frame"], at_p[0].get("frame"), "frame") is None, impl.label
