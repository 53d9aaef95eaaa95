"""Movement control: the control mode byte and the 17-byte command value.

Mirrors spec/osdk_control_mode.ksy (`control_mode`) and
spec/osdk_movement_control.ksy (`movement_control`), field for field. The
mode byte's fields are listed from bit 0 upward, as in the ksy; values
with no name (horizontal logic 3, vertical logic 3, frame 2 and 3) parse
as unnamed enum values, because the byte layout allows them and rules.yaml,
not the layout, says they are undefined.
"""
from __future__ import annotations

from construct import BitsInteger, Enum, Struct

from .bitfields import lsb_first
from .enums import HORIZONTAL_FRAME, HORIZONTAL_LOGIC, STABLE_MODE, VERTICAL_LOGIC, YAW_LOGIC
from .floats import F32le

__all__ = ["control_mode", "movement_control", "encode_movement_control"]

control_mode = lsb_first(
    "stable_mode" / Enum(BitsInteger(1), **STABLE_MODE),
    "horizontal_frame" / Enum(BitsInteger(2), **HORIZONTAL_FRAME),
    "yaw_logic" / Enum(BitsInteger(1), **YAW_LOGIC),
    "vertical_logic" / Enum(BitsInteger(2), **VERTICAL_LOGIC),
    "horizontal_logic" / Enum(BitsInteger(2), **HORIZONTAL_LOGIC),
)
"""osdk_control_mode: the control mode byte."""

movement_control = Struct(
    "control_mode" / control_mode,
    "x" / F32le,
    "y" / F32le,
    "z" / F32le,
    "yaw" / F32le,
)
"""osdk_movement_control: value of command set 0x01, id 0x03."""


def encode_movement_control(mode_byte: int, x, y, z, yaw) -> bytes:
    """The 17-byte movement control value. `mode_byte` is the whole control
    mode byte (0..255); x, y, z, yaw are numbers (rounded to float32) or F32."""
    if not isinstance(mode_byte, int) or not 0 <= mode_byte <= 0xFF:
        raise ValueError(f"control mode byte must be 0..255, got {mode_byte!r}")
    mode = control_mode.parse(bytes([mode_byte]))
    return movement_control.build({"control_mode": mode, "x": x, "y": y, "z": z, "yaw": yaw})
