"""The generated C library on a Cortex-M, answering the runner over a UART
(conformance/testees/c-target, osdk_conformance/board/bridge.py,
docs/ON-TARGET.md).

The firmware is built by `make setup` with Debian's arm-none-eabi-gcc and
newlib, and runs in qemu-system-arm: `--impl c-target` on the mps2-an386
(Cortex-M4), and the NUCLEO-F446RE board file on QEMU's netduinoplus2
(an STM32F405 with the same USART), reached through `--testee-port` on the
pseudo-terminal QEMU gives it, as a real board's /dev/ttyACM0 would be.
Here a sample of every vector file; the kit replays them all.
"""
from __future__ import annotations

import json
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path
from xml.etree import ElementTree as ET

import pytest

from osdk_conformance.harness.runner import TARGET_IMPLS
from osdk_conformance.harness.vectors import load_cases

ROOT = Path(__file__).resolve().parent.parent
FIRMWARE = ROOT / "conformance" / "testees" / "c-target" / "build"
MPS2_ELF = FIRMWARE / "mps2-an386" / "osdk-c-target.elf"
NUCLEO_ELF = FIRMWARE / "nucleo-f446re" / "osdk-c-target.elf"
OSDKC = [sys.executable, "-m", "osdk_conformance.cli"]
# every this-many-th case of each operation and profile, and the first of each
STRIDE = 120


@pytest.fixture(scope="module")
def sample(tmp_path_factory) -> tuple[list[str], int, set[str]]:
    """--vectors options for a sample of the vectors: every STRIDE-th case of each operation and profile."""
    chosen, seen = [], {}
    for c in load_cases():
        key = (c.operation, c.profile)
        if seen.get(key, 0) % STRIDE == 0:
            chosen.append(c)
        seen[key] = seen.get(key, 0) + 1
    path = tmp_path_factory.mktemp("sample") / "sample.json"
    doc = {"suite": "sample", "description": "every STRIDE-th case", "generator": "tools/gen_vectors.py",
           "numberOfTests": len(chosen), "notes": {},
           "testGroups": [{"operation": c.operation, "profile": c.profile, "tests": [{
               "id": c.id, "category": c.category, "comment": c.comment, "input": c.input,
               "result": c.result, "expected": c.expected, "flags": list(c.flags)}]} for c in chosen]}
    path.write_text(json.dumps(doc))
    return ["--vectors", str(path)], len(chosen), {c.operation for c in chosen}


def qemus_under(root: int) -> list[int]:
    """The QEMU processes descending from process `root`."""
    parent, qemu = {}, []
    for pid in filter(str.isdigit, os.listdir("/proc")):
        try:
            stat = (Path("/proc") / pid / "stat").read_text()
            cmd = (Path("/proc") / pid / "cmdline").read_bytes().split(b"\0")
        except OSError:
            continue
        parent[int(pid)] = int(stat.rsplit(")", 1)[1].split()[1])
        if cmd and cmd[0].endswith(b"qemu-system-arm"):
            qemu.append(int(pid))

    def descends(pid: int) -> bool:
        while pid > 1:
            if pid == root:
                return True
            pid = parent.get(pid, 0)
        return False

    return [q for q in qemu if descends(q)]


def bridges_on(port: str) -> bool:
    """Whether a bridge process has the board's port open."""
    for pid in os.listdir("/proc"):
        try:
            cmd = (Path("/proc") / pid / "cmdline").read_bytes().split(b"\0")
        except OSError:
            continue
        if b"osdk_conformance.board.bridge" in cmd and port.encode() in cmd:
            return True
    return False


def test_the_target_testee_conforms_on_a_sample_of_every_operation(sample, tmp_path):
    vectors, n, ops = sample
    summary = tmp_path / "summary.json"
    r = subprocess.run([*OSDKC, "run", "--impl", "c-target", *vectors, "-q", "--summary-json", str(summary)],
                       capture_output=True, text=True, timeout=600, cwd=ROOT)
    assert r.returncode == 0, r.stdout[-3000:] + r.stderr[-2000:]
    s = json.loads(summary.read_text())
    assert s["testee"] == "osdk-c-target" and s["conforms"] and s["cases"] == n
    assert s["statuses"]["pass"] == n
    assert ops == {"decode_stream", "decode_frame", "decode_payload", "classify_control_mode",
                   "check_movement_control", "encode_movement_control", "encode_frame"}
    assert str(MPS2_ELF) in s["command"]


def test_c_target_is_not_part_of_all_and_is_named_by_its_firmware():
    from osdk_conformance.harness.runner import BUNDLED_IMPLS

    assert "c-target" not in BUNDLED_IMPLS
    assert str(MPS2_ELF) in TARGET_IMPLS["c-target"]


@pytest.fixture
def nucleo_on_a_pty():
    """The NUCLEO-F446RE firmware in QEMU's netduinoplus2, USART2 on a pty; (pty path, QEMU)."""
    qemu = subprocess.Popen(["qemu-system-arm", "-machine", "netduinoplus2", "-display", "none", "-monitor", "stdio",
                             "-serial", "null", "-serial", "pty", "-accel", "tcg,tb-size=32",
                             "-kernel", str(NUCLEO_ELF)],
                            stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    out = b""
    deadline = time.monotonic() + 30
    while not (m := re.search(rb"(/dev/pts/\d+) \(label serial1\)", out)) and time.monotonic() < deadline:
        out += os.read(qemu.stdout.fileno(), 4096)
    assert m, out
    yield m[1].decode(), qemu
    qemu.kill()
    qemu.wait()


def test_a_board_on_a_serial_port_conforms_and_a_reset_mid_run_is_one_crash(nucleo_on_a_pty, tmp_path, sample):
    """`--testee-port`: the bridge on the board's tty. QEMU's monitor resets
    the board during the run: the request that was waiting fails as a crash
    of the testee that says so, and the run goes on with the board as it
    came back."""
    port, qemu = nucleo_on_a_pty
    vectors, n, _ = sample
    junit = tmp_path / "junit.xml"
    run = subprocess.Popen([*OSDKC, "run", "--testee-port", port, *vectors, "-q", "--junit", str(junit)],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=ROOT)
    deadline = time.monotonic() + 60
    while not bridges_on(port) and run.poll() is None and time.monotonic() < deadline:
        time.sleep(0.02)
    time.sleep(1.0)   # past the bridge's own 0.3 s settling, some requests in
    assert run.poll() is None, run.communicate()
    qemu.stdin.write(b"system_reset\n")
    qemu.stdin.flush()
    out, err = run.communicate(timeout=600)
    assert run.returncode == 1, out[-3000:] + err[-2000:]
    failures = [tc for tc in ET.parse(junit).getroot().iter("testcase")
                if tc.find("failure") is not None or tc.find("error") is not None]
    assert len(failures) == 1, [tc.get("name") for tc in failures]
    text = ET.tostring(failures[0], encoding="unicode")
    assert "testee_crash" in text and "the board restarted while a request waited" in text
    assert f"DOES NOT CONFORM (1 failed; {n} of {n} cases ran)" in out, out[-2000:]


def test_ctrl_c_stops_a_run_on_the_emulated_board_and_leaves_no_qemu():
    # every vector: the run takes minutes, so the signal always comes in the middle of it
    run = subprocess.Popen([*OSDKC, "run", "--impl", "c-target", "-q"], stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True, cwd=ROOT)
    deadline = time.monotonic() + 30
    while not (qemus := qemus_under(run.pid)) and time.monotonic() < deadline:
        time.sleep(0.05)
    assert qemus, "QEMU never started"
    time.sleep(0.5)
    t0 = time.monotonic()
    run.send_signal(signal.SIGINT)
    out, err = run.communicate(timeout=10)
    assert time.monotonic() - t0 < 2.0
    assert run.returncode == 130, out[-2000:] + err[-2000:]
    assert "INTERRUPTED" in out + err
    time.sleep(0.2)
    assert not [q for q in qemus if Path(f"/proc/{q}").exists()], "QEMU outlived the run"


def test_the_bridge_says_what_is_missing(tmp_path):
    r = subprocess.run([sys.executable, "-m", "osdk_conformance.board.bridge", "--qemu", str(tmp_path / "no.elf")],
                       input="", capture_output=True, text=True, timeout=30)
    assert r.returncode != 0 and "no firmware at" in r.stderr and "Traceback" not in r.stderr
    r = subprocess.run([*OSDKC, "run", "--testee-port", str(tmp_path / "ttyNONE"), "--filter", "encode"],
                       capture_output=True, text=True, timeout=60, cwd=ROOT)
    assert r.returncode == 2 and "cannot open" in r.stderr and "Traceback" not in r.stderr


def test_the_boards_limits_answer_internal_error_and_the_board_goes_on():
    """A line past the 4 KiB buffer, hostile nesting, then ordinary requests:
    the firmware has no heap to grow, so it says what did not fit."""
    lines = ['{"op": "decode_frame", "id": "x", "profile": "a3-fw3.1", "hex": "' + "aa" * 3000 + '"}',
             "[" * 5000 + "]" * 5000,
             "[" * 300 + "]" * 300,
             "not json",
             '{"op": "capabilities"}']
    r = subprocess.run([sys.executable, "-m", "osdk_conformance.board.bridge", "--qemu", str(MPS2_ELF)],
                       input="\n".join(lines) + "\n", capture_output=True, text=True, timeout=60)
    assert r.returncode == 0, r.stderr
    answers = [json.loads(line) for line in r.stdout.splitlines()]
    assert [a.get("error") for a in answers] == ["internal_error", "internal_error", "bad_request", "bad_request", None]
    assert "4096-byte line" in answers[0]["detail"] and "nested too deeply" in answers[2]["detail"]
    assert answers[-1]["ok"] and answers[-1]["result"]["name"] == "osdk-c-target"


# ---- footprint and instructions per frame on the board (osdkc bench --only footprint) ----------

@pytest.fixture(scope="module")
def board_footprint():
    from osdk_conformance.bench import board_footprint
    return board_footprint.measure(seconds=5.0)


def test_the_linked_programs_grow_with_each_feature_and_the_stack_bound_holds(board_footprint):
    b = board_footprint
    assert b["ok"], b.get("error")
    rows = b["features"]
    assert [r["feature"] for r in rows] == [0, 1, 2, 3]
    flash = [r["flash"] for r in rows]
    assert flash == sorted(flash) and len(set(flash)) == 4
    receive = rows[1]
    # the deframer keeps one maximum-length frame (LEN is 10 bits) and its detail sentence
    assert receive["static_ram"] >= 1023 + 160
    assert receive["ram"] == receive["static_ram"] + receive["stack"]["bytes"]
    assert receive["stack"]["path"][:3] == ["reset_handler", "main", "osdk_deframer_feed"]
    assert "osdk_frame_decode" in rows[2]["stack"]["path"]   # through the callback the deframer calls
    assert rows[3]["entries"]["osdk_encode_frame"] > 0
    goals = b["goals"]
    assert goals["flash"]["measured"] == receive["flash"] and goals["ram"]["measured"] == receive["ram"]
    c = b["cycles"]
    for mode in ("receive", "decode"):
        m = c["modes"][mode]
        # 25 MHz SysTick, one instruction per virtual ns; the calibration reads the clock to a tick
        assert abs(m["instructions_per_tick"] - 40.0) < 0.01
        assert 0 < m["stack_used"] <= c["stack_bound"]
        assert m["most_per_frame"] >= m["instructions_per_frame"] > 0
    assert c["modes"]["decode"]["instructions_per_frame"] > c["modes"]["receive"]["instructions_per_frame"]
    from osdk_conformance.bench.board_footprint import markdown
    text = "\n".join(markdown(b))
    assert "| 1: receive" in text and ("MISSED" in text or "met" in text)


def test_a_call_through_a_pointer_with_nothing_to_bound_it_fails_the_section(tmp_path):
    from osdk_conformance.bench import board_footprint
    elf = board_footprint.build() / "footprint-1.elf"
    with pytest.raises(board_footprint.BoardError, match="calls through a pointer"):
        board_footprint.call_graph(elf, {}, callbacks=("no_such_callback",))


def test_the_stack_paint_catches_a_bound_that_misses_a_path(monkeypatch, board_footprint):
    from osdk_conformance.bench import board_footprint as bf
    real = bf.deepest
    monkeypatch.setattr(bf, "deepest", lambda funcs, entries: {e: {**b, "bytes": 16}
                                                                for e, b in real(funcs, entries).items()})
    out = bf.measure(seconds=1.0)
    assert not out["ok"] and "more than the bound of 16" in out["error"]
