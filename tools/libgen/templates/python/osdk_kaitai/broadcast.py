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

${broadcast_properties}

def broadcast_of(frame: OsdkFrame) -> Broadcast | None:
    """The broadcast of a decoded frame, or None when the frame is not a
    plain (unencrypted) broadcast command."""
    if not isinstance(frame, OsdkFrame) or frame.is_ack or frame.len == HEADER_ONLY_LEN:
        return None
    data = getattr(frame, "data", None)
    if not isinstance(data, OsdkFrame.FrameData) or (data.cmd_set_code, data.cmd_id) != _BROADCAST:
        return None
    return Broadcast(data.value.body.data)
