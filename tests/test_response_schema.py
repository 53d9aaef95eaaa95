"""conformance/schemas/: the published JSON Schemas of every request and
response, and the runner's check of testee responses against them.

Sound: every expected result and error of every vector, every request the
runner sends, and the responses of the two Python bundled testees validate.
Complete enough: responses that are wrong in shape (unknown field, misspelt
enum name, error class not in the list, wrong type, an item the flag word
does not announce) are rejected, and the runner reports them as their own
failure kind, `schema_violation`.
"""
from __future__ import annotations

import copy
import importlib.util
import json
import re
import subprocess
import sys
from pathlib import Path

import pytest
from jsonschema import Draft202012Validator

from osdk_conformance.harness import response_schema as rs
from osdk_conformance.reference.codec import OPERATIONS
from osdk_conformance.harness.runner import BUNDLED_IMPLS, judge, request_of
from osdk_conformance.harness import testee as supervision
from osdk_conformance.harness.vectors import compare, load_cases

ROOT = Path(__file__).resolve().parents[1]


def _tool():
    spec = importlib.util.spec_from_file_location("gen_schemas_tool", ROOT / "tools" / "gen_schemas.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def cases():
    return load_cases()


def expected_responses(case) -> list[dict]:
    """The responses a vector case allows."""
    if case.result == "valid":
        return [{"ok": True, "result": case.expected}]
    if case.result == "invalid":
        return [{"ok": False, "error": case.expected["error"], "detail": "why"}]
    return [{"ok": True, "result": case.expected["value"]},
            {"ok": False, "error": case.expected["error"], "detail": "why"}]


# ---- the schema files ------------------------------------------------------------

def test_schema_files_are_2020_12_schemas_with_unique_ids():
    ids = set()
    files = sorted(rs.SCHEMA_DIR.glob("*.schema.json"))
    assert {f.name for f in files} >= {f"{op}.schema.json" for op in OPERATIONS}
    for path in files:
        doc = json.loads(path.read_text())
        assert doc["$schema"] == "https://json-schema.org/draft/2020-12/schema", path.name
        Draft202012Validator.check_schema(doc)
        assert doc["$id"] == rs.BASE_URI + path.name
        ids.add(doc["$id"])
    assert len(ids) == len(files)


def test_schema_files_are_what_the_spec_generates(capsys):
    assert _tool().main(["--check"]) == 0, capsys.readouterr().err


# (module attribute of tools/gen_schemas.py naming the document, (a generated line, a hand edit of it),
#  a region of the document)
GENERATED_DOCS = [
    ("NAMING", ("| `a3-fw3.1` | `a3_fw3_1` | 2 |", "| `a3-fw3.1` | `a3_fw3_1` | 3 |"), "profiles"),
    ("PROTOCOL", ("| 13 | (reserved) | (reserved) | control_info |", "| 13 | (reserved) | (reserved) | (reserved) |"),
     "flag_bits"),
]


def _mentions(text: str, name: str) -> bool:
    return re.search(rf"(?<![\w-]){re.escape(name)}(?![\w-])", text) is not None


@pytest.mark.parametrize("doc, edit, region", GENERATED_DOCS, ids=[d for d, _, _ in GENERATED_DOCS])
def test_doc_parts_restating_the_spec_are_generated_and_checked(doc, edit, region, tmp_path, monkeypatch, capsys):
    tool = _tool()
    text = getattr(tool, doc).read_text()
    # every profile and broadcast item of the rules is in a generated part
    parts = "".join(m.group("body") for m in tool._REGION.finditer(text))
    r = tool.ValueModel().r
    for name in (*r.profile_names, *r.broadcast_item_names):
        assert _mentions(parts, name), name
    # the generator reads copies of every such document, the one under test hand-edited inside a generated part
    for attr, _, _ in GENERATED_DOCS:
        copy_ = tmp_path / getattr(tool, attr).relative_to(ROOT)
        copy_.parent.mkdir(parents=True, exist_ok=True)
        copy_.write_text(getattr(tool, attr).read_text())
        monkeypatch.setattr(tool, attr, copy_)
    monkeypatch.setattr(tool, "ROOT", tmp_path)
    edited = getattr(tool, doc)
    assert text.count(edit[0]) == 1
    edited.write_text(text.replace(edit[0], edit[1]))
    assert tool.main(["--check"]) == 1
    err = capsys.readouterr().err
    name = str(edited.relative_to(tmp_path))
    assert f"differs: the generated parts of {name}" in err
    assert err.count("differs: the generated parts of") == 1, err
    # a lost marker stops the generator instead of leaving a part unwritten
    edited.write_text(text.replace(f"<!-- {region}:end -->", ""))
    with pytest.raises(SystemExit, match=f"{re.escape(name)}: no region '{region}'"):
        tool.main(["--check"])


def test_naming_md_types_no_profile_outside_its_generated_parts():
    tool = _tool()
    # profiles only: an item name may be an enum value name too (`rc` of control_device)
    outside = tool._REGION.sub("", tool.NAMING.read_text())
    for name in tool.ValueModel().r.profile_names:
        assert not _mentions(outside, name), name


def test_every_operation_has_a_request_and_a_response_schema():
    for op in OPERATIONS:
        assert rs.validator(op, "a3-fw3.1", "request") is not None, op
        assert rs.validator(op, "a3-fw3.1", "response") is not None, op


def test_value_model_documents_exactly_the_error_classes():
    text = (ROOT / "docs" / "VALUE-MODEL.md").read_text().split("Error classes:", 1)[1]
    table = set(re.findall(r"^\| `([a-z_0-9]+)` \|", text, re.M))
    assert table == set(rs.ERROR_CLASSES)
    for classes in rs.OPERATION_ERRORS.values():
        assert set(classes) <= set(rs.ERROR_CLASSES)


# ---- sound: what conforms validates ---------------------------------------------------

@pytest.mark.slow  # about 30 s: the broadcast results are large
def test_every_expected_result_and_every_request_validates(cases):
    """Every vector: their allowed responses and the requests the runner
    sends for them. (The runner relies on this to skip re-validating a result
    identical to the expected one.)"""
    bad = []
    for case in cases:
        for response in expected_responses(case):
            if not rs.validator(case.operation, case.profile).is_valid(response):
                bad.append((case.id, rs.violation(case.operation, case.profile, response)))
        if not rs.validator(case.operation, case.profile, "request").is_valid(request_of(case)):
            bad.append((case.id, "request: " + str(rs.violation(case.operation, case.profile, request_of(case),
                                                                 "request"))))
    assert not bad, bad[:5]


@pytest.mark.parametrize("impl", ["construct", "kaitai-python"])
def test_python_bundled_testee_responses_validate(cases, impl):
    """Every 40th vector and every stream case, with the whole response
    validated (no shortcut for results equal to the expected ones)."""
    sample = [c for i, c in enumerate(cases) if i % 40 == 0 or c.operation == "decode_stream"]
    testee = supervision.Testee(BUNDLED_IMPLS[impl], timeout=30)
    testee.start()
    try:
        caps = testee.request({"op": "capabilities"})
        assert rs.violation("capabilities", None, caps) is None
        bad = []
        for case in sample:
            response = testee.request(request_of(case))
            problem = rs.violation(case.operation, case.profile, response)
            if problem:
                bad.append((case.id, problem))
    finally:
        testee.close()
    assert not bad, bad[:5]


# ---- complete enough: what is wrong in shape is rejected --------------------------------

def _first(cases, case_id):
    return next(c for c in cases if c.id == case_id)


def _set(obj, path, value):
    *head, last = path
    for k in head:
        obj = obj[k]
    if value is _DELETE:
        del obj[last]
    else:
        obj[last] = value


_DELETE = object()
WORKED_FRAME = "frames.m100-fw2.3.worked.movement_control"
MODE = "control_mode.a3-fw3.1.0x4b"
BROADCAST = "broadcast.m100-fw2.3.single.time_stamp"

WRONG = [
    # (case, path into the ok response, new value, what is wrong)
    (MODE, ("result", "extra"), 1, "unknown field in a result"),
    (MODE, ("result", "fields", "yaw_logic", "name"), "yaw_rates", "misspelt enum name"),
    (MODE, ("result", "fields", "yaw_logic", "name"), "yaw_ang", "enum name of another value"),
    (MODE, ("result", "fields", "yaw_logic", "value"), 2, "value wider than the bit field"),
    (MODE, ("result", "combination"), None, "documented byte without its combination"),
    (MODE, ("result", "classification"), "documented?", "unknown classification"),
    (MODE, ("result", "fields", "horizontal_logic"), 1, "enum as a bare number"),
    (WORKED_FRAME, ("result", "frame", "seq"), "4660", "number as a string"),
    (WORKED_FRAME, ("result", "frame", "sof"), "AA", "upper-case hex"),
    (WORKED_FRAME, ("result", "frame", "crc32"), _DELETE, "missing field"),
    (WORKED_FRAME, ("result", "frame", "data", "value", "body", "x"), {"f32": "0x3f800000", "value": "NaN"},
     "NaN for a finite float's bits"),
    (WORKED_FRAME, ("result", "frame", "data", "value", "body", "x"), 1.0, "float without its bits"),
    (WORKED_FRAME, ("result", "frame", "data", "ack_value"), "00", "ack_value in a command frame"),
    (BROADCAST, ("result", "value", "data", "quaternion"), {"q0": {"f32": "0x00000000", "value": 0.0}},
     "an item whose flag is not set"),
    (BROADCAST, ("result", "value", "data", "time_stamp", "nano_time"), 5, "FW 3.1 time stamp field in FW 2.3"),
    (BROADCAST, ("result", "value", "data", "reserved_flags"), 1, "reserved flags set in a decoded value"),
    (BROADCAST, ("ok",), "true", "ok as a string"),
]


@pytest.mark.parametrize("case_id,path,value,what", WRONG, ids=[w[3] for w in WRONG])
def test_wrong_results_are_rejected(cases, case_id, path, value, what):
    case = _first(cases, case_id)
    response = {"ok": True, "result": copy.deepcopy(case.expected)}
    assert rs.violation(case.operation, case.profile, response) is None
    _set(response, path, value)
    assert rs.violation(case.operation, case.profile, response), what


@pytest.mark.parametrize("response,what", [
    ({"ok": False, "error": "bad_crc", "detail": "x"}, "error class not in the list"),
    ({"ok": False, "error": "undefined_mode", "detail": "x"}, "error class the operation cannot answer"),
    ({"ok": False, "error": "bad_crc32"}, "error without detail"),
    ({"ok": False, "error": "bad_crc32", "detail": 3}, "detail not a string"),
    ({"ok": False, "unsupported": True, "error": "bad_crc32"}, "unsupported with an error"),
    ({"ok": True}, "ok without a result"),
])
def test_wrong_errors_are_rejected(response, what):
    assert rs.violation("decode_frame", "a3-fw3.1", response), what


def test_bad_request_and_internal_error_are_classes_of_every_operation():
    for op in OPERATIONS:
        for cls in rs.UNIVERSAL_ERRORS:
            assert rs.violation(op, "a3-fw3.1", {"ok": False, "error": cls, "detail": "x"}) is None


# ---- the runner ----------------------------------------------------------------------

def test_runner_judges_a_schema_violation_apart_from_a_mismatch(cases):
    case = _first(cases, MODE)
    right = {"ok": True, "result": copy.deepcopy(case.expected)}
    assert judge(case, right, compare, 0.0).status == "pass"
    extra = copy.deepcopy(right)
    extra["trace"] = "debug"  # equal where compared, but not the published shape
    r = judge(case, extra, compare, 0.0)
    assert (r.status, r.kind) == ("fail", rs.SCHEMA_VIOLATION) and "trace" in r.message
    wrong_value = copy.deepcopy(right)
    wrong_value["result"]["combination"] = 5
    assert judge(case, wrong_value, compare, 0.0).kind == "mismatch"
    misspelt = copy.deepcopy(right)
    misspelt["result"]["classification"] = "Documented"
    r = judge(case, misspelt, compare, 0.0)
    assert r.kind == rs.SCHEMA_VIOLATION and "and:" in r.message  # the value is wrong too: both said


def _run_altered_reference(tmp_path, alter: str):
    """`osdkc run` on the reference answers, each changed by `alter` (Python
    lines run with `req` and `res` in scope), over 16 control-mode cases."""
    testee = tmp_path / "altered_reference_testee.py"
    body = "".join(f"    {line}\n" for line in alter.splitlines())
    testee.write_text(
        "import json, sys\n"
        f"sys.path.insert(0, {str(ROOT)!r})\n"
        "from osdk_conformance.reference.codec import request_answer\n"
        "for line in sys.stdin:\n"
        "    req = json.loads(line)\n"
        "    res = request_answer(req)\n"
        f"{body}"
        "    print(json.dumps(res), flush=True)\n")
    return subprocess.run([sys.executable, "-m", "osdk_conformance.cli", "run", "--testee",
                           f"{sys.executable} {testee}", "--filter", "control_mode.a3-fw3.1.0x4", "--quiet"],
                          capture_output=True, text=True, cwd=ROOT, timeout=120)


@pytest.mark.slow
def test_a_run_reports_schema_violations_in_its_failure_table(tmp_path):
    proc = _run_altered_reference(tmp_path, "if res.get('ok') and 'fields' in res['result']:\n"
                                            "    res['result']['note'] = 'not in the schema'")
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert "schema_violation 16" in proc.stdout, proc.stdout
    assert "[schema_violation]" in proc.stdout and "note" in proc.stdout


# ---- the documents say what the spec says ------------------------------------------------

def test_protocol_md_combination_table_is_the_rules():
    """PROTOCOL.md's table of combinations and input ranges, row by row,
    against rules.yaml for every profile (the ranges must not differ by
    profile, as the page says)."""
    from osdk_conformance.core import rules

    r = rules.default_rules()
    text = (ROOT / "conformance" / "PROTOCOL.md").read_text()
    rows = re.findall(r"^\| (\d+) \| (0x[0-9a-f]{2}) \| `(\w+)` \| `(\w+)` \| `(\w+)` \| ([^|]+) \| ([^|]+) \| ([^|]+) \|$",
                      text, re.M)
    combos = r.data["control_modes"]["combinations"]
    assert len(rows) == len(combos)

    def limits(d):
        if d["min"] is None and d["max"] is None:
            return "unbounded"
        return f"{'unbounded' if d['min'] is None else d['min']}..{'unbounded' if d['max'] is None else d['max']} {d['unit']}"

    for row, c in zip(rows, combos):
        ranges = {tuple(sorted((k, limits(v)) for k, v in c["ranges"][p].items())) for p in r.profile_names}
        assert len(ranges) == 1, c["index"]
        rng = c["ranges"][r.profile_names[0]]
        assert row == (str(c["index"]), f"0x{c['value']:02x}", c["horizontal"], c["vertical"], c["yaw"],
                       limits(rng["horizontal"]), limits(rng["vertical"]), limits(rng["yaw"])), row


@pytest.mark.slow
def test_a_capabilities_answer_that_breaks_its_schema_fails_the_run_but_lets_it_go_on(tmp_path):
    proc = _run_altered_reference(tmp_path, "if req['op'] == 'capabilities':\n    res['result']['version'] = 2")
    assert proc.returncode == 1, proc.stdout + proc.stderr
    assert "schema_violation 1" in proc.stdout and "version" in proc.stdout, proc.stdout
    assert "16 of 16" in proc.stdout or "16 / 16" in proc.stdout, proc.stdout  # the cases still ran and passed
