"""Enumerations of the spec, by the names the .ksy files give them.

Each mapping is name -> value and is named after its ksy enum (in upper
case); the comment says which .ksy file declares it. They are written out
here rather than read from the .ksy files because this package is the
second, independent transcription of the spec that the differential tests
hold against the Kaitai one; tests/test_construct_spec.py checks that the
two transcriptions name the same values. The exception is the profiles:
they are defined once, in spec/rules.yaml, and both the ksy enum `profile`
and PROFILE / PROFILE_IDS here are made from that definition.
"""
from __future__ import annotations

from collections.abc import Mapping

from construct import EnumIntegerString

from osdk_conformance.core.rules import default_rules

# osdk_control_mode.ksy
HORIZONTAL_LOGIC = {"hori_atti_tilt_ang": 0, "hori_vel": 1, "hori_pos": 2}
VERTICAL_LOGIC = {"vert_vel": 0, "vert_pos": 1, "vert_thrust": 2}
YAW_LOGIC = {"yaw_ang": 0, "yaw_rate": 1}
HORIZONTAL_FRAME = {"ground": 0, "body": 1}
STABLE_MODE = {"non_stable": 0, "stable": 1}

# osdk_broadcast_items.ksy
CONTROL_DEVICE = {"rc": 0, "mobile_device": 1, "onboard_device": 2}
CUR_MOV_CONTROL_MODE = {
    "atti_stop": 0,
    **{
        f"horiz_{h}_vert_{v}_yaw_{y}": 1 + 6 * vi + 2 * hi + yi
        for vi, v in enumerate(("vel", "pos", "thr"))
        for hi, h in enumerate(("ang", "vel", "pos"))
        for yi, y in enumerate(("ang", "rate"))
    },
    "gps_atti_ctrl_cl_yaw_rate": 97,
    "gps_atti_ctrl_yaw_rate": 98,
    "atti_ctrl_yaw_rate": 99,
    "atti_ctrl_stop": 100,
}

# osdk_payload.ksy (its enum `profile` is generated from rules.yaml profiles)
PROFILE = {name: value for value, name in default_rules().enum("profile").items()}
VERSION_ACK = {"activated": 0x0000, "not_activated": 0xFF01}
ACTIVATION_RESULT = {
    "success": 0,
    "invalid_parameters": 1,
    "cannot_recognize_encrypted_package": 2,
    "new_app_id": 3,
    "no_response_from_app": 4,
    "no_internet": 5,
    "server_rejected": 6,
    "level_insufficient": 7,
    "wrong_sdk_version": 8,
}
FREQUENCY_CODE = {
    "hz_0": 0, "hz_1": 1, "hz_10": 2, "hz_50": 3, "hz_100": 4, "keep": 5, "hz_200": 6, "hz_400": 7,
}
FREQUENCY_ACK = {"success": 0, "parameter_error": 1}
CONTROL_REQUEST_CODE = {"release": 0, "obtain": 1}
CONTROL_ACK = {
    "rc_not_in_f_mode": 0,
    "released": 1,
    "obtained": 2,
    "obtain_in_progress": 3,
    "release_in_progress": 4,
    "in_ioc_mode": 0xC9,
}

# osdk_frame.ksy
ENCRYPTION = {"plain": 0, "aes256": 1}
COMMAND_SET = {"activation": 0x00, "control": 0x01, "push": 0x02}

# Profile ids as the CLI, rules.yaml and the vectors spell them (docs/NAMING.md).
PROFILE_IDS = {name: default_rules().profile(name).value for name in default_rules().profile_names}

# Every enum above by its ksy file and ksy name, for the consistency test.
BY_KSY = {
    ("osdk_control_mode", "horizontal_logic"): HORIZONTAL_LOGIC,
    ("osdk_control_mode", "vertical_logic"): VERTICAL_LOGIC,
    ("osdk_control_mode", "yaw_logic"): YAW_LOGIC,
    ("osdk_control_mode", "horizontal_frame"): HORIZONTAL_FRAME,
    ("osdk_control_mode", "stable_mode"): STABLE_MODE,
    ("osdk_broadcast_items", "control_device"): CONTROL_DEVICE,
    ("osdk_broadcast_items", "cur_mov_control_mode"): CUR_MOV_CONTROL_MODE,
    ("osdk_payload", "profile"): PROFILE,
    ("osdk_payload", "version_ack"): VERSION_ACK,
    ("osdk_payload", "activation_result"): ACTIVATION_RESULT,
    ("osdk_payload", "frequency_code"): FREQUENCY_CODE,
    ("osdk_payload", "frequency_ack"): FREQUENCY_ACK,
    ("osdk_payload", "control_request_code"): CONTROL_REQUEST_CODE,
    ("osdk_payload", "control_ack"): CONTROL_ACK,
    ("osdk_frame", "encryption"): ENCRYPTION,
    ("osdk_frame", "command_set"): COMMAND_SET,
}


def enum_int(value, mapping: Mapping[str, int]) -> int:
    """The integer behind an enum field's value, whichever form it has: what
    Construct parsed (a named or unnamed enum value), a name, or an int."""
    if isinstance(value, EnumIntegerString):
        return int(value)  # EnumIntegerString.__int__ gives the parsed value
    if isinstance(value, str):
        return mapping[value]
    return int(value)


def profile_value(profile) -> int:
    """A wire profile as the integer of the ksy `profile` enum; accepts that
    integer, the ksy name (`a3_fw3_1`) or the profile id (`a3-fw3.1`)."""
    if isinstance(profile, str) and not isinstance(profile, EnumIntegerString):
        if profile in PROFILE_IDS:
            return PROFILE_IDS[profile]
        if profile in PROFILE:
            return PROFILE[profile]
        raise ValueError(f"unknown profile {profile!r} (known: {', '.join(PROFILE_IDS)})")
    return enum_int(profile, PROFILE)
