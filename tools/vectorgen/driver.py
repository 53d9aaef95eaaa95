"""Writing the suites: one file per suite and MANIFEST.json, or a byte
comparison with vectors/ (--check)."""
from __future__ import annotations

import filecmp
import hashlib
import tempfile
import time
from pathlib import Path
from typing import Callable

from osdk_conformance.harness.vectors import VECTORS_DIR, dump_suite, manifest_text

from .broadcast import gen_broadcast
from .builder import Suite
from .control_mode import gen_control_mode
from .control_ranges import gen_control_ranges
from .encode import gen_encode
from .frames import gen_frames
from .payloads import gen_payloads
from .streams import gen_streams

SUITES: dict[str, Callable[[], Suite]] = {
    "control_mode": gen_control_mode,
    "control_ranges": gen_control_ranges,
    "broadcast": gen_broadcast,
    "payloads": gen_payloads,
    "frames": gen_frames,
    "streams": gen_streams,
    "encode": gen_encode,
}
"""Every suite by name (its file is vectors/<name>.json), in generation order."""


def generate(out: Path, suites: list[str], manifest: bool = True, verbose: bool = True) -> dict[str, int]:
    """Write the suites' files (and MANIFEST.json over every suite file in
    `out`) and return the number of cases of each."""
    out.mkdir(parents=True, exist_ok=True)
    counts: dict[str, int] = {}
    for name in suites:
        t0 = time.perf_counter()
        suite = SUITES[name]()
        text = dump_suite(suite.document())
        (out / f"{name}.json").write_text(text, encoding="utf-8")
        counts[name] = sum(len(t) for t in suite.groups.values())
        if verbose:
            print(f"  {name:<15} {counts[name]:>6} cases  {len(text.encode()) / 1e6:6.2f} MB  "
                  f"{time.perf_counter() - t0:5.1f} s")
    if manifest:
        files = sorted(p.name for p in out.glob("*.json")
                       if p.name != "MANIFEST.json" and not p.name.endswith(".schema.json"))
        digests = {f: hashlib.sha256((out / f).read_bytes()).hexdigest() for f in files}
        (out / "MANIFEST.json").write_text(manifest_text(digests), encoding="utf-8")
    return counts


def differences(suites: list[str], whole: bool) -> tuple[list[str], int]:
    """Regenerate into a scratch directory: (the files that differ from
    vectors/ or are missing there, the number of files compared). `whole`:
    every suite, so MANIFEST.json is compared too and a file in vectors/
    that no suite writes counts as a difference."""
    with tempfile.TemporaryDirectory() as tmp:
        generate(Path(tmp), suites, manifest=whole, verbose=False)
        names = [f"{n}.json" for n in suites] + (["MANIFEST.json"] if whole else [])
        bad = [n for n in names if not (VECTORS_DIR / n).exists()
               or not filecmp.cmp(Path(tmp) / n, VECTORS_DIR / n, shallow=False)]
    if whole:
        extra = {p.name for p in VECTORS_DIR.glob("*.json")} - set(names) - {"vectors.schema.json"}
        bad += [f"{n} (not generated)" for n in sorted(extra)]
    return bad, len(names)
