"""The published JSON Schemas of the testee protocol (conformance/schemas/,
written by tools/gen_schemas.py) and the check of a testee's response
against them.

`violation(op, profile, response)` says why a response line breaks its
operation's schema (a field that should not be there, an enum name the
spec does not have, an error class outside the list, a wrong type), or
None. The runner reports such a response as failure kind
`schema_violation`, apart from a wrong value (`mismatch`).

The lists below are the protocol's vocabulary that the spec files do not
hold: the error classes (docs/VALUE-MODEL.md) and which of them each
operation can answer. The schemas are generated from them.
"""
from __future__ import annotations

import functools
import json
from typing import Any

from osdk_conformance.core.paths import ROOT
from osdk_conformance.core.schema_check import SchemaCheck

SCHEMA_DIR = ROOT / "conformance" / "schemas"
BASE_URI = "https://osdk-conformance.local/schemas/"

ERROR_CLASSES: dict[str, str] = {
    "bad_sof": "a frame handed over on its own (decode_frame) does not start with 0xAA",
    "bad_crc16": "header CRC-16 wrong",
    "bad_version": "VER is not 0",
    "reserved_bits": "RES0/RES1 of the header, or reserved broadcast flag bits, not 0",
    "impossible_length": "LEN below 12 or in 13..16 (or, encoding, a frame longer than LEN can hold)",
    "bad_encryption": "ENC not 0 or 1, or PADDING impossible for it",
    "bad_session": "an ACK frame in session 0",
    "bad_crc32": "CRC-32 wrong",
    "truncated_frame": "the input ended inside a frame",
    "truncated_payload": "the value is shorter than its layout (or the broadcast flag word) needs",
    "length_mismatch": "bytes left over after the value (or after the frame)",
    "undecodable": "anything else the spec rejects (should not happen)",
    "undefined_mode": "a movement control mode byte that is not a documented combination of the profile",
    "out_of_range": "a movement control setpoint outside its range, NaN and infinities included",
    "bad_request": "the request is not what conformance/PROTOCOL.md gives its operation "
                   "(not JSON, a missing or ill-typed argument, hex that is not hex)",
    "internal_error": "the testee failed in a way of its own (a bug; the case fails)",
}

UNIVERSAL_ERRORS = ("bad_request", "internal_error")
"""Classes any operation may answer."""

# Per operation, in the order of reference.OPERATIONS, the classes it can
# answer besides UNIVERSAL_ERRORS.
OPERATION_ERRORS: dict[str, tuple[str, ...]] = {
    "capabilities": (),
    "decode_stream": (),
    "decode_frame": ("bad_sof", "truncated_frame", "bad_crc16", "bad_version", "reserved_bits",
                     "impossible_length", "length_mismatch", "bad_crc32", "bad_encryption", "bad_session",
                     "truncated_payload", "undecodable"),
    "decode_payload": ("reserved_bits", "truncated_payload", "length_mismatch", "undecodable"),
    "classify_control_mode": (),
    "check_movement_control": ("truncated_payload", "length_mismatch", "undefined_mode", "out_of_range",
                               "undecodable"),
    "encode_movement_control": ("undefined_mode", "out_of_range"),
    "encode_frame": ("impossible_length", "bad_session"),
}

STREAM_ERRORS = ("bad_crc16", "bad_version", "reserved_bits", "impossible_length", "bad_crc32", "truncated_frame",
                 "bad_encryption", "bad_session", "truncated_payload", "length_mismatch", "undecodable")
"""Classes a decode_stream `error` event can carry."""

SCHEMA_VIOLATION = "schema_violation"


@functools.cache
def _resources() -> tuple[tuple[str, dict], ...]:
    """(uri, contents) of every schema of conformance/schemas/."""
    resources = []
    for path in sorted(SCHEMA_DIR.glob("*.schema.json")):
        doc = json.loads(path.read_text(encoding="utf-8"))
        resources.append((doc["$id"], doc))
    if not resources:
        raise FileNotFoundError(f"no schemas in {SCHEMA_DIR} (run tools/gen_schemas.py)")
    return tuple(resources)


@functools.cache
def validator(op: str, profile: str | None, part: str = "response") -> SchemaCheck | None:
    """A Draft 2020-12 validator of `part` ("response" or "request") of
    `op`, for `profile` where the operation's result depends on it; None
    for an operation without a schema."""
    uri = f"{BASE_URI}{op}.schema.json"
    doc = dict(_resources()).get(uri)
    if doc is None:
        return None
    defs = doc["$defs"]
    name = f"{part}.{profile}" if f"{part}.{profile}" in defs else part
    if name not in defs:
        return None
    return SchemaCheck({"$ref": f"{uri}#/$defs/{name}"}, _resources())


def violation(op: str, profile: str | None, response: Any, part: str = "response") -> str | None:
    """Why `response` breaks the schema of `op` (one line, with the JSON path
    of the offending part), or None when it conforms or `op` has no schema."""
    from jsonschema.exceptions import best_match

    v = validator(op, profile, part)
    if v is None:
        return None
    err = best_match(v.iter_errors(response))
    if err is None:
        return None
    where = err.json_path
    text = err.message if len(err.message) <= 200 else err.message[:200] + "…"
    return f"{where}: {text}"



def case_violation(case: Any, response: Any, result_matches: bool) -> str | None:
    """violation() of a testee's response to a vector case. When the runner
    found the result identical to the case's expected result (any operation
    but decode_stream, whose comparison skips some event fields), only the
    envelope around it is checked: every expected result of the vectors is
    valid against these schemas (tests/test_response_schema.py), and
    validating 30,000 identical results again would double a run's time."""
    if (result_matches and case.operation != "decode_stream" and isinstance(response, dict)
            and response.get("ok") is True):
        return violation("protocol", None, response, part="ok")
    return violation(case.operation, case.profile, response)
