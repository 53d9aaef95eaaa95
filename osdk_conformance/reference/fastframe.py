"""Straight from a frame's bytes to its value model, for frames whose layout
is already known.

Decoding a broadcast frame through Construct (osdk_construct.parse_frame)
and converting what it parsed (model.from_construct) makes a few hundred
Python objects per frame: containers, contexts, floats, enum values. But a
frame's layout, every offset and format of it, is decided by a few of its
bytes: the header (LEN, ACK, encryption), the command set and id, a
broadcast's flag word. `specialize` walks the Construct layout of one
frame, evaluating each condition, length and parametrised type (`when`,
ExactSize, Call) the way Construct does, with a context that records which
bytes every evaluation read (`consulted`). Given the bytes that are the same
in every frame it will be used for (`fixed`), it writes one Python function:
one struct unpack of the fields that vary, and one expression building the
model exactly as model.from_construct builds it from the Construct value;
the fields within the fixed bytes are constants in it.

The function is valid for every frame that has the same bytes at the
consulted positions: Construct takes the same path through such a frame.
The caller keys its functions by those bytes (`key_function`) and checks
that they cover what was consulted. Anything this walk does not know
exactly raises NotFast, and the caller decodes that frame as before.
"""
from __future__ import annotations

import struct
from typing import Any, Callable, Iterable, NamedTuple

import construct
from construct import Container, evaluate

from osdk_conformance.core import model
from osdk_conformance._construct import bitfields
from osdk_conformance._construct.combinators import Call

__all__ = ["NotFast", "Short", "Specialized", "specialize", "key_function"]

_INT_CODES = frozenset("bBhHiIlLqQ")
_GROUP_FORMATS = {1: "B", 2: "H", 4: "I", 8: "Q"}


class NotFast(Exception):
    """The layout takes a path this module does not specialise, or the
    frame fails a check: such frames are the interpreter's to decode."""


class Short(NotFast):
    """The frame ends before its layout does: this frame only, not its layout, is not fast."""


class _Traced(Container):
    """A parse context that notes the bytes behind every value read from it."""

    __slots__ = ("_where", "_seen")

    def __init__(self, seen: set[int], parent: "_Traced | None" = None) -> None:
        super().__init__()
        self._seen = seen
        self._where: dict[str, range] = {}
        if parent is not None:
            self["_"] = parent

    def put(self, key: str, value: Any, where: range | tuple = ()) -> None:
        self[key] = value
        self._where[key] = where

    def __getitem__(self, key: str) -> Any:
        where = self._where.get(key)
        if where:
            self._seen.update(where)
        return super().__getitem__(key)

    def get(self, key: str, default: Any = None) -> Any:
        return self[key] if key in self else default


class Specialized(NamedTuple):
    convert: Callable[[bytes], dict | None]
    """The model of a frame with the same bytes at `consulted` (None when the frame is shorter than its layout)."""
    context: _Traced
    """The walk's context of the frame's fields: reading it marks their bytes consulted too."""
    consulted: set[int]
    """Positions of the bytes the layout's conditions, lengths, parameters, checks and constants read."""


def specialize(con: Any, raw: bytes, fixed: Iterable[int] = ()) -> Specialized:
    """The converter of frames laid out as `raw` is by `con` (see the module
    doc); `fixed`: positions whose bytes are those of `raw` in every frame
    it will convert. Raises NotFast (Short when `raw` ends too soon)."""
    walk = _Walk(raw, frozenset(fixed))
    try:
        value, src, _, _ = walk.walk(con, _Traced(walk.seen), 0, len(raw))
    except NotFast:
        raise
    except Exception as e:  # noqa: BLE001 - a failed condition or check: the interpreter's error to report
        raise NotFast(f"{type(e).__name__}: {e}") from None
    if src is None or not isinstance(value, _Traced):
        raise NotFast("the frame is not a record of fields")
    return Specialized(walk.function(src), value, walk.seen)


def key_function(positions: Iterable[int]) -> Callable[[bytes], bytes]:
    """The bytes of a frame at `positions` (fewer when the frame is shorter), as one bytes object."""
    runs: list[list[int]] = []
    for p in sorted(set(positions)):
        if runs and runs[-1][1] == p:
            runs[-1][1] = p + 1
        else:
            runs.append([p, p + 1])
    if not runs:
        return lambda raw: b""
    body = " + ".join(f"raw[{a}:{b}]" for a, b in runs)
    return eval(f"lambda raw: {body}")  # noqa: S307 - slices of our own making


class _Walk:
    """One specialisation: the fields read at run time and the model source."""

    def __init__(self, raw: bytes, fixed: frozenset[int]) -> None:
        self.raw = raw
        self.fixed = fixed
        self.seen: set[int] = set()
        self.ints: list[tuple[int, str, str]] = []    # (offset, struct code, variable)
        self.floats: list[tuple[int, str, str]] = []
        self.end = 0
        self.top_limit = len(raw)
        self.env: dict[str, Any] = {"readable": model.readable_float, "from_bytes": int.from_bytes}
        self.prelude: list[str] = []  # run after the unpacking

    # -- reading ---------------------------------------------------------

    def read(self, pos: int, size: int, limit: int) -> range:
        if pos + size > limit:
            if limit == self.top_limit:
                raise Short(f"{pos + size} bytes needed, the frame has {limit}")
            raise NotFast(f"a field runs past its {limit}-byte region")
        self.end = max(self.end, pos + size)
        return range(pos, pos + size)

    def is_fixed(self, where: range) -> bool:
        return all(p in self.fixed for p in where)

    def variable(self, pos: int, code: str, floats: bool = False) -> str:
        table = self.floats if floats else self.ints
        name = f"{'f' if floats else 'v'}{len(self.ints) + len(self.floats)}"
        table.append((pos, code, name))
        return name

    def constant(self, value: Any) -> str:
        """Source of the model of a value Construct parsed; a literal makes a fresh dict at each call."""
        return repr(model.from_construct_generic(value))

    def names_of(self, enum: construct.Enum) -> str:
        name = f"N{len(self.env)}"
        self.env[name] = {int(k): str(v) for k, v in enum.decmapping.items()}
        return name

    # -- the layout ------------------------------------------------------

    def walk(self, con: Any, ctx: _Traced, pos: int, limit: int) -> tuple[Any, str | None, int, Any]:
        """(value for the context, model source or None when absent, position after, bytes of the value)."""
        while isinstance(con, construct.Renamed):
            con = con.subcon
        if isinstance(con, bitfields._Record):
            return self.record(con.subcon, con.groups, ctx, pos, limit)
        t = type(con)
        if t is construct.Struct:
            return self.record(con, {}, ctx, pos, limit)
        if isinstance(con, bitfields.BitGroup):
            values, items, end, where = self.group(con, ctx, pos, limit)
            group = _Traced(self.seen)
            for name, value in values.items():
                ctx.put(name, value, where)  # as BitGroup._parse puts them in the context
                group.put(name, value, where)
            return group, "{" + ", ".join(items) + "}", end, ()
        if isinstance(con, construct.IfThenElse):
            branch = con.thensubcon if evaluate(con.condfunc, ctx) else con.elsesubcon
            return self.walk(branch, ctx, pos, limit)
        if con is construct.Pass:
            return None, None, pos, ()
        if isinstance(con, Call):
            return self.walk(con._resolve(ctx), ctx, pos, limit)
        if isinstance(con, construct.FixedSized):  # ExactSize too: it parses as FixedSized does
            length = evaluate(con.length, ctx)
            if type(length) is not int or length < 0:
                raise NotFast("a size that is not a whole number of bytes")
            self.read(pos, length, limit)
            value, src, _, where = self.walk(con.subcon, ctx, pos, pos + length)
            return value, src, pos + length, where
        if con is construct.Terminated:
            if limit == self.top_limit or pos != limit:
                raise NotFast("bytes after the last field")
            return None, None, pos, ()
        if t is construct.Const:
            size = con.subcon.sizeof()
            where = self.read(pos, size, limit)
            value = con.subcon.parse(self.raw[pos:pos + size])
            if value != con.value:
                raise NotFast("a constant field without its value")
            self.seen.update(where)  # every frame this function takes must have it too
            return value, self.constant(value), pos + size, where
        if getattr(con, "ieee_class", None) is not None:
            return self.ieee(con, pos, limit)
        if t is construct.Enum and type(con.subcon) is construct.FormatField:
            number, end, where = self.number(con.subcon, pos, limit)
            value = con._decode(number, None, None)
            if self.is_fixed(where):
                return value, self.constant(value), end, where
            v = self.variable(pos, con.subcon.fmtstr[1:])
            return value, f"{{'value': {v}, 'name': {self.names_of(con)}.get({v})}}", end, where
        if t is construct.FormatField:
            value, end, where = self.number(con, pos, limit)
            if self.is_fixed(where):
                return value, self.constant(value), end, where
            return value, self.variable(pos, con.fmtstr[1:]), end, where
        if t is construct.Bytes and type(con.length) is int:
            where = self.read(pos, con.length, limit)
            value = self.raw[pos:pos + con.length]
            if self.is_fixed(where):
                return value, self.constant(value), pos + con.length, where
            return value, f"{self.variable(pos, f'{con.length}s')}.hex()", pos + con.length, where
        raise NotFast(f"no fast path for a {t.__name__}")

    def number(self, con: construct.FormatField, pos: int, limit: int) -> tuple[int, int, range]:
        fmt = con.fmtstr
        if len(fmt) != 2 or fmt[0] != "<" or fmt[1] not in _INT_CODES:
            raise NotFast(f"no fast path for the format {fmt!r}")
        size = struct.calcsize(fmt)
        where = self.read(pos, size, limit)
        return struct.unpack_from(fmt, self.raw, pos)[0], pos + size, where

    def ieee(self, con: Any, pos: int, limit: int) -> tuple[Any, str, int, range]:
        cls = con.ieee_class
        bits, end, where = self.number(con.subcon, pos, limit)
        value = cls(bits)
        if self.is_fixed(where):
            return value, self.constant(value), end, where
        width = cls.ieee_width
        b = self.variable(pos, con.subcon.fmtstr[1:])
        f = self.variable(pos, {32: "f", 64: "d"}[width], floats=True)
        key, digits = {32: ("f32", 8), 64: ("f64", 16)}[width]
        # as model.from_construct: the value is the number unless it is not finite
        return value, f"{{{key!r}: '0x%0{digits}x' % {b}, 'value': {f} if {f} - {f} == 0.0 else readable({f})}}", end, where

    def record(self, con: construct.Struct, groups: dict, ctx: _Traced, pos: int, limit: int) -> tuple[Any, str, int, Any]:
        """A Struct, or a record whose bit groups (`groups`, by their field names) are embedded in it."""
        local = _Traced(self.seen, ctx)
        items = []
        for sc in con.subcons:
            name = sc.name
            if name in groups:
                values, group_items, pos, where = self.group(groups[name], local, pos, limit)
                for key, value in values.items():
                    local.put(key, value, where)
                items += group_items
                continue
            value, src, pos, _where = self.walk(sc, local, pos, limit)
            if name:
                local.put(name, value, _where)
                if src is not None and not name.startswith("_") and name not in model.SKIPPED_FIELDS:
                    items.append(f"{name!r}: {src}")
        return local, "{" + ", ".join(items) + "}", pos, ()

    def group(self, con: bitfields.BitGroup, ctx: _Traced, pos: int, limit: int) -> tuple[dict, list[str], int, range]:
        """The values of a bit group, its model items (in the group's order), the position after it and its bytes."""
        try:
            nbytes, fields, checks = con._layout()
        except NotImplementedError:
            raise NotFast("a bit group of a kind the compiler keeps interpreted") from None
        where = self.read(pos, nbytes, limit)
        number = int.from_bytes(self.raw[pos:pos + nbytes], "little")
        fixed = self.is_fixed(where)
        v = ""
        if not fixed:
            v = self.variable(pos, _GROUP_FORMATS.get(nbytes, f"{nbytes}s"))
            if nbytes not in _GROUP_FORMATS:
                self.prelude.append(f"    {v} = from_bytes({v}, 'little')")
        values: dict[str, Any] = {}
        srcs: dict[str, str] = {}
        lsb = 0
        for name, kind, width, sub in fields:
            mask = (1 << width) - 1
            bits = number >> lsb & mask
            raw = f"({v} >> {lsb} & {mask})"
            if kind == "flag":
                values[name], srcs[name] = bits == 1, f"{raw} == 1"
            elif kind == "int":
                values[name], srcs[name] = bits, raw
            elif kind == "enum":
                values[name] = sub._decode(bits, None, None)
                srcs[name] = f"{{'value': {raw}, 'name': {self.names_of(sub)}.get({raw})}}"
            else:  # const
                if bits != sub.value:
                    raise NotFast("a constant bit field without its value")
                self.seen.update(where)
                values[name], srcs[name] = bits, raw
            lsb += width
        if checks:
            inner = _Traced(self.seen, ctx)
            for name, value in values.items():
                inner.put(name, value, where)
            for check in checks:
                if not evaluate(check, inner):
                    raise NotFast("a check fails")
        ordered = {name: values[name] for name in con.names}
        items = [f"{name!r}: {self.constant(value) if fixed else srcs[name]}" for name, value in ordered.items()]
        return ordered, items, pos + nbytes, where

    # -- the function ----------------------------------------------------

    def function(self, src: str) -> Callable[[bytes], dict | None]:
        lines = ["def convert(raw):", f"    if len(raw) < {self.end}:", "        return None"]
        for name, table in (("INTS", self.ints), ("FLOATS", self.floats)):
            if table:
                fmt, names = _format(table)
                self.env[name] = struct.Struct(fmt).unpack_from
                lines.append(f"    {', '.join(names)}, = {name}(raw)")
        lines += self.prelude
        lines.append(f"    return {src}")
        env = dict(self.env)
        exec(compile("\n".join(lines), "<fast frame>", "exec"), env)  # noqa: S102 - our own source
        return env["convert"]


def _format(table: list[tuple[int, str, str]]) -> tuple[str, list[str]]:
    """A struct format reading each (offset, code) of `table`, skipping the bytes between, and the variables in order."""
    fmt, names, pos = "<", [], 0
    for offset, code, name in sorted(table):
        if offset < pos:
            raise NotFast("fields overlap")
        if offset > pos:
            fmt += f"{offset - pos}x"
        fmt += code
        names.append(name)
        pos = offset + struct.calcsize("<" + code)
    return fmt, names
