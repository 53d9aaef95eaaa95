"""The bundled "accel" testee: the native accelerator of osdk_conformance
(osdk_conformance/reference/_accel.c: the generated C decoder of
generated/c with the value model of generated/cpython), which `osdkc
decode`, the Python API and the acceptance receiver use when it is
installed. This testee holds it to the vectors like any implementation.

    osdkc run --impl accel
    python conformance/testees/accel_testee.py   # speaks JSON Lines on stdin/stdout
    python conformance/testees/accel_testee.py --bench FILE --profile P

The accelerator decodes; it does not classify mode bytes or encode. So the
testee claims decode_stream, decode_frame and decode_payload, and the run
reports the other operations' cases as skipped. It uses the native module
whatever OSDKC_ACCEL says (it is the implementation under test), and
exits with a message when the module is not installed.
"""
from __future__ import annotations

import importlib
import re
import sys
from types import ModuleType
from typing import Any, Callable, Iterable, Iterator, Sequence

from osdk_conformance.core.deframe import header_fields, split_chunks
from osdk_conformance.core.rules import profile as load_profile, profile_names
from osdk_conformance.harness.serve import serve
from osdk_conformance.reference.accel import MODULE

NAME = "osdk-accel"
PROFILES = profile_names()
OPERATIONS = ("decode_stream", "decode_frame", "decode_payload")
_HEX = re.compile(r"(?:[0-9a-fA-F]{2})*")


def native() -> ModuleType:
    try:
        return importlib.import_module(MODULE)
    except ImportError as e:
        raise SystemExit(f"accel testee: the native decoder is not installed ({e}); it is built when the package "
                         "is installed where a C compiler exists (`make setup`, or pip install)") from None


class BadRequest(ValueError):
    """The request does not have the shape conformance/PROTOCOL.md gives its operation."""


def _arg(req: dict, key: str, kind: type) -> Any:
    value = req.get(key)
    if key not in req or isinstance(value, bool) != (kind is bool) or not isinstance(value, kind):
        raise BadRequest(f"argument {key!r} is missing or not a {kind.__name__}")
    return value


def _hex(req: dict) -> bytes:
    text = _arg(req, "hex", str)
    if not _HEX.fullmatch(text):
        raise BadRequest("argument 'hex' is not a hex string of whole bytes")
    return bytes.fromhex(text)


def _byte(req: dict, key: str) -> int:
    value = _arg(req, key, int)
    if not 0 <= value <= 0xFF:
        raise BadRequest(f"argument {key!r} must be 0..255, got {value}")
    return value


def stream_events(module: ModuleType, chunks: Iterable[bytes], profile: str) -> Iterator[dict]:
    """decode_stream's events, one read after another (also the bench mode's loop)."""
    decoder = module.Decoder(load_profile(profile).value, header_fields)
    for chunk in chunks:
        yield from decoder.feed(chunk)
    yield from decoder.finish()


def answerer(module: ModuleType) -> Callable[[dict], dict]:
    def decode_stream(req: dict, profile: str) -> dict:
        data = _hex(req)
        sizes = _arg(req, "chunks", list)
        if not all(isinstance(s, int) and not isinstance(s, bool) and s >= 0 for s in sizes):
            raise BadRequest("argument 'chunks' must be a list of non-negative integers")
        return {"events": list(stream_events(module, split_chunks(data, sizes), profile))}

    def decode_frame(req: dict, profile: str) -> dict:
        return {"frame": module.decode_frame(_hex(req), load_profile(profile).value)}

    def decode_payload(req: dict, profile: str) -> dict:
        data, cmd_set, cmd_id, is_ack = _hex(req), _byte(req, "cmd_set"), _byte(req, "cmd_id"), _arg(req, "is_ack", bool)
        return {"value": module.decode_payload(data, cmd_set, cmd_id, is_ack, load_profile(profile).value)["body"]}

    ops = {"decode_stream": decode_stream, "decode_frame": decode_frame, "decode_payload": decode_payload}

    def answer(req: dict) -> dict:
        op = req["op"]
        if op == "capabilities":
            return {"ok": True, "result": {"name": NAME, "operations": list(OPERATIONS), "profiles": list(PROFILES)}}
        fn = ops.get(op)
        profile = req.get("profile")
        if fn is None or profile not in PROFILES:
            return {"ok": False, "unsupported": True}
        try:
            return {"ok": True, "result": fn(req, profile)}
        except module.DecodeError as e:
            cls, detail = e.args
            return {"ok": False, "error": cls, "detail": detail}

    return answer


def main(argv: Sequence[str] = ()) -> int:
    module = native()
    if argv:
        from osdk_conformance.harness import testee_bench

        return testee_bench.main(argv, "accel", PROFILES, lambda chunks, profile: stream_events(module, chunks, profile))
    return serve(answerer(module))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
