"""Tests of the seed-to-spec trace (spec/trace.yaml, osdk_conformance/trace.py).

The real trace must pass; copies of it with one thing broken (in tmp_path,
the real files are never touched) must make the checker complain.
"""
from __future__ import annotations

import copy
import hashlib
import re
from pathlib import Path
from typing import Any

import pytest
import yaml

from osdk_conformance import ksy, trace
from osdk_conformance.paths import SEED

ROOT = Path(__file__).resolve().parents[1]
TRACE_PATH = ROOT / "spec" / "trace.yaml"
RULES_PATH = ROOT / "spec" / "rules.yaml"
KINDS = {"item", "field", "enum_value", "range", "rule", "table_row", "unit", "frequency"}


@pytest.fixture(scope="module")
def doc() -> dict[str, Any]:
    return yaml.safe_load(TRACE_PATH.read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def report() -> trace.Report:
    return trace.check()


@pytest.fixture(scope="module")
def seed_lines() -> list[str]:
    return SEED.read_text(encoding="utf-8").split("\n")


def _write(tmp_path: Path, data: dict[str, Any]) -> Path:
    path = tmp_path / "trace.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False, allow_unicode=True), encoding="utf-8")
    return path


def _problems(report: trace.Report) -> list[str]:
    return report.problems + [f"{e.id}: {p}" for e in report.entries for p in e.problems]


# ------------------------------------------------------------ the real trace


def test_real_trace_is_ok(report: trace.Report) -> None:
    assert _problems(report) == []
    assert report.uncovered == []
    assert report.ok


def test_every_nonblank_seed_line_is_covered(doc: dict[str, Any], seed_lines: list[str]) -> None:
    covered: set[int] = set()
    for e in doc["entries"]:
        covered.update(range(e["lines"][0], e["lines"][1] + 1))
    for r in doc["no_content"]:
        covered.update(range(r["lines"][0], r["lines"][1] + 1))
    nonblank = {i + 1 for i, line in enumerate(seed_lines) if line.strip()}
    assert len(nonblank) == 218
    assert nonblank - covered == set()


def test_every_entry_maps_to_existing_elements(doc: dict[str, Any]) -> None:
    resolver = trace.Resolver()
    missing = [(e["id"], ref) for e in doc["entries"] for ref in e["spec"] if not resolver.exists(ref)]
    assert missing == []
    assert all(e["spec"] for e in doc["entries"])


def test_entries_are_well_formed(doc: dict[str, Any], seed_lines: list[str]) -> None:
    assert doc["seed"] == "../shared/seeds/000_b7658b258220b5c1.txt"
    assert (ROOT / doc["seed"]).resolve() == SEED.resolve()  # relative to the repository root
    assert doc["seed_sha256"] == hashlib.sha256(SEED.read_bytes()).hexdigest()
    ids = [e["id"] for e in doc["entries"]]
    assert ids == [f"S{n:03d}" for n in range(1, len(ids) + 1)]
    assert len(ids) >= 200
    for e in doc["entries"]:
        assert e["kind"] in KINDS, e["id"]
        assert set(e) <= {"id", "lines", "kind", "seed", "spec", "note"}, e["id"]
        assert e["seed"].strip(), e["id"]
        first, last = e["lines"]
        # an entry never starts or ends on a blank line
        assert seed_lines[first - 1].strip() and seed_lines[last - 1].strip(), e["id"]


def test_no_content_is_rare_and_explained(doc: dict[str, Any], seed_lines: list[str]) -> None:
    n_lines = 0
    for r in doc["no_content"]:
        assert len(r["why"]) >= 7
        n_lines += sum(1 for i in range(r["lines"][0], r["lines"][1] + 1) if seed_lines[i - 1].strip())
    # headings, table headers and code-fence syntax only
    assert n_lines <= 30
    for r in doc["no_content"]:
        for i in range(r["lines"][0], r["lines"][1] + 1):
            text = seed_lines[i - 1].strip()
            assert not re.search(r"\d+\s*Hz|uint|float|int16|-?\d{3,}", text), f"line {i} has a fact: {text!r}"


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


def test_cli_prints_ok(capsys: pytest.CaptureFixture[str]) -> None:
    from osdk_conformance.cli import main

    assert main(["spec", "trace"]) == 0
    out = capsys.readouterr().out
    assert "trace: OK" in out
    assert "218 non-blank, 218 covered, 0 uncovered" in out


# ----------------------------------------------------- the checker bites


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


def test_unmodified_copy_is_ok(tmp_path: Path, doc: dict[str, Any]) -> None:
    assert trace.check(_write(tmp_path, doc)).ok


def test_removed_entry_leaves_lines_uncovered(tmp_path: Path, doc: dict[str, Any]) -> None:
    data = copy.deepcopy(doc)
    index, lines = _sole_owner(data)
    del data["entries"][index]
    report = trace.check(_write(tmp_path, data))
    assert not report.ok
    assert set(lines) <= set(report.uncovered)


def test_removed_no_content_leaves_lines_uncovered(tmp_path: Path, doc: dict[str, Any]) -> None:
    data = copy.deepcopy(doc)
    gone = data["no_content"].pop(0)
    report = trace.check(_write(tmp_path, data))
    assert not report.ok
    assert gone["lines"][0] in report.uncovered


def test_no_content_without_reason(tmp_path: Path, doc: dict[str, Any]) -> None:
    data = copy.deepcopy(doc)
    data["no_content"][0]["why"] = ""
    report = trace.check(_write(tmp_path, data))
    assert not report.ok and any("gives no reason" in p for p in report.problems)


@pytest.mark.parametrize("bad_ref", [
    "osdk_broadcast_items.ksy#position.altitude_msl",        # no such field
    "osdk_broadcast_items.ksy#positions",                    # no such type
    "osdk_broadcast_items.ksy#enum:control_device.drone",    # no such enum value
    "osdk_broadcast_items.ksy#enum:flight_mode",             # no such enum
    "osdk_broadcasts.ksy#position",                          # no such file
    "rules.yaml#/control_modes/combinations/14",             # only 14 combinations (0..13)
    "rules.yaml#/profiles/m100-fw2.3/item_sizes/gps_detail", # not in that profile
    "rules.yaml#/no_such_section",
    "ERRATA.md#E30",                                         # E01..E29 only
    "ERRATA.md#E2",
    "README.md#intro",                                       # not a spec file
])
def test_bad_reference_is_reported(tmp_path: Path, doc: dict[str, Any], bad_ref: str) -> None:
    data = copy.deepcopy(doc)
    data["entries"][5]["spec"].append(bad_ref)
    report = trace.check(_write(tmp_path, data))
    assert not report.ok
    bad = [e for e in report.entries if e.problems]
    assert [e.id for e in bad] == [data["entries"][5]["id"]]
    assert bad[0].problems == [f"no such spec element: {bad_ref}"]


def test_empty_spec_is_reported(tmp_path: Path, doc: dict[str, Any]) -> None:
    data = copy.deepcopy(doc)
    data["entries"][0]["spec"] = []
    report = trace.check(_write(tmp_path, data))
    assert not report.ok and report.entries[0].problems == ["maps to nothing"]


@pytest.mark.parametrize("mutate", ["wrong_words", "wrong_lines", "outside"])
def test_wrong_quote_is_reported(tmp_path: Path, doc: dict[str, Any], mutate: str) -> None:
    data = copy.deepcopy(doc)
    e = next(x for x in data["entries"] if x["seed"] == "Attitude control accuracy is about 0.5 degrees")
    if mutate == "wrong_words":
        e["seed"] = "Attitude control accuracy is about 0.05 degrees"
        expected = "quote not found"
    elif mutate == "wrong_lines":
        e["lines"] = [44, 44]   # the quote is on line 42
        expected = "quote not found"
    else:
        e["lines"] = [400, 401]
        expected = "outside the seed"
    report = trace.check(_write(tmp_path, data))
    assert not report.ok
    assert any(expected in p for x in report.entries if x.id == e["id"] for p in x.problems)


def test_quote_matching_normalises_whitespace(tmp_path: Path, doc: dict[str, Any]) -> None:
    data = copy.deepcopy(doc)
    e = next(x for x in data["entries"] if x["seed"] == "Attitude control accuracy is about 0.5 degrees")
    e["seed"] = "Attitude   control\taccuracy\n is about 0.5 degrees"
    assert trace.check(_write(tmp_path, data)).ok


def test_duplicate_id_is_reported(tmp_path: Path, doc: dict[str, Any]) -> None:
    data = copy.deepcopy(doc)
    data["entries"][1]["id"] = data["entries"][0]["id"]
    report = trace.check(_write(tmp_path, data))
    assert not report.ok and "duplicate id" in report.entries[1].problems


def test_changed_seed_hash_in_trace_is_reported(tmp_path: Path, doc: dict[str, Any]) -> None:
    data = copy.deepcopy(doc)
    data["seed_sha256"] = "0" * 64
    report = trace.check(_write(tmp_path, data))
    assert not report.ok
    assert any("seed_sha256" in p and "review the trace" in p for p in report.problems)


def test_changed_seed_is_reported(tmp_path: Path, doc: dict[str, Any]) -> None:
    seed = tmp_path / "seed.txt"
    # same line count, one character changed: the hash no longer matches, and
    # neither does the quote taken from the changed line
    seed.write_text(SEED.read_text(encoding="utf-8").replace("0.5 degrees", "0.6 degrees"), encoding="utf-8")
    report = trace.check(_write(tmp_path, doc), seed)
    assert not report.ok
    assert any("seed_sha256" in p for p in report.problems)
    assert any("quote not found" in p for e in report.entries for p in e.problems)


def test_missing_files_raise(tmp_path: Path) -> None:
    with pytest.raises(trace.TraceError, match="does not exist"):
        trace.check(tmp_path / "absent.yaml")
    (tmp_path / "trace.yaml").write_text("entries: [\n", encoding="utf-8")
    with pytest.raises(trace.TraceError, match="not valid YAML"):
        trace.check(tmp_path / "trace.yaml")
    with pytest.raises(trace.TraceError, match="not found"):
        trace.check(TRACE_PATH, tmp_path / "no-seed.txt")
