"""Construct's compiler applied to this spec, where its code is known to
parse exactly as the interpreter does.

`Construct.compile()` turns a construct into Python source, several times
faster to parse with, but it is not a drop-in replacement here: it cannot
emit the lambdas this spec uses for conditions and lengths, it skips the
custom classes (bit groups, records, bit-exact floats), and some of its
emitted code is more lenient than the interpreter (`Bytes(n)` returns
fewer bytes at the end of the input instead of failing). So:

- the spec's own classes (BitGroup, the record adapter, the float adapter,
  `when`, Call, ExactSize) emit their parse code and mix in `SelfCompiling`;
  they emit their children through `emit`, which keeps a child the
  compiler cannot be trusted with in the interpreter (linked);
- `safe` admits only built-in classes whose emitted code fails wherever the
  interpreter fails (struct.unpack raises on a short read, a Const compares
  whole values), so a compiled parse never accepts what the interpreter
  rejects;
- `parse` uses the compiled parser and, on any failure, parses again with
  the interpreter, so an error is always the interpreter's error (class,
  path and message), and a valid input gives the interpreter's value.

Compiled parsers are kept on the construct object, made on its third use.
A layout changed in place after that would keep its old parser: the
mutation selftest patches layouts before anything is parsed.
"""
from __future__ import annotations

import threading
from typing import Any

import construct
from construct.expr import ExprMixin

__all__ = ["SelfCompiling", "safe", "emit", "value_code", "link", "parser", "parse"]


class SelfCompiling:
    """Mixed into a construct whose `_emitparse` emits its children through `emit`."""


def safe(c: Any) -> bool:
    """Whether construct's own `_emitparse` of `c` parses as `c._parse` does, failing where it fails."""
    if isinstance(c, SelfCompiling):
        return True
    if isinstance(c, construct.Renamed):
        return safe(c.subcon)
    if isinstance(c, construct.Struct):
        return all(safe(sc) for sc in c.subcons)
    if isinstance(c, construct.Enum):
        return isinstance(c.subcon, construct.FormatField)
    if isinstance(c, construct.Const):
        # a short read yields fewer bytes, which cannot equal the value
        return isinstance(c.subcon, construct.FormatField) or (
            type(c.subcon) is construct.Bytes and isinstance(c.subcon.length, int))
    # FormatField: struct.unpack raises on a short read. Terminated has no
    # emitter, so the compiler links the interpreter's.
    return type(c) in (construct.FormatField, construct.Pass.__class__, construct.Terminated.__class__,
                       construct.GreedyBytes.__class__)


def link(code, obj: Any) -> str:
    """Source text naming `obj` inside the compiled module."""
    code.linkedinstances[id(obj)] = obj
    return f"linkedinstances[{id(obj)}]"


def emit(sub: Any, code) -> str:
    """Parse code of `sub`: compiled when safe, else its interpreter, linked."""
    fields = _flat_fields(sub)
    if fields is not None:
        return _emit_flat(fields, code)
    if safe(sub):
        return sub._compileparse(code)
    return f"{link(code, sub)}._parsereport(io, this, '(compiled)')"


def _flat_fields(c: Any) -> list[tuple] | None:
    """The parts of `c` when it is a Struct (or a construct with `_flat_struct`,
    the record adapter) of named fixed-size little-endian fields and bit
    groups with nothing that needs its context, else None. Parts:
    ("field", name, fmt, decode) with decode None, an IeeeFloat class or an
    adapter whose _decode needs no context; ("absent", name) for a `when`
    that is constantly false; ("bits", name or None when embedded, fmt,
    names, fields) for a bit group (see BitGroup._flat_bits)."""
    groups: Any = ()
    if type(c) is not construct.Struct:
        flat_struct = getattr(c, "_flat_struct", None)
        if flat_struct is None:
            return None
        c, groups = flat_struct()
        if type(c) is not construct.Struct:
            return None
    fields: list[tuple] = []
    for sc in c.subcons:
        if not isinstance(sc, construct.Renamed) or not sc.name:
            return None
        f = sc.subcon
        if sc.name in groups:
            bits = getattr(f, "_flat_bits", lambda: None)()
            if bits is None:
                return None
            fields.append(("bits", None, *bits))
            continue
        if groups and sc.name.startswith("_"):  # a record leaves these out of its value
            return None
        if isinstance(f, construct.IfThenElse):
            # `when` with a constant condition (a profile variant): present or always None
            if not isinstance(f.condfunc, bool) or f.elsesubcon is not construct.Pass:
                return None
            if not f.condfunc:
                fields.append(("absent", sc.name))
                continue
            f = f.thensubcon
        bits = getattr(f, "_flat_bits", None)
        if bits is not None:
            bits = bits()
            if bits is None:
                return None
            fields.append(("bits", sc.name, *bits))
            continue
        decode = None
        if getattr(f, "ieee_class", None) is not None:
            decode, f = f.ieee_class, f.subcon
        elif isinstance(f, construct.Enum) or getattr(f, "decode_needs_no_context", False):
            decode, f = f, f.subcon
        if type(f) is not construct.FormatField or not f.fmtstr.startswith("<"):
            return None
        fields.append(("field", sc.name, f.fmtstr[1:], decode))
    return fields


def _emit_flat(fields: list[tuple], code) -> str:
    # One read and one unpack for the whole Struct, where construct's code
    # reads and unpacks field by field and builds a context nobody reads.
    # A short read makes unpack raise, where the interpreter raises too.
    n = code.allocateId()
    fmt = "<" + "".join(part[2] for part in fields if part[0] != "absent")
    code.append(f"flat_{n} = struct.Struct({fmt!r})")
    names, body, items = [], [], []
    classes: dict[str, str] = {}
    for i, part in enumerate(fields):
        kind, name = part[0], part[1]
        if kind == "absent":
            items.append(f"{name!r}: None")
            continue
        v = f"v{i}"
        names.append(v)
        if kind == "bits":
            group = _emit_bits(v, part[3], part[4], code, body)
            if name is None:  # embedded in a record: its fields are the record's
                items += group
            else:
                items.append(f"{name!r}: Container({{{', '.join(group)}}})")
            continue
        decode = part[3]
        if isinstance(decode, type):
            # an IeeeFloat made without __init__: the value is the unpacked
            # integer of the float's own width, in range by construction
            cls = f"ieee_{id(decode)}"
            if cls not in classes:
                classes[cls] = f"    {cls} = {link(code, decode)}"  # linked instances are filled in after the module runs
            body += [f"    f{i} = new_{n}({cls})", f"    f{i}.ieee_bits = {v}"]
            v = f"f{i}"
        elif decode is not None:
            v = f"{link(code, decode)}._decode({v}, None, None)"
        items.append(f"{name!r}: {v}")
    if classes:
        code.append(f"new_{n} = object.__new__")
    unpack = [f"    {', '.join(names)}, = flat_{n}.unpack(io.read(flat_{n}.size))"] if names else []
    lines = [f"def parse_flat_{n}(io, this):", *unpack, *classes.values(), *body, f"    return Container({{{', '.join(items)}}})"]
    code.append("\n".join(lines))
    return f"parse_flat_{n}(io, this)"


def _emit_bits(v: str, names: tuple, fields: list, code, body: list[str]) -> list[str]:
    """Dict items of a bit group read as the integer `v` (first field in the
    lowest bits), in the group's order; its constant checks go to `body`."""
    values = {}
    lsb = 0
    for name, kind, width, sub in fields:
        raw = f"({v} >> {lsb} & {(1 << width) - 1})"
        if kind == "flag":
            values[name] = f"{raw} == 1"
        elif kind == "int":
            values[name] = raw
        elif kind == "enum":
            values[name] = f"{link(code, sub)}._decode({raw}, None, None)"
        else:  # const
            body += [f"    if {raw} != {sub.value!r}:", "        raise ConstError"]
            values[name] = raw
        lsb += width
    return [f"{name!r}: {values[name]}" for name in names]


def value_code(code, value: Any) -> str:
    """Source text of a construct parameter (a `this` expression, a context function or a constant) in context `this`."""
    if isinstance(value, ExprMixin):
        return repr(value)
    if callable(value):
        return f"{link(code, value)}(this)"
    return repr(value)


COMPILE_AFTER = 2
"""Parses a construct gets from the interpreter before it is compiled:
compiling costs milliseconds, a one-off command value (random data can
name any of 65,536 commands) is cheaper to interpret."""

_lock = threading.Lock()


def parser(c: Any):
    """The compiled parser of `c` from its (COMPILE_AFTER + 1)-th request on,
    else None (also when `c` cannot be compiled safely). Kept on `c` itself,
    so it goes when the construct goes (payload constructs live in an
    lru_cache)."""
    state = getattr(c, "_osdk_compiled", None)
    if state is not None and state[0] > COMPILE_AFTER:
        return state[1]
    with _lock:
        uses = getattr(c, "_osdk_compiled", (0, None))[0]
        state = (uses + 1, _compile(c) if uses == COMPILE_AFTER else None)
        c._osdk_compiled = state
    return state[1]


def _compile(c: Any):
    if not safe(c):
        return None
    try:
        return c.compile()
    except Exception:  # noqa: BLE001 - a construct the compiler cannot handle is parsed by the interpreter
        return None


def parse(c: Any, data: bytes) -> Any:
    """`c.parse(data)`, compiled where that is safe; every error is the interpreter's."""
    fast = parser(c)
    if fast is not None:
        try:
            return fast.parse(data)
        except Exception:  # noqa: BLE001 - the interpreter decides, and names the error
            pass
    return c.parse(data)
