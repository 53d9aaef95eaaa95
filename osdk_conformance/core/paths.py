"""Where the kit's files are, so no module guesses.

Two layouts, one set of names:
- a checkout of the repository (`make setup` installs it editable): ROOT is
  the checkout, and everything is where the repository keeps it;
- an installed wheel (`pip install osdk-conformance`): the files the
  commands read (spec/, vectors/, the testee protocol's schemas and failure
  lists, the Python testees, the value model) are package data under
  osdk_conformance/_data/, laid out as in the repository (pyproject.toml
  says which), and ROOT is that folder, found through importlib.resources.
  What only a checkout has (tools/, the testees in other languages, the C
  baseline) is then missing, and the commands that need it say so.
Nothing is ever written into an installed package: reports go to the working
directory and caches to the user's cache folder.
"""
from __future__ import annotations

import importlib.resources
import os
from pathlib import Path

_PACKAGE = Path(__file__).resolve().parents[1]
_REPOSITORY = _PACKAGE.parent

CHECKOUT: Path | None = _REPOSITORY if (_REPOSITORY / "pyproject.toml").is_file() \
    and (_REPOSITORY / "spec" / "rules.yaml").is_file() else None
"""The repository this package runs from, or None when it is installed."""

ROOT = CHECKOUT or Path(str(importlib.resources.files("osdk_conformance") / "_data"))
SPEC = ROOT / "spec"

REPORTS = (CHECKOUT or Path.cwd()) / "reports"
"""The default folder of reports (a checkout keeps them in reports/)."""

CACHE = CHECKOUT / ".cache" if CHECKOUT else \
    Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache") / "osdkc"
"""Where generated benchmark corpora and builds are kept between runs."""


def where_from() -> str:
    """What `osdkc --version` says of where the kit's files come from."""
    return f"checkout {CHECKOUT}" if CHECKOUT else f"installed at {_PACKAGE}"


def needs_checkout(what: str) -> str | None:
    """None in a checkout; else why `what` cannot run from an installed package."""
    if CHECKOUT:
        return None
    return (f"{what} needs a checkout of the osdk-conformance repository "
            f"(this osdkc is installed at {_PACKAGE}, without tools/ and the testees in other languages)")


# The seed that spec/trace.yaml maps is a source, not part of the repository:
# the trace cites it by name and SHA-256. `osdkc spec trace --seed FILE` (and
# `spec check`, `kit`) read it from the file given, else from this variable;
# without either, the checks against the seed are skipped and say so.
SEED_ENV = "OSDK_SEED"
