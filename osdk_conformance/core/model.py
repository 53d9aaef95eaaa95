"""The JSON value model: one representation of decoded values for every
implementation, the CLI and the golden vectors. Documented in
docs/VALUE-MODEL.md; keep the two in step.

- a structure is an object whose keys are its seq fields in wire order;
  a field whose `if` is false is absent, `trailing` (always empty once
  valid) is left out;
- integers are numbers, single bits are booleans, raw bytes are lowercase
  hex strings;
- an enum is {"value": <int>, "name": <str or null>} (null when the value
  has no name in the spec);
- a float is {"f32": "0x3f800000", "value": 1.0} or {"f64": "0x...", ...}:
  the hex of the IEEE bits is normative and is what comparisons use;
  "value" is for people and is a number, or "NaN", "Infinity",
  "-Infinity" (so every float, -0.0 and NaN payloads included, survives a
  JSON round trip).
"""
from __future__ import annotations

import enum
import json
import math
import struct
from typing import Any

from osdk_conformance.core import ksy

SKIPPED_FIELDS = frozenset({"trailing"})

# docs/VALUE-MODEL.md, "Error classes": the class a failed `valid` check of
# each field means, for decoders that learn the failing field (Kaitai
# runtimes, the generated tables for the other languages).
ERROR_BY_FIELD = {
    "sof": "bad_sof",
    "len": "impossible_length",
    "ver": "bad_version",
    "res0": "reserved_bits",
    "res1": "reserved_bits",
    "reserved_flags": "reserved_bits",
    "enc": "bad_encryption",
    "is_ack": "bad_session",
    "trailing": "length_mismatch",
}


def float_model(bits: int, width: int) -> dict:
    if width == 32:
        value = struct.unpack("<f", struct.pack("<I", bits))[0]
        key, digits = "f32", 8
    elif width == 64:
        value = struct.unpack("<d", struct.pack("<Q", bits))[0]
        key, digits = "f64", 16
    else:
        raise ValueError(f"no float of width {width}")
    return {key: f"0x{bits:0{digits}x}", "value": readable_float(value)}


def readable_float(value: float) -> float | str:
    if math.isnan(value):
        return "NaN"
    if math.isinf(value):
        return "Infinity" if value > 0 else "-Infinity"
    return value


def float_bits(model: dict) -> tuple[int, int]:
    """(width, bits) of a float model, the inverse of float_model."""
    if "f32" in model:
        return 32, int(model["f32"], 16)
    return 64, int(model["f64"], 16)


def f32_bits_of_double(value: float) -> int:
    return struct.unpack("<I", struct.pack("<f", value))[0]


def f64_bits_of_double(value: float) -> int:
    return struct.unpack("<Q", struct.pack("<d", value))[0]


def enum_model(value: int, name: str | None) -> dict:
    return {"value": int(value), "name": name}


# --- Kaitai-generated Python objects -> model --------------------------------

def from_kaitai(obj: Any) -> Any:
    """Model of a Kaitai-generated Python object, using the .ksy files for
    what the object cannot say: float widths, and that a plain int is an
    enum value the spec has no name for (the runtime leaves those as int)."""
    # local: only this path needs the runtime. Imported once per model and
    # handed down, not once per value: the import statement cost a third of
    # the conversion when it ran at every level.
    from kaitaistruct import KaitaiStruct

    index = ksy.load()
    return _kaitai_value(obj, index, None, KaitaiStruct)


def _kaitai_value(value: Any, index: ksy.KsyIndex, f: ksy.KsyField | None, struct_class: type) -> Any:
    if isinstance(value, struct_class):
        kt = index.type_for_class(type(value))
        out: dict[str, Any] = {}
        for name, sub in kt.fields.items():
            if name in SKIPPED_FIELDS or not hasattr(value, name):
                continue
            out[name] = _kaitai_value(getattr(value, name), index, sub, struct_class)
        return out
    if isinstance(value, list):
        return [_kaitai_value(v, index, f, struct_class) for v in value]
    if isinstance(value, enum.Enum):
        return enum_model(value.value, value.name)
    if isinstance(value, bool):
        return value
    if isinstance(value, float):
        if f is not None and f.type == "f8":
            return float_model(f64_bits_of_double(value), 64)
        return float_model(f32_bits_of_double(value), 32)
    if isinstance(value, int):
        return enum_model(value, None) if f is not None and f.enum else value
    if isinstance(value, (bytes, bytearray)):
        return bytes(value).hex()
    raise TypeError(f"no model for {type(value).__name__}")


# --- Construct containers -> model -------------------------------------------

def from_construct(value: Any) -> Any:
    """Model of what the Construct spec (osdk_construct) parsed.

    The same model as from_construct_generic, which defines it, made faster
    by converters specialised to the keys and value types of each kind of
    Container (see _Shape). Any exception on the fast path hands the value to
    the generic walk, so every error is the generic walk's."""
    if _types is None:
        _setup()
    try:
        return _fast(value)
    except Exception:  # noqa: BLE001 - the generic walk decides, and names the error
        return from_construct_generic(value)


def from_construct_generic(value: Any) -> Any:
    """The value model of a Construct value, field by field: the definition
    from_construct must agree with (tests/test_model_construct.py)."""
    # imported once per model, not once per value: the import statement
    # cost more than the conversion when it ran at every level
    from construct import Container, EnumInteger, EnumIntegerString, ListContainer

    def convert(value: Any) -> Any:
        if isinstance(value, Container):  # first: hasattr on a Container raises and catches a KeyError
            return {
                k: convert(v)
                for k, v in value.items()
                if not k.startswith("_") and k not in SKIPPED_FIELDS and v is not None
            }
        if hasattr(value, "ieee_bits"):
            return float_model(value.ieee_bits, value.ieee_width)
        if isinstance(value, ListContainer):
            return [convert(v) for v in value]
        if isinstance(value, EnumIntegerString):
            return enum_model(int(value), str(value))
        if isinstance(value, EnumInteger):  # a value the enum has no name for
            return enum_model(int(value), None)
        if isinstance(value, bool):
            return value
        if isinstance(value, int):
            return value
        if isinstance(value, (bytes, bytearray)):
            return bytes(value).hex()
        raise TypeError(f"no model for {type(value).__name__}")

    return convert(value)


# The fast path dispatches on exact types only (type(v) is T), each one
# handled as from_construct_generic handles it; any other type, a subclass
# included, goes to the generic walk. Filled in by _setup on first use.
_types: dict[type, Any] | None = None
_Container: Any = None
_ListContainer: Any = None
_F32: Any = None
_F64: Any = None
_ENUMS: dict[type, bool] = {}  # enum value type -> whether it has a name

MAX_SHAPES = 1024
"""Container key sequences with a converter of their own; others take _loop."""
MAX_VARIANTS = 16
"""Value-type combinations compiled per key sequence (optional items make several)."""

_shapes: dict[tuple, "_Shape"] = {}


def _setup() -> None:
    global _types, _Container, _ListContainer, _F32, _F64
    # Imported on first use, not at the top, for start-up time: the model
    # module is loaded by commands that never touch Construct (~20 ms to import).
    from construct import Container, EnumInteger, EnumIntegerString, ListContainer
    from osdk_conformance._construct.floats import F32, F64  # lazy for start-up time, as construct above

    def ieee(v: Any) -> dict:
        return float_model(v.ieee_bits, v.ieee_width)

    def enum_named(v: Any) -> Any:
        if hasattr(v, "ieee_bits"):  # instances of these take attributes; the generic walk checks first
            return from_construct_generic(v)
        return {"value": int(v), "name": str(v)}

    def enum_unnamed(v: Any) -> Any:
        if hasattr(v, "ieee_bits"):
            return from_construct_generic(v)
        return {"value": int(v), "name": None}

    def same(v: Any) -> Any:
        return v

    _Container, _ListContainer, _F32, _F64 = Container, ListContainer, F32, F64
    _ENUMS.update({EnumIntegerString: True, EnumInteger: False})
    _types = {
        int: same, bool: same, F32: ieee, F64: ieee,
        bytes: bytes.hex, bytearray: lambda v: bytes(v).hex(),
        EnumIntegerString: enum_named, EnumInteger: enum_unnamed,
        ListContainer: lambda v: [_fast(x) for x in v],
    }


def _fast(value: Any) -> Any:
    t = type(value)
    if t is _Container:
        return _container(value)
    handler = _types.get(t)  # type: ignore[union-attr]
    if handler is not None:
        return handler(value)
    return from_construct_generic(value)


def _container(c: Any) -> dict:
    shape = _shapes.get(tuple(c))
    if shape is None:
        shape = _shape(c)
        if shape is None:
            return _loop(c)
    return shape.entry(c)


def _shape(c: Any) -> "_Shape | None":
    """The _Shape of the keys of `c`, made now; None when there are MAX_SHAPES already."""
    if len(_shapes) >= MAX_SHAPES:
        return None
    keys = tuple(c)
    shape = _shapes[keys] = _Shape(keys)
    shape.entry = shape.converter(c)
    return shape


def _loop(c: Any) -> dict:
    """A Container as from_construct_generic converts it, value by value."""
    return {k: _fast(v) for k, v in c.items()
            if not k.startswith("_") and k not in SKIPPED_FIELDS and v is not None}


class _Shape:
    """Converters of Containers with one sequence of keys.

    Each is Python source compiled for one combination of value types: it
    unpacks the values, checks their exact types in one condition and
    builds the model dict in one expression, the floats of the Container
    decoded together by one struct pack/unpack. A Container whose types
    differ goes to `miss`, which compiles a converter for its combination
    (MAX_VARIANTS at most, then _loop). `entry` is the first one made."""

    def __init__(self, keys: tuple) -> None:
        self.keys = keys
        self.variants: dict[tuple, Any] = {}
        self.entry: Any = _loop
        try:
            self.keep = [not k.startswith("_") and k not in SKIPPED_FIELDS for k in keys]
        except Exception:  # noqa: BLE001 - a key the generic walk cannot take: it raises there
            self.keep = None

    def converter(self, c: Any):
        """The converter for the value types `c` has (its type checks pass for `c`)."""
        if self.keep is None:
            return _loop
        values = tuple(c.values())
        types = tuple(map(type, values))
        conv = self.variants.get(types)
        if conv is None:
            if len(self.variants) >= MAX_VARIANTS:
                return _loop
            conv = self.variants[types] = self._compile(values, types)
        return conv

    def miss(self, c: Any) -> dict:
        return self.converter(c)(c)

    def _compile(self, values: tuple, types: tuple):
        env: dict[str, Any] = {"miss": self.miss, "loop": _loop, "container": _container, "fast": _fast, "readable": readable_float,
                               "list_of": _types[_ListContainer], "NoneType": type(None)}  # type: ignore[index]
        names = [f"v{i}" if keep else "_" for i, keep in enumerate(self.keep)]  # type: ignore[arg-type]
        guards, attr_guards, items, floats = [], [], [], []
        for i, (key, keep, t) in enumerate(zip(self.keys, self.keep, types)):  # type: ignore[arg-type]
            if not keep:
                continue
            v = f"v{i}"
            if t is type(None):
                guards.append(f"{v} is None")
                continue
            env[f"T{i}"] = t
            guards.append(f"type({v}) is T{i}")
            if t is int or t is bool:
                expr = v
            elif t is _F32 or t is _F64:
                floats.append((i, t))
                digits = 8 if t is _F32 else 16
                expr = f"{{{'f32' if t is _F32 else 'f64'!r}: '0x%0{digits}x' % b{i}, 'value': f{i} if f{i} - f{i} == 0.0 else readable(f{i})}}"
            elif t is bytes:
                expr = f"{v}.hex()"
            elif t is _Container:
                # the converter of the keys this value has now, taken
                # directly while the value keeps them
                keys = tuple(values[i])
                inner = _shapes.get(keys) or _shape(values[i])
                env[f"K{i}"], env[f"C{i}"] = keys, (inner.converter(values[i]) if inner else _loop)
                expr = f"(C{i}({v}) if tuple({v}) == K{i} else container({v}))"
            elif t is _ListContainer:
                expr = f"list_of({v})"
            elif t in _ENUMS:
                attr_guards.append(f"not hasattr({v}, 'ieee_bits')")  # as enum_named does
                expr = f"{{'value': int({v}), 'name': {f'str({v})' if _ENUMS[t] else 'None'}}}"
            else:
                expr = f"fast({v})"
            items.append(f"{key!r}: {expr}")
        lines = ["def conv(c):", f"    {', '.join(names)}, = c.values()",
                 f"    if not ({' and '.join(guards) or 'True'}):", "        return miss(c)"]
        if attr_guards:  # types as compiled for, so not `miss`: it would come back here
            lines += [f"    if not ({' and '.join(attr_guards)}):", "        return loop(c)"]
        if floats:
            bits = ", ".join(f"b{i}" for i, _ in floats)
            env["pack"] = struct.Struct("<" + "".join("I" if t is _F32 else "Q" for _, t in floats)).pack
            env["unpack"] = struct.Struct("<" + "".join("f" if t is _F32 else "d" for _, t in floats)).unpack
            lines.append(f"    {bits}, = {', '.join(f'v{i}.ieee_bits' for i, _ in floats)},")
            lines.append(f"    {', '.join(f'f{i}' for i, _ in floats)}, = unpack(pack({bits}))")
        lines.append(f"    return {{{', '.join(items)}}}")
        if not self.keys:
            lines = ["def conv(c):", "    return {}"]
        exec(compile("\n".join(lines), f"<model converter {self.keys[:3]}>", "exec"), env)  # noqa: S102 - our own source
        return env["conv"]


# --- JSON ----------------------------------------------------------------------

def dumps(model: Any, **kwargs: Any) -> str:
    """JSON text of a model. allow_nan=False: non-finite floats are already
    strings in the model, so a bare NaN here is a bug, not data."""
    return json.dumps(model, allow_nan=False, **kwargs)
