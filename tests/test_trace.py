"""Tests of the seed-to-spec trace (spec/trace.yaml, osdk_conformance/traceability/trace.py).

The seed is not part of the repository, so nothing here reads it unless
$OSDK_SEED names it (the optional tests at the end). What needs no seed is
checked on the real trace: every reference resolves, the seed's enums and
tables are traced in full. What needs a seed text is checked on a small
synthetic seed and trace written to tmp_path, whose references are real spec
elements: the checker must pass it as written and complain about each thing
broken in a copy (the real files are never touched).
"""
from __future__ import annotations

import copy
import hashlib
import os
import re
from pathlib import Path
from typing import Any

import pytest
import yaml

from osdk_conformance.core import ksy
from osdk_conformance.traceability import trace
from osdk_conformance.cli import main
from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.paths import SEED_ENV
from osdk_conformance.traceability.check import Skipped, _trace

ROOT = Path(__file__).resolve().parents[1]
TRACE_PATH = ROOT / "spec" / "trace.yaml"
RULES_PATH = ROOT / "spec" / "rules.yaml"
KINDS = {"item", "field", "enum_value", "range", "rule", "table_row", "unit", "frequency"}


@pytest.fixture(scope="module")
def doc() -> dict[str, Any]:
    return yaml.safe_load(TRACE_PATH.read_text(encoding="utf-8"))


@pytest.fixture
def no_seed_env(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(SEED_ENV, raising=False)


def _write(tmp_path: Path, data: dict[str, Any]) -> Path:
    path = tmp_path / "trace.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False, allow_unicode=True), encoding="utf-8")
    return path


def _problems(report: trace.Report) -> list[str]:
    return report.problems + [f"{e.id}: {p}" for e in report.entries for p in e.problems]


# ------------------------------------------------ the real trace, no seed


def test_real_trace_without_seed_checks_references_and_says_what_it_skipped(no_seed_env: None) -> None:
    report = trace.check()
    assert _problems(report) == []
    assert report.ok
    assert report.seed is None and report.nonblank is None
    assert report.skipped is not None and "did not run: no seed given" in report.skipped
    assert len(report.entries) >= 200


def test_every_entry_maps_to_existing_elements(doc: dict[str, Any]) -> None:
    resolver = trace.Resolver()
    missing = [(e["id"], ref) for e in doc["entries"] for ref in e["spec"] if not resolver.exists(ref)]
    assert missing == []
    assert all(e["spec"] for e in doc["entries"])


def test_entries_are_well_formed(doc: dict[str, Any]) -> None:
    # the seed is cited by name and bound by hash; never a path to read
    assert doc["seed"] == "seeds/000_b7658b258220b5c1.txt"
    assert re.fullmatch(r"[0-9a-f]{64}", doc["seed_sha256"])
    assert doc["seed_sha256"].startswith(Path(doc["seed"]).stem.split("_")[1])
    ids = [e["id"] for e in doc["entries"]]
    assert ids == [f"S{n:03d}" for n in range(1, len(ids) + 1)]
    assert len(ids) >= 200
    for e in doc["entries"]:
        assert e["kind"] in KINDS, e["id"]
        assert set(e) <= {"id", "lines", "kind", "seed", "spec", "note"}, e["id"]
        assert e["seed"].strip(), e["id"]
        first, last = e["lines"]
        assert 1 <= first <= last, e["id"]


def test_no_content_is_explained(doc: dict[str, Any]) -> None:
    for r in doc["no_content"]:
        assert len(r["why"]) >= 7
        assert 1 <= r["lines"][0] <= r["lines"][1]


def _ksy_enum_refs(doc: dict[str, Any], file: str, enum: str) -> set[str]:
    prefix = f"{file}#enum:{enum}."
    return {ref[len(prefix):] for e in doc["entries"] for ref in e["spec"] if ref.startswith(prefix)}


@pytest.mark.parametrize(("file", "enum"), [
    ("osdk_broadcast_items.ksy", "cur_mov_control_mode"),
    ("osdk_broadcast_items.ksy", "control_device"),
    ("osdk_control_mode.ksy", "horizontal_logic"),
    ("osdk_control_mode.ksy", "vertical_logic"),
    ("osdk_control_mode.ksy", "yaw_logic"),
    ("osdk_control_mode.ksy", "horizontal_frame"),
    ("osdk_control_mode.ksy", "stable_mode"),
])
def test_every_value_of_seed_enums_is_traced(doc: dict[str, Any], file: str, enum: str) -> None:
    labels = set(ksy.load().enums[(file.removesuffix(".ksy"), enum)].values())
    assert _ksy_enum_refs(doc, file, enum) == labels


def test_every_combination_and_seed_table_row_is_traced(doc: dict[str, Any]) -> None:
    refs = {ref for e in doc["entries"] for ref in e["spec"]}
    for n in range(14):
        assert f"rules.yaml#/control_modes/combinations/{n}" in refs
    for n in range(6):
        assert f"rules.yaml#/flight_status/compatibility/{n}" in refs
    for n in range(5):
        assert f"rules.yaml#/flight_status/enums/old/values/{n}" in refs
    for n in range(3):
        assert f"rules.yaml#/flight_status/enums/new/values/{n}" in refs
    for ch in ("roll", "pitch", "yaw", "throttle", "mode", "gear"):
        assert f"rules.yaml#/rc_channels/channels/{ch}" in refs
    for n in range(4):
        assert f"rules.yaml#/device_byte/fields/{n}" in refs
        assert f"rules.yaml#/gimbal_limit/fields/{n}" in refs
    for n in range(3):
        assert f"rules.yaml#/velocity_status/fields/{n}" in refs
    assert {"rules.yaml#/control_mode/preconditions/0/functional_if_any",
            "rules.yaml#/control_mode/preconditions/1/functional_if_any",
            "rules.yaml#/control_mode/preconditions/2"} <= refs
    rates = {ref.rsplit("/", 1)[1] for ref in refs if "/default_rates_hz/" in ref}
    assert rates == set(yaml.safe_load(RULES_PATH.read_text())["profiles"]["a3-fw3.1"]["flag_bits"]) - {"gimbal"}


def _pointer_value(doc: Any, pointer: str) -> Any:
    node = doc
    for part in pointer.lstrip("/").split("/"):
        node = node[int(part)] if isinstance(node, list) else node[part]
    return node


def test_enum_refs_agree_between_ksy_and_rules(doc: dict[str, Any]) -> None:
    """An entry that names a ksy enum label and a rules enum value names the same one."""
    rules = yaml.safe_load(RULES_PATH.read_text(encoding="utf-8"))
    checked = 0
    for e in doc["entries"]:
        labels = {ref.rpartition(".")[2] for ref in e["spec"] if "#enum:" in ref and ref.count(".") >= 2}
        for ref in e["spec"]:
            m = re.fullmatch(r"rules\.yaml#(/(?:enums/[a-z_]+|control_mode/fields/\d)/values/\d+)", ref)
            if m and labels:
                assert _pointer_value(rules, m.group(1))["name"] in labels, (e["id"], ref, labels)
                checked += 1
    assert checked >= 40


def test_garbled_cur_mov_lines_cite_errata_e02(doc: dict[str, Any]) -> None:
    lines = [e for e in doc["entries"] if "#enum:cur_mov_control_mode." in " ".join(e["spec"])]
    assert len(lines) >= 27
    for e in lines:
        if e["kind"] == "enum_value":
            assert "ERRATA.md#E02" in e["spec"], e["id"]


def test_cli_without_seed_skips_the_seed_checks_and_says_so(
        no_seed_env: None, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["spec", "trace"]) == 0
    out = capsys.readouterr().out
    assert "seed lines: SKIPPED" in out
    assert "did not run: no seed given (--seed FILE, or set OSDK_SEED)" in out
    assert out.rstrip().endswith("SKIPPED the checks against the seed")
    assert "trace: OK, every seed entry is mapped" not in out


def test_cli_json_without_seed_leaves_the_seed_counts_empty(
        no_seed_env: None, capsys: pytest.CaptureFixture[str]) -> None:
    import json

    assert main(["spec", "trace", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["ok"] is True and out["seed"] is None
    assert out["seed_nonblank_lines"] is None and out["uncovered_lines"] is None
    assert "no seed given" in out["skipped"]


def test_spec_check_trace_step_without_seed_is_a_skip_not_a_pass(no_seed_env: None) -> None:
    with pytest.raises(Skipped, match=r"spec elements that all exist; .*did not run: no seed given"):
        _trace(None)


# ------------------------------------------- a synthetic seed and its trace

# Our own wording, shaped like the seed: a heading, facts on one line and
# across two, and a table header that carries no fact.
SYNTHETIC_SEED = """\
# Mode byte

Bits 7 and 6 of the mode byte select the horizontal logic.
Value 0b00 of those bits means a tilt angle.
Attitude holds within half a degree,
speed within 0.2 m/s.

| Column | Column |
"""
NONBLANK = 6


def _synthetic_trace(seed_text: str) -> dict[str, Any]:
    return {
        "seed": "synthetic.txt",
        "seed_sha256": hashlib.sha256(seed_text.encode("utf-8")).hexdigest(),
        "entries": [
            {"id": "S001", "lines": [3, 3], "kind": "field", "seed": "Bits 7 and 6 of the mode byte",
             "spec": ["osdk_control_mode.ksy#osdk_control_mode.horizontal_logic", "rules.yaml#/control_mode/fields/0"]},
            {"id": "S002", "lines": [4, 4], "kind": "enum_value", "seed": "0b00 of those bits means a tilt angle",
             "spec": ["osdk_control_mode.ksy#enum:horizontal_logic.hori_atti_tilt_ang",
                      "rules.yaml#/control_mode/fields/0/values/0", "ERRATA.md#E16"]},
            {"id": "S003", "lines": [5, 6], "kind": "rule", "seed": "Attitude holds within half a degree, speed",
             "spec": ["rules.yaml#/control_modes/accuracy/attitude_deg"]},
            {"id": "S004", "lines": [6, 6], "kind": "rule", "seed": "speed within 0.2 m/s",
             "spec": ["rules.yaml#/control_modes/accuracy/speed_mps"]},
        ],
        "no_content": [
            {"lines": [1, 1], "why": "heading"},
            {"lines": [8, 8], "why": "table header"},
        ],
    }


@pytest.fixture
def seed(tmp_path: Path) -> Path:
    path = tmp_path / "seed.txt"
    path.write_text(SYNTHETIC_SEED, encoding="utf-8")
    return path


@pytest.fixture
def synthetic() -> dict[str, Any]:
    return _synthetic_trace(SYNTHETIC_SEED)


def test_synthetic_trace_is_ok(tmp_path: Path, synthetic: dict[str, Any], seed: Path) -> None:
    report = trace.check(_write(tmp_path, synthetic), seed)
    assert _problems(report) == []
    assert report.ok and report.skipped is None
    assert (report.nonblank, report.uncovered) == (NONBLANK, [])


def _sole_owner(data: dict[str, Any]) -> tuple[int, list[int]]:
    """Index of an entry whose lines nothing else covers, and those lines."""
    for i, e in enumerate(data["entries"]):
        mine = set(range(e["lines"][0], e["lines"][1] + 1))
        others: set[int] = set()
        for j, o in enumerate(data["entries"]):
            if j != i:
                others.update(range(o["lines"][0], o["lines"][1] + 1))
        for r in data["no_content"]:
            others.update(range(r["lines"][0], r["lines"][1] + 1))
        if mine - others:
            return i, sorted(mine - others)
    raise AssertionError("every entry shares all its lines")


def test_removed_entry_leaves_lines_uncovered(tmp_path: Path, synthetic: dict[str, Any], seed: Path) -> None:
    index, lines = _sole_owner(synthetic)
    del synthetic["entries"][index]
    report = trace.check(_write(tmp_path, synthetic), seed)
    assert not report.ok
    assert report.uncovered == lines


def test_removed_no_content_leaves_lines_uncovered(tmp_path: Path, synthetic: dict[str, Any], seed: Path) -> None:
    gone = synthetic["no_content"].pop(0)
    report = trace.check(_write(tmp_path, synthetic), seed)
    assert not report.ok
    assert report.uncovered == [gone["lines"][0]]


@pytest.mark.parametrize("with_seed", [True, False])
def test_no_content_without_reason(tmp_path: Path, synthetic: dict[str, Any], seed: Path, with_seed: bool) -> None:
    synthetic["no_content"][1]["why"] = ""
    report = trace.check(_write(tmp_path, synthetic), seed if with_seed else None)
    assert not report.ok and report.problems == ["no_content 8-8 gives no reason"]


def test_malformed_no_content_lines_are_reported(tmp_path: Path, synthetic: dict[str, Any], seed: Path) -> None:
    synthetic["no_content"][0]["lines"] = [1]
    report = trace.check(_write(tmp_path, synthetic), seed)
    assert report.problems == ["no_content lines 0-0 are not a range of seed lines"]
    assert report.uncovered == [1]


def _absent_errata_id() -> str:
    return f"E{max(int(i[1:]) for i in trace.errata_ids()) + 1:02d}"


@pytest.mark.parametrize("with_seed", [True, False])
@pytest.mark.parametrize("bad_ref", [
    "osdk_broadcast_items.ksy#position.altitude_msl",        # no such field
    "osdk_broadcast_items.ksy#positions",                    # no such type
    "osdk_broadcast_items.ksy#enum:control_device.drone",    # no such enum value
    "osdk_broadcast_items.ksy#enum:flight_mode",             # no such enum
    "osdk_broadcasts.ksy#position",                          # no such file
    "rules.yaml#/control_modes/combinations/14",             # only 14 combinations (0..13)
    "rules.yaml#/profiles/m100-fw2.3/default_rates_hz/gps_detail",  # not in that profile
    "rules.yaml#/profiles/m100-fw2.3/item_sizes",            # sizes are computed from the ksy, not written
    "rules.yaml#/enums/profile",                             # made from the profiles' values, not written
    "rules.yaml#/no_such_section",
    "ERRATA.md#next",                                        # one past the last entry
    "ERRATA.md#E2",
    "README.md#intro",                                       # not a spec file
])
def test_bad_reference_is_reported(tmp_path: Path, synthetic: dict[str, Any], seed: Path,
                                   bad_ref: str, with_seed: bool) -> None:
    bad_ref = bad_ref.replace("#next", f"#{_absent_errata_id()}")
    synthetic["entries"][2]["spec"].append(bad_ref)
    report = trace.check(_write(tmp_path, synthetic), seed if with_seed else None)
    assert not report.ok
    assert _problems(report) == [f"S003: no such spec element: {bad_ref}"]


@pytest.mark.parametrize("with_seed", [True, False])
def test_empty_spec_and_duplicate_id_are_reported(tmp_path: Path, synthetic: dict[str, Any], seed: Path,
                                                  with_seed: bool) -> None:
    synthetic["entries"][0]["spec"] = []
    synthetic["entries"][3]["id"] = synthetic["entries"][2]["id"]
    report = trace.check(_write(tmp_path, synthetic), seed if with_seed else None)
    assert _problems(report) == ["S001: maps to nothing", "S003: duplicate id"]


@pytest.mark.parametrize("lines", [[0, 1], [4, 3], [2], "5", [1.0, 2.0], None])
def test_malformed_lines_are_reported_without_seed(tmp_path: Path, synthetic: dict[str, Any], lines: Any) -> None:
    synthetic["entries"][1]["lines"] = lines
    report = trace.check(_write(tmp_path, synthetic))
    assert not report.ok
    first, last = lines if isinstance(lines, list) and len(lines) == 2 and isinstance(lines[0], int) else (0, 0)
    assert _problems(report) == [f"S002: lines {first}-{last} are not a range of seed lines"]


@pytest.mark.parametrize(("mutate", "expected"), [
    ("wrong_words", "quote not found in seed lines 6-6"),
    ("wrong_lines", "quote not found in seed lines 5-5"),   # the quote is on line 6
    ("outside", "lines 8-10 outside the seed"),              # the seed has 8 lines (9 with the empty last)
    ("far_outside", "lines 400-401 outside the seed"),
])
def test_wrong_quote_is_reported_only_with_seed(tmp_path: Path, synthetic: dict[str, Any], seed: Path,
                                                mutate: str, expected: str) -> None:
    e = synthetic["entries"][3]
    if mutate == "wrong_words":
        e["seed"] = "speed within 0.02 m/s"
    elif mutate == "wrong_lines":
        e["lines"] = [5, 5]
    elif mutate == "outside":
        e["lines"] = [8, 10]
    else:
        e["lines"] = [400, 401]
    path = _write(tmp_path, synthetic)
    assert _problems(trace.check(path, seed)) == [f"S004: {expected}"]
    # without the seed nothing can say the quote is wrong: the check is skipped, not passed
    without = trace.check(path)
    assert without.ok and without.skipped


def test_quote_matching_normalises_whitespace(tmp_path: Path, synthetic: dict[str, Any], seed: Path) -> None:
    synthetic["entries"][2]["seed"] = "Attitude   holds\twithin half\n a degree,   speed"
    assert trace.check(_write(tmp_path, synthetic), seed).ok


def test_changed_seed_hash_in_trace_is_reported(tmp_path: Path, synthetic: dict[str, Any], seed: Path) -> None:
    synthetic["seed_sha256"] = "0" * 64
    report = trace.check(_write(tmp_path, synthetic), seed)
    assert not report.ok
    assert len(report.problems) == 1 and "review the trace" in report.problems[0]


def test_changed_seed_is_reported(tmp_path: Path, synthetic: dict[str, Any]) -> None:
    changed = tmp_path / "changed.txt"
    # same line count, one character changed: the hash no longer matches, and
    # neither does the quote taken from the changed line
    changed.write_text(SYNTHETIC_SEED.replace("0.2 m/s", "0.3 m/s"), encoding="utf-8")
    report = trace.check(_write(tmp_path, synthetic), changed)
    assert not report.ok
    assert any("seed_sha256" in p for p in report.problems)
    assert _problems(report)[-1] == "S004: quote not found in seed lines 6-6"


def test_unreadable_inputs_raise(tmp_path: Path, seed: Path) -> None:
    with pytest.raises(trace.TraceError, match="does not exist"):
        trace.check(tmp_path / "absent.yaml")
    (tmp_path / "trace.yaml").write_text("entries: [\n", encoding="utf-8")
    with pytest.raises(trace.TraceError, match="not valid YAML"):
        trace.check(tmp_path / "trace.yaml")
    (tmp_path / "trace.yaml").write_text("- a list\n", encoding="utf-8")
    with pytest.raises(trace.TraceError, match="not a mapping"):
        trace.check(tmp_path / "trace.yaml")
    (tmp_path / "trace.yaml").write_text("entries: [S001]\n", encoding="utf-8")
    with pytest.raises(trace.TraceError, match="entries is not a list of mappings"):
        trace.check(tmp_path / "trace.yaml")
    with pytest.raises(trace.TraceError, match="not found"):
        trace.check(TRACE_PATH, tmp_path / "no-seed.txt")
    binary = tmp_path / "binary.txt"
    binary.write_bytes(b"\xff\xfe\x00garbage")
    with pytest.raises(trace.TraceError, match="not UTF-8 text"):
        trace.check(TRACE_PATH, binary)


def test_seed_comes_from_the_option_then_the_environment(
        monkeypatch: pytest.MonkeyPatch, tmp_path: Path, seed: Path) -> None:
    monkeypatch.delenv(SEED_ENV, raising=False)
    assert trace.seed_from(None) is None
    monkeypatch.setenv(SEED_ENV, "")
    assert trace.seed_from(None) is None
    monkeypatch.setenv(SEED_ENV, str(seed))
    assert trace.seed_from(None) == seed
    other = tmp_path / "other.txt"
    other.write_text("x\n", encoding="utf-8")
    assert trace.seed_from(str(other)) == other
    with pytest.raises(UsageError, match=r"seed .*absent.txt \(from --seed\) not found"):
        trace.seed_from(str(tmp_path / "absent.txt"))
    monkeypatch.setenv(SEED_ENV, str(tmp_path / "gone.txt"))
    with pytest.raises(UsageError, match=r"\(from OSDK_SEED\) not found"):
        trace.seed_from(None)


def test_cli_checks_the_real_trace_against_the_seed_given(
        no_seed_env: None, seed: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # the synthetic seed is not the one the real trace maps: every check
    # against it runs, and the hash and quotes disagree
    assert main(["spec", "trace", "--seed", str(seed)]) == 1
    out = capsys.readouterr().out
    assert "problem: seed_sha256 is" in out and "quote not found" in out
    assert "SKIPPED" not in out
    assert out.rstrip().endswith("trace: FAILED")
    with pytest.raises(RuntimeError, match="run `osdkc spec trace`"):
        _trace(str(seed))


def test_cli_missing_seed_is_a_usage_error(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["spec", "trace", "--seed", str(tmp_path / "absent.txt")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "absent.txt (from --seed) not found" in err


# ------------------------------------ the real seed, when $OSDK_SEED names it

REAL_SEED = os.environ.get(SEED_ENV)
needs_real_seed = pytest.mark.skipif(
    not REAL_SEED, reason=f"{SEED_ENV} not set: the real seed is not part of the repository")


@needs_real_seed
def test_real_trace_against_the_real_seed(doc: dict[str, Any], capsys: pytest.CaptureFixture[str]) -> None:
    seed_path = Path(str(REAL_SEED))
    report = trace.check(TRACE_PATH, seed_path)
    assert _problems(report) == []
    assert report.uncovered == [] and report.nonblank == 218 and report.ok
    seed_lines = seed_path.read_text(encoding="utf-8").split("\n")
    for e in doc["entries"]:
        first, last = e["lines"]
        # an entry never starts or ends on a blank line
        assert seed_lines[first - 1].strip() and seed_lines[last - 1].strip(), e["id"]
    no_content_lines = 0
    for r in doc["no_content"]:
        for i in range(r["lines"][0], r["lines"][1] + 1):
            text = seed_lines[i - 1].strip()
            no_content_lines += bool(text)
            # headings, table headers and code-fence syntax only
            assert not re.search(r"\d+\s*Hz|uint|float|int16|-?\d{3,}", text), f"line {i} has a fact: {text!r}"
    assert no_content_lines <= 30
    assert main(["spec", "trace"]) == 0
    out = capsys.readouterr().out
    assert "218 non-blank, 218 covered, 0 uncovered" in out and "trace: OK, every seed entry is mapped" in out
