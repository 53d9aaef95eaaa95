"""The receive-and-send glue of every generated library (generated/<lang>/).

The Kaitai compiler gives parsers only: no CRCs, no deframer, no encoders,
and each runtime reports errors its own way. The glue around them is
generated here, the way MAVLink's generator works: one runtime template
per language (tools/libgen/templates/<lang>/), filled in from the spec's
tables (generated/tables/osdk_tables.json as tools/tables.py computes it:
the CRC parameters, the header's bit positions, the receiver's check order,
the broadcast items per profile and the layout of every command an onboard
computer sends). No language's glue is written by hand apart from its
template.

tools/regen.py calls write(lang, out) after the compiler has written the
parsers of that language into `out`.
"""
from __future__ import annotations

import importlib.util
import string
import sys
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
TEMPLATES = HERE / "templates"
ROOT = HERE.parents[1]
LANGS = ("python", "javascript", "java", "go", "c")


def _load(name: str, path: Path):
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def spec_tables() -> dict[str, Any]:
    """The tables as tools/tables.py computes them from spec/ now (not the
    checked-in JSON, which may be the stale thing being regenerated)."""
    return _load("osdk_tables_tool_libgen", ROOT / "tools" / "tables.py").tables()


def render(template: Path, values: dict[str, str]) -> str:
    """A template with its ${name} placeholders filled in; a missing value is an error."""
    return string.Template(template.read_text(encoding="utf-8")).substitute(values)


def crc_table(params: dict[str, Any]) -> list[int]:
    """The 256-entry lookup table of a reflected CRC (both of the spec's CRCs
    are reflected: tools/tables.py crc), for the templates to embed."""
    if not (params["reflect_in"] and params["reflect_out"]):
        raise SystemExit("libgen: only reflected CRCs have a table template")
    width = params["width"]
    poly = int(f"{params['poly']:0{width}b}"[::-1], 2)
    table = []
    for n in range(256):
        c = n
        for _ in range(8):
            c = (c >> 1) ^ poly if c & 1 else c >> 1
        table.append(c)
    return table


def write(lang: str, out: Path) -> None:
    module = HERE / f"{lang}.py"
    if not module.exists():
        raise SystemExit(f"libgen: no glue generator for {lang} ({module})")
    _load(f"osdk_libgen_{lang}", module).write(out, spec_tables())
