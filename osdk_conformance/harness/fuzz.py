"""`osdkc fuzz`: differential fuzzing of two or more implementations.

Every testee (a command, or a bundled implementation by name) runs as a
child process speaking conformance/PROTOCOL.md under the supervision of
osdk_conformance.harness.testee, exactly as in `osdkc run`. Hypothesis generates
requests for the decoding operations (decode_stream, decode_frame,
decode_payload, classify_control_mode, check_movement_control) and every
testee that claims the operation (capabilities) answers each one; an
operation two or more testees claim is fuzzed. Inputs are mostly structured: valid values and
frames built with the Construct spec (osdk_construct.build_frame,
encode_movement_control; broadcast payloads sized by their flag word from
rules.yaml), then mutated (bit flips, header bit flips with the CRCs made
right again so that the flip reaches the checks behind them, truncation,
extension, garbage insertion, deletion), and concatenated with noise for
streams; some are raw random bytes.

Answers are compared with the golden vectors' own judge,
osdk_conformance.harness.vectors.compare: the first testee's answer is turned into
a case (valid with its result, or invalid with its error class) and every
other answer must pass it, so `ok`, the error class and the result models
are compared exactly as `osdkc run` compares them (floats by their bits,
decode_stream events by kind, offset, error, length and frame only). An
answer the testee could not give (crash, timeout, garbage) counts as the
error class testee_crash / testee_timeout / testee_garbage. An
`unsupported` answer makes the example not count.

On the first disagreement Hypothesis shrinks the example; the minimised
input and every testee's answer are printed, and a vector file
(FORMAT.md, one group: operation, profile and one test whose result and expected
come from osdk_conformance.reference.codec.answer, category fuzz.regression; its
one flag is the spec rule behind the reference's error class, or of the
operation, because vectors.schema.json wants at least one; refine it when
adding the case to its suite's module in tools/vectorgen/) is written to --out (default: standard output, the report then goes to
standard error); `osdkc run --vectors` replays it as it is. Exit status 1.
Without a disagreement within the budget the command prints a summary (examples run, executions per second per
operation) and exits 0.

Budget and reproducibility. Hypothesis runs in batches of at most
BATCH examples; the run ends when `--max-examples` examples have run or
when `--seconds` have passed (checked between batches, so a run may
overshoot by one batch; shrinking is never cut short). Batch k uses the
Hypothesis seed S * SEED_STRIDE + k, where S is `--seed` or, without it, a
random seed that the summary prints: the same seed replays the same
examples (a time budget only decides how many batches run). The
example database is never used (database=None): a run reads and writes no
.hypothesis directory, and what it finds is reproduced by its seed or by
the written vector.
"""
from __future__ import annotations

import argparse
import functools
import hashlib
import json
import random
import struct
import sys
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Sequence, TextIO

from osdk_conformance import _construct as osdk_construct
from osdk_conformance.core.crc import crc16, crc32
from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.options import non_negative_int, positive_float, positive_int
from osdk_conformance.core.paths import CACHE
from osdk_conformance.core.rules import default_rules, input_ranges, profile as rules_profile
from osdk_conformance.harness.runner import ALL, BUNDLED_IMPLS, impl_argv, parse_capabilities, start_error
from osdk_conformance.harness.spec_rules import rule_flag
from osdk_conformance.harness.testee import Testee, TesteeFailure, TesteeStartError, split_command
from osdk_conformance.harness.vectors import Case, compare, project_result
from osdk_conformance.reference.codec import PROFILES, answer
from osdk_conformance._construct import payload as pl
from osdk_conformance._construct.floats import F32

FUZZ_OPS = ("decode_stream", "decode_frame", "decode_payload", "classify_control_mode", "check_movement_control")
CATEGORY = "fuzz.regression"
BATCH = 200
SEED_STRIDE = 1_000_003
"""Batch k of a run with seed S uses the Hypothesis seed S * SEED_STRIDE + k
(so runs with neighbouring seeds share no batch)."""
DEFAULT_SECONDS = 30.0
DEFAULT_TIMEOUT = 10.0

# The flag a regression case carries (vectors.schema.json wants at least
# one): the rule behind the reference's error class, else the operation's.
_ERROR_RULES = {
    "bad_sof": "frame.sof", "bad_crc16": "frame.crc16", "bad_crc32": "frame.crc32", "bad_version": "frame.ver",
    "impossible_length": "frame.len", "bad_encryption": "frame.enc", "bad_session": "frame.session",
    "truncated_frame": "frame.truncation", "undefined_mode": "control.undefined_mode",
    "out_of_range": "control.ranges",
}
_OP_RULES = {
    "decode_stream": "stream.resync", "decode_frame": "frame.data", "classify_control_mode": "control.classification",
    "check_movement_control": "control.ranges",
}


# ============================================================== inputs


def _hypothesis_home() -> None:
    """Hypothesis keeps caches of its own (the constants it collects from the
    code under test) in ./.hypothesis unless told otherwise: they go to the
    kit's cache folder, not into the user's working directory."""
    from hypothesis.configuration import set_hypothesis_home_dir

    set_hypothesis_home_dir(str(CACHE / "hypothesis"))


def _strategies(profiles: Sequence[str], ops: Sequence[str]):
    """The Hypothesis strategy of (op, profile, input) examples."""
    from hypothesis import strategies as st

    sizes: dict[int, int | None] = {}
    for k, body in pl.BODY_BY_KEY.items():
        try:
            sizes[k] = None if callable(body) else body.sizeof()
        except Exception:  # noqa: BLE001 - variable-size body
            sizes[k] = None
    keys = sorted(sizes)
    layouts = {p: rules_profile(p) for p in profiles}

    # -- mutations ---------------------------------------------------------
    float_patterns = (struct.pack("<I", 0x7F800001), struct.pack("<I", 0x80000000), struct.pack("<I", 0xFFBFFFFF),
                      struct.pack("<Q", 0x7FF0000000000001), struct.pack("<Q", 0x8000000000000000))
    mutation = st.tuples(st.sampled_from(("flip", "header_flip", "truncate", "extend", "insert", "delete", "set",
                                          "float")),
                         st.integers(0, 1 << 16), st.binary(min_size=1, max_size=8))

    def sometimes(strategy, chance: int = 2):
        """`strategy`'s value in about (chance-1)/chance of the draws, else ()
        (an explicit integer draw: Hypothesis' one_of favours its first branch)."""
        return st.integers(0, chance - 1).flatmap(lambda k: strategy if k else st.just(()))

    mutations = sometimes(st.lists(mutation, min_size=1, max_size=3).map(tuple))

    def mutate(data: bytes, muts, fix_crcs: bool = False) -> bytes:
        out = bytearray(data)
        for kind, pos, extra in muts:
            n = len(out)
            if kind == "flip" and n:
                bit = pos % (n * 8)
                out[bit // 8] ^= 1 << (bit % 8)
            elif kind == "header_flip" and n >= 10:
                bit = 8 + pos % 72  # bytes 1..9: LEN/VER, session/ACK/RES0, PADDING/ENC, RES1, SEQ
                out[bit // 8] ^= 1 << (bit % 8)
            elif kind == "truncate" and n:
                del out[n - 1 - pos % n:]  # small pos: drop the last byte or few
            elif kind == "extend":
                out += extra
            elif kind == "insert":
                i = pos % (n + 1)
                out[i:i] = extra
            elif kind == "delete" and n:
                del out[pos % n]
            elif kind == "set" and n:
                out[pos % n] = extra[0]
            elif kind == "float" and n:
                # a signalling NaN or -0.0 written over what may be a float field
                pattern = float_patterns[extra[0] % len(float_patterns)]
                i = pos % n
                out[i:i + len(pattern)] = pattern[:n - i]
        if fix_crcs and len(out) >= 12:
            out[10:12] = struct.pack("<H", crc16(bytes(out[:10])))
            length = (out[1] | out[2] << 8) & 0x3FF
            if 16 < length <= len(out):
                out[length - 4:length] = struct.pack("<I", crc32(bytes(out[:length - 4])))
        return bytes(out)

    # Header fields by their bits in bytes 1..9 read as one little-endian
    # integer. Setting one to a boundary value and fixing the CRCs reaches
    # checks a random bit flip rarely does (an ACK in session 0, PADDING on
    # a plain frame, a LEN of 13).
    header_fields = {"len": (0, 10), "ver": (10, 6), "session": (16, 5), "is_ack": (21, 1), "res0": (22, 2),
                     "padding": (24, 5), "enc": (29, 3), "res1": (32, 24), "seq": (56, 16)}
    boundary = {"len": (0, 11, 12, 13, 15, 16, 17, 18, 1023), "ver": (1, 63), "session": (0, 1, 31),
                "is_ack": (0, 1), "res0": (1, 3), "padding": (0, 1, 15, 16, 17, 31), "enc": (0, 1, 2, 7),
                "res1": (1, 1 << 23), "seq": (0, 0xFFFF)}

    def set_fields(data: bytes, changes) -> bytes:
        if len(data) < 10 or not changes:
            return data
        word = int.from_bytes(data[1:10], "little")
        for name, value in changes:
            shift, width = header_fields[name]
            mask = (1 << width) - 1
            word = word & ~(mask << shift) | (value & mask) << shift
        return data[:1] + word.to_bytes(9, "little") + data[10:]

    # -- values ------------------------------------------------------------
    def bits_of(value: float) -> int:
        return struct.unpack("<I", struct.pack("<f", value))[0]

    def near(value: float) -> list[int]:
        """The float32 bits of `value` and of its two neighbours."""
        b = bits_of(value)
        if b in (0, 0x80000000):
            return [0, 0x80000000, 1, 0x80000001]
        return [b, b + 1, b - 1]

    special_bits = [0x00000000, 0x80000000, 0x7F800000, 0xFF800000, 0x7FC00000, 0xFFC00000, 0x7F800001,
                    0xFF800001, 0x7FBFFFFF, 0x7FC12345, 0x00000001, 0x807FFFFF, 0x7F7FFFFF]
    for v in (4.0, 10.0, 30.0, 100.0, 180.0, 5.0, 35.0, 150.0, 2.0, 7.5, 120.0):
        special_bits += near(v) + near(-v)
    f32_bits = st.one_of(st.sampled_from(sorted(set(special_bits))), st.integers(0, 0xFFFFFFFF),
                         st.floats(width=32, allow_nan=False).map(bits_of))
    axis_range = {"x": "horizontal", "y": "horizontal", "z": "vertical", "yaw": "yaw"}
    non_finite = {0x7FC00000, 0x7F800001, 0x7F800000, 0xFF800000}

    documented_modes = sorted({c["value"] for c in _combinations()})

    @st.composite
    def movement_value(draw, profile: str) -> bytes:
        """A movement control value. Mostly a documented mode byte (any frame
        and bit 0) whose setpoints are inside the combination's ranges but for
        one probed axis, which is at, just inside or just outside a limit, or
        anything at all; else any mode byte and any setpoints."""
        # a documented mode: bits 7-3 from the table, frame 00/01, any bit 0
        if draw(st.integers(0, 3)):
            mode = draw(st.sampled_from(documented_modes)) | draw(st.integers(0, 3))
        else:
            mode = draw(st.integers(0, 255))
        ranges = input_ranges(mode, profile)
        if ranges is None:
            return osdk_construct.encode_movement_control(mode, *(F32(draw(f32_bits)) for _ in range(4)))
        probe = draw(st.sampled_from(tuple(axis_range)))
        xs = []
        for axis, which in axis_range.items():
            lo, hi = ranges[which].get("min"), ranges[which].get("max")
            inside = [bits_of(float(v)) for v in (lo, hi) if v is not None]
            inside.append(bits_of((lo + hi) / 2) if lo is not None and hi is not None else bits_of(float(lo or 0)))
            if axis != probe:
                xs.append(F32(draw(st.sampled_from(inside))))
                continue
            # mostly a limit, its neighbours or a non-finite value; else anything
            edge = sorted({b for v in (lo, hi) if v is not None for b in near(float(v))} | non_finite)
            xs.append(F32(draw(st.sampled_from(edge) if draw(st.integers(0, 3)) else f32_bits)))
        return osdk_construct.encode_movement_control(mode, *xs)

    @st.composite
    def broadcast_value(draw, profile: str) -> bytes:
        layout = layouts[profile]
        # each item present with probability 1/2 (an integer draw favours small
        # flag words, i.e. the first items); sometimes reserved bits as well
        bits = draw(st.lists(st.booleans(), min_size=len(layout.flag_bits), max_size=len(layout.flag_bits)))
        flags = sum(b << i for i, b in enumerate(bits)) | draw(st.one_of(st.just(0), st.integers(0, 0xFFFF)))
        n = layout.payload_size(flags & layout.all_flags)
        return struct.pack("<H", flags) + draw(st.binary(min_size=n, max_size=n))

    @st.composite
    def payload(draw, profile: str, is_ack: bool | None = None, k: int | None = None):
        if k is None:
            choices = [k for k in keys if is_ack is None or bool(k >> 16) == is_ack] + ["unknown"]
            k = draw(st.sampled_from(choices))
        if k == "unknown":
            ack = draw(st.booleans()) if is_ack is None else is_ack
            cmd_set, cmd_id = draw(st.integers(0, 255)), draw(st.integers(0, 255))
            return cmd_set, cmd_id, ack, draw(st.binary(max_size=40))
        ack, cmd_set, cmd_id = bool(k >> 16), k >> 8 & 0xFF, k & 0xFF
        if k == 0x0200:
            value = draw(broadcast_value(profile))
        elif k == 0x0103:
            value = draw(movement_value(profile))
        elif sizes[k] is not None:
            n = sizes[k]
            # random bytes, or a small number first (codes and enums sit at offset 0)
            small = st.one_of(st.integers(0, 15), st.integers(0, 0x1FF))
            value = draw(st.one_of(st.binary(min_size=n, max_size=n),
                                   small.map(lambda v: v.to_bytes(2, "little")[:n] + bytes(max(n - 2, 0)))))
        else:
            value = draw(st.binary(max_size=40))
        return cmd_set, cmd_id, ack, value

    @st.composite
    def frame(draw, profile: str) -> bytes:
        """A frame built valid by osdk_construct.build_frame, then often one
        header field set to a boundary value (CRCs made right again), then
        sometimes mutated (CRCs made right again or not)."""
        shape = draw(st.sampled_from(("command", "ack", "header_only", "aes")))
        seq = draw(st.integers(0, 0xFFFF))
        session = draw(st.integers(0, 31))
        fields: list[tuple[str, int]] = []
        if shape == "command":
            cmd_set, cmd_id, _, value = draw(payload(profile, is_ack=False))
            raw = osdk_construct.build_frame(cmd_set=cmd_set, cmd_id=cmd_id, value=value, session=session, seq=seq)
        elif shape == "ack":
            _, _, _, value = draw(payload(profile, is_ack=True))
            raw = osdk_construct.build_frame(value=value, is_ack=True, session=max(session, 1), seq=seq)
            fields.append(("session", session))  # an ACK in session 0 (1 in 32)
        elif shape == "header_only":
            ack = draw(st.booleans())
            raw = osdk_construct.build_frame(is_ack=ack, session=max(session, int(ack)), seq=seq)
            fields.append(("session", session))
        else:
            blocks = draw(st.integers(1, 4))
            raw = osdk_construct.build_frame(value=draw(st.binary(min_size=16 * blocks, max_size=16 * blocks)),
                                             enc=1, padding=draw(st.integers(1, 16)), seq=seq, session=session)
        if draw(st.integers(0, 1)):
            name = draw(st.sampled_from(sorted(header_fields)))
            boundary_value = draw(st.integers(0, 3)) != 0
            fields.append((name, draw(st.sampled_from(boundary[name]) if boundary_value
                                      else st.integers(0, (1 << header_fields[name][1]) - 1))))
        raw = mutate(set_fields(raw, fields), (), fix_crcs=True)
        return mutate(raw, draw(mutations), fix_crcs=draw(st.integers(0, 1)) == 1)

    answered = [k for k in keys if not k >> 16 and k | 0x10000 in sizes]

    @st.composite
    def exchange(draw, profile: str) -> bytes:
        """A command in session 1..31 and its ACK (same session and SEQ,
        value possibly mutated): what ACK matching works on."""
        k = draw(st.sampled_from(answered))
        session, seq = draw(st.integers(1, 31)), draw(st.integers(0, 0xFFFF))
        cmd_set, cmd_id, _, value = draw(payload(profile, k=k))
        _, _, _, ack = draw(payload(profile, k=k | 0x10000))
        return (osdk_construct.build_frame(cmd_set=cmd_set, cmd_id=cmd_id, value=value, session=session, seq=seq)
                + osdk_construct.build_frame(value=mutate(ack, draw(mutations)), is_ack=True, session=session,
                                             seq=seq))

    raw_bytes = st.binary(max_size=64)
    raw_frame = st.one_of(raw_bytes, raw_bytes.map(lambda b: b"\xaa" + b))

    def example(op: str):
        prof = st.sampled_from(tuple(profiles))
        if op == "classify_control_mode":
            return st.tuples(st.just(op), prof, st.integers(0, 255).map(lambda b: {"byte": b}))
        if op == "check_movement_control":
            size_change = st.tuples(st.tuples(st.sampled_from(("truncate", "extend")), st.integers(0, 64),
                                              st.binary(min_size=1, max_size=4)))

            @st.composite
            def movement_example(draw):
                p = draw(prof)
                shape = draw(st.integers(0, 4))  # three in five 17-byte values, then a length changed, then raw
                if shape < 3:
                    value = draw(movement_value(p))
                elif shape == 3:
                    value = mutate(draw(movement_value(p)), draw(size_change))
                else:
                    value = draw(st.binary(min_size=15, max_size=19))
                return op, p, {"hex": value.hex()}
            return movement_example()
        if op == "decode_payload":
            @st.composite
            def payload_example(draw):
                p = draw(prof)
                cmd_set, cmd_id, ack, value = draw(payload(p))
                value = mutate(value, draw(mutations))
                return op, p, {"hex": value.hex(), "cmd_set": cmd_set, "cmd_id": cmd_id, "is_ack": ack}
            return payload_example()
        if op == "decode_frame":
            @st.composite
            def frame_example(draw):
                p = draw(prof)
                data = draw(frame(p) if draw(st.integers(0, 5)) else raw_frame)
                return op, p, {"hex": data.hex()}
            return frame_example()
        if op == "decode_stream":
            @st.composite
            def stream_example(draw):
                p = draw(prof)
                parts = draw(st.lists(st.one_of(frame(p), st.binary(min_size=1, max_size=16), st.just(b"\xaa"),
                                                exchange(p)), min_size=1, max_size=4))
                data = b"".join(parts)
                chunks = draw(st.lists(st.integers(0, 48), max_size=5))
                return op, p, {"hex": data.hex(), "chunks": chunks}
            return stream_example()
        raise ValueError(f"cannot fuzz {op}")

    return st.one_of([example(op) for op in ops])


@functools.lru_cache(maxsize=None)
def _strategy_of(op: str, profile: str):
    """One operation's strategy, built once: building one costs about as much as drawing 64 examples."""
    return _strategies([profile], [op])


def drawn_inputs(op: str, profile: str, count: int, seed: int) -> list[dict]:
    """Up to `count` inputs of `op` for `profile`, drawn from the strategies
    above (Hypothesis' generate phase only; the same seed draws the same
    inputs): how `osdkc fuzz --port` gets its generated frames and streams
    from the one generator the differential fuzzer uses."""
    from hypothesis import HealthCheck, Phase, Verbosity, given, settings
    from hypothesis import seed as hypothesis_seed

    _hypothesis_home()

    drawn: list[dict] = []

    def keep(example) -> None:
        drawn.append(example[2])

    test = settings(max_examples=count, deadline=None, database=None, phases=(Phase.generate,),
                    verbosity=Verbosity.quiet, suppress_health_check=list(HealthCheck))(
        hypothesis_seed(seed)(given(_strategy_of(op, profile))(keep)))
    test()
    return drawn


def _combinations() -> list[dict]:
    """The documented control mode combinations (rules.yaml): mask value of bits 7-3."""

    return list(default_rules().data["control_modes"]["combinations"])


# ============================================================== testees and comparison


@dataclass
class Fuzzee:
    label: str
    argv: list[str]
    testee: Any = None
    name: str = ""


@dataclass(eq=False)  # hashable by identity, as exceptions are
class Disagreement(Exception):
    op: str
    profile: str
    input: dict
    answers: list[dict]
    reason: str
    between: tuple[int, int]

    def __str__(self) -> str:
        return f"{self.op} ({self.profile}): {self.reason}"


# The place of an answer a testee was not asked for: the operation is not among its capabilities.
NOT_CLAIMED = {"ok": False, "unsupported": True, "detail": "operation not claimed: not asked"}


@dataclass
class OpStats:
    examples: int = 0
    seconds: float = 0.0

    @property
    def rate(self) -> float:
        return self.examples / self.seconds if self.seconds else 0.0


def _case_of(op: str, profile: str, inp: dict, answer: dict):
    """A vectors.Case whose expectation is `answer` (valid with its result, or invalid with its error)."""

    if answer.get("ok"):
        try:
            expected = project_result(op, answer["result"])
        except Exception:  # noqa: BLE001 - a result of the wrong shape is compared as it is
            expected = answer["result"]
        result = "valid"
    else:
        result, expected = "invalid", {"error": answer.get("error")}
    return Case(file="fuzz", operation=op, profile=profile, id="fuzz", category=CATEGORY, comment="fuzz",
                input=inp, result=result, expected=expected, flags=())


def disagreement(op: str, profile: str, inp: dict, answers: Sequence[dict]) -> tuple[str, tuple[int, int]] | None:
    """Why the answers disagree (judged by vectors.compare against the first), or None."""

    case = _case_of(op, profile, inp, answers[0])
    for i, a in enumerate(answers[1:], 1):
        try:
            passed, reason = compare(case, a)
        except Exception as e:  # noqa: BLE001 - as the runner does: an answer the judge chokes on differs
            passed, reason = False, f"the answer could not be compared ({type(e).__name__}: {e})"
        if not passed:
            return reason, (0, i)
    return None


def _ask(f: Fuzzee, request: dict) -> dict:
    try:
        return f.testee.request(request)
    except TesteeFailure as e:
        return {"ok": False, "error": e.kind, "detail": e.message}


# ============================================================== the run


@dataclass
class FuzzOutcome:
    fuzzees: list[Fuzzee]
    ops: list[str]
    profiles: list[str]
    seed: int
    examples: int
    seconds: float
    stats: dict[str, OpStats] = field(default_factory=dict)
    found: Disagreement | None = None
    shrink_runs: int = 0
    """Examples run while shrinking the disagreement (not in `examples`)."""
    flaky: bool = False
    """The disagreement did not reproduce every time (a testee that is not deterministic)."""


def start_fuzzees(commands: Sequence[tuple[str | None, Sequence[str]]],
                  timeout: float = DEFAULT_TIMEOUT) -> list[Fuzzee]:
    """Start every testee and ask for its capabilities. A testee's label is
    the one given, else the name it reports in its capabilities, else its
    command; repeated labels get #2, #3, ..."""

    out: list[Fuzzee] = []
    for label, argv in commands:
        f = Fuzzee(label or " ".join(argv), list(argv))
        try:
            # Restarts are unlimited: a testee that crashes on every shrunk
            # example must keep answering with testee_crash, deterministically.
            f.testee = Testee(argv, timeout=timeout, max_restarts=1 << 30)
            f.testee.start()
            caps = parse_capabilities(f.testee.request({"op": "capabilities"}))
        except TesteeFailure as e:
            stop_fuzzees(out + [f])
            raise UsageError(str(start_error(f.testee, e))) from None
        except (TesteeStartError, ValueError) as e:
            stop_fuzzees(out + [f])
            raise UsageError(f"testee {f.label}: {e}") from None
        f.name = caps.name or f.label
        if label is None and caps.name:
            f.label = caps.name
        f.caps = caps  # type: ignore[attr-defined]
        taken = {g.label for g in out}
        if f.label in taken:
            f.label = next(f"{f.label}#{n}" for n in range(2, len(out) + 3) if f"{f.label}#{n}" not in taken)
        out.append(f)
    return out


def stop_fuzzees(fuzzees: Sequence[Fuzzee]) -> None:
    for f in fuzzees:
        if f.testee is not None:
            f.testee.close()


def fuzz(fuzzees: Sequence[Fuzzee], *, ops: Sequence[str] | None = None, profiles: Sequence[str] | None = None,
         seconds: float | None = DEFAULT_SECONDS, max_examples: int | None = None, seed: int | None = None,
         progress: Callable[[int, float], None] | None = None) -> FuzzOutcome:
    """Fuzz the started testees against each other (see the module doc)."""
    from hypothesis import HealthCheck, Phase, Verbosity, given, settings
    from hypothesis import seed as hypothesis_seed

    _hypothesis_home()

    # An operation is fuzzed among the testees that claim it, when two or more
    # do: one that only decodes (accel) must not take the others' control
    # mode and movement checks out of `fuzz --impl all`.
    claimants = {op: [i for i, f in enumerate(fuzzees) if op in f.caps.operations]  # type: ignore[attr-defined]
                 for op in FUZZ_OPS}
    fuzzable = [op for op in FUZZ_OPS if len(claimants[op]) >= 2]
    common_profiles = [p for p in PROFILES if all(p in f.caps.profiles for f in fuzzees)]  # type: ignore[attr-defined]
    ops = [op for op in (ops or fuzzable) if op in fuzzable]
    profiles = [p for p in (profiles or common_profiles) if p in common_profiles]
    if not ops or not profiles:
        raise UsageError("the testees have no fuzzable operation and profile in common (an operation needs two "
                         f"testees that claim it; operations {', '.join(fuzzable) or 'none'}; "
                         f"profiles {', '.join(common_profiles) or 'none'})")
    if seed is None:
        seed = random.SystemRandom().randrange(1 << 32)
    strategy = _strategies(profiles, ops)
    stats = {op: OpStats() for op in ops}
    outcome = FuzzOutcome(list(fuzzees), ops, profiles, seed, 0, 0.0, stats)
    counter: dict[str, Any] = {"n": 0, "found_at": None}

    def check(example) -> None:
        op, profile, inp = example
        request = {"op": op, "id": f"fuzz.{counter['n']}", "profile": profile, **inp}
        askers = claimants[op]
        t0 = time.perf_counter()
        answers = [_ask(f, request) if i in askers else dict(NOT_CLAIMED) for i, f in enumerate(fuzzees)]
        stats[op].seconds += time.perf_counter() - t0
        stats[op].examples += 1
        counter["n"] += 1
        if any(answers[i].get("unsupported") is True for i in askers):
            return
        d = disagreement(op, profile, inp, [answers[i] for i in askers])
        if d is not None:
            if counter["found_at"] is None:
                counter["found_at"] = counter["n"]
            reason, (a, b) = d
            raise Disagreement(op, profile, inp, answers, reason, (askers[a], askers[b]))

    start = time.monotonic()
    batch = 0
    try:
        while True:
            left = None if not max_examples else max_examples - counter["n"]
            if (left is not None and left <= 0) or (seconds and batch and time.monotonic() - start >= seconds):
                break
            size = BATCH if left is None else min(BATCH, left)
            test = settings(max_examples=size, deadline=None, database=None, derandomize=False,
                            phases=(Phase.generate, Phase.shrink), report_multiple_bugs=False, print_blob=False,
                            verbosity=Verbosity.quiet, suppress_health_check=list(HealthCheck))(
                hypothesis_seed(seed * SEED_STRIDE + batch)(given(strategy)(check)))
            before = counter["n"]
            test()
            batch += 1
            if progress is not None:
                progress(counter["n"], time.monotonic() - start)
            if counter["n"] == before:  # nothing left to generate
                break
    except Disagreement as d:
        outcome.found = d
    except Exception as e:  # noqa: BLE001 - e.g. Hypothesis' FlakyFailure around a Disagreement
        d = _find_disagreement(e)
        if d is None:
            raise
        outcome.found, outcome.flaky = d, True
    outcome.examples = counter["n"] if counter["found_at"] is None else counter["found_at"]
    outcome.shrink_runs = counter["n"] - outcome.examples
    outcome.seconds = time.monotonic() - start
    return outcome


def _find_disagreement(exc: BaseException, depth: int = 0) -> Disagreement | None:
    """The Disagreement inside an exception group or chain, if any."""
    if isinstance(exc, Disagreement):
        return exc
    if depth > 8:
        return None
    for inner in [*getattr(exc, "exceptions", ()), exc.__cause__, exc.__context__]:
        if inner is not None:
            found = _find_disagreement(inner, depth + 1)
            if found is not None:
                return found
    return None


# ============================================================== the regression vector


def regression_group(d: Disagreement, labels: Sequence[str], seed: int) -> dict:
    """A vector group (FORMAT.md) holding the minimised example as one test,
    its expectation from the reference."""
    a, b = d.between
    comment = (f"found by osdkc fuzz (seed {seed}): {labels[a]} and {labels[b]} disagree: {d.reason}")
    return regression_vector(d.op, d.profile, d.input, comment)


def regression_vector(op: str, profile: str, inp: dict, comment: str) -> dict:
    """A vector group (FORMAT.md) holding `inp` as one test of category
    fuzz.regression, its expectation from the reference (also what
    tools/fuzz_to_vector.py makes of a coverage-guided fuzzer's finding)."""

    ref = answer(op, profile, inp)
    if ref.get("ok"):
        result, expected = "valid", project_result(op, ref["result"])
    else:
        result, expected = "invalid", {"error": ref["error"]}
    digest = hashlib.sha256(json.dumps([op, profile, inp], sort_keys=True).encode()).hexdigest()[:12]
    test = {"id": f"fuzz.regression.{op}.{profile.replace('.', '_')}.{digest}", "category": CATEGORY,
            "comment": comment, "input": inp, "result": result, "expected": expected,
            "flags": [rule_flag(flag_rule(op, inp, ref))]}
    return {"operation": op, "profile": profile, "tests": [test]}


def flag_rule(op: str, inp: dict, ref: dict) -> str:
    """The spec rule a regression case pins (vectors.schema.json wants at
    least one flag): the rule behind the reference's error class, else the
    rule of the operation or, for decode_payload, of the value's layout."""
    broadcast = op == "decode_payload" and (inp["cmd_set"], inp["cmd_id"], inp["is_ack"]) == (2, 0, False)
    if not ref.get("ok"):
        err = ref["error"]
        if err in _ERROR_RULES:
            return _ERROR_RULES[err]
        if err == "reserved_bits":
            return "frame.reserved" if op in ("decode_frame", "decode_stream") else "broadcast.reserved_flags"
        if err in ("truncated_payload", "length_mismatch") and op == "decode_payload":
            return "broadcast.bounds" if broadcast else (
                "payload.truncated" if err == "truncated_payload" else "payload.trailing")
        if err == "length_mismatch" and op == "decode_frame":
            return "frame.extra_bytes"
        if err in ("truncated_payload", "length_mismatch") and op == "check_movement_control":
            return "control.value"
    if op == "decode_payload":
        return _payload_rule(inp)
    return _OP_RULES[op]


def _payload_rule(inp: dict) -> str:
    """The rule a decode_payload case of this command pins (its value layout)."""
    names = {(0, 0, False): "payload.version_query", (0, 0, True): "payload.version_ack",
             (0, 1, False): "payload.activation_request", (0, 1, True): "payload.activation_ack",
             (0, 0x10, False): "payload.frequency_request", (0, 0x10, True): "payload.frequency_ack",
             (1, 0, False): "payload.control_request", (1, 0, True): "payload.control_ack",
             (1, 3, False): "payload.movement_control", (2, 0, False): "broadcast.item_fields",
             (2, 1, False): "payload.lost_control", (2, 1, True): "payload.lost_control_ack"}
    return names.get((inp["cmd_set"], inp["cmd_id"], inp["is_ack"]), "payload.unknown")


def suite_document(group: dict) -> dict:
    """A vector file holding one group, for replaying it with `osdkc run --vectors`."""
    return {"suite": "fuzz_regression", "description": "a regression case found by osdkc fuzz",
            "generator": "tools/gen_vectors.py", "numberOfTests": len(group["tests"]), "notes": {},
            "testGroups": [group]}


# ============================================================== the command


def add_arguments(p: argparse.ArgumentParser, profiles: Sequence[str]) -> None:
    p.add_argument("--testee", action="append", default=[], metavar="COMMAND",
                   help="command that starts an implementation (split like a shell does; repeatable)")
    p.add_argument("--impl", action="append", default=[], choices=[*BUNDLED_IMPLS, ALL], metavar="IMPL",
                   help=f"a bundled implementation (repeatable; {', '.join(BUNDLED_IMPLS)}), or {ALL} for every one")
    p.add_argument("--seconds", type=positive_float, metavar="N",
                   help=f"time budget in seconds (default {DEFAULT_SECONDS:g} unless --max-examples is given)")
    p.add_argument("--max-examples", type=positive_int, metavar="N", help="stop after N examples")
    p.add_argument("--seed", type=non_negative_int, metavar="S", help="Hypothesis seed (default: random, printed)")
    p.add_argument("--out", metavar="FILE",
                   help="where the regression vector file goes (default: stdout); `osdkc run --vectors FILE` replays it")
    p.add_argument("--op", action="append", choices=FUZZ_OPS, metavar="OP",
                   help=f"only this operation (repeatable; {', '.join(FUZZ_OPS)})")
    p.add_argument("--profile", action="append", choices=profiles, metavar="PROFILE", help="only this profile (repeatable)")
    p.add_argument("--timeout", type=positive_float, metavar="S",
                   help=f"seconds per request (default {DEFAULT_TIMEOUT:g})")


def _show(obj: Any, limit: int = 2000) -> str:
    text = json.dumps(obj, sort_keys=True)
    return text if len(text) <= limit else text[:limit] + "…"


def print_summary(outcome: FuzzOutcome, out: TextIO) -> None:
    names = " vs ".join(f.label for f in outcome.fuzzees)
    runs = outcome.examples + outcome.shrink_runs
    rate = runs / outcome.seconds if outcome.seconds else 0.0
    shrunk = f" (+{outcome.shrink_runs} while shrinking)" if outcome.found is not None else ""
    out.write(f"osdkc fuzz: {names}: {outcome.examples} examples{shrunk} in {outcome.seconds:.1f} s "
              f"({rate:.0f}/s), seed {outcome.seed}\n")
    out.write(f"  profiles: {', '.join(outcome.profiles)}; execs/s: examples per second of request time "
              f"(every testee answering)\n")
    for op, s in outcome.stats.items():
        out.write(f"  {op:24} {s.examples:7} runs  {s.rate:7.0f} execs/s\n")


def print_disagreement(d: Disagreement, fuzzees: Sequence[Fuzzee], out: TextIO) -> None:
    out.write(f"DISAGREEMENT on {d.op} ({d.profile}), minimised input:\n")
    out.write(f"  {_show(d.input)}\n")
    for f, a in zip(fuzzees, d.answers):
        out.write(f"  [{f.label}] {_show(a)}\n")
    a, b = d.between
    out.write(f"  {fuzzees[b].label} against {fuzzees[a].label}: {d.reason}\n")


def run_fuzz(args: argparse.Namespace) -> int:
    names = [n for name in args.impl for n in (BUNDLED_IMPLS if name == ALL else [name])]
    commands: list[tuple[str | None, list[str]]] = [(name, impl_argv(name)) for name in dict.fromkeys(names)]
    try:
        commands += [(None, split_command(cmd)) for cmd in args.testee]
    except Exception as e:  # noqa: BLE001 - TesteeStartError from a command that does not split
        raise UsageError(str(e)) from None
    if len(commands) < 2:
        raise UsageError("give at least two implementations (--testee COMMAND / --impl NAME)")
    seconds = args.seconds if args.seconds is not None else (None if args.max_examples else DEFAULT_SECONDS)
    if args.out:
        parent = Path(args.out).resolve().parent
        if not parent.is_dir():
            raise UsageError(f"--out {args.out}: directory {parent} does not exist")
    human = sys.stdout if args.out else sys.stderr

    fuzzees = start_fuzzees(commands, timeout=args.timeout or DEFAULT_TIMEOUT)
    try:
        outcome = fuzz(fuzzees, ops=args.op, profiles=args.profile, seconds=seconds,
                       max_examples=args.max_examples, seed=args.seed)
    except TesteeStartError as e:  # a testee that could be started once cannot be restarted
        raise UsageError(str(e)) from None
    finally:
        stop_fuzzees(fuzzees)
    print_summary(outcome, human)
    if outcome.found is None:
        human.write("no disagreement\n")
        human.flush()
        return 0
    print_disagreement(outcome.found, fuzzees, human)
    if outcome.flaky:
        human.write("note: the disagreement did not reproduce every time (a testee is not deterministic)\n")
    group = regression_group(outcome.found, [f.label for f in fuzzees], outcome.seed)
    text = json.dumps(suite_document(group), indent=1, sort_keys=True, allow_nan=False) + "\n"
    if args.out:
        try:
            Path(args.out).write_text(text, encoding="utf-8")
        except OSError as e:
            raise UsageError(f"cannot write {args.out}: {e.strerror or e}") from None
        human.write(f"regression vector file written to {args.out} (replay: osdkc run --vectors {args.out})\n")
    else:
        human.flush()
        sys.stdout.write(text)
    sys.stdout.flush()
    return 1
