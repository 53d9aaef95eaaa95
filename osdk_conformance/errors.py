"""Errors the command line reports to the user without a traceback."""


class UsageError(Exception):
    """A problem with what the user asked for (arguments, unreadable input)."""
