#!/usr/bin/env python3
"""Regenerate generated/ from spec/ with the pinned Kaitai compiler, the C
generator (tools/cgen) and the table writer (tools/tables.py).

usage: tools/regen.py [--check] [--target TARGET ...]

First, whatever the targets, the profile-dependent .ksy of spec/ are written
from spec/rules.yaml (tools/gen_profile_ksy.py: the osdk_broadcast_<profile>.ksy
files and the marked parts of osdk_payload.ksy), so the compiler always
sees the profiles the rules define; --check reports them when they are stale.

Targets and where they go, relative to generated/:
  python      python/                  Kaitai, package osdk_kaitai (relative imports), + glue and pyproject.toml
  javascript  javascript/              Kaitai, CommonJS/UMD modules, + glue and package.json
  java        java/                    Kaitai, package osdk_kaitai, + glue and pom.xml
  go          go/                      Kaitai, package osdk_kaitai, + glue, go.mod and go.sum
  c           c/                       tools/cgen: C99 decoder, no heap, + encoders and build files

"+ glue" is tools/libgen: the deframer, CRCs, frame decoding with the
profile chosen at run time, broadcast item access, error types and the
encoders of the commands an onboard computer sends, from the spec's tables.
  cpython     cpython/                 tools/cgen: its value model as Python objects (the accelerator)
  tables      tables/osdk_tables.json  rules and value-model tables
  wireshark   wireshark/osdk.lua       tools/wiresharkgen: Wireshark Lua dissector

--check regenerates into a scratch directory and fails (exit 1) when the
result differs from what is checked in, so CI catches hand edits and specs
that changed without regeneration. Output is deterministic: the same spec
gives the same bytes.
"""
from __future__ import annotations

import argparse
import filecmp
import importlib.util
import multiprocessing
import os
import shutil
import subprocess
import sys
import tempfile
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path
from typing import Callable

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "spec"
GENERATED = ROOT / "generated"
TOOLS = ROOT / "tools"
DRIVER = TOOLS / "ksc" / "compile.js"

def ksy_files() -> list[Path]:
    return sorted(SPEC.glob("*.ksy"))


def _fresh(out: Path) -> None:
    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)


def _ksc(target: str, out: Path, *options: str) -> None:
    cmd = ["node", str(DRIVER), "--target", target, "--out", str(out), *options]
    cmd += [str(p) for p in ksy_files()]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.stderr.write(proc.stderr)
        raise SystemExit(f"regen: the Kaitai compiler failed for {target}")


def _load_tool(name: str, path: Path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def _libgen(lang: str, out: Path) -> None:
    _load_tool("osdk_libgen", TOOLS / "libgen" / "__init__.py").write(lang, out)


def gen_python(out: Path) -> None:
    (out / "osdk_kaitai").mkdir()
    # Relative imports: the osdk-conformance wheel installs these same files as
    # osdk_conformance._kaitai (pyproject.toml), so that installing or removing
    # the osdk-kaitai distribution never touches the package the kit runs.
    _ksc("python", out / "osdk_kaitai", "--python-package", ".")
    _libgen("python", out)


def gen_javascript(out: Path) -> None:
    _ksc("javascript", out)
    _libgen("javascript", out)


def gen_java(out: Path) -> None:
    # Maven's source layout (pom.xml is the glue's); the compiler writes the package's directories itself
    _ksc("java", out / "src" / "main" / "java", "--java-package", "osdk_kaitai")
    _libgen("java", out)


def gen_go(out: Path) -> None:
    _ksc("go", out, "--go-package", "osdk_kaitai")
    # Go cannot find a type by name: the glue gets the package's struct types from this list
    _load_tool("osdk_tables_tool", TOOLS / "tables.py").write_go_types(out / "osdk_kaitai")
    _libgen("go", out)


def _cgen(out: Path, target: str) -> None:
    cgen = TOOLS / "cgen" / "generate.py"
    if not cgen.exists():
        raise SystemExit("regen: tools/cgen/generate.py is missing")
    proc = subprocess.run([sys.executable, str(cgen), "--out", str(out), "--target", target],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        sys.stderr.write(proc.stdout + proc.stderr)
        raise SystemExit("regen: the C generator failed")


def gen_c(out: Path) -> None:
    _cgen(out, "c")
    _libgen("c", out)


def gen_cpython(out: Path) -> None:
    _cgen(out, "cpython")


def gen_tables(out: Path) -> None:
    _load_tool("osdk_tables_tool", TOOLS / "tables.py").write(out)


def gen_wireshark(out: Path) -> None:
    _load_tool("osdk_wiresharkgen", TOOLS / "wiresharkgen" / "generate.py").write(out)


# target -> (directory under generated/, generator writing into a fresh directory)
TARGETS: dict[str, tuple[Path, Callable[[Path], None]]] = {
    "python": (Path("python"), gen_python),
    "javascript": (Path("javascript"), gen_javascript),
    "java": (Path("java"), gen_java),
    "go": (Path("go"), gen_go),
    "c": (Path("c"), gen_c),
    "cpython": (Path("cpython"), gen_cpython),
    "tables": (Path("tables"), gen_tables),
    "wireshark": (Path("wireshark"), gen_wireshark),
}


def generate(target: str, out: Path) -> None:
    _fresh(out)
    TARGETS[target][1](out)


def differences(a: Path, b: Path) -> list[str]:
    diffs: list[str] = []
    # build output a user's own build leaves in a package directory (Maven's target/)
    cmp = filecmp.dircmp(a, b, ignore=["__pycache__", "target", "node_modules", "build"])
    diffs += [f"only in checked-in tree: {n}" for n in cmp.left_only]
    diffs += [f"missing from checked-in tree: {n}" for n in cmp.right_only]
    _, mismatch, errors = filecmp.cmpfiles(a, b, cmp.common_files, shallow=False)
    diffs += [f"differs: {n}" for n in mismatch + errors]
    for sub in cmp.common_dirs:
        diffs += differences(a / sub, b / sub)
    return diffs


def drift_of(target: str) -> list[str]:
    """How generated/ differs from what spec/ gives for `target`."""
    dest = GENERATED / TARGETS[target][0]
    with tempfile.TemporaryDirectory() as tmp:
        scratch = Path(tmp) / "out"
        generate(target, scratch)
        if not dest.exists():
            return [f"{target}: {dest.relative_to(ROOT)} does not exist"]
        return [f"{target}: {d}" for d in differences(dest, scratch)]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="fail if spec/ is not what rules.yaml gives or generated/ is not what spec/ produces")
    ap.add_argument("--target", action="append", choices=sorted(TARGETS), help="limit to these targets")
    args = ap.parse_args(argv)
    targets = args.target or list(TARGETS)
    profile_ksy = _load_tool("osdk_gen_profile_ksy", TOOLS / "gen_profile_ksy.py")
    drift: list[str] = []
    if args.check:
        drift += [f"spec: {d}" for d in profile_ksy.drift()]
        # each target in a process of its own: most of the time is spent waiting for the
        # Kaitai compiler and gcc, which then run side by side
        with ProcessPoolExecutor(max_workers=os.cpu_count() or 1,
                                 mp_context=multiprocessing.get_context("fork")) as pool:
            for found in pool.map(drift_of, targets):
                drift += found
    else:
        for path in profile_ksy.write():
            done = "->" if path.exists() else "removed"
            print(f"regen: spec (rules.yaml profiles) {done} {path.relative_to(ROOT)}")
        for target in targets:
            dest = GENERATED / TARGETS[target][0]
            generate(target, dest)
            print(f"regen: {target} -> {dest.relative_to(ROOT)}")
    if drift:
        print("regen: spec/ or generated/ is out of date (run `make regen`):", file=sys.stderr)
        for d in drift:
            print(f"  {d}", file=sys.stderr)
        return 1
    if args.check:
        print(f"regen: spec/ matches rules.yaml, and generated/ matches spec/ for {', '.join(targets)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
