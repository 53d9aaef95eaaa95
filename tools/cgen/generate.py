#!/usr/bin/env python3
"""Generate the C99 decoder of generated/c/ from spec/*.ksy and the rules.

usage: tools/cgen/generate.py --out DIR [--target c|cpython]

Every ksy type becomes a C struct and an `<type>_parse()` function that
reads it from a bounds-checked stream over a caller-supplied buffer (no
heap), checks every `valid` (translated by tools/cgen/expr.py) and reports
failures as the error classes of docs/VALUE-MODEL.md plus the type and
field that failed; a `<type>_to_json()` writes the JSON value model. The
parts that are not per-type (stream primitives, the CRC engine, the
streaming deframer, the JSON writer, the rule tables) come from the
templates in tools/cgen/templates/, filled with values derived from the
spec (CRC parameters and tables, header layout, receiver checks, control
mode tables). The output is deterministic.

--target cpython writes, instead, `<type>_to_py()` for every type: the same
value model built as Python objects (dicts, ints, bools, hex strings), and
osdk_columns.c: each profile's broadcast flattened to typed columns, one
row per frame (the tables of osdk_conformance/flight), both for the native
accelerator of osdk_conformance (osdk_conformance/reference/_accel.c). They
are kept apart from generated/c/, which needs nothing beyond libc.
"""
from __future__ import annotations

import argparse
import re
import importlib.util
import string
import sys
from pathlib import Path
from typing import Optional

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(ROOT))

import yaml  # noqa: E402

from expr import ExprError, Scope, Typed, names_used, translate  # noqa: E402
from spec import EnumSpec, FieldSpec, SafeLoader, Spec, SpecError, TypeRef, TypeSpec  # noqa: E402

TEMPLATES = HERE / "templates"
_INT_TYPE = re.compile(r"^([us])([1248])(le|be)?$")
BANNER = "/* Generated from spec/ by tools/cgen/generate.py. Do not edit. */\n"

# The frame type the receiver (deframer) works on, and the receiver's
# header checks: rules.yaml frame.receiver.header_checks in its order,
# CRC-16 always first (when it fails the other fields mean nothing) and
# without the start byte, which the hunt for it already guarantees.
FRAME_TYPE = "osdk_frame"
# The payload type whose switch on the profile holds each profile's broadcast layout.
BROADCAST_TYPE = "osdk_payload::broadcast"

# docs/VALUE-MODEL.md, error classes, in the table's order; the classes of
# error_by_field are added if one is missing here.
# Keys of the value model that are not field ids (docs/VALUE-MODEL.md).
PY_MODEL_KEYS = ["value", "name", "f32", "f64"]

ERROR_CLASSES = [
    "bad_sof", "bad_crc16", "bad_version", "reserved_bits", "impossible_length", "bad_encryption",
    "bad_session", "bad_crc32", "truncated_frame", "truncated_payload", "length_mismatch", "undecodable",
    "undefined_mode", "out_of_range",
]


class GenError(Exception):
    pass


def load_tables_module():
    spec = importlib.util.spec_from_file_location("osdk_tables_tool_for_cgen", ROOT / "tools" / "tables.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def c_string(s: str) -> str:
    out = []
    for ch in s:
        if ch in '"\\':
            out.append("\\" + ch)
        elif 32 <= ord(ch) < 127:
            out.append(ch)
        else:
            raise GenError(f"non-ASCII character in {s!r}")
    return '"' + "".join(out) + '"'


def uint_ctype(bits: int) -> str:
    for w in (8, 16, 32, 64):
        if bits <= w:
            return f"uint{w}_t"
    raise GenError(f"no C type for {bits} bits")


class Lines:
    def __init__(self) -> None:
        self.out: list[str] = []
        self.depth = 0

    def __call__(self, text: str = "") -> None:
        self.out.append(("    " * self.depth + text) if text else "")

    def open(self, text: str) -> None:
        self(text)
        self.depth += 1

    def func(self, signature: str) -> None:
        self(signature)
        self("{")
        self.depth += 1

    def close(self, text: str = "}") -> None:
        self.depth -= 1
        self(text)

    def text(self) -> str:
        return "\n".join(self.out) + "\n"


class Generator:
    def __init__(self, spec: Spec, tables: dict, rules_doc: dict, skipped: frozenset) -> None:
        self.spec = spec
        self.tables = tables
        self.rules = rules_doc
        self.skipped = skipped
        self.error_by_field: dict[str, str] = tables["error_by_field"]
        classes = list(ERROR_CLASSES)
        for cls in sorted(set(self.error_by_field.values())):
            if cls not in classes:
                classes.append(cls)
        self.classes = classes
        self.types = [t for t in spec.ordered_types() if t.fields]
        kept = {t.cname for t in self.types}
        for t in self.types:
            for _, ref in self.children(t):
                if ref.target.cname not in kept:
                    raise GenError(f"{t.ksy_name} uses {ref.target.ksy_name}, which has no seq")
        self.parent_of: dict[str, TypeSpec] = {}
        self.instances_used: dict[str, list[tuple[str, str, str]]] = {}  # cname -> [(id, ctype, cexpr)]
        self._inst_busy: set[tuple[str, str]] = set()
        self._inst_types: dict[tuple[str, str], Typed] = {}
        self.valid_predicates: dict[tuple[str, str], str] = {}
        self.parse_instances_used: dict[str, set] = {}
        self._wanted: set = set()
        self._compute_parents()
        self._compute_root_use()

    # ---- analysis ---------------------------------------------------------------------

    def children(self, t: TypeSpec) -> list[tuple[FieldSpec, TypeRef]]:
        out = []
        for f in t.fields:
            if f.ref is not None:
                out.append((f, f.ref))
            for c in f.cases:
                out.append((f, c.type))
            if f.default is not None:
                out.append((f, f.default))
        return out

    def _exprs(self, t: TypeSpec) -> list[object]:
        out: list[object] = []
        for f in t.fields:
            for e in (f.cond, f.size, f.switch_on):
                if e is not None:
                    out.append(e)
            if isinstance(f.valid, dict) and "expr" in f.valid:
                out.append(f.valid["expr"])
            for _, ref in self.children_of_field(f):
                out.extend(ref.args)
        for inst in t.instances.values():
            for key in ("value", "if", "pos"):
                if key in inst:
                    out.append(inst[key])
        return out

    @staticmethod
    def children_of_field(f: FieldSpec) -> list[tuple[FieldSpec, TypeRef]]:
        out = []
        if f.ref is not None:
            out.append((f, f.ref))
        out += [(f, c.type) for c in f.cases]
        if f.default is not None:
            out.append((f, f.default))
        return out

    def _uses(self, t: TypeSpec, prefix: str) -> bool:
        for e in self._exprs(t):
            if isinstance(e, (bool, int)):
                continue
            if any(n.startswith(prefix + ".") or n == prefix for n in names_used(e)):
                return True
        return False

    def _compute_parents(self) -> None:
        parents: dict[str, set[str]] = {}
        by_name = {t.cname: t for t in self.types}
        for t in self.types:
            for _, ref in self.children(t):
                parents.setdefault(ref.target.cname, set()).add(t.cname)
        for t in self.types:
            if self._uses(t, "_parent"):
                ps = sorted(parents.get(t.cname, ()))
                if len(ps) != 1:
                    raise GenError(f"{t.ksy_name} uses _parent but is used by {ps or 'no type'}")
                self.parent_of[t.cname] = by_name[ps[0]]

    def root_of(self, t: TypeSpec) -> TypeSpec:
        return self.spec.types[(t.file, ())]

    def _compute_root_use(self) -> None:
        needs = {t.cname: (self._uses(t, "_root") and not t.is_file_root) for t in self.types}
        changed = True
        while changed:
            changed = False
            for t in self.types:
                if needs[t.cname] or t.is_file_root:
                    continue
                for _, ref in self.children(t):
                    c = ref.target
                    if needs[c.cname] and c.file == t.file:
                        needs[t.cname] = True
                        changed = True
        for t in self.types:
            for _, ref in self.children(t):
                c = ref.target
                if needs[c.cname] and c.file != t.file:
                    raise GenError(f"{c.ksy_name} uses _root but is instantiated from another file ({t.ksy_name})")
        self.needs_root = needs

    # ---- naming -----------------------------------------------------------------------

    @staticmethod
    def enum_const(e: EnumSpec, name: str) -> str:
        return f"{e.cname}_{name}".upper()

    @staticmethod
    def status(cls: str) -> str:
        return "OSDK_ERR_" + cls.upper()

    def class_of_field(self, fid: str) -> str:
        return self.status(self.error_by_field.get(fid, "undecodable"))

    @staticmethod
    def present(fid: str) -> str:
        return f"{fid}_present"

    def switch_ctype(self, t: TypeSpec, f: FieldSpec) -> str:
        return f"{t.cname}_{f.id}_switch_t"

    def switch_members(self, t: TypeSpec, f: FieldSpec) -> list[tuple[str, TypeSpec]]:
        seen: dict[str, TypeSpec] = {}
        refs = [c.type for c in f.cases] + ([f.default] if f.default else [])
        for ref in refs:
            name = ref.target.name
            if name in seen and seen[name] is not ref.target:
                raise GenError(f"{t.ksy_name}.{f.id}: two case types named {name}")
            seen[name] = ref.target
        if "raw" in seen:
            raise GenError(f"{t.ksy_name}.{f.id}: a case type is named raw")
        return list(seen.items())

    def switch_tag(self, t: TypeSpec, f: FieldSpec, member: str) -> str:
        return f"{t.cname}_{f.id}_{member}".upper()

    def member_ctype(self, t: TypeSpec, f: FieldSpec) -> str:
        if f.kind == "int":
            return f"{'int' if f.signed else 'uint'}{8 * f.width}_t"
        if f.kind == "float":
            return "osdk_f32_t" if f.width == 4 else "osdk_f64_t"
        if f.kind == "bits":
            return "bool" if f.is_bool else uint_ctype(f.width)
        if f.kind in ("bytes", "contents"):
            return "osdk_bytes_t"
        if f.kind == "struct":
            return f"{f.ref.target.cname}_t"
        if f.kind == "switch":
            return self.switch_ctype(t, f)
        raise GenError(f"{t.ksy_name}.{f.id}: no C type for kind {f.kind}")

    @staticmethod
    def param_ctype(ptype: str) -> str:
        if ptype == "bool":
            return "bool"
        signed = ptype.startswith("s")
        return f"{'int' if signed else 'uint'}{8 * int(ptype[1])}_t"

    # ---- expression scopes --------------------------------------------------------------

    def field_typed(self, t: TypeSpec, f: FieldSpec, cexpr: str, element: bool = False) -> Typed:
        if f.repeat is not None and not element:
            raise ExprError(f"{t.ksy_name}.{f.id}: repeated fields cannot be used in expressions")
        if f.kind in ("int", "bits"):
            if f.is_bool:
                return Typed(cexpr, "bool")
            return Typed(f"((int64_t){cexpr})", f"enum:{f.enum.key}" if f.enum else "int")
        if f.kind in ("bytes", "contents"):
            return Typed(cexpr, "bytes")
        raise ExprError(f"{t.ksy_name}.{f.id}: a {f.kind} field cannot be used in expressions")

    def lookup(self, t: TypeSpec, base: str, name: str, allow_instances: bool) -> Optional[Typed]:
        for p in t.params:
            if p.id == name:
                if p.ptype == "bool":
                    return Typed(f"{base}{name}", "bool")
                return Typed(f"((int64_t){base}{name})", f"enum:{p.enum.key}" if p.enum else "int")
        for f in t.fields:
            if f.id == name:
                return self.field_typed(t, f, f"{base}{name}")
        if name in t.instances:
            if not allow_instances:
                raise ExprError(f"{t.ksy_name}: instance {name} used through _parent/_root")
            if "pos" in t.instances[name]:
                return self.parse_instance(t, name)
            return self.instance(t, name)
        return None

    def parse_instance(self, t: TypeSpec, name: str) -> Typed:
        """A `pos` instance: read where an expression needs it (see gen_parse)."""
        inst = t.instances[name]
        unknown = set(inst) - {"pos", "type", "if", "enum", "doc", "doc-ref"}
        m = _INT_TYPE.match(str(inst.get("type", "")))
        if unknown or not m:
            raise ExprError(f"{t.ksy_name}: instance {name}: only integer `pos` instances are supported")
        self._wanted.add(name)
        self.parse_instances_used.setdefault(t.cname, set()).add(name)
        enum = self.spec.resolve_enum(t, inst["enum"]) if "enum" in inst else None
        return Typed(f"((int64_t)self->{name})", f"enum:{enum.key}" if enum else "int")

    def parse_instance_ctype(self, t: TypeSpec, name: str) -> str:
        m = _INT_TYPE.match(str(t.instances[name]["type"]))
        return f"{'int' if m.group(1) == 's' else 'uint'}{8 * int(m.group(2))}_t"

    def gen_instance_reads(self, L: Lines, t: TypeSpec, names: set) -> None:
        for name in sorted(names):
            inst = t.instances[name]
            m = _INT_TYPE.match(str(inst["type"]))
            width, endian = int(m.group(2)), m.group(3) or t.meta.get("endian", "le")
            fail = (f"return osdk_fail(err, OSDK_ERR_TRUNCATED_PAYLOAD, {c_string(t.ksy_name)}, "
                    f"{c_string(name)}, io);")
            L(f"/* instance {name} (pos {inst['pos']}) */")
            if "if" in inst:
                L(f"self->{self.present(name)} = {self.tr(t, inst['if'], 'bool')};")
                L.open(f"if (self->{self.present(name)}) {{")
            else:
                L("{")
                L.depth += 1
            L("osdk_stream_t at;")
            L(f"int64_t pos = {self.tr(t, inst['pos'], 'int')};")
            L(f"if (pos < 0 || !osdk_stream_at(io, (uint64_t)pos, &at)) {fail}")
            L(f"if (!osdk_read_uint(&at, {width}, {int(endian == 'be')}, &u)) {fail}")
            if m.group(1) == "s":
                L(f"self->{name} = ({self.parse_instance_ctype(t, name)})osdk_sign_extend(u, {8 * width});")
            else:
                L(f"self->{name} = ({self.parse_instance_ctype(t, name)})u;")
            L.close()

    def scope(self, t: TypeSpec, underscore: Optional[Typed] = None) -> Scope:
        def member(obj: str, name: str) -> Optional[Typed]:
            if obj == "_parent":
                p = self.parent_of.get(t.cname)
                if p is None:
                    raise ExprError(f"{t.ksy_name}: _parent has no single type")
                return self.lookup(p, "parent->", name, False)
            if obj == "_root":
                r = self.root_of(t)
                base = "self->" if t.is_file_root else "root->"
                return self.lookup(r, base, name, t.is_file_root)
            return None

        def enum_const(parts: tuple) -> Optional[tuple[str, str]]:
            try:
                r = self.spec.enum_member(t, parts)
            except SpecError as e:
                raise ExprError(str(e)) from None
            if r is None:
                return None
            e, _, name = r
            return self.enum_const(e, name), e.key

        return Scope(lambda n: self.lookup(t, "self->", n, True), member, enum_const, underscore)

    def instance(self, t: TypeSpec, name: str) -> Typed:
        key = (t.cname, name)
        if key in self._inst_types:
            return self._inst_types[key]
        if key in self._inst_busy:
            raise ExprError(f"{t.ksy_name}: instance {name} refers to itself")
        inst = t.instances[name]
        if set(inst) - {"value", "doc", "doc-ref"}:
            raise ExprError(f"{t.ksy_name}: instance {name} is not a value instance")
        self._inst_busy.add(key)
        v = translate(inst["value"], self.scope(t))
        self._inst_busy.discard(key)
        if any(n.startswith("_parent") or n.startswith("_root") for n in names_used(inst["value"])):
            raise ExprError(f"{t.ksy_name}: instance {name} uses _parent/_root")
        fn = f"{t.cname}__{name}"
        ctype = "int64_t" if v.type != "bool" else "bool"
        self.instances_used.setdefault(t.cname, []).append((name, ctype, v.c))
        typed = Typed(f"{fn}(self)", v.type)
        self._inst_types[key] = typed
        return typed

    def tr(self, t: TypeSpec, text: object, want: Optional[str], underscore: Optional[Typed] = None) -> str:
        try:
            return translate(text, self.scope(t, underscore), want).c
        except ExprError as e:
            raise GenError(f"{t.ksy_name}: cannot translate {text!r}: {e}") from None

    def valid_expr(self, t: TypeSpec, f: FieldSpec, underscore: Typed) -> str:
        v = f.valid
        if isinstance(v, dict):
            parts = []
            for k, arg in v.items():
                if k == "expr":
                    parts.append(self.tr(t, arg, "bool", underscore))
                elif k == "eq":
                    parts.append(self.tr(t, f"_ == ({arg})", "bool", underscore))
                elif k == "min":
                    parts.append(self.tr(t, f"_ >= ({arg})", "bool", underscore))
                elif k == "max":
                    parts.append(self.tr(t, f"_ <= ({arg})", "bool", underscore))
                else:
                    raise GenError(f"{t.ksy_name}.{f.id}: unsupported valid form {k!r}")
            return " && ".join(parts)
        if isinstance(v, bool):  # a b1 field, which Kaitai reads as a boolean
            v = "true" if v else "false"
        elif not isinstance(v, (int, str)):
            raise GenError(f"{t.ksy_name}.{f.id}: unsupported valid {v!r}")
        return self.tr(t, f"_ == ({v})", "bool", underscore)

    # ---- ordering -----------------------------------------------------------------------

    def struct_order(self) -> list[TypeSpec]:
        order: list[TypeSpec] = []
        state: dict[str, int] = {}

        def visit(t: TypeSpec) -> None:
            s = state.get(t.cname)
            if s == 2:
                return
            if s == 1:
                raise GenError(f"{t.ksy_name}: recursive types cannot be held by value")
            state[t.cname] = 1
            for f, ref in self.children(t):
                visit(ref.target)
            state[t.cname] = 2
            order.append(t)

        for t in self.types:
            visit(t)
        return order

    # ---- enums ----------------------------------------------------------------------------

    def gen_enums(self) -> tuple[str, str]:
        h, c = Lines(), Lines()
        for key in sorted(self.spec.enums):
            e = self.spec.enums[key]
            h(f"/* enum {e.file}::{e.name} */")
            h("typedef enum {")
            for i, (v, n) in enumerate(e.values):
                if not -(1 << 31) <= v < (1 << 31):
                    raise GenError(f"{e.key}: value {v} does not fit a C enum")
                h(f"    {self.enum_const(e, n)} = {v}{',' if i + 1 < len(e.values) else ''}")
            h(f"}} {e.cname}_t;")
            h(f"/* The spec's name of a {e.name} value, or NULL when it has none. */")
            h("/*@ assigns \\nothing; */")
            h(f"const char *{e.cname}_name(int64_t value);")
            h()
            c.func(f"const char *{e.cname}_name(int64_t value)")
            c.open("switch (value) {")
            for v, n in e.values:
                c(f"case {v}: return {c_string(n)};")
            c("default: return NULL;")
            c.close()
            c.close()
            c()
        return h.text(), c.text()

    # ---- structs ----------------------------------------------------------------------------

    def gen_structs(self) -> str:
        h = Lines()
        for t in self.struct_order():
            for f in t.fields:
                if f.kind == "switch":
                    members = self.switch_members(t, f)
                    h(f"/* {t.ksy_name}.{f.id}: which case was read */")
                    h("enum {")
                    h(f"    {self.switch_tag(t, f, 'none')} = 0,")
                    tags = [self.switch_tag(t, f, m) for m, _ in members]
                    if f.size is not None or f.size_eos:
                        tags.append(self.switch_tag(t, f, "raw"))
                    for i, tag in enumerate(tags):
                        h(f"    {tag} = {i + 1}{',' if i + 1 < len(tags) else ''}")
                    h("};")
                    h("typedef struct {")
                    h("    int tag;")
                    h("    union {")
                    for m, target in members:
                        h(f"        {target.cname}_t {m};")
                    if f.size is not None or f.size_eos:
                        h("        osdk_bytes_t raw; /* no case matched: the bytes, unparsed */")
                    h("    } u;")
                    h(f"}} {self.switch_ctype(t, f)};")
                    h()
            names: set[str] = set()
            h(f"/* {t.ksy_name} */")
            h(f"typedef struct {t.cname} {{")
            for p in t.params:
                h(f"    {self.param_ctype(p.ptype)} {p.id}; /* param{', enum ' + p.enum.key if p.enum else ''} */")
                names.add(p.id)
            for f in t.fields:
                ctype = self.member_ctype(t, f)
                note = []
                if f.enum is not None:
                    note.append(f"enum {f.enum.key}")
                if f.kind == "bits":
                    note.append(f"b{f.width}")
                if f.cond is not None:
                    note.append("if " + str(f.cond))
                comment = f" /* {'; '.join(note)} */" if note else ""
                if f.repeat is not None:
                    h(f"    {ctype} {f.id}[{max(f.repeat, 1)}];{comment}")
                    h(f"    size_t {f.id}_count;")
                    names |= {f.id, f.id + "_count"}
                else:
                    h(f"    {ctype} {f.id};{comment}")
                    names.add(f.id)
                if f.cond is not None:
                    if self.present(f.id) in names or any(x.id == self.present(f.id) for x in t.fields):
                        raise GenError(f"{t.ksy_name}: member name clash on {self.present(f.id)}")
                    h(f"    bool {self.present(f.id)};")
                    names.add(self.present(f.id))
            for name in sorted(self.parse_instances_used.get(t.cname, ())):
                if name in names or self.present(name) in names:
                    raise GenError(f"{t.ksy_name}: member name clash on instance {name}")
                h(f"    {self.parse_instance_ctype(t, name)} {name}; /* instance, pos {t.instances[name]['pos']} */")
                names.add(name)
                if "if" in t.instances[name]:
                    h(f"    bool {self.present(name)};")
                    names.add(self.present(name))
            h(f"}} {t.cname}_t;")
            h()
        return h.text()

    # ---- parse functions -------------------------------------------------------------------

    def parse_signature(self, t: TypeSpec) -> str:
        args = ["osdk_stream_t *io", f"{t.cname}_t *self", *self.context_args(t)]
        for p in t.params:
            args.append(f"{self.param_ctype(p.ptype)} {p.id}")
        args.append("osdk_error_t *err")
        return f"osdk_status_t {t.cname}_parse({', '.join(args)})"

    def call_args(self, t: TypeSpec, ref: TypeRef, stream: str, target_lval: str) -> str:
        c = ref.target
        args = [stream, f"&{target_lval}"]
        if c.cname in self.parent_of:
            if self.parent_of[c.cname] is not t:
                raise GenError(f"{c.ksy_name}: _parent type mismatch")
            args.append("self")
        if self.needs_root[c.cname]:
            args.append("self" if t.is_file_root else "root")
        for p, a in zip(c.params, ref.args):
            want = "bool" if p.ptype == "bool" else "int"
            args.append(f"({self.param_ctype(p.ptype)})({self.tr(t, a, want)})")
        args.append("err")
        return ", ".join(args)

    def fail(self, t: TypeSpec, f: FieldSpec, status: str, stream: str = "io") -> str:
        return f"return osdk_fail(err, {status}, {c_string(t.ksy_name)}, {c_string(f.id)}, {stream});"

    def gen_read(self, L: Lines, t: TypeSpec, f: FieldSpec, lval: str) -> None:
        """Code that reads one value of field f into lval (and checks `valid`)."""
        trunc = self.fail(t, f, "OSDK_ERR_TRUNCATED_PAYLOAD")
        typed: Optional[Typed] = None
        if f.kind == "int":
            L(f"if (!osdk_read_uint(io, {f.width}, {int(f.endian == 'be')}, &u)) {trunc}")
            if f.signed:
                L(f"{lval} = ({self.member_ctype(t, f)})osdk_sign_extend(u, {8 * f.width});")
            else:
                L(f"{lval} = ({self.member_ctype(t, f)})u;")
            typed = self.field_typed(t, f, lval, element=True)
        elif f.kind == "float":
            L(f"if (!osdk_read_uint(io, {f.width}, {int(f.endian == 'be')}, &u)) {trunc}")
            if f.width == 4:
                L(f"{lval}.bits = (uint32_t)u;")
                L(f"{lval}.value = osdk_f32_from_bits({lval}.bits);")
            else:
                L(f"{lval}.bits = u;")
                L(f"{lval}.value = osdk_f64_from_bits({lval}.bits);")
        elif f.kind == "bits":
            L(f"if (!osdk_read_bits_le(io, {f.width}, &u)) {trunc}")
            if f.is_bool:
                L(f"{lval} = (u != 0);")
            else:
                L(f"{lval} = ({self.member_ctype(t, f)})u;")
            typed = self.field_typed(t, f, lval, element=True)
        elif f.kind == "contents":
            n = len(f.contents)
            L(f"if (!osdk_read_bytes(io, {n}, &{lval})) {trunc}")
            differs = " || ".join(f"{lval}.ptr[{i}] != 0x{b:02x}" for i, b in enumerate(f.contents))
            L(f"if ({differs}) {self.fail(t, f, self.class_of_field(f.id))}")
        elif f.kind == "bytes":
            if f.size_eos:
                L(f"osdk_read_bytes_eos(io, &{lval});")
            else:
                L("{")
                L(f"    int64_t n = {self.tr(t, f.size, 'int')};")
                L(f"    if (n < 0) {self.fail(t, f, 'OSDK_ERR_UNDECODABLE')}")
                L(f"    if (!osdk_read_bytes(io, (uint64_t)n, &{lval})) {trunc}")
                L("}")
            typed = Typed(lval, "bytes")
        elif f.kind == "struct":
            L("{")
            L.depth += 1
            stream = "io"
            if f.size is not None or f.size_eos:
                self.gen_substream(L, t, f)
                stream = "&sub"
            L(f"osdk_status_t st = {f.ref.target.cname}_parse({self.call_args(t, f.ref, stream, lval)});")
            L("if (st != OSDK_OK) return st;")
            L.depth -= 1
            L("}")
        elif f.kind == "switch":
            self.gen_switch(L, t, f, lval)
        else:
            raise GenError(f"{t.ksy_name}.{f.id}: cannot read kind {f.kind}")
        if f.valid is not None:
            if typed is None:
                raise GenError(f"{t.ksy_name}.{f.id}: valid on a {f.kind} field")
            pred = self.valid_predicates.get((t.cname, f.id))
            cond = f"{pred}({typed.c})" if pred else self.valid_expr(t, f, typed)
            L(f"if (!({cond})) {self.fail(t, f, self.class_of_field(f.id))}")

    def gen_substream(self, L: Lines, t: TypeSpec, f: FieldSpec) -> None:
        L("osdk_stream_t sub;")
        if f.size_eos:
            L("osdk_substream_eos(io, &sub);")
        else:
            L(f"int64_t n = {self.tr(t, f.size, 'int')};")
            L(f"if (n < 0) {self.fail(t, f, 'OSDK_ERR_UNDECODABLE')}")
            L(f"if (!osdk_substream(io, (uint64_t)n, &sub)) {self.fail(t, f, 'OSDK_ERR_TRUNCATED_PAYLOAD')}")

    def gen_switch(self, L: Lines, t: TypeSpec, f: FieldSpec, lval: str) -> None:
        members = {target.cname: m for m, target in self.switch_members(t, f)}
        sized = f.size is not None or f.size_eos
        L("{")
        L.depth += 1
        stream = "io"
        if sized:
            self.gen_substream(L, t, f)
            stream = "&sub"
        L(f"int64_t on = {self.tr(t, f.switch_on, 'int')};")
        first = True
        for case in f.cases:
            if isinstance(case.key, bool):
                raise GenError(f"{t.ksy_name}.{f.id}: boolean case keys are not supported")
            key = self.tr(t, case.key, "int")
            m = members[case.type.target.cname]
            L(f"{'if' if first else '} else if'} (on == {key}) {{")
            first = False
            self._switch_case(L, t, f, lval, m, case.type, stream)
        if not first:
            L("} else {")
        else:
            L("{")
        if f.default is not None:
            self._switch_case(L, t, f, lval, members[f.default.target.cname], f.default, stream)
        elif sized:
            L(f"    {lval}.tag = {self.switch_tag(t, f, 'raw')};")
            L(f"    {lval}.u.raw.ptr = sub.data;")
            L(f"    {lval}.u.raw.len = sub.size;")
        else:
            L(f"    {lval}.tag = {self.switch_tag(t, f, 'none')};")
        L("}")
        if not sized:
            L("(void)on;")
        L.depth -= 1
        L("}")

    def _switch_case(self, L: Lines, t: TypeSpec, f: FieldSpec, lval: str, m: str, ref: TypeRef, stream: str) -> None:
        L.depth += 1
        L("osdk_status_t st;")
        L(f"{lval}.tag = {self.switch_tag(t, f, m)};")
        L(f"st = {ref.target.cname}_parse({self.call_args(t, ref, stream, lval + '.u.' + m)});")
        L("if (st != OSDK_OK) return st;")
        L.depth -= 1

    def context_args(self, t: TypeSpec) -> list[str]:
        """The parent and root a parse function of t is given, as parameters."""
        args = []
        if t.cname in self.parent_of:
            args.append(f"const {self.parent_of[t.cname].cname}_t *parent")
        if self.needs_root[t.cname]:
            args.append(f"const {self.root_of(t).cname}_t *root")
        return args

    def parse_contract(self, t: TypeSpec) -> str:
        """What a parse function of t (or of one of its fields) needs and does:
        `make prove` proves it of each, and assumes it at each call."""
        reads = [a.rsplit("*", 1)[1] for a in self.context_args(t)]
        lines = ["/*@ requires osdk_stream_ok(io) && \\valid(self) && \\separated(io, self);",
                 "    requires err == \\null || (\\valid(err) && \\separated(err, io, self));"]
        if reads:
            lines.append("    requires " + " && ".join(f"\\valid_read({r})" for r in reads) + ";")
        lines += ["    assigns *io, *self, *err;",
                  "    ensures \\result == OSDK_OK ==> osdk_stream_on(io, \\old(io->data), \\old(io->size)); */"]
        return "\n".join(lines)

    def gen_parse(self, t: TypeSpec) -> str:
        """One static function per field, then the parse function that calls
        them in order. Small functions are what keeps the proof tractable: a
        parse function's goals then follow from the contract of the call just
        before, not from every read and write since its start; gcc and clang
        inline them back."""
        L = Lines()
        L(f"/* {t.ksy_name} */")
        L("/*@ requires \\valid(self);")
        L("    assigns *self; */")
        L.func(f"static void {t.cname}__zero({t.cname}_t *self)")
        L(f"static const {t.cname}_t zero;")
        L("*self = zero;")
        L.close()
        L()
        context = [a.rsplit("*", 1)[1] for a in self.context_args(t)]
        reader_args = ", ".join(["io", "self", *context, "err"])
        readers = []
        for f in t.fields:
            name = f"{t.cname}__read_{f.id}"
            readers.append(name)
            L(self.parse_contract(t))
            L.func(f"static osdk_status_t {name}({', '.join(['osdk_stream_t *io', f'{t.cname}_t *self', *self.context_args(t), 'osdk_error_t *err'])})")
            L("uint64_t u = 0;")
            if f.cond is not None:
                self._wanted = set()
                cond = self.tr(t, f.cond, 'bool')
                self.gen_instance_reads(L, t, self._wanted)
                L(f"self->{self.present(f.id)} = {cond};")
                L.open(f"if (self->{self.present(f.id)}) {{")
            body = Lines()
            body.depth = L.depth
            self._wanted = set()
            if f.repeat is not None:
                body(f"self->{f.id}_count = {f.repeat};")
                body(f"/*@ loop invariant 0 <= i <= {f.repeat} && osdk_stream_ok(io);")
                body("    loop invariant osdk_stream_on(io, \\at(io->data, Pre), \\at(io->size, Pre));")
                body("    loop assigns i, u, *io, *self;")
                body(f"    loop variant {f.repeat} - i; */")
                body.open(f"for (size_t i = 0; i < {f.repeat}; i++) {{")
                self.gen_read(body, t, f, f"self->{f.id}[i]")
                body.close()
            else:
                self.gen_read(body, t, f, f"self->{f.id}")
            self.gen_instance_reads(L, t, self._wanted)
            L.out.extend(body.out)
            if f.cond is not None:
                L.close()
            for unused in ["u", *context, "err"]:
                L(f"(void){unused};")
            L("return OSDK_OK;")
            L.close()
            L()
        L.func(self.parse_signature(t))
        if readers:
            L("osdk_status_t st;")
        L(f"{t.cname}__zero(self);")
        for p in t.params:
            L(f"self->{p.id} = {p.id};")
        for name in readers:
            L(f"st = {name}({reader_args});")
            L("if (st != OSDK_OK) return st;")
        for unused in [*context, "io", "err"] if not readers else []:
            L(f"(void){unused};")
        L("return OSDK_OK;")
        L.close()
        L()
        return L.text()

    def gen_valid_predicates(self) -> tuple[str, str]:
        """Public predicates for the `valid` of integer fields that depend on
        the value alone (the receiver uses those of the frame header)."""
        h, c = Lines(), Lines()
        for t in self.types:
            for f in t.fields:
                if f.valid is None or f.kind not in ("int", "bits") or f.is_bool or f.repeat is not None:
                    continue
                texts = [f.valid["expr"]] if isinstance(f.valid, dict) and "expr" in f.valid else []
                if any(names_used(x) - {"_"} for x in texts if isinstance(x, str)):
                    continue
                if isinstance(f.valid, dict) and set(f.valid) - {"expr", "eq", "min", "max"}:
                    continue
                name = f"{t.cname}_valid_{f.id}"
                expr = self.valid_expr(t, f, Typed("v", f"enum:{f.enum.key}" if f.enum else "int"))
                h(f"/* `valid` of {t.ksy_name}.{f.id}: {f.valid!r} */")
                h("/*@ assigns \\nothing; */")
                h(f"bool {name}(int64_t v);")
                c.func(f"bool {name}(int64_t v)")
                c(f"return {expr};")
                c.close()
                c()
                self.valid_predicates[(t.cname, f.id)] = name
        return h.text(), c.text()

    def gen_instances(self) -> str:
        L = Lines()
        for cname in sorted(self.instances_used):
            for name, ctype, cexpr in self.instances_used[cname]:
                L("/*@ requires \\valid_read(self);")
                L("    assigns \\nothing; */")
                L(f"static {ctype} {cname}__{name}(const {cname}_t *self)")
                L("{")
                L(f"    return {cexpr};")
                L("}")
                L()
        return L.text()

    def gen_decode_wrappers(self) -> tuple[str, str]:
        h, c = Lines(), Lines()
        for t in self.types:
            if not t.is_file_root:
                continue
            params = "".join(f", {self.param_ctype(p.ptype)} {p.id}" for p in t.params)
            names = "".join(f", {p.id}" for p in t.params)
            sig = (f"osdk_status_t {t.cname}_decode(const uint8_t *buf, size_t len{params}, "
                   f"{t.cname}_t *out, osdk_error_t *err)")
            h(f"/* Decode a whole {t.name} from buf[0..len). */")
            h("/*@ requires buf == \\null || len == 0 || \\valid_read(buf + (0 .. len - 1));")
            h("    requires \\valid(out) && (err == \\null || (\\valid(err) && \\separated(err, out)));")
            h("    assigns *out, *err; */")
            h(sig + ";")
            c.func(sig)
            c("osdk_stream_t io;")
            c("osdk_stream_init(&io, buf, len);")
            c("if (err) osdk_error_clear(err);")
            c(f"return {t.cname}_parse(&io, out{names}, err);")
            c.close()
            c()
        return h.text(), c.text()

    # ---- JSON ----------------------------------------------------------------------------------

    def gen_json_value(self, L: Lines, t: TypeSpec, f: FieldSpec, lval: str) -> None:
        if f.kind in ("int", "bits"):
            if f.enum is not None:
                L(f"osdk_json_enum(w, (int64_t){lval}, {f.enum.cname}_name((int64_t){lval}));")
            elif f.is_bool:
                L(f"osdk_json_bool(w, {lval});")
            elif f.kind == "int" and f.signed:
                L(f"osdk_json_int(w, (int64_t){lval});")
            else:
                L(f"osdk_json_uint(w, (uint64_t){lval});")
        elif f.kind == "float":
            L(f"osdk_json_f{32 if f.width == 4 else 64}(w, {lval}.bits);")
        elif f.kind in ("bytes", "contents"):
            L(f"osdk_json_hex(w, {lval}.ptr, {lval}.len);")
        elif f.kind == "struct":
            L(f"{f.ref.target.cname}_to_json(&{lval}, w);")
        elif f.kind == "switch":
            L.open(f"switch ({lval}.tag) {{")
            for m, target in self.switch_members(t, f):
                L(f"case {self.switch_tag(t, f, m)}: {target.cname}_to_json(&{lval}.u.{m}, w); break;")
            if f.size is not None or f.size_eos:
                L(f"case {self.switch_tag(t, f, 'raw')}: osdk_json_hex(w, {lval}.u.raw.ptr, {lval}.u.raw.len); break;")
            L("default: osdk_json_null(w); break;")
            L.close()

    def gen_json(self) -> tuple[str, str]:
        h, c = Lines(), Lines()
        for t in self.types:
            sig = f"void {t.cname}_to_json(const {t.cname}_t *self, osdk_json_t *w)"
            h(sig + ";")
            c(f"/* {t.ksy_name} */")
            c.func(sig)
            c("osdk_json_begin_object(w);")
            for f in t.fields:
                if f.id in self.skipped:
                    continue
                if f.cond is not None:
                    c.open(f"if (self->{self.present(f.id)}) {{")
                c(f"osdk_json_key(w, {c_string(f.id)});")
                if f.repeat is not None:
                    c("osdk_json_begin_array(w);")
                    c.open(f"for (size_t i = 0; i < self->{f.id}_count; i++) {{")
                    self.gen_json_value(c, t, f, f"self->{f.id}[i]")
                    c.close()
                    c("osdk_json_end_array(w);")
                else:
                    self.gen_json_value(c, t, f, f"self->{f.id}")
                if f.cond is not None:
                    c.close()
            c("osdk_json_end_object(w);")
            c.close()
            c()
            sig = f"bool {t.cname}_field_to_json(const {t.cname}_t *self, const char *field, osdk_json_t *w)"
            h(sig + ";")
            c(f"/* {t.ksy_name}: the model of one field; false when it has no such field or it is absent */")
            c.func(sig)
            for f in t.fields:
                cond = f" && self->{self.present(f.id)}" if f.cond is not None else ""
                c.open(f"if (strcmp(field, {c_string(f.id)}) == 0{cond}) {{")
                if f.repeat is not None:
                    c("osdk_json_begin_array(w);")
                    c.open(f"for (size_t i = 0; i < self->{f.id}_count; i++) {{")
                    self.gen_json_value(c, t, f, f"self->{f.id}[i]")
                    c.close()
                    c("osdk_json_end_array(w);")
                else:
                    self.gen_json_value(c, t, f, f"self->{f.id}")
                c("return true;")
                c.close()
            c("return false;")
            c.close()
            c()
        return h.text(), c.text()

    # ---- Python objects (the accelerator of osdk_conformance) ----------------------------------

    def py_keys(self) -> list[str]:
        """Every dict key the Python model can hold: field ids, then the keys of enums and floats."""
        keys: list[str] = []
        for t in self.types:
            for f in t.fields:
                if f.id not in self.skipped and f.id not in keys:
                    keys.append(f.id)
        for k in PY_MODEL_KEYS:
            if k not in keys:
                keys.append(k)
        return keys

    @staticmethod
    def py_key(key: str) -> str:
        return f"osdk_py_keys[OSDK_PY_K_{key.upper()}]"

    def gen_py_value(self, t: TypeSpec, f: FieldSpec, lval: str) -> str:
        """A C expression giving a new reference to the model of one value (NULL on failure)."""
        if f.kind in ("int", "bits"):
            if f.enum is not None:
                return f"osdk_py_enum((int64_t){lval}, {f.enum.cname}_name((int64_t){lval}))"
            if f.is_bool:
                return f"osdk_py_bool({lval})"
            if f.kind == "int" and f.signed:
                return f"PyLong_FromLongLong((long long){lval})"
            return f"PyLong_FromUnsignedLongLong((unsigned long long){lval})"
        if f.kind == "float":
            return f"osdk_py_f{32 if f.width == 4 else 64}({lval}.bits)"
        if f.kind in ("bytes", "contents"):
            return f"osdk_py_hex({lval}.ptr, {lval}.len)"
        if f.kind == "struct":
            return f"{f.ref.target.cname}_to_py(&{lval})"
        raise GenError(f"{t.ksy_name}.{f.id}: no Python model for kind {f.kind}")

    def gen_py(self) -> tuple[str, str]:
        h, c = Lines(), Lines()
        for t in self.types:
            h(f"PyObject *{t.cname}_to_py(const {t.cname}_t *self);")
        for t in self.types:
            kept = [f for f in t.fields if f.id not in self.skipped]
            c(f"/* {t.ksy_name} */")
            c.func(f"PyObject *{t.cname}_to_py(const {t.cname}_t *self)")
            c(f"PyObject *d = OSDK_PY_NEW_DICT({len(kept)});")
            c("if (d == NULL) return NULL;")
            for f in kept:
                if f.cond is not None:
                    c.open(f"if (self->{self.present(f.id)}) {{")
                key = self.py_key(f.id)
                if f.repeat is not None:
                    c.open("{")
                    c(f"PyObject *list = PyList_New((Py_ssize_t)self->{f.id}_count);")
                    c(f"if (osdk_py_put(d, {key}, list) < 0) goto fail;")
                    c.open(f"for (size_t i = 0; i < self->{f.id}_count; i++) {{")
                    c(f"PyObject *item = {self.gen_py_value(t, f, f'self->{f.id}[i]')};")
                    c("if (item == NULL) goto fail;")
                    c("PyList_SET_ITEM(list, (Py_ssize_t)i, item);")
                    c.close()
                    c.close()
                elif f.kind == "switch":
                    c.open("{")
                    c("PyObject *v;")
                    c.open(f"switch (self->{f.id}.tag) {{")
                    for m, target in self.switch_members(t, f):
                        c(f"case {self.switch_tag(t, f, m)}: v = {target.cname}_to_py(&self->{f.id}.u.{m}); break;")
                    if f.size is not None or f.size_eos:
                        c(f"case {self.switch_tag(t, f, 'raw')}: "
                          f"v = osdk_py_hex(self->{f.id}.u.raw.ptr, self->{f.id}.u.raw.len); break;")
                    c("default: v = Py_NewRef(Py_None); break;")
                    c.close()
                    c(f"if (osdk_py_put(d, {key}, v) < 0) goto fail;")
                    c.close()
                else:
                    c(f"if (osdk_py_put(d, {key}, {self.gen_py_value(t, f, f'self->{f.id}')}) < 0) goto fail;")
                if f.cond is not None:
                    c.close()
            # see osdk_py_untracked: only a dict that holds no list leaves the collector
            c("return osdk_py_untracked(d);" if all(f.repeat is None for f in kept) else "return d;")
            c.close("fail:")
            c.depth += 1
            c("Py_DECREF(d);")
            c("return NULL;")
            c.close()
            c()
        return h.text(), c.text()

    # ---- the broadcast as columns (for tables) ------------------------------------------

    def broadcast_switch(self) -> tuple[TypeSpec, FieldSpec]:
        """The payload's broadcast type and its data switch, whose cases are the profiles' layouts."""
        for t in self.types:
            if t.ksy_name == BROADCAST_TYPE:
                for f in t.fields:
                    if f.kind == "switch":
                        return t, f
        raise GenError(f"{BROADCAST_TYPE}: no switch on the profile")

    def column_leaves(self, t: TypeSpec, access: str, prefix: str, present: list[str], item: Optional[str],
                      out: list[dict]) -> None:
        """Every leaf of `t` as a column: its dotted name, its item (the root's field),
        its element type, its enum, the C expression of its value and of its presence.
        At the root the flag bits that only say whether an item is there (the fields
        that other fields' `if` name) and the checked fields are left out: a column's
        validity already says it."""
        conds = {n for g in t.fields if g.cond is not None for n in names_used(g.cond)}
        checked = set(self.tables["checked_fields"].get(t.cname, ()))
        for f in t.fields:
            if f.id in self.skipped or (item is None and (f.id in conds or f.id in checked)):
                continue
            name, here = prefix + f.id, present + ([f"{access}{self.present(f.id)}"] if f.cond is not None else [])
            leaf_item = item or f.id
            if f.repeat is not None or f.kind in ("bytes", "contents", "switch"):
                raise GenError(f"{t.ksy_name}.{f.id}: a broadcast column cannot hold a {f.kind}")
            if f.kind == "struct":
                self.column_leaves(f.ref.target, f"{access}{f.id}.", name + ".", here, leaf_item, out)
                continue
            if f.kind == "float":
                ctype, code, value = ("uint32_t", "F32", f"{access}{f.id}.bits") if f.width == 4 else \
                                     ("uint64_t", "F64", f"{access}{f.id}.bits")
            elif f.is_bool:
                ctype, code, value = "uint8_t", "BOOL", f"{access}{f.id}"
            else:
                bits = 8 * f.width if f.kind == "int" else max(8, 1 << (f.width - 1).bit_length())
                signed = f.kind == "int" and f.signed
                ctype = f"{'int' if signed else 'uint'}{bits}_t"
                code, value = f"{'I' if signed else 'U'}{bits}", f"{access}{f.id}"
            out.append({"name": name, "item": leaf_item, "ctype": ctype, "code": code,
                        "enum": f.enum.key if f.enum is not None else None, "value": value,
                        "present": " && ".join(here) or "true"})

    def gen_columns(self) -> tuple[str, str]:
        """The broadcast of each profile as one row of typed columns (osdk_columns.h)."""
        bt, sw = self.broadcast_switch()
        profile_enum = next(p.enum for p in bt.params if p.id == sw.switch_on)
        value_of = {name: value for value, name in profile_enum.values}
        h, c, items_c = Lines(), Lines(), Lines()
        item_types: dict[str, str] = {}
        by_profile: list[tuple[int, str, TypeSpec]] = []
        for case in sw.cases:
            key = str(case.key)
            enum_name = key.split("::")[-1]
            if enum_name not in value_of:
                raise GenError(f"{bt.ksy_name}.{sw.id}: case {key} is not a value of {profile_enum.key}")
            by_profile.append((value_of[enum_name], self.switch_tag(bt, sw, case.type.target.name), case.type.target))
        for _, _, t in by_profile:
            leaves: list[dict] = []
            self.column_leaves(t, "self->", "", [], None, leaves)
            items = list(dict.fromkeys(leaf["item"] for leaf in leaves))
            c(f"/* {t.ksy_name} */")
            c(f"static const osdk_column_t {t.cname}_columns[{len(leaves)}] = {{")
            for leaf in leaves:
                enum = c_string(leaf["enum"]) if leaf["enum"] else "NULL"
                c(f"    {{{c_string(leaf['name'])}, {items.index(leaf['item'])}, OSDK_COL_{leaf['code']}, {enum}}},")
            c("};")
            c(f"static const char *const {t.cname}_items[{len(items)}] = {{{', '.join(c_string(i) for i in items)}}};")
            c(f"static const osdk_column_set_t {t.cname}_column_set = "
              f"{{{t.cname}_columns, {len(leaves)}, {t.cname}_items, {len(items)}}};")
            c()
            # an item's leaves are written by one function per item type, which the profiles share
            c.func(f"static void {t.cname}_row(const {t.cname}_t *self, void *const *cols, uint8_t *const *valid, size_t row)")
            fields = {f.id: f for f in t.fields}
            if any(fields[item].kind != "struct" for item in items):
                c("bool p;")
            base = 0
            for item in items:
                mine = [leaf for leaf in leaves if leaf["item"] == item]
                f = fields[item]
                if f.kind == "struct":
                    target = f.ref.target
                    if target.cname not in item_types:
                        item_types[target.cname] = self.item_columns(target, item)
                        items_c(item_types[target.cname])
                    present = f"self->{self.present(f.id)}" if f.cond is not None else "true"
                    c(f"{target.cname}_cols(&self->{f.id}, {present}, cols + {base}, valid + {base}, row);")
                else:
                    self.column_writes(c, mine, base)
                base += len(mine)
            c.close()
            c()
        c.func("const osdk_column_set_t *osdk_broadcast_columns(uint8_t profile)")
        c.open("switch (profile) {")
        for value, _, t in by_profile:
            c(f"case {value}: return &{t.cname}_column_set;")
        c("default: return NULL;")
        c.close()
        c.close()
        c()
        c.func(f"bool osdk_broadcast_row(const {bt.cname}_t *b, void *const *cols, uint8_t *const *valid, size_t row)")
        c.open(f"switch (b->{sw.id}.tag) {{")
        for _, tag, t in by_profile:
            c(f"case {tag}: {t.cname}_row(&b->{sw.id}.u.{t.name}, cols, valid, row); return true;")
        c("default: return false;")
        c.close()
        c.close()
        h(f"/* The columns of the broadcast of `profile` (a value of {profile_enum.key}), NULL for none. */")
        h("const osdk_column_set_t *osdk_broadcast_columns(uint8_t profile);")
        h()
        h("/* Writes a decoded broadcast as row `row` of the columns of its profile: cols[i] is")
        h(" * column i's array of its element type, valid[i] its presence bytes (1 present, 0")
        h(" * absent; an absent value is written as 0). False when `b` holds no layout. */")
        h(f"bool osdk_broadcast_row(const {bt.cname}_t *b, void *const *cols, uint8_t *const *valid, size_t row);")
        return h.text(), items_c.text() + c.text()

    @staticmethod
    def column_writes(c: Lines, leaves: list[dict], base: int) -> None:
        for i, leaf in enumerate(leaves, base):
            c(f"p = {leaf['present']};")
            c(f"(({leaf['ctype']} *)cols[{i}])[row] = p ? ({leaf['ctype']}){leaf['value']} : 0;")
            c(f"valid[{i}][row] = p;")

    def item_columns(self, t: TypeSpec, item: str) -> str:
        """`<type>_cols()`: the leaves of an item type from cols[0] on, present where `present` and their own `if` say."""
        leaves: list[dict] = []
        self.column_leaves(t, "self->", "", ["present"], item, leaves)
        c = Lines()
        c(f"/* {t.ksy_name}: its leaves, in the columns from cols[0] on */")
        c.func(f"static void {t.cname}_cols(const {t.cname}_t *self, bool present, void *const *cols, "
               f"uint8_t *const *valid, size_t row)")
        c("bool p;")
        self.column_writes(c, leaves, 0)
        c.close()
        return c.text()

    def render_python(self) -> dict[str, str]:
        """The files of generated/cpython/: the value model as Python objects."""
        keys = self.py_keys()
        py_h, py_c = self.gen_py()
        columns_h, columns_c = self.gen_columns()
        values = {
            "banner": BANNER,
            "key_enum": "\n".join(f"    OSDK_PY_K_{k.upper()} = {i}," for i, k in enumerate(keys)),
            "key_count": str(len(keys)),
            "key_names": self._wrap([c_string(k) for k in keys], per=6),
            "py_h": py_h, "py_c": py_c,
            "columns_h": columns_h, "columns_c": columns_c,
        }
        files = {}
        for tpl in sorted((TEMPLATES / "cpython").glob("*.in")):
            files[tpl.name[:-3]] = string.Template(tpl.read_text(encoding="utf-8")).substitute(values)
        return files

    # ---- frame header (receiver) --------------------------------------------------------------

    def frame_prefix(self) -> tuple[int, dict[str, tuple[int, int]]]:
        """Bit offset and width of each field of the frame's fixed-size prefix."""
        t = self.spec.types[(FRAME_TYPE, ())]
        bit = 0
        out: dict[str, tuple[int, int]] = {}
        for f in t.fields:
            if f.cond is not None or f.repeat is not None or f.kind not in ("contents", "int", "bits", "float"):
                break
            if f.kind == "bits":
                out[f.id] = (bit, f.width)
                bit += f.width
                continue
            bit = (bit + 7) // 8 * 8
            if f.kind == "contents":
                width = 8 * len(f.contents)
            else:
                if f.endian != "le":
                    raise GenError(f"{t.ksy_name}.{f.id}: the header prefix must be little-endian")
                width = 8 * f.width
            out[f.id] = (bit, width)
            bit += width
        if bit % 8:
            raise GenError(f"{t.ksy_name}: the fixed header prefix is not whole bytes")
        return bit // 8, out

    def gen_frame_header(self) -> tuple[str, str, dict]:
        t = self.spec.types[(FRAME_TYPE, ())]
        prefix_len, fields = self.frame_prefix()
        h, c = Lines(), Lines()
        h(f"/* The fixed-size prefix (header) of {t.ksy_name}: {prefix_len} bytes. */")
        h(f"#define {FRAME_TYPE.upper()}_HEADER_LEN {prefix_len}u")
        sof = t.fields[0]
        if sof.kind != "contents" or len(sof.contents) != 1:
            raise GenError(f"{t.ksy_name}: the first field must be a one-byte start-of-frame `contents`")
        h(f"/* start byte ({sof.id} contents) */")
        h(f"#define {FRAME_TYPE.upper()}_SOF 0x{sof.contents[0]:02x}u")
        for fid, (off, width) in fields.items():
            h(f"/* {fid}: bits {off}..{off + width - 1} of the header, read without checks. */")
            h(f"/*@ requires \\valid_read(header + (0 .. {FRAME_TYPE.upper()}_HEADER_LEN - 1));")
            h(f"    assigns \\nothing; */")
            h(f"uint64_t {FRAME_TYPE}_peek_{fid}(const uint8_t *header);")
            c.func(f"uint64_t {FRAME_TYPE}_peek_{fid}(const uint8_t *header)")
            c(f"return osdk_peek_bits_le(header, {off}, {width});")
            c.close()
            c()
        recv = self.rules["frame"]["receiver"]["header_checks"]
        lenf = next(f for f in t.fields if f.id == "len")
        h(f"#define {FRAME_TYPE.upper()}_MAX_LEN {(1 << lenf.width) - 1}u")
        checks = [x for x in recv if x not in ("sof", "crc16")]
        for x in checks:
            if (t.cname, x) not in self.valid_predicates:
                raise GenError(f"receiver header check {x}: the field has no value-only `valid`")
            if x not in fields:
                raise GenError(f"receiver header check {x}: not in the fixed header")
        if "crc16" not in recv:
            raise GenError("the receiver's header checks do not include crc16")
        crc = self.tables["crc"]["crc16"]
        first, last = crc["covers"]
        s0, s1 = crc["stored_at"]
        if (s0 * 8, (s1 - s0 + 1) * 8) != fields["crc16"]:
            raise GenError("crc16 stored_at does not match the crc16 field of the frame header")
        L = Lines()
        L(f"uint16_t computed = osdk_crc16(header + {first}, {last - first + 1}u);")
        L(f"uint64_t stored = {FRAME_TYPE}_peek_crc16(header);")
        L("if ((uint64_t)computed != stored) {")
        L('    DETAIL(detail, cap, "CRC-16 is 0x%04x, expected 0x%04x", stored, computed);')
        L("    return OSDK_ERR_BAD_CRC16;")
        L("}")
        for x in checks:
            L("{")
            L(f"    uint64_t v = {FRAME_TYPE}_peek_{x}(header);")
            L(f"    if (!{self.valid_predicates[(t.cname, x)]}((int64_t)v)) {{")
            L(f'        DETAIL(detail, cap, "header field {x} is %lu, which its valid check rejects", v, 0);')
            L(f"        return {self.class_of_field(x)};")
            L("    }")
            L("}")
        checks_code = "\n".join("    " + line if line else "" for line in L.out)
        c32 = self.tables["crc"]["crc32"]
        if list(c32["covers"]) != [0, -5] or list(c32["stored_at"]) != [-4, -1]:
            raise GenError("the deframer expects CRC-32 over every byte before its last 4 bytes")
        return h.text(), c.text(), {"header_checks": checks_code, "FRAME_TYPE_HEADER_LEN": str(prefix_len)}

    # ---- CRC ---------------------------------------------------------------------------------------

    def gen_crc(self) -> dict:
        out = {}
        for name in ("crc16", "crc32"):
            p = self.tables["crc"][name]
            width, mask = p["width"], (1 << p["width"]) - 1
            if width not in (16, 32):
                raise GenError(f"{name}: width {width} is not supported")
            ctype = f"uint{width}_t"
            table = []
            if p["reflect_in"]:
                poly = int(f"{p['poly']:0{width}b}"[::-1], 2)
                for b in range(256):
                    r = b
                    for _ in range(8):
                        r = (r >> 1) ^ poly if r & 1 else r >> 1
                    table.append(r)
                step = f"reg = (({ctype})(reg >> 8)) ^ {name}_table[(reg ^ data[i]) & 0xffu];"
            else:
                top = 1 << (width - 1)
                for b in range(256):
                    r = b << (width - 8)
                    for _ in range(8):
                        r = ((r << 1) ^ p["poly"]) & mask if r & top else (r << 1) & mask
                    table.append(r)
                step = (f"reg = ({ctype})((({ctype})(reg << 8)) ^ "
                        f"{name}_table[((reg >> {width - 8}) ^ data[i]) & 0xffu]);")
            digits = width // 4
            rows = []
            for i in range(0, 256, 8):
                rows.append("    " + ", ".join(f"0x{v:0{digits}x}u" for v in table[i:i + 8]) + ",")
            out[f"{name}_table"] = "\n".join(rows)
            out[f"{name}_step"] = step
            out[f"{name}_init"] = f"0x{p['init'] & mask:0{digits}x}u"
            out[f"{name}_xorout"] = f"0x{p['xorout']:0{digits}x}u"
            out[f"{name}_check"] = f"0x{p['check']:0{digits}x}u"
            if p["reflect_out"] != p["reflect_in"]:
                raise GenError(f"{name}: reflect_out different from reflect_in is not supported")
            out[f"{name}_final"] = "/* reflect_out equals reflect_in: no final reflection */"
            out[f"{name}_params"] = (f"width {width}, poly 0x{p['poly']:x}, init 0x{p['init']:x} (register), "
                                     f"reflect_in {str(p['reflect_in']).lower()}, reflect_out "
                                     f"{str(p['reflect_out']).lower()}, xorout 0x{p['xorout']:x}")
        return out

    # ---- rule tables -------------------------------------------------------------------------------

    def gen_rule_tables(self) -> dict:
        profiles = self.tables["profiles"]
        cm = self.tables["control_modes"]
        classes = ["documented", "undocumented", "later_firmware", "invalid"]
        seen = {m["classification"] for p in profiles for m in cm[p]["modes"]}
        if seen - set(classes):
            raise GenError(f"unknown control mode classifications {sorted(seen - set(classes))}")
        axes = sorted({a for p in profiles for r in cm[p]["ranges"].values() for a in r})
        max_comb = max(int(k) for p in profiles for k in cm[p]["ranges"])
        prof_enum = self.spec.enums.get(("osdk_payload", "profile"))
        out: dict[str, str] = {}
        out["profile_count"] = str(len(profiles))
        out["profile_ids"] = ", ".join(c_string(p) for p in profiles)
        out["class_enum"] = "\n".join(f"    OSDK_MODE_{c.upper()} = {i}," for i, c in enumerate(classes))
        out["class_names"] = ", ".join(c_string(c) for c in classes)
        out["class_count"] = str(len(classes))
        out["axis_enum"] = "\n".join(f"    OSDK_AXIS_{a.upper()} = {i}," for i, a in enumerate(axes))
        out["axis_names"] = ", ".join(c_string(a) for a in axes)
        out["axis_count"] = str(len(axes))
        out["max_combination"] = str(max_comb)
        mode_rows, comb_rows, range_rows = [], [], []
        for p in profiles:
            modes = cm[p]["modes"]
            if len(modes) != 256:
                raise GenError(f"control_modes.{p}: {len(modes)} mode bytes, not 256")
            cls = [str(classes.index(m["classification"])) for m in modes]
            comb = [str(m["combination"] if m["combination"] is not None else -1) for m in modes]
            mode_rows.append(f"    /* {p} */\n    {{" + self._wrap(cls) + "}")
            comb_rows.append(f"    /* {p} */\n    {{" + self._wrap(comb) + "}")
            prow = []
            for k in range(max_comb + 1):
                r = cm[p]["ranges"].get(str(k))
                if r is None:
                    prow.append("        {" + ", ".join("{0, 0.0, 0, 0.0}" for _ in axes) + "}")
                    continue
                cells = []
                for a in axes:
                    lim = r[a]
                    lo, hi = lim.get("min"), lim.get("max")
                    cells.append("{%d, %s, %d, %s}" % (lo is not None, self._num(lo), hi is not None, self._num(hi)))
                prow.append("        {" + ", ".join(cells) + f"}} /* combination {k} */")
            range_rows.append(f"    /* {p} */\n    {{\n" + ",\n".join(prow) + "\n    }")
        out["mode_class"] = ",\n".join(mode_rows)
        out["mode_combination"] = ",\n".join(comb_rows)
        out["ranges"] = ",\n".join(range_rows)
        cmds = self.tables["commands"]
        out["command_count"] = str(len(cmds))
        out["commands"] = "\n".join(f"    {{{c['cmd_set']}, {c['cmd_id']}, {c_string(c['name'])}}}," for c in cmds)
        # profile id -> the value the decoder takes (the tables' profile_values), which must be a
        # member of the spec's profile enum
        members = {v for v, _ in (prof_enum.values if prof_enum else [])}
        values = []
        for p in profiles:
            value = self.tables["profile_values"].get(p)
            if value not in members:
                raise GenError(f"profile {p}: value {value} is not a member of enum osdk_payload::profile")
            values.append(str(value))
        out["profile_enum_values"] = ", ".join(values)
        return out

    @staticmethod
    def _num(v) -> str:
        if v is None:
            return "0.0"
        return repr(float(v))

    @staticmethod
    def _wrap(items: list[str], per: int = 16) -> str:
        rows = [", ".join(items[i:i + per]) for i in range(0, len(items), per)]
        return "\n     " + ",\n     ".join(rows) + "\n    "

    # ---- whole output -------------------------------------------------------------------------------

    def render(self) -> dict[str, str]:
        enums_h, enums_c = self.gen_enums()
        valid_h, valid_c = self.gen_valid_predicates()
        parse_c = "".join(self.gen_parse(t) for t in self.types)
        structs_h = self.gen_structs()
        protos = "\n".join(self.parse_contract(t) + "\n" + self.parse_signature(t) + ";" for t in self.types) + "\n"
        wrap_h, wrap_c = self.gen_decode_wrappers()
        json_h, json_c = self.gen_json()
        hdr_h, hdr_c, deframer_vals = self.gen_frame_header()
        instances_c = self.gen_instances()
        status_enum = "\n".join(f"    {self.status(c)} = {i + 1}," for i, c in enumerate(self.classes))
        status_names = ", ".join(c_string(c) for c in self.classes)
        values = {
            "banner": BANNER,
            "status_enum": status_enum,
            "status_names": status_names,
            "status_count": str(len(self.classes) + 1),
            "enums_h": enums_h, "enums_c": enums_c,
            "structs_h": structs_h,
            "valid_h": valid_h, "valid_c": valid_c,
            "protos": protos,
            "parse_c": parse_c,
            "instances_c": instances_c,
            "wrap_h": wrap_h, "wrap_c": wrap_c,
            "json_h": json_h, "json_c": json_c,
            "header_h": hdr_h, "header_c": hdr_c,
            "frame_type": FRAME_TYPE,
            "FRAME_TYPE": FRAME_TYPE.upper(),
        }
        values.update(deframer_vals)
        values.update(self.gen_crc())
        values.update(self.gen_rule_tables())
        files = {}
        for tpl in sorted(TEMPLATES.glob("*.in")):
            text = string.Template(tpl.read_text(encoding="utf-8")).substitute(values)
            files[tpl.name[:-3]] = text
        return files


def main(argv: Optional[list[str]] = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True, help="directory to write the C sources into")
    ap.add_argument("--target", choices=("c", "cpython"), default="c",
                    help="c: the C99 decoder (generated/c); cpython: its value model as Python objects, "
                         "for the accelerator of osdk_conformance (generated/cpython)")
    args = ap.parse_args(argv)
    try:
        spec = Spec(ROOT / "spec")
        tables_tool = load_tables_module()
        tables = tables_tool.tables()
        rules_doc = yaml.load((ROOT / "spec" / "rules.yaml").read_text(encoding="utf-8"), Loader=SafeLoader)  # noqa: S506
        from osdk_conformance.core.model import SKIPPED_FIELDS
        gen = Generator(spec, tables, rules_doc, frozenset(SKIPPED_FIELDS))
        files = gen.render() if args.target == "c" else gen.render_python()
    except (SpecError, GenError, ExprError) as e:
        print(f"cgen: {e}", file=sys.stderr)
        return 1
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    for name, text in sorted(files.items()):
        (out / name).write_text(text, encoding="utf-8")
    return 0


if __name__ == "__main__":
    sys.exit(main())
