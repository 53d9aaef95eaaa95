"""The one error type of the package, and how Kaitai's exceptions become it."""
from __future__ import annotations

import linecache
import re
import traceback

from kaitaistruct import KaitaiStruct, KaitaiStructError, ValidationFailedError

from ._tables import ERROR_BY_FIELD, SEQ


class OsdkError(ValueError):
    """Input the spec rejects. `error_class` is a docs/VALUE-MODEL.md class
    (bad_sof, truncated_frame, bad_crc16, ..., truncated_payload,
    reserved_bits, length_mismatch, undecodable, impossible_length,
    bad_session), `field` the ksy field id that failed its check or ran out
    of bytes (None where no field applies), `detail` one line for people."""

    def __init__(self, error_class: str, field: str | None, detail: str) -> None:
        super().__init__(f"{error_class} ({field or '-'}): {detail}")
        self.error_class = error_class
        self.field = field
        self.detail = detail


def one_line(exc: BaseException) -> str:
    return re.sub(r"\s+", " ", str(exc)).strip()


# What the generated _read assigns on the line that raised: `self.x = ...`,
# `self._raw_x = ...` or `self.x.append(...)`.
_ASSIGNED = re.compile(r"^\s*self\.(?:_raw_)?([A-Za-z_]\w*)(?:\s*=[^=]|\.append\()")


def _innermost(exc: BaseException):
    """(object, line) of the innermost Kaitai struct code the exception went
    through: the type whose field failed or ran out of bytes."""
    found = None
    for frame, lineno in traceback.walk_tb(exc.__traceback__):
        obj = frame.f_locals.get("self")
        if isinstance(obj, KaitaiStruct):
            found = (obj, linecache.getline(frame.f_code.co_filename, lineno, frame.f_globals))
    return found


def _seq(obj: KaitaiStruct) -> tuple[str, ...]:
    return SEQ.get(type(obj).__qualname__, ())


def _validation_field(exc: ValidationFailedError) -> str | None:
    # src_path is "/seq/N" of the type whose _read raised
    m = re.search(r"/seq/(\d+)$$", exc.src_path or "")
    found = _innermost(exc)
    if not m or found is None:
        return None
    fields = _seq(found[0])
    n = int(m.group(1))
    return fields[n] if n < len(fields) else None


def _eof_field(exc: BaseException) -> str | None:
    found = _innermost(exc)
    if found is None:
        return None
    obj, line = found
    m = _ASSIGNED.match(line)
    if m and m.group(1) in _seq(obj):
        return m.group(1)
    # no source to read (a zipped install): the first field not read yet
    return next((f for f in _seq(obj) if not hasattr(obj, f)), None)


def from_kaitai(exc: BaseException, truncated: str = "truncated_payload") -> OsdkError:
    """The OsdkError of an exception a Kaitai parser raised."""
    if isinstance(exc, ValidationFailedError):
        field = _validation_field(exc)
        return OsdkError(ERROR_BY_FIELD.get(field, "undecodable"), field,
                         f"{field or exc.src_path} fails its check: {one_line(exc)}")
    if isinstance(exc, EOFError):  # the runtime's EndOfStreamError is one
        field = _eof_field(exc)
        return OsdkError(truncated, field, f"ran out of bytes reading {field or 'a field'}: {one_line(exc)}")
    if isinstance(exc, KaitaiStructError):
        return OsdkError("undecodable", None, f"{type(exc).__name__}: {one_line(exc)}")
    raise TypeError(f"not a Kaitai parser exception: {exc!r}")
