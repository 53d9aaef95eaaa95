"""The golden vectors: checked, covering every rule and errata entry,
reproducible, and guarded against tampering; compare() as the runner uses it."""
from __future__ import annotations

import hashlib
import importlib
import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from osdk_conformance.reference import codec as reference
from osdk_conformance.core.paths import ROOT
from osdk_conformance.core.rules import profile as rules_profile
from osdk_conformance.harness.spec_rules import RULES
from osdk_conformance.traceability.trace import errata_ids
from osdk_conformance.harness.vectors import (
    MANIFEST_NAME, VECTORS_DIR, Case, compare, coverage_counts, load_cases, manifest_text, suite_files,
)

SMALL_SUITES = ("control_mode", "payloads", "frames", "streams", "encode")


def osdkc(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "osdk_conformance.cli", *args], capture_output=True, text=True,
                          timeout=600)


def small_copy(tmp_path: Path, suites=("payloads",)) -> Path:
    """A vectors directory holding some of the suites, with a manifest for them."""
    d = tmp_path / "vectors"
    d.mkdir()
    for name in suites:
        shutil.copy(VECTORS_DIR / f"{name}.json", d)
    write_manifest(d)
    return d


def write_manifest(d: Path) -> None:
    hashes = {p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in suite_files(d)}
    (d / MANIFEST_NAME).write_text(manifest_text(hashes))


@pytest.fixture(scope="module")
def cases() -> list[Case]:
    return load_cases()


# ------------------------------------------------------------ the checked-in vectors


@pytest.mark.slow
def test_vectors_check_passes():
    proc = osdkc("vectors", "check")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "vectors check: OK" in proc.stdout


def test_vectors_check_passes_on_the_small_suites(tmp_path):
    proc = osdkc("vectors", "check", "--dir", str(small_copy(tmp_path, SMALL_SUITES)))
    assert proc.returncode == 0, proc.stdout + proc.stderr


def test_manifest_lists_every_file_with_its_hash():
    manifest = json.loads((VECTORS_DIR / MANIFEST_NAME).read_text())
    assert sorted(manifest) == [p.name for p in suite_files()]
    for name, digest in manifest.items():
        assert hashlib.sha256((VECTORS_DIR / name).read_bytes()).hexdigest() == digest, name


@pytest.mark.slow
def test_vectors_coverage_passes():
    proc = osdkc("vectors", "coverage")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "UNPINNED" not in proc.stdout
    assert "HOLE" not in proc.stdout and "no hole in the 5 bug-class tables" in proc.stdout
    for title in ("stream error class", "frame rule pair", "header field bit", "command kind \\ ACK situation",
                  "mode byte class"):
        assert "\n" + title in proc.stdout, title


def test_coverage_fails_when_something_is_unpinned(tmp_path):
    proc = osdkc("vectors", "coverage", "--dir", str(small_copy(tmp_path, ("payloads",))))
    assert proc.returncode == 1
    assert "UNPINNED" in proc.stdout and "rule:frame.crc16" in proc.stdout.split("unpinned:")[-1]


def test_a_wrong_hand_written_expectation_stops_the_generator():
    builder = _vectorgen("builder")
    s = builder.Suite("t", "t", seed=1)
    with pytest.raises(builder.GenerationError, match="disagrees with the reference"):
        s.add("classify_control_mode", "a3-fw3.1", "t.a3.x", "t.c", "c", {"byte": 0x4B}, ["E15"],
              expected={"fields": {}, "classification": "documented", "combination": 4})
    with pytest.raises(builder.GenerationError, match="written error"):
        s.add("decode_frame", "a3-fw3.1", "t.a3.y", "t.c", "c", {"hex": "aa"}, ["E22"], error="bad_crc16")


def test_every_rule_and_errata_entry_is_pinned(cases):
    by_rule, by_errata = coverage_counts(cases)
    assert set(by_errata) == errata_ids() and len(by_errata) >= 30
    assert [e for e, n in by_errata.items() if not n] == []
    assert [r for r, n in by_rule.items() if not n] == []
    assert set(by_rule) == set(RULES)


def test_ids_are_unique_and_flags_known(cases):
    ids = [c.id for c in cases]
    assert len(ids) == len(set(ids))
    known = {f"rule:{r}" for r in RULES} | errata_ids()
    assert {f for c in cases for f in c.flags} <= known


def test_required_coverage_is_present(cases):
    by_op_profile: dict[tuple[str, str | None], set] = {}
    for c in cases:
        by_op_profile.setdefault((c.operation, c.profile), set()).add(c.id)
    for profile in reference.PROFILES:
        # all 256 mode bytes per profile
        assert {f"control_mode.{profile}.0x{b:02x}" for b in range(256)} <= by_op_profile[("classify_control_mode", profile)]
        # every flag word of every profile at least once
        bits = len(rules_profile(profile).flag_bits)
        ids = by_op_profile[("decode_payload", profile)]
        for flags in range(1 << bits):
            base = f"broadcast.{profile}.flags.0x{flags:04x}"
            assert base in ids or base + ".short_by_1" in ids, base
        # CRC-16 over every header bit, truncation at every byte
        frame_ids = by_op_profile[("decode_frame", profile)]
        assert {f"frames.{profile}.crc16.bit{b}" for b in range(96)} <= frame_ids
        assert {f"frames.{profile}.truncated.{n}" for n in range(35)} <= frame_ids
    # the worked frames are encoded byte for byte
    worked = {c.id: c for c in cases if c.id.startswith("encode.frame.worked.")}
    assert {c.expected["hex"] for c in worked.values()} == {
        "aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba",
        "aa1600000000000007001ede02000018035769c676b2"}


def test_total_size_is_reasonable():
    total = sum(p.stat().st_size for p in VECTORS_DIR.glob("*.json"))
    assert total < 30_000_000, total


# ------------------------------------------------------------ reproducibility


def test_small_suites_regenerate_byte_for_byte(tmp_path):
    args = [sys.executable, str(ROOT / "tools" / "gen_vectors.py"), "--out", str(tmp_path)]
    for s in SMALL_SUITES:
        args += ["--suite", s]
    proc = subprocess.run(args, capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    for s in SMALL_SUITES:
        assert (tmp_path / f"{s}.json").read_bytes() == (VECTORS_DIR / f"{s}.json").read_bytes(), s


@pytest.mark.slow
def test_every_suite_regenerates_byte_for_byte():
    proc = subprocess.run([sys.executable, str(ROOT / "tools" / "gen_vectors.py"), "--check"],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout + proc.stderr


# ------------------------------------------------------------ tampering


def test_a_tampered_file_fails_the_manifest_check(tmp_path):
    d = small_copy(tmp_path)
    f = d / "payloads.json"
    f.write_text(f.read_text().replace('"comment":"get version', '"comment":"Get version', 1))
    proc = osdkc("vectors", "check", "--dir", str(d), "--no-spec")
    assert proc.returncode == 1
    assert "payloads.json: SHA-256" in proc.stdout and "Traceback" not in proc.stderr


def test_an_altered_expectation_fails_the_spec_check(tmp_path):
    d = small_copy(tmp_path)
    f = d / "payloads.json"
    doc = json.loads(f.read_text())
    test = next(t for g in doc["testGroups"] for t in g["tests"] if t["id"] == "payloads.a3-fw3.1.control_ack.0x0002")
    test["expected"]["value"]["ack_code"]["value"] = 3
    f.write_text(json.dumps(doc))
    write_manifest(d)  # the manifest agrees: only the spec check can catch it
    proc = osdkc("vectors", "check", "--dir", str(d))
    assert proc.returncode == 1
    assert "payloads.a3-fw3.1.control_ack.0x0002: no longer matches the spec" in proc.stdout


def test_an_altered_error_class_fails_the_spec_check(tmp_path):
    d = small_copy(tmp_path, ("frames",))
    f = d / "frames.json"
    f.write_text(f.read_text().replace('"expected":{"error":"bad_version"}', '"expected":{"error":"reserved_bits"}', 1))
    write_manifest(d)
    proc = osdkc("vectors", "check", "--dir", str(d))
    assert proc.returncode == 1 and "now answers bad_version, expected reserved_bits" in proc.stdout


def test_a_schema_violation_is_reported(tmp_path):
    d = small_copy(tmp_path)
    f = d / "payloads.json"
    f.write_text(f.read_text().replace('"result":"valid"', '"result":"maybe"', 1))
    write_manifest(d)
    proc = osdkc("vectors", "check", "--dir", str(d), "--no-spec")
    assert proc.returncode == 1 and "schema" in proc.stdout


@pytest.mark.parametrize("content", ["{not json", "\udcff"])
def test_unreadable_files_exit_2_without_traceback(tmp_path, content):
    d = small_copy(tmp_path)
    (d / "broken.json").write_bytes(content.encode("utf-8", "surrogateescape"))
    for command in ("check", "coverage"):
        proc = osdkc("vectors", command, "--dir", str(d))
        assert proc.returncode == 2, proc.stdout + proc.stderr
        assert "broken.json" in proc.stderr and "Traceback" not in proc.stderr


def test_missing_directory_exits_2(tmp_path):
    proc = osdkc("vectors", "check", "--dir", str(tmp_path / "nope"))
    assert proc.returncode == 2 and "Traceback" not in proc.stderr


@pytest.mark.parametrize("old, new", [('"result":"valid"', '"result":"maybe"'),
                                      ('"numberOfTests": N', '"numberOfTests": N-1'),
                                      ('"flags":["rule:payload.version_query"]', '"flags":["E99"]')])
def test_run_vectors_rejects_what_vectors_check_rejects(tmp_path, old, new):
    """`osdkc run --vectors` and `vectors check` validate with the same code
    and name the same first problem."""
    import io

    from osdk_conformance.harness.vectors import VectorFileError, check, load_checked_cases

    d = small_copy(tmp_path)
    f = d / "payloads.json"
    if old.endswith("N"):   # the suite's own count, whatever it is today
        n = json.loads(f.read_text())["numberOfTests"]
        old, new = old.replace("N", str(n)), new.replace("N-1", str(n - 1))
    assert old in f.read_text()
    f.write_text(f.read_text().replace(old, new, 1))
    write_manifest(d)
    out = io.StringIO()
    assert check(d, spec=False, out=out) == 1
    first = out.getvalue().splitlines()[0].removeprefix("  FAIL  ")
    with pytest.raises(VectorFileError) as e:
        load_checked_cases([f])
    assert first in str(e.value)


def test_checked_loading_of_the_shipped_vectors_gives_every_case(cases):
    from osdk_conformance.harness.vectors import load_checked_cases

    assert load_checked_cases() == cases


# ------------------------------------------------------------ compare()


def case(op="decode_payload", result="valid", expected=None, **kw) -> Case:
    return Case(file="t.json", operation=op, profile="a3-fw3.1", id="t.a.1", category="t.c", comment="c",
                input=kw.get("input", {}), result=result, expected=expected, flags=("E01",))


def test_compare_valid_is_exact_but_floats_by_bits():
    c = case(expected={"value": {"x": {"f32": "0x7fc00001", "value": "NaN"}, "n": 1, "b": True}})
    assert compare(c, {"ok": True, "result": {"value": {"x": {"f32": "0x7FC00001", "value": 12}, "n": 1, "b": True}}}) == (True, "")
    ok, why = compare(c, {"ok": True, "result": {"value": {"x": {"f32": "0x7fc00000", "value": "NaN"}, "n": 1, "b": True}}})
    assert not ok and "result.value.x" in why
    assert not compare(c, {"ok": True, "result": {"value": {"x": {"f32": "0x7fc00001"}, "n": True, "b": True}}})[0]
    assert not compare(c, {"ok": True, "result": {"value": {"x": {"f32": "0x7fc00001"}, "n": 1, "b": True, "e": 0}}})[0]
    assert not compare(c, {"ok": False, "error": "truncated_payload", "detail": ""})[0]
    assert compare(c, {"ok": False, "unsupported": True}) == (False, "the testee does not support this case")
    assert not compare(c, "garbage")[0]


def test_a_differing_ack_code_is_shown_in_hex_with_its_name():
    want = {"value": {"ack_code": {"value": 0xFF01, "name": "not_activated"}}}
    got = {"ok": True, "result": {"value": {"ack_code": {"value": 3, "name": "obtain_in_progress"}}}}
    passed, reason = compare(case(expected=want), got)
    assert not passed
    assert reason == "result.value.ack_code: expected 0xFF01 not_activated, got 0x0003 obtain_in_progress"


def test_compare_invalid_and_acceptable():
    bad = case(result="invalid", expected={"error": "bad_crc16"})
    assert compare(bad, {"ok": False, "error": "bad_crc16", "detail": "x"}) == (True, "")
    assert not compare(bad, {"ok": False, "error": "bad_crc32", "detail": "x"})[0]
    assert not compare(bad, {"ok": True, "result": {}})[0]
    either = case(op="encode_movement_control", result="acceptable",
                  expected={"value": {"hex": "00" * 17}, "error": "undefined_mode"})
    assert compare(either, {"ok": True, "result": {"hex": "00" * 17}}) == (True, "")
    assert compare(either, {"ok": False, "error": "undefined_mode", "detail": ""}) == (True, "")
    assert not compare(either, {"ok": False, "error": "out_of_range", "detail": ""})[0]
    assert not compare(either, {"ok": True, "result": {"hex": "01" * 17}})[0]


def test_compare_stream_events_on_the_named_fields_only():
    frame = {"sof": "aa", "len": 12}
    c = case(op="decode_stream", expected={"events": [
        {"kind": "garbage", "offset": 0, "length": 2},
        {"kind": "error", "offset": 2, "error": "bad_crc16", "length": 1},
        {"kind": "frame", "offset": 3, "frame": frame, "command": "none"}]})
    got = {"events": [
        {"kind": "garbage", "offset": 0, "length": 2, "note": "x"},
        {"kind": "error", "offset": 2, "error": "bad_crc16", "length": 1, "detail": "anything"},
        {"kind": "frame", "offset": 3, "frame": frame}]}
    assert compare(c, {"ok": True, "result": got}) == (True, "")
    got["events"][1]["length"] = 2
    ok, why = compare(c, {"ok": True, "result": got})
    assert not ok and "events[1].length" in why
    got["events"][1]["length"] = 1
    assert not compare(c, {"ok": True, "result": {"events": got["events"][:2]}})[0]


def test_every_case_passes_against_the_reference_itself(cases):
    # The reference as a testee: what the bundled construct testee answers.
    failures = []
    for c in cases:
        if c.operation == "decode_payload" and "flags.0x" in c.id:
            continue  # thousands of them; covered by `vectors check`
        passed, why = compare(c, reference.answer(c.operation, c.profile, c.input))
        if not passed:
            failures.append(f"{c.id}: {why}")
    assert failures == []


def test_requests_carry_the_profile_only_where_the_operation_takes_one(cases):
    for c in cases:
        req = c.request()
        assert req["op"] == c.operation and req["id"] == c.id
        assert ("profile" in req) == (c.operation not in reference.PROFILE_FREE)


@pytest.mark.slow
def test_every_errata_entry_names_a_vector_that_exists_and_pins_it():
    import re

    from osdk_conformance.core.paths import SPEC
    from osdk_conformance.harness.vectors import load_cases

    text = (SPEC / "ERRATA.md").read_text()
    named = dict(re.findall(r"^## (E\d+):.*?^- \*\*Vectors:\*\* `([^`]+)`", text, flags=re.M | re.S))
    entries = re.findall(r"^## (E\d+):", text, flags=re.M)
    assert sorted(named) == sorted(entries), "every entry needs a vector id on its Vectors line"
    by_id = {c.id: c for c in load_cases()}
    for entry, case_id in named.items():
        assert case_id in by_id, f"{entry}: no vector {case_id}"
        assert entry in by_id[case_id].flags, f"{entry}: vector {case_id} does not flag {entry}"


# ------------------------------------------------------------ bug classes (osdk_conformance.harness.vector_tables)


def _vectorgen(module: str):
    """A module of the generator's package (tools/vectorgen; tools/ is not a package)."""
    sys.path.insert(0, str(ROOT / "tools"))
    try:
        return importlib.import_module(f"vectorgen.{module}")
    finally:
        sys.path.pop(0)


def test_no_bug_class_table_has_a_hole(cases):
    from osdk_conformance.harness.vector_tables import tables

    holes = {t.title: t.holes for t in tables(cases)}
    assert holes == {title: [] for title in holes}, holes
    assert len(holes) == 5


@pytest.mark.parametrize("prefix, title, make", [
    (".stream_error.", "stream error class", "stream_error_table"),
    (".precedence.", "frame rule pair", "rule_pair_table"),
    (".header_bits.", "header field bit", "header_bit_table"),
    (".ack.", "command kind \\ ACK situation", "ack_table"),
])
def test_each_table_shows_holes_without_its_cases(cases, prefix, title, make):
    """The tables count what the bytes exercise: without the cases generated
    for a class, its table has holes again (as it had before they existed).
    Only that table is made (each one reads every case)."""
    from osdk_conformance.harness import vector_tables

    rest = [c for c in cases if prefix not in c.id]
    assert len(rest) < len(cases)
    table = getattr(vector_tables, make)(rest)
    assert table.title == title and table.holes, title


def test_movement_precedence_holes_without_its_cases(cases):
    from osdk_conformance.harness.vector_tables import movement_table

    rest = [c for c in cases if c.operation == "check_movement_control" and ".precedence." not in c.id]
    assert set(movement_table(rest).holes) >= {"invalid x length + mode", "documented x length + range"}


def test_broken_rules_judges_each_rule_on_its_own():
    """Each breaker of the generator breaks its rule, and in a stream nothing else."""
    from osdk_conformance.harness.vector_tables import FRAME_RULES, broken_rules

    gen = _vectorgen("precedence")
    for rule in FRAME_RULES:
        for tag, breaker in gen.BREAKERS[rule.name].items():
            data = gen.broken_frame([breaker])
            assert rule.name in broken_rules(data, "a3-fw3.1", "decode_frame"), (rule.name, tag)
            if "decode_stream" in rule.contexts:
                assert broken_rules(data, "a3-fw3.1", "decode_stream") == {rule.name}, (rule.name, tag)
    assert set(gen.BREAKERS) == {r.name for r in FRAME_RULES}
    assert broken_rules(_vectorgen("wire").GOOD_FRAME, "a3-fw3.1", "decode_frame") == set()


def test_every_stream_error_class_is_produced_in_a_stream(cases):
    from osdk_conformance.harness.vector_tables import NOT_IN_STREAMS, frame_error_classes, stream_error_classes

    assert {"bad_crc16", "bad_crc32", "truncated_frame", "bad_session", "length_mismatch"} <= set(stream_error_classes())
    assert set(frame_error_classes()) == set(stream_error_classes()) | (set(NOT_IN_STREAMS) & set(frame_error_classes()))
    seen = {ev["error"] for c in cases if c.operation == "decode_stream" and c.result == "valid"
            for ev in c.expected["events"] if ev["kind"] == "error"}
    assert seen == set(stream_error_classes())
