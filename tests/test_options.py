"""Every numeric option of every osdkc subcommand is checked: NaN, infinities
and out-of-range values are a one-line usage error with exit status 2.

The options are found by walking the real parser, so an option added later
with a plain `type=float` fails test_every_numeric_option_has_a_checked_type."""
from __future__ import annotations

import argparse
import math
import re
import subprocess
import sys

import pytest

from osdk_conformance.core import options
from osdk_conformance.cli import build_parser, main


def subcommand_parsers(parser: argparse.ArgumentParser, path: tuple[str, ...] = ()):
    yield path, parser
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, sub in action.choices.items():
                yield from subcommand_parsers(sub, (*path, name))


def is_numeric(action: argparse.Action) -> bool:
    if action.nargs == 0:  # a flag (store_true, help, ...) takes no value
        return False
    default_is_number = isinstance(action.default, (int, float)) and not isinstance(action.default, bool)
    return action.type in (int, float) or isinstance(action.type, options.NumberType) or default_is_number


def numeric_options(parser: argparse.ArgumentParser) -> list[tuple[tuple[str, ...], argparse.Action]]:
    return [(path, a) for path, p in subcommand_parsers(parser) for a in p._actions if is_numeric(a)]


def unchecked(parser: argparse.ArgumentParser) -> list[str]:
    return [f"{' '.join(path)} {a.option_strings[0]}" for path, a in numeric_options(parser)
            if a.type not in options.CHECKED_TYPES]


NUMERIC = numeric_options(build_parser())
BAD_VALUES = ("nan", "NaN", "inf", "-inf", "1e999", "-1", "0", "x")


def test_every_numeric_option_has_a_checked_type():
    assert unchecked(build_parser()) == []
    found = {(" ".join(path), a.option_strings[0]) for path, a in NUMERIC}
    # the walk reaches every subcommand that has numbers, nested ones included
    assert {("device", "--max-jitter-ms"), ("device", "--duration"), ("sim", "--tcp"), ("sim", "--bitflip"),
            ("soak", "--hz"), ("run", "--timeout"), ("bench", "--repeats"), ("fuzz", "--seed"),
            ("selftest", "--max-failures")} <= found


def test_an_option_added_with_a_plain_number_type_is_caught():
    parser = build_parser()
    device = dict(subcommand_parsers(parser))[("device",)]
    device.add_argument("--new-float", type=float)
    device.add_argument("--new-default", default=3)
    assert unchecked(parser) == ["device --new-float", "device --new-default"]


@pytest.mark.parametrize("path, action", NUMERIC, ids=lambda v: " ".join(v) if isinstance(v, tuple)
                         else v.option_strings[0])
def test_bad_numbers_are_a_one_line_usage_error(path, action, capsys):
    opt = action.option_strings[0]
    rejected = [v for v in BAD_VALUES if v not in ("-1", "0") or not action.type.accepts(float(v))]
    assert {"nan", "inf", "-inf", "-1"} <= set(rejected)  # no option accepts these
    for value in rejected:
        assert main([*path, f"{opt}={value}"]) == 2, (opt, value)
        out, err = capsys.readouterr()
        assert out == "" and "Traceback" not in err
        (line,) = err.strip().splitlines()
        assert line.startswith(f"osdkc {' '.join(path)}: error: argument {opt}") and repr(value) in line


@pytest.mark.parametrize("path, action", NUMERIC, ids=lambda v: " ".join(v) if isinstance(v, tuple)
                         else v.option_strings[0])
def test_defaults_are_within_their_types(path, action):
    if action.default is not None:
        assert action.type.accepts(action.default) and action.type(str(action.default)) == action.default


@pytest.mark.parametrize("number_type, good, bad", [
    (options.positive_float, ["1e-9", "0.5", "86400"], ["0", "-0.0", "-1e-9"]),
    (options.non_negative_float, ["0", "0.0", "3.5"], ["-1e-9"]),
    (options.fraction, ["1e-9", "1", "0.1"], ["0", "1.0000001"]),
    (options.probability, ["0", "1", "0.25"], ["1.5", "-0.1"]),
    (options.rate_change, ["-0.5", "0", "0.25", "3"], ["-1", "-2"]),
    (options.positive_int, ["1", "100"], ["0", "1.5", "1e3"]),
    (options.non_negative_int, ["0", "7"], ["-3"]),
    (options.uint32, ["0", "4294967295"], ["4294967296", "-1"]),
    (options.tcp_port, ["0", "1", "65535"], ["65536", "99999", "-1"]),
    (options.baud_rate, ["50", "230400", "921600", "12000000"], ["0", "49", "12000001"]),
])
def test_each_type_keeps_its_range(number_type, good, bad):
    for text in good:
        value = number_type(text)
        assert math.isfinite(value) and value == number_type.parse(text)
    for text in [*bad, "nan", "inf", "-inf", "", "twelve"]:
        with pytest.raises(argparse.ArgumentTypeError, match=re.escape(number_type.expected)):
            number_type(text)


@pytest.mark.parametrize("args, option", [
    (["device", "--replay", "missing.pcapng", "--profile", "a3-fw3.1", "--max-jitter-ms", "nan"], "--max-jitter-ms"),
    (["device", "--port", "/nonexistent/tty", "--profile", "a3-fw3.1", "--duration", "inf"], "--duration"),
    (["sim", "--tcp", "99999"], "--tcp"),
])
def test_the_reported_cases_exit_2_as_a_user_runs_them(args, option):
    proc = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", *args], capture_output=True, text=True,
                          timeout=60)
    assert proc.returncode == 2 and proc.stdout == ""
    (line,) = proc.stderr.strip().splitlines()
    assert line.startswith(f"osdkc {args[0]}: error: argument {option}: ")


def options_named(name: str) -> list[tuple[str, argparse.Action]]:
    return [(" ".join(path), a) for path, p in subcommand_parsers(build_parser()) for a in p._actions
            if name in a.option_strings]


def test_the_same_option_means_the_same_in_every_subcommand():
    json_flags = options_named("--json")
    assert {cmd for cmd, _ in json_flags} >= {"spec trace", "soak", "bench"}
    # --json: print the numbers or the table as JSON on standard output, never a file name
    assert all(a.nargs == 0 and a.const is True for _, a in json_flags), json_flags
    # --impl: repeatable wherever it is taken
    impls = options_named("--impl")
    assert {cmd for cmd, _ in impls} >= {"run", "fuzz", "bench"}
    assert all(isinstance(a, argparse._AppendAction) for _, a in impls), impls
    # --jobs: one default
    jobs = options_named("--jobs")
    assert {cmd for cmd, _ in jobs} >= {"run", "selftest"}
    assert {a.default for _, a in jobs} == {options.DEFAULT_JOBS}
