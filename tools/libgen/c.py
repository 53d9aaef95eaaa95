"""The C library's glue (generated/c/, beside tools/cgen's decoder): the
encoders of the commands an onboard computer sends, the broadcast item
accessors, the build files (Makefile, CMakeLists.txt) and the list of
files per feature with the libc functions each needs (README.md,
features.json).

The libc needs are not written down by hand: every file is compiled here
(gcc at -O2 and -Os, so calls the compiler emits itself count, and at
-O0 -fno-builtin, so every call the source makes counts even where gcc
would expand it inline) and its
object's undefined symbols are read with nm. A symbol another file of the
library defines makes that file a dependency; the rest is libc.
"""
from __future__ import annotations

import hashlib
import importlib.util
import json
import os
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
TEMPLATES = HERE / "templates" / "c"
BANNER = "/* Generated from spec/ by tools/libgen/c.py. Do not edit. */\n"
BANNER_HASH = "# Generated from spec/ by tools/libgen/c.py. Do not edit.\n"

# The features a user picks files by, each named by the file that holds it
# (its dependencies are found from the objects).
FEATURES = (
    ("CRC-16 / CRC-32", "osdk_crc.c"),
    ("deframer (receiver)", "osdk_deframer.c"),
    ("decoder", "osdk_decoder.c"),
    ("broadcast item access", "osdk_broadcast.c"),
    ("ACK matching", "osdk_acks.c"),
    ("rule tables (control modes, command names, profiles)", "osdk_tables.c"),
    ("encoders", "osdk_encode.c"),
    ("JSON writer", "osdk_json.c"),
    ("value-model writer (JSON)", "osdk_model_json.c"),
)
# -fno-builtin: every call the source makes stays a call (gcc expands
# memcpy/memcmp of a known size inline even at -O0)
OPT_LEVELS = (("-O0", "-fno-builtin"), ("-O2",), ("-Os",))


def _render(name: str, values: dict[str, str]) -> str:
    from string import Template
    return Template((TEMPLATES / name).read_text(encoding="utf-8")).substitute(values)


def _cgen_spec():
    # spec.py imports its sibling expr.py by plain name, as cgen runs it
    cgen = ROOT / "tools" / "cgen"
    spec = importlib.util.spec_from_file_location("osdk_cgen_spec_for_libgen", cgen / "spec.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    sys.path.insert(0, str(cgen))
    try:
        spec.loader.exec_module(module)
    finally:
        sys.path.remove(str(cgen))
    return module.Spec(ROOT / "spec")


def _cident(text: str) -> str:
    return "".join(ch if ch.isalnum() else "_" for ch in text)


# ---- encoders ---------------------------------------------------------------------------

_CTYPE = {"u1": "uint8_t", "u2": "uint16_t", "u4": "uint32_t", "f4": "float"}
_WIDTH = {"u1": 1, "u2": 2, "u4": 4, "f4": 4}


def _params(cmd: dict, bits: bool) -> list[str]:
    out = []
    for f in cmd["fields"]:
        if f["wire"] == "bytes":
            out.append(f"const uint8_t {f['id']}[{f['size']}]")
        elif "count" in f:
            out.append(f"const {_CTYPE[f['wire']]} {f['id']}[{f['count']}]")
        elif f["wire"] == "f4" and bits:
            out.append(f"uint32_t {f['id']}")
        else:
            out.append(f"{_CTYPE[f['wire']]} {f['id']}")
    return out


def _encoder_contract(cmd: dict, size: str) -> str:
    """The ACSL contract of one value encoder: out holds the value's size,
    each array argument its count, and only out is written."""
    reads = [f"    requires \\valid_read({f['id']} + (0 .. {(f.get('size') or f['count']) - 1}));"
             for f in cmd["fields"] if f["wire"] == "bytes" or "count" in f]
    return "\n".join([f"/*@ requires \\valid(out + (0 .. {size} - 1));", *reads,
                      f"    assigns out[0 .. {size} - 1];", f"    ensures \\result == {size}; */"])


def _encoders(library: dict) -> tuple[str, str]:
    decls, defs = [], []
    for cmd in library["sent_commands"]:
        name, up = cmd["name"], cmd["name"].upper()
        size = f"OSDK_{up}_SIZE"
        layout = ", ".join(f"{f['id']} ({f['wire']}" + (f" x{f['count']}" if "count" in f else "")
                           + (f" {f['size']}" if f["wire"] == "bytes" else "") + ")" for f in cmd["fields"])
        decls += [f"/* {name}: command 0x{cmd['cmd_set']:02x}/0x{cmd['cmd_id']:02x}, value {cmd['type']}:",
                  f" * {layout}, little-endian. */",
                  f"#define OSDK_{up}_CMD_SET 0x{cmd['cmd_set']:02x}u",
                  f"#define OSDK_{up}_CMD_ID 0x{cmd['cmd_id']:02x}u",
                  f"#define {size} {cmd['size']}u"]
        has_float = any(f["wire"] == "f4" for f in cmd["fields"])
        variants = [(f"osdk_encode_{name}", False)] + ([(f"osdk_encode_{name}_bits", True)] if has_float else [])
        for fn, bits in variants:
            params = ", ".join(_params(cmd, bits) + [f"uint8_t out[{size}]"])
            if has_float:
                decls.append("/* The floats as their IEEE bits. */" if bits else
                             "/* Writes the value into out; returns its size. */")
            else:
                decls.append("/* Writes the value into out; returns its size. */")
            decls.append(_encoder_contract(cmd, size))
            decls.append(f"size_t {fn}({params});")
            body = []
            if has_float and not bits:
                args = ", ".join(f"f32_bits({f['id']})" if f["wire"] == "f4" else f["id"] for f in cmd["fields"])
                body.append(f"    return osdk_encode_{name}_bits({args}, out);")
            else:
                at, loop = 0, False
                for f in cmd["fields"]:
                    if f["wire"] == "bytes" or "count" in f:
                        n = f.get("size") or f["count"]
                        w = 1 if f["wire"] == "bytes" else _WIDTH[f["wire"]]
                        loop = True
                        put = f"out[{at} + i] = {f['id']}[i];" if w == 1 else f"put_le(out + {at} + {w} * i, {f['id']}[i], {w});"
                        body.append(f"    /*@ loop invariant 0 <= i <= {n};\n"
                                    f"        loop assigns i, out[{at} .. {at + n * w - 1}];\n"
                                    f"        loop variant {n} - i; */")
                        body.append(f"    for (i = 0; i < {n}; i++) {put}")
                        at += n * w
                    elif f["wire"] == "u1":
                        body.append(f"    out[{at}] = {f['id']};")
                        at += 1
                    else:
                        body.append(f"    put_le(out + {at}, {f['id']}, {_WIDTH[f['wire']]});")
                        at += _WIDTH[f["wire"]]
                if at != cmd["size"]:
                    raise SystemExit(f"libgen c: {name}: fields give {at} bytes, the table says {cmd['size']}")
                if loop:
                    body.insert(0, "    size_t i;")
                body.append(f"    return {size};")
            defs += ["", f"size_t {fn}({params})", "{", *body, "}"]
        decls.append("")
    return "\n".join(decls), "\n".join(defs) + "\n"


def _frame_values(library: dict) -> dict[str, str]:
    frame = library["frame"]
    fields = {f["id"]: f for f in frame["header_fields"]}
    session_max = (1 << fields["session"]["width"]) - 1
    if (1 << fields["len"]["width"]) - 1 < frame["max_len"]:
        raise SystemExit("libgen c: LEN's bits cannot hold the largest frame")
    sources = {"sof": f"0x{frame['sof']:02x}u", "len": "(uint32_t)frame_len", "session": "session",
               "is_ack": "is_ack ? 1u : 0u", "seq": "seq"}
    puts = []
    for f in frame["header_fields"]:
        bit = 8 * f["byte"] + f["lsb"]
        if f["id"] == "crc16":
            crc_at = bit
            continue
        if f["id"] in sources:
            puts.append(f"    put_bits(out, {bit}u, {f['width']}u, {sources[f['id']]}); /* {f['id']} */")
        else:
            puts.append(f"    /* {f['id']}: bits {bit}..{bit + f['width'] - 1} stay 0 */")
    puts.append(f"    put_bits(out, {crc_at}u, {fields['crc16']['width']}u, osdk_crc16(out, {crc_at // 8}u)); /* crc16 */")
    impossible = ["frame_len > OSDK_ENCODE_FRAME_MAX_LEN"]
    for lo, hi in frame["impossible_lengths"]:
        impossible.append(f"frame_len <= {hi}u" if lo == 0 else
                          f"frame_len == {lo}u" if lo == hi else f"(frame_len >= {lo}u && frame_len <= {hi}u)")
    return {"header_len": str(frame["header_len"]), "crc32_len": str(frame["crc32_len"]),
            "max_len": str(frame["max_len"]), "header_only_len": str(frame["header_only_len"]),
            "session_max": str(session_max), "header_puts": "\n".join(puts),
            "impossible": " ||\n        ".join(impossible)}


# ---- broadcast items --------------------------------------------------------------------

def _broadcast(library: dict, tables: dict) -> dict[str, str]:
    spec = _cgen_spec()
    bc = spec.types[("osdk_payload", ("broadcast",))]
    data = next(f for f in bc.fields if f.id == "data")
    enum = dict((v, n) for v, n in spec.enums[("osdk_payload", "profile")].values)
    by_enum_name = {}
    for case in data.cases:
        by_enum_name[str(case.key).split("::")[-1]] = case.type.target
    profiles = []  # (profile id, struct TypeSpec)
    for pid, items in library["broadcast_items"].items():
        t = by_enum_name.get(enum[tables["profile_values"][pid]])
        if t is None:
            raise SystemExit(f"libgen c: no broadcast layout for profile {pid}")
        profiles.append((pid, t, items))
    order: list[str] = []
    for _, _, items in profiles:
        order += [i for i in items if i not in order]
    ctypes: dict[str, str] = {}
    for pid, t, items in profiles:
        fields = {f.id: f for f in t.fields}
        for item in items:
            f = fields[item]
            if f.kind == "struct":
                ct = f.ref.target.cname + "_t"
            elif f.kind == "int" and not f.signed and f.enum is None:
                ct = f"uint{8 * f.width}_t"
            else:
                raise SystemExit(f"libgen c: {pid} item {item}: no accessor for a {f.kind} field")
            if ctypes.setdefault(item, ct) != ct:
                raise SystemExit(f"libgen c: item {item} is {ctypes[item]} in one profile and {ct} in {pid}")
    decls, defs = [], []
    for item in order:
        which = [pid for pid, _, items in profiles if item in items]
        note = "every profile" if len(which) == len(profiles) else ", ".join(which)
        sig = f"const {ctypes[item]} *osdk_broadcast_{item}(const osdk_payload_broadcast_t *b)"
        decls += [f"/* {item} ({note}) */", "/*@ requires b == \\null || \\valid_read(b);", "    assigns \\nothing; */",
                  sig + ";"]
        body = ["    if (b == NULL) return NULL;", "    switch (b->data.tag) {"]
        for pid, t, items in profiles:
            if item not in items:
                continue
            tag = f"OSDK_PAYLOAD_BROADCAST_DATA_{t.cname.upper()}"
            member = f"b->data.u.{t.cname}"
            body += [f"    case {tag}: /* {pid} */",
                     f"        return {member}.{item}_present ? &{member}.{item} : NULL;"]
        body += ["    default:", "        return NULL;", "    }"]
        defs += ["", sig, "{", *body, "}"]
    enum_names = {item: f"OSDK_BROADCAST_ITEM_{item.upper()}" for item in order}
    values = {
        "item_decls": "\n".join(decls) + "\n", "item_defs": "\n".join(defs) + "\n",
        "item_enum": "\n".join(f"    {enum_names[i]} = {n}," for n, i in enumerate(order))
        + f"\n    OSDK_BROADCAST_ITEM_COUNT_ = {len(order)}",
        "item_names": "\n".join(f'    "{i}",' for i in order),
        "item_cases": "\n".join(f"    case {enum_names[i]}:\n        return osdk_broadcast_{i}(b);" for i in order),
    }
    arrays, cases = [], []
    for pid, _, items in profiles:
        var = f"items_{_cident(pid)}"
        enum_value = tables["profile_values"][pid]
        arrays += [f"static const osdk_broadcast_item_t {var}[{len(items)}] = {{ /* {pid} */",
                   *[f"    {enum_names[i]}," for i in items], "};", ""]
        cases += [f"    case {enum_value}: /* {pid} */", f"        if (count) *count = {len(items)};",
                  f"        return {var};"]
    values["profile_items"] = "\n".join(arrays)
    values["profile_cases"] = "\n".join(cases)
    return values


# ---- files per feature ------------------------------------------------------------------

def _symbols(obj: Path, defined: bool) -> set[str]:
    args = ["nm", "-g", "--defined-only" if defined else "--undefined-only", "-j", str(obj)]
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    return {ln.strip() for ln in out.splitlines() if ln.strip()}


FEATURES_CACHE = ROOT / ".cache" / "libgen-c"


def features(out: Path) -> dict[str, Any]:
    """Each file's library dependencies and libc functions, from its objects;
    kept under .cache/ by the hash of everything they follow from (every
    file compiled, the compiler, the flags), since compiling 27 objects and
    reading their symbols takes most of a `regen --check`."""
    if shutil.which("gcc") is None or shutil.which("nm") is None:
        raise SystemExit("libgen c: gcc and nm are needed to find the libc functions of each file")
    digest = hashlib.sha256(repr((OPT_LEVELS, FEATURES)).encode())
    for tool in ("gcc", "nm"):
        digest.update(subprocess.run([tool, "--version"], check=True, capture_output=True).stdout)
    for path in sorted(out.glob("*.[ch]")):
        digest.update(path.name.encode() + b"\0" + path.read_bytes() + b"\0")
    cached = FEATURES_CACHE / f"{digest.hexdigest()}.json"
    try:
        return json.loads(cached.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        pass
    result = _features_from_objects(out)
    try:
        FEATURES_CACHE.mkdir(parents=True, exist_ok=True)
        part = cached.with_suffix(f".{os.getpid()}.part")
        part.write_text(json.dumps(result), encoding="utf-8")
        part.replace(cached)  # whole or absent, whoever else writes it at the same time
    except OSError:
        pass  # a read-only checkout measures again next time
    return result


def _features_from_objects(out: Path) -> dict[str, Any]:
    sources = sorted(p.name for p in out.glob("*.c"))
    defines: dict[str, str] = {}
    undefined: dict[str, set[str]] = {s: set() for s in sources}
    with tempfile.TemporaryDirectory(prefix="libgen-c-") as tmp:
        procs = []
        for opt in OPT_LEVELS:
            for src in sources:
                obj = Path(tmp) / f"{src[:-2]}{''.join(opt)}.o"
                procs.append((src, obj, subprocess.Popen(
                    ["gcc", *opt, "-std=c99", "-c", "-I", str(out), "-o", str(obj), str(out / src)],
                    stderr=subprocess.PIPE, text=True)))
        for src, obj, p in procs:
            _, err = p.communicate()
            if p.returncode:
                raise SystemExit(f"libgen c: gcc failed on {src}:\n{err}")
            undefined[src] |= _symbols(obj, False)
            for sym in _symbols(obj, True):
                defines[sym] = src
    deps = {s: sorted({defines[u] for u in undefined[s] if u in defines} - {s}) for s in sources}
    libc = {s: sorted(u for u in undefined[s] if u not in defines) for s in sources}
    stdio_direct = {s for s in sources if "#include <stdio.h>" in (out / s).read_text(encoding="utf-8")}

    def closure(src: str) -> list[str]:
        seen, todo = [], [src]
        while todo:
            s = todo.pop(0)
            if s not in seen:
                seen.append(s)
                todo += deps[s]
        return seen

    result: dict[str, Any] = {"features": [], "files": {}}
    for s in sources:
        result["files"][s] = {"needs": deps[s], "libc": libc[s]}
    covered = set()
    for name, src in FEATURES:
        if src not in deps:
            raise SystemExit(f"libgen c: feature {name}: {src} was not generated")
        files = closure(src)
        covered |= set(files)
        result["features"].append({"feature": name, "files": files,
                                   "libc": sorted({f for x in files for f in libc[x]})})
    if set(sources) - covered:
        raise SystemExit(f"libgen c: files in no feature: {sorted(set(sources) - covered)}")
    result["stdio"] = sorted(s for s in sources if set(closure(s)) & stdio_direct)
    return result


# ---- write --------------------------------------------------------------------------------

def write(out: Path, tables: dict[str, Any]) -> None:
    library = tables["library"]
    command_decls, command_defs = _encoders(library)
    values = {"banner": BANNER, "command_decls": command_decls, "command_defs": command_defs,
              **_frame_values(library)}
    for name in ("osdk_encode.h", "osdk_encode.c"):
        (out / name).write_text(_render(name + ".in", values), encoding="utf-8")
    values = {"banner": BANNER, **_broadcast(library, tables)}
    for name in ("osdk_broadcast.h", "osdk_broadcast.c"):
        (out / name).write_text(_render(name + ".in", values), encoding="utf-8")

    info = features(out)
    all_files = sorted(info["files"])
    stdio = info["stdio"]
    feature_vars = []
    for f in info["features"]:
        var = "OSDK_FEATURE_" + _cident(f["files"][0][5:-2]).upper()
        feature_vars.append(f"# {f['feature']}\n{var} := {' '.join(f['files'])}")
    build = {"banner_hash": BANNER_HASH, "all_files": " ".join(all_files), "stdio_files": " ".join(stdio),
             "feature_vars": "\n".join(feature_vars) + "\n"}
    (out / "Makefile").write_text(_render("Makefile.in", build), encoding="utf-8")
    (out / "CMakeLists.txt").write_text(_render("CMakeLists.txt.in", build), encoding="utf-8")
    rows = [f"| {f['feature']} | {', '.join(f'`{x}`' for x in f['files'])} | "
            f"{', '.join(f'`{x}`' for x in f['libc']) or 'none'} |" for f in info["features"]]
    readme = {"feature_rows": "\n".join(rows), "stdio_list": ", ".join(f"`{s}`" for s in stdio) or "none"}
    (out / "README.md").write_text(_render("README.md.in", readme), encoding="utf-8")
    (out / "features.json").write_text(json.dumps(info, indent=1, sort_keys=True) + "\n", encoding="utf-8")
