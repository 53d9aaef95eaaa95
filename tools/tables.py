"""The language-neutral tables every generated implementation needs besides
its parser: what spec/rules.yaml and the .ksy files say, flattened into data
so that no testee re-implements the rules engine or re-reads YAML.

Written by tools/regen.py to generated/tables/osdk_tables.json (and read by
the C generator). Everything here is derived, none of it is typed by hand
(the error classes by field are osdk_conformance.core.model.ERROR_BY_FIELD).

- profiles: the profile ids in value order; profile_values: each id's value
  in the ksy enum `profile` (what a generated parser takes as its profile);
- crc: CRC-16/CRC-32 parameters (init as the register value, as the SDK
  code holds it; ERRATA E21);
- commands: (set, id) -> the command name streams report as `ack_of`;
- error_by_field: the error class a failed `valid` check of a field means;
- control_modes: per profile, for each of the 256 mode bytes, the
  classification and combination index; per combination its setpoint
  ranges (ERRATA E15, E16);
- model: per ksy type (key "file" or "file.type.subtype"), its class path
  and its seq fields in wire order with what the value model needs to
  render each (docs/VALUE-MODEL.md); enums by "file.enum";
- library: what the generated libraries' receive-and-send glue
  (tools/libgen) is made from: the frame header's fields with their bit
  positions, the receiver's header checks in order, each profile's
  broadcast items by flag bit, and the wire layout of every command an
  onboard computer sends.

regen.py also writes, beside the Go parsers, the list of their struct types
(go_types(): Go cannot find a type by its name at run time).
"""
from __future__ import annotations

import json
import re
import sys
from pathlib import Path
from typing import Any, Iterator

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from osdk_conformance.core import ksy, rules  # noqa: E402
from osdk_conformance.core.commands import COMMANDS  # noqa: E402
from osdk_conformance.core.model import ERROR_BY_FIELD, SKIPPED_FIELDS  # noqa: E402

_PRIM = re.compile(r"^(u|s)(1|2|4|8)(le|be)?$")
_FLOAT = re.compile(r"^f(4|8)(le|be)?$")
_BITS = re.compile(r"^b(\d+)$")


def _enum_key(file_id: str, ref: str) -> str:
    if "::" in ref:
        f, name = ref.split("::", 1)
        return f"{f}.{name}"
    return f"{file_id}.{ref}"


def _type_key(file_id: str, path: tuple[str, ...]) -> str:
    return ".".join((file_id,) + path)


def _field_model(file_id: str, spec: dict) -> dict[str, Any]:
    out: dict[str, Any] = {"id": spec["id"]}
    t = spec.get("type")
    if "enum" in spec:
        out["enum"] = _enum_key(file_id, spec["enum"])
    if isinstance(t, dict):
        out["kind"] = "switch"
    elif t is None:
        out["kind"] = "bytes"
    elif m := _PRIM.match(t):
        out["kind"] = "int"
        out["signed"] = m.group(1) == "s"
        out["width"] = int(m.group(2))
    elif m := _FLOAT.match(t):
        out["kind"] = "float"
        out["width"] = int(m.group(1))
    elif m := _BITS.match(t):
        n = int(m.group(1))
        out["kind"] = "bool" if n == 1 and "enum" not in spec else "bits"
        out["width_bits"] = n
    else:
        out["kind"] = "struct"
    if "repeat" in spec:
        out["repeat"] = True
    if "if" in spec:
        out["optional"] = True
    return out


def _seqs() -> Iterator[tuple[str, tuple[str, ...], list[dict]]]:
    """(file id, type path, raw seq) of every ksy type, in key order."""
    index = ksy.load()
    for (file_id, path), kt in sorted(index.types.items()):
        yield file_id, path, index.raw_seq(kt)


def model_tables() -> dict[str, Any]:
    index = ksy.load()
    types: dict[str, Any] = {}
    for file_id, path, seq in _seqs():
        types[_type_key(file_id, path)] = {
            "class_path": [ksy.camel(file_id)] + [ksy.camel(p) for p in path],
            # every seq id in order: a runtime's validation error names its
            # field by position ("/seq/N"), skipped fields included
            "seq": [f["id"] for f in seq],
            "fields": [_field_model(file_id, f) for f in seq if f["id"] not in SKIPPED_FIELDS],
        }
    enums = {
        f"{file_id}.{name}": {str(k): v for k, v in sorted(values.items())}
        for (file_id, name), values in sorted(index.enums.items())
    }
    return {"types": types, "enums": enums}


def if_expressions() -> dict[str, Any]:
    """The `if` of every conditional seq field, by type key and field id.
    A runtime whose objects cannot show that an integer field is absent (Go
    keeps a zero there) evaluates the expression itself."""
    out: dict[str, Any] = {}
    for file_id, path, seq in _seqs():
        conds = {f["id"]: (str(f["if"]).lower() if isinstance(f["if"], bool) else str(f["if"]))
                 for f in seq if "if" in f}
        if conds:
            out[_type_key(file_id, path)] = conds
    return out


def checked_fields() -> dict[str, Any]:
    """The seq fields with a `valid` or `contents` check, by type key. With
    the position ("/seq/N") a validation error gives, they say which field
    failed when the runtime's error does not name the raising type (Go)."""
    out: dict[str, Any] = {}
    for file_id, path, seq in _seqs():
        ids = [f["id"] for f in seq if "valid" in f or "contents" in f]
        if ids:
            out[_type_key(file_id, path)] = ids
    return out


def control_mode_tables(r: rules.Rules) -> dict[str, Any]:
    out: dict[str, Any] = {}
    for profile in r.profile_names:
        modes = []
        combos: dict[str, Any] = {}
        for byte in range(256):
            c = r.classify_control_mode(byte, profile)
            modes.append({"classification": c["classification"], "combination": c["combination"]})
            if c["classification"] == "documented":
                ranges = r.input_ranges(byte, profile)
                entry = {axis: {"min": lim.get("min"), "max": lim.get("max")}
                         for axis, lim in sorted(ranges.items())}
                prev = combos.setdefault(str(c["combination"]), entry)
                if prev != entry:
                    raise SystemExit(f"tables: combination {c['combination']} has byte-dependent ranges on {profile}")
        out[profile] = {"modes": modes, "ranges": combos}
    return out


def crc_tables(r: rules.Rules) -> dict[str, Any]:
    out = {}
    for name in ("crc16", "crc32"):
        p = r.crc_params(name)
        out[name] = {
            "width": p.width, "poly": p.poly, "init": p.init, "reflect_in": p.reflect_in,
            "reflect_out": p.reflect_out, "xorout": p.xorout, "check": p.check,
            "covers": list(p.covers), "stored_at": list(p.stored_at),
        }
    return out


def _header_fields() -> list[dict[str, Any]]:
    """The fixed header of osdk_frame.ksy as bit positions from the frame's
    first bit (bit-endian le: a bit field starts at the lowest free bit)."""
    index = ksy.load()
    out, bit = [], 0
    for f in index.raw_seq(index.types[("osdk_frame", ())]):
        t = f.get("type")
        if "contents" in f:
            width = 8 * len(f["contents"])
        elif isinstance(t, str) and (m := _BITS.match(t)):
            width = int(m.group(1))
        elif isinstance(t, str) and (m := _PRIM.match(t)):
            width = 8 * int(m.group(2))
        else:
            break  # DATA: the header ends here
        out.append({"id": f["id"], "byte": bit // 8, "lsb": bit % 8, "width": width})
        bit += width
    return out


# A command value field as the encoders write it: "u1"/"u2"/"u4" (unsigned,
# little-endian), "f4" (float32 bits), "bytes" with a size; "count" repeats.
def _wire_field(file_id: str, f: dict, index: Any) -> dict[str, Any]:
    out: dict[str, Any] = {"id": f["id"]}
    t = f.get("type")
    if t is None and "size" in f:
        out.update(wire="bytes", size=int(f["size"]))
    elif isinstance(t, str) and (m := _PRIM.match(t)) and m.group(1) == "u":
        out["wire"] = f"u{m.group(2)}"
    elif isinstance(t, str) and (m := _FLOAT.match(t)) and m.group(1) == "4":
        out["wire"] = "f4"
    elif isinstance(t, str) and (file_id, ()) != (t, ()) and (t, ()) in index.types:
        # a type of its own file that is one byte of bit fields (the control mode byte)
        bits = sum(int(_BITS.match(g["type"]).group(1)) for g in index.raw_seq(index.types[(t, ())]))
        if bits != 8:
            raise SystemExit(f"tables: {file_id}.{f['id']}: type {t} is {bits} bits, not one byte")
        out.update(wire="u1", type=t)
    else:
        raise SystemExit(f"tables: {file_id}.{f['id']}: no encoder for type {t!r}")
    if "enum" in f:
        out["enum"] = _enum_key(file_id, f["enum"])
    if f.get("repeat") == "expr":
        out["count"] = int(f["repeat-expr"])
    return out


def _sent_commands() -> list[dict[str, Any]]:
    """Every command the spec names in the sets an onboard computer sends
    (command set 0x02 is what the flight controller pushes: PROTOCOL-FACTS
    section 2), with its value's layout from the osdk_payload.ksy switch."""
    index = ksy.load()
    cases = index.raw_seq(index.types[("osdk_payload", ())])[0]["type"]["cases"]
    out = []
    for (cmd_set, cmd_id), name in sorted(COMMANDS.items()):
        if cmd_set == 0x02:
            continue
        ref = cases[cmd_set * 0x100 + cmd_id]
        file_id, path = (ref, ()) if (ref, ()) in index.types else ("osdk_payload", (ref,))
        fields = [_wire_field(file_id, f, index) for f in index.raw_seq(index.types[(file_id, path)])]
        size = sum((f.get("size") or int(f["wire"][1:])) * f.get("count", 1) for f in fields)
        out.append({"name": name, "cmd_set": cmd_set, "cmd_id": cmd_id, "type": _type_key(file_id, path),
                    "size": size, "fields": fields})
    return out


def library_tables(r: rules.Rules) -> dict[str, Any]:
    frame = r.data["frame"]
    return {
        "frame": {
            "sof": frame["sof"], "header_len": frame["header_len"], "crc32_len": frame["crc32_len"],
            "max_len": frame["max_len"], "header_only_len": frame["header_only"]["len"],
            "impossible_lengths": [[0, frame["impossible_lengths"]["below"] - 1]]
            + [[x["min"], x["max"]] for x in frame["impossible_lengths"]["ranges"]],
            "header_checks": list(frame["receiver"]["header_checks"]),
            "header_fields": _header_fields(),
        },
        "broadcast_items": {p: list(r.profile(p).flag_bits) for p in r.profile_names},
        "sent_commands": _sent_commands(),
    }


def tables() -> dict[str, Any]:
    r = rules.default_rules()
    return {
        "comment": "Generated from spec/ by tools/regen.py (tools/tables.py). Do not edit.",
        "profiles": list(r.profile_names),
        "profile_values": {p: r.profile(p).value for p in r.profile_names},
        "crc": crc_tables(r),
        "commands": [{"cmd_set": s, "cmd_id": i, "name": n} for (s, i), n in sorted(COMMANDS.items())],
        "error_by_field": ERROR_BY_FIELD,
        "control_modes": control_mode_tables(r),
        "model": model_tables(),
        "if_expressions": if_expressions(),
        "checked_fields": checked_fields(),
        "library": library_tables(r),
    }


def write(out_dir: Path) -> None:
    out_dir.mkdir(parents=True, exist_ok=True)
    text = json.dumps(tables(), indent=1, sort_keys=False, allow_nan=False) + "\n"
    (out_dir / "osdk_tables.json").write_text(text)


GO_TYPES_FILE = "osdk_types.go"


def go_types() -> str:
    """A Go file for the generated package listing its struct types. Go
    cannot look a type up by name at run time, and the glue needs every
    struct type to trace a validation error to the type that raised it; the
    names are the tables' class paths joined by "_", as the Kaitai compiler
    names nested Go types."""
    names = sorted("_".join(t["class_path"]) for t in model_tables()["types"].values())
    lines = [
        "// Generated from spec/*.ksy by tools/regen.py (tools/tables.py). Do not edit.",
        "",
        "package osdk_kaitai",
        "",
        'import "reflect"',
        "",
        "// Types holds every struct type of this package, one per ksy type of the",
        "// tables' model (generated/tables/osdk_tables.json).",
        "var Types = []reflect.Type{",
        *(f"\treflect.TypeOf({n}{{}})," for n in names),
        "}",
    ]
    return "\n".join(lines) + "\n"


def write_go_types(package_dir: Path) -> None:
    (package_dir / GO_TYPES_FILE).write_text(go_types())


if __name__ == "__main__":
    write(Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "generated" / "tables")
