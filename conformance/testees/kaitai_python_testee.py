"""The bundled "kaitai-python" testee: the Kaitai-generated Python parsers
(generated/python/osdk_kaitai, compiled from spec/*.ksy) behind the testee
protocol of conformance/PROTOCOL.md.

    osdkc run --impl kaitai-python
    python conformance/testees/kaitai_python_testee.py --bench FILE --profile P   # osdk_conformance.harness.testee_bench

Every layout, field, enum and `valid` check comes from the generated
parsers, and the receiving and sending from the library generated around
them (generated/python, the package osdk_kaitai, imported here as the kit's
osdk_conformance._kaitai: the same files, which an osdk-kaitai installed or
removed beside the kit leaves as they are): its Deframer finds the
frames in decode_stream, its decode_frame / decode_payload apply the rule
order of conformance/PROTOCOL.md and raise OsdkError with the error class,
and its encoders answer encode_movement_control (float arguments as
Float32Bits, bit for bit) and encode_frame. What is left here is what the
testee protocol asks beyond the library:

- ACK matching in streams (one slot per session 2..31: an ACK's value, a
  header-only ACK's empty one too, is typed by the command waiting in its
  session's slot with its SEQ; ERRATA E32) and chunking of the input.
- Control mode classification and input ranges: osdk_conformance.core.rules
  (rules.yaml), applied to what OsdkControlMode / OsdkMovementControl read.
- The JSON value model: osdk_conformance.core.model.from_kaitai.

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
from io import BytesIO
from typing import Any, Iterable, Iterator, Sequence

from kaitaistruct import KaitaiStream, KaitaiStruct

from osdk_conformance import _kaitai as osdk_kaitai
from osdk_conformance.core import ksy, model
from osdk_conformance.core.commands import command_name
from osdk_conformance.core.rules import classify_control_mode, input_ranges, profile_names
from osdk_conformance.harness.serve import serve
from osdk_conformance._kaitai import Float32Bits, OsdkError, OsdkFrame
from osdk_conformance._kaitai.osdk_control_mode import OsdkControlMode

NAME = "osdk-kaitai-python"
PROFILES = profile_names()
OPERATIONS = ("decode_stream", "decode_frame", "decode_payload", "classify_control_mode", "check_movement_control",
              "encode_movement_control", "encode_frame")
NO_PROFILE = ("encode_movement_control", "encode_frame")  # their requests carry none

AXIS_RANGE = {"x": "horizontal", "y": "horizontal", "z": "vertical", "yaw": "yaw"}
ACK_SESSIONS = range(2, 32)  # sessions with an ACK slot (PROTOCOL.md "ACK matching")
MOVEMENT_CONTROL = osdk_kaitai.COMMANDS["movement_control"]
_HEX = re.compile(r"(?:[0-9a-fA-F]{2})*")
_F32 = re.compile(r"0x[0-9a-f]{8}")
KSY = ksy.load()


class BadRequest(ValueError):
    pass


def _one_line(exc: BaseException) -> str:
    return re.sub(r"\s+", " ", str(exc)).strip()


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


def body_model(body: KaitaiStruct, raw: bytes) -> Any:
    """The model of a payload's body (which starts the payload's bytes)."""
    m = model.from_kaitai(body)
    if "NaN" in json.dumps(m):
        restore_nan_bits(body, m, raw)
    return m


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


def _hex(req: dict, key: str = "hex") -> bytes:
    text = _arg(req, key, str)
    if not _HEX.fullmatch(text):
        raise BadRequest(f"argument {key!r} is not a hex string of whole bytes")
    return bytes.fromhex(text)


def _int_arg(req: dict, key: str, top: int) -> int:
    v = _arg(req, key, int)
    if not 0 <= v <= top:
        raise BadRequest(f"argument {key!r} must be 0..{top}")
    return v


def _byte_arg(req: dict, key: str) -> int:
    return _int_arg(req, key, 0xFF)


def _f32_arg(req: dict, key: str) -> Float32Bits:
    bits = _arg(req, key, dict).get("f32")
    if not isinstance(bits, str) or not _F32.fullmatch(bits):
        raise BadRequest(f'argument {key!r} must be {{"f32": "0x" and 8 hex digits}}')
    return Float32Bits(int(bits, 16))


# ---- operations -------------------------------------------------------------------------

def decode_payload(req: dict, profile: str) -> dict:
    data = _hex(req)
    cmd_set, cmd_id = _byte_arg(req, "cmd_set"), _byte_arg(req, "cmd_id")
    is_ack = _arg(req, "is_ack", bool)
    return {"value": body_model(osdk_kaitai.decode_payload(data, cmd_set, cmd_id, is_ack, profile), data)}


def classify(req: dict, profile: str) -> dict:
    byte = _byte_arg(req, "byte")
    fields = model.from_kaitai(OsdkControlMode(KaitaiStream(BytesIO(bytes([byte])))))
    c = classify_control_mode(byte, profile)
    return {"fields": fields, "classification": c["classification"], "combination": c["combination"]}


def check_movement_control(req: dict, profile: str) -> dict:
    data = _hex(req)
    # as a command value: osdk_movement_control plus the trailing-bytes check
    body = osdk_kaitai.decode_payload(data, *MOVEMENT_CONTROL, False, profile)
    value = body_model(body, data)
    byte = data[0]
    c = classify_control_mode(byte, profile)
    if c["classification"] != "documented":
        raise OsdkError("undefined_mode", "control_mode",
                        f"mode byte 0x{byte:02x} is {c['classification']} on {profile}")
    ranges = input_ranges(byte, profile)
    for axis, which in AXIS_RANGE.items():
        v = getattr(body, axis)  # a double; a quieted NaN is still a NaN
        lim = ranges[which]
        lo, hi = lim.get("min"), lim.get("max")
        if math.isnan(v) or math.isinf(v) or (lo is not None and v < lo) or (hi is not None and v > hi):
            raise OsdkError("out_of_range", axis, f"{axis} = {v!r} outside the {which} range {lo}..{hi}")
    return {"value": value, "combination": c["combination"]}


def decode_frame(req: dict, profile: str) -> dict:
    data = _hex(req)
    return {"frame": frame_model(osdk_kaitai.decode_frame(data, profile), data)}


def encode_movement_control(req: dict, profile: None) -> dict:
    mode = _byte_arg(req, "mode")
    x, y, z, yaw = (_f32_arg(req, k) for k in ("x", "y", "z", "yaw"))
    return {"hex": osdk_kaitai.encode_movement_control(mode, x, y, z, yaw).hex()}


def encode_frame(req: dict, profile: None) -> dict:
    is_ack = _arg(req, "is_ack", bool)
    cmd_set = None if is_ack else _byte_arg(req, "cmd_set")
    cmd_id = None if is_ack else _byte_arg(req, "cmd_id")
    session, seq = _int_arg(req, "session", 31), _int_arg(req, "seq", 0xFFFF)
    value = _hex(req, "value")
    return {"hex": osdk_kaitai.encode_frame(cmd_set, cmd_id, is_ack, session, seq, value).hex()}


class StreamDecoder:
    """Events of a stream: the library's Deframer events and decode_frame,
    then ACK matching. models=False leaves each value as Kaitai parsed it
    (the bench mode times decoding, not the value model)."""

    def __init__(self, profile: str, models: bool = True) -> None:
        self.profile = profile
        self.models = models
        self.slots: dict[int, tuple[int, int, int]] = {}  # session -> (seq, cmd_set, cmd_id) waiting for its ACK

    def event(self, ev: osdk_kaitai.Event) -> dict:
        if ev.kind == "garbage":
            return {"offset": ev.offset, "kind": "garbage", "length": ev.length}
        if ev.kind == "error":
            return {"offset": ev.offset, "kind": "error", "error": ev.error_class, "detail": ev.detail,
                    "length": ev.length}
        try:
            return self._frame(ev)
        except OsdkError as e:
            return {"offset": ev.offset, "kind": "error", "error": e.error_class, "detail": e.detail,
                    "length": ev.length}
        except Exception as e:  # our bug must not cost the rest of the stream
            return {"offset": ev.offset, "kind": "error", "error": "undecodable",
                    "detail": f"internal error ({type(e).__name__}: {_one_line(e)})", "length": ev.length}

    def _frame(self, ev: osdk_kaitai.Event) -> dict:
        f = osdk_kaitai.decode_frame(ev.raw, self.profile)
        out: dict[str, Any] = {"offset": ev.offset, "kind": "frame"}
        plain = not f.header_only and isinstance(f.data, OsdkFrame.FrameData)
        if f.is_ack and (plain or f.header_only) and f.session in ACK_SESSIONS:
            waiting = self.slots.get(f.session)
            if waiting is not None and waiting[0] == f.seq:
                del self.slots[f.session]
                _, cmd_set, cmd_id = waiting
                out["ack_of"] = command_name(cmd_set, cmd_id)
                raw = f.data.ack_value if plain else b""  # a header-only ACK's value is empty
                try:
                    ack = osdk_kaitai.decode_payload(raw, cmd_set, cmd_id, True, self.profile)
                except OsdkError as e:
                    return {"offset": ev.offset, "kind": "error", "error": e.error_class, "detail": e.detail,
                            "length": ev.length, "ack_of": out["ack_of"]}
                out["ack"] = body_model(ack, raw) if self.models else ack
        elif not f.is_ack and plain and f.session in ACK_SESSIONS:
            self.slots[f.session] = (f.seq, f.data.cmd_set_code, f.data.cmd_id)
        out["frame"] = frame_model(f, ev.raw) if self.models else f
        return out


def split_chunks(data: bytes, sizes: list[int]) -> Iterator[bytes]:
    """`data` cut into reads of the given sizes; what they leave over is one last read."""
    pos = 0
    for size in sizes:
        yield data[pos:pos + size]
        pos += size
    if pos < len(data):
        yield data[pos:]


def decode_stream(req: dict, profile: str) -> dict:
    data = _hex(req)
    sizes = _arg(req, "chunks", list)
    if not all(isinstance(s, int) and not isinstance(s, bool) and s >= 0 for s in sizes):
        raise BadRequest("argument 'chunks' must be a list of non-negative integers")
    return {"events": list(stream_events(split_chunks(data, sizes), profile))}


def stream_events(chunks: Iterable[bytes], profile: str, models: bool = True) -> Iterator[dict]:
    """decode_stream's events, one read after another (also the bench mode's loop)."""
    dec = StreamDecoder(profile, models)
    deframer = osdk_kaitai.Deframer()
    for chunk in chunks:
        for ev in deframer.feed(chunk):
            yield dec.event(ev)
    for ev in deframer.finish():
        yield dec.event(ev)


OPS = {
    "decode_stream": decode_stream,
    "decode_frame": decode_frame,
    "decode_payload": decode_payload,
    "classify_control_mode": classify,
    "check_movement_control": check_movement_control,
    "encode_movement_control": encode_movement_control,
    "encode_frame": encode_frame,
}


def answer(req: Any) -> dict:
    if not isinstance(req, dict) or not isinstance(req.get("op"), str):
        raise BadRequest('a request is a JSON object with an "op" string')
    op = req["op"]
    if op == "capabilities":
        return {"ok": True, "result": {"name": NAME, "operations": list(OPERATIONS), "profiles": list(PROFILES)}}
    fn = OPS.get(op)
    profile = req.get("profile")
    if fn is None or (op not in NO_PROFILE and profile not in PROFILES):
        return {"ok": False, "unsupported": True}
    try:
        return {"ok": True, "result": fn(req, profile)}
    except OsdkError as e:
        return {"ok": False, "error": e.error_class, "detail": e.detail}


def main(argv: Sequence[str] = ()) -> int:
    if argv:
        from osdk_conformance.harness import testee_bench

        return testee_bench.main(argv, "kaitai-python", PROFILES,
                                 lambda chunks, profile: stream_events(chunks, profile, models=False))
    return serve(answer)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
