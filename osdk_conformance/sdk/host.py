"""`osdkc sdk host-test`: DJI's own host stack against `osdkc sim`.

The user points --osdk at a checkout of DJI's Onboard-SDK. Its core and its
Linux serial driver (2.3: the one of the release's command-line sample) are
compiled, unchanged, together with our small driver program
(conformance/sdk_host/driver23.cpp, driver31.cpp or driver_vehicle.cpp, public
SDK API only) into a cache directory. For each profile the SDK supports, the driver then runs a whole
session against a simulator on a pseudo-terminal: version, activation with
app id and key, broadcast frequencies, ~500 broadcast frames that the SDK
decodes and we compare field by field (IEEE bits for floats) with what the
simulator sent (`osdkc sim --log-broadcast`), obtain control, encrypted
movement control that the simulated aircraft must follow, release, frequency
restore. Each step is reported PASS, FAIL or SKIP.

Exit status: 0 every step passed, 1 a step failed, 2 the tree cannot be
used (missing file, unsupported SDK version, no compiler, build error).
"""
from __future__ import annotations

import argparse
import contextlib
import hashlib
import json
import os
import queue
import re
import secrets
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path

from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.options import baud_rate, positive_int, uint32
from osdk_conformance.core.paths import ROOT
from osdk_conformance.core.priority import keep_priority
from osdk_conformance.core.rules import hz_of_code, profile as load_profile, profile_names
from osdk_conformance.sdk.families import protocol
from osdk_conformance.sdk.testee_build import detect as detect_family
from osdk_conformance.sim.simulator import VERSION_ID, VERSION_NAME, spawned
from osdk_conformance._construct.floats import IeeeFloat
from osdk_conformance._construct.payload import has_version_id, osdk_payload

DRIVER_DIR = ROOT / "conformance" / "sdk_host"
KEY_ENV = "OSDKC_HOST_TEST_KEY"
BAUDS = (230400, 921600)   # --baud choices; the Linux serial drivers of 2.3 to 3.2.x set 230400 at most
BAUD = BAUDS[0]
DEFAULT_APP_ID = 1010101
HZ_CODE = {hz: code for code, hz in hz_of_code().items()}   # the set-frequency command's codes
STEPS = ("version", "activation", "frequencies", "broadcast", "obtain_control", "movement",
         "release_control", "frequency_restore", "host_frames")


# --------------------------------------------------------------------------
# Which SDK the tree holds


@dataclass
class SdkTree:
    root: Path
    version: str
    profiles: tuple[str, ...]
    sources: list[Path]
    includes: list[Path]
    driver: Path
    defines: tuple[str, ...] = ()
    family: str = "core"                 # the sdk build family: "core" (CoreAPI) or "protocol" (Vehicle API)
    refusals: dict[str, str] = field(default_factory=dict)   # profile -> where the release refuses it by design
    bauds: dict[int, str] = field(default_factory=dict)      # rate -> "" when the serial driver sets it, else why not
    can_encrypt: bool = True             # the host can encrypt its commands (3.3.x cannot)


@dataclass(frozen=True)
class Layout31:
    """Where a 3.1.x or 3.2.x release keeps the core and the Linux serial driver."""

    inc: str
    src: str
    serial: str       # LinuxSerialDevice.h and .cpp
    serial_inc: str
    defines: tuple[str, ...] = ()   # what our driver must know about the release

    def required(self) -> list[str]:
        """What the build and our driver need by name; the core's other
        sources (SRC/*.cpp) are compiled too."""
        return ([f"{self.inc}/{h}" for h in ("DJI_Version.h", "DJI_API.h", "DJI_Flight.h", "DJI_Type.h",
                                             "DJI_Config.h")]
                + [f"{self.src}/{c}" for c in ("DJI_API.cpp", "DJI_App.cpp", "DJI_Link.cpp", "DJI_Codec.cpp",
                                               "DJI_Memory.cpp", "DJI_HardDriver.cpp", "DJI_Flight.cpp")]
                + [f"{self.serial_inc}/LinuxSerialDevice.h", f"{self.serial}/LinuxSerialDevice.cpp"])


LAYOUTS_31 = (
    Layout31("osdk-core/inc", "osdk-core/src", "platform/linux/src", "platform/linux/inc"),   # 3.1.9, 3.2.x
    Layout31("lib/inc", "lib/src", "platform", "platform", ("OSDKC_INIT_SETS_NO_STATUS",)),   # 3.1.8
)
# 3.2.1 and 3.2.2 take the firmware version from the aircraft's version reply
# (CoreAPI has no version argument any more); 3.2.0 still takes it from the caller.
FW_FROM_AIRCRAFT = re.compile(r"\bgetFwVersion\s*\(")
SUPPORTED = "2.3, 3.1.x, 3.2.x and 3.3 to 3.9"

# 2.3: lib/ holds the core, the Linux serial driver is the command-line sample's.
LIB_23 = ("lib/inc", "lib/src")
SERIAL_23 = "sample/commandline/Linux/conboardSDK"
REQUIRED_23 = ([f"lib/inc/{h}" for h in ("DJI_Version.h", "DJI_Config.h", "DJI_API.h", "DJI_Flight.h",
                                         "DJI_Type.h", "DJI_HardDriver.h")]
               + [f"lib/src/{c}" for c in ("DJI_API.cpp", "DJI_App.cpp", "DJI_Link.cpp", "DJI_Codec.cpp",
                                           "DJI_Memory.cpp", "DJI_HardDriver.cpp", "DJI_Flight.cpp")]
               + [f"{SERIAL_23}/DJIHardDriverManifold.h", f"{SERIAL_23}/DJIHardDriverManifold.cpp"])
# DJI_Config.h's switch -> the profile it builds for (its SDK_VERSION in DJI_Version.h);
# SDK_VERSION_3_1_A3 has no GPS or RTK item in 2.3's broadcast structure.
SWITCHES_23 = {"SDK_VERSION_2_3": "m100-fw2.3", "SDK_VERSION_3_1_M100": "m100-fw3.1"}

# 3.3 to 3.9 (the "protocol" family of `osdkc sdk build`): the Vehicle API,
# compiled with the tree's Linux platform layer. Paths below osdk-core/.
VEHICLE_SOURCE_DIRS = ("api/src", "hal/src", "protocol/src", "utility/src", "platform/linux/src",
                       "platform/default/src")
VEHICLE_INCLUDE_DIRS = ("api/inc", "hal/inc", "protocol/inc", "utility/inc", "platform/linux/inc",
                        "platform/default/inc")
VEHICLE_REQUIRED = ("api/inc/dji_vehicle.hpp", "api/src/dji_vehicle.cpp", "api/inc/dji_broadcast.hpp",
                    "api/inc/dji_control.hpp", "platform/linux/inc/linux_serial_device.hpp",
                    "platform/linux/src/linux_serial_device.cpp", "platform/linux/src/posix_thread.cpp")
# functionalSetUp's firmware check: below the extended version base only M100 FW 3.1 and the
# legacy M600 pass; the line that refuses is found in the tree (it moves between releases).
REFUSAL = re.compile(r"getFwVersion\(\)\s*<\s*extendedVersionBase\s*&&")
REFUSED_PROFILES = ("a3-fw3.1",)   # A3 on FW 3.1.100.0: neither M100_31 nor the legacy M600 (PM820V3, 3.2.15.62)


def _fw31_versions() -> dict[str, int]:
    """Profile -> SDK target version, for the profiles of protocol 3.1: the
    ones driver31.cpp speaks (the 2.3 protocol's version handshake differs)."""
    return {name: v for name in profile_names()
            if (v := load_profile(name).sdk_version) >> 16 == 0x0301}


def _profiles_of(version_h: str) -> tuple[str, ...]:
    """The 3.1 profiles whose SDK version DJI_Version.h defines (MAKE_VERSION(a, b, c, d))."""
    defined = {a << 24 | b << 16 | c << 8 | d for a, b, c, d in
               ((int(x) for x in m) for m in re.findall(r"MAKE_VERSION\((\d+),\s*(\d+),\s*(\d+),\s*(\d+)\)", version_h))}
    return tuple(name for name, v in _fw31_versions().items() if v in defined)


def serial_rates(root: Path, serial_cpp: Path) -> dict[int, str]:
    """The rates the tree's Linux serial driver knows: its _serialConfig pairs
    a table of rates (std_rate) with a table of termios speeds (st_baud) by
    index; a rate without a speed leaves the speed unset. For BAUDS only."""
    text = serial_cpp.read_text(errors="replace")
    rel = serial_cpp.relative_to(root)
    speeds = re.search(r"st_baud\[\]\s*=\s*\{([^}]*)\}", text)
    rates = re.search(r"std_rate\[\]\s*=\s*\{([^}]*)\}", text)
    if not speeds or not rates:
        return {b: "" for b in BAUDS}
    line = text[:speeds.start()].count("\n") + 1
    n_speeds = len(re.findall(r"\bB\d+\b", speeds.group(1)))
    known = [int(x) for x in re.findall(r"\d+", rates.group(1))][:n_speeds]
    out = {}
    for b in BAUDS:
        out[b] = "" if b in known else (f"{rel}:{line}: the release's Linux serial driver sets "
                                        f"{', '.join(map(str, known))} baud only; {b} leaves the line speed unset")
    return out


def _refusal_line(root: Path, core: Path) -> str:
    vehicle = core / "api" / "src" / "dji_vehicle.cpp"
    lines = vehicle.read_text(errors="replace").splitlines()
    for i, line in enumerate(lines, 1):
        if REFUSAL.search(line):
            return f"{vehicle.relative_to(root)}:{i}"
    return f"{vehicle.relative_to(root)} (functionalSetUp)"


def _detect_31(root: Path, version: str) -> SdkTree:
    layout = next((lay for lay in LAYOUTS_31 if (root / lay.inc / "DJI_Version.h").is_file()), None)
    if layout is None:
        raise UsageError(f"--osdk {root}: DJI Onboard-SDK {version}: missing osdk-core/inc/DJI_Version.h or "
                         "lib/inc/DJI_Version.h: the 3.1.x host stack cannot be built")
    for rel in layout.required():
        if not (root / rel).is_file():
            raise UsageError(f"--osdk {root}: missing {rel}: the {version} host stack cannot be built")
    includes = [root / layout.inc, root / layout.serial_inc]
    version_h = (root / layout.inc / "DJI_Version.h").read_text(errors="replace")
    profiles = _profiles_of(version_h)
    if not profiles:
        raise UsageError(f"--osdk {root}: {layout.inc}/DJI_Version.h defines no SDK version of a protocol 3.1 "
                         f"profile ({', '.join(f'{v:#010x}' for v in _fw31_versions().values())})")
    serial = root / layout.serial / "LinuxSerialDevice.cpp"
    sources = sorted((root / layout.src).glob("*.cpp")) + [serial]
    return SdkTree(root, version, profiles, sources, includes, DRIVER_DIR / "driver31.cpp", layout.defines,
                   family="core", bauds=serial_rates(root, serial))


def _detect_vehicle(root: Path, version: str) -> SdkTree:
    core = root / "osdk-core"
    for rel in VEHICLE_REQUIRED:
        if not (core / rel).is_file():
            raise UsageError(f"--osdk {root}: missing osdk-core/{rel}: the {version} host stack cannot be built")
    sources = sorted(p for d in VEHICLE_SOURCE_DIRS for p in (core / d).glob("*.cpp"))
    sources += sorted((core / "modules" / "src").glob("*/*.cpp"))          # 3.8 and later
    includes = [core / d for d in VEHICLE_INCLUDE_DIRS]
    includes += sorted(p for p in (core / "modules" / "inc").glob("*") if p.is_dir())
    serial_h = core / "platform" / "linux" / "inc" / "linux_serial_device.hpp"
    if "sys/select.h" not in serial_h.read_text(errors="replace"):
        includes.insert(0, protocol.SELECT_SHIM)   # 3.3 to 3.6 name fd_set without <sys/select.h>
    vehicle_h = (core / "api" / "inc" / "dji_vehicle.hpp").read_text(errors="replace")
    can_encrypt = "setEncryption" in vehicle_h
    refusal = f"refused by design ({_refusal_line(root, core)}: functionalSetUp accepts firmware below the " \
              "extended version base only for M100 FW 3.1.10.0 and the legacy M600)"
    return SdkTree(root, version, tuple(protocol.PROFILES), sources, includes, DRIVER_DIR / "driver_vehicle.cpp",
                   ("OSDKC_SET_ENCRYPTION",) if can_encrypt else (), family="protocol",
                   refusals={p: refusal for p in REFUSED_PROFILES},
                   bauds=serial_rates(root, core / "platform" / "linux" / "src" / "linux_serial_device.cpp"),
                   can_encrypt=can_encrypt)


def _detect_23(root: Path, version: str) -> SdkTree:
    for rel in REQUIRED_23:
        if not (root / rel).is_file():
            raise UsageError(f"--osdk {root}: missing {rel}: the 2.3 host stack cannot be built (2.3's lib/ has "
                             f"no serial driver; a Linux program takes the sample's, {SERIAL_23})")
    config = root / "lib" / "inc" / "DJI_Config.h"
    text = config.read_text(errors="replace")
    chosen = [(text[:m.start()].count("\n") + 1, m.group(1))
              for m in re.finditer(r"^[ \t]*#[ \t]*define[ \t]+(SDK_VERSION_\w+)", text, re.M)]
    profiles = tuple(SWITCHES_23[name] for _, name in chosen if name in SWITCHES_23)
    if len(chosen) != 1 or len(profiles) != 1:
        found = ", ".join(f"{name} (line {line})" for line, name in chosen) or "none"
        raise UsageError(f"--osdk {root}: lib/inc/DJI_Config.h must define exactly one of "
                         f"{', '.join(SWITCHES_23)}; it defines {found}")
    serial = root / SERIAL_23 / "DJIHardDriverManifold.cpp"
    sources = sorted((root / "lib" / "src").glob("*.cpp")) + [serial]
    return SdkTree(root, version, profiles, sources, [root / "lib" / "inc", root / SERIAL_23],
                   DRIVER_DIR / "driver23.cpp", family="core", bauds=serial_rates(root, serial))


def detect(root: Path) -> SdkTree:
    """The release family as `osdkc sdk build` recognises it (sdk/families/),
    then what host-test builds of it."""
    recipe = detect_family(root)
    if recipe.family == "protocol":
        return _detect_vehicle(root, recipe.version)
    if recipe.version == "2.3":
        return _detect_23(root, recipe.version)
    if recipe.version.startswith(("3.1.", "3.2.")):
        tree = _detect_31(root, recipe.version)
        api_h = tree.includes[0] / "DJI_API.h"
        if FW_FROM_AIRCRAFT.search(api_h.read_text(errors="replace")):
            tree.defines += ("OSDKC_FW_FROM_AIRCRAFT",)
        return tree
    raise UsageError(f"--osdk {root}: DJI Onboard-SDK {recipe.version} is not supported by sdk host-test; "
                     f"supported: {SUPPORTED}")


# --------------------------------------------------------------------------
# Building


def _compiler() -> str:
    cxx = os.environ.get("CXX") or "g++"
    if not shutil.which(cxx):
        raise UsageError(f"no C++ compiler: {cxx} not found (set CXX)")
    return cxx


def build(tree: SdkTree, out: Path) -> Path:
    """The driver linked with the tree's core and serial driver; rebuilt only
    when a source, the compiler or the flags changed."""
    cxx = _compiler()
    flags = (["-std=c++11", "-O1", "-pthread", "-w"] + [f"-I{d}" for d in tree.includes]
             + [f"-D{d}" for d in tree.defines])
    digest = hashlib.sha256(" ".join([cxx, *flags]).encode())
    for src in [*tree.sources, tree.driver, *sorted(p for d in tree.includes for p in d.glob("*.h*"))]:
        digest.update(str(src).encode() + b"\0" + src.read_bytes())
    stamp = digest.hexdigest()
    exe = out / "driver"
    stamp_file = out / "driver.stamp"
    if exe.is_file() and stamp_file.is_file() and stamp_file.read_text().strip() == stamp:
        return exe
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as e:
        raise UsageError(f"--out {out}: {e.strerror or e}") from None
    cmd = ["nice", cxx, *flags, *map(str, tree.sources), str(tree.driver), "-o", str(exe)]
    print(f"osdkc sdk host-test: building the SDK {tree.version} host stack into {out}", file=sys.stderr, flush=True)
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode:
        tail = "\n".join(proc.stderr.strip().splitlines()[-15:])
        raise UsageError(f"building against {tree.root} failed ({cxx} exit {proc.returncode}):\n{tail}")
    stamp_file.write_text(stamp + "\n")
    return exe


# --------------------------------------------------------------------------
# One session


@dataclass
class Step:
    name: str
    verdict: str          # PASS, FAIL, SKIP
    detail: str


@dataclass
class Session:
    steps: dict[str, dict] = field(default_factory=dict)
    broadcasts: list[dict] = field(default_factory=list)
    logs: list[str] = field(default_factory=list)
    done: dict | None = None
    stderr: str = ""
    exit_code: int | None = None
    exposed: list[str] | None = None     # the spec fields the driver can read (None: all)
    opened: dict = field(default_factory=dict)


def _reader(stream, q: queue.Queue) -> None:
    for line in stream:
        q.put(line)
    q.put(None)


def _stop_group(proc: subprocess.Popen, grace: float) -> None:
    """SIGTERM the driver's process group (it releases control and restores
    the frequencies first), SIGKILL it when it takes longer than `grace`."""
    if proc.poll() is not None:
        return
    try:
        os.killpg(proc.pid, signal.SIGTERM)
        proc.wait(timeout=grace)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.wait()
    except ProcessLookupError:
        pass


def _pump(lines: queue.Queue, s: Session, sim: subprocess.Popen, until: float) -> bool:
    """Take the driver's JSON lines into `s` until it closes its output
    (True) or the time is up (False)."""
    while True:
        try:
            line = lines.get(timeout=max(0.0, until - time.monotonic()))
        except queue.Empty:
            return False
        if line is None:
            return True
        try:
            ev = json.loads(line)
        except ValueError:
            s.logs.append(line.rstrip("\n"))
            continue
        kind = ev.get("ev")
        if kind == "bc":
            s.broadcasts.append(ev)
        elif kind == "open":
            s.opened = ev
            sim.send_signal(signal.SIGUSR1)
        elif kind == "fields":
            s.exposed = list(ev["names"])
        elif kind == "step":
            s.steps[ev["step"]] = ev
        elif kind == "log":
            s.logs.append(ev["text"])
        elif kind == "done":
            s.done = ev


# The driver needs this long after SIGTERM to release control and restore the
# frequencies (2 s per unanswered command at worst).
STOP_GRACE_S = 10.0


def drive(exe: Path, sim: subprocess.Popen, port: str, profile: str, app_id: int, frames: int, moves: int,
          restore: list[int], env: dict, timeout: float, baud: int = BAUD, encrypt: bool = False) -> Session:
    """Run the driver against the simulator at `port`; the broadcast starts
    (SIGUSR1 to the held simulator) once the SDK has the port open. On Ctrl-C
    the driver is told to stop, hands back control and restores the
    frequencies, and what it reported is printed before the interrupt goes on."""
    prof = load_profile(profile)
    cmd = [str(exe), "--port", port, "--baud", str(baud), "--sdk-version", str(prof.sdk_version),
           "--items", str(len(prof.flag_bits)), "--app-id", str(app_id),
           "--key-env", KEY_ENV, "--frames", str(frames), "--moves", str(moves),
           "--restore", ",".join(map(str, restore)), "--encrypt", "1" if encrypt else "0"]
    s = Session()
    # its own process group: the terminal's Ctrl-C reaches us, and we stop it in order
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
                            start_new_session=True, preexec_fn=keep_priority)
    lines: queue.Queue = queue.Queue()
    threading.Thread(target=_reader, args=(proc.stdout, lines), daemon=True).start()
    err: list[str] = []
    threading.Thread(target=lambda: err.extend(proc.stderr), daemon=True).start()
    try:
        if not _pump(lines, s, sim, time.monotonic() + timeout):
            s.stderr = f"the driver did not finish within {timeout:.0f} s"
    except KeyboardInterrupt:
        before = set(s.steps)
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGTERM)
        _pump(lines, s, sim, time.monotonic() + STOP_GRACE_S)
        _stop_group(proc, grace=1.0)
        for name in ("release_control", "frequency_restore"):
            if name in s.steps and name not in before:
                ev = s.steps[name]
                print(f"osdkc sdk host-test: {profile}: interrupted; {name} {'PASS' if ev['ok'] else 'FAIL'}: "
                      f"{ev['detail']}", file=sys.stderr, flush=True)
        raise
    finally:
        _stop_group(proc, grace=STOP_GRACE_S)
    s.exit_code = proc.returncode
    s.stderr = (s.stderr + "\n" + "".join(err)).strip()
    return s


# --------------------------------------------------------------------------
# Comparing what the SDK decoded with what the simulator sent


def _plain(value):
    if isinstance(value, IeeeFloat):
        return value.ieee_bits
    if hasattr(value, "int") and isinstance(value, str):   # a Construct enum value
        return int(value.int)
    return int(value)


def spec_fields(profile: str, value: bytes) -> tuple[int, dict[str, int]]:
    """Flag word and every field of the items present, as the spec decodes
    the value the simulator sent (floats as IEEE bits)."""

    data = osdk_payload(2, 0, False, profile).parse(value).body.data
    out: dict[str, int] = {}

    def walk(prefix: str, node) -> None:
        for k, v in node.items():
            if k.startswith("_"):
                continue
            if hasattr(v, "items"):
                walk(f"{prefix}{k}.", v)
            elif v is not None:
                out[prefix + k] = _plain(v)

    for item, v in data.items():
        if item.startswith("_") or item.startswith("has_") or item == "reserved_flags" or v is None:
            continue
        if hasattr(v, "items"):
            walk(f"{item}.", v)
        else:
            out[item] = _plain(v)
    return int.from_bytes(value[:2], "little"), out


@dataclass
class Comparison:
    compared: int = 0
    mismatched_frames: int = 0
    mismatches: list[str] = field(default_factory=list)   # the first few, for the report
    unknown: int = 0          # SEQs the SDK reported that the simulator never sent
    lost: int = 0             # frames sent between the SDK's first and last reported one that it never reported
    fields: int = 0
    items: set = field(default_factory=set)
    unexposed: set = field(default_factory=set)   # spec fields the driver's public API cannot read


def match_frames(decoded: list[dict], sent: dict[int, bytes], profile: str) -> list[dict]:
    """SEQ of each broadcast the driver reported without one: 3.3 to 3.9 hand
    a broadcast's callback the SEQ of the last ACK instead (their
    OpenProtocol::recvReqData does not set recvInfo.seqNumber). Such events
    name a field (`match`, the time stamp: 400 ticks a second, one value a
    frame) by which they are matched, in order, with the frames sent."""
    if not any("match" in ev for ev in decoded):
        return decoded
    order = sorted(sent)
    values = {}
    out, i = [], 0
    for n, ev in enumerate(decoded):
        name = ev.get("match")
        if not name:
            out.append(ev)
            continue
        want = ev["f"].get(name)
        pick = None
        for k in range(i, len(order)):
            if order[k] not in values:
                values[order[k]] = spec_fields(profile, sent[order[k]])[1].get(name)
            if values[order[k]] == want:
                pick = k
                break
        if pick is None:
            out.append(dict(ev, seq=-1 - n))   # matches nothing sent after the last match: unknown
            continue
        i = pick + 1
        out.append(dict(ev, seq=order[pick]))
    return out


def compare(profile: str, sent_log: Path, decoded: list[dict], exposed: list[str] | None = None) -> Comparison:
    sent: dict[int, bytes] = {}
    if sent_log.is_file():
        for line in sent_log.read_text().splitlines():
            rec = json.loads(line)
            sent[rec["seq"]] = bytes.fromhex(rec["value"])
    decoded = match_frames(decoded, sent, profile)
    readable = set(exposed) if exposed is not None else None
    c = Comparison()
    seen: set[int] = set()
    for ev in decoded:
        seq = ev["seq"]
        seen.add(seq)
        if seq not in sent:
            c.unknown += 1
            continue
        flags, want = spec_fields(profile, sent[seq])
        if readable is not None:
            c.unexposed.update(n for n in want if n not in readable)
            want = {n: v for n, v in want.items() if n in readable}
        got = ev["f"]
        bad = [] if ev["flags"] == flags else [f"flags: sent 0x{flags:04x}, SDK 0x{ev['flags']:04x}"]
        for name, v in want.items():
            if got.get(name) != v:
                bad.append(f"{name}: sent {v}, SDK {got.get(name, 'nothing')}")
        c.compared += 1
        c.fields += len(want)
        c.items.update(n.split(".")[0] for n in want)
        if bad:
            c.mismatched_frames += 1
            if len(c.mismatches) < 5:
                c.mismatches.append(f"SEQ {seq}: " + "; ".join(bad[:4]))
    known = [seq for seq in seen if seq in sent]
    if known:
        c.lost = sum(1 for seq in sent if min(known) <= seq <= max(known) and seq not in seen)
    return c


# --------------------------------------------------------------------------
# Verdicts


def _dotted(version: int) -> str:
    return ".".join(str(version >> shift & 0xFF) for shift in (24, 16, 8, 0))


def _why_stopped(s: Session) -> str:
    opened = s.steps.get("open")
    if opened and not opened["ok"]:
        return opened["detail"]
    if s.stderr:
        return s.stderr.splitlines()[-1]
    if s.exit_code is not None and s.exit_code < 0:
        try:
            name = signal.Signals(-s.exit_code).name
        except ValueError:
            name = "unknown"
        return f"the driver was killed by signal {-s.exit_code} ({name})"
    return f"the driver ended with status {s.exit_code}"


# The ACK each step's command gets on the wire: (command set, id), which of
# them (first or last), the command value it answers (None: any), and the
# codes that mean the command did what the step asked.
WIRE = {
    "version": ((0x00, 0x00), "first", None, {0x0000, 0xFF01}),   # answered; 0xFF01 = not activated yet
    "activation": ((0x00, 0x01), "last", None, {0x0000}),
    "frequencies": ((0x00, 0x10), "first", None, {0x0000}),
    "obtain_control": ((0x01, 0x00), "all", "01", {0x0002}),
    "release_control": ((0x01, 0x00), "all", "00", {0x0001}),
    "frequency_restore": ((0x00, 0x10), "last", None, {0x0000}),
}
FLAG = "SDK VERDICT NOT SUPPORTED BY THE WIRE"


def read_acks(path: Path) -> list[dict]:
    return [json.loads(line) for line in path.read_text().splitlines()] if path.is_file() else []


def wire_acks(step: str, acks: list[dict]) -> list[dict]:
    """The ACKs the simulator sent for `step`'s command, oldest first."""
    (cset, cid), which, command, _ = WIRE[step]
    mine = [a for a in acks if (a["set"], a["id"]) == (cset, cid) and not a.get("resent")
            and (command is None or a["command"] == command)]
    if not mine or which == "all":
        return mine
    return [mine[0]] if which == "first" else [mine[-1]]


def wire_check(step: str, ev: dict, acks: list[dict]) -> tuple[bool, str, bool]:
    """(the wire says the command succeeded, what the wire showed, the SDK's
    verdict or code disagrees with the wire)."""
    got = wire_acks(step, acks)
    if not got:
        return False, "wire: no ACK sent", False
    codes = [int.from_bytes(bytes.fromhex(a["value"])[:2], "little") for a in got]
    wire_ok = codes[-1] in WIRE[step][3]
    enc = sum(bool(a["encrypted"]) for a in got)
    text = f"wire: ACK {', '.join(f'0x{c:04X}' for c in codes)} ({enc} of {len(got)} encrypted)"
    flagged = False
    sdk_ok = ev.get("sdk_ok", ev.get("ok"))
    if "sdk_ok" in ev and sdk_ok is None:   # the SDK's caller got no ACK in time: no verdict to weigh
        text += "; no ACK reached the SDK's caller within 2 s"
    elif sdk_ok != wire_ok:
        flagged = True
        text += (f"; {FLAG}: the SDK reports {'success' if sdk_ok else 'failure'} where the wire's "
                 f"0x{codes[-1]:04X} means {'success' if wire_ok else 'failure'}")
    if "sdk_code" in ev and ev["sdk_code"] != codes[-1]:
        text += f"; the SDK hands the caller 0x{ev['sdk_code']:04X} for the wire's 0x{codes[-1]:04X}"
    return wire_ok, text, flagged


def expected_mode(flag: int) -> int:
    """The movement mode the simulator broadcasts for a control flag byte (its
    control_info.cur_mov_control_mode): 1 + 6 * vertical + 2 * horizontal + yaw."""
    return 1 + 6 * (flag >> 4 & 3) + 2 * (flag >> 6 & 3) + (flag >> 3 & 1)


def _verdicts(profile: str, s: Session, cmp: Comparison, stats: dict, frames: int,
              acks: list[dict] | None = None, refusal: str | None = None, encrypt: bool = False) -> list[Step]:
    out: list[Step] = []
    blocked = "not reached: " + _why_stopped(s)
    refused = "obtain_control" in s.steps and not s.steps["obtain_control"]["ok"]
    activation = s.steps.get("activation") or {}
    by_design = bool(activation.get("refused")) and refusal is not None
    can_encrypt = s.opened.get("can_encrypt", True)
    for name in STEPS:
        ev = s.steps.get(name)
        if name == "host_frames":
            rejected = stats.get("frames_rejected")
            garbage = stats.get("rx_bytes_discarded", {}).get("not_a_frame")
            ok = rejected == 0 and garbage == 0 and stats.get("commands_received", 0) > 0
            out.append(Step(name, "PASS" if ok else "FAIL",
                            f"simulator heard {stats.get('commands_received')} commands from the SDK, "
                            f"{rejected} frames rejected, {garbage} bytes outside frames"))
            continue
        if by_design and name != "version":
            detail = f"{refusal}; {activation.get('detail', '')}" if name == "activation" else refusal
            out.append(Step(name, "SKIP", detail))
            continue
        if ev is None:
            if name in ("movement", "release_control") and refused:
                out.append(Step(name, "SKIP", "control was not obtained"))
            else:
                out.append(Step(name, "FAIL", blocked))
            continue
        ok, detail = ev["ok"], ev["detail"]
        if name == "version":
            got_id = ev.get("version_id", next((t.split("version ID = ", 1)[1] for t in s.logs
                                                if "version ID = " in t), None))
            got_name = ev.get("version_name", next((t.split("version name = ", 1)[1] for t in s.logs
                                                    if "version name = " in t), None))
            want_name = VERSION_NAME[profile].decode()
            want_id = VERSION_ID.decode() if has_version_id(profile) else None   # FW 2.3's reply has no ID
            if "fw_version" in ev:
                # 3.2.1 and 3.2.2 keep the name to themselves: their getters give the ID and the
                # hardware and firmware they parsed out of the name ("... M100-03.01.01.00")
                want_hw = want_name.rsplit(" ", 1)[-1].split("-", 1)[0]
                want_fw = load_profile(profile).sdk_version
                got_hw, got_fw = ev.get("hw_version"), ev["fw_version"]
                ok = ok and got_id == want_id and got_hw == want_hw and got_fw == want_fw
                detail = (f"SDK read ID {got_id!r} (sent {want_id!r}), hardware {got_hw!r} and firmware "
                          f"{_dotted(got_fw)} from the name {want_name!r} (want {want_hw!r}, "
                          f"{_dotted(want_fw)}, the profile's SDK version); {detail}")
            else:
                ok = ok and got_id == want_id and got_name == want_name
                detail = (f"SDK read ID {got_id!r} (sent {want_id!r}), name {got_name!r} (sent {want_name!r}); "
                          f"{detail}")
        elif name == "broadcast":
            ok = ok and cmp.compared >= frames and cmp.mismatched_frames == 0 and cmp.unknown == 0 and cmp.lost == 0
            detail = (f"{cmp.compared} frames compared field by field ({cmp.fields} fields; items "
                      f"{', '.join(sorted(cmp.items))}): {cmp.mismatched_frames} with a mismatch, "
                      f"{cmp.lost} lost, {cmp.unknown} unknown; driver: {detail}")
            if cmp.unexposed:
                detail += f"; not readable through the SDK's public API: {', '.join(sorted(cmp.unexposed))}"
            if cmp.mismatches:
                detail += "; first: " + " | ".join(cmp.mismatches)
        elif name == "movement":
            sent = ev.get("sent", 0)
            heard, enc = stats.get("movement_commands"), stats.get("movement_commands_encrypted")
            want_enc = sent if encrypt and can_encrypt else 0
            ok = ok and heard == sent and enc == want_enc
            detail = f"{detail}; simulator received {heard}, {enc} of them encrypted"
            if encrypt and not can_encrypt:
                detail += " (the release cannot encrypt: its commands go out plain by design)"
            if "mode" in ev and "flag" in ev:
                want_mode = expected_mode(ev["flag"])
                ok = ok and ev["mode"] == want_mode
                if ev["mode"] != want_mode:
                    detail += f"; mode {ev['mode']} read, {want_mode} broadcast for flag 0x{ev['flag']:02X}"
        if name in WIRE and acks is not None:
            wire_ok, text, _ = wire_check(name, ev, acks)
            ok = ok and wire_ok
            detail = f"{detail}; {text}"
        out.append(Step(name, "PASS" if ok else "FAIL", detail))
    return out


def run_profile(exe: Path, profile: str, args: argparse.Namespace, work: Path, tree: SdkTree | None = None) -> list[Step]:
    prof = load_profile(profile)
    baud = getattr(args, "baud", BAUD)
    encrypt = getattr(args, "encrypt", False)
    unknown_rate = tree.bauds.get(baud, "") if tree else ""
    if unknown_rate:
        return [Step(name, "SKIP", unknown_rate) for name in STEPS]
    restore = [HZ_CODE[prof.default_rates_hz[item]] for item in prof.flag_bits]
    env = dict(os.environ, **{KEY_ENV: secrets.token_hex(32)})
    log, stats_file = work / f"{profile}.broadcast.jsonl", work / f"{profile}.sim-stats.json"
    ack_log = work / f"{profile}.acks.jsonl"
    sim_args = ["--profile", profile, "--hold", "--app-id", str(args.app_id), "--key-env", KEY_ENV,
                "--baud", str(baud), "--log-broadcast", str(log), "--log-acks", str(ack_log),
                "--stats", str(stats_file)] + (["--encrypt"] if encrypt else [])
    through_tap = getattr(args, "through_tap", False)
    tap_json = work / f"{profile}.tap.json"
    with spawned(*sim_args, env=env, new_session=True) as (port, sim):
        with (tapped(port, profile, baud, work, env) if through_tap else contextlib.nullcontext((port, None))) as (
                host_port, _):
            session = drive(exe, sim, host_port, profile, args.app_id, args.frames, args.moves, restore, env,
                            timeout=args.frames / 50 * 3 + args.moves / 50 * 3 + 30, baud=baud, encrypt=encrypt)
    (work / f"{profile}.driver.jsonl").write_text(
        "".join(json.dumps(e) + "\n" for e in [*session.steps.values(), *session.broadcasts])
        + "".join(json.dumps({"ev": "log", "text": t}) + "\n" for t in session.logs))
    stats = json.loads(stats_file.read_text()) if stats_file.is_file() else {}
    refusal = tree.refusals.get(profile) if tree else None
    steps = _verdicts(profile, session, compare(profile, log, session.broadcasts, session.exposed), stats,
                      args.frames, read_acks(ack_log), refusal, encrypt)
    if through_tap:
        steps.append(tap_step(tap_json, session))
    return steps


def tapped(fc_port: str, profile: str, baud: int, work: Path, env: dict):
    """`osdkc tap` between the simulator at `fc_port` and the SDK: yields
    (the pseudo-terminal the SDK opens instead of the simulator's, the tap's
    process). The tap is stopped on the way out and leaves its capture and
    summary in `work`."""
    return spawned("--fc", fc_port, "--profile", profile, "--baud", str(baud), "--key-env", KEY_ENV, "-q",
                   "--capture", str(work / f"{profile}.tap.pcapng"),
                   "--summary-json", str(work / f"{profile}.tap.json"), env=env, new_session=True, command="tap")


def tap_step(summary: Path, s: Session) -> Step:
    """The tap's verdict on the SDK's session: nothing failed, and it saw the
    movement commands the driver says it sent, with the driver's mode byte."""
    if not summary.is_file():
        return Step("tap", "FAIL", "the tap wrote no summary")
    tap = json.loads(summary.read_text())
    bad = [f"{c['id']}: {c['message']}" for c in tap["checks"] if c["status"] in ("fail", "error")]
    host = tap["host"]
    ev = s.steps.get("movement") or {}
    cadence = next((c["message"] for c in tap["checks"] if c["id"] == "host.cadence"), "")
    detail = f"tap {tap['summary']}; {cadence}; mode bytes {host['mode bytes']}"
    ok = not bad
    if "sent" in ev and host["movement commands"] != ev["sent"]:
        ok = False
        detail += f"; the tap saw {host['movement commands']} movement commands, the driver sent {ev['sent']}"
    if "flag" in ev and set(host["mode bytes"]) != {f"{ev['flag']:#04x}"}:
        ok = False
        detail += f"; the driver's mode byte is {ev['flag']:#04x}"
    if bad:
        detail += "; failed: " + " | ".join(bad[:3])
    return Step("tap", "PASS" if ok else "FAIL", detail)


# --------------------------------------------------------------------------
# Command line


def add_arguments(ap: argparse.ArgumentParser, profiles: tuple[str, ...]) -> None:
    ap.add_argument("--osdk", metavar="DIR", default=os.environ.get("OSDK_SRC"),
                    help=f"a checkout of DJI's Onboard-SDK ({SUPPORTED}); default $OSDK_SRC")
    ap.add_argument("--profile", action="append", choices=profiles,
                    help="profile to run (repeatable; default every profile the SDK supports)")
    ap.add_argument("--out", metavar="DIR", help="build directory (default ~/.cache/osdkc/sdk-host/VERSION)")
    ap.add_argument("--log-dir", metavar="DIR",
                    help="keep the simulator's broadcast and ACK logs, its counters and the driver's output here")
    ap.add_argument("--frames", type=positive_int, default=500, help="broadcast frames to compare at 50 Hz (default 500)")
    ap.add_argument("--moves", type=positive_int, default=150, help="movement control commands to send (default 150)")
    ap.add_argument("--app-id", type=uint32, default=DEFAULT_APP_ID, help="app id to activate with")
    ap.add_argument("--baud", type=baud_rate, choices=BAUDS, default=BAUD,
                    help="line speed of the host and the simulator (default 230400); a rate the release's Linux "
                         "serial driver does not set is reported SKIP with the place in its source")
    ap.add_argument("--encrypt", action="store_true",
                    help="the host encrypts its commands after activation and the simulator encrypts every frame "
                         "but the version and activation ACKs (both have the app key)")
    ap.add_argument("--through-tap", action="store_true",
                    help="put `osdkc tap` between the SDK and the simulator: the session must still succeed, and "
                         "the tap's report (step `tap`) must find nothing wrong and see the SDK's movement commands")


def _print_steps(profile: str, steps: list[Step]) -> None:
    print(profile)
    for st in steps:
        print(f"  {st.verdict:4}  {st.name:18} {st.detail}")
    sys.stdout.flush()


def run_host_test(args: argparse.Namespace) -> int:
    if not args.osdk:
        raise UsageError("sdk host-test needs --osdk DIR (a checkout of DJI's Onboard-SDK) or OSDK_SRC")
    tree = detect(Path(args.osdk).expanduser().resolve())
    wanted = tuple(dict.fromkeys(args.profile)) if args.profile else tree.profiles
    for p in wanted:
        if p not in tree.profiles:
            raise UsageError(f"--profile {p}: the SDK {tree.version} host test supports {', '.join(tree.profiles)}")
    out = Path(args.out).expanduser() if args.out else Path.home() / ".cache" / "osdkc" / "sdk-host" / tree.version
    exe = build(tree, out)
    print(f"osdkc sdk host-test: DJI Onboard-SDK {tree.version} from {tree.root}, driver {exe}, "
          f"{args.baud} baud, {'encrypted' if args.encrypt else 'plain'}")
    failed = total = flagged = 0
    with tempfile.TemporaryDirectory(prefix="osdkc-host-") as tmp:
        work = Path(args.log_dir) if args.log_dir else Path(tmp)
        work.mkdir(parents=True, exist_ok=True)
        for profile in wanted:
            steps = run_profile(exe, profile, args, work, tree)
            _print_steps(profile, steps)
            total += len(steps)
            failed += sum(st.verdict == "FAIL" for st in steps)
            flagged += sum(FLAG in st.detail for st in steps)
    print(f"{len(wanted)} profile(s), {total} steps: {total - failed} passed or skipped, {failed} failed"
          + (f"; {flagged} SDK verdict(s) the wire does not support" if flagged else ""))
    return 1 if failed else 0
