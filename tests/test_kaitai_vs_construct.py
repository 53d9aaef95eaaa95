"""Differential test: the Construct spec against the Kaitai spec.

The .ksy files are the source of truth; osdk_construct is a second,
independent transcription of them. For every message type this module
checks, with hypothesis, that

(a) a random valid message, built with Construct, is read by the
    Kaitai-generated parser (osdk_kaitai) into the same value model
    (docs/VALUE-MODEL.md) as Construct reads it, and builds back to the
    same bytes; and
(b) random bytes, mostly made by damaging valid messages (bit flips,
    overwritten, inserted and deleted bytes, truncation, extension), are
    accepted by both parsers or rejected by both, and read to the same
    model when accepted.

Each example of test_construct_and_kaitai_agree[_large] does (a) and then
(b), so the example count of the hypothesis profile (10,000 in "ci")
applies to both, per message type.

Floats compare by IEEE bits. The only difference allowed is the one the
Kaitai Python runtime causes itself: see
`same_float_modulo_kaitai_snan_quieting`.

The message structures are generated from the .ksy files and their enums
(via osdk_conformance.ksy), not from osdk_construct, so the two sides do not
share a table that could be wrong in the same way.
"""
from __future__ import annotations

import math
import struct
from collections.abc import Callable
from dataclasses import dataclass
from io import BytesIO

import construct
import pytest
from hypothesis import given, note
from hypothesis import strategies as st
from kaitaistruct import KaitaiStream, KaitaiStructError

import osdk_construct
from osdk_conformance import ksy, model
from osdk_construct.control import control_mode as c_control_mode
from osdk_construct.control import movement_control as c_movement_control
from osdk_construct.floats import F32, F64
from osdk_kaitai.osdk_broadcast_a3_fw3_1 import OsdkBroadcastA3Fw31
from osdk_kaitai.osdk_broadcast_m100_fw2_3 import OsdkBroadcastM100Fw23
from osdk_kaitai.osdk_broadcast_m100_fw3_1 import OsdkBroadcastM100Fw31
from osdk_kaitai.osdk_control_mode import OsdkControlMode
from osdk_kaitai.osdk_frame import OsdkFrame
from osdk_kaitai.osdk_movement_control import OsdkMovementControl
from osdk_kaitai.osdk_payload import OsdkPayload

KSY = ksy.load()


# --- the one tolerated float difference -----------------------------------------

def _is_signalling_nan(width: int, bits: int) -> bool:
    mantissa = 23 if width == 32 else 52
    exponent_mask = ((1 << (width - 1)) - 1) & ~((1 << mantissa) - 1)
    quiet_bit = 1 << (mantissa - 1)
    return bits & exponent_mask == exponent_mask and bits & (quiet_bit - 1) != 0 and not bits & quiet_bit


def same_float_modulo_kaitai_snan_quieting(width: int, construct_bits: int, kaitai_bits: int) -> bool:
    """True when the Kaitai parser read the float Construct read.

    The Kaitai Python runtime reads f4/f8 with `struct.unpack`, which gives
    a Python float (a C double). Converting a float32 signalling NaN to a
    double sets its quiet bit (IEEE 754 requires the conversion to quiet
    it), and on some platforms the same happens to a float64 sNaN passing
    through the FPU. So where the wire carries a signalling NaN, the Kaitai
    side may report the same NaN with the quiet bit (bit 22 of an f32,
    bit 51 of an f64) set. Construct (osdk_construct.floats) keeps the raw
    bits, so it is the reference.

    Accepted: identical bits; or construct_bits is a signalling NaN and
    kaitai_bits == construct_bits | quiet_bit. Any other difference, in
    either direction and for any other value, is a disagreement.
    """
    if width not in (32, 64):
        raise ValueError(f"no IEEE float of width {width}")
    if kaitai_bits == construct_bits:
        return True
    quiet_bit = 1 << (22 if width == 32 else 51)
    return _is_signalling_nan(width, construct_bits) and kaitai_bits == construct_bits | quiet_bit


def assert_same_model(c, k, path: str = "$") -> None:
    """Construct's model `c` equals Kaitai's model `k`: same keys in the same
    order, same values, floats by bits (with the one tolerated difference)."""
    if isinstance(c, dict) and ("f32" in c or "f64" in c):
        assert isinstance(k, dict) and list(k) == list(c), f"{path}: construct {c!r}, kaitai {k!r}"
        (cw, cb), (kw, kb) = model.float_bits(c), model.float_bits(k)
        assert cw == kw and same_float_modulo_kaitai_snan_quieting(cw, cb, kb), (
            f"{path}: construct {c!r}, kaitai {k!r}")
        return
    if isinstance(c, dict):
        assert isinstance(k, dict), f"{path}: construct {c!r}, kaitai {k!r}"
        assert list(c) == list(k), f"{path}: construct fields {list(c)}, kaitai fields {list(k)}"
        for key in c:
            assert_same_model(c[key], k[key], f"{path}.{key}")
        return
    if isinstance(c, list):
        assert isinstance(k, list) and len(c) == len(k), f"{path}: construct {c!r}, kaitai {k!r}"
        for i, (cv, kv) in enumerate(zip(c, k)):
            assert_same_model(cv, kv, f"{path}[{i}]")
        return
    assert type(c) is type(k) and c == k, f"{path}: construct {c!r}, kaitai {k!r}"


def kaitai_model(parsed):
    return model.from_kaitai(parsed)


# --- message generation ------------------------------------------------------------
#
# Hypothesis draws one byte string per example, and a Source turns it into a
# structured message, field by field. Drawing each field from hypothesis
# separately costs about 0.1 ms a draw, which at 10,000 examples per message
# type and a few hundred fields per broadcast would take far too long; one
# draw per example keeps the ci profile within minutes, and hypothesis still
# shrinks a failure (towards zero bytes, i.e. towards zero-valued fields).

# Bytes per example: enough for the largest message of the type (a full
# a3-fw3.1 broadcast, in a frame, takes about 280) plus the edits; a source
# that runs out reads zeros. Drawing fewer bytes is measurably cheaper, so the
# small message types get a smaller draw.
SMALL_BLOB, LARGE_BLOB = 160, 320


def _ieee_layout(width: int) -> tuple[int, int, int, int]:
    mantissa = 23 if width == 32 else 52
    exp_all_ones = ((1 << (width - 1 - mantissa)) - 1) << mantissa
    return mantissa, exp_all_ones, 1 << (width - 1), 1 << (mantissa - 1)


def _special_floats(width: int) -> tuple[int, ...]:
    mantissa, inf, sign, quiet = _ieee_layout(width)
    return (
        0, sign,                                  # +0.0, -0.0
        inf, inf | sign,                          # +inf, -inf
        inf | quiet, inf | quiet | sign,          # default quiet NaNs
        inf | 1, inf | (quiet - 1) | sign,        # signalling NaNs
        inf | quiet | 1,                          # quiet NaN with a payload
        1, (1 << mantissa) - 1, sign | 1,         # denormals
        1 << mantissa, inf - 1, sign | (inf - 1),  # smallest normal, largest finite
    )


SPECIAL_FLOATS = {32: _special_floats(32), 64: _special_floats(64)}


class Source:
    """Reads a message's choices from bytes; reads zeros once they run out."""

    def __init__(self, data: bytes) -> None:
        self.data = data
        self.pos = 0

    def bytes(self, n: int) -> bytes:
        chunk = self.data[self.pos:self.pos + n]
        self.pos += n
        return chunk + bytes(n - len(chunk))

    def uint(self, bits: int) -> int:
        return int.from_bytes(self.bytes((bits + 7) // 8), "little") & ((1 << bits) - 1)

    def sint(self, bits: int) -> int:
        v = self.uint(bits)
        return v - (1 << bits) if v >> (bits - 1) else v

    def flag(self) -> bool:
        return bool(self.uint(1))

    def below(self, n: int) -> int:
        return self.uint(16) % n

    def choice(self, seq):
        return seq[self.below(len(seq))]

    def between(self, lo: int, hi: int) -> int:
        return lo + self.below(hi - lo + 1)

    def binary(self, max_size: int, min_size: int = 0) -> bytes:
        return self.bytes(self.between(min_size, max_size))

    def ieee_bits(self, width: int) -> int:
        """Raw patterns most of the time, else a special value, a NaN with a
        random payload (signalling or quiet, either sign) or a denormal."""
        mantissa, inf, sign, quiet = _ieee_layout(width)
        kind = self.uint(8)
        if kind < 128:
            return self.uint(width)
        if kind < 176:
            return self.choice(SPECIAL_FLOATS[width])
        if kind < 224:
            payload = self.uint(mantissa - 1) or 1
            return (sign if self.flag() else 0) | inf | (quiet if self.flag() else 0) | payload
        return (sign if self.flag() else 0) | (self.uint(mantissa) or 1)

    def f32(self) -> F32:
        return F32(self.ieee_bits(32))

    def f64(self) -> F64:
        return F64(self.ieee_bits(64))

    def enum(self, names: tuple[str, ...], bits: int):
        """A name of the enum or any integer the field holds; Construct builds from either."""
        return self.choice(names) if self.flag() else self.uint(bits)


def ksy_enum(file_id: str, name: str, bits: int) -> Callable[[Source], object]:
    names = tuple(sorted(KSY.enums[(file_id, name)].values()))
    return lambda s: s.enum(names, bits)


def fields(**makers: Callable[[Source], object]) -> Callable[[Source], dict]:
    """A struct generator: one generator per field, called in order."""
    return lambda s: {name: make(s) for name, make in makers.items()}


def u(bits: int):
    return lambda s: s.uint(bits)


def i(bits: int):
    return lambda s: s.sint(bits)


def raw(size: int):
    return lambda s: s.bytes(size)


f32, f64, flag = Source.f32, Source.f64, Source.flag

CONTROL_MODE = fields(
    stable_mode=ksy_enum("osdk_control_mode", "stable_mode", 1),
    horizontal_frame=ksy_enum("osdk_control_mode", "horizontal_frame", 2),
    yaw_logic=ksy_enum("osdk_control_mode", "yaw_logic", 1),
    vertical_logic=ksy_enum("osdk_control_mode", "vertical_logic", 2),
    horizontal_logic=ksy_enum("osdk_control_mode", "horizontal_logic", 2),
)

MOVEMENT_CONTROL = fields(control_mode=CONTROL_MODE, x=f32, y=f32, z=f32, yaw=f32)

_GIMBAL_LIMIT = fields(pitch_limit=flag, roll_limit=flag, yaw_limit=flag, reserved=u(5))
_DEVICE_BYTE = dict(control_device=ksy_enum("osdk_broadcast_items", "control_device", 3),
                    onboard_requested=flag, virtual_rc=flag, reserved=u(3))

# Generator per ksy type expression, as the broadcast profiles' seq spells it.
ITEM_BY_KSY_TYPE = {
    "osdk_broadcast_items::time_stamp(false)": fields(time=u(32)),
    "osdk_broadcast_items::time_stamp(true)": fields(time=u(32), nano_time=u(32), sync_flag=u(8)),
    "osdk_broadcast_items::quaternion": fields(q0=f32, q1=f32, q2=f32, q3=f32),
    "osdk_broadcast_items::vector3f": fields(x=f32, y=f32, z=f32),
    "osdk_broadcast_items::velocity": fields(x=f32, y=f32, z=f32, data_valid=flag, sensor_id=u(4), reserved=u(3)),
    "osdk_broadcast_items::position": fields(latitude=f64, longitude=f64, altitude=f32, height=f32,
                                              gps_health=u(8)),
    "osdk_broadcast_items::gps_detail": fields(date=u(32), time=u(32), longitude=i(32), latitude=i(32),
                                                height_msl=i(32), vel_n=f32, vel_e=f32, vel_d=f32),
    "osdk_broadcast_items::rtk_detail": fields(date=u(32), time=u(32), longitude=f64, latitude=f64,
                                                height_msl=f32, vel_n=f32, vel_e=f32, vel_d=f32, yaw=i(16),
                                                position_flag=u(8), yaw_flag=u(8)),
    "osdk_broadcast_items::magnetometer": fields(x=i(16), y=i(16), z=i(16)),
    "osdk_broadcast_items::rc": fields(roll=i(16), pitch=i(16), yaw=i(16), throttle=i(16), mode=i(16),
                                       gear=i(16)),
    "osdk_broadcast_items::gimbal(false)": fields(roll=f32, pitch=f32, yaw=f32),
    "osdk_broadcast_items::gimbal(true)": fields(roll=f32, pitch=f32, yaw=f32, limit=_GIMBAL_LIMIT),
    "osdk_broadcast_items::control_info(false)": fields(**_DEVICE_BYTE),
    "osdk_broadcast_items::control_info(true)": fields(
        cur_mov_control_mode=ksy_enum("osdk_broadcast_items", "cur_mov_control_mode", 8), **_DEVICE_BYTE),
    "u1": u(8),
}

PROFILES = {0: "osdk_broadcast_m100_fw2_3", 1: "osdk_broadcast_m100_fw3_1", 2: "osdk_broadcast_a3_fw3_1"}
PROFILE_IDS = {0: "m100-fw2.3", 1: "m100-fw3.1", 2: "a3-fw3.1"}


def _profile_items(profile: int) -> list[tuple[str, Callable]]:
    """(item, generator) in flag-bit order, read from the profile's .ksy seq."""
    seq = KSY.files[PROFILES[profile]]["seq"]
    flags = [f["id"].removeprefix("has_") for f in seq if f["id"].startswith("has_")]
    by_id = {f["id"]: f for f in seq}
    return [(name, ITEM_BY_KSY_TYPE[by_id[name]["type"]]) for name in flags]


def broadcast_message(profile: int) -> Callable[[Source], dict]:
    items = _profile_items(profile)

    def make(s: Source) -> dict:
        present = s.uint(len(items))
        msg = {f"has_{name}": bool(present >> bit & 1) for bit, (name, _) in enumerate(items)}
        for bit, (name, item) in enumerate(items):
            if present >> bit & 1:
                msg[name] = item(s)
        return msg

    return make


def ack_code(enum_name: str):
    return fields(ack_code=ksy_enum("osdk_payload", enum_name, 16))


@dataclass(frozen=True)
class PayloadType:
    """One value type of osdk_payload.ksy: its dispatch and a generator for its body."""

    name: str
    cmd_set: int | None  # None: any set/id whose key has no type (unknown_value)
    cmd_id: int | None
    is_ack: bool
    body: Callable[[Source, int], dict]  # (source, profile) -> body
    profile: int | None = None  # fixed for the broadcast, else drawn


def _broadcast_body(profile: int):
    make = broadcast_message(profile)
    return lambda s, p: {"data": make(s)}


def _body(make):
    return lambda s, p: make(s)


PAYLOAD_TYPES = [
    PayloadType("version_query", 0x00, 0x00, False, _body(fields(arbitrary=u(8)))),
    PayloadType("activation_request", 0x00, 0x01, False, _body(fields(
        app_id=u(32), api_level=u(32), sdk_version=u(32), bundle_id=raw(32)))),
    PayloadType("frequency_request", 0x00, 0x10, False, _body(
        lambda s, code=ksy_enum("osdk_payload", "frequency_code", 8): {"codes": [code(s) for _ in range(16)]})),
    PayloadType("control_request", 0x01, 0x00, False, _body(fields(
        request=ksy_enum("osdk_payload", "control_request_code", 8)))),
    PayloadType("movement_control", 0x01, 0x03, False, _body(MOVEMENT_CONTROL)),
    *(PayloadType(f"broadcast_{PROFILE_IDS[p]}", 0x02, 0x00, False, _broadcast_body(p), profile=p)
      for p in PROFILES),
    PayloadType("lost_control", 0x02, 0x01, False, _body(fields(reason=u(8)))),
    *(PayloadType(f"version_ack_{PROFILE_IDS[p]}", 0x00, 0x00, True, _body(fields(
        ack_code=ksy_enum("osdk_payload", "version_ack", 16), version_crc=u(32),
        **({} if PROFILE_IDS[p] == "m100-fw2.3" else {"version_id": raw(11)}),   # E30
        version_name=raw(32))), profile=p) for p in PROFILES),
    PayloadType("activation_ack", 0x00, 0x01, True, _body(ack_code("activation_result"))),
    PayloadType("frequency_ack", 0x00, 0x10, True, _body(ack_code("frequency_ack"))),
    PayloadType("control_ack", 0x01, 0x00, True, _body(ack_code("control_ack"))),
    PayloadType("lost_control_ack", 0x02, 0x01, True, _body(fields(ack_code=u(16)))),
    PayloadType("unknown_command", None, None, False, _body(lambda s: {"raw": s.binary(64)})),
    PayloadType("unknown_ack", None, None, True, _body(lambda s: {"raw": s.binary(64)})),
]
COMMAND_TYPES = [t for t in PAYLOAD_TYPES if not t.is_ack]
ACK_TYPES = [t for t in PAYLOAD_TYPES if t.is_ack]


def _typed_keys() -> set[int]:
    """Dispatch keys with a type, read from osdk_payload.ksy's switch."""
    body = next(f for f in KSY.files["osdk_payload"]["seq"] if f["id"] == "body")
    return {k for k in body["type"]["cases"] if isinstance(k, int)}


TYPED_KEYS = _typed_keys()


def _profile(s: Source) -> int:
    return s.choice(sorted(PROFILES))


def _payload_args(ptype: PayloadType, s: Source, profile: int | None = None) -> tuple[int, int, bool, int]:
    """(cmd_set, cmd_id, is_ack, profile) for a value of this type."""
    if profile is None:
        profile = ptype.profile if ptype.profile is not None else _profile(s)
    if ptype.cmd_set is not None:
        return ptype.cmd_set, ptype.cmd_id, ptype.is_ack, profile
    ack = 0x10000 if ptype.is_ack else 0
    cmd_set, cmd_id = s.uint(8), s.uint(8)
    while ack + cmd_set * 0x100 + cmd_id in TYPED_KEYS:  # step to the next key with no type
        cmd_id = (cmd_id + 1) & 0xFF
        cmd_set = (cmd_set + (cmd_id == 0)) & 0xFF
    return cmd_set, cmd_id, ptype.is_ack, profile


def payload_message(ptype: PayloadType, s: Source, profile: int | None = None):
    """((cmd_set, cmd_id, is_ack, profile), value bytes built by Construct)."""
    args = _payload_args(ptype, s, profile)
    body = ptype.body(s, args[3])
    return args, osdk_construct.osdk_payload(*args).build({"body": body})


# --- frames -----------------------------------------------------------------------------

def command_frame(s: Source):
    ptype = s.choice(COMMAND_TYPES)
    (cmd_set, cmd_id, _, profile), value = payload_message(ptype, s)
    raw = osdk_construct.build_frame(cmd_set=cmd_set, cmd_id=cmd_id, value=value, session=s.uint(5),
                                     seq=s.uint(16))
    return (profile,), raw


def ack_frame(s: Source):
    profile = _profile(s)
    fits = [t for t in ACK_TYPES if t.profile in (None, profile)]   # a version ACK's layout is the profile's (E30)
    value = payload_message(s.choice(fits), s, profile)[1] if s.flag() else b""
    value = value or s.binary(48, min_size=1)
    raw = osdk_construct.build_frame(is_ack=True, value=value, session=s.between(1, 31), seq=s.uint(16))
    return (profile,), raw


def header_only_frame(s: Source):
    is_ack = s.flag()  # an ACK is never in session 0 (ERRATA E24)
    raw = osdk_construct.build_frame(is_ack=is_ack, session=s.between(int(is_ack), 31), seq=s.uint(16))
    return (_profile(s),), raw


def encrypted_frame(s: Source):
    # AES DATA is whole 16-byte blocks (ERRATA E23); an ACK is never in session 0 (E24).
    is_ack = s.flag()
    raw = osdk_construct.build_frame(enc=1, padding=s.between(1, 16), value=s.bytes(16 * s.between(1, 6)),
                                     is_ack=is_ack, session=s.between(int(is_ack), 31), seq=s.uint(16))
    return (_profile(s),), raw


# --- damaged bytes -----------------------------------------------------------------------------

def damage(s: Source, raw: bytes) -> bytes:
    """A valid message with one to three random edits."""
    data = bytearray(raw)
    for _ in range(s.between(1, 3)):
        edit = s.choice(("flip", "overwrite", "insert", "delete", "truncate", "extend"))
        pos = s.below(len(data)) if data else 0
        if edit == "flip" and data:
            data[pos] ^= 1 << s.uint(3)
        elif edit == "overwrite" and data:
            data[pos] = s.uint(8)
        elif edit == "insert":
            data[pos:pos] = s.binary(4, min_size=1)
        elif edit == "delete" and data:
            del data[pos:pos + s.between(1, 4)]
        elif edit == "truncate":
            del data[pos:]
        elif edit == "extend":
            data += s.binary(8, min_size=1)
    return bytes(data)


# --- message types --------------------------------------------------------------------------

def _stream(raw: bytes) -> KaitaiStream:
    return KaitaiStream(BytesIO(raw))


@dataclass(frozen=True)
class MessageType:
    name: str
    valid: Callable[[Source], tuple]        # source -> (args, bytes built by Construct)
    random_args: Callable[[Source], tuple]  # source -> args for arbitrary bytes
    construct: Callable                     # *args -> Construct
    kaitai: Callable                        # (*args, KaitaiStream) -> KaitaiStruct
    random_prefix: bytes = b""              # start of arbitrary inputs, half of the time

    @property
    def large(self) -> bool:
        """Needs LARGE_BLOB: broadcasts, and command frames (which may carry one)."""
        return "broadcast" in self.name or self.name == "frame_command"


def _no_args(s: Source) -> tuple:
    return ()


def _message_types() -> list[MessageType]:
    out = [
        MessageType("control_mode", lambda s: ((), c_control_mode.build(CONTROL_MODE(s))), _no_args,
                    lambda: c_control_mode, lambda io: OsdkControlMode(io)),
        MessageType("movement_control", lambda s: ((), c_movement_control.build(MOVEMENT_CONTROL(s))), _no_args,
                    lambda: c_movement_control, lambda io: OsdkMovementControl(io)),
    ]
    for p, kclass in ((0, OsdkBroadcastM100Fw23), (1, OsdkBroadcastM100Fw31), (2, OsdkBroadcastA3Fw31)):
        con, make = osdk_construct.broadcast_for_profile(p), broadcast_message(p)
        out.append(MessageType(f"broadcast_{PROFILE_IDS[p]}", lambda s, con=con, make=make: ((), con.build(make(s))),
                               _no_args, lambda con=con: con, lambda io, kclass=kclass: kclass(io)))
    for ptype in PAYLOAD_TYPES:
        out.append(MessageType(
            f"payload_{ptype.name}", lambda s, t=ptype: payload_message(t, s),
            lambda s, t=ptype: _payload_args(t, s), osdk_construct.osdk_payload,
            lambda cmd_set, cmd_id, is_ack, profile, io: OsdkPayload(cmd_set, cmd_id, is_ack, profile, io)))
    for name, make in (("command", command_frame), ("ack", ack_frame), ("header_only", header_only_frame),
                       ("encrypted", encrypted_frame)):
        out.append(MessageType(
            f"frame_{name}", make, lambda s: (_profile(s),), osdk_construct.osdk_frame,
            lambda profile, io: OsdkFrame(profile, io), random_prefix=b"\xaa"))
    return out


MESSAGE_TYPES = _message_types()

def _cases(large: bool):
    return [
        pytest.param(m, id=m.name)
        for m in MESSAGE_TYPES if m.large == large
    ]


def _parse_both(mtype: MessageType, args: tuple, raw: bytes):
    """(construct result or exception, kaitai result or exception)."""
    try:
        c = mtype.construct(*args).parse(raw)
    except construct.ConstructError as exc:
        c = exc
    try:
        k = mtype.kaitai(*args, _stream(raw))
    except KaitaiStructError as exc:
        k = exc
    return c, k


def check_valid_message(mtype: MessageType, args: tuple, raw: bytes) -> None:
    """(a) A message Construct built reads the same in both, and builds back."""
    c, k = _parse_both(mtype, args, raw)
    assert not isinstance(c, Exception), f"Construct rejects what it built: {c}"
    assert not isinstance(k, Exception), f"Kaitai rejects a valid message: {k}"
    assert_same_model(model.from_construct(c), kaitai_model(k))
    assert mtype.construct(*args).build(c) == raw


def check_arbitrary_bytes(mtype: MessageType, args: tuple, raw: bytes) -> None:
    """(b) Both accept or both reject; when both accept, they read the same."""
    c, k = _parse_both(mtype, args, raw)
    c_ok, k_ok = not isinstance(c, Exception), not isinstance(k, Exception)
    assert c_ok == k_ok, (f"construct {'accepts' if c_ok else f'rejects ({c})'}, "
                          f"kaitai {'accepts' if k_ok else f'rejects ({k})'}")
    if c_ok:
        assert_same_model(model.from_construct(c), kaitai_model(k))
        # What was read builds back to the bytes it was read from.
        assert raw.startswith(mtype.construct(*args).build(c))


def check_message_type(mtype: MessageType, blob: bytes) -> None:
    """One example: (a) on a random valid message, then (b) on bytes made from
    it (three times in four: the message with random edits) or arbitrary
    bytes (once in four; for frames, half of them start with 0xAA)."""
    s = Source(blob)
    args, raw = mtype.valid(s)
    note(f"valid message: args={args} bytes={raw.hex()}")
    check_valid_message(mtype, args, raw)

    if s.below(4):
        fuzz_args, fuzz = args, damage(s, raw)
    else:
        fuzz_args = mtype.random_args(s)
        fuzz = (mtype.random_prefix if s.flag() else b"") + s.binary(64)
    note(f"arbitrary input: args={fuzz_args} bytes={fuzz.hex()}")
    check_arbitrary_bytes(mtype, fuzz_args, fuzz)


@pytest.mark.slow
@pytest.mark.parametrize("mtype", _cases(large=False))
@given(blob=st.binary(min_size=SMALL_BLOB, max_size=SMALL_BLOB))
def test_construct_and_kaitai_agree(mtype: MessageType, blob: bytes):
    check_message_type(mtype, blob)


@pytest.mark.slow
@pytest.mark.parametrize("mtype", _cases(large=True))
@given(blob=st.binary(min_size=LARGE_BLOB, max_size=LARGE_BLOB))
def test_construct_and_kaitai_agree_large(mtype: MessageType, blob: bytes):
    check_message_type(mtype, blob)


# --- the float helper accepts exactly the one difference -----------------------------------

def _reference_is_snan(width: int, bits: int) -> bool:
    """Independent of the helper: via Python floats and the quiet bit."""
    value = float(F32(bits)) if width == 32 else float(F64(bits))
    quiet = 1 << (22 if width == 32 else 51)
    # float32 -> double already quiets, so look at the bits, not the double, for the quiet bit
    return math.isnan(value) and not bits & quiet


@pytest.mark.parametrize("width, snan, quieted", [
    (32, 0x7F800001, 0x7FC00001),
    (32, 0xFFBFFFFF, 0xFFFFFFFF),
    (32, 0x7FA12345, 0x7FE12345),
    (64, 0x7FF0000000000001, 0x7FF8000000000001),
    (64, 0xFFF7FFFFFFFFFFFF, 0xFFFFFFFFFFFFFFFF),
])
def test_float_helper_accepts_quieted_snan(width, snan, quieted):
    assert same_float_modulo_kaitai_snan_quieting(width, snan, quieted)
    assert same_float_modulo_kaitai_snan_quieting(width, snan, snan)


@pytest.mark.parametrize("width, construct_bits, kaitai_bits, why", [
    (32, 0x7FC00001, 0x7FC00000, "two quiet NaNs with different payloads"),
    (32, 0x7FC00001, 0x7F800001, "kaitai signalling where construct is quiet (reverse direction)"),
    (32, 0x7F800001, 0x7FC00000, "quieted but payload lost"),
    (32, 0x7F800001, 0xFFC00001, "quieted and sign flipped"),
    (32, 0x7F800000, 0x7FC00000, "+inf read as NaN"),
    (32, 0x3F800000, 0x3FC00000, "quiet bit set on a finite number"),
    (32, 0x00000000, 0x80000000, "+0.0 vs -0.0"),
    (32, 0x00000001, 0x00000000, "denormal flushed to zero"),
    (32, 0x7F800001, 0x7F800001 | (1 << 21), "wrong bit set (bit 21)"),
    (64, 0x7FF0000000000001, 0x7FF0000000400001, "f32 quiet bit (22) set on an f64"),
    (64, 0x7FF8000000000001, 0x7FF8000000000000, "two quiet f64 NaNs"),
    (64, 0x7FF0000000000000, 0x7FF8000000000000, "f64 +inf read as NaN"),
    (64, 0x3FF0000000000000, 0x3FF8000000000000, "quiet bit set on 1.0"),
])
def test_float_helper_rejects_other_differences(width, construct_bits, kaitai_bits, why):
    assert not same_float_modulo_kaitai_snan_quieting(width, construct_bits, kaitai_bits), why


@given(width=st.sampled_from((32, 64)), a=st.integers(0, 2**64 - 1), how=st.integers(0, 7),
       other=st.integers(0, 2**64 - 1))
def test_float_helper_accepts_exactly_equal_or_quieted_snan(width, a, how, other):
    mantissa, exp_all_ones, sign, quiet = _ieee_layout(width)
    a &= (1 << width) - 1
    if how & 1:  # exponent all ones: NaNs and infinities, where the tolerance applies
        a |= exp_all_ones
    b = (
        other & ((1 << width) - 1),     # anything
        a ^ (1 << (other % width)),     # every single-bit difference
        a,                              # no difference
        a | quiet,                      # the quiet bit set
    )[how >> 1]
    expected = a == b or (_reference_is_snan(width, a) and b == a | quiet)
    assert same_float_modulo_kaitai_snan_quieting(width, a, b) == expected


def test_float_helper_refuses_other_widths():
    with pytest.raises(ValueError):
        same_float_modulo_kaitai_snan_quieting(16, 0x7C01, 0x7E01)


def test_kaitai_runtime_quiets_f32_snan():
    """The difference tolerated above really happens (else the allowance is stale)."""
    k = OsdkMovementControl(_stream(b"\x00" + struct.pack("<I", 0x7F800001) + bytes(12)))
    assert model.from_kaitai(k)["x"]["f32"] == "0x7fc00001"
    c = c_movement_control.parse(b"\x00" + struct.pack("<I", 0x7F800001) + bytes(12))
    assert model.from_construct(c)["x"]["f32"] == "0x7f800001"


def test_model_comparison_rejects_a_changed_field():
    raw = osdk_construct.encode_movement_control(0x4B, 1.0, -2.0, 0.5, 30.0)
    c = model.from_construct(c_movement_control.parse(raw))
    k = kaitai_model(OsdkMovementControl(_stream(raw)))
    assert_same_model(c, k)
    k["control_mode"]["stable_mode"] = model.enum_model(0, "non_stable")
    with pytest.raises(AssertionError):
        assert_same_model(c, k)


# --- unnamed enum values ------------------------------------------------------------------

def test_model_from_kaitai_writes_unnamed_enum_values_with_null_name():
    m = model.from_kaitai(OsdkControlMode(_stream(b"\xff")))
    assert m["horizontal_logic"] == {"value": 3, "name": None}
