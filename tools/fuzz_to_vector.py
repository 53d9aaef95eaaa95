#!/usr/bin/env python3
"""Turn an input a coverage-guided fuzz target flagged into regression vectors.

usage: tools/fuzz_to_vector.py --target TARGET (ARTIFACT ... | --hex HEX) [--out FILE] [--why TEXT]

TARGET says how the fuzz target read its input (docs/FUZZING.md):
  deframer   C fuzz_deframer (libFuzzer)        a stream input (tools/fuzz_corpus.py stream_reads)
  decode     Python fuzz/fuzz_decode.py (atheris)  a stream input; a pcapng capture is replaced by its received bytes
  go         Go FuzzDecodeStream (go test -fuzz)   a stream input
  broadcast  C fuzz_broadcast (libFuzzer)       a broadcast value, decoded in every profile
A stream input becomes one decode_stream case (the profile and the reads
the target used); a broadcast value one decode_payload case per profile.
Each case's expectation is the reference's answer (osdk_conformance.reference.codec,
the Construct spec), made by the same function as `osdkc fuzz` uses for a
disagreement (osdk_conformance.harness.fuzz.regression_vector).

An ARTIFACT is a libFuzzer/atheris file (crash-*, leak-*, timeout-*, oom-*:
the raw input) or a Go corpus file (testdata/fuzz/FuzzDecodeStream/*:
"go test fuzz v1" and one []byte literal). --hex takes the input as
printed by the Go target's failure message.

Output: a vector file (vectors/FORMAT.md) on standard output or in --out,
to replay at once with `osdkc run --impl all --vectors FILE`; on standard
error, the generator line for each case, to paste into the suite's module
(tools/vectorgen/streams.py, tools/vectorgen/broadcast.py) so that the case
becomes a golden vector. Exit status 0; 2 for an unreadable artifact or bad arguments.
"""
from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tools"))

from fuzz_corpus import PROFILES, stream_reads  # noqa: E402

TARGETS = {"deframer": "C fuzz_deframer (libFuzzer)", "decode": "Python fuzz/fuzz_decode.py (atheris)",
           "go": "Go FuzzDecodeStream (go test -fuzz)", "broadcast": "C fuzz_broadcast (libFuzzer)"}
GO_HEADER = "go test fuzz v1"
SUITE_OF = {"decode_stream": "tools/vectorgen/streams.py", "decode_payload": "tools/vectorgen/broadcast.py"}
"""Where the generator builds the cases of an operation, for the line to paste."""


class BadInput(Exception):
    pass


# ---------------------------------------------------------------- reading artifacts

_SIMPLE_ESCAPES = {"a": 7, "b": 8, "f": 12, "n": 10, "r": 13, "t": 9, "v": 11, "\\": 92, '"': 34, "'": 39}


def go_string_bytes(literal: str) -> bytes:
    """The bytes of a Go interpreted string literal ("..."), as Go's fuzzing
    engine writes a []byte value (%q: \\xNN for bytes that are not UTF-8)."""
    if len(literal) < 2 or literal[0] != '"' or literal[-1] != '"':
        raise BadInput("not a double-quoted Go string")
    out, body, i = bytearray(), literal[1:-1], 0
    while i < len(body):
        c = body[i]
        if c != "\\":
            out += c.encode("utf-8")
            i += 1
            continue
        if i + 1 >= len(body):
            raise BadInput("a backslash at the end of the string")
        e = body[i + 1]
        if e in _SIMPLE_ESCAPES:
            out.append(_SIMPLE_ESCAPES[e])
            i += 2
        elif e in "xuU":
            width = {"x": 2, "u": 4, "U": 8}[e]
            digits = body[i + 2:i + 2 + width]
            try:
                value = int(digits, 16) if len(digits) == width else -1
            except ValueError:
                value = -1
            if value < 0:
                raise BadInput(f"bad \\{e} escape")
            out += bytes([value]) if e == "x" else chr(value).encode("utf-8")
            i += 2 + width
        elif e in "01234567":
            digits = body[i + 1:i + 4]
            if len(digits) != 3 or any(d not in "01234567" for d in digits) or int(digits, 8) > 255:
                raise BadInput("bad octal escape")
            out.append(int(digits, 8))
            i += 4
        else:
            raise BadInput(f"unknown escape \\{e}")
    return bytes(out)


def read_artifact(path: Path) -> bytes:
    try:
        data = path.read_bytes()
    except OSError as e:
        raise BadInput(f"cannot read {path}: {e.strerror or e}") from None
    if not data.startswith(GO_HEADER.encode()):
        return data
    lines = [ln.strip() for ln in data.decode("utf-8", "replace").splitlines()[1:] if ln.strip()]
    if len(lines) != 1 or not lines[0].startswith("[]byte(") or not lines[0].endswith(")"):
        raise BadInput(f"{path}: a Go corpus file holding one []byte value was expected")
    try:
        return go_string_bytes(lines[0][len("[]byte("):-1])
    except BadInput as e:
        raise BadInput(f"{path}: {e}") from None


# ---------------------------------------------------------------- inputs to cases

def stream_case(target: str, data: bytes) -> list[tuple[str, str, dict]]:
    from osdk_conformance.core.errors import UsageError
    from osdk_conformance.reference.decode import received_bytes

    parsed = stream_reads(data)
    if parsed is None:
        raise BadInput("an empty input: the stream targets ignore it")
    profile, reads = parsed
    if target == "decode":  # what fuzz_decode.py decoded: a capture's received bytes
        try:
            reads = list(received_bytes(reads))
        except UsageError as e:
            raise BadInput(f"the input is a pcapng capture that does not parse ({e}); vectors hold byte "
                           "streams, so pin it with a capture test (tests/test_capture.py)") from None
    return [("decode_stream", profile, {"hex": b"".join(reads).hex(), "chunks": [len(r) for r in reads]})]


def broadcast_cases(data: bytes) -> list[tuple[str, str, dict]]:
    return [("decode_payload", p, {"hex": data.hex(), "cmd_set": 2, "cmd_id": 0, "is_ack": False})
            for p in PROFILES]


def cases_of(target: str, data: bytes) -> list[tuple[str, str, dict]]:
    return broadcast_cases(data) if target == "broadcast" else stream_case(target, data)


def gen_vectors_line(group: dict) -> str:
    test = group["tests"][0]
    rules = ", ".join(json.dumps(f.removeprefix("rule:")) for f in test["flags"])
    return (f"# {SUITE_OF.get(group['operation'], 'the suite of ' + group['operation'])}:\n"
            f"s.add({json.dumps(group['operation'])}, {json.dumps(group['profile'])}, {json.dumps(test['id'])}, "
            f"{json.dumps(test['category'])}, {json.dumps(test['comment'])}, {json.dumps(test['input'])}, R({rules}))")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("artifacts", nargs="*", type=Path, metavar="ARTIFACT")
    ap.add_argument("--target", required=True, choices=sorted(TARGETS))
    ap.add_argument("--hex", help="the input as hex instead of an artifact file")
    ap.add_argument("--out", type=Path, help="write the vector file here (default: standard output)")
    ap.add_argument("--why", help="what went wrong, for the cases' comment")
    args = ap.parse_args(argv)
    from osdk_conformance.harness.fuzz import regression_vector, suite_document

    try:
        if bool(args.artifacts) == (args.hex is not None):
            raise BadInput("give ARTIFACT files or --hex, not both or neither")
        if args.hex is not None:
            try:
                inputs = [("--hex", bytes.fromhex(args.hex))]
            except ValueError:
                raise BadInput("--hex: not a hex string") from None
        else:
            inputs = [(p.name, read_artifact(p)) for p in args.artifacts]
        groups = []
        for name, data in inputs:
            comment = f"found by the {TARGETS[args.target]} fuzz target ({name})" + (f": {args.why}" if args.why else "")
            for op, profile, inp in cases_of(args.target, data):
                groups.append(regression_vector(op, profile, inp, comment))
        if args.out is not None and not args.out.resolve().parent.is_dir():
            raise BadInput(f"--out {args.out}: directory {args.out.resolve().parent} does not exist")
    except BadInput as e:
        print(f"fuzz_to_vector: {e}", file=sys.stderr)
        return 2
    doc = suite_document(groups[0])
    doc["description"] = "regression cases found by coverage-guided fuzzing (tools/fuzz_to_vector.py)"
    doc["testGroups"], doc["numberOfTests"] = groups, len(groups)
    text = json.dumps(doc, indent=1, sort_keys=True, allow_nan=False) + "\n"
    if args.out is not None:
        args.out.write_text(text, encoding="utf-8")
    else:
        sys.stdout.write(text)
    for g in groups:
        t = g["tests"][0]
        print(f"{t['id']}: {t['result']} {json.dumps(t['expected'])[:120]}", file=sys.stderr)
        print(gen_vectors_line(g), file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
