"""Broadcast item values in the shape a profile's Construct layout gives them.

The simulator and the benchmark corpus model physical values once, in the
fullest form an item has in any profile. This module cuts such a value to
the variant a profile sends (the FW 2.3 time stamp has no nano_time and no
sync_flag, its gimbal no limit byte, its control info no movement control
mode), fills in what nobody models with its rest value (numbers zero, flags
false, an enum at its zero, a constant at its value) and lists the fields
of an item. All of it comes from walking the Construct layout
(osdk_construct.broadcast.ITEMS), so an item or variant added to the spec
needs nothing here, and nothing in the simulator or the corpus either.

A field behind a ksy `if:` (`when`) is there when its condition holds,
evaluated the way Construct evaluates it while building: against the fields
before it in the same record. For `fields()` those are the rest values.

`profile` is anything osdk_construct.broadcast.for_profile takes: the
profile id (`a3-fw3.1`), its ksy name or its value.
"""
from __future__ import annotations

import functools
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import construct
from construct import Container, evaluate

from osdk_conformance._construct import bitfields
from osdk_conformance._construct.broadcast import ITEMS, for_profile
from osdk_conformance._construct.combinators import Call
from osdk_conformance._construct.enums import profile_value
from osdk_conformance._construct.floats import F32le

__all__ = ["Leaf", "items", "layout", "fields", "rest", "fit", "cut", "broadcast_data"]

# The time_stamp item's `time` counts ticks of 1/400 s (spec/osdk_broadcast_items.ksy).
FC_TICKS_PER_S = 400

_ABSENT = object()   # a field whose condition is false: left out of the value
_UNSET = object()    # no value given: the rest value is used


@dataclass(frozen=True)
class Leaf:
    """One field that holds a value (not a record of fields)."""

    kind: str             # int, float, flag, enum, const or bytes
    format: str | None    # struct format of a field of whole bytes; None for bit fields
    rest: Any             # the value at rest, as the layout decodes it


# Fields and leaves of a construct, by its identity: the simulator shapes
# every frame. Bounded, because a Call may make a new construct each time.
@functools.lru_cache(maxsize=4096)
def _leaf(con: construct.Construct) -> Leaf:
    if isinstance(con, type(construct.Flag)):   # construct.Flag is the one instance of its class
        return Leaf("flag", None, False)
    if isinstance(con, type(F32le)):
        fmt = con.subcon.fmtstr[0] + {32: "f", 64: "d"}[con.cls.ieee_width]
        return Leaf("float", fmt, con.cls(0))
    if isinstance(con, construct.FormatField):
        is_float = con.fmtstr[-1] in "efd"
        return Leaf("float" if is_float else "int", con.fmtstr, 0.0 if is_float else 0)
    if isinstance(con, (construct.BitsInteger, construct.BytesInteger)):
        return Leaf("int", None, 0)
    if isinstance(con, construct.Enum):
        # The parsed form of the zero (a name that is also the number), so a rest value decodes back equal.
        return Leaf("enum", _format(con.subcon), con.decmapping.get(0, 0))
    if isinstance(con, construct.Const):
        return Leaf("const", _format(con.subcon), con.value)
    if isinstance(con, construct.Bytes) and isinstance(con.length, int):
        return Leaf("bytes", f"{con.length}s", bytes(con.length))
    raise TypeError(f"values: no rest value known for a {type(con).__name__} field")


def _format(con: construct.Construct) -> str | None:
    return con.fmtstr if isinstance(con, construct.FormatField) else None


def _bit_group_fields(group: bitfields.BitGroup) -> list[tuple[str, construct.Construct]]:
    """The fields of a bit group in ksy order (the BitStruct inside holds them reversed)."""
    inner = group.subcon
    while not isinstance(inner, construct.Struct):
        inner = inner.subcon
    by_name = {sc.name: sc.subcon for sc in inner.subcons if isinstance(sc, construct.Renamed)}
    return [(name, by_name[name]) for name in group.names]


@functools.lru_cache(maxsize=4096)
def _members(con: construct.Construct) -> tuple[tuple[str, construct.Construct], ...] | None:
    """The value-carrying fields of a record, embedded bit groups flattened into it; None for a leaf."""
    if isinstance(con, bitfields.BitGroup):
        return _bit_group_fields(con)
    groups: Mapping[str, bitfields.BitGroup] = {}
    if isinstance(con, bitfields._Record):
        con, groups = con.subcon, con.groups
    if not isinstance(con, construct.Struct):
        return None
    out = []
    for sc in con.subcons:
        if sc.name in groups:
            out += _bit_group_fields(groups[sc.name])
        elif sc.name and not sc.name.startswith("_"):
            out.append((sc.name, sc.subcon))
        # an unnamed field (Terminated, Padding, Check) takes no value when built
    return tuple(out)


def _walk(con: construct.Construct, value: Any, context: Container, path: tuple[str, ...],
          leaves: dict[tuple[str, ...], Leaf] | None) -> Any:
    """`value` cut and completed to what `con` builds; _ABSENT when a false condition leaves it out."""
    while True:
        if isinstance(con, construct.Renamed):
            con = con.subcon
        elif isinstance(con, construct.IfThenElse):
            con = con.thensubcon if evaluate(con.condfunc, context) else con.elsesubcon
            if isinstance(con, type(construct.Pass)):
                return _ABSENT
        elif isinstance(con, Call):
            con = con._resolve(context)
        elif isinstance(con, construct.FixedSized):   # ExactSize too: the size does not change the value
            con = con.subcon
        else:
            break
    members = _members(con)
    if members is None:
        leaf = _leaf(con)
        if leaves is not None:
            leaves[path] = leaf
        return leaf.rest if value is _UNSET else value
    if value is _UNSET:
        value = {}
    elif not isinstance(value, Mapping):
        raise TypeError(f"values: {'.'.join(path) or 'the value'} is a record of fields, got {value!r}")
    out: dict[str, Any] = {}
    local = Container(_=context)
    for name, sub in members:
        v = _walk(sub, value.get(name, _UNSET), local, (*path, name), leaves)
        if v is not _ABSENT:
            out[name] = local[name] = v
    return out


def cut(con: construct.Construct, value: Any = _UNSET) -> Any:
    """`value` shaped for any construct `con`: fields `con` lacks dropped, fields
    `value` lacks at rest; without `value`, the rest value of `con`."""
    return _walk(con, value, Container(), (), None)


# ---- broadcast items ---------------------------------------------------------------


def layout(profile) -> tuple[tuple[str, construct.Construct], ...]:
    """(item, construct) of the profile in flag-bit order."""
    return ITEMS[profile_value(profile)]


def items(profile) -> tuple[str, ...]:
    """The profile's broadcast items in flag-bit order."""
    return tuple(name for name, _ in layout(profile))


def _item(profile, item: str) -> construct.Construct:
    for name, con in layout(profile):
        if name == item:
            return con
    raise ValueError(f"profile {profile!r} has no broadcast item {item!r}")


@functools.cache
def _fields(value: int, item: str) -> Mapping[str, Leaf]:
    leaves: dict[tuple[str, ...], Leaf] = {}
    _walk(_item(value, item), _UNSET, Container(), (), leaves)
    return {".".join(path): leaf for path, leaf in leaves.items()}


def fields(profile, item: str) -> Mapping[str, Leaf]:
    """Dotted path within the item (`limit.pitch_limit`; "" for an item that is
    one number) -> Leaf, in wire order, of the profile's variant of the item."""
    return dict(_fields(profile_value(profile), item))


def _paths(con: construct.Construct, context: Container, path: tuple[str, ...], out: set[str]) -> None:
    """Every dotted path under `con`, records included, whichever way its conditions go."""
    while isinstance(con, (construct.Renamed, construct.FixedSized)):
        con = con.subcon
    if isinstance(con, construct.IfThenElse):
        for branch in (con.thensubcon, con.elsesubcon):
            _paths(branch, context, path, out)
        return
    if isinstance(con, Call):
        try:
            con = con._resolve(context)
        except Exception:   # arguments the rest values cannot give: the field is known, its inside is not
            out.add(".".join(path))
            return
    if isinstance(con, type(construct.Pass)):
        return
    out.add(".".join(path))
    members = _members(con)
    if members is None:
        return
    local = Container(_=context)   # the rest values, for a Call's arguments
    for name, sub in members:
        _paths(sub, local, (*path, name), out)
        rest = _walk(sub, _UNSET, local, (), None)
        if rest is not _ABSENT:
            local[name] = rest


@functools.cache
def _known_paths(item: str) -> frozenset[str]:
    """Every dotted path, records included, the item has in any profile's layout."""
    out: set[str] = set()
    for value in ITEMS:
        for name, con in ITEMS[value]:
            if name == item:
                _paths(con, Container(), (), out)
    return frozenset(out)


def _check_known(item: str, value: Any, prefix: str = "") -> None:
    """A field no profile's variant of the item has is a slip of the caller's, not another variant's field."""
    if not isinstance(value, Mapping):
        return
    known = _known_paths(item)
    for key, sub in value.items():
        path = f"{prefix}{key}"
        if path not in known:
            raise ValueError(f"values: no profile's {item} has a field {path!r}")
        _check_known(item, sub, f"{path}.")


def rest(profile, item: str) -> Any:
    """The item at rest in the profile's variant: every number zero, flags false, enums at their zero."""
    return cut(_item(profile, item))


def fit(profile, item: str, value: Any) -> Any:
    """`value` (the item in any profile's form) cut to the fields of the
    profile's variant of the item; fields it does not give are at rest."""
    _check_known(item, value)
    return cut(_item(profile, item), value)


def broadcast_data(profile, present, model: Mapping[str, Any]) -> dict:
    """The `data` of a broadcast payload carrying the items `present`: its
    flags, and each item fitted from `model` (item -> value) or at rest when
    `model` has none."""
    order = items(profile)
    unknown = sorted(set(present) - set(order))
    if unknown:
        raise ValueError(f"profile {profile!r} has no broadcast item {', '.join(unknown)}")
    given: dict[str, Any] = {f"has_{it}": True for it in present}   # the flag names of spec/construct/broadcast.py
    for it in present:
        if it in model:
            _check_known(it, model[it])
            given[it] = model[it]
    data = cut(for_profile(profile), given)
    if [it for it in order if it in data] != [it for it in order if it in present]:
        raise RuntimeError(f"values: the flags of profile {profile!r} are not named has_<item>")
    return data
