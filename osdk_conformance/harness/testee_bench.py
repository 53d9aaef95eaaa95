"""The bench mode of the bundled Python testees (conformance/PROTOCOL.md):

    <testee> --bench FILE --profile P

FILE (or standard input for `-`) goes in reads of at most 64 KiB through the
testee's own stream decoder, the one its decode_stream answers with, with
the value models left out. Only counters are kept, so memory does not grow
with the stream. One JSON line reports the counts and the seconds of the
read+deframe+decode loop (the rules and CRC tables are loaded before it);
bad arguments or an unreadable file are one line on
standard error and exit status 2.
"""
from __future__ import annotations

import json
import sys
import time
from typing import Callable, Iterable, Iterator, Sequence

from osdk_conformance.core.crc import crc16, crc32
from osdk_conformance.core.errors import cannot_read
from osdk_conformance.core.rules import profile as load_profile

READ_SIZE = 64 * 1024  # the contract's bound on one read, whatever the decoder's own read size
USAGE = "usage: --bench FILE|- --profile P"

Events = Callable[[Iterable[bytes], str], Iterable[dict]]
"""(chunks, profile) -> the testee's decode_stream events, without value models."""


class BenchError(Exception):
    """Bad arguments or unreadable input: one line on stderr, exit 2."""


def parse_args(argv: Sequence[str], profiles: Sequence[str]) -> tuple[str, str]:
    """(file, profile) from `--bench FILE --profile P` in either order."""
    opts: dict[str, str] = {}
    args = list(argv)
    while args:
        key = args.pop(0)
        if key not in ("--bench", "--profile"):
            raise BenchError(f"unknown argument {key!r}; {USAGE}")
        if not args:
            raise BenchError(f"{key} needs a value; {USAGE}")
        if key in opts:
            raise BenchError(f"{key} given twice; {USAGE}")
        opts[key] = args.pop(0)
    if "--bench" not in opts or "--profile" not in opts:
        raise BenchError(USAGE)
    if opts["--profile"] not in profiles:
        raise BenchError(f"unknown profile {opts['--profile']!r} (known: {', '.join(profiles)})")
    return opts["--bench"], opts["--profile"]


def _reads(fh, counted: list[int]) -> Iterator[bytes]:
    while chunk := fh.read(READ_SIZE):
        counted[0] += len(chunk)
        yield chunk


def bench(path: str, profile: str, events: Events) -> dict:
    """The counts and seconds of decoding the file at `path` (`-`: stdin)."""
    try:
        # Unbuffered, so that one read is one read(2) of at most READ_SIZE bytes.
        fh = open(0 if path == "-" else path, "rb", buffering=0, closefd=path != "-")
    except OSError as e:
        raise BenchError(cannot_read(path, e)) from None
    counted = [0]
    frames = errors = garbage = 0
    # What a decoder loads once (the rules with their schema check, the CRC
    # tables, its own set-up) is loaded before the clock starts: the loop
    # measures decoding, not start-up, as the compiled testees' loops do.
    load_profile(profile)
    crc16(b"")
    crc32(b"")
    for _ in events([], profile):
        pass
    try:
        with fh:
            start = time.perf_counter()  # monotonic
            for ev in events(_reads(fh, counted), profile):
                kind = ev["kind"]
                if kind == "frame":
                    frames += 1
                elif kind == "error":
                    errors += 1
                else:
                    garbage += ev["length"]
            seconds = time.perf_counter() - start
    except OSError as e:
        raise BenchError(cannot_read(path, e)) from None
    return {"profile": profile, "bytes": counted[0], "frames": frames, "errors": errors,
            "garbage_bytes": garbage, "seconds": round(seconds, 6)}


def main(argv: Sequence[str], impl: str, profiles: Sequence[str], events: Events) -> int:
    """Run the bench mode; the exit status."""
    try:
        path, profile = parse_args(argv, profiles)
        result = bench(path, profile, events)
    except BenchError as e:
        print(f"{impl} --bench: {e}", file=sys.stderr)
        return 2
    print(json.dumps({"impl": impl, **result}), flush=True)
    return 0
