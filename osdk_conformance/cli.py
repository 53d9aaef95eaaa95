"""osdkc: the command line of the OPEN protocol conformance kit.

Each command is a row of COMMANDS: where it lives and the names of its
`add_arguments(parser, profiles)` and run function. Only the module of the
command being run is imported (start-up: `osdkc decode` in a pipeline should
not load the simulator, the harness and the benchmarks), so this is the one
place where the package imports lazily.
"""
from __future__ import annotations

import argparse
import importlib
import importlib.metadata
import os
import signal
import sys
import threading
from dataclasses import dataclass
from typing import Callable, NoReturn, Sequence

from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.paths import where_from


@dataclass(frozen=True)
class Command:
    path: tuple[str, ...]      # ("spec", "trace") is `osdkc spec trace`
    help: str
    module: str                # under osdk_conformance
    run: str                   # the run function: args -> exit status
    arguments: str = "add_arguments"

    def load(self, name: str) -> Callable:
        return getattr(importlib.import_module(f"osdk_conformance.{self.module}"), name)


GROUPS = {
    "spec": "inspect and check the specification",
    "vectors": "check the golden vectors and their coverage of the spec",
    "sdk": "DJI's Onboard-SDK itself against the kit (needs a checkout of it)",
    "wireshark": "the Wireshark dissector generated from the spec",
}

COMMANDS = (
    Command(("decode",), "find and decode frames in a byte stream, one JSON object per line (or the broadcasts "
                         "as a CSV or Parquet table)", "flight.decode_command", "run_decode"),
    Command(("watch",), "a live view of the broadcast: each item's rate and latest values, the link's errors, "
                        "updated in place", "flight.watch_command", "run_watch"),
    Command(("plot",), "draw the flight data of a capture (battery, attitude, velocity, any item) as HTML or SVG",
            "flight.plot_command", "run_plot"),
    Command(("spec", "trace"), "map every seed entry to the spec element that carries it",
            "traceability.trace", "run_trace"),
    Command(("spec", "check"), "compile the .ksy files, validate rules and trace, check generated/",
            "traceability.check", "run_spec_check"),
    Command(("kit",), "run the conformance kit (spec checks and worked examples)", "kit", "run_kit"),
    Command(("run",), "replay the golden vectors against an implementation (conformance/PROTOCOL.md)",
            "harness.runner", "run_command"),
    Command(("vectors", "check"), "schema, manifest hashes, unique ids, and every case against the spec",
            "harness.vectors", "run_vectors", "add_check_arguments"),
    Command(("vectors", "coverage"), "cases per spec rule and errata entry; fails when one has none",
            "harness.vectors", "run_vectors", "add_coverage_arguments"),
    Command(("selftest",), "mutation check: every deliberately broken implementation must fail the vectors",
            "harness.selftest", "run_selftest"),
    Command(("fuzz",), "differential fuzzing of two or more implementations (hypothesis), or of a "
                       "flight controller on a serial port (--port)", "device.fuzz_command", "run_fuzz"),
    Command(("sim",), "simulated flight controller on a pseudo-terminal or TCP port",
            "sim.simulator", "run_sim"),
    Command(("device",), "acceptance suite against a flight controller on a serial port (or a capture)",
            "device.acceptance", "run_device"),
    Command(("doctor",), "diagnose a serial link that does not work: the port, the wiring, the baud rate, "
                         "the profile, encryption, the FC's RX line, activation", "doctor.command", "run_doctor"),
    Command(("tap",), "sit between a host and a flight controller (or listen to both lines) and judge what the "
                      "host sends, the pair's exchange and the FC", "tap.command", "run_tap"),
    Command(("host",), "a whole onboard-computer session against a flight controller (or through a tap), "
                       "healthy or with a planted host bug (--bug)", "host.command", "run_host"),
    Command(("explain",), "what a control mode byte, an ACK code or a frame means, from the spec's tables",
            "explain", "run_explain"),
    Command(("soak",), "benchmark: every item at 100 Hz from osdkc sim over a pty, no frame may be lost",
            "device.soak", "run_soak"),
    Command(("sdk", "host-test"), "build DJI's host stack with our driver, run a whole session "
                                  "against osdkc sim for each profile", "sdk.host", "run_host_test"),
    Command(("sdk", "build"), "build a testee of DJI's own frame layer, broadcast unpacker and encoder "
                              "(prints the testee command last)", "sdk.testee_build", "run_build"),
    Command(("sdk", "test"), "build DJI's SDK as a testee, plain and with ASan/UBSan, and run the vectors "
                             "against both", "sdk.sdk_test", "run_sdk_test"),
    Command(("bench",), "benchmarks: decode speed against an SDK-style C baseline, run, fuzz, soak, device fuzzing",
            "bench.command", "run_bench"),
    Command(("wireshark", "install"), "copy the Wireshark dissector into your personal Lua plugin folder",
            "device.wireshark", "run_install"),
)


class Parser(argparse.ArgumentParser):
    """Reports a bad command line in one line, like every other usage error
    (subcommand parsers are of the same class)."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def _version() -> str:
    try:
        return importlib.metadata.version("osdk-conformance")
    except importlib.metadata.PackageNotFoundError:  # run from a tree that was never installed
        return "unknown version"


class _VersionAction(argparse.Action):
    """--version: also says which decoder `osdkc decode` and the API run (the
    native accelerator or pure Python, and why), which only then is looked up."""

    def __call__(self, parser, namespace, values, option_string=None) -> NoReturn:  # type: ignore[override]
        accel = importlib.import_module("osdk_conformance.reference.accel")  # only for --version (start-up)
        try:
            decoder = accel.describe()
        except UsageError as e:
            decoder = str(e)
        print(f"osdkc {_version()} ({where_from()}; decoder: {decoder})")
        parser.exit(0)


def _selected(argv: Sequence[str]) -> tuple[str, ...]:
    """The command words of a command line: what to load before parsing it."""
    return tuple(a for a in argv if not a.startswith("-"))[:2]


def _subparsers(p: argparse.ArgumentParser, dest: str, metavar: str) -> argparse._SubParsersAction:
    sub = p.add_subparsers(dest=dest, metavar=metavar)
    sub.required = True
    return sub


def build_parser(argv: Sequence[str] | None = None) -> argparse.ArgumentParser:
    """The whole parser, or (given the command line) one whose only complete
    subcommand is the one the command line names."""
    from osdk_conformance.core.rules import profile_names  # only for the command being run (start-up)

    words = None if argv is None else _selected(argv)
    ap = Parser(prog="osdkc",
                description="Specification and conformance kit for the DJI Onboard SDK OPEN serial protocol.")
    ap.add_argument("--version", action=_VersionAction, nargs=0,
                    help="show the version, where the kit runs from and which decoder it uses, and exit")
    top = _subparsers(ap, "command", "COMMAND")
    groups: dict[str, argparse._SubParsersAction] = {}
    for cmd in COMMANDS:
        if len(cmd.path) == 1:
            p = top.add_parser(cmd.path[0], help=cmd.help)
        else:
            group, name = cmd.path
            if group not in groups:
                g = top.add_parser(group, help=GROUPS[group])
                groups[group] = _subparsers(g, f"{group}_command", f"{group.upper()}_COMMAND")
            p = groups[group].add_parser(name, help=cmd.help)
        if words is None or words[:len(cmd.path)] == cmd.path:
            cmd.load(cmd.arguments)(p, profile_names())
            p.set_defaults(command_row=cmd)
    return ap


class _Terminated(BaseException):
    """SIGTERM, for a command that does not handle it itself: it ends the
    command as Ctrl-C does (a BaseException, so no `except Exception` keeps it)."""


def _terminate(signum: int, frame: object) -> NoReturn:
    raise _Terminated


def main(argv: Sequence[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    # The commands that must clean up in their own order on a signal (runs,
    # device sessions, the simulator) set their own handlers while they run;
    # every other one stops on SIGTERM as on Ctrl-C, with the shell's 143.
    in_main = threading.current_thread() is threading.main_thread()
    old = signal.signal(signal.SIGTERM, _terminate) if in_main else None
    try:
        try:
            args = build_parser(argv).parse_args(argv)
        except SystemExit as e:  # --help, or a bad command line already reported
            return e.code if isinstance(e.code, int) else 2
        cmd: Command = args.command_row
        return cmd.load(cmd.run)(args)
    except UsageError as e:
        print(f"osdkc: {e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:  # also while the command's modules are still being imported
        print("osdkc: interrupted", file=sys.stderr)
        return 130
    except _Terminated:
        print("osdkc: terminated", file=sys.stderr)
        return 128 + signal.SIGTERM
    except BrokenPipeError:
        # The reader went away (e.g. `| head`): not an error of ours. Point
        # stdout at /dev/null so the interpreter's final flush stays quiet.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    finally:
        if in_main:
            signal.signal(signal.SIGTERM, old)


if __name__ == "__main__":
    raise SystemExit(main())
