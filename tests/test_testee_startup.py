"""A testee that does not start is no verdict: `osdkc run` ends with one
line on standard error and exit status 2 (conformance/PROTOCOL.md, "Verdicts
and coverage"), not DOES NOT CONFORM, when the testee exits, hangs or writes
something other than a response before it answers its first request
(capabilities). The line names the command, how it ended and the end of
its standard error, and it speaks of the memory limit only when memory is
what stopped it.
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from osdk_conformance import api
from osdk_conformance.harness import runner, testee as supervision
from osdk_conformance.harness.vectors import load_cases

ROOT = Path(__file__).resolve().parents[1]
MISSING = "osdk_no_such_module_for_this_test"
# What a JVM prints (on standard output) when it cannot reserve its heap under RLIMIT_AS.
JVM_RESERVE = ("import sys\n"
               "print('Error occurred during initialization of VM')\n"
               "print('Could not reserve enough space for 2097152KB object heap', flush=True)\n"
               "sys.exit(1)\n")


def run(tmp_path: Path, source: str, *extra: str) -> tuple[subprocess.CompletedProcess[str], Path]:
    script = tmp_path / "testee.py"
    script.write_text(source)
    xml = tmp_path / "report.xml"
    proc = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "run", "--testee",
                           f"{sys.executable} {script}", "--filter", "worked", "--quiet", "--junit", str(xml),
                           *extra], capture_output=True, text=True, cwd=ROOT, timeout=120)
    return proc, xml


def test_a_testee_whose_import_fails_is_a_start_up_error(tmp_path: Path) -> None:
    proc, xml = run(tmp_path, f"import {MISSING}\n")
    assert proc.returncode == 2, proc.stdout + proc.stderr
    assert "CONFORM" not in proc.stdout and not xml.exists()  # no verdict, no report
    line, = proc.stderr.strip().splitlines()
    assert line.startswith("osdkc: testee ") and "did not start" in line
    assert "exited with status 1" in line
    assert f"ModuleNotFoundError: No module named '{MISSING}'" in line
    assert "memory" not in line and "JVM" not in line


@pytest.mark.slow
def test_the_memory_hint_comes_with_a_jvm_that_could_not_reserve_its_heap(tmp_path: Path) -> None:
    proc, _ = run(tmp_path, JVM_RESERVE)
    assert proc.returncode == 2, proc.stdout + proc.stderr
    line, = proc.stderr.strip().splitlines()
    assert "did not start" in line and "limit of 1024 MiB" in line and "--memory-mb" in line
    unlimited, _ = run(tmp_path, JVM_RESERVE, "--memory-mb", "0")
    assert unlimited.returncode == 2 and "--memory-mb" not in unlimited.stderr


@pytest.mark.slow
def test_a_testee_that_never_answers_its_first_request(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(supervision, "STARTUP_SECONDS", 0.2)
    cases = [c for c in load_cases() if "worked" in c.id]
    hanging = supervision.Testee([sys.executable, "-c", "import time; time.sleep(60)"], timeout=0.3)
    try:
        with pytest.raises(supervision.TesteeStartError, match=r"did not start: .*no response within 0\.3 s.*"
                                                                 r"it wrote nothing to standard error$"):
            runner.run_cases(hanging, cases, lambda case, response: (True, ""))
    finally:
        hanging.close()


@pytest.mark.slow
def test_the_api_raises_for_a_testee_that_does_not_start(tmp_path: Path) -> None:
    script = tmp_path / "testee.py"
    script.write_text(f"import {MISSING}\n")
    with pytest.raises(api.InputError, match=f"did not start.*No module named '{MISSING}'"):
        api.run_conformance([sys.executable, str(script)], filter="worked")
