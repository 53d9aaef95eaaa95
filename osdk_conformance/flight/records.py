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
from osdk_conformance.sim.simulator import quaternion_to_euler


class Attitude(NamedTuple):
    roll: float    # degrees
    pitch: float
    yaw: float


class LatLon(NamedTuple):
    latitude: float    # degrees
    longitude: float


def attitude_of(q0: float, q1: float, q2: float, q3: float) -> Attitude:
    """Roll, pitch and yaw in degrees (Z-Y-X Tait-Bryan angles) of the
    attitude quaternion the broadcast sends (ground frame to body frame), as
    the simulator and the acceptance report turn it into angles."""
    return Attitude(*(math.degrees(a) for a in quaternion_to_euler(q0, q1, q2, q3)))


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


class _Leaf:
    """One column as records read it: made into a list of Python values the
    first time any record reads it (a column read at all is read for every
    row, and indexing a list is many times cheaper than a numpy scalar)."""

    __slots__ = ("column", "_data", "_values", "_valid")

    def __init__(self, column: Column, data: FlightData) -> None:
        self.column, self._data = column, data
        self._values: list | None = None
        self._valid: list | None = None

    def value(self, row: int) -> Any:
        if self._values is None:
            self._load()
        return self._values[row] if self._valid[row] else None  # type: ignore[index]

    def bits(self, row: int) -> int:
        return int(self._data.raw(self.column.name)[row])

    def _load(self) -> None:
        values = self._data.values(self.column.name).tolist()
        convert = _converter(self.column)
        if convert not in (bool, float, int):
            values = [convert(v) for v in values]
        self._valid = self._data.valid(self.column.name).tolist()
        self._values = values


class _Node:
    """A structure of the layout: its fields (leaves or structures), and where
    it is present (any of its leaves is: an optional part of it may be absent)."""

    __slots__ = ("name", "fields", "_data", "_present")

    def __init__(self, name: str, data: FlightData) -> None:
        self.name, self._data = name, data
        self.fields: dict[str, _Leaf | _Node] = {}
        self._present: list | None = None

    def present(self) -> list:
        if self._present is None:
            self._present = self._data.present(self.name).tolist()
        return self._present


class _Shape:
    """Per FlightData: the tree of items and fields over its columns, and a
    record class for it whose items and fields are properties (an attribute
    found on the class costs a fraction of a __getattr__ fallback)."""

    def __init__(self, data: FlightData) -> None:
        self.root = _Node(data.profile, data)
        for c in data.columns:
            node = self.root
            parts = c.name.split(".")
            for i, part in enumerate(parts[:-1]):
                nxt = node.fields.get(part)
                if nxt is None:
                    nxt = node.fields[part] = _Node(".".join(parts[:i + 1]), data)
                node = nxt  # type: ignore[assignment]
            node.fields[parts[-1]] = _Leaf(c, data)
        stamp = self.root.fields.get(FC_TIME_COLUMN.split(".")[0])
        self.fc_ticks = stamp.fields.get(FC_TIME_COLUMN.split(".")[1]) if isinstance(stamp, _Node) else None
        self.record_class = _typed(Broadcast, "Broadcast", self.root)


def _getter(field: _Leaf | _Node) -> property:
    if isinstance(field, _Leaf):
        return property(lambda self: field.value(self._row))
    cls = _typed(Item, field.name.replace(".", "_"), field)
    return property(lambda self: cls(field, self._row) if field.present()[self._row] else None)


def _typed(base: type, name: str, node: _Node) -> type:
    return type(name, (base,), {"__slots__": (), **{k: _getter(f) for k, f in node.fields.items()}})


class Item:
    """One item (or sub-structure) of one broadcast: its fields as attributes."""

    __slots__ = ("_node", "_row")

    def __init__(self, node: _Node, row: int) -> None:
        self._node, self._row = node, row

    def __getattr__(self, field: str) -> Any:
        # only for names the item's class has no property of
        raise AttributeError(f"{self._node.name} has no field {field!r} (its fields: {', '.join(self._node.fields)})")

    def bits(self, field: str) -> int:
        """A float field's IEEE bits, exactly as received."""
        leaf = self._node.fields.get(field)
        if not isinstance(leaf, _Leaf) or leaf.column.kind not in ("f32", "f64"):
            raise AttributeError(f"{self._node.name}.{field} is not a float field")
        return leaf.bits(self._row)

    def as_dict(self) -> dict[str, Any]:
        out = {}
        for k in self._node.fields:
            v = getattr(self, k)
            out[k] = v.as_dict() if isinstance(v, Item) else v
        return out

    def __dir__(self) -> list[str]:
        return list(self._node.fields)

    def __repr__(self) -> str:
        return f"{self._node.name}({', '.join(f'{k}={v!r}' for k, v in self.as_dict().items())})"


class Broadcast:
    """One broadcast frame of a capture (see the module's text)."""

    __slots__ = ("_data", "_shape", "_row")

    def __init__(self, data: FlightData, shape: _Shape, row: int) -> None:
        self._data, self._shape, self._row = data, shape, row

    def __getattr__(self, item: str) -> Any:
        # only for names the record class has no property of: every item and field is one
        raise AttributeError(f"the {self._data.profile} broadcast has no item {item!r} (its items: "
                             f"{', '.join(self._data.items)})")

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
        leaf = self._shape.fc_ticks
        ticks = leaf.value(self._row) if isinstance(leaf, _Leaf) else None
        return None if ticks is None else ticks / FC_TICKS_PER_S

    @property
    def attitude(self) -> Attitude | None:
        q = self.quaternion if "quaternion" in self._shape.root.fields else None
        return None if q is None else attitude_of(q.q0, q.q1, q.q2, q.q3)

    @property
    def position_deg(self) -> LatLon | None:
        p = self.position if "position" in self._shape.root.fields else None
        return None if p is None else LatLon(math.degrees(p.latitude), math.degrees(p.longitude))

    @property
    def speed(self) -> float | None:
        v = self.velocity if "velocity" in self._shape.root.fields else None
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
    make = shape.record_class
    for row in range(data.rows):
        yield make(data, shape, row)
