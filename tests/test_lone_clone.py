"""The repository stands alone: a clone with nothing beside it checks its spec.

The copy is what a clone of this working tree holds (tracked files and new
files not ignored, so uncommitted work is tested too), alone in its own
directory: no shared/ folder is beside it, whatever this checkout has
beside it. Only what `make setup` installs outside git (the venv, the npm
packages of the Kaitai compiler) is reused. Everything then runs from the
copy, with the copy's modules first on the path.
"""
from __future__ import annotations

import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest

# a copy of the repository and its spec checks: `make quick` leaves it out
pytestmark = pytest.mark.slow

from osdk_conformance.core.paths import ROOT
from repo_copy import PACKAGES, checkout_files, make_copy

# A path out of the checkout to the project's shared sources, written or computed.
OUTSIDE = re.compile(r"""\.\./shared\b|\bparents?\b[^\n]*['"]shared['"]""")
# Prose that cites where a fact came from, and this file, which spells out
# what the pattern must catch.
NOT_SCANNED = ("docs/", "spec/ERRATA.md", "tests/test_lone_clone.py")


@pytest.fixture(scope="module")
def lone(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, dict[str, str]]:
    """The copy, and the environment to run it with."""
    base = tmp_path_factory.mktemp("lone")
    repo = base / "repo"
    env = make_copy(repo)
    assert sorted(p.name for p in base.iterdir()) == ["repo"]  # nothing beside the clone
    return repo, env


def _run(lone: tuple[Path, dict[str, str]], *argv: str, timeout: float = 120) -> subprocess.CompletedProcess[str]:
    repo, env = lone
    return subprocess.run([sys.executable, *argv], cwd=repo, env=env, capture_output=True, text=True, timeout=timeout)


SPEC_CHECK = ("-m", "osdk_conformance.cli", "spec", "check")
TRACE_TESTS = ("-m", "pytest", "-q", "-p", "no:cacheprovider", "-rs", "tests/test_trace.py")


@pytest.fixture(scope="module")
def slow_runs(lone: tuple[Path, dict[str, str]]) -> dict[tuple[str, ...], subprocess.CompletedProcess[str]]:
    """`osdkc spec check` and the copy's trace tests, the two long runs of this
    file, side by side: neither writes where the other reads (the check
    regenerates into scratch directories, the tests write to their
    tmp_path), and the tests are one Python process, which leaves the other
    core to the check. Each test below judges its own run."""
    with ThreadPoolExecutor(2) as pool:
        # the timeout allows for the two sharing the cores
        futures = {argv: pool.submit(_run, lone, *argv, timeout=300) for argv in (SPEC_CHECK, TRACE_TESTS)}
    return {argv: f.result() for argv, f in futures.items()}


def test_the_copy_runs_its_own_modules(lone: tuple[Path, dict[str, str]]) -> None:
    repo, _ = lone
    names = ", ".join(PACKAGES)
    proc = _run(lone, "-c", f"import {names}, osdk_conformance.core.paths as p\n"
                            f"for m in ({names}): print(m.__name__, m.__file__)\n"
                            "print('ROOT', p.ROOT)")
    assert proc.returncode == 0, proc.stderr
    where = dict(line.split(" ", 1) for line in proc.stdout.splitlines())
    for name, directory in PACKAGES.items():
        assert Path(where[name]).resolve() == (repo / directory / "__init__.py").resolve(), name
    assert Path(where["ROOT"]) == repo.resolve()


def test_spec_trace_skips_the_seed_checks_and_passes(lone: tuple[Path, dict[str, str]]) -> None:
    proc = _run(lone, "-m", "osdk_conformance.cli", "spec", "trace")
    assert proc.returncode == 0, proc.stdout[-2000:] + proc.stderr
    assert proc.stderr == ""
    lines = proc.stdout.splitlines()
    assert "did not run: no seed given (--seed FILE, or set OSDK_SEED)" in lines[-2]
    assert lines[-1] == ("trace: OK as far as checked (every spec reference resolves); "
                         "SKIPPED the checks against the seed")


def test_spec_check_passes_with_the_trace_partly_skipped(
        slow_runs: dict[tuple[str, ...], subprocess.CompletedProcess[str]]) -> None:
    proc = slow_runs[SPEC_CHECK]
    assert proc.returncode == 0, proc.stdout + proc.stderr
    status = {line.split()[1]: line.split()[0] for line in proc.stdout.splitlines() if line.startswith("  ")}
    assert status == {"ksy": "ok", "rules": "ok", "trace": "skip", "errata": "ok"}
    assert proc.stdout.splitlines()[-1] == "spec check: all passed (partly skipped: trace)"


def test_trace_tests_pass(slow_runs: dict[tuple[str, ...], subprocess.CompletedProcess[str]]) -> None:
    proc = slow_runs[TRACE_TESTS]
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr
    # the one test that needs the real seed says why it did not run
    assert "SKIPPED [1] tests/test_trace.py" in proc.stdout and "OSDK_SEED not set" in proc.stdout
    assert re.search(r"\b\d+ passed, 1 skipped\b", proc.stdout)


def test_no_source_reaches_outside_the_checkout() -> None:
    found = []
    for name in checkout_files():
        if name.startswith(NOT_SCANNED):
            continue
        try:
            text = (ROOT / name).read_text(encoding="utf-8")
        except UnicodeDecodeError:
            continue  # not a source file
        found += [f"{name}:{text.count(chr(10), 0, m.start()) + 1}: {m.group(0)}" for m in OUTSIDE.finditer(text)]
    assert found == []


def test_the_pattern_catches_both_ways_of_reaching_out() -> None:
    shelf = "sha" + "red"   # spelled apart, so this file holds no reference to the shelf itself
    assert OUTSIDE.search(f'SEED = "../{shelf}/seeds/x.txt"')
    assert OUTSIDE.search(f'SEED = ROOT.parent / "{shelf}" / "seeds" / "x.txt"')
    assert OUTSIDE.search("base = Path(__file__).parents[2] / 'shared'")
    assert not OUTSIDE.search('"""Item types shared by the three broadcast profiles"""')
