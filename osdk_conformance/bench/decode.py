"""The decode section of `osdkc bench`: every implementation's bench mode
(conformance/PROTOCOL.md, "Bench mode") on every corpus, best of N runs,
and the cross-check of what each one counted.

Runs are interleaved (every implementation once, then the next round), so
a change in the load of a shared machine spreads over all of them instead
of falling on one. An implementation whose runs add up to more than the
time budget runs no more rounds (its row says how many it had). Peak RSS
is the child's own ru_maxrss (os.wait4), the largest over its runs.
"""
from __future__ import annotations

import json
import sys
from dataclasses import dataclass, field
from typing import TextIO

from osdk_conformance.bench import child as bench_child
from osdk_conformance.bench.corpus import Corpus
from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.paths import ROOT
from osdk_conformance.harness.runner import BUILD_HINT, BUNDLED_IMPLS, impl_argv

BASELINE = "baseline"
BASELINE_BIN = ROOT / "conformance" / "baseline" / "build" / "osdk-baseline"
COUNTS = ("bytes", "frames", "errors", "garbage_bytes")


def impl_names() -> list[str]:
    return [BASELINE, *BUNDLED_IMPLS]


def bench_argv(name: str) -> list[str]:
    """The command that starts an implementation; its bench mode is this plus `--bench FILE --profile P`."""
    if name == BASELINE:
        if not BASELINE_BIN.exists():
            raise UsageError(f"the baseline is not built ({BASELINE_BIN} is missing); {BUILD_HINT}")
        return [str(BASELINE_BIN)]
    return impl_argv(name)


@dataclass
class Row:
    impl: str
    seconds: list[float] = field(default_factory=list)   # the loop time each run reported
    walls: list[float] = field(default_factory=list)     # start to exit, as the harness saw it
    maxrss_kib: int = 0
    counts: dict[str, int] | None = None
    error: str = ""

    def result(self, corpus: Corpus, baseline_mb_s: float | None) -> dict:
        out: dict = {"impl": self.impl, "ok": not self.error and bool(self.seconds), "runs": len(self.seconds)}
        if self.error:
            out["error"] = self.error
        if self.counts is not None:
            out["counts"] = self.counts
        if not self.seconds:
            return out
        best = min(self.seconds)
        mb_s = corpus.bytes / best / 1e6 if best > 0 else None
        out.update({
            "seconds": best, "wall_seconds": round(min(self.walls), 3),
            "frames_per_s": round(self.counts["frames"] / best) if best > 0 else None,
            "mb_per_s": round(mb_s, 2) if mb_s else None,
            "peak_rss_mib": round(self.maxrss_kib / 1024, 1),
            "ratio_to_baseline": round(mb_s / baseline_mb_s, 3) if mb_s and baseline_mb_s else None,
        })
        return out


def parse_result(child: bench_child.Child, profile: str) -> tuple[dict | None, str]:
    """(the result line, "") or (None, why there is none)."""
    if child.problem:
        return None, child.problem
    if child.code != 0:
        return None, f"exit {child.code}: {child.stderr_line() or 'no message'}"
    lines = [ln for ln in child.stdout.splitlines() if ln.strip()]
    if not lines:
        return None, "no result line (no bench mode?)"
    if len(lines) > 1:
        return None, f"{len(lines)} lines of output, the bench mode prints one"
    try:
        obj = json.loads(lines[0])
    except ValueError:
        return None, f"the result line is not JSON: {lines[0][:80]}"
    if not isinstance(obj, dict):
        return None, "the result line is not a JSON object"
    bad = [k for k in COUNTS if not (isinstance(obj.get(k), int) and not isinstance(obj.get(k), bool) and obj[k] >= 0)]
    secs = obj.get("seconds")
    if not isinstance(secs, (int, float)) or isinstance(secs, bool) or secs < 0:
        bad.append("seconds")
    if bad:
        return None, f"the result line lacks or garbles {', '.join(bad)}"
    if obj.get("profile") != profile:
        return None, f"the result is for profile {obj.get('profile')!r}, not {profile}"
    return obj, ""


def measure(corpora: list[Corpus], impls: list[str], repeats: int, timeout: float, budget: float,
            log: TextIO = sys.stderr) -> dict:
    """The decode section's results: per corpus, one row per implementation, and the mismatches."""
    argvs: dict[str, list[str] | str] = {}
    for name in impls:
        try:
            argvs[name] = bench_argv(name)
        except UsageError as e:
            argvs[name] = str(e)
    out: dict = {"repeats": repeats, "budget_seconds": budget, "corpora": [], "mismatches": []}
    for corpus in corpora:
        rows = {name: Row(name, error=a if isinstance(a, str) else "") for name, a in argvs.items()}
        for r in range(repeats):
            for name, row in rows.items():
                if row.error or (r and sum(row.walls) > budget):
                    continue
                child = bench_child.run([*argvs[name], "--bench", corpus.path, "--profile", corpus.profile], timeout,
                                        peak_rss=True)
                obj, why = parse_result(child, corpus.profile)
                if obj is None:
                    row.error = why
                    log.write(f"  {corpus.name}: {name}: {why}\n")
                    continue
                counts = {k: obj[k] for k in COUNTS}
                if row.counts is not None and counts != row.counts:
                    row.error = f"counts differ between runs: {row.counts} then {counts}"
                    continue
                row.counts = counts
                row.seconds.append(float(obj["seconds"]))
                row.walls.append(child.wall)
                row.maxrss_kib = max(row.maxrss_kib, child.maxrss_kib)
                log.write(f"  {corpus.name}: {name} run {r + 1}: {obj['seconds']:.3f} s\n")
                log.flush()
        base = rows.get(BASELINE)
        base_mb_s = corpus.bytes / min(base.seconds) / 1e6 if base and base.seconds and min(base.seconds) > 0 else None
        results = [row.result(corpus, base_mb_s) for row in rows.values()]
        expected = corpus.expected() if corpus.frames is not None else None
        out["mismatches"] += cross_check(corpus, results, expected)
        out["corpora"].append({**_describe(corpus), "results": results})
    return out


def cross_check(corpus: Corpus, results: list[dict], expected: dict | None) -> list[str]:
    """One line per implementation whose counts differ from the corpus's (or, for an input of
    unknown content, from the first implementation's)."""
    counted = [r for r in results if r.get("counts") is not None]
    if expected is None:
        if not counted:
            return []
        expected, source = counted[0]["counts"], counted[0]["impl"]
    else:
        source = "the corpus generator"
    out = []
    for r in counted:
        r["agrees"] = r["counts"] == expected
        if not r["agrees"]:
            diff = ", ".join(f"{k} {r['counts'][k]} (want {expected[k]})"
                             for k in COUNTS if r["counts"][k] != expected[k])
            out.append(f"{corpus.name}: {r['impl']} counts {diff}, per {source}")
    return out


def _describe(c: Corpus) -> dict:
    return {"name": c.name, "profile": c.profile, "corpus_seconds": c.seconds, "description": c.description,
            "path": c.path, "bytes": c.bytes,
            "expected": c.expected() if c.frames is not None else None}
