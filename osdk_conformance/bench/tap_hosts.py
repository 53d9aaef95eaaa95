"""Sessions of `osdkc host` through `osdkc tap` to `osdkc sim`: a healthy
host must pass every check, and a host with a planted bug (sim/host_bugs.py)
must fail the check that bug names. The tests run each once;
`osdkc bench --only tap` runs each over many seeds, on a saturated machine
(two busy loops per core), and publishes the table in docs/TAP.md."""
from __future__ import annotations

import json
import os
import select
import signal
import subprocess
import sys
import tempfile
import time
import tty
from pathlib import Path

from osdk_conformance._construct.payload import osdk_payload
from osdk_conformance.bench import ycable
from osdk_conformance.bench.reliability import BusyLoops
from osdk_conformance.bench.stand_in import SIM_NICE, favour
from osdk_conformance.core.wire import encode
from osdk_conformance.core.stats import percentile
from osdk_conformance.reference.values import broadcast_data, items
from osdk_conformance.sim.host_bugs import BUGS

KEY = "ab" * 32
KEY_ENV = "OSDK_TAP_BENCH_KEY"
APP_ID = 1234567
RELEASE_WAIT_S = 2.5   # a host that ends holding control must be silent this long before the tap stops (its grace: 2 s)
CASES = ("healthy", *BUGS)
# Through a Y-cable too: the hosts whose verdict hangs on the order of the two lines (an ACK and the
# command around it) or on their timing
PASSIVE_CASES = ("healthy", "no-control", "wrong-session", "retry-storm", "slow-cadence")
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
                baud: int = BAUD, passive: bool = False) -> dict:
    """One session of `case` ("healthy" or a bug name): the host's exit
    status, the tap's, its summary JSON and where its capture is. The tap
    relays between the host and the simulator, or (`passive`) listens to the
    two lines of a Y-cable between them (bench/ycable.py)."""
    env = {**os.environ, KEY_ENV: KEY}
    work.mkdir(parents=True, exist_ok=True)
    sim = subprocess.Popen(_cli("sim", "--profile", profile, "--app-id", str(APP_ID), "--key-env", KEY_ENV,
                                "--seed", str(seed), "--baud", str(baud)),
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    tap = host = cable = None
    lost: dict = {}
    try:
        favoured = favour(sim.pid)   # it stands in for a flight controller, which has a CPU of its own
        fc = _first_line(sim, "osdkc sim")
        summary, capture = work / "tap.json", work / "tap.pcapng"
        if passive:
            cable, ports = ycable.spawn(fc, baud)
            where = ["--listen-host-tx", ports["host_tx"], "--listen-fc-tx", ports["fc_tx"]]
        else:
            where = ["--fc", fc]
        tap = subprocess.Popen(_cli("tap", *where, "--profile", profile, "--baud", str(baud), "-q",
                                    "--capture", str(capture),
                                    "--summary-json", str(summary), "--html", str(work / "tap.html"),
                                    "--junit", str(work / "tap.xml")),
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
        if passive:   # its first words on stderr come as it starts to listen
            if not tap.stderr.readline():
                raise RuntimeError(f"osdkc tap did not start: {tap.communicate()[0].strip()}")
            port = ports["host"]
        else:
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
        if cable is not None:
            lost = ycable.stop(cable)
    result = {"case": case, "seed": seed, "mode": "passive" if passive else "relay",
              "host_status": host.returncode, "host_stderr": host_err[-2000:], "favoured": favoured,
              "host_s": round(host_s, 2), "tap_status": tap_status, "tap_stdout": out[-4000:],
              "tap_stderr": err[-2000:], "capture": str(capture)}
    if passive:   # bytes the Y-cable's line between host and FC lost: the stand-in fell behind, not the pair
        result["cable lost bytes"] = lost
    try:
        result["summary"] = json.loads(summary.read_text())
    except (OSError, ValueError) as e:
        result["summary"] = {"error": str(e), "checks": []}
    return result


LATENCY_PROBES = 2000


def _through(write_fd: int, read_fd: int, frame: bytes) -> float:
    """Seconds from writing `frame` on one side until all of it is read on the other."""
    t0 = time.perf_counter()
    os.write(write_fd, frame)
    got = 0
    while got < len(frame):
        ready, _, _ = select.select([read_fd], [], [], 5.0)
        if not ready:
            raise RuntimeError("a probe did not come through within 5 s")
        got += len(os.read(read_fd, 65536))
    return time.perf_counter() - t0


def measure_latency(probes: int = LATENCY_PROBES, profile: str = "m100-fw3.1") -> dict:
    """What the tap adds to a byte's way, end to end: full broadcast frames
    written into a pseudo-terminal the tap reads as the flight controller's
    port, timed until they come out of the tap's pseudo-terminal for the
    host, and the host's way back; against the same frames through a
    pseudo-terminal alone. 100 frames a second, as a broadcast at 100 Hz."""
    data = broadcast_data(profile, list(items(profile)), {})
    frame = encode(cmd_set=0x02, cmd_id=0x00, value=osdk_payload(0x02, 0x00, False, profile).build(
        {"body": {"data": data}}))
    fc_m, fc_s, fc_path = ycable.raw_pty()
    direct_m, direct_s, _ = ycable.raw_pty()
    tap = subprocess.Popen(_cli("tap", "--fc", fc_path, "--profile", profile, "--baud", str(BAUD), "--no-capture",
                                "-q"), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    host = -1
    try:
        port = _first_line(tap, "osdkc tap")
        host = os.open(port, os.O_RDWR | os.O_NOCTTY)
        tty.setraw(host)
        out: dict[str, list[float]] = {"direct": [], "fc to host": [], "host to fc": []}
        for n in range(probes):
            out["direct"].append(_through(direct_m, direct_s, frame))
            out["fc to host"].append(_through(fc_m, host, frame))
            if n % 10 == 0:   # a host sends less: a command for every tenth frame
                out["host to fc"].append(_through(host, fc_m, frame))
            time.sleep(0.01)
    finally:
        if host >= 0:
            os.close(host)
        _stop(tap, signal.SIGINT)
        for fd in (fc_m, fc_s, direct_m, direct_s):
            os.close(fd)

    def ms(v: list[float], p: float) -> float:
        return round(1000 * percentile(v, p), 3)

    return {"frame_bytes": len(frame), "probes": probes,
            **{way: {"p50_ms": ms(v, 50), "p99_ms": ms(v, 99), "max_ms": ms(v, 100)} for way, v in out.items()}}


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


def measure(runs: int, log, busy_per_core: int = 2, cases: tuple[str, ...] = CASES,
            passive_cases: tuple[str, ...] = PASSIVE_CASES) -> dict:
    """`runs` seeded sessions of each case through a relaying tap, and of
    each passive case through a Y-cable, one at a time, beside busy loops."""
    out: dict = {"runs": runs, "baud": BAUD, "cases": {}, "latency": {"idle": measure_latency()}}
    log(f"tap: latency idle: {out['latency']['idle']}")
    delays: dict[str, list[float]] = {}   # direction -> each session's p99 of the tap's forwarding delay, ms
    favoured_all = True
    with BusyLoops(busy_per_core) as busy, tempfile.TemporaryDirectory(prefix="osdkc-tap-bench-") as tmp:
        out["latency"]["saturated"] = measure_latency()
        log(f"tap: latency saturated: {out['latency']['saturated']}")
        sessions = [(case, False) for case in cases] + [(case, True) for case in passive_cases]
        for case, passive in sessions if runs else ():
            right, wrong = 0, []
            for seed in range(1, runs + 1):
                r = run_session(case, seed, Path(tmp) / f"{case}-{seed}{'-passive' if passive else ''}",
                                passive=passive)
                if judged_right(case, r):
                    right += 1
                else:
                    wrong.append({"seed": seed, "host": r["host_status"], "tap": r["tap_status"],
                                  "failed": failed_checks(r["summary"]),
                                  "host_said": r["host_stderr"].strip().splitlines()[-1:],
                                  "tap_said": r["tap_stderr"].strip().splitlines()[-2:],
                                  **({"cable lost bytes": r["cable lost bytes"]} if passive else {})})
                favoured_all = favoured_all and r["favoured"]
                for name, m in r["summary"].get("meta", {}).items():
                    if name.endswith("forwarding delay p99 (ms)"):
                        delays.setdefault(name.split(" forwarding")[0], []).append(m)
            mode = "passive" if passive else "relay"
            out["cases"][f"{case} ({mode})" if passive else case] = {
                "mode": mode, "host": case, "caught_by": "nothing fails" if case == "healthy" else BUGS[case][1],
                "right": right, "wrong": wrong}
            log(f"tap: {case} ({mode}): {right}/{runs} right")
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
    rows = []
    if result["cases"]:
        rows = [f"Beside {load['busy_loops']} busy loops on {load['cores']} cores (load average "
                f"{load['load_average_1min_at_end']} at the end; the simulator and the host, which stand in for "
                f"machines of their own, at nice {load['simulator_and_host_nice']}, the tap at the busy loops' 0), "
                f"{result['runs']} seeded sessions of each at {result['baud']} baud:", "",
                "| host | tap | the tap must | runs | right |", "|---|---|---|---|---|"]
        for c in result["cases"].values():
            must = "find nothing" if c["host"] == "healthy" else f"fail `{c['caught_by']}` and nothing else"
            rows.append(f"| {c['host']} | {c['mode']} | {must} | {result['runs']} | {c['right']} |")
        rows.append("")
    rows += [f"What the tap adds, end to end: a whole broadcast frame "
             f"({result['latency']['idle']['frame_bytes']} bytes) written into the flight controller's "
             "pseudo-terminal until all of it is read from the host's, 100 frames a second, against the same "
             "frame through one pseudo-terminal alone (`direct`):", "",
             "| machine | way | p50 ms | p99 ms | max ms |", "|---|---|---|---|---|"]
    for load_name, lat in result["latency"].items():
        for way in ("direct", "fc to host", "host to fc"):
            v = lat[way]
            rows.append(f"| {load_name} | {way} | {v['p50_ms']} | {v['p99_ms']} | {v['max_ms']} |")
    if result["forwarding_delay_p99_ms"]:
        rows += ["", "The tap's own forwarding delay (from its read() returning to the bytes written to the other "
                 "end), p99 of each session, over all sessions:", "",
                 "| direction | median of the p99s, ms | worst p99, ms |", "|---|---|---|"]
        for d, v in result["forwarding_delay_p99_ms"].items():
            rows.append(f"| {d} | {v['median']} | {v['max']} |")
    return "\n".join(rows) + "\n"
