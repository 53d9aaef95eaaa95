"""What the doctor found: findings with a stable id, a verdict, the evidence
and a remedy, printed for a person (the next step first) or as JSON."""
from __future__ import annotations

import json
from dataclasses import dataclass, field
from typing import Any, TextIO

OK, PROBLEM, WARNING, NOT_CHECKED = "ok", "problem", "warning", "not_checked"
FORMAT = 1   # the JSON form's version: a field's meaning never changes within one


@dataclass
class Finding:
    id: str
    verdict: str
    summary: str
    evidence: dict[str, Any] = field(default_factory=dict)
    remedy: str = ""

    def as_json(self) -> dict[str, Any]:
        out = {"id": self.id, "verdict": self.verdict, "summary": self.summary, "evidence": self.evidence}
        if self.remedy:
            out["remedy"] = self.remedy
        return out


@dataclass
class Diagnosis:
    port: str
    findings: list[Finding] = field(default_factory=list)
    seconds: float = 0.0
    interrupted: str | None = None   # the signal that cut the diagnosis short

    def add(self, f: Finding) -> Finding:
        self.findings.append(f)
        return f

    def problems(self) -> list[Finding]:
        return [f for f in self.findings if f.verdict == PROBLEM]

    def ids(self, verdict: str = PROBLEM) -> list[str]:
        return [f.id for f in self.findings if f.verdict == verdict]

    @property
    def link_works(self) -> bool:
        return not self.problems() and self.interrupted is None and any(
            f.id == "fc.answers" and f.verdict == OK for f in self.findings)

    def verdict(self) -> str:
        if self.interrupted:
            return "interrupted"
        if self.problems():
            return "problem"
        return "ok" if self.link_works else "incomplete"

    def as_json(self) -> dict[str, Any]:
        problems = self.problems()
        return {"tool": "osdkc doctor", "format": FORMAT, "port": self.port, "verdict": self.verdict(),
                "next_step": problems[0].remedy if problems else "", "seconds": round(self.seconds, 2),
                **({"interrupted_by": self.interrupted} if self.interrupted else {}),
                "findings": [f.as_json() for f in self.findings]}

    def write_json(self, out: TextIO) -> None:
        json.dump(self.as_json(), out, indent=2)
        out.write("\n")

    def write_text(self, out: TextIO, verbose: bool = False) -> None:
        problems = self.problems()
        if self.interrupted:
            out.write(f"INTERRUPTED by {self.interrupted} after {self.seconds:.1f} s: what was found so far\n")
        elif problems:
            first = problems[0]
            out.write(f"PROBLEM: {first.summary}\n  next step: {first.remedy}\n")
            for f in problems[1:]:
                out.write(f"also: {f.summary}\n  what to do: {f.remedy}\n")
        elif self.link_works:
            out.write(f"LINK WORKS ({self.seconds:.1f} s)\n")
        else:
            out.write("NOTHING WRONG FOUND, but the link was not checked to the end\n")
        out.write("\n")
        marks = {OK: "ok  ", PROBLEM: "FAIL", WARNING: "warn", NOT_CHECKED: "--  "}
        for f in self.findings:
            out.write(f"  {marks[f.verdict]} {f.id:22} {f.summary}\n")
            if verbose or f.verdict in (PROBLEM, WARNING):
                for k, v in f.evidence.items():
                    out.write(f"       {k}: {v}\n")
                if f.remedy and f.verdict == WARNING:
                    out.write(f"       what to do: {f.remedy}\n")
