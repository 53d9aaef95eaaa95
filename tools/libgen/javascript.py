"""The JavaScript library (generated/javascript): package.json and CommonJS
glue beside the Kaitai compiler's modules.

The templates (templates/javascript/) hold the runtime; this fills in what
the spec's tables say: CRC parameters and tables, the header's bit
positions and check order, error classes by field, profiles, broadcast
items, command ids, one encoder per sent command, and SITES, which names
the ksy field read or checked on each line of the compiled modules' _read
functions (the 0.11.0 runtime's errors do not carry it; decode.js reads
the raising line from V8's call sites).
"""
from __future__ import annotations

import importlib.util
import json
import re
import sys
import tomllib
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
TEMPLATE_DIR = HERE / "templates" / "javascript"


def _libgen():
    """tools/libgen/__init__.py (crc_table, render), as tools/regen.py loaded it or afresh."""
    module = sys.modules.get("osdk_libgen")
    if module is None or not hasattr(module, "crc_table"):
        spec = importlib.util.spec_from_file_location("osdk_libgen_js_base", HERE / "__init__.py")
        module = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(module)
    return module

GLUE = ("index.js", "tables.js", "errors.js", "crc.js", "frame.js", "deframer.js", "decode.js",
        "broadcast.js", "encode.js")

_READ = re.compile(r"^\s*(\w+)\.prototype\._read = function\(\)")
_LEAVE = re.compile(r"^\s*(function \w+\(_io|Object\.defineProperty\(|\w+\.prototype\.\w+ = function)")
_ASSIGN = re.compile(r"^\s*this\.(?:_raw_)?([A-Za-z]\w*)(?: = |\.push\()")
_SEQ = re.compile(r'"/seq/(\d+)"')


def camel(ident: str) -> str:
    """A ksy id as the Kaitai JavaScript compiler names it (lowerCamelCase)."""
    first, *rest = ident.split("_")
    return first + "".join(p[:1].upper() + p[1:] for p in rest)


def _js(value: Any) -> str:
    return json.dumps(value, separators=(", ", ": "))


def _sites(out: Path, types: dict[str, Any]) -> dict[str, dict[str, str]]:
    """Per compiled module, line number -> the ksy field its _read reads or
    checks on that line."""
    at: dict[tuple[str, str], str | None] = {}
    for key, t in types.items():
        where = (t["class_path"][0], t["class_path"][-1])
        at[where] = None if where in at else key
    sites: dict[str, dict[str, str]] = {}
    for path in sorted(out.glob("*.js")):
        lines: dict[str, str] = {}
        key = None
        for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            if m := _READ.match(line):
                key = at.get((path.stem, m.group(1)))
                continue
            if _LEAVE.match(line):
                key = None
                continue
            if key is None:
                continue
            seq = types[key]["seq"]
            if m := _SEQ.search(line):
                i = int(m.group(1))
                if i < len(seq):
                    lines[str(n)] = seq[i]
            elif m := _ASSIGN.match(line):
                ids = [f for f in seq if camel(f) == m.group(1)]
                if len(ids) == 1:
                    lines[str(n)] = ids[0]
        if lines:
            sites[path.stem] = lines
    return sites


def _header_reader(f: dict[str, Any]) -> str:
    n = (f["lsb"] + f["width"] + 7) // 8
    word = " + ".join(f"b[o + {f['byte'] + i}]" + (f" * {256 ** i}" if i else "") for i in range(n))
    if f["lsb"]:
        word = f"Math.floor(({word}) / {2 ** f['lsb']})"
    if f["lsb"] + f["width"] < 8 * n:
        word = f"{word} % {2 ** f['width']}" if f["lsb"] else f"({word}) % {2 ** f['width']}"
    return f"  {f['id']}: (b, o) => {word},"


def _header_checks(t: dict[str, Any]) -> list[dict[str, Any]]:
    frame, crc, by_field = t["library"]["frame"], t["crc"], t["error_by_field"]
    out = []
    for check in frame["header_checks"]:
        if check in crc:
            out.append({"id": check, "kind": "crc", "errorClass": f"bad_{check}"})
        elif check == "sof":
            out.append({"id": check, "kind": "equals", "value": frame["sof"], "errorClass": by_field[check]})
        elif check == "len":
            out.append({"id": check, "kind": "length", "errorClass": by_field[check]})
        else:  # the version and the reserved fields must be 0
            out.append({"id": check, "kind": "zero", "errorClass": by_field[check]})
    return out


_WIRE_DOC = {"u1": "integer 0..255", "u2": "integer 0..65535", "u4": "integer 0..4294967295",
             "f4": "number or {f32Bits}"}


def _encoder(cmd: dict[str, Any]) -> tuple[str, str]:
    name = "encode" + camel(cmd["name"])[:1].upper() + camel(cmd["name"])[1:]
    params = [camel(f["id"]) for f in cmd["fields"]]
    doc = ["/**", f" * The {cmd['size']}-byte value of {cmd['name']} (command set {cmd['cmd_set']:#04x}, "
           f"id {cmd['cmd_id']:#04x}; ksy {cmd['type']}).", " * Wrong arguments: TypeError / RangeError."]
    body = [f"  const w = new Writer({cmd['size']});"]
    for f, p in zip(cmd["fields"], params):
        if f["wire"] == "bytes":
            kind = f"{f['size']} bytes (Uint8Array, Buffer or array)"
            call = f"w.bytes({p}, {f['size']}, '{f['id']}')"
        elif "count" in f:
            kind = f"array of {f['count']}, each {_WIRE_DOC[f['wire']]}"
            call = f"w.repeat({p}, {f['count']}, '{f['wire']}', '{f['id']}')"
        else:
            kind = _WIRE_DOC[f["wire"]]
            call = f"w.{f['wire']}({p}, '{f['id']}')"
        if "count" in f and f["wire"] == "bytes":
            raise SystemExit(f"libgen javascript: {cmd['name']}.{f['id']}: repeated bytes have no encoder")
        doc.append(f" * @param {p} {f['id']}: {kind}")
        body.append(f"  {call};")
    doc.append(" * @returns {Uint8Array}")
    doc.append(" */")
    body.append("  return w.out;")
    text = "\n".join(doc) + f"\nfunction {name}({', '.join(params)}) {{\n" + "\n".join(body) + "\n}\n"
    return name, text


def write(out: Path, t: dict[str, Any]) -> None:
    lib, model = t["library"], t["model"]
    frame = lib["frame"]
    types = model["types"]
    compiled = sorted(p.stem for p in out.glob("*.js"))
    clash = set(compiled) & {Path(g).stem for g in GLUE}
    if clash:
        raise SystemExit(f"libgen javascript: compiled modules named like the glue: {sorted(clash)}")

    header_ids = [f["id"] for f in frame["header_fields"]]
    frame_key = next(k for k, v in types.items() if v["seq"][: len(header_ids)] == header_ids)
    rest = types[frame_key]["seq"][len(header_ids):]
    if len(rest) != 2 or rest[1] not in t["crc"]:
        raise SystemExit(f"libgen javascript: {frame_key} after the header is not DATA and a CRC: {rest}")
    data_field, crc32_field = rest
    data_key = next(k for k, v in types.items() if k.startswith(frame_key + ".") and v["class_path"][0] == types[frame_key]["class_path"][0])
    payload_key = "osdk_payload"
    broadcast = next(c for c in t["commands"] if c["name"] == "broadcast")

    base = _libgen()
    crc = {name: {**{k: p[k] for k in ("width", "init", "xorout", "check", "covers", "stored_at")},
                  "table": base.crc_table(p)} for name, p in t["crc"].items()}
    frame_js = {
        "SOF": frame["sof"], "HEADER_LEN": frame["header_len"], "HEADER_ONLY_LEN": frame["header_only_len"],
        "CRC32_LEN": frame["crc32_len"], "MAX_LEN": frame["max_len"],
        "IMPOSSIBLE_LENGTHS": frame["impossible_lengths"],
        "HEADER_CHECKS": _header_checks(t),
        "HEADER_FIELDS": [{**f, "end": (f["byte"] * 8 + f["lsb"] + f["width"] + 7) // 8} for f in frame["header_fields"]],
        "CRC32_CLASS": f"bad_{crc32_field}",
    }
    fields = {f["id"]: f for f in frame["header_fields"]}
    modules = sorted({v["class_path"][0] for v in types.values()})
    missing = [m for m in modules if m not in compiled]
    if missing:
        raise SystemExit(f"libgen javascript: no compiled module for {missing}")
    requires = "const MODULES = {\n" + "".join(f"  {m}: require('./{m}').{m},\n" for m in modules) + "};"

    items = list(dict.fromkeys(i for p in t["profiles"] for i in lib["broadcast_items"][p]))
    getters = "".join(
        f"\n  /** {i}: the item, or null when absent. */\n"
        f"  get {camel(i)}() {{\n"
        f"    return this.data.{camel('has_' + i)} === true ? this.data.{camel(i)} : null;\n  }}\n"
        for i in items)
    # the getters read each item's flag as `has_<item>`: every profile's layout must say so
    for p in t["profiles"]:
        its = lib["broadcast_items"][p]
        if not any(all(v.get(i) == f"has_{i}" for i in its) for v in t["if_expressions"].values()):
            raise SystemExit(f"libgen javascript: no broadcast layout of {p} guards its items by has_<item>")
    encoders = [_encoder(c) for c in lib["sent_commands"]]

    writes = [f"  setHeaderField(out, '{i}', {v});" for i, v in
              (("sof", "SOF"), ("len", "len"), ("session", "session"), ("is_ack", "isAck ? 1 : 0"), ("seq", "seq"))]
    crc_writes = [f"  putCrc(out, '{name}', len);" if name != crc32_field else
                  f"  if (len > HEADER_ONLY_LEN) putCrc(out, '{name}', len);" for name in t["crc"]]

    project = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))["project"]
    ksc = json.loads((ROOT / "tools" / "ksc" / "package.json").read_text(encoding="utf-8"))
    files = sorted([f"{m}.js" for m in compiled] + list(GLUE))
    values = {
        "version": project["version"],
        "license": project.get("license", "UNLICENSED") if isinstance(project.get("license"), str) else "UNLICENSED",
        "files": json.dumps(files, indent=4).replace("\n]", "\n  ]"),
        "runtime_version": ksc["dependencies"]["kaitai-struct-compiler"],
        "profile_values": _js(t["profile_values"]),
        "crc": _js(crc),
        "frame": _js(frame_js),
        "data_field": _js(data_field),
        "crc32_field": _js(crc32_field),
        "error_by_field": _js(t["error_by_field"]),
        "commands": _js({c["name"]: [c["cmd_set"], c["cmd_id"]] for c in t["commands"]}),
        "broadcast_command": _js([broadcast["cmd_set"], broadcast["cmd_id"]]),
        "broadcast_items": _js(lib["broadcast_items"]),
        "class_paths": _js({k: v["class_path"] for k, v in types.items()}),
        "sites": _js(_sites(out, types)),
        "header_readers": "\n".join(_header_reader(f) for f in frame["header_fields"]),
        "requires": requires,
        "frame_class": f"MODULES.{'.'.join(types[frame_key]['class_path'])}",
        "payload_class": f"MODULES.{'.'.join(types[payload_key]['class_path'])}",
        "frame_key": _js(frame_key),
        "frame_data_key": _js(data_key),
        "getters": getters,
        "getter_table": "".join(f"  {i}: Object.getOwnPropertyDescriptor(Broadcast.prototype, '{camel(i)}').get,\n" for i in items),
        "encoders": "".join("\n" + text for _, text in encoders),
        "encoder_names": ", ".join(name for name, _ in encoders),
        "max_session": str(2 ** fields["session"]["width"] - 1),
        "max_seq": str(2 ** fields["seq"]["width"] - 1),
        "header_writes": "\n".join(writes),
        "crc_writes": "\n".join(crc_writes),
    }
    for name in (*GLUE, "package.json"):
        (out / name).write_text(base.render(TEMPLATE_DIR / name, values), encoding="utf-8")
