#!/usr/bin/env python3
"""Write conformance/schemas/: JSON Schema (2020-12) for every request and
response of the testee protocol (conformance/PROTOCOL.md), generated from
the spec so that field names, enum names, bit widths and presence rules
cannot drift from it.

usage: tools/gen_schemas.py [--check]

- value-model.schema.json: one definition per .ksy type and enum in the
  JSON value model (docs/VALUE-MODEL.md), read from spec/*.ksy (field ids,
  widths, enums, `if` presence rules, `contents`/`valid` constants, docs);
  a type that depends on the wire profile gets one definition per profile.
- protocol.schema.json: what every operation shares (profile ids, error
  classes, response envelope, decode_stream events).
- <operation>.schema.json: the operation's request and its response, per
  profile where the result depends on it.

Error classes, operations and command names come from
osdk_conformance.harness.response_schema and osdk_conformance.core.commands, profiles
and control mode combinations from spec/rules.yaml.

It also writes the parts of docs/NAMING.md (the profiles, the control mode
byte, the broadcast item names, where the version ID is, the enums) and of
conformance/PROTOCOL.md (the profile ids, the version ACK per profile, the
flag bit table, the broadcast item variants, the control mode findings and
what bit 0 is per profile, how many mode bytes each profile documents, the
input range table) that restate the spec, each
between `<!-- NAME:begin (tools/gen_schemas.py writes this part) -->` and
`<!-- NAME:end -->`; the rest of those files is prose it leaves alone.

--check regenerates in memory and fails (exit 1) when the checked-in files
differ.
"""
from __future__ import annotations

import argparse
import json
import re
import sys
import textwrap
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from osdk_conformance.core import ksy, rules  # noqa: E402
from osdk_conformance.core.commands import COMMANDS  # noqa: E402
from osdk_conformance.core.model import SKIPPED_FIELDS  # noqa: E402
from osdk_conformance.harness.response_schema import (  # noqa: E402
    BASE_URI, ERROR_CLASSES, OPERATION_ERRORS, SCHEMA_DIR, STREAM_ERRORS, UNIVERSAL_ERRORS,
)

DIALECT = "https://json-schema.org/draft/2020-12/schema"
VM = "value-model.schema.json"
PROTO = "protocol.schema.json"
HEX = "^([0-9a-f]{2})*$"
_PRIM = re.compile(r"^(u|s)(1|2|4|8)(le|be)?$")
_FLOAT = re.compile(r"^f(4|8)(le|be)?$")
_BITS = re.compile(r"^b(\d+)$")
_CALL = re.compile(r"^([a-z0-9_:]+)(?:\((.*)\))?$")


# ----------------------------------------------------------------- the value model from spec/*.ksy

class ValueModel:
    """Schema definitions of the .ksy types, built on demand and memoised by
    (type, bound parameters)."""

    def __init__(self) -> None:
        self.index = ksy.load()
        self.r = rules.default_rules()
        # profile id -> its name in the ksy enum `profile`, by the profile's value
        profile_enum = self.index.enums[("osdk_payload", "profile")]
        self.ksy_profiles = {p: profile_enum[self.r.profile(p).value] for p in self.r.profile_names}
        self.defs: dict[str, Any] = {}

    # -- names
    def _resolve(self, file_id: str, scope: tuple[str, ...], name: str) -> tuple[str, tuple[str, ...]]:
        if "::" in name:
            f, rest = name.split("::", 1)
            return f, tuple(rest.split("::"))
        if name in self.index.files:
            return name, ()
        for depth in range(len(scope), -1, -1):  # innermost scope first, as Kaitai resolves
            key = (file_id, scope[:depth] + (name,))
            if key in self.index.types:
                return key
        raise SystemExit(f"gen_schemas: {file_id}: unknown type {name!r}")

    def _enum_key(self, file_id: str, ref: str) -> tuple[str, str]:
        if "::" in ref:
            f, name = ref.split("::", 1)
            return f, name
        return file_id, ref

    @staticmethod
    def def_name(key: tuple[str, tuple[str, ...]], profile: str | None, bound: dict[str, Any]) -> str:
        name = ".".join((key[0],) + key[1])
        args = [f"{k}={str(v).lower()}" for k, v in sorted(bound.items())]
        if args:
            name += "(" + ",".join(args) + ")"
        return name + (f"@{profile}" if profile else "")

    # -- profile dependency
    def depends_on_profile(self, key, seen=frozenset()) -> bool:
        if key in seen:
            return False
        kt = self.index.types[key]
        body = self.index.files[key[0]]
        for part in key[1]:
            body = body["types"][part]
        if any("profile::" in str(inst.get("value", "")) for inst in body.get("instances", {}).values()):
            return True   # a field present or not by profile (e.g. the FW 3.1 version ID, ERRATA E30)
        for f in self.index.raw_seq(kt):
            t = f.get("type")
            if isinstance(t, dict):
                if t["switch-on"] in ("profile", "_root.profile"):
                    return True
                targets = [c for c in t["cases"].values()]
            elif isinstance(t, str) and not self._scalar(t):
                targets = [t]
            else:
                targets = []
            for target in targets:
                m = _CALL.match(target)
                if m.group(2) and "profile" in m.group(2):
                    return True
                if self.depends_on_profile(self._resolve(key[0], key[1], m.group(1)), seen | {key}):
                    return True
        return False

    @staticmethod
    def _scalar(t: str) -> bool:
        return bool(_PRIM.match(t) or _FLOAT.match(t) or _BITS.match(t) or t in ("bool", "str", "strz"))

    # -- definitions
    def enum_ref(self, file_id: str, ref: str, top: int) -> dict:
        """The definition of an enum read from a field of `top` + 1 possible values (every use of one
        enum in the spec has the same width: checked)."""
        fid, name = self._enum_key(file_id, ref)
        def_name = f"enum.{fid}.{name}"
        if def_name not in self.defs:
            values = self.index.enums[(fid, name)]
            # a known value with exactly its name (one `enum` of whole objects: cheap to check), or an
            # unknown value with the name null
            pairs = [{"enum": [{"value": v, "name": n} for v, n in sorted(values.items())]},
                     {"properties": {"value": {"not": {"enum": sorted(values)}}, "name": {"const": None}}}]
            self.defs[def_name] = {
                "description": f"enum {name} of {fid}.ksy: "
                               + ", ".join(f"{v} {n}" for v, n in sorted(values.items()))
                               + "; any other value has the name null",
                "type": "object",
                "required": ["value", "name"],
                "additionalProperties": False,
                "properties": {"value": {"type": "integer", "minimum": 0, "maximum": top},
                               "name": {"type": ["string", "null"]}},
                "anyOf": pairs,
            }
        elif self.defs[def_name]["properties"]["value"]["maximum"] != top:
            raise SystemExit(f"gen_schemas: enum {fid}::{name} is read with two different widths")
        return {"$ref": f"#/$defs/{def_name}"}

    def type_ref(self, key, profile: str | None, bound: dict[str, Any]) -> dict:
        profile = profile if self.depends_on_profile(key) else None
        name = self.def_name(key, profile, bound)
        if name not in self.defs:
            self.defs[name] = {}  # placeholder against recursion
            self.defs[name] = self._object(key, profile, bound)
        return {"$ref": f"#/$defs/{name}"}

    def _bind_args(self, key, args: str | None, profile: str | None, env: dict) -> dict[str, Any]:
        params = list(self.index.types[key].params)
        if not args:
            return {}
        bound: dict[str, Any] = {}
        for name, arg in zip(params, (a.strip() for a in args.split(","))):
            if arg in ("true", "false"):
                bound[name] = arg == "true"
            elif arg in env and isinstance(env[arg], bool):
                bound[name] = env[arg]
            # anything else (profile, numbers read from the stream) stays unbound
        return bound

    def _object(self, key, profile: str | None, bound: dict[str, Any]) -> dict:
        kt = self.index.types[key]
        body = self.index.files[key[0]]
        for part in key[1]:
            body = body["types"][part]
        seq = [f for f in self.index.raw_seq(kt) if f["id"] not in SKIPPED_FIELDS]
        siblings = {f["id"]: f for f in seq}
        props: dict[str, Any] = {}
        required: list[str] = []
        conditions: list[dict] = []
        bit = 0
        for f in seq:
            fid = f["id"]
            m = _BITS.match(str(f.get("type", "")))
            width = int(m.group(1)) if m else None
            where = None
            if width is not None and self.index.files[key[0]]["meta"].get("bit-endian") == "le":
                where = (bit, bit + width - 1)
                bit += width
            else:
                bit = 0
            schema, branches = self._field(key, f, profile, bound, where)
            props[fid] = schema
            for cond, then in branches:
                conditions.append({"if": cond, "then": {"properties": {fid: then}}})
            presence = self._presence(f, bound, siblings, self._instance_flags(body, profile))
            if presence is True:
                required.append(fid)
            elif presence is False:
                props[fid] = False
            else:
                conditions.append({"if": presence, "then": {"required": [fid]},
                                   "else": {"not": {"required": [fid]}}})
        out: dict[str, Any] = {}
        if body.get("doc"):
            out["description"] = _one_line(body["doc"])
        out.update({"type": "object", "required": required, "additionalProperties": False, "properties": props})
        if conditions:
            out["allOf"] = conditions
        return out

    def _instance_flags(self, body: dict, profile: str | None) -> dict[str, bool]:
        """The type's instances that compare the profile with enum values,
        decided for the profile the schema is for."""
        if profile is None:
            return {}
        return ksy.instance_flags(body, {"profile": f"profile::{self._ksy_profile(profile)}"})

    def _presence(self, f: dict, bound: dict[str, Any], siblings: dict, flags: dict[str, bool]) -> Any:
        """True (always present), False (never) or an `if` schema on the
        siblings that holds exactly when the field is present. A condition
        of another form stops the generator: the spec grew one it must learn."""
        if "if" not in f:
            return True
        expr = str(f["if"]).strip()
        neg = expr.startswith("not ")
        name = expr[4:].strip() if neg else expr
        if name.startswith("_parent.") and name[8:] in bound:
            return bound[name[8:]] != neg
        if name in bound:
            return bound[name] != neg
        if name in flags:
            return flags[name] != neg
        if name in siblings and siblings[name].get("type") == "b1" and "enum" not in siblings[name]:
            return {"properties": {name: {"const": not neg}}, "required": [name]}
        m = re.fullmatch(r"([a-z_]+) > (\d+)", expr)
        if m and m.group(1) in siblings:
            return {"properties": {m.group(1): {"exclusiveMinimum": int(m.group(2))}}, "required": [m.group(1)]}
        raise SystemExit(f"gen_schemas: cannot express the condition `if: {expr}` of field {f['id']}")

    def _field(self, key, f: dict, profile, bound, where) -> tuple[dict, list[tuple[dict, dict]]]:
        """(schema of the field, [(condition on siblings, schema the field then has)])."""
        t = f.get("type")
        doc = _one_line(f.get("doc") or "")
        if where is not None:
            lo, hi = where
            bits = f"bit {lo}" if lo == hi else f"bits {hi}-{lo}"
            doc = f"{bits} (from the least significant bit). {doc}".strip()
        branches: list[tuple[dict, dict]] = []
        if "contents" in f:
            schema: dict = {"const": bytes(f["contents"]).hex()}
        elif isinstance(t, dict):
            schema, branches = self._switch(key, f, t, profile, bound)
        elif t is None:
            size = f.get("size")
            schema = {"$ref": f"{PROTO}#/$defs/hex"}
            if isinstance(size, int):
                schema = {"allOf": [schema, {"minLength": 2 * size, "maxLength": 2 * size}]}
        else:
            schema, branches = self._typed(key, f, t, profile, bound)
        if "repeat" in f:
            n = f.get("repeat-expr")
            schema = {"type": "array", "items": schema}
            if isinstance(n, int):
                schema.update(minItems=n, maxItems=n)
        if isinstance(f.get("valid"), (int, bool)) and not isinstance(t, dict):
            schema = {"allOf": [schema, {"const": f["valid"]}]}
        if doc:
            schema = {"description": doc, **schema}
        return schema, branches

    def _typed(self, key, f, t: str, profile, bound) -> tuple[dict, list]:
        file_id, scope = key
        if m := _PRIM.match(t):
            n = int(m.group(2))
            lo, hi = (-(1 << (8 * n - 1)), (1 << (8 * n - 1)) - 1) if m.group(1) == "s" else (0, (1 << (8 * n)) - 1)
            if "enum" in f:
                return self.enum_ref(file_id, f["enum"], hi), []
            return {"type": "integer", "minimum": lo, "maximum": hi}, []
        if m := _FLOAT.match(t):
            return {"$ref": f"{PROTO}#/$defs/f{32 if m.group(1) == '4' else 64}"}, []
        if m := _BITS.match(t):
            n = int(m.group(1))
            if "enum" in f:
                return self.enum_ref(file_id, f["enum"], (1 << n) - 1), []
            if n == 1:
                return {"type": "boolean"}, []
            return {"type": "integer", "minimum": 0, "maximum": (1 << n) - 1}, []
        m = _CALL.match(t)
        target = self._resolve(file_id, scope, m.group(1))
        parent_refs = self._parent_refs(target)
        if not parent_refs:
            return self.type_ref(target, profile, self._bind_args(target, m.group(2), profile, bound)), []
        # the target's layout depends on fields of this object (`_parent.x`): one schema per value
        return self._by_parent(target, m.group(2), parent_refs, profile, bound)

    def _by_parent(self, target, args, parent_refs: list[str], profile, bound) -> tuple[dict, list]:
        branches = []
        for value in (True, False):
            env = {**bound, **{r: value for r in parent_refs}}
            b = {**self._bind_args(target, args, profile, env), **{f"_parent.{r}": value for r in parent_refs}}
            cond = {"properties": {r: {"const": value} for r in parent_refs}, "required": parent_refs}
            branches.append((cond, self.type_ref(target, profile, {k.removeprefix("_parent."): v
                                                                   for k, v in b.items()})))
        return {"anyOf": [s for _, s in branches]}, branches

    def _parent_refs(self, key) -> list[str]:
        kt = self.index.types[key]
        refs = set()
        for f in self.index.raw_seq(kt):
            refs |= set(re.findall(r"_parent\.([a-z_]+)", str(f.get("if", ""))))
        return sorted(refs)

    def _switch(self, key, f, t: dict, profile, bound) -> tuple[dict, list]:
        file_id, scope = key
        on = t["switch-on"]
        cases = t["cases"]
        if on in ("profile", "_root.profile"):
            chosen = cases.get(f"profile::{self._ksy_profile(profile)}")
            if chosen is None:
                raise SystemExit(f"gen_schemas: switch on profile without a profile in {key}")
            return self._typed(key, f, chosen, profile, bound)
        siblings = {s["id"]: s for s in self.index.raw_seq(self.index.types[key])}
        if on in siblings and "enum" in siblings[on]:
            # one branch per case (and per value of the fields the case type
            # reads from this object), the raw bytes otherwise
            fid, ename = self._enum_key(file_id, siblings[on]["enum"])
            values = {n: v for v, n in self.index.enums[(fid, ename)].items()}
            branches, known = [], []
            for label, target in cases.items():
                v = values[label.split("::")[-1]]
                known.append(v)
                schema, inner = self._typed(key, f, target, profile, bound)
                for cond, sch in inner or [({}, schema)]:
                    branches.append(({"properties": {on: {"properties": {"value": {"const": v}}},
                                                     **cond.get("properties", {})},
                                      "required": [on, *cond.get("required", [])]}, sch))
            branches.append(({"properties": {on: {"properties": {"value": {"not": {"enum": known}}}}},
                              "required": [on]}, {"$ref": f"{PROTO}#/$defs/hex"}))
            return {"anyOf": [s for _, s in branches]}, branches
        # a switch on a value computed from parameters (osdk_payload's key): any case, told apart by
        # the first field of each case type (an anyOf only among cases that share it)
        groups: dict[str, list[dict]] = {}
        for target in cases.values():
            first = self.index.raw_seq(self.index.types[self._resolve(file_id, scope, _CALL.match(target).group(1))])
            schema = self._typed(key, f, target, profile, bound)[0]
            groups.setdefault(first[0]["id"], []).append(schema)
        return {"type": "object", "anyOf": [{"required": [k]} for k in groups],
                "allOf": [{"if": {"required": [k]}, "then": g[0] if len(g) == 1 else {"anyOf": g}}
                          for k, g in groups.items()]}, []

    def _ksy_profile(self, profile: str | None) -> str | None:
        return self.ksy_profiles[profile] if profile else None


def _one_line(text: str) -> str:
    return re.sub(r"\s+", " ", text).strip()


# ----------------------------------------------------------------- the protocol

def _doc(schema_id: str, title: str, description: str, defs: dict, root: dict | None = None) -> dict:
    out = {"$schema": DIALECT, "$id": BASE_URI + schema_id, "title": title, "description": description}
    if root:
        out.update(root)
    out["$defs"] = defs
    return out


def protocol_schema(vm: ValueModel) -> dict:
    profiles = list(vm.r.profile_names)
    names = sorted(set(COMMANDS.values()) | {"unknown"})
    nan = "^0x[7f]f[89a-f][0-9a-f]{5}$"
    nan64 = "^0x[7f]f[f][0-9a-f]{13}$"
    defs: dict[str, Any] = {
        "hex": {"description": "bytes as lowercase hex, two digits a byte", "type": "string", "pattern": HEX},
        "profile": {"description": "a wire profile id (docs/NAMING.md)", "enum": profiles},
        "f32": _float_schema(32, nan, "0x7f800000", "0xff800000"),
        "f64": _float_schema(64, nan64, "0x7ff0000000000000", "0xfff0000000000000"),
        "f32_input": {"description": "a float32 argument: the IEEE-754 bits as 0x + 8 hex digits; `value` "
                                     "(for people) may be present and is ignored",
                      "type": "object", "required": ["f32"], "additionalProperties": False,
                      "properties": {"f32": {"type": "string", "pattern": "^0x[0-9a-f]{8}$"},
                                     "value": {"type": ["number", "string"]}}},
        "error_class": {"description": "every error class of docs/VALUE-MODEL.md: "
                                       + "; ".join(f"{k}: {v}" for k, v in ERROR_CLASSES.items()),
                        "enum": list(ERROR_CLASSES)},
        "ok": {"description": "the operation succeeded; `result` is the operation's result schema",
               "type": "object", "required": ["ok", "result"], "additionalProperties": False,
               "properties": {"ok": {"const": True}, "result": {"type": "object"}}},
        "error": {"description": "the input was rejected with an error class; `detail` says why, for people",
                  "type": "object", "required": ["ok", "error", "detail"], "additionalProperties": False,
                  "properties": {"ok": {"const": False}, "error": {"$ref": "#/$defs/error_class"},
                                 "detail": {"type": "string"}}},
        "unsupported": {"description": "the testee does not implement this operation or profile (the case is "
                                       "skipped); `detail` is optional",
                        "type": "object", "required": ["ok", "unsupported"], "additionalProperties": False,
                        "properties": {"ok": {"const": False}, "unsupported": {"const": True},
                                       "detail": {"type": "string"}}},
        "response": {"description": "any response line, before the operation's own schema is applied",
                     "type": "object", "required": ["ok"], "properties": {"ok": {"type": "boolean"}},
                     "if": {"properties": {"ok": {"const": True}}}, "then": {"$ref": "#/$defs/ok"},
                     "else": {"if": {"required": ["unsupported"]}, "then": {"$ref": "#/$defs/unsupported"},
                              "else": {"$ref": "#/$defs/error"}}},
        "command_name": {"description": "the name of a command by (cmd_set, cmd_id): "
                                        + ", ".join(f"0x{s:02x}/0x{i:02x} {n}" for (s, i), n in sorted(COMMANDS.items()))
                                        + "; any other pair is unknown",
                         "enum": names},
        "frame_header": {
            "description": "the 12-byte header of a frame whose value did not decode, its fields as plain "
                           "values: numbers, is_ack a boolean, enc a number (not an enum object)",
            "type": "object", "additionalProperties": False,
            "required": ["len", "ver", "session", "is_ack", "res0", "padding", "enc", "res1", "seq", "crc16"],
            "properties": {"len": _uint(10), "ver": _uint(6), "session": _uint(5), "is_ack": {"type": "boolean"},
                           "res0": _uint(2), "padding": _uint(5), "enc": _uint(3), "res1": _uint(24),
                           "seq": _uint(16), "crc16": _uint(16)}},
    }
    return _doc(PROTO, "osdk testee protocol: shared definitions",
                "Shared by the operation schemas (conformance/PROTOCOL.md): response envelope, error classes, "
                "floats, hex, profile ids, command names. Generated by tools/gen_schemas.py.",
                defs, {"$ref": "#/$defs/response"})


def _uint(bits: int) -> dict:
    return {"type": "integer", "minimum": 0, "maximum": (1 << bits) - 1}


def _float_schema(width: int, nan: str, inf: str, ninf: str) -> dict:
    digits = width // 4
    return {
        "description": f"an IEEE-754 binary{width}: `f{width}` holds its bits (normative, compared exactly), "
                       "`value` is for people: a JSON number when finite, else \"NaN\", \"Infinity\" or "
                       "\"-Infinity\"",
        "type": "object", "required": [f"f{width}", "value"], "additionalProperties": False,
        "properties": {f"f{width}": {"type": "string", "pattern": f"^0x[0-9a-f]{{{digits}}}$"},
                       "value": {"anyOf": [{"type": "number"}, {"enum": ["NaN", "Infinity", "-Infinity"]}]}},
        # a name for special bits must match them (a finite number beside special bits is not checked
        # here: the bits are normative and compared exactly, and the check would double the cost)
        "if": {"properties": {"value": {"type": "string"}}},
        "then": {"anyOf": [
            {"properties": {"value": {"const": "NaN"}, f"f{width}": {"pattern": nan}}},
            {"properties": {"value": {"const": "Infinity"}, f"f{width}": {"const": inf}}},
            {"properties": {"value": {"const": "-Infinity"}, f"f{width}": {"const": ninf}}},
        ]},
    }


def _request(op: str, args: dict, required: list[str], with_profile: bool) -> dict:
    props: dict[str, Any] = {"op": {"const": op}}
    req = ["op"]
    if op != "capabilities":
        props["id"] = {"description": "the vector id, for the testee's own logging", "type": "string"}
        req.append("id")
    if with_profile:
        props["profile"] = {"$ref": f"{PROTO}#/$defs/profile"}
        req.append("profile")
    props.update(args)
    return {"type": "object", "required": req + required, "additionalProperties": False, "properties": props}


def _response(op: str, result: dict) -> dict:
    errors = list(OPERATION_ERRORS[op]) + list(UNIVERSAL_ERRORS)
    # if/then rather than oneOf, so that a violation is reported at the field that breaks it
    return {"type": "object", "required": ["ok"], "properties": {"ok": {"type": "boolean"}},
            "if": {"properties": {"ok": {"const": True}}},
            "then": {"allOf": [{"$ref": f"{PROTO}#/$defs/ok"}, {"properties": {"result": result}}]},
            "else": {"if": {"required": ["unsupported"]},
                     "then": {"$ref": f"{PROTO}#/$defs/unsupported"},
                     "else": {"allOf": [{"$ref": f"{PROTO}#/$defs/error"}, {"properties": {"error": {
                         "description": f"the error classes {op} can answer", "enum": errors}}}]}}}


def _u(bits: int, doc: str) -> dict:
    return {"description": doc, **_uint(bits)}


HEXARG = {"$ref": f"{PROTO}#/$defs/hex"}


def operation_schemas(vm: ValueModel) -> dict[str, dict]:
    profiles = list(vm.r.profile_names)
    frame_key = ("osdk_frame", ())
    payload_key = ("osdk_payload", ())
    mode_key = ("osdk_control_mode", ())
    movement_key = ("osdk_movement_control", ())
    combos = sorted({c for p in profiles for b in range(256)
                     if (c := vm.r.classify_control_mode(b, p)["combination"]) is not None})
    classifications = list(vm.r.data["control_mode"]["classification_precedence"])
    ops: dict[str, dict] = {}

    def vm_ref(key, profile=None, bound=None) -> dict:
        ref = vm.type_ref(key, profile, bound or {})
        return {"$ref": VM + ref["$ref"]}

    def payload_body(profile) -> dict:
        """The model of osdk_payload's `body` for the profile (any command or ACK)."""
        return {"$ref": VM + vm.type_ref(payload_key, profile, {})["$ref"] + "/properties/body"}

    # capabilities
    ops["capabilities"] = {
        "request": _request("capabilities", {}, [], False),
        "result": {"type": "object", "required": ["name", "operations", "profiles"], "additionalProperties": False,
                   "properties": {
                       "name": {"type": "string"},
                       "operations": {"type": "array", "uniqueItems": True,
                                      "items": {"enum": list(OPERATION_ERRORS)}},
                       "profiles": {"type": "array", "uniqueItems": True,
                                    "items": {"$ref": f"{PROTO}#/$defs/profile"}}}},
    }
    # decode_stream
    ev_common = {"offset": {"description": "absolute byte offset of the first byte the event covers",
                            "type": "integer", "minimum": 0}}

    def stream_result(p):
        frame = vm_ref(frame_key, p)
        ack = {"description": "the ACK's value decoded as the answer to `ack_of` "
                              "(osdk_payload's body with is_ack true)", "allOf": [payload_body(p)]}
        frame_event = {"type": "object", "required": ["offset", "kind", "frame"], "additionalProperties": False,
                       "dependentRequired": {"ack_of": ["ack"], "ack": ["ack_of"]},
                       "properties": {**ev_common, "kind": {"const": "frame"}, "frame": frame,
                                      "command": {"description": "informative, not compared: the command's name, "
                                                                 "or none (header-only), encrypted, ack (an ACK "
                                                                 "not matched); the reference leaves it out of a "
                                                                 "matched ACK, whose ack_of names the command",
                                                  "anyOf": [{"$ref": f"{PROTO}#/$defs/command_name"},
                                                            {"enum": ["none", "encrypted", "ack"]}]},
                                      "ack_of": {"$ref": f"{PROTO}#/$defs/command_name"},
                                      "ack": {"$ref": "#/$defs/ack_body." + p}}}
        error_event = {"type": "object", "required": ["offset", "kind", "error", "length"],
                       "additionalProperties": False,
                       "properties": {**ev_common, "kind": {"const": "error"},
                                      "error": {"enum": list(STREAM_ERRORS)},
                                      "length": {"description": "how many bytes the event covers (see PROTOCOL.md, "
                                                                "stream rules)", "type": "integer", "minimum": 1},
                                      "detail": {"type": "string"},
                                      "frame_header": {"$ref": f"{PROTO}#/$defs/frame_header"},
                                      "ack_of": {"$ref": f"{PROTO}#/$defs/command_name"},
                                      "raw": {"description": "informative, not compared: the bytes the event "
                                                             "covers (the reference adds them to an undecodable "
                                                             "event, a failure of its own)", **HEXARG}}}
        garbage_event = {"type": "object", "required": ["offset", "kind", "length"], "additionalProperties": False,
                         "properties": {**ev_common, "kind": {"const": "garbage"},
                                        "length": {"type": "integer", "minimum": 1}}}
        return {"type": "object", "required": ["events"], "additionalProperties": False,
                "properties": {"events": {"type": "array", "items": {"oneOf": [frame_event, error_event,
                                                                                garbage_event]}}}}, ack

    stream = {"request": _request("decode_stream", {
        "hex": HEXARG,
        "chunks": {"description": "sizes of the reads the bytes arrive in; what they leave over arrives as one "
                                  "last read", "type": "array", "items": {"type": "integer", "minimum": 0}}},
        ["hex", "chunks"], True)}
    for p in profiles:
        res, ack = stream_result(p)
        stream[f"result.{p}"] = res
        stream[f"ack_body.{p}"] = ack
    ops["decode_stream"] = stream

    frame_op = {"request": _request("decode_frame", {"hex": {"description": "exactly one frame's bytes",
                                                            **HEXARG}}, ["hex"], True)}
    for p in profiles:
        frame_op[f"result.{p}"] = {"type": "object", "required": ["frame"], "additionalProperties": False,
                                   "properties": {"frame": vm_ref(frame_key, p)}}
    ops["decode_frame"] = frame_op

    pay = {"request": _request("decode_payload", {
        "hex": HEXARG, "cmd_set": _u(8, "command set"), "cmd_id": _u(8, "command id"),
        "is_ack": {"description": "true: the value of an ACK answering (cmd_set, cmd_id)", "type": "boolean"}},
        ["hex", "cmd_set", "cmd_id", "is_ack"], True)}
    for p in profiles:
        pay[f"result.{p}"] = {"type": "object", "required": ["value"], "additionalProperties": False,
                              "properties": {"value": {"description": "the model of osdk_payload's `body`",
                                                       **payload_body(p)}}}
    ops["decode_payload"] = pay

    combination = {"description": "index of the documented combination (rules.yaml control_modes.combinations)",
                   "enum": combos}
    ops["classify_control_mode"] = {
        "request": _request("classify_control_mode", {"byte": _u(8, "the control mode byte")}, ["byte"], True),
        "result": {"type": "object", "required": ["fields", "classification", "combination"],
                   "additionalProperties": False,
                   "properties": {"fields": vm_ref(mode_key),
                                  "classification": {"enum": classifications},
                                  "combination": {"anyOf": [combination, {"type": "null"}]}},
                   "allOf": [{"if": {"properties": {"classification": {"const": "documented"}}},
                              "then": {"properties": {"combination": combination}},
                              "else": {"properties": {"combination": {"type": "null"}}}}]},
    }
    ops["check_movement_control"] = {
        "request": _request("check_movement_control", {"hex": {"description": "the 17-byte value", **HEXARG}},
                            ["hex"], True),
        "result": {"type": "object", "required": ["value", "combination"], "additionalProperties": False,
                   "properties": {"value": vm_ref(movement_key), "combination": combination}},
    }
    f32 = {"$ref": f"{PROTO}#/$defs/f32_input"}
    ops["encode_movement_control"] = {
        "request": _request("encode_movement_control", {"mode": _u(8, "the control mode byte"),
                                                         "x": f32, "y": f32, "z": f32, "yaw": f32},
                            ["mode", "x", "y", "z", "yaw"], False),
        "result": {"type": "object", "required": ["hex"], "additionalProperties": False,
                   "properties": {"hex": {"description": "the 17-byte value", "type": "string",
                                          "pattern": "^[0-9a-f]{34}$"}}},
    }
    enc_req = _request("encode_frame", {
        "cmd_set": _u(8, "command set (absent for an ACK)"), "cmd_id": _u(8, "command id (absent for an ACK)"),
        "is_ack": {"type": "boolean"}, "session": _u(5, "session 0-31"), "seq": _u(16, "sequence number"),
        "value": {"description": "the value bytes (after cmd_set and cmd_id)", **HEXARG}},
        ["is_ack", "session", "seq", "value"], False)
    enc_req["allOf"] = [{"if": {"properties": {"is_ack": {"const": True}}},
                         "then": {"not": {"anyOf": [{"required": ["cmd_set"]}, {"required": ["cmd_id"]}]}},
                         "else": {"required": ["cmd_set", "cmd_id"]}}]
    ops["encode_frame"] = {"request": enc_req,
                           "result": {"type": "object", "required": ["hex"], "additionalProperties": False,
                                      "properties": {"hex": {"description": "the whole frame", "type": "string",
                                                             "pattern": "^aa([0-9a-f]{2}){11,}$"}}}}

    version_id = optional_field(vm, VERSION_ACK, "version_id")
    out = {}
    for op, defs in ops.items():
        results = {k: v for k, v in defs.items() if k.startswith("result")}
        for k, v in list(results.items()):
            defs["response" + k[len("result"):]] = _response(op, {"$ref": f"#/$defs/{k}"})
        out[op] = _doc(f"{op}.schema.json", f"osdk testee protocol: {op}",
                       f"Request and response of `{op}` (conformance/PROTOCOL.md). $defs/request is the request "
                       "line; $defs/response (or $defs/response.<profile> for an operation whose result depends "
                       "on the profile: the broadcast layout, and the version ACK's version_id on "
                       f"{_and(version_id['on'])}, ERRATA E30) a response line. Generated by tools/gen_schemas.py.",
                       defs)
    return out


VERSION_ACK = ("osdk_payload", ("version_ack_value",))


def optional_field(vm: ValueModel, key, fid: str) -> dict[str, Any]:
    """Where a field that only some profiles have is present: the profiles
    with it ("on") and without it ("off"), as the schema of the type decides
    them per profile, and its neighbours and size in the type's seq."""
    on, off = [], []
    for p in vm.r.profile_names:
        props = vm.defs[vm.type_ref(key, p, {})["$ref"].removeprefix("#/$defs/")]["properties"]
        (off if props[fid] is False else on).append(p)
    seq = vm.index.raw_seq(vm.index.types[key])
    at = [f["id"] for f in seq].index(fid)
    return {"on": on, "off": off, "size": seq[at].get("size"),
            "after": seq[at - 1]["id"] if at else None, "before": seq[at + 1]["id"] if at + 1 < len(seq) else None}


def _and(names: list[str], quote: str = "") -> str:
    q = [f"{quote}{n}{quote}" for n in names]
    return " and ".join(q) if len(q) < 3 else ", ".join(q[:-1]) + " and " + q[-1]


def schemas(vm: ValueModel | None = None) -> dict[str, dict]:
    vm = vm or ValueModel()
    ops = operation_schemas(vm)
    proto = protocol_schema(vm)
    value_model = _doc(VM, "osdk JSON value model", "One definition per spec/*.ksy type (\"file.type\", with "
                       "bound parameters in parentheses and @profile when the layout depends on the wire "
                       "profile) and per enum (\"enum.file.name\"), as docs/VALUE-MODEL.md renders them. "
                       "Generated by tools/gen_schemas.py from spec/*.ksy.", dict(sorted(vm.defs.items())))
    return {PROTO: proto, VM: value_model, **{f"{op}.schema.json": s for op, s in ops.items()}}


def render(doc: dict) -> str:
    return json.dumps(doc, indent=1, ensure_ascii=False, allow_nan=False) + "\n"


# ----------------------------------------------------------------- generated regions of docs/NAMING.md

NAMING = ROOT / "docs" / "NAMING.md"
_REGION = re.compile(r"(?P<open><!-- (?P<name>[a-z_]+):begin \(tools/gen_schemas\.py writes this part\) -->\n)"
                     r"(?P<body>.*?)(?P<close><!-- (?P=name):end -->)", re.S)


def naming_regions(vm: ValueModel) -> dict[str, str]:
    """The parts of docs/NAMING.md that restate the spec: the profiles with
    their ksy enum names and values, the control mode byte's fields, the
    broadcast item names, which profiles the version ACK's version_id is on,
    and the other enums."""
    rows = ["| id (CLI, rules, vectors) | ksy enum name (`profile`) | value |", "|---|---|---|"]
    rows += [f"| `{p}` | `{vm.ksy_profiles[p]}` | {vm.r.profile(p).value} |" for p in vm.r.profile_names]
    items = vm.r.broadcast_item_names
    vid = optional_field(vm, VERSION_ACK, "version_id")
    version = f"`version_id` ({vid['size']} bytes, hex) is present "
    version += f"on {_and(vid['on'], '`')} only" if vid["off"] else "on every profile"
    version += f", between `{vid['after']}` and `{vid['before']}`"
    if vid["off"]:
        version += f"; {_and(vid['off'], '`')} {'has' if len(vid['off']) == 1 else 'have'} no such field"
    version += " (spec/ERRATA.md E30)."
    fields = vm.r.data["control_mode"]["fields"]
    mode_lines = []
    for f in fields:
        top = f["lsb"] + f["width"] - 1
        bits = f"bits {top}-{f['lsb']}" if f["width"] > 1 else f"bit {f['lsb']}"
        undefined = [str(u["value"]) for u in f["undefined"]]
        mode_lines.append(f"- `{f['name']}` ({bits}): " + ", ".join(f"`{v['name']}`={v['value']}" for v in f["values"])
                          + (f" ({', '.join(undefined)} undefined)" if undefined else ""))
    enum_lines = []
    for name in vm.r.enum_names:
        if name == "profile" or name in {f["name"] for f in fields}:
            continue  # in the Profiles table and the control mode byte above
        values = vm.r.enum(name)
        wide = max(values) > 0xFF  # a u2 enum reads best in hex
        enum_lines.append(f"- `{name}`: " + ", ".join(f"{f'0x{v:04X}' if wide else v} `{n}`" for v, n in values.items()))
    return {
        "profiles": "\n".join(rows),
        "control_mode": "\n".join(mode_lines),
        "broadcast_items": textwrap.fill(", ".join(f"`{i}`" for i in items) + ".", width=79),
        "version_id": textwrap.fill(version, width=79),
        "enums": "\n".join(enum_lines),
    }


# ----------------------------------------------------------------- generated regions of conformance/PROTOCOL.md

PROTOCOL = ROOT / "conformance" / "PROTOCOL.md"
RESERVED = "(reserved)"


def _variant_fields(vm: ValueModel, item: rules.BroadcastItem, params: dict) -> list[str]:
    """The fields of a parametric item's type that its params leave out."""
    ref = vm.type_ref((rules.ITEMS_KSY_ID, (item.type,)), None, params)["$ref"].removeprefix("#/$defs/")
    return [fid for fid, schema in vm.defs[ref]["properties"].items() if schema is False]


def protocol_regions(vm: ValueModel) -> dict[str, str]:
    """The parts of conformance/PROTOCOL.md that restate the spec: the profile
    ids, the version ACK's layout per profile, the flag bit table, the
    variants of the parametric broadcast items and the control mode parts
    (_control_mode_regions)."""
    r = vm.r
    names = r.profile_names
    profiles = {p: r.profile(p) for p in names}

    fid = "version_id"
    vid = optional_field(vm, VERSION_ACK, fid)
    sizes = {p: vm.index.type_size(VERSION_ACK[0], VERSION_ACK[1][0], {"profile": f"profile::{vm.ksy_profiles[p]}"})
             for p in names}

    def ack_size(group: list[str]) -> int:
        if len({sizes[p] for p in group}) != 1:
            raise SystemExit(f"gen_schemas: version_ack_value has several sizes on {', '.join(group)}: "
                             "conformance/PROTOCOL.md cannot say them in one phrase")
        return sizes[group[0]]

    carries = f"`{fid}` ({vid['size']} bytes, hex) between `{vid['after']}` and `{vid['before']}`"
    if vid["off"]:
        version = (f"On {_and(vid['on'], '`')} the version ACK carries {carries} ({ack_size(vid['on'])} bytes in all); "
                   f"on {_and(vid['off'], '`')} it has no `{fid}` ({ack_size(vid['off'])} bytes; "
                   "ERRATA E30). Decoding either layout under a profile of the other is a length error "
                   "(`truncated_payload` or `length_mismatch`).")
    else:
        version = f"On every profile the version ACK carries {carries} ({ack_size(vid['on'])} bytes in all)."

    # one row per flag bit; consecutive bits on which every profile agrees (the same item, or reserved)
    # share a row, their items listed once and the other profiles' cells saying "same"
    width = int(re.fullmatch(r"u(\d+)(?:_[lb]e)?", r.data["frame"]["broadcast"]["flags"]).group(1))
    cells = [tuple(profiles[p].flag_bits[b] if b < len(profiles[p].flag_bits) else RESERVED for p in names)
             for b in range(width)]

    def agreed(row: tuple[str, ...]) -> str | None:
        return None if len(set(row)) > 1 else "reserved" if row[0] == RESERVED else "item"

    groups: list[list[int]] = []
    for b, row in enumerate(cells):
        if groups and agreed(row) is not None and agreed(row) == agreed(cells[groups[-1][-1]]):
            groups[-1].append(b)
        else:
            groups.append([b])
    table = ["| flag bit | " + " | ".join(names) + " |", "|---" * (len(names) + 1) + "|"]
    for bits in groups:
        span = str(bits[0]) if len(bits) == 1 else f"{bits[0]}-{bits[-1]}"
        row = cells[bits[0]]
        shown = [", ".join(cells[b][0] for b in bits)] + ["same"] * (len(names) - 1) if agreed(row) == "item" \
            else list(row)
        table.append(f"| {span} | " + " | ".join(shown) + " |")

    # per profile, the variant of each parametric item it has; profiles with the same variants share a line
    lines: dict[str, list[str]] = {}
    for p in names:
        parts = []
        for name in profiles[p].flag_bits:
            item = r.broadcast_item(name)
            if not item.params:
                continue
            left_out = _variant_fields(vm, item, dict(profiles[p].item_params[name]))
            size = profiles[p].item_sizes[name]
            without = f" without {_and(left_out, '`')}" if left_out else ""
            parts.append(f"`{name}`{without} ({size} byte{'s' if size != 1 else ''})")
        lines.setdefault(", ".join(parts), []).append(p)
    variants = [f"- {', '.join(f'`{p}`' for p in ps)}: {text}." for text, ps in lines.items()]

    return {
        "profile_ids": textwrap.fill(f"The profiles are the ids {_and(list(names), '`')} (docs/NAMING.md).",
                                     width=75),
        "version_ack": textwrap.fill(version, width=75),
        "flag_bits": "\n".join(table),
        "item_variants": "\n".join(textwrap.fill(v, width=75, subsequent_indent="  ") for v in variants),
        **_control_mode_regions(r),
    }


def _grouped(keys: dict[str, Any]) -> list[tuple[Any, list[str]]]:
    """(key, the profiles with that key), in the order keys first appear."""
    out: dict[Any, list[str]] = {}
    for p, k in keys.items():
        out.setdefault(k, []).append(p)
    return list(out.items())


def _span(values: list[int]) -> str:
    return f"{values[0]}-{values[-1]}" if values == list(range(values[0], values[-1] + 1)) and len(values) > 1 \
        else _and([str(v) for v in values])


def _range(r: dict[str, Any]) -> str:
    if r["min"] is None and r["max"] is None:
        return "unbounded"
    lo, hi = ("unbounded" if v is None else str(v) for v in (r["min"], r["max"]))
    return f"{lo}..{hi} {r['unit']}"


def _control_mode_regions(r: rules.Rules) -> dict[str, str]:
    """The classify_control_mode findings (undefined field values, what bit 0
    is on each profile, documented and undocumented combinations), how many
    bytes each profile documents, and the input range table."""
    names = r.profile_names
    cm, cmodes = r.data["control_mode"], r.data["control_modes"]
    fields = {f["name"]: f for f in cm["fields"]}

    # undefined field values, one clause per classification, in the order the fields name them
    by_class: dict[str, list[str]] = {}
    for f in cm["fields"]:
        for cls in dict.fromkeys(u["classification"] for u in f["undefined"]):
            mine = [str(u["value"]) for u in f["undefined"] if u["classification"] == cls]
            by_class.setdefault(cls, []).append(f"`{f['name']}` {' or '.join(mine)}")
    findings = ["- " + "; ".join(f"{', '.join(fs)}: `{cls}`" for cls, fs in by_class.items()) + ";"]

    # bit 0: where it is the yaw frame, a yaw angle needs one of its values (errata E15)
    yaw_ang = next(v["value"] for v in fields["yaw_logic"]["values"] if v["name"] == "yaw_ang")
    bit0 = cm["bit0_by_profile"]
    frames = {p: (bit0[p]["yaw_ang_requires"], bit0[p]["violation"]["classification"],
                  tuple(dict.fromkeys(re.findall(r"errata (E\d+)", bit0[p]["source"]))))
              for p in names if bit0[p]["meaning"] == "yaw_frame"}
    for (requires, cls, errata), ps in _grouped(frames):
        where = "on every profile" if len(ps) == len(names) else f"on {_and(ps, '`')} only"
        cite = f" (ERRATA {', '.join(errata)})" if errata else ""
        other = next(v["value"] for v in bit0[ps[0]]["values"] if v["value"] != requires)
        findings.append(f"- {where}, bit 0 is the yaw frame{cite}: `yaw_logic` {yaw_ang} (`yaw_ang`) with "
                        f"bit 0 = {other} is `{cls}`;")
    if not frames:
        findings.append("- bit 0 is `stable_mode` on every profile and has no finding of its own;")

    # logic triples: the documented rows of the range table, the rest undocumented
    per_profile = {p: tuple(tuple(_range(c["ranges"][p][axis]) for axis in ("horizontal", "vertical", "yaw"))
                            for c in cmodes["combinations"])
                   for p in names}
    range_groups = _grouped(per_profile)
    undocumented = cmodes["undocumented"]
    which = []
    for axis, fname in (("horizontal", "horizontal_logic"), ("vertical", "vertical_logic"), ("yaw", "yaw_logic")):
        used = list(dict.fromkeys(c[axis] for c in undocumented))
        if len(used) < len(fields[fname]["values"]):  # an axis that takes every value says nothing
            which.append(" or ".join(f"`{n}`" for n in used))
    kinds = " with ".join(which) + ", " if which else ""
    findings.append(f"- when the three logic fields all have names: their combination is `documented` when it "
                    f"is one of the {len(cmodes['combinations'])} rows of "
                    f"{'the table' if len(range_groups) == 1 else 'each table'} below, else "
                    f"({kinds}indices {_span([c['index'] for c in undocumented])}) "
                    "`undocumented`.")

    counts = {p: sum(r.classify_control_mode(b, p)["classification"] == "documented" for b in range(256))
              for p in names}
    groups = sorted(_grouped(counts), key=lambda kv: -kv[0])
    if len(groups) == 1:
        documented = f"So {groups[0][0]} bytes are documented on every profile."
    else:
        documented = "So " + ", ".join(f"{n}{' bytes are documented' if i == 0 else ''} on {_and(ps, '`')}"
                                       for i, (n, ps) in enumerate(groups)) + "."

    # input ranges: one table per group of profiles whose ranges agree on every combination
    masks = {c["mask"] for c in cmodes["combinations"]}
    if len(masks) != 1:
        raise SystemExit("gen_schemas: control_modes.combinations have several masks: "
                         "conformance/PROTOCOL.md cannot show them in one column")
    mask = masks.pop()
    bits = [b for b in range(8) if mask >> b & 1]
    header = (f"| combination | mode bits {bits[-1]}-{bits[0]} (byte & 0x{mask:02X}) | horizontal | vertical | yaw "
              "| x, y range | z range | yaw range |")
    tables = []
    for ranges, ps in range_groups:
        where = "The ranges are the same on every profile" if len(ps) == len(names) \
            else f"On {_and(ps, '`')} the ranges are"
        sources = list(dict.fromkeys(cmodes["profile_ranges"][p] for p in ps))
        rows = [textwrap.fill(f"{where} (rules.yaml `control_modes.profile_ranges`: "
                              f"{', '.join(f'`{s}`' for s in sources)}):", width=75),
                "", header, "|---" * 8 + "|"]
        rows += [f"| {c['index']} | 0x{c['value']:02X} | `{c['horizontal']}` | `{c['vertical']}` | `{c['yaw']}` | "
                 + " | ".join(rng) + " |" for c, rng in zip(cmodes["combinations"], ranges)]
        tables.append("\n".join(rows))

    return {
        "control_mode_findings": "\n".join(textwrap.fill(f, width=75, subsequent_indent="  ") for f in findings),
        "documented_bytes": textwrap.fill(documented, width=75),
        "input_ranges": "\n\n".join(tables),
    }


def fill_regions(text: str, regions: dict[str, str], where: str) -> str:
    """`text` with the body of each marked region replaced; every region
    must be marked exactly once."""
    found = [m.group("name") for m in _REGION.finditer(text)]
    problems = [f"no region {n!r}" for n in regions if n not in found]
    problems += [f"region {n!r} is marked {found.count(n)} times" for n in set(found) if found.count(n) > 1]
    problems += [f"unknown region {n!r}" for n in found if n not in regions]
    if problems:
        raise SystemExit(f"gen_schemas: {where}: " + "; ".join(sorted(problems)))
    return _REGION.sub(lambda m: m.group("open") + regions[m.group("name")] + "\n" + m.group("close"), text)


def generated_docs(vm: ValueModel) -> dict[Path, tuple[str, str]]:
    """Each document with generated parts: (its text now, its text as the spec writes it)."""
    out = {}
    for path, regions in ((NAMING, naming_regions(vm)), (PROTOCOL, protocol_regions(vm))):
        have = path.read_text()
        out[path] = (have, fill_regions(have, regions, str(path.relative_to(ROOT))))
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true",
                    help="fail if conformance/schemas/ or the generated parts of docs/NAMING.md and "
                         "conformance/PROTOCOL.md are not what the spec produces")
    args = ap.parse_args(argv)
    vm = ValueModel()
    want = {name: render(doc) for name, doc in schemas(vm).items()}
    docs = generated_docs(vm)
    doc_names = " and ".join(str(path.relative_to(ROOT)) for path in docs)
    if args.check:
        have = {p.name: p.read_text() for p in SCHEMA_DIR.glob("*.schema.json")} if SCHEMA_DIR.is_dir() else {}
        drift = [f"differs: {n}" for n in want if have.get(n) != want[n]]
        drift += [f"not generated: {n}" for n in have if n not in want]
        drift += [f"differs: the generated parts of {path.relative_to(ROOT)}"
                  for path, (text, wanted) in docs.items() if text != wanted]
        if drift:
            print(f"gen_schemas: conformance/schemas/ or the generated parts of {doc_names} are out of date "
                  "(run tools/gen_schemas.py):", file=sys.stderr)
            for d in drift:
                print(f"  {d}", file=sys.stderr)
            return 1
        print(f"gen_schemas: conformance/schemas/ ({len(want)} files) and the generated parts of {doc_names} "
              "match spec/")
        return 0
    SCHEMA_DIR.mkdir(parents=True, exist_ok=True)
    for old in SCHEMA_DIR.glob("*.schema.json"):
        if old.name not in want:
            old.unlink()
    for name, text in want.items():
        (SCHEMA_DIR / name).write_text(text)
    for path, (text, wanted) in docs.items():
        if wanted != text:
            path.write_text(wanted)
    print(f"gen_schemas: {len(want)} files -> {SCHEMA_DIR.relative_to(ROOT)}; generated parts of {doc_names}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
