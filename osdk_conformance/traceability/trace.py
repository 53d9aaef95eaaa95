"""Traceability from the seed to the spec (spec/trace.yaml).

Every non-blank line of the seed must be covered, either by an entry that
maps a quoted piece of it to spec elements that exist, or by a `no_content`
range that says why the line carries no fact (a heading, a blank table cell,
OCR debris already covered by an errata entry). The trace is bound to the
seed's SHA-256: if the seed changes, the trace must be reviewed.

The seed is a source, not part of the repository: it is an input (--seed
FILE, or $OSDK_SEED). Without it the checks that need its text (the hash,
each quote in its lines, every line covered) are skipped and reported as
skipped; the rest (every spec reference resolves, ids unique, every
no_content range explained) always runs.

Spec references:
  file.ksy                       a .ksy file
  file.ksy#type  / #type.field   a type, or a field, instance or param of it
  file.ksy#enum:name[.label]     an enum, or one of its values
  rules.yaml#/json/pointer       a node in the rules file
  ERRATA.md#E07                  an errata entry
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import re
from dataclasses import dataclass, field
from typing import Sequence
from pathlib import Path

import yaml

from osdk_conformance.core import ksy, rules
from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.paths import SEED_ENV, SPEC

TRACE = SPEC / "trace.yaml"
ERRATA = SPEC / "ERRATA.md"
RULES = SPEC / "rules.yaml"
SEED_CHECKS = "the checks against the seed (its SHA-256, each quote in its lines, every line covered)"


class TraceError(Exception):
    pass


@dataclass
class Entry:
    id: str
    lines: tuple[int, int]
    kind: str
    seed: str
    spec: list[str]
    problems: list[str] = field(default_factory=list)


@dataclass
class Report:
    entries: list[Entry]
    uncovered: list[int]
    problems: list[str]
    nonblank: int | None  # None: no seed, so neither counted nor checked
    seed: Path | None

    @property
    def ok(self) -> bool:
        """Everything that ran passed (see `skipped` for what did not run)."""
        return not self.problems and not self.uncovered and all(not e.problems for e in self.entries)

    @property
    def skipped(self) -> str | None:
        if self.seed is not None:
            return None
        return f"{SEED_CHECKS} did not run: no seed given (--seed FILE, or set {SEED_ENV})"


def _norm(text: str) -> str:
    return re.sub(r"\s+", " ", text).strip()


def _pointer(doc: object, pointer: str) -> bool:
    node = doc
    if pointer in ("", "/"):
        return True
    for raw in pointer.lstrip("/").split("/"):
        part = raw.replace("~1", "/").replace("~0", "~")
        if isinstance(node, dict):
            if part in node:
                node = node[part]
            elif part.lstrip("-").isdigit() and int(part) in node:
                node = node[int(part)]
            else:
                return False
        elif isinstance(node, list) and part.isdigit() and int(part) < len(node):
            node = node[int(part)]
        else:
            return False
    return True


def errata_ids(path: Path = ERRATA) -> set[str]:
    """The ERRATA.md entry ids; none when the file is missing (the trace reports that itself)."""
    return rules.errata_ids(path) if path.exists() else set()


class Resolver:
    def __init__(self) -> None:
        self.index = ksy.load()
        self.rules = yaml.load(RULES.read_text(), Loader=ksy.SafeLoader) if RULES.exists() else {}  # noqa: S506
        self.errata = errata_ids()

    def exists(self, ref: str) -> bool:
        target, _, frag = ref.partition("#")
        if target.endswith(".ksy"):
            return self.index.element_exists(ref)
        if target == "rules.yaml":
            return _pointer(self.rules, frag)
        if target == "ERRATA.md":
            return frag in self.errata
        return False


def seed_from(arg: str | None) -> Path | None:
    """The seed named by --seed, else by $OSDK_SEED; None when neither names one."""
    raw, source = (arg, "--seed") if arg else (os.environ.get(SEED_ENV, ""), SEED_ENV)
    if not raw:
        return None
    path = Path(raw).expanduser()
    if not path.is_file():
        raise UsageError(f"seed {path} (from {source}) not found")
    return path


def _load(trace_path: Path) -> dict:
    if not trace_path.exists():
        raise TraceError(f"{trace_path} does not exist")
    try:
        doc = yaml.load(trace_path.read_text(encoding="utf-8"), Loader=ksy.SafeLoader)  # noqa: S506 - a safe loader
    except yaml.YAMLError as e:
        raise TraceError(f"{trace_path.name}: not valid YAML: {e}") from None
    if not isinstance(doc, dict):
        raise TraceError(f"{trace_path.name}: not a mapping with seed_sha256, entries and no_content")
    for key in ("entries", "no_content"):
        items = doc.get(key) or []
        if not isinstance(items, list) or not all(isinstance(item, dict) for item in items):
            raise TraceError(f"{trace_path.name}: {key} is not a list of mappings")
    return doc


def _span(raw: dict) -> tuple[int, int]:
    lines = raw.get("lines")
    if (isinstance(lines, (list, tuple)) and len(lines) == 2
            and all(isinstance(n, int) and not isinstance(n, bool) for n in lines)):
        return lines[0], lines[1]
    return 0, 0  # reported as not a range of seed lines


def _entries(doc: dict) -> list[Entry]:
    """The entries, each with the problems that need no seed to see."""
    resolver = Resolver()
    entries: list[Entry] = []
    seen: set[str] = set()
    for raw in doc.get("entries", []) or []:
        e = Entry(id=str(raw.get("id")), lines=_span(raw), kind=str(raw.get("kind")),
                  seed=str(raw.get("seed", "")), spec=list(raw.get("spec", []) or []))
        if e.id in seen:
            e.problems.append("duplicate id")
        seen.add(e.id)
        first, last = e.lines
        if not 1 <= first <= last:
            e.problems.append(f"lines {first}-{last} are not a range of seed lines")
        if not e.spec:
            e.problems.append("maps to nothing")
        e.problems += [f"no such spec element: {ref}" for ref in e.spec if not resolver.exists(ref)]
        entries.append(e)
    return entries


def _read_seed(seed_path: Path) -> bytes:
    if not seed_path.is_file():
        raise TraceError(f"seed {seed_path} not found")
    seed_bytes = seed_path.read_bytes()
    try:
        seed_bytes.decode("utf-8")
    except UnicodeDecodeError:
        raise TraceError(f"seed {seed_path} is not UTF-8 text") from None
    return seed_bytes


def _against_seed(doc: dict, entries: list[Entry], seed_bytes: bytes) -> tuple[list[str], list[int], int]:
    """Problems, uncovered line numbers and the count of non-blank lines, of
    the trace held against the seed: its hash, each quote in its lines, and
    every non-blank line covered."""
    seed_lines = seed_bytes.decode("utf-8").split("\n")
    problems: list[str] = []
    digest = hashlib.sha256(seed_bytes).hexdigest()
    if doc.get("seed_sha256") != digest:
        problems.append(f"seed_sha256 is {doc.get('seed_sha256')}, the seed's is {digest}: review the trace")
    covered: set[int] = set()
    for e in entries:
        first, last = e.lines
        if not 1 <= first <= last:
            continue  # already reported
        if last > len(seed_lines):
            e.problems.append(f"lines {first}-{last} outside the seed")
            continue
        if _norm(e.seed) not in _norm(" ".join(seed_lines[first - 1:last])):
            e.problems.append(f"quote not found in seed lines {first}-{last}")
        covered.update(range(first, last + 1))
    for rng in doc.get("no_content", []) or []:
        first, last = _span(rng)
        covered.update(range(first, last + 1))
    nonblank = [i + 1 for i, line in enumerate(seed_lines) if line.strip()]
    return problems, [n for n in nonblank if n not in covered], len(nonblank)


def _no_content_problems(doc: dict) -> list[str]:
    problems = []
    for rng in doc.get("no_content", []) or []:
        first, last = _span(rng)
        if not 1 <= first <= last:
            problems.append(f"no_content lines {first}-{last} are not a range of seed lines")
        if not rng.get("why"):
            problems.append(f"no_content {first}-{last} gives no reason")
    return problems


def check(trace_path: Path = TRACE, seed_path: Path | None = None) -> Report:
    """The trace checked: every reference resolves and every no_content range
    says why; with a seed, also everything of `_against_seed`."""
    doc = _load(trace_path)
    entries = _entries(doc)
    problems = _no_content_problems(doc)
    if seed_path is None:
        return Report(entries=entries, uncovered=[], problems=problems, nonblank=None, seed=None)
    seed_problems, uncovered, nonblank = _against_seed(doc, entries, _read_seed(seed_path))
    return Report(entries=entries, uncovered=uncovered, problems=problems + seed_problems,
                  nonblank=nonblank, seed=seed_path)


def _clip(text: str, width: int) -> str:
    text = _norm(text)
    return text if len(text) <= width else text[: width - 1] + "…"


def _print_json(report: Report) -> None:
    print(json.dumps({
        "ok": report.ok,
        "seed": None if report.seed is None else str(report.seed),
        "skipped": report.skipped,
        "seed_nonblank_lines": report.nonblank,
        "uncovered_lines": None if report.seed is None else report.uncovered,
        "problems": report.problems,
        "entries": [e.__dict__ | {"lines": list(e.lines)} for e in report.entries],
    }, indent=2))


def _print_table(report: Report) -> None:
    print(f"{'id':<6} {'lines':<9} {'kind':<11} {'seed':<44} spec")
    for e in report.entries:
        status = "" if not e.problems else "  !! " + "; ".join(e.problems)
        lines = f"{e.lines[0]}-{e.lines[1]}" if e.lines[0] != e.lines[1] else str(e.lines[0])
        print(f"{e.id:<6} {lines:<9} {e.kind:<11} {_clip(e.seed, 44):<44} {', '.join(e.spec)}{status}")
    mapped = sum(1 for e in report.entries if not e.problems)
    kinds: dict[str, int] = {}
    for e in report.entries:
        kinds[e.kind] = kinds.get(e.kind, 0) + 1
    print()
    print(f"seed entries: {len(report.entries)} ({', '.join(f'{k} {v}' for k, v in sorted(kinds.items()))}); "
          f"mapped: {mapped}; unmapped or broken: {len(report.entries) - mapped}")
    if report.nonblank is None:
        print(f"seed lines: SKIPPED, {report.skipped}")
    else:
        print(f"seed lines: {report.nonblank} non-blank, {report.nonblank - len(report.uncovered)} covered, "
              f"{len(report.uncovered)} uncovered{': ' + ', '.join(map(str, report.uncovered)) if report.uncovered else ''}")
    for p in report.problems:
        print(f"problem: {p}")
    print(_verdict(report))


def _verdict(report: Report) -> str:
    if not report.ok:
        return "trace: FAILED"
    if report.skipped:
        return "trace: OK as far as checked (every spec reference resolves); SKIPPED the checks against the seed"
    return "trace: OK, every seed entry is mapped"


def add_seed_argument(p: argparse.ArgumentParser) -> None:
    """--seed, shared by every command that runs the trace (spec trace, spec check, kit)."""
    p.add_argument("--seed", metavar="FILE",
                   help="the seed text spec/trace.yaml maps (not in the repository; default: $OSDK_SEED). "
                        "Without one, the trace's checks against the seed are skipped, and the output says so")


def add_arguments(p: argparse.ArgumentParser, profiles: Sequence[str] = ()) -> None:
    p.add_argument("--json", action="store_true", help="print the table as JSON")
    add_seed_argument(p)


def run_trace(args: argparse.Namespace) -> int:
    """Exit 0 when every check that ran passed (without a seed, the checks
    against it are skipped and the output says so), 1 when one failed, 2 when
    the trace or the seed named cannot be read."""
    try:
        report = check(seed_path=seed_from(getattr(args, "seed", None)))
    except TraceError as e:
        raise UsageError(str(e)) from None
    (_print_json if getattr(args, "json", False) else _print_table)(report)
    return 0 if report.ok else 1
