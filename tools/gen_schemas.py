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
osdk_conformance.response_schema and osdk_conformance.commands, profiles
and control mode combinations from spec/rules.yaml. --check regenerates in
memory and fails (exit 1) when the checked-in files differ.
"""
from __future__ import annotations

import argparse
import json
import re
import sys
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from osdk_conformance import ksy, rules  # noqa: E402
from osdk_conformance.commands import COMMANDS  # noqa: E402
from osdk_conformance.model import SKIPPED_FIELDS  # noqa: E402
from osdk_conformance.response_schema import (  # noqa: E402
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
        self.profile_ids = {i: p for i, p in enumerate(self.r.profile_names)}  # ksy enum value -> id
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

    @staticmethod
    def _instance_flags(body: dict, profile: str | None) -> dict[str, bool]:
        """The type's value instances of the form `profile == profile::x` or
        `profile != profile::x`, decided for the profile the schema is for."""
        out = {}
        for name, inst in body.get("instances", {}).items():
            m = re.fullmatch(r"profile (==|!=) profile::(\w+)", str(inst.get("value", "")).strip())
            if m and profile is not None:
                same = profile.replace("-", "_").replace(".", "_") == m.group(2)
                out[name] = same == (m.group(1) == "==")
        return out

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
        return profile.replace("-", "_").replace(".", "_") if profile else None


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

    out = {}
    for op, defs in ops.items():
        results = {k: v for k, v in defs.items() if k.startswith("result")}
        for k, v in list(results.items()):
            defs["response" + k[len("result"):]] = _response(op, {"$ref": f"#/$defs/{k}"})
        out[op] = _doc(f"{op}.schema.json", f"osdk testee protocol: {op}",
                       f"Request and response of `{op}` (conformance/PROTOCOL.md). $defs/request is the request "
                       "line; $defs/response (or $defs/response.<profile> for an operation whose result depends "
                       "on the profile: the broadcast layout, and the version ACK's version_id on m100-fw3.1 and "
                       "a3-fw3.1, ERRATA E30) a response line. Generated by tools/gen_schemas.py.",
                       defs)
    return out


def schemas() -> dict[str, dict]:
    vm = ValueModel()
    ops = operation_schemas(vm)
    proto = protocol_schema(vm)
    value_model = _doc(VM, "osdk JSON value model", "One definition per spec/*.ksy type (\"file.type\", with "
                       "bound parameters in parentheses and @profile when the layout depends on the wire "
                       "profile) and per enum (\"enum.file.name\"), as docs/VALUE-MODEL.md renders them. "
                       "Generated by tools/gen_schemas.py from spec/*.ksy.", dict(sorted(vm.defs.items())))
    return {PROTO: proto, VM: value_model, **{f"{op}.schema.json": s for op, s in ops.items()}}


def render(doc: dict) -> str:
    return json.dumps(doc, indent=1, ensure_ascii=False, allow_nan=False) + "\n"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="fail if conformance/schemas/ is not what the spec produces")
    args = ap.parse_args(argv)
    want = {name: render(doc) for name, doc in schemas().items()}
    if args.check:
        have = {p.name: p.read_text() for p in SCHEMA_DIR.glob("*.schema.json")} if SCHEMA_DIR.is_dir() else {}
        drift = [f"differs: {n}" for n in want if have.get(n) != want[n]]
        drift += [f"not generated: {n}" for n in have if n not in want]
        if drift:
            print("gen_schemas: conformance/schemas/ is out of date (run tools/gen_schemas.py):", file=sys.stderr)
            for d in drift:
                print(f"  {d}", file=sys.stderr)
            return 1
        print(f"gen_schemas: conformance/schemas/ matches spec/ ({len(want)} files)")
        return 0
    SCHEMA_DIR.mkdir(parents=True, exist_ok=True)
    for old in SCHEMA_DIR.glob("*.schema.json"):
        if old.name not in want:
            old.unlink()
    for name, text in want.items():
        (SCHEMA_DIR / name).write_text(text)
    print(f"gen_schemas: {len(want)} files -> {SCHEMA_DIR.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
