#!/usr/bin/env python3
"""The test suite (`make test`, `make quick`) as two pytest runs side by side.

The `realtime` tests judge a live simulator's timing and spend most of their
time waiting for it; the rest are CPU work. Run one after the other on two
cores, the CPU idles through the realtime part. So both start together:

- the realtime tests one at a time (or `--realtime-jobs` at a time), at
  normal priority, their output kept in a log that is printed when the
  other part has finished (two outputs interleaved line by line would be
  unreadable);
- everything else spread over the cores by pytest-xdist at nice 10, so the
  scheduler gives a realtime test the CPU whenever it wants it, and the rest
  gets what it leaves. A realtime test therefore runs beside busy processes
  of lower priority, as a bench tool on a loaded laptop does.
  Linux shares the CPU between sessions before it looks at nice values
  (autogroup scheduling), so the testees, sanitizer and benchmark children
  that the kit starts in sessions of their own take their nice value along
  (osdk_conformance/core/priority.py); else they would compete with the
  realtime part at full weight.

Exit status: 0 when both parts pass; otherwise the first non-zero status of
the parallel part, then of the realtime part; 130 or 143 when interrupted.
Each run has a process group of its own: a Ctrl-C or a SIGTERM reaches this
runner, which hands a SIGINT to both groups (each pytest then stops as it
does at a Ctrl-C, its workers and their children with it) and, should a
group still be there GRACE_S later, kills it.
"""
from __future__ import annotations

import argparse
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PYTEST = [sys.executable, "-m", "pytest", "-q"]
LOWER_PRIORITY = 10
GRACE_S = 1.0  # after a signal, how long the two runs get to stop as pytest does


def _lower_priority() -> None:
    os.nice(LOWER_PRIORITY)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--jobs", default="auto", help="pytest-xdist workers for the non-realtime part")
    ap.add_argument("--realtime-jobs", type=int, default=1,
                    help="realtime tests at a time (default 1; `make quick` runs 2: faster, and each one then "
                         "shares the machine with another live simulator)")
    ap.add_argument("--marks", default="", help="a further pytest -m expression for both parts, e.g. 'not slow'")
    ap.add_argument("pytest_args", nargs="*", help="passed to both runs (after --)")
    args = ap.parse_args(argv)
    both = f" and ({args.marks})" if args.marks else ""

    signalled: list[int] = []
    signal.signal(signal.SIGINT, lambda signum, frame: signalled.append(signum))
    signal.signal(signal.SIGTERM, lambda signum, frame: signalled.append(signum))

    with tempfile.TemporaryDirectory(prefix="osdk-tests-") as tmp:
        log_path = Path(tmp) / "realtime.log"
        with open(log_path, "wb") as log:
            spread = ["-n", str(args.realtime_jobs), "--dist", "loadfile"] if args.realtime_jobs > 1 else []
            realtime = subprocess.Popen([*PYTEST, *spread, "-m", f"realtime{both}", *args.pytest_args], cwd=ROOT,
                                        stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
                                        process_group=0)
        rest = subprocess.Popen([*PYTEST, "-n", args.jobs, "--dist", "loadfile", "-m", f"not realtime{both}",
                                 *args.pytest_args], cwd=ROOT, stdin=subprocess.DEVNULL,
                                preexec_fn=_lower_priority, process_group=0)
        runs = (rest, realtime)
        print("run_tests: the realtime tests run beside the others; their output follows at the end",
              flush=True)
        stopping_since = None
        while any(p.poll() is None for p in runs):
            if signalled and stopping_since is None:
                stopping_since = time.monotonic()
                _signal_groups(runs, signal.SIGINT)
            elif stopping_since is not None and time.monotonic() - stopping_since > GRACE_S:
                _signal_groups(runs, signal.SIGKILL)
                stopping_since = float("inf")  # once
            time.sleep(0.05)
        if signalled:   # what the groups hold once their pytest ended, interrupted
            _signal_groups(runs, signal.SIGKILL, even_if_done=True)
            _wait_for_empty_groups(runs, timeout=0.5)
        print("\n---- realtime tests " + "-" * 50, flush=True)
        with open(log_path, "rb") as log:
            shutil.copyfileobj(log, sys.stdout.buffer)
        sys.stdout.flush()
    if signalled:
        return 128 + signalled[0]
    return next((p.returncode for p in runs if p.returncode), 0)


def _signal_groups(runs, signum: int, even_if_done: bool = False) -> None:
    for p in runs:
        if p.poll() is None or even_if_done:
            try:
                os.killpg(p.pid, signum)
            except ProcessLookupError:
                pass


def _wait_for_empty_groups(runs, timeout: float) -> None:
    deadline = time.monotonic() + timeout
    for p in runs:
        while time.monotonic() < deadline:
            try:
                os.killpg(p.pid, 0)
            except ProcessLookupError:
                break
            time.sleep(0.02)


if __name__ == "__main__":
    sys.exit(main())
