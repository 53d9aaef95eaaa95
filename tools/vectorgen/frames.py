"""frames.json: decode_frame on exactly one frame's bytes: the worked
frames, every header field's invalid values, single-bit CRC errors,
truncation at every byte, header-only, AES and ACK frames, and values that
do not decode."""
from __future__ import annotations

import random
from typing import Any

from osdk_conformance.core.rules import profile as rules_profile

from .broadcast_values import Values, broadcast_flags_model, payload
from .builder import PROFILES, R, Suite
from .control_mode import FIELDS_0X4B
from .header_bits import add_header_bits
from .precedence import add_rule_pairs
from .scalars import enum, f32_model, le16
from .wire import WORKED_BROADCAST, WORKED_BROADCAST_PROFILE, WORKED_MOVEMENT, flip, frame_bytes

MOVE = bytes.fromhex(WORKED_MOVEMENT)
MOVE_VALUE = MOVE[14:-4]


class FrameCases:
    """The cases of one profile: ids under frames.<profile>."""

    def __init__(self, s: Suite, profile: str) -> None:
        self.s = s
        self.profile = profile

    def add(self, name: str, category: str, comment: str, data: bytes, flags: list[str], **kw: Any) -> None:
        self.s.add("decode_frame", self.profile, f"frames.{self.profile}.{name}", category, comment,
                   {"hex": data.hex()}, flags, **kw)


def gen_frames() -> Suite:
    s = Suite("frames", "decode_frame: exactly one frame's bytes: the worked frames, every header field's invalid "
                        "values, single-bit CRC errors, truncation at every byte, header-only, AES and ACK frames, "
                        "and values that do not decode.", seed=505)
    for profile in PROFILES:
        c = FrameCases(s, profile)
        bcast_value = payload(profile, 1 | 1 << rules_profile(profile).bit("battery"), Values(s.rng))
        bcast = frame_bytes(cmd_set=2, cmd_id=0, value=bcast_value, seq=7)
        add_worked_frames(c)
        c.add("broadcast", "frame.valid", f"a {profile} broadcast frame (time stamp and battery)", bcast,
              R("frame.data", f"broadcast.flag_order.{profile}"))
        add_bad_header_values(c)
        add_lengths(c, s.rng)
        add_header_only(c)
        add_encryption(c, s.rng)
        add_sessions_and_values(c)
        add_crc_bits(c, bcast)
        add_truncation(c)
        add_rule_pairs(profile, "decode_frame", "precedence", c.add)
        add_header_bits(c.add, stream=False)
    return s


def add_worked_frames(c: FrameCases) -> None:
    """The two PROTOCOL-FACTS frames with hand-written expectations; the
    broadcast one is in one profile's layout and reserved bits in the others."""
    c.add("worked.movement_control", "frame.worked",
          "hand-written: the PROTOCOL-FACTS movement control frame (session 0, seq 0x1234, mode 0x4B, x 1.0, "
          "y -2.0, z 0.5, yaw 30.0); CRC-16 0x72e1 and CRC-32 0xba01dbfc as stored little-endian",
          MOVE, R("frame.crc16", "frame.crc32", "frame.data", "frame.len") + ["E21"],
          expected={"frame": {
              "sof": "aa", "len": 35, "ver": 0, "session": 0, "is_ack": False, "res0": 0, "padding": 0,
              "enc": enum(0, "plain"), "res1": 0, "seq": 0x1234, "crc16": 0x72E1,
              "data": {"cmd_set": enum(1, "control"), "cmd_id": 3, "value": {"body": {
                  "control_mode": FIELDS_0X4B,
                  "x": f32_model(0x3F800000), "y": f32_model(0xC0000000), "z": f32_model(0x3F000000),
                  "yaw": f32_model(0x41F00000)}}},
              "crc32": 0xBA01DBFC}})
    worked_b = bytes.fromhex(WORKED_BROADCAST)
    bits = rules_profile(c.profile).flag_bits
    if tuple(bits[11:13]) == ("flight_status", "battery"):   # the A3 layout's bits 11 and 12
        c.add("worked.broadcast", "frame.worked",
              "hand-written: the PROTOCOL-FACTS broadcast frame (seq 7, flags 0x1800, flight status 3, battery 87)"
              + ("" if c.profile == WORKED_BROADCAST_PROFILE else f", in {c.profile} as in the A3 layout"),
              worked_b, R("frame.crc16", "frame.crc32", "frame.data", f"broadcast.flag_order.{c.profile}") + ["E21"],
              expected={"frame": {
                  "sof": "aa", "len": 22, "ver": 0, "session": 0, "is_ack": False, "res0": 0, "padding": 0,
                  "enc": enum(0, "plain"), "res1": 0, "seq": 7, "crc16": 0xDE1E,
                  "data": {"cmd_set": enum(2, "push"), "cmd_id": 0, "value": {"body": {"data": {
                      **broadcast_flags_model(c.profile, {"flight_status", "battery"}),
                      "flight_status": 3, "battery": 87}}}},
                  "crc32": 0xB276C669}})
    elif len(bits) <= 12:
        c.add("worked.broadcast", "frame.worked",
              "the A3 worked broadcast frame decoded with an M100 profile: flag bit 12 is reserved there",
              worked_b, R("frame.crc32", "broadcast.profile_select", "broadcast.reserved_flags") + ["E28", "E25"],
              error="reserved_bits")
    else:
        c.add("worked.broadcast", "frame.worked",
              f"the A3 worked broadcast frame decoded as {c.profile}, whose bits 11 and 12 carry other items",
              worked_b, R("frame.crc32", "broadcast.profile_select") + ["E28"])


def add_bad_header_values(c: FrameCases) -> None:
    """SOF, VER, RES0 and RES1 values a frame must not have."""
    for b in (0x00, 0xAB, 0x2A, 0x55):
        c.add(f"sof.0x{b:02x}", "frame.sof", f"first byte 0x{b:02x}, not the start byte: bad_sof (a stream "
              f"reports such bytes as garbage instead)", bytes([b]) + MOVE[1:], R("frame.sof"), error="bad_sof")
    for ver in range(1, 64):
        c.add(f"ver.{ver}", "frame.ver", f"header version {ver} (both CRCs right): bad_version",
              frame_bytes(cmd_set=1, cmd_id=3, value=MOVE_VALUE, seq=0x1234, ver=ver), R("frame.ver"),
              error="bad_version")
    for res0 in (1, 2, 3):
        c.add(f"res0.{res0}", "frame.reserved", f"RES0 = {res0}: reserved_bits",
              frame_bytes(cmd_set=1, cmd_id=3, value=MOVE_VALUE, res0=res0), R("frame.reserved") + ["E29"],
              error="reserved_bits")
    for res1 in (0x000001, 0x000080, 0x000100, 0x010000, 0x800000, 0xFFFFFF):
        c.add(f"res1.0x{res1:06x}", "frame.reserved", f"RES1 = 0x{res1:06x}: reserved_bits",
              frame_bytes(cmd_set=1, cmd_id=3, value=MOVE_VALUE, res1=res1), R("frame.reserved") + ["E29"],
              error="reserved_bits")


def add_lengths(c: FrameCases, rng: random.Random) -> None:
    """Impossible LEN values, the shortest frames with DATA, and the longest frame."""
    for length in list(range(0, 12)) + [13, 14, 15, 16]:
        c.add(f"len.{length}", "frame.len", f"LEN {length} (header only, CRC-16 right): impossible_length",
              frame_bytes(length=length, data=b""), R("frame.len") + ["E22"], error="impossible_length")
        if length >= 12:
            data = frame_bytes(length=length, data=b"") + bytes(length - 12)
            c.add(f"len.{length}.with_bytes", "frame.len",
                  f"LEN {length} and {length} bytes in all: still impossible_length", data,
                  R("frame.len") + ["E22"], error="impossible_length")
    c.add("len.17.one_data_byte", "frame.data", "LEN 17: a command frame with only the command set: truncated_payload",
          frame_bytes(data=b"\x01"), R("frame.data", "frame.len") + ["E22"], error="truncated_payload")
    c.add("len.18.set_and_id", "frame.data", "LEN 18: version query with no value byte: truncated_payload",
          frame_bytes(cmd_set=0, cmd_id=0), R("frame.data", "payload.truncated") + ["E22"], error="truncated_payload")
    c.add("len.17.ack_one_byte", "frame.data", "LEN 17: an ACK frame with a 1-byte value (session 1)",
          frame_bytes(is_ack=True, session=1, value=b"\x00"), R("frame.data", "frame.len", "frame.session") + ["E22"])
    big = bytes(rng.getrandbits(8) for _ in range(1005))
    c.add("len.1023", "frame.len", "LEN 1023, the largest frame: an unknown command with a 1005-byte value",
          frame_bytes(cmd_set=0x00, cmd_id=0x7F, value=big), R("frame.len", "payload.unknown") + ["E22"])


def add_header_only(c: FrameCases) -> None:
    for session, is_ack, seq in ((0, False, 0), (5, False, 0xFFFF), (1, True, 1), (31, True, 0x1234)):
        c.add(f"header_only.s{session}{'.ack' if is_ack else ''}", "frame.header_only",
              f"header-only frame (LEN 12, no DATA, no CRC-32), session {session}, {'ACK' if is_ack else 'command'}, "
              f"seq {seq}", frame_bytes(session=session, is_ack=is_ack, seq=seq), R("frame.header_only") + ["E22"])
    c.add("header_only.ack_session0", "frame.session", "header-only ACK in session 0: bad_session",
          frame_bytes(session=0, is_ack=True), R("frame.header_only", "frame.session") + ["E24"], error="bad_session")
    c.add("header_only.ack_session0.enc1", "frame.session",
          "header-only ACK in session 0 with ENC 1 and no padding: two rules broken, the first in wire order "
          "(SESSION/ACK before ENC) is reported: bad_session (found by osdkc fuzz)",
          frame_bytes(session=0, is_ack=True, enc=1), R("frame.header_only", "frame.session", "frame.enc")
          + ["E23", "E24"], error="bad_session")


def add_encryption(c: FrameCases, rng: random.Random) -> None:
    """ENC and PADDING: undefined ENC values, padding on plain frames, AES frames valid and not."""
    for enc in range(2, 8):
        c.add(f"enc.{enc}", "frame.enc", f"ENC {enc} (plain-sized DATA, PADDING 0): bad_encryption",
              frame_bytes(cmd_set=1, cmd_id=3, value=MOVE_VALUE, enc=enc), R("frame.enc") + ["E23"],
              error="bad_encryption")
        c.add(f"enc.{enc}.blocks", "frame.enc", f"ENC {enc} with 16-byte DATA and PADDING 4: bad_encryption",
              frame_bytes(data=bytes(16), enc=enc, padding=4), R("frame.enc") + ["E23"], error="bad_encryption")
    for padding in (1, 15, 16, 31):
        c.add(f"plain.padding.{padding}", "frame.enc", f"plain frame with PADDING {padding}: bad_encryption",
              frame_bytes(cmd_set=1, cmd_id=3, value=MOVE_VALUE, padding=padding), R("frame.enc") + ["E23"],
              error="bad_encryption")
    for blocks, padding in ((1, 1), (1, 16), (2, 7), (4, 16)):
        data = bytes(rng.getrandbits(8) for _ in range(16 * blocks))
        c.add(f"aes.{blocks}blocks.padding{padding}", "frame.aes",
              f"AES frame, {blocks} block(s) of ciphertext, PADDING {padding}: valid, DATA kept raw",
              frame_bytes(data=data, enc=1, padding=padding), R("frame.enc", "frame.aes_raw") + ["E23"])
    c.add("aes.ack", "frame.aes", "AES ACK frame (session 3), one block: valid, kept raw",
          frame_bytes(data=bytes(range(16)), enc=1, padding=14, is_ack=True, session=3),
          R("frame.aes_raw", "frame.session"))
    for padding, blocks, why in ((0, 1, "PADDING 0"), (17, 2, "PADDING 17"), (31, 2, "PADDING 31")):
        c.add(f"aes.padding{padding}", "frame.enc", f"AES frame with {why}: bad_encryption",
              frame_bytes(data=bytes(16 * blocks), enc=1, padding=padding), R("frame.enc") + ["E23"],
              error="bad_encryption")
    for size in (15, 17, 31):
        c.add(f"aes.data{size}", "frame.enc", f"AES frame with {size} bytes of DATA (not whole blocks): bad_encryption",
              frame_bytes(data=bytes(size), enc=1, padding=1), R("frame.enc") + ["E23"], error="bad_encryption")
    c.add("aes.header_only", "frame.enc", "AES flag on a header-only frame: bad_encryption",
          frame_bytes(enc=1, padding=16), R("frame.enc", "frame.header_only") + ["E23"], error="bad_encryption")


def add_sessions_and_values(c: FrameCases) -> None:
    """ACKs and commands per session, an unknown command set, and values that do not decode."""
    for session in (0, 1, 2, 31):
        c.add(f"ack.session{session}", "frame.session",
              f"control ACK frame in session {session}" + (": bad_session" if session == 0 else ""),
              frame_bytes(is_ack=True, session=session, seq=40, value=b"\x02\x00"), R("frame.session", "frame.data")
              + ["E24"])
        c.add(f"command.session{session}", "frame.session", f"control request command in session {session}",
              frame_bytes(cmd_set=1, cmd_id=0, value=b"\x01", session=session, seq=40), R("frame.session"))
    c.add("unknown_set", "frame.valid", "command set 0x05 (no name), id 0x01: value kept raw",
          frame_bytes(cmd_set=5, cmd_id=1, value=b"\x01\x02\x03"), R("frame.data", "payload.unknown", "enums.unnamed"))
    c.add("value.movement_16_bytes", "frame.value", "movement control frame with a 16-byte value: truncated_payload",
          frame_bytes(cmd_set=1, cmd_id=3, value=bytes(16)), R("frame.data", "payload.truncated"))
    c.add("value.broadcast_reserved", "frame.value", "broadcast frame with reserved flag bit 15: reserved_bits",
          frame_bytes(cmd_set=2, cmd_id=0, value=le16(0x8000)), R("broadcast.reserved_flags") + ["E25"])
    c.add("value.broadcast_trailing", "frame.value", "broadcast frame, flag word 0 and one byte: length_mismatch",
          frame_bytes(cmd_set=2, cmd_id=0, value=b"\x00\x00\x00"), R("broadcast.bounds") + ["E25"])
    c.add("value.broadcast_short", "frame.value", "broadcast frame promising a time stamp it lacks: truncated_payload",
          frame_bytes(cmd_set=2, cmd_id=0, value=b"\x01\x00\x01"), R("broadcast.bounds") + ["E25"])


def add_crc_bits(c: FrameCases, bcast: bytes) -> None:
    """Every header bit of the movement frame flipped, then every bit of a broadcast frame."""
    for bit in range(96):
        err = "bad_sof" if bit < 8 else "bad_crc16"
        c.add(f"crc16.bit{bit}", "frame.crc16",
              f"movement frame with header bit {bit} (byte {bit // 8}, bit {bit % 8}) flipped: {err}"
              + (" (the start byte is no longer 0xAA)" if bit < 8 else ""),
              flip(MOVE, bit), R("frame.crc16") + (R("frame.sof") if bit < 8 else []) + ["E21"], error=err)
    for bit in range(len(bcast) * 8):
        err = "bad_sof" if bit < 8 else "bad_crc16" if bit < 96 else "bad_crc32"
        c.add(f"crc32.bit{bit}", "frame.crc32" if bit >= 96 else "frame.crc16",
              f"broadcast frame with bit {bit} (byte {bit // 8}) flipped: {err}", flip(bcast, bit),
              R("frame.crc32" if bit >= 96 else "frame.crc16") + ["E21"], error=err)


def add_truncation(c: FrameCases) -> None:
    for n in range(len(MOVE)):
        c.add(f"truncated.{n}", "frame.truncation", f"the movement frame cut after {n} of {len(MOVE)} bytes: "
              "truncated_frame", MOVE[:n], R("frame.truncation"), error="truncated_frame")
    for extra in (b"\x00", b"\xaa", bytes(12)):
        c.add(f"extra.{len(extra)}.{extra[:1].hex()}", "frame.extra_bytes",
              f"the movement frame followed by {len(extra)} more byte(s): length_mismatch", MOVE + extra,
              R("frame.extra_bytes"), error="length_mismatch")
