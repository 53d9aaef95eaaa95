"""The optional `flight` extra (numpy, pyarrow, pandas): the modules of this
package that need it, loaded when a command or the API asks for them, with
one clear error where it is not installed (the conformance kit itself runs
without it)."""
from __future__ import annotations

import importlib
from types import ModuleType

from osdk_conformance.core.errors import UsageError, one_line

INSTALL = "pip install 'osdk-conformance[flight]'"


def load(*names: str) -> tuple[ModuleType, ...]:
    """osdk_conformance.flight.<name> for each name; UsageError naming the
    missing dependency when the extra is not installed."""
    try:
        return tuple(importlib.import_module(f"osdk_conformance.flight.{n}") for n in names)
    except ImportError as e:
        raise UsageError(f"flight data needs the optional dependencies numpy, pyarrow and pandas "
                         f"({one_line(e)}): {INSTALL}") from None
