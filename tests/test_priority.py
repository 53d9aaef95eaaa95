"""A child in a session of its own keeps its parent's priority
(core/priority.py): under Linux's autogroup scheduling a new session would
otherwise compete at full weight with the suite's live simulators."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from osdk_conformance.core.priority import AUTOGROUP, keep_priority

needs_autogroup = pytest.mark.skipif(not Path(AUTOGROUP).exists(), reason="this kernel has no autogroup")


def autogroup_nice_of(pid: int | str) -> int:
    # "/autogroup-123 nice 10"
    return int(Path(f"/proc/{pid}/autogroup").read_text().split()[-1])


def _niced_child(code: str, preexec: bool) -> str:
    """What `code` prints, run in a new session by a process 7 nicer than
    this one (this one runs at 10 in `make test`), after that process's own
    nice value."""
    out = subprocess.run([sys.executable, "-c", f"import os, subprocess, sys\n"
                          f"from osdk_conformance.core.priority import keep_priority\nprint(os.nice(7))\n"
                          f"print(subprocess.run([sys.executable, '-c', {code!r}], capture_output=True, text=True, "
                          f"start_new_session=True{', preexec_fn=keep_priority' if preexec else ''}).stdout, end='')"],
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    return out.stdout


READ = "from pathlib import Path; print(Path('/proc/self/autogroup').read_text().split()[-1])"


@needs_autogroup
def test_a_new_session_escapes_its_parents_nice_unless_kept() -> None:
    own, child = _niced_child(READ, preexec=False).split()
    assert child == "0"    # what keep_priority is for
    own, child = _niced_child(READ, preexec=True).split()
    assert child == own and int(own) >= 7


@needs_autogroup
def test_a_testee_runs_at_its_runners_priority() -> None:
    # a testee that answers one request with its own autogroup's nice, from a niced runner
    code = ("import json, sys\nfrom pathlib import Path\nfor line in sys.stdin:\n"
            "    n = Path('/proc/self/autogroup').read_text().split()[-1]\n"
            "    print(json.dumps({'ok': True, 'result': {'nice': n}}), flush=True)\n")
    out = subprocess.run([sys.executable, "-c", "import os, sys\nprint(os.nice(5))\n"
                          "from osdk_conformance.harness.testee import Testee\n"
                          f"with Testee([sys.executable, '-c', {code!r}]) as t:\n"
                          "    print(t.request({'op': 'capabilities'})['result']['nice'])"],
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    own, testee = out.stdout.split()
    assert testee == own and int(own) >= 5
