"""The .ksy files follow the kaitai_struct_formats conventions: meta with
id, title, application, license, endian (bit-endian where bit fields are
used, imports where used), a top-level doc and doc-ref, and a doc on every
field, param, instance and enum-less type. The profile files that
tools/gen_profile_ksy.py writes are held to the same rules."""
from __future__ import annotations

import re

import pytest

from osdk_conformance.core import ksy
from osdk_conformance.core.rules import default_rules

INDEX = ksy.load()
FILES = sorted(INDEX.files)
GENERATED = sorted(f"osdk_broadcast_{default_rules().profile(n).ksy_name}" for n in default_rules().profile_names)


def _seqs(body):
    yield body.get("seq") or []
    for sub in (body.get("types") or {}).values():
        yield from _seqs(sub)


def test_generated_profile_files_are_checked_here():
    assert GENERATED and set(GENERATED) <= set(FILES)


@pytest.mark.parametrize("fid", FILES)
def test_meta_and_top_level_docs(fid):
    doc = INDEX.files[fid]
    meta = doc["meta"]
    for key in ("id", "title", "application", "license", "ks-version", "endian"):
        assert meta.get(key), f"{fid}: meta.{key} missing"
    assert meta["id"] == fid
    uses_bits = any(re.fullmatch(r"b\d+", str(f.get("type"))) for seq in _seqs(doc) for f in seq)
    assert not uses_bits or meta.get("bit-endian") == "le", f"{fid}: bit fields without meta.bit-endian le"
    assert doc.get("doc"), f"{fid}: no top-level doc"
    assert doc.get("doc-ref"), f"{fid}: no doc-ref"


@pytest.mark.parametrize("fid", FILES)
def test_every_field_param_instance_and_type_is_documented(fid):
    undocumented = []
    for (f, path), t in INDEX.types.items():
        if f != fid:
            continue
        where = ".".join((fid,) + path)
        if path:
            body = INDEX.files[fid]
            for part in path:
                body = body["types"][part]
            if not body.get("doc"):
                undocumented.append(f"type {where}")
        undocumented += [f"field {where}.{n}" for n, fld in t.fields.items() if not fld.doc]
        undocumented += [f"param {where}.{n}" for n, p in t.params.items() if not p.get("doc")]
        undocumented += [f"instance {where}.{n}" for n, i in t.instances.items() if not i.get("doc")]
    assert undocumented == []


@pytest.mark.parametrize("fid", FILES)
def test_imports_are_declared_and_exist(fid):
    for name in INDEX.files[fid]["meta"].get("imports", []):
        assert name in INDEX.files, f"{fid} imports {name}, which is not in spec/"
