"""The conformance status section of generated/README.md, rendered from the
last `osdkc run --impl all` (reports/conformance.json), so the page says
what was measured, not what someone typed."""
from __future__ import annotations

import json
import re
from pathlib import Path

from osdk_conformance.core.paths import ROOT

README = ROOT / "generated" / "README.md"
BEGIN, END = "<!-- status:begin (osdkc kit writes this part) -->", "<!-- status:end -->"

# What each bundled implementation is, in the words a reader of generated/ wants.
WHAT = {
    "construct": "Construct spec (spec/construct), the project's reference encoder/decoder",
    "kaitai-python": "generated/python (Kaitai + libgen glue) + conformance/testees/kaitai_python_testee.py",
    "js": "generated/javascript (Kaitai + libgen glue) + conformance/testees/javascript",
    "java": "generated/java (Kaitai + libgen glue) + conformance/testees/java",
    "go": "generated/go (Kaitai + libgen glue) + conformance/testees/go",
    "c": "generated/c (tools/cgen + libgen encoders) + conformance/testees/c",
    "accel": "generated/c + generated/cpython as a Python extension (osdk_conformance/reference/_accel.c) + "
             "conformance/testees/accel_testee.py; decoding operations only",
}


def render(status: dict) -> str:
    rows = ["| implementation | what | passed | failed | listed (xfail) | skipped | verdict |",
            "|---|---|---:|---:|---:|---:|---|"]
    for s in status["implementations"]:
        st = s.get("statuses") or {}
        bad = st.get("fail", 0) + st.get("xpass", 0) + st.get("error", 0)
        verdict = "conforms" if s.get("conforms") else "**does not conform**"
        rows.append(f"| `{s['impl']}` | {WHAT.get(s['impl'], '')} | {st.get('pass', 0)} | {bad} | "
                    f"{st.get('xfail', 0)} | {st.get('skip', 0)} | {verdict} |")
    scope = f" (selection: `{status['selection']}`)" if status.get("selection") else ""
    return "\n".join([BEGIN, "", f"Last `osdkc run --impl all`{scope}; skipped cases are operations an "
                      "implementation reports as unsupported (the native decoder only decodes; every "
                      "generated library encodes too).", "",
                      *rows, "", END])


def update(status_path: Path, readme: Path = README) -> bool:
    """Rewrite the status section; False (and nothing written) when there is
    no usable status, no README, or the run was a selection or interrupted."""
    try:
        status = json.loads(status_path.read_text())
        text = readme.read_text()
    except (OSError, ValueError):
        return False
    if status.get("selection") or status.get("interrupted") or BEGIN not in text or END not in text:
        return False
    new = re.sub(re.escape(BEGIN) + r".*?" + re.escape(END), lambda _: render(status), text, flags=re.S)
    if new != text:
        readme.write_text(new)
    return True
