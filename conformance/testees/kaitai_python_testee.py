"""The bundled "kaitai-python" testee: the Kaitai-generated Python parsers
(generated/python/osdk_kaitai, compiled from spec/*.ksy) behind the testee
protocol of conformance/PROTOCOL.md.

    osdkc run --impl kaitai-python
    python conformance/testees/kaitai_python_testee.py --bench FILE --profile P   # osdk_conformance.harness.testee_bench

Every layout, field, enum and `valid` check comes from the generated
parsers. The glue below does only what a .ksy cannot:

- CRC-16/CRC-32 checks: osdk_conformance.core.crc (parameters from rules.yaml).
- Finding frames in a byte stream (hunting for 0xAA, the receiver's header
  check, rescanning after a rejection): the testee REUSES
  osdk_conformance.core.deframe (the Deframer for decode_stream, and its
  header_problem for decode_frame). That is frame-layer receiver logic, not
  part of the .ksy, and shared on purpose so that both bundled
  implementations meet the same receiver; no Construct code is involved.
  decode_frame's pre-parse checks follow the order of the receiver
  (start byte, 12 header bytes, header check, byte count against LEN,
  CRC-32), as conformance/PROTOCOL.md's reference does.
- ACK matching in streams (an ACK's value is typed by the command with the
  same session and SEQ seen earlier) and chunking of the input.
- Control mode classification and input ranges: osdk_conformance.core.rules
  (rules.yaml), applied to what OsdkControlMode / OsdkMovementControl read.
- The JSON value model: osdk_conformance.core.model.from_kaitai.
- Error classes: a Kaitai `valid` failure (ValidationNotEqualError,
  ValidationExprError) names its field by `src_path` ("/seq/N") in the type
  whose `_read` raised it, found from the traceback; the field maps to the
  class of docs/VALUE-MODEL.md (`len` impossible_length, `ver` bad_version,
  `res0`/`res1`/`reserved_flags` reserved_bits, `enc` bad_encryption,
  `is_ack` bad_session, `trailing` length_mismatch). Running out of bytes
  (EndOfStreamError, an EOFError) inside a value is truncated_payload.
- Encoding operations are unsupported: the Kaitai Python runtime cannot
  serialise.

Signalling NaNs. The Kaitai Python runtime reads f4/f8 through
`struct.unpack` into a Python float (a C double), and the conversion sets
the quiet bit of a signalling NaN; the value model compares IEEE bits, so
the parsed object alone cannot say which NaN the wire carried. The testee
recovers the bits from the input instead: when a response model holds a
NaN, `restore_nan_bits` walks the parsed object alongside the ksy seq of
its type (osdk_conformance.core.ksy) and computes each field's byte offset
within the object's stream. Every type in this spec is fixed-size given
the fields already read: primitives have their width, bit fields are packed
and byte-aligned before the next byte-sized field, raw byte fields have
the length of the bytes read, `if`-false fields are absent, a sub-object
that Kaitai gave its own substream (`size:` / `size-eos:`) starts at 0 of
its `_raw_<field>` bytes and advances the parent by their length, and any
other sub-object continues in the parent's stream at the current offset.
For each f4/f8 field whose parsed value is NaN it re-reads the 4/8 bytes at
that offset and puts their bits in the model. As a guard against an offset
error, the bits read must be the NaN Kaitai returned modulo the quiet bit;
otherwise the testee reports an internal error rather than guess. This
needs no change to the runtime or the generated code and costs nothing
unless a NaN was parsed.
"""
from __future__ import annotations

import json
import math
import re
import sys
import traceback
from io import BytesIO
from typing import Any, Iterable, Iterator, Sequence

from kaitaistruct import EndOfStreamError, KaitaiStream, KaitaiStruct, KaitaiStructError, ValidationFailedError

from osdk_conformance.core import ksy, model
from osdk_conformance.core.commands import command_name
from osdk_conformance.core.crc import crc32
from osdk_conformance.core.deframe import (HEADER_LEN, Frame, Garbage, Rejected, deframe, frame_length,
                                      header_problem, split_chunks)
from osdk_conformance.core.rules import classify_control_mode, input_ranges, profile_names
from osdk_conformance.harness.serve import serve
from osdk_kaitai.osdk_control_mode import OsdkControlMode
from osdk_kaitai.osdk_frame import OsdkFrame
from osdk_kaitai.osdk_payload import OsdkPayload

NAME = "osdk-kaitai-python"
PROFILES = profile_names()
OPERATIONS = ("decode_stream", "decode_frame", "decode_payload", "classify_control_mode", "check_movement_control")

AXIS_RANGE = {"x": "horizontal", "y": "horizontal", "z": "vertical", "yaw": "yaw"}
PENDING_LIMIT = 1024  # unanswered commands remembered for ACK matching
_HEX = re.compile(r"(?:[0-9a-fA-F]{2})*")
KSY = ksy.load()


class BadRequest(ValueError):
    pass


class Rejection(Exception):
    """The input was rejected with an error class."""

    def __init__(self, cls: str, detail: str) -> None:
        super().__init__(detail)
        self.cls, self.detail = cls, detail


def _profile(name: str) -> OsdkPayload.Profile:
    return OsdkPayload.Profile[name.replace("-", "_").replace(".", "_")]


def _stream(data: bytes) -> KaitaiStream:
    return KaitaiStream(BytesIO(data))


# ---- Kaitai exceptions -> error classes ------------------------------------------

def _raising_field(exc: ValidationFailedError) -> str | None:
    """The ksy field id whose `valid` check raised `exc`."""
    m = re.search(r"/seq/(\d+)$", exc.src_path or "")
    if not m:
        return None
    obj = None
    for frame, _ in traceback.walk_tb(exc.__traceback__):
        candidate = frame.f_locals.get("self")
        if isinstance(candidate, KaitaiStruct):
            obj = candidate  # the innermost KaitaiStruct whose code ran
    if obj is None:
        return None
    fields = list(KSY.type_for_class(type(obj)).fields)
    n = int(m.group(1))
    return fields[n] if n < len(fields) else None


def rejection(exc: Exception) -> Rejection:
    if isinstance(exc, ValidationFailedError):
        name = _raising_field(exc)
        return Rejection(model.ERROR_BY_FIELD.get(name, "undecodable"), f"{name or exc.src_path}: {_one_line(exc)}")
    if isinstance(exc, (EndOfStreamError, EOFError)):
        return Rejection("truncated_payload", _one_line(exc))
    return Rejection("undecodable", f"{type(exc).__name__}: {_one_line(exc)}")


def _one_line(exc: BaseException) -> str:
    return re.sub(r"\s+", " ", str(exc)).strip()


def parse(make, data: bytes):
    """make(stream) with Kaitai errors turned into a Rejection."""
    try:
        return make(_stream(data))
    except (KaitaiStructError, EOFError) as e:
        raise rejection(e) from None


# ---- signalling NaNs: the wire's bits back into the model ----------------------------

_WIDTH = {"u1": 1, "s1": 1, "u2": 2, "s2": 2, "u4": 4, "s4": 4, "u8": 8, "s8": 8, "f4": 4, "f8": 8}


def _prim(t: Any) -> str | None:
    if isinstance(t, str):
        base = t[:-2] if t[-2:] in ("le", "be") and t[:-2] in _WIDTH else t
        if base in _WIDTH:
            return base
    return None


def restore_nan_bits(obj: KaitaiStruct, m: dict, buf: bytes, pos: int = 0) -> int:
    """Put the wire bits of every NaN float of `obj` into its model `m`.
    `buf` is the whole of obj's stream, `pos` where obj starts in it.
    Returns where obj ends."""
    bits = 0
    for spec in KSY.raw_seq(KSY.type_for_class(type(obj))):
        name = spec["id"]
        if not hasattr(obj, name):
            continue  # `if` was false
        t = spec.get("type")
        if isinstance(t, str) and re.fullmatch(r"b\d+", t):
            bits += int(t[1:])
            continue
        pos += (bits + 7) // 8
        bits = 0
        value = getattr(obj, name)
        if "contents" in spec:
            c = spec["contents"]
            pos += len(c) if isinstance(c, list) else len(str(c).encode())
            continue
        elements = value if "repeat" in spec else [value]
        models = m.get(name) if "repeat" in spec else [m.get(name)]
        for i, v in enumerate(elements):
            sub = models[i] if isinstance(models, list) and i < len(models) else None
            raw = getattr(obj, f"_raw_{name}", None)
            p = _prim(t)
            if p is not None:
                if p in ("f4", "f8") and isinstance(v, float) and math.isnan(v):
                    width = _WIDTH[p]
                    wire = int.from_bytes(buf[pos:pos + width], "little")
                    seen = model.float_bits(sub)[1]  # what Kaitai's double gave
                    quiet = 1 << (22 if width == 4 else 51)
                    if seen not in (wire, wire | quiet) or model.float_model(wire, width * 8)["value"] != "NaN":
                        raise RuntimeError(f"NaN bit recovery for {name} at offset {pos} read 0x{wire:x}, "
                                           f"Kaitai read {sub}")
                    fixed = model.float_model(wire, width * 8)
                    if "repeat" in spec:
                        m[name][i] = fixed
                    else:
                        m[name] = fixed
                pos += _WIDTH[p]
            elif isinstance(v, KaitaiStruct):
                if raw is not None:  # its own substream
                    if isinstance(sub, dict):
                        restore_nan_bits(v, sub, raw, 0)
                    pos += len(raw)
                else:
                    pos = restore_nan_bits(v, sub if isinstance(sub, dict) else {}, buf, pos)
            elif isinstance(v, (bytes, bytearray)):
                pos += len(v)
            else:
                raise RuntimeError(f"NaN bit recovery: no size for field {name} of type {t!r}")
    return pos + (bits + 7) // 8


def frame_model(frame: OsdkFrame, raw: bytes) -> dict:
    m = model.from_kaitai(frame)
    if "NaN" in json.dumps(m):
        restore_nan_bits(frame, m, raw)
    return m


def payload_body_model(payload: OsdkPayload, raw: bytes) -> Any:
    m = model.from_kaitai(payload)
    if "NaN" in json.dumps(m):
        restore_nan_bits(payload, m, raw)
    return m["body"]


# ---- arguments ------------------------------------------------------------------------

def _arg(req: dict, key: str, kind) -> Any:
    if key not in req:
        raise BadRequest(f"missing argument {key!r}")
    v = req[key]
    if isinstance(v, bool) and kind is not bool:
        raise BadRequest(f"argument {key!r} must not be a boolean")
    if not isinstance(v, kind):
        raise BadRequest(f"argument {key!r} has the wrong type ({type(v).__name__})")
    return v


def _hex(req: dict) -> bytes:
    text = _arg(req, "hex", str)
    if not _HEX.fullmatch(text):
        raise BadRequest("argument 'hex' is not a hex string of whole bytes")
    return bytes.fromhex(text)


def _byte_arg(req: dict, key: str) -> int:
    v = _arg(req, key, int)
    if not 0 <= v <= 0xFF:
        raise BadRequest(f"argument {key!r} must be 0..255")
    return v


# ---- operations -------------------------------------------------------------------------

def decode_payload(req: dict, profile: str) -> dict:
    data = _hex(req)
    cmd_set, cmd_id = _byte_arg(req, "cmd_set"), _byte_arg(req, "cmd_id")
    is_ack = _arg(req, "is_ack", bool)
    p = parse(lambda io: OsdkPayload(cmd_set, cmd_id, is_ack, _profile(profile), io), data)
    return {"value": payload_body_model(p, data)}


def classify(req: dict, profile: str) -> dict:
    byte = _arg(req, "byte", int)
    if not 0 <= byte <= 0xFF:
        raise BadRequest("argument 'byte' must be 0..255")
    fields = model.from_kaitai(parse(OsdkControlMode, bytes([byte])))
    c = classify_control_mode(byte, profile)
    return {"fields": fields, "classification": c["classification"], "combination": c["combination"]}


def check_movement_control(req: dict, profile: str) -> dict:
    data = _hex(req)
    # As a command value: OsdkPayload(0x01, 0x03) is osdk_movement_control plus the trailing-bytes check.
    p = parse(lambda io: OsdkPayload(0x01, 0x03, False, _profile(profile), io), data)
    body = p.body
    value = payload_body_model(p, data)
    byte = data[0]
    c = classify_control_mode(byte, profile)
    if c["classification"] != "documented":
        raise Rejection("undefined_mode", f"mode byte 0x{byte:02x} is {c['classification']} on {profile}")
    ranges = input_ranges(byte, profile)
    for axis, which in AXIS_RANGE.items():
        v = getattr(body, axis)  # a double; a quieted NaN is still a NaN
        lim = ranges[which]
        lo, hi = lim.get("min"), lim.get("max")
        if math.isnan(v) or math.isinf(v) or (lo is not None and v < lo) or (hi is not None and v > hi):
            raise Rejection("out_of_range", f"{axis} = {v!r} outside the {which} range {lo}..{hi}")
    return {"value": value, "combination": c["combination"]}


def _frame(raw: bytes, profile: str) -> OsdkFrame:
    return parse(lambda io: OsdkFrame(_profile(profile), io), raw)


def decode_frame(req: dict, profile: str) -> dict:
    data = _hex(req)
    # The receiver's checks, in the order a receiver meets them.
    if not data:
        raise Rejection("truncated_frame", "no bytes")
    if data[0] != 0xAA:
        raise Rejection("bad_sof", f"first byte 0x{data[0]:02x} is not the start byte")
    if len(data) < HEADER_LEN:
        raise Rejection("truncated_frame", f"{len(data)} bytes, less than a header")
    problem = header_problem(data[:HEADER_LEN])
    if problem:
        raise Rejection(*problem)
    length = frame_length(data)
    if len(data) < length:
        raise Rejection("truncated_frame", f"{len(data)} bytes of a frame of LEN {length}")
    if len(data) > length:
        raise Rejection("length_mismatch", f"{len(data)} bytes for LEN {length}")
    if length > HEADER_LEN and crc32(data) != 0:
        raise Rejection("bad_crc32", "CRC-32 does not match")
    return {"frame": frame_model(_frame(data, profile), data)}


class StreamDecoder:
    """Events of a stream: Deframer boundaries, Kaitai values, ACK matching.
    models=False leaves each value as Kaitai parsed it (the bench mode times
    decoding, not the value model)."""

    def __init__(self, profile: str, models: bool = True) -> None:
        self.profile = profile
        self.models = models
        self.pending: dict[tuple[int, int], tuple[int, int]] = {}

    def event(self, ev) -> dict:
        if isinstance(ev, Garbage):
            return {"offset": ev.offset, "kind": "garbage", "length": ev.length}
        if isinstance(ev, Rejected):
            return {"offset": ev.offset, "kind": "error", "error": ev.error, "detail": ev.detail, "length": ev.length}
        assert isinstance(ev, Frame)
        try:
            return self._frame(ev)
        except Rejection as r:
            return {"offset": ev.offset, "kind": "error", "error": r.cls, "detail": r.detail, "length": len(ev.raw)}
        except Exception as e:  # our bug must not cost the rest of the stream
            return {"offset": ev.offset, "kind": "error", "error": "undecodable",
                    "detail": f"internal error ({type(e).__name__}: {_one_line(e)})", "length": len(ev.raw)}

    def _frame(self, ev: Frame) -> dict:
        f = _frame(ev.raw, self.profile)
        out: dict[str, Any] = {"offset": ev.offset, "kind": "frame"}
        if f.len > HEADER_LEN and isinstance(f.data, OsdkFrame.FrameData):
            if f.is_ack:
                key = (f.session, f.seq)
                if key in self.pending:
                    cmd_set, cmd_id = self.pending.pop(key)
                    out["ack_of"] = command_name(cmd_set, cmd_id)
                    try:
                        ack = parse(lambda io: OsdkPayload(cmd_set, cmd_id, True, _profile(self.profile), io),
                                    f.data.ack_value)
                    except Rejection as r:
                        return {"offset": ev.offset, "kind": "error", "error": r.cls, "detail": r.detail,
                                "length": len(ev.raw), "ack_of": out["ack_of"]}
                    out["ack"] = payload_body_model(ack, f.data.ack_value) if self.models else ack.body
            elif f.session > 0:
                self.pending[(f.session, f.seq)] = (int(f.data.cmd_set), f.data.cmd_id)
                if len(self.pending) > PENDING_LIMIT:
                    self.pending.pop(next(iter(self.pending)))
        out["frame"] = frame_model(f, ev.raw) if self.models else f
        return out


def decode_stream(req: dict, profile: str) -> dict:
    data = _hex(req)
    sizes = _arg(req, "chunks", list)
    if not all(isinstance(s, int) and not isinstance(s, bool) and s >= 0 for s in sizes):
        raise BadRequest("argument 'chunks' must be a list of non-negative integers")
    return {"events": list(stream_events(split_chunks(data, sizes), profile))}


def stream_events(chunks: Iterable[bytes], profile: str, models: bool = True) -> Iterator[dict]:
    """decode_stream's events, one read after another (also the bench mode's loop)."""
    dec = StreamDecoder(profile, models)
    for ev in deframe(chunks):
        yield dec.event(ev)


OPS = {
    "decode_stream": decode_stream,
    "decode_frame": decode_frame,
    "decode_payload": decode_payload,
    "classify_control_mode": classify,
    "check_movement_control": check_movement_control,
}


def answer(req: Any) -> dict:
    if not isinstance(req, dict) or not isinstance(req.get("op"), str):
        raise BadRequest('a request is a JSON object with an "op" string')
    op = req["op"]
    if op == "capabilities":
        return {"ok": True, "result": {"name": NAME, "operations": list(OPERATIONS), "profiles": list(PROFILES)}}
    fn = OPS.get(op)
    profile = req.get("profile")
    if fn is None or profile not in PROFILES:
        return {"ok": False, "unsupported": True}
    try:
        return {"ok": True, "result": fn(req, profile)}
    except Rejection as r:
        return {"ok": False, "error": r.cls, "detail": r.detail}


def main(argv: Sequence[str] = ()) -> int:
    if argv:
        from osdk_conformance.harness import testee_bench

        return testee_bench.main(argv, "kaitai-python", PROFILES,
                                 lambda chunks, profile: stream_events(chunks, profile, models=False))
    return serve(answer)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
