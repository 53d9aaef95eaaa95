"""`osdkc selftest`: the golden vectors kill every mutant of the reference.

Two real runs of the command (the real runner and child processes) are
shared by the tests below and together hold every mutant once: the
bug-class mutants, each until it has failed many vectors, and all the
others with the default stop after 3 failures (a bug-class mutant would
only repeat there the first failures of its own run). Both leave out the baseline, the unmutated harness replaying every
vector: that replay is the construct testee's, which tests/test_runner.py's
run of every implementation makes once for the suite. The baseline's own
part, voiding the score when it fails, is tested on a small vector file.
"""
from __future__ import annotations

import json
import re
import subprocess
import sys
from pathlib import Path

import pytest

from osdk_conformance.harness import mutants
from osdk_conformance.harness.selftest import interleave
from osdk_conformance.harness.spec_rules import RULES
from osdk_conformance.traceability.trace import errata_ids

ROOT = Path(__file__).resolve().parents[1]
MUTANT_TESTEE = ROOT / "conformance" / "testees" / "mutant_testee.py"

# The faults the brief of the mutation check names, by our mutant names.
REQUIRED = {
    "position_lat_lon_swapped", "magnetometer_5_bytes", "crc16_init_ffff", "crc32_final_xor",
    "header_reserved_ignored", "version_not_checked", "a3_m100_flag_order", "thrust_0_to_100",
    "broadcast_no_length_check", "len_13_to_16_accepted", "no_rescan_after_bad_crc32", "bad_header_drops_12",
    "ack_session0_accepted", "broadcast_trailing_accepted", "reserved_flags_ignored", "fw23_gimbal_limit_byte",
    "fw31_control_info_1_byte", "yaw_rate_150", "horizontal_0b11_documented", "e15_ignored", "snan_quieted",
    "neg_zero_normalised", "seq_big_endian", "cur_mov_control_mode_shifted", "encoder_len_without_crc32",
    "crash_on_aes", "hang_on_empty_read",
}


def osdkc(*args: str, timeout: float = 600) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "osdk_conformance.cli", *args], capture_output=True, text=True,
                          timeout=timeout, cwd=ROOT)


# The mutants of the bug classes of osdk_conformance.harness.vector_tables: each must
# fail many vectors, not a handful (a class closed case by case would not).
BUG_CLASS_MUTANTS = {
    "value_error_rescans_after_sof", "truncated_tail_no_rescan", "ack_repeat_matched", "ack_match_seq_only",
    "ack_last_command_only", "ack_first_command_kept", "ack_rejected_command_remembered", "ack_header_only_ignored",
    "ack_table_by_key", "ack_other_seq_consumes",
    "crc16_checked_last", "len_checked_before_ver", "reserved_checked_before_ver", "enc_checked_before_session",
    "size_checked_before_header", "session_enc_in_header_check", "movement_mode_before_length",
    "movement_non_finite_before_mode", "len_takes_a_ver_bit", "ver_takes_a_len_bit", "ver_takes_a_session_bit",
    "session_takes_a_ver_bit", "res0_takes_a_padding_bit", "padding_takes_a_res0_bit", "padding_takes_a_enc_bit",
    "enc_takes_a_padding_bit", "enc_takes_a_res1_bit", "res1_takes_a_enc_bit",
}
MANY = 10


@pytest.fixture(scope="module")
def selftest_run():
    """The command as a user runs it, with the default stop after 3 failures and no baseline, on
    every mutant that bug_class_run does not run."""
    args = [a for name in mutants.MUTANTS if name not in BUG_CLASS_MUTANTS for a in ("--mutant", name)]
    return osdkc("selftest", "--quiet", "--no-baseline", *args)


@pytest.fixture(scope="module")
def bug_class_run():
    """The bug-class mutants again, each until MANY failures (a mutant with fewer failing
    vectors than that would replay the whole suite, so the others are not in this run)."""
    args = [a for name in sorted(BUG_CLASS_MUTANTS) for a in ("--mutant", name)]
    return osdkc("selftest", "--quiet", "--no-baseline", "--max-failures", str(MANY), *args)


def rows(stdout: str) -> dict[str, list[str]]:
    """mutant name -> its table row split on runs of 2+ spaces."""
    out = {}
    for line in stdout.splitlines():
        cells = re.split(r"\s{2,}", line.strip())
        if cells and cells[0] in mutants.MUTANTS:
            out[cells[0]] = cells
    return out


@pytest.mark.slow
def test_every_mutant_is_killed(selftest_run, bug_class_run):
    table = {}
    for proc in (selftest_run, bug_class_run):
        assert proc.returncode == 0, proc.stdout[-6000:] + proc.stderr[-3000:]
        n = len(rows(proc.stdout))
        assert f"mutation score: {n}/{n} killed (100.0%)" in proc.stdout
        assert "SELFTEST PASSED" in proc.stdout and "Traceback" not in proc.stderr
        assert not set(table) & set(rows(proc.stdout))
        table.update(rows(proc.stdout))
    assert set(table) == set(mutants.MUTANTS)
    assert all(cells[1] == "yes" for cells in table.values())


@pytest.mark.slow
def test_crash_and_hang_are_recorded_as_testee_failures(selftest_run):
    proc = selftest_run
    table = rows(proc.stdout)
    assert "testee_crash" in table["crash_on_aes"][3]
    assert "testee_timeout" in table["hang_on_empty_read"][3]
    assert "note:" not in proc.stdout  # every misbehaving mutant died the way it should


@pytest.mark.slow
def test_the_truncation_vectors_kill_the_sdk_style_broadcast_copy(selftest_run):
    proc = selftest_run
    first = rows(proc.stdout)["broadcast_no_length_check"][3]
    assert re.search(r"(short_by_1|truncated|missing|flag_word|broadcast_short)", first), first


@pytest.mark.slow
def test_bug_class_mutants_fail_many_vectors(bug_class_run):
    assert bug_class_run.returncode == 0, bug_class_run.stdout[-4000:] + bug_class_run.stderr[-2000:]
    table = rows(bug_class_run.stdout)
    few = {name: table[name][2] for name in BUG_CLASS_MUTANTS if table[name][2] != f"{MANY}+"}
    assert few == {}, few


def _payload_vectors(tmp_path: Path, break_one: bool) -> Path:
    """vectors/payloads.json (216 cases), with one expected value made wrong if asked."""
    doc = json.loads((ROOT / "vectors" / "payloads.json").read_text())
    if break_one:
        case = doc["testGroups"][0]["tests"][0]
        assert case["expected"] == {"value": {"arbitrary": 0}}, case
        case["expected"]["value"]["arbitrary"] = 1
    path = tmp_path / "payloads.json"
    path.write_text(json.dumps(doc))
    return path


@pytest.mark.parametrize("broken", [False, True], ids=["vectors-right", "one-vector-wrong"])
def test_the_baseline_replays_the_vectors_and_a_failing_one_voids_the_score(tmp_path, broken):
    vectors = _payload_vectors(tmp_path, broken)
    proc = osdkc("selftest", "--quiet", "--vectors", str(vectors), "--mutant", "activation_fields_swapped")
    cases = sum(len(g["tests"]) for g in json.loads(vectors.read_text())["testGroups"])
    if not broken:
        assert proc.returncode == 0, proc.stdout + proc.stderr
        assert re.search(rf"baseline \(no fault\): {cases} cases, 0 failing, .*: OK", proc.stdout)
        assert "SELFTEST PASSED" in proc.stdout
    else:
        assert proc.returncode == 1, proc.stdout + proc.stderr
        assert re.search(rf"baseline \(no fault\): {cases} cases, 1 failing, .*: FAILS", proc.stdout)
        assert "first: payloads.m100-fw2.3.version_query.0x00" in proc.stdout
        assert "SELFTEST FAILED: the unmutated harness does not pass the vectors" in proc.stdout


def test_registry():
    assert len(mutants.MUTANTS) >= 24
    assert REQUIRED <= set(mutants.MUTANTS) and BUG_CLASS_MUTANTS <= set(mutants.MUTANTS)
    errata = errata_ids()
    for m in mutants.MUTANTS.values():
        assert re.fullmatch(r"[a-z0-9_]+", m.name) and m.name != mutants.NONE
        assert m.description and "\n" not in m.description
        assert m.violates, m.name
        for v in m.violates:
            assert (v.startswith("rule:") and v[5:] in RULES) or v in errata, (m.name, v)
        assert m.expect in ("mismatch", "testee_crash", "testee_timeout")


def test_interleave_keeps_every_case_once():
    from osdk_conformance.harness.vectors import load_cases

    cases = load_cases()
    ordered = interleave(cases)
    assert sorted(c.id for c in ordered) == sorted(c.id for c in cases)
    # every (category, operation, profile) group shows up among the first cases
    groups = {(c.category, c.operation, c.profile) for c in cases}
    assert {(c.category, c.operation, c.profile) for c in ordered[:len(groups)]} == groups


@pytest.mark.slow
def test_one_mutant_through_osdkc_run():
    """A mutant testee is an ordinary testee: `osdkc run` says it does not conform."""
    proc = osdkc("run", "--testee", f"{sys.executable} {MUTANT_TESTEE} position_lat_lon_swapped",
                 "--filter", "broadcast.a3-fw3.1.single.position", "--quiet")
    assert proc.returncode == 1, proc.stdout
    assert "DOES NOT CONFORM" in proc.stdout and "latitude" in proc.stdout


def test_usage_errors():
    proc = osdkc("selftest", "--mutant", "no_such_mutant", "--no-baseline")
    assert proc.returncode == 2 and "no mutant" in proc.stderr
    listing = osdkc("selftest", "--list")
    assert listing.returncode == 0 and all(name in listing.stdout for name in REQUIRED)
    bad = subprocess.run([sys.executable, str(MUTANT_TESTEE), "no_such_mutant"], capture_output=True, text=True)
    assert bad.returncode == 2
