"""tools/run_tests.py, which `make test` and `make quick` run: the realtime
tests beside the rest, both outputs readable, one exit status, and a Ctrl-C
that stops both runs. Checked on small test files of its own (a pytest.ini
in tmp_path), not on the suite that is running it."""
from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from osdk_conformance.core.paths import ROOT

RUNNER = ROOT / "tools" / "run_tests.py"
INI = "[pytest]\nmarkers =\n    realtime: timing\n    slow: slow\n"


def suite(tmp_path: Path, body: str) -> list[str]:
    (tmp_path / "pytest.ini").write_text(INI)
    (tmp_path / "test_small.py").write_text("import os, time\nimport pytest\n\n" + body)
    # --jobs 0: the other part in one process; starting pytest-xdist workers is not what is tested
    return ["--jobs", "0", "--", "-c", str(tmp_path / "pytest.ini"), "--rootdir", str(tmp_path),
            "-p", "no:cacheprovider", str(tmp_path)]


def run(args: list[str], **kw) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, str(RUNNER), *args], capture_output=True, text=True, timeout=120, **kw)


@pytest.mark.slow
def test_both_parts_run_side_by_side_and_the_realtime_output_comes_last(tmp_path):
    args = suite(tmp_path, (
        "@pytest.mark.realtime\n"
        f"def test_timing():\n    open({str(tmp_path / 'nice-realtime')!r}, 'w').write(str(os.nice(0)))\n\n"
        f"def test_work():\n    open({str(tmp_path / 'nice-rest')!r}, 'w').write(str(os.nice(0)))\n\n"
        "@pytest.mark.slow\ndef test_slow_work():\n    pass\n"))
    proc = run(args)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    realtime_nice, rest_nice = (int((tmp_path / f"nice-{part}").read_text()) for part in ("realtime", "rest"))
    assert rest_nice == min(realtime_nice + 10, 19)  # 19: the lowest priority there is
    rest, _, realtime = proc.stdout.partition("---- realtime tests")
    assert "2 passed" in rest and "1 passed, 2 deselected" in realtime
    quick = run(["--marks", "not slow", *args])
    rest, _, realtime = quick.stdout.partition("---- realtime tests")
    assert quick.returncode == 0 and "1 passed" in rest and "1 passed, 2 deselected" in realtime
    # two realtime tests at a time: pytest-xdist's workers, each at normal priority
    two = run(["--realtime-jobs", "2", *args])
    rest, _, realtime = two.stdout.partition("---- realtime tests")
    assert two.returncode == 0 and "bringing up nodes" in realtime and "1 passed" in realtime, two.stdout
    assert int((tmp_path / "nice-realtime").read_text()) == realtime_nice


@pytest.mark.slow
def test_a_failure_in_either_part_fails_the_run(tmp_path):
    for body in ("@pytest.mark.realtime\ndef test_timing():\n    assert False\n\ndef test_work():\n    pass\n",
                 "@pytest.mark.realtime\ndef test_timing():\n    pass\n\ndef test_work():\n    assert False\n"):
        proc = run(suite(tmp_path, body))
        assert proc.returncode == 1, proc.stdout
        assert "1 failed" in proc.stdout and "Traceback" not in proc.stderr


@pytest.mark.parametrize("sig", [pytest.param(signal.SIGINT, id="ctrl-c-to-the-group"),
                                 pytest.param(signal.SIGTERM, id="sigterm-to-the-runner", marks=pytest.mark.slow)])
def test_a_signal_stops_both_parts(tmp_path, sig):
    """A Ctrl-C reaches the terminal's whole process group; a SIGTERM (a CI
    job cancelled) may reach the runner alone, which passes it on. The
    time to the exit is printed (pytest -s); the bound asserted is only a
    guard against the runs going on, since the suite runs on a loaded machine."""
    marker = tmp_path / "started"
    args = suite(tmp_path, (
        f"@pytest.mark.realtime\ndef test_timing():\n    open({str(marker)!r} + '1', 'w').close()\n"
        "    time.sleep(60)\n\n"
        f"def test_work():\n    open({str(marker)!r} + '2', 'w').close()\n    time.sleep(60)\n"))
    # the child gets a shell's SIGINT disposition (a pytest-xdist worker ignores SIGINT)
    proc = subprocess.Popen([sys.executable, str(RUNNER), *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, start_new_session=True,
                            preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    try:
        deadline = time.monotonic() + 60
        while not (Path(f"{marker}1").exists() and Path(f"{marker}2").exists()):
            assert time.monotonic() < deadline and proc.poll() is None, proc.communicate()
            time.sleep(0.05)
        t0 = time.monotonic()
        if sig == signal.SIGINT:
            os.killpg(proc.pid, sig)
        else:
            proc.send_signal(sig)
        out, err = proc.communicate(timeout=60)
        seconds = time.monotonic() - t0
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
    print(f"exit {proc.returncode} {seconds:.2f} s after {sig.name}")
    assert proc.returncode == 128 + sig, out + err
    assert seconds < 20
    assert "Traceback" not in err and "---- realtime tests" in out
    deadline = time.monotonic() + 10   # killed processes are gone once their new parent reaps them
    while (left := subprocess.run(["pgrep", "-s", str(proc.pid)], capture_output=True, text=True).stdout.split()):
        assert time.monotonic() < deadline, subprocess.run(["ps", "-o", "pid,stat,args", "-p", ",".join(left)],
                                                           capture_output=True, text=True).stdout
        time.sleep(0.1)
