"""The "protocol" family of DJI Onboard-SDK releases (3.3 to 3.9): the frame
layer is osdk-core/protocol (OpenProtocol on ProtocolBase, dji_aes, the CRC
tables of dji_crc.hpp), the broadcast unpacker osdk-core/api DataBroadcast.

The adapter (conformance/sdk_testee/protocol/) follows the ProtocolBase
pipeline that 3.4 introduced; 3.3.x keeps the older single-class Protocol
receiver (its CRC tables in dji_open_protocol.hpp), which the same adapter
drives on a second code path (OKIT_SDK_PROTOCOL_33) with stubs33.cpp and the
platform stand-ins of platform33/.
"""
from __future__ import annotations

import re
from pathlib import Path

from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.paths import ROOT
from osdk_conformance.sdk.family import Recipe

ADAPTER_DIR = ROOT / "conformance" / "sdk_testee" / "protocol"
SELECT_SHIM = ADAPTER_DIR / "platform_select"
MARKERS = ("osdk-core/protocol/inc/dji_open_protocol.hpp",)   # what detect() looks for first

# The SDK's own files the testee needs: the receive pipeline, AES and the
# encoder (protocol/), the serial-driver and thread base classes and the
# session memory manager it allocates from (hal/), the broadcast unpacker
# and what it links against (api/). Paths below osdk-core/.
SDK_SOURCES = (
    "protocol/src/dji_open_protocol.cpp",
    "protocol/src/dji_protocol_base.cpp",
    "protocol/src/dji_aes.cpp",
    "hal/src/dji_hard_driver.cpp",
    "hal/src/dji_memory.cpp",
    "hal/src/dji_thread_manager.cpp",
    "api/src/dji_broadcast.cpp",
    "api/src/dji_version.cpp",
    "api/src/dji_ack.cpp",
    "api/src/dji_error.cpp",
    "api/src/dji_command.cpp",
)
INCLUDE_DIRS = ("api/inc", "protocol/inc", "hal/inc", "utility/inc", "platform/linux/inc")
# Headers the adapter itself names (a tree without them is not buildable).
ADAPTER_HEADERS = (
    "platform/linux/inc/linux_serial_device.hpp",
    "hal/inc/dji_log.hpp",
    "protocol/inc/dji_open_protocol.hpp",
    "protocol/inc/dji_protocol_base.hpp",
    "protocol/inc/dji_crc.hpp",
    "hal/inc/dji_platform_manager.hpp",
    "api/inc/dji_broadcast.hpp",
    "api/inc/dji_telemetry.hpp",
    "api/inc/dji_vehicle.hpp",
)

# 3.3.x: the same layers in fewer files. Its Linux platform layer is
# replaced as a whole (platform33/ comes first on the include path and the
# SDK's platform/linux/inc is left off: Protocol constructs its serial device
# and thread handle by those class names, and the SDK's serial header does not
# compile against current glibc); dji_log.cpp is replaced by the log stub.
BASE_SOURCE = "protocol/src/dji_protocol_base.cpp"   # ProtocolBase, new in 3.4
SDK_SOURCES_33 = tuple(rel for rel in SDK_SOURCES if rel != BASE_SOURCE)
INCLUDE_DIRS_33 = tuple(d for d in INCLUDE_DIRS if not d.startswith("platform/"))
ADAPTER_HEADERS_33 = (
    "protocol/inc/dji_open_protocol.hpp",
    "api/inc/dji_type.hpp",
    "api/inc/dji_broadcast.hpp",
    "api/inc/dji_telemetry.hpp",
    "api/inc/dji_vehicle.hpp",
)
# API_TRACE_DATA switches on the SDK's own frame trace (printFrame at the
# entry of Protocol::appHandler): 3.3's pipeline steps are not virtual, and
# that trace is where the adapter sees a frame delivered. It only reads.
DEFINES_33 = ("OKIT_SDK_PROTOCOL_33", "API_TRACE_DATA")

# How each error class is read off what the SDK did; the SDK itself reports
# none (its receiver drops bytes silently and raises no error).
DERIVATIONS = {
    "bad_sof": "decode_frame: the first byte is not 0xAA, the first condition of OpenProtocol::verifyHead, "
               "and no frame starting at offset 0 reached OpenProtocol::callApp",
    "bad_crc16": "decode_frame: OpenProtocol::verifyHead rejected the header at offset 0 (it shifts one byte) and "
                 "the SDK's own crcHeadCheck over those 12 bytes is not 0",
    "bad_version": "decode_frame: verifyHead rejected the header at offset 0, its CRC-16 checks out and the SDK's "
                   "OpenHeader.version is not 0",
    "reserved_bits": "decode_frame: verifyHead rejected the header at offset 0, CRC-16 and version are fine and "
                     "OpenHeader.reserved0 or reserved1 is not 0",
    "impossible_length": "decode_frame: verifyHead rejected the header at offset 0 and only its length condition "
                         "(length < MAX_RECV_LEN) remains; encode_frame: OpenProtocol::encrypt returned 0 "
                         "(its own data-size limit)",
    "bad_crc32": "decode_frame: OpenProtocol::verifyData ran on the frame at offset 0 and did not reach callApp "
                 "(its crcTailCheck over the LEN bytes is not 0)",
    "truncated_frame": "decode_frame: no bytes, fewer than 12 bytes, or a header verifyHead accepted while the "
                       "receiver still waits for the rest of the frame (it has no other verdict, so a LEN it can "
                       "never reach is reported the same way)",
}

# 3.3.x: the same rejections, seen differently (no virtual step to watch).
DERIVATIONS_33 = {
    "bad_sof": "decode_frame: the first byte is not 0xAA, the first condition of Protocol::verifyHead, and no "
               "frame starting at offset 0 reached the SDK's frame trace (printFrame at the entry of appHandler, "
               "which callApp reaches for every frame it delivers)",
    "bad_crc16": "decode_frame: the bytes arrive as two reads (the first 12, then the rest); after the first, "
                 "Protocol::verifyHead had shifted one byte out (it holds 11, not 12) and the SDK's own "
                 "sdk_stream_crc16_calc over those 12 bytes is not 0",
    "bad_version": "decode_frame: verifyHead shifted the header at offset 0 out (as for bad_crc16), its CRC-16 "
                   "checks out and the SDK's Header.version is not 0",
    "reserved_bits": "decode_frame: verifyHead shifted the header at offset 0 out, CRC-16 and version are fine "
                     "and Header.reserved0 or reserved1 is not 0",
    "impossible_length": "encode_frame only: Protocol::encrypt returned 0 (its own data-size limit, more than "
                         "1024 data bytes); verifyHead's length condition (length < maxRecv, 1024) holds for "
                         "every 10-bit LEN, so decode_frame never answers it",
    "bad_crc32": "decode_frame: verifyHead kept the header at offset 0 (it holds all 12 bytes after the first "
                 "read), LEN is above 12, all LEN bytes arrived, and no frame from offset 0 reached the frame "
                 "trace: Protocol::verifyData, which checkStream runs when it holds LEN bytes, rejected it (its "
                 "sdk_stream_crc32_calc over the LEN bytes is not 0)",
    "truncated_frame": "decode_frame: no bytes, fewer than 12 bytes, or a header verifyHead kept while the "
                       "receiver still waits for the rest of the frame (it has no other verdict, so a LEN below "
                       "12, which it can never reach, is reported the same way)",
}

# decode_payload answers only the broadcast; decode_frame/decode_stream
# answer `unsupported` for a frame whose command value the SDK does not
# decode on receipt (conformance/sdk_testee/protocol/adapter.cpp).
OPERATIONS = ("decode_stream", "decode_frame", "decode_payload", "encode_frame")
# m100-fw3.1: DataBroadcast::unpackM100Data (M100 on FW 3.1.10.0);
# a3-fw3.1: DataBroadcast::unpackOldM600Data (legacy M600 on FW 3.2.15.62),
# which reads the 14-item FW 3.1 layout. No FW 2.3 code in these releases.
PROFILES = ("m100-fw3.1", "a3-fw3.1")

_HEADING = re.compile(r"^#\s*DJI Onboard SDK \(OSDK\)\s+(\d+\.\d+(?:\.\d+)?)\s*$", re.M)
_RELEASED = re.compile(r"\bOSDK (\d+\.\d+(?:\.\d+)?) (?:was|is) released\b")


# 4.0 and later ship their frame layer only as a prebuilt library
# (osdk-core/linker/<arch>/lib/libdji-linker.a): there is no source to build.
UNSUPPORTED_4X = ("{root}: Onboard-SDK {version} is not supported: its frame layer is the prebuilt library "
                  "osdk-core/linker/<arch>/lib/libdji-linker.a, no source to build; supported: 2.3, 3.1.7 to 3.2.2 "
                  "and 3.3 to 3.9")


def _core(root: Path) -> Path | None:
    for cand in (root / "osdk-core", root):
        if (cand / "protocol" / "inc" / "dji_open_protocol.hpp").is_file():
            return cand
    return None


def _version(root: Path, core: Path) -> str:
    """The release as the tree names it: the README heading, made exact by
    the first "OSDK x.y.z was released" sentence of the same series."""
    for readme in (root / "README.md", core.parent / "README.md"):
        if readme.is_file():
            text = readme.read_text(encoding="utf-8", errors="replace")
            m = _HEADING.search(text)
            if not m:
                continue
            version = m.group(1)
            for r in _RELEASED.finditer(text):
                if r.group(1).startswith(version + ".") or r.group(1) == version:
                    version = r.group(1) if r.group(1).count(".") > version.count(".") else version
                    break
            return version
    raise UsageError(f"{root}: the Onboard-SDK version is not in README.md (no '# DJI Onboard SDK (OSDK) x.y' heading)")


def detect(root: Path) -> Recipe | None:
    root = Path(root)
    core = _core(root)
    if core is None:
        if (root / "osdk-core" / "linker").is_dir():
            raise UsageError(UNSUPPORTED_4X.format(root=root, version="4.x"))
        return None
    version = _version(root, core)
    parts = tuple(int(p) for p in version.split("."))
    if parts[:2] < (3, 3):
        return None
    if parts[0] > 3:
        raise UsageError(UNSUPPORTED_4X.format(root=root, version=version))
    if not (core / BASE_SOURCE).is_file():
        if parts[:2] != (3, 3):
            raise UsageError(f"{root}: Onboard-SDK {version} tree lacks osdk-core/protocol/src/dji_protocol_base.cpp "
                             "(3.4 to 3.9 have it; only 3.3.x has the single-class Protocol receiver)")
        return _recipe_33(root, core, version)
    for rel in SDK_SOURCES + ADAPTER_HEADERS:
        if not (core / rel).is_file():
            raise UsageError(f"{root}: Onboard-SDK {version} tree lacks osdk-core/{rel}")
    serial_h = core / "platform" / "linux" / "inc" / "linux_serial_device.hpp"
    # 3.4 to 3.6: their serial header needs <sys/select.h> first (platform_select/)
    shim = () if "sys/select.h" in serial_h.read_text(encoding="utf-8", errors="replace") else (SELECT_SHIM,)
    return Recipe(
        family="protocol",
        version=version,
        profiles=PROFILES,
        operations=OPERATIONS,
        sdk_sources=tuple(core / rel for rel in SDK_SOURCES),
        # 3.8+ keep payload/flight module headers that dji_vehicle.hpp includes
        includes=shim + tuple(sorted(p for p in (core / "modules" / "inc").glob("*") if p.is_dir()))
        + tuple(core / rel for rel in INCLUDE_DIRS),
        adapter_sources=(ADAPTER_DIR / "adapter.cpp", ADAPTER_DIR / "stubs.cpp"),
        defines=(f'OKIT_SDK_VERSION="{version}"',) + _log_defines(core),
        cxx_std="c++11",
        derivations=dict(DERIVATIONS),
    )


def _log_defines(core: Path) -> tuple[str, ...]:
    """3.4.x's Log has no two-argument title(), which the log stub defines from 3.5 on."""
    log_h = (core / "hal" / "inc" / "dji_log.hpp").read_text(encoding="utf-8", errors="replace")
    return () if re.search(r"title\(int level, const char\* prefix\);", log_h) else ("OKIT_SDK_LOG_NO_SHORT_TITLE",)


def _recipe_33(root: Path, core: Path, version: str) -> Recipe:
    for rel in SDK_SOURCES_33 + ADAPTER_HEADERS_33:
        if not (core / rel).is_file():
            raise UsageError(f"{root}: Onboard-SDK {version} tree lacks osdk-core/{rel}")
    return Recipe(
        family="protocol",
        version=version,
        profiles=PROFILES,
        operations=OPERATIONS,
        sdk_sources=tuple(core / rel for rel in SDK_SOURCES_33),
        includes=(ADAPTER_DIR / "platform33",) + tuple(core / rel for rel in INCLUDE_DIRS_33),
        adapter_sources=(ADAPTER_DIR / "adapter.cpp", ADAPTER_DIR / "stubs33.cpp"),
        defines=(f'OKIT_SDK_VERSION="{version}"',) + DEFINES_33,
        cxx_std="c++11",
        derivations=dict(DERIVATIONS_33),
    )
