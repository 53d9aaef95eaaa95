"""A translator from the Kaitai Struct expression subset the spec uses to C.

It parses an expression into a small tree, types it (int, bool, bytes or
an enum) against a scope supplied by the generator, and renders C99. Any
construct it does not know raises ExprError, so that generation fails
loudly instead of emitting something that might be wrong.

Supported: integer literals (decimal, 0x, 0b), true/false, identifiers,
`_`, `_parent.x`, `_root.x`, `enum::member` and `file::enum::member`,
`.to_i` on enums and booleans, `.length` on byte arrays, unary `-` and
`not`, `* / %`, `+ -`, comparisons, `and`, `or` and the ternary `c ? a : b`.
Integer arithmetic is done in int64_t; `/` and `%` follow Kaitai (floor
division, non-negative remainder for a positive divisor) through helpers.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Callable, Optional


class ExprError(Exception):
    pass


_TOKEN = re.compile(r"""
    \s*(?:
      (?P<num>0[xX][0-9a-fA-F_]+|0[bB][01_]+|[0-9][0-9_]*)
    | (?P<name>[A-Za-z_][A-Za-z0-9_]*)
    | (?P<op>::|==|!=|<=|>=|<<|>>|[-+*/%<>().?:])
    )""", re.X)

KEYWORDS = {"and", "or", "not", "true", "false"}


def tokenize(text: str) -> list[tuple[str, str]]:
    pos, out = 0, []
    text = text.strip()
    while pos < len(text):
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            raise ExprError(f"cannot tokenize {text!r} at {pos}: {text[pos:]!r}")
        pos = m.end()
        if m.group("num") is not None:
            out.append(("num", m.group("num").replace("_", "")))
        elif m.group("name") is not None:
            name = m.group("name")
            out.append(("kw" if name in KEYWORDS else "name", name))
        else:
            out.append(("op", m.group("op")))
    out.append(("end", ""))
    return out


# ---- tree --------------------------------------------------------------------------

@dataclass
class Node:
    kind: str  # num, bool, name, path, enumref, unary, binary, ternary, attr
    value: object = None
    args: tuple = ()


class Parser:
    def __init__(self, text: str) -> None:
        self.text = text
        self.toks = tokenize(text)
        self.i = 0

    def peek(self) -> tuple[str, str]:
        return self.toks[self.i]

    def take(self) -> tuple[str, str]:
        t = self.toks[self.i]
        self.i += 1
        return t

    def expect(self, kind: str, value: str) -> None:
        t = self.take()
        if t != (kind, value):
            raise ExprError(f"{self.text!r}: expected {value!r}, got {t[1]!r}")

    def parse(self) -> Node:
        n = self.ternary()
        if self.peek()[0] != "end":
            raise ExprError(f"{self.text!r}: unexpected {self.peek()[1]!r}")
        return n

    def ternary(self) -> Node:
        cond = self.or_()
        if self.peek() == ("op", "?"):
            self.take()
            a = self.ternary()
            self.expect("op", ":")
            b = self.ternary()
            return Node("ternary", None, (cond, a, b))
        return cond

    def or_(self) -> Node:
        n = self.and_()
        while self.peek() == ("kw", "or"):
            self.take()
            n = Node("binary", "or", (n, self.and_()))
        return n

    def and_(self) -> Node:
        n = self.not_()
        while self.peek() == ("kw", "and"):
            self.take()
            n = Node("binary", "and", (n, self.not_()))
        return n

    def not_(self) -> Node:
        if self.peek() == ("kw", "not"):
            self.take()
            return Node("unary", "not", (self.not_(),))
        return self.cmp()

    def cmp(self) -> Node:
        n = self.add()
        t = self.peek()
        if t[0] == "op" and t[1] in ("==", "!=", "<", "<=", ">", ">="):
            self.take()
            n = Node("binary", t[1], (n, self.add()))
            t2 = self.peek()
            if t2[0] == "op" and t2[1] in ("==", "!=", "<", "<=", ">", ">="):
                raise ExprError(f"{self.text!r}: chained comparisons are not supported")
        return n

    def add(self) -> Node:
        n = self.mul()
        while self.peek()[0] == "op" and self.peek()[1] in ("+", "-"):
            op = self.take()[1]
            n = Node("binary", op, (n, self.mul()))
        return n

    def mul(self) -> Node:
        n = self.unary()
        while self.peek()[0] == "op" and self.peek()[1] in ("*", "/", "%"):
            op = self.take()[1]
            n = Node("binary", op, (n, self.unary()))
        return n

    def unary(self) -> Node:
        if self.peek() == ("op", "-"):
            self.take()
            return Node("unary", "-", (self.unary(),))
        return self.postfix()

    def postfix(self) -> Node:
        n = self.primary()
        while self.peek() == ("op", "."):
            self.take()
            t = self.take()
            if t[0] != "name":
                raise ExprError(f"{self.text!r}: expected an attribute name after '.'")
            if t[1] == "as" and self.peek() == ("op", "<"):
                self.take()
                target = self.take()
                if target[0] != "name":
                    raise ExprError(f"{self.text!r}: expected a type name in .as<>")
                self.expect("op", ">")
                n = Node("cast", target[1], (n,))
                continue
            n = Node("attr", t[1], (n,))
        return n

    def primary(self) -> Node:
        t = self.take()
        if t[0] == "num":
            return Node("num", int(t[1], 0))
        if t == ("kw", "true"):
            return Node("bool", True)
        if t == ("kw", "false"):
            return Node("bool", False)
        if t == ("op", "("):
            n = self.ternary()
            self.expect("op", ")")
            return n
        if t[0] == "name":
            parts = [t[1]]
            while self.peek() == ("op", "::"):
                self.take()
                nt = self.take()
                if nt[0] != "name":
                    raise ExprError(f"{self.text!r}: expected a name after '::'")
                parts.append(nt[1])
            if len(parts) > 1:
                return Node("enumref", tuple(parts))
            return Node("name", t[1])
        raise ExprError(f"{self.text!r}: unexpected {t[1]!r}")


def parse(text: object) -> Node:
    if isinstance(text, bool):
        return Node("bool", text)
    if isinstance(text, int):
        return Node("num", text)
    if not isinstance(text, str):
        raise ExprError(f"not an expression: {text!r}")
    return Parser(text).parse()


# ---- typing and rendering ---------------------------------------------------------------

@dataclass(frozen=True)
class Typed:
    c: str
    type: str  # "int", "bool", "bytes", "enum:<key>"


class Scope:
    """What names mean where an expression is evaluated. The generator fills
    the callbacks: `name(id)` and `member(obj_kind, id)` return a Typed or None,
    `enum_const(parts)` returns (c constant, enum key) or None."""

    def __init__(self, name: Callable[[str], Optional[Typed]],
                 member: Callable[[str, str], Optional[Typed]],
                 enum_const: Callable[[tuple], Optional[tuple[str, str]]],
                 underscore: Optional[Typed] = None) -> None:
        self.name = name
        self.member = member
        self.enum_const = enum_const
        self.underscore = underscore


def _is_intlike(t: str) -> bool:
    return t == "int" or t.startswith("enum:")


def render(node: Node, scope: Scope) -> Typed:
    k = node.kind
    if k == "num":
        v = int(node.value)
        if not -(1 << 63) <= v < (1 << 63):
            raise ExprError(f"integer literal {v} does not fit int64")
        return Typed(f"INT64_C({v})", "int")
    if k == "bool":
        return Typed("1" if node.value else "0", "bool")
    if k == "name":
        if node.value == "_":
            if scope.underscore is None:
                raise ExprError("'_' used outside a valid/repeat expression")
            return scope.underscore
        if node.value in ("_parent", "_root", "_io"):
            raise ExprError(f"{node.value} must be followed by a member")
        t = scope.name(node.value)
        if t is None:
            raise ExprError(f"unknown name {node.value!r}")
        return t
    if k == "enumref":
        r = scope.enum_const(node.value)
        if r is None:
            raise ExprError(f"unknown enum constant {'::'.join(node.value)}")
        return Typed(r[0], "enum:" + r[1])
    if k == "attr":
        (obj,) = node.args
        attr = node.value
        if obj.kind == "name" and obj.value in ("_parent", "_root"):
            t = scope.member(obj.value, attr)
            if t is None:
                raise ExprError(f"unknown member {obj.value}.{attr}")
            return t
        inner = render(obj, scope)
        if attr == "to_i":
            if inner.type.startswith("enum:") or inner.type in ("bool", "int"):
                return Typed(f"((int64_t)({inner.c}))", "int")
            raise ExprError(f".to_i on {inner.type}")
        if attr == "length" and inner.type == "bytes":
            return Typed(f"((int64_t)({inner.c}).len)", "int")
        raise ExprError(f"unsupported attribute .{attr} on {inner.type}")
    if k == "cast":
        (a,) = node.args
        ta = render(a, scope)
        if not re.fullmatch(r"[us][1248](le|be)?", str(node.value)):
            raise ExprError(f".as<{node.value}> is not supported (integer types only)")
        if not _is_intlike(ta.type):
            raise ExprError(f".as<{node.value}> on {ta.type}")
        # a type annotation for statically typed targets; the value is unchanged
        return Typed(f"((int64_t)({ta.c}))", "int")
    if k == "unary":
        (a,) = node.args
        ta = render(a, scope)
        if node.value == "not":
            if ta.type != "bool":
                raise ExprError(f"'not' needs a boolean, got {ta.type}")
            return Typed(f"(!{ta.c})", "bool")
        if node.value == "-":
            if ta.type != "int":
                raise ExprError(f"unary '-' needs an integer, got {ta.type}")
            return Typed(f"(-{ta.c})", "int")
    if k == "ternary":
        c, a, b = (render(x, scope) for x in node.args)
        if c.type != "bool":
            raise ExprError(f"ternary condition must be boolean, got {c.type}")
        if a.type != b.type and not (_is_intlike(a.type) and _is_intlike(b.type)):
            raise ExprError(f"ternary branches differ: {a.type} vs {b.type}")
        t = a.type if a.type == b.type else "int"
        return Typed(f"({c.c} ? {a.c} : {b.c})", t)
    if k == "binary":
        op = node.value
        a, b = (render(x, scope) for x in node.args)
        if op in ("and", "or"):
            if a.type != "bool" or b.type != "bool":
                raise ExprError(f"'{op}' needs booleans, got {a.type} and {b.type}")
            return Typed(f"({a.c} {'&&' if op == 'and' else '||'} {b.c})", "bool")
        if op in ("==", "!="):
            if a.type == "bool" and b.type == "bool":
                return Typed(f"(({a.c} ? 1 : 0) {op} ({b.c} ? 1 : 0))", "bool")
            if a.type.startswith("enum:") and b.type.startswith("enum:") and a.type != b.type:
                raise ExprError(f"comparing different enums {a.type} and {b.type}")
            if _is_intlike(a.type) and _is_intlike(b.type):
                return Typed(f"((int64_t)({a.c}) {op} (int64_t)({b.c}))", "bool")
            raise ExprError(f"cannot compare {a.type} with {b.type}")
        if op in ("<", "<=", ">", ">="):
            if a.type == "int" and b.type == "int":
                return Typed(f"({a.c} {op} {b.c})", "bool")
            raise ExprError(f"ordering needs integers, got {a.type} and {b.type}")
        if op in ("+", "-", "*"):
            if a.type == "int" and b.type == "int":
                return Typed(f"({a.c} {op} {b.c})", "int")
            raise ExprError(f"arithmetic needs integers, got {a.type} and {b.type}")
        if op in ("/", "%"):
            if a.type == "int" and b.type == "int":
                fn = "osdk_kdiv" if op == "/" else "osdk_kmod"
                return Typed(f"{fn}({a.c}, {b.c})", "int")
            raise ExprError(f"arithmetic needs integers, got {a.type} and {b.type}")
    raise ExprError(f"unsupported expression node {k} {node.value!r}")


def translate(text: object, scope: Scope, want: Optional[str] = None) -> Typed:
    t = render(parse(text), scope)
    if want == "bool" and t.type != "bool":
        raise ExprError(f"{text!r}: expected a boolean expression, got {t.type}")
    if want == "int" and not _is_intlike(t.type):
        raise ExprError(f"{text!r}: expected an integer expression, got {t.type}")
    return t


def names_used(text: object) -> set[str]:
    """Top-level names and `_parent`/`_root` an expression refers to."""
    out: set[str] = set()

    def walk(n: Node) -> None:
        if n.kind == "name":
            out.add(str(n.value))
        elif n.kind == "attr":
            (obj,) = n.args
            if obj.kind == "name" and obj.value in ("_parent", "_root"):
                out.add(f"{obj.value}.{n.value}")
            walk(obj)
        for a in n.args:
            if isinstance(a, Node):
                walk(a)

    walk(parse(text))
    return out


def const_value(text: object) -> int:
    """The value of a constant integer expression (repeat counts)."""
    n = parse(text)

    def ev(n: Node) -> int:
        if n.kind == "num":
            return int(n.value)
        if n.kind == "unary" and n.value == "-":
            return -ev(n.args[0])
        if n.kind == "binary" and n.value in ("+", "-", "*"):
            a, b = ev(n.args[0]), ev(n.args[1])
            return a + b if n.value == "+" else a - b if n.value == "-" else a * b
        raise ExprError(f"{text!r} is not a constant integer expression")

    return ev(n)
