#!/usr/bin/env python3
"""Seed corpora for the coverage-guided fuzz targets, from the golden vectors.

usage: tools/fuzz_corpus.py {deframer,broadcast} OUT_DIR [--limit N] [--length-prefix]

deframer:  every decode_stream and decode_frame input, prefixed with the
           byte the target reads first (profile and read size); the seeds of
           every stream target (C fuzz_deframer, Python fuzz/fuzz_decode.py,
           Go FuzzDecodeStream), which all read their input as stream_input
           and stream_reads below do (tools/fuzz_to_vector.py as well);
broadcast: every broadcast value of a decode_payload case.
One file per distinct input, named by its SHA-1, so reruns are idempotent.
--length-prefix puts each seed behind its length in 4 big-endian bytes: how
a Go fuzz target built for libFuzzer by go-118-fuzz-build (ClusterFuzzLite)
reads its []byte argument.
"""
from __future__ import annotations

import argparse
import hashlib
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from osdk_conformance.core.deframe import split_chunks  # noqa: E402
from osdk_conformance.core.rules import profile_names  # noqa: E402
from osdk_conformance.harness.vectors import load_cases  # noqa: E402

PROFILES = profile_names()
"""The profiles in value order, as the generated tables list them (C
osdk_profile_ids, the Go testee's tables): the order the selector byte indexes."""


def stream_input(data: bytes) -> tuple[str, int, bytes] | None:
    """(profile, read size, stream) of a stream target's input, None when it
    is empty: the first byte modulo 3 picks the profile, its top six bits
    plus one the size of the reads the rest arrives in (1..64)."""
    if not data:
        return None
    return PROFILES[data[0] % len(PROFILES)], (data[0] >> 2) + 1, data[1:]


def stream_reads(data: bytes) -> tuple[str, list[bytes]] | None:
    """(profile, reads) of a stream target's input: the stream cut into
    reads of the size the selector byte picked, what they leave over one
    last read; None when the input is empty."""
    parsed = stream_input(data)
    if parsed is None:
        return None
    profile, size, stream = parsed
    return profile, split_chunks(stream, [size] * (len(stream) // size))


def stream_seed(profile: str, stream: bytes) -> bytes:
    """The input stream_input reads as `stream` in `profile`; the read size
    comes from the stream's length, so that the seeds spread over all 64."""
    want = PROFILES.index(profile) if profile in PROFILES else 0
    high = (len(stream) % 64) << 2
    # of four neighbouring selector values, one has each residue modulo 3
    return bytes([next(high | low for low in range(4) if (high | low) % 3 == want)]) + stream


def seeds(target: str):
    for case in load_cases():
        inp = case.input if isinstance(case.input, dict) else {}
        data = inp.get("hex")
        if not isinstance(data, str):
            continue
        raw = bytes.fromhex(data)
        if target == "deframer" and case.operation in ("decode_stream", "decode_frame"):
            yield stream_seed(case.profile, raw)
        elif target == "broadcast" and case.operation == "decode_payload" and inp.get("cmd_set") == 2 \
                and inp.get("cmd_id") == 0 and not inp.get("is_ack"):
            yield raw


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("target", choices=("deframer", "broadcast"))
    ap.add_argument("out", type=Path)
    ap.add_argument("--limit", type=int, default=0, help="at most N seeds (0: all)")
    ap.add_argument("--length-prefix", action="store_true", help="each seed behind its length (4 bytes, big-endian)")
    args = ap.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    written = set()
    for data in seeds(args.target):
        if args.length_prefix:
            data = len(data).to_bytes(4, "big") + data
        name = hashlib.sha1(data).hexdigest()
        if name in written:
            continue
        (args.out / name).write_bytes(data)
        written.add(name)
        if args.limit and len(written) >= args.limit:
            break
    print(f"fuzz_corpus: {len(written)} seeds for {args.target} in {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
