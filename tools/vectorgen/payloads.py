"""payloads.json: decode_payload of every command and ACK value of
osdk_payload.ksy other than the broadcast (valid, short, long), and of
commands the spec does not describe."""
from __future__ import annotations

import struct
from typing import Any

from osdk_conformance._construct.enums import FREQUENCY_CODE
from osdk_conformance._construct.payload import VERSION_ID_SIZE, has_version_id

from osdk_conformance.core.rules import default_rules, profile as rules_profile

from .builder import PROFILES, R, Suite
from .scalars import enum, le16

VERSION_ID = b"01.00.0100".ljust(VERSION_ID_SIZE, b"\x00")
"""10 characters and a NUL: the ID that DJI's fixed and scanning readers read alike (ERRATA E30)."""
BUNDLE_ID = b"12345678901234567890123456789012"
CONTROL_ACK_NAMES = {0: "rc_not_in_f_mode", 1: "released", 2: "obtained", 3: "obtain_in_progress",
                     4: "release_in_progress", 0xC9: "in_ioc_mode"}
"""The control ACK codes with a name, hand-written from ERRATA E26."""


class PayloadCases:
    """The cases of one profile: ids under payloads.<profile>, category from the name's first part."""

    def __init__(self, s: Suite, profile: str) -> None:
        self.s = s
        self.profile = profile

    def add(self, name: str, cmd_set: int, cmd_id: int, is_ack: bool, data: bytes, comment: str,
            flags: list[str], **kw: Any) -> None:
        self.s.add("decode_payload", self.profile, f"payloads.{self.profile}.{name}", "payload." + name.split(".")[0],
                   comment, {"hex": data.hex(), "cmd_set": cmd_set, "cmd_id": cmd_id, "is_ack": is_ack}, flags, **kw)

    def lengths(self, name: str, cmd_set: int, cmd_id: int, is_ack: bool, good: bytes, rule: str,
                errata: list[str]) -> None:
        """A good value one byte short and one byte long."""
        self.add(f"{name}.short_by_1", cmd_set, cmd_id, is_ack, good[:-1], f"{name}, one byte short: truncated_payload",
                 R(rule, "payload.truncated") + errata, error="truncated_payload")
        self.add(f"{name}.trailing", cmd_set, cmd_id, is_ack, good + b"\x00", f"{name}, one byte too many: length_mismatch",
                 R(rule, "payload.trailing") + errata, error="length_mismatch")


def gen_payloads() -> Suite:
    s = Suite("payloads", "decode_payload of every other command and ACK value of osdk_payload.ksy (valid, short, "
                          "long) and of commands the spec does not describe.", seed=404)
    for profile in PROFILES:
        c = PayloadCases(s, profile)
        add_version_query(c)
        add_version_ack(c)
        add_activation(c)
        add_frequencies(c)
        add_control_authority(c)
        add_movement_and_lost_control(c)
        add_unknown_commands(c, s)
    return s


def add_version_query(c: PayloadCases) -> None:
    for b in (0x00, 0x01, 0xFF):
        c.add(f"version_query.0x{b:02x}", 0, 0, False, bytes([b]), f"get version, arbitrary byte 0x{b:02x}",
              R("payload.version_query"))
    c.add("version_query.empty", 0, 0, False, b"", "get version with no byte: truncated_payload",
          R("payload.version_query", "payload.truncated"), error="truncated_payload")
    c.add("version_query.two_bytes", 0, 0, False, b"\x00\x00", "get version with two bytes: length_mismatch",
          R("payload.version_query", "payload.trailing"), error="length_mismatch")


def version_name(profile: str) -> bytes:
    """The 32-byte name field with the profile's name in DJI's form (rules.yaml)."""
    return rules_profile(profile).version_name.encode().ljust(32, b"\x00")


def add_version_ack(c: PayloadCases) -> None:
    """The version ACK in the profile's layout (an 11-byte version ID between
    the CRC and the name, or none: ERRATA E30), and in the other layout."""
    id_bytes = VERSION_ID if has_version_id(c.profile) else b""
    name = version_name(c.profile)
    for code, cname in ((0x0000, "activated"), (0xFF01, "not_activated"), (0x0001, None)):
        data = struct.pack("<HI", code, 0x12345678) + id_bytes + name
        kw = {}
        if code == 0x0000:
            kw["expected"] = {"value": {"ack_code": enum(0, "activated"), "version_crc": 0x12345678,
                                        **({"version_id": id_bytes.hex()} if id_bytes else {}),
                                        "version_name": name.hex()}}
        c.add(f"version_ack.0x{code:04x}", 0, 0, True, data,
              f"version ACK, code 0x{code:04x} ({cname or 'no name'}), CRC 0x12345678, "
              + ("an 11-byte version ID of 10 characters and a NUL, " if id_bytes else "no version ID (FW 2.3), ")
              + f"the 32-byte name {name.rstrip(bytes(1)).decode()!r}, NUL-padded" + ("; hand-written" if kw else ""),
              R("payload.version_ack") + ["E30"] + (R("enums.unnamed") if cname is None else []), **kw)
    c.lengths("version_ack", 0, 0, True, struct.pack("<HI", 0, 1) + id_bytes + name, "payload.version_ack",
              ["E30"])
    if id_bytes:
        c.add("version_ack.fw2_3_layout", 0, 0, True, struct.pack("<HI", 0, 1) + name,
              "the FW 2.3 version ACK (no version ID, 38 bytes) in a FW 3.1 profile: 11 bytes short, "
              "truncated_payload", R("payload.version_ack", "payload.truncated") + ["E30"], error="truncated_payload")
    else:
        c.add("version_ack.fw3_1_layout", 0, 0, True, struct.pack("<HI", 0, 1) + VERSION_ID + name,
              "the FW 3.1 version ACK (11-byte version ID, 49 bytes) in the FW 2.3 profile: 11 bytes too many, "
              "length_mismatch", R("payload.version_ack", "payload.trailing") + ["E30"], error="length_mismatch")


def add_activation(c: PayloadCases) -> None:
    """The activation request with the SDK version of each profile (hand-written
    expectation for the profile's own), the 40-byte form without the API level, and the ACK codes."""
    for prof_name in PROFILES:
        version = rules_profile(prof_name).sdk_version
        data = struct.pack("<III", 1012345, 2, version) + BUNDLE_ID
        kw = {}
        if prof_name == c.profile:
            kw["expected"] = {"value": {"app_id": 1012345, "api_level": 2, "sdk_version": version,
                                        "bundle_id": BUNDLE_ID.hex()}}
        c.add(f"activation_request.{prof_name}", 0, 1, False, data,
              f"activation with app id 1012345, API level 2 at offset 4, SDK version 0x{version:08x} ({prof_name}), "
              f"32-byte bundle id (44 bytes)" + ("; hand-written" if kw else ""),
              R("payload.activation_request") + ["E12", "E31"], **kw)
    data40 = struct.pack("<II", 1012345, 0x03010A00) + b"1" * 32
    c.add("activation_request.forty_bytes", 0, 1, False, data40,
          "the 40-byte activation of a client that left out the API level word: truncated_payload",
          R("payload.activation_request", "payload.truncated") + ["E12"], error="truncated_payload")
    c.lengths("activation_request", 0, 1, False, struct.pack("<III", 1, 2, 3) + bytes(32), "payload.activation_request",
              ["E12"])
    for code in range(0, 10):
        c.add(f"activation_ack.{code}", 0, 1, True, le16(code), f"activation ACK code {code}",
              R("payload.activation_ack") + (R("enums.unnamed") if code > 8 else []) + ["E12"])
    c.lengths("activation_ack", 0, 1, True, le16(0), "payload.activation_ack", [])


def frequency_code(hz: int) -> int:
    """The set-frequency code of a rate (rules.yaml frequencies)."""
    return next(code for code in FREQUENCY_CODE.values() if default_rules().frequency_hz(code) == hz)


def add_frequencies(c: PayloadCases) -> None:
    codes = list(range(8)) + [8, 255] + [0] * 6
    c.add("frequency_request.all_codes", 0, 0x10, False, bytes(codes),
          "set frequency with codes 0..7, then 8 and 255 (no name), then zeros; 6 and 7 are later-SDK codes",
          R("payload.frequency_request", "enums.unnamed") + ["E11"])
    rp = rules_profile(c.profile)
    defaults = [frequency_code(rp.default_rates_hz[i]) for i in rp.flag_bits]
    data = bytes(defaults + [0] * (16 - len(defaults)))
    c.add("frequency_request.default_rates", 0, 0x10, False, data,
          f"set frequency to the default rates of {c.profile} (ERRATA E10), reserved tail zero",
          R("payload.frequency_request") + ["E10", "E11", "E31"])
    c.add("frequency_request.reserved_tail", 0, 0x10, False, bytes([5] * 12 + [1, 2, 3, 4]),
          "set frequency, keep everything, non-zero tail bytes: reported by rules, decoded here",
          R("payload.frequency_request") + ["E11"])
    c.lengths("frequency_request", 0, 0x10, False, bytes(16), "payload.frequency_request", ["E11"])
    for code in (0, 1, 2):
        c.add(f"frequency_ack.{code}", 0, 0x10, True, le16(code), f"set frequency ACK {code}",
              R("payload.frequency_ack") + (R("enums.unnamed") if code > 1 else []))
    c.lengths("frequency_ack", 0, 0x10, True, le16(0), "payload.frequency_ack", [])


def add_control_authority(c: PayloadCases) -> None:
    for b in (0, 1, 2):
        c.add(f"control_request.{b}", 1, 0, False, bytes([b]), f"control request {b}",
              R("payload.control_request") + (R("enums.unnamed") if b > 1 else ["E31"]))
    c.lengths("control_request", 1, 0, False, b"\x01", "payload.control_request", [])
    for code in (0, 1, 2, 3, 4, 5, 6, 0xC9, 0xFFFF):
        name = CONTROL_ACK_NAMES.get(code)
        c.add(f"control_ack.0x{code:04x}", 1, 0, True, le16(code),
              f"control ACK 0x{code:04x}: {name or 'no name (5 and 6 are SDK-local, never on the wire)'}"
              "; hand-written", R("payload.control_ack") + ["E26", "E31"]
              + (R("enums.unnamed") if code not in CONTROL_ACK_NAMES else []),
              expected={"value": {"ack_code": enum(code, name)}})
    c.lengths("control_ack", 1, 0, True, le16(2), "payload.control_ack", ["E26"])


def add_movement_and_lost_control(c: PayloadCases) -> None:
    # movement control as a payload: any mode byte parses
    for byte in (0x00, 0x4B, 0xFF):
        data = bytes([byte]) + struct.pack("<ffff", 0.5, -0.5, 10.0, 90.0)
        c.add(f"movement_control.0x{byte:02x}", 1, 3, False, data,
              f"movement control value with mode byte 0x{byte:02x}: the layout parses any byte (unnamed fields "
              f"have name null); check_movement_control judges it", R("payload.movement_control", "control.fields")
              + (R("enums.unnamed") if byte == 0xFF else []) + (["E31"] if byte == 0x4B else []))
    c.lengths("movement_control", 1, 3, False, bytes(17), "payload.movement_control", [])
    # lost control and its ACK (E24)
    c.add("lost_control.0x04", 2, 1, False, b"\x04", "lost control authority, reason 0x04",
          R("payload.lost_control") + ["E31"])
    c.lengths("lost_control", 2, 1, False, b"\x04", "payload.lost_control", [])
    c.add("lost_control_ack.zero", 2, 1, True, b"\x00\x00",
          "the device's 2-byte zero answer to a lost-control push in session > 0",
          R("payload.lost_control_ack") + ["E24", "E31"])
    c.lengths("lost_control_ack", 2, 1, True, b"\x00\x00", "payload.lost_control_ack", ["E24"])


def add_unknown_commands(c: PayloadCases, s: Suite) -> None:
    """Commands and ACKs without a layout: the value stays raw."""
    for (cs, ci, ack, n) in ((0x00, 0x02, False, 5), (0x01, 0x01, False, 0), (0x01, 0x03, True, 2),
                             (0x02, 0x00, True, 3), (0x03, 0x00, False, 7), (0xFF, 0xFF, True, 1)):
        data = bytes(s.rng.getrandbits(8) for _ in range(n))
        what = {(0x01, 0x03, True): "ACK of movement control (it has none)",
                (0x02, 0x00, True): "ACK of the broadcast (it has none)"}.get((cs, ci, ack),
                                                                               "a command the spec does not describe")
        c.add(f"unknown.0x{cs:02x}{ci:02x}{'.ack' if ack else ''}", cs, ci, ack, data,
              f"set 0x{cs:02x} id 0x{ci:02x}{' ACK' if ack else ''}: {what}; the {n}-byte value stays raw",
              R("payload.unknown"), expected={"value": {"raw": data.hex()}})
