"""The native accelerator of decoding, and the switch that picks it.

`osdk_conformance.reference._accel` is the generated C decoder (generated/c)
with its value model built as Python objects (generated/cpython) behind the
event stream of reference/decode.py, compiled when the package is installed
where a C compiler exists (pyproject.toml, `ext-modules`; the install goes
on without it). `osdkc decode`, the Python API's decoding and the acceptance
receiver use it when it is there; the conformance suite replays every
vector against it as the bundled implementation `c-accel`
(conformance/testees/accel_testee.py), so it answers what the spec says as
surely as the others. The pure-Python path (Construct) stays the reference
and the fallback.

The environment variable OSDKC_ACCEL chooses:

- unset, empty or `auto`: the accelerator when it can be imported, else pure Python;
- `0` (or `off`, `no`, `false`): pure Python, always;
- `1` (or `on`, `yes`, `true`): the accelerator, and an error when it is missing.

Events are the same either way, key for key; only `detail`, text for
people, is worded by whichever decoder ran.
"""
from __future__ import annotations

import functools
import importlib
import os
from types import ModuleType
from typing import Any, Iterator

from osdk_conformance.core.deframe import header_fields
from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.rules import profile as load_profile

ENV = "OSDKC_ACCEL"
MODULE = "osdk_conformance.reference._accel"

# Sessions with an ACK slot (PROTOCOL.md "ACK matching", ERRATA E32); the pure-Python decoder has the same.
ACK_SESSIONS = range(2, 32)

_OFF = {"0", "off", "no", "false"}
_ON = {"1", "on", "yes", "true"}


def _setting() -> str:
    value = os.environ.get(ENV, "").strip().lower()
    if value in ("", "auto"):
        return "auto"
    if value in _OFF:
        return "off"
    if value in _ON:
        return "on"
    raise UsageError(f"{ENV}={os.environ[ENV]!r}: use 1 (the native decoder), 0 (pure Python) or auto")


@functools.lru_cache(maxsize=1)
def _import() -> tuple[ModuleType | None, str]:
    try:
        return importlib.import_module(MODULE), ""
    except ImportError as e:
        return None, str(e)


def native() -> ModuleType | None:
    """The native module when it is to be used (OSDKC_ACCEL), else None.
    UsageError when OSDKC_ACCEL asks for it and it cannot be imported."""
    setting = _setting()
    if setting == "off":
        return None
    module, why = _import()
    if module is None and setting == "on":
        raise UsageError(f"{ENV}=1 but the native decoder is not installed ({why}); it is built when the "
                         "package is installed where a C compiler exists (pip install reinstalls it)")
    return module


def available() -> bool:
    """Whether the native module can be imported at all (whatever OSDKC_ACCEL says)."""
    return _import()[0] is not None


def describe() -> str:
    """Which decoder runs, and why, for `osdkc --version` and reports."""
    setting = _setting()
    module, why = _import()
    if setting == "off":
        return f"pure Python ({ENV}=0)"
    if module is None:
        return f"pure Python (no native decoder: {why})"
    return f"native ({os.path.basename(module.__file__ or MODULE)})"


# Bytes handed to the native decoder at a time. Each call returns the events
# of its bytes as a list; a 64 KiB read makes some 300 events of 180 objects
# each before the first is used, and walking them afterwards misses the CPU
# caches. A few kilobytes at a time keep making and letting go of events hot
# in the caches (measured: 6.4 us per a3-fw3.1 frame with 64 KiB, 5.8 with 2
# to 8 KiB).
SLICE = 4096


class NativeStream:
    """The native decoder of one stream of either direction, with
    reference/decode.py's interface: events of the bytes fed so far."""

    def __init__(self, module: ModuleType, profile: str) -> None:
        self._decoder = module.Decoder(load_profile(profile).value, header_fields)

    def feed(self, data: bytes, direction: str | None = None) -> Iterator[dict[str, Any]]:
        view = memoryview(data)
        for start in range(0, len(view), SLICE):
            yield from self._decoder.feed(view[start:start + SLICE], direction)

    def finish(self, direction: str | None = None) -> list[dict[str, Any]]:
        return self._decoder.finish(direction)


def stream(profile: str) -> NativeStream | None:
    """A native decoder for `profile`, or None when pure Python is to run."""
    module = native()
    return NativeStream(module, profile) if module is not None else None
