"""The Go library's glue (generated/go): the module files and, beside the
Kaitai parsers in package osdk_kaitai, the CRCs, the deframer, frame and
payload decoding in the spec's rule order, the one error type, broadcast
item access and the encoders.

The runtime is tools/libgen/templates/go/*.tmpl; everything table-driven is
written here from the tables as Go source and substituted into it. Some Go
facts cannot come from the tables (which Go type the compiler gave a field,
whether a name in an `if` is a field or an instance): they are read from
the compiler's output in the same package, so a change of the spec that the
glue cannot follow fails here rather than in a user's build.
"""
from __future__ import annotations

import importlib.util
import re
from pathlib import Path
from typing import Any


def _common():
    # loaded by path (tools/libgen is not an installed package), as regen.py loads it
    spec = importlib.util.spec_from_file_location("osdk_libgen_common_go", Path(__file__).with_name("__init__.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


_libgen = _common()
crc_table, render = _libgen.crc_table, _libgen.render
HERE = _libgen.TEMPLATES / "go"
PACKAGE = "osdk_kaitai"
MODULE = "osdk-conformance.local/generated/go"

# (template, file written under out/); the test file is the library's own
# check of its tables (CRC check values, the worked frame) and runs with
# `go test` in generated/go.
FILES = (
    ("go.mod.tmpl", "go.mod"),
    ("go.sum.tmpl", "go.sum"),
    ("osdk_lib_errors.go.tmpl", f"{PACKAGE}/osdk_lib_errors.go"),
    ("osdk_lib_crc.go.tmpl", f"{PACKAGE}/osdk_lib_crc.go"),
    ("osdk_lib_deframer.go.tmpl", f"{PACKAGE}/osdk_lib_deframer.go"),
    ("osdk_lib_decode.go.tmpl", f"{PACKAGE}/osdk_lib_decode.go"),
    ("osdk_lib_broadcast.go.tmpl", f"{PACKAGE}/osdk_lib_broadcast.go"),
    ("osdk_lib_encode.go.tmpl", f"{PACKAGE}/osdk_lib_encode.go"),
    ("osdk_lib_test.go.tmpl", f"{PACKAGE}/osdk_lib_test.go"),
)


def camel(ident: str) -> str:
    """The Go name the Kaitai compiler gives a ksy id (has_ns_and_sync -> HasNsAndSync)."""
    return "".join(p[:1].upper() + p[1:] for p in ident.split("_") if p)


def lower_camel(ident: str) -> str:
    c = camel(ident)
    return c[:1].lower() + c[1:]


def go_string(s: str) -> str:
    if not re.fullmatch(r"[A-Za-z0-9_.\- ]*", s):
        raise SystemExit(f"libgen go: {s!r} is not a plain identifier")
    return f'"{s}"'


# ---- what the compiler wrote -------------------------------------------------------

class GoSource:
    """Struct fields and instance methods of the compiler's Go files."""

    def __init__(self, pkg: Path) -> None:
        self.fields: dict[str, dict[str, str]] = {}
        self.methods: dict[str, dict[str, str]] = {}
        for path in sorted(pkg.glob("*.go")):
            text = path.read_text(encoding="utf-8")
            for m in re.finditer(r"^type (\w+) struct \{\n(.*?)^\}", text, re.M | re.S):
                self.fields[m.group(1)] = dict(
                    re.findall(r"^\t(\w+) (\S+)$", m.group(2), re.M))
            for m in re.finditer(r"^func \(this \*(\w+)\) (\w+)\(\) \(v (\w+), err error\)", text, re.M):
                self.methods.setdefault(m.group(1), {})[m.group(2)] = m.group(3)

    def field_type(self, struct: str, name: str) -> str:
        try:
            return self.fields[struct][name]
        except KeyError:
            raise SystemExit(f"libgen go: the compiler's {struct} has no field {name}") from None


def go_type_name(tables: dict[str, Any], key: str) -> str:
    return "_".join(tables["model"]["types"][key]["class_path"])


_TOKEN = re.compile(r"\s*(?:(?P<num>0x[0-9a-fA-F_]+|\d[\d_]*)|(?P<name>[A-Za-z_][\w.]*)|(?P<op>==|!=|<=|>=|<|>|\(|\)))")


def condition(expr: str, struct: str, src: GoSource, recv: str) -> tuple[list[str], str]:
    """A Kaitai `if` expression as Go over `recv` (a *struct): the lines that
    compute instances first, then the boolean expression. Only the grammar
    the spec's conditions use (names with _parent paths, not/and/or,
    comparisons, integers); anything else stops the generator."""
    pre: list[str] = []
    out: list[str] = []
    pos = 0
    while pos < len(expr):
        m = _TOKEN.match(expr, pos)
        if not m or m.end() == pos:
            if expr[pos:].strip() == "":
                break
            raise SystemExit(f"libgen go: cannot translate `if: {expr}` at {pos}")
        pos = m.end()
        if m.group("num"):
            out.append(m.group("num").replace("_", ""))
        elif m.group("op"):
            out.append(m.group("op"))
        else:
            word = m.group("name")
            if word in ("not", "and", "or"):
                out.append({"not": "!", "and": "&&", "or": "||"}[word])
                continue
            if word in ("true", "false"):
                out.append(word)
                continue
            go, owner = recv, struct
            parts = word.split(".")
            for i, part in enumerate(parts):
                if part in ("_parent", "_root"):
                    t = src.field_type(owner, part)
                    if not t.startswith("*"):
                        raise SystemExit(f"libgen go: `{expr}`: {owner}.{part} is a {t}, not a known struct")
                    go, owner = f"{go}.{part}", t[1:]
                    continue
                name = camel(part)
                if name in src.fields.get(owner, {}):
                    go = f"{go}.{name}"
                    owner = src.fields[owner][name].lstrip("*")
                elif name in src.methods.get(owner, {}) and i == len(parts) - 1:
                    var = f"v{len(pre)}"
                    pre.append(f"{var}, err := {go}.{name}()\n\t\tif err != nil {{\n\t\t\treturn false\n\t\t}}")
                    go = var
                else:
                    raise SystemExit(f"libgen go: `{expr}`: {owner} has no field or instance {name}")
            out.append(go)
    text = " ".join(out).replace("! ", "!").replace("( ", "(").replace(" )", ")")
    return pre, text


# ---- the pieces ---------------------------------------------------------------------

def crc_go(tables: dict[str, Any]) -> dict[str, str]:
    out = {}
    for name in ("crc16", "crc32"):
        p = tables["crc"][name]
        width = p["width"]
        gt = f"uint{width}"
        table = crc_table(p)
        digits = width // 4
        rows = []
        for i in range(0, 256, 8):
            rows.append("\t" + " ".join(f"0x{v:0{digits}x}," for v in table[i:i + 8]))
        out[f"{name}_type"] = gt
        out[f"{name}_table"] = "\n".join(rows)
        out[f"{name}_init"] = f"0x{p['init']:0{digits}x}"
        out[f"{name}_xorout"] = f"0x{p['xorout']:0{digits}x}"
        out[f"{name}_check"] = f"0x{p['check']:0{digits}x}"
        out[f"{name}_width"] = str(width)
    return out


def header_go(tables: dict[str, Any]) -> dict[str, str]:
    lib = tables["library"]
    frame = lib["frame"]
    fields = {f["id"]: f for f in frame["header_fields"]}
    byfield = tables["error_by_field"]
    crc32 = tables["crc"]["crc32"]
    lines = []
    for f in frame["header_fields"]:
        lines.append(f"\thf{camel(f['id'])} = headerField{{id: {go_string(f['id'])}, byte: {f['byte']}, "
                     f"lsb: {f['lsb']}, width: {f['width']}}}")
    hf_vars = "\n".join(lines)
    hf_list = ", ".join(f"hf{camel(f['id'])}" for f in frame["header_fields"])
    checks = []
    for check in frame["header_checks"]:
        if check in tables["crc"]:
            p = tables["crc"][check]
            lo, hi = p["covers"]
            s_lo, s_hi = p["stored_at"]
            if lo < 0 or hi < 0 or s_lo < 0:
                raise SystemExit(f"libgen go: header check {check} is not over the header")
            if fields.get(check, {}).get("byte") != s_lo or s_hi != s_lo + p["width"] // 8 - 1:
                raise SystemExit(f"libgen go: {check} is not stored where the header field says")
            checks.append(
                f"\tif stored, computed := hf{camel(check)}.get(h), uint64({camel(check)}(h[{lo}:{hi + 1}])); stored != computed {{\n"
                f"\t\treturn newError({go_string('bad_' + check)}, {go_string(check)}, \"%s is 0x%0{p['width'] // 4}x, expected 0x%0{p['width'] // 4}x\", {go_string(check.upper())}, stored, computed)\n\t}}")
        elif check == "sof":
            checks.append(
                f"\tif v := hfSof.get(h); v != frameSOF {{\n"
                f"\t\treturn newError({go_string(byfield['sof'])}, \"sof\", \"start byte 0x%02x, must be 0x%02x\", v, frameSOF)\n\t}}")
        elif check == "len":
            checks.append(
                f"\tif v := hfLen.get(h); impossibleLength(v) {{\n"
                f"\t\treturn newError({go_string(byfield['len'])}, \"len\", \"LEN %d is impossible\", v)\n\t}}")
        else:
            # version and reserved fields: the spec's only allowed value is 0
            checks.append(
                f"\tif v := hf{camel(check)}.get(h); v != 0 {{\n"
                f"\t\treturn newError({go_string(byfield[check])}, {go_string(check)}, \"{check.upper()} is %d, must be 0\", v)\n\t}}")
    impossible = " || ".join(f"(n >= {a} && n <= {b})" for a, b in frame["impossible_lengths"])
    # the frame's fields after the header (DATA, CRC-32): what a short frame runs out in
    seq = tables["model"]["types"]["osdk_frame"]["seq"]
    after = seq[len(frame["header_fields"]):]
    if len(after) != 2:
        raise SystemExit(f"libgen go: osdk_frame after its header has {after}, not DATA and CRC-32")
    if crc32["stored_at"] != [-frame["crc32_len"], -1] or crc32["covers"] != [0, -frame["crc32_len"] - 1]:
        raise SystemExit("libgen go: the CRC-32 is not the frame's last bytes over all before it")
    return {
        "sof": f"0x{frame['sof']:02x}",
        "header_len": str(frame["header_len"]),
        "crc32_len": str(frame["crc32_len"]),
        "max_len": str(frame["max_len"]),
        "header_only_len": str(frame["header_only_len"]),
        "header_field_vars": hf_vars,
        "header_field_list": hf_list,
        "header_checks": "\n".join(checks),
        "impossible_length": impossible,
        "data_field": go_string(after[0]),
        "crc32_field": go_string(after[1]),
    }


def profiles_go(tables: dict[str, Any]) -> dict[str, str]:
    vals = tables["profile_values"]
    return {
        "profile_values": "\n".join(f"\t{go_string(p)}: OsdkPayload_Profile({vals[p]})," for p in tables["profiles"]),
        "profile_list": ", ".join(go_string(p) for p in tables["profiles"]),
    }


def commands_go(tables: dict[str, Any]) -> dict[str, str]:
    lines, names = [], []
    for c in tables["commands"]:
        n = camel(c["name"])
        lines.append(f"\t// Command{n} is {c['name']} (0x{c['cmd_set']:02x}, 0x{c['cmd_id']:02x}).\n"
                     f"\tCommand{n} = Command{{CmdSet: {c['cmd_set']}, CmdID: {c['cmd_id']}, Name: {go_string(c['name'])}}}")
        names.append(f"\tCommand{n},")
    return {"command_vars": "\n".join(lines), "command_list": "\n".join(names)}


_KIND = {"bool": "kindBits", "bits": "kindBits", "int": "kindInt", "float": "kindInt",
         "bytes": "kindBytes", "struct": "kindStruct", "switch": "kindStruct"}


def layouts_go(tables: dict[str, Any], src: GoSource) -> str:
    """Each type's fields with their widths and presence: how far a parse
    got, to name the field a truncated value ran out in."""
    model = tables["model"]["types"]
    ifs = tables["if_expressions"]
    out = []
    for key in sorted(model):
        t = go_type_name(tables, key)
        if t not in src.fields:
            raise SystemExit(f"libgen go: no Go struct {t} for {key}")
        rows = []
        for f in model[key]["fields"]:
            bits = f.get("width_bits") or 8 * f.get("width", 0)
            present = "nil"
            if f.get("optional"):
                expr = ifs.get(key, {}).get(f["id"])
                if expr is None:
                    raise SystemExit(f"libgen go: {key}.{f['id']} is optional without an if expression")
                pre, cond = condition(expr, t, src, "o")
                body = "".join(f"\t\t{p}\n" for p in pre)
                present = f"func(x any) bool {{\n\t\to := x.(*{t})\n{body}\t\treturn {cond}\n\t}}"
            src.field_type(t, camel(f["id"]))
            rows.append(f"\t\t{{id: {go_string(f['id'])}, goName: {go_string(camel(f['id']))}, kind: {_KIND[f['kind']]}, "
                        f"bits: {bits}, repeat: {'true' if f.get('repeat') else 'false'}, present: {present}}},")
        out.append(f"\treflect.TypeOf({t}{{}}): {{\n" + "\n".join(rows) + "\n\t},")
    return "\n".join(out)


def checked_go(tables: dict[str, Any], src: GoSource) -> str:
    """The fields with a `valid` check, by type and seq position: a Go
    validation error names only "/seq/N" and its actual value."""
    model = tables["model"]["types"]
    rows = []
    for key in sorted(tables["checked_fields"]):
        t = go_type_name(tables, key)
        for fid in tables["checked_fields"][key]:
            n = model[key]["seq"].index(fid)
            src.field_type(t, camel(fid))
            cls = tables["error_by_field"].get(fid, "undecodable")
            rows.append(f"\t{{srcPath: \"/seq/{n}\", typ: reflect.TypeOf({t}{{}}), goName: {go_string(camel(fid))}, "
                        f"id: {go_string(fid)}, class: {go_string(cls)}}},")
    return "\n".join(rows)


def broadcast_go(tables: dict[str, Any], src: GoSource) -> dict[str, str]:
    items_by_profile = tables["library"]["broadcast_items"]
    bc = next(c for c in tables["commands"] if c["name"] == "broadcast")
    union: list[str] = []
    for p in tables["profiles"]:
        for item in items_by_profile[p]:
            if item not in union:
                union.append(item)
    per_profile = {}
    for p in tables["profiles"]:
        key = "osdk_broadcast_" + re.sub(r"[^a-z0-9]", "_", p)
        if key not in tables["model"]["types"]:
            raise SystemExit(f"libgen go: no broadcast type {key} for profile {p}")
        per_profile[p] = (key, go_type_name(tables, key))
    methods = []
    item_cases = []
    for item in union:
        name = camel(item)
        gtypes = {src.field_type(per_profile[p][1], name) for p in tables["profiles"] if item in items_by_profile[p]}
        if len(gtypes) != 1:
            raise SystemExit(f"libgen go: item {item} has the Go types {sorted(gtypes)} across profiles")
        gt = gtypes.pop()
        ret = gt if gt.startswith("*") else "*" + gt
        cases = []
        for p in tables["profiles"]:
            if item not in items_by_profile[p]:
                continue
            key, t = per_profile[p]
            expr = tables["if_expressions"][key][item]
            pre, cond = condition(expr, t, src, "d")
            if pre:
                raise SystemExit(f"libgen go: broadcast flag of {item} is an instance")
            value = f"d.{name}" if gt.startswith("*") else f"&d.{name}"
            cases.append(f"\tcase *{t}:\n\t\tif {cond} {{\n\t\t\treturn {value}\n\t\t}}")
        profiles = ", ".join(p for p in tables["profiles"] if item in items_by_profile[p])
        methods.append(
            f"// {name} is the {item} item, nil when its flag bit is clear or the\n"
            f"// profile has no such item ({profiles}).\n"
            f"func (b *Broadcast) {name}() {ret} {{\n"
            f"\tswitch d := b.data.(type) {{\n" + "\n".join(cases) + "\n\t}\n\treturn nil\n}\n")
        item_cases.append(f"\tcase {go_string(item)}:\n\t\tif v := b.{name}(); v != nil {{\n\t\t\treturn v\n\t\t}}")
    items = "\n".join(f"\t{go_string(p)}: {{" + ", ".join(go_string(i) for i in items_by_profile[p]) + "},"
                      for p in tables["profiles"])
    return {
        "broadcast_cmd_set": str(bc["cmd_set"]),
        "broadcast_cmd_id": str(bc["cmd_id"]),
        "broadcast_methods": "\n".join(methods),
        "broadcast_item_cases": "\n".join(item_cases),
        "broadcast_items": items,
    }


_GO_WIRE = {"u1": ("uint8", 1), "u2": ("uint16", 2), "u4": ("uint32", 4), "f4": ("float32", 4)}


def encoders_go(tables: dict[str, Any]) -> str:
    out = []
    for c in tables["library"]["sent_commands"]:
        name = camel(c["name"])
        has_float = any(f["wire"] == "f4" for f in c["fields"])
        for bits_variant in ((False, True) if has_float else (False,)):
            params, body = [], []
            for f in c["fields"]:
                arg = lower_camel(f["id"])
                if f["wire"] == "bytes":
                    params.append(f"{arg} [{f['size']}]byte")
                    body.append(f"\tout = append(out, {arg}[:]...)")
                    continue
                gt, size = _GO_WIRE[f["wire"]]
                if f["wire"] == "f4" and bits_variant:
                    gt = "uint32"
                if "count" in f:
                    params.append(f"{arg} [{f['count']}]{gt}")
                    body.append(f"\tfor _, v := range {arg} {{\n\t{put(f['wire'], 'v', bits_variant)}\n\t}}")
                else:
                    params.append(f"{arg} {gt}")
                    body.append(put(f["wire"], arg, bits_variant))
            fname = f"Encode{name}{'Bits' if bits_variant else ''}"
            doc = (f"// {fname} is the {c['size']}-byte value of {c['name']} (0x{c['cmd_set']:02x}, 0x{c['cmd_id']:02x}),\n"
                   f"// fields in wire order ({', '.join(f['id'] for f in c['fields'])})")
            if has_float:
                doc += (",\n// each float given as its IEEE 754 bits (NaN payloads, -0.0)" if bits_variant
                        else ",\n// floats written with their exact float32 bits")
            out.append(f"{doc}.\nfunc {fname}({', '.join(params)}) []byte {{\n"
                       f"\tout := make([]byte, 0, {c['size']})\n" + "\n".join(body) + "\n\treturn out\n}\n")
    return "\n".join(out)


def put(wire: str, arg: str, bits: bool) -> str:
    if wire == "u1":
        return f"\tout = append(out, {arg})"
    if wire == "u2":
        return f"\tout = binary.LittleEndian.AppendUint16(out, {arg})"
    if wire == "u4":
        return f"\tout = binary.LittleEndian.AppendUint32(out, {arg})"
    if wire == "f4":
        return f"\tout = binary.LittleEndian.AppendUint32(out, {arg if bits else f'math.Float32bits({arg})'})"
    raise SystemExit(f"libgen go: no encoder for wire type {wire}")


def frame_writer_go(tables: dict[str, Any]) -> dict[str, str]:
    fields = {f["id"]: f for f in tables["library"]["frame"]["header_fields"]}
    for need in ("len", "session", "is_ack", "seq", "sof", "crc16"):
        if need not in fields:
            raise SystemExit(f"libgen go: the header has no {need} field")
    p16 = tables["crc"]["crc16"]
    lo, hi = p16["covers"]
    return {
        "session_max": str((1 << fields["session"]["width"]) - 1),
        "crc16_covers_end": str(hi + 1),
        "crc16_covers_start": str(lo),
        "ack_field": go_string("is_ack"),
        "len_field": go_string("len"),
        "bad_session": go_string(tables["error_by_field"]["is_ack"]),
        "impossible_length_class": go_string(tables["error_by_field"]["len"]),
    }


def write(out: Path, tables: dict[str, Any]) -> None:
    pkg = out / PACKAGE
    src = GoSource(pkg)
    values: dict[str, str] = {"module": MODULE, "package": PACKAGE}
    values.update(crc_go(tables))
    values.update(header_go(tables))
    values.update(profiles_go(tables))
    values.update(commands_go(tables))
    values.update(broadcast_go(tables, src))
    values.update(frame_writer_go(tables))
    values["layouts"] = layouts_go(tables, src)
    values["checked_fields"] = checked_go(tables, src)
    values["encoders"] = encoders_go(tables)
    values["error_by_field_truncation"] = go_string("truncated_payload")
    for template, name in FILES:
        text = render(HERE / template, values)
        (out / name).write_text(text, encoding="utf-8")
