"""IEEE 754 floats that keep every bit, and the Construct fields for them.

The spec compares decoded values by their IEEE bits (docs/VALUE-MODEL.md),
so a decoder must not change any bit. Going through a Python float does:
`struct` turns a signalling float32 NaN into a quiet one on the way to a
double. Construct's Float32l/Float64l use `struct`, so this spec does not;
its float fields read and write the raw integer and wrap it in F32/F64.

F32/F64 compare equal by bits (so -0.0 != 0.0, and a NaN equals itself when
the payload is the same); float(x) gives the numeric value for people and
for range checks.
"""
from __future__ import annotations

import math
import struct

from construct import Adapter, FormatField, Int32ul, Int64ul

from .compiled import SelfCompiling, emit, link

__all__ = ["IeeeFloat", "F32", "F64", "F32le", "F64le"]


class IeeeFloat:
    """Raw bits of one IEEE 754 binary float. Subclasses fix the width."""

    ieee_width: int = 0
    _pack: str = ""  # struct format of the same-width integer
    _fmt: str = ""   # struct format of the float
    _end = 0         # 1 << ieee_width

    __slots__ = ("ieee_bits",)

    def __init__(self, bits: int) -> None:
        # `type(bits) is int` first: a decoder makes one per float field,
        # and the two isinstance calls cost more than the rest
        if (type(bits) is not int and (not isinstance(bits, int) or isinstance(bits, bool))) or not 0 <= bits < self._end:
            raise ValueError(f"{type(self).__name__} needs an integer 0..2**{self.ieee_width}-1, got {bits!r}")
        self.ieee_bits = bits

    @classmethod
    def from_float(cls, value: float) -> "IeeeFloat":
        """The float of this width nearest `value` (OverflowError when out of range)."""
        return cls(struct.unpack(cls._pack, struct.pack(cls._fmt, value))[0])

    # field layout
    @property
    def mantissa_bits(self) -> int:
        return 23 if self.ieee_width == 32 else 52

    @property
    def quiet_bit(self) -> int:
        """The mantissa bit that makes a NaN quiet (IEEE 754-2008)."""
        return 1 << (self.mantissa_bits - 1)

    @property
    def is_nan(self) -> bool:
        exp_mask = ((1 << self.ieee_width) - 1) >> 1 & ~((1 << self.mantissa_bits) - 1)
        return self.ieee_bits & exp_mask == exp_mask and self.ieee_bits & ((1 << self.mantissa_bits) - 1) != 0

    @property
    def is_signalling_nan(self) -> bool:
        return self.is_nan and not self.ieee_bits & self.quiet_bit

    def __float__(self) -> float:
        return self._to_float(self._from_bits(self.ieee_bits))[0]

    def __eq__(self, other: object) -> bool:
        if isinstance(other, IeeeFloat):
            return self.ieee_width == other.ieee_width and self.ieee_bits == other.ieee_bits
        return NotImplemented

    def __hash__(self) -> int:
        return hash((self.ieee_width, self.ieee_bits))

    def __repr__(self) -> str:
        value = float(self)
        shown = "nan" if math.isnan(value) else repr(value)
        return f"{type(self).__name__}(0x{self.ieee_bits:0{self.ieee_width // 4}x}) # {shown}"


class F32(IeeeFloat):
    """A float32 (ksy `f4`) by its bits."""

    ieee_width = 32
    _pack = "<I"
    _fmt = "<f"
    _end = 1 << 32
    _from_bits = struct.Struct(_pack).pack
    _to_float = struct.Struct(_fmt).unpack
    __slots__ = ()


class F64(IeeeFloat):
    """A float64 (ksy `f8`) by its bits."""

    ieee_width = 64
    _pack = "<Q"
    _fmt = "<d"
    _end = 1 << 64
    _from_bits = struct.Struct(_pack).pack
    _to_float = struct.Struct(_fmt).unpack
    __slots__ = ()


class _IeeeAdapter(SelfCompiling, Adapter):
    """Little-endian IEEE float field whose value is an F32/F64 (the raw bits).

    Building accepts an F32/F64 of the right width, or any real number, which
    is rounded to the field's width."""

    decode_needs_no_context = True  # compiled.py may decode it inside a merged read

    def __init__(self, subcon, cls: type[IeeeFloat]) -> None:
        super().__init__(subcon)
        self.cls = cls

    def _decode(self, obj, context, path):
        return self.cls(obj)

    @property
    def ieee_class(self) -> type[IeeeFloat] | None:
        """The float class, when the field is the unsigned little-endian
        integer of the float's width: every value it reads is then in range,
        and compiled code may make the float without __init__'s check."""
        fmt = getattr(self.subcon, "fmtstr", None)
        wanted = {32: ("<I", "<L"), 64: ("<Q",)}.get(self.cls.ieee_width, ())
        return self.cls if type(self.subcon) is FormatField and fmt in wanted else None

    def _emitparse(self, code):
        cls = self.ieee_class
        if cls is None:
            return f"{link(code, self)}._decode({emit(self.subcon, code)}, None, None)"
        fname = f"parse_ieee_{code.allocateId()}"
        code.append(f"""
            def {fname}(bits, new=object.__new__):
                value = new({link(code, cls)})
                value.ieee_bits = bits
                return value
        """)
        return f"{fname}({emit(self.subcon, code)})"

    def _encode(self, obj, context, path):
        if isinstance(obj, IeeeFloat):
            if obj.ieee_width != self.cls.ieee_width:
                raise ValueError(f"a float{obj.ieee_width} given for a float{self.cls.ieee_width} field")
            return obj.ieee_bits
        if isinstance(obj, (int, float)) and not isinstance(obj, bool):
            return self.cls.from_float(obj).ieee_bits
        raise TypeError(f"a float field needs a number or {self.cls.__name__}, got {type(obj).__name__}")


F32le = _IeeeAdapter(Int32ul, F32)
"""ksy `f4` (little-endian float32), bit-exact."""

F64le = _IeeeAdapter(Int64ul, F64)
"""ksy `f8` (little-endian float64), bit-exact."""
