"""A child given a session of its own keeps the priority of its parent.

Linux's scheduler shares the CPU first between sessions and only then by
nice value inside each one (the "autogroup", on by default in the common
distribution kernels; sched(7)). A child started with
`start_new_session=True`, so that its whole process group can be killed,
therefore escapes the nice value of the program that started it: a
testee of a runner at nice 10 competes at full weight with a live
simulator's or a tap's timing, and a verdict about timing measures that
competition. `keep_priority` gives the child's new autogroup the nice
value the child inherited.
"""
from __future__ import annotations

import os

AUTOGROUP = "/proc/self/autogroup"


def keep_priority() -> None:
    """For `preexec_fn` (it runs in the child after its setsid()): the new
    session's autogroup at this process's nice value. Nothing happens where
    there is no autogroup (another kernel, another system) or it may not be
    changed."""
    try:
        nice = os.getpriority(os.PRIO_PROCESS, 0)
        if nice > 0:   # only ever lower the priority: raising it needs a privilege, and is not ours to take
            with open(AUTOGROUP, "w") as f:
                f.write(str(nice))
    except OSError:
        pass
