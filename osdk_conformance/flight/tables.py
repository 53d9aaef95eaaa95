"""FlightData as Apache Arrow tables, and the files `osdkc decode --format` writes.

`to_arrow(data, items)` is one row per broadcast frame: `offset`, `time`
(the capture time, timestamp[ns, UTC]; only when the input carried times),
`fc_time` (the FC's time stamp in seconds, float64, null without one),
then one column per field of the chosen items, named by its dotted path,
null where the frame did not carry the item. The arrays are the native
decoder's buffers, wrapped without a copy; floats keep every bit. A
field with an enum keeps the integer the wire carried (the value model's
`value`) and names its values in the field's metadata (`enum`).

`item_table(data, item)` is one item alone, one row per frame that carried
it, with that item's own `time` and `fc_time`: the shape for an item sent
at a rate of its own (pyulog's datasets, a MAVLink message type).

Writers: CSV (pyarrow's: floats in their shortest decimal form that reads
back to the same float, empty cells for nulls) and Parquet (the Arrow types
as they are). `osdkc decode`'s JSON lines stay the value model's events.
"""
from __future__ import annotations

import json
from typing import IO, Iterable

import numpy as np
import pyarrow as pa
import pyarrow.csv as pa_csv
import pyarrow.parquet as pa_parquet

from osdk_conformance.flight.columns import NO_TIME, Column, FlightData
from osdk_conformance.flight.records import int_enum


ARROW_TYPES = {"bool": pa.bool_(), "u8": pa.uint8(), "u16": pa.uint16(), "u32": pa.uint32(), "u64": pa.uint64(),
               "i8": pa.int8(), "i16": pa.int16(), "i32": pa.int32(), "i64": pa.int64(),
               "f32": pa.float32(), "f64": pa.float64()}


def _bitmap(mask: np.ndarray) -> pa.Buffer | None:
    if mask.all():
        return None
    return pa.py_buffer(np.packbits(mask, bitorder="little"))


def _array(values: np.ndarray, kind: str, mask: np.ndarray) -> pa.Array:
    n = len(values)
    nulls = int(n - np.count_nonzero(mask))
    if kind == "bool":
        data = pa.py_buffer(np.packbits(values.view(np.uint8) != 0, bitorder="little"))
    else:
        data = pa.py_buffer(values)
    return pa.Array.from_buffers(ARROW_TYPES[kind], n, [_bitmap(mask), data], null_count=nulls)


def _field(c: Column) -> pa.Field:
    meta = {"item": c.item}
    members = int_enum(c.enum) if c.enum else None
    if members is not None:
        meta["enum"] = json.dumps({str(m.value): m.name for m in members})
    return pa.field(c.name, ARROW_TYPES[c.kind], nullable=True, metadata=meta)


def _time_fields(data: FlightData, rows: np.ndarray | None) -> tuple[list[pa.Field], list[pa.Array]]:
    take = (lambda a: a) if rows is None else (lambda a: a[rows])
    fields, arrays = [pa.field("offset", pa.uint64(), nullable=False)], [pa.array(take(data.offset))]
    if data.has_capture_time:
        ns = take(data.time_ns)
        fields.append(pa.field("time", pa.timestamp("ns", tz="UTC"), metadata={
            "doc": "capture time of the pcapng record that completed the frame"}))
        arrays.append(pa.Array.from_buffers(pa.timestamp("ns", tz="UTC"), len(ns),
                                            [_bitmap(ns != NO_TIME), pa.py_buffer(np.ascontiguousarray(ns))]))
    fc = take(data.fc_time)
    fields.append(pa.field("fc_time", pa.float64(), metadata={
        "doc": "the flight controller's time stamp (time_stamp.time, ticks of 1/400 s) in seconds"}))
    arrays.append(pa.array(fc, mask=np.isnan(fc)))
    return fields, arrays


def to_arrow(data: FlightData, items: Iterable[str] | None = None) -> pa.Table:
    columns = data.columns_of(items)
    fields, arrays = _time_fields(data, None)
    for c in columns:
        fields.append(_field(c))
        arrays.append(_array(data.values(c.name), c.kind, data.valid(c.name)))
    meta = {"profile": data.profile, "source": data.source,
            "counts": json.dumps(data.counts, sort_keys=True)}
    return pa.Table.from_arrays(arrays, schema=pa.schema(fields, metadata=meta))


def item_table(data: FlightData, item: str) -> pa.Table:
    columns = data.columns_of([item])
    if not columns:
        data.columns_of(["?" + item])  # raises the error that names the items
    rows = np.flatnonzero(data.present(item))
    fields, arrays = _time_fields(data, rows)
    for c in columns:
        fields.append(_field(c))
        arrays.append(_array(np.ascontiguousarray(data.values(c.name)[rows]), c.kind,
                             np.ascontiguousarray(data.valid(c.name)[rows])))
    return pa.Table.from_arrays(arrays, schema=pa.schema(fields, metadata={"profile": data.profile, "item": item}))


def write(table: pa.Table, fmt: str, out: IO[bytes]) -> None:
    """`table` to `out` as csv or parquet."""
    if fmt == "csv":
        pa_csv.write_csv(table, out, pa_csv.WriteOptions(quoting_style="none"))
    elif fmt == "parquet":
        pa_parquet.write_table(table, out)
    else:
        raise ValueError(f"unknown format {fmt!r}")
