"""The .ksy subset this project uses, read into a form the C emitter can walk.

Every type of every spec/*.ksy file becomes a `TypeSpec` (its params, seq
fields and value instances); type and enum references are resolved the way
Kaitai resolves them (nested types of the current type and its ancestors,
then top-level types of the imported files). Anything outside the subset
(big-endian bit fields, repeat-until, process, pos instances used by the
seq, ...) raises SpecError: the generator refuses rather than guesses.
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Optional

import yaml

from osdk_conformance.core.ksy import SafeLoader  # libyaml's, where PyYAML has it
from expr import ExprError, const_value, names_used  # noqa: F401  (re-exported for generate.py)


class SpecError(Exception):
    pass


_INT = re.compile(r"^([us])([1248])(le|be)?$")
_FLOAT = re.compile(r"^f([48])(le|be)?$")
_BITS = re.compile(r"^b(\d+)(le|be)?$")
_CALL = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*(?:::[A-Za-z_][A-Za-z0-9_]*)*)(?:\((.*)\))?$", re.S)

FIELD_KEYS = {"id", "type", "doc", "doc-ref", "enum", "if", "valid", "size", "size-eos", "contents",
              "repeat", "repeat-expr"}


@dataclass
class EnumSpec:
    file: str
    name: str
    values: list[tuple[int, str]]  # sorted by value

    @property
    def key(self) -> str:
        return f"{self.file}.{self.name}"

    @property
    def cname(self) -> str:
        return f"{self.file}_{self.name}"


@dataclass
class Case:
    key: Any  # the raw ksy case key (int or expression string)
    type: "TypeRef"


@dataclass
class TypeRef:
    target: "TypeSpec"
    args: list[str]


@dataclass
class FieldSpec:
    id: str
    kind: str  # int, float, bits, bytes, contents, struct, switch
    raw: dict
    width: int = 0  # bytes for int/float, bits for bits
    signed: bool = False
    endian: str = "le"
    enum: Optional[EnumSpec] = None
    cond: Optional[str] = None
    valid: Any = None
    size: Optional[str] = None
    size_eos: bool = False
    contents: Optional[bytes] = None
    repeat: Optional[int] = None
    ref: Optional[TypeRef] = None
    switch_on: Optional[str] = None
    cases: list[Case] = field(default_factory=list)
    default: Optional[TypeRef] = None

    @property
    def is_bool(self) -> bool:
        return self.kind == "bits" and self.width == 1 and self.enum is None


@dataclass
class ParamSpec:
    id: str
    ptype: str  # "bool" or an integer type u1..s8
    enum: Optional[EnumSpec] = None


@dataclass
class TypeSpec:
    file: str
    path: tuple[str, ...]
    body: dict
    params: list[ParamSpec] = field(default_factory=list)
    fields: list[FieldSpec] = field(default_factory=list)
    instances: dict[str, Any] = field(default_factory=dict)
    children: dict[str, "TypeSpec"] = field(default_factory=dict)
    parent_scope: Optional["TypeSpec"] = None  # lexical parent (nesting)
    meta: dict = field(default_factory=dict)

    @property
    def name(self) -> str:
        return self.path[-1] if self.path else self.file

    @property
    def ksy_name(self) -> str:
        return "::".join((self.file,) + self.path)

    @property
    def cname(self) -> str:
        return "_".join((self.file,) + self.path)

    @property
    def is_file_root(self) -> bool:
        return not self.path


class Spec:
    def __init__(self, spec_dir: Path) -> None:
        self.files: dict[str, dict] = {}
        for path in sorted(spec_dir.glob("*.ksy")):
            doc = yaml.load(path.read_text(encoding="utf-8"), Loader=SafeLoader)  # noqa: S506 - a safe loader
            fid = doc["meta"]["id"]
            if fid != path.stem:
                raise SpecError(f"{path.name}: meta.id {fid!r} differs from the file name")
            self.files[fid] = doc
        self.enums: dict[tuple[str, str], EnumSpec] = {}
        self.types: dict[tuple[str, tuple[str, ...]], TypeSpec] = {}
        for fid, doc in self.files.items():
            for ename, values in (doc.get("enums") or {}).items():
                self.enums[(fid, ename)] = EnumSpec(fid, ename, self._enum_values(fid, ename, values))
            self._declare(fid, (), doc, None, doc["meta"])
        for t in self.ordered_types():
            self._fill_params(t)
        for t in self.ordered_types():
            self._fill(t)

    # ---- declaration ---------------------------------------------------------------

    @staticmethod
    def _enum_values(fid: str, ename: str, values: dict) -> list[tuple[int, str]]:
        out = []
        for k, v in values.items():
            if not isinstance(k, int) or isinstance(k, bool):
                raise SpecError(f"{fid}.{ename}: enum key {k!r} is not an integer")
            name = v["id"] if isinstance(v, dict) else v
            if not isinstance(name, str) or not re.fullmatch(r"[a-z_][a-z0-9_]*", name):
                raise SpecError(f"{fid}.{ename}: bad enum name {name!r}")
            out.append((k, name))
        return sorted(out)

    def _declare(self, fid: str, path: tuple[str, ...], body: dict, lexical: Optional[TypeSpec], meta: dict) -> TypeSpec:
        for key in body:
            if key not in ("meta", "doc", "doc-ref", "seq", "types", "enums", "instances", "params"):
                raise SpecError(f"{fid}{'::' + '::'.join(path) if path else ''}: unsupported key {key!r}")
        if path and body.get("enums"):
            raise SpecError(f"{fid}::{'::'.join(path)}: enums inside types are not supported")
        t = TypeSpec(fid, path, body, parent_scope=lexical, meta=meta)
        self.types[(fid, path)] = t
        for name, sub in (body.get("types") or {}).items():
            t.children[name] = self._declare(fid, path + (name,), sub, t, meta)
        return t

    def ordered_types(self) -> list[TypeSpec]:
        return [self.types[k] for k in sorted(self.types)]

    # ---- resolution -----------------------------------------------------------------

    def resolve_type(self, where: TypeSpec, name: str) -> TypeSpec:
        parts = name.split("::")
        if len(parts) == 1:
            scope: Optional[TypeSpec] = where
            while scope is not None:
                if name in scope.children:
                    return scope.children[name]
                scope = scope.parent_scope
            if (name, ()) in self.types:
                self._check_import(where, name)
                return self.types[(name, ())]
        elif parts[0] in self.files:
            self._check_import(where, parts[0])
            key = (parts[0], tuple(parts[1:]))
            if key in self.types:
                return self.types[key]
        raise SpecError(f"{where.ksy_name}: cannot resolve type {name!r}")

    def _check_import(self, where: TypeSpec, fid: str) -> None:
        if fid != where.file and fid not in (self.files[where.file]["meta"].get("imports") or []):
            raise SpecError(f"{where.file}: uses {fid} without importing it")

    def resolve_enum(self, where: TypeSpec, name: str) -> EnumSpec:
        parts = name.split("::")
        if len(parts) == 1 and (where.file, name) in self.enums:
            return self.enums[(where.file, name)]
        if len(parts) == 2 and tuple(parts) in self.enums:
            self._check_import(where, parts[0])
            return self.enums[(parts[0], parts[1])]
        raise SpecError(f"{where.ksy_name}: cannot resolve enum {name!r}")

    def enum_member(self, where: TypeSpec, parts: tuple) -> Optional[tuple[EnumSpec, int, str]]:
        if len(parts) == 2:
            e = self.resolve_enum(where, parts[0])
        elif len(parts) == 3:
            e = self.resolve_enum(where, f"{parts[0]}::{parts[1]}")
        else:
            return None
        for v, n in e.values:
            if n == parts[-1]:
                return e, v, n
        raise SpecError(f"{where.ksy_name}: enum {e.key} has no member {parts[-1]!r}")

    def type_ref(self, where: TypeSpec, text: str) -> TypeRef:
        m = _CALL.match(text.strip())
        if not m:
            raise SpecError(f"{where.ksy_name}: cannot read type reference {text!r}")
        args = split_args(m.group(2)) if m.group(2) is not None else []
        target = self.resolve_type(where, m.group(1))
        if len(args) != len(target.params):
            raise SpecError(f"{where.ksy_name}: {text!r} passes {len(args)} arguments, "
                            f"{target.ksy_name} takes {len(target.params)}")
        return TypeRef(target, args)

    # ---- filling in ------------------------------------------------------------------

    def _fill_params(self, t: TypeSpec) -> None:
        for p in t.body.get("params") or []:
            unknown = set(p) - {"id", "type", "enum", "doc"}
            if unknown:
                raise SpecError(f"{t.ksy_name}: param {p['id']}: unsupported keys {sorted(unknown)}")
            ptype = p.get("type")
            if ptype != "bool" and not (isinstance(ptype, str) and _INT.match(ptype)):
                raise SpecError(f"{t.ksy_name}: param {p['id']}: unsupported type {ptype!r}")
            t.params.append(ParamSpec(p["id"], ptype, self.resolve_enum(t, p["enum"]) if "enum" in p else None))

    def _fill(self, t: TypeSpec) -> None:
        endian = t.meta.get("endian", "le")
        bit_endian = t.meta.get("bit-endian", "be")
        for inst_id, inst in (t.body.get("instances") or {}).items():
            t.instances[inst_id] = inst
        for raw in t.body.get("seq") or []:
            unknown = set(raw) - FIELD_KEYS
            if unknown:
                raise SpecError(f"{t.ksy_name}.{raw.get('id')}: unsupported keys {sorted(unknown)}")
            t.fields.append(self._field(t, raw, endian, bit_endian))
        ids = [f.id for f in t.fields] + [p.id for p in t.params]
        if len(set(ids)) != len(ids):
            raise SpecError(f"{t.ksy_name}: a field or param id is used twice")

    def _field(self, t: TypeSpec, raw: dict, endian: str, bit_endian: str) -> FieldSpec:
        fid = raw["id"]
        where = f"{t.ksy_name}.{fid}"
        ty = raw.get("type")
        f = FieldSpec(id=fid, kind="", raw=raw)
        if "if" in raw:
            f.cond = raw["if"] if not isinstance(raw["if"], bool) else ("true" if raw["if"] else "false")
        f.valid = raw.get("valid")
        if "repeat" in raw:
            if raw["repeat"] != "expr":
                raise SpecError(f"{where}: only repeat: expr is supported")
            f.repeat = const_value(raw["repeat-expr"])
            if f.repeat < 0:
                raise SpecError(f"{where}: negative repeat count")
        if "size" in raw:
            f.size = str(raw["size"]) if not isinstance(raw["size"], str) else raw["size"]
        if raw.get("size-eos"):
            f.size_eos = True
        if f.size is not None and f.size_eos:
            raise SpecError(f"{where}: size and size-eos together")
        if "contents" in raw:
            c = raw["contents"]
            if isinstance(c, list) and all(isinstance(b, int) and 0 <= b <= 255 for b in c):
                f.contents = bytes(c)
            elif isinstance(c, str):
                f.contents = c.encode("utf-8")
            else:
                raise SpecError(f"{where}: unsupported contents {c!r}")
            f.kind = "contents"
            if ty is not None or f.size is not None or f.size_eos:
                raise SpecError(f"{where}: contents with a type or size")
            return f
        if "enum" in raw:
            f.enum = self.resolve_enum(t, raw["enum"])
        if isinstance(ty, dict):
            if set(ty) != {"switch-on", "cases"}:
                raise SpecError(f"{where}: unsupported switch keys {sorted(ty)}")
            f.kind = "switch"
            f.switch_on = str(ty["switch-on"])
            for key, target in ty["cases"].items():
                ref = self.type_ref(t, target)
                if key == "_":
                    f.default = ref
                else:
                    f.cases.append(Case(key, ref))
            if f.enum is not None:
                raise SpecError(f"{where}: enum on a switch")
            return f
        if ty is None:
            if f.size is None and not f.size_eos:
                raise SpecError(f"{where}: raw bytes need size or size-eos")
            f.kind = "bytes"
            return f
        if f.size is not None or f.size_eos:
            # a user type in its own substream
            f.kind = "struct"
            f.ref = self.type_ref(t, ty)
            return f
        if m := _INT.match(ty):
            f.kind, f.signed, f.width = "int", m.group(1) == "s", int(m.group(2))
            f.endian = m.group(3) or endian
            return f
        if m := _FLOAT.match(ty):
            f.kind, f.width = "float", int(m.group(1))
            f.endian = m.group(2) or endian
            if f.enum is not None:
                raise SpecError(f"{where}: enum on a float")
            return f
        if m := _BITS.match(ty):
            f.kind, f.width = "bits", int(m.group(1))
            be = m.group(2) or bit_endian
            if be != "le":
                raise SpecError(f"{where}: only bit-endian le is supported")
            if not 1 <= f.width <= 56:
                raise SpecError(f"{where}: bit fields of 1 to 56 bits only")
            return f
        f.kind = "struct"
        f.ref = self.type_ref(t, ty)
        if f.enum is not None:
            raise SpecError(f"{where}: enum on a user type")
        return f


def split_args(text: str) -> list[str]:
    out, depth, cur = [], 0, ""
    for ch in text:
        if ch == "(":
            depth += 1
        elif ch == ")":
            depth -= 1
        if ch == "," and depth == 0:
            out.append(cur.strip())
            cur = ""
        else:
            cur += ch
    if cur.strip():
        out.append(cur.strip())
    return out
