"""`osdkc spec check`: everything that must hold for spec/ to be usable.

Each check prints one line, "ok", "FAIL" or "skip" (what ran passed, but a
part could not run: the trace without a seed); the exit status is 1 when any
fails. The same checks run in the test suite; this command is for people
editing spec/.
"""
from __future__ import annotations

import argparse
import subprocess
import sys
from typing import Callable, Sequence

from osdk_conformance.core import ksy
from osdk_conformance.core.paths import ROOT, needs_checkout
from osdk_conformance.core.rules import load_rules
from osdk_conformance.traceability.trace import add_seed_argument
from osdk_conformance.traceability.trace import check, errata_ids, seed_from


def _generated_in_sync() -> str:
    if why := needs_checkout("compiling the .ksy files and comparing generated/ with them"):
        index = ksy.load()
        raise Skipped(f"{len(index.files)} .ksy files read; {why}")
    proc = subprocess.run([sys.executable, str(ROOT / "tools" / "regen.py"), "--check"],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        raise RuntimeError((proc.stderr or proc.stdout).strip())
    return "every .ksy compiles with no warning, and generated/ matches"


def _rules() -> str:
    rules = load_rules()
    counts = {c: 0 for c in ("documented", "undocumented", "later_firmware", "invalid")}
    for b in range(256):
        counts[rules.classify_control_mode(b, "a3-fw3.1")["classification"]] += 1
    return "rules.yaml validates; mode bytes (a3-fw3.1): " + ", ".join(f"{k} {v}" for k, v in counts.items())


class Skipped(Exception):
    """A check whose every part that ran passed, but a part did not run; the
    message says what ran and what did not."""


def _trace(seed: str | None) -> str:
    report = check(seed_path=seed_from(seed))
    if not report.ok:
        bad = [e.id for e in report.entries if e.problems]
        raise RuntimeError(f"{len(bad)} broken entries ({', '.join(bad[:10])}), "
                           f"{len(report.problems)} other problems, "
                           f"{len(report.uncovered)} uncovered seed lines; run `osdkc spec trace`")
    if report.skipped:
        raise Skipped(f"trace.yaml maps {len(report.entries)} seed entries to spec elements that all exist; "
                      f"{report.skipped}")
    return f"trace.yaml maps {len(report.entries)} seed entries, all {report.nonblank} non-blank seed lines covered"


def _errata() -> str:
    ids = sorted(errata_ids(), key=lambda s: int(s[1:]))
    if not ids:
        raise RuntimeError("spec/ERRATA.md has no entries")
    return f"ERRATA.md has {len(ids)} entries ({ids[0]}..{ids[-1]})"


def _checks(args: argparse.Namespace | None) -> list[tuple[str, Callable[[], str]]]:
    seed = getattr(args, "seed", None)
    return [
        ("ksy", _generated_in_sync),
        ("rules", _rules),
        ("trace", lambda: _trace(seed)),
        ("errata", _errata),
    ]


def add_arguments(p: argparse.ArgumentParser, profiles: Sequence[str] = ()) -> None:
    add_seed_argument(p)


def run_spec_check(args: argparse.Namespace | None = None) -> int:
    failed: list[str] = []
    skipped: list[str] = []
    for name, fn in _checks(args):
        try:
            print(f"  ok    {name:<7} {fn()}")
        except Skipped as e:
            skipped.append(name)
            print(f"  skip  {name:<7} {e}")
        except Exception as e:  # each check reports its own failure; no traceback for users
            failed.append(name)
            print(f"  FAIL  {name:<7} {e}")
    verdict = f"{len(failed)} failed" if failed else "all passed"
    if skipped:
        verdict += f" (partly skipped: {', '.join(skipped)})"
    print("spec check: " + verdict)
    return 1 if failed else 0
