"""The Java glue of generated/java: a Maven project (pom.xml) around the
Kaitai parsers in src/main/java/osdk_kaitai, with the deframer, the CRCs,
decodeFrame/decodePayload in the rule order, OsdkException, the broadcast
view and the encoders of package osdk_kaitai.

The glue names the field a parse failed in. A failed `valid` check says
"/seq/N" of the class that threw; running out of bytes (the runtime's
ByteBuffer underflows) says nothing, so the field is found from the line of
the throwing class's _read() on the stack: the compiler's own output is
read here to learn which lines read which seq field.
"""
from __future__ import annotations

import importlib.util
import re
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
TEMPLATES = HERE / "templates" / "java"
PACKAGE = "osdk_kaitai"
SRC = Path("src") / "main" / "java" / PACKAGE
# the ksy enum the parsers take the profile as (osdk_payload.ksy `profile`)
PROFILE_ENUM = "osdk_payload.profile"
GROUP_ID = "osdk-conformance"
ARTIFACT_ID = "osdk-kaitai"
VERSION = "0.1.0"


def _libgen():
    # this file is loaded by path (tools/libgen/__init__.py write()), not as a package member
    spec = importlib.util.spec_from_file_location("osdk_libgen_java_base", HERE / "__init__.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def camel(ident: str, upper: bool = False) -> str:
    """Kaitai's Java names: snake_case ids -> lowerCamelCase (UpperCamelCase for types)."""
    parts = [p for p in ident.split("_") if p]
    out = "".join(p[:1].upper() + p[1:] for p in parts)
    return out if upper else out[:1].lower() + out[1:]


def java_string(s: str | None) -> str:
    if s is None:
        return "null"
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"') + '"'


def _hex_list(values: list[int], digits: int, per_line: int = 8) -> str:
    lines = []
    for i in range(0, len(values), per_line):
        lines.append("        " + ", ".join(f"0x{v:0{digits}x}" for v in values[i:i + per_line]) + ",")
    return "\n".join(lines)


# ---- reading the compiler's output --------------------------------------------------------

_CLASS = re.compile(r"\b(?:class|enum|interface)\s+(\w+)")
_STRING = re.compile(r'"(?:\\.|[^"\\])*"')
_ASSIGN = re.compile(r"\bthis\.(?:_raw_)?(\w+)\s*=|\bKaitaiStream\s+_io_(\w+)\s*=")
_GETTER = re.compile(r"public\s+([\w.<>\[\]]+)\s+(\w+)\(\)\s*\{\s*return\s+\w+;\s*\}")


def _read_methods(source: str) -> dict[str, list[tuple[int, str]]]:
    """binary class name -> [(line, camel field)] of the assignments in its _read(),
    from the compiler's Java source (braces counted outside strings and comments)."""
    out: dict[str, list[tuple[int, str]]] = {}
    stack: list[tuple[str, int]] = []  # (class name, depth of its body)
    pending: str | None = None
    depth = 0
    in_read: tuple[str, int] | None = None
    in_comment = False
    for lineno, line in enumerate(source.splitlines(), 1):
        code = line
        if in_comment:
            if "*/" not in code:
                continue
            code = code.split("*/", 1)[1]
            in_comment = False
        code = _STRING.sub('""', code)
        code = re.sub(r"/\*.*?\*/", "", code)
        if "/*" in code:
            code, in_comment = code.split("/*", 1)[0], True
        code = code.split("//", 1)[0]
        m = _CLASS.search(code)
        if m:
            pending = m.group(1)
        if re.search(r"\bvoid\s+_read\s*\(\s*\)", code) and stack:
            in_read = ("$".join(c for c, _ in stack), depth + 1)
            out[in_read[0]] = []
        if in_read:
            for a in _ASSIGN.finditer(code):
                out[in_read[0]].append((lineno, a.group(1) or a.group(2)))
        for ch in code:
            if ch == "{":
                depth += 1
                if pending is not None:
                    stack.append((pending, depth))
                    pending = None
            elif ch == "}":
                if in_read and depth == in_read[1]:
                    in_read = None
                if stack and stack[-1][1] == depth:
                    stack.pop()
                depth -= 1
    return out


def _line_maps(src: Path, types: dict[str, Any]) -> list[str]:
    """Java statements filling LINES: per generated class, the first line of
    each seq field's reads in _read(), in line order."""
    reads: dict[str, list[tuple[int, str]]] = {}
    for f in sorted(src.glob("*.java")):
        reads.update(_read_methods(f.read_text(encoding="utf-8")))
    stmts = []
    for key, t in sorted(types.items()):
        binary = "$".join(t["class_path"])
        if binary not in reads:
            if t["seq"]:
                raise SystemExit(f"libgen java: no _read() of {binary} in the compiler's output")
            continue
        by_camel = {camel(s): s for s in t["seq"]}
        starts: dict[str, int] = {}
        for line, name in reads[binary]:
            if name in by_camel and by_camel[name] not in starts:
                starts[by_camel[name]] = line
        ordered = sorted((line, fid) for fid, line in starts.items())
        if not ordered:
            continue
        if [fid for _, fid in ordered] != [s for s in t["seq"] if s in starts]:
            raise SystemExit(f"libgen java: {binary}._read() does not read its seq in order")
        lines = ", ".join(str(line) for line, _ in ordered)
        ids = ", ".join(java_string(fid) for _, fid in ordered)
        stmts.append(f'        lines("{binary}", new int[] {{{lines}}}, new String[] {{{ids}}});')
    return stmts


def _getter_types(source: str) -> dict[str, str]:
    return {m.group(2): m.group(1) for m in _GETTER.finditer(source)}


# ---- pieces of the glue ---------------------------------------------------------------------

def _profile_class(tables: dict[str, Any], profile: str) -> str:
    key = "osdk_broadcast_" + re.sub(r"[^a-z0-9]", "_", profile.lower())
    t = tables["model"]["types"].get(key)
    if t is None:
        raise SystemExit(f"libgen java: profile {profile} has no broadcast type {key} in the tables")
    return ".".join(t["class_path"])


def _broadcast(tables: dict[str, Any], src: Path) -> dict[str, str]:
    items_by_profile = tables["library"]["broadcast_items"]
    union: list[str] = []
    for items in items_by_profile.values():
        union += [i for i in items if i not in union]
    classes = {p: _profile_class(tables, p) for p in items_by_profile}
    getters = {p: _getter_types((src / f"{c}.java").read_text(encoding="utf-8")) for p, c in classes.items()}
    methods, item_cases, order = [], [], []
    for item in union:
        g = camel(item)
        types = {getters[p][g] for p, items in items_by_profile.items() if item in items}
        if len(types) != 1:
            raise SystemExit(f"libgen java: broadcast item {item} has getters of types {sorted(types)}")
        jtype = types.pop()
        if jtype in ("int", "long", "boolean", "double", "float"):
            raise SystemExit(f"libgen java: broadcast item {item} has a primitive getter ({jtype}), no null")
        body = []
        for p, items in items_by_profile.items():
            if item in items:
                c = classes[p]
                body.append(f"        if (data instanceof {c}) {{\n            return (({c}) data).{g}();\n        }}")
        methods.append(
            f"    /** The item {item}, or null when its flag bit is clear or the profile has no such item. */\n"
            f"    public {jtype} {g}() {{\n" + "\n".join(body) + "\n        return null;\n    }\n")
        item_cases.append(f'            case "{item}":\n                return {g}();')
    for p, items in items_by_profile.items():
        order.append(f'        ITEMS.put("{p}", Collections.unmodifiableList(Arrays.asList('
                     + ", ".join(java_string(i) for i in items) + ")));")
    known = " || ".join(f"data instanceof {c}" for c in classes.values())
    return {"getters": "\n".join(methods), "item_cases": "\n".join(item_cases),
            "item_order": "\n".join(order), "known_data": known}


_WIRE = {"u1": (1, 0xFF), "u2": (2, 0xFFFF), "u4": (4, 0xFFFFFFFF)}


def _encoders(tables: dict[str, Any]) -> str:
    out = []
    for c in tables["library"]["sent_commands"]:
        name = camel(c["name"], upper=True)
        params, bits_params, writes, bits_writes, checks = [], [], [], [], []
        has_float = False
        for f in c["fields"]:
            fid, v = f["id"], camel(f["id"])
            count = f.get("count")
            wire = f["wire"]
            if wire == "bytes":
                size = f["size"]
                params.append(f"byte[] {v}")
                bits_params.append(f"byte[] {v}")
                checks.append(f'        size("{fid}", {v}, {size});')
                w = f"        out.put({v});"
                writes.append(w)
                bits_writes.append(w)
            elif wire == "f4":
                if count:
                    raise SystemExit(f"libgen java: {c['name']}.{fid}: repeated floats have no encoder")
                has_float = True
                params.append(f"float {v}")
                bits_params.append(f"int {v}Bits")
                writes.append(f"        out.putInt(Float.floatToRawIntBits({v}));")
                bits_writes.append(f"        out.putInt({v}Bits);")
            elif wire in _WIRE:
                width, top = _WIRE[wire]
                jtype = "long" if width == 4 else "int"
                put = {1: "out.put((byte) {x})", 2: "out.putShort((short) {x})", 4: "out.putInt((int) {x})"}[width]
                if count:
                    params.append(f"{jtype}[] {v}")
                    bits_params.append(f"{jtype}[] {v}")
                    checks.append(f'        count("{fid}", {v}, {count});')
                    checks.append(f'        for ({jtype} x : {v}) {{\n            range("{fid}", x, 0x{top:X}L);\n        }}')
                    w = f"        for ({jtype} x : {v}) {{\n            {put.format(x='x')};\n        }}"
                else:
                    params.append(f"{jtype} {v}")
                    bits_params.append(f"{jtype} {v}")
                    checks.append(f'        range("{fid}", {v}, 0x{top:X}L);')
                    w = f"        {put.format(x=v)};"
                writes.append(w)
                bits_writes.append(w)
            else:
                raise SystemExit(f"libgen java: {c['name']}.{fid}: no encoder for wire type {wire}")
        doc = (f"    /** The {c['size']}-byte value of {c['name']} (cmd_set 0x{c['cmd_set']:02x}, cmd_id 0x{c['cmd_id']:02x}, "
               f"{c['type']}); out-of-range arguments are an IllegalArgumentException. */\n")

        def method(suffix: str, ps: list[str], ws: list[str], note: str = "") -> str:
            return (doc.replace(" */", note + " */") + f"    public static byte[] encode{name}{suffix}({', '.join(ps)}) {{\n"
                    + "".join(x + "\n" for x in checks)
                    + f"        ByteBuffer out = ByteBuffer.allocate({c['size']}).order(ByteOrder.LITTLE_ENDIAN);\n"
                    + "".join(x + "\n" for x in ws)
                    + "        return out.array();\n    }\n")
        out.append(method("", params, writes, " Floats are written with their raw bits (NaN payloads, -0.0 kept)." if has_float else ""))
        if has_float:
            out.append(method("Bits", bits_params, bits_writes, " Floats given as their IEEE-754 bits."))
    return "\n".join(out)


def _commands(tables: dict[str, Any]) -> str:
    sent = {c["name"] for c in tables["library"]["sent_commands"]}
    rows = []
    for c in tables["commands"]:
        rows.append(f'    {c["name"].upper()}({c["cmd_set"]}, {c["cmd_id"]}, "{c["name"]}", {str(c["name"] in sent).lower()})')
    return ",\n".join(rows) + ";"


def _header(tables: dict[str, Any]) -> dict[str, str]:
    lib = tables["library"]["frame"]
    fields = {f["id"]: f for f in lib["header_fields"]}
    consts = []
    for f in lib["header_fields"]:
        consts.append(f"    static final int[] H_{f['id'].upper()} = {{{f['byte']}, {f['lsb']}, {f['width']}}};")
    # the first header field a short input ends in
    ends = ", ".join(str((f["byte"] * 8 + f["lsb"] + f["width"] + 7) // 8) for f in lib["header_fields"])
    ids = ", ".join(java_string(f["id"]) for f in lib["header_fields"])
    crc_names = set(tables["crc"])
    checks = []
    ebf = tables["error_by_field"]
    for check in lib["header_checks"]:
        if check not in fields:
            raise SystemExit(f"libgen java: header check {check} is not a header field")
        if check in crc_names:
            checks.append(
                f"        {{\n            long stored = field(d, at, H_{check.upper()});\n"
                f"            long computed = Crc.{check}(d, at + CRC16_FROM, at + CRC16_TO);\n"
                f"            if (stored != computed) {{\n"
                f'                return new OsdkException("bad_{check}", "{check}", String.format("{check.upper()} is 0x%04x, expected 0x%04x", stored, computed));\n'
                f"            }}\n        }}")
        elif check == "sof":
            checks.append(
                f"        if (field(d, at, H_SOF) != SOF) {{\n"
                f'            return new OsdkException("{ebf[check]}", "sof", String.format("start byte 0x%02x, must be 0x%02x", field(d, at, H_SOF), SOF));\n'
                f"        }}")
        elif check == "len":
            checks.append(
                f"        if (impossibleLength((int) field(d, at, H_LEN))) {{\n"
                f'            return new OsdkException("{ebf[check]}", "len", "LEN " + field(d, at, H_LEN) + " is impossible");\n'
                f"        }}")
        else:  # a version or reserved field: must be 0
            checks.append(
                f"        if (field(d, at, H_{check.upper()}) != 0) {{\n"
                f'            return new OsdkException("{ebf[check]}", "{check}", "{check.upper()} is " + field(d, at, H_{check.upper()}) + ", must be 0");\n'
                f"        }}")
    impossible = " || ".join(f"(len >= {lo} && len <= {hi})" for lo, hi in lib["impossible_lengths"])
    return {"header_fields": "\n".join(consts), "header_field_ends": ends, "header_field_ids": ids,
            "header_checks": "\n".join(checks), "impossible": impossible}


def write(out: Path, tables: dict[str, Any]) -> None:
    base = _libgen()
    src = out / SRC
    lib = tables["library"]["frame"]
    types = tables["model"]["types"]
    frame_seq = types["osdk_frame"]["seq"]
    header_ids = [f["id"] for f in lib["header_fields"]]
    if frame_seq[:len(header_ids)] != header_ids or len(frame_seq) != len(header_ids) + 2:
        raise SystemExit("libgen java: osdk_frame's seq is not the header, DATA and the CRC-32")
    enum_path = PROFILE_ENUM.split(".")
    profile_enum = ".".join(camel(p, upper=True) for p in enum_path)
    if PROFILE_ENUM not in tables["model"]["enums"]:
        raise SystemExit(f"libgen java: no enum {PROFILE_ENUM} in the tables")
    crc16, crc32 = tables["crc"]["crc16"], tables["crc"]["crc32"]
    for p in (crc16, crc32):
        if p["covers"][0] != 0 or p["stored_at"][1] - p["stored_at"][0] + 1 != p["width"] // 8:
            raise SystemExit("libgen java: a CRC that does not cover from the first byte has no template")
    values = {
        "package": PACKAGE,
        "group_id": GROUP_ID, "artifact_id": ARTIFACT_ID, "version": VERSION,
        "crc16_table": _hex_list(base.crc_table(crc16), 4),
        "crc32_table": _hex_list(base.crc_table(crc32), 8),
        "crc16_init": f"0x{crc16['init']:x}", "crc16_xorout": f"0x{crc16['xorout']:x}", "crc16_check": f"0x{crc16['check']:x}",
        "crc32_init": f"0x{crc32['init']:x}L", "crc32_xorout": f"0x{crc32['xorout']:x}L", "crc32_check": f"0x{crc32['check']:x}L",
        "crc16_from": str(crc16["covers"][0]), "crc16_to": str(crc16["covers"][1] + 1),
        "crc32_len": str(lib["crc32_len"]),
        "sof": f"0x{lib['sof']:02X}", "header_len": str(lib["header_len"]), "max_len": str(lib["max_len"]),
        "header_only_len": str(lib["header_only_len"]),
        "data_field": frame_seq[len(header_ids)], "crc32_field": frame_seq[-1],
        "profile_enum": profile_enum,
        "profiles": "\n".join(f'        profile("{p}", {profile_enum}.byId({v}L));'
                              for p, v in tables["profile_values"].items()),
        "error_by_field": "\n".join(f'        ERROR_BY_FIELD.put("{k}", "{v}");'
                                    for k, v in sorted(tables["error_by_field"].items())),
        "seqs": "\n".join(f'        seq("{"$".join(t["class_path"])}", '
                          + ", ".join(java_string(s) for s in t["seq"]) + ");"
                          for _, t in sorted(types.items()) if t["seq"]),
        "lines": "\n".join(_line_maps(src, types)),
        "encoders": _encoders(tables),
        "commands": _commands(tables),
        **_header(tables),
        **_broadcast(tables, src),
    }
    for template in sorted(TEMPLATES.rglob("*")):
        if template.is_dir():
            continue
        rel = template.relative_to(TEMPLATES)
        dest = out / (SRC / rel.name if rel.suffix == ".java" else rel)
        dest.parent.mkdir(parents=True, exist_ok=True)
        dest.write_text(base.render(template, values), encoding="utf-8")
