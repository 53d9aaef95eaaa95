"""Broadcast item access with one "absent": None, whether the item's flag
bit is clear or the frame's profile has no such item."""
from __future__ import annotations

from typing import Any

from ._tables import COMMANDS, HEADER_ONLY_LEN, ITEM_FLAGS
from .osdk_frame import OsdkFrame

_BROADCAST = COMMANDS["broadcast"]


class Broadcast:
    """The items of one broadcast frame. `data` is the parsed layout of the
    frame's profile (OsdkBroadcastA3Fw31, ...)."""

    __slots__ = ("data",)

    def __init__(self, data: Any) -> None:
        self.data = data

    def _item(self, name: str) -> Any:
        flag = ITEM_FLAGS.get(type(self.data).__qualname__, {}).get(name)
        if flag is None or not getattr(self.data, flag, False):
            return None
        return getattr(self.data, name)

    @property
    def time_stamp(self) -> Any:
        """`time_stamp` (every profile), or None when absent."""
        return self._item('time_stamp')

    @property
    def quaternion(self) -> Any:
        """`quaternion` (every profile), or None when absent."""
        return self._item('quaternion')

    @property
    def acceleration(self) -> Any:
        """`acceleration` (every profile), or None when absent."""
        return self._item('acceleration')

    @property
    def velocity(self) -> Any:
        """`velocity` (every profile), or None when absent."""
        return self._item('velocity')

    @property
    def angular_rate(self) -> Any:
        """`angular_rate` (every profile), or None when absent."""
        return self._item('angular_rate')

    @property
    def position(self) -> Any:
        """`position` (every profile), or None when absent."""
        return self._item('position')

    @property
    def magnetometer(self) -> Any:
        """`magnetometer` (every profile), or None when absent."""
        return self._item('magnetometer')

    @property
    def rc(self) -> Any:
        """`rc` (every profile), or None when absent."""
        return self._item('rc')

    @property
    def gimbal(self) -> Any:
        """`gimbal` (every profile), or None when absent."""
        return self._item('gimbal')

    @property
    def flight_status(self) -> Any:
        """`flight_status` (every profile), or None when absent."""
        return self._item('flight_status')

    @property
    def battery(self) -> Any:
        """`battery` (every profile), or None when absent."""
        return self._item('battery')

    @property
    def control_info(self) -> Any:
        """`control_info` (every profile), or None when absent."""
        return self._item('control_info')

    @property
    def gps_detail(self) -> Any:
        """`gps_detail` (a3-fw3.1), or None when absent."""
        return self._item('gps_detail')

    @property
    def rtk_detail(self) -> Any:
        """`rtk_detail` (a3-fw3.1), or None when absent."""
        return self._item('rtk_detail')


def broadcast_of(frame: OsdkFrame) -> Broadcast | None:
    """The broadcast of a decoded frame, or None when the frame is not a
    plain (unencrypted) broadcast command."""
    if not isinstance(frame, OsdkFrame) or frame.is_ack or frame.len == HEADER_ONLY_LEN:
        return None
    data = getattr(frame, "data", None)
    if not isinstance(data, OsdkFrame.FrameData) or (data.cmd_set_code, data.cmd_id) != _BROADCAST:
        return None
    return Broadcast(data.value.body.data)
