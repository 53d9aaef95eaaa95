"""The walk-through of docs/EXTENDING.md, performed on a copy of the repository:
a made-up broadcast item (`wind`) in a made-up profile (`x9-fw9.9`, an
a3-fw3.1 with the new item at flag bit 14 and, like m100-fw2.3, no version
ID in its version ACK).

Only the three hand-written files the document names are edited
(spec/rules.yaml, spec/osdk_broadcast_items.ksy, spec/construct/
broadcast_items.py); everything else comes from the generators that
`make regen` and `make vectors` run. Then the Construct (Python) and the C
implementations must conform on every case of the new profile, and the
simulator must send the new item.

Independent steps run two at a time, so that the walk-through takes
little more than its longest chain (the vector generator, then the
Construct run): the vector generator beside the other generators and the
C build, then the Construct run beside the C run.
"""
from __future__ import annotations

import copy
import json
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from typing import Any, Callable

import pytest
import yaml

from repo_copy import make_copy

pytestmark = pytest.mark.slow

LIKE, NEW, ITEM = "a3-fw3.1", "x9-fw9.9", "wind"

KSY_TYPE = """\
  wind:
    doc: Wind estimate of the flight controller (made up by tests/test_extending.py).
    seq:
      - id: speed
        type: u2
        doc: Wind speed, cm/s.
      - id: direction
        type: u2
        doc: Direction the wind blows from, degrees clockwise from north.
"""

CONSTRUCT_TYPE = '''

wind = Struct(
    "speed" / Int16ul,
    "direction" / Int16ul,
)
'''


def also_for_new_profile(node: Any) -> Any:
    """Every place of rules.yaml that says something per profile says the
    same of the new profile as of the one it is like."""
    if isinstance(node, dict):
        out = {k: also_for_new_profile(v) for k, v in node.items()}
        if LIKE in node and NEW not in node:
            out[NEW] = copy.deepcopy(out[LIKE])
        return out
    if isinstance(node, list):
        out = [also_for_new_profile(v) for v in node]
        return out + [NEW] if LIKE in node and NEW not in node else out
    return node


def edit_rules(path: Path) -> None:
    rules = also_for_new_profile(yaml.safe_load(path.read_text()))
    rules["broadcast_items"][ITEM] = {"type": ITEM, "doc": "Wind estimate.",
                                      "source": "made up by tests/test_extending.py"}
    new = rules["profiles"][NEW]
    new["value"] = len(rules["profiles"]) - 1
    new["description"] = "made-up profile: a3-fw3.1 with a wind item at bit 14; 15 items"
    new["flag_bits"].append(ITEM)
    new["default_rates_hz"][ITEM] = {"hz": 10, "source": "made up"}
    # unlike a3-fw3.1, no version ID in the version ACK: the second profile
    # without one makes has_version_id a condition of two terms
    new["version_ack"] = {"version_id": False, "source": "made up",
                          "version_name": "SDK-v1.0 BETA M100-03.02.01.00", "version_name_source": "made up"}
    rules["units"]["items"][ITEM] = {"source": "made up", "fields": {
        "speed": {"unit": "cm/s"}, "direction": {"unit": "deg"}}}
    path.write_text(yaml.safe_dump(rules, sort_keys=False, allow_unicode=True, width=120))


def edit_ksy(path: Path) -> None:
    text = path.read_text()
    assert "\nenums:\n" in text
    path.write_text(text.replace("\nenums:\n", "\n" + KSY_TYPE + "enums:\n", 1))


def edit_construct(path: Path) -> None:
    text = path.read_text().replace('"control_info",\n]', '"control_info", "wind",\n]', 1)
    text = text.replace("from construct import ", "from construct import Int16ul, ", 1)
    path.write_text(text + CONSTRUCT_TYPE)


@pytest.fixture(scope="module")
def extended(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, dict[str, str]]:
    repo = tmp_path_factory.mktemp("extending") / "repo"
    env = make_copy(repo)
    edit_rules(repo / "spec/rules.yaml")
    edit_ksy(repo / "spec/osdk_broadcast_items.ksy")
    edit_construct(repo / "spec/construct/broadcast_items.py")
    # What `make regen` and `make vectors` run, then the C testee's build.
    # Once the profile .ksy files are in spec/ (the first step of
    # tools/regen.py, which then finds them current), the vector generator
    # reads nothing the other steps write: it runs beside them, which take
    # about as long as it does.
    run(repo, env, sys.executable, "tools/gen_profile_ksy.py")

    def regen_and_build() -> None:
        run(repo, env, sys.executable, "tools/regen.py")
        run(repo, env, sys.executable, "tools/gen_schemas.py")
        run(repo, env, "make", "-s", "-C", "conformance/testees/c", "build")

    side_by_side(lambda: run(repo, env, sys.executable, "tools/gen_vectors.py"), regen_and_build)
    return repo, env


def side_by_side(*steps: Callable[[], Any]) -> list[Any]:
    """Each step in a thread of its own, all at once; their results, in order
    (the first failure is raised once every step has ended)."""
    with ThreadPoolExecutor(len(steps)) as pool:
        futures = [pool.submit(step) for step in steps]
    return [f.result() for f in futures]


def execute(repo: Path, env: dict[str, str], *argv: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(list(argv), cwd=repo, env=env, capture_output=True, text=True, timeout=600)


def succeeded(proc: subprocess.CompletedProcess[str]) -> subprocess.CompletedProcess[str]:
    assert proc.returncode == 0, \
        f"{' '.join(proc.args)}: exit {proc.returncode}\n{proc.stdout[-3000:]}{proc.stderr[-3000:]}"
    return proc


def run(repo: Path, env: dict[str, str], *argv: str) -> subprocess.CompletedProcess[str]:
    return succeeded(execute(repo, env, *argv))


def osdkc(extended: tuple[Path, dict[str, str]], *argv: str) -> subprocess.CompletedProcess[str]:
    repo, env = extended
    return run(repo, env, sys.executable, "-m", "osdk_conformance", *argv)


def test_the_new_profile_gets_its_generated_layout(extended: tuple[Path, dict[str, str]]) -> None:
    repo, _ = extended
    ksy = yaml.safe_load((repo / "spec/osdk_broadcast_x9_fw9_9.ksy").read_text())
    assert [f["id"] for f in ksy["seq"]][14:16] == ["has_wind", "reserved_flags"]
    assert any(f["id"] == ITEM and f["type"] == "osdk_broadcast_items::wind" for f in ksy["seq"])
    assert (repo / "generated/python/osdk_kaitai/osdk_broadcast_x9_fw9_9.py").exists()
    assert "x9_fw9_9" in (repo / "generated/c/osdk_decoder.h").read_text()
    dissector = (repo / "generated/wireshark/osdk.lua").read_text()
    assert '"x9-fw9.9"' in dissector and f'"osdk.broadcast.{ITEM}' in dissector
    payload = (repo / "spec/osdk_payload.ksy").read_text()
    assert "profile != profile::m100_fw2_3 and profile != profile::x9_fw9_9" in payload


def test_the_vectors_cover_the_new_item(extended: tuple[Path, dict[str, str]]) -> None:
    repo, _ = extended
    groups = json.loads((repo / "vectors/broadcast.json").read_text())["testGroups"]
    cases = [t for g in groups if g["profile"] == NEW for t in g["tests"]]
    assert cases and any(ITEM in t["id"] for t in cases)


IMPLS = ("construct", "c")


@pytest.fixture(scope="module")
def conformance_runs(extended: tuple[Path, dict[str, str]]) -> dict[str, subprocess.CompletedProcess[str]]:
    """`osdkc run --impl IMPL --profile NEW` of each implementation, side by
    side (each run is a runner and its testee taking turns, about one core
    between them); each test below judges its own."""
    repo, env = extended
    procs = side_by_side(*(
        lambda impl=impl: execute(repo, env, sys.executable, "-m", "osdk_conformance", "run", "--impl", impl,
                                  "--profile", NEW, "--quiet", "--summary-json", str(repo / f"{impl}-summary.json"))
        for impl in IMPLS))
    return dict(zip(IMPLS, procs))


@pytest.mark.parametrize("impl", IMPLS)
def test_python_and_c_conform_on_the_new_profile(extended: tuple[Path, dict[str, str]],
                                                 conformance_runs: dict[str, subprocess.CompletedProcess[str]],
                                                 impl: str) -> None:
    repo, _ = extended
    succeeded(conformance_runs[impl])
    got = json.loads((repo / f"{impl}-summary.json").read_text())
    assert got["conforms"] and got["complete"], got["verdict_line"]
    assert got["statuses"]["pass"] == got["cases"] > 1000, got["statuses"]


def test_the_simulator_sends_the_new_item(extended: tuple[Path, dict[str, str]]) -> None:
    repo, _ = extended
    log = repo / "broadcast.jsonl"
    osdkc(extended, "sim", "--profile", NEW, "--exit-after", "0.5", "--log-broadcast", str(log))
    flags = [int.from_bytes(bytes.fromhex(json.loads(line)["value"])[:2], "little")
             for line in log.read_text().splitlines()]
    assert any(f >> 14 & 1 for f in flags), "no broadcast carried the wind item (flag bit 14)"
