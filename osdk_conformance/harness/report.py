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

No Python repr reaches a report: a yes/no value (a detail, a metadata
entry, a JUnit property) is written "yes" or "no", and a metadata entry or
property whose value is None is left out (`value_text`).
"""
from __future__ import annotations

import html
import json
import time
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterable, Sequence
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


def _xml_safe(text: str) -> str:
    """XML 1.0 cannot carry most control characters, even escaped."""
    return "".join(ch if ch in "\t\n\r" or (ord(ch) >= 0x20 and ch not in "\ufffe\uffff") else f"\\x{ord(ch):02x}"
                   for ch in text)


def junit_xml(results: Sequence[Result], suite_name: str, properties: dict[str, Any] | None = None) -> bytes:
    """JUnit XML: one <testsuite> per category, one <testcase> per result
    (`properties` as `value_text` writes them)."""
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
        for r in rs:
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
            elif r.status == SKIP:
                ET.SubElement(tc, "skipped", message=msg)
        tot.update(tests=len(rs), failures=failures, errors=c[ERROR], skipped=skipped)
    for k in ("tests", "failures", "errors", "skipped"):
        root.set(k, str(tot[k]))
    ET.indent(root)
    return ET.tostring(root, encoding="utf-8", xml_declaration=True) + b"\n"


# ---- HTML -----------------------------------------------------------------------

_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Helvetica,Arial,sans-serif;margin:2em;color:#1b1b1b;max-width:80em}
h1{font-size:1.5em} h2{font-size:1.2em;margin-top:2em} h3{font-size:1em;margin:0}
table{border-collapse:collapse;margin:1em 0} th,td{border:1px solid #ccc;padding:.25em .6em;text-align:right}
th:first-child,td:first-child{text-align:left} thead th{background:#f2f2f2}
td.bad{background:#fde2e2;font-weight:bold} td.good{background:#e3f6e3}
.verdict{font-size:1.2em;font-weight:bold;padding:.5em 1em;display:inline-block}
.ok{background:#e3f6e3;color:#145214} .no{background:#fde2e2;color:#8b1414}
details.case{border:1px solid #ddd;margin:.5em 0;padding:.4em .8em;border-radius:4px}
details.case summary{cursor:pointer} .status{font-weight:bold;text-transform:uppercase;font-size:.85em}
.s-fail,.s-xpass,.s-error{color:#8b1414} .s-xfail{color:#8a6d00}
pre{background:#f7f7f7;padding:.5em;overflow-x:auto;white-space:pre-wrap;word-break:break-all;margin:.2em 0 .6em}
dt{font-weight:bold;margin-top:.4em} dd{margin-left:1em}
.flag{display:inline-block;background:#e8eefc;border:1px solid #b8c7ee;border-radius:3px;padding:0 .4em;margin:0 .2em .2em 0;font-family:monospace}
.meta td{text-align:left}
"""


def _esc(value: Any) -> str:
    return html.escape(str(value), quote=True)


def html_report(results: Sequence[Result], title: str, meta: dict[str, Any] | None = None,
                appendix: dict[str, str] | None = None, max_cases: int = 2000,
                extra_html: str | None = None, verdict: tuple[str, bool] | None = None) -> str:
    """A self-contained HTML page (no external assets, no scripts). Every
    case that did not pass is listed with its details, up to `max_cases`
    (fail, xpass and error first); `appendix` adds titled text blocks;
    `extra_html` (trusted markup, e.g. inline SVG plots) goes after the
    table by category. `verdict` (its line and whether it is good) replaces
    the CONFORMS / DOES NOT CONFORM drawn from the statuses alone, for
    callers that know more (what ran, an interruption)."""
    by_cat = counts_by_category(results)
    total: Counter = Counter()
    for c in by_cat.values():
        total.update(c)
    line, ok = verdict or (("CONFORMS", True) if conforms(results) else ("DOES NOT CONFORM", False))
    out = ["<!DOCTYPE html>", '<html lang="en"><head><meta charset="utf-8">',
           f"<title>{_esc(title)}</title><style>{_CSS}</style></head><body>",
           f"<h1>{_esc(title)}</h1>",
           f'<p class="verdict {"ok" if ok else "no"}">{_esc(line)}</p>']
    meta = _words(meta)
    meta.setdefault("generated", time.strftime("%Y-%m-%d %H:%M:%S %z"))
    out.append('<table class="meta"><tbody>')
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
        name = f'<a href="#cat-{_esc(cat)}">{_esc(cat)}</a>' if cat != "total" and any(
            c[s] for s in (FAIL, XPASS, ERROR, XFAIL)) else _esc(cat)
        out.append(f"<tr><td>{name}</td>{''.join(cells)}<td>{sum(c.values())}</td></tr>")
    out.append("</tbody></table>")

    if extra_html:
        out.append(extra_html)

    order = {FAIL: 0, XPASS: 1, ERROR: 2, XFAIL: 3}
    not_passed = [r for r in results if r.status in order]
    shown = sorted(not_passed, key=lambda r: order[r.status])[:max_cases]
    out.append(f"<h2>Cases that did not pass ({len(not_passed)})</h2>")
    if not shown:
        out.append("<p>Not one: every case passed or was skipped.</p>")
    elif len(shown) < len(not_passed):
        out.append(f"<p>The first {len(shown)} are listed here; the JUnit report has all of them.</p>")
    cats = sorted({r.category for r in shown})
    for cat in cats:
        rs = sorted((r for r in shown if r.category == cat), key=lambda r: (order[r.status], r.id))
        out.append(f'<h2 id="cat-{_esc(cat)}">{_esc(cat)}</h2>')
        for r in rs:
            opened = " open" if len(shown) <= 50 and r.status != XFAIL else ""
            out.append(f'<details class="case" id="case-{_esc(r.id)}"{opened}><summary>'
                       f'<span class="status s-{r.status}">{_esc(r.status)}</span> '
                       f"<code>{_esc(r.id)}</code>"
                       + (f" ({_esc(r.kind)})" if r.kind else "")
                       + (f": {_esc(r.message.splitlines()[0])}" if r.message else "")
                       + "</summary><dl>")
            if r.message and "\n" in r.message:
                out.append(f"<dt>message</dt><dd><pre>{_esc(r.message)}</pre></dd>")
            for label, value in r.details.items():
                if label == "flags" and isinstance(value, list):
                    tags = "".join(f'<span class="flag">{_esc(f)}</span>' for f in value) or "none"
                    out.append(f"<dt>{_esc(label)}</dt><dd>{tags}</dd>")
                else:
                    out.append(f"<dt>{_esc(label)}</dt><dd><pre>{_esc(detail_text(value))}</pre></dd>")
            out.append("</dl></details>")
    for heading, text in (appendix or {}).items():
        out.append(f"<h2>{_esc(heading)}</h2><pre>{_esc(text)}</pre>")
    out.append("</body></html>")
    return "\n".join(out) + "\n"


def write_junit(path: str | Path, results: Sequence[Result], suite_name: str,
                properties: dict[str, Any] | None = None) -> None:
    Path(path).write_bytes(junit_xml(results, suite_name, properties))


def write_html(path: str | Path, results: Sequence[Result], title: str, meta: dict[str, Any] | None = None,
               appendix: dict[str, str] | None = None, extra_html: str | None = None,
               verdict: tuple[str, bool] | None = None) -> None:
    Path(path).write_text(html_report(results, title, meta, appendix, extra_html=extra_html, verdict=verdict),
                          encoding="utf-8")
