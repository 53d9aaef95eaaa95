"""streams.json: decode_stream: frames found in byte streams as the SDK
receiver finds them: garbage, resynchronisation after bad headers and
CRCs, a frame hidden in a corrupt one, reads split at every point,
truncated tails, and ACKs decoded from their command."""
from __future__ import annotations

import struct
from typing import Any

from osdk_conformance._construct.payload import VERSION_ID_SIZE, has_version_id

from osdk_conformance.core.rules import profile as rules_profile

from .acks import add_ack_memory, add_ack_situations
from .broadcast_values import Values, payload
from .builder import PROFILES, R, Suite
from .header_bits import add_header_bits
from .precedence import add_rule_pairs
from .stream_errors import add_stream_errors
from .wire import WORKED_MOVEMENT, flip, frame_bytes

MOVE = bytes.fromhex(WORKED_MOVEMENT)


class StreamCases:
    """The cases of one profile (ids under streams.<profile>), with a
    broadcast frame of every item and noise drawn from the suite's generator."""

    def __init__(self, s: Suite, profile: str) -> None:
        self.s = s
        self.profile = profile
        self.rng = s.rng
        self.bc = frame_bytes(cmd_set=2, cmd_id=0, seq=9,
                              value=payload(profile, rules_profile(profile).all_flags, Values(s.rng)))

    def add(self, name: str, category: str, comment: str, data: bytes, flags: list[str],
            chunks: list[int] | None = None, **kw: Any) -> None:
        self.s.add("decode_stream", self.profile, f"streams.{self.profile}.{name}", category, comment,
                   {"hex": data.hex(), "chunks": chunks if chunks is not None else [len(data)]}, flags, **kw)

    def noise(self, n: int, allow_sof: bool = False) -> bytes:
        """n random bytes, without the start byte 0xAA unless allowed."""
        out = bytearray()
        while len(out) < n:
            b = self.rng.getrandbits(8)
            if b != 0xAA or allow_sof:
                out.append(b)
        return bytes(out)


def gen_streams() -> Suite:
    s = Suite("streams", "decode_stream: frames found in byte streams as the SDK receiver finds them: garbage, "
                         "resynchronisation after bad headers and CRCs, a frame hidden in a corrupt one, reads split "
                         "at every point, truncated tails, and ACKs decoded from their command.", seed=606)
    for profile in PROFILES:
        c = StreamCases(s, profile)
        garbage = add_garbage(c)
        add_resync(c)
        add_truncated_tails_and_splits(c, garbage)
        add_ack_matching(c)
        add_ack_memory(c.add, profile)
        add_random_mix(c)
        add_long_streams(c)
        add_stream_errors(profile, c.add)
        add_rule_pairs(profile, "decode_stream", "precedence", c.add)
        add_header_bits(c.add, stream=True)
        add_ack_situations(s, profile)
    return s


def add_garbage(c: StreamCases) -> tuple[bytes, bytes, bytes]:
    """Frames back to back, garbage around them, and noise full of false
    start bytes; returns the three garbage runs, fed again byte by byte later."""
    c.add("back_to_back", "stream.frames", "the worked movement frame, a broadcast, a version query (session 1) and "
          "a header-only frame, back to back",
          MOVE + c.bc + frame_bytes(cmd_set=0, cmd_id=0, value=b"\x01", session=1, seq=3) + frame_bytes(session=2, seq=4),
          R("frame.sof", "frame.header_only", "frame.len"))
    g1, g2, g3 = c.noise(5), c.noise(17), c.noise(3)
    c.add("garbage_between", "stream.garbage", "garbage (no 0xAA) before, between and after two frames: three "
          "garbage runs", g1 + MOVE + g2 + c.bc + g3, R("stream.garbage", "frame.sof"))
    c.add("garbage_only", "stream.garbage", "64 bytes without a start byte: one garbage event", c.noise(64),
          R("stream.garbage"))
    c.add("empty", "stream.garbage", "no bytes at all: no events", b"", R("stream.garbage"))
    for k in range(3):
        n = c.noise(48, allow_sof=True)
        n = bytes(0xAA if i % 7 == k else b for i, b in enumerate(n))
        c.add(f"noise_with_sof.{k}", "stream.resync", "noise with many 0xAA bytes, then the movement frame: each "
              "false start byte is rejected (drop one byte, rescan), then the frame is found", n + MOVE,
              R("stream.resync", "frame.crc16"))
    return g1, g2, g3


def add_resync(c: StreamCases) -> None:
    """After a bad header or CRC, scanning resumes and finds the next frame,
    also one hidden inside the corrupt frame's DATA."""
    bad_ver = frame_bytes(cmd_set=1, cmd_id=3, value=MOVE[14:-4], ver=1)
    c.add("bad_version_then_frame", "stream.resync", "a frame with VER 1, then a good frame: bad_version, garbage, "
          "frame", bad_ver + MOVE, R("stream.resync", "frame.ver"))
    bad_len = frame_bytes(length=14, data=b"")
    c.add("impossible_length_then_frame", "stream.resync", "a header with LEN 14, then a good frame",
          bad_len + MOVE, R("stream.resync", "frame.len") + ["E22"])
    c.add("bad_crc16_then_frame", "stream.resync", "the movement frame with a wrong CRC-16, then a broadcast",
          flip(MOVE, 8 * 10) + c.bc, R("stream.resync", "frame.crc16"))
    c.add("bad_crc32_then_frame", "stream.resync", "the movement frame with a wrong CRC-32, then a broadcast: "
          "bad_crc32 covers the frame, the rest is rescanned", flip(MOVE, len(MOVE) * 8 - 1) + c.bc,
          R("stream.resync", "frame.crc32"))
    outer = bytearray(frame_bytes(cmd_set=0x00, cmd_id=0x7E, value=b"\x11\x22" + MOVE + b"\x33"))
    outer[-1] ^= 0x5A
    c.add("hidden_frame", "stream.resync", "an unknown command whose value carries the whole movement frame, with a "
          "wrong CRC-32: bad_crc32 at 0, then the inner frame is found at offset 16",
          bytes(outer), R("stream.resync", "frame.crc32"))


def add_truncated_tails_and_splits(c: StreamCases, garbage: tuple[bytes, bytes, bytes]) -> None:
    """A frame cut off at the end of the stream, a frame split over two reads
    at every point, byte-wise and empty reads, and values that do not decode."""
    bc = c.bc
    for cut in (1, 5, 12, 20, len(MOVE) - 1):
        c.add(f"truncated_tail.{cut}", "stream.truncated_tail",
              f"a broadcast, then the first {cut} bytes of the movement frame: truncated_frame (then rescanned)",
              bc + MOVE[:cut], R("stream.truncated_tail", "frame.truncation"))
    for k in range(1, len(MOVE)):
        c.add(f"split.{k}", "stream.chunking", f"the movement frame in two reads of {k} and {len(MOVE) - k} bytes",
              MOVE, R("stream.chunking"), chunks=[k, len(MOVE) - k])
    g1, g2, g3 = garbage
    everything = g1 + MOVE + g2 + bc + g3
    c.add("split.bytewise", "stream.chunking", "garbage, two frames and garbage, one byte per read",
          everything, R("stream.chunking", "stream.garbage"), chunks=[1] * len(everything))
    c.add("split.empty_reads", "stream.chunking", "reads of 0 bytes between the pieces change nothing", MOVE + bc,
          R("stream.chunking"), chunks=[0, 7, 0, 0, 30, 0, len(MOVE + bc) - 37])
    c.add("value_error", "stream.frames", "a broadcast promising more than it carries: an error event with its "
          "length, then the next frame", frame_bytes(cmd_set=2, cmd_id=0, value=b"\x02\x00\x01") + MOVE,
          R("broadcast.bounds") + ["E25"])
    c.add("ack_session0", "stream.frames", "an ACK frame in session 0: bad_session as an error event",
          frame_bytes(is_ack=True, session=0, value=b"\x00\x00") + MOVE, R("frame.session") + ["E24"])


def add_ack_matching(c: StreamCases) -> None:
    """An ACK decodes with the layout of the command it answers (same session and SEQ), else stays raw."""
    cmd = frame_bytes(cmd_set=1, cmd_id=0, value=b"\x01", session=2, seq=40)
    ack = frame_bytes(is_ack=True, value=b"\x03\x00", session=2, seq=40)
    c.add("ack.matched", "stream.ack", "obtain control (session 2, seq 40) then its ACK 3: the ACK decodes as "
          "obtain_in_progress", cmd + ack, R("stream.ack_match", "payload.control_ack") + ["E26"])
    c.add("ack.matched_bad_value", "stream.ack", "obtain control, then an ACK with a 3-byte value: decoded as the "
          "control ACK, length_mismatch", cmd + frame_bytes(is_ack=True, value=b"\x03\x00\x00", session=2, seq=40),
          R("stream.ack_match", "payload.trailing"))
    c.add("ack.unmatched", "stream.ack", "an ACK with no command before it: a frame with the raw ACK value",
          ack + cmd, R("stream.ack_match"))
    c.add("ack.other_seq", "stream.ack", "an ACK whose SEQ matches no command: raw", cmd +
          frame_bytes(is_ack=True, value=b"\x03\x00\x00", session=2, seq=41), R("stream.ack_match"))
    version_id = bytes(VERSION_ID_SIZE if has_version_id(c.profile) else 0)  # ERRATA E30
    version_ack = struct.pack("<HI", 0xFF01, 7) + version_id + bytes(32)
    for session, outcome in ((2, "matched"), (1, "never matched: DJI's receivers match sessions 2 to 31 only, raw")):
        vq = frame_bytes(cmd_set=0, cmd_id=0, value=b"\x00", session=session, seq=77)
        vack = frame_bytes(is_ack=True, session=session, seq=77, value=version_ack)
        c.add(f"ack.session{session}_version", "stream.ack",
              f"get version in session {session} and its ACK (not_activated): {outcome}",
              vq + vack, R("stream.ack_match", "payload.version_ack") + ["E24", "E30"])
    lc = frame_bytes(cmd_set=2, cmd_id=1, value=b"\x04", session=3, seq=5)
    lack = frame_bytes(is_ack=True, session=3, seq=5, value=b"\x00\x00")
    c.add("ack.lost_control", "stream.ack", "a lost-control push in session 3 and the device's 2-byte zero ACK",
          lc + lack, R("stream.ack_match", "payload.lost_control_ack") + ["E24"])
    mc0 = frame_bytes(cmd_set=1, cmd_id=3, value=MOVE[14:-4], session=0, seq=6)
    c.add("ack.session0_command", "stream.ack", "a movement command in session 0 wants no ACK; a later ACK with "
          "session 1 and the same SEQ is not matched", mc0 + frame_bytes(is_ack=True, session=1, seq=6, value=b"\x00"),
          R("stream.ack_match", "frame.session"))


def random_part(c: StreamCases) -> bytes:
    """Noise, the movement frame, the broadcast frame (intact or with a bit
    flipped), or a set-frequency command, at random."""
    rng = c.rng
    choice = rng.randrange(5)
    if choice == 0:
        return c.noise(rng.randrange(1, 20), allow_sof=True)
    if choice == 1:
        return MOVE
    if choice == 2:
        return c.bc
    if choice == 3:
        return flip(c.bc, rng.randrange(len(c.bc) * 8))
    return frame_bytes(cmd_set=0, cmd_id=0x10, value=bytes(rng.randrange(6) for _ in range(16)),
                       session=rng.randrange(32), seq=rng.getrandbits(16))


def add_random_mix(c: StreamCases) -> None:
    for k in range(3):
        data = b"".join(random_part(c) for _ in range(8))
        sizes, left = [], len(data)
        while left > 0:
            sizes.append(min(left, c.rng.randrange(1, 40)))
            left -= sizes[-1]
        c.add(f"mix.{k}", "stream.mix", f"random mix #{k} of frames, corrupted frames and noise, random read sizes",
              data, R("stream.resync", "stream.chunking"), chunks=sizes)


RECEIVE_BUFFERS = (300, 1024)
"""Receive-buffer sizes of known receivers: every long stream below crosses both."""
MAX_LEN = 1023


def _small_reads(c: StreamCases, n: int) -> list[int]:
    sizes, left = [], n
    while left > 0:
        sizes.append(min(left, c.rng.randrange(1, 64)))
        left -= sizes[-1]
    return sizes


def add_long_streams(c: StreamCases) -> None:
    """Streams longer than a receive buffer: a receiver that keeps its
    garbage, its half-read frame or its header in a fixed buffer must not
    lose the frame after it. Each whole and in small reads."""
    unknown = (0x00, 0x7E)
    max_frame = frame_bytes(cmd_set=unknown[0], cmd_id=unknown[1], value=c.noise(MAX_LEN - 12 - 2 - 4, allow_sof=True),
                            session=0, seq=11)
    mid_frame = frame_bytes(cmd_set=unknown[0], cmd_id=unknown[1], value=c.noise(400, allow_sof=True), session=0,
                            seq=12)
    assert len(max_frame) == MAX_LEN
    long_header = frame_bytes(cmd_set=unknown[0], cmd_id=unknown[1], value=b"", length=MAX_LEN, data=b"")[:12]
    cases = {
        "noise_then_frame": ("1,100 bytes of noise without a start byte, then the movement frame: one garbage event",
                             c.noise(1100) + MOVE, R("stream.garbage", "stream.long")),
        "noise_with_sof_then_frame": ("1,100 bytes of noise with false start bytes, then the movement frame",
                                      c.noise(1100, allow_sof=True) + MOVE, R("stream.resync", "stream.long")),
        "max_frame_then_frame": (f"a {MAX_LEN}-byte frame (the largest LEN), then the movement frame and a broadcast",
                                 max_frame + MOVE + c.bc, R("frame.len", "stream.long")),
        "frames_past_buffer": (f"a {len(mid_frame)}-byte frame, then movement frames back to back past 1,100 bytes",
                               mid_frame + MOVE * ((1100 - len(mid_frame)) // len(MOVE) + 1),
                               R("frame.len", "stream.long")),
        "long_len_header_then_frame": (f"a good header announcing LEN {MAX_LEN} (no frame follows it), then the "
                                       "movement frame and 1,000 bytes of noise: bad_crc32 over the announced length, "
                                       "then the rescan finds the frame", long_header + MOVE + c.noise(1000),
                                       R("stream.resync", "frame.crc32", "stream.long")),
        "long_len_header_cut": (f"a good header announcing LEN {MAX_LEN}, then the movement frame and 600 bytes of "
                                "noise, and the stream ends before the announced length: truncated_frame, then the "
                                "rescan finds the frame", long_header + MOVE + c.noise(600),
                                R("stream.truncated_tail", "stream.long")),
    }
    for name, (comment, data, flags) in cases.items():
        assert len(data) > RECEIVE_BUFFERS[0], name
        c.add(f"long.{name}", "stream.long", comment, data, flags)
        c.add(f"long.{name}.small_reads", "stream.long", comment + "; in reads of 1 to 63 bytes", data,
              flags + R("stream.chunking"), chunks=_small_reads(c, len(data)))

