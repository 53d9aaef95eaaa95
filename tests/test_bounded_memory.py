"""Memory use of every decoder is bounded by the frame size, whatever the
input; a gibibyte of random bytes decodes without a crash in bounded memory.

Every bundled implementation runs its bench mode (conformance/PROTOCOL.md:
`<argv> --bench - --profile P`) on the hostile streams of
osdk_conformance.harness.hostile_streams, fed through a pipe, once with a short and
once with a long stream of the same kind. Its peak resident set comes from
conformance/baseline's osdk-peak-rss (the meter `osdkc bench` uses): the kernel's peak
RSS of a direct child includes the pages of the process it was forked from
(here the test process, tens of MiB), while a child of that small program
starts from its RSS (under 2 MiB), so the C decoder's 2 MiB can be seen.

The bound. A receiver needs one maximum frame (1023 bytes) plus one read
(at most 64 KiB); a decoded value is smaller than its frame. Everything
else in the peak is the runtime: interpreter, JIT code, and, where there is
one, the garbage-collected heap, which grows until it reaches its working
size (the JVM runs with -Xmx256m, runner.py, and its young generation alone
is tens of MiB; Node, its young generation capped (below), settles at
74 to 86 MiB on the rejection-heavy streams; Go's heap target follows its
live heap). So the long stream's peak may exceed the short one's by at most GROWTH_BOUND = 16 MiB for those
runtimes (16 times what one read and one frame need; the growth measured
once they are warm, over five runs each on a loaded machine, is at most
8 MiB), and by NO_GC_GROWTH_BOUND = 4 MiB for C (no heap at all) and
CPython (reference counting frees at once; measured growth under 0.5 MiB).
The short stream is long enough for the runtime to be warm (the JVM: 16 MiB
of random bytes, where it reaches 107 MiB; before that its heap is still
growing towards that size; Node: see SPECIAL_LENGTHS). Go's peak varies
between runs of the same stream (64 MiB of whole frames: 9.9 to 35 MiB over
ten runs on a loaded machine), so for Go the long stream's peak is the
least of three runs (RUNS): a leak shows in every run, the highs came once
in several (a high short run only makes the check more lenient). Node
sizes its young generation between runs of the same stream too: on the
truncated headers its peak was 84 to 87 or 120 to 125 MiB, whatever the
length (1 to 32 MiB, three runs each), which once failed CI with a low
short run and a high long one. Its semi-spaces are therefore capped at
4 MiB here (RUNTIME_ENV; measured after that: 81 to 86 MiB on 2 to 32 MiB
of truncated headers, four runs each). That hides no leak: what a
decoder keeps survives the young generation and is promoted to the old
one, which stays uncapped.

What that catches. A decoder that keeps its input grows by the difference
between the two random or whole-frame streams (48 MiB; 7 MiB for the Python
ones, against their 4 MiB bound); one that keeps anything per event grows
on the rejection-heavy streams, whose long run holds 16,000 to 700,000
rejections more than the short one. Checked by running the construct testee
with such leaks put in: keeping its input, it grew by 7 MiB on random bytes
and on whole frames; keeping every event, by 16 MiB on random bytes, 17 MiB
on whole frames, 37 and 68 MiB on the two header streams. And with the
JavaScript testee keeping every event, its young generation capped as
here: it grew by 63 MiB on random bytes, 131 MiB on whole frames, 89 and
319 MiB on the two header streams.

Lengths. The streams that make a receiver work hardest per byte (a header
claiming 1023 bytes every 12 bytes costs 1023 bytes of CRC-32 each; a start
byte every 6 bytes) are shorter, for the CI budget; what a per-event leak
would keep is still there (above). The Python implementations are several
times slower than the others (on the header streams, under 1 MiB/s) and get
shorter streams; their deframer is also measured in-process with
tracemalloc, where the bound is tight.

The gibibyte: test_a_gibibyte_of_random_bytes streams 1 GiB through the
implementations fast enough for CI (c, go) and, in `make memory`, a shorter
stream through the others; OSDK_FULL_GIB=1 gives every implementation the
full gibibyte. Its peak may exceed the short random run's by
GIB_GROWTH_BOUND = 64 MiB, a sixteenth of the stream, for what runtimes do only on long runs: Node's
heap grows in steps after hundreds of MiB (measured: 51 MiB after 16 MiB,
65 MiB after 256 and 512 MiB, 83 to 87 MiB after 1 and 2 GiB), and Go's
peak over 1 GiB varied from 10 to 47 MiB between runs on the loaded machine
(9 MiB after 16 MiB). Keeping a sixteenth of the input, or 16 bytes for
each of its 8 million events, would not fit. It prints each
implementation's loop time and peak RSS (`pytest -s`). No time is asserted
anywhere.

The suite runs a smoke subset of all this (CAMPAIGN below); `make memory`
(OSDK_MEMORY_CAMPAIGN=1) runs every case.
"""
from __future__ import annotations

import json
import os
import signal
import subprocess
import tempfile
import threading
import tracemalloc
from dataclasses import dataclass
from functools import cache

import pytest

# long streams through every implementation: `make quick` leaves it out
pytestmark = pytest.mark.slow

from osdk_conformance.harness import hostile_streams
from osdk_conformance.core.deframe import MAX_LEN, deframe
from osdk_conformance.core.paths import ROOT
from osdk_conformance.core.priority import keep_priority
from osdk_conformance.harness.runner import BUNDLED_IMPLS, impl_argv

MiB = 1 << 20
GiB = 1 << 30
READ = 64 * 1024  # the bench mode's largest read
GROWTH_BOUND = 16 * MiB  # go, js, java: garbage-collected heaps (module doc)
NO_GC_GROWTH_BOUND = 4 * MiB  # c, and the CPython ones
GIB_GROWTH_BOUND = 64 * MiB  # from the short random stream to the gibibyte (module doc)
PROFILE = "a3-fw3.1"
PYTHON_IMPLS = ("construct", "kaitai-python")
FULL_GIB = os.environ.get("OSDK_FULL_GIB") == "1"
# `make memory` runs every case below; the suite runs a smoke subset, for its 10-minute budget:
# every implementation on random bytes (a decoder that keeps its input), the native accelerator on every
# stream, the Python deframer on the two cheap streams, the gibibyte through C and Go (which share one
# run of Go: each implementation's counts are checked against another's).
CAMPAIGN = os.environ.get("OSDK_MEMORY_CAMPAIGN") == "1" or FULL_GIB
from osdk_conformance.bench.child import PEAK_RSS_BIN  # noqa: E402 - the one peak-RSS meter

# (short, long) stream lengths by kind.
LENGTHS = {
    "random": (16 * MiB, 64 * MiB),
    "max_len_frames": (16 * MiB, 64 * MiB),
    "truncated_headers": (1 * MiB, 4 * MiB),
    "max_len_headers": (MiB // 2, 2 * MiB),
}
# Where V8 needs a longer short stream to reach its working heap (measured
# with RUNTIME_ENV, four runs each: 62 to 63 MiB after 0.5 MiB of
# max_len_headers, 74 to 76 MiB after 2, 8 and 32 MiB; 75 to 82 MiB after
# 1 MiB of truncated_headers, 81 to 86 MiB after 2 to 32 MiB), and for the
# much slower Python implementations (module doc).
SPECIAL_LENGTHS = {
    ("js", "max_len_headers"): (2 * MiB, 4 * MiB),
    ("js", "truncated_headers"): (4 * MiB, 8 * MiB),
    **{(impl, kind): lengths for impl in PYTHON_IMPLS for kind, lengths in {
        "random": (1 * MiB, 8 * MiB),
        "max_len_frames": (1 * MiB, 8 * MiB),
        "truncated_headers": (MiB // 4, 1 * MiB),
        "max_len_headers": (MiB // 4, 1 * MiB),
    }.items()},
    # the slowest pair by far (the Kaitai runtime parses 1023 claimed bytes per 12 bytes of input:
    # 43 s for the 1.25 MiB above): a quarter of the stream still holds 16,000 rejections more in
    # its long run, which a per-event leak turns into several MiB (module doc)
    ("kaitai-python", "max_len_headers"): (MiB // 16, MiB // 4),
}
# Go's peak varies between runs of the same stream; a leak shows in every run.
RUNS = {"go": 3}
# Node's young generation, fixed so that its size does not vary between runs (module doc).
RUNTIME_ENV = {"js": {"NODE_OPTIONS": "--max-semi-space-size=4"}}
# The gibibyte in CI: the full one where it takes seconds, a shorter stream elsewhere.
GIB_IN_CI = {"c": GiB, "go": GiB, "js": 128 * MiB, "java": 128 * MiB, "construct": 16 * MiB,
             "kaitai-python": 16 * MiB, "accel": 256 * MiB}


def lengths(impl: str, kind: str) -> tuple[int, int]:
    return SPECIAL_LENGTHS.get((impl, kind), LENGTHS[kind])


def growth_bound(impl: str) -> int:
    # accel is C inside CPython: reference counting, no garbage-collected heap to settle
    return NO_GC_GROWTH_BOUND if impl in ("c", "accel") or impl in PYTHON_IMPLS else GROWTH_BOUND


@dataclass(frozen=True)
class Bench:
    impl: str
    kind: str
    total: int
    status: int  # exit status; negative: killed by that signal
    result: dict  # the bench line, or {} when there was none
    peak_rss: int  # bytes
    stderr: str

    def counts(self) -> tuple:
        return tuple(self.result.get(k) for k in ("bytes", "frames", "errors", "garbage_bytes"))

    def why(self) -> str:
        return (f"{self.impl} on {self.total} bytes of {self.kind}: exit {self.status}, {self.result}, "
                f"{self.stderr[-500:]}")


@cache
def bench(impl: str, kind: str, total: int, run: int = 0) -> Bench:
    """Run `impl`'s bench mode on the stream through a pipe (cached: the
    counts are deterministic and some tests share runs; `run` numbers
    repeated runs)."""
    if not os.access(PEAK_RSS_BIN, os.X_OK):
        pytest.fail(f"{PEAK_RSS_BIN} is missing; run `make setup` (it builds conformance/baseline)")
    argv = impl_argv(impl) + ["--bench", "-", "--profile", PROFILE]
    with tempfile.TemporaryDirectory() as tmp, \
            open(os.path.join(tmp, "out"), "w+b") as out, open(os.path.join(tmp, "err"), "w+b") as err:
        rss_file = os.path.join(tmp, "rss")
        proc = subprocess.Popen([str(PEAK_RSS_BIN), rss_file, *argv], stdin=subprocess.PIPE, stdout=out,
                                stderr=err, cwd=ROOT, start_new_session=True, preexec_fn=keep_priority,
                                env={**os.environ, **RUNTIME_ENV.get(impl, {})})
        # Against a hang only (a testee that stops reading would block the
        # writes for ever): generous for the slowest decoder on this stream.
        guard = threading.Timer(120 + total / (256 * 1024), _kill_group, (proc.pid,))
        guard.start()
        try:
            for block in hostile_streams.blocks(kind, total, seed=1):
                proc.stdin.write(block)
            proc.stdin.close()
        except BrokenPipeError:
            pass  # it stopped reading; its exit status says why
        finally:
            status = proc.wait()
            guard.cancel()
        out.seek(0)
        err.seek(0)
        lines = out.read().decode(errors="replace").splitlines()
        stderr = err.read().decode(errors="replace")
        try:
            result = json.loads(lines[-1]) if status == 0 and lines else {}
        except ValueError:
            result = {}
        try:
            # "<status> <peak KiB> <cpu seconds>"
            with open(rss_file) as f:
                peak_kib = int(f.read().split()[1])
        except (OSError, IndexError, ValueError):
            peak_kib = 0  # the meter itself was killed; the status says so
    return Bench(impl, kind, total, status, result, peak_kib * 1024, stderr)


def peak_rss(impl: str, kind: str, total: int) -> int:
    """The peak RSS of decoding the stream: the least of RUNS[impl] runs."""
    return min(bench(impl, kind, total, run).peak_rss for run in range(RUNS.get(impl, 1)))


def _kill_group(pid: int) -> None:
    try:
        os.killpg(pid, signal.SIGKILL)
    except ProcessLookupError:
        pass


def checked(impl: str, kind: str, total: int) -> Bench:
    """The run, with everything but its memory checked: it ended well, read
    every byte, found what the stream holds, and counted what another
    implementation counts for the same bytes."""
    b = bench(impl, kind, total)
    assert b.status == 0 and b.result, b.why()
    assert b.result.get("impl") == impl and b.result.get("profile") == PROFILE, b.why()
    assert b.result["bytes"] == total, b.why()
    if kind == "max_len_frames":  # whole frames, then a frame cut short unless the length divides evenly
        assert b.result["frames"] == total // MAX_LEN, b.why()
        assert (b.result["errors"] > 0) == (total % MAX_LEN > 0), b.why()
    else:  # nothing in these streams is a frame (random bytes: for this seed)
        assert b.result["frames"] == 0 and b.result["errors"] > 0, b.why()
    assert 0 <= b.result["garbage_bytes"] < total, b.why()
    other = bench("go" if impl == "c" else "c", kind, total)
    assert other.status == 0 and b.counts() == other.counts(), (b.why(), other.why())
    return b


def smoke_or_campaign(*values, smoke: bool):
    """A test case; outside the smoke subset it runs only in the campaign (`make memory`)."""
    marks = () if smoke else pytest.mark.skipif(not CAMPAIGN, reason="in the memory campaign: make memory")
    return pytest.param(*values, marks=marks)


# ---------------------------------------------------------------- the Python deframer, in-process


@pytest.mark.parametrize("kind, total", [
    smoke_or_campaign(kind, total, smoke=kind in ("random", "max_len_frames"))
    for kind, total in (("random", 4 * MiB), ("max_len_frames", 4 * MiB), ("truncated_headers", MiB // 2),
                        ("max_len_headers", MiB // 2))])
def test_python_deframer_holds_one_read_and_one_frame(kind, total):
    """Peak traced memory while deframing a stream several times the bound
    in 64 KiB reads: one read and the unscanned rest of a frame in the
    buffer (with the allocator's slack), one frame's copy, one event."""
    data = memoryview(b"".join(hostile_streams.blocks(kind, total)))
    reads = (data[at:at + READ] for at in range(0, total, READ))
    list(deframe([bytes(data[:4 * MAX_LEN])]))  # CRC tables and rules loaded before measuring
    tracemalloc.start()
    try:
        before = tracemalloc.get_traced_memory()[0]
        events = sum(1 for _ in deframe(reads))
        peak = tracemalloc.get_traced_memory()[1] - before
    finally:
        tracemalloc.stop()
    bound = 2 * (READ + MAX_LEN)
    assert total > 3 * bound and events > 1000  # the stream could not fit under the bound
    assert peak < bound, f"{peak} bytes traced at the peak, bound {bound}"


# ---------------------------------------------------------------- every implementation, peak RSS


@pytest.mark.parametrize("impl, kind", [smoke_or_campaign(impl, kind, smoke=kind == "random" or impl == "accel")
                                        for impl in BUNDLED_IMPLS for kind in hostile_streams.KINDS])
def test_peak_rss_does_not_grow_with_the_stream(impl, kind):
    short_len, long_len = lengths(impl, kind)
    short = checked(impl, kind, short_len).peak_rss
    checked(impl, kind, long_len)
    long = peak_rss(impl, kind, long_len)
    growth = long - short
    print(f"{impl} {kind}: peak RSS {short / MiB:.1f} MiB after {short_len / MiB:g} MiB, "
          f"{long / MiB:.1f} MiB after {long_len / MiB:g} MiB")
    assert growth < growth_bound(impl), (f"{impl}: peak RSS grew by {growth / MiB:.1f} MiB from "
                                         f"{short_len / MiB:g} to {long_len / MiB:g} MiB of {kind}")


# ---------------------------------------------------------------- a gibibyte of random bytes


@pytest.mark.slow
@pytest.mark.parametrize("impl", [smoke_or_campaign(impl, smoke=impl in ("c", "go")) for impl in BUNDLED_IMPLS])
def test_a_gibibyte_of_random_bytes(impl):
    total = GiB if FULL_GIB else GIB_IN_CI[impl]
    reference = checked(impl, "random", lengths(impl, "random")[0])
    run = checked(impl, "random", total)
    seconds = run.result["seconds"]
    print(f"{impl}: {total / MiB:g} MiB of random bytes in {seconds:.2f} s of decoding "
          f"({total / MiB / seconds:.1f} MiB/s), peak RSS {run.peak_rss / MiB:.1f} MiB")
    assert run.peak_rss - reference.peak_rss < GIB_GROWTH_BOUND, (
        f"{impl}: peak RSS {run.peak_rss / MiB:.1f} MiB after {total / MiB:g} MiB, "
        f"{reference.peak_rss / MiB:.1f} MiB after {reference.total / MiB:g} MiB")


def test_the_meter_reports_the_child_not_the_parent():
    """The measurement itself: a child of this (large) process, measured
    through osdk-peak-rss, reports a peak far below this process's own."""
    import resource

    own = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    small = bench("c", "random", READ)
    assert small.status == 0, small.why()
    assert small.peak_rss < min(own, 16 * MiB), (small.peak_rss, own)
