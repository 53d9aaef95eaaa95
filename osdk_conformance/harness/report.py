"""Reports of a conformance run: terminal summary, JUnit XML, HTML.

Generic over a list of `Result`s (category, id, status, message, details),
so any suite can use them: `osdkc run` over the golden vectors today, the
serial acceptance suite later.

Statuses:
  pass   the case passed
  fail   the case failed (and was not expected to)
  xfail  the case failed and is listed in the failure list (ignored)
  xpass  the case passed but is listed in the failure list (fails the run:
         remove it from the list)
  skip   the case was not run (the implementation does not support it)
  error  the case could not be judged (run aborted, unknown failure-list id)

`details` maps a label to a value shown with the case: a string, or any
JSON value (shown as JSON). The JUnit and HTML writers put every detail of
every non-passing case in the report; nothing is interpreted except the
label `flags` (a list of strings), which is shown as tags.

The HTML page leads with its verdict and the counts, then what failed
(fail, xpass, error, each with its evidence), then anything the caller
puts there (`lead_html`: plots), and only then the run's metadata and the
tables by category. A caller that knows what was compared (`diff`) gets
the expected and the actual value side by side, in one key order, the
differing values marked. In the JUnit XML the skipped cases of a suite
collapse into one testcase per skip reason (its count and a few ids in
the message); the suites' `tests` and `skipped` still count cases.

No Python repr reaches a report: a yes/no value (a detail, a metadata
entry, a JUnit property) is written "yes" or "no", and a metadata entry or
property whose value is None is left out (`value_text`).
"""
from __future__ import annotations

import html
import json
import re
import time
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable, Iterable, Sequence
from xml.etree import ElementTree as ET

PASS, FAIL, XFAIL, XPASS, SKIP, ERROR = "pass", "fail", "xfail", "xpass", "skip", "error"
STATUSES = (PASS, FAIL, XFAIL, XPASS, SKIP, ERROR)
BAD = frozenset({FAIL, XPASS, ERROR})  # statuses that make a run fail


@dataclass
class Result:
    category: str
    id: str
    status: str
    message: str = ""
    details: dict[str, Any] = field(default_factory=dict)
    kind: str = ""  # what sort of failure: e.g. "mismatch", "testee_timeout"; for a skip, why (in a few words)
    seconds: float = 0.0

    def __post_init__(self) -> None:
        if self.status not in STATUSES:
            raise ValueError(f"unknown status {self.status!r}")


def conforms(results: Iterable[Result]) -> bool:
    return not any(r.status in BAD for r in results)


def counts_by_category(results: Iterable[Result]) -> dict[str, Counter]:
    out: dict[str, Counter] = {}
    for r in results:
        out.setdefault(r.category, Counter())[r.status] += 1
    return dict(sorted(out.items()))


def value_text(value: Any) -> str | None:
    """A metadata value or JUnit property as report text: yes/no for a
    boolean, None (left out) for None, never a Python repr."""
    if value is None:
        return None
    if isinstance(value, bool):
        return "yes" if value else "no"
    return str(value)


def detail_text(value: Any) -> str:
    if isinstance(value, str):
        return value
    if value is None or isinstance(value, bool):
        return value_text(value) or "none"
    return json.dumps(value, indent=2, ensure_ascii=False, allow_nan=True, default=str)


def _words(meta: dict[str, Any] | None) -> dict[str, str]:
    """`meta` with every value as report text, None values left out."""
    return {str(k): t for k, v in (meta or {}).items() if (t := value_text(v)) is not None}


# ---- terminal -----------------------------------------------------------------

def summary_table(results: Sequence[Result]) -> str:
    """Plain-text table: one row per category, counts per status, a total row."""
    by_cat = counts_by_category(results)
    total: Counter = Counter()
    for c in by_cat.values():
        total.update(c)
    cols = [s for s in STATUSES if s in (PASS, FAIL, SKIP) or total[s]]
    name_w = max([len("category"), len("total")] + [len(c) for c in by_cat])
    widths = [max(len(s), len(str(total[s]))) for s in cols]
    def row(name: str, c: Counter | None, header: bool = False) -> str:
        cells = [s if header else str(c[s]) for s in cols]  # type: ignore[index]
        return "  ".join([name.ljust(name_w)] + [v.rjust(w) for v, w in zip(cells, widths)])
    lines = [row("category", None, header=True), "-" * len(row("category", None, header=True))]
    lines += [row(cat, c) for cat, c in by_cat.items()]
    lines.append("-" * len(lines[0]))
    lines.append(row("total", total))
    return "\n".join(lines)


# ---- JUnit XML ----------------------------------------------------------------

def _junit_body(r: Result) -> str:
    parts = [r.message] if r.message else []
    for label, value in r.details.items():
        text = ", ".join(value) if label == "flags" and isinstance(value, list) else detail_text(value)
        parts.append(f"{label}:\n{text}" if "\n" in text else f"{label}: {text}")
    return _xml_safe("\n".join(parts))


# The characters _xml_safe replaces: the C0 controls but tab, newline and
# carriage return, and U+FFFE and U+FFFF.
_XML_UNSAFE = re.compile(r"[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]")


def _xml_safe(text: str) -> str:
    """XML 1.0 cannot carry most control characters, even escaped: each
    becomes the text \\xNN. One regular-expression pass (a JUnit report of
    the whole suite has over 100,000 strings, nearly all clean; a Python
    loop over their characters cost a second per run)."""
    return _XML_UNSAFE.sub(lambda m: f"\\x{ord(m.group()):02x}", text)


SKIP_EXAMPLES = 5   # ids named in the testcase that stands for a skip reason's cases


def skip_reason(r: Result) -> str:
    """What groups skipped cases in the JUnit XML: the result's `kind` (why,
    in a few words), else its message."""
    return r.kind or r.message or "skipped"


def _skipped_testcase(suite: ET.Element, cat: str, group: list[Result]) -> None:
    """One testcase for the skipped cases of one reason: a partial testee
    skips tens of thousands, and a testcase each made reports of megabytes
    that said the same thing over and over. A reason with one case keeps
    that case's own name."""
    first = group[0]
    seconds = f"{sum(r.seconds for r in group):.3f}"
    if len(group) == 1:
        tc = ET.SubElement(suite, "testcase", classname=_xml_safe(cat), name=_xml_safe(first.id), time=seconds)
        msg = first.message.splitlines()[0] if first.message else first.status
        ET.SubElement(tc, "skipped", message=_xml_safe(msg))
        return
    reason, n = skip_reason(first), len(group)
    ids = ", ".join(r.id for r in group[:SKIP_EXAMPLES]) + (", …" if n > SKIP_EXAMPLES else "")
    tc = ET.SubElement(suite, "testcase", classname=_xml_safe(cat), name=_xml_safe(f"{n:,} skipped: {reason}"),
                       time=seconds)
    el = ET.SubElement(tc, "skipped", message=_xml_safe(f"{n:,} skipped ({reason}), e.g. {ids}"))
    lines = [f"{r.id}: {r.message}" for r in group[:SKIP_EXAMPLES]]
    if n > SKIP_EXAMPLES:
        lines.append(f"… and {n - SKIP_EXAMPLES:,} more with the same reason")
    el.text = _xml_safe("\n".join(lines))


def junit_xml(results: Sequence[Result], suite_name: str, properties: dict[str, Any] | None = None) -> bytes:
    """JUnit XML: one <testsuite> per category, one <testcase> per result
    that ran, one per skip reason for those skipped (`_skipped_testcase`),
    `properties` as `value_text` writes them. A suite's `tests` and
    `skipped` count cases, a collapsed testcase standing for its count."""
    properties = _words(properties)
    root = ET.Element("testsuites", name=_xml_safe(suite_name))
    tot = Counter()
    by_cat: dict[str, list[Result]] = {}
    for r in results:
        by_cat.setdefault(r.category, []).append(r)
    for cat in sorted(by_cat):
        rs = by_cat[cat]
        c = Counter(r.status for r in rs)
        failures = c[FAIL] + c[XPASS]
        skipped = c[SKIP] + c[XFAIL]
        suite = ET.SubElement(root, "testsuite", name=_xml_safe(cat), tests=str(len(rs)),
                              failures=str(failures), errors=str(c[ERROR]), skipped=str(skipped),
                              time=f"{sum(r.seconds for r in rs):.3f}")
        if properties:
            props = ET.SubElement(suite, "properties")
            for k, v in properties.items():
                ET.SubElement(props, "property", name=_xml_safe(k), value=_xml_safe(v))
        skip_groups: dict[str, list[Result]] = {}
        for r in rs:
            if r.status == SKIP:
                skip_groups.setdefault(skip_reason(r), []).append(r)
        for r in rs:
            if r.status == SKIP:
                group = skip_groups.pop(skip_reason(r), None)   # written where its first case was
                if group:
                    _skipped_testcase(suite, cat, group)
                continue
            tc = ET.SubElement(suite, "testcase", classname=_xml_safe(cat), name=_xml_safe(r.id),
                               time=f"{r.seconds:.3f}")
            msg = _xml_safe(r.message.splitlines()[0] if r.message else r.status)
            if r.status == FAIL:
                el = ET.SubElement(tc, "failure", message=msg, type=_xml_safe(r.kind or "failure"))
                el.text = _junit_body(r)
            elif r.status == XPASS:
                el = ET.SubElement(tc, "failure", message=msg, type="unexpected_pass")
                el.text = _junit_body(r)
            elif r.status == ERROR:
                el = ET.SubElement(tc, "error", message=msg, type=_xml_safe(r.kind or "error"))
                el.text = _junit_body(r)
            elif r.status == XFAIL:
                el = ET.SubElement(tc, "skipped", message=_xml_safe("expected failure (in the failure list): "
                                                                  + (r.message or "")))
                el.text = _junit_body(r)
        tot.update(tests=len(rs), failures=failures, errors=c[ERROR], skipped=skipped)
    for k in ("tests", "failures", "errors", "skipped"):
        root.set(k, str(tot[k]))
    ET.indent(root)
    return ET.tostring(root, encoding="utf-8", xml_declaration=True) + b"\n"


# ---- HTML -----------------------------------------------------------------------

_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Helvetica,Arial,sans-serif;margin:2em;color:#1b1b1b;max-width:80em}
h1{font-size:1.5em} h2{font-size:1.2em;margin-top:2em} h3{font-size:1em;margin:1em 0 .3em}
table{border-collapse:collapse;margin:1em 0} th,td{border:1px solid #ccc;padding:.25em .6em;text-align:right}
th:first-child,td:first-child{text-align:left} thead th{background:#f2f2f2}
td.bad{background:#fde2e2;font-weight:bold} td.good{background:#e3f6e3}
.verdict{font-size:1.2em;font-weight:bold;padding:.5em 1em;display:inline-block;margin-bottom:.3em}
.ok{background:#e3f6e3;color:#145214} .no{background:#fde2e2;color:#8b1414}
p.counts{margin:.2em 0 1em}
details.case{border:1px solid #ddd;margin:.5em 0;padding:.4em .8em;border-radius:4px}
details.case summary{cursor:pointer} .status{font-weight:bold;text-transform:uppercase;font-size:.85em}
.s-fail,.s-xpass,.s-error{color:#8b1414} .s-xfail{color:#8a6d00} .s-pass{color:#145214} .s-skip{color:#555}
pre{background:#f7f7f7;padding:.5em;overflow-x:auto;white-space:pre-wrap;word-break:break-all;margin:.2em 0 .6em}
dt{font-weight:bold;margin-top:.4em} dd{margin-left:1em}
.flag{display:inline-block;background:#e8eefc;border:1px solid #b8c7ee;border-radius:3px;padding:0 .4em;margin:0 .2em .2em 0;font-family:monospace}
.meta td{text-align:left}
table.diff{margin:.2em 0 .6em;font-family:monospace;font-size:.9em;width:100%}
table.diff td,table.diff th{text-align:left;white-space:pre-wrap;word-break:break-all;border:none;
  border-left:1px solid #ddd;padding:0 .8em;vertical-align:top;width:50%}
table.diff mark{background:#ffd43b;color:#000} table.diff td.only{background:#fff3bf}
table.diff .absent{color:#777;font-style:italic}
table.records{margin:.2em 0 .6em;font-size:.9em}
"""

STATUS_WORDS = {FAIL: "failed", XPASS: "passed unexpectedly", ERROR: "errored", PASS: "passed",
                XFAIL: "failed as expected", SKIP: "skipped"}
"""How the counts line names each status, in the order it lists them."""


def _esc(value: Any) -> str:
    return html.escape(str(value), quote=True)


# ---- expected and actual, side by side ---------------------------------------------

_ABSENT = object()   # a key or an item one side of a diff does not have
COMPACT_CHARS = 72   # a value whose JSON is no longer is shown on one line


def _is_float_model(v: Any) -> bool:
    return isinstance(v, dict) and ("f32" in v or "f64" in v)


def _bits(v: dict) -> tuple[str, Any]:
    key = "f32" if "f32" in v else "f64"
    try:
        return key, int(v[key], 16)
    except (TypeError, ValueError):
        return key, v[key]


def same(a: Any, b: Any) -> bool:
    """Equal as the golden vectors are compared: a float model by its bits
    alone (its "value" is for people), numbers by value, a boolean is no
    number, objects and arrays item by item."""
    if _is_float_model(a) or _is_float_model(b):
        return _is_float_model(a) and _is_float_model(b) and _bits(a) == _bits(b)
    if isinstance(a, bool) or isinstance(b, bool):
        return type(a) is type(b) and a == b
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return a == b
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return type(a) is type(b) and a == b


def _json(v: Any, indent: int | None = None) -> str:
    # json.dumps writes a float as repr does: the shortest text that reads back
    # as the same bits, -0.0 included; NaN and infinities of the value model are strings already
    return json.dumps(v, indent=indent, ensure_ascii=False, allow_nan=True, default=str)


def _lines(v: Any) -> list[str]:
    one = _json(v)
    return [one] if len(one) <= COMPACT_CHARS or not isinstance(v, (dict, list)) else _json(v, 2).splitlines()


Row = tuple[str, str, bool]   # expected cell, actual cell (markup), whether only one side has the value


def _diff_rows(e: Any, a: Any, depth: int, key: str) -> tuple[list[Row], int]:
    """Rows aligned line by line, and how many values differ. Objects are
    walked in the expected side's key order, then the keys only the actual
    side has, so both sides list their keys in one order."""
    pad = "  " * depth
    if e is _ABSENT or a is _ABSENT:
        present = [f"{pad}{key}<mark>{_esc(line)}</mark>" if i == 0 else f"{pad}<mark>{_esc(line)}</mark>"
                   for i, line in enumerate(_lines(a if e is _ABSENT else e))]
        gone = [f'{pad}{key}<span class="absent">(absent)</span>'] + [""] * (len(present) - 1)
        pairs = zip(gone, present) if e is _ABSENT else zip(present, gone)
        return [(le, ri, True) for le, ri in pairs], 1
    if same(e, a):   # each side as it was written: 1 and 1.0 compare equal, and both are shown
        return _side_by_side(e, _in_order_of(a, e), pad, key, ""), 0
    if isinstance(e, dict) and isinstance(a, dict) and not (_is_float_model(e) or _is_float_model(a)):
        rows, n = [(f"{pad}{key}{{", f"{pad}{key}{{", False)], 0
        for k in list(e) + [k for k in a if k not in e]:
            sub, m = _diff_rows(e.get(k, _ABSENT), a.get(k, _ABSENT), depth + 1, f"{_esc(_json(k))}: ")
            rows += sub
            n += m
        return rows + [(f"{pad}}}", f"{pad}}}", False)], n
    if isinstance(e, list) and isinstance(a, list):
        rows, n = [(f"{pad}{key}[", f"{pad}{key}[", False)], 0
        for i in range(max(len(e), len(a))):
            sub, m = _diff_rows(e[i] if i < len(e) else _ABSENT, a[i] if i < len(a) else _ABSENT, depth + 1, "")
            rows += sub
            n += m
        return rows + [(f"{pad}]", f"{pad}]", False)], n
    return _side_by_side(e, _in_order_of(a, e), pad, key, "mark"), 1


def _in_order_of(a: Any, e: Any) -> Any:
    """`a` with the keys of its objects in the order `e` has them (its own after)."""
    if isinstance(a, dict) and isinstance(e, dict):
        keys = [k for k in e if k in a] + [k for k in a if k not in e]
        return {k: _in_order_of(a[k], e.get(k)) for k in keys}
    if isinstance(a, list) and isinstance(e, list):
        return [_in_order_of(x, e[i] if i < len(e) else None) for i, x in enumerate(a)]
    return a


def _side_by_side(e: Any, a: Any, pad: str, key: str, tag: str) -> list[Row]:
    """Both values whole, each in its own text, the shorter padded with empty rows."""
    def cells(v: Any) -> list[str]:
        wrap = (lambda t: f"<{tag}>{t}</{tag}>") if tag else (lambda t: t)
        return [f"{pad}{key if i == 0 else ''}{wrap(_esc(line))}" for i, line in enumerate(_lines(v))]

    left, right = cells(e), cells(a)
    width = max(len(left), len(right))
    return [(le, ri, False) for le, ri in zip(left + [""] * (width - len(left)), right + [""] * (width - len(right)))]


def diff_html(expected: Any, actual: Any) -> str:
    """The expected and the actual value side by side as a table of aligned
    lines, the differing values in <mark>, a key only one side has on a
    shaded row. Values are shown as JSON, floats exactly (`_json`)."""
    rows, n = _diff_rows(expected, actual, 0, "")
    body = "".join(f'<tr><td class="only">{le}</td><td class="only">{ri}</td></tr>' if only
                   else f"<tr><td>{le}</td><td>{ri}</td></tr>" for le, ri, only in rows)
    what = f"{n} difference{'' if n == 1 else 's'} marked" if n else "no difference in the values compared"
    return (f'<table class="diff"><thead><tr><th>expected</th><th>actual ({what})</th></tr></thead>'
            f"<tbody>{body}</tbody></table>")


# ---- the page ---------------------------------------------------------------------------

def counts_html(results: Sequence[Result], noun: str = "case") -> str:
    """'12 cases: 2 failed, 10 passed': every status there is, bad ones first."""
    c = Counter(r.status for r in results)
    parts = [f'<span class="s-{s}">{c[s]:,} {STATUS_WORDS[s]}</span>' for s in STATUS_WORDS if c[s]]
    total = sum(c.values())
    return f'<p class="counts">{total:,} {noun}{"" if total == 1 else "s"}: {", ".join(parts) or "none"}</p>'


def _case_html(r: Result, opened: bool, diff: Callable[[Result], tuple[Any, Any] | None] | None) -> str:
    out = [f'<details class="case" id="case-{_esc(r.id)}"{" open" if opened else ""}><summary>'
           f'<span class="status s-{r.status}">{_esc(r.status)}</span> '
           f"<code>{_esc(r.id)}</code>"
           + (f" ({_esc(r.kind)})" if r.kind else "")
           + (f": {_esc(r.message.splitlines()[0])}" if r.message else "")
           + "</summary><dl>"]
    if r.message and "\n" in r.message:
        out.append(f"<dt>message</dt><dd><pre>{_esc(r.message)}</pre></dd>")
    pair = diff(r) if diff else None
    shown = dict(r.details)
    if pair is not None:
        out.append(f"<dt>expected and actual, as compared</dt><dd>{diff_html(*pair)}</dd>")
        shown.pop("expected", None)
        whole = shown.pop("actual", None)
    for label, value in shown.items():
        if label == "flags" and isinstance(value, list):
            tags = "".join(f'<span class="flag">{_esc(f)}</span>' for f in value) or "none"
            out.append(f"<dt>{_esc(label)}</dt><dd>{tags}</dd>")
        elif _records(value):
            out.append(f"<dt>{_esc(label)}</dt><dd>{_records_html(value)}</dd>")
        else:
            out.append(f"<dt>{_esc(label)}</dt><dd><pre>{_esc(detail_text(value))}</pre></dd>")
    if pair is not None:
        out.append(f"<dt>the whole answer</dt><dd><details><summary>as received</summary>"
                   f"<pre>{_esc(detail_text(whole))}</pre></details></dd>")
    out.append("</dl></details>")
    return "".join(out)


def _records(value: Any) -> bool:
    """Whether a detail is a set of records: names, each with the same kind
    of flat fields (per broadcast item: expected Hz, frames, measured Hz),
    which reads better as a table than as JSON."""
    return (isinstance(value, dict) and len(value) >= 2 and not _is_float_model(value)
            and all(isinstance(v, dict) and v and not _is_float_model(v)
                    and all(not isinstance(x, (dict, list)) for x in v.values()) for v in value.values()))


def _records_html(value: dict) -> str:
    columns = list(dict.fromkeys(k for v in value.values() for k in v))

    def cell(v: Any) -> str:
        if isinstance(v, str):
            return _esc(v)
        if v is None or isinstance(v, bool):
            return value_text(v) or "none"
        return _esc(_json(v))

    head = "".join(f"<th>{_esc(c)}</th>" for c in columns)
    rows = "".join(f"<tr><td>{_esc(name)}</td>" + "".join(f"<td>{cell(v.get(c))}</td>" for c in columns) + "</tr>"
                   for name, v in value.items())
    return f'<table class="records"><thead><tr><th></th>{head}</tr></thead><tbody>{rows}</tbody></table>'


def _cases_html(rs: Sequence[Result], anchor: str, opened: bool,
                diff: Callable[[Result], tuple[Any, Any] | None] | None) -> list[str]:
    """The cases grouped by category, each group under a heading `anchor`-CATEGORY."""
    order = {FAIL: 0, XPASS: 1, ERROR: 2, XFAIL: 3}
    out = []
    for cat in sorted({r.category for r in rs}):
        out.append(f'<h3 id="{anchor}-{_esc(cat)}">{_esc(cat)}</h3>')
        out += [_case_html(r, opened, diff) for r in sorted((r for r in rs if r.category == cat),
                                                            key=lambda r: (order[r.status], r.id))]
    return out


def html_report(results: Sequence[Result], title: str, meta: dict[str, Any] | None = None,
                appendix: dict[str, str] | None = None, max_cases: int = 2000,
                extra_html: str | None = None, verdict: tuple[str, bool] | None = None,
                lead_html: str | None = None, diff: Callable[[Result], tuple[Any, Any] | None] | None = None,
                noun: str = "case") -> str:
    """A self-contained HTML page (no external assets, no scripts), in the
    order a reader needs it: the verdict and the counts; what failed (fail,
    xpass, error, up to `max_cases`, each with its details, and with
    `diff(result)` -> (expected, actual) side by side when it gives them);
    `lead_html` (trusted markup: plots); the metadata; the table by
    category; `extra_html` (trusted markup: more tables); the expected
    failures (xfail); `appendix` (titled text blocks). `verdict` (its line
    and whether it is good) replaces the CONFORMS / DOES NOT CONFORM drawn
    from the statuses alone, for callers that know more (what ran, an
    interruption). `noun` is what the counts line counts."""
    by_cat = counts_by_category(results)
    total: Counter = Counter()
    for c in by_cat.values():
        total.update(c)
    line, ok = verdict or (("CONFORMS", True) if conforms(results) else ("DOES NOT CONFORM", False))
    out = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
           f"<title>{_esc(title)}</title><style>{_CSS}</style></head><body>",
           f"<h1>{_esc(title)}</h1>",
           f'<p class="verdict {"ok" if ok else "no"}">{_esc(line)}</p>',
           counts_html(results, noun)]

    bad = [r for r in results if r.status in BAD]
    if bad:
        shown = bad[:max_cases]
        out.append(f'<h2 id="failures">What failed ({len(bad):,})</h2>')
        kinds = Counter(r.kind or r.status for r in bad)
        if len(kinds) > 1:
            out.append("<p>" + ", ".join(f"{n:,} {_esc(k)}" for k, n in kinds.most_common()) + "</p>")
        if len(shown) < len(bad):
            out.append(f"<p>The first {len(shown):,} are listed here; the JUnit report has all of them.</p>")
        out += _cases_html(shown, "cat", len(shown) <= 50, diff)
    if lead_html:
        out.append(lead_html)

    meta = _words(meta)
    meta.setdefault("generated", time.strftime("%Y-%m-%d %H:%M:%S %z"))
    out.append('<h2>About this run</h2><table class="meta"><tbody>')
    out += [f"<tr><th>{_esc(k)}</th><td>{_esc(v)}</td></tr>" for k, v in meta.items()]
    out.append("</tbody></table>")

    out.append("<h2>By category</h2><table><thead><tr><th>category</th>")
    out += [f"<th>{s}</th>" for s in STATUSES]
    out.append("<th>total</th></tr></thead><tbody>")
    for cat, c in list(by_cat.items()) + [("total", total)]:
        cells = []
        for s in STATUSES:
            cls = ' class="bad"' if s in BAD and c[s] else (' class="good"' if s == PASS and c[s] else "")
            cells.append(f"<td{cls}>{c[s]}</td>")
        anchor = "cat" if any(c[s] for s in BAD) else "known" if c[XFAIL] else ""
        name = f'<a href="#{anchor}-{_esc(cat)}">{_esc(cat)}</a>' if cat != "total" and anchor else _esc(cat)
        out.append(f"<tr><td>{name}</td>{''.join(cells)}<td>{sum(c.values())}</td></tr>")
    out.append("</tbody></table>")

    if extra_html:
        out.append(extra_html)

    known = [r for r in results if r.status == XFAIL]
    if known:
        shown = known[:max_cases]
        out.append(f'<h2 id="known">Expected failures, in the failure list ({len(known):,})</h2>')
        if len(shown) < len(known):
            out.append(f"<p>The first {len(shown):,} are listed here; the JUnit report has all of them.</p>")
        out += _cases_html(shown, "known", False, diff)
    for heading, text in (appendix or {}).items():
        out.append(f"<h2>{_esc(heading)}</h2><pre>{_esc(text)}</pre>")
    out.append("</body></html>")
    return "\n".join(out) + "\n"


def write_junit(path: str | Path, results: Sequence[Result], suite_name: str,
                properties: dict[str, Any] | None = None) -> None:
    Path(path).write_bytes(junit_xml(results, suite_name, properties))


def write_html(path: str | Path, results: Sequence[Result], title: str, meta: dict[str, Any] | None = None,
               appendix: dict[str, str] | None = None, extra_html: str | None = None,
               verdict: tuple[str, bool] | None = None, lead_html: str | None = None,
               diff: Callable[[Result], tuple[Any, Any] | None] | None = None, noun: str = "case") -> None:
    Path(path).write_text(html_report(results, title, meta, appendix, extra_html=extra_html, verdict=verdict,
                                      lead_html=lead_html, diff=diff, noun=noun), encoding="utf-8")
