"""A copy of this checkout as a clone would hold it, alone in a directory,
run with its own modules first on the path (used by the lone-clone and the
extending walk-through tests).

The copy holds the tracked files and new files not ignored, so uncommitted
work is tested too. Only what `make setup` installs outside git (the venv,
the npm packages of the Kaitai compiler and of the JavaScript testee) is
reused, by link.
"""
from __future__ import annotations

import os
import shutil
import subprocess
from pathlib import Path

import pytest

from osdk_conformance.core.paths import ROOT, SEED_ENV

PACKAGES = {  # importable name -> its directory in the repository (pyproject.toml package-dir)
    "osdk_conformance": "osdk_conformance",
    "osdk_conformance._construct": "spec/construct",
    "osdk_conformance._kaitai": "generated/python/osdk_kaitai",
}


def checkout_files() -> list[str]:
    if not (ROOT / ".git").exists():
        pytest.skip("not a git checkout: no way to tell which files a clone would hold")
    out = subprocess.run(["git", "ls-files", "-z", "-co", "--exclude-standard"], cwd=ROOT,
                         capture_output=True, check=True).stdout.decode()
    return sorted({f for f in out.split("\0") if f and (ROOT / f).is_file()})


def make_copy(repo: Path) -> dict[str, str]:
    """Copy the checkout to `repo`; return the environment that runs the copy."""
    for name in checkout_files():
        (repo / name).parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(ROOT / name, repo / name, follow_symlinks=False)
    (repo / "tools/ksc/node_modules").symlink_to(ROOT / "tools/ksc/node_modules")
    # The subpackages that live elsewhere in the repository (spec/construct,
    # generated/python/osdk_kaitai) reach the copy's osdk_conformance through
    # links: the venv's editable install would give this checkout's instead.
    for name, directory in PACKAGES.items():
        if name.startswith("osdk_conformance."):
            (repo / name.replace(".", "/")).symlink_to(repo / directory)
    env = {k: v for k, v in os.environ.items() if k != SEED_ENV}
    # generated/python: the library osdk_kaitai, importable as its users import it
    env["PYTHONPATH"] = os.pathsep.join([str(repo), str(repo / "generated/python")])
    env["PYTHONDONTWRITEBYTECODE"] = "1"
    return env
