#!/usr/bin/env python3
"""Generate the golden vectors in vectors/ (format: vectors/FORMAT.md).

usage: tools/gen_vectors.py [--out DIR] [--suite NAME ...] [--check]

Deterministic: every suite draws from its own random.Random(seed), ids are
stable, and files are written with sorted keys, so the same spec gives the
same bytes. `expected` comes from osdk_conformance.reference.codec.answer, except
for hand-written edge cases (the worked frames of PROTOCOL-FACTS, the
latitude/longitude order, ...), whose expected value is written out by hand
from the spec and checked against the reference: any disagreement stops the
generator. The suites are built by the modules of tools/vectorgen/, one per
vector file (vectorgen/__init__.py lists them).

Layout of a file: the suite header and groups are indented; each test is
one line of compact JSON (one line per case keeps 30,000 cases diffable
and the files under 30 MB; the bytes are still a pure function of the spec).

--check regenerates into a scratch directory and fails (exit 1) when the
result differs from vectors/, byte for byte (with --suite: those suites'
files only). --suite limits generation to the named suites; MANIFEST.json of
the output directory is rewritten over the suite files it then holds.
"""
from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))  # a checkout run without the package installed still finds it

from osdk_conformance.harness.vectors import VECTORS_DIR  # noqa: E402
from vectorgen.builder import GenerationError  # noqa: E402 - tools/, the script's directory, is on sys.path
from vectorgen.driver import SUITES, differences, generate  # noqa: E402


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, help="write here instead of vectors/")
    ap.add_argument("--suite", action="append", choices=sorted(SUITES), help="only this suite (repeatable)")
    ap.add_argument("--check", action="store_true", help="regenerate into a scratch directory and compare with vectors/")
    args = ap.parse_args(argv)
    suites = args.suite or list(SUITES)
    t0 = time.perf_counter()
    try:
        if args.check:
            bad, compared = differences(suites, whole=not args.suite)
            if bad:
                print("gen_vectors --check: vectors/ differs from what the spec generates: " + ", ".join(bad)
                      + "\n  run: .venv/bin/python tools/gen_vectors.py", file=sys.stderr)
                return 1
            print(f"gen_vectors --check: vectors/ is up to date ({compared} files, {time.perf_counter() - t0:.1f} s)")
            return 0
        counts = generate(args.out or VECTORS_DIR, suites)
        print(f"gen_vectors: {sum(counts.values())} cases in {len(counts)} files, {time.perf_counter() - t0:.1f} s")
        return 0
    except GenerationError as e:
        print(f"gen_vectors: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    raise SystemExit(main())
