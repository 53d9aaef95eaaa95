"""The two worked frames of PROTOCOL-FACTS section 1, with what they mean.

They were computed independently of this project's code, so they check the
encoder and both decoders against an outside reference, not against
themselves.
"""
from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class WorkedFrame:
    name: str
    hex: str
    profile: str
    build: dict  # arguments of osdk_construct.frame.build_frame
    expect: dict  # dotted path in the frame model -> expected model value


def f32(bits: int, value: float) -> dict:
    return {"f32": f"0x{bits:08x}", "value": value}


MOVEMENT = WorkedFrame(
    name="movement control, mode 0x4B, x 1.0, y -2.0, z 0.5, yaw 30.0",
    hex="aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba",
    profile="a3-fw3.1",
    build={"cmd_set": 0x01, "cmd_id": 0x03, "session": 0, "seq": 0x1234,
           "value": bytes.fromhex("4b0000803f000000c00000003f0000f041")},
    expect={
        "len": 35, "session": 0, "is_ack": False, "seq": 0x1234,
        "data.cmd_set": {"value": 1, "name": "control"}, "data.cmd_id": 3,
        "data.value.body.control_mode.horizontal_logic": {"value": 1, "name": "hori_vel"},
        "data.value.body.control_mode.vertical_logic": {"value": 0, "name": "vert_vel"},
        "data.value.body.control_mode.yaw_logic": {"value": 1, "name": "yaw_rate"},
        "data.value.body.control_mode.horizontal_frame": {"value": 1, "name": "body"},
        "data.value.body.control_mode.stable_mode": {"value": 1, "name": "stable"},
        "data.value.body.x": f32(0x3F800000, 1.0),
        "data.value.body.y": f32(0xC0000000, -2.0),
        "data.value.body.z": f32(0x3F000000, 0.5),
        "data.value.body.yaw": f32(0x41F00000, 30.0),
    },
)

BROADCAST = WorkedFrame(
    name="broadcast (a3-fw3.1), flags 0x1800: flight status 3, battery 87",
    hex="aa1600000000000007001ede02000018035769c676b2",
    profile="a3-fw3.1",
    build={"cmd_set": 0x02, "cmd_id": 0x00, "session": 0, "seq": 7, "value": bytes.fromhex("00180357")},
    expect={
        "len": 22, "seq": 7,
        "data.cmd_set": {"value": 2, "name": "push"}, "data.cmd_id": 0,
        "data.value.body.data.has_flight_status": True,
        "data.value.body.data.has_battery": True,
        "data.value.body.data.has_time_stamp": False,
        "data.value.body.data.flight_status": 3,
        "data.value.body.data.battery": 87,
    },
)

WORKED_FRAMES = (MOVEMENT, BROADCAST)


def lookup(model: dict, dotted: str):
    node = model
    for part in dotted.split("."):
        node = node[part]
    return node
