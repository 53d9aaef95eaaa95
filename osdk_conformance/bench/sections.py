"""The sections of `osdkc bench` besides decoding: the conformance run, the
differential fuzzer, the acceptance receiver at 100 Hz, the device fuzzer
against the simulator over a pty, and the machine.

Each runs the project's own command in a child process (bench_child) and
reads the numbers that command already reports, so nothing is measured
twice in two ways.
"""
from __future__ import annotations

import json
import os
import platform
import re
import subprocess
import sys
import tempfile
from pathlib import Path

from osdk_conformance.bench import child as bench_child
from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.paths import ROOT
from osdk_conformance.sim.simulator import spawned

OSDKC = [sys.executable, "-m", "osdk_conformance.cli"]


def _failure(child: bench_child.Child) -> str:
    return child.problem or f"exit {child.code}: {child.stderr_line() or child.stdout.strip()[-200:] or 'no message'}"


def conformance_run(timeout: float) -> dict:
    """Wall and CPU time of `osdkc run --impl all` (reports to a temporary directory)."""
    with tempfile.TemporaryDirectory(prefix="osdkc-bench-run-") as tmp:
        child = bench_child.run([*OSDKC, "run", "--impl", "all", "--quiet", "--report-dir", tmp], timeout)
        try:
            status = json.loads((Path(tmp) / "conformance.json").read_text())
        except (OSError, ValueError):
            status = None
    out = {"command": "osdkc run --impl all", "wall_seconds": round(child.wall, 1), "cpu_seconds": round(child.cpu, 1),
           "ok": child.code == 0}
    if status:
        out["jobs"] = status.get("jobs")
        out["per_impl_seconds"] = {s["impl"]: s.get("seconds") for s in status.get("implementations", [])}
        out["conforms"] = all(s.get("conforms") for s in status.get("implementations", []))
    if child.code != 0:
        out["error"] = _failure(child)
    return out


FUZZ_HEAD = re.compile(r"osdkc fuzz: .*?: (\d+) examples.*? in ([\d.]+) s \((\d+)/s\)")
FUZZ_OP = re.compile(r"^\s+(\w+)\s+(\d+) runs\s+(\d+) execs/s", re.M)


def fuzz(examples: int, seed: int, timeout: float) -> dict:
    """Executions per second of `osdkc fuzz --impl all` over a fixed number of examples and seed."""
    cmd = ["fuzz", "--impl", "all", "--max-examples", str(examples), "--seed", str(seed)]
    child = bench_child.run([*OSDKC, *cmd], timeout)
    out: dict = {"command": "osdkc " + " ".join(cmd), "wall_seconds": round(child.wall, 1), "ok": child.code == 0}
    head = FUZZ_HEAD.search(child.stderr)
    if head:
        out.update({"examples": int(head[1]), "seconds": float(head[2]), "execs_per_s": int(head[3]),
                    "per_op_execs_per_s": {m[1]: int(m[3]) for m in FUZZ_OP.finditer(child.stderr)}})
    if child.code != 0 or not head:
        out["ok"] = False
        out["error"] = _failure(child) if child.code != 0 else "no summary line in the output of osdkc fuzz"
        if child.code == 1 and "DISAGREEMENT" in child.stderr:
            out["error"] = "the implementations disagreed (see `osdkc " + " ".join(cmd) + "`)"
    return out


def acceptance(seconds: float, timeout: float) -> dict:
    """CPU use of the acceptance receiver at 100 Hz: `osdkc soak --json` (a3-fw3.1, every item)."""
    cmd = ["soak", "--duration", f"{seconds:g}", "--json"]
    child = bench_child.run([*OSDKC, *cmd], timeout)
    out: dict = {"command": "osdkc " + " ".join(cmd), "ok": child.code == 0}
    line = next((ln for ln in child.stdout.splitlines() if ln.startswith("{")), None)
    try:
        soak = json.loads(line) if line else None
    except ValueError:
        soak = None
    if isinstance(soak, dict):
        out.update({k: soak.get(k) for k in ("profile", "rate_hz", "duration_s", "frames_sent", "frames_lost",
                                               "receiver_cpu_percent", "latency_ms")})
    if child.code != 0 or not isinstance(soak, dict):
        out["ok"] = False
        out["error"] = _failure(child) if child.code not in (0, 1) or not soak else "frames were lost"
    return out


DEVICE_FUZZ_BAUDS = (921600, 230400)
DEVICE_FUZZ_PROFILE = "a3-fw3.1"
DEVICE_FUZZ_HEAD = re.compile(r"^osdkc fuzz: ([^:]+): (\d+) cases in ([\d.]+) s \(([\d.]+) cases/s at (\d+) baud, "
                              r"([\d.]+) bytes/case\)", re.M)


def device_fuzz(cases: int, seed: int, timeout: float, bauds: tuple[int, ...] = DEVICE_FUZZ_BAUDS,
                profile: str = DEVICE_FUZZ_PROFILE) -> dict:
    """Cases per second of `osdkc fuzz --port` against a healthy `osdkc sim` over a pty, at each baud rate,
    beside what the line could carry of the bytes each case took."""
    rows = [_device_fuzz_at(baud, cases, seed, profile, timeout) for baud in bauds]
    return {"command": f"osdkc fuzz --port PTY --profile {profile} --cases {cases} --seed {seed} --no-capture",
            "profile": profile, "seed": seed, "rows": rows, "ok": all(r["ok"] for r in rows)}


def _device_fuzz_at(baud: int, cases: int, seed: int, profile: str, timeout: float) -> dict:
    cmd = ["fuzz", "--profile", profile, "--baud", str(baud), "--cases", str(cases), "--seed", str(seed),
           "--no-capture"]
    out: dict = {"baud": baud, "command": "osdkc " + " ".join(cmd[:1] + ["--port", "PTY"] + cmd[1:]), "ok": False}
    with tempfile.TemporaryDirectory(prefix="osdkc-bench-device-fuzz-") as tmp:
        stats_path = Path(tmp) / "sim-stats.json"
        try:
            # the simulator checks the pty's speed: bytes at another baud would be counted as garbage
            with spawned("--profile", profile, "--baud", str(baud), "--stats", str(stats_path)) as (url, _):
                child = bench_child.run([*OSDKC, *cmd, "-q", "--port", url,
                                         "--findings-dir", str(Path(tmp) / "findings")], timeout)
        except UsageError as e:
            out["error"] = str(e)
            return out
        try:
            sim = json.loads(stats_path.read_text())
        except (OSError, ValueError):
            sim = {}
    out["wall_seconds"] = round(child.wall, 1)
    head = DEVICE_FUZZ_HEAD.search(child.stdout)
    if head:
        verdict, n = head[1], int(head[2])
        out.update({"verdict": verdict, "cases": n, "seconds": float(head[3]), "cases_per_s": float(head[4]),
                    "findings": int(found[1]) if (found := re.match(r"FOUND (\d+)", verdict)) else 0})
        per_case = float(head[6])   # everything the fuzzer sent while fuzzing, over the cases
        if per_case > 0 and n:
            out["bytes_per_case"] = round(per_case, 1)
            out["line_cases_per_s"] = round(baud / 10 / per_case, 1)
            out["share_of_line"] = round(out["cases_per_s"] / out["line_cases_per_s"], 3)
    mismatch = (sim.get("rx_bytes_discarded") or {}).get("baud_mismatch")
    if child.code != 0 or not head:
        fails = [ln.strip() for ln in child.stdout.splitlines() if ln.startswith(("FAIL", "ERROR"))]
        out["error"] = ((f"{head[1]} on a healthy simulator" + (f": {fails[0]}" if fails else "")) if head
                        else _failure(child) if child.code != 0 else "no summary line in the output of osdkc fuzz")
    elif not sim:
        out["error"] = "the simulator left no statistics"
    elif mismatch:
        out["error"] = f"the simulator read {mismatch} bytes at another baud rate than {baud}"
    else:
        out["ok"] = True
    return out


# ---- the machine ----------------------------------------------------------------------------


def _first_line(argv: list[str]) -> str:
    try:
        r = subprocess.run(argv, capture_output=True, text=True, timeout=30, stdin=subprocess.DEVNULL, cwd=ROOT)
    except (OSError, subprocess.TimeoutExpired):
        return "not found"
    lines = [ln.strip() for ln in (r.stdout + r.stderr).splitlines() if ln.strip()]
    return lines[0] if lines else "not found"


def _proc_value(path: str, key: str) -> str:
    try:
        for line in Path(path).read_text().splitlines():
            if line.startswith(key):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown"


def machine() -> dict:
    mem = _proc_value("/proc/meminfo", "MemTotal")
    try:
        mem = f"{int(mem.split()[0]) / 1024 ** 2:.1f} GiB"
    except (ValueError, IndexError):
        pass
    rev = _first_line(["git", "rev-parse", "--short", "HEAD"])
    dirty = _first_line(["git", "status", "--porcelain", "--untracked-files=no"])
    return {
        "cpu": _proc_value("/proc/cpuinfo", "model name"),
        "cores": os.cpu_count(),
        "memory": mem,
        "kernel": f"{platform.system()} {platform.release()}",
        "load_average_at_start": " ".join(f"{x:.2f}" for x in os.getloadavg()),
        "python": platform.python_version(),
        "node": _first_line(["node", "--version"]),
        "java": _first_line(["java", "-version"]),
        "go": _first_line(["go", "version"]),
        "gcc": _first_line(["gcc", "--version"]),
        "git": rev + (" with uncommitted changes" if dirty != "not found" else ""),
    }
