"""What the generated libraries' examples (examples/<language>/) must print,
computed from the reference, so every language's example is checked
against the same bytes and the same expected lines (generated/README.md
documents the two programs).

`receive PROFILE` reads a byte stream on standard input and prints one line
per event of the receiver, in stream order:

    garbage OFFSET LENGTH
    error OFFSET LENGTH CLASS          (the deframer's, or decode_frame's)
    empty OFFSET SEQ                   (a header-only frame)
    ack OFFSET SEQ                     (an ACK frame; its value is not decoded)
    frame OFFSET SEQ CMD_SET CMD_ID    (a plain command frame)

and after a broadcast frame one line per item of the profile in flag-bit
order: `  battery N` and `  time_stamp N` (its `time` field) with the
value, any other item `  ITEM present`, and `  ITEM absent` for an item
whose flag bit is clear, through the library's item access.

`send` prints `NAME HEX` for one frame of each command an onboard computer
sends, with the arguments of SENT below: the bytes must be the reference
encoder's, in every language.
"""
from __future__ import annotations

import struct

from osdk_conformance import api

# (name, session, seq, value fields) of the frames `send` prints; the
# movement control frame is PROTOCOL-FACTS' worked frame.
SENT = (
    ("version_query", 2, 1, {"arbitrary": 0}),
    ("activation", 2, 2, {"app_id": 1000001, "api_level": 2, "sdk_version": 0x03016400,
                          "bundle_id": b"0123456789abcdef0123456789abcdef"}),
    ("set_frequency", 2, 3, {"codes": [1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 0, 0]}),
    ("control_authority", 2, 4, {"request": 1}),
    ("movement_control", 0, 0x1234, {"control_mode": 0x4B, "x": 1.0, "y": -2.0, "z": 0.5, "yaw": 30.0}),
)
WORKED_FRAME = "aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba"

_COMMAND = {"version_query": (0, 0), "activation": (0, 1), "set_frequency": (0, 0x10),
            "control_authority": (1, 0), "movement_control": (1, 3)}


def _value(name: str, f: dict) -> bytes:
    # written out from the ksy layouts (spec/osdk_payload.ksy), not with the
    # library under test
    if name == "version_query":
        return bytes([f["arbitrary"]])
    if name == "activation":
        return struct.pack("<III", f["app_id"], f["api_level"], f["sdk_version"]) + f["bundle_id"]
    if name == "set_frequency":
        return bytes(f["codes"])
    if name == "control_authority":
        return bytes([f["request"]])
    return api.encode_movement_control(f["control_mode"], f["x"], f["y"], f["z"], f["yaw"])


def send_expected() -> list[str]:
    lines = []
    for name, session, seq, fields in SENT:
        cmd_set, cmd_id = _COMMAND[name]
        frame = api.encode_frame(cmd_set=cmd_set, cmd_id=cmd_id, value=_value(name, fields), session=session, seq=seq)
        lines.append(f"{name} {frame.hex()}")
    assert lines[-1] == f"movement_control {WORKED_FRAME}"
    return lines


def receive_stream(profile: str) -> bytes:
    """Garbage, broadcasts with every item, some items and one item, a
    corrupted CRC-32, a command, a broadcast with a reserved flag bit, an
    ACK, a header-only frame and a frame cut off by the end of the input."""
    items = api.broadcast_items(profile)
    full = api.encode_broadcast_frame(profile, {i: None for i in items} | {"battery": 87}, seq=1)
    some = api.encode_broadcast_frame(profile, {"battery": 12, "flight_status": None}, seq=2)
    stamp = api.encode_broadcast_frame(profile, {"time_stamp": {"time": 123456}}, seq=3)
    bad_crc = bytearray(api.encode_broadcast_frame(profile, {"battery": 50}, seq=4))
    bad_crc[-1] ^= 0x01
    reserved_word = 1 << 15
    reserved = api.encode_frame(cmd_set=2, cmd_id=0, value=struct.pack("<H", reserved_word), seq=5)
    ack = api.encode_frame(value=b"\x00\x00", is_ack=True, session=1, seq=99)
    empty = api.encode_frame(session=0, seq=7)
    return (b"\x01\x02\x03" + full + some + stamp + bytes(bad_crc) + bytes.fromhex(WORKED_FRAME)
            + reserved + ack + empty + full[:20])


def _int(v):
    return v["value"] if isinstance(v, dict) else v


def receive_expected(profile: str) -> list[str]:
    items = api.broadcast_items(profile)
    lines = []
    for e in api.decode(receive_stream(profile), profile):
        if e.kind == "garbage":
            lines.append(f"garbage {e.offset} {e.length}")
        elif e.kind == "error":
            lines.append(f"error {e.offset} {e.length} {e.error}")
        else:
            f = e.frame
            seq = _int(f["seq"])
            if "data" not in f:
                lines.append(f"empty {e.offset} {seq}")
            elif f["is_ack"]:
                lines.append(f"ack {e.offset} {seq}")
            else:
                d = f["data"]
                cmd_set, cmd_id = _int(d["cmd_set"]), _int(d["cmd_id"])
                lines.append(f"frame {e.offset} {seq} {cmd_set} {cmd_id}")
                if (cmd_set, cmd_id) == (2, 0):
                    data = d["value"]["body"]["data"]
                    for item in items:
                        if item not in data:
                            lines.append(f"  {item} absent")
                        elif item == "battery":
                            lines.append(f"  battery {_int(data[item])}")
                        elif item == "time_stamp":
                            lines.append(f"  time_stamp {_int(data[item]['time'])}")
                        else:
                            lines.append(f"  {item} present")
    return lines
