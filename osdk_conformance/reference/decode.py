"""`osdkc decode`: frames and errors in a byte stream, as JSON lines.

Deframing follows the SDK receiver (deframe.py); each intact frame is then
decoded with the Construct spec for the chosen profile and printed in the
JSON value model (docs/VALUE-MODEL.md). ACK values are decoded when the
same stream, or with --direction both the capture's sent bytes, carried the
command they answer: the one command waiting in the ACK's session (2..31)
with the ACK's SEQ, as DJI's receivers match them (ERRATA E32).

That is the reference, `decode_events`. What `osdkc decode`, the Python
API and the acceptance receiver run (`stream_events`, `payload_body`) is the
native accelerator when it is installed (accel.py; OSDKC_ACCEL chooses),
which gives the same events.
"""
from __future__ import annotations

import argparse
import functools
import re
import sys
import threading
from itertools import chain
from typing import IO, Any, Callable, Iterable, Iterator, NamedTuple, Sequence

import construct

from osdk_conformance.core import model
from osdk_conformance.core.capture import CaptureError, CaptureReader, NAMES, is_pcapng
from osdk_conformance.core.commands import command_name
from osdk_conformance.core.deframe import Deframer, Frame, Garbage, Rejected, deframe, header_fields
from osdk_conformance.core.errors import UsageError, cannot_read, one_line
from osdk_conformance.reference import accel, fastframe, values
from osdk_conformance.core.rules import profile as load_profile
from osdk_construct.compiled import parse
from osdk_construct.enums import profile_value
from osdk_construct.frame import build_frame, osdk_frame, parse_frame
from osdk_construct.payload import BODY_BY_KEY, broadcast, payload

READ_SIZE = 64 * 1024

# Which spec rule a failed check enforces, by the name of the field it guards.
FIELD_ERRORS = {
    "ver": "bad_version",
    "res0": "reserved_bits",
    "res1": "reserved_bits",
    "reserved_flags": "reserved_bits",
    "len": "impossible_length",
    "enc": "bad_encryption",
    "padding": "bad_encryption",
    "is_ack": "bad_session",
    "session": "bad_session",
}


def classify(exc: construct.ConstructError) -> str:
    """The error class (docs/VALUE-MODEL.md) of a Construct parse failure."""
    if isinstance(exc, construct.StreamError):
        return "truncated_payload"
    if isinstance(exc, construct.TerminatedError):
        return "length_mismatch"
    path = getattr(exc, "path", None) or ""
    names = re.findall(r"[a-z_][a-z0-9_]*", path.split("->")[-1]) if path else []
    for name in reversed(names):
        name = name.removeprefix("_valid_")  # osdk_construct's named checks
        if name in FIELD_ERRORS:
            return FIELD_ERRORS[name]
    text = str(exc)
    for name, cls in FIELD_ERRORS.items():
        if re.search(rf"\b{name}\b", text):
            return cls
    return "undecodable"


class Decoder:
    def __init__(self, profile: str) -> None:
        self._parse_frame = parse_frame
        self._payload = payload
        self.profile = profile
        self._model = model.from_construct
        self._slots: dict[int, tuple[int, int, int]] = {}  # session 2..31 -> (seq, set, id) of the command waiting
        self._fast = _fast_frames(profile)

    def event(self, ev: Frame | Rejected | Garbage) -> dict:
        if isinstance(ev, Garbage):
            return {"offset": ev.offset, "kind": "garbage", "length": ev.length}
        if isinstance(ev, Rejected):
            return {"offset": ev.offset, "kind": "error", "error": ev.error, "detail": ev.detail, "length": ev.length}
        try:
            return self._frame(ev)
        except Exception as e:  # a bug of ours must not cost the user the rest of the stream
            return {"offset": ev.offset, "kind": "error", "error": "undecodable",
                    "detail": f"internal error ({type(e).__name__}: {one_line(e)}); please report it with this frame",
                    "length": len(ev.raw), "raw": ev.raw.hex()}

    def _frame(self, ev: Frame) -> dict:
        fast = self._fast
        if fast is not None:
            known = fast.lookup(ev.raw)
            if known is not None:
                frame = known.convert(ev.raw)
                if frame is not None:
                    self._expect_ack(known.session, frame["seq"], known.cmd)
                    return {"offset": ev.offset, "kind": "frame", "command": known.command, "frame": frame}
        try:
            parsed = self._parse_frame(ev.raw, self.profile)
        except construct.ConstructError as e:
            return {"offset": ev.offset, "kind": "error", "error": classify(e),
                    "detail": one_line(e), "length": len(ev.raw), "frame_header": header_fields(ev.raw)}
        out: dict[str, Any] = {"offset": ev.offset, "kind": "frame"}
        frame = self._model(parsed)
        data = parsed.get("data")
        cmd = self._take_ack(parsed.session, parsed.seq) if parsed.is_ack and (parsed.len == 12 or isinstance(data, dict)) else None
        if cmd is not None:  # a header-only ACK too: its value is empty
            out["ack_of"] = command_name(*cmd)
            try:
                out["ack"] = self._model(self._payload(*cmd, True, self.profile).parse(
                    b"" if parsed.len == 12 else data.ack_value))["body"]
            except construct.ConstructError as e:
                return {"offset": ev.offset, "kind": "error", "error": classify(e), "detail": one_line(e),
                        "length": len(ev.raw), "frame_header": header_fields(ev.raw), "ack_of": out["ack_of"]}
        elif parsed.len == 12:
            out["command"] = "none"
        elif not isinstance(data, dict):
            out["command"] = "encrypted"
        elif parsed.is_ack:
            out["command"] = "ack"
        else:
            cmd = (int(data.cmd_set), data.cmd_id)
            out["command"] = command_name(*cmd)
            self._expect_ack(parsed.session, parsed.seq, cmd)
        out["frame"] = frame
        return out

    def _expect_ack(self, session: int, seq: int, cmd: tuple[int, int]) -> None:
        """A plain command that decoded takes its session's slot (sessions 2..31; 0 and 1 have none)."""
        if session in accel.ACK_SESSIONS:
            self._slots[session] = (seq, *cmd)

    def _take_ack(self, session: int, seq: int) -> tuple[int, int] | None:
        """The command a plain ACK answers, taken out of its session's slot: the one waiting there with its SEQ."""
        waiting = self._slots.get(session)
        if waiting is None or waiting[0] != seq:
            return None
        del self._slots[session]
        return waiting[1:]


class _Known(NamedTuple):
    """A command frame layout with a converter straight to its model (fastframe.py)."""

    convert: Callable[[bytes], dict | None]
    command: str
    cmd: tuple[int, int]
    session: int


class _FastFrames:
    """The fast converters of one profile's frames, by the bytes that decide their layout.

    Those bytes are the ones the layout of a broadcast frame consults
    (fastframe.specialize): the header's start byte and bit fields, the
    command set and id, the flag word. A layout gets its converter when its
    bytes have come COMPILE_AFTER + 1 times (a one-off layout, as random
    data makes, is cheaper to interpret), and only when the frame is a
    plain broadcast (not an ACK, encrypted, header-only or another
    command), its converter consulted no other bytes, and it gives for that
    frame the model the interpreter gives. Any other frame, and any frame
    of a layout refused, is the interpreter's: so are all errors."""

    COMPILE_AFTER = 2
    MAX_LAYOUTS = 4096
    """Layouts kept, compiled or refused; then they are forgotten, all at once."""
    MAX_COMPILED = 256
    """Compiled layouts among them (some 14 kB each); later ones are refused until then.
    A capture has a few: one per flag word its item rates make, in each session."""

    def __init__(self, profile: int) -> None:
        self.profile = profile
        self.frame = osdk_frame(profile)
        k = next(k for k, body in BODY_BY_KEY.items() if body is broadcast)
        cmd_set, cmd_id = self.cmd = (k >> 8 & 0xFF, k & 0xFF)
        data = values.broadcast_data(profile, values.items(profile), {})
        sample = build_frame(cmd_set=cmd_set, cmd_id=cmd_id,
                             value=payload(cmd_set, cmd_id, False, profile).build({"body": {"data": data}}))
        found = fastframe.specialize(self.frame, sample)
        _event_fields(found.context)
        self.positions = frozenset(found.consulted)
        self.key = fastframe.key_function(self.positions)
        self.known: dict[bytes, _Known | None] = {}
        self.seen: dict[bytes, int] = {}
        self.compiled = 0
        self.lock = threading.Lock()

    def lookup(self, raw: bytes) -> _Known | None:
        key = self.key(raw)
        try:
            return self.known[key]
        except KeyError:
            pass
        with self.lock:
            if key in self.known:
                return self.known[key]
            if len(self.known) >= self.MAX_LAYOUTS:
                self.known.clear()  # bounded; the layouts still in use are compiled again
                self.compiled = 0
            if len(self.seen) >= 4 * self.MAX_LAYOUTS:
                self.seen.clear()
            uses = self.seen[key] = self.seen.get(key, 0) + 1
            if uses <= self.COMPILE_AFTER:
                return None
            try:
                known = self._compile(raw) if self.compiled < self.MAX_COMPILED else None
            except fastframe.Short:
                return None  # this frame is cut short, not its layout: the next one may do
            del self.seen[key]
            self.known[key] = known
            self.compiled += known is not None
            return known

    def _compile(self, raw: bytes) -> _Known | None:
        try:
            parsed = parse_frame(raw, self.profile)
        except construct.ConstructError:
            try:
                fastframe.specialize(self.frame, raw, self.positions)  # Short: only this frame is cut short
            except fastframe.Short:
                raise
            except fastframe.NotFast:
                pass
            return None
        data = parsed.get("data")
        if parsed.len == 12 or not isinstance(data, dict) or parsed.is_ack:
            return None
        cmd = (int(data.cmd_set), data.cmd_id)
        if cmd != self.cmd:
            # Other commands' layouts would be keyed by their values' first
            # bytes too: one layout per value, each compiled for a few frames.
            return None
        try:
            found = fastframe.specialize(self.frame, raw, self.positions)
        except fastframe.NotFast:
            return None
        _event_fields(found.context)
        if not found.consulted <= self.positions:
            return None
        got = found.convert(raw)
        if got is None or model.dumps(got) != model.dumps(model.from_construct(parsed)):
            return None
        return _Known(found.convert, command_name(*cmd), cmd, parsed.session)


def _event_fields(context: Any) -> None:
    """Read, through a specialisation's context, the fields Decoder._frame
    takes from a parsed frame besides its model, so that they count as
    consulted: a fast layout must fix them."""
    data = context["data"]
    context["len"], context["is_ack"], context["session"], data["cmd_set"], data["cmd_id"]  # noqa: B018 - read for the trace


@functools.lru_cache(maxsize=None)
def _fast_frames_of(value: int) -> _FastFrames | None:
    try:
        return _FastFrames(value)
    except (fastframe.NotFast, LookupError, ValueError, construct.ConstructError):
        return None  # a profile whose broadcast this cannot specialise: all its frames are interpreted


def _fast_frames(profile: str) -> _FastFrames | None:
    try:
        value = profile_value(profile)
    except (ValueError, KeyError):
        return None
    return _fast_frames_of(value)


def parse_hex(text: str) -> bytes:
    cleaned = re.sub(r"[\s:,]", "", text)
    if cleaned.lower().startswith("0x"):
        cleaned = cleaned[2:]
    try:
        return bytes.fromhex(cleaned)
    except ValueError:
        raise UsageError("--hex: not a hex string (pairs of 0-9a-f, optionally separated by spaces or colons)") from None


def read_chunks(stream: IO[bytes]) -> Iterator[bytes]:
    while chunk := stream.read(READ_SIZE):
        yield chunk


def capture_pieces(chunks: Iterable[bytes], directions: frozenset[str] = frozenset({"rx"}),
                   name: str = "capture") -> Iterator[tuple[str, bytes]]:
    """(direction, bytes) in input order: the chunks as they are, all "rx",
    or, when they form a pcapng capture (osdkc device --capture; detected by
    the Section Header Block magic), the records of the wanted directions,
    read block by block. A capture that cannot be read is a UsageError naming
    `name` and the byte offset; an incomplete last block (a killed writer)
    is left out, as it is in `osdkc device --replay`."""

    it = iter(chunks)
    first = next(it, b"")
    if not is_pcapng(first):
        if directions != {"rx"}:
            raise UsageError(f"{name}: raw bytes hold only what was received; "
                             "--direction tx or both needs a pcapng capture (osdkc device --capture)")
        if first:
            yield "rx", first
        for chunk in it:
            yield "rx", chunk
        return
    reader = CaptureReader(chain([first], it), name)
    try:
        for rec in reader:
            if NAMES[rec.direction] in directions:
                yield NAMES[rec.direction], rec.data
    except CaptureError as e:
        raise UsageError(str(e)) from None


def received_bytes(chunks: Iterable[bytes], name: str = "capture") -> Iterator[bytes]:
    """The bytes received from the flight controller: the chunks, or a capture's rx records."""
    return (data for _, data in capture_pieces(chunks, frozenset({"rx"}), name))


def decode_events(chunks: Iterable[bytes], profile: str) -> Iterator[dict]:
    decoder = Decoder(profile)
    for ev in deframe(chunks):
        yield decoder.event(ev)


def both_directions_events(chunks: Iterable[bytes], profile: str, name: str) -> Iterator[dict]:
    """The events of both directions of a capture, each marked with its
    direction, in capture order. Each direction is deframed on its own (its
    offsets count its own bytes); one decoder sees both, so an ACK the flight
    controller sent is matched with the command the host sent."""
    decoder = Decoder(profile)
    deframers = {"rx": Deframer(), "tx": Deframer()}
    for direction, data in capture_pieces(chunks, frozenset(deframers), name):
        for ev in deframers[direction].feed(data):
            yield {"direction": direction, **decoder.event(ev)}
    for direction, d in deframers.items():
        for ev in d.finish():
            yield {"direction": direction, **decoder.event(ev)}


def stream_events(chunks: Iterable[bytes], profile: str, direction: str = "rx", name: str = "input") -> Iterator[dict]:
    """What `osdkc decode` prints for --direction rx, tx or both: the native
    decoder's events when it is to run (accel.py), else the reference's."""
    native = accel.stream(profile)
    if direction == "both":
        if native is None:
            return both_directions_events(chunks, profile, name)
        return _native_both(native, capture_pieces(chunks, frozenset({"rx", "tx"}), name))
    pieces = capture_pieces(chunks, frozenset({direction}), name)
    if native is None:
        return decode_events((data for _, data in pieces), profile)
    return accel.events((data for _, data in pieces), native)


def _native_both(native: accel.NativeStream, pieces: Iterable[tuple[str, bytes]]) -> Iterator[dict]:
    # as both_directions_events: one receiver per direction, one ACK table, rx finished first
    for direction, data in pieces:
        yield from native.feed(data, direction)
    for direction in ("rx", "tx"):
        yield from native.finish(direction)


class DecodeFailure(ValueError):
    """A payload the decoder rejected: its error class (docs/VALUE-MODEL.md) and a detail for people."""

    def __init__(self, error_class: str, detail: str) -> None:
        super().__init__(f"{error_class}: {detail}")
        self.error_class = error_class
        self.detail = detail


def payload_body(profile: str) -> Callable[[bytes, int, int, bool], dict]:
    """A function giving the model of a payload's body (docs/VALUE-MODEL.md)
    for (value, cmd_set, cmd_id, is_ack), raising DecodeFailure: the native
    decoder when it is to run, else the Construct spec."""
    module = accel.native()
    if module is not None:
        value = load_profile(profile).value

        def native_body(data: bytes, cmd_set: int, cmd_id: int, is_ack: bool) -> dict:
            try:
                return module.decode_payload(data, cmd_set, cmd_id, is_ack, value)["body"]
            except module.DecodeError as e:
                raise DecodeFailure(*e.args) from None
        return native_body

    def construct_body(data: bytes, cmd_set: int, cmd_id: int, is_ack: bool) -> dict:
        try:
            return model.from_construct(parse(payload(cmd_set, cmd_id, is_ack, profile), data))["body"]
        except construct.ConstructError as e:
            raise DecodeFailure(classify(e), one_line(e)) from None
    return construct_body


def add_arguments(d: argparse.ArgumentParser, profiles: Sequence[str]) -> None:
    d.add_argument("--profile", required=True, choices=profiles, help="broadcast wire profile of the flight controller")
    src = d.add_mutually_exclusive_group(required=True)
    src.add_argument("--hex", help="the bytes as hex (spaces and colons allowed)")
    src.add_argument("file", nargs="?", help="a file of raw bytes or a pcapng capture (osdkc device), or - for standard input")
    d.add_argument("--direction", choices=("rx", "tx", "both"), default="rx",
                   help="of a capture: bytes received (default), sent, or both, each event marked with its direction")
    d.add_argument("--pretty", action="store_true", help="indent each JSON object")


def run_decode(args: argparse.Namespace) -> int:
    name = args.file if args.file not in (None, "-") else "--hex" if args.hex is not None else "standard input"
    if args.hex is not None:
        source: Iterable[bytes] = [parse_hex(args.hex)]
        close = None
    elif args.file == "-":
        source, close = read_chunks(sys.stdin.buffer), None
    elif args.file:
        try:
            fh = open(args.file, "rb")
        except OSError as e:
            raise UsageError(cannot_read(args.file, e)) from None
        source, close = read_chunks(fh), fh
    else:
        raise UsageError("give --hex HEX, a FILE, or - for standard input")
    errors = 0
    indent = 2 if args.pretty else None
    try:
        for ev in stream_events(source, args.profile, args.direction, name):
            if ev["kind"] == "error":
                errors += 1
            sys.stdout.write(model.dumps(ev, indent=indent) + "\n")
    except BrokenPipeError:
        raise
    except OSError as e:
        raise UsageError(f"reading failed: {e.strerror or e}") from None
    finally:
        if close:
            close.close()
    sys.stdout.flush()
    return 1 if errors else 0
