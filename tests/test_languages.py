"""The generated parsers in every language, beyond the vector replay of
tests/test_runner.py (which runs `osdkc run --impl all`): each language's own
unit tests, the C decoder under gcc and clang with warnings as errors, the
sanitized C testee over every vector, and the libFuzzer smoke runs.

The compiled testees are built by `make setup`; these tests rebuild what is
missing with the same Makefiles, so they also run after a bare `pip install`.
The libFuzzer targets come from .clusterfuzzlite/build.sh, built once for
these smoke runs and its own test in tests/test_fuzz_targets.py
(tests/libfuzzer_build.py).
"""
from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest
from libfuzzer_build import TARGETS, clusterfuzzlite_build
from osdk_conformance.core import rules

ROOT = Path(__file__).resolve().parents[1]
TESTEES = ROOT / "conformance" / "testees"
C_DIR = TESTEES / "c"
CLANG = "clang-14"


def make(directory: Path, *targets: str, timeout: float = 900, **variables: str) -> subprocess.CompletedProcess:
    cmd = ["make", "--no-print-directory", "-C", str(directory), *targets, *(f"{k}={v}" for k, v in variables.items())]
    return subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)


def osdkc(*args: str, timeout: float = 900) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "osdk_conformance.cli", *args], capture_output=True, text=True,
                          timeout=timeout, cwd=ROOT)


def ok(proc: subprocess.CompletedProcess) -> str:
    assert proc.returncode == 0, proc.stdout[-5000:] + proc.stderr[-5000:]
    return proc.stdout + proc.stderr


def test_c_unit_tests_pass_plain_and_under_asan_ubsan():
    # gcc's ASan/UBSan and clang's UBSan, which alone flags NULL + 0: test_edges gives every decoder no
    # buffer at all (it failed with "applying zero offset to null pointer" before osdk_stream_init took
    # NULL to a static empty buffer) and osdk_kdiv/osdk_kmod INT64_MIN and -1
    out = ok(make(C_DIR, "test"))
    for name in ("test_crc", "test_deframer", "test_mode", "test_payload", "test_worked", "test_edges"):
        assert f"== {name} (asan+ubsan)" in out and f"== {name} (clang ubsan)" in out
    assert "test_edges: " in out and "checks passed" in out
    assert "runtime error" not in out and "AddressSanitizer" not in out


@pytest.mark.slow
@pytest.mark.parametrize("compiler", ["gcc", CLANG])
def test_c_decoder_compiles_without_warnings(compiler, tmp_path):
    if shutil.which(compiler) is None:
        pytest.fail(f"{compiler} is not installed; `make setup` installs it (tools/apt-packages.sh)")
    # -Werror: any warning fails the build
    out = ok(make(C_DIR, f"{tmp_path}/osdk-c-testee", BUILD=str(tmp_path), CC=compiler))
    assert "warning" not in out.lower()
    assert (tmp_path / "osdk-c-testee").exists()


def test_fuzz_harnesses_compile_without_warnings():
    # the flags and -Werror of `make fuzz`; the smoke runs below use the build script's binaries
    out = ok(make(C_DIR, "fuzz-lint"))
    assert "warning" not in out.lower()


def test_c_decoder_never_allocates():
    # The decoder works on caller-supplied buffers only (the testee around
    # it may allocate; the generated code may not).
    for src in (ROOT / "generated" / "c").glob("*.[ch]"):
        text = src.read_text()
        for fn in ("malloc(", "calloc(", "realloc(", "free("):
            assert fn not in text, f"{src.name} calls {fn[:-1]}"


@pytest.mark.slow
def test_sanitized_c_testee_conforms_over_every_vector(tmp_path):
    ok(make(C_DIR, "sanitize"))
    summary = tmp_path / "asan.json"
    proc = osdkc("run", "--testee", str(C_DIR / "build" / "osdk-c-testee-asan"), "--quiet",
                 "--summary-json", str(summary))
    out = ok(proc)
    assert "CONFORMS" in out
    assert "AddressSanitizer" not in out and "runtime error" not in out
    statuses = json.loads(summary.read_text())["statuses"]
    assert statuses["fail"] == 0 and statuses["error"] == 0 and statuses["pass"] > 30000


def test_go_glue_unit_tests():
    out = ok(make(TESTEES / "go", "test"))
    assert "ok" in out


def glue_sources() -> list[Path]:
    """The hand-written code around the generated parsers: the testees'
    glue, the C baseline and the C generator (not their unit tests and
    READMEs, whose examples name a profile on purpose)."""
    files = [*(TESTEES / "go").glob("*.go"), *(TESTEES / "javascript").glob("*.js"),
             *(TESTEES / "java" / "src").rglob("*.java"), *(C_DIR / "src").iterdir(), *(C_DIR / "fuzz").iterdir(),
             *(ROOT / "conformance" / "baseline" / "src").iterdir(), ROOT / "conformance" / "baseline" / "gen_items.py",
             *(ROOT / "tools" / "cgen").rglob("*.py"), *(ROOT / "tools" / "cgen" / "templates").iterdir()]
    return [f for f in files if f.is_file()]


def test_glue_names_no_profile_and_no_broadcast_item_type():
    # A profile or item is added in the spec alone: the glue gets profiles and
    # types from the tables and the generated code, so it spells none of them
    # (id, ksy name, or the class names the compilers make of them).
    r = rules.default_rules()
    spellings = {"OsdkBroadcastItems", "osdk_broadcast_items"}
    for p in r.profile_names:
        name = rules.ksy_name(p)
        spellings |= {p, name, name.upper(), "".join(part.capitalize() for part in name.split("_"))}
    sources = glue_sources()
    assert len(sources) > 20
    found = [f"{f.relative_to(ROOT)}: {s}" for f in sources for s in sorted(spellings) if s in f.read_text()]
    assert not found


@pytest.mark.slow
def test_libfuzzer_smoke_runs_find_nothing(tmp_path, tmp_path_factory):
    # Both targets at once, 10 s each, from their whole seed corpus (the
    # vectors; a smoke run: `make fuzz` is the long one), with the options of
    # `make fuzz-smoke`. A finding makes libFuzzer exit non-zero and leaves
    # the input in tmp_path.
    build = clusterfuzzlite_build(tmp_path_factory)
    assert build.returncode == 0, build.failure()
    env = {**os.environ, "ASAN_OPTIONS": "abort_on_error=1:detect_leaks=1",
           "UBSAN_OPTIONS": "halt_on_error=1:print_stacktrace=1"}
    runs = {}
    for target in TARGETS:
        # new coverage goes into a corpus of its own: the seeds are shared
        (tmp_path / target).mkdir()
        with open(tmp_path / f"{target}.log", "w") as log:
            runs[target] = subprocess.Popen(
                [str(build.out / f"fuzz_{target}"), "-max_total_time=10", "-print_final_stats=1",
                 "-rss_limit_mb=1024", f"-artifact_prefix={tmp_path}/{target}-", str(tmp_path / target),
                 str(build.seeds(target))], stdout=log, stderr=subprocess.STDOUT, env=env)
    try:
        for proc in runs.values():
            proc.wait(timeout=600)
    finally:
        for proc in runs.values():
            if proc.poll() is None:
                proc.kill()
                proc.wait()
    for target, proc in runs.items():
        out = (tmp_path / f"{target}.log").read_text(errors="replace")
        assert proc.returncode == 0, out[-5000:]
        # every seed the build script packaged was read, from its unzipped
        # copy; libFuzzer leaves out empty files (it runs the empty input anyway)
        with zipfile.ZipFile(build.out / f"fuzz_{target}_seed_corpus.zip") as z:
            seeds = sum(1 for info in z.infolist() if info.file_size)
        assert re.search(rf"\b{seeds} files found in {re.escape(str(build.seeds(target)))}\n", out), out[-3000:]
        assert "stat::number_of_executed_units" in out
        assert "ERROR: libFuzzer" not in out and "AddressSanitizer" not in out
