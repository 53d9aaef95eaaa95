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

What a file or standard input holds besides frames is said on standard
error after the events (`Tally`): where the recording stopped inside a frame
(that truncated_frame, and the rescan of its bytes, are marked
`"capture_end": true` and not counted as errors: `mark_capture_end`), a
pcapng block cut at the end, no frame at all, and the profile the
broadcasts decode with when most do not decode with --profile.
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
from osdk_conformance.core.deframe import (HEADER_LEN, MAX_LEN, Deframer, Frame, Garbage, Rejected, deframe,
                                           frame_length, header_fields)
from osdk_conformance.core.errors import UsageError, cannot_read, one_line
from osdk_conformance.reference import accel, fastframe, values
from osdk_conformance.core.rules import profile as load_profile, profile_names
from osdk_conformance._construct.compiled import parse
from osdk_conformance._construct.enums import profile_value
from osdk_conformance._construct.frame import build_frame, osdk_frame, parse_frame
from osdk_conformance._construct.payload import BODY_BY_KEY, broadcast, payload

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


class InputSeen:
    """What `osdkc decode` read, noted as it went by, for what it says after
    the events: the input's size, whether it was a pcapng capture and how
    much of a block cut at its end it holds, and each direction's byte count
    with its latest bytes. The bytes of any event are among those latest
    bytes when the event comes: the events of a piece come before the next
    piece is read, and the deframer holds back less than one longest frame
    (MAX_LEN bytes) from the pieces before."""

    def __init__(self) -> None:
        self.size = 0                        # bytes of the input: the file's, standard input's
        self.pcapng = False
        self.cut_block = 0                   # bytes of an incomplete last pcapng block
        self.received: dict[str, int] = {}   # bytes decoded, by direction
        self._latest: dict[str, bytearray] = {}

    def count(self, chunks: Iterable[bytes]) -> Iterator[bytes]:
        for chunk in chunks:
            self.size += len(chunk)
            yield chunk

    def piece(self, direction: str, data: bytes) -> None:
        latest = self._latest.setdefault(direction, bytearray())
        latest += data
        del latest[:max(0, len(latest) - len(data) - MAX_LEN)]  # bounded: this piece and one frame before it
        self.received[direction] = self.received.get(direction, 0) + len(data)

    def bytes_at(self, direction: str, offset: int, length: int) -> bytes | None:
        """Bytes [offset, offset + length) of a direction, when they are among its latest; else None."""
        latest = self._latest.get(direction, bytearray())
        start = offset - (self.received.get(direction, 0) - len(latest))
        if start < 0 or start + length > len(latest):
            return None
        return bytes(latest[start:start + length])

    def reaches_end(self, direction: str, ev: dict) -> bool:
        """Whether an event's bytes run to the end of its direction's input."""
        return ev["offset"] + ev.get("length", 0) == self.received.get(direction, 0)


def capture_pieces(chunks: Iterable[bytes], directions: frozenset[str] = frozenset({"rx"}),
                   name: str = "capture", seen: InputSeen | None = None) -> Iterator[tuple[str, bytes]]:
    """(direction, bytes) in input order: the chunks as they are, all "rx",
    or, when they form a pcapng capture (osdkc device --capture; detected by
    the Section Header Block magic), the records of the wanted directions,
    read block by block. A capture that cannot be read is a UsageError naming
    `name` and the byte offset; an incomplete last block (a killed writer)
    is left out, as it is in `osdkc device --replay`, and noted in `seen`
    (when given, it notes everything that goes by: InputSeen)."""
    return ((direction, data) for direction, data, _ in timed_pieces(chunks, directions, name, seen))


def timed_pieces(chunks: Iterable[bytes], directions: frozenset[str] = frozenset({"rx"}),
                 name: str = "capture", seen: InputSeen | None = None) -> Iterator[tuple[str, bytes, int | None]]:
    """capture_pieces with each piece's capture time: (direction, bytes,
    nanoseconds since the Unix epoch), the time the pcapng record carries
    (when the kit's recorder read those bytes from the port); None for raw
    bytes, which carry no time."""
    if seen is None:
        yield from _pieces(chunks, directions, name, InputSeen())
        return
    for direction, data, ts_ns in _pieces(seen.count(chunks), directions, name, seen):
        seen.piece(direction, data)
        yield direction, data, ts_ns


def _pieces(chunks: Iterable[bytes], directions: frozenset[str], name: str,
            seen: InputSeen) -> Iterator[tuple[str, bytes, int | None]]:
    it = iter(chunks)
    first = next(it, b"")
    if not is_pcapng(first):
        if directions != {"rx"}:
            raise UsageError(f"{name}: raw bytes hold only what was received; "
                             "--direction tx or both needs a pcapng capture (osdkc device --capture)")
        if first:
            yield "rx", first, None
        for chunk in it:
            yield "rx", chunk, None
        return
    seen.pcapng = True
    reader = CaptureReader(chain([first], it), name)
    try:
        for rec in reader:
            if NAMES[rec.direction] in directions:
                yield NAMES[rec.direction], rec.data, rec.ts_ns
    except CaptureError as e:
        raise UsageError(str(e)) from None
    seen.cut_block = reader.partial_tail


def received_bytes(chunks: Iterable[bytes], name: str = "capture") -> Iterator[bytes]:
    """The bytes received from the flight controller: the chunks, or a capture's rx records."""
    return (data for _, data in capture_pieces(chunks, frozenset({"rx"}), name))


def decode_events(chunks: Iterable[bytes], profile: str) -> Iterator[dict]:
    decoder = Decoder(profile)
    for ev in deframe(chunks):
        yield decoder.event(ev)


def both_directions_events(chunks: Iterable[bytes], profile: str, name: str) -> Iterator[dict]:
    """The reference's events of both directions of a capture, each marked
    with its direction, in capture order (see timed_events)."""
    pieces = timed_pieces(chunks, frozenset({"rx", "tx"}), name)
    return (ev for ev, _ in _reference_events(pieces, profile, ("rx", "tx"), True))


def stream_events(chunks: Iterable[bytes], profile: str, direction: str = "rx", name: str = "input",
                  seen: InputSeen | None = None) -> Iterator[dict]:
    """What `osdkc decode` prints for --direction rx, tx or both: the native
    decoder's events when it is to run (accel.py), else the reference's.
    `seen`, when given, notes what the input held (InputSeen)."""
    return (ev for ev, _ in timed_events(chunks, profile, direction, name, seen))


def timed_events(chunks: Iterable[bytes], profile: str, direction: str = "rx", name: str = "input",
                 seen: InputSeen | None = None) -> Iterator[tuple[dict, int | None]]:
    """stream_events, each event with the capture time (ns since the Unix
    epoch) of the pcapng record whose bytes completed it, None for raw
    bytes. The events the end of the input leaves (a frame the recording
    stopped inside) get the time of the last record. With --direction both,
    each direction is deframed on its own (its offsets count its own bytes)
    and one decoder sees both, so an ACK the flight controller sent is
    matched with the command the host sent; the received direction is
    finished first."""
    both = direction == "both"
    pieces = timed_pieces(chunks, frozenset({"rx", "tx"}) if both else frozenset({direction}), name, seen)
    native = accel.stream(profile)
    tag = (lambda d: d) if both else (lambda d: None)
    ends = ("rx", "tx") if both else (direction,)
    last: int | None = None
    if native is not None:
        for d, data, ts in pieces:
            last = ts
            for ev in native.feed(data, tag(d)):
                yield ev, ts
        for d in ends:
            for ev in native.finish(tag(d)):
                yield ev, last
        return
    yield from _reference_events(pieces, profile, ends, both)


def _reference_events(pieces: Iterable[tuple[str, bytes, int | None]], profile: str, ends: tuple[str, ...],
                      both: bool) -> Iterator[tuple[dict, int | None]]:
    decoder = Decoder(profile)
    deframers = {d: Deframer() for d in ends}
    mark = (lambda d, ev: {"direction": d, **ev}) if both else (lambda d, ev: ev)
    last: int | None = None
    for d, data, ts in pieces:
        last = ts
        for ev in deframers[d].feed(data):
            yield mark(d, decoder.event(ev)), ts
    for d in ends:
        for ev in deframers[d].finish():
            yield mark(d, decoder.event(ev)), last


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


BROADCAST = (0x02, 0x00)  # command set and id of the broadcast (push data)


def profiles_decoding(values: Sequence[bytes], profile: str) -> list[str]:
    """The profiles other than `profile` under which every one of `values`
    (broadcast values, flag word first) decodes: what a stream that does not
    decode with `profile` was most likely sent with. `osdkc decode` and the
    `decode.profile` check of `osdkc device` both suggest them."""
    fits = []
    for other in profile_names():
        if other == profile:
            continue
        construct_ = payload(*BROADCAST, False, other)
        if all(_parses(construct_, value) for value in values):
            fits.append(other)
    return fits


def _parses(construct_: construct.Construct, value: bytes) -> bool:
    try:
        construct_.parse(value)
    except Exception:  # whatever the reason, the value does not fit that layout
        return False
    return True


EPILOG = ("exit status: 0 when every frame decoded; 1 when an error event was counted, or a FILE or standard "
          "input holds no frame at all; 2 when the input cannot be read or the arguments are wrong. Where a FILE "
          "or standard input ends inside a frame (a recording stopped there), that error event has "
          "\"capture_end\": true and is not counted; --hex bytes are taken as given, a frame they cut short counts.")


def add_arguments(d: argparse.ArgumentParser, profiles: Sequence[str]) -> argparse._MutuallyExclusiveGroup:
    """The options; returns the group of the input's sources, which takes one."""
    d.epilog = EPILOG
    d.add_argument("--profile", required=True, choices=profiles, help="broadcast wire profile of the flight controller")
    src = d.add_mutually_exclusive_group(required=True)
    src.add_argument("--hex", help="the bytes as hex (spaces and colons allowed)")
    src.add_argument("file", nargs="?", help="a file of raw bytes or a pcapng capture (osdkc device), or - for standard input")
    d.add_argument("--direction", choices=("rx", "tx", "both"), default="rx",
                   help="of a capture: bytes received (default), sent, or both, each event marked with its direction")
    d.add_argument("--pretty", action="store_true", help="indent each JSON object")
    return src


def _whole_frame(ev: dict) -> bool:
    """Whether an event is about a frame the receiver found whole: decoded,
    or with its value or CRC-32 rejected (not a frame the input cuts short)."""
    return ev["kind"] == "frame" or "frame_header" in ev or ev.get("error") == "bad_crc32"


def mark_capture_end(events: Iterable[dict], seen: InputSeen, direction: str) -> Iterator[dict]:
    """The events of a recording (a file, standard input), with
    `"capture_end": true` on the errors about the frame the recording stopped
    inside: in each direction, the first truncated_frame after the last
    whole frame, whose bytes run to the end of that direction's input, and
    the errors after it, which are the receiver's rescan of those same bytes
    (a 0xAA in the cut frame's value taken for a header). A truncated_frame
    followed by a whole frame is a frame the device cut short: an error like
    any other.

    A truncated_frame comes only once the input has ended (Deframer.finish),
    so from the first one on the events are held back until the end shows
    which one the tail starts at: at most the rescan of one frame's bytes
    per direction."""
    held: list[dict] = []
    for ev in events:
        if held or ev.get("error") == "truncated_frame":
            held.append(ev)
        else:
            yield ev
    where = [ev.get("direction", direction) for ev in held]
    last_whole = {d: i for i, (d, ev) in enumerate(zip(where, held)) if _whole_frame(ev)}
    tail: dict[str, int] = {}
    for i, (d, ev) in enumerate(zip(where, held)):
        if (d not in tail and i > last_whole.get(d, -1) and ev.get("error") == "truncated_frame"
                and seen.reaches_end(d, ev)):
            tail[d] = i
    for i, (d, ev) in enumerate(zip(where, held)):
        yield {**ev, "capture_end": True} if ev["kind"] == "error" and i >= tail.get(d, len(held)) else ev


def cut_block_note(seen: InputSeen, done: str) -> str:
    """The warning about a capture whose last pcapng block is cut short (a killed writer)."""
    at = seen.size - seen.cut_block
    return (f"warning: the capture is cut inside a pcapng block after {seen.cut_block} bytes (the block at offset "
            f"{at}: its writer was stopped or killed); the frames before it are {done}")


class Tally:
    """What `osdkc decode` says on standard error after the events, and its
    exit status, from the events as they go by."""

    SAMPLES = 200  # undecoded broadcast values kept to try the other profiles on, as `osdkc device` keeps

    def __init__(self, profile: str, direction: str, seen: InputSeen) -> None:
        self.profile = profile
        self.direction = direction
        self.seen = seen
        self.errors = 0
        self.frames = 0                    # whole frames, decoded or not
        self.broadcasts = 0                # broadcast frames, decoded or not
        self.undecoded: list[bytes] = []   # values of broadcasts that did not decode (the first SAMPLES)
        self.undecoded_count = 0
        self.tails: dict[str, dict] = {}   # the truncated_frame a recording ends inside, by direction

    def add(self, ev: dict) -> None:
        if ev.get("capture_end"):
            self.tails.setdefault(ev.get("direction", self.direction), ev)
            return
        if ev["kind"] == "error":
            self.errors += 1
        if not _whole_frame(ev):
            return
        self.frames += 1
        if ev.get("command") == "broadcast":
            self.broadcasts += 1
        elif "frame_header" in ev:
            self._undecoded(ev.get("direction", self.direction), ev)

    def _undecoded(self, d: str, ev: dict) -> None:
        raw = self.seen.bytes_at(d, ev["offset"], ev["length"])
        if raw is None or len(raw) < HEADER_LEN + 2 + 4:
            return
        h = header_fields(raw)
        if h["is_ack"] or h["enc"] or tuple(raw[HEADER_LEN:HEADER_LEN + 2]) != BROADCAST:
            return  # not a plain broadcast: which profile it wants cannot be told from its value
        self.broadcasts += 1
        self.undecoded_count += 1
        if len(self.undecoded) < self.SAMPLES:
            self.undecoded.append(raw[HEADER_LEN + 2:-4])

    def notes(self, name: str, recording: bool) -> list[str]:
        """The lines for standard error, each about what the events alone do not say."""
        out = []
        if self.seen.cut_block:
            out.append(cut_block_note(self.seen, "decoded"))
        for d, ev in self.tails.items():
            out.append(self._tail_note(d, ev))
        if self.undecoded_count * 2 > self.broadcasts:
            out.append(self._profile_note())
        if recording and not self.frames:
            out.append(f"no frame found in {name} ({self.seen.size} bytes{self._what_was_read()})")
        return out

    def _tail_note(self, d: str, ev: dict) -> str:
        have = ev["length"]
        header = self.seen.bytes_at(d, ev["offset"], HEADER_LEN) if have >= HEADER_LEN else None
        # a header the deframer saw whole was checked: its LEN is the frame's length
        want = f"{frame_length(header)}" if header else f"{HEADER_LEN}+"
        which = f" ({d})" if self.direction == "both" else ""
        return (f"the input{which} ends inside a frame ({have} of {want} bytes): the recording stopped there; "
                "not counted as an error")

    def _profile_note(self) -> str:
        said = f"{self.undecoded_count} of {self.broadcasts} broadcast frames do not decode as {self.profile}"
        fits = profiles_decoding(self.undecoded, self.profile)
        if fits:
            return f"{said}; they decode as {' and '.join(fits)}: try --profile {fits[0]}"
        others = ", ".join(p for p in profile_names() if p != self.profile)
        return f"{said}, and no other profile ({others}) decodes them either"

    def _what_was_read(self) -> str:
        if not self.seen.pcapng:
            return ""
        wanted = ("rx", "tx") if self.direction == "both" else (self.direction,)
        held = " and ".join(f"{self.seen.received.get(d, 0)} {d}" for d in wanted)
        return f"; a pcapng capture holding {held} bytes"

    def status(self, recording: bool) -> int:
        return 1 if self.errors or (recording and not self.frames) else 0


def open_input(args: argparse.Namespace) -> tuple[str, Iterable[bytes], IO[bytes] | None]:
    """The input's name for messages, its chunks, and the file to close after."""
    if args.hex is not None:
        return "--hex", [parse_hex(args.hex)], None
    if args.file == "-":
        return "standard input", read_chunks(sys.stdin.buffer), None
    if args.file:
        try:
            fh = open(args.file, "rb")
        except OSError as e:
            raise UsageError(cannot_read(args.file, e)) from None
        return args.file, read_chunks(fh), fh
    raise UsageError("give --hex HEX, a FILE, or - for standard input")


def run_decode(args: argparse.Namespace, opened: tuple[str, Iterable[bytes], IO[bytes] | None] | None = None,
               live: bool = False) -> int:
    """`osdkc decode` to JSON lines; `opened` is the input when the caller
    opened it (name, chunks, file to close); `live` flushes each event as it
    comes (a port, a growing file)."""
    name, source, close = opened or open_input(args)
    # A file or standard input is a recording: where it ends, the recording
    # stopped, whatever the device was sending. --hex is exactly the bytes
    # the user meant; a frame they cut short is theirs to see as an error.
    recording = args.hex is None
    seen = InputSeen()
    tally = Tally(args.profile, args.direction, seen)
    indent = 2 if args.pretty else None
    try:
        events = stream_events(source, args.profile, args.direction, name, seen)
        if recording:
            events = mark_capture_end(events, seen, args.direction)
        for ev in events:
            tally.add(ev)
            sys.stdout.write(model.dumps(ev, indent=indent) + "\n")
            if live:
                sys.stdout.flush()
    except BrokenPipeError:
        raise
    except OSError as e:
        raise UsageError(f"reading failed: {e.strerror or e}") from None
    finally:
        if close:
            close.close()
    sys.stdout.flush()
    for line in tally.notes(name, recording):
        print(f"osdkc decode: {line}", file=sys.stderr)
    return tally.status(recording)
