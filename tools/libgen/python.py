"""The Python glue of generated/python: the package `osdk_kaitai` around
the compiler's parsers (pyproject.toml, CRCs, deframer, frame decoding with
the rule order, broadcast item access, encoders), from the spec's tables.

The templates in templates/python/ are the runtime; everything that comes
from the spec is rendered here as Python literals or generated functions,
so a change of the spec changes the package only through regen.py.
"""
from __future__ import annotations

import importlib.util
import sys
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
TEMPLATES = HERE / "templates" / "python"
VERSION = "0.1.0"

# The templates in the package, rendered into out/osdk_kaitai/.
MODULES = ("__init__.py", "_tables.py", "errors.py", "crc.py", "deframer.py", "decode.py", "broadcast.py",
           "encode.py")


def _libgen():
    # this file is loaded by path (tools/libgen/__init__.py _load), not as a package member
    name = "osdk_libgen_for_python"
    if name not in sys.modules:
        spec = importlib.util.spec_from_file_location(name, HERE / "__init__.py")
        module = importlib.util.module_from_spec(spec)
        sys.modules[name] = module
        spec.loader.exec_module(module)
    return sys.modules[name]


def _lit(value: Any) -> str:
    """A Python literal: tuples for lists (the tables are read-only)."""
    if isinstance(value, dict):
        return "{" + ", ".join(f"{_lit(k)}: {_lit(v)}" for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple)):
        inner = ", ".join(_lit(v) for v in value)
        return f"({inner},)" if len(value) == 1 else f"({inner})"
    return repr(value)


def _block(name: str, mapping: dict[str, Any]) -> str:
    lines = [f"{name} = {{"]
    lines += [f"    {k!r}: {_lit(v)}," for k, v in mapping.items()]
    lines.append("}")
    return "\n".join(lines)


def _crc_table(name: str, table: list[int], width: int) -> str:
    digits = width // 4
    rows = [", ".join(f"0x{v:0{digits}X}" for v in table[i:i + 8]) for i in range(0, 256, 8)]
    return f"{name} = (\n" + "".join(f"    {r},\n" for r in rows) + ")"


def _crc_params(p: dict[str, Any]) -> dict[str, Any]:
    keys = ("width", "init", "xorout", "check", "covers", "stored_at")
    return {k: p[k] for k in keys}


def _item_flags(tables: dict[str, Any]) -> dict[str, dict[str, str]]:
    """Kaitai class name of each broadcast layout -> {item: its flag field}:
    the layouts are the types whose `if` fields are exactly a profile's items."""
    item_sets = {frozenset(v) for v in tables["library"]["broadcast_items"].values()}
    out = {}
    for key, ifs in sorted(tables["if_expressions"].items()):
        if frozenset(ifs) in item_sets:
            out[".".join(tables["model"]["types"][key]["class_path"])] = dict(ifs)
    missing = item_sets - {frozenset(v) for v in out.values()}
    if missing:
        raise SystemExit(f"libgen python: no broadcast layout for items {sorted(map(sorted, missing))}")
    return out


def _union_items(tables: dict[str, Any]) -> list[str]:
    out: list[str] = []
    for items in tables["library"]["broadcast_items"].values():
        out += [i for i in items if i not in out]
    return out


def _broadcast_properties(tables: dict[str, Any]) -> str:
    per_profile = tables["library"]["broadcast_items"]
    out = []
    for item in _union_items(tables):
        where = [p for p, items in per_profile.items() if item in items]
        said = "every profile" if len(where) == len(per_profile) else ", ".join(where)
        out.append(f"    @property\n"
                   f"    def {item}(self) -> Any:\n"
                   f'        """`{item}` ({said}), or None when absent."""\n'
                   f"        return self._item({item!r})\n")
    return "\n".join(out)


_WRITERS = {"u1": "_u1", "u2": "_u2", "u4": "_u4", "f4": "_f4"}
_HINTS = {"u1": "int", "u2": "int", "u4": "int", "f4": "float | Float32Bits"}


def _encoder(cmd: dict[str, Any]) -> str:
    params, parts, said = [], [], []
    for f in cmd["fields"]:
        fid, wire = f["id"], f["wire"]
        if wire == "bytes":
            hint, part = "bytes", f"_bytes({fid}, {f['size']}, {fid!r})"
        else:
            hint, part = _HINTS[wire], f"{_WRITERS[wire]}({fid}, {fid!r})"
        if "count" in f:
            hint, part = f"Sequence[{hint}]", f"_repeat({fid}, {f['count']}, {fid!r}, {_WRITERS[wire]})"
        params.append(f"{fid}: {hint}")
        parts.append(part)
        extra = f", enum {f['enum']}" if "enum" in f else (f", one {f['type']} byte" if "type" in f else "")
        count = f" x {f['count']}" if "count" in f else ""
        size = f"{f['size']} bytes" if wire == "bytes" else wire
        said.append(f"    {fid}: {size}{count}{extra}")
    doc = (f'    """The {cmd["size"]}-byte value of {cmd["name"]} (command set 0x{cmd["cmd_set"]:02x}, '
           f'id 0x{cmd["cmd_id"]:02x}, {cmd["type"]}):\n\n' + "\n".join(said) + '\n    """')
    body = "    return _sized(b\"\".join((\n" + "".join(f"        {p},\n" for p in parts) + \
        f"    )), {cmd['size']}, {cmd['name']!r})\n"
    return f"def encode_{cmd['name']}({', '.join(params)}) -> bytes:\n{doc}\n{body}"


def _values(tables: dict[str, Any]) -> dict[str, str]:
    lib = tables["library"]
    frame = lib["frame"]
    crc = tables["crc"]
    libgen = _libgen()
    seq = {".".join(t["class_path"]): t["seq"] for t in tables["model"]["types"].values()}
    header = {f["id"]: (f["byte"], f["lsb"], f["width"]) for f in frame["header_fields"]}
    frame_seq = seq["OsdkFrame"]
    after_header = [s for s in frame_seq if s not in header]
    if len(after_header) != 2:
        raise SystemExit(f"libgen python: expected DATA and CRC-32 after the header, got {after_header}")
    commands = {c["name"]: (c["cmd_set"], c["cmd_id"]) for c in tables["commands"]}
    sent = lib["sent_commands"]
    return {
        "version": VERSION,
        "sof": str(frame["sof"]),
        "header_len": str(frame["header_len"]),
        "crc32_len": str(frame["crc32_len"]),
        "max_len": str(frame["max_len"]),
        "header_only_len": str(frame["header_only_len"]),
        "impossible_lengths": _lit(frame["impossible_lengths"]),
        "header_checks": _lit(frame["header_checks"]),
        "header_fields": _block("HEADER_FIELDS", header),
        "data_field": repr(after_header[0]),
        "crc32_field": repr(after_header[1]),
        "crc16_params": _lit(_crc_params(crc["crc16"])),
        "crc32_params": _lit(_crc_params(crc["crc32"])),
        "crc16_table": _crc_table("CRC16_TABLE", libgen.crc_table(crc["crc16"]), 16),
        "crc32_table": _crc_table("CRC32_TABLE", libgen.crc_table(crc["crc32"]), 32),
        "crc_classes": _lit({name: f"bad_{name}" for name in ("crc16", "crc32")}),
        "error_by_field": _block("ERROR_BY_FIELD", tables["error_by_field"]),
        "profile_values": _block("PROFILES", tables["profile_values"]),
        "broadcast_items": _block("BROADCAST_ITEMS", lib["broadcast_items"]),
        "item_flags": _block("ITEM_FLAGS", _item_flags(tables)),
        "commands": _block("COMMANDS", commands),
        "seq": _block("SEQ", seq),
        "broadcast_properties": _broadcast_properties(tables),
        "encoders": "\n\n\n".join(_encoder(c) for c in sent),
        "encoder_names": "\n".join(f'    "encode_{c["name"]}",' for c in sent),
        "encoder_imports": "".join(f"    encode_{c['name']},\n" for c in sent),
        "sent_names": _lit([c["name"] for c in sent]),
    }


def write(out: Path, tables: dict[str, Any]) -> None:
    libgen = _libgen()
    values = _values(tables)
    package = out / "osdk_kaitai"
    package.mkdir(parents=True, exist_ok=True)
    (out / "pyproject.toml").write_text(libgen.render(TEMPLATES / "pyproject.toml", values))
    (out / "README.md").write_text(libgen.render(TEMPLATES / "README.md", values))
    for name in MODULES:
        (package / name).write_text(libgen.render(TEMPLATES / "osdk_kaitai" / name, values))
