"""The fast path of the reference decoder (reference/fastframe.py, used by
Decoder._frame for command frames whose layout it knows) against the
interpreter and the generic model walk: for every profile, broadcasts with
every single item, none, all and random subsets of them, random item bytes
(NaN and infinite floats, unnamed enum values), other sessions and the ACKs
that answer them, and payloads cut short, extended, or with reserved flag
bits set, each frame seen often enough to be compiled, the same events as
model.dumps text, errors included."""
from __future__ import annotations

import random

import pytest

from osdk_conformance.core import model
from osdk_conformance.core.deframe import Frame
from osdk_conformance.reference import decode, fastframe, values
from osdk_conformance._construct import broadcast_for_profile, build_frame, parse_frame
from osdk_conformance._construct.broadcast import FLAG_BITS, ITEMS, NAMES

PROFILES = sorted(NAMES)
REPEAT = decode._FastFrames.COMPILE_AFTER + 2  # the last uses of a layout take the compiled converter
BROADCAST = (0x02, 0x00)


def generic_decoder(profile: int) -> decode.Decoder:
    d = decode.Decoder(profile)
    d._fast = None
    d._model = model.from_construct_generic
    return d


def payload_of(profile: int, present, rng: random.Random) -> bytes:
    """A broadcast value with the items `present`, every byte after the flag word random."""
    data = values.broadcast_data(profile, present, {})
    raw = broadcast_for_profile(profile).build(data)
    return raw[:2] + bytes(rng.randrange(256) for _ in raw[2:])


def flag_sets(profile: int, rng: random.Random) -> list[tuple[str, ...]]:
    names = [name for name, _ in ITEMS[profile]]
    sets = [(), tuple(names)] + [(name,) for name in names]
    sets += [tuple(n for n in names if rng.random() < 0.5) for _ in range(40)]
    return sets


def compare(profile: int, frames: list[bytes]) -> decode.Decoder:
    """Each frame REPEAT times through a fresh fast decoder and a generic one: the same events."""
    decode._fast_frames_of.cache_clear()  # layouts compiled by this test only
    fast, generic = decode.Decoder(profile), generic_decoder(profile)
    assert fast._fast is not None
    offset = 0
    for raw in frames:
        for _ in range(REPEAT):
            ev = Frame(offset, raw)
            assert model.dumps(fast.event(ev)) == model.dumps(generic.event(ev)), raw.hex()
            offset += len(raw)
    return fast


def fast_layouts(decoder: decode.Decoder) -> int:
    return sum(known is not None for known in decoder._fast.known.values())


@pytest.mark.parametrize("profile", PROFILES)
def test_broadcasts_of_every_flag_word_have_the_generic_model(profile):
    rng = random.Random(profile)
    sets = flag_sets(profile, rng)
    frames = [build_frame(cmd_set=BROADCAST[0], cmd_id=BROADCAST[1], value=payload_of(profile, s, rng), seq=n)
              for n, s in enumerate(sets)]
    fast = compare(profile, frames)
    assert fast_layouts(fast) == len({f[1:8] + f[12:16] for f in frames})


@pytest.mark.parametrize("profile", PROFILES)
def test_floats_enums_and_bits_of_any_value_have_the_generic_model(profile):
    rng = random.Random(1000 + profile)
    names = [name for name, _ in ITEMS[profile]]
    special = [b"\x00\x00\xc0\x7f", b"\x01\x00\x80\x7f", b"\x00\x00\x80\xff", b"\x00\x00\x80\x7f", b"\x00\x00\x00\x80"]
    frames = []
    for n in range(30):
        value = bytearray(payload_of(profile, names, rng))
        for pos in range(2, len(value) - 3, 4):  # NaNs (quiet, signalling), infinities, -0.0 at float-aligned places
            if rng.random() < 0.3:
                value[pos:pos + 4] = rng.choice(special)
        frames.append(build_frame(cmd_set=BROADCAST[0], cmd_id=BROADCAST[1], value=bytes(value), seq=n))
    fast = compare(profile, frames)
    assert fast_layouts(fast) == 1  # one flag word, one layout, every value through it


@pytest.mark.parametrize("profile", PROFILES)
def test_payloads_the_layout_rejects_are_the_interpreters(profile):
    rng = random.Random(2000 + profile)
    frames = []
    for s in flag_sets(profile, rng)[:12]:
        value = payload_of(profile, s, rng)
        flags = int.from_bytes(value[:2], "little")
        reserved = [bit for bit in range(len(ITEMS[profile]), FLAG_BITS)]
        cut_items = (value[:2],) if len(value) > 2 else ()
        for bad in (value[:-1], value + b"\x00", value + bytes(7), *cut_items,
                    *((flags | 1 << bit).to_bytes(2, "little") + value[2:] for bit in reserved)):
            frames.append(build_frame(cmd_set=BROADCAST[0], cmd_id=BROADCAST[1], value=bad))
    frames.append(build_frame(cmd_set=BROADCAST[0], cmd_id=BROADCAST[1], value=value[:1]))
    fast = compare(profile, frames)
    for raw in frames:
        with pytest.raises(Exception):
            parse_frame(raw, profile)
    assert fast_layouts(fast) == 0


@pytest.mark.parametrize("profile", PROFILES)
def test_sessions_acks_and_other_frames_decode_as_before(profile):
    rng = random.Random(3000 + profile)
    names = [name for name, _ in ITEMS[profile]]
    value = payload_of(profile, names, rng)
    frames = []
    for session in (0, 1, 5, 31):
        for seq in (0, 7, 0xFFFF):
            frames.append(build_frame(cmd_set=BROADCAST[0], cmd_id=BROADCAST[1], value=value, session=session, seq=seq))
            if session:
                frames.append(build_frame(value=b"\x00\x00", is_ack=True, session=session, seq=seq))
    frames += [
        build_frame(),  # header only
        build_frame(cmd_set=0x01, cmd_id=0x03, value=bytes(17)),
        build_frame(cmd_set=0x02, cmd_id=0x01, value=b"\x07"),
        build_frame(cmd_set=0x00, cmd_id=0x00, value=b"\x01"),
        build_frame(value=bytes(32), enc=1, padding=3),
    ]
    # the same frame with each header byte changed, the CRCs left as they were
    for pos in range(1, 16):
        bad = bytearray(frames[0])
        bad[pos] ^= 1 << rng.randrange(8)
        frames.append(bytes(bad))
    fast = compare(profile, frames)
    assert fast_layouts(fast) >= 4  # the broadcast in each session


def test_the_key_is_the_bytes_a_broadcast_layout_consults():
    for profile in PROFILES:
        found = decode._fast_frames(profile)
        assert found is not None
        # start byte, header bit fields, command set and id, flag word: found, not listed
        assert sorted(found.positions) == [0, 1, 2, 3, 4, 5, 6, 7, 12, 13, 14, 15]


def test_a_frame_cut_short_is_not_fast_but_its_layout_may_be():
    profile = PROFILES[-1]
    frame = build_frame(cmd_set=BROADCAST[0], cmd_id=BROADCAST[1], value=payload_of(profile, (), random.Random(4)))
    con = decode.osdk_frame(profile)
    with pytest.raises(fastframe.Short):
        fastframe.specialize(con, frame[:-1])
    found = fastframe.specialize(con, frame, range(16))
    assert found.convert(frame[:-1]) is None
    assert model.dumps(found.convert(frame)) == model.dumps(model.from_construct(parse_frame(frame, profile)))


def test_layouts_are_bounded_and_the_rest_interpreted(monkeypatch):
    profile = PROFILES[-1]
    rng = random.Random(5)
    names = [name for name, _ in ITEMS[profile]]
    frames = [build_frame(cmd_set=BROADCAST[0], cmd_id=BROADCAST[1], value=payload_of(profile, names[:n], rng))
              for n in range(len(names) + 1)]
    monkeypatch.setattr(decode._FastFrames, "MAX_COMPILED", 3)
    fast = compare(profile, frames)
    assert fast_layouts(fast) == 3
    monkeypatch.setattr(decode._FastFrames, "MAX_LAYOUTS", 4)
    fast = compare(profile, frames)
    assert len(fast._fast.known) <= 4
    assert fast_layouts(fast) >= 1
