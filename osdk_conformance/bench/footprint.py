"""The `footprint` section of `osdkc bench`: what the C library
(generated/c) costs on a board. Per feature (generated/c/features.json:
a feature's files with the files they call into) and for the whole
library: text (code and read-only data), data and bss of the objects; per
public function: the deepest stack it can use.

Two targets, compile only (no link): x86-64 with gcc -Os, and Cortex-M4
with clang-14 (thumbv7em, hard float, -Os -ffreestanding), which gets no
libc headers but a directory per file declaring exactly the libc functions
features.json lists for that file; so a file that needed more, or stdio
where the list says none, fails to compile here.

Stack depth: each function's frame from -fstack-usage, the calls from the
relocations of its own section (-ffunction-sections), summed along the
deepest path. Calls through pointers are not seen: the deframer's event
callback and anything the user's callbacks do come on top, and so do the
frames of libc functions (memmove, snprintf, ...). Recursion or a frame of
unbounded (dynamic) size fails the section. Sizes are of whole objects: a
link with --gc-sections drops the functions a program does not use.
"""
from __future__ import annotations

import json
import re
import shutil
import subprocess
import tempfile
from pathlib import Path

from osdk_conformance.bench import board_footprint, report
from osdk_conformance.bench.child import kill_group
from osdk_conformance.bench.stack_depth import StackBoundError, deepest_paths, su_frames
from osdk_conformance.core.paths import ROOT

LIB = ROOT / "generated" / "c"
BEGIN = "<!-- bench:footprint:begin (osdkc bench --only footprint --markdown writes this part) -->"
END = "<!-- bench:footprint:end -->"

COMMON = ["-std=c99", "-ffunction-sections", "-fdata-sections", "-fstack-usage",
          "-Werror=implicit-function-declaration", "-c"]
TARGETS = {
    "x86-64": {"cc": "gcc", "flags": ["-Os"], "tiny_libc": False},
    "cortex-m4": {"cc": "clang-14", "flags": ["--target=thumbv7em-none-eabihf", "-mcpu=cortex-m4",
                                              "-mfpu=fpv4-sp-d16", "-mfloat-abi=hard", "-Os", "-ffreestanding",
                                              "-nostdlibinc"], "tiny_libc": True},
}

# The C99 declarations of the libc functions a file may need, by header;
# a function not here stops the Cortex-M4 build with a clear message.
PROTOTYPES = {
    "memchr": ("string.h", "void *memchr(const void *s, int c, size_t n);"),
    "memcmp": ("string.h", "int memcmp(const void *a, const void *b, size_t n);"),
    "memcpy": ("string.h", "void *memcpy(void *restrict d, const void *restrict s, size_t n);"),
    "memmove": ("string.h", "void *memmove(void *d, const void *s, size_t n);"),
    "memset": ("string.h", "void *memset(void *d, int c, size_t n);"),
    "strchr": ("string.h", "char *strchr(const char *s, int c);"),
    "strcmp": ("string.h", "int strcmp(const char *a, const char *b);"),
    "strlen": ("string.h", "size_t strlen(const char *s);"),
    "strncmp": ("string.h", "int strncmp(const char *a, const char *b, size_t n);"),
    "strpbrk": ("string.h", "char *strpbrk(const char *s, const char *accept);"),
    "snprintf": ("stdio.h", "int snprintf(char *restrict s, size_t n, const char *restrict fmt, ...);"),
    "vsnprintf": ("stdio.h", "int vsnprintf(char *restrict s, size_t n, const char *restrict fmt, va_list ap);"),
}
# headers the compiler itself provides to freestanding code
FREESTANDING = {"stddef.h", "stdint.h", "stdbool.h", "stdarg.h", "float.h", "limits.h", "iso646.h"}
# What GCC and Clang may call on their own, even in freestanding code (a copy
# loop or a struct assignment becomes memmove or memcpy): an object can need
# one of these while its source includes no header that declares it.
COMPILER_EMITTED = {"memcpy", "memmove", "memset", "memcmp"}
INCLUDE = re.compile(r"^\s*#\s*include\s*<([^>]+)>", re.M)


class FootprintError(Exception):
    pass


def _run(argv: list[str], cwd: Path | None = None) -> str:
    r = subprocess.run(argv, capture_output=True, text=True, cwd=cwd)
    if r.returncode:
        raise FootprintError(f"{' '.join(argv[:1])} failed: {(r.stderr or r.stdout).strip()[:2000]}")
    return r.stdout


def _tiny_libc(src: Path, libc: list[str], where: Path) -> Path:
    """A header directory for one file: each <header> it includes, declaring
    only the libc functions the file list gives for it."""
    where.mkdir(parents=True)
    wanted = {}
    for name in libc:
        if name not in PROTOTYPES:
            raise FootprintError(f"{src.name} needs {name}, which has no declaration here (add it to PROTOTYPES)")
        header, proto = PROTOTYPES[name]
        wanted.setdefault(header, []).append(proto)
    for header in sorted(set(INCLUDE.findall(src.read_text(encoding="utf-8"))) - FREESTANDING):
        lines = [f"/* {header}: only what features.json lists for {src.name} */", "#include <stddef.h>"]
        if header == "stdio.h":
            lines.append("#include <stdarg.h>")
        (where / header).write_text("\n".join(lines + wanted.pop(header, [])) + "\n")
    for header in list(wanted):
        wanted[header] = [p for p in wanted[header] if _name(p) not in COMPILER_EMITTED]
        if not wanted[header]:
            del wanted[header]
    if wanted:
        raise FootprintError(f"{src.name} needs {', '.join(sorted(f for fs in wanted.values() for f in fs))} "
                             f"but does not include {', '.join(sorted(wanted))}")
    return where


def _name(prototype: str) -> str:
    return re.search(r"(\w+)\(", prototype).group(1)


def _sizes(obj: Path, readelf: str) -> dict[str, int]:
    out = {"text": 0, "data": 0, "bss": 0}
    for line in _run([readelf, "-SW", str(obj)]).splitlines():
        if "]" not in line or not line.lstrip().startswith("["):
            continue
        f = line.split("]", 1)[1].split()
        if len(f) < 6 or f[0] == "Name":
            continue
        kind, size = f[1], int(f[4], 16)
        flags = f[6] if len(f) > 6 and f[6].isalpha() else ""
        if "A" not in flags:
            continue
        out["bss" if kind == "NOBITS" else "data" if "W" in flags else "text"] += size
    return out


def _symbols(obj: Path, readelf: str) -> tuple[set[str], set[str]]:
    """Global and local function symbols defined in the object."""
    glob, local = set(), set()
    for line in _run([readelf, "-sW", str(obj)]).splitlines():
        f = line.split()
        if len(f) >= 8 and f[3] == "FUNC" and f[6] != "UND":
            (glob if f[4] == "GLOBAL" else local).add(f[7])
    return glob, local


def _calls(obj: Path, readelf: str) -> dict[str, set[str]]:
    """Symbols referenced from each function's own text section."""
    calls: dict[str, set[str]] = {}
    current = None
    for line in _run([readelf, "-rW", str(obj)]).splitlines():
        m = re.match(r"Relocation section '\.rela?\.text\.([^']+)'", line)
        if m:
            current = calls.setdefault(m.group(1), set())
            continue
        if line.startswith("Relocation section"):
            current = None
            continue
        f = line.split()
        if current is not None and len(f) >= 5 and re.fullmatch(r"[0-9a-f]+", f[0]):
            name = f[4]
            current.add(name[len(".text."):] if name.startswith(".text.") else name)
    return calls


def measure_target(name: str, info: dict, lib: Path = LIB) -> dict:
    t = TARGETS[name]
    readelf = shutil.which("readelf") or shutil.which("llvm-readelf-14")
    if shutil.which(t["cc"]) is None or readelf is None:
        missing = t["cc"] if shutil.which(t["cc"]) is None else "readelf"
        return {"ok": False, "error": f"{missing} not found (tools/apt-packages.sh installs it)"}
    flags = t["flags"] + COMMON
    out: dict = {"command": f"{t['cc']} {' '.join(flags)}", "ok": True}
    with tempfile.TemporaryDirectory(prefix="osdkc-footprint-") as tmp:
        work = Path(tmp)
        procs = []
        failed = []
        try:
            for src in sorted(info["files"]):
                path = lib / src
                inc = ["-isystem", str(_tiny_libc(path, info["files"][src]["libc"], work / "libc" / src))] \
                    if t["tiny_libc"] else []
                obj = work / (src[:-2] + ".o")
                # a group of its own: the driver's cc1 and as go with it when it is killed
                procs.append((src, obj, subprocess.Popen([t["cc"], *flags, *inc, "-I", str(lib), "-o", str(obj),
                                                          str(path)], cwd=work, stdout=subprocess.PIPE,
                                                         stderr=subprocess.PIPE, text=True, process_group=0)))
            for src, obj, p in procs:
                _, err = p.communicate()
                if p.returncode:
                    failed.append(f"{src}: {err.strip()[:1500]}")
        finally:   # a signal or an error on the way: no compiler is left running
            for _, _, p in procs:
                if p.poll() is None:
                    kill_group(p)
        if failed:
            return {**out, "ok": False, "error": "compile failed: " + " | ".join(failed)}
        sizes, funcs, globals_, entries = {}, {}, {}, []
        objs = {src: work / (src[:-2] + ".o") for src in info["files"]}
        for src, obj in objs.items():
            sizes[src] = _sizes(obj, readelf)
            g, local = _symbols(obj, readelf)
            for sym in g:
                globals_[sym] = src
            frames = su_frames(obj.with_suffix(".su"))
            for fn in g | local:
                frame, bounded = frames.get(fn, (0, True))
                funcs[(src, fn)] = {"frame": frame, "bounded": bounded, "refs": set()}
            for fn, refs in _calls(obj, readelf).items():
                if (src, fn) in funcs:
                    funcs[(src, fn)]["refs"] = refs
            entries += [(src, fn) for fn in sorted(g)]
        for (src, fn), f in funcs.items():
            # a name in the same file first (a static function), else the library's global
            f["calls"] = sorted({(src, r) if (src, r) in funcs else (globals_[r], r)
                                 for r in f.pop("refs") if (src, r) in funcs or r in globals_} - {(src, fn)})
            if any(r == fn for r in f["calls"]):
                raise FootprintError(f"{fn} calls itself")
        try:
            out["stack"] = deepest_paths(funcs, entries)
        except StackBoundError as e:
            return {**out, "ok": False, "error": str(e)}

    def total(files) -> dict[str, int]:
        return {k: sum(sizes[f][k] for f in files) for k in ("text", "data", "bss")}

    out["files"] = sizes
    out["features"] = [{"feature": f["feature"], "files": f["files"], **total(f["files"])} for f in info["features"]]
    out["library"] = total(info["files"])
    out["library_no_stdio"] = total([f for f in info["files"] if f not in info["stdio"]])
    return out


def measure(targets: tuple[str, ...] = tuple(TARGETS), lib: Path = LIB, board: bool = True) -> dict:
    """The objects per target; with `board`, the programs linked for a board too (board_footprint.py)."""
    try:
        info = json.loads((lib / "features.json").read_text(encoding="utf-8"))
    except (OSError, ValueError) as e:
        return {"ok": False, "error": f"cannot read {lib / 'features.json'}: {e}", "targets": {}}
    result: dict = {"targets": {}}
    for name in targets:
        try:
            result["targets"][name] = measure_target(name, info, lib)
        except FootprintError as e:
            result["targets"][name] = {"ok": False, "error": str(e)}
    if board:
        result["board"] = board_footprint.measure()
    result["ok"] = all(t["ok"] for t in result["targets"].values()) and result.get("board", {"ok": True})["ok"]
    return result


# ---- what is printed ------------------------------------------------------------------------

def _size_rows(fp: dict) -> tuple[list[str], list[list[str]]]:
    names = [n for n, t in fp["targets"].items() if t["ok"]]
    header = ["feature", "files"] + [f"{n} {k}" for n in names for k in ("text", "data", "bss")]
    first = fp["targets"][names[0]] if names else {"features": []}
    rows = []
    for i, feat in enumerate(first["features"]):
        rows.append([feat["feature"], ", ".join(feat["files"])]
                    + [str(fp["targets"][n]["features"][i][k]) for n in names for k in ("text", "data", "bss")])
    for key, label in (("library", "whole library"), ("library_no_stdio", "whole library, OSDK_NO_STDIO=1")):
        if names:
            rows.append([label, ""] + [str(fp["targets"][n][key][k]) for n in names for k in ("text", "data", "bss")])
    return header, rows


def _stack_rows(fp: dict) -> tuple[list[str], list[list[str]]]:
    names = [n for n, t in fp["targets"].items() if t["ok"]]
    header = ["function", "file"] + [f"{n} bytes" for n in names] + ["deepest path (" + (names[-1] if names else "") + ")"]
    rows = []
    if names:
        last = fp["targets"][names[-1]]["stack"]
        for fn in sorted(last, key=lambda f: (last[f]["file"], f)):
            cells = [fn, last[fn]["file"]]
            cells += [str(fp["targets"][n]["stack"].get(fn, {}).get("bytes", "–")) for n in names]
            rows.append(cells + [" > ".join(last[fn]["path"])])
    return header, rows


def terminal(fp: dict) -> str:
    lines = ["footprint: generated/c, per feature (bytes of the objects) and stack per public function"]
    for n, t in fp["targets"].items():
        lines.append(f"  {n}: " + (t["command"] if t["ok"] else f"FAILED: {t['error']}"))
    if "error" in fp:
        lines.append(f"  FAILED: {fp['error']}")
    header, rows = _size_rows(fp)
    if rows:
        lines += ["  " + "  ".join(header)] + ["  " + "  ".join(r) for r in rows]
        _, stack = _stack_rows(fp)
        deepest = sorted(stack, key=lambda r: -int(r[2]) if r[2].isdigit() else 0)[:5]
        lines += ["  deepest stacks: " + "; ".join(f"{r[0]} {', '.join(r[2:-1])}" for r in deepest)]
    if "board" in fp:
        lines += board_footprint.terminal(fp["board"])
    return "\n".join(lines)


def _md(header: list[str], rows: list[list[str]], numeric: range) -> list[str]:
    align = ["---:" if i in numeric else "---" for i in range(len(header))]
    return ["| " + " | ".join(header) + " |", "|" + "|".join(align) + "|"] + \
        ["| " + " | ".join(c.replace("|", "\\|") for c in r) + " |" for r in rows]


def markdown(fp: dict, command: str) -> str:
    lines = [BEGIN, "", f"Command: `{command}`.", ""]
    for n, t in fp["targets"].items():
        lines.append(f"- {n}: " + (f"`{t['command']}`" if t["ok"] else f"FAILED: {t['error']}"))
    if "error" in fp:
        lines.append(f"- FAILED: {fp['error']}")
    header, rows = _size_rows(fp)
    if rows:
        lines += ["", "Bytes of the objects (text includes read-only data) per feature, a feature with the files "
                      "it calls into:", ""]
        lines += _md(header, [[r[0], ", ".join(f"`{x}`" for x in r[1].split(", ") if x)] + r[2:] for r in rows],
                     range(2, len(header)))
        header, rows = _stack_rows(fp)
        lines += ["", "Deepest stack per public function, in bytes (callbacks and libc functions not included; "
                      "on x86-64 a frame includes the return address the call pushed):", ""]
        lines += _md(header, [[f"`{r[0]}`", f"`{r[1]}`", *r[2:]] for r in rows], range(2, len(header) - 1))
    if "board" in fp:
        lines += board_footprint.markdown(fp["board"])
    return "\n".join(lines + ["", END])


def write_markdown(path: Path, block: str) -> None:
    """Replace the footprint block of `path`, or add it at the end."""
    report.write_markdown(path, block, BEGIN, END)
