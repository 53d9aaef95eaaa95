#!/usr/bin/env python3
"""Write generated/wireshark/osdk.lua: the Lua runtime of tools/wiresharkgen/runtime.lua
followed by tables describing every layout of spec/*.ksy and spec/rules.yaml.

usage: tools/wiresharkgen/generate.py --out DIR

The dissector is table-driven: the runtime interprets one layout tree per
broadcast profile, made here by resolving the .ksy types with their params
bound. Whatever can be decided from the profile alone (which items and item
variants a profile has, the broadcast layout chosen by the profile) is
decided here; conditions on values read from the wire (flag bits, LEN,
IS_ACK, the command set and id) become small Lua functions, translated from
the ksy expressions with tools/cgen/expr.py's parser.

Field names: frame and DATA fields are `osdk.<ksy id>`; a command's value is
`osdk.<command name>.<path>`, the value model's key path inside the body,
where a field whose type is a switch (the broadcast's profile switch) adds
no key, as the names of docs/NAMING.md show (`osdk.broadcast.battery`).
A matched ACK's value is `osdk.<command name>.ack.<path>`, laid out by
ACKS, osdk_payload with is_ack true, per profile.
"""
from __future__ import annotations

import argparse
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tools"))

from cgen.expr import Node, parse  # noqa: E402
from osdk_conformance.core import ksy  # noqa: E402
from osdk_conformance.core.commands import COMMANDS, command_name  # noqa: E402
from osdk_conformance.core.crc import engine  # noqa: E402
from osdk_conformance.core.model import ERROR_BY_FIELD  # noqa: E402
from osdk_conformance.core.paths import SPEC  # noqa: E402
from osdk_conformance.core.rules import crc_params, default_rules  # noqa: E402

RUNTIME = Path(__file__).resolve().parent / "runtime.lua"
PROTOCOL_SCHEMA = ROOT / "conformance" / "schemas" / "protocol.schema.json"
ROOT_FILE = "osdk_frame"
PAYLOAD_FILE = "osdk_payload"
ACK_VALUE_FIELD = "ack_value"  # frame_data's raw ACK value: decoded once its command is matched
ACK_KEY = 0x10000  # the bit osdk_payload's dispatch key sets for an ACK layout
CHECKSUM_ERRORS = {"bad_crc16", "bad_crc32"}
_BITS = re.compile(r"b(\d+)")
_PRIM = re.compile(r"([us])([1248])|f([48])")
UINT_TYPES = {1: "uint8", 2: "uint16", 3: "uint24", 4: "uint32", 8: "uint64"}
INT_TYPES = {1: "int8", 2: "int16", 3: "int24", 4: "int32", 8: "int64"}


class GenError(Exception):
    pass


class Runtime:
    """A value only known on the wire: its Lua expression."""

    def __init__(self, lua: str) -> None:
        self.lua = lua


def lua_str(s: str) -> str:
    return '"' + s.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


class Generator:
    def __init__(self) -> None:
        self.index = ksy.load(SPEC)
        self.rules = default_rules()
        self.fields: dict[str, dict] = {}  # abbr -> ProtoField description
        self.enums: dict[str, dict[int, str]] = {}  # "file::enum" -> names

    # ---- ksy lookups ------------------------------------------------------

    def body(self, file_id: str, path: tuple[str, ...]) -> dict:
        b = self.index.files[file_id]
        for part in path:
            b = b["types"][part]
        return b

    def resolve_type(self, file_id: str, path: tuple[str, ...], name: str) -> tuple[str, tuple[str, ...]]:
        """A type name as Kaitai resolves it from inside (file_id, path)."""
        if "::" in name:
            fid, tname = name.split("::")
            return (fid, (tname,)) if tname in (self.index.files[fid].get("types") or {}) else (tname, ())
        for depth in range(len(path), -1, -1):
            scope = self.body(file_id, path[:depth])
            if name in (scope.get("types") or {}):
                return file_id, path[:depth] + (name,)
        if name in self.index.files:
            return name, ()
        raise GenError(f"{file_id}: unknown type {name}")

    def enum_key(self, file_id: str, name: str) -> str:
        fid, ename = name.split("::") if "::" in name else (file_id, name)
        if (fid, ename) not in self.index.enums:
            raise GenError(f"{file_id}: unknown enum {name}")
        key = f"{fid}::{ename}"
        self.enums[key] = self.index.enums[(fid, ename)]
        return key

    def enum_value(self, file_id: str, parts: tuple[str, ...]) -> int:
        fid, ename, member = (file_id, *parts) if len(parts) == 2 else parts
        for value, label in self.index.enums[(fid, ename)].items():
            if label == member:
                return value
        raise GenError(f"{'::'.join(parts)} is not an enum member")

    # ---- expressions ------------------------------------------------------

    def expr(self, text, scope: dict):
        """A ksy expression evaluated when every name it uses is known in
        `scope` (Python values); else a Runtime with its Lua translation.
        YAML has already made a literal `true`, `false` or number a value."""
        if isinstance(text, (bool, int)):
            return text
        return self.node(parse(text), scope)

    def node(self, n: Node, scope: dict):
        k = n.kind
        if k in ("num", "bool"):
            return n.value
        if k == "enumref":
            return self.enum_value(scope["@file"], n.value)
        if k == "name":
            return self.name(n.value, scope)
        if k == "cast":
            return self.node(n.args[0], scope)
        if k == "attr":
            if n.value == "to_i":
                return self.node(n.args[0], scope)
            if n.args[0].kind == "name" and n.args[0].value in ("_parent", "_root"):
                which = n.args[0].value
                target = scope["@parent"] if which == "_parent" else scope["@root"]
                return self.name(n.value, target, prefix="p" if which == "_parent" else "r")
            inner = self.node(n.args[0], scope)
            if n.value == "length":
                return len(inner) if not isinstance(inner, Runtime) else Runtime(f"#{inner.lua}")
            raise GenError(f"attribute .{n.value} is not supported")
        if k == "unary":
            a = self.node(n.args[0], scope)
            if not isinstance(a, Runtime):
                return (not a) if n.value == "not" else -a
            return Runtime(f"({'not ' if n.value == 'not' else '-'}{a.lua})")
        if k == "ternary":
            c = self.node(n.args[0], scope)
            if not isinstance(c, Runtime):
                return self.node(n.args[1] if c else n.args[2], scope)
            a, b = (self.lua(self.node(x, scope)) for x in n.args[1:])
            return Runtime(f"(({c.lua}) and {a} or {b})")
        if k == "binary":
            op = n.value
            a, b = self.node(n.args[0], scope), self.node(n.args[1], scope)
            if not isinstance(a, Runtime) and not isinstance(b, Runtime):
                return {
                    "and": lambda: a and b, "or": lambda: a or b, "==": lambda: a == b, "!=": lambda: a != b,
                    "<": lambda: a < b, "<=": lambda: a <= b, ">": lambda: a > b, ">=": lambda: a >= b,
                    "+": lambda: a + b, "-": lambda: a - b, "*": lambda: a * b, "/": lambda: a // b,
                    "%": lambda: a % b,
                }[op]()
            # a decided operand of and/or settles or drops its side
            if op in ("and", "or"):
                for known, other in ((a, b), (b, a)):
                    if not isinstance(known, Runtime):
                        if op == "and":
                            return other if known else False
                        return True if known else other
            la, lb = self.lua(a), self.lua(b)
            if op == "/":
                return Runtime(f"math.floor({la} / {lb})")
            lop = {"!=": "~="}.get(op, op)
            return Runtime(f"({la} {lop} {lb})")
        raise GenError(f"expression node {k} is not supported")

    def name(self, name: str, scope: dict, prefix: str = "v"):
        if name == "_":
            return scope["@self"]
        if name in scope.get("@params", {}):
            return scope["@params"][name]
        if name in scope.get("@fields", ()):
            return Runtime(f"{prefix}.{name}")
        inst = (scope.get("@instances") or {}).get(name)
        if inst is not None:
            if "value" in inst:
                return self.expr(inst["value"], scope)
            if "pos" in inst and isinstance(inst.get("type"), str) and _PRIM.fullmatch(inst["type"]):
                if prefix != "v":
                    raise GenError(f"instance {name} read from another struct is not supported")
                size = int(inst["type"][1:])
                return Runtime(f"RU(s + {inst['pos']}, {size})")
        raise GenError(f"name {name} is not known here")

    @staticmethod
    def lua(value) -> str:
        if isinstance(value, Runtime):
            return value.lua
        if isinstance(value, bool):
            return "true" if value else "false"
        if isinstance(value, int):
            return str(value)
        raise GenError(f"cannot write {value!r} in Lua")

    def fn(self, value) -> str:
        return f"function(x, v, p, r, a, s) return {self.lua(value)} end"

    # ---- fields -----------------------------------------------------------

    def proto_field(self, abbr: str, ftype: str, label: str, **extra) -> str:
        desc = {"abbr": abbr, "type": ftype, "name": label, **extra}
        seen = self.fields.get(abbr)
        if seen is not None and seen != desc:
            # One field name, two profiles: a single bit in one (a b1 reads as a
            # bool) and a wider field in the other, as a spare flag bit is when a
            # profile fills 15 of the 16 (docs/EXTENDING.md). The integer holds
            # both; the runtime shows the bool as 0 or 1 there.
            pair = {seen["type"], ftype}
            wider = seen if ftype == "bool" else desc
            if "bool" in pair and wider["type"] in UINT_TYPES.values() and not wider.get("enum"):
                self.fields[abbr] = wider
                return abbr
            raise GenError(f"{abbr}: two different field types ({seen} and {desc})")
        self.fields[abbr] = desc
        return abbr

    # ---- layouts ----------------------------------------------------------

    def struct(self, file_id: str, path: tuple[str, ...], params: dict, prefix: str,
               parent: dict | None, root: dict | None, profile: int) -> tuple[list[str], dict]:
        """Lua nodes of a type's seq with its params bound, and its scope."""
        body = self.body(file_id, path)
        scope = {
            "@file": file_id, "@params": params, "@fields": set(), "@instances": body.get("instances") or {},
            "@parent": parent, "@self": None,
        }
        scope["@root"] = root if root is not None else scope
        nodes: list[str] = []
        seq = body.get("seq") or []
        bitrun: list[dict] = []
        bits = 0
        for f in seq:
            t = f.get("type")
            if isinstance(t, str) and _BITS.fullmatch(t):
                if "if" in f or "repeat" in f:
                    raise GenError(f"{f['id']}: a bit field with if/repeat is not supported")
                bitrun.append(f)
                bits += int(t[1:])
                if bits % 8 == 0:
                    nodes.append(self.bit_group(file_id, bitrun, bits, prefix, scope))
                    bitrun, bits = [], 0
                continue
            if bitrun:
                raise GenError(f"{f['id']}: bit fields before it do not fill whole bytes")
            node = self.field(file_id, path, f, prefix, scope, profile)
            scope["@fields"].add(f["id"])
            if node is not None:
                nodes.append(node)
        if bitrun:
            raise GenError(f"{file_id}: trailing bit fields do not fill whole bytes")
        return nodes, scope

    def bit_group(self, file_id: str, run: list[dict], bits: int, prefix: str, scope: dict) -> str:
        size = bits // 8
        if size not in (1, 2, 3, 4):
            raise GenError(f"a bit group of {size} bytes is not supported")
        items, shift = [], 0
        for f in run:
            width = int(f["type"][1:])
            abbr = f"{prefix}.{f['id']}"
            enum = self.enum_key(file_id, f["enum"]) if f.get("enum") else None
            # no ProtoField mask: a flag's bit differs between profiles, so the
            # runtime adds the value it extracted instead
            if width == 1 and enum is None:
                self.proto_field(abbr, "bool", f["id"])
            else:
                self.proto_field(abbr, UINT_TYPES[(width + 7) // 8], f["id"], enum=enum, base="DEC")
            item = [f"id = {lua_str(f['id'])}", f"shift = {shift}", f"width = {width}", f"f = {lua_str(abbr)}"]
            if width == 1 and enum is None:
                item.append("bool = true")
            item += self.valid(f, scope)
            items.append("{ " + ", ".join(item) + " }")
            scope["@fields"].add(f["id"])
            shift += width
        return "{ k = \"bits\", size = %d, items = { %s } }" % (size, ", ".join(items))

    def valid(self, f: dict, scope: dict) -> list[str]:
        if "valid" not in f:
            return []
        v = f["valid"]
        # `valid: false` on a b1 (a spare flag bit) arrives from YAML as a Python bool
        literal = str(v).lower() if isinstance(v, bool) else v
        text = v["expr"] if isinstance(v, dict) else f"_ == {literal}"
        fscope = dict(scope, **{"@self": Runtime("x")})
        check = self.expr(text, fscope)
        if check is True:
            return []
        return [f"valid = {self.fn(check)}", f"err = {lua_str(ERROR_BY_FIELD.get(f['id'], 'undecodable'))}"]

    def field(self, file_id: str, path: tuple[str, ...], f: dict, prefix: str, scope: dict, profile: int) -> str | None:
        fid = f["id"]
        parts = [f"id = {lua_str(fid)}"]
        if "if" in f:
            cond = self.expr(f["if"], scope)
            if cond is False:
                return None
            if cond is not True:
                parts.append(f"cond = {self.fn(cond)}")
        parts += self.valid(f, scope)
        if "size" in f:
            size = self.expr(f["size"], scope)
            parts.append(f"size = {self.fn(size)}")
        elif f.get("size-eos"):
            parts.append("eos = true")
        if f.get("repeat"):
            if f["repeat"] != "expr":
                raise GenError(f"{fid}: repeat {f['repeat']} is not supported")
            count = self.expr(f["repeat-expr"], scope)
            if isinstance(count, Runtime):
                raise GenError(f"{fid}: a repeat count read from the wire is not supported")
            parts.append(f"rep = {count}")
        abbr = f"{prefix}.{fid}"
        t = f.get("type")
        in_model = fid != "trailing"  # never part of the value model: only checked
        if "contents" in f:
            parts += ["k = \"bytes\"", f"n = {len(f['contents'])}", f"f = {lua_str(abbr)}"]
            self.proto_field(abbr, "bytes", fid)
            contents = "".join(f"\\x{b:02x}" for b in f["contents"])
            parts += [f"valid = function(x) return x == \"{contents}\" end",
                      f"err = {lua_str(ERROR_BY_FIELD.get(fid, 'undecodable'))}"]
            return "{ " + ", ".join(parts) + " }"
        if t is None:
            parts.append("k = \"bytes\"")
            if fid == ACK_VALUE_FIELD and file_id == ROOT_FILE:
                parts.append("ack = true")
            if in_model:
                parts.append(f"f = {lua_str(abbr)}")
                self.proto_field(abbr, "bytes", fid)
            return "{ " + ", ".join(parts) + " }"
        if isinstance(t, dict):
            return self.switch(file_id, path, f, t, prefix, scope, parts, profile)
        m = _PRIM.fullmatch(t)
        if m:
            if m.group(3):
                size = int(m.group(3))
                self.proto_field(abbr, "float" if size == 4 else "double", fid)
                self.proto_field(abbr + ".bits", UINT_TYPES[size], fid + " (IEEE bits)", base="HEX")
                parts += ["k = \"f\"", f"n = {size}", f"f = {lua_str(abbr)}", f"fb = {lua_str(abbr + '.bits')}"]
            else:
                size, signed = int(m.group(2)), m.group(1) == "s"
                enum = self.enum_key(file_id, f["enum"]) if f.get("enum") else None
                self.proto_field(abbr, (INT_TYPES if signed else UINT_TYPES)[size], fid, enum=enum, base="DEC")
                parts += [f"k = \"{'s' if signed else 'u'}\"", f"n = {size}", f"f = {lua_str(abbr)}"]
            return "{ " + ", ".join(parts) + " }"
        return self.user(file_id, path, f, t, prefix, scope, parts, profile)

    def user(self, file_id, path, f, t, prefix, scope, parts, profile) -> str:
        name, _, args = t.partition("(")
        tfile, tpath = self.resolve_type(file_id, path, name)
        tbody = self.body(tfile, tpath)
        declared = [p["id"] for p in tbody.get("params") or []]
        values = [self.expr(a.strip(), scope) for a in args.rstrip(")").split(",")] if args else []
        if len(values) != len(declared):
            raise GenError(f"{f['id']}: {t} takes {declared}")
        params = dict(zip(declared, values))
        if tfile == PAYLOAD_FILE and not tpath:
            return self.payload(f, params, scope, parts, profile)
        if any(isinstance(x, Runtime) for x in values):
            raise GenError(f"{f['id']}: params read from the wire are supported for osdk_payload only")
        child_prefix = f"{prefix}.{f['id']}"
        nodes, _ = self.struct(tfile, tpath, params, child_prefix, scope, scope["@root"], profile)
        self.proto_field(child_prefix, "none", f["id"])
        parts += ["k = \"struct\"", f"f = {lua_str(child_prefix)}", "seq = {\n" + ",\n".join(nodes) + "\n}"]
        return "{ " + ", ".join(parts) + " }"

    def switch(self, file_id, path, f, t, prefix, scope, parts, profile) -> str:
        on = self.expr(t["switch-on"], scope)
        cases = {}
        default = None
        for key, tname in t["cases"].items():
            if key == "_":
                default = tname
                continue
            kval = self.expr(str(key), scope) if isinstance(key, str) else key
            cases[kval] = tname
        if not isinstance(on, Runtime):
            chosen = cases.get(on, default)
            if chosen is None:
                raise GenError(f"{f['id']}: no case for {on}")
            return self.user_inline(file_id, path, f, chosen, prefix, scope, parts, profile)
        out = []
        for kval, tname in sorted(cases.items()):
            out.append(f"[{kval}] = " + self.user_inline(file_id, path, f, tname, prefix, scope, [], profile))
        parts += ["k = \"switch\"", f"on = {self.fn(on)}", "cases = {\n" + ",\n".join(out) + "\n}"]
        if default is not None:
            parts.append("default = " + self.user_inline(file_id, path, f, default, prefix, scope, [], profile))
        else:
            # a switch without a default keeps the bytes raw (Kaitai's rule)
            abbr = f"{prefix}.{f['id']}"
            self.proto_field(abbr, "bytes", f["id"])
            parts.append(f"default = {{ k = \"bytes\", id = {lua_str(f['id'])}, eos = true, f = {lua_str(abbr)} }}")
        return "{ " + ", ".join(parts) + " }"

    def user_inline(self, file_id, path, f, tname, prefix, scope, parts, profile) -> str:
        """A switch case: the type's fields under the switch field's own path
        (a switch adds no key to the path); the values still go under its id."""
        name, _, args = tname.partition("(")
        tfile, tpath = self.resolve_type(file_id, path, name)
        tbody = self.body(tfile, tpath)
        declared = [p["id"] for p in tbody.get("params") or []]
        values = [self.expr(a.strip(), scope) for a in args.rstrip(")").split(",")] if args else []
        if any(isinstance(x, Runtime) for x in values):
            raise GenError(f"{tname}: params read from the wire are not supported in a switch case")
        params = dict(zip(declared, values))
        nodes, _ = self.struct(tfile, tpath, params, prefix, scope, scope["@root"], profile)
        return "{ " + ", ".join(parts + ["k = \"struct\"", "seq = {\n" + ",\n".join(nodes) + "\n}"]) + " }"

    def payload(self, f, params, scope, parts, profile) -> str:
        """osdk_payload: its body switch by command key, each case's fields
        under `osdk.<command name>`; ACK layouts only when is_ack can be true.
        With is_ack true (the layout of a matched ACK's value) the fields go
        under `osdk.<command name>.ack`, and every named command has a case,
        so that a command without an ACK layout still names its raw value."""
        ack = params.get("is_ack") is True
        body = self.body(PAYLOAD_FILE, ())
        pscope = {"@file": PAYLOAD_FILE, "@params": params, "@fields": set(), "@instances": body.get("instances") or {},
                  "@parent": scope, "@self": None, "@root": scope["@root"]}
        seq = {x["id"]: x for x in body["seq"]}
        sw = seq["body"]["type"]
        on = self.expr(sw["switch-on"], pscope)
        if not isinstance(on, Runtime):
            raise GenError("osdk_payload: the command key must come from the wire")
        self.proto_field("osdk.ack_of" if ack else "osdk.command", "string", "ack_of" if ack else "command")
        suffix = ".ack" if ack else ""
        cases = {k: t for k, t in sw["cases"].items() if k != "_" and bool(k & ACK_KEY) == bool(params.get("is_ack"))}
        if ack:
            for cmd_set, cmd_id in COMMANDS:
                cases.setdefault(ACK_KEY | cmd_set << 8 | cmd_id, sw["cases"]["_"])
        elif params.get("is_ack") is not False:
            raise GenError("osdk_payload: is_ack must be known when the layout is generated")
        out = []
        for key, tname in sorted(cases.items()):
            name = command_name(key >> 8 & 0xFF, key & 0xFF)
            out.append(f"[{key}] = " + self.case(tname, f"osdk.{name}{suffix}", pscope, profile, name))
        default = self.case(sw["cases"]["_"], f"osdk.unknown{suffix}", pscope, profile, "unknown")
        trailing = self.field(PAYLOAD_FILE, (), seq["trailing"], "osdk.value", pscope, profile)
        if ack:
            parts.append("ack = true")
        parts += ["k = \"payload\"", f"on = {self.fn(on)}", "cases = {\n" + ",\n".join(out) + "\n}",
                  f"default = {default}", f"trailing = {trailing}",
                  "args = {" + ", ".join(f"{k} = {self.fn(v)}" for k, v in params.items()) + "}"]
        return "{ " + ", ".join(parts) + " }"

    def case(self, tname: str, prefix: str, pscope: dict, profile: int, command: str) -> str:
        name, _, args = tname.partition("(")
        tfile, tpath = self.resolve_type(PAYLOAD_FILE, (), name)
        tbody = self.body(tfile, tpath)
        declared = [p["id"] for p in tbody.get("params") or []]
        values = [self.expr(a.strip(), pscope) for a in args.rstrip(")").split(",")] if args else []
        nodes, _ = self.struct(tfile, tpath, dict(zip(declared, values)), prefix, pscope, pscope["@root"], profile)
        return "{ k = \"struct\", command = %s, seq = {\n%s\n} }" % (lua_str(command), ",\n".join(nodes))

    # ---- the whole file ---------------------------------------------------

    def profiles(self) -> list[tuple[str, int]]:
        return sorted(((name, p["value"]) for name, p in self.rules.data["profiles"].items()), key=lambda x: x[1])

    def frame(self, profile: int) -> str:
        nodes, _ = self.struct(ROOT_FILE, (), {"profile": profile}, "osdk", None, None, profile)
        return "{\n" + ",\n".join(nodes) + "\n}"

    def ack_layout(self, profile: int) -> str:
        """The layout of a matched ACK's value: osdk_payload(cmd_set, cmd_id,
        true, profile), the pair being the remembered command's (the runtime
        passes them as the values `cmd_set` and `cmd_id`)."""
        body = self.body(PAYLOAD_FILE, ())
        scope = {"@file": PAYLOAD_FILE, "@params": {}, "@fields": {"cmd_set", "cmd_id"}, "@instances": {},
                 "@parent": None, "@self": None}
        scope["@root"] = scope
        declared = [p["id"] for p in body["params"]]
        known = {"cmd_set": Runtime("v.cmd_set"), "cmd_id": Runtime("v.cmd_id"), "is_ack": True, "profile": profile}
        if set(declared) != set(known):
            raise GenError(f"osdk_payload: params {declared}, the ACK layout binds {sorted(known)}")
        return self.payload({"id": "ack"}, known, scope, ["id = \"ack\""], profile)

    def header(self) -> str:
        """The header's fixed fields (those before the first one whose size or
        presence depends on LEN) with their valid checks: what the receiver
        checks on 12 bytes, in rules.yaml's header_checks order."""
        checks = self.rules.data["frame"]["receiver"]["header_checks"]
        out = []
        for name in checks:
            if name in ("crc16", "crc32"):
                p = crc_params(name)
                first, last = p.covers
                out.append("{ crc = %s, from = %d, to = %d, at = %d, n = %d, err = %s }" % (
                    lua_str(name), first, last, p.stored_at[0], p.stored_at[1] - p.stored_at[0] + 1,
                    lua_str(f"bad_{name}")))
            else:
                out.append(f"{{ field = {lua_str(name)} }}")
        return "{ " + ", ".join(out) + " }"

    def crc(self, name: str) -> str:
        p = crc_params(name)
        if not (p.reflect_in and p.reflect_out):
            raise GenError(f"{name}: the runtime computes reflected CRCs only")
        e = engine(name)
        table = ", ".join(str(x) for x in e.table)
        return f"{{ width = {p.width}, init = {p.init}, xorout = {p.xorout}, table = {{ [0] = {table} }} }}"

    def render(self) -> str:
        import json

        frames = [f"[{lua_str(name)}] = {self.frame(value)}" for name, value in self.profiles()]
        acks = [f"[{lua_str(name)}] = {self.ack_layout(value)}" for name, value in self.profiles()]
        errors = json.loads(PROTOCOL_SCHEMA.read_text())["$defs"]["error_class"]["enum"]
        out = [RUNTIME.read_text(), "\n-- ---- generated from spec/*.ksy and spec/rules.yaml ----\n"]
        out.append("ERRORS = {" + ", ".join(
            f"{{ {lua_str(e)}, {'true' if e in CHECKSUM_ERRORS else 'false'} }}" for e in errors) + "}\n")
        out.append("PROFILES = {" + ", ".join(f"{{ {lua_str(n)}, {v} }}" for n, v in self.profiles()) + "}\n")
        # the newest firmware's profile, as the project's tools assume when none is given
        default = self.profiles()[-1][0]
        out.append(f"DEFAULT_PROFILE = {lua_str(default)}\n")
        out.append(f"CRC = {{ crc16 = {self.crc('crc16')},\n crc32 = {self.crc('crc32')} }}\n")
        out.append(f"HEADER_CHECKS = {self.header()}\n")
        out.append("FRAMES = {\n" + ",\n".join(frames) + "\n}\n")
        out.append("ACKS = {\n" + ",\n".join(acks) + "\n}\n")
        out.append("ENUMS = {\n" + ",\n".join(
            f"[{lua_str(k)}] = {{ " + ", ".join(f"[{v}] = {lua_str(n)}" for v, n in sorted(names.items())) + " }"
            for k, names in sorted(self.enums.items())) + "\n}\n")
        out.append("FIELDS = {\n" + ",\n".join(self.field_desc(d) for _, d in sorted(self.fields.items())) + "\n}\n")
        out.append("main()\n")
        return "".join(out)

    @staticmethod
    def field_desc(d: dict) -> str:
        parts = [f"abbr = {lua_str(d['abbr'])}", f"type = {lua_str(d['type'])}", f"name = {lua_str(d['name'])}"]
        for key in ("base",):
            if d.get(key):
                parts.append(f"base = {lua_str(d[key])}")
        if d.get("enum"):
            parts.append(f"enum = {lua_str(d['enum'])}")
        if d.get("mask") is not None:
            parts.append(f"mask = {d['mask']}")
        if d.get("bits") is not None:
            parts.append(f"bits = {d['bits']}")
        return "{ " + ", ".join(parts) + " }"


def write(out: Path) -> Path:
    out.mkdir(parents=True, exist_ok=True)
    dest = out / "osdk.lua"
    dest.write_text(Generator().render())
    return dest


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True, type=Path)
    args = ap.parse_args(argv)
    try:
        write(args.out)
    except GenError as exc:
        print(f"wiresharkgen: {exc}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
