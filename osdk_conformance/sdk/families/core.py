"""The "core" family of DJI Onboard-SDK releases: 2.3, 3.1.7 and 3.1.8 (lib/
layout), 3.1.9, 3.2.0 and 3.2.2 (osdk-core/ layout), built on CoreAPI with
DJI_Codec (frame layer), DJI_Link (sessions), DJI_App (broadcast unpacker).

The adapter (conformance/sdk_testee/core/adapter.cpp) compiles DJI_Codec.cpp
inside itself, so that the frame layer's hand-over to appHandler can be
observed; every other source of the core is compiled unchanged.
"""
from __future__ import annotations

from pathlib import Path

from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.paths import ROOT
from osdk_conformance.sdk.family import Recipe

ADAPTER_DIR = ROOT / "conformance" / "sdk_testee" / "core"
LAYOUTS = ("osdk-core", "lib")          # 3.1.9 and later, then 3.1.8 and earlier
MARKERS = tuple(f"{d}/src/DJI_Codec.cpp" for d in LAYOUTS)   # what detect() looks for first
NEEDED = ("DJI_API.cpp", "DJI_App.cpp", "DJI_Codec.cpp", "DJI_Link.cpp", "DJI_Memory.cpp", "DJI_HardDriver.cpp")
SUPPORTED = {"2.3": 230, "3.1.7": 317, "3.1.8": 318, "3.1.9": 319, "3.2.0": 320, "3.2.2": 322}
PROFILE_BITS = {"m100-fw2.3": 1, "m100-fw3.1": 2, "a3-fw3.1": 4}   # adapter.cpp ALL_PROFILES order

# 2.3 has one broadcast layout, chosen at compile time by SDK_VERSION_2_3, which its
# DJI_Config.h defines; 3.1.x and 3.2.x choose by the aircraft's version at run time.
PROFILES = {230: ("m100-fw2.3",)}
DEFAULT_PROFILES = ("m100-fw2.3", "m100-fw3.1", "a3-fw3.1")

OPERATIONS = ("decode_stream", "decode_frame", "decode_payload", "encode_frame")

DERIVATIONS = {
    "frame events": "decode_stream reports the frames CoreAPI::callApp hands to appHandler, nothing else: "
                    "the SDK drops rejected bytes silently and has no error or garbage events. A frame's "
                    "offset is derived from the SDK's receive indices at hand-over (input bytes fed, minus "
                    "the replay area recvBuf[reuseIndex..], minus recvIndex); the adapter checks that the "
                    "input there is the frame the SDK checked. The SDK's appHandler still runs afterwards.",
    "value of a command": "only the broadcast (0x02/0x00) is unpacked by the SDK (CoreAPI::broadcast, run on "
                          "the delivered frame); a command the spec does not type is written as raw bytes; a "
                          "typed command the SDK only sends (version, activation, frequencies, control, "
                          "movement control, lost control) has no SDK decoder: the case is answered unsupported.",
    "ENC != 0": "the SDK decrypts DATA in place and shortens its length by PADDING before appHandler; the "
                "frame is reported with the wire LEN and the DATA bytes as received (the spec keeps ciphertext).",
    "bad_sof, bad_crc16, bad_version, reserved_bits": "decode_frame: the SDK's verifyHead rejects the 12 "
                                                     "header bytes with one combined condition (start byte, VER, "
                                                     "LEN below the receive buffer, RES0, RES1, CRC-16); the "
                                                     "class is its first failing part in the spec's order.",
    "truncated_frame": "decode_frame: fewer than 12 bytes (checkStream waits for a whole header, the start byte "
                       "is not looked at before), fewer than LEN bytes, or a LEN below 12 that verifyHead lets "
                       "through (checkStream then waits for recvIndex == LEN, which never comes).",
    "bad_crc32": "decode_frame: verifyData's CRC-32 over the LEN bytes (_SDK_CALC_CRC_TAIL) is not 0.",
    "length_mismatch, bad_session, bad_encryption, impossible_length (decoding)":
        "never answered by decoding: the SDK has no such check (bytes after LEN start the next frame).",
    "impossible_length (encode_frame)": "a value over PRO_PURE_DATA_MAX_SIZE (1007 bytes with set and id for "
                                        "a command): the limit CoreAPI::sendInterface and ackInterface apply "
                                        "before encrypt() frames it.",
    "bad_session (encode_frame)": "CoreAPI::ackInterface returns without sending anything for session 0.",
    "decode_payload": "broadcast only: the value is framed by the SDK's encrypt() as a session-0 command and "
                      "fed through the receive path to CoreAPI::broadcast; the items are read from its "
                      "BroadcastData (floats as bits). The SDK checks no length and no reserved flag bits.",
}


def _version(base: Path) -> str:
    """The release, from what the adapter depends on: the file headers' @version tags are
    not bumped reliably (3.1.8 says 3.1.7, 3.2.x say 3.1.9), so the code tells."""
    inc = base / "inc"
    if base.name == "lib":
        if not (inc / "DJICommonType.h").is_file():
            return "2.3"
        link = (base / "src" / "DJI_Link.cpp").read_text(errors="replace")
        return "3.1.8" if "notifyCaller" in link else "3.1.7"
    types = (inc / "DJI_Type.h").read_text(errors="replace") if (inc / "DJI_Type.h").is_file() else ""
    if "fwVersion" in types:
        return "3.2.2"
    version_h = (inc / "DJI_Version.h").read_text(errors="replace") if (inc / "DJI_Version.h").is_file() else ""
    return "3.2.0" if "versionA3_32" in version_h else "3.1.9"


def detect(root: Path) -> Recipe | None:
    base = next((root / d for d in LAYOUTS if (root / d / "inc" / "DJI_API.h").is_file()
                 and (root / d / "src" / "DJI_Codec.cpp").is_file()), None)
    if base is None:
        return None
    for name in NEEDED:
        if not (base / "src" / name).is_file():
            raise UsageError(f"--osdk {root}: missing {(base / 'src' / name).relative_to(root)}: "
                             "the CoreAPI frame layer cannot be built")
    version = _version(base)
    code = SUPPORTED.get(version)
    if code is None:
        raise UsageError(f"--osdk {root}: DJI Onboard-SDK {version} (CoreAPI layout) is "
                         f"not supported; supported: {', '.join(SUPPORTED)}")
    profiles = PROFILES.get(code, DEFAULT_PROFILES)
    bits = sum(PROFILE_BITS[p] for p in profiles)
    sources = tuple(sorted(p for p in (base / "src").glob("*.cpp") if p.name != "DJI_Codec.cpp"))
    return Recipe(
        family="core",
        version=version,
        profiles=profiles,
        operations=OPERATIONS,
        sdk_sources=sources,
        # src/ too: the adapter includes DJI_Codec.cpp
        includes=(base / "inc", base / "src"),
        adapter_sources=(ADAPTER_DIR / "adapter.cpp",),
        defines=(f"OSDKC_CORE_VERSION={code}", f"OSDKC_CORE_PROFILES={bits}"),
        cxx_std="c++11",
        derivations=dict(DERIVATIONS),
    )
