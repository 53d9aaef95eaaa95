"""One judge run against a fresh `osdkc sim` standing in for a flight
controller, as the reliability measurements make them: the simulator with
`--stats`, raised above the busy loops where the user may, and one `osdkc`
child command against its port; what the child printed is kept in the run's
directory, beside the simulator's statistics."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from osdk_conformance.core.errors import UsageError
from osdk_conformance.sim.simulator import spawned

OSDKC = [sys.executable, "-m", "osdk_conformance.cli"]

# The simulator stands in for a flight controller, which has a CPU of its own:
# it runs above the busy loops where this user may raise a priority, so that
# what is measured is the judge on a saturated host, not a starved stand-in.
SIM_NICE = -5


@dataclass
class Run:
    code: int | None          # the child's exit status; None when it timed out or the simulator did not start
    out: str                  # its stdout and stderr
    stats: dict               # the simulator's --stats at exit ({} when it left none)
    favoured: bool            # the simulator ran at SIM_NICE


def favour(pid: int) -> bool:
    try:
        os.setpriority(os.PRIO_PROCESS, pid, SIM_NICE)
        return True
    except OSError:   # not permitted: the stand-in shares the host's fate, and its stats say when it fell behind
        return False


def run(run_dir: Path, sim_args: tuple[str, ...], command: Callable[[str, int], list[str]], timeout: float,
        output_name: str) -> Run:
    """`osdkc sim SIM_ARGS` and `osdkc COMMAND(url, simulator pid)` against it."""
    run_dir.mkdir(parents=True, exist_ok=True)
    stats = run_dir / "sim-stats.json"
    try:
        with spawned(*sim_args, "--stats", str(stats)) as (url, sim):
            favoured = favour(sim.pid)
            proc = subprocess.run([*OSDKC, *command(url, sim.pid)], capture_output=True, text=True, timeout=timeout)
            code, out = proc.returncode, proc.stdout + proc.stderr
    except subprocess.TimeoutExpired as e:
        favoured, code, out = False, None, f"timed out after {timeout:g} s: {e.stdout or ''}"
    except UsageError as e:   # the simulator did not start: this run went wrong, the next ones still count
        favoured, code, out = False, None, str(e)
    (run_dir / output_name).write_text(out)
    try:
        sim_stats = json.loads(stats.read_text())
    except (OSError, ValueError):
        sim_stats = {}
    return Run(code, out, sim_stats, favoured)
