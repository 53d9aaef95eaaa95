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

import construct
from construct import Adapter, BitStruct, ByteSwapped, Construct, Container, Struct, Subconstruct
from construct.lib import bytes2bits, swapbytes

from .compiled import SelfCompiling, emit, link, value_code

__all__ = ["lsb_first", "record", "BitGroup"]


class BitGroup(SelfCompiling, Subconstruct):
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

    def _emitparse(self, code):
        # The interpreter swaps the bytes, expands them to one byte per bit
        # and reads the fields from the top; the compiled code reads the
        # little-endian integer and shifts, from the fields as they are now.
        nbytes, fields, checks = self._layout()
        fname = f"parse_bitgroup_{code.allocateId()}"
        lines = [
            f"def {fname}(io, this):",
            f"    data = io.read({nbytes})",
            f"    if len(data) != {nbytes}:",
            "        raise StreamError",
            "    v = int.from_bytes(data, 'little')",
            "    group = Container()",
        ]
        lsb = 0
        for name, kind, width, sub in fields:
            raw = f"(v >> {lsb} & {(1 << width) - 1})"
            if kind == "flag":
                lines.append(f"    group[{name!r}] = {raw} == 1")
            elif kind == "int":
                lines.append(f"    group[{name!r}] = {raw}")
            elif kind == "enum":
                lines.append(f"    group[{name!r}] = {link(code, sub)}._decode({raw}, None, None)")
            else:  # const
                lines += [f"    if {raw} != {sub.value!r}:", "        raise ConstError",
                          f"    group[{name!r}] = {raw}"]
            lsb += width
        if checks:
            lines += ["    inner = Container(_ = this, _params = this['_params'], _root = None, _parsing = True, "
                      "_building = False, _sizing = False, _subcons = None, _io = io, _index = this.get('_index', None))",
                      "    inner['_root'] = this.get('_root', inner)",
                      "    dict.update(inner, group)",
                      "    this_ = this",
                      "    this = inner"]
            for func in checks:
                lines += [f"    if not ({value_code(code, func)}):", "        raise CheckError"]
            lines.append("    this = this_")
        if [f[0] for f in fields] != list(self.names):  # the interpreter lists them in the ksy order
            lines.append(f"    group = Container((n, group[n]) for n in {self.names!r})")
        lines += ["    dict.update(this, group)", "    return group"]
        code.append("\n".join(lines))
        return f"{fname}(io, this)"

    def _flat_bits(self) -> tuple[str, tuple[str, ...], list[tuple[str, str, int, Construct]]] | None:
        """(struct format of the group's little-endian integer, names in ksy
        order, fields from bit 0 up) for compiled.py to read the group within
        a merged read; None when the group has checks (they need the context)
        or is not 1, 2, 4 or 8 bytes."""
        try:
            nbytes, fields, checks = self._layout()
        except NotImplementedError:
            return None
        fmt = {1: "B", 2: "H", 4: "I", 8: "Q"}.get(nbytes)
        if checks or fmt is None:
            return None
        return fmt, self.names, fields

    def _layout(self) -> tuple[int, list[tuple[str, str, int, Construct]], list]:
        """(bytes, [(name, kind, width, construct)] from bit 0 up, [check functions]) of
        the group as it is now; NotImplementedError (the compiler then keeps
        the interpreter) for anything but plain, flag, enum and constant bit fields."""
        swap = self.subcon
        bits = getattr(swap, "subcon", None)
        inner = getattr(bits, "subcon", None)
        if not (isinstance(swap, construct.Transformed) and swap.decodefunc is swapbytes
                and isinstance(bits, construct.Transformed) and bits.decodefunc is bytes2bits
                and isinstance(inner, Struct)):
            raise NotImplementedError
        fields, checks = [], []
        for sc in reversed(inner.subcons):
            if not isinstance(sc, construct.Renamed):
                raise NotImplementedError
            c = sc.subcon
            if isinstance(c, construct.Check):
                checks.insert(0, c.func)
                continue
            if c is construct.Flag:
                fields.append((sc.name, "flag", 1, c))
                continue
            kind = {construct.Enum: "enum", construct.Const: "const"}.get(type(c), "int")
            number = c.subcon if kind != "int" else c
            if not (type(number) is construct.BitsInteger and isinstance(number.length, int)
                    and not number.signed and not number.swapped):
                raise NotImplementedError
            if kind == "const" and not isinstance(c.value, int):
                raise NotImplementedError
            fields.append((sc.name, kind, number.length, c))
        if sum(f[2] for f in fields) != 8 * swap.decodeamount or sorted(f[0] for f in fields) != sorted(self.names):
            raise NotImplementedError
        return swap.decodeamount, fields, checks


def lsb_first(*fields: Construct, checks: tuple[Construct, ...] = ()) -> BitGroup:
    """Bit fields (Flag, BitsInteger(n), Enum(BitsInteger(n)), Const(.., BitsInteger(n)))
    in ksy order, least significant first; their widths must add up to whole bytes."""
    return BitGroup(*fields, checks=checks)


class _Record(SelfCompiling, Adapter):
    """Presents the fields of embedded bit groups as fields of the record."""

    def __init__(self, subcon: Struct, groups: dict[str, BitGroup]) -> None:
        super().__init__(subcon)
        self.groups = groups

    def _emitparse(self, code):
        # The Struct and _decode in one function: the fields go straight
        # into the record (what _decode gives), and into the context as the
        # Struct puts them there.
        if not isinstance(self.subcon, Struct):
            raise NotImplementedError
        fname = f"parse_record_{code.allocateId()}"
        lines = [
            f"def {fname}(io, this):",
            "    result = Container()",
            "    this = Container(_ = this, _params = this['_params'], _root = None, _parsing = True, _building = False, "
            "_sizing = False, _subcons = None, _io = io, _index = this.get('_index', None))",
            "    this['_root'] = this['_'].get('_root', this)",
            "    try:",
        ]
        for sc in self.subcon.subcons:
            value, name = emit(sc, code), sc.name
            if name in self.groups:
                lines += [f"        this[{name!r}] = group = {value}",
                          "        dict.update(result, group)"]
            elif name and not name.startswith("_"):
                lines.append(f"        result[{name!r}] = this[{name!r}] = {value}")
            elif name:
                lines.append(f"        this[{name!r}] = {value}")
            else:
                lines.append(f"        {value}")
        lines += ["    except StopFieldError:", "        pass", "    return result"]
        code.append("\n".join(lines))
        return f"{fname}(io, this)"

    def _flat_struct(self) -> tuple[Struct, dict[str, BitGroup]]:
        """The Struct and the names of its embedded groups, for compiled.py
        to read a record of fixed-size fields in one go."""
        return self.subcon, self.groups

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
