"""Construct's compiler on this spec (osdk_construct.compiled) against the interpreter.

The compiled parsers must read every input to the interpreter's value, and
must never accept an input the interpreter rejects (compiled.parse then
falls back to the interpreter, so errors are the interpreter's). Checked on
the inputs of the golden vectors (valid and invalid, every message type)
and on damaged full broadcast frames. The hot constructs (frames, broadcast
payloads) must also really compile: a silent fall-back to the interpreter
would be correct but several times slower.
"""
from __future__ import annotations

import functools
import json
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from osdk_conformance.core import model
from osdk_conformance.core.deframe import Frame, deframe
from osdk_conformance.core.rules import profile_names
from osdk_conformance._construct import build_frame, compiled, osdk_frame, osdk_payload
from osdk_conformance._construct.payload import broadcast as broadcast_value

VECTORS = Path(__file__).resolve().parent.parent / "vectors"
PROFILES = profile_names()
EVERY_NTH_FLAG_SUBSET = 16  # that category alone holds some 20,000 similar broadcasts


def outcome(parse, c, data: bytes):
    try:
        return "ok", model.from_construct(parse(c, data))
    except Exception as e:  # noqa: BLE001 - the class and text are what is compared
        return "error", type(e).__name__, str(e)


def interpreted(c, data: bytes):
    return c.parse(data)


def compiled_parser(c):
    """The compiled parser, asked for as often as it takes to have it made."""
    for _ in range(compiled.COMPILE_AFTER + 1):
        fast = compiled.parser(c)
    return fast


def check(c, data: bytes) -> tuple:
    """The interpreter's outcome, after checking the compiled parsers against it."""
    slow = outcome(interpreted, c, data)
    assert outcome(compiled.parse, c, data) == slow
    fast = compiled_parser(c)
    if fast is not None:
        raw = outcome(lambda c, d: fast.parse(d), c, data)
        if raw[0] == "ok":
            assert raw == slow, "the compiled parser reads another value"
    return slow


@functools.cache
def groups(path: Path) -> list[dict]:
    return json.loads(path.read_text())["testGroups"]


def vector_inputs():
    """(construct, bytes, whether the vector is valid or None when the layout
    alone does not say) of every decode_payload / decode_frame input and of
    every frame in the decode_stream inputs."""
    n = 0
    for path in sorted(VECTORS.glob("*.json")):
        if path.name in ("MANIFEST.json", "vectors.schema.json"):
            continue
        for group in groups(path):
            op, profile = group["operation"], group.get("profile")
            for t in group["tests"]:
                inp = t["input"]
                if t["category"] == "broadcast.flag_subsets":
                    n += 1
                    if n % EVERY_NTH_FLAG_SUBSET:
                        continue
                if op == "decode_payload":
                    yield (osdk_payload(inp["cmd_set"], inp["cmd_id"], inp["is_ack"], profile),
                           bytes.fromhex(inp["hex"]), t["result"] == "valid")
                elif op == "decode_frame":  # valid or not also depends on the CRCs, which the layout leaves out
                    yield osdk_frame(profile), bytes.fromhex(inp["hex"]), None
                elif op == "decode_stream":
                    for ev in deframe([bytes.fromhex(inp["hex"])]):
                        if isinstance(ev, Frame):
                            yield osdk_frame(profile), ev.raw, None


@pytest.mark.slow
def test_compiled_parsers_agree_on_every_vector_input():
    seen = valid = 0
    for c, data, is_valid in vector_inputs():
        result = check(c, data)
        seen += 1
        if is_valid is not None:
            assert (result[0] == "ok") == is_valid, data.hex()
            valid += is_valid
    assert seen > 2000 and valid > 500


@pytest.mark.parametrize("profile", PROFILES)
def test_frames_and_broadcasts_compile(profile):
    for c in (osdk_frame(profile), osdk_payload(2, 0, False, profile)):
        assert compiled_parser(c) is not None, c


def full_broadcast_frame(profile: str) -> bytes:
    """A broadcast frame with every item of the profile, from the all-items vector."""
    for group in groups(VECTORS / "broadcast.json"):
        if group.get("profile") != profile:
            continue
        for t in group["tests"]:
            if t["category"] == "broadcast.all_items" and t["result"] == "valid":
                value = bytes.fromhex(t["input"]["hex"])
                return build_frame(cmd_set=2, cmd_id=0, value=value, seq=7)
    raise AssertionError(f"no all-items broadcast vector for {profile}")


FULL = {p: full_broadcast_frame(p) for p in PROFILES}


@pytest.mark.parametrize("profile", PROFILES)
def test_full_broadcast_frames_take_the_compiled_path(profile):
    raw = FULL[profile]
    fast = compiled_parser(osdk_frame(profile)).parse(raw)  # raises if the compiled parser cannot read it
    assert model.from_construct(fast) == model.from_construct(osdk_frame(profile).parse(raw))
    payload = raw[14:-4]
    fast = compiled_parser(broadcast_value(profile)).parse(payload)
    assert model.from_construct(fast) == model.from_construct(broadcast_value(profile).parse(payload))


@settings(max_examples=300)
@given(profile=st.sampled_from(PROFILES), edits=st.lists(
    st.tuples(st.sampled_from(("flip", "overwrite", "insert", "delete", "truncate")),
              st.integers(0, 255), st.integers(0, 255)), min_size=1, max_size=3))
def test_damaged_broadcast_frames_agree(profile, edits):
    data = bytearray(FULL[profile])
    for edit, pos, value in edits:
        pos %= len(data) or 1
        if edit == "flip" and data:
            data[pos] ^= 1 << (value % 8)
        elif edit == "overwrite" and data:
            data[pos] = value
        elif edit == "insert":
            data[pos:pos] = bytes([value])
        elif edit == "delete":
            del data[pos:pos + 1 + value % 4]
        else:
            del data[pos:]
    check(osdk_frame(profile), bytes(data))
    if len(data) > 18:
        check(osdk_payload(2, 0, False, profile), bytes(data[14:-4]))
