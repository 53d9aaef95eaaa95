"""Smoke runs of the coverage-guided fuzz targets that are not C (the C
libFuzzer smoke runs are in tests/test_languages.py), the local build of
the ClusterFuzzLite layout, and the crash -> vector tool (docs/FUZZING.md).

The atheris and Go runs start together when the first slow test asks
(about 20 s each, one core each) and run while build.sh builds, so that the
file costs about a minute of wall time (less when tests/test_languages.py,
whose C smoke runs share the build, made it first: tests/libfuzzer_build.py).
A finding fails the run: atheris exits non-zero, `go test -fuzz` fails and
writes the input to conformance/testees/go/testdata/fuzz/.
"""
from __future__ import annotations

import json
import re
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
GO_DIR = ROOT / "conformance" / "testees" / "go"
GO_SMOKE_EXECS = 150_000   # about what SMOKE_SECONDS give on 2 cores (15k-30k execs/s)
SMOKE_SECONDS = 10

sys.path.insert(0, str(ROOT / "tools"))
import fuzz_corpus  # noqa: E402
import fuzz_to_vector  # noqa: E402
from libfuzzer_build import TARGETS, clusterfuzzlite_build  # noqa: E402


class Smoke:
    def __init__(self, argv: list[str], cwd: Path) -> None:
        self.proc = subprocess.Popen(argv, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
        self._out: str | None = None

    def output(self) -> tuple[int, str]:
        if self._out is None:
            # bounded by the engines' own time limits; the timeout only
            # guards against a run that never starts fuzzing
            self._out, _ = self.proc.communicate(timeout=600)
        return self.proc.returncode, self._out


@pytest.fixture(scope="module")
def smoke_runs(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("fuzz_smoke")
    corpus = tmp / "decode_corpus"
    fuzz_corpus.main(["deframer", str(corpus)])
    runs = {
        "atheris": Smoke([sys.executable, str(ROOT / "fuzz" / "fuzz_decode.py"), str(corpus),
                          f"-max_total_time={SMOKE_SECONDS}", "-print_final_stats=1",
                          f"-artifact_prefix={tmp}/"], cwd=tmp),
        # a count, not a duration: with -fuzztime=Ns the Go 1.26 coordinator can
        # report its own deadline as a failure when a loaded machine is slow to
        # stop the worker (go.dev/issue/75804, fixed in Go 1.27)
        "go": Smoke(["go", "test", "-run", "^$", "-fuzz", "^FuzzDecodeStream$", f"-fuzztime={GO_SMOKE_EXECS}x",
                     "-fuzzminimizetime=100x", "-parallel=1", "."], cwd=GO_DIR),
    }
    yield runs
    for run in runs.values():
        if run.proc.poll() is None:
            run.proc.kill()
            run.proc.communicate()


@pytest.mark.slow
def test_clusterfuzzlite_build_script_builds_c_targets_that_run(tmp_path, tmp_path_factory, smoke_runs):
    # smoke_runs: the atheris and Go runs start now and fuzz while this builds
    build = clusterfuzzlite_build(tmp_path_factory)
    assert build.returncode == 0, build.failure()
    # outside the builder image the Go copy is compiled (go vet), not linked
    assert "fuzz_go_decode_stream skipped (its package copy compiles)" in build.stdout
    for target in TARGETS:
        binary, seeds = build.out / f"fuzz_{target}", build.out / f"fuzz_{target}_seed_corpus.zip"
        with zipfile.ZipFile(seeds) as z:
            names = z.namelist()
            assert len(names) > 100
            corpus = tmp_path / f"seeds_{target}"
            z.extractall(corpus, members=names[:200])
        run = subprocess.run([str(binary), "-runs=1", str(corpus)], capture_output=True, text=True, timeout=300)
        assert run.returncode == 0, run.stderr[-3000:]
        # every seed once, plus libFuzzer's own one or two runs (the empty input
        # it tries, the mutation asked for): the total has been 201 and, once
        # in a full suite under load, 202 for 200 seeds
        done = re.search(r"Done (\d+) runs", run.stderr)
        assert "INITED" in run.stderr and done, run.stderr[-2000:]
        assert len(names[:200]) + 1 <= int(done.group(1)) <= len(names[:200]) + 2, run.stderr[-2000:]


@pytest.mark.slow
def test_atheris_target_runs_and_finds_nothing(smoke_runs):
    rc, out = smoke_runs["atheris"].output()
    assert rc == 0, out[-5000:]
    executed = int(re.search(r"stat::number_of_executed_units: (\d+)", out).group(1))
    assert executed > 0
    assert "Uncaught Python exception" not in out


@pytest.mark.slow
def test_go_fuzz_target_runs_and_finds_nothing(smoke_runs):
    rc, out = smoke_runs["go"].output()
    assert rc == 0, out[-5000:]
    execs = [int(n) for n in re.findall(r"execs: (\d+)", out)]
    assert execs and max(execs) > 0, out[-2000:]
    assert "--- FAIL" not in out and out.rstrip().splitlines()[-1].startswith("ok")


def test_go_corpus_file_reads_as_its_bytes(tmp_path):
    artifact = tmp_path / "0123abcd"
    artifact.write_text('go test fuzz v1\n[]byte("\\x05\\xaa\\x00\\xffhi\\n\\u00e9\\\\\\"")\n')
    assert fuzz_to_vector.read_artifact(artifact) == b"\x05\xaa\x00\xffhi\n\xc3\xa9\\\""


def test_stream_artifact_becomes_a_vector_with_the_reference_answer(tmp_path):
    from osdk_conformance.reference.codec import answer

    worked = bytes.fromhex("aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba")
    broken = worked[:20] + b"\xaa" + worked[21:] + worked[:13]  # a bad CRC-32, a truncated tail
    artifact = tmp_path / "crash-1"
    artifact.write_bytes(fuzz_corpus.stream_seed("m100-fw3.1", broken))
    vec = tmp_path / "v.json"
    assert fuzz_to_vector.main(["--target", "deframer", str(artifact), "--out", str(vec)]) == 0
    doc = json.loads(vec.read_text())
    (group,) = doc["testGroups"]
    (test,) = group["tests"]
    assert (group["operation"], group["profile"], test["category"]) == ("decode_stream", "m100-fw3.1",
                                                                         "fuzz.regression")
    size = len(broken) % 64 + 1  # the read size the selector byte chose; the rest is one last read
    reads = [size] * (len(broken) // size) + ([len(broken) % size] if len(broken) % size else [])
    assert test["input"] == {"hex": broken.hex(), "chunks": reads}
    ref = answer("decode_stream", "m100-fw3.1", test["input"])
    assert test["result"] == "valid"
    assert [e["error"] for e in test["expected"]["events"] if e["kind"] == "error"] == \
        [e["error"] for e in ref["result"]["events"] if e["kind"] == "error"]
    assert "bad_crc32" in [e.get("error") for e in test["expected"]["events"]]
    run = subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "run", "--impl", "construct", "--vectors",
                          str(vec), "--quiet"], capture_output=True, text=True, cwd=ROOT, timeout=300)
    assert run.returncode == 0 and "CONFORMS" in run.stdout, run.stdout[-2000:] + run.stderr[-2000:]


def test_broadcast_artifact_becomes_one_case_per_profile(tmp_path, capsys):
    assert fuzz_to_vector.main(["--target", "broadcast", "--hex", "ffff00"]) == 0
    captured = capsys.readouterr()
    doc = json.loads(captured.out)
    assert [g["profile"] for g in doc["testGroups"]] == list(fuzz_corpus.PROFILES)
    for g in doc["testGroups"]:
        (test,) = g["tests"]
        assert test["input"] == {"hex": "ffff00", "cmd_set": 2, "cmd_id": 0, "is_ack": False}
        assert test["result"] == "invalid"  # reserved flag bits, or a value shorter than the flags promise
    assert captured.err.count("s.add(\"decode_payload\"") == 3


@pytest.mark.parametrize("args, message", [
    (["--target", "go", "--hex", "zz"], "--hex: not a hex string"),
    (["--target", "deframer", "--hex", ""], "an empty input"),
    (["--target", "go", "/nonexistent/crash-1"], "cannot read /nonexistent/crash-1"),
])
def test_bad_input_is_one_line_and_exit_2(args, message, capsys):
    assert fuzz_to_vector.main(args) == 2
    err = capsys.readouterr().err
    assert message in err and len(err.strip().splitlines()) == 1


@pytest.fixture(scope="module")
def harness():
    sys.path.insert(0, str(ROOT / "fuzz"))
    import fuzz_decode

    return fuzz_decode


def test_atheris_harness_passes_the_worked_frames_and_flags_broken_promises(harness):
    worked = bytes.fromhex("aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba"
                           "aa1600000000000007001ede02000018035769c676b2")
    for profile in fuzz_corpus.PROFILES:
        harness.test_one_input(fuzz_corpus.stream_seed(profile, worked))
    frame = {"offset": 0, "kind": "frame", "frame": {"sof": "aa", "len": 35}}
    harness.check_events([frame, {"offset": 35, "kind": "garbage", "length": 3}], 38, "t")
    with pytest.raises(harness.Finding, match="out of order or outside"):
        harness.check_events([frame], 30, "t")
    with pytest.raises(harness.Finding, match="out of order or outside"):
        harness.check_events([{"offset": 5, "kind": "garbage", "length": 4}, frame], 40, "t")
    with pytest.raises(harness.Finding, match="error class 'undecodable'"):
        harness.check_events([{"offset": 0, "kind": "error", "error": "undecodable", "length": 35}], 35, "t")
