#!/usr/bin/env python3
"""Regenerate generated/ from spec/*.ksy with the pinned Kaitai compiler.

usage: tools/regen.py [--check] [--target python ...]

--check regenerates into a scratch directory and fails (exit 1) when the
result differs from what is checked in, so CI catches hand edits and specs
that changed without regeneration.
"""
from __future__ import annotations

import argparse
import filecmp
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "spec"
GENERATED = ROOT / "generated"
DRIVER = ROOT / "tools" / "ksc" / "compile.js"

# Where each Kaitai target's output lives, relative to generated/.
TARGETS = {
    "python": Path("python") / "osdk_kaitai",
}

PY_INIT = '''"""Parsers generated from spec/*.ksy by tools/regen.py. Do not edit."""
'''


def ksy_files() -> list[Path]:
    return sorted(SPEC.glob("*.ksy"))


def generate(target: str, out: Path) -> None:
    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)
    cmd = ["node", str(DRIVER), "--target", target, "--out", str(out)]
    if target == "python":
        cmd += ["--python-package", "osdk_kaitai"]
    cmd += [str(p) for p in ksy_files()]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode != 0:
        sys.stderr.write(proc.stderr)
        raise SystemExit(f"regen: the Kaitai compiler failed for {target}")
    if target == "python":
        (out / "__init__.py").write_text(PY_INIT)


def differences(a: Path, b: Path) -> list[str]:
    diffs: list[str] = []
    cmp = filecmp.dircmp(a, b)
    diffs += [f"only in checked-in tree: {n}" for n in cmp.left_only]
    diffs += [f"missing from checked-in tree: {n}" for n in cmp.right_only]
    _, mismatch, errors = filecmp.cmpfiles(a, b, cmp.common_files, shallow=False)
    diffs += [f"differs: {n}" for n in mismatch + errors]
    for sub in cmp.common_dirs:
        diffs += differences(a / sub, b / sub)
    return diffs


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="fail if generated/ is not what the spec produces")
    ap.add_argument("--target", action="append", choices=sorted(TARGETS), help="limit to these targets")
    args = ap.parse_args(argv)
    targets = args.target or sorted(TARGETS)
    drift: list[str] = []
    for target in targets:
        dest = GENERATED / TARGETS[target]
        if args.check:
            with tempfile.TemporaryDirectory() as tmp:
                scratch = Path(tmp) / "out"
                generate(target, scratch)
                if not dest.exists():
                    drift.append(f"{target}: {dest.relative_to(ROOT)} does not exist")
                else:
                    drift += [f"{target}: {d}" for d in differences(dest, scratch)]
        else:
            generate(target, dest)
            print(f"regen: {target} -> {dest.relative_to(ROOT)}")
    if drift:
        print("regen: generated/ is out of date with spec/ (run `make regen`):", file=sys.stderr)
        for d in drift:
            print(f"  {d}", file=sys.stderr)
        return 1
    if args.check:
        print(f"regen: generated/ matches spec/ for {', '.join(targets)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
