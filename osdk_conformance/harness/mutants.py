"""Deliberately broken implementations: the mutants of `osdkc selftest`.

A golden-vector suite is only worth something if it fails implementations
that are wrong in the ways real ones are wrong. Each mutant here is the
reference implementation (osdk_conformance.reference.codec, the answers of the
bundled "construct" testee) with ONE fault injected for the life of the
process, modelled on a mistake an implementer can plausibly make: most of
them come straight from the disagreements in spec/ERRATA.md (the SDK's
no-length-check broadcast copy, the doc's longitude-first table, the later
SDK's wider limits, ...).

Faults are injected into the real code path, not into the answers, wherever
the code has a place for them: the CRC functions the receiver and the
encoder call, the receiver's header check and its rescanning, the Construct
layouts of items and headers (fields swapped, resized or unchecked), the
rules lookups the control mode checks call, the float adapter. Only faults
that live outside the decoder proper (an error class mapped wrongly, a
crash, a hang) wrap `reference.answer`.

`conformance/testees/mutant_testee.py NAME` applies one mutant and then
runs the construct testee's request loop; `apply(name)` is what it calls.
Each `Mutant` has a name, a one-line description, the spec rules
(`rule:<name>`, osdk_conformance.harness.spec_rules) and errata entries it violates,
and the failure kind the runner should record for it (`mismatch` for a
wrong answer, `testee_crash` / `testee_timeout` for the two misbehaving
ones).

Patching is process-wide and irreversible: never apply a mutant in a
process that does anything else.
"""
from __future__ import annotations

import dataclasses
import functools
import io
import os
import sys
import time
from dataclasses import dataclass
from typing import Any, Callable
from osdk_conformance import _construct as osdk_construct
from osdk_conformance.core import crc, deframe, rules
from osdk_conformance.core.crc import crc16, crc32
from osdk_conformance.core.deframe import HEADER_LEN, Rejected, header_fields
from osdk_conformance.core.rules import classify_control_mode
from osdk_conformance.reference import accel, codec as reference, decode
from osdk_conformance.reference.decode import Decoder
from osdk_conformance._construct import broadcast as b, broadcast_items as items, floats, frame, payload
from osdk_conformance._construct.enums import CONTROL_ACK, ENCRYPTION, enum_int

NONE = "none"
"""The name mutant_testee.py accepts for "no fault" (the baseline run)."""


@dataclass(frozen=True)
class Mutant:
    name: str
    description: str
    violates: tuple[str, ...]
    apply: Callable[[], None]
    expect: str = "mismatch"
    """The failure kind a kill should have: mismatch, testee_crash or testee_timeout."""


MUTANTS: dict[str, Mutant] = {}


def _mutant(name: str, description: str, *violates: str, expect: str = "mismatch"):
    def register(fn: Callable[[], None]) -> Callable[[], None]:
        if name in MUTANTS or name == NONE:
            raise ValueError(f"duplicate mutant name {name!r}")
        MUTANTS[name] = Mutant(name, description, tuple(violates), fn, expect)
        return fn

    return register


def apply(name: str) -> None:
    """Inject mutant `name` into this process (NONE: nothing). KeyError for an unknown name."""
    if name == NONE:
        return
    MUTANTS[name].apply()


# ============================================================== patching helpers


def _replace_field(root: Any, name: str, make: Callable[[Any], Any]) -> int:
    """Replace, in place, every field called `name` in the Construct tree
    under `root` by `name / make(old inner construct)`; returns how many."""
    import construct

    seen: set[int] = set()
    count = 0

    def visit(c: Any) -> None:
        nonlocal count
        if not isinstance(c, construct.Construct) or id(c) in seen:
            return
        seen.add(id(c))
        subcons = getattr(c, "subcons", None)
        if isinstance(subcons, list):
            for i, sc in enumerate(subcons):
                if getattr(sc, "name", None) == name:
                    new = name / make(sc.subcon)
                    subcons[i] = new
                    if isinstance(getattr(c, "_subcons", None), dict):
                        c._subcons[name] = new
                    count += 1
                else:
                    visit(sc)
        for attr in ("subcon", "thensubcon", "elsesubcon"):
            visit(getattr(c, attr, None))

    visit(root)
    if not count:
        raise RuntimeError(f"mutant: no field {name!r} found to replace")
    return count


def _swap_fields(struct: Any, a: str, b: str) -> None:
    """Swap the wire positions of two fields of a Struct, in place."""
    names = [getattr(sc, "name", None) for sc in struct.subcons]
    i, j = names.index(a), names.index(b)
    struct.subcons[i], struct.subcons[j] = struct.subcons[j], struct.subcons[i]


def _clear_layout_caches() -> None:
    payload.broadcast.cache_clear()
    payload._payload.cache_clear()
    frame.frame_data.cache_clear()
    frame._frame.cache_clear()


def _rebuild_broadcast(change: Callable[[int, list], list | None]) -> None:
    """Rebuild the broadcast profile constructs from changed item lists:
    change(profile value, [(item name, construct), ...] in flag-bit order)
    returns the new list, or None to keep the profile."""

    for p, order in list(b.ITEMS.items()):
        new = change(p, list(order))
        if new is None:
            continue
        b.ITEMS[p] = tuple(new)
        b._BY_PROFILE[p] = b._profile(tuple(new))
        setattr(b, b.NAMES[p], b._BY_PROFILE[p])
    _clear_layout_caches()


def _replace_item(order: list, item: str, construct_: Any) -> list:
    return [(n, construct_ if n == item else c) for n, c in order]


def _set_crc(name: str, **changes: int) -> None:
    """Replace CRC `name` ("crc16"/"crc32") everywhere it is called by an
    engine with changed parameters (init, xorout)."""

    bad = crc.Crc(dataclasses.replace(crc.engine(name).spec, **changes))
    for module in (crc, deframe, reference, frame):
        if hasattr(module, name):
            setattr(module, name, bad)


def _header_check(*, version: bool = True, reserved: bool = True, lengths: bool = True) -> None:
    """Replace the receiver's header check (deframe.header_problem, also used
    by reference.decode_frame) by one that skips some of its rules."""

    def header_problem(header: bytes) -> tuple[str, str] | None:
        stored = header[10] | header[11] << 8
        computed = deframe.crc16(header[:10])
        if computed != stored:
            return "bad_crc16", f"CRC-16 is 0x{stored:04x}, expected 0x{computed:04x}"
        word = header[1] | header[2] << 8
        length, ver = word & 0x3FF, word >> 10
        if version and ver != 0:
            return "bad_version", f"header version {ver}, must be 0"
        if reserved and (header[3] >> 6 or any(header[5:8])):
            return "reserved_bits", "RES0/RES1 not 0"
        if length < 12 or (lengths and 12 < length <= 16):
            return "impossible_length", f"LEN {length} is impossible"
        return None

    deframe.header_problem = header_problem
    reference.header_problem = header_problem


def _header_field(name: str, make: Callable[[Any], Any]) -> None:
    """Replace a field of the frame header layout (shared by every frame construct)."""

    _replace_field(frame._header_bits, name, make)
    _clear_layout_caches()


def _unchecked(old: Any) -> Any:
    """A Const(0, BitsInteger(n)) field that reads any value (and builds 0)."""
    import construct

    return construct.Default(old.subcon, 0)


def _check(fn: Callable[[Any], bool]) -> Callable[[Any], Any]:
    import construct

    return lambda old: construct.Check(fn)


def _on_deframer_events(fn: Callable[[Any, Any], Any]) -> None:
    """Filter the receiver's events: fn(deframer, event) returns the event to
    report (or None) and may drop bytes from the deframer's buffer. It runs
    after the event is produced and before the receiver resumes: for a
    header or CRC-32 rejection, before the receiver drops the start byte."""

    original = deframe.Deframer._scan

    def _scan(self, final):
        for ev in original(self, final):
            out = fn(self, ev)
            if out is not None:
                yield out

    deframe.Deframer._scan = _scan


def _wrap_answer(fn: Callable[..., dict]) -> None:
    """reference.answer becomes fn(original answer, op, profile, input)."""

    original = reference.answer

    def answer(op, profile, input):  # noqa: A002 - the protocol's word
        return fn(original, op, profile, input)

    reference.answer = answer


def _wrap_rules(classify: Callable | None = None, ranges: Callable | None = None) -> None:
    """rules.classify_control_mode / rules.input_ranges (which the reference
    looks up at call time) become fn(original, byte, profile)."""

    if classify is not None:
        orig_c = rules.classify_control_mode
        rules.classify_control_mode = lambda byte, profile: classify(orig_c, byte, profile)
    if ranges is not None:
        orig_r = rules.input_ranges
        rules.input_ranges = lambda byte, profile: ranges(orig_r, byte, profile)


def _broadcast_input(transform: Callable[[bytes, Any], bytes]) -> None:
    """The broadcast value (set 0x02, id 0x00) is parsed from
    transform(its bytes, the profile's broadcast construct) instead of its bytes."""
    import construct

    class Preprocessed(construct.Subconstruct):
        def _parse(self, stream, context, path):
            data = construct.stream_read_entire(stream, path)
            return self.subcon._parsereport(io.BytesIO(transform(data, self.subcon)), context, path)

        def _sizeof(self, context, path):
            raise construct.SizeofError("variable size", path=path)

    original = payload._payload

    @functools.lru_cache(maxsize=4096)
    def _payload(k: int, profile: int):
        if k != payload.key(0x02, 0x00, False):
            return original(k, profile)
        return construct.Struct("body" / Preprocessed(payload.broadcast(profile)), construct.Terminated)

    payload._payload = _payload
    _clear_layout_caches()


def _float_decode(fix: Callable[[Any], Any]) -> None:
    """Every decoded float32/float64 passes through fix(F32 or F64)."""

    original = floats._IeeeAdapter._decode

    def _decode(self, obj, context, path):
        return fix(original(self, obj, context, path))

    floats._IeeeAdapter._decode = _decode


def _decoded(data_hex: Any) -> bytes:
    try:
        return bytes.fromhex(data_hex) if isinstance(data_hex, str) else b""
    except ValueError:
        return b""


# ============================================================== frame layer


@_mutant("crc16_init_ffff", "CRC-16 register starts at 0xFFFF instead of 0x3AA3 (receiver and encoder)",
         "rule:frame.crc16", "E21")
def _crc16_init_ffff() -> None:
    _set_crc("crc16", init=0xFFFF)


@_mutant("crc32_final_xor", "CRC-32 with a final XOR of 0xFFFFFFFF (the common zlib habit; the SDK has none)",
         "rule:frame.crc32", "E21")
def _crc32_final_xor() -> None:
    _set_crc("crc32", xorout=0xFFFFFFFF)


@_mutant("header_reserved_ignored", "RES0 and RES1 of the header are not checked (decoded as plain numbers)",
         "rule:frame.reserved")
def _header_reserved_ignored() -> None:
    _header_check(reserved=False)
    _header_field("res0", _unchecked)
    _header_field("res1", _unchecked)


@_mutant("version_not_checked", "VER of the header is not checked", "rule:frame.ver")
def _version_not_checked() -> None:
    _header_check(version=False)
    _header_field("ver", _unchecked)


@_mutant("len_13_to_16_accepted", "LEN 13..16 accepted as frame lengths (only LEN < 12 rejected)",
         "rule:frame.len", "E22")
def _len_13_to_16_accepted() -> None:
    _header_check(lengths=False)
    _header_field("_valid_len", _check(lambda this: this.len >= 12))


@_mutant("ack_session0_accepted", "an ACK frame in session 0 is accepted (decoder and encoder)",
         "rule:frame.session", "E24")
def _ack_session0_accepted() -> None:
    _header_field("_valid_session", _check(lambda this: True))


@_mutant("enc_padding_unchecked", "ENC 0/1 accepted with any PADDING and any DATA length (no block rules)",
         "rule:frame.enc", "E23")
def _enc_padding_unchecked() -> None:
    _header_field("_valid_enc", _check(lambda this: enum_int(this.enc, ENCRYPTION) in (0, 1)))


@_mutant("seq_big_endian", "SEQ read and written big-endian", "rule:frame.data", "rule:encode.frame")
def _seq_big_endian() -> None:
    import construct

    for root in (frame._crc16_covered, frame.header, *(frame._frame(p) for p in range(3))):
        _replace_field(root, "seq", lambda old: construct.Int16ub)


@_mutant("encoder_len_without_crc32", "the encoder writes LEN without the 4 CRC-32 bytes (CRCs otherwise right)",
         "rule:encode.frame", "rule:frame.len", "E22")
def _encoder_len_without_crc32() -> None:
    original = osdk_construct.build_frame

    def build_frame(**kw: Any) -> bytes:
        raw = bytearray(original(**kw))
        if len(raw) > 12:
            word = (raw[1] | raw[2] << 8) & ~0x3FF | (len(raw) - 4)
            raw[1:3] = word.to_bytes(2, "little")
            raw[10:12] = crc16(bytes(raw[:10])).to_bytes(2, "little")
            raw[-4:] = crc32(bytes(raw[:-4])).to_bytes(4, "little")
        return bytes(raw)

    osdk_construct.build_frame = build_frame


# ============================================================== the receiver

_HEADER_ERRORS = frozenset({"bad_crc16", "bad_version", "reserved_bits", "impossible_length"})


@_mutant("no_rescan_after_bad_crc32", "after a bad CRC-32 the receiver skips the whole frame instead of "
         "rescanning after its start byte", "rule:stream.resync")
def _no_rescan_after_bad_crc32() -> None:
    def skip_frame(d, ev):
        if isinstance(ev, Rejected) and ev.error == "bad_crc32":
            d._drop(ev.length - 1)  # the receiver drops the start byte itself
        return ev

    _on_deframer_events(skip_frame)


@_mutant("bad_header_drops_12", "on a bad header the receiver drops all 12 header bytes instead of one",
         "rule:stream.resync")
def _bad_header_drops_12() -> None:
    def drop_header(d, ev):
        if isinstance(ev, Rejected) and ev.error in _HEADER_ERRORS:
            d._drop(HEADER_LEN - 1)
            return dataclasses.replace(ev, length=HEADER_LEN)
        return ev

    _on_deframer_events(drop_header)


@_mutant("truncated_tail_silent", "a frame cut off by the end of the stream is dropped silently "
         "(no truncated_frame event, no rescan)", "rule:stream.truncated_tail")
def _truncated_tail_silent() -> None:
    def silent(d, ev):
        if isinstance(ev, Rejected) and ev.error == "truncated_frame":
            d._drop(len(d._buf))
            return None
        return ev

    _on_deframer_events(silent)


@_mutant("ack_matching_disabled", "ACK values are never typed by the command they answer (kept raw)",
         "rule:stream.ack_match")
def _ack_matching_disabled() -> None:
    original = Decoder._frame

    def _frame(self, ev):
        out = original(self, ev)
        self._slots.clear()
        return out

    Decoder._frame = _frame


@_mutant("session1_ack_matched", "session 1 has an ACK slot too: its ACKs are matched like any other session's "
         "(what the doc suggests, not what DJI's receivers do)", "E24", "E32", "rule:stream.ack_match")
def _session1_ack_matched() -> None:
    original = Decoder._expect_ack

    def _expect_ack(self, session, seq, cmd):
        if session == 1:
            self._slots[1] = (seq, *cmd)
        original(self, session, seq, cmd)

    Decoder._expect_ack = _expect_ack


# ============================================================== broadcast


@_mutant("position_lat_lon_swapped", "position item read longitude first, as the Appendix table lists it",
         "E01", "rule:broadcast.item_fields")
def _position_lat_lon_swapped() -> None:
    _swap_fields(items.position, "latitude", "longitude")


@_mutant("magnetometer_5_bytes", "magnetometer item read as 5 bytes (z as one signed byte)",
         "rule:broadcast.item_sizes", "E07")
def _magnetometer_5_bytes() -> None:
    import construct

    _replace_field(items.magnetometer, "z", lambda old: construct.Int8sl)


@_mutant("a3_m100_flag_order", "a3-fw3.1 payloads decoded with the M100 flag-bit order (no GPS/RTK at bits 6-7)",
         "rule:broadcast.flag_order.a3-fw3.1", "E28")
def _a3_m100_flag_order() -> None:
    m100 = list(b.ITEMS[1])  # same item variants as a3-fw3.1, M100 bit order
    _rebuild_broadcast(lambda p, order: m100 if p == 2 else None)


@_mutant("broadcast_no_length_check", "broadcast items copied without a length check, like both DJI SDKs "
         "(reading past the end gives zeros)", "rule:broadcast.bounds", "rule:broadcast.flag_word", "E25")
def _broadcast_no_length_check() -> None:
    import construct

    def zero_padded(data: bytes, sub: Any) -> bytes:
        for extra in range(0, 1024):
            try:
                sub.parse(data + bytes(extra))
            except construct.StreamError:
                continue
            except construct.ConstructError:
                pass
            return data + bytes(extra)
        return data

    _broadcast_input(zero_padded)


@_mutant("broadcast_trailing_accepted", "bytes after the last flagged broadcast item are ignored",
         "rule:broadcast.bounds", "E25")
def _broadcast_trailing_accepted() -> None:
    import construct

    for rec in b._BY_PROFILE.values():
        subcons = rec.subcon.subcons
        assert isinstance(subcons[-1], construct.Terminated.__class__)
        subcons[-1] = "_rest" / construct.GreedyBytes
    _clear_layout_caches()


@_mutant("reserved_flags_ignored", "reserved flag bits of the broadcast flag word are not checked",
         "rule:broadcast.reserved_flags", "E25")
def _reserved_flags_ignored() -> None:
    for rec in b._BY_PROFILE.values():
        _replace_field(rec, "reserved_flags", _unchecked)
    _clear_layout_caches()


@_mutant("flag_word_big_endian", "the broadcast flag word read big-endian", "rule:broadcast.flag_word")
def _flag_word_big_endian() -> None:
    _broadcast_input(lambda data, sub: data[1::-1] + data[2:] if len(data) >= 2 else data)


@_mutant("fw23_time_stamp_long", "m100-fw2.3 time stamp read in its 9-byte FW 3.1 form",
         "rule:broadcast.item_sizes", "E08")
def _fw23_time_stamp_long() -> None:
    _rebuild_broadcast(lambda p, order: _replace_item(order, "time_stamp", items.time_stamp(True)) if p == 0 else None)


@_mutant("fw23_gimbal_limit_byte", "m100-fw2.3 gimbal item read with the FW 3.1 limit byte (13 bytes)",
         "rule:broadcast.item_sizes", "E09")
def _fw23_gimbal_limit_byte() -> None:
    _rebuild_broadcast(lambda p, order: _replace_item(order, "gimbal", items.gimbal(True)) if p == 0 else None)


@_mutant("fw31_control_info_1_byte", "FW 3.1 control info read as the 1-byte FW 2.3 form (no mode byte)",
         "rule:broadcast.item_sizes", "E03")
def _fw31_control_info_1_byte() -> None:
    _rebuild_broadcast(lambda p, order: _replace_item(order, "control_info", items.control_info(False)) if p else None)


@_mutant("cur_mov_control_mode_shifted", "cur_mov_control_mode names shifted by one (value n gets the name of n-1)",
         "rule:broadcast.item_fields", "E02")
def _cur_mov_control_mode_shifted() -> None:
    items.CUR_MOV_CONTROL_MODE = {name: value + 1 for name, value in items.CUR_MOV_CONTROL_MODE.items()}
    shifted = items.control_info.__wrapped__(True)
    _rebuild_broadcast(lambda p, order: _replace_item(order, "control_info", shifted) if p else None)


@_mutant("gps_detail_lat_first", "A3 GPS detail read latitude before longitude", "rule:broadcast.item_fields", "E13")
def _gps_detail_lat_first() -> None:
    _swap_fields(items.gps_detail, "latitude", "longitude")


@_mutant("rtk_yaw_unsigned", "A3 RTK detail yaw read as an unsigned 16-bit number",
         "rule:broadcast.item_fields", "E14")
def _rtk_yaw_unsigned() -> None:
    import construct

    _replace_field(items.rtk_detail, "yaw", lambda old: construct.Int16ul)


@_mutant("velocity_reserved_rejected", "reserved bits of the velocity status byte rejected instead of decoded",
         "rule:broadcast.reserved_item_bits", "E04")
def _velocity_reserved_rejected() -> None:
    import construct

    _replace_field(items.velocity, "reserved", lambda old: construct.Const(0, old))


# ============================================================== other payloads


@_mutant("control_ack_sdk_names", "control ACK codes 3/4 named as failures (obtain_failed / release_failed) "
         "as the 3.x doc has it", "rule:payload.control_ack", "E26")
def _control_ack_sdk_names() -> None:
    import construct

    renamed = {{"obtain_in_progress": "obtain_failed", "release_in_progress": "release_failed"}.get(k, k): v
               for k, v in CONTROL_ACK.items()}
    _replace_field(payload.control_ack_value, "ack_code", lambda old: construct.Enum(construct.Int16ul, **renamed))
    _clear_layout_caches()


@_mutant("activation_fields_swapped", "activation request read with API level before the app id",
         "rule:payload.activation_request", "E12")
def _activation_fields_swapped() -> None:
    _swap_fields(payload.activation_request, "app_id", "api_level")


@_mutant("size_errors_merged", "every size problem reported as length_mismatch (truncated_payload never used)",
         "rule:payload.truncated", "rule:broadcast.bounds")
def _size_errors_merged() -> None:
    def merge(original, op, profile, inp):
        res = original(op, profile, inp)
        if res.get("ok") is False and res.get("error") == "truncated_payload":
            res = dict(res, error="length_mismatch")
        return res

    _wrap_answer(merge)


# ============================================================== floats


@_mutant("snan_quieted", "signalling NaNs come out quiet (the float goes through a C double)",
         "rule:floats.bit_exact")
def _snan_quieted() -> None:
    def quiet(f):
        return type(f)(f.ieee_bits | f.quiet_bit) if f.is_signalling_nan else f

    _float_decode(quiet)


@_mutant("neg_zero_normalised", "-0.0 decoded as 0.0", "rule:floats.bit_exact")
def _neg_zero_normalised() -> None:
    def positive(f):
        return type(f)(0) if f.ieee_bits == 1 << (f.ieee_width - 1) else f

    _float_decode(positive)


# ============================================================== control mode and ranges


def _with_ranges(change: Callable[[dict], None]) -> Callable:
    def ranges(original, byte, profile):
        r = original(byte, profile)
        if r is not None:
            change(r)
        return r

    return ranges


@_mutant("thrust_0_to_100", "thrust accepted from 0 % (the Mode table's scale) instead of 10 %",
         "rule:control.ranges", "E05")
def _thrust_0_to_100() -> None:
    def widen(r: dict) -> None:
        if r["vertical"].get("unit") == "percent":
            r["vertical"]["min"] = 0

    _wrap_rules(ranges=_with_ranges(widen))


@_mutant("yaw_rate_150", "yaw rate accepted up to ±150 deg/s (the later SDK's limit) instead of ±100",
         "rule:control.ranges", "E16")
def _yaw_rate_150() -> None:
    def widen(r: dict) -> None:
        if r["yaw"].get("unit") == "deg/s":
            r["yaw"]["min"], r["yaw"]["max"] = -150, 150

    _wrap_rules(ranges=_with_ranges(widen))


@_mutant("range_limits_exclusive", "setpoints exactly at a range limit rejected (limits taken as exclusive)",
         "rule:control.ranges")
def _range_limits_exclusive() -> None:
    original = reference._out_of_range

    def _out_of_range(value: float, limits: dict) -> str | None:
        why = original(value, limits)
        if why is None and value in (limits.get("min"), limits.get("max")):
            return "at an (exclusive) limit"
        return why

    reference._out_of_range = _out_of_range


@_mutant("nan_passes_range_check", "NaN setpoints pass the range check (plain < and > comparisons), and "
         "infinities pass unbounded limits", "rule:control.non_finite", "E05")
def _nan_passes_range_check() -> None:
    def _out_of_range(value: float, limits: dict) -> str | None:
        lo, hi = limits.get("min"), limits.get("max")
        if lo is not None and value < lo:
            return f"below {lo}"
        if hi is not None and value > hi:
            return f"above {hi}"
        return None

    reference._out_of_range = _out_of_range


def _as_other_byte(mapping: Callable[[int, str], tuple[int, str] | None],
                   horizontal: dict | None = None) -> None:
    """Classify (and range-check) some mode bytes as if they were another
    byte / profile: mapping(byte, profile) gives (byte', profile') or None."""

    def classify(original, byte, profile):
        other = mapping(byte, profile)
        if other is None:
            return original(byte, profile)
        out = original(*other)
        return dict(out, byte=byte, profile=profile)

    def ranges(original, byte, profile):
        other = mapping(byte, profile)
        r = original(*(other or (byte, profile)))
        if other is not None and r is not None and horizontal is not None:
            r["horizontal"] = dict(horizontal)
        return r

    _wrap_rules(classify=classify, ranges=ranges)


@_mutant("horizontal_0b11_documented", "horizontal logic 0b11 (later firmware's angular rate, ±150 deg/s) "
         "accepted as a documented mode", "rule:control.undefined", "E16")
def _horizontal_0b11_documented() -> None:
    _as_other_byte(lambda byte, profile: (byte & 0x3F, profile) if byte >> 6 == 3 else None,
                   horizontal={"min": -150, "max": 150, "unit": "deg/s"})


@_mutant("frame_0b1x_accepted", "horizontal frame bit 2 ignored, so frames 0b10/0b11 pass as ground/body",
         "rule:control.undefined", "E16")
def _frame_0b1x_accepted() -> None:
    _as_other_byte(lambda byte, profile: (byte & ~0x04, profile) if byte & 0x04 else None)


@_mutant("e15_ignored", "on m100-fw2.3 bit 0 read as the stable flag (FW 3.1 meaning), not the yaw frame",
         "rule:control.bit0_fw2_3", "E15")
def _e15_ignored() -> None:
    _as_other_byte(lambda byte, profile: (byte, "m100-fw3.1") if profile == "m100-fw2.3" else None)


# ============================================================== bug classes of osdk_conformance.harness.vector_tables
#
# One realistic fault per cell of the tables `osdkc vectors coverage` shows:
# a stream decoder resuming at the wrong place after an error class, ACK
# matching that remembers or forgets wrongly, two frame rules checked in
# the other order, the movement checks in the other order, and every header
# field read one bit too wide or too narrow.


@_mutant("value_error_rescans_after_sof", "after a frame whose value does not decode (bad_session, bad_encryption, "
         "payload errors) the receiver rescans from the byte after its start byte, as after a bad CRC-32",
         "rule:stream.resync")
def _value_error_rescans_after_sof() -> None:
    rejected: list[bool] = []
    original_event = decode.Decoder.event

    def event(self, ev):
        out = original_event(self, ev)
        rejected.append(isinstance(ev, deframe.Frame) and out["kind"] == "error")
        return out

    original_scan = deframe.Deframer._scan

    def _scan(self, final):
        for ev in original_scan(self, final):
            yield ev  # the decoder judges it before the receiver resumes
            if isinstance(ev, deframe.Frame) and rejected and rejected.pop():
                n = len(ev.raw)  # put all but the start byte back behind the frame the receiver drops next
                self._buf[n:n] = ev.raw[1:]
                self._base -= n - 1

    decode.Decoder.event = event
    deframe.Deframer._scan = _scan


@_mutant("truncated_tail_no_rescan", "a frame cut off by the end of the stream is reported as truncated_frame, "
         "but the bytes after its start byte are not rescanned", "rule:stream.truncated_tail", "rule:stream.resync")
def _truncated_tail_no_rescan() -> None:
    def no_rescan(d, ev):
        if isinstance(ev, Rejected) and ev.error == "truncated_frame":
            d._drop(len(d._buf))
        return ev

    _on_deframer_events(no_rescan)


def _on_decoded_frames(fn: Callable[[Any, Any, dict, dict], dict]) -> None:
    """ACK matching after each frame: fn(decoder, frame event, slots before,
    answer) returns the answer and may change decoder._slots."""

    original = Decoder._frame

    def _frame(self, ev):
        before = dict(self._slots)
        return fn(self, ev, before, original(self, ev))

    Decoder._frame = _frame


def _header(ev) -> dict:
    return header_fields(ev.raw[:12])


@_mutant("ack_repeat_matched", "a matched command is not forgotten: a repeated ACK is decoded again",
         "rule:stream.ack_match")
def _ack_repeat_matched() -> None:
    def keep(decoder, ev, before, out):
        if "ack_of" in out:
            decoder._slots = before
        return out

    _on_decoded_frames(keep)


@_mutant("ack_match_seq_only", "ACKs matched to commands by SEQ alone (the session is ignored)", "rule:stream.ack_match")
def _ack_match_seq_only() -> None:
    def _take_ack(self, session, seq):
        for s, waiting in self._slots.items():
            if waiting[0] == seq:
                del self._slots[s]
                return waiting[1:]
        return None

    Decoder._take_ack = _take_ack


@_mutant("ack_last_command_only", "only the latest command waits (one slot for all sessions instead of one per "
         "session)", "rule:stream.ack_match", "E32")
def _ack_last_command_only() -> None:
    def one_slot(decoder, ev, before, out):
        added = [k for k in decoder._slots if k not in before or decoder._slots[k] != before[k]]
        if added:
            decoder._slots = {added[-1]: decoder._slots[added[-1]]}
        return out

    _on_decoded_frames(one_slot)


@_mutant("ack_first_command_kept", "a second command in a session whose slot holds one does not take the slot",
         "rule:stream.ack_match", "E32")
def _ack_first_command_kept() -> None:
    def first_wins(decoder, ev, before, out):
        for k, cmd in before.items():
            if k in decoder._slots:
                decoder._slots[k] = cmd
        return out

    _on_decoded_frames(first_wins)


@_mutant("ack_table_by_key", "commands wait under their (SESSION, SEQ), several per session (the kit's former "
         "table): a later command with another SEQ does not take the first one's place", "rule:stream.ack_match",
         "E32")
def _ack_table_by_key() -> None:
    def _expect_ack(self, session, seq, cmd):
        if session in accel.ACK_SESSIONS:
            self._slots[(session, seq)] = (seq, *cmd)

    def _take_ack(self, session, seq):
        waiting = self._slots.pop((session, seq), None)
        return None if waiting is None else waiting[1:]

    Decoder._expect_ack = _expect_ack
    Decoder._take_ack = _take_ack


@_mutant("ack_other_seq_consumes", "an ACK in a session whose slot holds another SEQ empties the slot",
         "rule:stream.ack_match", "E32")
def _ack_other_seq_consumes() -> None:
    original = Decoder._take_ack

    def _take_ack(self, session, seq):
        found = original(self, session, seq)
        self._slots.pop(session, None)
        return found

    Decoder._take_ack = _take_ack


@_mutant("ack_rejected_command_remembered", "a command whose value does not decode still takes its session's slot",
         "rule:stream.ack_match")
def _ack_rejected_command_remembered() -> None:
    def remember(decoder, ev, before, out):
        h = _header(ev)
        if out["kind"] == "error" and not h["is_ack"] and h["session"] in accel.ACK_SESSIONS and h["enc"] == 0 \
                and len(ev.raw) > 17:
            decoder._slots[h["session"]] = (h["seq"], ev.raw[12], ev.raw[13])
        return out

    _on_decoded_frames(remember)


@_mutant("ack_header_only_ignored", "a header-only ACK (no value) neither matches nor consumes the command (the "
         "kit's former rule), so a later full ACK is matched", "rule:stream.ack_match", "rule:frame.header_only",
         "E32")
def _ack_header_only_ignored() -> None:
    original = Decoder._frame

    def _frame(self, ev):
        h = _header(ev)
        if not (h["is_ack"] and h["len"] == 12):
            return original(self, ev)
        slots, self._slots = self._slots, {}
        try:
            return original(self, ev)
        finally:
            self._slots = slots

    Decoder._frame = _frame


def _header_rules_in_order(order: tuple[str, ...]) -> None:
    """The receiver's header checks (deframe.header_problem, also used by
    decode_frame) run in `order` instead of CRC-16, VER, RES0, RES1, LEN."""

    def header_problem(header: bytes) -> tuple[str, str] | None:
        f = deframe.header_fields(header)
        checks = {
            "crc16": deframe.crc16(header[:10]) != f["crc16"] and ("bad_crc16", "CRC-16 wrong"),
            "ver": f["ver"] != 0 and ("bad_version", "VER not 0"),
            "res0": f["res0"] != 0 and ("reserved_bits", "RES0 not 0"),
            "res1": f["res1"] != 0 and ("reserved_bits", "RES1 not 0"),
            "len": (f["len"] < 12 or 12 < f["len"] <= 16) and ("impossible_length", "LEN impossible"),
        }
        return next((checks[name] for name in order if checks[name]), None)

    deframe.header_problem = header_problem
    reference.header_problem = header_problem


@_mutant("crc16_checked_last", "the header's CRC-16 checked after VER, RES0, RES1 and LEN (the order of the SDK's "
         "verifyHead)", "rule:frame.crc16")
def _crc16_checked_last() -> None:
    _header_rules_in_order(("ver", "res0", "res1", "len", "crc16"))


@_mutant("len_checked_before_ver", "LEN checked before VER, RES0 and RES1", "rule:frame.len", "rule:frame.ver")
def _len_checked_before_ver() -> None:
    _header_rules_in_order(("crc16", "len", "ver", "res0", "res1"))


@_mutant("reserved_checked_before_ver", "RES0 and RES1 checked before VER", "rule:frame.reserved", "rule:frame.ver")
def _reserved_checked_before_ver() -> None:
    _header_rules_in_order(("crc16", "res0", "res1", "ver", "len"))


@_mutant("enc_checked_before_session", "ENC/PADDING checked before the ACK-in-session-0 rule", "rule:frame.session",
         "rule:frame.enc", "E23", "E24")
def _enc_checked_before_session() -> None:
    _swap_fields(frame._header_bits.subcon.subcon.subcon, "_valid_session", "_valid_enc")
    _clear_layout_caches()


@_mutant("size_checked_before_header", "decode_frame compares the byte count with LEN before checking the header",
         "rule:frame.extra_bytes", "rule:frame.truncation")
def _size_checked_before_header() -> None:
    original = reference.frame_problem

    def frame_problem(data: bytes):
        if len(data) >= 12 and data[0] == 0xAA and len(data) != reference.frame_length(data):
            short = len(data) < reference.frame_length(data)
            return ("truncated_frame" if short else "length_mismatch"), "byte count differs from LEN"
        return original(data)

    reference.frame_problem = frame_problem


@_mutant("session_enc_in_header_check", "bad_session and bad_encryption found by the receiver's header check "
         "(before LEN and CRC-32; the start byte dropped and the rest rescanned)", "rule:frame.session",
         "rule:frame.enc", "rule:stream.resync")
def _session_enc_in_header_check() -> None:
    original = deframe.header_problem

    def header_problem(header: bytes):
        problem = original(header)
        f = deframe.header_fields(header)
        if problem is None and f["is_ack"] and f["session"] == 0:
            return "bad_session", "ACK in session 0"
        if problem is None and (f["padding"] if f["enc"] == 0 else not (
                f["enc"] == 1 and 1 <= f["padding"] <= 16 and f["len"] > 16 and (f["len"] - 16) % 16 == 0)):
            return "bad_encryption", "ENC/PADDING impossible"
        return problem

    deframe.header_problem = header_problem
    reference.header_problem = header_problem


def _movement_check_first(problem: Callable[[bytes, str], tuple[str, str] | None]) -> None:
    """check_movement_control runs problem(bytes, profile) before its own checks."""

    original = reference._OPS["check_movement_control"]

    def check(profile, inp):
        found = problem(reference._hex(inp), profile)
        return reference.error(*found) if found else original(profile, inp)

    reference._OPS["check_movement_control"] = check


@_mutant("movement_mode_before_length", "check_movement_control judges the mode byte before the value's length",
         "rule:control.value", "rule:control.undefined_mode")
def _movement_mode_before_length() -> None:
    def mode(data: bytes, profile: str):
        if data and classify_control_mode(data[0], profile)["classification"] != "documented":
            return "undefined_mode", "mode byte not documented"
        return None

    _movement_check_first(mode)


@_mutant("movement_non_finite_before_mode", "check_movement_control rejects NaN and infinite setpoints "
         "(out_of_range) before it judges the mode byte", "rule:control.non_finite", "rule:control.undefined_mode")
def _movement_non_finite_before_mode() -> None:
    import math
    import struct

    def non_finite(data: bytes, profile: str):
        if len(data) == 17 and not all(math.isfinite(v) for v in struct.unpack("<4f", data[1:])):
            return "out_of_range", "a setpoint is not finite"
        return None

    _movement_check_first(non_finite)


HEADER_FIELD_RULES = {"len": "rule:frame.len", "ver": "rule:frame.ver", "session": "rule:frame.session",
                      "res0": "rule:frame.reserved", "padding": "rule:frame.enc", "enc": "rule:frame.enc",
                      "res1": "rule:frame.reserved"}
"""The rule guarding each header bit field whose width a mutant changes (is_ack, one bit, keeps its width)."""


def _header_widths(widths: dict[str, int]) -> None:
    """Read the header's bit fields (bytes 1-7) with other widths, adding up
    to the same 56 bits: in the receiver (its checks and LEN) and in the
    Construct layout."""
    import construct

    layout = frame._header_bits._layout()[1]

    def fields(header: bytes) -> dict[str, int]:
        v, lsb, out = int.from_bytes(header[1:8], "little"), 0, {}
        for name, _, _, _ in layout:
            out[name] = v >> lsb & (1 << widths[name]) - 1
            lsb += widths[name]
        return out

    def frame_length(data: bytes) -> int:
        return fields(data)["len"]

    def header_problem(header: bytes) -> tuple[str, str] | None:
        if deframe.crc16(header[:10]) != header[10] | header[11] << 8:
            return "bad_crc16", "CRC-16 wrong"
        f = fields(header)
        if f["ver"]:
            return "bad_version", "VER not 0"
        if f["res0"] or f["res1"]:
            return "reserved_bits", "RES0/RES1 not 0"
        if f["len"] < 12 or 12 < f["len"] <= 16:
            return "impossible_length", "LEN impossible"
        return None

    for module in (deframe, reference):
        module.frame_length = frame_length
        module.header_problem = header_problem
    kinds = {"int": lambda w: construct.BitsInteger(w), "const": lambda w: construct.Const(0, construct.BitsInteger(w)),
             "enum": lambda w: construct.Enum(construct.BitsInteger(w), **ENCRYPTION)}
    for name, kind, width, _ in layout:
        if widths[name] != width:
            _replace_field(frame._header_bits, name, lambda old, kind=kind, w=widths[name]: kinds[kind](w))
    _clear_layout_caches()


def _register_header_width_mutants() -> None:
    """For every boundary between two adjacent header bit fields (but the
    one-bit ACK flag's), the field below it read one bit wider and the one
    above one bit narrower, and the other way round."""

    layout = [(name, width) for name, _, width, _ in frame._header_bits._layout()[1]]
    for (low, lw), (high, hw) in zip(layout, layout[1:]):
        if "is_ack" in (low, high):
            continue
        for wider, narrower, shift in ((low, high, +1), (high, low, -1)):
            widths = dict(layout)
            widths[low] += shift
            widths[high] -= shift
            name = f"{wider}_takes_a_{narrower}_bit"
            description = (f"header {wider.upper()} read with {widths[wider]} bits (taking the "
                           f"{'lowest' if shift > 0 else 'highest'} bit of {narrower.upper()}), "
                           f"{narrower.upper()} with {widths[narrower]}")
            _mutant(name, description, *sorted({HEADER_FIELD_RULES[low], HEADER_FIELD_RULES[high]}))(
                functools.partial(_header_widths, widths))


_register_header_width_mutants()


# ============================================================== misbehaving processes


def _is_aes_frame(inp: Any) -> bool:
    data = _decoded(inp.get("hex") if isinstance(inp, dict) else None)
    return len(data) >= 12 and data[0] == 0xAA and data[4] >> 5 == 1


@_mutant("crash_on_aes", "the process dies (exit status 70) when decode_frame meets an AES frame",
         "rule:frame.aes_raw", "E23", expect="testee_crash")
def _crash_on_aes() -> None:
    def crash(original, op, profile, inp):
        if op == "decode_frame" and _is_aes_frame(inp):
            sys.stderr.write("mutant crash_on_aes: no key for ciphertext, giving up\n")
            sys.stderr.flush()
            os._exit(70)
        return original(op, profile, inp)

    _wrap_answer(crash)


@_mutant("hang_on_empty_read", "decode_stream never returns when a read delivers 0 bytes (waits for more)",
         "rule:stream.chunking", expect="testee_timeout")
def _hang_on_empty_read() -> None:
    def hang(original, op, profile, inp):
        if op == "decode_stream" and isinstance(inp, dict) and 0 in (inp.get("chunks") or []):
            while True:
                time.sleep(3600)
        return original(op, profile, inp)

    _wrap_answer(hang)
