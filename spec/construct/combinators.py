"""Three ksy features Construct has no exact counterpart for.

- `when`: a ksy `if:` field is absent when its condition is false. Construct's
  If parses it as None (which the value model drops) but, when building,
  insists on the key being present; `when` lets a built value simply leave
  an absent field out, the way the value model writes it.
- `Call`: a ksy `type: t(a, b)` evaluates the arguments where the field is
  used and instantiates the parametrised type with those values. In this
  package a parametrised type is a Python function returning a Construct
  (`time_stamp(has_ns_and_sync)`, `osdk_payload(cmd_set, cmd_id,
  is_ack, profile)`); Call evaluates its argument expressions in the current context
  and delegates to what the function returns for them.
- `ExactSize`: a ksy `size: n` field occupies exactly n bytes. Construct's
  FixedSized parses the same way but pads with zero bytes when the value
  builds shorter, which would hide a wrong length in a built frame (the
  padding would land as trailing bytes the spec forbids). ExactSize refuses
  to build anything but exactly n bytes.
"""
from __future__ import annotations

import io
from collections.abc import Callable

from construct import Construct, FixedSized, IfThenElse, Pass, SizeofError, evaluate, stream_write

from .compiled import SelfCompiling, emit, link, parser, value_code

__all__ = ["when", "Cond", "Call", "ExactSize"]


class Cond(SelfCompiling, IfThenElse):
    """IfThenElse whose condition may be any context function (the compiler
    emits only `this` expressions)."""

    def _emitparse(self, code):
        return (f"(({emit(self.thensubcon, code)}) if ({value_code(code, self.condfunc)}) "
                f"else ({emit(self.elsesubcon, code)}))")


def when(condition, subcon: Construct) -> Construct:
    """ksy `if: condition`: None when false; may be left out when building."""
    field = Cond(condition, subcon, Pass)
    field.flagbuildnone = True
    return field


class Call(SelfCompiling, Construct):
    """Use `factory(*args)` as the field's construct, args evaluated per parse/build."""

    def __init__(self, factory: Callable[..., Construct], *args) -> None:
        super().__init__()
        self.factory = factory
        self.args = args

    def _resolve(self, context) -> Construct:
        return self.factory(*(evaluate(a, context) for a in self.args))

    def _parse(self, stream, context, path):
        return self._resolve(context)._parsereport(stream, context, path)

    def _build(self, obj, stream, context, path):
        return self._resolve(context)._build(obj, stream, context, path)

    def _sizeof(self, context, path):
        return self._resolve(context)._sizeof(context, path)

    def _emitparse(self, code):
        return f"{link(code, self)}._parse_compiled(io, this)"

    def _parse_compiled(self, stream, context):
        sub = self._resolve(context)
        fast = parser(sub)
        if fast is None:
            return sub._parsereport(stream, context, "(compiled)")
        return fast.parsefunc(stream, context)


class ExactSize(SelfCompiling, FixedSized):
    """FixedSized whose build fails unless the value is exactly `length` bytes."""

    def _emitparse(self, code):
        fname = f"parse_exactsize_{code.allocateId()}"
        code.append(f"""
            def {fname}(io, this):
                length = {value_code(code, self.length)}
                if length < 0:
                    raise PaddingError
                data = io.read(length)
                if len(data) != length:
                    raise StreamError
                return restream(data, lambda io: {emit(self.subcon, code)})
        """)
        return f"{fname}(io, this)"

    def _build(self, obj, stream, context, path):
        length = evaluate(self.length, context)
        buffer = io.BytesIO()
        result = self.subcon._build(obj, buffer, context, path)
        data = buffer.getvalue()
        if len(data) != length:
            raise SizeofError(f"value builds to {len(data)} bytes, the field holds exactly {length}", path=path)
        stream_write(stream, data, length, path)
        return result
