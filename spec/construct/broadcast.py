"""The flight data broadcast payload in each wire profile.

Mirrors spec/osdk_broadcast_<profile>.ksy: a u2 flag word read as bit
fields from bit 0 (`has_<item>` flags, then `reserved_flags`, which must be
0), then each present item in flag-bit order, then nothing: a payload with
bytes after its last item, or fewer bytes than its flags promise, is
rejected.

Which item sits at which bit, and which variant of an item a profile sends,
is defined once, in spec/rules.yaml (`profiles`: flag_bits, item_params and
value; `broadcast_items`: each item's ksy type), read here through
osdk_conformance.core.rules, which tools/gen_profile_ksy.py also writes the
profile .ksy files from. An item's layout is the construct of broadcast_items.py
named as its ksy type, called with the profile's params by their ksy names, or
a bare byte for `u1`; those layouts are this package's own transcription.
"""
from __future__ import annotations

from construct import BitsInteger, Const, Construct, Flag, Int8ul, Terminated

from osdk_conformance.core.rules import Profile, default_rules

from . import broadcast_items as items
from .bitfields import lsb_first, record
from .combinators import when
from .enums import profile_value

FLAG_BITS = 16
_BARE = {"u1": Int8ul}
_RULES = default_rules()


def _profile(bit_order):
    """The payload construct of a profile whose items, in flag-bit order, are `bit_order`."""
    flags = [f"has_{name}" / Flag for name, _ in bit_order]
    spare = FLAG_BITS - len(bit_order)
    if spare:
        # one spare bit is a b1 in the ksy, which Kaitai reads as a boolean
        flags.append("reserved_flags" / (Const(False, Flag) if spare == 1 else Const(0, BitsInteger(spare))))
    present = [name / when(lambda this, key=f"has_{name}": this[key], sub) for name, sub in bit_order]
    return record(lsb_first(*flags), *present, Terminated)


def item_construct(profile: Profile, item: str) -> Construct:
    """The construct of one item as `profile` sends it."""
    spec = _RULES.broadcast_item(item)
    if spec.type in _BARE:
        return _BARE[spec.type]
    layout = getattr(items, spec.type, None)
    if layout is None:
        raise LookupError(f"spec/construct/broadcast_items.py has no {spec.type!r} "
                          f"(the type of rules.yaml broadcast_items.{item})")
    return layout(**profile.item_params[item]) if spec.params else layout


def bit_order(profile: Profile) -> tuple[tuple[str, Construct], ...]:
    """(item, construct) of a profile in flag-bit order."""
    return tuple((item, item_construct(profile, item)) for item in profile.flag_bits)


_PROFILES = {p.value: p for p in map(_RULES.profile, _RULES.profile_names)}

NAMES = {value: p.ksy_name for value, p in _PROFILES.items()}
"""ksy name (osdk_broadcast_<name>) by profile value."""

ITEMS = {value: bit_order(p) for value, p in _PROFILES.items()}
"""(item name, item construct) in flag-bit order, by profile value."""

_BY_PROFILE = {value: _profile(order) for value, order in ITEMS.items()}

# One module attribute per profile, named as its ksy (m100_fw2_3 is
# osdk_broadcast_m100_fw2_3): the profiles are listed in rules.yaml only.
globals().update({NAMES[value]: con for value, con in _BY_PROFILE.items()})

__all__ = ["ITEMS", "NAMES", "bit_order", "item_construct", "for_profile", *NAMES.values()]


def for_profile(profile):
    """The broadcast payload construct of a profile (value, ksy name or profile id)."""
    return _BY_PROFILE[profile_value(profile)]
