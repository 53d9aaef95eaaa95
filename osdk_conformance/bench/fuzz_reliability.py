"""The device fuzzer's part of `osdkc bench --only reliability`: no false
finding on a saturated host, every planted firmware bug still found.

It runs inside the reliability section's busy loops (reliability.measure),
with the simulator favoured as there: what is measured is the fuzzer on a
saturated host.

Healthy sessions: `osdkc fuzz --port` against a fault-free `osdkc sim`
(seed = session number), FUZZ_CASES cases each. None may find anything:
exit status 0 (NOTHING FOUND), or 3 (INCONCLUSIVE: checks this busy host
kept from a verdict, counted apart); and the simulator must end with its
initial broadcast rates and control at the RC.

Bug sessions: each planted firmware bug (sim/bugs.py) with seeds 1..N, the
simulator restarted by `kill -HUP` between trials: the session must end
FOUND 1 with the finding confirmed by replay.

Every session is a pair of child processes, as a user runs them; the files
of one that went wrong are kept.
"""
from __future__ import annotations

import re
import shutil
from pathlib import Path

from osdk_conformance.bench import stand_in
from osdk_conformance.core.errors import EXIT_INCONCLUSIVE
from osdk_conformance.sim.bugs import BUGS

FUZZ_CASES = 150
BUG_CASES = 400          # the tests find each bug within about 120 cases (six rounds of the kinds)
SESSION_TIMEOUT = 300.0
SUMMARY = re.compile(r"^osdkc fuzz: ([A-Z][A-Z ]*[A-Z])\b", re.M)


def _session(name: str, tmp: Path, sim_args: tuple[str, ...], fuzz_args: tuple[str, ...],
             restart: bool = False) -> dict:
    run_dir = tmp / name

    def command(url: str, pid: int) -> list[str]:
        return ["fuzz", "--port", url, "--capture", str(run_dir / "capture.pcapng"), "--findings-dir",
                str(run_dir / "findings"), "-q", *fuzz_args, *(("--restart-cmd", f"kill -HUP {pid}") if restart else ())]
    r = stand_in.run(run_dir, sim_args, command, SESSION_TIMEOUT, "fuzz-output.txt")
    word = SUMMARY.search(r.out)
    return {"name": name, "dir": run_dir, "code": r.code, "out": r.out, "word": word[1] if word else None,
            "stats": r.stats, "traceback": "Traceback" in r.out, "favoured": r.favoured}


def healthy_problems(r: dict) -> list[str]:
    """What went wrong in a healthy session ([] when nothing); an INCONCLUSIVE
    one is not wrong and is counted apart (r["inconclusive"])."""
    r["inconclusive"] = r["code"] == EXIT_INCONCLUSIVE
    bad = [] if r["code"] in (0, EXIT_INCONCLUSIVE) else [f"exit {r['code']} ({r['word'] or 'no summary line'})"]
    if r["traceback"]:
        bad.append("traceback")
    st = r["stats"]
    if not st:
        bad.append("the simulator left no statistics")
    elif st.get("rates") != st.get("initial_rates") or st.get("control") != "rc":
        bad.append("the simulator was left with other rates or control than it started with")
    return bad


def bug_problems(r: dict) -> list[str]:
    bad = [] if r["code"] == 1 and r["word"] == "FOUND" else [f"exit {r['code']} ({r['word'] or 'no summary line'})"]
    if "confirmed by replay" not in r["out"]:
        bad.append("no finding confirmed by replay")
    if r["traceback"]:
        bad.append("traceback")
    return bad


def measure(runs: int, bug_runs: int, tmp: Path, profile: str, batch, log) -> dict:
    """`runs` healthy sessions and `bug_runs` seeded sessions per planted bug,
    `batch(tasks)` running them (some at a time)."""
    out: dict = {"cases": FUZZ_CASES, "runs": runs, "bug_cases": BUG_CASES, "bugs": {}}

    def healthy(i: int):
        def one() -> dict:
            r = _session(f"fuzz-healthy-{i:04d}", tmp, ("--profile", profile, "--seed", str(i)),
                         ("--profile", profile, "--cases", str(FUZZ_CASES), "--seed", str(i)))
            r["problems"] = healthy_problems(r)
            log(f"{r['name']}: {'; '.join(r['problems']) or r['word']}")
            return r
        return one

    if runs:
        log(f"fuzz: {runs} healthy sessions of {FUZZ_CASES} cases")
    results = batch([healthy(i) for i in range(runs)])
    went_wrong = [{"run": r["name"], "problems": r["problems"], "kept": str(r["dir"])} for r in results if r["problems"]]
    for r in results:
        if not r["problems"]:
            shutil.rmtree(r["dir"], ignore_errors=True)
    out.update({"inconclusive": sum(1 for r in results if r["inconclusive"] and not r["problems"]),
                "false_findings": sum(1 for r in results if r["word"] == "FOUND"),
                "failures": went_wrong, "favoured": bool(results) and all(r["favoured"] for r in results)})
    out["clean"] = runs - len(went_wrong) - out["inconclusive"]
    for bug in BUGS if bug_runs else ():
        log(f"fuzz: planted bug {bug}: {bug_runs} seeded sessions")
        tasks = [lambda s=seed, b=bug: _session(f"fuzz-bug-{b}-{s:03d}", tmp, ("--profile", profile, "--seed", str(s),
                                                                                 "--bug", b),
                                                 ("--profile", profile, "--cases", str(BUG_CASES), "--seed", str(s),
                                                  "--max-findings", "1"), restart=True)
                 for seed in range(1, bug_runs + 1)]
        missed = []
        for seed, r in enumerate(batch(tasks), start=1):
            bad = bug_problems(r)
            if bad:
                missed.append({"seed": seed, "problems": bad, "kept": str(r["dir"])})
            else:
                shutil.rmtree(r["dir"], ignore_errors=True)
        out["bugs"][bug] = {"runs": bug_runs, "found": bug_runs - len(missed), "missed": missed}
    out["ok"] = not went_wrong and not out["false_findings"] and all(not b["missed"] for b in out["bugs"].values())
    return out


def summary(fz: dict) -> str:
    text = (f"fuzz sessions ({fz['cases']} cases each): {fz['clean']} of {fz['runs']} found nothing, "
            f"{fz['inconclusive']} inconclusive (host too busy), {fz['false_findings']} with a false finding")
    if fz["failures"]:
        text += "; went wrong: " + "; ".join(f"{p['run']}: {', '.join(p['problems'])}" for p in fz["failures"][:5])
    if fz["bugs"]:
        text += (f"; planted bugs: {len(fz['bugs'])} x {min(b['runs'] for b in fz['bugs'].values())} seeds, found and "
                 f"confirmed in {sum(b['found'] for b in fz['bugs'].values())} of "
                 f"{sum(b['runs'] for b in fz['bugs'].values())} sessions")
        missed = [f"{k} (seeds {', '.join(str(m['seed']) for m in b['missed'])})" for k, b in fz["bugs"].items()
                  if b["missed"]]
        if missed:
            text += "; missed: " + "; ".join(missed)
    return text
