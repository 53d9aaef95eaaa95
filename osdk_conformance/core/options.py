"""Checked types for the numeric options of every osdkc subcommand.

Each one is an argparse `type=`: a value that is NaN, infinite or outside the
range where the option means something becomes argparse's one-line usage
error and exit status 2, before any command runs. Plain `type=float` would let
`--max-jitter-ms nan` turn a check into a pass (every comparison with NaN is
false) and `--duration inf` run forever; tests/test_options.py walks the
parser so that no numeric option is left with a plain type.
"""
from __future__ import annotations

import argparse
import math
import os
from dataclasses import dataclass
from typing import Callable


@dataclass(frozen=True)
class NumberType:
    """Parses one option value with `parse` and accepts it when it is finite
    and within low..high; `low_open` excludes `low` itself."""

    name: str
    parse: Callable[[str], int | float]
    low: float
    high: float = math.inf
    low_open: bool = False
    expected: str = ""

    def accepts(self, value: float) -> bool:
        above = value > self.low if self.low_open else value >= self.low
        return math.isfinite(value) and above and value <= self.high

    def __call__(self, text: str) -> int | float:
        try:
            value = self.parse(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{self.expected} was expected, got {text!r}") from None
        if not self.accepts(value):
            raise argparse.ArgumentTypeError(f"{self.expected} was expected, got {text!r}")
        return value


positive_float = NumberType("positive_float", float, 0.0, low_open=True, expected="a finite number > 0")
non_negative_float = NumberType("non_negative_float", float, 0.0, expected="a finite number >= 0")
fraction = NumberType("fraction", float, 0.0, 1.0, low_open=True, expected="a fraction in (0, 1]")
probability = NumberType("probability", float, 0.0, 1.0, expected="a probability in [0, 1]")
# A rate factor 1 + x must stay positive: -1 would stop the clock, below it runs backwards.
rate_change = NumberType("rate_change", float, -1.0, low_open=True, expected="a finite fraction > -1")
positive_int = NumberType("positive_int", int, 1, expected="an integer >= 1")
non_negative_int = NumberType("non_negative_int", int, 0, expected="an integer >= 0")
uint32 = NumberType("uint32", int, 0, 2**32 - 1, expected="an integer in 0..4294967295")
tcp_port = NumberType("tcp_port", int, 0, 65535, expected="a TCP port in 0..65535 (0: any free port)")
# 50 baud is the slowest standard rate, 12 Mbaud the fastest USB serial adapters reach.
baud_rate = NumberType("baud_rate", int, 50, 12_000_000, expected="a baud rate in 50..12000000")

CHECKED_TYPES = (positive_float, non_negative_float, fraction, probability, rate_change, positive_int,
                 non_negative_int, uint32, tcp_port, baud_rate)


DEFAULT_JOBS = os.cpu_count() or 1
"""The one default of every --jobs: as many at a time as there are CPUs."""
