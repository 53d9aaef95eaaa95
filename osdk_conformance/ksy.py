"""Read-only index of spec/*.ksy: types, their seq fields and enums.

The value model needs to know what the Kaitai-generated Python code cannot
tell at run time (a Python float does not say whether it was an f4 or an
f8), and the traceability check needs to know which spec elements exist.
Both read the .ksy files themselves instead of keeping a second copy.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass, field
from pathlib import Path

import yaml

from .paths import SPEC


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
        module = cls.__module__.rsplit(".", 1)[-1]
        parts = cls.__qualname__.split(".")
        path: tuple[str, ...] = ()
        for part in parts[1:]:
            path = path + (snake_child(self, module, path, part),)
        return self.types[(module, path)]

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


@functools.cache
def load(spec_dir: Path = SPEC) -> KsyIndex:
    files: dict[str, dict] = {}
    types: dict[tuple[str, tuple[str, ...]], KsyType] = {}
    enums: dict[tuple[str, str], dict[int, str]] = {}
    for path in sorted(spec_dir.glob("*.ksy")):
        doc = yaml.safe_load(path.read_text())
        fid = doc["meta"]["id"]
        files[fid] = doc
        _walk(fid, (), doc, types)
        for ename, values in (doc.get("enums", {}) or {}).items():
            enums[(fid, ename)] = {
                int(k): (v["id"] if isinstance(v, dict) else v) for k, v in values.items()
            }
    return KsyIndex(files=files, types=types, enums=enums)
