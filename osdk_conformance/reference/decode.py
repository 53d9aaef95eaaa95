"""`osdkc decode`: frames and errors in a byte stream, as JSON lines.

Deframing follows the SDK receiver (deframe.py); each intact frame is then
decoded with the Construct spec for the chosen profile and printed in the
JSON value model (docs/VALUE-MODEL.md). ACK values are decoded when the
same stream, or with --direction both the capture's sent bytes, carried the
command they answer (matched by SEQ and session).
"""
from __future__ import annotations

import argparse
import re
import sys
from itertools import chain
from typing import IO, Any, Iterable, Iterator, Sequence

import construct

from osdk_conformance.core import model
from osdk_conformance.core.capture import CaptureError, CaptureReader, NAMES, is_pcapng
from osdk_conformance.core.commands import command_name
from osdk_conformance.core.deframe import Deframer, Frame, Garbage, Rejected, deframe, header_fields
from osdk_conformance.core.errors import UsageError, cannot_read, one_line
from osdk_construct.frame import parse_frame
from osdk_construct.payload import payload

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
    def __init__(self, profile: str, models: bool = True) -> None:
        # models=False leaves each value as Construct parsed it: the testees'
        # bench mode times decoding, not the value model.

        self._parse_frame = parse_frame
        self._payload = payload
        self.profile = profile
        self._model = model.from_construct if models else _as_parsed
        self._pending: dict[tuple[int, int], tuple[int, int]] = {}  # (session, seq) -> (set, id)

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
        try:
            parsed = self._parse_frame(ev.raw, self.profile)
        except construct.ConstructError as e:
            return {"offset": ev.offset, "kind": "error", "error": classify(e),
                    "detail": one_line(e), "length": len(ev.raw), "frame_header": header_fields(ev.raw)}
        out: dict[str, Any] = {"offset": ev.offset, "kind": "frame"}
        frame = self._model(parsed)
        data = parsed.get("data")
        if parsed.len == 12:
            out["command"] = "none"
        elif not isinstance(data, dict):
            out["command"] = "encrypted"
        elif parsed.is_ack:
            key = (parsed.session, parsed.seq)
            if key in self._pending:
                cmd = self._pending.pop(key)
                out["ack_of"] = command_name(*cmd)
                try:
                    out["ack"] = self._model(self._payload(*cmd, True, self.profile).parse(data.ack_value))["body"]
                except construct.ConstructError as e:
                    return {"offset": ev.offset, "kind": "error", "error": classify(e), "detail": one_line(e),
                            "length": len(ev.raw), "frame_header": header_fields(ev.raw), "ack_of": out["ack_of"]}
            else:
                out["command"] = "ack"
        else:
            cmd = (int(data.cmd_set), data.cmd_id)
            out["command"] = command_name(*cmd)
            if parsed.session > 0:
                self._pending[(parsed.session, parsed.seq)] = cmd
                if len(self._pending) > 1024:  # bounded: unanswered commands are forgotten
                    self._pending.pop(next(iter(self._pending)))
        out["frame"] = frame
        return out


def _as_parsed(parsed: Any) -> Any:
    return parsed


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


def decode_events(chunks: Iterable[bytes], profile: str, models: bool = True) -> Iterator[dict]:
    decoder = Decoder(profile, models)
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
    """What `osdkc decode` prints for --direction rx, tx or both."""
    if direction == "both":
        return both_directions_events(chunks, profile, name)
    pieces = capture_pieces(chunks, frozenset({direction}), name)
    return decode_events((data for _, data in pieces), profile)


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
