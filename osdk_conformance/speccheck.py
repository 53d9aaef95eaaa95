"""`osdkc spec check`: everything that must hold for spec/ to be usable.

Each check prints one line; the exit status is 1 when any fails. The same
checks run in the test suite; this command is for people editing spec/.
"""
from __future__ import annotations

import argparse
import subprocess
import sys
from typing import Callable

from .paths import ROOT


def _generated_in_sync() -> str:
    proc = subprocess.run([sys.executable, str(ROOT / "tools" / "regen.py"), "--check"],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        raise RuntimeError((proc.stderr or proc.stdout).strip())
    return "every .ksy compiles with no warning, and generated/ matches"


def _rules() -> str:
    from .rules import load_rules

    rules = load_rules()
    counts = {c: 0 for c in ("documented", "undocumented", "later_firmware", "invalid")}
    for b in range(256):
        counts[rules.classify_control_mode(b, "a3-fw3.1")["classification"]] += 1
    return "rules.yaml validates; mode bytes (a3-fw3.1): " + ", ".join(f"{k} {v}" for k, v in counts.items())


def _trace() -> str:
    from .trace import check

    report = check()
    if not report.ok:
        bad = [e.id for e in report.entries if e.problems]
        raise RuntimeError(f"{len(bad)} broken entries ({', '.join(bad[:10])}), "
                           f"{len(report.uncovered)} uncovered seed lines; run `osdkc spec trace`")
    return f"trace.yaml maps {len(report.entries)} seed entries, all {report.nonblank} non-blank seed lines covered"


def _errata() -> str:
    from .trace import errata_ids

    ids = sorted(errata_ids(), key=lambda s: int(s[1:]))
    if not ids:
        raise RuntimeError("spec/ERRATA.md has no entries")
    return f"ERRATA.md has {len(ids)} entries ({ids[0]}..{ids[-1]})"


CHECKS: list[tuple[str, Callable[[], str]]] = [
    ("ksy", _generated_in_sync),
    ("rules", _rules),
    ("trace", _trace),
    ("errata", _errata),
]


def run_spec_check(args: argparse.Namespace | None = None) -> int:
    failed = 0
    for name, fn in CHECKS:
        try:
            print(f"  ok    {name:<7} {fn()}")
        except Exception as e:  # each check reports its own failure; no traceback for users
            failed += 1
            print(f"  FAIL  {name:<7} {e}")
    print("spec check: " + ("all passed" if not failed else f"{failed} failed"))
    return 1 if failed else 0
