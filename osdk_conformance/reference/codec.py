"""The reference answers to every operation of the testee protocol.

`answer(op, profile, input)` returns exactly the response a conforming
testee gives (conformance/PROTOCOL.md): `{"ok": True, "result": ...}`,
`{"ok": False, "error": CLASS, "detail": ...}` or, for an operation or
profile this module does not know, `{"ok": False, "unsupported": True}`.
`input` holds the operation's arguments without `op`, `id` and `profile`
(the shape of a vector's `input`). A request that is malformed (a missing
or ill-typed argument, hex that is not hex) raises `BadRequest`, a
ValueError: that is a bug of the caller, not an answer about the protocol.

It is built from the parts of the spec that already exist and repeats none
of them: the Construct spec (osdk_construct) for every layout, the SDK-style
receiver (deframe) for frame boundaries and header checks, decode.Decoder
for stream events and ACK matching, decode.classify for the error class of a
failed parse, and rules.py for the control mode byte and input ranges.
tools/gen_vectors.py computes the golden vectors' `expected` with it, and
the bundled "construct" testee answers with it.

Decisions this module takes where the operation's description leaves room
(each one is pinned by vectors and documented in their comments):

- decode_frame checks, in order: the start byte (`bad_sof`), fewer than 12 bytes (`truncated_frame`), the header
  as the receiver checks it (deframe.header_problem: `bad_crc16`,
  `bad_version`, `reserved_bits`, `impossible_length`), the byte count
  against LEN (fewer bytes: `truncated_frame`, more: `length_mismatch`),
  the CRC-32 (`bad_crc32`), and finally the Construct parse, whose failures
  are classified by decode.classify (`bad_encryption`, `bad_session`,
  `truncated_payload`, `length_mismatch`, `reserved_bits`, ...). This is
  the order in which a stream receiver meets the same problems.
- decode_stream splits the bytes into reads of the given `chunks` sizes; a
  remainder not covered by `chunks` arrives as one last read.
- check_movement_control checks, in order: the value's length (it must
  parse as 17 bytes: `truncated_payload` / `length_mismatch`, whatever the
  mode byte), the mode byte (`undefined_mode`, whatever the setpoints), then
  the setpoints (`out_of_range`).
- check_movement_control maps x and y to the combination's horizontal range,
  z to its vertical range and yaw to its yaw range; limits are inclusive,
  compared as the float32's exact value; NaN and infinities are always out
  of range, also against an unbounded limit.
- encode_movement_control encodes any mode byte and any float bits (it is a
  byte-level encoder); vectors mark undefined modes and out-of-range
  setpoints `acceptable`, so an encoder that refuses them passes too.
- encode_frame with a value too long for the 10-bit LEN answers
  `impossible_length`; an ACK in session 0 answers `bad_session`.
"""
from __future__ import annotations

import math
import re
from typing import Any, Callable

import construct

# The control-mode rules and the frame encoder are called through their
# modules, at call time, so that the selftest's mutants (harness/mutants.py),
# which replace them there, reach the reference testee.
from osdk_conformance import _construct as osdk_construct
from osdk_conformance.core import model, rules
from osdk_conformance.core.crc import crc32
from osdk_conformance.core.deframe import HEADER_LEN, frame_length, header_problem, split_chunks
from osdk_conformance.core.errors import one_line
from osdk_conformance.reference.decode import classify, decode_events
from osdk_conformance._construct import F32, encode_movement_control, osdk_control_mode, osdk_payload, parse_frame

PROFILES = rules.profile_names()
OPERATIONS = (
    "capabilities", "decode_stream", "decode_frame", "decode_payload", "classify_control_mode",
    "check_movement_control", "encode_movement_control", "encode_frame",
)
PROFILE_FREE = frozenset({"capabilities", "encode_movement_control", "encode_frame"})
"""Operations that take no profile argument."""

NAME = "osdk-construct-reference"

# Which setpoint of the movement control value is checked against which range.
AXIS_RANGE = {"x": "horizontal", "y": "horizontal", "z": "vertical", "yaw": "yaw"}

_HEX = re.compile(r"(?:[0-9a-fA-F]{2})*")


class BadRequest(ValueError):
    """The request does not have the shape conformance/PROTOCOL.md gives its operation."""


# ----------------------------------------------------------------- responses

def ok(result: dict) -> dict:
    return {"ok": True, "result": result}


def error(cls: str, detail: str) -> dict:
    return {"ok": False, "error": cls, "detail": detail}


UNSUPPORTED = {"ok": False, "unsupported": True}


def _construct_error(exc: construct.ConstructError) -> dict:
    return error(classify(exc), one_line(exc))


# ----------------------------------------------------------------- arguments

def _arg(inp: dict, key: str, kind: type | tuple[type, ...]) -> Any:
    if key not in inp:
        raise BadRequest(f"missing argument {key!r}")
    value = inp[key]
    if isinstance(value, bool) and bool not in (kind if isinstance(kind, tuple) else (kind,)):
        raise BadRequest(f"argument {key!r} must be {getattr(kind, '__name__', kind)}, got a boolean")
    if not isinstance(value, kind):
        raise BadRequest(f"argument {key!r} has the wrong type ({type(value).__name__})")
    return value


def _hex(inp: dict, key: str = "hex") -> bytes:
    text = _arg(inp, key, str)
    if not _HEX.fullmatch(text):
        raise BadRequest(f"argument {key!r} is not a hex string of whole bytes")
    return bytes.fromhex(text)


def _int(inp: dict, key: str, top: int) -> int:
    value = _arg(inp, key, int)
    if not 0 <= value <= top:
        raise BadRequest(f"argument {key!r} must be 0..{top}, got {value}")
    return value


def _f32(inp: dict, key: str):
    value = _arg(inp, key, dict)
    bits = value.get("f32")
    if not isinstance(bits, str) or not re.fullmatch(r"0x[0-9a-fA-F]{1,8}", bits):
        raise BadRequest(f"argument {key!r} must be {{\"f32\": \"0x........\"}}")
    return F32(int(bits, 16))


# ----------------------------------------------------------------- operations

def _capabilities(profile: str | None, inp: dict) -> dict:
    return ok({"name": NAME, "operations": [op for op in OPERATIONS if op != "capabilities"],
               "profiles": list(PROFILES)})


def _classify_control_mode(profile: str, inp: dict) -> dict:
    byte = _int(inp, "byte", 0xFF)
    fields = model.from_construct(osdk_control_mode.parse(bytes([byte])))
    c = rules.classify_control_mode(byte, profile)
    return ok({"fields": fields, "classification": c["classification"], "combination": c["combination"]})


def _out_of_range(value: float, limits: dict) -> str | None:
    """Why `value` is outside [min, max] (None means unbounded), or None."""
    if math.isnan(value):
        return "NaN"
    if math.isinf(value):
        return "infinite"
    lo, hi = limits.get("min"), limits.get("max")
    if lo is not None and value < lo:
        return f"below {lo}"
    if hi is not None and value > hi:
        return f"above {hi}"
    return None


def _check_movement_control(profile: str, inp: dict) -> dict:
    data = _hex(inp)
    try:
        parsed = osdk_payload(0x01, 0x03, False, profile).parse(data)
    except construct.ConstructError as e:
        return _construct_error(e)
    body = parsed.body
    value = model.from_construct(body)
    byte = data[0]
    c = rules.classify_control_mode(byte, profile)
    if c["classification"] != "documented":
        return error("undefined_mode", f"mode byte 0x{byte:02x} is {c['classification']} on {profile}: {c['reasons'][0]}")
    ranges = rules.input_ranges(byte, profile)
    for axis, which in AXIS_RANGE.items():
        why = _out_of_range(float(body[axis]), ranges[which])
        if why:
            limits = ranges[which]
            return error("out_of_range", f"{axis} = {model.readable_float(float(body[axis]))} is {why} "
                                         f"({which} range {limits.get('min')}..{limits.get('max')} {limits.get('unit', '')})")
    return ok({"value": value, "combination": c["combination"]})


def _decode_payload(profile: str, inp: dict) -> dict:
    data = _hex(inp)
    cmd_set = _int(inp, "cmd_set", 0xFF)
    cmd_id = _int(inp, "cmd_id", 0xFF)
    is_ack = _arg(inp, "is_ack", bool)
    try:
        parsed = osdk_payload(cmd_set, cmd_id, is_ack, profile).parse(data)
    except construct.ConstructError as e:
        return _construct_error(e)
    return ok({"value": model.from_construct(parsed)["body"]})


def frame_problem(data: bytes) -> tuple[str, str] | None:
    """The first thing wrong with `data` as exactly one frame, before its
    DATA is parsed: (error class, detail), or None."""
    if not data:
        return "truncated_frame", "no bytes at all"
    if data[0] != 0xAA:
        return "bad_sof", f"first byte 0x{data[0]:02x} is not the start byte 0xaa"
    if len(data) < HEADER_LEN:
        return "truncated_frame", f"{len(data)} byte(s), less than the 12-byte header"
    problem = header_problem(data[:HEADER_LEN])
    if problem:
        return problem
    length = frame_length(data)
    if len(data) < length:
        return "truncated_frame", f"{len(data)} byte(s) of a frame of LEN {length}"
    if len(data) > length:
        return "length_mismatch", f"{len(data)} bytes for a frame of LEN {length}"
    if length > HEADER_LEN and crc32(data) != 0:
        stored = int.from_bytes(data[-4:], "little")
        return "bad_crc32", f"CRC-32 is 0x{stored:08x}, expected 0x{crc32(data[:-4]):08x}"
    return None


def _decode_frame(profile: str, inp: dict) -> dict:
    data = _hex(inp)
    problem = frame_problem(data)
    if problem:
        return error(*problem)
    try:
        parsed = parse_frame(data, profile)
    except construct.ConstructError as e:
        return _construct_error(e)
    return ok({"frame": model.from_construct(parsed)})


def _decode_stream(profile: str, inp: dict) -> dict:
    data = _hex(inp)
    sizes = _arg(inp, "chunks", list)
    if not all(isinstance(s, int) and not isinstance(s, bool) and s >= 0 for s in sizes):
        raise BadRequest("argument 'chunks' must be a list of non-negative integers")
    return ok({"events": list(decode_events(split_chunks(data, sizes), profile))})


def _encode_movement_control(profile: str | None, inp: dict) -> dict:
    mode = _int(inp, "mode", 0xFF)
    x, y, z, yaw = (_f32(inp, k) for k in ("x", "y", "z", "yaw"))
    return ok({"hex": encode_movement_control(mode, x, y, z, yaw).hex()})


def _encode_frame(profile: str | None, inp: dict) -> dict:
    is_ack = _arg(inp, "is_ack", bool)
    session = _int(inp, "session", 31)
    seq = _int(inp, "seq", 0xFFFF)
    value = _hex(inp, "value")
    if is_ack:
        if "cmd_set" in inp or "cmd_id" in inp:
            raise BadRequest("an ACK frame has no cmd_set or cmd_id")
        cmd_set = cmd_id = None
    else:
        cmd_set, cmd_id = _int(inp, "cmd_set", 0xFF), _int(inp, "cmd_id", 0xFF)
    data_len = len(value) + (0 if is_ack else 2)
    if data_len and HEADER_LEN + data_len + 4 > 0x3FF:
        return error("impossible_length", f"{data_len} bytes of DATA make a frame of {HEADER_LEN + data_len + 4} "
                                          f"bytes; LEN holds at most 1023")
    try:
        raw = osdk_construct.build_frame(cmd_set=cmd_set, cmd_id=cmd_id, value=value, is_ack=is_ack, session=session, seq=seq)
    except construct.ConstructError as e:
        return _construct_error(e)
    return ok({"hex": raw.hex()})


_OPS: dict[str, Callable[[Any, dict], dict]] = {
    "capabilities": _capabilities,
    "decode_stream": _decode_stream,
    "decode_frame": _decode_frame,
    "decode_payload": _decode_payload,
    "classify_control_mode": _classify_control_mode,
    "check_movement_control": _check_movement_control,
    "encode_movement_control": _encode_movement_control,
    "encode_frame": _encode_frame,
}


def answer(op: str, profile: str | None, input: dict) -> dict:  # noqa: A002 - the protocol's word
    """The reference response to one request (see the module doc)."""
    fn = _OPS.get(op)
    if fn is None:
        return dict(UNSUPPORTED)
    if op not in PROFILE_FREE and profile not in PROFILES:
        return dict(UNSUPPORTED)
    if not isinstance(input, dict):
        raise BadRequest("the arguments must be a JSON object")
    return fn(profile, input)


def request_answer(request: dict) -> dict:
    """The reference response to a whole protocol request line (a dict with
    `op`, optionally `id` and `profile`, and the arguments)."""
    args = {k: v for k, v in request.items() if k not in ("op", "id", "profile")}
    return answer(request.get("op", ""), request.get("profile"), args)
