"""broadcast.json, the ERRATA decisions about items: hand-written values
(the field order of E01 and E13, the enum of E02, ...) and each variant an
item has, sent to the profile that uses it and to one that does not.

Which variant a profile uses comes from the layout (broadcast_values);
the profiles named here are those an erratum is about."""
from __future__ import annotations

import struct

from osdk_conformance.core.rules import profile as rules_profile

from .broadcast_values import bc_input, broadcast_flags_model, describe, has_field, item_fields, other_form, pack
from .builder import R, Suite
from .scalars import enum, f32, le16
from .wire import WORKED_BROADCAST_PROFILE, WORKED_BROADCAST_VALUE

OP = "decode_payload"

DOC_2X_PROFILE = "m100-fw2.3"
"""The profile the 2.x protocol document describes, whose size table is wrong (ERRATA E27)."""

LATER_FIRMWARE_BASE = "a3-fw3.1"
"""The profile whose flag bits later firmware keeps while widening items (ERRATA E20)."""

TIME_STAMP = {"time": 400, "nano_time": 2_500_000, "sync_flag": 1}
GIMBAL_ANGLES = {"roll": f32(1.5), "pitch": f32(-90.0), "yaw": f32(180.0)}


def add_broadcast_errata(s: Suite, profile: str) -> None:
    """Each erratum's cases whose items the profile has (a profile without
    an item simply has none of its cases)."""
    items = set(rules_profile(profile).flag_bits)
    for needs, add in ERRATA_CASES:
        if needs <= items:
            add(s, profile)


def add_e01_position(s: Suite, profile: str) -> None:
    # hand-written: latitude first. 0.5 rad, -2.0 rad, altitude 100.5 m, height 3.25 m, health 4.
    data = le16(1 << rules_profile(profile).bit("position")) + struct.pack("<ddffB", 0.5, -2.0, 100.5, 3.25, 4)
    s.add(OP, profile, f"broadcast.{profile}.e01.latitude_first", "broadcast.item_fields",
          "hand-written (ERRATA E01): the position item starts with latitude (0.5 rad), then longitude (-2.0 rad), "
          "altitude, height, GPS health; a decoder following the seed's table would swap them",
          bc_input(data), R("broadcast.item_fields") + ["E01", "E29"],
          expected={"value": {"data": {**broadcast_flags_model(profile, {"position"}), "position": {
              "latitude": {"f64": "0x3fe0000000000000", "value": 0.5},
              "longitude": {"f64": "0xc000000000000000", "value": -2.0},
              "altitude": {"f32": "0x42c90000", "value": 100.5},
              "height": {"f32": "0x40500000", "value": 3.25},
              "gps_health": 4}}}})


def e02_mode_names() -> dict[int, str]:
    """The cur_mov_control_mode names as ERRATA E02 decides them, written
    out independently of the spec's enum so that the two are compared."""
    names = {0: "atti_stop", 97: "gps_atti_ctrl_cl_yaw_rate", 98: "gps_atti_ctrl_yaw_rate",
             99: "atti_ctrl_yaw_rate", 100: "atti_ctrl_stop"}
    for vi, vname in enumerate(("vel", "pos", "thr")):
        for hi, hname in enumerate(("ang", "vel", "pos")):
            for yi, yname in enumerate(("ang", "rate")):
                names[1 + 6 * vi + 2 * hi + yi] = f"horiz_{hname}_vert_{vname}_yaw_{yname}"
    return names


def add_e02_control_modes(s: Suite, profile: str) -> None:
    """Every cur_mov_control_mode value, and unnamed ones, where the control info variant has the mode."""
    if not has_field(profile, "control_info", "cur_mov_control_mode"):
        return
    names = e02_mode_names()
    bit = rules_profile(profile).bit("control_info")
    for mode in [*range(0, 19), 19, 96, 97, 98, 99, 100, 101, 255]:
        data = le16(1 << bit) + bytes([mode, 0x0A])
        expected = {"value": {"data": {**broadcast_flags_model(profile, {"control_info"}), "control_info": {
            "cur_mov_control_mode": enum(mode, names.get(mode)), "control_device": enum(2, "onboard_device"),
            "onboard_requested": True, "virtual_rc": False, "reserved": 0}}}}
        s.add(OP, profile, f"broadcast.{profile}.e02.cur_mov_control_mode.{mode}", "broadcast.control_info",
              f"hand-written (ERRATA E02): control info with current mode {mode} "
              f"({names.get(mode) or 'no name: decodes with name null, not an error'}), device byte 0x0a",
              bc_input(data), R("broadcast.item_fields") + ["E02"] + (R("enums.unnamed") if mode not in names else []),
              expected=expected)


def add_e03_device_byte(s: Suite, profile: str) -> None:
    """The device byte alone (FW 2.3) or after the mode byte (FW 3.1), as
    the profile's variant says; reserved bits never an error. The device
    byte is one bit run, named after its first field (control_device)."""
    flag = le16(1 << rules_profile(profile).bit("control_info"))
    fields = item_fields(profile, "control_info")
    for dev in (0x00, 0x01, 0x02, 0x03, 0x07, 0x08, 0x10, 0xE0, 0xFF):
        item = pack(fields, {"cur_mov_control_mode": 5, "control_device": dev})
        s.add(OP, profile, f"broadcast.{profile}.e03.device_byte.0x{dev:02x}", "broadcast.control_info",
              f"control info ({len(item)} byte{'s' if len(item) > 1 else ''} in {profile}) with device byte 0x{dev:02x}"
              + ("; device values 3..7 have no name" if dev & 7 > 2 else "")
              + ("; reserved bits 5-7 set, still valid" if dev & 0xE0 else ""),
              bc_input(flag + item), R("broadcast.item_fields", "broadcast.reserved_item_bits", "broadcast.item_sizes")
              + ["E03"] + (R("enums.unnamed") if dev & 7 > 2 else []))
    other_fields = other_form(profile, "control_info")
    if other_fields is None:
        return
    mine = pack(fields, {"cur_mov_control_mode": 5, "control_device": 0x02})
    other = pack(other_fields, {"cur_mov_control_mode": 5, "control_device": 0x02})
    s.add(OP, profile, f"broadcast.{profile}.e03.other_firmware_size", "broadcast.control_info",
          f"control info in the size of the other firmware ({len(other)} byte): "
          + ("truncated_payload" if len(other) < len(mine) else "length_mismatch"),
          bc_input(flag + other), R("broadcast.item_sizes", "broadcast.bounds") + ["E03"])


def add_e04_velocity_status(s: Suite, profile: str) -> None:
    flag = le16(1 << rules_profile(profile).bit("velocity"))
    for status in (0x00, 0x01, 0x06, 0x07, 0x0D, 0x0F, 0x1F, 0xE1, 0xFF):
        data = flag + struct.pack("<fffB", 1.5, -0.25, 0.0, status)
        s.add(OP, profile, f"broadcast.{profile}.e04.velocity_status.0x{status:02x}", "broadcast.velocity",
              f"velocity with status byte 0x{status:02x}: data_valid {status & 1}, sensor_id {status >> 1 & 15}, "
              f"reserved {status >> 5} (informative bits, never an error)",
              bc_input(data), R("broadcast.item_fields", "broadcast.reserved_item_bits") + ["E04"])


def add_e13_gps_detail(s: Suite, profile: str) -> None:
    """GPS detail field order and encodings (E06 is the seed's damage to the same block)."""
    data = le16(1 << rules_profile(profile).bit("gps_detail")) + struct.pack(
        "<IIiiifff", 20170315, 123456, 1139876543, 225432100, -45678, 12.5, -3.0, 0.25)
    s.add(OP, profile, f"broadcast.{profile}.e13.gps_detail_longitude_first", "broadcast.item_fields",
          "hand-written (ERRATA E13): GPS detail is date 20170315 (decimal yyyymmdd), time 123456 (hhmmss), "
          "longitude 113.9876543 deg x 1e7 before latitude 22.54321 deg x 1e7, height -45678 mm, "
          "velocities 12.5, -3.0, 0.25 cm/s (32 bytes)",
          bc_input(data), R("broadcast.item_fields", "broadcast.item_sizes") + ["E13", "E06"],
          expected={"value": {"data": {**broadcast_flags_model(profile, {"gps_detail"}), "gps_detail": {
              "date": 20170315, "time": 123456, "longitude": 1139876543, "latitude": 225432100,
              "height_msl": -45678, "vel_n": {"f32": "0x41480000", "value": 12.5},
              "vel_e": {"f32": "0xc0400000", "value": -3.0}, "vel_d": {"f32": "0x3e800000", "value": 0.25}}}}})


def add_e14_rtk_yaw(s: Suite, profile: str) -> None:
    flag = le16(1 << rules_profile(profile).bit("rtk_detail"))
    for yaw in (-32768, -1, 0, 1800, 32767):
        data = flag + struct.pack("<IIddffffhBB", 20170315, 235959, 113.5, 22.25, 50.5, 1.0, 2.0, 3.0, yaw, 50, 16)
        s.add(OP, profile, f"broadcast.{profile}.e14.rtk_yaw.{yaw}", "broadcast.item_fields",
              f"RTK detail (44 bytes) with yaw {yaw} decoded as a raw i16, no range check",
              bc_input(data), R("broadcast.item_fields", "broadcast.item_sizes") + ["E14", "E06"])


def add_e20_later_firmware(s: Suite, profile: str) -> None:
    """Items in the sizes later firmware sends them (ERRATA E20 sources)."""
    if profile != LATER_FIRMWARE_BASE:
        return
    p = rules_profile(profile)
    for item, size, sizes in (("gps_detail", 68, "later firmware GPS detail (68 bytes)"),
                              ("rtk_detail", 74, "the 74 bytes the A3 OPENProtocol edition lists"),
                              ("time_stamp", 15, "later firmware time stamp (15 bytes)"),
                              ("position", 50, "later firmware position (50 bytes)"),
                              ("flight_status", 4, "later firmware flight status (4 bytes)"),
                              ("battery", 13, "later firmware battery (13 bytes)")):
        data = le16(1 << p.bit(item)) + bytes(s.rng.getrandbits(8) for _ in range(size))
        s.add(OP, profile, f"broadcast.{profile}.e20.later_firmware.{item}", "broadcast.later_firmware",
              f"{sizes} decoded as {profile} ({p.item_sizes[item]} bytes): length_mismatch, not a misread",
              bc_input(data), R("broadcast.bounds", "broadcast.item_sizes") + ["E20", "E25"] +
              (["E13"] if item == "gps_detail" else ["E14"] if item == "rtk_detail" else []),
              error="length_mismatch")


def add_e07_magnetometer(s: Suite, profile: str) -> None:
    flag = le16(1 << rules_profile(profile).bit("magnetometer"))
    for tag, vals in (("extremes", (-32768, 32767, 0)), ("signs", (-1, 1, -300))):
        s.add(OP, profile, f"broadcast.{profile}.e07.magnetometer.{tag}", "broadcast.item_fields",
              f"magnetometer (3 x i16, 6 bytes) {vals}", bc_input(flag + struct.pack("<3h", *vals)),
              R("broadcast.item_fields", "broadcast.item_sizes") + ["E07"])


def add_e17_rc(s: Suite, profile: str) -> None:
    """RC channels: raw i16 values, whatever their range."""
    flag = le16(1 << rules_profile(profile).bit("rc"))
    for tag, vals in (("nominal_p_gear_up", (-10000, 10000, 0, 5000, -8000, -10000)),
                      ("nominal_a_gear_down", (0, 0, 0, 0, 0, -4545)),
                      ("nominal_f", (10000, -10000, 10000, -10000, 8000, -4545)),
                      ("off_nominal", (-32768, 32767, 12000, -12000, 7000, -6000))):
        s.add(OP, profile, f"broadcast.{profile}.e17.rc.{tag}", "broadcast.item_fields",
              f"RC (6 x i16: roll, pitch, yaw, throttle, mode, gear) {vals}; raw values are always kept "
              f"(ranges and switch positions are plausibility, not decoding)",
              bc_input(flag + struct.pack("<6h", *vals)), R("broadcast.item_fields", "broadcast.item_sizes")
              + ["E07", "E17"])


def add_e08_time_stamp(s: Suite, profile: str) -> None:
    """The profile's time stamp variant, and the other firmware's."""
    flag = le16(1 << rules_profile(profile).bit("time_stamp"))
    fields = item_fields(profile, "time_stamp")
    s.add(OP, profile, f"broadcast.{profile}.e08.time_stamp", "broadcast.time_stamp",
          f"time stamp of {profile}: {describe(fields, TIME_STAMP)}",
          bc_input(flag + pack(fields, TIME_STAMP)), R("broadcast.item_sizes", "broadcast.item_fields") + ["E08"])
    other_fields = other_form(profile, "time_stamp")
    if other_fields is None:
        return
    other = pack(other_fields, TIME_STAMP)
    s.add(OP, profile, f"broadcast.{profile}.e08.time_stamp_other_firmware", "broadcast.time_stamp",
          f"time stamp in the other firmware's size ({len(other)} bytes) decoded as {profile}",
          bc_input(flag + other), R("broadcast.item_sizes", "broadcast.bounds") + ["E08", "E28"])


def add_e09_gimbal(s: Suite, profile: str) -> None:
    """The gimbal with every kind of limit byte where the variant has one, and the other firmware's variant."""
    flag = le16(1 << rules_profile(profile).bit("gimbal"))
    fields = item_fields(profile, "gimbal")
    limits = (0x00, 0x01, 0x02, 0x04, 0xF8, 0xFF) if has_field(profile, "gimbal", "limit") else (None,)
    for limit in limits:
        item = pack(fields, {**GIMBAL_ANGLES, "limit": limit})
        s.add(OP, profile, f"broadcast.{profile}.e09.gimbal{'.limit_0x%02x' % limit if limit is not None else ''}",
              "broadcast.gimbal",
              f"gimbal roll 1.5, pitch -90, yaw 180 ({len(item)} bytes)"
              + (f", limit byte 0x{limit:02x}" + ("; reserved bits set, still valid" if limit & 0xF8 else "")
                 if limit is not None else ", no limit byte on FW 2.3"),
              bc_input(flag + item),
              R("broadcast.item_fields", "broadcast.item_sizes", "broadcast.reserved_item_bits") + ["E09"])
    other_fields = other_form(profile, "gimbal")
    if other_fields is None:
        return
    other = pack(other_fields, {**GIMBAL_ANGLES, "limit": 0x01})
    s.add(OP, profile, f"broadcast.{profile}.e09.gimbal_other_firmware", "broadcast.gimbal",
          f"gimbal in the other firmware's size ({len(other)} bytes) decoded as {profile}",
          bc_input(flag + other), R("broadcast.item_sizes", "broadcast.bounds") + ["E09"])


def add_e18_units(s: Suite, profile: str) -> None:
    """Units are not on the wire: acceleration and angular rate decode as plain floats."""
    p = rules_profile(profile)
    for item in ("acceleration", "angular_rate"):
        data = le16(1 << p.bit(item)) + struct.pack("<fff", 9.8125, -0.5, 1.0)
        s.add(OP, profile, f"broadcast.{profile}.e18.{item}", "broadcast.item_fields",
              f"{item} x 9.8125, y -0.5, z 1.0: plain float32, m/s^2 or g (acceleration) is a device setting",
              bc_input(data), R("broadcast.item_fields", "floats.bit_exact") + ["E18"])


def add_e19_flight_status(s: Suite, profile: str) -> None:
    """Flight status is a raw byte; the old/new enum is applied by plausibility, not decoding."""
    flag = le16(1 << rules_profile(profile).bit("flight_status"))
    for value in (0, 1, 2, 3, 4, 5, 6, 255):
        s.add(OP, profile, f"broadcast.{profile}.e19.flight_status.{value}", "broadcast.flight_status",
              f"flight status {value}: decoded as the raw byte in every profile (old enum on M100, new on A3)",
              bc_input(flag + bytes([value])), R("broadcast.item_fields") + ["E19"],
              expected={"value": {"data": {**broadcast_flags_model(profile, {"flight_status"}),
                                           "flight_status": value}}})


def add_worked_value(s: Suite, profile: str) -> None:
    """The worked frame's value (flight status 3 and battery 87 at bits 11/12 of
    the A3 layout); in the M100 profiles bit 12 is reserved (E28: the profile decides)."""
    value = bytes.fromhex(WORKED_BROADCAST_VALUE)
    bits = rules_profile(profile).flag_bits
    if tuple(bits[11:13]) == ("flight_status", "battery"):
        s.add(OP, profile, f"broadcast.{profile}.worked_value", "broadcast.worked",
              "hand-written: the value of the PROTOCOL-FACTS broadcast frame, flags 0x1800 (flight status 3, "
              f"battery 87) in the A3 layout{'' if profile == WORKED_BROADCAST_PROFILE else ', which ' + profile + ' shares'}",
              bc_input(value), R(f"broadcast.flag_order.{profile}") + ["E28"],
              expected={"value": {"data": {**broadcast_flags_model(profile, {"flight_status", "battery"}),
                                           "flight_status": 3, "battery": 87}}})
    elif len(bits) <= 12:
        s.add(OP, profile, f"broadcast.{profile}.worked_value", "broadcast.worked",
              "the A3 worked broadcast value decoded as an M100 profile: bit 12 is reserved there (reserved_bits); "
              "the layout comes from the profile, never from the bytes",
              bc_input(value), R("broadcast.profile_select", "broadcast.reserved_flags") + ["E28"],
              error="reserved_bits")
    else:
        s.add(OP, profile, f"broadcast.{profile}.worked_value", "broadcast.worked",
              f"the A3 worked broadcast value decoded as {profile}, whose bits 11 and 12 carry other items: "
              "the layout comes from the profile, never from the bytes",
              bc_input(value), R("broadcast.profile_select") + ["E28"])


def add_e28_profile_select(s: Suite, profile: str) -> None:
    """The same bytes mean different things in each profile."""
    data = le16(1 << 6) + bytes(range(32))
    s.add(OP, profile, f"broadcast.{profile}.e28.bit6_32_bytes", "broadcast.profile_select",
          "flag bit 6 and 32 bytes: GPS detail in a3-fw3.1, a 6-byte magnetometer plus 26 stray bytes in the M100 "
          "profiles (length_mismatch)", bc_input(data), R("broadcast.profile_select") + ["E28"])
    data = le16(1 << 8) + struct.pack("<fff", 1.0, 2.0, 3.0) + b"\x07"
    s.add(OP, profile, f"broadcast.{profile}.e28.bit8_13_bytes", "broadcast.profile_select",
          "flag bit 8 and 13 bytes: gimbal with limit byte in m100-fw3.1, gimbal and a stray byte in m100-fw2.3, "
          "a 6-byte magnetometer and 7 stray bytes in a3-fw3.1", bc_input(data), R("broadcast.profile_select") + ["E28"])


def add_e27_doc_2x_sizes(s: Suite, profile: str) -> None:
    """The 2.x doc's size table (position 24, magnetometer 12, RC 10) is wrong."""
    if profile != DOC_2X_PROFILE:
        return
    doc_sizes = {"time_stamp": 4, "quaternion": 16, "acceleration": 12, "velocity": 13, "angular_rate": 12,
                 "position": 24, "magnetometer": 12, "rc": 10, "gimbal": 12, "flight_status": 1, "battery": 1,
                 "control_info": 1}
    pid = f"broadcast.{profile}"
    data = le16(0x0FFF) + bytes(sum(doc_sizes.values()))
    s.add(OP, profile, f"{pid}.e27.doc_2x_sizes", "broadcast.item_sizes",
          "every item in the sizes of the 2.x doc table (118 bytes instead of 117): length_mismatch",
          bc_input(data), R("broadcast.item_sizes", "broadcast.bounds") + ["E27"], error="length_mismatch")
    data = le16(1 << 6) + bytes(12)
    s.add(OP, profile, f"{pid}.e27.magnetometer_12", "broadcast.item_sizes",
          "magnetometer in the 2.x table's 12 bytes: length_mismatch (it is 3 x i16)",
          bc_input(data), R("broadcast.item_sizes", "broadcast.bounds") + ["E27", "E07"], error="length_mismatch")
    data = le16(0x0FFF) + bytes(117)
    s.add(OP, profile, f"{pid}.e27.all_items_117", "broadcast.item_sizes",
          "every item, all zero: 117 bytes after the flag word (the sizes of the structs)",
          bc_input(data), R("broadcast.item_sizes") + ["E27"])


ERRATA_CASES = (
    ({"position"}, add_e01_position),
    ({"control_info"}, add_e02_control_modes),
    ({"control_info"}, add_e03_device_byte),
    ({"velocity"}, add_e04_velocity_status),
    ({"gps_detail"}, add_e13_gps_detail),
    ({"rtk_detail"}, add_e14_rtk_yaw),
    (set(), add_e20_later_firmware),
    ({"magnetometer"}, add_e07_magnetometer),
    ({"rc"}, add_e17_rc),
    ({"time_stamp"}, add_e08_time_stamp),
    ({"gimbal"}, add_e09_gimbal),
    ({"acceleration", "angular_rate"}, add_e18_units),
    ({"flight_status"}, add_e19_flight_status),
    (set(), add_worked_value),
    (set(), add_e28_profile_select),
    (set(), add_e27_doc_2x_sizes),
)
"""(the items a profile needs for them, the cases), in the order the cases appear in broadcast.json."""
