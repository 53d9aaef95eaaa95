"""Traceability from the seed to the spec (spec/trace.yaml).

Every non-blank line of the seed must be covered, either by an entry that
maps a quoted piece of it to spec elements that exist, or by a `no_content`
range that says why the line carries no fact (a heading, a blank table cell,
OCR debris already covered by an errata entry). The trace is bound to the
seed's SHA-256: if the seed changes, the trace must be reviewed.

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
import re
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from . import ksy
from .errors import UsageError
from .paths import SEED, SPEC

TRACE = SPEC / "trace.yaml"
ERRATA = SPEC / "ERRATA.md"
RULES = SPEC / "rules.yaml"


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
    nonblank: int

    @property
    def ok(self) -> bool:
        return not self.problems and not self.uncovered and all(not e.problems for e in self.entries)


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
    if not path.exists():
        return set()
    return set(re.findall(r"^## (E\d+):", path.read_text(), flags=re.M))


class Resolver:
    def __init__(self) -> None:
        self.index = ksy.load()
        self.rules = yaml.safe_load(RULES.read_text()) if RULES.exists() else {}
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


def check(trace_path: Path = TRACE, seed_path: Path = SEED) -> Report:
    if not trace_path.exists():
        raise TraceError(f"{trace_path} does not exist")
    if not seed_path.exists():
        raise TraceError(f"seed {seed_path} not found")
    try:
        doc = yaml.safe_load(trace_path.read_text())
    except yaml.YAMLError as e:
        raise TraceError(f"{trace_path.name}: not valid YAML: {e}") from None
    seed_bytes = seed_path.read_bytes()
    seed_lines = seed_bytes.decode("utf-8").split("\n")
    problems: list[str] = []
    digest = hashlib.sha256(seed_bytes).hexdigest()
    if doc.get("seed_sha256") != digest:
        problems.append(f"seed_sha256 is {doc.get('seed_sha256')}, the seed's is {digest}: review the trace")
    resolver = Resolver()
    covered: set[int] = set()
    entries: list[Entry] = []
    seen: set[str] = set()
    for raw in doc.get("entries", []) or []:
        e = Entry(id=str(raw.get("id")), lines=tuple(raw.get("lines", (0, 0))), kind=str(raw.get("kind")),
                  seed=str(raw.get("seed", "")), spec=list(raw.get("spec", []) or []))
        if e.id in seen:
            e.problems.append("duplicate id")
        seen.add(e.id)
        first, last = e.lines
        if not (1 <= first <= last <= len(seed_lines)):
            e.problems.append(f"lines {first}-{last} outside the seed")
        else:
            text = _norm(" ".join(seed_lines[first - 1:last]))
            if _norm(e.seed) not in text:
                e.problems.append(f"quote not found in seed lines {first}-{last}")
            covered.update(range(first, last + 1))
        if not e.spec:
            e.problems.append("maps to nothing")
        for ref in e.spec:
            if not resolver.exists(ref):
                e.problems.append(f"no such spec element: {ref}")
        entries.append(e)
    for rng in doc.get("no_content", []) or []:
        first, last = rng.get("lines", (0, 0))
        if not rng.get("why"):
            problems.append(f"no_content {first}-{last} gives no reason")
        covered.update(range(first, last + 1))
    nonblank = [i + 1 for i, line in enumerate(seed_lines) if line.strip()]
    uncovered = [n for n in nonblank if n not in covered]
    return Report(entries=entries, uncovered=uncovered, problems=problems, nonblank=len(nonblank))


def _clip(text: str, width: int) -> str:
    text = _norm(text)
    return text if len(text) <= width else text[: width - 1] + "…"


def run_trace(args: argparse.Namespace) -> int:
    try:
        report = check()
    except TraceError as e:
        raise UsageError(str(e)) from None
    if getattr(args, "json", False):
        print(json.dumps({
            "ok": report.ok,
            "seed_nonblank_lines": report.nonblank,
            "uncovered_lines": report.uncovered,
            "problems": report.problems,
            "entries": [e.__dict__ | {"lines": list(e.lines)} for e in report.entries],
        }, indent=2))
        return 0 if report.ok else 1
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
    print(f"seed lines: {report.nonblank} non-blank, {report.nonblank - len(report.uncovered)} covered, "
          f"{len(report.uncovered)} uncovered{': ' + ', '.join(map(str, report.uncovered)) if report.uncovered else ''}")
    for p in report.problems:
        print(f"problem: {p}")
    print("trace: OK, every seed entry is mapped" if report.ok else "trace: FAILED")
    return 0 if report.ok else 1
