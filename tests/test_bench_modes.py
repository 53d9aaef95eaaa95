"""The bench mode of every bundled implementation (conformance/PROTOCOL.md):
`<its argv from runner.BUNDLED_IMPLS> --bench FILE --profile P`.

For a stream made of every decode_stream and decode_frame input of a
profile's vectors, shuffled, separated by random garbage and longer than
one 64 KiB read, each implementation's bench line must count exactly the
frames, errors and garbage bytes its own decode_stream operation reports for
the same bytes; all implementations must print the same counts; `-` must
read standard input; and bad arguments must end with exit status 2 and one
line on standard error, no traceback. Times are printed, never asserted.

The C testee is skipped only if it reports --bench itself as an unknown
option (a build from before its bench mode).
"""
from __future__ import annotations

import json
import random
import re
import subprocess
from functools import cache
from pathlib import Path

import pytest

from osdk_conformance.harness import testee as testee_client
from osdk_conformance.harness.runner import BUNDLED_IMPLS, impl_argv
from osdk_conformance.harness.vectors import VECTORS_DIR, load_cases

IMPLS = list(BUNDLED_IMPLS)
# `make quick` runs the bench mode of the reference implementation; `make test` of every bundled one
QUICK_ONE_IMPL = [pytest.param(i, marks=() if i == "construct" else pytest.mark.slow) for i in IMPLS]
PROFILES = ("m100-fw2.3", "a3-fw3.1")  # the two ends: the oldest layout, the newest
COUNTS = ("bytes", "frames", "errors", "garbage_bytes")
MIN_STREAM = 64 * 1024 + 1  # more than one read, so that frames straddle a read boundary
RUN_TIMEOUT = 120  # seconds; only against a hang, each run takes a few at most
# What a testee without a bench mode says about its first argument.
UNKNOWN_BENCH = re.compile(r"(unknown|unrecognized|invalid) (option|argument)\W+--bench\b", re.IGNORECASE)
TRACEBACK = re.compile(r"Traceback|Exception|\bat [\w.$]+\(|goroutine \d|panic:|node:internal")


def build_stream(profile: str) -> bytes:
    """Every decode_stream and decode_frame input of the profile's vectors,
    in a seeded random order, each behind 0-24 random bytes (one in eight a
    start byte), repeated until the stream spans more than one read."""
    cases = load_cases([VECTORS_DIR / "streams.json", VECTORS_DIR / "frames.json"])
    inputs = [bytes.fromhex(c.input["hex"]) for c in cases
              if c.profile == profile and c.operation in ("decode_stream", "decode_frame")]
    rng = random.Random(f"bench-modes {profile}")
    out = bytearray()
    while len(out) < MIN_STREAM:
        rng.shuffle(inputs)
        for raw in inputs:
            out += bytes(0xAA if rng.randrange(8) == 0 else rng.randrange(256) for _ in range(rng.randrange(25)))
            out += raw
    return bytes(out)


@pytest.fixture(scope="module")
def streams(tmp_path_factory) -> dict[str, Path]:
    directory = tmp_path_factory.mktemp("bench-streams")
    out = {}
    for profile in PROFILES:
        out[profile] = directory / f"{profile}.bin"
        out[profile].write_bytes(build_stream(profile))
    return out


def run_bench(impl: str, *args: str, stdin: bytes = b"") -> subprocess.CompletedProcess:
    """The implementation started with `args`, `stdin` written to it through a pipe."""
    proc = subprocess.run([*impl_argv(impl), *args], input=stdin, capture_output=True, timeout=RUN_TIMEOUT)
    return subprocess.CompletedProcess(proc.args, proc.returncode, proc.stdout.decode(errors="replace"),
                                       proc.stderr.decode(errors="replace"))


def skip_if_no_bench_mode(impl: str, proc: subprocess.CompletedProcess) -> None:
    if impl == "c" and proc.returncode != 0 and UNKNOWN_BENCH.search(proc.stderr):
        pytest.skip(f"the C testee has no bench mode yet: {proc.stderr.strip()}")


def bench_line(impl: str, proc: subprocess.CompletedProcess, profile: str) -> dict:
    """The one JSON line of a successful bench run, checked for shape."""
    skip_if_no_bench_mode(impl, proc)
    assert proc.returncode == 0, f"{impl}: exit {proc.returncode}: {proc.stderr}"
    lines = proc.stdout.splitlines()
    assert len(lines) == 1, f"{impl}: expected one line, got {proc.stdout!r}"
    result = json.loads(lines[0])
    assert set(result) == {"impl", "profile", *COUNTS, "seconds"}, result
    assert result["impl"] == impl and result["profile"] == profile, result
    assert all(isinstance(result[k], int) and result[k] >= 0 for k in COUNTS), result
    assert isinstance(result["seconds"], (int, float)) and result["seconds"] >= 0, result
    return result


@cache
def bench_of(impl: str, path: Path, profile: str) -> dict:
    return bench_line(impl, run_bench(impl, "--bench", str(path), "--profile", profile), profile)


def decode_stream_counts(impl: str, data: bytes, profile: str) -> dict:
    """What the implementation's decode_stream reports for the bytes, counted
    as the bench mode counts. The bytes arrive in the bench mode's read size."""
    with testee_client.Testee(impl_argv(impl), timeout=RUN_TIMEOUT) as testee:
        res = testee.request({"op": "decode_stream", "id": "bench-modes", "profile": profile,
                              "hex": data.hex(), "chunks": [64 * 1024] * (len(data) // (64 * 1024))})
    assert res.get("ok") is True, f"{impl}: {res}"
    events = res["result"]["events"]
    return {"bytes": len(data),
            "frames": sum(ev["kind"] == "frame" for ev in events),
            "errors": sum(ev["kind"] == "error" for ev in events),
            "garbage_bytes": sum(ev["length"] for ev in events if ev["kind"] == "garbage")}


@pytest.mark.parametrize("impl", QUICK_ONE_IMPL)
def test_bench_counts_what_decode_stream_reports(impl, streams):
    for profile, path in streams.items():
        got = bench_of(impl, path, profile)
        expected = decode_stream_counts(impl, path.read_bytes(), profile)
        assert {k: got[k] for k in COUNTS} == expected, f"{impl} {profile}"
        # the stream exercises every kind of event, so no count agrees by being 0
        assert all(expected[k] > 0 for k in COUNTS), expected


def test_implementations_agree(streams):
    for profile, path in streams.items():
        counts = {}
        for impl in IMPLS:
            try:
                counts[impl] = {k: bench_of(impl, path, profile)[k] for k in COUNTS}
            except pytest.skip.Exception:
                continue  # the C testee without a bench mode; the others still have to agree
        assert len(counts) >= len(IMPLS) - 1, counts
        assert len({json.dumps(c, sort_keys=True) for c in counts.values()}) == 1, f"{profile}: {counts}"


@pytest.mark.parametrize("impl", QUICK_ONE_IMPL)
def test_bench_reads_stdin(impl, streams):
    profile = "a3-fw3.1"
    path = streams[profile]
    from_stdin = bench_line(impl, run_bench(impl, "--bench", "-", "--profile", profile, stdin=path.read_bytes()),
                            profile)
    from_file = bench_of(impl, path, profile)
    assert {k: from_stdin[k] for k in COUNTS} == {k: from_file[k] for k in COUNTS}


BAD_ARGUMENTS = {
    "missing file": ("--bench", "/nonexistent/osdk-bench-input.bin", "--profile", "a3-fw3.1"),
    "unknown profile": ("--bench", "-", "--profile", "no-such-profile"),
    "no profile": ("--bench", "-"),
    "option without value": ("--bench", "-", "--profile"),
    "unknown option": ("--bench", "-", "--profile", "a3-fw3.1", "--fast", "1"),
}


@pytest.mark.parametrize("impl", QUICK_ONE_IMPL)
def test_bad_arguments_exit_2_with_one_line(impl):
    probe = run_bench(impl, *BAD_ARGUMENTS["missing file"])
    skip_if_no_bench_mode(impl, probe)
    for what, args in BAD_ARGUMENTS.items():
        proc = probe if what == "missing file" else run_bench(impl, *args)
        assert proc.returncode == 2, f"{impl}, {what}: exit {proc.returncode}, stderr {proc.stderr!r}"
        assert proc.stdout == "", f"{impl}, {what}: {proc.stdout!r}"
        lines = proc.stderr.splitlines()
        assert len(lines) == 1 and lines[0].strip(), f"{impl}, {what}: {proc.stderr!r}"
        assert not TRACEBACK.search(proc.stderr), f"{impl}, {what}: {proc.stderr!r}"
