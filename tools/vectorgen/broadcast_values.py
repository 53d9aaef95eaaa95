"""Broadcast payloads with random or chosen item values, packed from the
one layout definition.

Which items a profile has, at which flag bit, and the fields of each item
(with the profile's variant: the 4- or 9-byte time stamp, the gimbal with
or without its limit byte, ...) come from the Construct spec
(osdk_construct.broadcast.ITEMS: rules.yaml's profiles and broadcast_items
laid out by the item constructs; the spec the reference decodes with);
nothing here lists items or variants. The bytes are packed here field by
field from that field list, not by Construct's builder: a run of bit
fields is drawn as one integer, and every random draw happens in wire
order, so that the vectors stay a pure function of the seed.
"""
from __future__ import annotations

import functools
import random
from dataclasses import dataclass
from typing import Any

import construct
from osdk_conformance._construct.bitfields import BitGroup
from osdk_conformance._construct.broadcast import ITEMS
from osdk_conformance._construct.floats import F32le, F64le

from osdk_conformance.core.rules import profile as rules_profile

from .builder import PROFILES, GenerationError
from .scalars import f32, f64, le16

PAYLOAD_ARGS = {"cmd_set": 0x02, "cmd_id": 0x00, "is_ack": False}


@dataclass(frozen=True)
class Field:
    """One byte-aligned field of an item. A run of bit fields is one field
    (`bits`) whose value is the whole run as an integer; embedded in a
    record it has no name of its own and takes its first bit field's."""

    name: str
    size: int
    kind: str                      # unsigned, signed, float, bits or enum
    choices: tuple[int, ...] = ()  # an enum's named values, ascending


def _fields(c: construct.Construct, name: str = "") -> list[Field]:
    """The fields `c` lays out, in wire order, with `when` conditions resolved."""
    if c is F32le or c is F64le:
        return [Field(name, c.sizeof(), "float")]
    if isinstance(c, BitGroup):
        return [Field(name if name and not name.startswith("_") else c.names[0], c.sizeof(), "bits")]
    if isinstance(c, construct.Enum):
        return [Field(name, c.sizeof(), "enum", tuple(sorted(c.decmapping)))]
    if isinstance(c, construct.FormatField) and c.fmtstr[-1] in "bBhHiIlLqQ":
        # only integers: a struct float field would not keep a NaN's bits, and the spec has none
        return [Field(name, c.sizeof(), "signed" if c.fmtstr[-1].islower() else "unsigned")]
    if isinstance(c, construct.Struct):
        return [f for sub in c.subcons for f in _fields(sub, sub.name or "")]
    if isinstance(c, construct.IfThenElse):
        if not isinstance(c.condfunc, bool):
            raise GenerationError(f"field {name}: its condition depends on other fields; an item's may not")
        return _fields(c.thensubcon if c.condfunc else c.elsesubcon, name)
    if c is construct.Pass:
        return []
    if isinstance(c, construct.Renamed):
        return _fields(c.subcon, c.name)
    if isinstance(c, construct.Subconstruct):  # adapters that keep the layout of what they wrap
        return _fields(c.subcon, name)
    raise GenerationError(f"field {name}: no packing for {c!r}")


@functools.cache
def profile_items(profile: str) -> tuple[tuple[str, tuple[Field, ...]], ...]:
    """(item, its fields) of a profile, in flag-bit order."""
    # an item that is one plain field (flight status, battery) is named after the item
    return tuple((item, tuple(_fields(c, item))) for item, c in ITEMS[rules_profile(profile).value])


def item_fields(profile: str, item: str) -> tuple[Field, ...]:
    for name, fields in profile_items(profile):
        if name == item:
            return fields
    raise GenerationError(f"profile {profile} has no item {item}")


def has_field(profile: str, item: str, field: str) -> bool:
    """Whether the profile's variant of `item` carries `field`."""
    return any(f.name == field for f in item_fields(profile, item))


def other_form(profile: str, item: str) -> tuple[Field, ...] | None:
    """The fields of `item` in the first profile that lays it out otherwise
    (the other firmware's variant, sent to this profile by the cases that
    pin the difference), or None when every profile agrees."""
    mine = item_fields(profile, item)
    for other in PROFILES:
        theirs = dict(profile_items(other)).get(item)
        if theirs is not None and theirs != mine:
            return theirs
    return None


def float_items(profile: str) -> list[str]:
    """The items of a profile with a float field, in flag-bit order."""
    return [item for item, fields in profile_items(profile) if any(f.kind == "float" for f in fields)]


class Values:
    """Random item values, compact in JSON: floats are multiples of 1/8
    (exact in float32, short to print), integers span their whole type."""

    def __init__(self, rng: random.Random, specials: list[tuple[int, int]] | None = None) -> None:
        self.rng = rng
        self.specials = specials  # when given: (f32 bits, f64 bits) used in turn for every float
        self.turn = 0

    def _special(self, width: int) -> int:
        pair = self.specials[self.turn % len(self.specials)]
        self.turn += 1
        return pair[0] if width == 32 else pair[1]

    def f4(self) -> int:
        if self.specials:
            return self._special(32)
        return f32(self.rng.randint(-80000, 80000) / 8)

    def f8(self) -> int:
        if self.specials:
            return self._special(64)
        return f64(self.rng.randint(-3_000_000, 3_000_000) / 1_048_576)

    def u(self, bits: int) -> int:
        return self.rng.getrandbits(bits)

    def s(self, bits: int) -> int:
        return self.rng.getrandbits(bits) - (1 << (bits - 1))

    def of(self, field: Field) -> int:
        """A value for `field` (a float by its bits; an enum one of its named values)."""
        if field.kind == "float":
            return self.f4() if field.size == 4 else self.f8()
        if field.kind == "signed":
            return self.s(8 * field.size)
        if field.kind == "enum":
            return self.rng.choice(field.choices)
        return self.u(8 * field.size)


def field_bytes(field: Field, value: int) -> bytes:
    return value.to_bytes(field.size, "little", signed=field.kind == "signed")


def pack(fields: tuple[Field, ...], values: dict[str, int]) -> bytes:
    """The fields with the given values by name (floats by their bits);
    values for fields the variant does not have are ignored."""
    missing = [f.name for f in fields if f.name not in values]
    if missing:
        raise GenerationError(f"no value for field(s) {', '.join(missing)}")
    return b"".join(field_bytes(f, values[f.name]) for f in fields)


def describe(fields: tuple[Field, ...], values: dict[str, Any]) -> str:
    """The values of the fields a variant has, as "name value, ... (N bytes)"."""
    return f"{', '.join(f'{f.name} {values[f.name]}' for f in fields)} ({sum(f.size for f in fields)} bytes)"


def random_item(fields: tuple[Field, ...], v: Values) -> bytes:
    """An item with a random value in every field, drawn in wire order."""
    return b"".join(field_bytes(f, v.of(f)) for f in fields)


def payload(profile: str, flags: int, v: Values) -> bytes:
    """Flag word and the flagged items in bit order, values from `v`."""
    out = le16(flags)
    for bit, (_, fields) in enumerate(profile_items(profile)):
        if flags >> bit & 1:
            out += random_item(fields, v)
    return out


def broadcast_flags_model(profile: str, present: set[str]) -> dict:
    """The flag-word part of a broadcast model, from the profile's bit order."""
    bits = rules_profile(profile).flag_bits
    out: dict[str, Any] = {f"has_{item}": item in present for item in bits}
    if len(bits) < 16:  # one spare bit is a b1, a boolean; sixteen items leave none
        out["reserved_flags"] = False if len(bits) == 15 else 0
    return out


def bc_input(data: bytes) -> dict:
    """A decode_payload input: `data` as the broadcast value."""
    return {"hex": data.hex(), **PAYLOAD_ARGS}
