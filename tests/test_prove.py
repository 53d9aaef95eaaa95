"""`make prove` (tools/prove.py): Frama-C WP proves the generated C units
that carry contracts, and a bounds bug planted in a copy fails the proof
(a proof that cannot fail would show nothing)."""
from __future__ import annotations

import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
PROVE = [sys.executable, str(ROOT / "tools" / "prove.py")]
GENERATED = ROOT / "generated" / "c"



def prove(*args: str) -> subprocess.CompletedProcess:
    if shutil.which("frama-c") is None:
        pytest.fail("frama-c is not installed; `make setup` installs it (tools/apt-packages.sh)")
    return subprocess.run([*PROVE, *args], capture_output=True, text=True, timeout=600, cwd=ROOT)


def test_every_unit_with_contracts_is_proved() -> None:
    proc = prove("-v")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    for unit in ("osdk_crc.c", "osdk_acks.c"):
        line = next(x for x in proc.stdout.splitlines() if x.startswith(unit))
        _, goals, proved, _, verdict = line.split()
        assert verdict == "PROVED" and int(goals) == int(proved) > 10, line
    for fn in ("osdk_crc16", "osdk_crc32", "osdk_acks_init", "osdk_acks_command", "osdk_acks_take"):
        assert f"    {fn} " in proc.stdout, proc.stdout


# (unit, the line as generated, the line with the bug, what WP can no longer prove)
BUGS = {
    "crc-reads-one-past-the-end": ("osdk_crc.c", "for (i = 0; i < len; i++) {", "for (i = 0; i <= len; i++) {",
                                   "osdk_crc16_assert_rte_mem_access"),
    "acks-session-check-missing": ("osdk_acks.c",
                                   "if (session < OSDK_ACK_FIRST_SESSION || session >= OSDK_ACK_SESSIONS) return;",
                                   "if (session < OSDK_ACK_FIRST_SESSION) return;",
                                   "osdk_acks_command_assert_rte_pointer_value"),
}


@pytest.mark.parametrize("bug", list(BUGS))
def test_a_planted_bounds_bug_fails_the_proof(bug: str, tmp_path: Path) -> None:
    unit, good, bad, goal = BUGS[bug]
    copy = tmp_path / "c"
    shutil.copytree(GENERATED, copy)
    text = (copy / unit).read_text()
    assert text.count(good) >= 1, f"{unit} no longer has {good!r}: update the planted bug"
    (copy / unit).write_text(text.replace(good, bad, 1))
    # the goal a bug breaks cannot be proved, so it would use the whole timeout of each prover: every goal of
    # these units is proved in well under a second, 2 s is ample
    proc = prove("--source", str(copy), "--no-cache", "--timeout", "2", unit)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert "NOT PROVED" in proc.stdout and f"not proved: {goal}" in proc.stdout, proc.stdout


@pytest.mark.parametrize("args, says", [
    (("no_such_unit.c",), "no such unit"),
    (("--source", "/nonexistent", "osdk_crc.c"), "no such unit"),
])
def test_bad_arguments_are_one_line_and_exit_2(args, says) -> None:
    proc = prove(*args)
    assert proc.returncode == 2 and says in proc.stderr and "Traceback" not in proc.stderr, proc.stderr


@pytest.mark.parametrize("sig, status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_a_signal_stops_the_proof_and_every_prover_within_2_s(sig, status) -> None:
    if shutil.which("frama-c") is None:
        pytest.fail("frama-c is not installed; `make setup` installs it (tools/apt-packages.sh)")
    proc = subprocess.Popen([*PROVE, "--no-cache"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            cwd=ROOT)
    time.sleep(2.5)   # Frama-C is running (a cold proof takes about 10 s), in a session of its own
    sessions = subprocess.run(["pgrep", "-P", str(proc.pid)], capture_output=True, text=True).stdout.split()
    assert sessions, "Frama-C was not running"
    t0 = time.monotonic()
    proc.send_signal(sig)
    out, err = proc.communicate(timeout=10)
    took = time.monotonic() - t0
    assert proc.returncode == status and took < 2, (proc.returncode, took, err)
    assert f"stopped by {sig.name}" in err and "Traceback" not in err, err
    time.sleep(0.5)   # the provers, killed with Frama-C's session, are reaped by init
    left = [line for line in subprocess.run(["ps", "-e", "-o", "sid=,stat=,comm="], capture_output=True,
                                            text=True).stdout.splitlines()
            if line.split()[0] in sessions and not line.split()[1].startswith("Z")]
    assert left == [], left
