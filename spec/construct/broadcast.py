"""The flight data broadcast payload in each of the three wire profiles.

Mirrors spec/osdk_broadcast_<profile>.ksy: a u2 flag word read as bit
fields from bit 0 (`has_<item>` flags, then `reserved_flags`, which must be
0), then each present item in flag-bit order, then nothing: a payload with
bytes after its last item, or fewer bytes than its flags promise, is
rejected. The profiles differ in which item sits at which bit and in the
variants of time_stamp, gimbal and control_info (PROTOCOL-FACTS §3), so
each profile is generated from its list of (item, construct) in bit order.
"""
from __future__ import annotations

from construct import BitsInteger, Const, Flag, Int8ul, Terminated

from . import broadcast_items as items
from .bitfields import lsb_first, record
from .combinators import when
from .enums import profile_value

__all__ = ["ITEMS", "m100_fw2_3", "m100_fw3_1", "a3_fw3_1", "for_profile"]


def _profile(bit_order):
    """The payload construct of a profile whose items, in flag-bit order, are `bit_order`."""
    flags = [f"has_{name}" / Flag for name, _ in bit_order]
    reserved = "reserved_flags" / Const(0, BitsInteger(16 - len(bit_order)))
    present = [name / when(lambda this, key=f"has_{name}": this[key], sub) for name, sub in bit_order]
    return record(lsb_first(*flags, reserved), *present, Terminated)


def _bit_order(fw3_1: bool, a3: bool):
    """Items in flag-bit order. The profiles differ in two ways only: FW 3.1
    uses the long forms of time stamp, gimbal and control info, and the A3
    family inserts GPS and RTK detail at bits 6 and 7 (PROTOCOL-FACTS §3)."""
    return (
        ("time_stamp", items.time_stamp(fw3_1)),
        ("quaternion", items.quaternion),
        ("acceleration", items.vector3f),
        ("velocity", items.velocity),
        ("angular_rate", items.vector3f),
        ("position", items.position),
        *((("gps_detail", items.gps_detail), ("rtk_detail", items.rtk_detail)) if a3 else ()),
        ("magnetometer", items.magnetometer),
        ("rc", items.rc),
        ("gimbal", items.gimbal(fw3_1)),
        ("flight_status", Int8ul),
        ("battery", Int8ul),
        ("control_info", items.control_info(fw3_1)),
    )


_FW2_3 = _bit_order(fw3_1=False, a3=False)
_FW3_1 = _bit_order(fw3_1=True, a3=False)
_A3_FW3_1 = _bit_order(fw3_1=True, a3=True)

ITEMS = {0: _FW2_3, 1: _FW3_1, 2: _A3_FW3_1}
"""(item name, item construct) in flag-bit order, by profile value."""

m100_fw2_3 = _profile(_FW2_3)
"""osdk_broadcast_m100_fw2_3."""

m100_fw3_1 = _profile(_FW3_1)
"""osdk_broadcast_m100_fw3_1."""

a3_fw3_1 = _profile(_A3_FW3_1)
"""osdk_broadcast_a3_fw3_1."""

_BY_PROFILE = {0: m100_fw2_3, 1: m100_fw3_1, 2: a3_fw3_1}


def for_profile(profile):
    """The broadcast payload construct of a profile (value, ksy name or profile id)."""
    return _BY_PROFILE[profile_value(profile)]
