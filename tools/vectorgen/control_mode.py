"""control_mode.json: every control mode byte in every profile, classified."""
from __future__ import annotations

from osdk_conformance.core.rules import classify_control_mode

from .builder import PROFILES, R, Suite
from .scalars import enum

# The mode byte of the worked frame, hand-written from the seed's mode table.
FIELDS_0X4B = {"stable_mode": enum(1, "stable"), "horizontal_frame": enum(1, "body"),
               "yaw_logic": enum(1, "yaw_rate"), "vertical_logic": enum(0, "vert_vel"),
               "horizontal_logic": enum(1, "hori_vel")}
# 0x41 (velocity, yaw angle, bit 0 set): ERRATA E15 makes it invalid on FW 2.3 only.
FIELDS_0X41 = {"stable_mode": enum(1, "stable"), "horizontal_frame": enum(0, "ground"),
               "yaw_logic": enum(0, "yaw_ang"), "vertical_logic": enum(0, "vert_vel"),
               "horizontal_logic": enum(1, "hori_vel")}
HAND_WRITTEN = {
    ("a3-fw3.1", 0x4B): {"fields": FIELDS_0X4B, "classification": "documented", "combination": 4},
    ("m100-fw2.3", 0x4B): {"fields": FIELDS_0X4B, "classification": "documented", "combination": 4},
    ("m100-fw2.3", 0x41): {"fields": FIELDS_0X41, "classification": "invalid", "combination": None},
    ("m100-fw3.1", 0x41): {"fields": FIELDS_0X41, "classification": "documented", "combination": 3},
}
"""Expectations written from the seed mode table and ERRATA E15, compared with the reference's."""


def bit0_is_yaw_frame(c: dict) -> bool:
    """Whether bit 0 selects the yaw frame in the classified byte's profile
    (ERRATA E15: FW 2.3), rather than the stable flag."""
    return c["bit0"]["meaning"] == "yaw_frame"


def mode_flags(c: dict) -> list[str]:
    """The rules and errata a classified mode byte exercises."""
    flags = R("control.fields")
    raw, fields = c["raw"], c["fields"]
    if None in fields.values():
        flags += R("control.undefined", "enums.unnamed") + ["E16"]
    if None not in (fields["horizontal_logic"], fields["vertical_logic"], fields["yaw_logic"]):
        flags += R("control.combinations")
        if c["combination"] is None and c["classification"] == "undocumented":
            flags += ["E16"]
    if c["classification"] != "documented":
        flags += R("control.classification")
    if raw["stable_mode"]:
        flags += ["E15"]
    if bit0_is_yaw_frame(c) and raw["yaw_logic"] == 0 and raw["stable_mode"]:
        flags += R("control.bit0_fw2_3")
    if fields["horizontal_logic"] == "hori_pos" or fields["vertical_logic"] == "vert_thrust":
        flags += ["E29"]  # the spec's names (hori_pos, vert_thrust), not the seed's typos
    if fields["vertical_logic"] == "vert_thrust" and c["combination"]:
        flags += ["E05"]
    return flags


def gen_control_mode() -> Suite:
    s = Suite("control_mode", "Every control mode byte in every profile, classified (op classify_control_mode): "
                              "fields and enum names, documented / undocumented / later_firmware / invalid, "
                              "combination index.", seed=101)
    for profile in PROFILES:
        for byte in range(256):
            c = classify_control_mode(byte, profile)
            label = c["classification"] + (f", combination {c['combination']}" if c["combination"] else "")
            comment = f"mode byte 0x{byte:02x} ({byte:08b}) on {profile}: {label}; {c['reasons'][0]}"
            expected = HAND_WRITTEN.get((profile, byte))
            if expected:
                comment = "hand-written from the seed mode table and ERRATA E15: " + comment
            s.add("classify_control_mode", profile, f"control_mode.{profile}.0x{byte:02x}", "control.mode_byte",
                  comment, {"byte": byte}, mode_flags(c), expected=expected)
    return s
