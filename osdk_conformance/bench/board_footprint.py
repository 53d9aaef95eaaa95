"""The board part of the `footprint` section of `osdkc bench`: the C
library linked into the smallest programs that use it as a board does
(conformance/testees/c-target/measure/), on the Cortex-M4 QEMU emulates.

- Flash and RAM per feature (measure/footprint.c, FEATURE 0 to 3: the
  board alone; receive; + decode; + encode), linked with newlib-nano and
  --gc-sections, from the ELF's sections: flash is what is stored (code,
  read-only data, the unwind index and the initial values of .data), RAM
  what the program keeps (.data and .bss) plus the stack bound below.
  The library's share is the difference from FEATURE 0.
- The stack bound: each function's frame and calls, read from the linked
  ELF (`objdump -d`), so libc functions and inlining are as linked. A
  frame comes from -fstack-usage for the files the build compiled, from
  the pushes and sub sp of their bodies, all added up, for newlib's; a call is a bl or a
  branch to another function's start (a tail call counted as a call: an
  over-estimate, never an under-one). The only call through a pointer,
  the deframer's callback, is resolved to the program's `on_event`;
  any other fails the section. The boards take no interrupt (they are
  masked), so the deepest path from reset_handler is the program's stack.
- Instructions per broadcast frame (measure/cycles.c) over the first
  CYCLES_SECONDS of the a3-hour corpus, loaded into the board's memory and
  run in qemu-system-arm with -icount shift=0: the virtual clock advances
  one nanosecond per instruction, so SysTick counts instructions, not
  cycles (a Cortex-M4 takes one to a dozen cycles per instruction; on a
  real board the same SysTick would count cycles). The program calibrates
  a tick against a loop of known length, and reports the deepest the
  stack went (painted at start), which must stay within the bound.
"""
from __future__ import annotations

import re
import selectors
import shutil
import struct
import subprocess
import tempfile
import time
from pathlib import Path

from osdk_conformance.bench import corpus as bench_corpus
from osdk_conformance.bench.child import kill_group
from osdk_conformance.bench.stack_depth import StackBoundError, deepest_paths, su_frames
from osdk_conformance.board.bridge import MACHINE, QEMU
from osdk_conformance.core.paths import ROOT

C_TARGET = ROOT / "conformance" / "testees" / "c-target"
BOARD = "mps2-an386"      # the board file QEMU's MACHINE runs
CROSS = "arm-none-eabi-"
FEATURES = (
    (0, "the board alone (start-up, UART, a loop taking bytes)"),
    (1, "receive (deframer: frames, rejections)"),
    (2, "receive + decode (a3-fw3.1 frames, two broadcast items read)"),
    (3, "receive + decode + encode (a movement control frame per broadcast)"),
)
RECEIVE_ONLY = 1
GOALS = {"flash": 8 * 1024, "ram": 1024}   # issue 30: a receive-only build, RAM including the stack
CALLBACK = "on_event"
ENTRY = "reset_handler"
LIBRARY_ENTRIES = ("osdk_deframer_feed", "osdk_deframer_finish", "osdk_frame_decode", "osdk_encode_frame",
                   "osdk_encode_movement_control")
CYCLES_SECONDS = 60.0
CYCLES_CORPUS = "a3-hour"
MODES = {"receive": 1, "decode": 2}        # measure/cycles.c's second header word
CALIB_INSNS = 4 * 100_000                  # measure/cycles.c: CALIB_LOOPS turns of CALIB_INSNS
INPUT_ROOM = 3 * 1024 * 1024               # Makefile: __input is 1 MiB into 4 MiB of code RAM
QEMU_TIMEOUT = 120.0


class BoardError(Exception):
    pass


def _run(argv: list[str], timeout: float = 600.0) -> str:
    try:
        # a group of its own: a signal or the timeout takes make's compilers along with it
        p = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, process_group=0)
    except OSError as e:
        raise BoardError(f"cannot run {argv[0]}: {e.strerror or e} (tools/apt-packages.sh installs it)") from None
    try:
        out, err = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        raise BoardError(f"{' '.join(argv[:3])} took more than {timeout:g} s") from None
    finally:
        if p.returncode is None:
            kill_group(p)
    if p.returncode:
        raise BoardError(f"{' '.join(argv[:3])} failed: {(err or out).strip()[-2000:]}")
    return out


def build(board: str = BOARD) -> Path:
    """`make measure` for the board; the directory of its programs."""
    if shutil.which(CROSS + "gcc") is None:
        raise BoardError(f"{CROSS}gcc not found (tools/apt-packages.sh installs gcc-arm-none-eabi)")
    _run(["make", "-s", "-C", str(C_TARGET), f"BOARD={board}", "measure"])
    return C_TARGET / "build" / board / "measure"


# ---- sizes ---------------------------------------------------------------------------------

def sections(elf: Path) -> dict[str, tuple[int, int]]:
    """Allocated sections of a linked ELF: name -> (size, address)."""
    out = {}
    for line in _run([CROSS + "size", "-A", "-d", str(elf)]).splitlines():
        f = line.split()
        if len(f) == 3 and f[1].isdigit() and f[2].isdigit() and f[0].startswith("."):
            out[f[0]] = (int(f[1]), int(f[2]))
    return out


def sizes(elf: Path) -> dict[str, int]:
    s = {k: v[0] for k, v in sections(elf).items()}
    unknown = set(s) - {".text", ".ARM.exidx", ".data", ".bss", ".heap", ".stack", ".comment", ".ARM.attributes"} \
        - {k for k in s if k.startswith(".debug")}
    if unknown:   # a section this accounting does not place would go uncounted
        raise BoardError(f"{elf.name} has sections the footprint does not account for: {', '.join(sorted(unknown))}")
    if s.get(".heap"):
        raise BoardError(f"{elf.name} reserves a heap of {s['.heap']} bytes: the measuring programs use none")
    text, exidx, data, bss = (s.get(k, 0) for k in (".text", ".ARM.exidx", ".data", ".bss"))
    return {"text": text, "data": data, "bss": bss, "flash": text + exidx + data, "static_ram": data + bss}


# ---- the stack bound -----------------------------------------------------------------------

FUNC = re.compile(r"^([0-9a-f]+) <([^>]+)>:$")
INSN = re.compile(r"^\s*([0-9a-f]+):\s+(\S+)(?:\s+(.*))?$")
TARGET = re.compile(r"\b([0-9a-f]+) <([^>+]+)(\+0x[0-9a-f]+)?>")
REGS = re.compile(r"\{([^}]*)\}")


def _reg_count(text: str) -> tuple[int, int]:
    """Registers in a {list} and the bytes each takes (d registers 8, others 4)."""
    m = REGS.search(text)
    if not m:
        return 0, 4
    n = 0
    width = 4
    for part in m.group(1).split(","):
        part = part.strip()
        if part.startswith("d"):
            width = 8
        if "-" in part:
            a, b = part.split("-")
            n += int(b.strip()[1:]) - int(a.strip()[1:]) + 1
        elif part:
            n += 1
    return n, width


def _pushed_frame(insns: list[tuple[str, str]]) -> int:
    """The stack a function without a .su takes: every push, vpush and sub sp
    in its body added up, as if one path took them all (an upper bound;
    newlib-nano's functions are leaves that push once, often after a branch)."""
    frame = 0
    for mnem, ops in insns:
        base = mnem.split(".")[0]
        if base in ("push", "vpush") or (base == "stmdb" and ops.startswith("sp!")):
            n, width = _reg_count(ops)
            frame += n * width
        elif base in ("sub", "subw") and re.match(r"sp,\s*(sp,\s*)?#", ops):
            frame += int(re.search(r"#(\d+)", ops).group(1))
    return frame


def _su_frames(obj_dir: Path, program: str) -> dict[str, tuple[int, bool]]:
    """-fstack-usage of the files one program links (its own and the library's, not
    the other programs'): name -> (bytes, bounded); a static name in two files
    takes the larger frame, and is bounded only if both are."""
    out: dict[str, tuple[int, bool]] = {}
    others = {p.name for p in obj_dir.glob("footprint-*.su")} | {"cycles.su"}
    for su in sorted(obj_dir.glob("*.su")):
        if su.name in others and su.name != f"{program}.su":
            continue
        for name, (size, bounded) in su_frames(su).items():
            had = out.get(name, (size, bounded))
            out[name] = (max(size, had[0]), bounded and had[1])
    return out


def call_graph(elf: Path, su: dict[str, tuple[int, bool]], callbacks: tuple[str, ...] = (CALLBACK,)) -> dict:
    """name -> {"frame", "bounded", "calls", "source"} for every function of the linked program."""
    listing = _run([CROSS + "objdump", "-d", "--no-show-raw-insn", str(elf)])
    funcs: dict[str, dict] = {}
    body: dict[str, list[tuple[str, str]]] = {}
    current = None
    for line in listing.splitlines():
        m = FUNC.match(line)
        if m:
            current = m.group(2)
            body[current] = []
            continue
        m = INSN.match(line)
        if m and current is not None:
            body[current].append((m.group(2), m.group(3) or ""))
    names = set(body)
    for name, insns in body.items():
        calls: set[str] = set()
        for mnem, ops in insns:
            base = mnem.split(".")[0]
            if base in ("blx", "bx") and re.fullmatch(r"r\d+|ip|sl|fp", ops.strip()):
                if base == "bx" and ops.strip() == "lr":
                    continue
                present = [c for c in callbacks if c in names]
                if not present:
                    raise BoardError(f"{name} calls through a pointer ({mnem} {ops}) and the program has no "
                                     f"{' or '.join(callbacks)} to bound it by")
                calls.update(present)
                continue
            if not base.startswith("b") or base in ("bic", "bfi", "bfc"):
                continue
            t = TARGET.search(ops)
            if t and t.group(3) is None and t.group(2) != name and t.group(2) in names:
                calls.add(t.group(2))
        if name in su:
            frame, bounded = su[name]
            source = "stack-usage"
        else:
            frame, bounded, source = _pushed_frame(insns), True, "pushes"
        funcs[name] = {"frame": frame, "bounded": bounded, "calls": sorted(calls), "source": source}
    return funcs


def deepest(funcs: dict, entries: list[str]) -> dict[str, dict]:
    """The deepest stack from each entry: bytes and the path that takes them."""
    missing = [e for e in entries if e not in funcs]
    if missing:
        raise BoardError(f"the program has no function {', '.join(missing)}")
    keyed = {("", n): {"frame": f["frame"], "bounded": f["bounded"], "calls": [("", c) for c in f["calls"]]}
             for n, f in funcs.items()}
    try:
        found = deepest_paths(keyed, [("", e) for e in entries])
    except StackBoundError as e:
        raise BoardError(str(e)) from None
    return {e: {"bytes": d["bytes"], "path": d["path"]} for e, d in found.items()}


# ---- instructions per frame ------------------------------------------------------------------

LINE = re.compile(rb"#cycles ((?:\w+=\d+ ?)+)")


def input_address(elf: Path) -> int:
    """Where measure/cycles.c reads its capture: __input, checked to lie past the image."""
    secs = sections(elf)
    end = max(addr + size for name, (size, addr) in secs.items() if name in (".text", ".ARM.exidx")
              ) + secs.get(".data", (0, 0))[0]
    addr = _symbol(elf, "__input")
    if end > addr:
        raise BoardError(f"the image ends at {end:#x}, past __input at {addr:#x}")
    return addr


def run_cycles(elf: Path, addr: int, data: bytes, mode: str, timeout: float = QEMU_TIMEOUT) -> dict[str, int]:
    """measure/cycles.c over `data`, loaded at `addr` (input_address), in QEMU: its answer line as numbers."""
    if len(data) + 8 > INPUT_ROOM:
        raise BoardError(f"{len(data)} bytes do not fit the {INPUT_ROOM} bytes at __input")
    with tempfile.NamedTemporaryFile(prefix="osdkc-cycles-", suffix=".bin") as fh:
        fh.write(struct.pack("<II", len(data), MODES[mode]) + data)
        fh.flush()
        # -no-reboot: a fault's reset (boards/startup.c) ends QEMU instead of starting the program again
        argv = [QEMU, "-machine", MACHINE, "-display", "none", "-monitor", "none", "-serial", "stdio", "-no-reboot",
                "-icount", "shift=0", "-accel", "tcg,tb-size=32", "-device", f"loader,file={fh.name},addr={addr:#x}",
                "-kernel", str(elf)]
        try:
            p = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
        except OSError as e:
            raise BoardError(f"cannot start {QEMU}: {e.strerror or e} (tools/apt-packages.sh installs it)") from None
        out = b""
        sel = selectors.DefaultSelector()
        try:
            # the firmware waits after its line: read until it is there, then stop QEMU
            sel.register(p.stdout, selectors.EVENT_READ)
            deadline = time.monotonic() + timeout
            while not LINE.search(out) or not out.endswith(b"\n"):
                if b"#fault" in out:
                    raise BoardError("the measuring program faulted on the board")
                left = deadline - time.monotonic()
                if left <= 0 or not sel.select(left):
                    raise BoardError(f"{QEMU} gave no #cycles line in {timeout:g} s: {out[-300:]!r}")
                chunk = p.stdout.read1(4096)
                if not chunk:
                    err = p.stderr.read().decode(errors="replace").strip()
                    raise BoardError(f"{QEMU} ended before the #cycles line: {(err or out.decode(errors='replace'))[-300:]}")
                out += chunk
        finally:
            sel.close()
            p.kill()
            p.wait()
    return {k.decode(): int(v) for k, v in (kv.split(b"=") for kv in LINE.search(out).group(1).split())}


def _symbol(elf: Path, name: str) -> int:
    for line in _run([CROSS + "nm", str(elf)]).splitlines():
        f = line.split()
        if len(f) == 3 and f[2] == name:
            return int(f[0], 16)
    raise BoardError(f"{elf.name} has no symbol {name}")


# ---- the whole measurement -------------------------------------------------------------------

def measure(board: str = BOARD, seconds: float = CYCLES_SECONDS) -> dict:
    try:
        return _measure(board, seconds)
    except BoardError as e:
        return {"ok": False, "error": str(e), "board": board}


def _measure(board: str, seconds: float) -> dict:
    out_dir = build(board)
    features = []
    for n, label in FEATURES:
        elf = out_dir / f"footprint-{n}.elf"
        funcs = call_graph(elf, _su_frames(out_dir / "obj", elf.stem))
        bounds = deepest(funcs, [ENTRY, *(e for e in LIBRARY_ENTRIES if e in funcs)])
        row = {"feature": n, "label": label, **sizes(elf), "stack": bounds.pop(ENTRY)}
        row["ram"] = row["static_ram"] + row["stack"]["bytes"]
        row["entries"] = {e: b["bytes"] for e, b in bounds.items()}
        features.append(row)
    board_only = features[0]
    for row in features:
        row["library"] = {k: row[k] - board_only[k] for k in ("flash", "static_ram", "ram")}
    receive = features[RECEIVE_ONLY]
    goals = {k: {"goal": v, "measured": receive[k], "met": receive[k] < v} for k, v in GOALS.items()}

    elf = out_dir / "cycles.elf"
    funcs = call_graph(elf, _su_frames(out_dir / "obj", elf.stem))
    bound = deepest(funcs, [ENTRY])[ENTRY]
    c = bench_corpus.corpus(CYCLES_CORPUS, seconds=seconds)
    data = Path(c.path).read_bytes()
    cycles = {"corpus": CYCLES_CORPUS, "seconds": seconds, "frames": c.frames, "bytes": c.bytes,
              "stack_bound": bound["bytes"], "modes": {}}
    addr = input_address(elf)
    for mode in MODES:
        r = run_cycles(elf, addr, data, mode)
        if r.get("frames") != c.frames or r.get("errors") != 0 or r.get("bytes") != c.bytes:
            raise BoardError(f"the board counted {r.get('frames')} frames and {r.get('errors')} errors in "
                             f"{r.get('bytes')} bytes; the corpus holds {c.frames} frames, no error, {c.bytes} bytes")
        if not r.get("calib"):
            raise BoardError("the board's calibration loop took no time: SysTick is not running")
        per_tick = CALIB_INSNS / r["calib"]
        if r["stack"] > bound["bytes"]:
            raise BoardError(f"the board used {r['stack']} bytes of stack, more than the bound of {bound['bytes']}: "
                             "the bound misses a path")
        cycles["modes"][mode] = {"ticks": r["ticks"], "instructions_per_tick": per_tick,
                                 "instructions_per_frame": round(r["ticks"] * per_tick / c.frames),
                                 "instructions_per_byte": round(r["ticks"] * per_tick / c.bytes, 1),
                                 "most_per_frame": round(r["max"] * per_tick), "stack_used": r["stack"]}
    cycles["decode_only_per_frame"] = cycles["modes"]["decode"]["instructions_per_frame"] \
        - cycles["modes"]["receive"]["instructions_per_frame"]
    return {"ok": True, "board": board, "command": f"make -C conformance/testees/c-target BOARD={board} measure",
            "compiler": _run([CROSS + "gcc", "--version"]).splitlines()[0], "features": features, "goals": goals,
            "cycles": cycles}


# ---- what is printed -------------------------------------------------------------------------

def _goal_words(g: dict) -> str:
    return f"{g['measured']} bytes against under {g['goal']}: {'met' if g['met'] else 'MISSED'}"


def terminal(b: dict) -> list[str]:
    if not b.get("ok"):
        return [f"  board ({b.get('board')}): FAILED: {b.get('error')}"]
    lines = [f"  board {b['board']}, linked ({b['command']}):"]
    for r in b["features"]:
        lines.append(f"    {r['feature']} {r['label']}: flash {r['flash']}, RAM {r['static_ram']} + stack "
                     f"{r['stack']['bytes']} = {r['ram']} (library: flash {r['library']['flash']}, "
                     f"RAM {r['library']['ram']})")
    lines.append(f"    receive-only goal: flash {_goal_words(b['goals']['flash'])}; RAM with stack "
                 f"{_goal_words(b['goals']['ram'])}")
    c = b["cycles"]
    for mode, m in c["modes"].items():
        lines.append(f"    {mode}: {m['instructions_per_frame']} instructions per frame "
                     f"({m['instructions_per_byte']} per byte, at most {m['most_per_frame']}), "
                     f"stack used {m['stack_used']} of a bound of {c['stack_bound']}")
    return lines


def markdown(b: dict) -> list[str]:
    if not b.get("ok"):
        return ["", f"Board ({b.get('board')}): FAILED: {b.get('error')}"]
    lines = ["", f"Linked for `{b['board']}` (`{b['command']}`, {b['compiler']}, newlib-nano, `-Os`, "
                 "`--gc-sections`): bytes per program, the library's share beside it.", "",
             "| program | flash | static RAM | stack bound | RAM with stack | library flash | library RAM "
             "with stack | deepest path |",
             "|---|---:|---:|---:|---:|---:|---:|---|"]
    for r in b["features"]:
        lines.append(f"| {r['feature']}: {r['label']} | {r['flash']} | {r['static_ram']} | {r['stack']['bytes']} | "
                     f"{r['ram']} | {r['library']['flash']} | {r['library']['ram']} | "
                     f"{' > '.join(r['stack']['path'])} |")
    g = b["goals"]
    lines += ["", f"Receive-only goal (the whole program 1): flash {_goal_words(g['flash'])}; RAM including "
                  f"the stack {_goal_words(g['ram'])}.", ""]
    entries = sorted({e for r in b["features"] for e in r["entries"]})
    lines += ["Stack bound per entry point as linked in each program (bytes; the deframer's with its "
              "callback):", "", "| entry point | " + " | ".join(f"program {r['feature']}" for r in b["features"]) + " |",
              "|---|" + "---:|" * len(b["features"])]
    for e in entries:
        lines.append(f"| `{e}` | " + " | ".join(str(r["entries"].get(e, "–")) for r in b["features"]) + " |")
    c = b["cycles"]
    lines += ["", f"Instructions per frame in QEMU (`-icount shift=0`: instructions executed, not cycles), "
                  f"the first {c['seconds']:g} s of `{c['corpus']}` ({c['frames']} frames of every a3-fw3.1 item, "
                  f"{c['bytes']} bytes) from the board's memory:", "",
              "| work | instructions per frame | per byte | most for one frame | stack used (bound) |",
              "|---|---:|---:|---:|---:|"]
    for mode, m in c["modes"].items():
        lines.append(f"| {'deframe' if mode == 'receive' else 'deframe + decode'} | {m['instructions_per_frame']} | "
                     f"{m['instructions_per_byte']} | {m['most_per_frame']} | {m['stack_used']} "
                     f"({c['stack_bound']}) |")
    return lines
