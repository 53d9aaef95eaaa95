"""osdkc: the command line of the OPEN protocol conformance kit."""
from __future__ import annotations

import argparse
import os
import sys
from typing import Callable, NoReturn, Sequence

from .errors import UsageError

PROFILES = ("m100-fw2.3", "m100-fw3.1", "a3-fw3.1")


def _decode(args: argparse.Namespace) -> int:
    from .decode import run_decode

    return run_decode(args)


def _spec_trace(args: argparse.Namespace) -> int:
    from .trace import run_trace

    return run_trace(args)


def _spec_check(args: argparse.Namespace) -> int:
    from .speccheck import run_spec_check

    return run_spec_check(args)


def _kit(args: argparse.Namespace) -> int:
    from .kit import run_kit

    return run_kit(args)


def _run(args: argparse.Namespace) -> int:
    from .runner import run_command

    return run_command(args)


def _vectors(args: argparse.Namespace) -> int:
    from .vectors import run_vectors

    return run_vectors(args)


def _sim(args: argparse.Namespace) -> int:
    from .sim import run_sim

    return run_sim(args)


def _device(args: argparse.Namespace) -> int:
    from .device import run_device

    return run_device(args)


def _soak(args: argparse.Namespace) -> int:
    from .soak import run_soak

    return run_soak(args)


class Parser(argparse.ArgumentParser):
    """Reports a bad command line in one line, like every other usage error
    (subcommand parsers are of the same class)."""

    def error(self, message: str) -> NoReturn:
        self.exit(2, f"{self.prog}: error: {message} (see {self.prog} --help)\n")


def _add_seed_argument(p: argparse.ArgumentParser) -> None:
    p.add_argument("--seed", metavar="FILE",
                   help="the seed text spec/trace.yaml maps (not in the repository; default: $OSDK_SEED). "
                        "Without one, the trace's checks against the seed are skipped, and the output says so")


def build_parser() -> argparse.ArgumentParser:
    ap = Parser(
        prog="osdkc",
        description="Specification and conformance kit for the DJI Onboard SDK OPEN serial protocol.",
    )
    sub = ap.add_subparsers(dest="command", metavar="COMMAND")
    sub.required = True

    d = sub.add_parser("decode", help="find and decode frames in a byte stream, one JSON object per line")
    d.add_argument("--profile", required=True, choices=PROFILES, help="broadcast wire profile of the flight controller")
    src = d.add_mutually_exclusive_group(required=True)
    src.add_argument("--hex", help="the bytes as hex (spaces and colons allowed)")
    src.add_argument("file", nargs="?", help="a file of raw bytes or a pcapng capture (osdkc device), or - for standard input")
    d.add_argument("--direction", choices=("rx", "tx", "both"), default="rx",
                   help="of a capture: bytes received (default), sent, or both, each event marked with its direction")
    d.add_argument("--pretty", action="store_true", help="indent each JSON object")
    d.set_defaults(func=_decode)

    s = sub.add_parser("spec", help="inspect and check the specification")
    ssub = s.add_subparsers(dest="spec_command", metavar="SPEC_COMMAND")
    ssub.required = True
    t = ssub.add_parser("trace", help="map every seed entry to the spec element that carries it")
    t.add_argument("--json", action="store_true", help="print the table as JSON")
    _add_seed_argument(t)
    t.set_defaults(func=_spec_trace)
    c = ssub.add_parser("check", help="compile the .ksy files, validate rules and trace, check generated/")
    _add_seed_argument(c)
    c.set_defaults(func=_spec_check)

    k = sub.add_parser("kit", help="run the conformance kit (spec checks and worked examples)")
    _add_seed_argument(k)
    k.set_defaults(func=_kit)

    from .runner import add_arguments as add_run_arguments

    r = sub.add_parser("run", help="replay the golden vectors against an implementation (conformance/PROTOCOL.md)")
    add_run_arguments(r, PROFILES)
    r.set_defaults(func=_run)

    v = sub.add_parser("vectors", help="check the golden vectors and their coverage of the spec")
    vsub = v.add_subparsers(dest="vectors_command", metavar="VECTORS_COMMAND")
    vsub.required = True
    vc = vsub.add_parser("check", help="schema, manifest hashes, unique ids, and every case against the spec")
    vc.add_argument("--dir", help="the vectors directory (default: vectors/)")
    vc.add_argument("--no-spec", action="store_true", help="skip re-running the reference on every case")
    vc.set_defaults(func=_vectors)
    vv = vsub.add_parser("coverage", help="cases per spec rule and errata entry; fails when one has none")
    vv.add_argument("--dir", help="the vectors directory (default: vectors/)")
    vv.set_defaults(func=_vectors)

    from . import fuzz, selftest  # both import only the standard library until they run

    st = sub.add_parser("selftest", help="mutation check: every deliberately broken implementation must fail the vectors")
    selftest.add_arguments(st)
    st.set_defaults(func=selftest.run_selftest)
    fz = sub.add_parser("fuzz", help="differential fuzzing of two or more implementations (hypothesis)")
    fuzz.add_arguments(fz, PROFILES)
    fz.set_defaults(func=fuzz.run_fuzz)
    from . import device, sim, soak  # standard library and osdk_conformance only until they run

    sm = sub.add_parser("sim", help="simulated flight controller on a pseudo-terminal or TCP port")
    sim.add_arguments(sm, PROFILES)
    sm.set_defaults(func=_sim)
    dv = sub.add_parser("device", help="acceptance suite against a flight controller on a serial port (or a capture)")
    device.add_arguments(dv, PROFILES)
    dv.set_defaults(func=_device)
    sk = sub.add_parser("soak", help="benchmark: every item at 100 Hz from osdkc sim over a pty, no frame may be lost")
    soak.add_arguments(sk, PROFILES)
    sk.set_defaults(func=_soak)
    from . import sdk_host  # standard library and osdk_conformance only until it runs

    sd = sub.add_parser("sdk", help="DJI's Onboard-SDK itself against the kit (needs a checkout of it)")
    sdsub = sd.add_subparsers(dest="sdk_command", metavar="SDK_COMMAND")
    sdsub.required = True
    ht = sdsub.add_parser("host-test", help="build DJI's host stack with our driver, run a whole session "
                                            "against osdkc sim for each profile")
    sdk_host.add_arguments(ht, PROFILES)
    ht.set_defaults(func=sdk_host.run_host_test)
    from . import bench  # no third-party import until it runs

    bn = sub.add_parser("bench", help="benchmarks: decode speed against an SDK-style C baseline, run, fuzz, soak")
    bench.add_arguments(bn, PROFILES)
    bn.set_defaults(func=bench.run_bench)
    return ap


def main(argv: Sequence[str] | None = None) -> int:
    ap = build_parser()
    try:
        args = ap.parse_args(argv)
    except SystemExit as e:  # --help, or a bad command line already reported
        return e.code if isinstance(e.code, int) else 2
    func: Callable[[argparse.Namespace], int] = args.func
    try:
        return func(args)
    except UsageError as e:
        print(f"osdkc: {e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        print("osdkc: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        # The reader went away (e.g. `| head`): not an error of ours. Point
        # stdout at /dev/null so the interpreter's final flush stays quiet.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0


if __name__ == "__main__":
    raise SystemExit(main())
