"""`osdkc kit`: the conformance kit's run over what this repository bundles.

It checks the specification (spec check), runs the outside worked examples
through every bundled implementation (the Construct encoder, the Construct
decoder behind `osdkc decode`, the Kaitai-generated parser), replays every
golden vector against each bundled implementation in every language with
the conformance runner (reports in reports/; the status section of
generated/README.md is rendered from that run), and proves the suite bites
with the mutation check. Last, it runs the serial acceptance suite against
the simulated flight controller over a pseudo-terminal (report in
reports/device.html, capture in reports/device.pcapng), and fuzzes it over
one (`osdkc fuzz --port`: a healthy simulator survives every case kind; report
in reports/fuzz.html, capture in reports/fuzz.pcapng), and the link doctor
must find that link healthy (`osdkc doctor`, with the baud rate and profile
to find); last, the reference host (`osdkc host`) runs a session through the
tap (`osdkc tap`), which must pass it (reports in reports/tap/). With
OSDK_SRC naming a
checkout of DJI's Onboard-SDK, DJI's own host stack runs a whole session
against the simulator too (`osdkc sdk host-test`).
"""
from __future__ import annotations

import argparse
import os
from pathlib import Path
from typing import Callable, Sequence

from kaitaistruct import BytesIO, KaitaiStream
from osdk_conformance._construct.frame import build_frame
from osdk_conformance._kaitai.osdk_frame import OsdkFrame
from osdk_conformance._kaitai.osdk_payload import OsdkPayload

from osdk_conformance.bench import tap_hosts
from osdk_conformance.core import model
from osdk_conformance.core.errors import UsageError, exit_status_of_signal
from osdk_conformance.core.paths import CHECKOUT, REPORTS
from osdk_conformance.core.rules import profile_names
from osdk_conformance.device.acceptance import add_arguments as device_arguments, run_device
from osdk_conformance.device.fuzz_command import add_arguments as fuzz_arguments, run_fuzz
from osdk_conformance.doctor.command import add_arguments as doctor_arguments, run_doctor
from osdk_conformance.harness import status_readme
from osdk_conformance.harness.runner import ALL, add_arguments as run_arguments, run_command
from osdk_conformance.harness.selftest import add_arguments as selftest_arguments, run_selftest
from osdk_conformance.reference.decode import decode_events
from osdk_conformance.reference.worked_examples import WORKED_FRAMES, WorkedFrame, lookup
from osdk_conformance.sdk.host import add_arguments as host_test_arguments, run_host_test
from osdk_conformance.sim.simulator import spawned
from osdk_conformance.traceability.check import run_spec_check
from osdk_conformance.traceability.trace import add_seed_argument


def _mismatches(frame_model: dict, wf: WorkedFrame) -> list[str]:
    out = []
    for path, want in wf.expect.items():
        try:
            got = lookup(frame_model, path)
        except (KeyError, TypeError):
            out.append(f"{path}: missing")
            continue
        if got != want:
            out.append(f"{path}: {model.dumps(got)} != {model.dumps(want)}")
    return out


def _construct_encode(wf: WorkedFrame) -> list[str]:
    built = build_frame(**wf.build).hex()
    return [] if built == wf.hex else [f"built {built}"]


def _construct_decode(wf: WorkedFrame) -> list[str]:
    events = list(decode_events([bytes.fromhex(wf.hex)], wf.profile))
    if len(events) != 1 or events[0]["kind"] != "frame":
        return [f"decoded to {model.dumps(events)}"]
    return _mismatches(events[0]["frame"], wf)


def _kaitai_decode(wf: WorkedFrame) -> list[str]:
    profile = OsdkPayload.Profile[wf.profile.replace("-", "_").replace(".", "_")]
    parsed = OsdkFrame(profile, KaitaiStream(BytesIO(bytes.fromhex(wf.hex))))
    return _mismatches(model.from_kaitai(parsed), wf)


IMPLEMENTATIONS: list[tuple[str, Callable[[WorkedFrame], list[str]]]] = [
    ("construct encoder", _construct_encode),
    ("construct decoder", _construct_decode),
    ("kaitai-python decoder", _kaitai_decode),
]




def _command(name: str, add_arguments: Callable, run: Callable, *argv: str) -> int:
    """Run one osdkc command the way the command line would, through its own
    argument parser (so its defaults and checks apply) and run function."""
    print(f"== osdkc {name} {' '.join(argv)}".rstrip(), flush=True)
    parser = argparse.ArgumentParser(prog=f"osdkc {name}")
    add_arguments(parser, profile_names())
    try:
        return run(parser.parse_args(list(argv)))
    except UsageError as e:
        print(f"osdkc: {e}")
        return 2


def _acceptance_on_simulator(reports: Path) -> int:
    """`osdkc device --active` against `osdkc sim` on a pseudo-terminal: what
    a bench acceptance run of a real flight controller does, without one."""
    app_id = "1234"  # what the simulated FC accepts, as a configured app would be
    print("== osdkc sim --profile a3-fw3.1 --pty  +  osdkc device --active", flush=True)
    try:
        with spawned("--profile", "a3-fw3.1", "--app-id", app_id, new_session=True) as (url, _):
            return _command("device", device_arguments, run_device, "--port", url, "--profile", "a3-fw3.1", "--duration", "5", "--active",
                          "--app-id", app_id, "--quiet", "--capture", str(reports / "device.pcapng"),
                          "--html", str(reports / "device.html"), "--junit", str(reports / "device.xml"))
    except UsageError as e:
        print(f"  {e}")
        return 1


FUZZ_CASES = 600   # two rounds of every case kind and more: about 3 s at 921600 baud


def _fuzz_on_simulator(reports: Path) -> int:
    """`osdkc fuzz --port` against a healthy `osdkc sim`: it must survive every case."""
    print("== osdkc sim --profile a3-fw3.1 --pty  +  osdkc fuzz --port", flush=True)
    try:
        with spawned("--profile", "a3-fw3.1", new_session=True) as (url, _):
            return _command("fuzz", fuzz_arguments, run_fuzz, "--port", url, "--profile", "a3-fw3.1", "--baud",
                            "921600", "--cases", str(FUZZ_CASES), "--seed", "1", "--quiet",
                            "--capture", str(reports / "fuzz.pcapng"), "--findings-dir", str(reports / "fuzz-findings"),
                            "--html", str(reports / "fuzz.html"), "--junit", str(reports / "fuzz.xml"))
    except UsageError as e:
        print(f"  {e}")
        return 1


def _doctor_on_simulator() -> int:
    """`osdkc doctor` against a healthy `osdkc sim` at a baud rate it is not told: it must find it and the
    profile, and say the link works."""
    print("== osdkc sim --profile m100-fw3.1 --baud 921600 --pty  +  osdkc doctor", flush=True)
    try:
        with spawned("--profile", "m100-fw3.1", "--baud", "921600", new_session=True) as (url, _):
            return _command("doctor", doctor_arguments, run_doctor, "--port", url)
    except UsageError as e:
        print(f"  {e}")
        return 1


def _tap_on_simulator(reports: Path) -> int:
    """`osdkc host`, the reference host, through `osdkc tap` to `osdkc sim`: the tap must stay
    transparent (the host's session completes) and find nothing wrong with either side."""
    print("== osdkc sim --profile m100-fw3.1 --baud 921600  +  osdkc tap --fc SIM  +  osdkc host --port TAP",
          flush=True)
    try:
        session = tap_hosts.run_session("healthy", 1, reports / "tap")
    except (OSError, RuntimeError) as e:
        print(f"  {e}")
        return 1
    out = session["tap_stdout"].rstrip().splitlines()
    print("\n".join(line for line in out if not line.startswith(("PASS", "/dev/"))), flush=True)
    if session["host_status"] != 0:
        print(f"  the host's session did not complete (exit {session['host_status']}): "
              f"{session['host_stderr'].strip().splitlines()[-1:]}")
    return 0 if tap_hosts.judged_right("healthy", session) else 1


def add_arguments(p: argparse.ArgumentParser, profiles: Sequence[str] = ()) -> None:
    add_seed_argument(p)
    p.add_argument("--report-dir", default=str(REPORTS), metavar="DIR",
                   help=f"where the reports go (default {REPORTS}); in a checkout the run step also renders "
                        "the status section of generated/README.md from them")


def run_kit(args: argparse.Namespace | None = None) -> int:
    print("== specification")
    failed = 1 if run_spec_check(args) else 0  # args.seed: the trace's seed, if given
    print("== worked frames (PROTOCOL-FACTS section 1)")
    passed = 0
    for wf in WORKED_FRAMES:
        for name, fn in IMPLEMENTATIONS:
            problems = fn(wf)
            print(f"  {'ok  ' if not problems else 'FAIL'}  {name:<22} {wf.name}")
            for p in problems:
                print(f"          {p}")
            passed += not problems
            failed += bool(problems)
    reports = Path(args.report_dir) if args is not None else REPORTS
    try:
        reports.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise UsageError(f"--report-dir {reports}: {e.strerror or e}") from None
    steps: list[tuple[str, Callable[[], int]]] = [
        ("run", lambda: _command("run", run_arguments, run_command, "--impl", ALL, "--report-dir", str(reports))),
        ("selftest", lambda: _command("selftest", selftest_arguments, run_selftest)),
        ("device", lambda: _acceptance_on_simulator(reports)),
        ("fuzz", lambda: _fuzz_on_simulator(reports)),
        ("doctor", _doctor_on_simulator),
        ("tap", lambda: _tap_on_simulator(reports)),
    ]
    if CHECKOUT:   # the firmware is built in a checkout (make setup), not shipped in the package
        steps.insert(1, ("run c-target", lambda: _command(
            "run", run_arguments, run_command, "--impl", "c-target", "--junit", str(reports / "c-target.xml"),
            "--html", str(reports / "c-target.html"), "--summary-json", str(reports / "c-target.json"))))
    if os.environ.get("OSDK_SRC"):   # DJI's own host stack from the user's checkout against the simulator
        steps.append(("sdk host-test", lambda: _command("sdk host-test", host_test_arguments, run_host_test,
                                                        "--osdk", os.environ["OSDK_SRC"])))
    for n, (name, step) in enumerate(steps):
        try:
            status = step()
        except KeyboardInterrupt:  # a Ctrl-C outside the step's own handling (its start, its end)
            status = exit_status_of_signal("SIGINT")
        if status in INTERRUPTED:
            # The step wrote its own partial reports marked interrupted; the
            # later steps do not run, so the reports they left stay as they were.
            print(f"reports: {reports}/")
            later = ", ".join(s for s, _ in steps[n + 1:]) or "none"
            print(f"kit: INTERRUPTED by {INTERRUPTED[status]} during {name}: {passed} passed, {failed} failed "
                  f"before it; not run: {later}")
            return status
        passed += status == 0
        failed += status != 0
        # the status section of the checkout's generated/README.md, from the
        # checkout's own reports only; an installed package is not written to
        if name == "run" and CHECKOUT and reports.resolve() == REPORTS.resolve():
            status_readme.update(reports / "conformance.json")
    print(f"reports: {reports}/")
    print(f"kit: {passed} passed, {failed} failed")
    return 1 if failed else 0


INTERRUPTED = {exit_status_of_signal(name): name for name in ("SIGINT", "SIGTERM")}
