"""Read-only index of spec/*.ksy: types, their seq fields and enums.

The value model needs to know what the Kaitai-generated Python code cannot
tell at run time (a Python float does not say whether it was an f4 or an
f8), the traceability check needs to know which spec elements exist, and
the rules loader needs the size of each broadcast item in each profile.
All read the .ksy files themselves instead of keeping a second copy.
"""
from __future__ import annotations

import functools
import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import yaml

from osdk_conformance.core.paths import SPEC

# libyaml's parser where PyYAML has it (its wheels do): the pure-Python one
# takes a quarter of a second for rules.yaml and the .ksy files, in every
# process that reads the spec (each testee, simulator and command).
SafeLoader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


PRIMITIVE_SIZES = {"u1": 1, "s1": 1, "u2": 2, "s2": 2, "u4": 4, "s4": 4, "f4": 4, "u8": 8, "s8": 8, "f8": 8}
_TYPE_REF = re.compile(r"(?:(\w+)::)?(\w+)(?:\((.*)\))?")
_ENUM_LITERAL = re.compile(r"\w+::\w+")
_BITS = re.compile(r"b(\d+)")


class KsyError(ValueError):
    """A ksy type whose size cannot be worked out: it is not fixed, a
    condition is not a known boolean, or bit fields do not fill whole bytes."""


@dataclass(frozen=True)
class KsyField:
    id: str
    type: str | None  # None for raw bytes / contents; "switch" for switch-on
    enum: str | None
    doc: str | None


@dataclass
class KsyType:
    file: str  # ksy id of the file
    path: tuple[str, ...]  # nested type path, () for the file's top-level type
    fields: dict[str, KsyField] = field(default_factory=dict)
    instances: dict[str, dict] = field(default_factory=dict)
    params: dict[str, dict] = field(default_factory=dict)

    @property
    def name(self) -> str:
        return self.path[-1] if self.path else self.file

    @property
    def class_name(self) -> str:
        return camel(self.name)


def camel(name: str) -> str:
    return "".join(part.capitalize() for part in name.split("_"))


@dataclass
class KsyIndex:
    files: dict[str, dict]
    types: dict[tuple[str, tuple[str, ...]], KsyType]
    enums: dict[tuple[str, str], dict[int, str]]

    def type_for_class(self, cls: type) -> KsyType:
        """The ksy type a Kaitai-generated Python class was compiled from."""
        # Kept per class: model.from_kaitai asks once for every object it
        # converts (some 90,000 times in a replay of the vectors by the
        # kaitai-python testee), and the answer is a scan of every type of
        # every file. An index is not changed once made (ksy.load caches it).
        known = self.__dict__.setdefault("_types_by_class", {})
        kt = known.get(cls)
        if kt is None:
            module = cls.__module__.rsplit(".", 1)[-1]
            parts = cls.__qualname__.split(".")
            path: tuple[str, ...] = ()
            for part in parts[1:]:
                path = path + (snake_child(self, module, path, part),)
            kt = known[cls] = self.types[(module, path)]
        return kt

    def raw_seq(self, kt: KsyType) -> list[dict]:
        """The seq of a type as the .ksy file writes it (every key of every
        field, `trailing` included)."""
        body = self.files[kt.file]
        for part in kt.path:
            body = body["types"][part]
        return body.get("seq") or []

    def element_exists(self, ref: str) -> bool:
        """True for 'file.ksy', 'file.ksy#type', 'file.ksy#type.field' or
        'file.ksy#enum:name' / 'file.ksy#enum:name.value'."""
        fname, _, frag = ref.partition("#")
        fid = fname.removesuffix(".ksy")
        if fid not in self.files:
            return False
        if not frag:
            return True
        if frag.startswith("enum:"):
            ename, _, label = frag[5:].partition(".")
            values = self.enums.get((fid, ename))
            return values is not None and (not label or label in values.values())
        tname, _, fld = frag.partition(".")
        candidates = [t for (f, p), t in self.types.items() if f == fid and (p[-1:] == (tname,) or (not p and tname == fid))]
        if not candidates:
            return False
        if not fld:
            return True
        return any(fld in t.fields or fld in t.instances or fld in t.params for t in candidates)

    # ---- sizes of fixed-size types ------------------------------------------
    #
    # Enough of Kaitai's semantics for the types of spec/: primitive types, bN
    # bit fields (which must fill whole bytes), `size:` with a constant, user
    # types with boolean or enum-literal params, `if:` naming a param or a
    # boolean instance of the form `param == enum::x` / `param != enum::x`.

    def type_size(self, file_id: str, type_name: str, params: Mapping[str, Any] | None = None) -> int:
        """Bytes of a user type once its params are known: `params` maps each
        param id to a Python bool, int, or an enum literal ("profile::a3_fw3_1").
        The type is one of the file's `types`, or an imported file's top-level type."""
        params = dict(params or {})
        local = self.files[file_id].get("types") or {}
        if type_name in local:
            body = local[type_name]
        elif type_name in (self.files[file_id]["meta"].get("imports") or []) and type_name in self.files:
            file_id, body = type_name, self.files[type_name]
        else:
            raise KsyError(f"{file_id}: unknown type {type_name}")
        declared = [p["id"] for p in body.get("params") or []]
        if sorted(declared) != sorted(params):
            raise KsyError(f"{file_id}::{type_name} takes params {declared}, got {sorted(params)}")
        return self.seq_size(file_id, body.get("seq") or [], {**params, **instance_flags(body, params)})

    def ref_size(self, ref: str, file_id: str) -> int:
        """Bytes of a `type:` as a seq entry writes it: a primitive, or
        `[file::]type[(args)]` with literal arguments, resolved in `file_id`."""
        if ref in PRIMITIVE_SIZES:
            return PRIMITIVE_SIZES[ref]
        target, type_name, args = parse_type_ref(ref, file_id)
        body = (self.files[target].get("types") or {}).get(type_name)
        if body is None and type_name in self.files:
            body = self.files[type_name]
        if body is None:
            raise KsyError(f"{file_id}: unknown type {ref}")
        declared = [p["id"] for p in body.get("params") or []]
        if len(declared) != len(args):
            raise KsyError(f"{ref}: {target}::{type_name} takes params {declared}, got {len(args)} arguments")
        return self.type_size(target, type_name, dict(zip(declared, args)))

    def field_size(self, file_id: str, f: Mapping[str, Any], env: Mapping[str, Any]) -> tuple[int, int]:
        """(bytes, bits) one seq entry occupies; (0, 0) when its `if` is false."""
        cond = f.get("if")
        if cond is not None:
            if cond not in env or not isinstance(env[cond], bool):
                raise KsyError(f"{f['id']}: condition {cond!r} is not a known boolean")
            if not env[cond]:
                return 0, 0
        t = f.get("type")
        if isinstance(t, str) and _BITS.fullmatch(t):
            return 0, int(t[1:])
        if "size" in f:
            if not isinstance(f["size"], int):
                raise KsyError(f"{f['id']}: size {f['size']!r} is not fixed")
            return f["size"], 0
        if not isinstance(t, str):
            raise KsyError(f"{f['id']}: no fixed size")
        return self.ref_size(t, file_id), 0

    def seq_size(self, file_id: str, seq: Iterable[Mapping[str, Any]], env: Mapping[str, Any]) -> int:
        """Bytes of a seq whose conditions are decided by `env` (param and instance values)."""
        total, bits = 0, 0
        for f in seq:
            nbytes, nbits = self.field_size(file_id, f, env)
            if nbits:
                bits += nbits
                continue
            if nbytes:
                if bits % 8:
                    raise KsyError(f"{f['id']}: the bit fields before it do not fill whole bytes")
                total, bits = total + bits // 8, 0
            total += nbytes
        if bits % 8:
            raise KsyError(f"{file_id}: trailing bit fields do not fill whole bytes")
        return total + bits // 8


def parse_type_ref(ref: str, file_id: str) -> tuple[str, str, list[Any]]:
    """(file id, type name, argument values) of `[file::]type[(args)]`;
    arguments are ksy literals: true/false, integers, or enum literals (kept as text)."""
    m = _TYPE_REF.fullmatch(ref)
    if not m:
        raise KsyError(f"{ref!r} is not a type reference")
    args = [literal(a.strip()) for a in m.group(3).split(",")] if m.group(3) else []
    return m.group(1) or file_id, m.group(2), args


def literal(text: str) -> bool | int | str:
    """A ksy argument literal as a Python value; enum literals stay text."""
    if text in ("true", "false"):
        return text == "true"
    if re.fullmatch(r"-?(0x[0-9a-fA-F_]+|\d+)", text):
        return int(text, 0)
    if _ENUM_LITERAL.fullmatch(text):
        return text
    raise KsyError(f"only boolean, integer and enum literal arguments are supported, got {text!r}")


_TERM = re.compile(r"(\w+) (==|!=) (\w+::\w+)")


def instance_flags(body: Mapping[str, Any], env: Mapping[str, Any]) -> dict[str, bool]:
    """The type's boolean instances that compare params with enum values:
    `true`, `false`, or terms `param == enum::x` / `param != enum::x` joined by
    `and` or by `or` (what tools/gen_profile_ksy.py writes), decided for the
    param values in `env`. Instances of other forms, or on params not in
    `env`, are left out."""
    out = {}
    for name, inst in (body.get("instances") or {}).items():
        value = _decide(str(inst.get("value", "")).strip(), env)
        if value is not None:
            out[name] = value
    return out


def _decide(expr: str, env: Mapping[str, Any]) -> bool | None:
    if expr in ("true", "false"):
        return expr == "true"
    joiner, combine = (" or ", any) if " or " in expr else (" and ", all)
    matches = [_TERM.fullmatch(term.strip()) for term in expr.split(joiner)]
    if not all(m and m.group(1) in env for m in matches):  # another form, or mixed and/or
        return None
    return combine((env[m.group(1)] == m.group(3)) == (m.group(2) == "==") for m in matches)


def snake_child(index: KsyIndex, module: str, parent: tuple[str, ...], class_part: str) -> str:
    for (f, p) in index.types:
        if f == module and len(p) == len(parent) + 1 and p[:-1] == parent and camel(p[-1]) == class_part:
            return p[-1]
    raise KeyError(f"{module}: no ksy type for class {class_part}")


def _field(spec: dict) -> KsyField:
    t = spec.get("type")
    if isinstance(t, dict):
        t = "switch"
    return KsyField(id=spec["id"], type=t, enum=spec.get("enum"), doc=spec.get("doc"))


def _walk(file_id: str, path: tuple[str, ...], body: dict, out: dict) -> None:
    kt = KsyType(file=file_id, path=path)
    for f in body.get("seq", []) or []:
        kt.fields[f["id"]] = _field(f)
    kt.instances = dict(body.get("instances", {}) or {})
    kt.params = {p["id"]: p for p in body.get("params", []) or []}
    out[(file_id, path)] = kt
    for name, sub in (body.get("types", {}) or {}).items():
        _walk(file_id, path + (name,), sub, out)


def _index(paths: Iterable[Path]) -> KsyIndex:
    files: dict[str, dict] = {}
    types: dict[tuple[str, tuple[str, ...]], KsyType] = {}
    enums: dict[tuple[str, str], dict[int, str]] = {}
    for path in paths:
        doc = yaml.load(path.read_text(), Loader=SafeLoader)  # noqa: S506 - a safe loader
        fid = doc["meta"]["id"]
        files[fid] = doc
        _walk(fid, (), doc, types)
        for ename, values in (doc.get("enums", {}) or {}).items():
            enums[(fid, ename)] = {
                int(k): (v["id"] if isinstance(v, dict) else v) for k, v in values.items()
            }
    return KsyIndex(files=files, types=types, enums=enums)


@functools.cache
def load(spec_dir: Path = SPEC) -> KsyIndex:
    """Every spec_dir/*.ksy."""
    return _index(sorted(spec_dir.glob("*.ksy")))


@functools.cache
def load_file(path: Path) -> KsyIndex:
    """One .ksy file alone (its imports are not followed)."""
    return _index([path])
