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


# what the suite proves: the units whose proof takes seconds, and of the decoder the receiver's header reads
# and checks; `make prove` proves every function of every unit of tools/prove.py's UNITS (the encoders, the
# deframer and the whole decoder too: about 25 minutes of CPU cold, docs/VERIFICATION.md)
FAST_UNITS = ("osdk_crc.c", "osdk_acks.c")
FAST_DECODER = r"osdk_peek_bits_le|osdk_frame_peek_\w+|osdk_frame_valid_\w+|osdk_kdiv|osdk_kmod"


def _all_proved(proc: subprocess.CompletedProcess, units: tuple[str, ...]) -> None:
    assert proc.returncode == 0, proc.stdout + proc.stderr
    for unit in units:
        line = next(x for x in proc.stdout.splitlines() if x.startswith(unit))
        _, goals, proved, _, verdict = line.split()
        assert verdict == "PROVED" and int(goals) == int(proved) > 10, line


def test_the_fast_units_are_proved() -> None:
    proc = prove("-v", *FAST_UNITS)
    _all_proved(proc, FAST_UNITS)
    for fn in ("osdk_crc16", "osdk_crc32", "osdk_acks_init", "osdk_acks_command", "osdk_acks_take"):
        assert f"    {fn} " in proc.stdout, proc.stdout


def test_the_receivers_header_reads_are_proved() -> None:
    proc = prove("-v", "osdk_decoder.c", "--function", FAST_DECODER)
    _all_proved(proc, ("osdk_decoder.c",))
    for fn in ("osdk_peek_bits_le", "osdk_frame_peek_len", "osdk_frame_valid_len", "osdk_kdiv", "osdk_kmod"):
        assert f"    {fn} " in proc.stdout, proc.stdout
    assert "osdk_payload_parse" not in proc.stdout, "only the functions asked for"


def test_the_deframers_callers_of_the_callback_are_proved_with_its_model() -> None:
    # next_event and take, whose contracts these rely on, take minutes: `make prove`
    proc = prove("-v", "osdk_deframer.c", "--function", "scan|osdk_deframer_feed|osdk_deframer_finish")
    _all_proved(proc, ("osdk_deframer.c",))
    for fn in ("scan", "osdk_deframer_feed", "osdk_deframer_finish"):
        assert f"    {fn} " in proc.stdout, proc.stdout



def test_every_unit_make_prove_proves_selects_functions_that_exist() -> None:
    sys.path.insert(0, str(ROOT / "tools"))
    import prove as tool

    for unit, rule in tool.UNITS.items():
        chosen = tool.selected(unit, GENERATED)
        assert rule is None or chosen, unit
        assert tool.left_out(unit, GENERATED) == [], unit   # every unit is proved whole
    # the decoder: every parse function, every field reader, the stream primitives and the header's helpers
    chosen = tool.selected("osdk_decoder.c", GENERATED)
    for fn in ("osdk_frame_parse", "osdk_payload_parse", "osdk_broadcast_a3_fw3_1_parse", "osdk_frame__read_data",
               "osdk_read_bits_le", "osdk_substream", "osdk_stream_init", "osdk_kmod", "osdk_frame_decode"):
        assert fn in chosen, fn


# the cheap ones; `make prove` also plants the encoder's, whose failing proof takes about a minute of CPU
SUITE_MUTANTS = ("crc-reads-one-past-the-end", "acks-session-check-missing")


def test_a_planted_bounds_bug_fails_the_proof() -> None:
    proc = prove("--mutants", *SUITE_MUTANTS)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    for name in SUITE_MUTANTS:
        line = next(x for x in proc.stdout.splitlines() if x.startswith(f"mutant {name}:"))
        assert "the proof fails, as it must" in line, line
    assert not [x for x in proc.stdout.splitlines() if x.startswith("osdk_")], "only the mutants ran"


def test_a_mutant_whose_line_is_gone_fails_the_run(tmp_path: Path) -> None:
    # the generated code changed under the mutant: it plants nothing, and must say so, not pass
    copy = tmp_path / "c"
    shutil.copytree(GENERATED, copy)
    unit = copy / "osdk_crc.c"
    unit.write_text(unit.read_text().replace("for (i = 0; i < len; i++) {", "for (i = 0; len > i; i++) {"))
    proc = prove("--source", str(copy), "--mutants", "crc-reads-one-past-the-end")
    assert proc.returncode == 1 and "NOT CAUGHT" in proc.stdout and "update the mutant" in proc.stdout, proc.stdout


@pytest.mark.parametrize("args, says", [
    (("no_such_unit.c",), "no such unit"),
    (("--source", "/nonexistent", "osdk_crc.c"), "no such unit"),
    (("osdk_crc.c", "--function", "osdk_no_such_function"), "no function of osdk_crc.c matches osdk_no_such_function"),
])
def test_bad_arguments_are_one_line_and_exit_2(args, says) -> None:
    proc = prove(*args)
    assert proc.returncode == 2 and says in proc.stderr and "Traceback" not in proc.stderr, proc.stderr


# a unit proved by one Frama-C, and one whose functions two Frama-C runs share
@pytest.mark.parametrize("args", [(), ("--jobs", "2", "osdk_decoder.c", "--function", FAST_DECODER)],
                         ids=["one-run", "two-runs"])
@pytest.mark.parametrize("sig, status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_a_signal_stops_the_proof_and_every_prover_within_2_s(sig, status, args) -> None:
    if shutil.which("frama-c") is None:
        pytest.fail("frama-c is not installed; `make setup` installs it (tools/apt-packages.sh)")
    proc = subprocess.Popen([*PROVE, "--no-cache", *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, cwd=ROOT)
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
