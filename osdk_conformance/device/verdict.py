"""The words a run on a serial port ends with: the same at the terminal, in
the HTML banner and in the JUnit properties.

Conformance is what `osdkc run` judges (CONFORMS / DOES NOT CONFORM, only
there). An acceptance run (`osdkc device`) PASSES or FAILS, is
INCONCLUSIVE (nothing failed, but this host was too busy to judge some
checks: device/hostload.withheld), or was INTERRUPTED; a fuzzing session (`osdkc fuzz --port`) FOUND n findings or
found NOTHING, is INCONCLUSIVE (the FC failed its check with no case sent
while this host was busy), or was INTERRUPTED (device/fuzz_command.py). Whatever the
word, the summary line says how many checks ran, passed, failed and were
skipped, and why the skipped ones were, in a few words (`counts`): a PASS
with half the checks skipped must not read like a full one, with or
without -q.
"""
from __future__ import annotations

import re
from collections import Counter
from typing import Sequence

from osdk_conformance.harness.report import ERROR, FAIL, PASS, SKIP, XFAIL, XPASS, Result

PASSED, FAILED, INTERRUPTED = "PASS", "FAIL", "INTERRUPTED"   # osdkc device
INCONCLUSIVE = "INCONCLUSIVE"   # nothing failed, but this host kept checks from being judged
FOUND, NOTHING_FOUND = "FOUND", "NOTHING FOUND"                # osdkc fuzz --port

NAMES_PER_REASON = 3   # check names listed after a skip reason, then "…"
REASON_CHARS = 40


def skip_reason(r: Result) -> str:
    """Why a check was skipped, in a few words: its `kind` when it has one,
    else its message up to the first colon, semicolon or parenthesis."""
    if r.kind:
        return r.kind
    text = re.split(r"[:;(]", r.message, maxsplit=1)[0].strip() or "no reason given"
    return text if len(text) <= REASON_CHARS else text[:REASON_CHARS - 1].rstrip() + "…"


def short_name(r: Result) -> str:
    """The check's id without its group: `activation` for `active.activation`,
    `movement.zero` for `fuzz.cases.movement.zero`."""
    _, sep, tail = r.id.partition(f"{r.category}.")
    return tail if sep and tail else r.id


def counts(results: Sequence[Result]) -> str:
    """'26 checks ran (25 passed, 1 failed), 4 skipped (no --app-id: activation,
    control_obtain; …)': every number, always, and the skip reasons."""
    c = Counter(r.status for r in results)
    ran = sum(n for status, n in c.items() if status != SKIP)
    parts = [f"{c[PASS]} passed"]
    if c[FAIL] + c[XPASS]:
        parts.append(f"{c[FAIL] + c[XPASS]} failed")
    if c[ERROR]:
        parts.append(f"{c[ERROR]} errored")
    if c[XFAIL]:
        parts.append(f"{c[XFAIL]} failed as expected")
    text = f"{ran} check{'' if ran == 1 else 's'} ran ({', '.join(parts)})"
    skipped = [r for r in results if r.status == SKIP]
    if not skipped:
        return text + ", none skipped"
    by_reason: dict[str, list[str]] = {}
    for r in skipped:
        by_reason.setdefault(skip_reason(r), []).append(short_name(r))
    groups = []
    for reason, names in by_reason.items():
        shown = ", ".join(names[:NAMES_PER_REASON]) + (", …" if len(names) > NAMES_PER_REASON else "")
        groups.append(f"{reason}: {shown}")
    return f"{text}, {len(skipped)} skipped ({'; '.join(groups)})"


def acceptance_word(ok: bool, signame: str | None, host_withheld: bool = False) -> str:
    """PASS, FAIL, INCONCLUSIVE or INTERRUPTED: the word of an `osdkc device`
    run. INCONCLUSIVE when nothing failed but a check was not judged because
    this host was too busy to read the port in time: not a PASS, since the
    check did not run, and not the device's failure."""
    if signame:
        return INTERRUPTED
    if not ok:
        return FAILED
    return INCONCLUSIVE if host_withheld else PASSED
