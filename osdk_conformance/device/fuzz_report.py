"""What a device fuzzing session leaves behind: the verdict's results, a
reproducer file and a vector group per confirmed finding, and the JUnit and
HTML reports (with the liveness timeline).

The verdict claims no more than was checked: each case kind is a result
(PASS with how many cases were sent and checked, FAIL when a finding
followed one, SKIP with the reason when none was sent), cases withheld for
safety are counted, and a finding that could not be replayed says so.
"""
from __future__ import annotations

import hashlib
import json
import math
from pathlib import Path

from osdk_conformance.core.deframe import Deframer, Frame
from osdk_conformance.device.fuzz_cases import KINDS, MOTION_KINDS
from osdk_conformance.device.fuzz_session import Finding, SessionOutcome
from osdk_conformance.device.hostload import HOST_TOO_BUSY
from osdk_conformance.device.plots import Marker, Panel, markers_html, small_multiples
from osdk_conformance.harness.fuzz import regression_vector, suite_document
from osdk_conformance.harness.report import ERROR, FAIL, PASS, SKIP, Result

REPRO_FORMAT = "osdkc-device-fuzz-reproducer/1"


def results_of(out: SessionOutcome, repro_paths: dict[int, Path], kinds: tuple[str, ...] | None = None) -> list[Result]:
    """The session's results; `kinds` are the --kind options (None: every kind), which tell a kind left out
    from one the budget did not reach. A SKIP's `kind` says why in a few words (the summary line's)."""
    res: list[Result] = []
    if out.start_problem:
        res.append(Result("fuzz", "fuzz.start", ERROR, f"the device was not live before the first case: "
                          f"{out.start_problem}; nothing was fuzzed", kind="not_live"))
    if out.port_lost:
        res.append(Result("fuzz", "fuzz.port", FAIL, out.port_lost + "; the session ended there", kind="port_lost"))
    if out.unwell:
        res.append(Result("fuzz", "fuzz.health", SKIP if out.unwell_host else ERROR,
                          (f"not judged: this host was busy ({out.unwell_host}); a flight controller simulated on "
                           "this host may have been starved of CPU. " if out.unwell_host else "")
                          + out.unwell + "; the session ended there",
                          kind=HOST_TOO_BUSY if out.unwell_host else "not_live"))
    by_kind: dict[str, list[Finding]] = {}
    for f in out.findings:
        for k in sorted(set(f.kinds) | f.repeated_kinds):
            by_kind.setdefault(k, []).append(f)
    for kind, what in KINDS.items():
        sent, withheld = out.sent.get(kind, 0), out.withheld.get(kind, 0)
        held = f"; {withheld} withheld for safety" if withheld else ""
        cid = f"fuzz.cases.{kind}"
        if by_kind.get(kind):
            nums = ", ".join(str(f.number) for f in by_kind[kind])
            res.append(Result("cases", cid, FAIL, f"{sent} sent{held}; finding(s) {nums} followed cases of this kind",
                              {"sent": sent, "withheld": withheld, "what": what}, kind="finding"))
        elif sent:
            res.append(Result("cases", cid, PASS, f"{sent} sent and checked, no finding{held}",
                              {"sent": sent, "withheld": withheld, "what": what}))
        else:
            if withheld:
                why, short = f"every case of this kind was withheld for safety ({withheld})", "withheld for safety"
            elif kind in MOTION_KINDS and (kinds is None or kind in kinds):
                why = f"movement control {out.motion}"
                short = "no --allow-motion" if out.motion.startswith("not allowed") else "no control authority"
            elif kinds is not None and kind not in kinds:
                why, short = "not sent: --kind left it out", "left out by --kind"
            else:
                why, short = "none sent: the budget ended first", "budget ended first"
            res.append(Result("cases", cid, SKIP, why, {"withheld": withheld, "what": what}, kind=short))
    for f in out.findings:
        res.append(finding_result(f, repro_paths.get(f.number)))
    if out.not_judged:
        n = len(out.not_judged)
        replayed = sum(j.replayed for j in out.not_judged)
        res.append(Result("liveness", "fuzz.host", SKIP,
                          f"not judged: {n} check(s) failed on timing alone while this host was busy "
                          f"({replayed} passed when their cases were replayed, {n - replayed} saw a live but slower "
                          f"broadcast); no finding made of them (after {', '.join(j.after for j in out.not_judged[:20])}"
                          f"{'…' if n > 20 else ''}; {out.not_judged[-1].host})",
                          {"after": [j.after for j in out.not_judged], "symptoms": [j.check.symptoms for j in out.not_judged]},
                          kind=HOST_TOO_BUSY))
    if out.checks:
        failed = len(out.findings) + sum(f.repeats for f in out.findings)
        busy = f", {len(out.not_judged)} more on timing alone while this host was busy" if out.not_judged else ""
        res.append(Result("liveness", "fuzz.liveness", PASS if not out.findings else FAIL,
                          f"{out.checks} checks after cases, {failed} failed{busy}, {out.retried_checks} needed a "
                          "second probe after padding",
                          {"checks": out.checks, "retried": out.retried_checks, "not_judged": len(out.not_judged)}))
    return res


def finding_result(f: Finding, path: Path | None) -> Result:
    state = {True: "confirmed by replay from the capture" if f.from_capture else "confirmed by replay",
             False: f"NOT confirmed: {f.why_unconfirmed}", None: f"not replayed: {f.why_unconfirmed}"}[f.confirmed]
    cases = f.reproducer or f.suspects
    size = sum(len(w) for c in cases for w in c.writes)
    msg = (f"{f.check.describe()}, after {f.suspects[-1].id}; {state}"
           + (f"; minimised to {len(cases)} case(s), {size} byte(s) in {sum(len(c.writes) for c in cases)} "
              f"write(s) ({f.trials} trials)" if f.confirmed else "")
           + (f"; the same symptoms {f.repeats} more time(s), after {', '.join(f.repeated_after)}"
              + ("…" if f.repeats > len(f.repeated_after) else "") if f.repeats else "")
           + (f"; reproducer {path}" if path else ""))
    details = {"symptoms": f.check.symptoms, "after": [c.id for c in f.suspects], "repeated_after": f.repeated_after,
               "reproducer": [c.to_json() for c in cases], "trials": f.trials}
    return Result("findings", f"fuzz.finding.{f.number}", FAIL, msg, details, kind="+".join(f.check.symptoms))


def reproducer_doc(f: Finding, profile: str, seed: int, meta: dict) -> dict:
    cases = f.reproducer or f.suspects
    return {"format": REPRO_FORMAT, "profile": profile, "seed": seed, "finding": f.number,
            "symptoms": f.check.symptoms, "description": f.check.describe(),
            "confirmed": f.confirmed, "minimised": bool(f.confirmed and f.reproducer),
            "trials": f.trials, "run": meta, "cases": [c.to_json() for c in cases],
            "replay": f"osdkc fuzz --port PORT --profile {profile} --replay THIS_FILE"}


def vector_group(f: Finding, profile: str, seed: int) -> dict | None:
    """The reproducer as a decode_stream vector (what the receive path must
    make of these bytes), when it is a confirmed byte sequence: the
    decode_stream operation of a testee is the device's receive path."""
    if not f.confirmed:
        return None
    writes = [w for c in (f.reproducer or f.suspects) for w in c.writes]
    data = b"".join(writes)
    chunks = [len(w) for w in writes[:-1]]
    frames = sum(isinstance(e, Frame) for e in Deframer().feed(data))
    comment = (f"found by osdkc fuzz --port (seed {seed}): after these bytes the device failed its liveness "
               f"check: {f.check.describe()}; {frames} complete frame(s) in them")
    return regression_vector("decode_stream", profile, {"hex": data.hex(), "chunks": chunks}, comment)


def write_findings(out: SessionOutcome, directory: Path, profile: str, seed: int, meta: dict) -> dict[int, Path]:
    """A reproducer (and, when it maps, a vector file) per finding; returns the reproducer paths."""
    paths: dict[int, Path] = {}
    if not out.findings:
        return paths
    directory.mkdir(parents=True, exist_ok=True)
    for f in out.findings:
        doc = reproducer_doc(f, profile, seed, meta)
        digest = hashlib.sha256(json.dumps(doc["cases"]).encode()).hexdigest()[:8]
        p = directory / f"finding-{f.number}-{digest}.repro.json"
        p.write_text(json.dumps(doc, indent=1) + "\n", encoding="utf-8")
        paths[f.number] = p
        group = vector_group(f, profile, seed)
        if group is not None:
            (directory / f"finding-{f.number}-{digest}.vectors.json").write_text(
                json.dumps(suite_document(group), indent=1, sort_keys=True, allow_nan=False) + "\n", encoding="utf-8")
    return paths


def timeline_html(live, out: SessionOutcome) -> str:
    """The liveness timeline as small multiples on one time axis: broadcast
    frames, the version query's round trip, checks and failed checks, per
    second; findings are numbered markers. Only whole seconds are drawn:
    the session starts and ends inside a second, and a part of one counted
    as a whole read as a rate falling off at both ends."""
    if not live.bins:
        return "<h2>Liveness timeline</h2><p>No check was made.</p>"
    with live.an.lock:
        start, end = live.an.first_t, live.an.last_t
    seconds = sorted(live.bins)
    start = seconds[0] if start is None else start
    end = seconds[-1] + 1 if end is None else end
    whole = range(math.ceil(start), math.floor(end))   # seconds that lie wholly inside the session
    t0 = start
    rows = [(s + 0.5 - t0, live.bins.get(s, [0, 0, 0.0, 0, 0])) for s in whole]
    panels = [Panel("broadcast", "frames per second", _steps([(x, r[4]) for x, r in rows]), floor=0.0),
              Panel("round trip", "ms, mean of the second", _steps([(x, r[2] / r[3] if r[3] else math.nan)
                                                                   for x, r in rows]), floor=0.0),
              Panel("checks", "per second", _steps([(x, r[0]) for x, r in rows]), floor=0.0),
              Panel("failed checks", "per second", _steps([(x, r[1]) for x, r in rows]), floor=0.0)]
    marks = [Marker(f.check.t - t0, f"finding {f.number}: {f.check.describe()}", "finding") for f in out.findings]
    return "\n".join([
        "<h2>Liveness timeline</h2>",
        f"<p>{out.checks} checks; {len(out.findings)} finding(s); every case's bytes are in the capture with "
        "its id as the block comment. Per whole second of the session (the partial first and last seconds "
        "are left out).</p>",
        markers_html(marks),
        small_multiples("Liveness per second", panels, (start - t0, end - t0), marks,
                        "t (s) from the first byte received"),
    ])


def _steps(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """Each per-second value drawn across its second; a missing one lifts the pen."""
    out: list[tuple[float, float]] = []
    for x, y in points:
        out += [(x - 0.5, y), (x + 0.5, y)] if math.isfinite(y) else [(x, math.nan)]
    return out
