"""The broadcasts of a capture as typed columns, filled by the native decoder.

`read(source, profile)` deframes and decodes what the flight controller
sent (a pcapng capture's received records, or raw bytes) with the native
decoder (reference/_accel.c, `Columns`), which writes each broadcast frame
as one row: one column per leaf of the profile's layout (generated from the
spec: generated/cpython/osdk_columns.h), each with a presence mask, since an
item the frame did not carry has no value. Nothing is made per value in
Python; the arrays become numpy arrays without a copy.

Beside the values, per row:

- `offset`: where the frame starts in the received bytes (the offset
  `osdkc decode` reports);
- `time_ns`: the capture time, nanoseconds since the Unix epoch, of the
  pcapng record whose bytes completed the frame: when the kit's recorder
  read it from the port, so it includes the link's and the host's delays.
  Raw bytes carry no time: the column is then absent (`has_capture_time`
  is False, and tables leave it out rather than fill it with nulls);
- `fc_time`: the flight controller's own time stamp (item time_stamp,
  field `time`, counted in ticks of 1/400 s by the spec) in seconds, NaN
  where the frame carried no time stamp. It is the FC's clock, free of the
  host's scheduling, and starts wherever the FC's counter stood.

Floats are held as their IEEE bits and viewed as float32/float64, so every
bit the wire carried is there (NaN payloads, -0.0); `bits(name)` gives the
bits themselves.
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Iterable

import numpy as np

from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.rules import profile as load_profile
from osdk_conformance.reference import accel
from osdk_conformance.reference.decode import InputSeen, read_chunks, timed_pieces
from osdk_conformance.reference.values import FC_TICKS_PER_S

FC_TIME_COLUMN = "time_stamp.time"
NO_TIME = np.iinfo(np.int64).min  # a row whose bytes came without a capture time (_accel.c)

# Element types of the native columns (osdk_columns.h) as numpy types; floats
# arrive as bits and are viewed as the float of their width.
STORAGE = {"bool": np.uint8, "u8": np.uint8, "u16": np.uint16, "u32": np.uint32, "u64": np.uint64,
           "i8": np.int8, "i16": np.int16, "i32": np.int32, "i64": np.int64, "f32": np.uint32, "f64": np.uint64}
VIEW = {"bool": np.bool_, "f32": np.float32, "f64": np.float64}


@dataclass(frozen=True)
class Column:
    name: str            # the leaf's dotted path in the value model: "quaternion.q0"
    item: str            # the broadcast item it belongs to: "quaternion"
    kind: str            # bool, u8..u64, i8..i64, f32, f64
    enum: str | None     # the spec's enum ("osdk_broadcast_items.control_device"), when it has one

    @property
    def field(self) -> str:
        """The name within its item ("q0"); the item's own name for a one-value item ("battery")."""
        return self.name[len(self.item) + 1:] if self.name != self.item else self.name


class FlightData:
    """The broadcasts of one capture as columns (see the module's text)."""

    def __init__(self, profile: str, columns: tuple[Column, ...], taken: dict, source: str,
                 has_capture_time: bool, seen: InputSeen) -> None:
        self.profile = profile
        self.source = source
        self.columns = columns
        self.rows: int = taken["rows"]
        self.counts: dict[str, int] = dict(taken["counts"])
        self._raw = {c.name: np.frombuffer(taken["data"][i], dtype=STORAGE[c.kind])
                     for i, c in enumerate(columns)}
        self._valid = {c.name: np.frombuffer(taken["valid"][i], dtype=np.bool_) for i, c in enumerate(columns)}
        self.offset = np.frombuffer(taken["offset"], dtype=np.uint64)
        self.time_ns = np.frombuffer(taken["time"], dtype=np.int64)
        self.has_capture_time = has_capture_time
        self.seen = seen   # what the input held besides frames: a pcapng block cut at its end
        self._by_name = {c.name: c for c in columns}
        self.items: tuple[str, ...] = tuple(dict.fromkeys(c.item for c in columns))

    def __len__(self) -> int:
        return self.rows

    def column(self, name: str) -> Column:
        try:
            return self._by_name[name]
        except KeyError:
            raise UsageError(f"no column {name!r} in the {self.profile} broadcast "
                             f"(its items: {', '.join(self.items)})") from None

    def values(self, name: str) -> np.ndarray:
        """The column's values in their types (floats as float32/float64, bools
        as bool); where the frame did not carry the item the value is 0
        (see `valid`)."""
        c = self.column(name)
        raw = self._raw[name]
        return raw.view(VIEW[c.kind]) if c.kind in VIEW else raw

    def bits(self, name: str) -> np.ndarray:
        """A float column's IEEE bits (uint32 or uint64), exactly as received."""
        c = self.column(name)
        if c.kind not in ("f32", "f64"):
            raise UsageError(f"{name} is not a float (it is {c.kind})")
        return self._raw[name]

    def raw(self, name: str) -> np.ndarray:
        """The column as stored: a float column's bits, any other its values."""
        self.column(name)
        return self._raw[name]

    def valid(self, name: str) -> np.ndarray:
        """True where the frame carried the column's value."""
        self.column(name)
        return self._valid[name]

    def present(self, prefix: str) -> np.ndarray:
        """Where the item or sub-structure `prefix` ("gimbal", "gimbal.limit")
        is present: where any of its leaves is (an optional part may be absent)."""
        mask = np.zeros(self.rows, dtype=bool)
        for c in self.columns:
            if c.name == prefix or c.name.startswith(prefix + "."):
                mask |= self._valid[c.name]
        return mask

    def columns_of(self, items: Iterable[str] | None) -> tuple[Column, ...]:
        """The columns of the named items (or of leaves named in full), in layout order; all for None."""
        if items is None:
            return self.columns
        wanted = list(items)
        for name in wanted:
            if name not in self.items and name not in self._by_name:
                raise UsageError(f"no item {name!r} in the {self.profile} broadcast (its items: "
                                 f"{', '.join(self.items)}; a single field is named item.field, e.g. quaternion.q0)")
        return tuple(c for c in self.columns if c.item in wanted or c.name in wanted)

    @property
    def fc_time(self) -> np.ndarray:
        """The flight controller's time stamp in seconds (float64), NaN where absent."""
        if FC_TIME_COLUMN not in self._by_name:
            return np.full(self.rows, np.nan)
        seconds = self._raw[FC_TIME_COLUMN] / FC_TICKS_PER_S
        return np.where(self._valid[FC_TIME_COLUMN], seconds, np.nan)

    @property
    def time(self) -> np.ndarray:
        """The capture time in seconds since the Unix epoch (float64; NaN for raw bytes).
        `time_ns` keeps the nanoseconds exactly."""
        seconds = self.time_ns / 1e9
        return np.where(self.time_ns == NO_TIME, np.nan, seconds)


def _native():
    module = accel.native()
    if module is None or not hasattr(module, "Columns"):
        raise UsageError("flight data tables need the native decoder, which is built when the kit is installed "
                         f"where a C compiler exists; it is not available here ({accel.describe()})")
    return module


def read(source: str | os.PathLike | bytes | bytearray | memoryview, profile: str,
         name: str | None = None) -> FlightData:
    """The broadcasts in `source` (a file's path, or its bytes) as columns."""
    if isinstance(source, (bytes, bytearray, memoryview)):
        return read_chunks_of([bytes(source)], profile, name or "input")
    path = os.fspath(source)
    with open(path, "rb") as fh:
        return read_chunks_of(read_chunks(fh), profile, name or path)


def read_chunks_of(chunks: Iterable[bytes], profile: str, name: str) -> FlightData:
    filler = open_filler(profile)
    seen = InputSeen()
    timed = False
    for _, data, ts_ns in timed_pieces(chunks, frozenset({"rx"}), name, seen):
        timed = timed or ts_ns is not None
        feed(filler, data, ts_ns)
    filler.finish()
    return take(filler, profile, schema_of(filler), name, timed, seen)


def open_filler(profile: str):
    """The native decoder's columns of one received stream (reference/_accel.c, Columns)."""
    return _native().Columns(load_profile(profile).value)


def schema_of(filler) -> tuple[Column, ...]:
    return tuple(Column(n, item, kind, enum) for n, item, kind, enum in filler.schema())


def feed(filler, data: bytes, ts_ns: int | None) -> None:
    filler.feed(data, ts_ns)


def take(filler, profile: str, schema: tuple[Column, ...], name: str = "stream", timed: bool = True,
         seen: InputSeen | None = None) -> FlightData:
    """The rows filled since the last take (a live stream's batch), as FlightData."""
    return FlightData(profile, schema, filler.take(), name, timed, seen or InputSeen())
