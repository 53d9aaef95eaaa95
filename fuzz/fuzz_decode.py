#!/usr/bin/env python3
"""atheris target: the Python receiver on arbitrary byte streams.

The input is read as every stream target reads it (tools/fuzz_corpus.py
stream_reads: a selector byte for the profile and the read size, then the
stream). The stream goes through what `osdkc decode` runs (decode.received_bytes,
so pcapng captures too, then deframe + decode.Decoder on the Construct spec)
and through the Kaitai-Python testee's stream decoder on the same reads.

A finding is an uncaught exception (only UsageError, the documented answer
to an unreadable capture, is expected), an event class outside the value
model or `undecodable` (which docs/VALUE-MODEL.md says should not happen),
events out of stream order or outside the input, a frame event that is not
LEN bytes, a model JSON cannot carry, or the two decoders disagreeing
(judged by osdk_conformance.harness.fuzz.disagreement, as `osdkc fuzz` judges).

    .venv/bin/python fuzz/fuzz_decode.py CORPUS_DIR -max_total_time=60
    .venv/bin/python fuzz/fuzz_decode.py crash-FILE        # replay one input

Seeds: tools/fuzz_corpus.py deframer CORPUS_DIR.
"""
from __future__ import annotations

import json
import sys
from pathlib import Path

import atheris

HERE = Path(__file__).resolve().parent
for extra in (HERE.parent / "tools", HERE.parent / "conformance" / "testees"):
    if extra.is_dir():  # a source checkout; a PyInstaller bundle has them inside
        sys.path.insert(0, str(extra))

# Instrument only the project's code: coverage inside construct and the
# kaitaistruct runtime would slow every run and mostly measure the libraries.
with atheris.instrument_imports(include=["osdk_conformance", "kaitai_python_testee", "fuzz_corpus"]):
    import kaitai_python_testee as kaitai
    import osdk_conformance._construct.frame  # noqa: F401 - decode.Decoder imports it lazily; instrument it now
    import osdk_conformance._construct.payload  # noqa: F401
    from fuzz_corpus import stream_reads
    from osdk_conformance.core import model
    from osdk_conformance.reference.decode import decode_events, received_bytes
    from osdk_conformance.core.errors import UsageError
    from osdk_conformance.harness.fuzz import disagreement
    from osdk_conformance.harness.vectors import SCHEMA_PATH

ERROR_CLASSES = frozenset(json.loads(SCHEMA_PATH.read_text(encoding="utf-8"))["$defs"]["error_class"]["enum"]) \
    - {"undecodable"}


class Finding(AssertionError):
    pass


def check_events(events: list[dict], total: int, who: str) -> None:
    next_offset = 0
    for ev in events:
        off, kind = ev["offset"], ev["kind"]
        length = ev["frame"]["len"] if kind == "frame" else ev["length"]
        if off < next_offset or length < 1 or off + length > total:
            raise Finding(f"{who}: event out of order or outside the {total}-byte input: {ev}")
        if kind == "error" and ev["error"] not in ERROR_CLASSES:
            raise Finding(f"{who}: error class {ev['error']!r}: {ev.get('detail')}")
        if kind == "frame" and ev["frame"]["sof"] != "aa":
            raise Finding(f"{who}: a frame event that does not start with 0xAA: {ev}")
        # a rejected start byte lets the scan resume at the next byte
        next_offset = off + (length if kind == "garbage" else 1)
        model.dumps(ev)


def test_one_input(data: bytes) -> None:
    parsed = stream_reads(data)
    if parsed is None:
        return
    profile, reads = parsed
    try:
        received = list(received_bytes(reads))
    except UsageError:
        return  # a pcapng capture that cannot be read: exit status 2 in `osdkc decode`
    total = sum(len(r) for r in received)
    construct_events = list(decode_events(received, profile))
    check_events(construct_events, total, "osdkc decode (Construct)")
    request = {"hex": b"".join(received).hex(), "chunks": [len(r) for r in received]}
    kaitai_events = kaitai.decode_stream(request, profile)["events"]
    check_events(kaitai_events, total, "kaitai-python testee")
    answers = [{"ok": True, "result": {"events": construct_events}}, {"ok": True, "result": {"events": kaitai_events}}]
    differs = disagreement("decode_stream", profile, request, answers)
    if differs is not None:
        raise Finding(f"Construct and Kaitai-Python disagree ({profile}, {request}): {differs[0]}")


def main() -> None:
    atheris.Setup(sys.argv, test_one_input)
    atheris.Fuzz()


if __name__ == "__main__":
    main()
