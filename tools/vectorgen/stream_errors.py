"""Bug class "stream error class" (osdk_conformance.harness.vector_tables):
every error class a stream can report, each way of producing it, followed
by a good frame and with a good frame hidden inside it."""
from __future__ import annotations

from typing import Any, Callable

from osdk_conformance.harness import vector_tables as vt
from osdk_conformance.reference import codec as reference

from .builder import GenerationError, R
from .scalars import le16
from .wire import GOOD_FRAME, flip, flip_last, frame_bytes

STREAM_ERROR_FLAGS = {"bad_crc16": "frame.crc16", "bad_version": "frame.ver", "impossible_length": "frame.len",
                      "bad_crc32": "frame.crc32", "truncated_frame": "stream.truncated_tail",
                      "bad_session": "frame.session", "bad_encryption": "frame.enc",
                      "truncated_payload": "payload.truncated", "length_mismatch": "payload.trailing"}


def stream_error_makers() -> dict[str, tuple[str, Callable[[bytes], bytes]]]:
    """A bad frame per way of producing each stream error class:
    name -> (class, make(inner)), `inner` carried inside the frame's DATA."""

    def unknown(inner: bytes, **kw: Any) -> bytes:
        return frame_bytes(cmd_set=0, cmd_id=0x7E, value=b"\x11" + inner + b"\x22", seq=0x0405, **kw)

    return {
        "crc16": ("bad_crc16", lambda inner: flip(unknown(inner), 80)),
        "ver": ("bad_version", lambda inner: unknown(inner, ver=1)),
        "res0": ("reserved_bits", lambda inner: unknown(inner, res0=1)),
        "res1": ("reserved_bits", lambda inner: unknown(inner, res1=0x000001)),
        "len3": ("impossible_length", lambda inner: frame_bytes(length=3, data=b"") + b"\x11" + inner),
        "len14": ("impossible_length", lambda inner: frame_bytes(length=14, data=b"") + b"\x11" + inner),
        "crc32": ("bad_crc32", lambda inner: flip_last(unknown(inner))),
        "truncated": ("truncated_frame", lambda inner: unknown(inner + bytes(24))[:15 + len(inner)]),
        "session": ("bad_session", lambda inner: frame_bytes(is_ack=True, session=0, seq=0x0405,
                                                             value=b"\x02\x00" + inner)),
        "enc": ("bad_encryption", lambda inner: unknown(inner, enc=2)),
        "padding": ("bad_encryption", lambda inner: unknown(inner, padding=1)),
        "activation_short": ("truncated_payload", lambda inner: frame_bytes(cmd_set=0, cmd_id=1, seq=0x0405,
                                                                             value=inner + b"\x00")),
        "control_trailing": ("length_mismatch", lambda inner: frame_bytes(cmd_set=1, cmd_id=0, seq=0x0405,
                                                                           value=b"\x01\x22" + inner)),
        "broadcast_reserved": ("reserved_bits", lambda inner: frame_bytes(cmd_set=2, cmd_id=0, seq=0x0405,
                                                                           value=le16(0x8000) + inner)),
    }


def add_stream_errors(profile: str, add: Callable[..., None]) -> None:
    """Every stream error class (vt.stream_error_classes), each way of
    producing it: the bad frame then a good one; with a good frame inside
    its DATA as well (found only where scanning resumes after the start
    byte); and that one fed a byte at a time."""
    makers = stream_error_makers()
    missing = set(vt.stream_error_classes()) - {cls for cls, _ in makers.values()}
    if missing:
        raise GenerationError(f"no stream error vector produces {', '.join(sorted(missing))}")
    for name, (cls, make) in makers.items():
        flags = R("stream.resync", STREAM_ERROR_FLAGS.get(cls) or
                  ("broadcast.reserved_flags" if name.startswith("broadcast") else "frame.reserved"))
        for shape, data, chunks, what in (
                ("then_good", make(b"") + GOOD_FRAME, None, "then a good frame"),
                ("hidden", make(GOOD_FRAME) + GOOD_FRAME, None,
                 "with a good frame inside its DATA, then the same good frame"),
                ("hidden.bytewise", make(GOOD_FRAME) + GOOD_FRAME, [1] * (len(make(GOOD_FRAME)) + len(GOOD_FRAME)),
                 "with a good frame inside its DATA, then the same good frame, one byte per read")):
            ref = reference.answer("decode_stream", profile, {"hex": data.hex(), "chunks": [len(data)]})
            ev = ref["result"]["events"][0]
            if ev["kind"] != "error" or ev["offset"] != 0 or ev["error"] != cls:
                raise GenerationError(f"stream error {name}: first event {ev}, want {cls} at 0")
            resumes = "after its start byte" if ev["length"] < len(make(b"")) or cls in (
                "bad_crc32", "truncated_frame") else "after the frame"
            add(f"stream_error.{name}.{shape}", "stream.error_classes",
                f"{cls} ({name}) {what}: the error at offset 0 covers {ev['length']} byte(s) and scanning "
                f"resumes {resumes}", data, flags + (R("stream.chunking") if chunks else []), chunks=chunks)
