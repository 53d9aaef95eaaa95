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
(via osdk_conformance.core.ksy), not from osdk_construct, so the two sides do not
share a table that could be wrong in the same way.
"""
from __future__ import annotations

import importlib
import math
import re
import struct
from collections.abc import Callable
from dataclasses import dataclass
from io import BytesIO

import construct
import pytest
from hypothesis import given, note
from hypothesis import strategies as st
from kaitaistruct import KaitaiStream, KaitaiStructError

from osdk_conformance import _construct as osdk_construct
from osdk_conformance.core import ksy, model
from osdk_conformance.core.rules import profile as rules_profile, profile_names
from osdk_conformance._construct.control import control_mode as c_control_mode
from osdk_conformance._construct.control import movement_control as c_movement_control
from osdk_conformance._construct.floats import F32, F64
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


def fields(**makers: Callable[[Source], object]) -> Callable[[Source], dict]:
    """A struct generator: one generator per field, called in order."""
    return lambda s: {name: make(s) for name, make in makers.items()}


def u(bits: int):
    return lambda s: s.uint(bits)


def raw(size: int):
    return lambda s: s.bytes(size)


# --- generators read from the .ksy types --------------------------------------------
#
# A struct's generator is built from its type's seq, so adding a broadcast item
# or a field to spec/osdk_broadcast_items.ksy needs no change here. Each kind of
# field draws the values that try a decoder hardest: floats as raw IEEE patterns
# and specials (Source.f32/f64), integers over their whole width, an enum field
# a name or any integer its width holds, b1 a flag, other bit fields (reserved
# ones included) a plain uint.

_INT_TYPE = re.compile(r"([us])([1248])")
_BIT_TYPE = re.compile(r"b([1-9]\d*)")
# Keys of a seq entry the generators understand; any other (repeat, contents,
# valid, process, ...) would need a generator that honours it, so it is refused
# rather than drawn wrongly.
_FIELD_KEYS = frozenset({"id", "type", "enum", "if", "size", "doc", "doc-ref"})


def ksy_enum(file_id: str, name: str, bits: int) -> Callable[[Source], object]:
    """`name` is an enum of `file_id`, or `other_file::enum`."""
    owner, _, ename = name.rpartition("::")
    names = tuple(sorted(KSY.enums[(owner or file_id, ename)].values()))
    return lambda s: s.enum(names, bits)


def value_generator(file_id: str, ref: str, enum: str | None = None) -> Callable[[Source], object]:
    """Generator for a value of the ksy type `ref` as a seq entry writes it: a
    primitive, bN, or `[file::]type[(args)]` with literal arguments, resolved in `file_id`."""
    if m := _BIT_TYPE.fullmatch(ref):
        signed, bits = False, int(m[1])
    elif m := _INT_TYPE.fullmatch(ref):
        signed, bits = m[1] == "s", 8 * int(m[2])
    else:
        signed, bits = False, None
    if enum is not None:
        if bits is None or signed:
            raise ksy.KsyError(f"{file_id}: enum {enum} on {ref}: only unsigned integer enums are drawn")
        return ksy_enum(file_id, enum, bits)
    if ref == "f4":
        return Source.f32
    if ref == "f8":
        return Source.f64
    if ref == "b1":
        return Source.flag
    if bits is not None:
        return (lambda s: s.sint(bits)) if signed else u(bits)
    target, name, args = ksy.parse_type_ref(ref, file_id)
    return type_generator(target, name, tuple(args))


def _type_body(file_id: str, name: str) -> tuple[str, dict]:
    """(file id, ksy body) of a type of `file_id`, or of an imported file's top-level type."""
    local = KSY.files[file_id].get("types") or {}
    if name in local:
        return file_id, local[name]
    if name in KSY.files:
        return name, KSY.files[name]
    raise ksy.KsyError(f"{file_id}: unknown type {name}")


def type_generator(file_id: str, name: str, args: tuple = ()) -> Callable[[Source], dict]:
    """Generator for a user type with `args` bound to its params: its seq fields
    in order. A field whose `if` (a param, or an instance `param ==/!= enum::x`)
    is false is left out, as both parsers leave it out."""
    owner, body = _type_body(file_id, name)
    declared = [p["id"] for p in body.get("params") or []]
    if len(args) != len(declared):
        raise ksy.KsyError(f"{owner}::{name} takes params {declared}, got {len(args)} arguments")
    env = dict(zip(declared, args))
    # the same reading of such instances as the ksy index's sizes (rules' item sizes)
    env.update(ksy.instance_flags(body, env))
    makers = {}
    for f in body.get("seq") or []:
        where = f"{owner}::{name}.{f['id']}"
        if unknown := sorted(set(f) - _FIELD_KEYS):
            raise ksy.KsyError(f"{where}: no value generator for {unknown}")
        cond = f.get("if")
        if cond is not None:
            if not isinstance(env.get(cond), bool):
                raise ksy.KsyError(f"{where}: condition {cond!r} is not a param or instance known here")
            if not env[cond]:
                continue
        if "size" in f:
            if "type" in f or not isinstance(f["size"], int):
                raise ksy.KsyError(f"{where}: only raw bytes of a fixed size are drawn")
            makers[f["id"]] = raw(f["size"])
        else:
            makers[f["id"]] = value_generator(owner, f["type"], f.get("enum"))
    return fields(**makers)


CONTROL_MODE = type_generator("osdk_control_mode", "osdk_control_mode")
MOVEMENT_CONTROL = type_generator("osdk_movement_control", "osdk_movement_control")

PROFILE_IDS = {rules_profile(name).value: name for name in profile_names()}
PROFILES = {value: "osdk_broadcast_" + re.sub(r"[-.]", "_", name) for value, name in PROFILE_IDS.items()}


def _profile_items(profile: int) -> list[tuple[str, Callable]]:
    """(item, generator) in flag-bit order, read from the profile's .ksy seq."""
    file_id = PROFILES[profile]
    seq = KSY.files[file_id]["seq"]
    flags = [f["id"].removeprefix("has_") for f in seq if f["id"].startswith("has_")]
    by_id = {f["id"]: f for f in seq}
    return [(name, value_generator(file_id, by_id[name]["type"], by_id[name].get("enum"))) for name in flags]


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
    # its layout is the profile's (E30): the type's param is the profile's enum literal
    *(PayloadType(f"version_ack_{PROFILE_IDS[p]}", 0x00, 0x00, True, _body(type_generator(
        "osdk_payload", "version_ack_value", (f"profile::{KSY.enums[('osdk_payload', 'profile')][p]}",))),
        profile=p) for p in PROFILES),
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
    for p, file_id in PROFILES.items():
        # found by name, so that a new profile needs no import here
        kclass = getattr(importlib.import_module(f"osdk_kaitai.{file_id}"), ksy.camel(file_id))
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
