"""The Construct spec (osdk_construct) on its own: the worked frames, round
trips, and the `valid` rules of the .ksy files enforced in both directions.

The agreement with the Kaitai spec is tested in test_kaitai_vs_construct.py.
"""
from __future__ import annotations

import dataclasses
import random
import struct

import construct
import pytest
from hypothesis import given
from hypothesis import strategies as st

from osdk_conformance import _construct as oc
from osdk_conformance.core import ksy
from osdk_conformance.core.rules import default_rules
from osdk_conformance._construct import broadcast, broadcast_items, enums, payload
from osdk_conformance._construct.floats import F32, F64, F32le, F64le
from osdk_conformance._construct.frame import header

MOVEMENT_FRAME = bytes.fromhex("aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba")
BROADCAST_FRAME = bytes.fromhex("aa1600000000000007001ede02000018035769c676b2")
MOVEMENT_VALUE = MOVEMENT_FRAME[14:-4]
PROFILES = ("m100-fw2.3", "m100-fw3.1", "a3-fw3.1")

Rejected = construct.ConstructError


def _items(profile: int) -> list[str]:
    return [name for name, _ in broadcast.ITEMS[profile]]


def _all_flags_off(profile: int) -> dict:
    return {f"has_{name}": False for name in _items(profile)}


# --- worked frames (PROTOCOL-FACTS §1) -----------------------------------------------------

def test_movement_control_frame_builds():
    value = oc.encode_movement_control(0x4B, 1.0, -2.0, 0.5, 30.0)
    assert value == MOVEMENT_VALUE
    assert oc.build_frame(cmd_set=0x01, cmd_id=0x03, value=value, session=0, seq=0x1234) == MOVEMENT_FRAME


def test_movement_control_frame_parses():
    f = oc.parse_frame(MOVEMENT_FRAME, "a3-fw3.1")
    assert (f.len, f.ver, f.session, f.is_ack, f.res0, f.padding, f.enc, f.res1, f.seq) == (
        35, 0, 0, False, 0, 0, "plain", 0, 0x1234)
    assert f.crc16 == 0x72E1 and f.crc32 == 0xBA01DBFC
    assert f.data.cmd_set == "control" and f.data.cmd_id == 3
    body = f.data.value.body
    assert dict((k, str(v)) for k, v in body.control_mode.items() if not k.startswith("_")) == {
        "stable_mode": "stable", "horizontal_frame": "body", "yaw_logic": "yaw_rate",
        "vertical_logic": "vert_vel", "horizontal_logic": "hori_vel",
    }
    assert (body.x, body.y, body.z, body.yaw) == tuple(F32.from_float(v) for v in (1.0, -2.0, 0.5, 30.0))
    assert oc.osdk_frame("a3-fw3.1").build(f) == MOVEMENT_FRAME


def test_broadcast_frame_builds():
    value = oc.osdk_broadcast_a3_fw3_1.build({**_all_flags_off(2), "has_flight_status": True, "has_battery": True,
                               "flight_status": 3, "battery": 87})
    assert value == b"\x00\x18\x03\x57"
    assert oc.build_frame(cmd_set="push", cmd_id=0x00, value=value, seq=7) == BROADCAST_FRAME


def test_broadcast_frame_parses():
    f = oc.parse_frame(BROADCAST_FRAME, "a3-fw3.1")
    data = f.data.value.body.data
    present = [name for name in _items(2) if data[f"has_{name}"]]
    assert present == ["flight_status", "battery"]
    assert (data.flight_status, data.battery, data.reserved_flags) == (3, 87, 0)
    assert oc.osdk_frame(2).build(f) == BROADCAST_FRAME


@pytest.mark.parametrize("profile", ["m100-fw2.3", "m100-fw3.1"])
def test_broadcast_frame_is_invalid_in_the_m100_profiles(profile):
    # Flag bit 12 carries no item in the M100 profiles: reserved_flags != 0.
    with pytest.raises(Rejected):
        oc.parse_frame(BROADCAST_FRAME, profile)


@pytest.mark.parametrize("form", [2, "a3_fw3_1", "a3-fw3.1"])
def test_profile_can_be_given_three_ways(form):
    assert oc.osdk_frame(form) is oc.osdk_frame(2)


# --- round trips -------------------------------------------------------------------------------

def _full_broadcast(profile: int, seed: int) -> bytes:
    """All items present, random item bytes (any item content is valid)."""
    size = sum(len(sub.build(sub.parse(bytes(64)))) for _, sub in broadcast.ITEMS[profile])
    rnd = random.Random(seed)
    return struct.pack("<H", (1 << len(_items(profile))) - 1) + bytes(rnd.getrandbits(8) for _ in range(size))


@pytest.mark.parametrize("seed", range(20))
@pytest.mark.parametrize("profile", [0, 1, 2])
def test_full_broadcast_round_trip(profile, seed):
    raw = _full_broadcast(profile, seed)
    con = oc.broadcast_for_profile(profile)
    assert con.build(con.parse(raw)) == raw


def test_full_broadcast_sizes_match_the_profiles():
    # PROTOCOL-FACTS §3 item sizes, summed per profile.
    assert [len(_full_broadcast(p, 0)) - 2 for p in (0, 1, 2)] == [
        4 + 16 + 12 + 13 + 12 + 25 + 6 + 12 + 12 + 1 + 1 + 1,
        9 + 16 + 12 + 13 + 12 + 25 + 6 + 12 + 13 + 1 + 1 + 2,
        9 + 16 + 12 + 13 + 12 + 25 + 32 + 44 + 6 + 12 + 13 + 1 + 1 + 2,
    ]


def _size(con) -> int:
    return len(con.build(con.parse(bytes(64))))


@pytest.mark.parametrize("name", PROFILES)
def test_item_sizes_agree_with_the_rules(name):
    """This package's own item layouts give the sizes the rules compute from
    osdk_broadcast_items.ksy (the two transcriptions of the items agree)."""
    p = default_rules().profile(name)
    assert {item: _size(con) for item, con in broadcast.ITEMS[p.value]} == dict(p.item_sizes)


# --- the profiles are composed as spec/rules.yaml says ---------------------------------------

def test_profiles_come_from_the_rules():
    r = default_rules()
    assert list(broadcast.ITEMS) == [r.profile(n).value for n in r.profile_names] == [0, 1, 2]
    assert enums.PROFILE_IDS == {n: r.profile(n).value for n in r.profile_names}
    assert enums.PROFILE == {r.profile(n).ksy_name: r.profile(n).value for n in r.profile_names}
    for name in r.profile_names:
        p = r.profile(name)
        assert [item for item, _ in broadcast.ITEMS[p.value]] == list(p.flag_bits)
        assert broadcast.NAMES[p.value] == p.ksy_name
        assert getattr(oc, f"osdk_broadcast_{p.ksy_name}") is broadcast.for_profile(name)
        assert getattr(broadcast, p.ksy_name) is broadcast.for_profile(p.value)


def test_item_constructs_are_found_by_type_name_and_take_params_by_name():
    fw31 = default_rules().profile("m100-fw3.1")
    short_gimbal = dataclasses.replace(fw31, item_params={**fw31.item_params, "gimbal": {"has_limit_byte": False}})
    layout = dict(broadcast.bit_order(short_gimbal))
    assert layout["gimbal"] is broadcast_items.gimbal(has_limit_byte=False)
    assert _size(layout["gimbal"]) == 12 and _size(layout["time_stamp"]) == 9
    assert layout["acceleration"] is layout["angular_rate"] is broadcast_items.vector3f
    assert layout["battery"] is construct.Int8ul


def test_a_profile_with_sixteen_items_has_no_reserved_flags():
    con = broadcast._profile(tuple((f"item{n}", construct.Int8ul) for n in range(16)))
    parsed = con.parse(b"\xff\xff" + bytes(range(16)))
    assert [parsed[f"item{n}"] for n in range(16)] == list(range(16))
    assert "reserved_flags" not in parsed


@given(raw=st.binary(min_size=1, max_size=40))
def test_control_mode_and_movement_control_round_trip(raw):
    assert oc.osdk_control_mode.build(oc.osdk_control_mode.parse(raw)) == raw[:1]
    if len(raw) >= 17:
        assert oc.osdk_movement_control.build(oc.osdk_movement_control.parse(raw)) == raw[:17]


@given(profile=st.sampled_from(PROFILES), raw=st.binary(max_size=80).map(lambda b: b"\xaa" + b))
def test_frame_round_trip(profile, raw):
    try:
        parsed = oc.parse_frame(raw, profile)
    except Rejected:
        return
    assert raw.startswith(oc.osdk_frame(profile).build(parsed))


@pytest.mark.parametrize("frame", [
    oc.build_frame(seq=1),
    oc.build_frame(is_ack=True, session=3, seq=9, value=b"\x02\x00"),
    oc.build_frame(enc=1, padding=16, value=bytes(range(32)), session=31, seq=0xFFFF),
    oc.build_frame(cmd_set=0x07, cmd_id=0x42, value=b"opaque"),
    oc.build_frame(cmd_set=0x00, cmd_id=0x10, value=bytes(range(8)) * 2),
    MOVEMENT_FRAME, BROADCAST_FRAME,
], ids=["header_only", "ack", "encrypted", "unknown_command", "frequency_request", "movement", "broadcast"])
@pytest.mark.parametrize("profile", PROFILES)
def test_frame_examples_round_trip(frame, profile):
    try:
        parsed = oc.parse_frame(frame, profile)
    except Rejected:
        assert frame is BROADCAST_FRAME and profile != "a3-fw3.1"
        return
    assert oc.osdk_frame(profile).build(parsed) == frame


def test_ack_frame_keeps_the_value_raw():
    f = oc.parse_frame(oc.build_frame(is_ack=True, session=1, value=b"\x02\x00", seq=5), 0)
    assert f.data.ack_value == b"\x02\x00" and f.data.cmd_set is None and f.data.value is None


def test_encrypted_frame_keeps_the_data_raw():
    f = oc.parse_frame(oc.build_frame(enc=1, padding=4, value=b"\x01\x03ciphertext\x00\x00\x00\x00"), 0)
    assert f.enc == "aes256" and f.padding == 4 and f.data == b"\x01\x03ciphertext\x00\x00\x00\x00"


def test_header_only_frame_has_neither_data_nor_crc32():
    raw = oc.build_frame(session=2, seq=0x0102)
    assert len(raw) == 12
    f = oc.parse_frame(raw, 1)
    assert f.len == 12 and f.data is None and f.crc32 is None


def test_unknown_command_value_is_raw():
    f = oc.parse_frame(oc.build_frame(cmd_set=0x05, cmd_id=0x01, value=b"xyz"), 0)
    assert int(f.data.cmd_set) == 5 and f.data.cmd_set.__class__ is construct.EnumInteger
    assert f.data.value.body.raw == b"xyz"


# --- floats ------------------------------------------------------------------------------------

@pytest.mark.parametrize("cls, fmt, field, bits", [
    (F32, "<I", F32le, 0x7F800001),          # signalling NaN
    (F32, "<I", F32le, 0xFFA00005),          # negative signalling NaN with payload
    (F32, "<I", F32le, 0x80000000),          # -0.0
    (F32, "<I", F32le, 0x00000001),          # smallest denormal
    (F64, "<Q", F64le, 0x7FF0000000000001),  # signalling NaN
    (F64, "<Q", F64le, 0xFFF4000000000123),
    (F64, "<Q", F64le, 0x8000000000000000),
])
def test_floats_are_bit_exact(cls, fmt, field, bits):
    raw = struct.pack(fmt, bits)
    value = field.parse(raw)
    assert isinstance(value, cls) and value.ieee_bits == bits and value.ieee_width == cls.ieee_width
    assert field.build(value) == raw


def test_float_values():
    assert F32.from_float(1.0) == F32(0x3F800000) and float(F32(0x3F800000)) == 1.0
    assert F64.from_float(-2.5) == F64(0xC004000000000000)
    assert F32.from_float(0.0) != F32.from_float(-0.0)
    assert F32(0x7FC00001) == F32(0x7FC00001) != F32(0x7FC00002)
    assert F32(0x3F800000) != F64.from_float(1.0)
    assert F32(0x7F800001).is_signalling_nan and not F32(0x7FC00001).is_signalling_nan
    assert F32(0x7F800000).is_nan is False
    assert len({F32(1), F32(1), F32(2)}) == 2


def test_float_fields_build_from_numbers_and_refuse_wrong_widths():
    assert F32le.build(30.0) == struct.pack("<f", 30.0)
    assert F64le.build(3) == struct.pack("<d", 3.0)
    with pytest.raises(ValueError):
        F32le.build(F64.from_float(1.0))
    with pytest.raises(TypeError):
        F32le.build("1.0")
    with pytest.raises(ValueError):
        F32(1 << 32)


# --- valid rules: reserved flag bits ---------------------------------------------------------------

@pytest.mark.parametrize("profile, reserved_bits", [(0, range(12, 16)), (1, range(12, 16)), (2, range(14, 16))])
def test_reserved_flag_bits_rejected_on_parse(profile, reserved_bits):
    con = oc.broadcast_for_profile(profile)
    for bit in reserved_bits:
        with pytest.raises(Rejected):
            con.parse(struct.pack("<H", 1 << bit) + bytes(64))


@pytest.mark.parametrize("profile", [0, 1, 2])
def test_reserved_flag_bits_rejected_on_build(profile):
    con = oc.broadcast_for_profile(profile)
    assert con.build({**_all_flags_off(profile), "reserved_flags": 0}) == b"\x00\x00"
    with pytest.raises(Rejected):
        con.build({**_all_flags_off(profile), "reserved_flags": 1})


# --- valid rules: frame header ------------------------------------------------------------------------

def _header(**fields) -> dict:
    base = {"len": 12, "session": 0, "is_ack": False, "padding": 0, "enc": 0, "seq": 0, "crc16": 0}
    return {**base, **fields}


def _with_len(frame: bytes, length: int) -> bytes:
    word = int.from_bytes(frame[1:3], "little")
    return frame[:1] + ((word & ~0x3FF) | length).to_bytes(2, "little") + frame[3:]


@pytest.mark.parametrize("length", [0, 1, 11, 13, 14, 15, 16])
def test_impossible_len_rejected_on_parse(length):
    raw = _with_len(MOVEMENT_FRAME, length) + bytes(40)
    with pytest.raises(Rejected):
        oc.parse_frame(raw, 0)


@pytest.mark.parametrize("length", [0, 11, 13, 14, 15, 16])
def test_impossible_len_rejected_on_build(length):
    with pytest.raises(Rejected):
        header.build(_header(len=length))
    with pytest.raises(Rejected):
        oc.osdk_frame(0).build({**_header(len=length), "data": b"" if length >= 16 else None, "crc32": 0})


@pytest.mark.parametrize("length", [12, 17, 1023])
def test_possible_len_accepted(length):
    assert len(header.build(_header(len=length))) == 12


@pytest.mark.parametrize("offset, mask, name", [
    (2, 0xFC, "ver"), (3, 0xC0, "res0"), (5, 0xFF, "res1 byte 5"), (6, 0xFF, "res1 byte 6"), (7, 0xFF, "res1 byte 7"),
])
def test_reserved_header_bits_rejected_on_parse(offset, mask, name):
    for bit in range(8):
        if mask >> bit & 1:
            raw = bytearray(MOVEMENT_FRAME)
            raw[offset] |= 1 << bit
            with pytest.raises(Rejected):
                oc.parse_frame(bytes(raw), 0)


@pytest.mark.parametrize("field, value", [("ver", 1), ("ver", 63), ("res0", 2), ("res1", 1), ("res1", 0x800000)])
def test_reserved_header_fields_rejected_on_build(field, value):
    assert header.build(_header(**{field: 0})) == header.build(_header())
    with pytest.raises(Rejected):
        header.build(_header(**{field: value}))


def test_wrong_start_byte_rejected():
    with pytest.raises(Rejected):
        oc.parse_frame(b"\xab" + MOVEMENT_FRAME[1:], 0)
    with pytest.raises(Rejected):
        header.build({**_header(), "sof": b"\xab"})


def test_aes_data_must_be_whole_blocks():
    for data_len, ok in ((16, True), (32, True), (17, False), (15, False), (2, False)):
        raw = bytearray(oc.build_frame(cmd_set=0x05, cmd_id=0x01, value=bytes(data_len - 2)))
        raw[4] = 1 | 1 << 5
        if ok:
            oc.parse_frame(bytes(raw), 0)
        else:
            with pytest.raises(Rejected):
                oc.parse_frame(bytes(raw), 0)


def test_ack_in_session_zero_rejected():
    raw = bytearray(oc.build_frame(is_ack=True, session=1, value=b"\x00\x00"))
    raw[3] &= ~0x1F
    with pytest.raises(Rejected):
        oc.parse_frame(bytes(raw), 0)
    with pytest.raises(Rejected):
        oc.build_frame(is_ack=True, session=0, value=b"\x00\x00")


@pytest.mark.parametrize("enc, padding, ok", [
    (0, 0, True), (0, 1, False), (0, 16, False), (1, 0, False), (1, 1, True), (1, 16, True), (1, 17, False),
    (1, 31, False), (2, 0, False), (2, 1, False), (7, 5, False),
])
def test_encryption_and_padding_rule(enc, padding, ok):
    word = padding | enc << 5
    # 16 bytes of DATA, so that the AES block rule (ERRATA E23) holds.
    raw = bytearray(oc.build_frame(cmd_set=0x05, cmd_id=0x01, value=bytes(14)))
    raw[4] = word
    if ok:
        oc.parse_frame(bytes(raw), 0)
        header.build(_header(len=32, enc=enc, padding=padding))
        oc.build_frame(enc=enc, padding=padding, value=b"x" * 16)
    else:
        with pytest.raises(Rejected):
            oc.parse_frame(bytes(raw), 0)
        with pytest.raises(Rejected):
            header.build(_header(len=32, enc=enc, padding=padding))
        with pytest.raises((Rejected, ValueError)):
            oc.build_frame(enc=enc, padding=padding, value=b"x" * 16)


# --- valid rules: trailing and missing bytes --------------------------------------------------------------

def test_trailing_bytes_after_a_broadcast_rejected():
    value = BROADCAST_FRAME[14:-4]
    oc.osdk_broadcast_a3_fw3_1.parse(value)
    with pytest.raises(Rejected):
        oc.osdk_broadcast_a3_fw3_1.parse(value + b"\x00")


def test_missing_item_bytes_rejected():
    value = BROADCAST_FRAME[14:-4]
    with pytest.raises(Rejected):
        oc.osdk_broadcast_a3_fw3_1.parse(value[:-1])


@pytest.mark.parametrize("cmd_set, cmd_id, is_ack, value", [
    (0x00, 0x00, False, b"\x01\x02"),
    (0x01, 0x03, False, MOVEMENT_VALUE + b"\x00"),
    (0x01, 0x00, True, b"\x02\x00\x00"),
    (0x02, 0x00, False, BROADCAST_FRAME[14:-4] + b"\xff"),
])
def test_trailing_bytes_after_a_value_rejected(cmd_set, cmd_id, is_ack, value):
    con = oc.osdk_payload(cmd_set, cmd_id, is_ack, "a3-fw3.1")
    with pytest.raises(Rejected):
        con.parse(value)
    # without the extra byte it parses
    con.parse(value[:-1])


def test_trailing_bytes_inside_a_frame_rejected_on_parse():
    # LEN one byte longer than the movement control value needs.
    raw = oc.build_frame(cmd_set=1, cmd_id=3, value=MOVEMENT_VALUE + b"\x00")
    with pytest.raises(Rejected):
        oc.parse_frame(raw, 0)


def test_data_not_matching_len_rejected_on_build():
    parsed = oc.parse_frame(MOVEMENT_FRAME, 0)
    for length in (parsed.len - 1, parsed.len + 1):
        with pytest.raises(Rejected):
            oc.osdk_frame(0).build({**parsed, "len": length})


def test_trailing_bytes_cannot_be_built():
    # No field holds trailing bytes: a built value ends where its last field does.
    body = oc.osdk_movement_control.parse(MOVEMENT_VALUE)
    assert oc.osdk_payload(1, 3, False, 0).build({"body": body}) == MOVEMENT_VALUE


# --- build_frame arguments ------------------------------------------------------------------------------------

@pytest.mark.parametrize("kwargs", [
    {"cmd_set": 1},
    {"cmd_id": 3},
    {"cmd_set": 1, "cmd_id": 3, "is_ack": True},
    {"value": bytes(1008)},
    {"session": 32},
    {"seq": 0x10000},
    {"padding": 1},
    {"enc": 1},
    {"enc": 1, "padding": 17, "value": b"x"},
])
def test_build_frame_refuses_what_the_spec_forbids(kwargs):
    with pytest.raises((Rejected, ValueError)):
        oc.build_frame(**kwargs)


def test_build_frame_longest_frame():
    raw = oc.build_frame(value=bytes(1007), is_ack=True, session=1)
    assert len(raw) == 1023 and oc.parse_frame(raw, 0).len == 1023


def test_encode_movement_control_refuses_bad_mode_bytes():
    for bad in (-1, 256, 1.0):
        with pytest.raises(ValueError):
            oc.encode_movement_control(bad, 0, 0, 0, 0)


# --- the transcription matches the .ksy enums -----------------------------------------------------------------

def test_enums_match_the_ksy_files():
    index = ksy.load()
    assert set(enums.BY_KSY) == set(index.enums), "every ksy enum, and only those, is transcribed"
    for key, mapping in enums.BY_KSY.items():
        assert {v: k for k, v in mapping.items()} == index.enums[key], key


def test_payload_dispatch_matches_the_ksy_switch():
    body = next(f for f in ksy.load().files["osdk_payload"]["seq"] if f["id"] == "body")
    cases = {k for k in body["type"]["cases"] if isinstance(k, int)}
    assert set(payload.BODY_BY_KEY) == cases
