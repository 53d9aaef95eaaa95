"""`osdkc run`: the conformance runner, its testee supervision and reports.

The bundled implementations must conform with empty failure lists; the
failure list works protobuf-style; misbehaving testees (tests/testees/)
are recorded case by case and never stop or hang the run.
"""
from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path
from xml.etree import ElementTree as ET

import pytest

from osdk_conformance.harness import report
from osdk_conformance.harness.report import Result
from osdk_conformance.harness import testee as supervision
from osdk_conformance.harness.runner import BUNDLED_IMPLS, default_failure_list, read_failure_list

HERE = Path(__file__).resolve().parent
TESTEES = HERE / "testees"
ROOT = HERE.parent


def osdkc(*args: str, timeout: float = 300) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "osdk_conformance.cli", *args], capture_output=True, text=True,
                          timeout=timeout, cwd=ROOT)


def command_for(name: str, *extra: str) -> str:
    return " ".join([sys.executable, str(TESTEES / f"{name}.py"), *extra])


@pytest.fixture(scope="module")
def cases():
    from osdk_conformance.harness.vectors import load_cases

    return load_cases()


def subset(cases, tmp_path: Path, op: str, n: int, name: str = "subset.json") -> tuple[Path, list[str]]:
    """A vector file with the first `n` cases of operation `op`, and their ids."""
    chosen = [c for c in cases if c.operation == op][:n]
    assert len(chosen) == n
    path = tmp_path / name
    write_vectors(chosen, path)
    return path, [c.id for c in chosen]


def write_vectors(chosen, path: Path) -> None:
    """A vector file holding `chosen` (Case objects), one group each."""
    n = len(chosen)
    doc = {"suite": "subset", "description": "test subset", "generator": "tools/gen_vectors.py",
           "numberOfTests": n, "notes": {},
           "testGroups": [{"operation": c.operation, "profile": c.profile, "tests": [{
               "id": c.id, "category": c.category, "comment": c.comment, "input": c.input,
               "result": c.result, "expected": c.expected, "flags": list(c.flags)}]} for c in chosen]}
    path.write_text(json.dumps(doc))


def junit(path: Path) -> ET.Element:
    return ET.parse(path).getroot()


# ---- the bundled implementations conform ----------------------------------------

@pytest.mark.slow
def test_every_bundled_implementation_conforms(tmp_path):
    # One `--impl all` run: every language, each in its own process, with
    # empty failure lists (or reviewed ones in conformance/failure_lists/).
    from osdk_conformance.harness.runner import BUNDLED_IMPLS

    proc = osdkc("run", "--impl", "all", "--jobs", "2", "--report-dir", str(tmp_path), timeout=1200)
    assert proc.returncode == 0, proc.stdout[-6000:] + proc.stderr[-2000:]
    assert "ALL CONFORM" in proc.stdout and "Traceback" not in proc.stderr
    status = json.loads((tmp_path / "conformance.json").read_text())
    assert [s["impl"] for s in status["implementations"]] == list(BUNDLED_IMPLS)
    for s in status["implementations"]:
        assert s["conforms"] and s["exit"] == 0
        assert s["statuses"]["pass"] > 0 and s["statuses"]["fail"] == 0, s
        root = junit(tmp_path / f"{s['impl']}.xml")
        assert root.get("failures") == "0" and root.get("errors") == "0"
        assert int(root.get("tests")) == s["cases"]
        assert "CONFORMS" in (tmp_path / f"{s['impl']}.html").read_text()
    # every operation is complete in every generated library, encoders
    # included (generated/README.md); only the native decoder skips
    from osdk_conformance.harness.vectors import load_cases

    cases = load_cases()
    for s in status["implementations"]:
        if s["impl"] == "accel":  # the native decoder decodes and does nothing else
            assert s["statuses"]["skip"] == sum(not c.operation.startswith("decode_") for c in cases), s
        else:
            assert s["statuses"]["skip"] == 0, s


def test_status_section_of_generated_readme_is_rendered_from_a_run(tmp_path):
    from osdk_conformance.harness import status_readme

    readme = tmp_path / "README.md"
    readme.write_text(f"intro\n{status_readme.BEGIN}\nold\n{status_readme.END}\noutro\n")
    status = {"seconds": 1.0, "jobs": 1, "selection": None, "implementations": [
        {"impl": "go", "cases": 3, "conforms": True, "statuses": {"pass": 2, "skip": 1}},
        {"impl": "c", "cases": 3, "conforms": False, "statuses": {"pass": 1, "fail": 2}}]}
    path = tmp_path / "conformance.json"
    path.write_text(json.dumps(status))
    assert status_readme.update(path, readme)
    text = readme.read_text()
    assert "old" not in text and text.startswith("intro\n") and text.endswith("outro\n")
    assert "| `go` |" in text and "| 2 | 0 | 0 | 1 | conforms |" in text
    assert "| `c` |" in text and "**does not conform**" in text
    status["selection"] = "--filter x"  # a partial run never overwrites the page
    path.write_text(json.dumps(status))
    assert not status_readme.update(path, readme)


# ---- failure list ----------------------------------------------------------------------

@pytest.mark.slow
def test_a_listed_case_that_passes_fails_the_run(cases, tmp_path):
    case_id = next(c.id for c in cases if c.operation == "classify_control_mode")
    flist = tmp_path / "failures.txt"
    flist.write_text(f"# expected failures\n{case_id}   # listed, but construct passes it\n")
    # --filter on the full vector set: the listed case and whatever else contains its id.
    proc = osdkc("run", "--impl", "construct", "--filter", case_id, "--failure-list", str(flist), "--quiet")
    assert proc.returncode == 1, proc.stdout
    assert "remove it from the list" in proc.stdout and case_id in proc.stdout


def test_a_failing_testee_passes_with_its_failures_listed(cases, tmp_path):
    vec, ids = subset(cases, tmp_path, "decode_payload", 5)
    broken = ids[1:3]
    cmd = command_for("wrong_answers", *broken)
    xml, page = tmp_path / "r.xml", tmp_path / "r.html"

    proc = osdkc("run", "--testee", cmd, "--vectors", str(vec), "--quiet", "--junit", str(xml),
                 "--html", str(page))
    assert proc.returncode == 1, proc.stdout
    assert all(i in proc.stdout for i in broken)
    root = junit(xml)
    assert root.get("failures") == str(len(broken)) and root.get("tests") == str(len(ids))
    failed = {tc.get("name") for tc in root.iter("testcase") if tc.find("failure") is not None}
    assert failed == set(broken)
    body = next(tc.find("failure").text for tc in root.iter("testcase") if tc.find("failure") is not None)
    for label in ("hex:", "expected:", "actual:", "flags:"):
        assert label in body
    text = page.read_text()
    assert all(f'id="case-{i}"' in text for i in broken) and "DOES NOT CONFORM" in text

    flist = tmp_path / "failures.txt"
    flist.write_text("".join(f"{i}\n" for i in broken))
    proc = osdkc("run", "--testee", cmd, "--vectors", str(vec), "--quiet", "--failure-list", str(flist),
                 "--junit", str(xml))
    assert proc.returncode == 0, proc.stdout
    assert junit(xml).get("failures") == "0" and "CONFORMS" in proc.stdout


def test_unknown_ids_in_the_failure_list_are_errors(cases, tmp_path):
    vec, _ = subset(cases, tmp_path, "classify_control_mode", 3)
    flist = tmp_path / "failures.txt"
    flist.write_text("no.such.case.id\n")
    xml = tmp_path / "r.xml"
    proc = osdkc("run", "--impl", "construct", "--vectors", str(vec), "--failure-list", str(flist), "--quiet",
                 "--junit", str(xml))
    assert proc.returncode == 1
    assert "no.such.case.id" in proc.stdout
    assert junit(xml).get("errors") == "1"


def test_failure_list_syntax(tmp_path):
    f = tmp_path / "list"
    f.write_text("# header\n\n  a.b.c  # why\nd.e\n#x.y\na.b.c\n")
    assert read_failure_list(f) == {"a.b.c": 3, "d.e": 4}


# ---- misbehaving testees ---------------------------------------------------------------

@pytest.mark.parametrize("name, kind, extra", [
    pytest.param("sleeper", "testee_timeout", ["--timeout", "0.5"], marks=pytest.mark.slow),
    ("exit_first", "testee_crash", []),
    ("garbage", "testee_garbage", []),
    pytest.param("memory_hog", "testee_oom", ["--memory-mb", "256"], marks=pytest.mark.slow),
])
def test_misbehaving_testees_are_recorded_and_the_run_finishes(cases, tmp_path, name, kind, extra):
    vec, ids = subset(cases, tmp_path, "decode_frame", 3)
    xml, page = tmp_path / "r.xml", tmp_path / "r.html"
    # a hang here would hit the subprocess timeout and fail the test
    proc = osdkc("run", "--testee", command_for(name), "--vectors", str(vec), "--quiet", "--junit", str(xml),
                 "--html", str(page), *extra, timeout=120)
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert "Traceback" not in proc.stderr
    assert f"{kind} {len(ids)}" in proc.stdout  # e.g. "testee failures: testee_timeout 3"
    kinds = {tc.get("name"): tc.find("failure").get("type") for tc in junit(xml).iter("testcase")}
    assert kinds == {i: kind for i in ids}
    assert all(f'id="case-{i}"' in page.read_text() for i in ids)


@pytest.mark.slow
def test_misbehaving_testee_in_a_filtered_run_of_the_real_vectors(cases):
    case_id = next(c.id for c in cases if c.operation == "decode_frame")
    proc = osdkc("run", "--testee", command_for("sleeper"), "--filter", case_id, "--timeout", "0.3", "--quiet")
    assert proc.returncode == 1 and "testee_timeout" in proc.stdout


def test_a_testee_that_keeps_failing_ends_the_run(cases, tmp_path):
    vec, ids = subset(cases, tmp_path, "classify_control_mode", 10)
    xml = tmp_path / "r.xml"
    proc = osdkc("run", "--testee", command_for("exit_first"), "--vectors", str(vec), "--quiet",
                 "--junit", str(xml))
    assert proc.returncode == 1
    assert "run aborted" in proc.stdout
    root = junit(xml)
    assert root.get("failures") == "6"  # the first failure and five restarts
    assert root.get("errors") == str(len(ids) - 6)  # not run


@pytest.mark.slow
def test_a_testee_that_does_not_start_is_a_usage_error():
    proc = osdkc("run", "--testee", "/nonexistent/testee --flag", "--quiet")
    assert proc.returncode == 2
    assert "cannot start testee" in proc.stderr and "Traceback" not in proc.stderr


@pytest.mark.parametrize("args, message", [
    (["--impl", "construct", "--failure-list", "/nonexistent/list"], "cannot read the failure list"),
    (["--impl", "construct", "--filter", "no case has this in its id"], "no vector matches"),
    (["--impl", "construct", "--timeout", "0"], "--timeout"),
    (["--impl", "construct", "--junit", "/nonexistent/dir/r.xml"], "--junit"),
])
def test_usage_errors_exit_2_without_traceback(args, message):
    proc = osdkc("run", *args, "--quiet")
    assert proc.returncode == 2, proc.stdout
    assert message in proc.stderr and "Traceback" not in proc.stderr


# ---- honest verdicts: coverage, validated vectors, interruptions -------------------------

def mixed_vectors(cases, tmp_path: Path, counts: dict[str, int]) -> Path:
    """A vector file with the first counts[op] cases of each operation."""
    chosen = [c for op, n in counts.items() for c in [c for c in cases if c.operation == op][:n]]
    path = tmp_path / "mixed.json"
    write_vectors(chosen, path)
    return path


@pytest.mark.parametrize("claims", ["nothing", "everything"])
def test_a_testee_that_runs_nothing_gets_no_verdict(cases, tmp_path, claims):
    # Claiming no operation, or claiming all and answering `unsupported` to
    # each: both used to be CONFORMS with exit 0.
    vec = mixed_vectors(cases, tmp_path, {"classify_control_mode": 3, "decode_frame": 2})
    xml, page, summary = tmp_path / "r.xml", tmp_path / "r.html", tmp_path / "s.json"
    cmd = command_for("claims_nothing", *(["--all"] if claims == "everything" else []))
    proc = osdkc("run", "--testee", cmd, "--vectors", str(vec), "--quiet", "--junit", str(xml),
                 "--html", str(page), "--summary-json", str(summary))
    assert proc.returncode == 4, proc.stdout + proc.stderr
    assert "CONFORMS" not in proc.stdout
    assert proc.stdout.rstrip().splitlines()[-1].startswith("NOTHING RAN: no verdict (0 of 5 cases ran")
    why = "operation not claimed" if claims == "nothing" else "answered unsupported"
    assert f"3 {why}" in proc.stdout and f"2 {why}" in proc.stdout  # the coverage table says why
    s = json.loads(summary.read_text())
    assert (s["conforms"], s["complete"], s["verdict"]) == (False, False, "NOTHING RAN")
    assert s["coverage"]["ran"] == 0 and s["coverage"]["available"] == 5
    assert "CONFORMS" not in page.read_text() and "NOTHING RAN" in page.read_text()
    props = {p.get("name"): p.get("value") for p in junit(xml).iter("property")}
    assert props["coverage"] == "0 of 5 cases ran" and props["verdict"].startswith("NOTHING RAN")


def test_a_partial_testee_conforms_only_for_what_ran(cases, tmp_path):
    vec = mixed_vectors(cases, tmp_path, {"classify_control_mode": 3, "decode_frame": 2})
    xml, summary = tmp_path / "r.xml", tmp_path / "s.json"
    proc = osdkc("run", "--testee", readme_testee(tmp_path), "--vectors", str(vec), "--quiet",
                 "--junit", str(xml), "--summary-json", str(summary))
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert proc.stdout.rstrip().splitlines()[-1] == "CONFORMS for classify_control_mode: 3 of 5 cases"
    s = json.loads(summary.read_text())
    assert (s["conforms"], s["complete"]) == (True, False)
    rows = {(r["operation"], r["profile"]): (r["ran"], r["available"], r["skipped"]) for r in s["coverage"]["rows"]}
    frame_profile = next(c.profile for c in cases if c.operation == "decode_frame")
    assert rows[("decode_frame", frame_profile)] == (0, 2, {"operation not claimed": 2})
    assert sum(ran for ran, _, _ in rows.values()) == 3
    props = {p.get("name"): p.get("value") for p in junit(xml).iter("property")}
    assert props[f"coverage decode_frame {frame_profile}"] == "0 / 2; 2 operation not claimed"


def _vector_file_variants(cases, tmp_path: Path) -> dict[str, tuple[list[str], str]]:
    """Broken vector selections: --vectors arguments and the problem named."""
    good, _ = subset(cases, tmp_path, "classify_control_mode", 3, "good.json")
    doc = json.loads(good.read_text())
    variants = {}
    maybe = json.loads(json.dumps(doc))
    maybe["testGroups"][0]["tests"][0]["result"] = "maybe"  # used to count as a pass
    count = dict(doc, numberOfTests=4)
    flag = json.loads(json.dumps(doc))
    flag["testGroups"][1]["tests"][0]["flags"] = ["rule:no.such.rule"]
    for name, d in (("maybe", maybe), ("count", count), ("flag", flag)):
        (tmp_path / f"{name}.json").write_text(json.dumps(d))
    (tmp_path / "copy.json").write_text(good.read_text())
    (tmp_path / "broken.json").write_text("{not json")
    return {
        "result maybe": ([str(tmp_path / "maybe.json")], "'maybe' is not one of"),
        "numberOfTests": ([str(tmp_path / "count.json")], "numberOfTests is 4, the file has 3 tests"),
        "unknown flag": ([str(tmp_path / "flag.json")], "unknown rule rule:no.such.rule"),
        "same file twice": ([str(good), str(good)], "given twice"),  # used to run every case twice
        "same ids in two files": ([str(good), str(tmp_path / "copy.json")], "also in good.json"),
        "shipped file twice under two names": ([str(ROOT / "vectors" / "payloads.json"),
                                               str(_copy(ROOT / "vectors" / "payloads.json", tmp_path))],
                                              "also in payloads.json"),
        "not JSON": ([str(tmp_path / "broken.json")], "is not valid JSON"),
    }


def _copy(src: Path, tmp_path: Path) -> Path:
    dst = tmp_path / "payloads_copy.json"
    dst.write_bytes(src.read_bytes())
    return dst


@pytest.mark.parametrize("variant", ["result maybe", "numberOfTests", "unknown flag", "same file twice",
                                     "same ids in two files", "shipped file twice under two names", "not JSON"])
def test_run_vectors_validates_the_files_like_vectors_check(cases, tmp_path, variant):
    files, problem = _vector_file_variants(cases, tmp_path)[variant]
    proc = osdkc("run", "--testee", command_for("claims_nothing"), "--quiet",
                 *(a for f in files for a in ("--vectors", f)))
    assert proc.returncode == 2, proc.stdout + proc.stderr
    assert problem in proc.stderr and "Traceback" not in proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1, proc.stderr


def _group_members(pgid: int) -> list[int]:
    """Live (not zombie) processes of process group `pgid`."""
    members = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[2]) == pgid and fields[0] != "Z":
            members.append(int(stat.parent.name))
    return members


@pytest.mark.parametrize("signame", ["SIGINT", pytest.param("SIGTERM", marks=pytest.mark.slow)])
def test_an_interrupted_run_writes_partial_reports_and_leaves_no_testee(cases, tmp_path, signame):
    import os
    import signal
    import time

    vec, ids = subset(cases, tmp_path, "classify_control_mode", 10)
    marker = tmp_path / "stalled"
    xml, page, summary = tmp_path / "r.xml", tmp_path / "r.html", tmp_path / "s.json"
    proc = subprocess.Popen(
        [sys.executable, "-m", "osdk_conformance.cli", "run", "--testee", command_for("stalls_after", "4", str(marker)),
         "--vectors", str(vec), "--timeout", "300", "--quiet", "--junit", str(xml), "--html", str(page),
         "--summary-json", str(summary)],
        cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    pgid = None
    try:
        deadline = time.monotonic() + 60
        while not marker.exists() and proc.poll() is None and time.monotonic() < deadline:
            time.sleep(0.05)
        assert marker.exists(), proc.communicate(timeout=10)
        _, pgid, _ = map(int, marker.read_text().split())
        assert _group_members(pgid)  # the testee and its child, stalled on case 5
        proc.send_signal(getattr(signal, signame))
        out, err = proc.communicate(timeout=60)
        left = _group_members(pgid)
    finally:
        if proc.poll() is None:
            proc.kill()
        if pgid is not None and _group_members(pgid):  # a failing run must not leak them either
            os.killpg(pgid, signal.SIGKILL)
    assert left == []  # the testee and its child are gone
    assert proc.returncode == 128 + getattr(signal, signame), out + err  # the shell's convention: 130, 143
    assert "Traceback" not in err
    assert out.rstrip().splitlines()[-1] == f"INTERRUPTED by {signame}: no verdict (4 of 10 cases ran)"
    assert "6 interrupted" in out  # the coverage table
    s = json.loads(summary.read_text())
    assert s["interrupted"] == signame and s["conforms"] is False
    assert s["statuses"]["pass"] == 4 and s["statuses"]["skip"] == 6
    root = junit(xml)
    assert root.get("tests") == "10" and root.get("skipped") == "6" and root.get("failures") == "0"
    props = {p.get("name"): p.get("value") for p in root.iter("property")}
    assert props["interrupted"].startswith(f"by {signame}")
    assert "INTERRUPTED" in page.read_text()


# ---- supervision in-process -------------------------------------------------------------

def test_testee_restarts_after_a_failure_and_gives_up_after_five():
    t = supervision.Testee([sys.executable, str(TESTEES / "exit_first.py")])
    try:
        assert t.request({"op": "capabilities"})["ok"] is True
        kinds = []
        with pytest.raises(supervision.TesteeGaveUp):
            for _ in range(10):
                try:
                    t.request({"op": "decode_frame", "id": "x"})
                except supervision.TesteeFailure as f:
                    kinds.append(f.kind)
                    assert "giving up" in f.stderr
        assert kinds == ["testee_crash"] * 6
    finally:
        t.close()
    assert not t.running


def test_testee_timeout_kills_the_process_group():
    t = supervision.Testee([sys.executable, str(TESTEES / "sleeper.py")], timeout=0.3)
    t.request({"op": "capabilities"})
    pid = t._proc.pid
    with pytest.raises(supervision.TesteeFailure) as e:
        t.request({"op": "decode_frame"})
    assert e.value.kind == "testee_timeout"
    assert not t.running
    with pytest.raises(ProcessLookupError):
        import os
        os.kill(pid, 0)


@pytest.mark.parametrize("obj, ok", [
    ({"ok": True, "result": {}}, True),
    ({"ok": False, "error": "bad_crc16", "detail": "x"}, True),
    ({"ok": False, "unsupported": True}, True),
    ({"ok": True}, False),
    ({"ok": False}, False),
    ({"ok": "yes", "result": {}}, False),
    ([1, 2], False),
    ("ok", False),
])
def test_response_shapes(obj, ok):
    assert (supervision.validate_response(obj) is None) == ok


# ---- reports ---------------------------------------------------------------------------

def test_reports_escape_everything():
    nasty = '<script>alert("x")</script> & \x01'
    results = [
        Result("cat<1>", "id&1", "fail", nasty, {"hex": "aa", "expected": {"k": nasty}, "flags": ["E01", nasty]},
               kind="mismatch"),
        Result("cat<1>", "id2", "pass"),
        Result("cat2", "id3", "skip", "unsupported"),
        Result("cat2", "id4", "xfail", "known"),
        Result("cat2", "id5", "xpass", "remove it"),
        Result("cat2", "id6", "error", "not run"),
    ]
    page = report.html_report(results, "t<itle>")
    assert "<script>" not in page and "&lt;script&gt;" in page
    assert "http" not in page.replace('lang="en"', "")  # no external assets
    root = ET.fromstring(report.junit_xml(results, "suite"))
    assert root.get("tests") == "6" and root.get("failures") == "2" and root.get("errors") == "1"
    assert root.get("skipped") == "2"
    table = report.summary_table(results)
    assert "cat<1>" in table and "total" in table
    assert not report.conforms(results)
    assert report.conforms([r for r in results if r.status in ("pass", "skip", "xfail")])


# ---- the README's example testee ------------------------------------------------------------

def readme_testee(tmp_path: Path) -> str:
    """The command of the README's example testee (classify_control_mode only)."""
    readme = (ROOT / "README.md").read_text()
    section = readme[readme.index("## Testing your own implementation"):]
    code = section[section.index("```python\n") + len("```python\n"):section.index("```\n", section.index("```python"))]
    mine = tmp_path / "mine.py"
    mine.write_text(code)
    return f"{sys.executable} {mine}"


@pytest.mark.slow
def test_the_readme_example_testee_conforms(cases, tmp_path):
    xml = tmp_path / "r.xml"
    proc = osdkc("run", "--testee", readme_testee(tmp_path), "--quiet", "--junit", str(xml))
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-2000:]
    root = junit(xml)
    ran = [tc for tc in root.iter("testcase") if tc.find("skipped") is None]
    assert len(ran) >= 256 * 3 and root.get("failures") == "0"  # every mode byte in every profile
    # it conforms for what it implements, and says how much that is (the README's comment)
    mine = sum(c.operation == "classify_control_mode" for c in cases)
    verdict = proc.stdout.rstrip().splitlines()[-1]
    assert verdict == f"CONFORMS for classify_control_mode: {mine:,} of {len(cases):,} cases"


# ---- the Kaitai testee keeps signalling NaNs bit-exact ---------------------------------------

def _kaitai_testee():
    import importlib.util

    spec = importlib.util.spec_from_file_location("kaitai_python_testee",
                                                  ROOT / "conformance" / "testees" / "kaitai_python_testee.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


SNAN32 = (0x7F800001, 0xFFA00000, 0x7FBFFFFF)
SNAN64 = (0x7FF0000000000001, 0xFFF4000000000000)


def _snan_inputs():
    import struct

    from osdk_conformance._construct import build_frame

    mc = bytes([0x4B]) + struct.pack("<4I", SNAN32[0], SNAN32[1], 0x3F800000, SNAN32[2])
    # a3-fw3.1 broadcast: quaternion (f4 x4) and position (f8, f8, f4, f4, u1)
    bc = struct.pack("<H", 0b100010) + struct.pack("<4I", *SNAN32, 0x7FC00000) \
        + struct.pack("<2Q2IB", *SNAN64, SNAN32[0], 0x80000000, 5)
    return [
        {"op": "decode_payload", "profile": "a3-fw3.1", "hex": mc.hex(), "cmd_set": 1, "cmd_id": 3, "is_ack": False},
        {"op": "decode_payload", "profile": "a3-fw3.1", "hex": bc.hex(), "cmd_set": 2, "cmd_id": 0, "is_ack": False},
        {"op": "decode_frame", "profile": "a3-fw3.1", "hex": build_frame(cmd_set=2, cmd_id=0, value=bc).hex()},
        {"op": "decode_frame", "profile": "a3-fw3.1", "hex": build_frame(cmd_set=1, cmd_id=3, value=mc).hex()},
        {"op": "decode_stream", "profile": "a3-fw3.1", "chunks": [7],
         "hex": (b"\x00" + build_frame(cmd_set=1, cmd_id=3, value=mc) + build_frame(cmd_set=2, cmd_id=0, value=bc)).hex()},
    ]


@pytest.mark.parametrize("req", _snan_inputs(), ids=lambda r: r["op"])
def test_kaitai_testee_restores_signalling_nan_bits(req):
    from osdk_conformance.reference.codec import request_answer
    from osdk_conformance.harness.vectors import Case, compare

    kt = _kaitai_testee()
    got = json.loads(json.dumps(kt.answer(dict(req))))
    want = request_answer(dict(req))
    assert want["ok"] and got["ok"]
    case = Case("-", req["op"], req["profile"], "snan", "floats", "", {}, "valid", want["result"], ())
    assert compare(case, got) == (True, "")
    text = json.dumps(got)
    assert "0x7f800001" in text and "0x7fc00001" not in text  # the wire's sNaN, not the quieted one


def test_kaitai_testee_does_not_use_construct():
    """Its answers come from the Kaitai-generated parsers, never from the Construct spec."""
    testee = ROOT / "conformance" / "testees" / "kaitai_python_testee.py"
    lines = "".join(json.dumps(r) + "\n" for r in [{"op": "capabilities"}, *_snan_inputs()])
    probe = (f"import sys, io, runpy\n"
             f"sys.stdin = io.StringIO({lines!r})\n"
             f"try:\n    runpy.run_path({str(testee)!r}, run_name='__main__')\nexcept SystemExit:\n    pass\n"
             f"print(sorted(m for m in sys.modules if m.split('.')[0] == 'construct' "
             f"or m.startswith('osdk_conformance._construct')))\n")
    proc = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, timeout=60)
    assert proc.returncode == 0, proc.stderr
    out = proc.stdout.splitlines()
    assert len(out) == 1 + len(_snan_inputs()) + 1 and all(json.loads(x)["ok"] for x in out[:-1])
    assert out[-1] == "[]"


def test_every_bundled_implementation_has_a_reviewed_failure_list() -> None:
    # protobuf keeps one list per testee even when it is empty: the file is
    # where a known failure gets written down, with its reason
    for impl in BUNDLED_IMPLS:
        path = default_failure_list(impl)
        assert path.exists(), path
        assert read_failure_list(path) == {}, f"{path}: every bundled implementation conforms, so its list is empty"


@pytest.mark.slow
def test_impl_is_repeatable_and_runs_the_chosen_implementations_side_by_side(tmp_path: Path) -> None:
    proc = osdkc("run", "--impl", "construct", "--impl", "kaitai-python", "--filter", "worked",
                 "--report-dir", str(tmp_path), "--quiet")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "2 implementations" in proc.stdout and "ALL CONFORM" in proc.stdout
    ran = json.loads((tmp_path / "conformance.json").read_text())["implementations"]
    assert [s["impl"] for s in ran] == ["construct", "kaitai-python"]


def test_the_first_request_also_waits_for_the_start_up(tmp_path: Path) -> None:
    # start-up on a loaded machine is not a slow answer; later requests get the plain timeout
    slow = tmp_path / "slow_start.py"
    slow.write_text("import json, sys, time\ntime.sleep(1.0)\nfor line in sys.stdin:\n"
                    "    print(json.dumps({'ok': False, 'unsupported': True}), flush=True)\n")
    t = supervision.Testee([sys.executable, str(slow)], timeout=0.3)
    try:
        assert t.request({"op": "capabilities"}) == {"ok": False, "unsupported": True}
        assert t.request({"op": "decode_frame"}) == {"ok": False, "unsupported": True}
    finally:
        t.close()


@pytest.mark.parametrize("value, every", [(None, 10.0), ("2.5", 2.5), ("0", 10.0), ("-1", 10.0), ("soon", 10.0)])
def test_progress_lines_off_a_terminal_come_as_often_as_the_environment_says(monkeypatch, value, every):
    import io

    from osdk_conformance.harness.runner import PROGRESS_EVERY_ENV, StatusLine

    if value is None:
        monkeypatch.delenv(PROGRESS_EVERY_ENV, raising=False)
    else:
        monkeypatch.setenv(PROGRESS_EVERY_ENV, value)
    line = StatusLine(io.StringIO())
    assert line.every == every
    line.last -= every - 0.2
    assert not line.due() and line.due(changed=True)
    line.last -= 0.3
    assert line.due()
