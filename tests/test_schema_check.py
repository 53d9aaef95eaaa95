"""The compiled schema validator only ever speeds up a check: whatever it
says, the answer and the messages are jsonschema's (core/schema_check.py)."""
from __future__ import annotations

import copy
import json
import random

import pytest
from jsonschema import Draft202012Validator

from osdk_conformance.core.schema_check import SchemaCheck
from osdk_conformance.harness import response_schema as rs
from osdk_conformance.harness.vectors import SCHEMA_PATH, VECTORS_DIR, load_cases, suite_files


def messages(errors) -> list[str]:
    return sorted(f"{list(e.absolute_path)} {e.message}" for e in errors)


@pytest.fixture(scope="module")
def vector_check() -> tuple[SchemaCheck, Draft202012Validator]:
    schema = json.loads(SCHEMA_PATH.read_text())
    return SchemaCheck(schema), Draft202012Validator(schema)


def _small(doc: dict, rng: random.Random, groups: int = 3, tests: int = 4) -> dict:
    """The document with a few of its groups, each with a few of its cases:
    valid for the same reasons, and quick for jsonschema to go through."""
    picked = []
    for g in rng.sample(doc["testGroups"], min(groups, len(doc["testGroups"]))):
        few = rng.sample(g["tests"], min(tests, len(g["tests"])))
        picked.append(copy.deepcopy({**g, "tests": few}))
    return {**copy.deepcopy({k: v for k, v in doc.items() if k != "testGroups"}), "testGroups": picked,
            "numberOfTests": sum(len(g["tests"]) for g in picked)}


@pytest.fixture(scope="module")
def documents() -> list[dict]:
    return [json.loads(p.read_text()) for p in suite_files(VECTORS_DIR)]


def test_every_vector_file_is_valid_for_both(vector_check, documents):
    fast, authority = vector_check
    rng = random.Random(3)
    for doc in documents:
        assert fast.is_valid(doc), doc["suite"]   # whole: what `osdkc vectors check` does
        for _ in range(5):                        # jsonschema agrees on samples of it (whole would take a minute)
            assert authority.is_valid(_small(doc, rng)), doc["suite"]


def _broken(doc: dict, rng: random.Random) -> dict:
    """The document with one case damaged in one of the ways a hand edit or a bad generator damages it."""
    group = rng.choice(doc["testGroups"])
    case = rng.choice(group["tests"])
    key = rng.choice(sorted(case))
    how = rng.randrange(5)
    if how == 0:
        del case[key]
    elif how == 1:
        case[key] = [case[key]]
    elif how == 2:
        case["unknown_field"] = 1
    elif how == 3:
        case[key] = None
    else:
        case[key] = str(case[key]) + "\n"
    return doc


@pytest.mark.slow
def test_damaged_vector_files_get_jsonschemas_verdict_and_messages(vector_check, documents):
    fast, authority = vector_check
    rng = random.Random(7)
    for _ in range(200):
        bad = _broken(_small(rng.choice(documents), rng), rng)
        assert fast.is_valid(bad) == authority.is_valid(bad)
        assert messages(fast.iter_errors(bad)) == messages(authority.iter_errors(bad))


def test_responses_the_compiled_validator_cannot_take_go_to_jsonschema():
    check = rs.validator("classify_control_mode", None)
    for response in ({"ok": True, "result": float("nan")}, {"ok": True, "result": {"x": 2 ** 200}},
                     {"ok": float("inf")}):
        want = rs.validator("classify_control_mode", None).authority.is_valid(response)
        assert check.is_valid(response) == want
        assert bool(list(check.iter_errors(response))) == (not want)


@pytest.mark.slow
def test_every_expected_answer_and_broken_ones_agree_with_jsonschema():
    rng = random.Random(11)
    cases = load_cases()
    for case in rng.sample(cases, 150):
        check = rs.validator(case.operation, case.profile)
        if check is None:
            continue
        good = {"ok": True, "result": case.expected} if "error" not in case.expected else \
            {"ok": False, **case.expected}
        for response in (good, {"ok": True, "result": {"surplus": True}}, {"ok": "yes"}, {**good, "extra": 1}):
            assert check.is_valid(response) == check.authority.is_valid(response), (case.id, response)
            assert messages(check.iter_errors(response)) == messages(check.authority.iter_errors(response))
