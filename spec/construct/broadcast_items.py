"""The flight data (broadcast) items, one construct per ksy type.

Mirrors spec/osdk_broadcast_items.ksy. The names are the ksy type names;
the three ksy types with params (time_stamp, gimbal, control_info) are
functions of those params, because the profiles differ exactly there
(FW 2.3 sends the short forms, FW 3.1 the long ones). Which bit carries
which item, and with which params, is the business of spec/rules.yaml:
broadcast.py looks each item's construct up here by its ksy type name and
passes the params by their ksy ids, so names and parameter names here are
the ksy's.
"""
from __future__ import annotations

import functools

from construct import BitsInteger, Enum, Flag, Int8ul, Int16sl, Int32sl, Int32ul, Struct

from .bitfields import lsb_first, record
from .combinators import when
from .enums import CONTROL_DEVICE, CUR_MOV_CONTROL_MODE
from .floats import F32le, F64le

__all__ = [
    "time_stamp", "quaternion", "vector3f", "velocity", "position", "gps_detail", "rtk_detail",
    "magnetometer", "rc", "gimbal", "gimbal_limit", "control_info",
]


@functools.cache
def time_stamp(has_ns_and_sync: bool):
    """Time stamp: 4 bytes (FW 2.3) or 9 bytes with nanoseconds and sync flag (FW 3.1)."""
    return Struct(
        "time" / Int32ul,
        "nano_time" / when(has_ns_and_sync, Int32ul),
        "sync_flag" / when(has_ns_and_sync, Int8ul),
    )


quaternion = Struct(
    "q0" / F32le,
    "q1" / F32le,
    "q2" / F32le,
    "q3" / F32le,
)

vector3f = Struct(
    "x" / F32le,
    "y" / F32le,
    "z" / F32le,
)

velocity = record(
    "x" / F32le,
    "y" / F32le,
    "z" / F32le,
    lsb_first(
        "data_valid" / Flag,
        "sensor_id" / BitsInteger(4),
        "reserved" / BitsInteger(3),
    ),
)

position = Struct(
    "latitude" / F64le,
    "longitude" / F64le,
    "altitude" / F32le,
    "height" / F32le,
    "gps_health" / Int8ul,
)

gps_detail = Struct(
    "date" / Int32ul,
    "time" / Int32ul,
    "longitude" / Int32sl,
    "latitude" / Int32sl,
    "height_msl" / Int32sl,
    "vel_n" / F32le,
    "vel_e" / F32le,
    "vel_d" / F32le,
)

rtk_detail = Struct(
    "date" / Int32ul,
    "time" / Int32ul,
    "longitude" / F64le,
    "latitude" / F64le,
    "height_msl" / F32le,
    "vel_n" / F32le,
    "vel_e" / F32le,
    "vel_d" / F32le,
    "yaw" / Int16sl,
    "position_flag" / Int8ul,
    "yaw_flag" / Int8ul,
)

magnetometer = Struct(
    "x" / Int16sl,
    "y" / Int16sl,
    "z" / Int16sl,
)

rc = Struct(
    "roll" / Int16sl,
    "pitch" / Int16sl,
    "yaw" / Int16sl,
    "throttle" / Int16sl,
    "mode" / Int16sl,
    "gear" / Int16sl,
)

gimbal_limit = lsb_first(
    "pitch_limit" / Flag,
    "roll_limit" / Flag,
    "yaw_limit" / Flag,
    "reserved" / BitsInteger(5),
)


@functools.cache
def gimbal(has_limit_byte: bool):
    """Gimbal angles: 12 bytes (FW 2.3) or 13 with the limit byte (FW 3.1)."""
    return Struct(
        "roll" / F32le,
        "pitch" / F32le,
        "yaw" / F32le,
        "limit" / when(has_limit_byte, gimbal_limit),
    )


@functools.cache
def control_info(has_mode: bool):
    """Control info: the device byte (FW 2.3), preceded by the current
    movement control mode in FW 3.1."""
    return record(
        "cur_mov_control_mode" / when(has_mode, Enum(Int8ul, **CUR_MOV_CONTROL_MODE)),
        lsb_first(
            "control_device" / Enum(BitsInteger(3), **CONTROL_DEVICE),
            "onboard_requested" / Flag,
            "virtual_rc" / Flag,
            "reserved" / BitsInteger(3),
        ),
    )

