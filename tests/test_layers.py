"""The layer order of osdk_conformance and the absence of import cycles,
checked by import-linter (pinned in constraints.txt) against the contracts in
pyproject.toml's [tool.importlinter], plus the rule that the package imports
its own modules at module level (a lazy import only for start-up time, said
in a comment).
"""
from __future__ import annotations

import ast
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
LINT = Path(sys.executable).with_name("lint-imports")
OURS = ("osdk_conformance",)  # its Construct spec and Kaitai parsers are subpackages


def lint(where: Path) -> subprocess.CompletedProcess:
    # PYTHONPATH first, so that a copy under test is what gets analysed
    env = {**os.environ, "PYTHONPATH": str(where)}
    return subprocess.run([str(LINT), "--no-cache", "--config", str(where / "pyproject.toml")],
                          cwd=where, env=env, capture_output=True, text=True, timeout=120)


def test_the_package_keeps_its_layers_and_has_no_cycles() -> None:
    proc = lint(ROOT)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "0 broken" in proc.stdout


@pytest.fixture
def package_copy(tmp_path: Path) -> Path:
    shutil.copytree(ROOT / "osdk_conformance", tmp_path / "osdk_conformance",
                    ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copy(ROOT / "pyproject.toml", tmp_path)
    return tmp_path


def add_import(copy: Path, module: str, statement: str) -> None:
    path = copy / (module.replace(".", "/") + ".py")
    path.write_text(path.read_text() + f"\n{statement}\n")


@pytest.mark.parametrize("module, statement, broken", [
    # a protocol primitive that reaches up into the simulator
    ("osdk_conformance.core.crc", "import osdk_conformance.sim.simulator", "osdk_conformance layers"),
    # two layers declared independent
    ("osdk_conformance.bench.child", "import osdk_conformance.device.analysis", "osdk_conformance layers"),
    # a cycle inside one package (acceptance imports plots)
    ("osdk_conformance.device.plots", "import osdk_conformance.device.acceptance",
     "no cycles among sibling modules"),
    ("osdk_conformance.harness.runner", "import osdk_conformance.cli", "nothing imports the command line"),
])
def test_the_checker_catches_a_violation(package_copy: Path, module: str, statement: str, broken: str) -> None:
    add_import(package_copy, module, statement)
    proc = lint(package_copy)
    assert proc.returncode != 0
    assert f"{broken} BROKEN" in proc.stdout, proc.stdout


def lazy_imports(path: Path) -> list[str]:
    """Imports of our packages below module level that no comment explains."""
    lines = path.read_text().splitlines()
    tree = ast.parse("\n".join(lines))
    top = {id(node) for node in tree.body}
    out = []
    for node in ast.walk(tree):
        if id(node) in top or not isinstance(node, (ast.Import, ast.ImportFrom)):
            continue
        names = [node.module or ""] if isinstance(node, ast.ImportFrom) else [a.name for a in node.names]
        if not any(n.split(".")[0] in OURS for n in names):
            continue
        said = lines[node.lineno - 1] + (lines[node.lineno - 2] if node.lineno > 1 else "")
        if "start-up" not in said:
            out.append(f"{path.relative_to(ROOT)}:{node.lineno}")
    return out


def test_package_modules_are_imported_at_module_level() -> None:
    found = [hit for path in sorted((ROOT / "osdk_conformance").rglob("*.py")) for hit in lazy_imports(path)]
    assert found == [], "import these at module level, or say in a comment why start-up time needs them lazy"
