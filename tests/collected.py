"""What a module's selected tests need from a module fixture that prepares
many live runs at once (simulator sessions, a few at a time): only those,
so that `make quick`, which leaves some of the tests out, does not pay for
the runs of the tests it left out."""
from __future__ import annotations

from typing import Any, Callable

import pytest


def needed(request: pytest.FixtureRequest, need: Callable[[pytest.Item], Any]) -> set:
    """`need(item)` over the tests of the requesting module that this session
    runs (after -m, -k and deselection), None left out."""
    return {n for item in request.session.items if item.module is request.module and (n := need(item)) is not None}


def scenario(item: pytest.Item) -> str | None:
    """The run a test reads, from its `scenario` mark: a name, formatted with
    the test's parameters (`@pytest.mark.scenario("motion-{profile}")`)."""
    mark = item.get_closest_marker("scenario")
    if mark is None:
        return None
    spec = getattr(item, "callspec", None)
    return mark.args[0].format(**(spec.params if spec else {}))
