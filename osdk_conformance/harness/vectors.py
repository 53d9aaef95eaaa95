"""The golden vectors: loading them, comparing answers with them, checking them.

The file format is vectors/FORMAT.md (schema: vectors/vectors.schema.json);
tools/gen_vectors.py writes the files. These functions are the interface the
runner uses:

`load_cases(paths=None) -> list[Case]`
    Every case of the given vector files (default: every suite file in
    vectors/), in file order. A Case has `file` (the file name), `operation`
    and `profile` (from its group; profile is None for the operations that
    take none), `id`, `category`, `comment`, `input`, `result` ("valid",
    "invalid" or "acceptable"), `expected` and `flags`. `Case.request()`
    builds the protocol request line for it. Raises VectorFileError (a
    UsageError: `osdkc` exits 2 with its message) when a file cannot be
    read, is not JSON, or lacks the parts a case needs.

`load_checked_cases(paths=None) -> list[Case]`
    The same, every file validated as `osdkc vectors check` validates it
    (`document_cases`: schema and numberOfTests; `case_problems`: ids unique
    across all the files, known flags); what `osdkc run` loads. Raises
    VectorFileError naming the first problem.

`compare(case, response) -> (passed, reason)`
    Whether a testee's response object passes the case, per FORMAT.md:
    - valid: `ok` is true and `result` equals `expected`;
    - invalid: `ok` is false and `error` equals `expected["error"]`;
    - acceptable: either `ok` true and `result` equals `expected["value"]`,
      or `ok` false and `error` equals `expected["error"]`.
    Equality is structural and strict about types (a boolean is not a
    number, 1 is 1.0 is fine only as numbers), except that a float model
    ({"f32": ...} / {"f64": ...}) is compared by its IEEE bits alone, so
    "value" never matters and every NaN payload counts. For decode_stream
    only the event fields PROTOCOL.md names are compared: `kind` and
    `offset` of every event, `error` and `length` of errors, `length` of
    garbage, `frame` of frames, and `ack_of`/`ack` of a frame when either
    side has them; other fields (`detail`, `command`, ...) and other keys of
    the result are ignored. `reason` is "" when the
    case passed, else says what differed first and where. A response with
    `unsupported` does not pass; runners are expected to set those cases
    aside before calling compare.

`check()` and `coverage()` are `osdkc vectors check` / `coverage`.
"""
from __future__ import annotations

import argparse
import contextlib
import gc
import hashlib
import json
import re
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Iterable, Sequence

from osdk_conformance.core.commands import ack_code_text
from osdk_conformance.core.errors import UsageError, cannot_read
from osdk_conformance.core.paths import ROOT, SPEC
from osdk_conformance.core.schema_check import SchemaCheck
from osdk_conformance.harness.spec_rules import RULES
from osdk_conformance.harness.vector_tables import tables
from osdk_conformance.reference.codec import BadRequest, answer
from osdk_conformance.traceability.trace import errata_ids

VECTORS_DIR = ROOT / "vectors"
SCHEMA_PATH = VECTORS_DIR / "vectors.schema.json"
MANIFEST_NAME = "MANIFEST.json"
ERRATA_PATH = SPEC / "ERRATA.md"

COMPARED_EVENT_KEYS = {"frame": ("kind", "offset", "frame"), "error": ("kind", "offset", "error", "length"),
                       "garbage": ("kind", "offset", "length")}
"""The fields of a decode_stream event compare() looks at, by kind."""

MATCHED_ACK_KEYS = ("ack_of", "ack")
"""Fields of a frame event that exist only when an ACK was matched (by
session and SEQ) to a command earlier in the stream; compared when present
on either side."""

STORED_EVENT_KEYS = ("kind", "offset", "error", "length", "frame", "command", "ack_of", "ack")
"""The fields of a decode_stream event the vectors record: the compared ones,
plus `command` to show readers what was decoded."""


class VectorFileError(UsageError):
    """A vector file cannot be read or is not a vector file at all."""


def _errata_summary() -> dict[str, str]:
    try:
        text = ERRATA_PATH.read_text(encoding="utf-8")
    except OSError:
        return {}
    return dict(re.findall(r"^\| (E\d\d) \| (.+?) \|$", text, flags=re.M))


ERRATA_SUMMARY = _errata_summary()


# ----------------------------------------------------------------- cases


@dataclass(frozen=True)
class Case:
    file: str
    operation: str
    profile: str | None
    id: str
    category: str
    comment: str
    input: dict
    result: str
    expected: dict
    flags: tuple[str, ...]

    def request(self) -> dict:
        """The protocol request line for this case."""
        req: dict[str, Any] = {"op": self.operation, "id": self.id}
        if self.profile is not None:
            req["profile"] = self.profile
        req.update(self.input)
        return req


def suite_files(directory: Path = VECTORS_DIR) -> list[Path]:
    """The suite files of a vectors directory (every *.json but the manifest and schema)."""
    return sorted(p for p in directory.glob("*.json") if p.name != MANIFEST_NAME and not p.name.endswith(".schema.json"))


def read_json(path: Path) -> Any:
    return parse_json(_read_bytes(path), path)


def _read_bytes(path: Path) -> bytes:
    try:
        return path.read_bytes()
    except OSError as e:
        raise VectorFileError(cannot_read(path, e)) from None


def parse_json(raw: bytes, path: Path) -> Any:
    """The JSON document in `raw` (read from `path`, for messages)."""
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as e:
        raise VectorFileError(f"{path} is not UTF-8: {e}") from None
    try:
        return json.loads(text, parse_constant=_no_constant)
    except (json.JSONDecodeError, ValueError) as e:
        raise VectorFileError(f"{path} is not valid JSON: {e}") from None


def _no_constant(name: str) -> Any:
    raise ValueError(f"bare {name} is not JSON")


def cases_of(doc: Any, file: str) -> list[Case]:
    """The cases of one parsed vector file."""
    out = []
    try:
        for group in doc["testGroups"]:
            for t in group["tests"]:
                out.append(Case(file=file, operation=group["operation"], profile=group.get("profile"), id=t["id"],
                                category=t["category"], comment=t["comment"], input=t["input"], result=t["result"],
                                expected=t["expected"], flags=tuple(t["flags"])))
    except (KeyError, TypeError) as e:
        raise VectorFileError(f"{file}: not a vector file (missing or wrong part: {e})") from None
    return out


@contextlib.contextmanager
def _no_cycle_collection():
    """The cycle collector off while the vectors are parsed, as it was after.

    The shipped suites parse into some three million dicts, lists and
    strings, which cannot form cycles (JSON trees and frozen Cases of them;
    reference counting frees them). With the collector on, the allocations
    set off collections that walk everything parsed so far again and again:
    about half of the 1.8 s of CPU a load costs, paid by every `osdkc run`,
    selftest and API process and every test module that loads the vectors."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()


def load_cases(paths: Iterable[str | Path] | None = None) -> list[Case]:
    """Every case of the given files (default: every suite file in vectors/)."""
    files = [Path(p) for p in paths] if paths is not None else suite_files()
    if paths is None and not files:
        raise VectorFileError(f"no vector files in {VECTORS_DIR}")
    out: list[Case] = []
    with _no_cycle_collection():
        for path in files:
            out += cases_of(read_json(path), path.name)
    return out


# ----------------------------------------------------------------- comparing


def _is_float_model(v: Any) -> bool:
    return isinstance(v, dict) and ("f32" in v or "f64" in v)


def _float_key(v: dict) -> tuple[str, int] | None:
    key = "f32" if "f32" in v else "f64"
    try:
        return key, int(v[key], 16)
    except (TypeError, ValueError):
        return None


def _kind(v: Any) -> str:
    if isinstance(v, bool):
        return "boolean"
    if isinstance(v, (int, float)):
        return "number"
    if v is None:
        return "null"
    return {dict: "object", list: "array", str: "string"}.get(type(v), type(v).__name__)


def _short(v: Any) -> str:
    text = json.dumps(v, sort_keys=True, default=str)
    return text if len(text) <= 80 else text[:77] + "..."


def _ack_code_shown(v: Any) -> str:
    """An ACK code (enum model or number) as messages show it: "0xFF01 not_activated"."""

    if isinstance(v, dict) and isinstance(v.get("value"), int) and not isinstance(v["value"], bool):
        return ack_code_text(v["value"]) + (f" {v['name']}" if isinstance(v.get("name"), str) else "")
    if isinstance(v, int) and not isinstance(v, bool):
        return ack_code_text(v)
    return _short(v)


def _same(expected: Any, got: Any) -> bool:
    """True only where _value_difference finds no difference: the common case
    (a passing answer) decided without building a path for every value."""
    kind = type(expected)
    if kind is dict:
        if type(got) is not dict or len(got) != len(expected):
            return False
        if "f32" in expected or "f64" in expected:
            return expected == got  # hex strings equal as text are equal as bits
        for key, value in expected.items():
            if key not in got or not _same(value, got[key]):
                return False
        return True
    if kind is list:
        return type(got) is list and len(got) == len(expected) and all(map(_same, expected, got))
    if kind is str or kind is bool:
        return type(got) is kind and expected == got
    if kind is int or kind is float:
        return (type(got) is int or type(got) is float) and expected == got
    return expected is None and got is None


def difference(expected: Any, got: Any, path: str = "result") -> str | None:
    """Where `got` first differs from `expected` (float models by bits), or None."""
    if _same(expected, got):
        return None
    d = _value_difference(expected, got, path)
    if d is not None and path.endswith(".ack_code") and _kind(expected) == _kind(got):
        return f"{path}: expected {_ack_code_shown(expected)}, got {_ack_code_shown(got)}"
    return d


def _value_difference(expected: Any, got: Any, path: str) -> str | None:
    if _is_float_model(expected):
        if not _is_float_model(got):
            return f"{path}: expected a float {_short(expected)}, got {_short(got)}"
        want, have = _float_key(expected), _float_key(got)
        if have is None or want != have:
            return f"{path}: expected {want[0]} {expected[want[0]]}, got {_short(got)}"
        return None
    if _kind(expected) != _kind(got):
        return f"{path}: expected {_kind(expected)} {_short(expected)}, got {_kind(got)} {_short(got)}"
    if isinstance(expected, dict):
        missing = [k for k in expected if k not in got]
        if missing:
            return f"{path}: missing {', '.join(sorted(missing))}"
        extra = [k for k in got if k not in expected]
        if extra:
            return f"{path}: unexpected {', '.join(sorted(extra))}"
        for k in expected:
            d = difference(expected[k], got[k], f"{path}.{k}")
            if d:
                return d
        return None
    if isinstance(expected, list):
        if len(expected) != len(got):
            return f"{path}: expected {len(expected)} items, got {len(got)}"
        for i, (e, g) in enumerate(zip(expected, got)):
            d = difference(e, g, f"{path}[{i}]")
            if d:
                return d
        return None
    if expected != got:
        return f"{path}: expected {_short(expected)}, got {_short(got)}"
    return None


def _stream_difference(expected: dict, got: Any) -> str | None:
    if not isinstance(got, dict) or not isinstance(got.get("events"), list):
        return f"result: expected {{\"events\": [...]}}, got {_short(got)}"
    want, have = expected["events"], got["events"]
    for i, (e, g) in enumerate(zip(want, have)):
        if not isinstance(g, dict):
            return f"result.events[{i}]: not an object: {_short(g)}"
        keys = COMPARED_EVENT_KEYS.get(e["kind"], ("kind", "offset"))
        for k in keys:
            if k not in g:
                return f"result.events[{i}] ({e['kind']} at {e['offset']}): missing {k}"
            d = difference(e.get(k), g[k], f"result.events[{i}].{k}")
            if d:
                return d
        for k in MATCHED_ACK_KEYS:  # present exactly when the ACK was matched to its command
            if (k in e) != (k in g):
                return (f"result.events[{i}] ({e['kind']} at {e['offset']}): "
                        + (f"missing {k} (the ACK answers a command earlier in the stream)" if k in e
                           else f"unexpected {k} (no command in the stream matches this ACK)"))
            if k in e:
                d = difference(e[k], g[k], f"result.events[{i}].{k}")
                if d:
                    return d
    if len(want) != len(have):
        return (f"result.events: expected {len(want)} events, got {len(have)}"
                + (f"; first extra: {_short(have[len(want)])}" if len(have) > len(want) else
                   f"; first missing: {_short(want[len(have)])}"))
    return None


def _result_difference(case: Case, expected: Any, result: Any) -> str | None:
    if case.operation == "decode_stream":
        return _stream_difference(expected, result)
    return difference(expected, result)


def compare(case: Case, response: Any) -> tuple[bool, str]:
    """(passed, reason) of a testee's response to `case` (see the module doc)."""
    if not isinstance(response, dict) or not isinstance(response.get("ok"), bool):
        if isinstance(response, dict) and response.get("unsupported") is True:
            return False, "the testee does not support this case"
        return False, f"not a response object: {_short(response)}"
    if response.get("unsupported") is True:
        return False, "the testee does not support this case"
    exp = case.expected
    if response["ok"]:
        if "result" not in response:
            return False, "ok response without a result"
        if case.result == "invalid":
            return False, f"accepted; expected the error {exp['error']}"
        want = exp["value"] if case.result == "acceptable" else exp
        d = _result_difference(case, want, response["result"])
        return (False, d) if d else (True, "")
    if case.result == "valid":
        return False, f"rejected with {response.get('error')!r} ({response.get('detail', '')}); expected a result"
    if response.get("error") != exp["error"]:
        return False, f"error {response.get('error')!r}, expected {exp['error']!r}"
    return True, ""


def compared_answers(operation: str, result: str, expected: dict, response: Any) -> tuple[dict, dict] | None:
    """The answer a case expects and the testee's, cut down to what compare()
    looks at (`ok`, then `result` or `error`; for decode_stream the compared
    fields of each event), for a report to show side by side. None when
    the response is no response object (nothing to line up)."""
    if not isinstance(response, dict) or not isinstance(response.get("ok"), bool):
        return None
    if response["ok"]:
        got = {"ok": True, "result": response["result"]} if "result" in response else {"ok": True}
    else:
        got = {"ok": False, "error": response.get("error")}
    if result == "invalid" or (result == "acceptable" and not response["ok"]):
        return {"ok": False, "error": expected.get("error")}, got
    want = expected.get("value") if result == "acceptable" else expected
    if operation == "decode_stream" and isinstance(want, dict) and isinstance(got.get("result"), dict):
        want, got["result"] = _compared_events(want, got["result"])
    return {"ok": True, "result": want}, got


def _compared_events(want: dict, got: dict) -> tuple[dict, dict]:
    """Both streams' events with only the fields _stream_difference compares
    (those of the expected event's kind at the same index, and a matched
    ACK's fields); other keys of the result are not compared either."""
    w, g = want.get("events"), got.get("events")
    if not isinstance(w, list) or not isinstance(g, list):
        return want, got

    def cut(ev: Any, like: Any) -> Any:
        if not isinstance(ev, dict):
            return ev
        kind = like.get("kind") if isinstance(like, dict) else ev.get("kind")
        keys = COMPARED_EVENT_KEYS.get(kind, ("kind", "offset")) + MATCHED_ACK_KEYS
        return {k: ev[k] for k in keys if k in ev}

    return ({"events": [cut(e, e) for e in w]},
            {"events": [cut(e, w[i] if i < len(w) else e) for i, e in enumerate(g)]})


# ----------------------------------------------------------------- writing (for the generator)


def project_event(ev: dict) -> dict:
    return {k: ev[k] for k in STORED_EVENT_KEYS if k in ev}


def project_result(operation: str, result: dict) -> dict:
    """A successful result as the vectors record it (decode_stream events trimmed to STORED_EVENT_KEYS)."""
    if operation == "decode_stream":
        return {"events": [project_event(e) for e in result["events"]]}
    return result


def canonical(value: Any) -> str:
    return json.dumps(value, sort_keys=True, allow_nan=False, ensure_ascii=False)


def same_json(a: Any, b: Any) -> bool:
    """Equal as JSON text (so True is not 1 and 1.0 is not 1, unlike ==)."""
    return canonical(a) == canonical(b)


def dump_suite(doc: dict) -> str:
    """A suite document as text: header and groups indented, one test per line, sorted keys."""
    groups = doc["testGroups"]
    head = {k: v for k, v in doc.items() if k != "testGroups"}
    lines = ["{"]
    for k in sorted(head):
        lines.append(f' {json.dumps(k)}: {json.dumps(head[k], indent=1, sort_keys=True, allow_nan=False, ensure_ascii=False).replace(chr(10), chr(10) + " ")},')
    lines.append(' "testGroups": [')
    for gi, g in enumerate(groups):
        lines.append("  {")
        lines.append(f'   "operation": {json.dumps(g["operation"])},')
        lines.append(f'   "profile": {json.dumps(g["profile"])},')
        lines.append('   "tests": [')
        tests = g["tests"]
        for ti, t in enumerate(tests):
            lines.append("    " + json.dumps(t, sort_keys=True, allow_nan=False, ensure_ascii=False, separators=(",", ":"))
                         + ("," if ti < len(tests) - 1 else ""))
        lines.append("   ]")
        lines.append("  }" + ("," if gi < len(groups) - 1 else ""))
    lines.append(" ]")
    lines.append("}")
    return "\n".join(lines) + "\n"


def manifest_text(hashes: dict[str, str]) -> str:
    return json.dumps(dict(sorted(hashes.items())), indent=1, sort_keys=True) + "\n"


# ----------------------------------------------------------------- check and coverage


@dataclass
class CheckReport:
    files: int = 0
    cases: int = 0
    problems: list[str] | None = None

    def __post_init__(self) -> None:
        self.problems = [] if self.problems is None else self.problems


def _validator() -> SchemaCheck:
    schema = read_json(SCHEMA_PATH)
    check = SchemaCheck(schema)
    problem = check.schema_problem()
    if problem:  # a broken schema is a problem of the kit, reported without a traceback
        raise VectorFileError(f"{SCHEMA_PATH} is not a valid JSON Schema: {problem}")
    return check


def known_flags() -> tuple[set[str], set[str]]:
    return set(RULES), errata_ids(ERRATA_PATH)


def spec_difference(case: Case) -> str | None:
    """How the reference's answer today differs from the case's expectation, or None."""

    try:
        ref = answer(case.operation, case.profile, case.input)
    except BadRequest as e:
        return f"the reference refuses the input: {e}"
    except Exception as e:  # noqa: BLE001 - a crash of the reference is a finding about this case
        return f"the reference crashed: {type(e).__name__}: {e}"
    if ref.get("unsupported"):
        return "the reference does not support this operation/profile"
    if case.result == "valid":
        if not ref["ok"]:
            return f"the spec now rejects it with {ref['error']} ({ref['detail']})"
        got = project_result(case.operation, ref["result"])
        if not same_json(got, case.expected):
            return difference(case.expected, got) or "differs in float \"value\" text or number types"
        return None
    if case.result == "invalid":
        if ref["ok"]:
            return f"the spec now accepts it (expected {case.expected['error']})"
        if ref["error"] != case.expected["error"]:
            return f"the spec now answers {ref['error']}, expected {case.expected['error']}"
        return None
    passed, reason = compare(case, ref)
    return None if passed else reason


def document_cases(doc: Any, name: str, validator) -> tuple[list[Case] | None, list[str]]:
    """The cases of one parsed vector file and its problems: schema (the
    cases are None when the schema rejects the file) and numberOfTests."""
    errors = sorted(validator.iter_errors(doc), key=lambda e: list(map(str, e.absolute_path)))
    problems = [f"{name}: schema: {'/'.join(map(str, e.absolute_path)) or '(top)'}: {e.message[:200]}"
                for e in errors[:10]]
    if len(errors) > 10:
        problems.append(f"{name}: schema: ... and {len(errors) - 10} more")
    if errors:
        return None, problems
    cases = cases_of(doc, name)
    if doc["numberOfTests"] != len(cases):
        problems.append(f"{name}: numberOfTests is {doc['numberOfTests']}, the file has {len(cases)} tests")
    return cases, problems


def case_problems(cases: Iterable[Case], seen: dict[str, str], rules: set[str], errata: set[str]) -> list[str]:
    """Ids unique across files (`seen`: id -> file name, updated here) and
    flags that name a known rule or errata entry."""
    problems = []
    for case in cases:
        if case.id in seen:
            problems.append(f"{case.file}: id {case.id} also in {seen[case.id]}")
        seen[case.id] = case.file
        for f in case.flags:
            if f.startswith("rule:") and f[5:] not in rules:
                problems.append(f"{case.id}: unknown rule {f}")
            elif not f.startswith("rule:") and f not in errata:
                problems.append(f"{case.id}: unknown errata id {f}")
    return problems


def _manifest_digests(directory: Path = VECTORS_DIR) -> set[str]:
    try:
        manifest = json.loads((directory / MANIFEST_NAME).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return set()
    return {v for v in manifest.values() if isinstance(v, str)} if isinstance(manifest, dict) else set()


def load_checked_cases(paths: Iterable[str | Path] | None = None) -> list[Case]:
    """`load_cases`, but every file validated as `osdkc vectors check` does
    (schema, numberOfTests, ids unique across all the files, known flags);
    VectorFileError naming the first problem otherwise. A file whose SHA-256
    vectors/MANIFEST.json lists is one tools/gen_vectors.py wrote and
    `vectors check` guards: its schema pass (17 s for the shipped suites) is
    skipped, the id and flag checks are not."""
    files = [Path(p) for p in paths] if paths is not None else suite_files()
    if not files:
        raise VectorFileError(f"no vector files in {VECTORS_DIR}")
    trusted = _manifest_digests()
    validator = None
    problems: list[str] = []
    out: list[Case] = []
    given: set[Path] = set()
    with _no_cycle_collection():  # see load_cases
        for path in files:
            if path.resolve() in given:
                problems.append(f"{path}: given twice")
                continue
            given.add(path.resolve())
            raw = _read_bytes(path)
            doc = parse_json(raw, path)
            if hashlib.sha256(raw).hexdigest() in trusted:
                cases, file_problems = cases_of(doc, path.name), []
            else:
                validator = validator or _validator()
                cases, file_problems = document_cases(doc, path.name, validator)
            problems += file_problems
            out += cases or []
        rules, errata = known_flags()
        problems += case_problems(out, {}, rules, errata)
    if problems:
        more = f" (and {len(problems) - 1} more problems)" if len(problems) > 1 else ""
        raise VectorFileError(f"bad vector files: {problems[0]}{more}")
    return out


def check(directory: Path = VECTORS_DIR, spec: bool = True, out=sys.stdout) -> int:
    """`osdkc vectors check`: 0 all good, 1 problems; VectorFileError for unreadable files."""
    report = CheckReport()
    problems = report.problems
    validator = _validator()
    manifest_path = directory / MANIFEST_NAME
    manifest = read_json(manifest_path)
    files = suite_files(directory)
    if not isinstance(manifest, dict):
        problems.append(f"{MANIFEST_NAME}: not an object of file -> sha256")
        manifest = {}
    for name in sorted(set(manifest) - {p.name for p in files}):
        problems.append(f"{MANIFEST_NAME}: lists {name}, which is not there")
    rules, errata = known_flags()
    seen: dict[str, str] = {}
    for path in files:
        report.files += 1
        raw = _read_bytes(path)
        digest = hashlib.sha256(raw).hexdigest()
        if path.name not in manifest:
            problems.append(f"{path.name}: not in {MANIFEST_NAME}")
        elif manifest[path.name] != digest:
            problems.append(f"{path.name}: SHA-256 {digest[:16]}... differs from {MANIFEST_NAME} "
                            f"({str(manifest[path.name])[:16]}...): the file was changed after generation")
        with _no_cycle_collection():  # see load_cases
            cases, file_problems = document_cases(parse_json(raw, path), path.name, validator)
        problems += file_problems
        if cases is None:
            continue
        report.cases += len(cases)
        problems += case_problems(cases, seen, rules, errata)
        for case in cases if spec else ():
            d = spec_difference(case)
            if d:
                problems.append(f"{case.id}: no longer matches the spec: {d}")
    shown = problems[:50]
    for p in shown:
        print(f"  FAIL  {p}", file=out)
    if len(problems) > len(shown):
        print(f"  ... and {len(problems) - len(shown)} more problems", file=out)
    what = "schema, manifest, ids, flags" + (", reference answers" if spec else "")
    if problems:
        print(f"vectors check: {len(problems)} problem(s) in {report.files} files, {report.cases} cases ({what})", file=out)
        return 1
    print(f"vectors check: OK, {report.files} files, {report.cases} cases ({what})", file=out)
    return 0


def coverage_counts(cases: list[Case]) -> tuple[dict[str, int], dict[str, int]]:
    rules, errata = known_flags()
    by_rule = {r: 0 for r in rules}
    by_errata = {e: 0 for e in sorted(errata, key=lambda s: int(s[1:]))}
    for c in cases:
        for f in set(c.flags):
            if f.startswith("rule:") and f[5:] in by_rule:
                by_rule[f[5:]] += 1
            elif f in by_errata:
                by_errata[f] += 1
    return by_rule, by_errata


def coverage(directory: Path = VECTORS_DIR, out=sys.stdout) -> int:
    """`osdkc vectors coverage`: cases per rule and errata id, then one table
    per bug class of osdk_conformance.harness.vector_tables; 1 when a rule or errata
    entry has no case or a table has a hole."""

    cases = load_cases(suite_files(directory))
    by_rule, by_errata = coverage_counts(cases)
    width = max(len(r) for r in RULES) + 5
    print(f"{'rule / errata':<{width}} {'cases':>6}", file=out)
    for name in RULES:
        print(f"{'rule:' + name:<{width}} {by_rule[name]:>6}" + ("   UNPINNED" if not by_rule[name] else ""), file=out)
    for eid, n in by_errata.items():
        summary = ERRATA_SUMMARY.get(eid, "")
        print(f"{eid:<{width}} {n:>6}" + ("   UNPINNED" if not n else f"   {summary[:70]}"), file=out)
    holes, class_tables = [], tables(cases)
    for table in class_tables:
        print("", *table.lines(), sep="\n", file=out)
        holes += [f"{table.title}: {h}" for h in table.holes]
    unpinned = [k for k, n in {**{f"rule:{r}": n for r, n in by_rule.items()}, **by_errata}.items() if not n]
    if holes:
        print(f"vectors coverage: {len(holes)} hole(s): {'; '.join(holes)}", file=out)
    if unpinned:
        print(f"vectors coverage: {len(unpinned)} unpinned: {', '.join(unpinned)}", file=out)
    if holes or unpinned:
        return 1
    print(f"vectors coverage: OK, {len(by_rule)} rules and {len(by_errata)} errata entries pinned, no hole in "
          f"the {len(class_tables)} bug-class tables, {len(cases)} cases", file=out)
    return 0


def add_check_arguments(p: argparse.ArgumentParser, profiles: Sequence[str] = ()) -> None:
    p.add_argument("--dir", help="the vectors directory (default: vectors/)")
    p.add_argument("--no-spec", action="store_true", help="skip re-running the reference on every case")


def add_coverage_arguments(p: argparse.ArgumentParser, profiles: Sequence[str] = ()) -> None:
    p.add_argument("--dir", help="the vectors directory (default: vectors/)")


def run_vectors(args: argparse.Namespace) -> int:
    directory = Path(args.dir) if getattr(args, "dir", None) else VECTORS_DIR
    if not directory.is_dir():
        raise VectorFileError(f"{directory}: not a directory")
    if args.vectors_command == "check":
        return check(directory, spec=not args.no_spec)
    return coverage(directory)
