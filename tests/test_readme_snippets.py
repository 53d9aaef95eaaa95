"""Every fenced code block of every README the project ships is accounted
for here, in one of three ways, and test_every_block_is_accounted_for lists
each block that is not:

- run by this module. Shell commands run as written in a throwaway
  directory laid out as the README assumes (a checkout beside the user's
  project); Python runs with the interpreter the README's install gives;
  the Go, JavaScript, Java and C snippets become one throwaway program per
  language, built against the generated library installed the way the
  README installs it, fed the frames of tests/library_examples.py, and
  their output is held against the reference (osdk_conformance.api). Where
  a snippet leaves names open (a stream, a callback body), the harness
  around it gives them values and nothing else.
- the same text as what another test runs (Elsewhere): that test's file
  must hold the code that runs it.
- marked in its README on the line before the fence,
  `<!-- snippet: not run: REASON -->`, where REASON is one of NOT_RUN.

A shell block whose lines fall into different groups is accounted for line
by line (LINES): every command of it must be listed there, and each listed
command is run, found in another test, or given one of NOT_RUN's reasons.

The languages build concurrently (threads around subprocesses), each
reusing what a user's machine already has: the Go module and build caches
(offline, GOPROXY=off), npm's cache, a copy of ~/.m2 (so that the README's
`mvn install` leaves the real one alone), the objects examples/c built.
"""
from __future__ import annotations

import concurrent.futures
import csv
import functools
import json
import os
import re
import shlex
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

import pytest

# every README snippet built and run in its language: `make quick` leaves it out
pytestmark = pytest.mark.slow

from osdk_conformance import api
from osdk_conformance.core.capture import RX, TX, CaptureWriter

from library_examples import WORKED_FRAME, receive_stream

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent          # the venv's bin: python, pip, osdkc
PROFILES = api.profiles()

# Why a block (or a line of a shell block) cannot run inside a test. A
# marker with any other text is an error, so nothing is skipped silently.
NOT_RUN = {
    "too slow for a test": "the kit, the whole suite, a replay of every golden vector, a fuzzing campaign or a "
                           "benchmark: tens of seconds to many minutes",
    "needs a flight controller": "a flight controller on a serial port, or a capture of one",
    "needs a checkout of DJI's Onboard-SDK": "DJI's sources, which are not part of this repository",
    "needs the seed": "the seed file, which is not part of this repository",
    "rewrites files in the checkout": "regenerates generated/ or rebuilds in place, in a tree other work is using",
    "runs until stopped": "a server: the simulator serves its pseudo-terminal until it is killed",
}

MARKER = re.compile(r"<!-- snippet: not run: (?P<reason>.+?) -->")
FENCE = re.compile(r"^(?P<indent> {0,3})(?P<fence>`{3,}|~{3,})(?P<info>.*)$")
SKIP_DIRS = {".git", ".venv", "node_modules", "build", "target", "bin", "dist", "__pycache__", ".pytest_cache",
             ".hypothesis", ".cache"}


# ---------------------------------------------------------------- the blocks

@dataclass(frozen=True)
class Block:
    readme: str          # relative to ROOT
    line: int            # of the opening fence, 1-based
    lang: str            # the info string's first word
    text: str
    marker: str | None   # the reason of a not-run marker on the line before the fence

    @property
    def where(self) -> str:
        return f"{self.readme}:{self.line} ```{self.lang}"


@functools.cache
def readmes() -> tuple[Path, ...]:
    """README*.md of the repository, outside dependency, build and ignored trees."""
    found = []
    for dirpath, dirnames, filenames in os.walk(ROOT):
        dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS)
        found += [Path(dirpath) / f for f in sorted(filenames) if re.fullmatch(r"README.*\.md", f)]
    if (ROOT / ".git").exists():
        rel = "\n".join(str(p.relative_to(ROOT)) for p in found)
        ignored = subprocess.run(["git", "check-ignore", "--stdin"], cwd=ROOT, input=rel, capture_output=True,
                                 text=True).stdout.split()
        found = [p for p in found if str(p.relative_to(ROOT)) not in ignored]
    return tuple(found)


def read_blocks(path: Path) -> tuple[list[Block], list[str]]:
    """The fenced blocks of a README, and what is wrong with its markers."""
    rel = str(path.relative_to(ROOT))
    lines = path.read_text(encoding="utf-8").splitlines()
    blocks, problems, used_markers = [], [], set()
    i = 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        fence, indent = m["fence"], len(m["indent"])
        closing = re.compile(rf"^ {{0,3}}{re.escape(fence[0])}{{{len(fence)},}}\s*$")
        body = []
        j = i + 1
        while j < len(lines) and not closing.match(lines[j]):
            body.append(lines[j][min(indent, len(lines[j]) - len(lines[j].lstrip(" "))):])
            j += 1
        if j == len(lines):
            problems.append(f"{rel}:{i + 1}: a fence that is never closed")
        marker = None
        if i > 0 and (mm := MARKER.fullmatch(lines[i - 1].strip())):
            marker = mm["reason"]
            used_markers.add(i - 1)
        blocks.append(Block(rel, i + 1, (m["info"].split() or [""])[0], "\n".join(body) + "\n", marker))
        i = j + 1
    for n, line in enumerate(lines):
        if "snippet:" in line and "<!--" in line and n not in used_markers:
            problems.append(f"{rel}:{n + 1}: a snippet marker that is not `<!-- snippet: not run: REASON -->` "
                            f"on the line right before a fence: {line.strip()}")
    return blocks, problems


@functools.cache   # once a session: the jobs look their blocks up from several threads
def all_blocks() -> tuple[list[Block], list[str]]:
    blocks, problems = [], []
    for path in readmes():
        b, p = read_blocks(path)
        blocks += b
        problems += p
    return blocks, problems


@dataclass(frozen=True)
class Snippet:
    """Picks one block: the only one of `readme` in `lang` that contains `anchor`."""
    readme: str
    lang: str
    anchor: str

    def matches(self, block: Block) -> bool:
        return block.readme == self.readme and block.lang == self.lang and self.anchor in block.text


SNIPPETS = {
    "readme.tree": Snippet("README.md", "", "spec/        the single source of truth"),
    "readme.osdkc": Snippet("README.md", "sh", "osdkc decode --profile a3-fw3.1 capture.bin"),
    "readme.console": Snippet("README.md", "console", "$ osdkc decode"),
    "readme.api": Snippet("README.md", "python", "from osdk_conformance import api"),
    "readme.testee": Snippet("README.md", "python", 'req["op"] == "capabilities"'),
    "readme.testee_run": Snippet("README.md", "sh", 'osdkc run --testee "python3 mine.py"'),
    "gen.python.install": Snippet("generated/README.md", "sh", "pip install generated/python"),
    "gen.python.receive": Snippet("generated/README.md", "python", "osdk_kaitai.Deframer()"),
    "gen.python.send": Snippet("generated/README.md", "python", "osdk_kaitai.encode_frame("),
    "gen.js.install": Snippet("generated/README.md", "sh", "npm install"),
    "gen.js.receive": Snippet("generated/README.md", "js", "new osdk.Deframer()"),
    "gen.js.send": Snippet("generated/README.md", "js", "osdk.encodeFrame("),
    "gen.java.install": Snippet("generated/README.md", "sh", "mvn "),
    "gen.java.dependency": Snippet("generated/README.md", "xml", "<artifactId>osdk-kaitai</artifactId>"),
    "gen.java.receive": Snippet("generated/README.md", "java", "new Deframer()"),
    "gen.java.send": Snippet("generated/README.md", "java", "Osdk.encodeFrame("),
    "gen.go.install": Snippet("generated/README.md", "sh", "go build"),
    "gen.go.receive": Snippet("generated/README.md", "go", "func receive("),
    "gen.go.send": Snippet("generated/README.md", "go", "osdk.EncodeFrame("),
    "gen.c.build": Snippet("generated/README.md", "sh", "make -C generated/c"),
    "gen.c.receive": Snippet("generated/README.md", "c", "osdk_deframer_init("),
    "gen.c.send": Snippet("generated/README.md", "c", "osdk_encode_frame("),
    "gen.wireshark": Snippet("generated/README.md", "sh", "tshark"),
    "gen.regen": Snippet("generated/README.md", "sh", "tools/regen.py"),
    "c.build": Snippet("generated/c/README.md", "sh", "make -C generated/c"),
    "testees.c.usage": Snippet("conformance/testees/c/README.md", "c", "osdk_frame_problem(buf, len"),
    "testees.c.build": Snippet("conformance/testees/c/README.md", "sh", "make -C conformance/testees/c"),
    "baseline": Snippet("conformance/baseline/README.md", "sh", "osdk-baseline --bench"),
    "kit.declaration": Snippet("conformance/testee-kit/c/README.md", "c", "void my_encode_movement("),
    "kit.callback": Snippet("conformance/testee-kit/c/README.md", "c",
                            "static void encode_movement_control(okit_request *req)"),
    "kit.main": Snippet("conformance/testee-kit/c/README.md", "c", "okit_main(&t"),
    "kit.build": Snippet("conformance/testee-kit/c/README.md", "sh", "encode_only.c"),
    "kit.error": Snippet("conformance/testee-kit/c/README.md", "c", 'okit_error(req, "bad_crc16"'),
}


def snippet(name: str) -> Block:
    sel = SNIPPETS[name]
    hits = [b for b in all_blocks()[0] if sel.matches(b)]
    assert len(hits) == 1, (f"{name}: {len(hits)} ```{sel.lang} blocks of {sel.readme} contain {sel.anchor!r}; "
                            f"expected exactly one (did the README change?)")
    return hits[0]


# ---------------------------------------------------------------- shell lines

RUN = "run"


@dataclass(frozen=True)
class Elsewhere:
    """A test, or a Makefile target `make test` depends on, already runs this command: `path` holds each `code`."""
    path: str
    code: tuple[str, ...]


@dataclass(frozen=True)
class NotRun:
    reason: str


# Shell blocks accounted for line by line: command (comments dropped,
# continuations joined, blanks collapsed) -> RUN, Elsewhere or NotRun.
SLOW, FC, DJI = NotRun("too slow for a test"), NotRun("needs a flight controller"), \
    NotRun("needs a checkout of DJI's Onboard-SDK")
LINES: dict[str, dict[str, object]] = {
    "readme.osdkc": {
        "osdkc decode --profile a3-fw3.1 capture.bin": RUN,
        "osdkc decode --profile a3-fw3.1 --direction both run.pcapng": RUN,
        "osdkc decode --profile a3-fw3.1 --format csv --items battery,quaternion run.pcapng > flight.csv": RUN,
        "osdkc plot run.pcapng --profile a3-fw3.1 --items battery,attitude -o flight.html": RUN,
        "osdkc watch --port /dev/ttyUSB0 --profile a3-fw3.1": FC,
        "osdkc decode --profile a3-fw3.1 --port /dev/ttyUSB0": FC,
        "osdkc spec trace --seed FILE": NotRun("needs the seed"),
        "osdkc spec check": Elsewhere("tests/test_lone_clone.py", ('"osdk_conformance.cli", "spec", "check")',)),
        "osdkc vectors check": Elsewhere("tests/test_vectors.py", ('osdkc("vectors", "check")',)),
        "osdkc vectors coverage": Elsewhere("tests/test_vectors.py", ('osdkc("vectors", "coverage")',)),
        "osdkc run --impl construct": SLOW,
        "osdkc run --impl all": Elsewhere("tests/test_runner.py", ('osdkc("run", "--impl", "all",',)),
        "osdkc run --impl c --impl go": SLOW,
        "osdkc run --impl c-target": Elsewhere("tests/test_on_target.py", ('"run", "--impl", "c-target"',)),
        "osdkc selftest": SLOW,
        "osdkc fuzz --impl all": SLOW,
        "osdkc sim --profile a3-fw3.1": NotRun("runs until stopped"),
        "osdkc sim --bug long-frame-hang": NotRun("runs until stopped"),
        "osdkc explain 0x4B": RUN,
        "osdkc doctor --port /dev/ttyUSB0": FC,
        "osdkc tap --fc /dev/ttyUSB0 --profile a3-fw3.1": FC,
        "osdkc tap --listen-host-tx /dev/ttyUSB1 --listen-fc-tx /dev/ttyUSB2 --profile a3-fw3.1": FC,
        "osdkc host --port /dev/pts/3 --profile a3-fw3.1 --app-id N --key-env VAR --bug gap": FC,
        "osdkc device --port /dev/ttyUSB0 --profile a3-fw3.1 --active": FC,
        "osdkc device --port /dev/ttyUSB0 --profile a3-fw3.1 --active --app-id N --allow-motion": FC,
        "osdkc device --replay captures/run.pcapng --profile a3-fw3.1": FC,
        "osdkc fuzz --port /dev/ttyUSB0 --profile a3-fw3.1": FC,
        "osdkc wireshark install": RUN,
        "osdkc soak --duration 600": SLOW,
        "osdkc bench": SLOW,
        "osdkc bench --only reliability --runs 200": SLOW,
        "osdkc bench --only doctor": SLOW,
        "osdkc bench --only tap": SLOW,
        "osdkc sdk host-test --osdk ~/Onboard-SDK": DJI,
        "osdkc sdk test --osdk ~/Onboard-SDK": DJI,
        "osdkc kit": SLOW,
        "osdkc --version": RUN,
    },
    "readme.testee_run": {
        'osdkc run --testee "python3 mine.py"': Elsewhere("tests/test_runner.py",
                                                          ('osdkc("run", "--testee", readme_testee(tmp_path)',)),
        'osdkc run --testee "python3 mine.py" --filter control_mode. --junit report.xml --html report.html': RUN,
        "osdkc run --impl kaitai-python": SLOW,
    },
    "gen.python.install": {
        "pip install generated/python": RUN,
        "make -C examples/python build": Elsewhere("Makefile", ("EXAMPLES := python",
                                                                "-C examples/$$lang build")),
    },
    "gen.wireshark": {
        "osdkc wireshark install": RUN,
        "tshark -r capture.pcapng -o osdk.profile:m100-fw3.1 -V": RUN,
        "tshark -r capture.pcapng -X lua_script:generated/wireshark/osdk.lua -T fields -e osdk.command "
        "-e osdk.broadcast.battery": RUN,
    },
    "gen.regen": {
        "make regen": NotRun("rewrites files in the checkout"),
        ".venv/bin/python tools/regen.py --target go": NotRun("rewrites files in the checkout"),
        ".venv/bin/python tools/regen.py --check": Elsewhere("Makefile", ("$(BIN)/python tools/regen.py --check",)),
    },
    "testees.c.build": {
        "make -C conformance/testees/c build": Elsewhere("Makefile", ("LANGS  := javascript java go c",
                                                                      "-C conformance/testees/$$lang build")),
        "make -C conformance/testees/c sanitize": Elsewhere("tests/test_languages.py", ('make(C_DIR, "sanitize")',)),
        "make -C conformance/testees/c test": Elsewhere("tests/test_languages.py", ('make(C_DIR, "test")',)),
        ".venv/bin/osdkc run --impl c": SLOW,
        ".venv/bin/osdkc run --testee conformance/testees/c/build/osdk-c-testee-asan": Elsewhere(
            "tests/test_languages.py", ('osdkc("run", "--testee", str(C_DIR / "build" / "osdk-c-testee-asan"),',)),
    },
    "kit.build": {
        "cc -std=c99 -O2 -Iconformance/testee-kit/c -Igenerated/c -o encode-only "
        "conformance/testee-kit/c/example/encode_only.c conformance/testee-kit/c/okit.c "
        "conformance/testee-kit/c/jsonread.c generated/c/osdk_json.c": RUN,
        "osdkc run --testee ./encode-only": Elsewhere("tests/test_testee_kit.py",
                                                      ('"run", "--testee", str(KIT / "build" / "encode-only")',)),
    },
}
# Placeholders the README writes for values the user fills in, given a
# value only to check that osdkc accepts the rest of the command line.
PLACEHOLDERS = {"N": "1000001"}


def commands(block: Block) -> list[str]:
    """The commands of a shell block: continuations joined, comments dropped."""
    out, pending = [], ""
    for line in block.text.splitlines():
        pending += line
        if pending.endswith("\\"):
            pending = pending[:-1] + " "
            continue
        code, quote = [], None
        for k, ch in enumerate(pending):
            if quote:
                quote = None if ch == quote else quote
            elif ch in "'\"":
                quote = ch
            elif ch == "#" and (k == 0 or pending[k - 1].isspace()):
                break
            code.append(ch)
        if "".join(code).strip():
            out.append(" ".join("".join(code).split()))
        pending = ""
    return out


def same_code_in(path: str, code: str) -> bool:
    text = (ROOT / path).read_text(encoding="utf-8")
    return " ".join(code.split()) in " ".join(text.split())


def account_lines(name: str) -> list[str]:
    """Checks the line plan of a shell block; returns the commands to run, in order."""
    block = snippet(name)
    plan = LINES[name]
    have = commands(block)
    missing, stale = [c for c in have if c not in plan], [c for c in plan if c not in have]
    assert not missing and not stale, (
        f"{block.where}: its commands and LINES[{name!r}] differ\n  in the README only: {missing}\n"
        f"  in LINES only: {stale}")
    problems = []
    for cmd, action in plan.items():
        if isinstance(action, Elsewhere):
            if not (ROOT / action.path).is_file():
                problems.append(f"{block.where}: `{cmd}` is said to run in {action.path}, which does not exist")
                continue
            for code in action.code:
                if not same_code_in(action.path, code):
                    problems.append(f"{block.where}: `{cmd}` is said to run in {action.path}, which has no {code!r}")
        elif isinstance(action, NotRun):
            if action.reason not in NOT_RUN:
                problems.append(f"{block.where}: `{cmd}`: {action.reason!r} is not one of NOT_RUN")
        else:
            assert action == RUN, action
    assert not problems, "\n".join(problems)
    return [c for c in have if plan[c] == RUN]


# ---------------------------------------------------------------- running things

def env(**extra: str) -> dict[str, str]:
    out = dict(os.environ, PATH=f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}")
    out.update(extra)
    return out


def run(argv: list[str] | str, cwd: Path, what: str, *, stdin: bytes = b"", environ: dict | None = None,
        timeout: float = 300, status: int | None = 0) -> subprocess.CompletedProcess:
    """Runs argv (a string: a bash script, -e and pipefail) and fails with `what`, the output and the status."""
    cmd = ["bash", "-e", "-o", "pipefail", "-c", argv] if isinstance(argv, str) else argv
    try:
        proc = subprocess.run(cmd, cwd=cwd, input=stdin, capture_output=True, timeout=timeout,
                              env=environ if environ is not None else env())
    except subprocess.TimeoutExpired:
        pytest.fail(f"{what}: no answer within {timeout:g} s: {cmd}")
    if status is not None and proc.returncode != status:
        pytest.fail(f"{what}: exit status {proc.returncode}, expected {status}\n$ {argv}\n--- stdout\n"
                    f"{proc.stdout.decode(errors='replace')[-4000:]}\n--- stderr\n"
                    f"{proc.stderr.decode(errors='replace')[-4000:]}")
    return proc


def out_lines(proc: subprocess.CompletedProcess) -> list[str]:
    return proc.stdout.decode().splitlines()


def need(*tools: str) -> None:
    missing = [t for t in tools if shutil.which(t) is None]
    if missing:
        pytest.fail(f"{', '.join(missing)} not on PATH: the README snippets of that language cannot be built "
                    f"(`make setup` installs the toolchains, README.md)")


def split_at(block: Block, marker: str) -> tuple[str, str]:
    """The lines of a fragment before the comment line starting with
    `marker`, and those after it and the comment lines following it."""
    lines = block.text.splitlines()
    at = [k for k, line in enumerate(lines) if line.lstrip().startswith(marker)]
    assert len(at) == 1, f"{block.where}: the harness splits this fragment at its {marker!r} line, which is gone"
    k = at[0] + 1
    while k < len(lines) and lines[k].lstrip().startswith(("//", "/*", "#")):
        k += 1
    return "\n".join(lines[:at[0]]) + "\n", "\n".join(lines[k:]) + "\n"


def indent(text: str, by: str = "    ") -> str:
    return "".join(by + line + "\n" if line.strip() else "\n" for line in text.splitlines())


def shown_hex(block: Block) -> str:
    """The worked frame the snippet's comment shows (whole, or cut as `aa2300...fcdb01ba`)."""
    m = re.search(r"\b(aa[0-9a-f]{10,})\b", block.text) or re.search(r"\b(aa[0-9a-f]*)\.\.\.([0-9a-f]+)\b", block.text)
    assert m, f"{block.where}: no frame in hex in its comments"
    return m.group(0)


def matches_shown(shown: str, actual: str) -> bool:
    head, _, tail = shown.partition("...")
    return actual == shown if not tail else actual.startswith(head) and actual.endswith(tail)


# ---------------------------------------------------------------- the reference

def worked_frame() -> str:
    value = api.encode_movement_control(0x4B, 1.0, -2.0, 0.5, 30.0)
    frame = api.encode_frame(cmd_set=1, cmd_id=3, value=value, session=0, seq=0x1234).hex()
    assert frame == WORKED_FRAME
    return frame


def broadcast_data(event: api.Event) -> dict | None:
    """The items of a plain broadcast frame event, else None."""
    if event.kind != "frame" or event.command != "broadcast" or event.frame["is_ack"]:
        return None
    return event.frame["data"]["value"]["body"]["data"]


def rejected_frame(event: api.Event) -> bool:
    """An error of the frame decoder (the deframer passed the bytes on)."""
    return event.kind == "error" and event.frame_header is not None


@functools.cache
def error_by_field() -> dict[str, str]:
    tables = ROOT / "generated" / "tables" / "osdk_tables.json"
    if not tables.is_file():
        pytest.fail(f"{tables} is missing: `.venv/bin/python tools/regen.py` writes it")
    return json.loads(tables.read_text())["error_by_field"]


def check_field(where: str, error_class: str, field: str) -> None:
    """A library's error field: the ksy field whose check gives that class."""
    if error_class in error_by_field().values():
        assert error_by_field().get(field) == error_class, f"{where}: {error_class} names field {field!r}"
    else:
        assert field, f"{where}: {error_class} names no field"


def compare_error_lines(where: str, got: list[str], want: list[str]) -> None:
    """`want` has `error OFFSET CLASS` where the output has `error OFFSET CLASS FIELD`."""
    assert len(got) == len(want), f"{where}: printed\n" + "\n".join(got) + "\nexpected\n" + "\n".join(want)
    for g, w in zip(got, want):
        if w.startswith("error "):
            head, _, field = g.rpartition(" ")
            assert head == w, f"{where}: printed {g!r}, expected {w!r} and a field"
            check_field(where, w.split()[2], field)
        else:
            assert g == w, f"{where}: printed {g!r}, expected {w!r}"


def write_capture(path: Path, records: list[tuple[int, bytes]]) -> Path:
    writer = CaptureWriter(path, {"profile": "snippets"})
    for direction, data in records:
        writer.record(direction, data)
    writer.close()
    return path


def well_formed_stream(profile: str) -> bytes:
    """Garbage, good frames, a broken CRC-32 and a cut-off end; every value one the spec accepts."""
    full = api.encode_broadcast_frame(profile, {i: None for i in api.broadcast_items(profile)} | {"battery": 87},
                                      seq=1)
    stamp = api.encode_broadcast_frame(profile, {"time_stamp": {"time": 7}}, seq=2)
    bad_crc = bytearray(api.encode_broadcast_frame(profile, {"battery": 50}, seq=3))
    bad_crc[-1] ^= 0x01
    ack = api.encode_frame(value=b"\x00\x00", is_ack=True, session=1, seq=99)
    empty = api.encode_frame(session=0, seq=7)
    return b"\x05\x06" + full + stamp + bytes(bad_crc) + bytes.fromhex(WORKED_FRAME) + ack + empty + full[:20]


def checkout(tmp: Path, copies: tuple[str, ...] = (), links: tuple[str, ...] = ()) -> Path:
    """tmp/osdk-conformance: the parts of the checkout a block reads (`links`,
    symlinks) or builds in (`copies`, so that nothing is written into the tree)."""
    co = tmp / "osdk-conformance"
    for rel in copies:
        shutil.copytree(ROOT / rel, co / rel, symlinks=True,
                        ignore=shutil.ignore_patterns("build", "target", "node_modules", "*.egg-info"))
    for rel in links:
        (co / rel).parent.mkdir(parents=True, exist_ok=True)
        (co / rel).symlink_to(ROOT / rel)
    return co


def seed_c_objects(build: Path) -> None:
    """Starts a C build directory from the objects examples/c built (mtimes
    kept): the library's Makefile recompiles only what is out of date."""
    built = ROOT / "examples" / "c" / "build" / "osdk"
    if built.is_dir():
        shutil.copytree(built, build, dirs_exist_ok=True)


# ---------------------------------------------------------------- static checks

def test_every_block_is_accounted_for():
    blocks, problems = all_blocks()
    names = {str(p.relative_to(ROOT)) for p in readmes()}
    assert {"README.md", "generated/README.md"} <= names, f"README discovery found only {sorted(names)}"
    claimed: dict[str, list[str]] = {}
    for name, sel in SNIPPETS.items():
        hits = [b for b in blocks if sel.matches(b)]
        if len(hits) != 1:
            problems.append(f"SNIPPETS[{name!r}]: {len(hits)} ```{sel.lang} blocks of {sel.readme} contain "
                            f"{sel.anchor!r}, expected exactly one")
        for b in hits:
            claimed.setdefault(b.where, []).append(name)
    for b in blocks:
        if b.marker is not None:
            if b.marker not in NOT_RUN:
                problems.append(f"{b.where}: not-run reason {b.marker!r} is none of {sorted(NOT_RUN)}")
            if b.where in claimed:
                problems.append(f"{b.where}: marked not run, yet {claimed[b.where]} runs it")
        elif b.where not in claimed:
            first = b.text.strip().splitlines()[0] if b.text.strip() else "(empty)"
            problems.append(f"{b.where}: not run by tests/test_readme_snippets.py, not the code of another test "
                            f"and not marked `<!-- snippet: not run: REASON -->`: {first}")
    assert not problems, "README blocks not accounted for:\n" + "\n".join(problems)


def test_every_not_run_reason_is_used():
    used = {b.marker for b in all_blocks()[0]}
    used |= {a.reason for plan in LINES.values() for a in plan.values() if isinstance(a, NotRun)}
    assert set(NOT_RUN) <= used, f"reasons nothing uses (drop them): {sorted(set(NOT_RUN) - used)}"


def test_shell_blocks_line_by_line():
    # The lines another test runs or no test can run; the RUN lines run in the jobs below.
    for name in LINES:
        account_lines(name)


def test_the_tree_is_what_test_readme_tree_checks():
    import test_readme_tree

    block = snippet("readme.tree")
    assert "\n".join(test_readme_tree.tree_block()).strip("\n") == block.text.strip("\n"), (
        f"{block.where}: tests/test_readme_tree.py reads another block")


PARSE = r"""
import contextlib, io, json, sys
from osdk_conformance.cli import build_parser
bad = []
for argv in json.load(sys.stdin):
    err = io.StringIO()
    try:
        with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
            build_parser(argv).parse_args(argv)
    except SystemExit as e:
        if e.code:
            bad.append([argv, err.getvalue().strip()])
    except Exception as e:
        bad.append([argv, f"{type(e).__name__}: {e}"])
print(json.dumps(bad))
"""


def test_osdkc_lines_that_do_not_run_are_still_valid_command_lines():
    """osdkc's own parser accepts every osdkc line no test here runs, so a
    renamed command or option shows even where the command cannot run."""
    argvs = []
    for name, plan in LINES.items():
        for cmd, action in plan.items():
            words = shlex.split(cmd)
            if action != RUN and words and Path(words[0]).name == "osdkc":
                argvs.append([PLACEHOLDERS.get(w, w) for w in words[1:]])
    assert argvs
    proc = run([sys.executable, "-c", PARSE], ROOT, "parsing the osdkc lines", stdin=json.dumps(argvs).encode())
    bad = json.loads(proc.stdout)
    assert bad == [], "osdkc does not accept these README lines:\n" + "\n".join(
        f"  osdkc {shlex.join(argv)}: {why}" for argv, why in bad)


# ---------------------------------------------------------------- jobs

JOBS: dict[str, Callable[[Path], None]] = {}


def job(fn: Callable[[Path], None]) -> Callable[[Path], None]:
    JOBS[fn.__name__.removeprefix("job_")] = fn
    return fn


@job
def job_java(tmp: Path) -> None:
    need("mvn", "java")
    m2 = Path.home() / ".m2" / "repository"
    if not (m2 / "io" / "kaitai").is_dir():
        pytest.fail(f"{m2} has no Kaitai runtime: `make setup` (make -C examples/java build) fills Maven's "
                    f"local repository once online")
    # a copy of ~/.m2 without the library: the README's install must put it there
    repo = tmp / "repo"
    shutil.copytree(m2, repo, ignore=lambda d, names: ["osdk-conformance"] if Path(d) == m2 else [])
    # C1 only: Maven's and javac's short runs start twice as fast
    maven = env(MAVEN_OPTS=f"-Dmaven.repo.local={repo} -XX:TieredStopAtLevel=1 -XX:+UseSerialGC")
    co = checkout(tmp, copies=("generated/java",))
    install = snippet("gen.java.install")
    run(install.text, co, install.where, environ=maven)

    app = tmp / "app"
    template = ROOT / "examples" / "java" / "pom.xml"
    if not template.is_file():
        pytest.fail(f"{template} (the project this harness builds the Java snippets in, plugins pinned) is missing")
    pom = template.read_text()
    dependency = snippet("gen.java.dependency")
    pom, n = re.subn(r"<dependencies>.*?</dependencies>", lambda _: f"<dependencies>\n{dependency.text}</dependencies>",
                     pom, flags=re.S)
    assert n == 1, "examples/java/pom.xml (this harness's project template) has no <dependencies> block"
    for old, new in (("<artifactId>osdk-kaitai-examples</artifactId>", "<artifactId>snippets</artifactId>"),
                     ("osdk_examples.Main", "snippets.Main"), ("<finalName>osdk-examples</finalName>",
                                                               "<finalName>snippets</finalName>")):
        assert old in pom, f"examples/java/pom.xml (this harness's project template) has no {old}"
        pom = pom.replace(old, new)
    (app / "src" / "main" / "java" / "snippets").mkdir(parents=True)
    (app / "pom.xml").write_text(pom)
    receive, send = snippet("gen.java.receive"), snippet("gen.java.send")
    head, body = split_at(receive, "// print():")
    (app / "src" / "main" / "java" / "snippets" / "Main.java").write_text(f"""\
package snippets;

import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import osdk_kaitai.Broadcast;
import osdk_kaitai.Command;
import osdk_kaitai.Deframer;
import osdk_kaitai.Osdk;
import osdk_kaitai.OsdkException;
import osdk_kaitai.OsdkFrame;

/** generated/README.md's Java snippets: `receive PROFILE` on standard input, or `send`. */
public final class Main {{
    public static void main(String[] args) throws IOException {{
        if (args.length != 1) {{
            System.err.println("usage: Main PROFILE|send");
            System.exit(2);
        }}
        if (args[0].equals("send")) {{
            send();
        }} else {{
            receive(args[0], System.in, System.out);
        }}
    }}

    static void receive(String profile, InputStream in, PrintStream out) throws IOException {{
        byte[] buf = new byte[4096];
{indent(head, " " * 8)}    }}

    // the README's print(): frames only, as its comment says
    static void print(Deframer.Event e, String profile, PrintStream out) {{
        if (e.kind() != Deframer.Kind.FRAME) {{
            return;
        }}
{indent(body, " " * 8)}    }}

    static void send() {{
{indent(send.text, " " * 8)}        StringBuilder hex = new StringBuilder();
        for (byte b : frame) {{
            hex.append(String.format("%02x", b & 0xff));
        }}
        System.out.println(hex);
    }}
}}
""")
    run(["mvn", "-B", "-q", "-o", "package"], app, "building the Java snippets against the installed artifact",
        environ=maven)
    jar = app / "target" / "snippets.jar"
    java = ["java", "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC", "-jar", str(jar)]
    for profile in PROFILES:
        want = []
        for e in api.decode(receive_stream(profile), profile):
            if rejected_frame(e):
                want.append(f"error {e.offset} {e.length} {e.error}")
            elif (d := broadcast_data(e)) is not None and "battery" in d:
                want.append(f"battery {d['battery']}")
        got = out_lines(run([*java, profile], app, receive.where, stdin=receive_stream(profile)))
        assert got == want, f"{receive.where} ({profile})"
    assert out_lines(run([*java, "send"], app, send.where)) == [worked_frame()], send.where


@job
def job_python(tmp: Path) -> None:
    # The README's `pip install` puts the package into the active
    # environment: here a new, empty one (PIP_PYTHON points pip at it).
    co = checkout(tmp, copies=("generated/python",))
    venv = tmp / "venv"
    run([sys.executable, "-m", "venv", "--without-pip", str(venv)], tmp, "a throwaway virtual environment")
    python = venv / "bin" / "python"
    for cmd in account_lines("gen.python.install"):
        assert cmd == "pip install generated/python", cmd
        run(cmd, co, f"{snippet('gen.python.install').where}: {cmd}", environ=env(PIP_PYTHON=str(python)))

    receive = snippet("gen.python.receive")
    (tmp / "receive.py").write_text(receive.text)
    want = []
    for e in api.decode(receive_stream("a3-fw3.1"), "a3-fw3.1"):
        if rejected_frame(e):
            want.append(f"error {e.offset} {e.length} {e.error}")
        elif (d := broadcast_data(e)) is not None:
            want.append(f"{d.get('battery')} {d['time_stamp']['time'] if 'time_stamp' in d else 'absent'}")
    got = out_lines(run([str(python), "receive.py"], tmp, receive.where, stdin=receive_stream("a3-fw3.1")))
    assert got == want, receive.where

    send = snippet("gen.python.send")
    (tmp / "send.py").write_text(f"import osdk_kaitai\n\n{send.text}\nprint(frame.hex())\n")
    got = out_lines(run([str(python), "send.py"], tmp, send.where))
    assert got == [worked_frame()] and matches_shown(shown_hex(send), got[0]), send.where


@job
def job_go(tmp: Path) -> None:
    need("go")
    checkout(tmp, links=("generated/go",))
    app = tmp / "app"
    app.mkdir()
    receive, send = snippet("gen.go.receive"), snippet("gen.go.send")
    (app / "receive.go").write_text(f"package main\n\n{receive.text}")
    (app / "main.go").write_text(f"""\
package main

// generated/README.md's Go snippets: receive() over the bytes on standard
// input with the profile given, or the send fragment.

import (
	"encoding/hex"
	"fmt"
	"io"
	"os"

	osdk "osdk-conformance.local/generated/go/osdk_kaitai"
)

func main() {{
	if len(os.Args) != 2 {{
		fmt.Fprintln(os.Stderr, "usage: app PROFILE|send")
		os.Exit(2)
	}}
	if os.Args[1] == "send" {{
		send()
		return
	}}
	data, err := io.ReadAll(os.Stdin)
	if err != nil {{
		panic(err)
	}}
	receive(data, os.Args[1])
}}

func send() {{
{indent(send.text, chr(9))}	if err != nil {{
		fmt.Fprintln(os.Stderr, err)
		os.Exit(1)
	}}
	fmt.Println(hex.EncodeToString(raw))
}}
""")
    install = snippet("gen.go.install")
    # offline: what the README promises needs only the module cache
    run(install.text, app, install.where, environ=env(GOPROXY="off", GOFLAGS=os.environ.get("GOFLAGS", "")))
    exe = app / "app"
    assert exe.is_file(), f"{install.where}: `go build` made no ./app"
    for profile in PROFILES:
        want = []
        for e in api.decode(receive_stream(profile), profile):
            if rejected_frame(e):
                want.append(f"error {e.offset} {e.error}")
            elif (d := broadcast_data(e)) is not None:
                want += [f"battery {d['battery']}"] if "battery" in d else []
                want += [f"time_stamp {d['time_stamp']['time']}"] if "time_stamp" in d else []
        got = out_lines(run([str(exe), profile], app, receive.where, stdin=receive_stream(profile)))
        compare_error_lines(f"{receive.where} ({profile})", got, want)
    got = out_lines(run([str(exe), "send"], app, send.where))
    assert got == [worked_frame()] and matches_shown(shown_hex(send), got[0]), send.where


@job
def job_javascript(tmp: Path) -> None:
    need("node", "npm")
    checkout(tmp, links=("generated/javascript",))
    app = tmp / "app"
    app.mkdir()
    install = snippet("gen.js.install")
    # npm's cache first: the Kaitai runtime need not be fetched again
    run(install.text, app, install.where, environ=env(npm_config_prefer_offline="true", npm_config_audit="false",
                                                       npm_config_fund="false", npm_config_update_notifier="false"))
    receive, send = snippet("gen.js.receive"), snippet("gen.js.send")
    head, body = split_at(receive, "// in show(ev)")
    (app / "receive.js").write_text(f"""\
'use strict';
// each console.log as one JSON array, so that values compare exactly
console.log = (...values) => process.stdout.write(`${{JSON.stringify(values)}}\\n`);
{head}
// the README's show(ev): frames only; the OsdkError it says decodeFrame throws is printed
function show(ev) {{
  if (ev.kind !== 'frame') return;
  try {{
{indent(body, "    ")}  }} catch (err) {{
    if (!(err instanceof osdk.OsdkError)) throw err;
    console.log('error', ev.offset, err.errorClass, err.field);
  }}
}}
""")
    (app / "send.js").write_text(f"'use strict';\nconst osdk = require('osdk-kaitai');\n{send.text}"
                                 "console.log(Buffer.from(frame).toString('hex'));\n")
    items = list(api.broadcast_items("a3-fw3.1"))
    want = []
    for e in api.decode(receive_stream("a3-fw3.1"), "a3-fw3.1"):
        if rejected_frame(e):
            want.append(["error", e.offset, e.error])
        elif (d := broadcast_data(e)) is not None:
            want.append([d.get("battery"), d["time_stamp"]["time"] if "time_stamp" in d else None, items])
    got = [json.loads(line) for line in out_lines(run(["node", "receive.js"], app, receive.where,
                                                        stdin=receive_stream("a3-fw3.1")))]
    assert len(got) == len(want), f"{receive.where}: printed {got}, expected {want}"
    for g, w in zip(got, want):
        if w[0] == "error":
            assert g[:3] == w, receive.where
            check_field(receive.where, w[2], g[3])
        else:
            assert g == w, receive.where
    assert out_lines(run(["node", "send.js"], app, send.where)) == [worked_frame()], send.where


C_HARNESS = """\
#include <stdio.h>
#include <string.h>

#include "osdk_broadcast.h"
#include "osdk_decoder.h"
#include "osdk_deframer.h"
#include "osdk_encode.h"
#include "osdk_tables.h"

/* The C snippets of generated/README.md and conformance/testees/c/README.md:
 *   app receive      < bytes   (the receive snippet, profile a3-fw3.1)
 *   app send                   (the send snippet; write_to_uart prints hex)
 *   app frame HEX              (the testee README's usage snippet on one frame) */

{on_event}
static int snippet_receive(void)
{{
    uint8_t chunk[4096];
    size_t n;
{receive}    return 0;
}}

static void write_to_uart(const uint8_t *frame, size_t n)
{{
    size_t i;
    for (i = 0; i < n; i++) printf("%02x", frame[i]);
    printf("\\n");
}}

static int snippet_send(void)
{{
{send}    return 0;
}}

static int snippet_frame(const uint8_t *buf, size_t len)
{{
{usage}    return 0;
}}

int main(int argc, char **argv)
{{
    static uint8_t buf[2048];
    size_t len = 0;
    if (argc == 2 && strcmp(argv[1], "receive") == 0) return snippet_receive();
    if (argc == 2 && strcmp(argv[1], "send") == 0) return snippet_send();
    if (argc == 3 && strcmp(argv[1], "frame") == 0 && strlen(argv[2]) / 2 <= sizeof buf) {{
        for (; sscanf(argv[2] + 2 * len, "%2hhx", &buf[len]) == 1; len++) {{}}
        return snippet_frame(buf, len);
    }}
    fprintf(stderr, "usage: app receive|send|frame HEX\\n");
    return 2;
}}
"""


def quiet(proc: subprocess.CompletedProcess, block: Block) -> None:
    # cmake warns and goes on where it ignores an argument (an option written as `[-DX=ON]`)
    text = (proc.stdout + proc.stderr).decode(errors="replace")
    assert "CMake Warning" not in text and "warning:" not in text, f"{block.where}: warnings\n{text[-3000:]}"


@job
def job_c(tmp: Path) -> None:
    need("make", "cc", "cmake", "ar")
    # generated/README.md: the library built as it says, then app.c with the snippets
    user = tmp / "user"
    checkout(user, links=("generated",))
    work = user / "osdk-conformance"
    seed_c_objects(work / "build" / "osdk")
    receive, send, usage = snippet("gen.c.receive"), snippet("gen.c.send"), snippet("testees.c.usage")
    on_event, main_part = split_at(receive, "/* ... */")
    (work / "app.c").write_text(C_HARNESS.format(on_event=on_event, receive=indent(main_part),
                                                 send=indent(send.text), usage=indent(usage.text)))
    build = snippet("gen.c.build")
    quiet(run(build.text, work, build.where), build)
    exe = work / "app"
    want = [f"battery {d['battery']}" for e in api.decode(receive_stream("a3-fw3.1"), "a3-fw3.1")
            if (d := broadcast_data(e)) is not None and "battery" in d]
    got = out_lines(run([str(exe), "receive"], work, receive.where, stdin=receive_stream("a3-fw3.1")))
    assert got == want, receive.where
    got = out_lines(run([str(exe), "send"], work, send.where))
    assert got == [worked_frame()] and matches_shown(shown_hex(send), got[0]), send.where
    bad_crc = bytearray(bytes.fromhex(WORKED_FRAME))
    bad_crc[-1] ^= 0x80
    reserved = api.encode_frame(cmd_set=2, cmd_id=0, value=(1 << 15).to_bytes(2, "little"), seq=5)
    full = api.encode_broadcast_frame("a3-fw3.1", {"battery": 87}, seq=9)
    for frame in (bytes.fromhex(WORKED_FRAME), bytes(bad_crc), reserved, full):
        e = api.decode(frame, "a3-fw3.1")[0]
        if e.kind == "frame":
            d = e.frame["data"]
            want = f"seq {e.frame['seq']} cmd {d['cmd_set']['value']}/{d['cmd_id']}"
        else:
            want = f"rejected: {e.error}"
        assert out_lines(run([str(exe), "frame", frame.hex()], work, usage.where)) == [want], (usage.where,
                                                                                               frame.hex())

    # generated/c/README.md: its commands in a copy of generated/c (they build inside it)
    lib = checkout(tmp / "lib", copies=("generated/c",))
    seed_c_objects(lib / "generated" / "c" / "build")
    block = snippet("c.build")
    quiet(run(block.text, lib, block.where), block)
    archived = run(["ar", "t", "generated/c/build/libosdk.a"], lib, block.where).stdout.decode().split()
    assert archived and not {"osdk_json.o", "osdk_model_json.o"} & set(archived), (
        f"{block.where}: OSDK_NO_STDIO=1 left the JSON writers in: {archived}")
    assert (lib / "build" / "osdk" / "libosdk.a").is_file(), f"{block.where}: the cmake build made no libosdk.a"
    assert "OSDK_NO_STDIO:BOOL=ON" in (lib / "build" / "osdk" / "CMakeCache.txt").read_text(), block.where


@job
def job_c_tools(tmp: Path) -> None:
    need("make", "cc")
    # conformance/baseline/README.md, in a copy of the baseline (it builds in place)
    co = checkout(tmp / "baseline", links=("generated", "spec", ".venv"))
    shutil.copytree(ROOT / "conformance" / "baseline", co / "conformance" / "baseline", symlinks=True)
    stream = well_formed_stream("a3-fw3.1")
    (co / "capture.bin").write_bytes(stream)
    block = snippet("baseline")
    events = api.decode(stream, "a3-fw3.1")
    assert not any(rejected_frame(e) for e in events), "the README promises equal counts for accepted values only"
    got = json.loads(run(block.text, co, block.where).stdout.decode().splitlines()[-1])
    want = {"bytes": len(stream), "frames": sum(e.kind == "frame" for e in events),
            "errors": sum(e.kind == "error" for e in events),
            "garbage_bytes": sum(e.length for e in events if e.kind == "garbage")}
    assert {k: got.get(k) for k in want} == want and got["profile"] == "a3-fw3.1", f"{block.where}: {got}"

    # conformance/testee-kit/c/README.md: its build line, then the walkthrough's code built the same way
    kit = checkout(tmp / "kit", links=("conformance", "generated"))
    (cc,) = account_lines("kit.build")
    build = snippet("kit.build")
    run(cc, kit, build.where)
    example = [json.loads(line) for line in out_lines(run(["./encode-only"], kit, build.where,
                                                          stdin=b'{"op": "capabilities"}\n'))]
    assert example[0]["result"]["operations"] == ["encode_movement_control"], build.where
    pieces = [snippet(n) for n in ("kit.declaration", "kit.callback", "kit.main")]
    (kit / "walkthrough.c").write_text(
        "#include <stdint.h>\n\n#include \"okit.h\"\n\n" + pieces[0].text + """
/* the implementation the walkthrough wraps: the mode byte, then x, y, z, yaw little-endian */
void my_encode_movement(uint8_t mode, const uint32_t setpoint_bits[4], uint8_t out[17])
{
    int i, k;
    out[0] = mode;
    for (i = 0; i < 4; i++)
        for (k = 0; k < 4; k++) out[1 + 4 * i + k] = (uint8_t)(setpoint_bits[i] >> (8 * k));
}

""" + pieces[1].text + "\n" + pieces[2].text)
    error = snippet("kit.error")
    (kit / "grow.c").write_text(f"""\
#include "okit.h"

/* the README's error answer, as a decoding callback gives it */
static void decode_frame(okit_request *req)
{{
{indent(error.text)}}}

int main(int argc, char **argv)
{{
    static const char *const profiles[] = {{"a3-fw3.1", NULL}};
    okit_testee t = {{0}};
    t.name = "grow";
    t.profiles = profiles;
    t.decode_frame = decode_frame;
    return okit_main(&t, argc, argv);
}}
""")
    source = "conformance/testee-kit/c/example/encode_only.c"
    assert source in cc and "-o encode-only" in cc, f"{build.where}: the build line no longer builds {source}"
    for name in ("walkthrough", "grow"):
        run(cc.replace(source, f"{name}.c").replace("-o encode-only", f"-o {name}"), kit,
            f"{build.where}, building {name}.c ({', '.join(p.where for p in pieces + [error])})")
    cases = [(0x4B, [0x3F800000, 0xC0000000, 0x3F000000, 0x41F00000]),
             (0xFF, [0x7F800001, 0xFFBFFFFF, 0x80000000, 0x7FC12345])]   # NaN payloads, -0.0: bits, not floats
    requests = [{"op": "capabilities"}] + [
        {"op": "encode_movement_control", "mode": mode, **{axis: {"f32": f"0x{b:08x}"}
                                                           for axis, b in zip(("x", "y", "z", "yaw"), bits)}}
        for mode, bits in cases] + [{"op": "encode_movement_control", "x": {"f32": "0x0"}}]
    answers = [json.loads(line) for line in out_lines(run(
        ["./walkthrough"], kit, pieces[1].where, stdin="".join(json.dumps(r) + "\n" for r in requests).encode()))]
    assert answers[0]["result"]["name"] == "encode-only example", pieces[2].where
    assert answers[0]["result"]["operations"] == ["encode_movement_control"], pieces[2].where
    for (mode, bits), answer in zip(cases, answers[1:3]):
        want = api.encode_movement_control(mode, *(api.F32(b) for b in bits)).hex()
        assert answer == {"ok": True, "result": {"hex": want}}, pieces[1].where
    assert answers[3]["ok"] is False and answers[3]["error"] == "bad_request", pieces[1].where
    request = {"op": "decode_frame", "hex": WORKED_FRAME, "profile": "a3-fw3.1"}
    answer = json.loads(run(["./grow"], kit, error.where, stdin=(json.dumps(request) + "\n").encode()).stdout)
    assert answer == {"ok": False, "error": "bad_crc16", "detail": "CRC-16 is 0x1234, expected 0x5678"}, error.where


def wireshark_records(profile: str) -> list[tuple[int, bytes]]:
    return [(RX, api.encode_broadcast_frame(profile, {"battery": 87, "flight_status": None}, seq=1)),
            (RX, api.encode_broadcast_frame(profile, {"time_stamp": {"time": 5}}, seq=2)),
            (TX, bytes.fromhex(WORKED_FRAME))]


def dissected(profile: str) -> list[tuple[str, int | None]]:
    """Per packet of wireshark_records: the reference's command and battery."""
    out = []
    for _, data in wireshark_records(profile):
        (e,) = api.decode(data, profile)
        d = broadcast_data(e) or {}
        out.append((e.command, d.get("battery")))
    return out


def osdkc_wireshark_install(cmd: str, home: Path, where: str) -> None:
    home.mkdir(exist_ok=True)
    run(cmd, home, where, environ=env(HOME=str(home), XDG_CONFIG_HOME=str(home / ".config")))
    installed = home / ".local" / "lib" / "wireshark" / "plugins" / "osdk.lua"
    assert installed.read_bytes() == (ROOT / "generated" / "wireshark" / "osdk.lua").read_bytes(), where


@job
def job_wireshark(tmp: Path) -> None:
    need("tshark")
    block = snippet("gen.wireshark")
    install, installed, loaded = account_lines("gen.wireshark")
    # installed: a HOME of its own, with the plugin `osdkc wireshark install` put there
    home = tmp / "installed"
    osdkc_wireshark_install(install, home, block.where)
    write_capture(home / "capture.pcapng", wireshark_records("m100-fw3.1"))
    proc = run(installed, home, block.where, environ=env(HOME=str(home), XDG_CONFIG_HOME=str(home / ".config")))
    text = proc.stdout.decode()
    assert "Expert Info (Error" not in text and "Lua" not in proc.stderr.decode(), block.where
    shown = re.findall(r"^\s+(command|battery): (\S+)$", text, re.M)
    want = []
    for command, battery in dissected("m100-fw3.1"):
        want += [("command", command)] + ([("battery", str(battery))] if battery is not None else [])
    assert shown == want, f"{block.where}: `{installed}`"
    # without installing: a HOME with no plugin (a second osdk protocol would not load), the checkout's file
    plain = checkout(tmp / "plain", links=("generated/wireshark",))
    write_capture(plain / "capture.pcapng", wireshark_records("a3-fw3.1"))
    proc = run(loaded, plain, block.where, environ=env(HOME=str(tmp / "plain"),
                                                       XDG_CONFIG_HOME=str(tmp / "plain" / ".config")))
    assert "Lua" not in proc.stderr.decode(), proc.stderr.decode()
    want = [f"{command}\t{'' if battery is None else battery}" for command, battery in dissected("a3-fw3.1")]
    assert out_lines(proc) == want, f"{block.where}: `{loaded}`"


@job
def job_osdkc(tmp: Path) -> None:
    """README.md: the osdkc lines that run quickly, the console example, the
    Python API example and the example testee."""
    listing = snippet("readme.osdkc")
    ran = {}
    capture = tmp / "capture.bin"
    capture.write_bytes(receive_stream("a3-fw3.1"))
    write_capture(tmp / "run.pcapng", [(RX, receive_stream("a3-fw3.1")), (TX, bytes.fromhex(WORKED_FRAME))])

    def decoded(cmd: str, path: Path, direction: str) -> None:
        proc = run(cmd, tmp, f"{listing.where}: {cmd}", status=None)
        got = [json.loads(line) for line in out_lines(proc)]
        want = [e.model for e in api.decode_file(path, "a3-fw3.1", direction=direction)]
        # the README: a file that ends inside a frame ends with that truncated_frame marked capture_end
        at_end = [g.pop("capture_end", False) for g in got]
        assert got == want, f"{listing.where}: `{cmd}` and the reference differ"
        assert all(g["error"] == "truncated_frame" for g, end in zip(got, at_end) if end), f"{listing.where}: {cmd}"
        errors = any(g["kind"] == "error" and not end for g, end in zip(got, at_end))
        assert proc.returncode == (1 if errors else 0), f"{listing.where}: `{cmd}` exit status {proc.returncode}"

    def version(cmd: str) -> None:
        line = run(cmd, tmp, listing.where).stdout.decode()
        assert re.fullmatch(r"osdkc \S+ \(.*; decoder: .*\)\n", line), f"{listing.where}: `{cmd}` printed {line!r}"

    ran["osdkc decode --profile a3-fw3.1 capture.bin"] = lambda cmd: decoded(cmd, capture, "rx")
    ran["osdkc decode --profile a3-fw3.1 --direction both run.pcapng"] = lambda cmd: decoded(cmd, tmp / "run.pcapng",
                                                                                             "both")
    ran["osdkc wireshark install"] = lambda cmd: osdkc_wireshark_install(cmd, tmp / "home", listing.where)
    ran["osdkc --version"] = version

    def tabled(cmd: str) -> None:
        broadcasts = [e for e in api.decode_file(tmp / "run.pcapng", "a3-fw3.1") if e.command == "broadcast"]
        json_status = run("osdkc decode --profile a3-fw3.1 run.pcapng > /dev/null", tmp, cmd, status=None).returncode
        run(cmd, tmp, f"{listing.where}: {cmd}", status=json_status)
        with open(tmp / "flight.csv", newline="") as fh:
            rows = list(csv.DictReader(fh))
        # an empty cell: a frame without the battery item
        assert [r["battery"] for r in rows] == [str(e.value["data"].get("battery", "")) for e in broadcasts] and rows, cmd
        assert list(rows[0])[:3] == ["offset", "time", "fc_time"] and "quaternion.q0" in rows[0], cmd

    def plotted(cmd: str) -> None:
        run(cmd, tmp, f"{listing.where}: {cmd}")
        page = (tmp / "flight.html").read_text()
        assert all(f'data-series="{s}"' in page for s in ("battery", "roll", "pitch", "yaw")), cmd

    ran["osdkc decode --profile a3-fw3.1 --format csv --items battery,quaternion run.pcapng > flight.csv"] = tabled
    ran["osdkc plot run.pcapng --profile a3-fw3.1 --items battery,attitude -o flight.html"] = plotted

    def explained(cmd: str) -> None:
        out = run(cmd, tmp, listing.where).stdout.decode()
        assert out.startswith("control mode byte 0x4B = 0b01001011\n"), f"{listing.where}: `{cmd}` printed {out!r}"
        assert "a3-fw3.1: DOCUMENTED, combination 4" in out, f"{listing.where}: `{cmd}` printed {out!r}"

    ran["osdkc explain 0x4B"] = explained
    todo = account_lines("readme.osdkc")
    assert sorted(todo) == sorted(ran), f"{listing.where}: RUN lines without a check here: {set(todo) ^ set(ran)}"
    for cmd in todo:
        ran[cmd](cmd)

    console = snippet("readme.console")
    lines = console.text.splitlines()
    assert lines and lines[0].startswith("$ "), f"{console.where}: not a `$ command` then its output"
    proc = run(lines[0][2:], tmp, console.where)
    got, shown = out_lines(proc), lines[1:]
    assert len(got) == len(shown), f"{console.where}: printed {got}"
    for g, s in zip(got, shown):
        pieces = s.split("…")
        assert g.startswith(pieces[0]) and g.endswith(pieces[-1]), f"{console.where}: {g!r} is not {s!r}"
        at = 0
        for piece in pieces:
            at = g.find(piece.strip(), at)
            assert at >= 0, f"{console.where}: {piece!r} is not in {g!r}"

    example = snippet("readme.api")
    (tmp / "api_example.py").write_text(example.text)
    shown = [line.strip()[3:] for line in example.text.splitlines() if line.strip().startswith("#> ")]
    assert shown, f"{example.where}: no `#>` output lines"
    assert out_lines(run([sys.executable, "api_example.py"], tmp, example.where)) == shown, example.where

    testee = snippet("readme.testee")
    (tmp / "mine.py").write_text(testee.text)
    requests = [{"op": "capabilities"}, {"op": "decode_frame", "hex": WORKED_FRAME, "profile": "a3-fw3.1"}]
    requests += [{"op": "classify_control_mode", "byte": b, "profile": p} for p in PROFILES for b in range(256)]
    stdin = "".join(json.dumps(r) + "\n" for r in requests).encode()
    answers = [json.loads(line) for line in out_lines(run([sys.executable, "mine.py"], tmp, testee.where, stdin=stdin))]
    assert len(answers) == len(requests), testee.where
    assert answers[0]["result"]["operations"] == ["classify_control_mode"], testee.where
    assert sorted(answers[0]["result"]["profiles"]) == sorted(PROFILES), testee.where
    assert answers[1] == {"ok": False, "unsupported": True}, testee.where
    for request, answer in zip(requests[2:], answers[2:]):
        ref = api.classify_control_mode(request["byte"], request["profile"])
        want = {"fields": ref.fields, "classification": ref.classification, "combination": ref.combination}
        assert answer == {"ok": True, "result": want}, (testee.where, request)

    run_block = snippet("readme.testee_run")
    (cmd,) = account_lines("readme.testee_run")
    proc = run(cmd, tmp, run_block.where)
    verdict = out_lines(proc)[-1]
    assert re.fullmatch(r"CONFORMS for classify_control_mode: 768 of [\d,]+ cases", verdict), (run_block.where,
                                                                                               verdict)
    for report in ("report.xml", "report.html"):
        assert (tmp / report).stat().st_size > 0, f"{run_block.where}: no {report}"


# All start at once (the module takes as long as the slowest, Java), longest first.
ORDER = ("java", "python", "c", "osdkc", "c_tools", "go", "wireshark", "javascript")
assert sorted(ORDER) == sorted(JOBS)


@pytest.fixture(scope="module")
def jobs(request, tmp_path_factory):
    wanted = {item.name.removeprefix("test_").removesuffix("_snippets") for item in request.session.items
              if item.module is sys.modules[__name__]}
    pool = concurrent.futures.ThreadPoolExecutor(max_workers=len(ORDER), thread_name_prefix="snippets")
    futures = {name: pool.submit(JOBS[name], tmp_path_factory.mktemp(name)) for name in ORDER if name in wanted}
    yield futures
    pool.shutdown(wait=True, cancel_futures=True)


def result(jobs, name: str) -> None:
    # pytest.fail raised in a job's thread surfaces here, in the test
    jobs[name].result()


def test_java_snippets(jobs):
    result(jobs, "java")


def test_python_snippets(jobs):
    result(jobs, "python")


def test_c_snippets(jobs):
    result(jobs, "c")


def test_osdkc_snippets(jobs):
    result(jobs, "osdkc")


def test_c_tools_snippets(jobs):
    result(jobs, "c_tools")


def test_go_snippets(jobs):
    result(jobs, "go")


def test_wireshark_snippets(jobs):
    result(jobs, "wireshark")


def test_javascript_snippets(jobs):
    result(jobs, "javascript")
