"""The Python API of the kit: what `osdkc` does, callable from Python.

A thin, stable facade over the modules that do the work; it adds typed
results and one error type, and no protocol logic of its own:

- decoding (`decode`, `decode_hex`, `decode_file`, `decode_stream`) is
  `osdkc decode`: the SDK-style receiver (core/deframe.py), the Construct
  spec, pcapng captures (core/capture.py) told from raw bytes by their
  first block, events in the JSON value model (docs/VALUE-MODEL.md);
- encoding (`encode_frame`, `encode_movement_control`, `encode_broadcast`,
  `encode_broadcast_frame`) is the Construct spec (osdk_construct) and the
  broadcast values of reference/values.py, as the simulator builds them;
- `classify_control_mode` and `check_movement_control` answer exactly what
  the reference answers in the testee protocol (reference/codec.py,
  conformance/PROTOCOL.md), typed;
- `run_conformance` is `osdkc run` for one testee: the golden vectors,
  the testee supervisor, the failure list, coverage and the verdict
  (harness/runner.py);
- `simulator` runs `osdkc sim` in a thread of this process, on a
  pseudo-terminal;
- `judge_tap_capture` is `osdkc tap --replay`: every check of the tap on a
  recorded session (tap/), and `write_capture` records one from bytes and
  their times, in the kit's pcapng format (core/capture.py).

Everything in `__all__` is the stable interface (docs/API.md says what that
promises); every other module of the package may change without notice.
Arguments that cannot be used (bad hex, an unknown profile, a byte out of
range, a value the layout cannot hold, a testee that cannot be started, a
damaged capture) raise `InputError`; reading a file that is not there raises
the usual OSError.
"""
from __future__ import annotations

import os
import threading
import time
from collections import Counter
from collections.abc import Iterable, Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any, BinaryIO, Literal, cast

import construct

from osdk_conformance.core import model as value_model
from osdk_conformance.core import rules
from osdk_conformance.core.capture import CaptureError, CaptureWriter, RX, TX
from osdk_conformance.core.errors import UsageError, one_line
from osdk_conformance.core.options import non_negative_int, positive_float, probability
from osdk_conformance.core.wire import encode as encode_wire_frame
from osdk_conformance.harness import report
from osdk_conformance.harness.runner import (apply_failure_list, available_impls, coverage as coverage_rows,
                                             coverage_table, default_failure_list, impl_argv, no_result_reason,
                                             read_failure_list, run_cases, select_cases, verdict_of, CoverageRow)
from osdk_conformance.harness.testee import DEFAULT_MEMORY_MB, DEFAULT_TIMEOUT, Testee, TesteeStartError
from osdk_conformance.harness.vectors import Case, compare as judge, load_checked_cases
from osdk_conformance.reference import codec, values
from osdk_conformance.reference.decode import classify as error_class, parse_hex, read_chunks, timed_events
from osdk_conformance.flight import extra as flight_extra, output as flight_output
from osdk_conformance.sim.bugs import BUGS
from osdk_conformance.sim.simulator import FAULTS, RC_MODE, PtyTransport, SimConfig, Simulator
from osdk_conformance.device.checks import Options as _DeviceOptions
from osdk_conformance.device.verdict import acceptance_word
from osdk_conformance.tap.checks import TapOptions as _TapOptions
from osdk_conformance.tap.replay import judge_capture as _judge_capture
from osdk_conformance._construct import F32, F64, encode_movement_control as _encode_movement_value, osdk_payload

__all__ = [
    # errors and types
    "InputError", "BytesLike", "Direction", "EventKind", "Classification", "Status", "F32", "F64",
    # the spec
    "profiles", "broadcast_items", "ieee_float",
    # decoding
    "Event", "decode", "decode_hex", "decode_file", "decode_stream",
    # flight data for people (the `flight` extra)
    "flight_data", "broadcasts", "table", "plot",
    # encoding
    "encode_frame", "encode_movement_control", "encode_broadcast", "encode_broadcast_frame",
    # the control mode byte and movement control
    "ControlMode", "MovementCheck", "classify_control_mode", "check_movement_control",
    # a conformance run
    "Capabilities", "CaseResult", "Coverage", "ConformanceRun", "bundled_implementations", "run_conformance",
    # the simulator
    "RunningSimulator", "simulator",
    # a host judged from a capture
    "write_capture", "TapCheck", "TapReport", "judge_tap_capture",
]

BytesLike = bytes | bytearray | memoryview
"""What the functions that take bytes accept."""

Direction = Literal["rx", "tx", "both"]
"""Which bytes of a pcapng capture to decode: received, sent, or both (raw bytes are always "rx")."""

EventKind = Literal["frame", "error", "garbage"]
"""What a decoded event is (docs/VALUE-MODEL.md, "`osdkc decode` output")."""

Classification = Literal["documented", "undocumented", "later_firmware", "invalid"]
"""The classes of a control mode byte (conformance/PROTOCOL.md, classify_control_mode)."""

Status = Literal["pass", "fail", "xfail", "xpass", "skip", "error"]
"""The status of one case of a conformance run (harness/report.py)."""

_DIRECTIONS = ("rx", "tx", "both")
_SETPOINTS = ("x", "y", "z", "yaw")


class InputError(ValueError):
    """An argument the API cannot use: hex that is not hex, something that
    is not bytes, an unknown profile or item, a number out of its range, a
    value the layout cannot hold, a damaged capture, a testee that cannot be
    started. The message says which and why, in one line."""


# ---------------------------------------------------------------- arguments

def _profile(profile: object) -> str:
    names = rules.profile_names()
    if not isinstance(profile, str) or profile not in names:
        raise InputError(f"unknown profile {profile!r} (one of {', '.join(names)})")
    return profile


def _bytes(data: object, what: str) -> bytes:
    if not isinstance(data, (bytes, bytearray, memoryview)):
        hint = "; for hex text use bytes.fromhex() or decode_hex()" if isinstance(data, str) else ""
        raise InputError(f"{what} must be bytes, got {type(data).__name__}{hint}")
    return bytes(data)


def _int(value: object, what: str, top: int) -> int:
    if not isinstance(value, int) or isinstance(value, bool) or not 0 <= value <= top:
        raise InputError(f"{what} must be an integer 0..{top}, got {value!r}")
    return value


def _direction(direction: object) -> Direction:
    if direction not in _DIRECTIONS:
        raise InputError(f"direction must be one of {', '.join(_DIRECTIONS)}, got {direction!r}")
    return cast(Direction, direction)


# ---------------------------------------------------------------- the spec

def profiles() -> tuple[str, ...]:
    """The wire profile ids of spec/rules.yaml, in the order of their values:
    what every `profile` argument takes."""
    return rules.profile_names()


def broadcast_items(profile: str) -> tuple[str, ...]:
    """The broadcast items of `profile` in flag-bit order: the keys
    `encode_broadcast` takes and the fields a decoded broadcast has."""
    return values.items(_profile(profile))


def ieee_float(value: Mapping[str, Any]) -> F32 | F64:
    """The float of a value-model float (`{"f32": "0x3f800000", "value": 1.0}`)
    as F32 or F64, which keep every bit: equal by bits (so -0.0 != 0.0 and
    a NaN equals the NaN of the same payload); `float(x)` is the number.
    The encoders take them, so a decoded float goes back out unchanged."""
    try:
        width, bits = value_model.float_bits(cast("dict[str, Any]", value))
        return F32(bits) if width == 32 else F64(bits)
    except (KeyError, TypeError, ValueError, AttributeError):
        raise InputError(f"not a float of the value model ({{\"f32\": \"0x...\"}} or {{\"f64\": ...}}): "
                         f"{value!r}") from None


# ---------------------------------------------------------------- decoding

@dataclass(frozen=True)
class Event:
    """One object of `osdkc decode`'s output: a frame, an error or a run of garbage.

    Which fields are set depends on `kind` (docs/VALUE-MODEL.md):
    a frame has `command` (or, an ACK matched to its command, `ack_of` and
    `ack`) and `frame`, the model of osdk_frame; an error has `error` (the
    class), `detail` and `length`, and `frame_header` when the frame's
    header was good; garbage has `length`. `direction` is set when both
    directions of a capture are decoded. `model` is the whole event exactly
    as `osdkc decode` prints it; `to_json()` is that line.

    `time` is the capture time in seconds since the Unix epoch: that of the
    pcapng record whose bytes completed the event (when the kit's recorder
    read them from the port); None for raw bytes, which carry no time.
    `time_ns` is the same in exact nanoseconds. `fc_time` is the flight
    controller's own time stamp of a decoded broadcast (item time_stamp,
    which counts 1/400 s) in seconds; None for other events and for a
    broadcast without the item. Neither is part of the value model.
    """

    offset: int
    kind: EventKind
    direction: Literal["rx", "tx"] | None = None
    command: str | None = None
    frame: Mapping[str, Any] | None = None
    ack_of: str | None = None
    ack: Any = None
    error: str | None = None
    detail: str | None = None
    length: int | None = None
    frame_header: Mapping[str, Any] | None = None
    raw: str | None = None
    time_ns: int | None = None
    model: Mapping[str, Any] = field(default_factory=dict, repr=False, compare=False)

    @property
    def time(self) -> float | None:
        """The capture time in seconds since the Unix epoch; None for raw bytes."""
        return None if self.time_ns is None else self.time_ns / 1e9

    @property
    def fc_time(self) -> float | None:
        """A broadcast's own time stamp (item time_stamp) in seconds; None without one."""
        if self.command != "broadcast":
            return None
        stamp = (self.value or {}).get("data", {}).get("time_stamp")
        return None if stamp is None else stamp["time"] / values.FC_TICKS_PER_S

    @classmethod
    def from_model(cls, event: Mapping[str, Any]) -> "Event":
        """The Event of one object of `osdkc decode`'s output."""
        model = dict(event)
        if "offset" not in model or "kind" not in model:
            raise InputError(f"not an event of osdkc decode (no offset or kind): {model!r}")
        return _event({k: model[k] for k in model if k in _EVENT_FIELDS}, model)

    @property
    def value(self) -> Any:
        """The decoded value of a frame: the body of a plain command (for a
        broadcast `{"data": {...}}`), or an ACK's value when the ACK was
        matched to its command ({"raw": ""}-like for a matched header-only
        ACK); None for anything else (header-only frames not matched,
        encrypted, an unmatched ACK, an error, garbage)."""
        if self.ack_of is not None:
            return self.ack
        data = self.frame.get("data") if self.frame else None
        if isinstance(data, Mapping) and isinstance(data.get("value"), Mapping):
            return data["value"].get("body")
        return None

    def to_json(self, indent: int | None = None) -> str:
        """The event as `osdkc decode` prints it (one JSON line unless `indent`)."""
        return value_model.dumps(self.model, indent=indent)


_EVENT_FIELDS = frozenset(Event.__dataclass_fields__) - {"model", "time_ns"}
_new_event = object.__new__
_set_state = object.__setattr__


def _event(state: dict[str, Any], model: dict[str, Any]) -> Event:
    # The fields go straight into the instance dict: the generated __init__
    # of a frozen dataclass sets each of them through object.__setattr__,
    # which costs more per event than the native decoder takes to decode a
    # frame. Fields an event does not have are the class's defaults (None).
    state["model"] = model
    ev = _new_event(Event)
    _set_state(ev, "__dict__", state)
    return ev


def _events(timed: Iterable[tuple[dict[str, Any], int | None]]) -> Iterator[Event]:
    # every key of a decoder's event is a field of Event (tests/test_accel.py)
    try:
        for ev, ts in timed:
            state = ev.copy()
            if ts is not None:
                state["time_ns"] = ts
            yield _event(state, ev)
    except UsageError as e:  # a damaged capture, or --direction tx/both on raw bytes
        raise InputError(str(e)) from None


def decode(data: BytesLike, profile: str, *, direction: Direction = "rx") -> list[Event]:
    """The events in `data`: raw bytes received from a flight controller, or
    a whole pcapng capture (`osdkc device --capture`; then `direction` picks
    the received, sent or both directions). What `osdkc decode --hex`
    prints, as Events."""
    raw = _bytes(data, "data")
    _profile(profile)
    _direction(direction)
    return list(_events(timed_events([raw], profile, direction, "data")))


def decode_hex(text: str, profile: str, *, direction: Direction = "rx") -> list[Event]:
    """`decode` of hex text; spaces, colons, commas and a leading 0x are allowed."""
    if not isinstance(text, str):
        raise InputError(f"hex text must be a str, got {type(text).__name__}")
    try:
        data = parse_hex(text)
    except UsageError:
        raise InputError("not a hex string (pairs of 0-9a-f, optionally separated by spaces, colons "
                         "or commas)") from None
    return decode(data, profile, direction=direction)


def decode_stream(source: Iterable[bytes] | BinaryIO, profile: str, *, direction: Direction = "rx",
                  name: str = "input") -> Iterator[Event]:
    """The events of a stream, lazily, in bounded memory: `source` is a
    binary file object (read in 64 KiB chunks, e.g. `sys.stdin.buffer`) or
    any iterable of byte chunks. Raw bytes or a pcapng capture, as in
    `decode`; `name` is what an error about a damaged capture calls the
    input. Reading errors (OSError) pass through."""
    _profile(profile)
    _direction(direction)
    if hasattr(source, "read"):
        chunks = read_chunks(cast(BinaryIO, source))
    elif isinstance(source, Iterable):
        chunks = (_bytes(chunk, "each chunk") for chunk in source)
    else:
        raise InputError(f"source must be a binary file object or an iterable of bytes, got {type(source).__name__}")
    return _events(timed_events(chunks, profile, direction, name))


def decode_file(path: str | os.PathLike[str], profile: str, *, direction: Direction = "rx") -> Iterator[Event]:
    """The events of a file of raw bytes or a pcapng capture, lazily, in
    bounded memory whatever the file's size: `osdkc decode FILE`. The file
    is opened when the iteration starts and closed when it ends (OSError if
    it cannot be read)."""
    _profile(profile)
    _direction(direction)
    try:
        name = os.fspath(path)
    except TypeError:
        raise InputError(f"path must be a str or path-like, got {type(path).__name__}") from None

    def read() -> Iterator[Event]:
        with open(name, "rb") as fh:
            yield from decode_stream(fh, profile, direction=direction, name=str(name))

    return read()


# ---------------------------------------------------------------- flight data

def _flight():
    try:
        return flight_extra.load("columns", "records", "tables", "plot")
    except UsageError as e:
        raise InputError(str(e)) from None


def _flight_source(source: object, profile: str) -> Any:
    columns = _flight()[0]
    _profile(profile)
    if not isinstance(source, (bytes, bytearray, memoryview)):
        try:
            source = os.fspath(cast(Any, source))
        except TypeError:
            raise InputError(f"source must be a path or bytes, got {type(source).__name__}") from None
    try:
        return columns.read(cast(Any, source), profile)
    except UsageError as e:
        raise InputError(str(e)) from None


def flight_data(source: str | os.PathLike[str] | BytesLike, profile: str) -> Any:
    """The broadcasts of a capture (a path, or the bytes of a pcapng capture
    or of raw received bytes) as columns filled by the native decoder: a
    `FlightData` (osdk_conformance/flight/columns.py) with `values(name)`,
    `valid(name)`, `bits(name)` as numpy arrays, `time`, `fc_time`,
    `offset` per frame, `counts` of everything else the input held, and
    `to_arrow()`/`records()`. Needs the `flight` extra and the native
    decoder; InputError when either is missing."""
    return _flight_source(source, profile)


def broadcasts(source: str | os.PathLike[str] | BytesLike, profile: str) -> Iterator[Any]:
    """Each broadcast frame as a typed record (flight/records.py):
    `b.battery` an int or None, `b.quaternion.q0` a float, enums as
    IntEnums, `b.time` (capture time, s), `b.fc_time` (the FC's time
    stamp, s), `b.attitude` (roll, pitch, yaw in degrees)."""
    data = _flight_source(source, profile)
    return _flight()[1].records(data)


def table(source: str | os.PathLike[str] | BytesLike, profile: str, items: Sequence[str] | None = None) -> Any:
    """The broadcasts as a pyarrow Table, one row per frame: `offset`, `time`
    (when the capture has times), `fc_time`, then a column per field of
    `items` (all when None), named by its dotted path ("quaternion.q0"),
    null where the frame lacked the item. `.to_pandas()` makes a DataFrame."""
    data = _flight_source(source, profile)
    tables = _flight()[2]
    try:
        return tables.to_arrow(data, None if items is None else list(items))
    except UsageError as e:
        raise InputError(str(e)) from None


def plot(source: str | os.PathLike[str] | BytesLike, profile: str, items: Sequence[str] = ("battery", "attitude"),
         output: str | os.PathLike[str] = "flight.html") -> str:
    """Draws `items` of a capture (`osdkc plot`): an HTML page, or an SVG
    when `output` ends in .svg. Returns the output's path."""
    data = _flight_source(source, profile)
    plot_module = _flight()[3]
    out = os.fspath(output)
    try:
        text = plot_module.svg(data, list(items)) if out.lower().endswith(".svg") else plot_module.page(data, list(items))
    except UsageError as e:
        raise InputError(str(e)) from None
    flight_output.write_replacing(out, lambda fh: fh.write(text.encode("utf-8")))
    return out


# ---------------------------------------------------------------- encoding

# The words for a Construct check that fails while a frame is built: the
# check's own message names only the field.
_RULE_TEXT = {"bad_session": "an ACK frame is never in session 0 (ERRATA E24)"}


def encode_frame(*, cmd_set: int | None = None, cmd_id: int | None = None, value: BytesLike = b"",
                 is_ack: bool = False, session: int = 0, seq: int = 0, key: bytes | None = None) -> bytes:
    """A whole frame with LEN and both CRCs filled in (osdk_construct.build_frame).

    A command frame has `cmd_set` and `cmd_id`; an ACK frame (`is_ack`) has
    neither, only its value; with no value and no command the frame is the
    12-byte header alone. With `key` (the 32-byte AES-256 app key) DATA is
    encrypted as the flight controller and the SDK do. What the spec
    forbids (an ACK in session 0, more than 1023 bytes, a field out of
    range) is an InputError."""
    raw = _bytes(value, "value")
    if (cmd_set is None) != (cmd_id is None):
        raise InputError("give both cmd_set and cmd_id (a command frame), or neither (an ACK or a header-only frame)")
    if cmd_set is not None:
        _int(cmd_set, "cmd_set", 0xFF)
        _int(cmd_id, "cmd_id", 0xFF)
    _int(session, "session", 31)
    _int(seq, "seq", 0xFFFF)
    if key is not None and (not isinstance(key, bytes) or len(key) != 32):
        raise InputError("key must be the 32 bytes of the AES-256 app key")
    try:
        return encode_wire_frame(cmd_set=cmd_set, cmd_id=cmd_id, value=raw, is_ack=bool(is_ack),
                                 session=session, seq=seq, key=key)
    except construct.ConstructError as e:
        cls = error_class(e)
        raise InputError(f"the frame breaks a rule of the spec ({cls}): {_RULE_TEXT.get(cls, one_line(e))}") from None
    except ValueError as e:
        raise InputError(one_line(e)) from None


def _setpoint(value: object, axis: str) -> F32 | float:
    if isinstance(value, F32) or (isinstance(value, (int, float)) and not isinstance(value, bool)):
        return value
    raise InputError(f"{axis} must be a number or an F32, got {value!r}")


def encode_movement_control(mode: int, x: float | F32, y: float | F32, z: float | F32, yaw: float | F32) -> bytes:
    """The 17-byte movement control value (command set 0x01, id 0x03): the
    control mode byte, then x, y, z, yaw as little-endian float32. Numbers
    are rounded to float32; an F32 goes out bit for bit (NaN payloads and
    -0.0 included). Any mode byte and any float encode: whether the command
    is one to send is `check_movement_control`'s answer."""
    _int(mode, "mode", 0xFF)
    args = [_setpoint(v, axis) for v, axis in zip((x, y, z, yaw), _SETPOINTS)]
    try:
        return bytes(_encode_movement_value(mode, *args))
    except (OverflowError, ValueError, TypeError, construct.ConstructError) as e:
        raise InputError(f"movement control: {one_line(e)} (a setpoint beyond the float32 range?)") from None


def encode_broadcast(profile: str, items: Mapping[str, Any]) -> bytes:
    """The broadcast value (command set 0x02, id 0x00) of `profile` carrying
    `items`: the flag word, then each item given in flag-bit order.

    `items` maps an item (`broadcast_items(profile)`) to its value in the
    shape of the decoded item without the value model's wrapping: an int for
    a one-byte item (`"battery": 87`), a dict of fields for the others
    (`"gimbal": {"roll": 1.5, ...}`), numbers or F32/F64 for floats, ints
    or names for enums, bytes for raw fields. Fields not given are at rest
    (zero, false); fields another profile's variant of the item has and
    this one lacks are dropped (reference/values.py), so one dict serves
    every profile. `None` sends the item at rest."""
    _profile(profile)
    if not isinstance(items, Mapping):
        raise InputError(f"items must be a mapping of item name to value, got {type(items).__name__}")
    given = {item: v for item, v in items.items() if v is not None}
    try:
        data = values.broadcast_data(profile, list(items), given)
        return cast(bytes, osdk_payload(0x02, 0x00, False, profile).build({"body": {"data": data}}))
    except (OverflowError, ValueError, TypeError, construct.ConstructError) as e:
        raise InputError(f"broadcast on {profile}: {one_line(e)}") from None


def encode_broadcast_frame(profile: str, items: Mapping[str, Any], *, seq: int = 0, key: bytes | None = None) -> bytes:
    """The whole broadcast frame of `encode_broadcast(profile, items)`, in
    session 0 as the flight controller sends it; encrypted with `key`."""
    return encode_frame(cmd_set=0x02, cmd_id=0x00, value=encode_broadcast(profile, items), seq=seq, key=key)


# ---------------------------------------------------------------- control mode and movement control

@dataclass(frozen=True)
class ControlMode:
    """What the control mode byte means on a profile.

    `fields`, `classification` and `combination` are the reference's answer
    to the testee protocol's classify_control_mode (conformance/PROTOCOL.md);
    `reasons` says why, in words (spec/rules.yaml); `input_ranges` gives,
    for a documented byte, each axis's limits (`horizontal`, `vertical`,
    `yaw` -> `min`, `max`, `unit`, ...; a None limit is unbounded).
    """

    byte: int
    profile: str
    fields: Mapping[str, Any]
    classification: Classification
    combination: int | None
    reasons: tuple[str, ...]
    input_ranges: Mapping[str, Mapping[str, Any]] | None

    @property
    def documented(self) -> bool:
        """Whether the byte is one of the 14 documented combinations on the profile."""
        return self.classification == "documented"

    def response(self) -> dict[str, Any]:
        """The testee-protocol response a conforming implementation gives."""
        return {"ok": True, "result": {"fields": self.fields, "classification": self.classification,
                                       "combination": self.combination}}


@dataclass(frozen=True)
class MovementCheck:
    """The verdict on one movement control value (17 bytes) for a profile.

    `ok` with `value` (the model of osdk_movement_control) and `combination`,
    or not `ok` with `error` (`truncated_payload`, `length_mismatch`,
    `undefined_mode`, `out_of_range`, `undecodable`) and `detail`: the
    reference's answer to check_movement_control (conformance/PROTOCOL.md).
    """

    ok: bool
    value: Mapping[str, Any] | None = None
    combination: int | None = None
    error: str | None = None
    detail: str | None = None

    @property
    def setpoints(self) -> dict[str, F32] | None:
        """x, y, z and yaw bit for bit, when the value was accepted."""
        if self.value is None:
            return None
        return {axis: cast(F32, ieee_float(self.value[axis])) for axis in _SETPOINTS}

    def response(self) -> dict[str, Any]:
        """The testee-protocol response a conforming implementation gives."""
        if self.ok:
            return {"ok": True, "result": {"value": self.value, "combination": self.combination}}
        return {"ok": False, "error": self.error, "detail": self.detail}


def classify_control_mode(byte: int, profile: str) -> ControlMode:
    """Classify a control mode byte (0..255) on a profile."""
    _int(byte, "control mode byte", 0xFF)
    _profile(profile)
    result = codec.answer("classify_control_mode", profile, {"byte": byte})["result"]
    found = rules.classify_control_mode(byte, profile)
    return ControlMode(byte=byte, profile=profile, fields=result["fields"],
                       classification=result["classification"], combination=result["combination"],
                       reasons=tuple(found["reasons"]), input_ranges=rules.input_ranges(byte, profile))


def check_movement_control(value: BytesLike, profile: str) -> MovementCheck:
    """Check a movement control value (the 17 bytes after cmd_set and cmd_id)
    on a profile, in the order of conformance/PROTOCOL.md: its length, the
    mode byte (documented on the profile), then x, y (horizontal range),
    z (vertical) and yaw against the combination's limits (inclusive; NaN
    and infinities are always out of range)."""
    raw = _bytes(value, "value")
    _profile(profile)
    response = codec.answer("check_movement_control", profile, {"hex": raw.hex()})
    if response["ok"]:
        res = response["result"]
        return MovementCheck(ok=True, value=res["value"], combination=res["combination"])
    return MovementCheck(ok=False, error=response["error"], detail=response["detail"])


# ---------------------------------------------------------------- a conformance run

@dataclass(frozen=True)
class Capabilities:
    """What a testee said it implements (its answer to `capabilities`)."""

    name: str
    operations: frozenset[str]
    profiles: frozenset[str]


@dataclass(frozen=True)
class CaseResult:
    """One case of a run: a vector (category = its suite), the capabilities
    request, or a failure-list line. `kind` says what sort of failure or skip
    (`mismatch`, `schema_violation`, `testee_timeout`, `op_not_claimed`, ...);
    `details` holds what a report shows for a case that did not pass
    (input, expected, actual, ...)."""

    id: str
    category: str
    status: Status
    message: str = ""
    kind: str = ""
    seconds: float = 0.0
    details: Mapping[str, Any] = field(default_factory=dict, repr=False)

    @property
    def bad(self) -> bool:
        """Whether this case makes the run fail (fail, xpass or error)."""
        return self.status in report.BAD

    @classmethod
    def _of(cls, r: report.Result) -> "CaseResult":
        return cls(r.id, r.category, cast(Status, r.status), r.message, r.kind, r.seconds, r.details)

    def _result(self) -> report.Result:
        return report.Result(self.category, self.id, self.status, self.message, dict(self.details), self.kind,
                             self.seconds)


@dataclass(frozen=True)
class Coverage:
    """The cases of one operation and profile: how many the selection
    offered, how many ran, and why the others did not (reason -> cases)."""

    operation: str
    profile: str | None
    available: int
    ran: int
    skipped: Mapping[str, int]


@dataclass(frozen=True)
class ConformanceRun:
    """The outcome of `run_conformance`, as `osdkc run` reports it.

    `verdict` is CONFORMS, DOES NOT CONFORM or NOTHING RAN; `verdict_line`
    the line `osdkc run` ends with; `exit_status` its exit status (0, 1, 4).
    `conforms`: every case that ran passed; `complete`: every case the
    selection offered ran. `results` holds one CaseResult per case (and for
    the capabilities request or a failure-list line when they failed);
    `coverage` one row per operation and profile.
    """

    testee: str
    command: tuple[str, ...]
    verdict: str
    verdict_line: str
    exit_status: int
    conforms: bool
    complete: bool
    cases: int
    results: tuple[CaseResult, ...]
    coverage: tuple[Coverage, ...]
    capabilities: Capabilities | None
    failure_list: str | None
    aborted: str | None
    seconds: float
    testee_stderr: str = field(default="", repr=False)

    @property
    def statuses(self) -> dict[str, int]:
        """Cases by status, every status present (0 when none)."""
        counts: Counter[str] = Counter(r.status for r in self.results)
        return {st: counts[st] for st in report.STATUSES}

    @property
    def failures(self) -> tuple[CaseResult, ...]:
        """The results that make the run fail."""
        return tuple(r for r in self.results if r.bad)

    def summary(self) -> str:
        """The tables `osdkc run` prints (statuses by category, coverage) and the verdict line."""
        rows = [CoverageRow(c.operation, c.profile, c.available, c.ran, Counter(c.skipped)) for c in self.coverage]
        return "\n\n".join([report.summary_table([r._result() for r in self.results]),
                            "coverage (cases run / available):\n" + coverage_table(rows), self.verdict_line])


def bundled_implementations() -> tuple[str, ...]:
    """The bundled implementations `run_conformance(impl=...)` can start
    here: all seven in a checkout (the compiled ones once `make setup` built
    them); when installed, the two Python ones (construct, kaitai-python) and
    the accelerator's (accel) if it was compiled at install."""
    return tuple(available_impls()[0])


def _load(paths: Sequence[str | os.PathLike[str]] | None) -> list[Case]:
    try:
        return load_checked_cases([os.fspath(p) for p in paths] if paths is not None else None)
    except UsageError as e:
        raise InputError(str(e)) from None
    except Exception as e:  # a vector file that is not what it should be is the caller's input, as in osdkc run
        raise InputError(f"cannot load the vectors: {type(e).__name__}: {one_line(e)}") from None


def run_conformance(testee: str | Sequence[str] | None = None, *, impl: str | None = None,
                    profiles: Sequence[str] | None = None, filter: str | None = None,  # noqa: A002 - osdkc's word
                    vectors: Sequence[str | os.PathLike[str]] | None = None,
                    failure_list: str | os.PathLike[str] | None = None,
                    timeout: float = DEFAULT_TIMEOUT, memory_mb: int = DEFAULT_MEMORY_MB) -> ConformanceRun:
    """Replay the golden vectors against a testee: `osdkc run` for one implementation.

    Give `testee`, the command that starts an implementation speaking
    conformance/PROTOCOL.md (a shell-like string or an argv list), or
    `impl`, a bundled implementation (`bundled_implementations()`).
    `profiles` and `filter` (a substring of the case id) select cases as
    `--profile` and `--filter` do; `vectors` replaces vectors/*.json (each
    file validated as `osdkc vectors check` does); `failure_list` names
    known failures (for `impl`, its reviewed list is used when none is
    given). `timeout` is per request in seconds, `memory_mb` the testee's
    address-space limit (0: none). The testee is stopped when the run ends,
    also when it is interrupted (KeyboardInterrupt propagates); no signal
    handler is installed.
    """
    if (testee is None) == (impl is None):
        raise InputError("give either a testee command or impl, the name of a bundled implementation")
    if testee is not None and not isinstance(testee, str) and not (
            isinstance(testee, Sequence) and all(isinstance(a, (str, os.PathLike)) for a in testee)):
        raise InputError(f"testee must be a command line or a list of its words, got {testee!r}")
    if not positive_float.accepts(timeout):
        raise InputError(f"timeout must be a finite number of seconds > 0, got {timeout!r}")
    if isinstance(memory_mb, bool) or not isinstance(memory_mb, int) or not non_negative_int.accepts(memory_mb):
        raise InputError(f"memory_mb must be an integer >= 0, got {memory_mb!r}")
    for p in profiles or ():
        _profile(p)
    try:
        argv = impl_argv(impl) if impl is not None else testee
    except UsageError as e:
        raise InputError(str(e)) from None
    if failure_list is None and impl is not None and default_failure_list(impl).exists():
        failure_list = default_failure_list(impl)
    list_name = os.fspath(failure_list) if failure_list is not None else None
    try:
        listed = read_failure_list(failure_list) if failure_list is not None else {}
    except UsageError as e:
        raise InputError(str(e)) from None

    all_cases = _load(vectors)
    cases = select_cases(all_cases, profiles, filter)
    if not cases:
        raise InputError("no vector matches the profiles / filter selection")

    try:
        runner = Testee(cast("str | Sequence[str]", argv), timeout=timeout, memory_mb=memory_mb)
        try:
            runner.start()
            outcome = run_cases(runner, cases, judge)
        finally:
            runner.close()
    except TesteeStartError as e:
        raise InputError(str(e)) from None

    results = apply_failure_list(outcome.results, listed, {c.id for c in all_cases}, list_name or "failure list")
    rows = coverage_rows(cases, results, no_result_reason(outcome))
    verdict = verdict_of(results, rows, outcome.interrupted)
    caps = outcome.capabilities
    return ConformanceRun(
        testee=caps.name if caps and caps.name else " ".join(runner.argv),
        command=tuple(runner.argv),
        verdict=verdict.word, verdict_line=verdict.line, exit_status=verdict.exit,
        conforms=verdict.conforms, complete=verdict.complete, cases=len(cases),
        results=tuple(CaseResult._of(r) for r in results),
        coverage=tuple(Coverage(r.operation, r.profile, r.available, r.ran, dict(sorted(r.skipped.items())))
                       for r in rows),
        capabilities=Capabilities(caps.name, caps.operations, caps.profiles) if caps else None,
        failure_list=list_name, aborted=outcome.aborted, seconds=outcome.seconds,
        testee_stderr=outcome.testee_stderr)



# ---------------------------------------------------------------- the simulator

# Seconds the simulator's loop may take to notice it is asked to stop: it
# waits at most 0.1 s for its port, so this is only reached when it hangs.
_STOP_TIMEOUT = 10.0


class RunningSimulator:
    """A simulated flight controller running in this process (see `simulator`).

    `url` is the pseudo-terminal a client opens, with pyserial
    (`serial.Serial(url)` or `serial.serial_for_url(url)`) or as a file.
    """

    def __init__(self, sim: Simulator, transport: PtyTransport, profile: str) -> None:
        self._sim = sim
        self.url: str = transport.url
        self.profile: str = profile

    def stats(self) -> dict[str, Any]:
        """Its counters so far: frames and bytes sent, broadcasts, ACKs,
        commands received and rejected, faults injected, planted bugs triggered (as `osdkc sim --stats`)."""
        return {k: dict(v) if isinstance(v, dict) else list(v) if isinstance(v, list) else v
                for k, v in self._sim.stats.items()}

    def authority(self) -> dict[str, Any]:
        """Who has control (`rc` or `onboard`), whether it was activated, and the broadcast rates now."""
        return self._sim.authority_state()

    def restart(self, timeout: float = 2.0) -> None:
        """Restart it, as `osdkc sim` on SIGHUP: a power cycle that brings a
        hung simulator back. It loses what a reboot loses (SEQ, time stamp,
        activation, control authority, rates, pending commands, bytes not yet
        sent) and what planted bugs did (a hang, a wedged command handler;
        their record in the stats stays), and is deaf and silent for 0.3 s
        before it broadcasts again. Returns once it has restarted, which
        `stats()["restarts"]` counts; raises RuntimeError if it has not within
        `timeout` seconds (a stopped simulator does not), InputError for a
        timeout that is not a number of seconds > 0."""
        if isinstance(timeout, bool) or not isinstance(timeout, (int, float)) or not positive_float.accepts(timeout):
            raise InputError(f"timeout must be a finite number of seconds > 0, got {timeout!r}")
        wanted = self._sim.request_restart()
        end = time.monotonic() + timeout
        while self._sim.restart_requests_done < wanted:
            if time.monotonic() >= end:
                raise RuntimeError(f"the simulator did not restart within {timeout:g} s")
            time.sleep(0.005)

    def __repr__(self) -> str:
        return f"RunningSimulator(url={self.url!r}, profile={self.profile!r})"


def _sim_config(profile: str, seed: int | None, rates: Mapping[str, int] | None, rc_mode: str,
                app_id: int | None, key: bytes | None, encrypt: bool, faults: Mapping[str, float] | None,
                implausible: bool, wrong_profile: str | None, bugs: Sequence[str]) -> SimConfig:
    items = rules.profile(_profile(profile)).flag_bits
    hz = sorted(set(rules.hz_of_code().values()))
    for item, rate in (rates or {}).items():
        if item not in items or rate not in hz or isinstance(rate, bool):
            raise InputError(f"rates: {item}={rate!r}: want an item of {profile} ({', '.join(items)}) "
                             f"and a rate in Hz of {', '.join(map(str, hz))}")
    if rc_mode not in RC_MODE:
        raise InputError(f"rc_mode must be one of {', '.join(RC_MODE)}, got {rc_mode!r}")
    if seed is not None:
        _int(seed, "seed", 2**63 - 1)
    if app_id is not None:
        _int(app_id, "app_id", 0xFFFFFFFF)
    if key is not None and (not isinstance(key, bytes) or len(key) != 32):
        raise InputError("key must be the 32 bytes of the AES-256 app key")
    if encrypt and key is None:
        raise InputError("encrypt needs the key")
    for name, p in (faults or {}).items():
        if name not in FAULTS or isinstance(p, bool) or not isinstance(p, (int, float)) or not probability.accepts(p):
            raise InputError(f"faults: {name}={p!r}: want one of {', '.join(FAULTS)} and a probability 0..1")
    if wrong_profile is not None:
        _profile(wrong_profile)
    if isinstance(bugs, str) or any(b not in BUGS for b in bugs):
        raise InputError(f"bugs: {bugs!r}: want a list of names of {', '.join(BUGS)}")
    return SimConfig(profile=profile, seed=seed, app_id=app_id, key=key, encrypt=encrypt, rc_mode=rc_mode,
                     faults=dict(faults or {}), implausible=implausible, wrong_profile=wrong_profile,
                     rates=dict(rates) if rates else None, bugs=tuple(dict.fromkeys(bugs)))


@contextmanager
def simulator(profile: str = SimConfig.profile, *, seed: int | None = None, rates: Mapping[str, int] | None = None,
              rc_mode: str = "F", app_id: int | None = None, key: bytes | None = None, encrypt: bool = False,
              faults: Mapping[str, float] | None = None, implausible: bool = False,
              wrong_profile: str | None = None, bugs: Sequence[str] = ()) -> Iterator[RunningSimulator]:
    """`osdkc sim` in a background thread of this process, on a pseudo-terminal.

    Yields a RunningSimulator whose `url` a client opens; the simulator
    broadcasts flight data at once and answers commands as `osdkc sim`
    does. On leaving the block, also by an exception, it is stopped and
    its pseudo-terminal closed (close your own port inside the block). An
    exception of the simulator's own thread is raised then, as RuntimeError.

    `rates` sets initial broadcast rates (item -> Hz: 0, 1, 10, 50 or 100);
    `rc_mode` the RC switch (obtaining control needs F); `app_id` the only
    app id activation accepts (default: any); `key` the AES-256 app key and
    `encrypt` whether every frame sent is encrypted (all but the version
    and activation ACKs, which no DJI host can read before it is activated:
    ERRATA E30); `faults` a probability per broadcast frame for each fault (noise, bitflip, drop_bytes,
    truncate, bad_crc, duplicate), reproducible with `seed`; `implausible`
    broadcasts implausible values; `wrong_profile` broadcasts in another
    profile's layout; `bugs` plants firmware bugs (`osdkc sim --bug`,
    docs/ACCEPTANCE.md), which the stats record when they trigger.
    """
    cfg = _sim_config(profile, seed, rates, rc_mode, app_id, key, encrypt, faults, implausible, wrong_profile,
                      bugs)
    try:
        transport = PtyTransport()
    except OSError as e:
        raise InputError(f"cannot open a pseudo-terminal: {e.strerror or e}") from None
    failed: list[BaseException] = []
    try:
        sim = Simulator(cfg, transport)

        def loop() -> None:
            try:
                sim.run()
            except BaseException as e:  # reported when the block ends, not lost in the thread
                failed.append(e)

        thread = threading.Thread(target=loop, name="osdkc-sim", daemon=True)
        thread.start()
        body_ok = False
        try:
            yield RunningSimulator(sim, transport, profile)
            body_ok = True
        finally:
            sim.running = False
            thread.join(_STOP_TIMEOUT)
            if thread.is_alive() and body_ok:
                raise RuntimeError(f"the simulator did not stop within {_STOP_TIMEOUT:g} s")
            if failed and body_ok:
                raise RuntimeError(f"the simulator failed: {type(failed[0]).__name__}: "
                                   f"{one_line(failed[0])}") from failed[0]
    finally:
        transport.close()


# ---------------------------------------------------------------- a host judged from a capture


def write_capture(path: str | os.PathLike[str], records: Iterable[tuple[str, float, BytesLike]], *,
                  comment: Mapping[str, Any] | None = None) -> int:
    """Record (direction, time in s, bytes) triples in a pcapng capture of
    the kit's format: "tx" the host's bytes (sent to the flight controller),
    "rx" the flight controller's. Returns how many records were written.
    What `osdkc tap`, `osdkc device --replay` and `osdkc decode` read; a
    host's own log turned into one can be judged by `judge_tap_capture`."""
    rows = []
    for n, rec in enumerate(records):
        try:
            direction, t, data = rec
        except (TypeError, ValueError):
            raise InputError(f"record {n}: want (direction, time, bytes), got {rec!r}") from None
        if direction not in ("rx", "tx"):
            raise InputError(f"record {n}: direction must be 'rx' or 'tx', got {direction!r}")
        if not isinstance(t, (int, float)) or isinstance(t, bool) or t != t or t in (float("inf"), float("-inf")) or t < 0:
            raise InputError(f"record {n}: time must be a finite number of seconds >= 0, got {t!r}")
        rows.append((RX if direction == "rx" else TX, round(t * 1e9), _bytes(data, f"record {n}")))
    writer = CaptureWriter(os.fspath(path), dict(comment or {"tool": "osdk_conformance.api.write_capture"}))
    try:
        for direction, ts, data in rows:
            writer.record(direction, data, ts)
    finally:
        writer.close()
    return len(rows)


@dataclass(frozen=True)
class TapCheck:
    """One check of `osdkc tap`: `id` (host.cadence, pair.unanswered, stream.rates, ...), its `category`
    (host, pair, fc.link, fc.stream, ...), `status` and what was found."""

    id: str
    category: str
    status: Status
    message: str
    kind: str = ""


@dataclass(frozen=True)
class TapReport:
    """What `osdkc tap --replay` says of a capture: `verdict` PASS or FAIL,
    every check, and what the host sent."""

    verdict: str
    checks: tuple[TapCheck, ...]
    commands: tuple[str, ...]               # the host's commands that want an answer, in order
    movement_commands: int
    mode_bytes: dict[int, int]              # movement control mode byte -> how many

    def failed(self, category: str | None = None) -> list[str]:
        """The ids of the checks that failed (of one category, or of a group: "host", "pair", "fc")."""
        return [c.id for c in self.checks if c.status in ("fail", "error")
                and (category is None or c.category == category or c.category.startswith(category + "."))]


def judge_tap_capture(path: str | os.PathLike[str], profile: str, *, key: bytes | None = None,
                      min_movement_hz: float = 10.0, max_movement_gap: float = 0.5) -> TapReport:
    """Every check of `osdkc tap` on a recorded session: the host's
    commands, the exchange of host and flight controller, and the flight
    controller's passive checks (docs/TAP.md). OSError when the file cannot
    be read; InputError when it is not a capture or is damaged."""
    _profile(profile)
    if key is not None and (not isinstance(key, (bytes, bytearray)) or len(key) != 32):
        raise InputError("key must be 32 bytes (the app key)")
    for name, v in (("min_movement_hz", min_movement_hz), ("max_movement_gap", max_movement_gap)):
        try:
            positive_float(str(v))
        except Exception:
            raise InputError(f"{name} must be a finite number > 0, got {v!r}") from None
    opts = _TapOptions(device=_DeviceOptions(profile=profile), min_movement_hz=float(min_movement_hz),
                       max_movement_gap=float(max_movement_gap))
    try:
        judged = _judge_capture(os.fspath(path), opts, bytes(key) if key else None)
    except CaptureError as e:
        raise InputError(str(e)) from None
    checks = tuple(TapCheck(r.id, r.category, cast(Status, r.status), r.message, r.kind) for r in judged.results)
    modes: Counter[int] = Counter(m.mode for m in judged.judge.moves)
    return TapReport(acceptance_word(report.conforms(judged.results), None), checks,
                     tuple(c.name for c in judged.judge.commands), len(judged.judge.moves), dict(modes))
