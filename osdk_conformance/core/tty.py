"""A terminal's two speeds. The C library keeps one speed for both
directions (CBAUD in c_cflag: cfgetispeed reports the output speed too);
the Linux kernel keeps an input speed of its own in the CIBAUD bits, 0 there
meaning "as the output speed". A port that sends at one rate and receives at
another (osdkc doctor's query at another rate, osdkc sim --rx-baud) needs both."""
from __future__ import annotations

import termios

IBSHIFT = 16   # where CIBAUD sits in c_cflag


def split_speeds(cflag: int) -> tuple[int, int]:
    """(input, output) speed constants of a terminal's c_cflag."""
    out = cflag & termios.CBAUD
    return ((cflag & termios.CIBAUD) >> IBSHIFT) or out, out


def with_input_speed(cflag: int, speed: int) -> int:
    """c_cflag with its input speed set to the speed constant `speed`."""
    return (cflag & ~termios.CIBAUD) | speed << IBSHIFT
