"""Sessions of `osdkc host` through `osdkc tap` to `osdkc sim`: a healthy
host must pass every check, and a host with a planted bug (sim/host_bugs.py)
must fail the check that bug names. The tests run each once;
`osdkc bench --only tap` runs each over many seeds, on a saturated machine
(two busy loops per core), and publishes the table in docs/TAP.md."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from osdk_conformance.bench.reliability import BusyLoops
from osdk_conformance.bench.stand_in import SIM_NICE, favour
from osdk_conformance.sim.host_bugs import BUGS

KEY = "ab" * 32
KEY_ENV = "OSDK_TAP_BENCH_KEY"
APP_ID = 1234567
RELEASE_WAIT_S = 2.5   # a host that ends holding control must be silent this long before the tap stops (its grace: 2 s)
CASES = ("healthy", *BUGS)
BAUD = 921600   # the fastest rate the profiles use: where a relay's added delay matters most


def _cli(*args: str) -> list[str]:
    return [sys.executable, "-m", "osdk_conformance.cli", *args]


def _first_line(proc: subprocess.Popen, what: str) -> str:
    line = proc.stdout.readline().strip()
    if not line:
        proc.wait()
        raise RuntimeError(f"{what} did not start: {proc.stderr.read().strip()}")
    return line


def _stop(proc: subprocess.Popen, sig: int, timeout: float = 10.0) -> int:
    if proc.poll() is None:
        proc.send_signal(sig)
    try:
        proc.wait(timeout)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()
    return proc.returncode


def run_session(case: str, seed: int, work: Path, profile: str = "m100-fw3.1", seconds: float = 1.5,
                baud: int = BAUD) -> dict:
    """One session of `case` ("healthy" or a bug name): the host's exit
    status, the tap's, its summary JSON and where its capture is."""
    import signal

    env = {**os.environ, KEY_ENV: KEY}
    work.mkdir(parents=True, exist_ok=True)
    sim = subprocess.Popen(_cli("sim", "--profile", profile, "--app-id", str(APP_ID), "--key-env", KEY_ENV,
                                "--seed", str(seed), "--baud", str(baud)), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                           env=env)
    tap = host = None
    try:
        favoured = favour(sim.pid)   # it stands in for a flight controller, which has a CPU of its own
        fc = _first_line(sim, "osdkc sim")
        summary, capture = work / "tap.json", work / "tap.pcapng"
        tap = subprocess.Popen(_cli("tap", "--fc", fc, "--profile", profile, "--baud", str(baud), "-q",
                                    "--capture", str(capture),
                                    "--summary-json", str(summary), "--html", str(work / "tap.html"),
                                    "--junit", str(work / "tap.xml")),
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
        port = _first_line(tap, "osdkc tap")
        bugs = [] if case == "healthy" else ["--bug", case]
        t0 = time.monotonic()
        host = subprocess.Popen(_cli("host", "--port", port, "--profile", profile, "--baud", str(baud),
                                     "--app-id", str(APP_ID), "--key-env", KEY_ENV, "--yes", "--seed", str(seed),
                                     "--seconds", str(seconds), *bugs),
                                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
        favoured = favour(host.pid) and favoured   # so does the host: the computer it runs on is not the tap's
        host_err = host.communicate(timeout=120)[1]
        host_s = time.monotonic() - t0
        time.sleep(RELEASE_WAIT_S if case == "no-release" else 0.3)
        tap_status = _stop(tap, signal.SIGINT)
        out, err = tap.communicate()
    finally:
        for p in (host, tap, sim):
            if p is not None and p.poll() is None:
                _stop(p, 15)
    result = {"case": case, "seed": seed, "host_status": host.returncode, "host_stderr": host_err[-2000:],
              "favoured": favoured,
              "host_s": round(host_s, 2), "tap_status": tap_status, "tap_stdout": out[-4000:],
              "tap_stderr": err[-2000:], "capture": str(capture)}
    try:
        result["summary"] = json.loads(summary.read_text())
    except (OSError, ValueError) as e:
        result["summary"] = {"error": str(e), "checks": []}
    return result


def failed_checks(summary: dict) -> list[str]:
    return [c["id"] for c in summary.get("checks", []) if c["status"] in ("fail", "error")]


def judged_right(case: str, result: dict) -> bool:
    """Healthy: the host's session ran and the tap found nothing. A bug: the
    check it names failed, and no other. The tap exits 130: it was stopped
    by SIGINT, its usual end."""
    failed = failed_checks(result["summary"])
    if result["host_status"] != 0 or result["tap_status"] != 130:
        return False
    return failed == ([] if case == "healthy" else [BUGS[case][1]])


def measure(runs: int, log, busy_per_core: int = 2, cases: tuple[str, ...] = CASES) -> dict:
    """`runs` seeded sessions of each case, one at a time, beside busy loops."""
    out: dict = {"runs": runs, "baud": BAUD, "cases": {}}
    delays: dict[str, list[float]] = {}   # direction -> each session's p99 of the tap's forwarding delay, ms
    favoured_all = True
    with BusyLoops(busy_per_core) as busy, tempfile.TemporaryDirectory(prefix="osdkc-tap-bench-") as tmp:
        for case in cases:
            right, wrong = 0, []
            for seed in range(1, runs + 1):
                r = run_session(case, seed, Path(tmp) / f"{case}-{seed}")
                if judged_right(case, r):
                    right += 1
                else:
                    wrong.append({"seed": seed, "host": r["host_status"], "tap": r["tap_status"],
                                  "failed": failed_checks(r["summary"]),
                                  "host_said": r["host_stderr"].strip().splitlines()[-1:],
                                  "tap_said": r["tap_stderr"].strip().splitlines()[-2:]})
                favoured_all = favoured_all and r["favoured"]
                for name, m in r["summary"].get("meta", {}).items():
                    if name.endswith("forwarding delay p99 (ms)"):
                        delays.setdefault(name.split(" forwarding")[0], []).append(m)
            out["cases"][case] = {"caught_by": "nothing fails" if case == "healthy" else BUGS[case][1],
                                  "right": right, "wrong": wrong}
            log(f"tap: {case}: {right}/{runs} right")
        try:
            load = os.getloadavg()[0]
        except OSError:
            load = None
        out["load"] = {"busy_loops": busy.count, "cores": os.cpu_count() or 1,
                       "load_average_1min_at_end": None if load is None else round(load, 2),
                       "simulator_and_host_nice": SIM_NICE if favoured_all else 0}
    out["forwarding_delay_p99_ms"] = {d: {"median": sorted(v)[len(v) // 2], "max": max(v)} for d, v in delays.items()}
    out["ok"] = all(not c["wrong"] for c in out["cases"].values())
    return out


def markdown(result: dict) -> str:
    load = result["load"]
    rows = [f"Beside {load['busy_loops']} busy loops on {load['cores']} cores (load average "
            f"{load['load_average_1min_at_end']} at the end; the simulator and the host, which stand in for "
            f"machines of their own, at nice {load['simulator_and_host_nice']}, the tap at the busy loops' 0), "
            f"{result['runs']} seeded sessions of each at {result['baud']} baud:", "",
            "| host | the tap must | runs | right |", "|---|---|---|---|"]
    for case, c in result["cases"].items():
        must = "find nothing" if case == "healthy" else f"fail `{c['caught_by']}` and nothing else"
        rows.append(f"| {case} | {must} | {result['runs']} | {c['right']} |")
    rows += ["", "The tap's forwarding delay (from its read() returning to the bytes written to the other end), "
             "p99 of each session, over all sessions:", "", "| direction | median of the p99s, ms | worst p99, ms |",
             "|---|---|---|"]
    for d, v in result["forwarding_delay_p99_ms"].items():
        rows.append(f"| {d} | {v['median']} | {v['max']} |")
    return "\n".join(rows) + "\n"
