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
    index = ksy.load()
    return _kaitai_value(obj, index, None)


def _kaitai_value(value: Any, index: ksy.KsyIndex, f: ksy.KsyField | None) -> Any:
    from kaitaistruct import KaitaiStruct  # local: only this path needs the runtime

    if isinstance(value, KaitaiStruct):
        kt = index.type_for_class(type(value))
        out: dict[str, Any] = {}
        for name, sub in kt.fields.items():
            if name in SKIPPED_FIELDS or not hasattr(value, name):
                continue
            out[name] = _kaitai_value(getattr(value, name), index, sub)
        return out
    if isinstance(value, list):
        return [_kaitai_value(v, index, f) for v in value]
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
    """Model of what the Construct spec (osdk_construct) parsed."""
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


# --- JSON ----------------------------------------------------------------------

def dumps(model: Any, **kwargs: Any) -> str:
    """JSON text of a model. allow_nan=False: non-finite floats are already
    strings in the model, so a bare NaN here is a bug, not data."""
    return json.dumps(model, allow_nan=False, **kwargs)
