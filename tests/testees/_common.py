"""Shared by the misbehaving test testees: the capabilities answer."""
import json
import sys

CAPABILITIES = {"ok": True, "result": {
    "name": "misbehaving",
    "operations": ["decode_stream", "decode_frame", "decode_payload", "classify_control_mode",
                   "check_movement_control", "encode_movement_control", "encode_frame"],
    "profiles": ["m100-fw2.3", "m100-fw3.1", "a3-fw3.1"],
}}


def reply(obj) -> None:
    sys.stdout.write(json.dumps(obj) + "\n")
    sys.stdout.flush()


def requests():
    """Requests after capabilities (which is answered here)."""
    for line in sys.stdin:
        req = json.loads(line)
        if req.get("op") == "capabilities":
            reply(CAPABILITIES)
            continue
        yield req
