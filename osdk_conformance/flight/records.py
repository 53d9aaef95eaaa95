"""Typed records over the columns: one broadcast as Python values.

`Broadcast` is a row of a FlightData: attribute access reads the columns
at that row when it is asked (nothing is made for what is not read), in
real Python types:

- a float field is a float (NaN a float NaN), its exact IEEE bits one call
  away: `b.quaternion.bits("q0")`;
- an enum field is a member of an IntEnum made from the spec's enum
  (`ControlDevice.onboard_device`); a value the spec does not name stays an
  int, as the value model gives it without a name;
- a single bit is a bool, any other integer an int;
- an item the frame did not carry is None: `b.battery is None`;
- an item of several fields is an `Item` with one attribute per field, and
  `as_dict()`.

Each record also has `time` (the capture time, seconds since the Unix
epoch, None for raw bytes), `time_ns`, `fc_time` (the FC's time stamp in
seconds, None without one), `offset`, and the helpers people analysing a
flight want: `attitude` (roll, pitch, yaw in degrees from the quaternion),
`position_deg` (latitude, longitude in degrees: the position item sends
radians), `speed` (the magnitude of the velocity item, m/s).
"""
from __future__ import annotations

import enum
import functools
import math
from typing import Any, Iterator, NamedTuple

from osdk_conformance._construct import enums as spec_enums
from osdk_conformance.flight.columns import NO_TIME, FC_TICKS_PER_S, FC_TIME_COLUMN, Column, FlightData


class Attitude(NamedTuple):
    roll: float    # degrees
    pitch: float
    yaw: float


class LatLon(NamedTuple):
    latitude: float    # degrees
    longitude: float


def attitude_of(q0: float, q1: float, q2: float, q3: float) -> Attitude:
    """Roll, pitch and yaw in degrees (Z-Y-X Tait-Bryan angles) of the
    attitude quaternion the broadcast sends (ground frame to body frame)."""
    roll = math.atan2(2 * (q0 * q1 + q2 * q3), 1 - 2 * (q1 * q1 + q2 * q2))
    # asin's argument leaves [-1, 1] by rounding alone at ±90° pitch: clamp it
    pitch = math.asin(max(-1.0, min(1.0, 2 * (q0 * q2 - q3 * q1))))
    yaw = math.atan2(2 * (q0 * q3 + q1 * q2), 1 - 2 * (q2 * q2 + q3 * q3))
    return Attitude(math.degrees(roll), math.degrees(pitch), math.degrees(yaw))


@functools.lru_cache(maxsize=None)
def int_enum(key: str) -> type[enum.IntEnum] | None:
    """The IntEnum of a spec enum ("osdk_broadcast_items.control_device" ->
    ControlDevice), from the spec's names (spec/construct/enums.py)."""
    mapping = getattr(spec_enums, key.rsplit(".", 1)[-1].upper(), None)
    if not isinstance(mapping, dict):
        return None
    name = "".join(part.capitalize() for part in key.rsplit(".", 1)[-1].split("_"))
    return enum.IntEnum(name, mapping)  # type: ignore[return-value]


def _converter(c: Column):
    if c.kind == "bool":
        return bool
    if c.kind in ("f32", "f64"):
        return float
    members = int_enum(c.enum) if c.enum else None
    if members is None:
        return int

    def named(value: int) -> int:
        try:
            return members(value)
        except ValueError:
            return value
    return named


class _Leaf(NamedTuple):
    column: Column
    values: Any      # numpy array in the column's type
    valid: Any       # numpy bool array
    convert: Any     # numpy scalar's Python value -> the typed value
    raw: Any         # the stored array (a float's bits)


class _Shape:
    """Per FlightData: for each item, its one column or its tree of fields."""

    def __init__(self, data: FlightData) -> None:
        self.tree: dict[str, Any] = {}
        for c in data.columns:
            node = self.tree
            parts = c.name.split(".")
            for part in parts[:-1]:
                node = node.setdefault(part, {})
            node[parts[-1]] = _Leaf(c, data.values(c.name), data.valid(c.name), _converter(c), data.raw(c.name))


def _value(leaf: _Leaf, row: int) -> Any:
    if not leaf.valid[row]:
        return None
    return leaf.convert(leaf.values[row].item())


class Item:
    """One item of one broadcast: its fields as attributes."""

    __slots__ = ("_node", "_row", "_name")

    def __init__(self, node: dict, row: int, name: str) -> None:
        self._node, self._row, self._name = node, row, name

    def __getattr__(self, field: str) -> Any:
        try:
            leaf = self._node[field]
        except KeyError:
            raise AttributeError(f"{self._name} has no field {field!r} (its fields: "
                                 f"{', '.join(self._node)})") from None
        if isinstance(leaf, dict):
            return Item(leaf, self._row, f"{self._name}.{field}") if _present(leaf, self._row) else None
        return _value(leaf, self._row)

    def bits(self, field: str) -> int:
        """A float field's IEEE bits, exactly as received."""
        leaf = self._node.get(field)
        if not isinstance(leaf, _Leaf) or leaf.column.kind not in ("f32", "f64"):
            raise AttributeError(f"{self._name}.{field} is not a float field")
        return int(leaf.raw[self._row])

    def as_dict(self) -> dict[str, Any]:
        return {k: (getattr(self, k).as_dict() if isinstance(self._node[k], dict) and getattr(self, k) is not None
                    else getattr(self, k)) for k in self._node}

    def __dir__(self) -> list[str]:
        return list(self._node)

    def __repr__(self) -> str:
        return f"{self._name}({', '.join(f'{k}={v!r}' for k, v in self.as_dict().items())})"


def _present(node: dict, row: int) -> bool:
    # a sub-structure is there when any of its leaves is (an optional part of it may be absent)
    for leaf in node.values():
        if isinstance(leaf, dict):
            if _present(leaf, row):
                return True
        elif leaf.valid[row]:
            return True
    return False


class Broadcast:
    """One broadcast frame of a capture (see the module's text)."""

    __slots__ = ("_data", "_shape", "_row")

    def __init__(self, data: FlightData, shape: _Shape, row: int) -> None:
        self._data, self._shape, self._row = data, shape, row

    def __getattr__(self, item: str) -> Any:
        try:
            node = self._shape.tree[item]
        except KeyError:
            raise AttributeError(f"the {self._data.profile} broadcast has no item {item!r} (its items: "
                                 f"{', '.join(self._data.items)})") from None
        if isinstance(node, dict):
            return Item(node, self._row, item) if _present(node, self._row) else None
        return _value(node, self._row)

    @property
    def offset(self) -> int:
        return int(self._data.offset[self._row])

    @property
    def time_ns(self) -> int | None:
        t = int(self._data.time_ns[self._row])
        return None if t == NO_TIME else t

    @property
    def time(self) -> float | None:
        t = self.time_ns
        return None if t is None else t / 1e9

    @property
    def fc_time(self) -> float | None:
        leaf = self._shape.tree.get(FC_TIME_COLUMN.split(".")[0], {}).get(FC_TIME_COLUMN.split(".")[1])
        ticks = _value(leaf, self._row) if leaf is not None else None
        return None if ticks is None else ticks / FC_TICKS_PER_S

    @property
    def attitude(self) -> Attitude | None:
        q = self.quaternion if "quaternion" in self._shape.tree else None
        return None if q is None else attitude_of(q.q0, q.q1, q.q2, q.q3)

    @property
    def position_deg(self) -> LatLon | None:
        p = self.position if "position" in self._shape.tree else None
        return None if p is None else LatLon(math.degrees(p.latitude), math.degrees(p.longitude))

    @property
    def speed(self) -> float | None:
        v = self.velocity if "velocity" in self._shape.tree else None
        return None if v is None else math.sqrt(v.x * v.x + v.y * v.y + v.z * v.z)

    def as_dict(self) -> dict[str, Any]:
        out: dict[str, Any] = {"offset": self.offset, "time": self.time, "fc_time": self.fc_time}
        for item in self._data.items:
            value = getattr(self, item)
            out[item] = value.as_dict() if isinstance(value, Item) else value
        return out

    def __dir__(self) -> list[str]:
        return [*self._data.items, "offset", "time", "time_ns", "fc_time", "attitude", "position_deg", "speed",
                "as_dict"]

    def __repr__(self) -> str:
        return f"Broadcast(offset={self.offset}, time={self.time}, items={[i for i in self._data.items if getattr(self, i) is not None]})"


def records(data: FlightData) -> Iterator[Broadcast]:
    """The rows of `data` as Broadcast records, in capture order."""
    shape = _Shape(data)
    for row in range(data.rows):
        yield Broadcast(data, shape, row)
