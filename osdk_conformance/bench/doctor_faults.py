"""The faults the doctor must tell apart, each as the simulator (or this host)
makes it, with the one finding a diagnosis must name and no other. The
tests run each once; `osdkc bench --only doctor` runs each many times over
seeds and publishes the table (docs/DOCTOR.md)."""
from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Iterator

KEY = "ab" * 32
OTHER_KEY = "cd" * 32
KEY_ENV = "OSDK_DOCTOR_KEY"


@dataclass(frozen=True)
class Fault:
    sim: tuple[str, ...]            # osdkc sim arguments (the seed is added per run)
    doctor: tuple[str, ...] = ()    # osdkc doctor arguments
    expect: str = ""                # the one problem the diagnosis must name ("": none, the link works)
    host: str = ""                  # a fault of this host rather than of the line: "busy", "console", "permission"
    key: str | None = None          # the key the doctor's --key-env holds


FAULTS: dict[str, Fault] = {
    "healthy": Fault(()),
    "baud": Fault(("--baud", "921600"), ("--baud", "230400"), "link.baud"),
    "baud_scan": Fault(("--baud", "115200"), (), ""),   # no --baud: the scan finds it, and the link works
    "unusual_baud": Fault(("--baud", "57600"), (), "link.baud"),   # bytes, and no frame at any usual rate
    "encrypted_no_key": Fault(("--encrypt",), (), "link.encryption"),
    "wrong_key": Fault(("--encrypt",), ("--key-env", KEY_ENV), "link.encryption", key=OTHER_KEY),
    "wrong_profile": Fault(("--profile", "m100-fw3.1"), ("--profile", "a3-fw3.1"), "link.profile"),
    "noise": Fault(("--noise", "0.05"), (), "line.health"),
    "deaf": Fault(("--deaf",), (), "fc.deaf"),
    "silent_until_activated": Fault(("--silent-until-activated",), (), "fc.broadcast"),
    "loopback": Fault(("--loopback",), (), "link.loopback"),
    "split_baud": Fault(("--baud", "230400", "--rx-baud", "115200"), (), "fc.rx_baud"),
    "activation_refused": Fault(("--app-id", "1234"), ("--app-id", "999"), "fc.activation"),
    "silent_then_activated": Fault(("--silent-until-activated", "--app-id", "1234"), ("--app-id", "1234"), ""),
    "port_busy": Fault((), (), "port.busy", host="busy"),
    "console": Fault((), (), "port.console", host="console"),
    "permission": Fault((), (), "port.permission", host="permission"),
}


@contextmanager
def simulator(args: tuple[str, ...], env: dict | None = None) -> Iterator[str]:
    """`osdkc sim ARGS` on a pseudo-terminal; yields its path. Unlike
    sim.simulator.spawned this process does not hold the terminal open: a
    doctor must find no other program on a healthy port."""
    proc = subprocess.Popen([sys.executable, "-m", "osdk_conformance.cli", "sim", *args], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=env)
    try:
        path = proc.stdout.readline().strip()
        if not path:
            raise RuntimeError("osdkc sim did not start: " + proc.stderr.read().strip())
        yield path
    finally:
        proc.terminate()
        try:
            proc.wait(5)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


@contextmanager
def holder(path: str, program: str) -> Iterator[int]:
    """Another program with the port open: `program` is the name the kernel
    gives it (a symlink to this interpreter under that name). A console
    writes a login prompt, as agetty does."""
    with tempfile.TemporaryDirectory(prefix="osdk-holder-") as tmp:
        exe = Path(tmp) / program
        exe.symlink_to(sys.executable)
        code = ("import os, sys, time\nfd = os.open(sys.argv[1], os.O_RDWR | os.O_NOCTTY)\n"
                + ("os.write(fd, b'\\r\\nDebian GNU/Linux 12 fc ttyS0\\r\\n\\r\\nfc login: ')\n" if program == "agetty"
                   else "")
                + "print('ready', flush=True)\ntime.sleep(120)\n")
        proc = subprocess.Popen([str(exe), "-c", code, path], stdout=subprocess.PIPE, text=True)
        try:
            proc.stdout.readline()
            yield proc.pid
        finally:
            proc.kill()
            proc.wait()


def doctor_command(path: str, fault: Fault) -> list[str]:
    return [sys.executable, "-m", "osdk_conformance.cli", "doctor", "--port", path, "--json", *fault.doctor]


def run_fault(name: str, seed: int, timeout: float = 90) -> tuple[int, dict, float]:
    """One diagnosis of fault `name`: (exit status, the JSON diagnosis, seconds)."""
    import json

    fault = FAULTS[name]
    env = {**os.environ, KEY_ENV: fault.key or KEY, "OSDK_SIM_KEY": KEY}
    sim_args = ("--seed", str(seed), *fault.sim)
    if "--encrypt" in sim_args:
        sim_args = (*sim_args, "--key-env", "OSDK_SIM_KEY")
    with simulator(sim_args, env) as path:
        cmd = doctor_command(path, fault)
        t0 = time.monotonic()
        if fault.host == "permission":
            proc = _unprivileged(cmd, path, env, timeout)
        elif fault.host:
            with holder(path, "agetty" if fault.host == "console" else "sleeper"):
                proc = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=timeout)
        else:
            proc = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=timeout)
        seconds = time.monotonic() - t0
    try:
        diagnosis = json.loads(proc.stdout)
    except ValueError:
        diagnosis = {"error": (proc.stdout + proc.stderr)[-2000:]}
    return proc.returncode, diagnosis, seconds


def _unprivileged(cmd: list[str], path: str, env: dict, timeout: float) -> subprocess.CompletedProcess:
    """The doctor as a user who may not open the port. As root: the doctor
    in a child that gives up root first (to nobody, in no group), as a user
    outside the dialout group is. Otherwise: the port's mode taken away."""
    if os.geteuid() != 0:
        mode = os.stat(path).st_mode
        os.chmod(path, 0)
        try:
            return subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=timeout)
        finally:
            os.chmod(path, mode)

    # the interpreter's own files may be out of nobody's reach (a Python under /root): the child loads
    # what the doctor needs, then gives up root before the command line is read
    code = ("import os, sys\nfrom osdk_conformance.cli import main, build_parser\nbuild_parser(sys.argv[1:])\n"
            "import osdk_conformance.doctor.command, osdk_conformance.doctor.diagnose\n"
            "from osdk_conformance.core.rules import default_rules\ndefault_rules()\n"
            "os.setgroups([]); os.setgid(65534); os.setuid(65534)\nsys.exit(main(sys.argv[1:]))\n")
    return subprocess.run([sys.executable, "-c", code, *cmd[3:]], capture_output=True, text=True, env=env,
                          timeout=timeout)


def judged_right(name: str, status: int, diagnosis: dict) -> bool:
    """The diagnosis names the fault's finding as its problem, and no other; a healthy link exits 0."""
    fault = FAULTS[name]
    problems = [f["id"] for f in diagnosis.get("findings", []) if f["verdict"] == "problem"]
    if not fault.expect:
        return status == 0 and not problems
    return status == 1 and problems == [fault.expect]



def measure(runs: int, log, names: tuple[str, ...] = tuple(FAULTS)) -> dict:
    """`runs` seeded diagnoses of each fault, one at a time: how many named
    the fault and no other, what the others said, and the time to a diagnosis."""
    out: dict = {"runs": runs, "faults": {}}
    for name in names:
        right, wrong, times = 0, [], []
        for seed in range(1, runs + 1):
            status, diagnosis, seconds = run_fault(name, seed)
            times.append(seconds)
            if judged_right(name, status, diagnosis):
                right += 1
            else:
                problems = [f["id"] for f in diagnosis.get("findings", []) if f["verdict"] == "problem"]
                wrong.append({"seed": seed, "exit": status, "problems": problems,
                              **({"error": diagnosis["error"]} if "error" in diagnosis else {})})
        times.sort()
        out["faults"][name] = {"expect": FAULTS[name].expect or "link works", "right": right, "wrong": wrong,
                               "median_s": round(times[len(times) // 2], 2), "max_s": round(times[-1], 2)}
        log(f"doctor: {name}: {right}/{runs} right, median {times[len(times) // 2]:.1f} s, max {times[-1]:.1f} s")
    out["ok"] = all(not f["wrong"] for f in out["faults"].values())
    return out


def markdown(result: dict) -> str:
    rows = ["| fault | diagnosis it must give | runs | right | median s | max s |", "|---|---|---|---|---|---|"]
    for name, f in result["faults"].items():
        rows.append(f"| {name} | {f['expect']} | {result['runs']} | {f['right']} | {f['median_s']} | {f['max_s']} |")
    return "\n".join(rows) + "\n"
