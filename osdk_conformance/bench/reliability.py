"""`osdkc bench --only reliability`: no false FAIL, no missed fault, on a
saturated machine.

The whole measurement runs beside `--busy-per-core` busy-loop processes per
core (default 2: the machine saturated, load about twice the cores; 0 for an
idle machine), stated in the report.

Healthy runs: against a fault-free `osdkc sim` (a fresh one per run, seed =
run number), alternately `osdkc device --active --allow-motion` and a
passive listen. Each must pass, send every command once (no retransmission:
an ACK lost to a race makes the command go out again), and leave the
simulator with control back at the RC and its initial broadcast rates (its
--stats at exit). The device runs with its default limits: a verdict must
not depend on how busy the host is.

Fault runs: every fault kind the simulator injects, with seeds 1..N: the
checks that fault must fail (docs/ACCEPTANCE.md, the simulator's table) fail
in every run.

Fuzz sessions (fuzz_reliability.py, with --fuzz-runs and --bug-runs): the
device fuzzer under the same load, healthy and against each planted bug.

Every run is a pair of child processes, exactly as a user runs them; the
files of a run that went wrong are kept and their directory is printed.
"""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from osdk_conformance.core.capture import read_capture
from osdk_conformance.core.errors import EXIT_INCONCLUSIVE
from osdk_conformance.core.wire import commands_sent
from osdk_conformance.bench import fuzz_reliability, stand_in
from osdk_conformance.bench.stand_in import SIM_NICE
from osdk_conformance.sim.simulator import BEHIND_S

LINE = re.compile(r"^(PASS|FAIL|SKIP|ERROR)\s+(\S+)\s+(.*)$", re.M)
PROFILE, APP_ID = "a3-fw3.1", "1234"
# Short steps, as in the tests' active scenario; the default limits.
# --yes: a child process cannot answer the --allow-motion question.
HEALTHY_DEVICE_ARGS = ("--profile", PROFILE, "--duration", "1", "--active", "--allow-motion", "--yes",
                       "--app-id", APP_ID, "--active-window", "1", "--motion-seconds", "1.2")
PASSIVE_DEVICE_ARGS = ("--profile", PROFILE, "--duration", "2.5")
RUN_TIMEOUT = 120.0

# kind -> (simulator options, extra device options, checks that must fail, seconds of listening)
FAULT_CASES: dict[str, tuple[tuple[str, ...], tuple[str, ...], tuple[str, ...], float]] = {
    "noise": (("--noise", "0.05"), (), ("link.framing",), 2.5),
    "bitflip": (("--bitflip", "0.05"), (), ("link.crc",), 2.5),
    "drop_bytes": (("--drop-bytes", "0.05"), (), ("link.short_frames",), 2.5),
    "truncate": (("--truncate", "0.05"), (), ("link.short_frames",), 2.5),
    "bad_crc": (("--bad-crc", "0.05"), (), ("link.crc", "stream.sequence"), 2.5),
    "duplicate": (("--duplicate", "0.05"), (), ("stream.duplicates",), 2.5),
    "jitter": (("--jitter", "80"), (), ("stream.jitter",), 2.5),
    "rate_drift": (("--rate-drift", "0.25"), (), ("stream.rates",), 2.5),
    "implausible": (("--implausible",), (), ("values.quaternion_norm", "values.gps_health", "values.battery",
                                             "values.rc_channels", "values.flight_status", "values.time_stamp"), 2.5),
    "wrong_profile": (("--wrong-profile", "m100-fw3.1"), (), ("decode.profile", "decode.frames"), 2.5),
    # the simulator's clock starts about a second before the device listens: the device must have the port
    # open before the unplug, and listen long enough after the stall starts (at least 2.5 s of silence)
    "stall": (("--stall-at", "2.5"), (), ("link.stall",), 5.0),
    "unplug": (("--unplug-at", "4", "--unplug-for", "0.8"), (), ("link.connection",), 4.5),
    "baud": (("--baud", "921600"), ("--baud", "115200"), ("link.baud",), 1.5),
}


def _log(text: str) -> None:
    print(f"osdkc bench: reliability: {text}", file=sys.stderr, flush=True)


STAND_IN_BEHIND = ("the simulator itself fell more than {:g} s behind its schedule and skipped {} frames: "
                   "no healthy stand-in for a flight controller")


def _pair(name: str, tmp: Path, sim_args: tuple[str, ...], dev_args: tuple[str, ...]) -> dict:
    """One `osdkc sim` and one `osdkc device` against it: exit status, checks, simulator statistics."""

    run_dir = tmp / name
    cap = run_dir / "capture.pcapng"
    extra = ("--link", str(run_dir / "tty")) if "--unplug-at" in sim_args else ()
    r = stand_in.run(run_dir, (*sim_args, *extra), lambda url, _: ["device", "--port", url, "--capture", str(cap),
                                                                    *dev_args],
                     RUN_TIMEOUT, "device-output.txt")
    checks = {m.group(2): m.group(1) for m in LINE.finditer(r.out)}
    return {"name": name, "dir": run_dir, "code": r.code, "checks": checks, "stats": r.stats, "capture": cap,
            "traceback": "Traceback" in r.out, "sim_favoured": r.favoured}


def retransmissions(capture: Path) -> int:
    """Commands that went out more than once with one SEQ (session 2: ACK wanted)."""

    seen, again = set(), 0
    for op in commands_sent(read_capture(capture).records):
        if op.session == 2 and not op.is_ack:
            again += op.seq in seen
            seen.add(op.seq)
    return again


def _healthy_verdict(r: dict) -> list[str]:
    """What went wrong in a healthy run ([] when nothing). An INCONCLUSIVE run
    (exit 3: the judge's host too busy to read the port in time, nothing
    failed) is not wrong, and is counted apart (r["inconclusive"])."""
    r["inconclusive"] = r["code"] == EXIT_INCONCLUSIVE
    bad = [f"exit {r['code']}"] if r["code"] not in (0, EXIT_INCONCLUSIVE) else []
    bad += [f"{cid} {status}" for cid, status in r["checks"].items() if status in ("FAIL", "ERROR")]
    if r["traceback"]:
        bad.append("traceback")
    st = r["stats"]
    if not st:
        bad.append("the simulator left no statistics")
    else:
        if st.get("control") != "rc" or st.get("control_pending"):
            bad.append(f"simulator left with control {st.get('control')} (pending {st.get('control_pending')})")
        if st.get("rates") != st.get("initial_rates"):
            bad.append("simulator left with other broadcast rates than it started with")
        if st.get("broadcast_skipped_behind"):
            bad.append(STAND_IN_BEHIND.format(BEHIND_S, st["broadcast_skipped_behind"]))
    if r["capture"].exists():
        n = retransmissions(r["capture"])
        r["retransmissions"] = n
        if n:
            bad.append(f"{n} command(s) retransmitted")
    else:
        bad.append("no capture")
    # nothing went wrong but the simulated FC starving: the judge's verdict on it is no measure of the judge
    r["stand_in_only"] = len(bad) == 1 and bool(st and st.get("broadcast_skipped_behind"))
    return bad


class BusyLoops:
    """`per_core` busy-loop processes per core while the with-block runs."""

    def __init__(self, per_core: int) -> None:
        self.count = per_core * (os.cpu_count() or 1)

    def __enter__(self):
        self.procs = [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(self.count)]
        return self

    def __exit__(self, *exc):
        for p in self.procs:
            p.kill()
            p.wait()


def _batch(jobs: int, tasks: list) -> list[dict]:
    with ThreadPoolExecutor(max_workers=jobs) as pool:
        return list(pool.map(lambda t: t(), tasks))


def measure(runs: int, fault_runs: int, busy_per_core: int, jobs: int, kinds: list[str] | None = None,
            fuzz_runs: int = 0, bug_runs: int = 0) -> dict:
    t0 = time.monotonic()
    with BusyLoops(busy_per_core) as busy:
        out = _measure(runs, fault_runs, jobs, kinds, f"{busy.count} busy-loop processes")
        if fuzz_runs or bug_runs:
            tmp = Path(tempfile.mkdtemp(prefix="osdkc-reliability-fuzz-"))
            fz = out["fuzz"] = fuzz_reliability.measure(fuzz_runs, bug_runs, tmp, PROFILE,
                                                        lambda tasks: _batch(jobs, tasks), _log)
            if fz["ok"]:
                shutil.rmtree(tmp, ignore_errors=True)
            else:   # the sessions that went wrong kept their files there
                fz["kept_dir"] = str(tmp)
            out["ok"] = out["ok"] and fz["ok"]
            if not runs:   # the simulators' priority is then the fuzz sessions'
                out["simulator_nice"] = SIM_NICE if fz["favoured"] else 0
        out["seconds"] = round(time.monotonic() - t0, 1)
    out["load"] = {"busy_loops_per_core": busy_per_core, "cores": os.cpu_count() or 1,
                   "load_average_1min_at_end": round(os.getloadavg()[0], 2),
                   "simulator_nice": out.pop("simulator_nice", 0)}
    return out


def _measure(runs: int, fault_runs: int, jobs: int, kinds: list[str] | None, beside: str) -> dict:
    t0 = time.monotonic()
    tmp = Path(tempfile.mkdtemp(prefix="osdkc-reliability-"))
    kinds = kinds or list(FAULT_CASES)
    out: dict = {"command": "", "healthy": {"runs": runs, "active": (runs + 1) // 2, "passive": runs // 2,
                                            "device_args": " ".join(HEALTHY_DEVICE_ARGS),
                                            "passive_device_args": " ".join(PASSIVE_DEVICE_ARGS)},
                 "faults": {}}

    def healthy(i: int):
        active = i % 2 == 0

        def one() -> dict:
            r = _pair(f"healthy-{'active' if active else 'passive'}-{i:04d}", tmp,
                      ("--profile", PROFILE, "--app-id", APP_ID, "--seed", str(i)),
                      HEALTHY_DEVICE_ARGS if active else PASSIVE_DEVICE_ARGS)
            r["problems"] = _healthy_verdict(r)
            done = "inconclusive (host too busy)" if r["inconclusive"] else "passed"
            _log(f"{r['name']}: {'; '.join(r['problems']) or done}")   # progress, and numbers if cut short
            return r
        return one

    _log(f"{runs} healthy runs (active and passive in turn), {jobs} at a time, beside {beside}")
    results = _batch(jobs, [healthy(i) for i in range(runs)])
    problems = []
    for r in results:
        bad = r["problems"]
        if bad:
            problems.append({"run": r["name"], "problems": bad, "kept": str(r["dir"])})
        else:
            shutil.rmtree(r["dir"], ignore_errors=True)
    h = out["healthy"]
    out["simulator_nice"] = SIM_NICE if results and all(r["sim_favoured"] for r in results) else 0
    h["inconclusive"] = sum(1 for r in results if r["inconclusive"] and not r["problems"])
    h["passed"] = runs - len(problems) - h["inconclusive"]
    h["stand_in_behind"] = sum(1 for r in results if r.get("stand_in_only"))
    h["false_fails"] = sum(1 for r in results if any(st in ("FAIL", "ERROR") for st in r["checks"].values()))
    h["retransmissions"] = sum(r.get("retransmissions", 0) for r in results)
    h["failures"] = problems
    for kind in kinds if fault_runs else []:
        sim_args, dev_extra, must_fail, seconds = FAULT_CASES[kind]
        _log(f"fault {kind}: {fault_runs} seeded runs")
        tasks = [lambda s=seed, k=kind: _pair(f"fault-{k}-{s:03d}", tmp, ("--profile", PROFILE, "--seed", str(s), *sim_args),
                                               ("--profile", PROFILE, "--duration", f"{seconds:g}", *dev_extra))
                 for seed in range(1, fault_runs + 1)]
        missed = []
        for seed, r in enumerate(_batch(jobs, tasks), start=1):
            undetected = [c for c in must_fail if r["checks"].get(c) != "FAIL"]
            if undetected or r["code"] != 1 or r["traceback"]:
                missed.append({"seed": seed, "not failed": undetected, "exit": r["code"], "kept": str(r["dir"])})
            else:
                shutil.rmtree(r["dir"], ignore_errors=True)
        out["faults"][kind] = {"runs": fault_runs, "detected": fault_runs - len(missed), "must_fail": list(must_fail),
                               "missed": missed}
    out["seconds"] = round(time.monotonic() - t0, 1)
    out["ok"] = not problems and all(not f["missed"] for f in out["faults"].values())
    if out["ok"]:
        shutil.rmtree(tmp, ignore_errors=True)
    else:
        out["kept_dir"] = str(tmp)
    return out


def summary(rel: dict) -> str:
    h = rel["healthy"]
    load = rel.get("load") or {}
    text = (f"beside {load.get('busy_loops_per_core', '?')} busy loops per core (load average "
            f"{load.get('load_average_1min_at_end', '?')} on {load.get('cores', '?')} cores; the simulators at nice "
            f"{load.get('simulator_nice', 0)}, the judge at the busy loops' 0): "
            f"healthy: {h['passed']} of {h['runs']} runs passed ({h['active']} active, {h['passive']} passive), "
            f"{h['inconclusive']} inconclusive (host too busy), {h['false_fails']} with a FAIL, "
            f"{h['retransmissions']} commands retransmitted")
    if h["failures"]:
        text += "; went wrong: " + "; ".join(f"{p['run']}: {', '.join(p['problems'])}" for p in h["failures"][:5])
    faults = rel["faults"]
    if faults:
        runs = {f["runs"] for f in faults.values()}
        text += (f"; faults: {len(faults)} kinds x {'/'.join(map(str, sorted(runs)))} seeds, detected in "
                 f"{sum(f['detected'] for f in faults.values())} of {sum(f['runs'] for f in faults.values())} runs")
        missed = [f"{k} (seeds {', '.join(str(m['seed']) for m in f['missed'])})" for k, f in faults.items() if f["missed"]]
        if missed:
            text += "; missed: " + "; ".join(missed)
    if rel.get("fuzz"):
        text += "; " + fuzz_reliability.summary(rel["fuzz"])
        if rel["fuzz"].get("kept_dir"):
            text += f" (files of the sessions that went wrong: {rel['fuzz']['kept_dir']})"
    if rel.get("kept_dir"):
        text += f"; files of the runs that went wrong: {rel['kept_dir']}"
    return text
