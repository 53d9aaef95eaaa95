"""The C libFuzzer targets, built once per test run by .clusterfuzzlite/build.sh
for the two tests that need them: the build script's own test
(tests/test_fuzz_targets.py) and the libFuzzer smoke runs
(tests/test_languages.py).

The ASan+UBSan compile of the generated decoder and the ~25,000 broadcast
seeds cost tens of seconds of CPU, so one build serves both. For a smoke
run the build script's binaries are those of `make -C
conformance/testees/c fuzz`: clang 14, -O1 -g, libFuzzer, ASan and UBSan
that stop at the first error (the Makefile adds -fno-omit-frame-pointer and
its warnings-as-errors).

The result lives in the run's base temporary directory: under pytest-xdist
that is the parent of the workers' own, so the two files can run on two
workers and still share one build; a file lock lets one worker build while
the other waits.
"""
from __future__ import annotations

import fcntl
import json
import os
import shutil
import subprocess
import sys
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
TARGETS = ("deframer", "broadcast")
CLANG, CLANGXX = "clang-14", "clang++-14"
# what ClusterFuzzLite passes to an ASan build, with UBSan in the same build:
# the C targets have a build with each (.clusterfuzzlite/project.yaml)
ENV = {"CC": CLANG, "CXX": CLANGXX,
       "CFLAGS": "-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fsanitize=fuzzer-no-link",
       "LIB_FUZZING_ENGINE": "-fsanitize=fuzzer", "SANITIZER": "address", "PYTHON": sys.executable}


@dataclass(frozen=True)
class Build:
    returncode: int
    stdout: str
    stderr: str
    out: Path   # $OUT: fuzz_<target> and fuzz_<target>_seed_corpus.zip
    work: Path  # $WORK

    def failure(self) -> str:
        return self.stdout[-3000:] + self.stderr[-3000:]

    def seeds(self, target: str) -> Path:
        """The seed corpus of fuzz_<target> as build.sh wrote it before
        zipping it (its seeds()): the smoke runs read it there rather than
        unpack ~25,000 files again."""
        return self.work / "seeds" / f"fuzz_{target}"


def clusterfuzzlite_build(tmp_path_factory: pytest.TempPathFactory) -> Build:
    """Run build.sh, or return the result of the run this test run already made."""
    base = tmp_path_factory.getbasetemp()
    if os.environ.get("PYTEST_XDIST_WORKER"):
        base = base.parent
    top = base / "clusterfuzzlite"
    result = top / "result.json"
    with _locked(base / "clusterfuzzlite.lock"):
        if not result.exists():
            shutil.rmtree(top, ignore_errors=True)  # a build cut short (a timeout)
            top.mkdir()
            env = {"SRC": str(ROOT), "OUT": str(top / "out"), "WORK": str(top / "work"), **ENV}
            proc = subprocess.run(["bash", str(ROOT / ".clusterfuzzlite" / "build.sh")], capture_output=True,
                                  text=True, timeout=600, env={**_base_env(), **env})
            result.write_text(json.dumps({"returncode": proc.returncode, "stdout": proc.stdout,
                                          "stderr": proc.stderr}))
    done = json.loads(result.read_text())
    return Build(done["returncode"], done["stdout"], done["stderr"], top / "out", top / "work")


@contextmanager
def _locked(path: Path):
    with open(path, "w") as f:
        fcntl.flock(f, fcntl.LOCK_EX)
        try:
            yield
        finally:
            fcntl.flock(f, fcntl.LOCK_UN)


def _base_env() -> dict[str, str]:
    # build.sh links with $CXXFLAGS when set: a caller's own would replace ENV's CFLAGS
    return {k: v for k, v in os.environ.items() if k not in ("CFLAGS", "CXXFLAGS", "LIB_FUZZING_ENGINE")}
