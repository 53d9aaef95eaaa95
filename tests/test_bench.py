"""`osdkc bench` on short corpora: every implementation's bench mode reports
the counts the corpus generator wrote, the JSON and Markdown reports have
their shape, and bad arguments are one-line usage errors. No timing is
asserted anywhere: speed is what `osdkc bench` reports, not what a test checks."""
from __future__ import annotations

import json
import random
import subprocess
import sys

import pytest

from osdk_conformance.bench import corpus as bench_corpus
from osdk_conformance.bench.decode import BASELINE, cross_check, impl_names
from osdk_conformance.bench.report import BEGIN, END
from osdk_conformance.cli import main
from osdk_conformance.reference.decode import decode_events
from osdk_conformance.core.paths import ROOT
from osdk_conformance.core.rules import profile_names

SECONDS = 3.0   # of traffic per corpus: enough for every kind of frame and fault, quick to decode
OSDKC = [sys.executable, "-m", "osdk_conformance.cli"]


def osdkc(*args: str, timeout: float = 300) -> subprocess.CompletedProcess:
    return subprocess.run([*OSDKC, *args], capture_output=True, text=True, cwd=ROOT, timeout=timeout,
                          stdin=subprocess.DEVNULL)


@pytest.fixture(scope="module")
def bench_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("bench")
    proc = osdkc("bench", "--only", "decode", "--corpus-seconds", f"{SECONDS:g}", "--repeats", "1",
                 "--json", "--markdown", str(out / "bench.md"))
    if proc.returncode == 0:  # --json prints the numbers; the tests read them from a file
        (out / "bench.json").write_text(proc.stdout)
    return proc, out


@pytest.mark.slow
def test_every_implementation_counts_what_the_generator_wrote(bench_run):
    proc, out = bench_run
    assert proc.returncode == 0, proc.stdout + proc.stderr
    result = json.loads((out / "bench.json").read_text())
    decode = result["decode"]
    assert decode["mismatches"] == []
    assert [c["name"] for c in decode["corpora"]] == list(bench_corpus.CORPORA)
    for c in decode["corpora"]:
        written = bench_corpus.corpus(c["name"], SECONDS)
        assert c["expected"] == written.expected()
        assert c["bytes"] == written.bytes
        assert [r["impl"] for r in c["results"]] == impl_names()
        for r in c["results"]:
            assert r["ok"], r
            assert r["counts"] == written.expected(), (c["name"], r["impl"])
            assert r["agrees"] is True


def test_corpus_sizes_follow_from_their_rates():
    hour = bench_corpus.corpus("a3-hour", SECONDS)
    assert (hour.frames, hour.errors, hour.garbage_bytes) == (300, 0, 0)   # 100 Hz, every frame intact
    assert hour.bytes == 300 * (12 + 2 + 2 + 198 + 4)                        # every a3-fw3.1 item in each
    for profile in profile_names():
        mixed = bench_corpus.corpus(f"{profile}-mixed", SECONDS)
        # 50 Hz of broadcasts (intact or broken) and as many movement commands, plus the start-up exchanges
        assert mixed.frames + mixed.errors == 2 * 150 + 2 * 5
        assert mixed.garbage_bytes > 0


def test_corpus_values_move_like_a_flight():
    hour = bench_corpus.corpus("a3-hour", SECONDS)
    with open(hour.path, "rb") as fh:
        events = list(decode_events([fh.read()], "a3-fw3.1"))
    data = [ev["frame"]["data"]["value"]["body"]["data"] for ev in events]
    assert [ev["frame"]["seq"] for ev in events] == list(range(len(events)))
    assert [d["time_stamp"]["time"] for d in data[:5]] == [0, 4, 8, 12, 16]   # 400 Hz ticks at 100 Hz
    assert len({d["quaternion"]["q3"]["f32"] for d in data}) > 100            # the attitude moves
    assert all(set(d) >= {"gps_detail", "rtk_detail", "control_info"} for d in data)


@pytest.mark.slow
def test_reports_have_their_shape(bench_run):
    proc, out = bench_run
    result = json.loads((out / "bench.json").read_text())
    assert result["command"].startswith("osdkc bench --only decode")
    assert {"cpu", "cores", "memory", "kernel", "python", "gcc", "git"} <= set(result["machine"])
    row = result["decode"]["corpora"][0]["results"][0]
    assert row["impl"] == BASELINE and row["ratio_to_baseline"] == 1.0
    for r in result["decode"]["corpora"][0]["results"]:
        assert {"seconds", "frames_per_s", "mb_per_s", "peak_rss_mib", "ratio_to_baseline", "runs"} <= set(r)
        assert r["peak_rss_mib"] > 0
    assert [t["met"] for t in result["targets"]][2:] == [None, None]   # run and acceptance did not run
    md = (out / "bench.md").read_text()
    assert md.startswith(BEGIN) and md.rstrip().endswith(END)
    for impl in impl_names():
        assert f"| `{impl}` |" in md
    for name in bench_corpus.CORPORA:
        assert name in proc.stdout


@pytest.mark.slow
def test_markdown_replaces_only_its_block(tmp_path, bench_run):
    _, out = bench_run
    doc = tmp_path / "PERFORMANCE.md"
    doc.write_text(f"# Title\n\nprose before\n\n{BEGIN}\nold numbers\n{END}\n\nprose after\n")
    from osdk_conformance.bench.report import markdown, write_markdown

    result = json.loads((out / "bench.json").read_text())
    write_markdown(doc, markdown(result))
    text = doc.read_text()
    assert "old numbers" not in text
    assert text.startswith("# Title\n\nprose before\n\n" + BEGIN) and text.endswith(END + "\n\nprose after\n")


def test_a_capture_of_unknown_content_is_checked_between_implementations(tmp_path):
    hour = bench_corpus.corpus("a3-hour", SECONDS)
    rng = random.Random(7)
    capture = tmp_path / "capture.bin"
    with open(hour.path, "rb") as fh:
        frames = fh.read()
    capture.write_bytes(rng.randbytes(5000) + frames[:20000] + rng.randbytes(5000) + frames[:777])
    proc = osdkc("bench", "--only", "decode", "--input", str(capture), "--profile", "a3-fw3.1",
                 "--impl", BASELINE, "--impl", "c", "--impl", "go", "--repeats", "1", "--json")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    (c,) = json.loads(proc.stdout)["decode"]["corpora"]
    assert c["expected"] is None
    counts = [r["counts"] for r in c["results"]]
    assert counts[0]["bytes"] == capture.stat().st_size and counts[0]["errors"] > 0
    assert counts == [counts[0]] * 3


def test_a_count_mismatch_names_the_implementation():
    corpus = bench_corpus.Corpus(name="x", profile="a3-fw3.1", seconds=1.0, path="x.bin", bytes=10, frames=2,
                                 errors=0, garbage_bytes=0, description="")
    good = {"bytes": 10, "frames": 2, "errors": 0, "garbage_bytes": 0}
    results = [{"impl": "c", "counts": dict(good)}, {"impl": "go", "counts": {**good, "frames": 1, "errors": 1}},
               {"impl": "java", "ok": False, "error": "exit 1"}]
    (line,) = cross_check(corpus, results, corpus.expected())
    assert line == "x: go counts frames 1 (want 2), errors 1 (want 0), per the corpus generator"
    assert [r.get("agrees") for r in results] == [True, False, None]


@pytest.mark.parametrize("args, message", [
    (("--only", "decode,nosuch"), "unknown section 'nosuch'"),
    (("--impl", "cobol"), "unknown implementation 'cobol'"),
    (("--corpora", "a-day"), "unknown corpus 'a-day'"),
    (("--repeats", "0"), "argument --repeats: an integer >= 1 was expected, got '0'"),
    (("--device-fuzz-cases", "0"), "argument --device-fuzz-cases: an integer >= 1 was expected, got '0'"),
    (("--input", "/nonexistent/capture.bin", "--profile", "a3-fw3.1"), "cannot read /nonexistent/capture.bin"),
    (("--input", "x.bin"), "--input and --profile go together"),
    (("--markdown", "/nonexistent/dir/out.md"), "--markdown /nonexistent/dir/out.md: directory"),
])
def test_bad_arguments_are_one_line_usage_errors(args, message, capsys):
    assert main(["bench", *args]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and message in lines[0], err


def test_reliability_targets_do_not_call_an_unmeasured_part_missed():
    """`--runs 0` measures fault detection only: the healthy-run target is
    "not measured", not MISSED; a short or failed healthy batch is MISSED."""
    from osdk_conformance.bench.report import _reliability_targets, _verdict

    faults = {"noise": {"runs": 20, "detected": 20, "missed": []}}
    none = {"runs": 0, "passed": 0, "active": 0, "passive": 0, "retransmissions": 0, "inconclusive": 0,
            "false_fails": 0}
    short = {**none, "runs": 10, "passed": 10, "active": 5, "passive": 5}
    full = {**none, "runs": 200, "passed": 200, "active": 100, "passive": 100}
    # runs the judge's busy host kept from a verdict blame nobody: not a false FAIL
    host_busy = {**full, "passed": 197, "inconclusive": 3}
    one_fail = {**full, "passed": 199, "false_fails": 1}
    stand_in = {**full, "passed": 199, "stand_in_behind": 1}   # the simulated FC starved, the judge did not FAIL
    stand_in_and_fail = {**stand_in, "false_fails": 1}

    def verdicts(h, busy=2):
        rel = {"healthy": h, "faults": faults, "load": {"busy_loops_per_core": busy}}
        return [_verdict(t["met"]) for t in _reliability_targets(rel)]

    assert verdicts(none) == ["not measured", "met"]
    assert verdicts(short) == ["MISSED", "met"]
    assert verdicts(full) == ["met", "met"]
    assert verdicts(full, busy=0) == ["MISSED", "met"]   # an idle machine proves nothing about load
    assert verdicts(host_busy) == ["met", "met"]
    assert verdicts(one_fail) == ["MISSED", "met"]
    assert verdicts(stand_in) == ["met", "met"]
    assert verdicts(stand_in_and_fail) == ["MISSED", "met"]


def test_fuzz_reliability_targets_count_inconclusive_sessions_but_no_false_finding():
    from osdk_conformance.bench.fuzz_reliability import summary
    from osdk_conformance.bench.report import _reliability_targets, _verdict

    none = {"runs": 0, "passed": 0, "active": 0, "passive": 0, "retransmissions": 0, "inconclusive": 0,
            "false_fails": 0}
    bugs = {b: {"runs": 20, "found": 20, "missed": []} for b in ("long-frame-hang", "unknown-cmd-silence")}
    clean = {"cases": 150, "runs": 40, "clean": 37, "inconclusive": 3, "false_findings": 0, "failures": [],
             "bug_cases": 400, "bugs": bugs}
    found = {**clean, "clean": 36, "false_findings": 1,
             "failures": [{"run": "fuzz-healthy-0007", "problems": ["exit 1 (FOUND)"], "kept": "/tmp/x"}]}
    missed = {**clean, "bugs": {**bugs, "long-frame-hang": {"runs": 20, "found": 19,
                                                             "missed": [{"seed": 4, "problems": ["exit 0"]}]}}}

    def verdicts(fz, busy=2):
        rel = {"healthy": none, "faults": {}, "load": {"busy_loops_per_core": busy}, "fuzz": fz}
        return [_verdict(t["met"]) for t in _reliability_targets(rel)][2:]

    assert verdicts(clean) == ["met", "met"]
    assert verdicts(clean, busy=0) == ["MISSED", "met"]
    assert verdicts(found) == ["MISSED", "met"]
    assert verdicts(missed) == ["met", "MISSED"]
    assert verdicts({**clean, "runs": 0, "clean": 0, "inconclusive": 0}) == ["not measured", "met"]
    assert "37 of 40 found nothing, 3 inconclusive (host too busy), 0 with a false finding" in summary(clean)
    assert "found and confirmed in 39 of 40 sessions; missed: long-frame-hang (seeds 4)" in summary(missed)
    assert "fuzz-healthy-0007: exit 1 (FOUND)" in summary(found)


# a live simulator answering the fuzzer within its time-outs: with the realtime tests (beside the niced
# CPU-heavy files the simulator, niced with them, is starved: the session ends INCONCLUSIVE, no speed measured)
@pytest.mark.slow
@pytest.mark.realtime
def test_device_fuzz_section_reports_each_baud_rate(tmp_path):
    """The device fuzzer against a healthy simulator over a pty, a few cases at
    each baud rate: every number is there and positive, nothing was found."""
    from osdk_conformance.bench.sections import DEVICE_FUZZ_BAUDS

    cases = 20
    proc = osdkc("bench", "--only", "device_fuzz", "--device-fuzz-cases", str(cases), "--json",
                 "--markdown", str(tmp_path / "bench.md"), timeout=120)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    result = json.loads(proc.stdout)
    assert result["command"] == f"osdkc bench --only device_fuzz --device-fuzz-cases {cases}"
    assert set(result) >= {"device_fuzz", "targets", "ok"} and "decode" not in result and result["ok"]
    dfz = result["device_fuzz"]
    assert dfz["ok"] and [r["baud"] for r in dfz["rows"]] == list(DEVICE_FUZZ_BAUDS)
    for r in dfz["rows"]:
        assert r["ok"] and r["verdict"] == "NOTHING FOUND" and r["findings"] == 0, r
        assert r["cases"] == cases and f"--baud {r['baud']} --cases {cases} --seed 1" in r["command"]
        for key in ("seconds", "cases_per_s", "bytes_per_case", "line_cases_per_s", "share_of_line"):
            assert r[key] > 0, (key, r)
        assert r["line_cases_per_s"] == pytest.approx(r["baud"] / 10 / r["bytes_per_case"], rel=0.01)
    (target,) = [t for t in result["targets"] if "osdkc fuzz --port" in t["target"]]
    assert target["met"] is None and target["verdict"] == "reported, no target"
    md = (tmp_path / "bench.md").read_text()
    for baud in DEVICE_FUZZ_BAUDS:
        assert f"| device fuzzing, a3-fw3.1 simulator over a pty at {baud} baud |" in md
    assert "| reported, no target |" in md


def test_a_device_fuzz_failure_is_missed_not_reported():
    from osdk_conformance.bench.report import _device_fuzz_targets, _target_verdict

    good = {"baud": 921600, "ok": True, "cases_per_s": 900.0, "share_of_line": 0.8}
    bad = {"baud": 230400, "ok": False, "cases_per_s": 10.0, "error": "FOUND 1 on a healthy simulator"}
    (t,) = _device_fuzz_targets({"ok": False, "rows": [good, bad]})
    assert _target_verdict(t) == "MISSED"
    assert t["measured"].endswith("FAILED: 230400 baud: FOUND 1 on a healthy simulator")
    (t,) = _device_fuzz_targets({"ok": True, "rows": [good]})
    assert _target_verdict(t) == "reported, no target" and t["measured"] == "900 cases/s at 921600 baud (80% of what the line carries)"
