"""The words a run on a serial port ends with, and the question before
anything moves.

- One vocabulary per command, the same at the terminal, in the HTML banner
  and in the JUnit property `verdict`: `osdkc device` PASSes, FAILs or was
  INTERRUPTED (with the time it actually ran); `osdkc fuzz --port` FOUND n
  or NOTHING FOUND; CONFORMS / DOES NOT CONFORM is `osdkc run`'s alone. No
  Python repr (True, False, None) in a report.
- The summary line, with or without -q, says how many checks ran, passed,
  failed and were skipped, and why the skipped ones were.
- `--allow-motion` asks at a terminal (a real pseudo-terminal as standard
  input, against a live `osdkc sim`): "no", end of input or Ctrl-C send
  nothing (exit 2, 2, 130); "yes" runs. Without a terminal and without
  --yes it refuses at once (exit 2) instead of blocking.
"""
from __future__ import annotations

import io
import json
import os
import re
import signal
import subprocess
import sys
import threading
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from osdk_conformance.core.capture import read_capture
from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.wire import commands_sent
from osdk_conformance.device.acceptance import confirm_motion, motion_plan
from osdk_conformance.device.verdict import counts
from osdk_conformance.harness.report import PASS, SKIP, FAIL, Result, html_report, junit_xml
from osdk_conformance.sim.simulator import spawned

CLI = [sys.executable, "-m", "osdk_conformance.cli"]
APP = "1234"
QUICK = ("--active-window", "0.5", "--max-jitter-ms", "150")
MOVEMENT = (0x01, 0x03)
REPR = re.compile(r"\b(True|False|None)\b")
QUESTION = "type yes to go on"


def banner(page: str) -> str:
    m = re.search(r'<p class="verdict (ok|no)">([^<]*)</p>', page)
    assert m, page[:2000]
    return m[2].replace("&#x27;", "'").replace("&quot;", '"').replace("&amp;", "&")


def junit_verdict(path: Path) -> str:
    props = {p.get("name"): p.get("value") for p in ET.parse(path).getroot().iter("property")}
    return props["verdict"]


def no_reprs(page: str, xml: str) -> None:
    meta = re.findall(r"<tr><th>[^<]*</th><td>([^<]*)</td></tr>", page)
    assert meta and not [v for v in meta if REPR.search(v)], meta
    values = re.findall(r'<property name="[^"]*" value="([^"]*)"', xml)
    assert values and not [v for v in values if REPR.search(v)], values


# ---- without a device --------------------------------------------------------


def test_the_count_names_every_number_and_why_checks_were_skipped():
    results = [Result("link", "link.open", PASS), Result("active", "active.version", PASS),
               Result("active", "active.activation", SKIP, "no --app-id given: activation not tried",
                      kind="no --app-id"),
               Result("active", "active.control_obtain", SKIP, "needs an activated app", kind="no --app-id"),
               Result("values", "values.rc_channels", SKIP, "item not broadcast: rc not checked"),
               Result("stream", "stream.rates", FAIL, "too slow")]
    assert counts(results) == ("3 checks ran (2 passed, 1 failed), 3 skipped (no --app-id: activation, "
                               "control_obtain; item not broadcast: rc_channels)")
    assert counts(results[:2]) == "2 checks ran (2 passed), none skipped"
    many = [Result("cases", f"fuzz.cases.k{i}", SKIP, "x", kind="left out by --kind") for i in range(5)]
    assert counts(many) == "0 checks ran (0 passed), 5 skipped (left out by --kind: k0, k1, k2, …)"


def test_reports_write_words_not_python_reprs():
    results = [Result("c", "c.a", FAIL, "bad", {"confirmed": False, "reason": None, "n": 3})]
    meta = {"active": True, "interrupted": False, "app id": None, "port": "/dev/x"}
    page = html_report(results, "t", meta)
    xml = junit_xml(results, "s", meta).decode()
    no_reprs(page, xml)
    assert "<th>active</th><td>yes</td>" in page and "<th>interrupted</th><td>no</td>" in page
    assert "app id" not in page and "app id" not in xml
    assert 'name="active" value="yes"' in xml
    assert not REPR.search(page.split("</style>")[-1]) and not REPR.search(xml)
    assert not REPR.search(html_report([Result("c", "c.a", PASS)], "t", meta).split("</style>")[-1])


class FakeTerminal(io.StringIO):
    def isatty(self) -> bool:
        return True


class Interrupted(FakeTerminal):
    def readline(self, *_):
        raise KeyboardInterrupt


@pytest.mark.parametrize("answer, status", [("yes\n", None), ("y\n", None), (" YES \n", None), ("no\n", 2),
                                            ("yess\n", 2), ("\n", 2), ("", 2)])
def test_only_yes_goes_on(answer, status):
    err = io.StringIO()
    assert confirm_motion("osdkc device", motion_plan(1.5), False, FakeTerminal(answer), err) == status
    assert "about 6.0 s" in err.getvalue() and QUESTION in err.getvalue()
    if status:
        assert "nothing was sent" in err.getvalue()


def test_ctrl_c_at_the_question_is_130_and_yes_asks_nothing():
    err = io.StringIO()
    assert confirm_motion("osdkc device", "x", False, Interrupted(), err) == 130
    assert "interrupted at the question: nothing was sent" in err.getvalue()
    err = io.StringIO()
    assert confirm_motion("osdkc device", "x", True, Interrupted(), err) is None and err.getvalue() == ""
    with pytest.raises(UsageError, match="add --yes"):
        confirm_motion("osdkc device", "x", False, io.StringIO("yes\n"), err)


@pytest.mark.parametrize("command", [["device", "--active"], ["fuzz"]])
def test_without_a_terminal_allow_motion_needs_yes_and_does_not_block(command):
    """Refused before the port is opened: a port that does not exist is never reached."""
    done = subprocess.run(CLI + [command[0], "--port", "/nonexistent/tty", "--profile", "a3-fw3.1",
                                 *command[1:], "--allow-motion"],
                          stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=60)
    assert done.returncode == 2, done.stdout + done.stderr
    assert "add --yes" in done.stderr and "standard input is not a terminal" in done.stderr
    assert "cannot open port" not in done.stderr and "Traceback" not in done.stderr
    # with --yes the question is skipped and the run goes on to the port
    done = subprocess.run(CLI + [command[0], "--port", "/nonexistent/tty", "--profile", "a3-fw3.1",
                                 *command[1:], "--allow-motion", "--yes"],
                          stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=60)
    assert done.returncode == 2 and "cannot open port" in done.stderr, done.stderr


# ---- against a live simulator ---------------------------------------------------


@pytest.mark.realtime
def test_a_quiet_active_run_without_app_id_says_what_it_skipped(tmp_path):
    html, junit = tmp_path / "r.html", tmp_path / "r.xml"
    with spawned("--app-id", APP) as (url, _):
        done = subprocess.run(CLI + ["device", "--no-capture", "--port", url, "--profile", "a3-fw3.1",
                                     "--duration", "1", "--active", "-q", *QUICK, "--html", str(html),
                                     "--junit", str(junit)],
                              stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=90)
    assert done.returncode == 0, done.stdout + done.stderr
    last = done.stdout.rstrip().splitlines()[-1]
    m = re.fullmatch(r"osdkc device: (PASS: (\d+) checks ran \((\d+) passed\), 4 skipped \((.*)\)); "
                     r"[\d.]+ s, a3-fw3.1 on (.*)", last)
    assert m, last
    assert m[2] == m[3] and int(m[2]) > 20
    assert m[4] == ("no --app-id: activation, control_obtain; no --allow-motion: movement; "
                    "nothing to undo: control_release")
    page, xml = html.read_text(), junit.read_text()
    assert banner(page) == m[1] == junit_verdict(junit)
    assert "CONFORM" not in page and "CONFORM" not in xml
    assert "<title>OPEN protocol acceptance run: a3-fw3.1</title>" in page
    no_reprs(page, xml)


@pytest.mark.realtime
def test_an_interrupted_run_says_interrupted_and_how_long_it_ran(tmp_path):
    html, junit = tmp_path / "r.html", tmp_path / "r.xml"
    with spawned("--app-id", APP) as (url, _):
        dev = subprocess.Popen(CLI + ["device", "--capture", str(tmp_path / "r.pcapng"), "--port", url, "--profile",
                                      "a3-fw3.1", "--duration", "30", "--html", str(html), "--junit", str(junit)],
                               stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        assert "capturing to" in dev.stderr.readline()
        time.sleep(1.5)
        t0 = time.monotonic()
        dev.send_signal(signal.SIGINT)
        out, err = dev.communicate(timeout=60)
    assert dev.returncode == 130, out + err
    last = out.rstrip().splitlines()[-1]
    m = re.fullmatch(r"osdkc device: (INTERRUPTED by SIGINT during phase passive after ([\d.]+) s, clean-up "
                     r"nothing to undo: \d+ checks ran \(\d+ passed, 1 errored\), .*); a3-fw3.1 on .*", last)
    assert m, last
    assert 1.4 < float(m[2]) < 10.0   # what it ran, not the 30 s planned
    page, xml = html.read_text(), junit.read_text()
    assert banner(page) == m[1] == junit_verdict(junit)
    assert '<p class="verdict no">' in page and "CONFORM" not in page
    duration = re.search(r"<th>duration</th><td>([^<]*)</td>", page)[1]
    assert duration == f"{m[2]} s (interrupted; 30 s of listening planned)", duration
    no_reprs(page, xml)
    assert time.monotonic() - t0 < 30


@pytest.mark.realtime
def test_a_fuzz_session_that_finds_nothing_says_so_everywhere(tmp_path):
    html, junit = tmp_path / "f.html", tmp_path / "f.xml"
    with spawned("--baud", "921600") as (url, _):
        done = subprocess.run(CLI + ["fuzz", "--port", url, "--profile", "a3-fw3.1", "--baud", "921600", "--cases",
                                     "30", "--seed", "1", "--no-capture", "-q", "--findings-dir", str(tmp_path / "fd"),
                                     "--html", str(html), "--junit", str(junit)],
                              stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=90)
    assert done.returncode == 0, done.stdout + done.stderr
    last = done.stdout.rstrip().splitlines()[-1]
    m = re.fullmatch(r"osdkc fuzz: (NOTHING FOUND: 30 cases in .*; (\d+) checks ran \((\d+) passed\), 2 skipped "
                     r"\(no --allow-motion: movement.zero; nothing to undo: control_release\))", last)
    assert m and m[2] == m[3], last
    page, xml = html.read_text(), junit.read_text()
    assert banner(page) == m[1] == junit_verdict(junit)
    assert '<p class="verdict ok">' in page and "CONFORM" not in page and "CONFORM" not in xml
    no_reprs(page, xml)


# ---- the question, on a real pseudo-terminal --------------------------------------


class Child:
    """A command with a pseudo-terminal as standard input; its stderr is
    collected as it comes (the question has no newline after it)."""

    def __init__(self, argv: list[str], env: dict | None = None) -> None:
        self.master, slave = os.openpty()
        self.proc = subprocess.Popen(argv, stdin=slave, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                     env=dict(os.environ, **(env or {})),
                                     # a pytest-xdist worker ignores SIGINT, and an ignored signal stays
                                     # ignored across exec: give the child the disposition a shell gives
                                     preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
        os.close(slave)
        self.err = b""
        self.lock = threading.Condition()
        threading.Thread(target=self._read, daemon=True).start()

    def _read(self) -> None:
        while chunk := os.read(self.proc.stderr.fileno(), 4096):
            with self.lock:
                self.err += chunk
                self.lock.notify_all()
        with self.lock:
            self.lock.notify_all()

    def wait_for(self, text: str, timeout: float = 60) -> None:
        end = time.monotonic() + timeout
        with self.lock:
            while text.encode() not in self.err:
                assert self.proc.poll() is None or time.monotonic() < end, self.err.decode()
                assert time.monotonic() < end, f"no {text!r} in {self.err.decode()}"
                self.lock.wait(0.2)

    def type(self, data: bytes) -> None:
        os.write(self.master, data)

    def finish(self, timeout: float = 120) -> tuple[int, str, str]:
        out = self.proc.stdout.read().decode()
        self.proc.wait(timeout=timeout)
        os.close(self.master)
        time.sleep(0.1)
        with self.lock:
            return self.proc.returncode, out, self.err.decode()


def _device_at_a_terminal(tmp: Path, answer: bytes | int) -> dict:
    """`osdkc device --active --allow-motion` with a terminal as stdin: at the
    question, type `answer`, or send that signal."""
    stats, cap = tmp / "sim.json", tmp / "run.pcapng"
    with spawned("--app-id", APP, "--stats", str(stats)) as (url, _):
        child = Child(CLI + ["device", "--port", url, "--capture", str(cap), "--profile", "a3-fw3.1",
                             "--duration", "0.5", "--active", "--allow-motion", "--app-id", APP,
                             "--active-window", "1", "--motion-seconds", "1.2", "--max-jitter-ms", "150"])
        child.wait_for(QUESTION)
        assert child.proc.poll() is None   # it waits for the answer
        if isinstance(answer, bytes):
            child.type(answer)
        else:
            os.kill(child.proc.pid, answer)
        rc, out, err = child.finish()
    sent = [(op.cmd_set, op.cmd_id) for op in commands_sent(read_capture(cap).records)] if cap.exists() else []
    return {"rc": rc, "out": out, "err": err, "stats": json.loads(stats.read_text()), "sent": sent}


@pytest.mark.realtime
@pytest.mark.parametrize("answer, why", [(b"no\n", 'the answer was "no", not yes'),
                                         (b"\x04", "no answer (end of input)")], ids=["no", "end-of-input"])
def test_no_at_the_terminal_sends_nothing(tmp_path, answer, why):
    r = _device_at_a_terminal(tmp_path, answer)
    assert r["rc"] == 2, r["out"] + r["err"]
    assert "MOVES THE AIRCRAFT" in r["err"] and "about 4.9 s in all" in r["err"]
    assert f"movement control not confirmed ({why}): nothing was sent" in r["err"]
    assert "Traceback" not in r["err"]
    assert r["sent"] == [] and MOVEMENT not in r["sent"]
    assert r["stats"]["rx_bytes"] == 0 and r["stats"]["movement_commands"] == 0, r["stats"]


@pytest.mark.realtime
def test_ctrl_c_at_the_terminal_question_exits_130_with_nothing_sent(tmp_path):
    r = _device_at_a_terminal(tmp_path, signal.SIGINT)
    assert r["rc"] == 130, r["out"] + r["err"]
    assert "interrupted at the question: nothing was sent" in r["err"] and "Traceback" not in r["err"]
    assert r["sent"] == []
    assert r["stats"]["rx_bytes"] == 0 and r["stats"]["movement_commands"] == 0, r["stats"]


@pytest.mark.slow
@pytest.mark.realtime
def test_yes_at_the_terminal_runs_the_movement_check(tmp_path):
    r = _device_at_a_terminal(tmp_path, b"yes\n")
    assert r["rc"] == 0, r["out"] + r["err"]
    assert re.search(r"^PASS\s+active.movement", r["out"], re.M), r["out"]
    assert MOVEMENT in r["sent"] and r["stats"]["movement_commands"] > 0
    assert r["stats"]["control"] == "rc"   # released at the end
    assert r["out"].rstrip().splitlines()[-1].startswith("osdkc device: PASS: ")


@pytest.mark.realtime
def test_the_fuzzer_asks_too(tmp_path):
    stats = tmp_path / "sim.json"
    with spawned("--app-id", "7", "--stats", str(stats)) as (url, _):
        child = Child(CLI + ["fuzz", "--port", url, "--profile", "a3-fw3.1", "--allow-motion", "--app-id", "7",
                             "--cases", "20", "--no-capture", "--findings-dir", str(tmp_path / "fd")])
        child.wait_for(QUESTION)
        child.type(b"n\n")
        rc, out, err = child.finish()
    assert rc == 2, out + err
    assert "up to 20 cases, then control released" in err and "nothing was sent" in err
    assert json.loads(stats.read_text())["rx_bytes"] == 0
