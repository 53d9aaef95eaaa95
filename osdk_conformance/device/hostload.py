"""How busy the host was during a live run: the load average and this
process's own CPU time. A verdict about the flight controller must not rest
on what a busy host did to the arrival times (scheduling, a reader thread
left waiting), so checks that can only see arrival times say how busy the
host was, and do not blame the FC when it was busy.
"""
from __future__ import annotations

import os
import time
from dataclasses import dataclass, replace
from typing import Sequence

from osdk_conformance.harness.report import FAIL, SKIP, Result

# Checks whose verdict rests on every frame being read in time: a reader that
# was not scheduled lets the host's buffers overflow, and the frames lost there
# read as a flight controller that skipped SEQs, slowed down or stopped.
HOST_TIMED = ("link.stall", "stream.rates", "stream.jitter", "stream.sequence", "active.frequency",
              "active.frequency_restore", "active.movement")
HOST_TOO_BUSY = "host too busy"


@dataclass(frozen=True)
class HostLoad:
    cores: int
    load1: float          # 1-minute load average at the end of the run
    cpu_s: float          # this process's CPU time over the run
    wall_s: float

    @property
    def busy(self) -> bool:
        """More runnable work than cores: a reader may wait for a core."""
        return self.load1 >= self.cores

    def text(self) -> str:
        return (f"load average {self.load1:.2f} on {self.cores} cores, this process used {self.cpu_s:.2f} s of CPU "
                f"in {self.wall_s:.1f} s")

    def details(self) -> dict:
        return {"host load average (1 min)": round(self.load1, 2), "host cores": self.cores,
                "process CPU s": round(self.cpu_s, 2), "run s": round(self.wall_s, 1)}


class HostClock:
    """Started when a live run starts; `load()` at its end."""

    def __init__(self) -> None:
        self.cpu0, self.wall0 = time.process_time(), time.monotonic()

    def load(self) -> HostLoad:
        try:
            load1 = os.getloadavg()[0]
        except OSError:   # no load average on this system: treat the host as busy, never blame the FC
            load1 = float("inf")
        return HostLoad(os.cpu_count() or 1, load1, time.process_time() - self.cpu0, time.monotonic() - self.wall0)


def withheld(results: Sequence[Result], stalls: Sequence[tuple[float, float]], load: HostLoad | None) -> list[Result]:
    """`results` with each failure of a HOST_TIMED check turned into a check
    not judged (SKIP, kind HOST_TOO_BUSY) when the reader was not scheduled
    for HOST_STALL_S or more during the run: what it measured may be this
    host's doing, and the verdict must not blame the flight controller for it.
    The message keeps what was measured."""
    if not stalls:
        return list(results)
    longest = max(seconds for _, seconds in stalls)
    why = (f"not judged: this host did not read the port for up to {longest:.1f} s ({len(stalls)} time(s)"
           + (f"; {load.text()}" if load else "") + "); frames may have been lost on this host. Measured: ")
    return [replace(r, status=SKIP, message=why + r.message, kind=HOST_TOO_BUSY)
            if r.status == FAIL and r.id in HOST_TIMED else r for r in results]
