"""encode.json: encode_movement_control and encode_frame: the
PROTOCOL-FACTS worked frames, every mode byte, float bit patterns, ACKs,
header-only and maximum-length frames."""
from __future__ import annotations

import struct
from typing import Any

from osdk_conformance.core.rules import classify_control_mode, input_ranges
from osdk_conformance.reference import codec as reference

from .builder import PROFILES, R, Suite
from .control_ranges import mid
from .scalars import F32_SPECIALS, f32, f32_model, f32_next_up
from .wire import WORKED_BROADCAST, WORKED_BROADCAST_VALUE, WORKED_MOVEMENT, WORKED_MOVEMENT_VALUE

MODE_PROFILE = "a3-fw3.1"
"""The profile whose ranges give the setpoints of every mode byte (encoding
does not depend on the profile; any one with every combination will do)."""


def gen_encode() -> Suite:
    s = Suite("encode", "encode_movement_control and encode_frame: the PROTOCOL-FACTS worked frames, every mode "
                        "byte, float bit patterns, ACKs, header-only and maximum-length frames.", seed=707)
    add_movement_controls(s)
    add_worked_and_ack_frames(s)
    add_frame_lengths(s)
    add_random_frames(s)
    return s


def add_movement_control(s: Suite, id: str, category: str, comment: str, mode: int, xs: tuple[int, ...],
                         flags: list[str], **kw: Any) -> None:
    """One encode_movement_control case; a value some profile's check rejects
    is `acceptable`: an encoder may refuse it with that class."""
    data = bytes([mode]) + struct.pack("<4I", *xs)
    problems = {reference.answer("check_movement_control", p, {"hex": data.hex()}).get("error") for p in PROFILES}
    problems.discard(None)
    inp = {"mode": mode, **{k: f32_model(b) for k, b in zip(("x", "y", "z", "yaw"), xs)}}
    if problems and "expected" not in kw:
        why = sorted(problems)[0]
        kw["acceptable"] = why
        comment += f"; check_movement_control rejects it ({why}) in some profile, so an encoder may refuse it"
    s.add("encode_movement_control", None, id, category, comment, inp, flags, **kw)


def add_movement_controls(s: Suite) -> None:
    """The worked value, every mode byte, special floats, random bit patterns."""
    add_movement_control(s, "encode.movement_control.worked", "encode.movement_control",
                         "hand-written: the value of the PROTOCOL-FACTS movement control frame", 0x4B,
                         (f32(1.0), f32(-2.0), f32(0.5), f32(30.0)), R("encode.movement_control", "floats.bit_exact"),
                         expected={"hex": WORKED_MOVEMENT_VALUE})
    for byte in range(256):
        if classify_control_mode(byte, MODE_PROFILE)["combination"]:
            ranges = input_ranges(byte, MODE_PROFILE)
            xs = tuple(f32(mid(ranges[reference.AXIS_RANGE[a]])) for a in ("x", "y", "z", "yaw"))
        else:
            xs = (f32(1.0), f32(2.0), f32(3.0), f32(4.0))
        add_movement_control(s, f"encode.movement_control.mode.0x{byte:02x}", "encode.movement_control",
                             f"mode byte 0x{byte:02x} with fixed setpoints", byte, xs,
                             R("encode.movement_control", "control.fields"))
    for name, bits in F32_SPECIALS.items():
        xs = (bits, f32_next_up(0) if bits != 1 else 0, 0x3F800000, bits)
        add_movement_control(s, f"encode.movement_control.special.{name}", "encode.floats",
                             f"x and yaw {name} (0x{bits:08x}): the bits go to the wire unchanged", 0x48, xs,
                             R("encode.movement_control", "floats.bit_exact"))
    for k in range(20):
        xs = tuple(s.rng.getrandbits(32) for _ in range(4))
        add_movement_control(s, f"encode.movement_control.random_bits.{k}", "encode.floats",
                             "random float32 bit patterns (any NaN kept)", s.rng.getrandbits(8), xs,
                             R("encode.movement_control", "floats.bit_exact"))


def add_frame(s: Suite, id: str, category: str, comment: str, inp: dict, flags: list[str], **kw: Any) -> None:
    s.add("encode_frame", None, id, category, comment, inp, flags, **kw)


def add_worked_and_ack_frames(s: Suite) -> None:
    add_frame(s, "encode.frame.worked.movement_control", "encode.frame",
              "hand-written: the PROTOCOL-FACTS movement control frame (session 0, seq 0x1234)",
              {"cmd_set": 1, "cmd_id": 3, "is_ack": False, "session": 0, "seq": 0x1234,
               "value": WORKED_MOVEMENT_VALUE}, R("encode.frame", "frame.crc16", "frame.crc32") + ["E21"],
              expected={"hex": WORKED_MOVEMENT})
    add_frame(s, "encode.frame.worked.broadcast", "encode.frame",
              "hand-written: the PROTOCOL-FACTS broadcast frame (seq 7, flags 0x1800, flight status 3, battery 87)",
              {"cmd_set": 2, "cmd_id": 0, "is_ack": False, "session": 0, "seq": 7, "value": WORKED_BROADCAST_VALUE},
              R("encode.frame", "frame.crc16", "frame.crc32") + ["E21"], expected={"hex": WORKED_BROADCAST})
    add_frame(s, "encode.frame.header_only_ack", "encode.frame", "an ACK with an empty value is the 12-byte header alone",
              {"is_ack": True, "session": 2, "seq": 513, "value": ""}, R("encode.frame", "frame.header_only") + ["E22"])
    for session in (1, 2, 31):
        add_frame(s, f"encode.frame.ack.session{session}", "encode.frame", f"control ACK (obtained) in session {session}",
                  {"is_ack": True, "session": session, "seq": 40, "value": "0200"},
                  R("encode.frame", "frame.session") + ["E24"])
    add_frame(s, "encode.frame.ack.session0", "encode.frame", "an ACK in session 0 cannot be sent: bad_session",
              {"is_ack": True, "session": 0, "seq": 40, "value": "0200"}, R("encode.frame", "frame.session") + ["E24"],
              error="bad_session")
    add_frame(s, "encode.frame.lost_control_ack", "encode.frame", "the 2-byte zero answer to lost control, session 4",
              {"is_ack": True, "session": 4, "seq": 9, "value": "0000"},
              R("encode.frame", "payload.lost_control_ack") + ["E24"])


def add_frame_lengths(s: Suite) -> None:
    """The longest command and ACK, one byte more, and the largest SEQ."""
    add_frame(s, "encode.frame.max_command", "encode.frame", "a command with a 1005-byte value: LEN 1023, the maximum",
              {"cmd_set": 0, "cmd_id": 0x7F, "is_ack": False, "session": 0, "seq": 1, "value": bytes(1005).hex()},
              R("encode.frame", "frame.len") + ["E22"])
    add_frame(s, "encode.frame.too_long_command", "encode.frame", "a command with a 1006-byte value would need LEN "
              "1024: impossible_length", {"cmd_set": 0, "cmd_id": 0x7F, "is_ack": False, "session": 0, "seq": 1,
                                          "value": bytes(1006).hex()}, R("encode.frame", "frame.len") + ["E22"],
              error="impossible_length")
    add_frame(s, "encode.frame.max_ack", "encode.frame", "an ACK with a 1007-byte value: LEN 1023",
              {"is_ack": True, "session": 1, "seq": 1, "value": bytes(1007).hex()},
              R("encode.frame", "frame.len") + ["E22"])
    add_frame(s, "encode.frame.too_long_ack", "encode.frame", "an ACK with a 1008-byte value: impossible_length",
              {"is_ack": True, "session": 1, "seq": 1, "value": bytes(1008).hex()},
              R("encode.frame", "frame.len") + ["E22"], error="impossible_length")
    add_frame(s, "encode.frame.too_long_ack_session0", "encode.frame", "an ACK in session 0 with a 1008-byte value "
              "breaks two rules: the length is checked first, impossible_length",
              {"is_ack": True, "session": 0, "seq": 1, "value": bytes(1008).hex()},
              R("encode.frame", "frame.len", "frame.session") + ["E22", "E24"], error="impossible_length")
    add_frame(s, "encode.frame.seq_max", "encode.frame", "SEQ 0xFFFF, session 31",
              {"cmd_set": 1, "cmd_id": 0, "is_ack": False, "session": 31, "seq": 0xFFFF, "value": "01"},
              R("encode.frame", "frame.session"))


def add_random_frames(s: Suite) -> None:
    rng = s.rng
    for k in range(30):
        is_ack = rng.random() < 0.3
        value = bytes(rng.getrandbits(8) for _ in range(rng.randrange(0 if is_ack else 0, 60)))
        inp: dict[str, Any] = {"is_ack": is_ack, "session": rng.randrange(1 if is_ack else 0, 32),
                               "seq": rng.getrandbits(16), "value": value.hex()}
        if not is_ack:
            inp = {"cmd_set": rng.randrange(4), "cmd_id": rng.getrandbits(8), **inp}
        add_frame(s, f"encode.frame.random.{k}", "encode.frame", f"random {'ACK' if is_ack else 'command'} frame #{k}",
                  inp, R("encode.frame", "frame.crc16", "frame.crc32"))
