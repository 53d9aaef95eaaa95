"""The DJI Onboard SDK OPEN protocol, generated from the osdk-conformance
spec by tools/regen.py (do not edit): the Kaitai parsers (osdk_frame,
osdk_payload, ...) and the glue to receive and send.

Receive: Deframer().feed(chunk) / finish() give Events; decode_frame(raw,
profile) the parsed OsdkFrame; broadcast_of(frame) its Broadcast (an item
is None when absent). Send: encode_<command>(...) a command's value,
encode_frame(...) the whole frame. Rejected input raises OsdkError
(.error_class, .field, .detail); bad arguments ValueError or TypeError.
"""
from ._tables import BROADCAST_ITEMS, COMMANDS, PROFILES, SENT_COMMANDS
from .broadcast import Broadcast, broadcast_of
from .crc import crc16, crc32
from .decode import decode_frame, decode_payload
from .deframer import Deframer, Event
from .encode import (
    Float32Bits,
    encode_frame,
    encode_version_query,
    encode_activation,
    encode_set_frequency,
    encode_control_authority,
    encode_movement_control,
)
from .errors import OsdkError
from .osdk_frame import OsdkFrame
from .osdk_payload import OsdkPayload

__all__ = [
    "BROADCAST_ITEMS", "COMMANDS", "PROFILES", "SENT_COMMANDS",
    "Broadcast", "broadcast_of", "crc16", "crc32", "decode_frame", "decode_payload",
    "Deframer", "Event", "Float32Bits", "encode_frame", "OsdkError", "OsdkFrame", "OsdkPayload",
    "encode_version_query",
    "encode_activation",
    "encode_set_frequency",
    "encode_control_authority",
    "encode_movement_control",
]
