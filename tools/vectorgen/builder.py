"""The suite builder: every case goes through Suite.add, which asks the
reference for the expectation and refuses a case whose hand-written
expectation, flags or id is wrong."""
from __future__ import annotations

import json
import random

from osdk_conformance.core.rules import profile_names
from osdk_conformance.harness.spec_rules import RULES, rule_flag
from osdk_conformance.harness.vectors import ERRATA_SUMMARY, project_result, same_json
from osdk_conformance.reference import codec as reference
from osdk_conformance.traceability.trace import errata_ids

GENERATOR = "tools/gen_vectors.py"
ERRATA = errata_ids()
PROFILES = profile_names()
"""Every wire profile, in the order of their values (rules.yaml)."""


class GenerationError(Exception):
    """A hand-written expectation disagrees with the reference, or a case is malformed."""


def R(*names: str) -> list[str]:
    """The vector flags of spec rules (rules.yaml names). One letter because
    nearly every case line names its rules."""
    return [rule_flag(n) for n in names]


class Suite:
    """One vector file: its cases grouped by (operation, profile) in the order they were added."""

    def __init__(self, name: str, description: str, seed: int) -> None:
        self.name = name
        self.description = description
        self.rng = random.Random(seed)
        self.groups: dict[tuple[str, str | None], list[dict]] = {}
        self.ids: set[str] = set()
        self.used: set[str] = set()

    def add(self, op: str, profile: str | None, id: str, category: str, comment: str, input: dict,
            flags: list[str], *, expected: dict | None = None, error: str | None = None,
            acceptable: str | None = None) -> dict:
        """One case. Without `expected`/`error` the reference's answer is the
        expectation; with them (hand-written from the spec) the reference
        must agree. `acceptable=CLASS` makes a case the reference answers
        validly also pass when rejected with CLASS."""
        self._check_id_and_flags(id, flags)
        ref = reference.answer(op, profile, input)
        if "unsupported" in ref:
            raise GenerationError(f"{id}: the reference does not support {op} / {profile}")
        got_result = project_result(op, ref["result"]) if ref["ok"] else None
        if expected is not None and not (ref["ok"] and same_json(got_result, expected)):
            raise GenerationError(f"{id}: hand-written expectation disagrees with the reference\n"
                                  f"  written:   {json.dumps(expected, sort_keys=True)}\n"
                                  f"  reference: {json.dumps(ref, sort_keys=True)}")
        if error is not None and (ref["ok"] or ref["error"] != error):
            raise GenerationError(f"{id}: written error {error}, reference answered {json.dumps(ref)}")
        if acceptable is not None:
            if not ref["ok"]:
                raise GenerationError(f"{id}: acceptable case the reference rejects: {ref}")
            result, exp = "acceptable", {"value": got_result, "error": acceptable}
        elif ref["ok"]:
            result, exp = "valid", got_result
        else:
            result, exp = "invalid", {"error": ref["error"]}
        test = {"id": id, "category": category, "comment": comment, "input": input, "result": result,
                "expected": exp, "flags": sorted(set(flags))}
        self.ids.add(id)
        self.used.update(flags)
        self.groups.setdefault((op, profile), []).append(test)
        return test

    def _check_id_and_flags(self, id: str, flags: list[str]) -> None:
        if id in self.ids:
            raise GenerationError(f"duplicate id {id}")
        for f in flags:
            if f.startswith("rule:"):
                if f[5:] not in RULES:
                    raise GenerationError(f"{id}: unknown rule {f}")
            elif f not in ERRATA:
                raise GenerationError(f"{id}: unknown flag {f}")
        if not flags:
            raise GenerationError(f"{id}: no flags")

    def document(self) -> dict:
        """The suite as vectors/FORMAT.md lays out a file (notes for the flags it used)."""
        notes = {}
        for f in sorted(self.used):
            notes[f] = RULES[f[5:]] if f.startswith("rule:") else f"ERRATA {f}: {ERRATA_SUMMARY.get(f, '')}"
        groups = [{"operation": op, "profile": prof, "tests": tests} for (op, prof), tests in self.groups.items()]
        return {
            "suite": self.name, "description": self.description, "generator": GENERATOR,
            "numberOfTests": sum(len(g["tests"]) for g in groups), "notes": notes, "testGroups": groups,
        }
