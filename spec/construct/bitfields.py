"""Bit fields numbered from the least significant bit, as the .ksy files use.

The .ksy files say `bit-endian: le`: a run of bN fields is read from a
little-endian integer, the first field taking the lowest bits (the way GCC
lays out C bit-fields on little-endian machines, which is how the DJI SDK
declares them). Construct's BitStruct reads bits from the most significant
end of each byte. `lsb_first` bridges the two: it reverses the byte order
of the run (so its little-endian integer reads big-endian) and hands the
fields to a BitStruct in reverse order; the parsed Container then lists
them again in the ksy order.

In a ksy seq the bit fields sit between the other fields at the same level
(`len`, `ver`, ... `seq`, `crc16` are all fields of the frame). `record`
gives the same shape: a Struct in which `lsb_first` groups are embedded, so
their fields become fields of the record, visible to later fields'
conditions (`this.len`, `this.is_ack`) while parsing and building.
"""
from __future__ import annotations

from construct import Adapter, BitStruct, ByteSwapped, Construct, Container, Struct, Subconstruct

__all__ = ["lsb_first", "record", "BitGroup"]


class BitGroup(Subconstruct):
    """A byte-aligned run of bit fields, first field in the lowest bits.

    `checks` (construct Check instances) run after the whole run is read,
    and before it is written, with every field of the run in `this`."""

    def __init__(self, *fields: Construct, checks: tuple[Construct, ...] = ()) -> None:
        self.names = tuple(f.name for f in fields)
        if not all(self.names):
            raise ValueError("every field of a bit group needs a name")
        super().__init__(ByteSwapped(BitStruct(*reversed(fields), *checks)))

    def _parse(self, stream, context, path):
        raw = self.subcon._parsereport(stream, context, path)
        fields = Container((name, raw[name]) for name in self.names)
        # Embedded in a record: later fields of the record see these by name.
        context.update(fields)
        return fields

    def _build(self, obj, stream, context, path):
        self.subcon._build(obj, stream, context, path)
        return obj


def lsb_first(*fields: Construct, checks: tuple[Construct, ...] = ()) -> BitGroup:
    """Bit fields (Flag, BitsInteger(n), Enum(BitsInteger(n)), Const(.., BitsInteger(n)))
    in ksy order, least significant first; their widths must add up to whole bytes."""
    return BitGroup(*fields, checks=checks)


class _Record(Adapter):
    """Presents the fields of embedded bit groups as fields of the record."""

    def __init__(self, subcon: Struct, groups: dict[str, BitGroup]) -> None:
        super().__init__(subcon)
        self.groups = groups

    def _decode(self, obj, context, path):
        out = Container()
        for key, value in obj.items():
            if key in self.groups:
                out.update(value)
            elif not key.startswith("_"):
                out[key] = value
        return out

    def _encode(self, obj, context, path):
        nested = Container(obj)
        for key, group in self.groups.items():
            nested[key] = Container((n, obj[n]) for n in group.names if n in obj)
        return nested


def record(*fields: Construct) -> Construct:
    """A Struct of `fields` in which every unnamed `lsb_first` group is embedded."""
    groups: dict[str, BitGroup] = {}
    subcons = []
    for f in fields:
        if isinstance(f, BitGroup) and not f.name:
            key = f"_bits{len(groups)}"
            groups[key] = f
            f = key / f
        subcons.append(f)
    return _Record(Struct(*subcons), groups)
