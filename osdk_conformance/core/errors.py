"""Errors the command line reports to the user without a traceback."""


class UsageError(Exception):
    """A problem with what the user asked for (arguments, unreadable input)."""


# `osdkc device`: nothing failed, but the judge's own host was too busy to read
# the port in time for some checks (INCONCLUSIVE); the reliability bench reads it too.
EXIT_INCONCLUSIVE = 3


def exit_status_of_signal(signame: str) -> int:
    """Exit status of a command ended by SIGINT or SIGTERM after it wrote what
    it had (partial reports marked interrupted): the shell's 128 + the signal
    number, 130 for SIGINT and 143 for SIGTERM, as `osdkc` returns 130 for any
    command interrupted with Ctrl-C."""
    import signal

    return 128 + signal.Signals[signame].value


def one_line(exc: BaseException) -> str:
    """An exception's message on one line (white space folded), or its type's
    name when it has none: what a report or a one-line error shows."""
    return " ".join(str(exc).split()) or type(exc).__name__


def cannot_read(path: object, exc: BaseException, what: str = "") -> str:
    """The one-line message for a file that could not be read: the OS's
    reason (strerror) when there is one, else the exception's own text."""
    reason = getattr(exc, "strerror", None) or one_line(exc)
    return f"cannot read {what + ' ' if what else ''}{path}: {reason}"
