"""`osdkc doctor`: each link fault it must tell apart gets its own finding
and no other, a healthy link a clean bill, over a real pseudo-terminal
against `osdkc sim` (and, for the faults of this host, another program on
the port, a login console, a user who may not open it). One seeded run of
each here; `osdkc bench --only doctor` runs each 20 times (docs/DOCTOR.md)."""
from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time

import pytest

from osdk_conformance.bench.doctor_faults import FAULTS, doctor_command, holder, judged_right, run_fault, simulator
from osdk_conformance.doctor import ports
from osdk_conformance.doctor.diagnose import _console_text
from osdk_conformance.doctor.findings import OK, PROBLEM, Diagnosis, Finding

QUICK = ("healthy", "baud", "deaf", "port_busy")   # `make quick`: one of each family


@pytest.mark.realtime
@pytest.mark.parametrize("fault", [pytest.param(name, marks=() if name in QUICK else pytest.mark.slow)
                                   for name in FAULTS])
def test_each_fault_gets_its_own_diagnosis_and_no_other(fault):
    status, diagnosis, seconds = run_fault(fault, seed=1)
    print(f"{fault}: exit {status} in {seconds:.1f} s")
    problems = [f["id"] for f in diagnosis.get("findings", []) if f["verdict"] == PROBLEM]
    assert judged_right(fault, status, diagnosis), (status, problems, diagnosis)
    if problems:
        first = next(f for f in diagnosis["findings"] if f["verdict"] == PROBLEM)
        assert first["remedy"] and diagnosis["next_step"] == first["remedy"]


@pytest.mark.realtime
def test_the_human_form_puts_the_next_step_first():
    with simulator(("--baud", "921600")) as path:
        proc = subprocess.run([*doctor_command(path, FAULTS["baud"])[:-1 - len(FAULTS["baud"].doctor)],
                               "--baud", "230400"], capture_output=True, text=True, timeout=60)
    lines = proc.stdout.splitlines()
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert lines[0] == "PROBLEM: the flight controller sends at 921600 baud, not 230400"
    assert lines[1].startswith("  next step: use --baud 921600")
    assert "Traceback" not in proc.stderr


def test_a_missing_port_names_the_serial_devices_there_are():
    proc = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "doctor", "--port", "/dev/ttyUSB-none",
                           "--json"], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 1
    d = json.loads(proc.stdout)
    (f,) = d["findings"]
    assert f["id"] == "port.found" and f["verdict"] == PROBLEM
    assert f["evidence"]["serial devices on this host"] == (ports.candidates() or "none")


@pytest.mark.parametrize("port", ["/dev/null", "/etc/hostname"])
def test_something_that_is_not_a_serial_port_is_named_so(port):
    proc = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "doctor", "--port", port, "--json"],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 1, proc.stderr
    problems = [f["id"] for f in json.loads(proc.stdout)["findings"] if f["verdict"] == PROBLEM]
    assert problems == ["port.serial"]


@pytest.mark.parametrize("args, message", [
    (("--port", " "), "--port: empty"),
    (("--port", "/dev/null", "--baud", "12"), "--baud"),
    (("--port", "/dev/null", "--profile", "x"), "--profile"),
    (("--port", "/dev/null", "--key-env", "OSDK_NO_SUCH_VARIABLE"), "OSDK_NO_SUCH_VARIABLE"),
    (("--port", "/dev/null", "--app-id", "-1"), "--app-id"),
])
def test_usage_errors_exit_2_in_one_line(args, message):
    proc = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "doctor", *args], capture_output=True,
                          text=True, timeout=60)
    assert proc.returncode == 2 and message in proc.stderr, proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1 and "Traceback" not in proc.stderr


@pytest.mark.realtime
@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_a_signal_stops_it_within_two_seconds_with_what_it_found(sig):
    """Interrupted while it scans the baud rates of a line that only echoes nothing back."""
    with simulator(("--deaf", "--hold")) as path:
        proc = subprocess.Popen([sys.executable, "-m", "osdk_conformance.cli", "doctor", "--port", path, "--json"],
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                                preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
        time.sleep(1.5)
        t0 = time.monotonic()
        proc.send_signal(sig)
        out, err = proc.communicate(timeout=30)
        seconds = time.monotonic() - t0
    print(f"{sig.name}: exit {proc.returncode} after {seconds:.2f} s")
    assert proc.returncode == 128 + sig and seconds < 2.0, err
    d = json.loads(out)
    assert d["verdict"] == "interrupted" and d["interrupted_by"] == sig.name
    assert [f["id"] for f in d["findings"]][:3] == ["port.found", "port.permission", "port.free"]
    assert "Traceback" not in err


@pytest.mark.realtime
def test_the_master_of_a_pseudo_terminal_is_not_another_program_on_it():
    with simulator(()) as path:
        assert ports.holders(os.path.realpath(path)) == []
        with holder(path, "sleeper") as pid:
            (h,) = ports.holders(os.path.realpath(path))
            assert h.pid == pid and h.program == "sleeper" and not h.is_console
        with holder(path, "agetty") as pid:
            (h,) = ports.holders(os.path.realpath(path))
            assert h.pid == pid and h.is_console


def test_text_on_the_line_is_told_from_garbage():
    assert _console_text(b"\r\nDebian GNU/Linux 12 fc ttyS0\r\n\r\nfc login: ") == \
        "Debian GNU/Linux 12 fc ttyS0 | fc login:"
    assert _console_text(bytes(range(256)) * 4) == ""
    assert _console_text(b"ok") == ""


def test_the_json_form_is_stable_and_says_what_was_not_reached():
    d = Diagnosis("/dev/x", [Finding("port.found", OK, "there"),
                             Finding("link.bytes", PROBLEM, "nothing", {"listened s": 1.0}, "check the wiring")])
    got = d.as_json()
    assert got["verdict"] == "problem" and got["next_step"] == "check the wiring" and got["format"] == 1
    assert [f["id"] for f in got["findings"]] == ["port.found", "link.bytes"]
    assert "remedy" not in got["findings"][0]
    assert not d.link_works
    assert Diagnosis("/dev/x", [Finding("port.found", OK, "there")]).verdict() == "incomplete"


@pytest.mark.realtime
def test_the_kit_step_finds_a_simulated_link_at_an_unknown_rate_healthy(capsys):
    from osdk_conformance import kit

    assert kit._doctor_on_simulator() == 0
    out = capsys.readouterr().out
    assert "LINK WORKS" in out and "921600 baud: CRC-valid frames (found by listening)" in out
    assert "the broadcast fits m100-fw3.1" in out
