"""The spec rules golden vectors pin, by name, with what each one says.

A vector names the rules it pins in its `flags` as `rule:<name>` (next to
the ERRATA ids it pins); `osdkc vectors coverage` counts the cases per rule
and fails when one has none. This table is the one place the names are
defined: the generator refuses a flag that is not here, and `osdkc vectors
check` refuses a vector file that uses one.
"""
from __future__ import annotations

from osdk_conformance.reference.codec import PROFILES

RULES: dict[str, str] = {
    # frame layer (osdk_frame.ksy, rules.yaml#frame, deframe.py)
    "frame.sof": "a frame starts with the start byte 0xAA; bytes before one are not a frame",
    "frame.len": "LEN is 12 or 17..1023; 0..11 and 13..16 are impossible_length",
    "frame.header_only": "LEN 12 is a header-only frame with neither DATA nor CRC-32",
    "frame.ver": "VER is 0, else bad_version",
    "frame.reserved": "RES0 and RES1 are 0, else reserved_bits",
    "frame.crc16": "CRC-16 (init 0x3AA3, reflected 0x8005) over bytes 0-9, little-endian at 10-11",
    "frame.crc32": "CRC-32 (init 0x3AA3, reflected 0x04C11DB7) over every byte before it, little-endian",
    "frame.enc": "ENC is 0 (PADDING 0) or 1 (DATA whole 16-byte blocks, PADDING 1..16), else bad_encryption",
    "frame.aes_raw": "AES DATA is kept as ciphertext (hex), never decoded",
    "frame.session": "an ACK is never in session 0 (bad_session); sessions 1..31 carry ACKs",
    "frame.data": "command DATA is set, id, value (at least 2 bytes); ACK DATA is the value alone",
    "frame.truncation": "input that ends inside a frame is truncated_frame",
    "frame.extra_bytes": "decode_frame: bytes after LEN are length_mismatch",
    # streams (rules.yaml#/frame/receiver, deframe.py, decode.py)
    "stream.garbage": "a run of bytes with no start byte is one garbage event",
    "stream.resync": "a bad header drops one byte and rescans; a bad CRC-32 rescans after the start byte",
    "stream.chunking": "events do not depend on how the bytes are split into reads",
    "stream.truncated_tail": "a frame cut off by the end of the stream is truncated_frame, then rescanned",
    "stream.long": "streams longer than a receive buffer (300 and 1,024 bytes): long garbage, the largest frame, "
                   "a header announcing LEN 1023; the frame after them is still found",
    "stream.ack_match": "an ACK in session 2..31 is decoded as the ACK of the command waiting in its session's slot "
                        "when their SEQs are equal (a header-only ACK too); session-1 ACKs are never matched",
    "stream.ack_memory": "what ACK matching remembers: one slot per session 2..31, taken by each plain command that "
                         "decodes; a match empties it even when its value fails to decode, a command that fails to "
                         "decode changes nothing, all 30 slots are held at once",
    # broadcast (osdk_broadcast_*.ksy, rules.yaml#profiles, #/frame/broadcast)
    **{f"broadcast.flag_order.{p}": f"items follow the flag word in the flag-bit order of {p}" for p in PROFILES},
    "broadcast.item_sizes": "each item has its profile's size (time stamp 4/9, gimbal 12/13, control info 1/2, ...)",
    "broadcast.item_fields": "the fields of each item, their order, types and signedness",
    "broadcast.flag_word": "the payload starts with a u16 flag word; fewer than 2 bytes is truncated_payload",
    "broadcast.bounds": "a flag word promising more than the payload is truncated_payload; bytes after the last item are length_mismatch",
    "broadcast.reserved_flags": "flag bits above the profile's last item must be 0, else reserved_bits",
    "broadcast.reserved_item_bits": "reserved bits inside items (velocity status, gimbal limit, device byte) are decoded, never an error",
    "broadcast.profile_select": "the layout is chosen by the explicit profile, never sniffed from the bytes",
    # control mode byte and movement control (osdk_control_mode.ksy, rules.yaml#control_mode, #control_modes)
    "control.fields": "mode byte fields: bits 7-6 horizontal, 5-4 vertical, 3 yaw, 2-1 frame, 0 stable, with their enum names",
    "control.undefined": "horizontal 0b11, vertical 0b11 and frame 0b10/0b11 are undefined (later_firmware / invalid)",
    "control.combinations": "the 14 documented horizontal/vertical/yaw combinations, and the 4 undocumented ones",
    "control.classification": "a byte gets the most severe class of its reasons (invalid > later_firmware > undocumented > documented)",
    "control.bit0_fw2_3": "on m100-fw2.3 bit 0 is the yaw frame; yaw angle needs it 0",
    "control.value": "the movement control value is exactly 17 bytes: mode byte and four float32",
    "control.undefined_mode": "check_movement_control rejects a mode byte that is not documented for the profile",
    "control.ranges": "setpoints within the combination's inclusive ranges (x, y horizontal; z vertical; yaw), else out_of_range",
    "control.non_finite": "NaN and infinite setpoints are out_of_range, also against an unbounded limit",
    # other payloads (osdk_payload.ksy)
    "payload.version_query": "get version: 1 arbitrary byte",
    "payload.version_ack": "version ACK: u16 code, u32 version CRC, an 11-byte version ID on FW 3.1 (none on FW 2.3), 32-byte name",
    "payload.activation_request": "activation: u32 app id, u32 API level, u32 SDK version, 32-byte bundle id (44 bytes)",
    "payload.activation_ack": "activation ACK: u16 activation_result",
    "payload.frequency_request": "set frequency: 16 frequency codes in flag-bit order",
    "payload.frequency_ack": "set frequency ACK: u16 frequency_ack",
    "payload.control_request": "obtain/release control: 1 byte",
    "payload.control_ack": "obtain/release control ACK: u16 control_ack",
    "payload.movement_control": "movement control value as a payload (any mode byte parses)",
    "payload.lost_control": "lost control push: 1 byte reason",
    "payload.lost_control_ack": "lost control ACK: u16, always 0",
    "payload.unknown": "a command or ACK the spec does not describe keeps its value as raw hex",
    "payload.truncated": "a value shorter than its layout is truncated_payload",
    "payload.trailing": "bytes after a known value are length_mismatch",
    "enums.unnamed": "an enum value with no name decodes as {value, name: null}, not as an error",
    # values
    "floats.bit_exact": "floats are compared by their IEEE bits: -0.0, NaN payloads, infinities, denormals survive",
    # encoders
    "encode.movement_control": "the 17-byte movement control value from a mode byte and four float32 bit patterns",
    "encode.frame": "a frame with LEN, CRC-16 and CRC-32 filled in",
}


def rule_flag(name: str) -> str:
    """`rule:<name>`; KeyError for a name that is not in RULES."""
    if name not in RULES:
        raise KeyError(f"no spec rule named {name!r}")
    return f"rule:{name}"
