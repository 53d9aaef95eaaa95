"""reference.values: item values cut to a profile's variant and rest values,
all from walking the Construct layout, checked against the item sizes
rules.yaml computes from the Kaitai layout (an independent transcription)
and against Construct's own build and parse; plus a made-up item in a
made-up profile, to show that a new item needs nothing in the value code."""
from __future__ import annotations

import struct

import construct
import pytest
from construct import BitsInteger, Bytes, Const, Enum, Flag, Int8ul, Int16sl, Int32ul, Struct, Terminated, this

from osdk_conformance.core.rules import profile, profile_names
from osdk_conformance.reference import values
from osdk_conformance._construct.bitfields import lsb_first, record
from osdk_conformance._construct.broadcast import for_profile
from osdk_conformance._construct.combinators import Call, ExactSize, when
from osdk_conformance._construct.enums import CONTROL_DEVICE
from osdk_conformance._construct.floats import F32, F64, F32le, F64le

PROFILES = profile_names()
MARKER = {"int": 1, "float": 1.5, "flag": True, "enum": 1}   # non-zero in every field of that kind


def decoded(value):
    """A parsed Construct value as the value model writes it: no private keys, absent fields left out."""
    if isinstance(value, dict):
        return {k: decoded(v) for k, v in value.items() if not k.startswith("_") and v is not None}
    return value


def flat(value, prefix: str = "") -> dict:
    """Dotted path -> value of every field ("" for an item that is one number)."""
    if not isinstance(value, dict):
        return {prefix: value}
    out = {}
    for key, sub in value.items():
        out.update(flat(sub, f"{prefix}{key}." if isinstance(sub, dict) else f"{prefix}{key}"))
    return out


def number(v):
    """A parsed field as the number it was built from."""
    if isinstance(v, (F32, F64)):
        return float(v)
    return int(v) if isinstance(v, construct.EnumIntegerString) else v


def fullest(item: str):
    """The item with every field any profile's variant of it has, non-zero where the field can hold it."""
    out: dict = {}
    for name in PROFILES:
        if item not in values.items(name):
            continue
        for path, leaf in values.fields(name, item).items():
            marker = MARKER.get(leaf.kind, leaf.rest)
            if not path:
                return marker
            *records, last = path.split(".")
            node = out
            for r in records:
                node = node.setdefault(r, {})
            node[last] = marker
    return out


def test_every_profile_lists_the_items_of_its_flag_bits():
    for name in PROFILES:
        assert values.items(name) == profile(name).flag_bits


@pytest.mark.parametrize("name", PROFILES)
def test_rest_values_build_to_the_item_size_and_decode_back(name):
    prof = profile(name)
    for item, con in values.layout(name):
        rest = values.rest(name, item)
        raw = con.build(rest)
        assert len(raw) == prof.item_sizes[item], item
        if all(leaf.kind != "const" for leaf in values.fields(name, item).values()):
            assert raw == bytes(len(raw)), item
        assert decoded(con.parse(raw)) == rest, item


@pytest.mark.parametrize("name", PROFILES)
def test_fit_cuts_the_fullest_value_to_the_profiles_variant(name):
    prof = profile(name)
    for item, con in values.layout(name):
        full = flat(fullest(item))
        fitted = values.fit(name, item, fullest(item))
        assert set(flat(fitted)) == set(values.fields(name, item)) <= set(full), item
        raw = con.build(fitted)
        assert len(raw) == prof.item_sizes[item], item
        back = flat(decoded(con.parse(raw)))
        assert {p: number(v) for p, v in back.items()} == {p: full[p] for p in back}, item


def test_the_variants_differ_where_the_profiles_do():
    """The FW 2.3 forms lack what FW 3.1 adds (PROTOCOL-FACTS §3), in whichever profiles have each form."""
    full = {it: fullest(it) for it in ("time_stamp", "gimbal", "control_info")}
    short = {name for name in PROFILES if profile(name).item_sizes["time_stamp"] == 4}
    assert short and short != set(PROFILES)
    for name in PROFILES:
        ts = values.fit(name, "time_stamp", full["time_stamp"])
        gimbal = values.fit(name, "gimbal", full["gimbal"])
        info = values.fit(name, "control_info", full["control_info"])
        if name in short:
            assert list(ts) == ["time"] and "limit" not in gimbal and "cur_mov_control_mode" not in info
            assert (profile(name).item_sizes["gimbal"], profile(name).item_sizes["control_info"]) == (12, 1)
        else:
            assert list(ts) == ["time", "nano_time", "sync_flag"]
            assert gimbal["limit"] == full["gimbal"]["limit"] and info["cur_mov_control_mode"] == 1


def test_fit_fills_fields_it_is_not_given_with_their_rest():
    name = PROFILES[-1]
    assert values.fit(name, "gimbal", {"pitch": -30.0}) == {
        "roll": F32(0), "pitch": -30.0, "yaw": F32(0),
        "limit": {"pitch_limit": False, "roll_limit": False, "yaw_limit": False, "reserved": 0}}
    assert values.rest(name, "control_info")["control_device"] == "rc"


def test_a_field_no_profile_has_is_refused():
    with pytest.raises(ValueError, match="no profile's gimbal has a field 'limit.pich_limit'"):
        values.fit(PROFILES[0], "gimbal", {"limit": {"pich_limit": True}})
    with pytest.raises(ValueError, match="no profile's time_stamp has a field 'nanos'"):
        values.fit(PROFILES[0], "time_stamp", {"time": 1, "nanos": 2})


def with_field(value, path: str, v):
    if not path:
        return v
    head, _, rest = path.partition(".")
    return {**value, head: with_field(value[head], rest, v)}


def test_the_wire_format_of_a_byte_field_is_where_the_layout_puts_it():
    """One field set to a sentinel: the bytes that change are the sentinel packed in the field's format."""
    for name in PROFILES:
        for item, con in values.layout(name):
            rest = values.rest(name, item)
            base = con.build(rest)
            for path, leaf in values.fields(name, item).items():
                if leaf.format is None or leaf.kind not in ("int", "float"):
                    continue
                sentinel = struct.unpack(leaf.format, b"\x5a" * struct.calcsize(leaf.format))[0]
                raw = con.build(with_field(rest, path, sentinel))
                diff = [i for i, (a, b) in enumerate(zip(base, raw)) if a != b]
                assert raw[diff[0]:diff[-1] + 1] == struct.pack(leaf.format, sentinel), (name, item, path)


def test_broadcast_data_sets_the_flags_and_sends_unmodelled_items_at_rest():
    for name in PROFILES:
        order = values.items(name)
        present = order[::2]
        first = fullest(order[0])
        data = values.broadcast_data(name, present, {order[0]: first})
        payload = for_profile(name)
        parsed = decoded(payload.parse(payload.build(data)))
        assert [it for it in order if parsed[f"has_{it}"]] == list(present)
        sent = {p: number(v) for p, v in flat(parsed[order[0]]).items()}
        assert sent == flat(values.fit(name, order[0], first)) != flat(values.rest(name, order[0]))
        for it in present[1:]:
            assert data[it] == values.rest(name, it)
    with pytest.raises(ValueError, match="has no broadcast item wind"):
        values.broadcast_data(PROFILES[0], ["wind"], {})


# ---- a made-up item in a made-up profile ---------------------------------------------


def _blob(n: int):
    return Bytes(n)


WIND = record(
    "speed" / F32le,
    "direction" / Int16sl,
    lsb_first(
        "valid" / Flag,
        "source" / Enum(BitsInteger(3), **CONTROL_DEVICE),
        "reserved" / BitsInteger(4),
    ),
    "version" / Const(2, Int8ul),
    "extra_len" / Int8ul,
    "extra" / when(this.extra_len > 0, Call(_blob, this.extra_len)),
    "tail" / ExactSize(9, Struct("lat" / F64le, "gust" / when(True, lsb_first("hi" / Flag, "lo" / BitsInteger(7))))),
    "note" / when(False, Int32ul),
)
MADE_UP = 200   # a profile value no enum has


@pytest.fixture
def made_up_profile(monkeypatch):
    """The last profile's items and the made-up one after them, as profile MADE_UP,
    its payload laid out as spec/construct/broadcast.py lays out every profile."""
    order = (*values.layout(PROFILES[-1]), ("wind", WIND))
    flags = [f"has_{name}" / Flag for name, _ in order]
    reserved = "reserved_flags" / Const(0, BitsInteger(16 - len(order)))
    present = [name / when(lambda ctx, key=f"has_{name}": ctx[key], sub) for name, sub in order]
    payload = record(lsb_first(*flags, reserved), *present, Terminated)
    monkeypatch.setitem(values.ITEMS, MADE_UP, order)
    monkeypatch.setattr(values, "for_profile", lambda p: payload if p == MADE_UP else for_profile(p))
    yield payload
    values._fields.cache_clear()
    values._known_paths.cache_clear()


def test_a_made_up_item_gets_a_rest_value_that_builds_and_decodes_back(made_up_profile):
    rest = values.rest(MADE_UP, "wind")
    assert rest == {"speed": F32(0), "direction": 0, "valid": False, "source": "rc", "reserved": 0, "version": 2,
                    "extra_len": 0, "tail": {"lat": F64(0), "gust": {"hi": False, "lo": 0}}}
    raw = WIND.build(rest)
    assert raw == bytes(7) + b"\x02\x00" + bytes(9)
    assert decoded(WIND.parse(raw)) == rest
    assert {p: (leaf.kind, leaf.format) for p, leaf in values.fields(MADE_UP, "wind").items()} == {
        "speed": ("float", "<f"), "direction": ("int", "<h"), "valid": ("flag", None), "source": ("enum", None),
        "reserved": ("int", None), "version": ("const", "<B"), "extra_len": ("int", "<B"),
        "tail.lat": ("float", "<d"), "tail.gust.hi": ("flag", None), "tail.gust.lo": ("int", None)}


def test_a_made_up_item_is_fitted_by_its_conditions_and_sent(made_up_profile):
    value = {"speed": 3.5, "direction": -90, "valid": True, "source": 2, "extra_len": 3, "extra": b"abc",
             "note": 7, "tail": {"lat": 1.25}}
    fitted = values.fit(MADE_UP, "wind", value)
    assert "note" not in fitted and fitted["extra"] == b"abc" and fitted["version"] == 2
    assert "extra" not in values.fit(MADE_UP, "wind", {**value, "extra_len": 0})
    data = values.broadcast_data(MADE_UP, ["time_stamp", "wind"], {"wind": value})
    parsed = made_up_profile.parse(made_up_profile.build(data))
    assert parsed.has_wind and parsed.wind.extra == b"abc" and parsed.wind.direction == -90
    assert parsed.wind.source == "onboard_device" and float(parsed.wind.tail.lat) == 1.25
    assert decoded(parsed.time_stamp) == values.rest(MADE_UP, "time_stamp")
    assert not parsed.has_quaternion
    with pytest.raises(ValueError, match="has no broadcast item"):
        values.rest(PROFILES[-1], "wind")


def test_a_field_without_a_known_rest_value_is_named():
    with pytest.raises(TypeError, match="no rest value known for a GreedyBytes field"):
        values.cut(Struct("x" / Int8ul, "blob" / construct.GreedyBytes))
