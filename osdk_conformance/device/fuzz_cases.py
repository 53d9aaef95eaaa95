"""The cases `osdkc fuzz --port` sends to a flight controller.

A case is a short burst of bytes, sent as one or more writes (a frame split
across writes is a case of its own), with an id that names its kind: the
id goes into the capture as the block comment of every write, and the
kind is a row of the verdict's coverage table. Cases come from three
places, none of them a second generator:

- the golden vectors' invalid inputs (every header rule broken, bad
  CRC-16/32, impossible lengths, truncated frames, bad encryption fields,
  wrong session and ACK bits; the streams with their read splits; the
  invalid values of the commands an onboard computer sends, in valid
  frames);
- the differential fuzzer's Hypothesis strategies (harness/fuzz.py
  `drawn_inputs`): mutated frames and streams, drawn by seed;
- the spec's own tables, for what is only meaningful on a live link:
  every LEN boundary up to 1023 with and without the rest of the frame,
  valid frames cut short or split at every point, garbage runs, command
  sets and ids the spec does not know, and the commands with boundary
  values (version query, activation, set frequency, control release).

Safety (`safe`): by default no case may carry anything a flight controller
could take for movement control or for a request of control authority.
Every position of a start byte is looked at as if a frame began there,
encrypted or not, garbage or not: a case in which command set 1 shows
with anything but a release request (command 0, value 0) is withheld and
counted. With `allow_motion`, movement control is allowed only with zero
setpoints in a velocity mode (horizontal and vertical velocity, yaw rate),
and obtaining control only as the session's own request.
"""
from __future__ import annotations

import random
import struct
from dataclasses import dataclass
from typing import Iterator

from osdk_conformance._construct.control import encode_movement_control
from osdk_conformance._construct.enums import COMMAND_SET
from osdk_conformance._construct.payload import osdk_payload

from osdk_conformance.core.crc import crc16, crc32
from osdk_conformance.core.deframe import HEADER_LEN, MAX_LEN, SOF, split_chunks
from osdk_conformance.core.rules import profile as load_profile
from osdk_conformance.core.wire import encode
from osdk_conformance.harness.fuzz import drawn_inputs
from osdk_conformance.harness.vectors import VECTORS_DIR, load_cases

KINDS: dict[str, str] = {
    "vector.frame": "the golden vectors' invalid frames: each header rule broken, bad CRC-16/32, impossible "
                    "lengths, truncation, encryption fields, session and ACK bits",
    "vector.stream": "the golden vectors' streams, in their read splits (garbage, interrupted frames)",
    "vector.payload": "the golden vectors' invalid values of the commands an onboard computer sends, in valid frames",
    "generated.frame": "frames drawn from the differential fuzzer's strategies (boundary header fields, mutations)",
    "generated.stream": "streams drawn from the differential fuzzer's strategies, split across writes",
    "header": "a version query with each header rule broken in turn (SOF, VER, RES0, RES1, LEN, CRC-16, CRC-32), "
              "the CRC-16 made right again where it is not the rule",
    "length": "headers with a good CRC-16 and every boundary LEN up to 1023: alone, whole, whole with a bad CRC-32",
    "truncated": "valid commands cut short at every length",
    "split": "valid commands split across two writes at every point, and byte by byte",
    "garbage": "runs of random bytes, of start bytes, and of start bytes with random headers",
    "encryption": "frames with bad encryption fields: ENC 2 to 7, PADDING that does not fit, ciphertext "
                  "that is not whole AES blocks",
    "session": "wrong session and ACK bits: ACK frames sent to the flight controller, commands in every session",
    "unknown.set": "valid frames with command sets the spec does not know",
    "unknown.id": "valid frames with unknown command ids in the known command sets",
    "command.version": "version queries with boundary values and value lengths",
    "command.activation": "activation requests with boundary app ids, API levels and SDK versions",
    "command.frequency": "set frequency with boundary codes (the run restores the rates after each)",
    "command.control": "control authority: release with boundary value lengths (other values need --allow-motion)",
    "movement.zero": "movement control with zero setpoints in a velocity mode, framed every way (--allow-motion)",
}
"""Case kinds, in the order the session takes them round-robin; `osdkc fuzz
--help` and docs/DEVICE-FUZZING.md list them from here."""

MOTION_KINDS = frozenset({"movement.zero"})
ZERO_VELOCITY_MODES = tuple(range(0x48, 0x50))
"""Control mode bytes of horizontal velocity, vertical velocity and yaw rate
(rules.yaml combination 4, any frame bits): zero setpoints hold position."""
VECTOR_FILES = ("frames.json", "streams.json", "payloads.json")
"""The suites holding the frames, streams and command values cases come from
(not broadcast.json: broadcast values are what the device sends, not receives)."""
GENERATED_BATCH = 64
SEED_STRIDE = 7919
LENGTH_BOUNDARIES = (0, 1, 11, 12, 13, 15, 16, 17, 18, 19, 64, 255, 256, 299, 300, 301, 512, 1022, MAX_LEN)
COMMANDS_SENT = ((0x00, 0x00), (0x00, 0x01), (0x00, 0x10), (0x01, 0x00), (0x01, 0x03))
"""The commands an onboard computer sends (version, activation, frequency,
control authority, movement control)."""


@dataclass(frozen=True)
class FuzzCase:
    id: str
    kind: str
    writes: tuple[bytes, ...]
    source: str = ""   # the vector id or strategy seed it comes from

    @property
    def data(self) -> bytes:
        return b"".join(self.writes)

    def to_json(self) -> dict:
        return {"id": self.id, "kind": self.kind, "source": self.source, "writes": [w.hex() for w in self.writes]}

    @classmethod
    def from_json(cls, d: dict) -> "FuzzCase":
        return cls(str(d["id"]), str(d["kind"]), tuple(bytes.fromhex(w) for w in d["writes"]), str(d.get("source", "")))


# ---------------------------------------------------------------- safety


def _motion_free(frame_at: bytes, allow_motion: bool) -> bool:
    """Whether bytes that may be a frame starting here carry nothing that
    moves the aircraft or takes control (module doc)."""
    if len(frame_at) < HEADER_LEN + 2 or frame_at[HEADER_LEN] != 0x01:
        return True
    cmd_id, value = frame_at[HEADER_LEN + 1], frame_at[HEADER_LEN + 2:]
    if cmd_id == 0x00:   # control authority: only a release, unless motion is allowed
        return not value or value[0] == 0 or allow_motion
    if cmd_id == 0x03 and allow_motion:
        return zero_velocity(value)
    return False   # movement control, and every other command of the control set


def zero_velocity(value: bytes) -> bool:
    """A movement control value that can only hold position: a velocity mode
    byte and four zero setpoints (+0.0 or -0.0), or fewer bytes than that."""
    if not value or value[0] not in ZERO_VELOCITY_MODES:
        return False
    setpoints = value[1:17]
    return all(struct.unpack_from("<I", setpoints.ljust(16, b"\0"), i)[0] & 0x7FFFFFFF == 0 for i in range(0, 16, 4))


def safe(data: bytes, allow_motion: bool = False) -> bool:
    """No start byte in `data` begins anything that moves the aircraft or takes control."""
    start = data.find(SOF)
    while start >= 0:
        if not _motion_free(data[start:start + HEADER_LEN + 19], allow_motion):
            return False
        start = data.find(SOF, start + 1)
    return True


# ---------------------------------------------------------------- building blocks


def _with_crcs(header10: bytes, body: bytes = b"", good_crc32: bool = True) -> bytes:
    head = header10 + struct.pack("<H", crc16(header10))
    if not body:
        return head
    crc = crc32(head + body)
    return head + body + struct.pack("<I", crc if good_crc32 else crc ^ 0xFFFFFFFF)


def _header10(length: int, session: int = 0, seq: int = 0, is_ack: bool = False, padding: int = 0,
              enc: int = 0) -> bytes:
    word = length & 0x3FF
    return (bytes([SOF, word & 0xFF, word >> 8, session & 0x1F | is_ack << 5, padding & 0x1F | (enc & 7) << 5,
                   0, 0, 0]) + struct.pack("<H", seq))


def _frame_of(data: bytes, **header) -> bytes:
    """A frame around DATA with any header fields, CRCs right."""
    return _with_crcs(_header10(HEADER_LEN + len(data) + 4, **header), data)


def command_value(profile: str, cmd_set: int, cmd_id: int, body: dict) -> bytes:
    return osdk_payload(cmd_set, cmd_id, False, profile).build({"body": body})


class Builder:
    """The cases of one session: profile, seed and what may be sent."""

    def __init__(self, profile: str, seed: int, allow_motion: bool = False) -> None:
        self.profile = profile
        self.prof = load_profile(profile)
        self.seed = seed
        self.allow_motion = allow_motion
        self.rng = random.Random(seed)
        self.seq = 0x4000   # case SEQs stay clear of the probes' (device/liveness.py starts at 1)
        self.withheld: dict[str, int] = {}

    def _seq(self) -> int:
        self.seq = self.seq + 1 & 0xFFFF or 0x4000
        return self.seq

    def frame(self, cmd_set: int, cmd_id: int, value: bytes, session: int = 2) -> bytes:
        return encode(cmd_set=cmd_set, cmd_id=cmd_id, value=value, session=session, seq=self._seq())

    def version_query(self) -> bytes:
        return self.frame(0, 0, command_value(self.profile, 0, 0, {"arbitrary": 0}))

    # ---- the kinds -------------------------------------------------------

    def vector_cases(self) -> dict[str, list[tuple[tuple[bytes, ...], str]]]:
        out: dict[str, list] = {"vector.frame": [], "vector.stream": [], "vector.payload": []}
        for c in load_cases([VECTORS_DIR / name for name in VECTOR_FILES]):
            if c.profile != self.profile:
                continue
            if c.operation == "decode_frame" and c.result == "invalid":
                out["vector.frame"].append(((bytes.fromhex(c.input["hex"]),), c.id))
            elif c.operation == "decode_stream":
                data = bytes.fromhex(c.input["hex"])
                out["vector.stream"].append((tuple(w for w in split_chunks(data, c.input.get("chunks", [])) if w),
                                             c.id))
            elif (c.operation == "decode_payload" and c.result == "invalid" and not c.input["is_ack"]
                  and (c.input["cmd_set"], c.input["cmd_id"]) in COMMANDS_SENT):
                value = bytes.fromhex(c.input["hex"])
                out["vector.payload"].append(((self.frame(c.input["cmd_set"], c.input["cmd_id"], value),), c.id))
        return out

    def header_cases(self) -> list[tuple[tuple[bytes, ...], str]]:
        query = self.version_query()
        body = query[HEADER_LEN:-4]

        def broken(change, note: str, crc32_right: bool = True):
            h = bytearray(query[:10])
            change(h)
            head = bytes(h) + struct.pack("<H", crc16(bytes(h)))
            crc = crc32(head + body)
            return ((head + body + struct.pack("<I", crc if crc32_right else crc ^ 1),), note)

        def field(i: int, value: int):
            def change(h: bytearray) -> None:
                h[i] = value
            return change
        out = [broken(field(0, b), f"SOF {b:#04x}") for b in (0x55, 0xAB, 0x00)]
        out += [broken(field(2, query[2] & 3 | ver << 2), f"VER {ver}") for ver in (1, 2, 63)]
        out += [broken(field(3, query[3] | r << 6), f"RES0 {r}") for r in (1, 2, 3)]
        out += [broken(field(i, 1 << bit), f"RES1 byte {i - 5} bit {bit}") for i in (5, 6, 7) for bit in (0, 7)]
        out += [broken(field(1, n), f"LEN {n} (impossible)") for n in (0, 11, 13, 14, 15, 16)]
        out.append(((query[:10] + bytes([query[10] ^ 1, query[11]]) + query[12:],), "CRC-16 wrong"))
        out.append(broken(lambda h: None, "CRC-32 wrong", crc32_right=False))
        return out

    def length_cases(self) -> list[tuple[tuple[bytes, ...], str]]:
        out = []
        for n in LENGTH_BOUNDARIES:
            out.append(((_with_crcs(_header10(n, seq=self._seq())),), f"LEN {n}, header alone"))
            if n > HEADER_LEN + 4:
                # command set 0, id 0 (a version query) in a body of LEN n
                body = bytes(n - HEADER_LEN - 4)
                h = _header10(n, session=2, seq=self._seq())
                out.append(((_with_crcs(h, body),), f"LEN {n}, whole frame"))
                out.append(((_with_crcs(h, body, good_crc32=False),), f"LEN {n}, whole frame, bad CRC-32"))
        return out

    def valid_commands(self) -> list[bytes]:
        p = self.profile
        return [self.version_query(),
                self.frame(0, 1, command_value(p, 0, 1, {"app_id": 0, "api_level": 2,
                                                          "sdk_version": self.prof.sdk_version,
                                                          "bundle_id": bytes(32)})),
                self.frame(0, 0x10, command_value(p, 0, 0x10, {"codes": [5] * 16})),
                self.frame(1, 0, command_value(p, 1, 0, {"request": 0}))]

    def truncated_cases(self) -> list[tuple[tuple[bytes, ...], str]]:
        return [((f[:n],), f"command {f[12]:#04x}/{f[13]:#04x} cut to {n} of {len(f)} bytes")
                for f in self.valid_commands() for n in range(1, len(f))]

    def split_cases(self) -> list[tuple[tuple[bytes, ...], str]]:
        out = []
        for f in self.valid_commands():
            out += [((f[:n], f[n:]), f"command {f[12]:#04x}/{f[13]:#04x} split after {n} bytes")
                    for n in range(1, len(f))]
            out.append((tuple(f[i:i + 1] for i in range(len(f))), f"command {f[12]:#04x}/{f[13]:#04x} byte by byte"))
        return out

    def garbage_cases(self) -> list[tuple[tuple[bytes, ...], str]]:
        r = random.Random(self.seed ^ 0x6A7B)
        out = []
        for n in (1, 2, 11, 12, 13, 64, 300, 301, 1024, 2048):
            out.append(((r.randbytes(n),), f"{n} random bytes"))
            out.append(((bytes([SOF]) * n,), f"{n} start bytes"))
        for _ in range(32):
            out.append(((bytes([SOF]) + r.randbytes(r.randrange(11, 40)),), "a start byte and a random header"))
        return out

    def encryption_cases(self) -> list[tuple[tuple[bytes, ...], str]]:
        r = random.Random(self.seed ^ 0x3C1F)
        query = bytes([0, 0]) + command_value(self.profile, 0, 0, {"arbitrary": 0})
        out = [((_frame_of(query, session=2, seq=self._seq(), enc=e),), f"ENC {e}, a plain version query")
               for e in range(2, 8)]
        for blocks, pad in ((1, 0), (1, 16), (1, 17), (2, 31), (1, 1), (2, 15)):
            out.append(((_frame_of(r.randbytes(16 * blocks), session=2, seq=self._seq(), enc=1, padding=pad),),
                        f"ENC 1, {blocks} block(s), PADDING {pad}"))
        for n in (1, 15, 17, 33):
            out.append(((_frame_of(r.randbytes(n), session=2, seq=self._seq(), enc=1, padding=1),),
                        f"ENC 1, {n} bytes of ciphertext"))
        out.append(((_frame_of(query, session=2, seq=self._seq(), enc=0, padding=5),), "ENC 0 with PADDING 5"))
        return out

    def session_cases(self) -> list[tuple[tuple[bytes, ...], str]]:
        query = bytes([0, 0]) + command_value(self.profile, 0, 0, {"arbitrary": 0})
        ack = bytes(2)   # an ACK code of success
        out = [((_frame_of(ack, session=s, seq=self._seq(), is_ack=True),), f"an ACK frame in session {s}")
               for s in (0, 1, 2, 31)]
        out += [((_frame_of(query, session=s, seq=self._seq()),), f"a version query in session {s}")
                for s in (0, 1, 3, 16, 30, 31)]
        out.append(((_with_crcs(_header10(HEADER_LEN, session=2, seq=self._seq(), is_ack=True)),),
                    "a header-only ACK frame"))
        q = _frame_of(query, session=2, seq=self._seq())
        out.append(((q + q,), "the same version query twice (a retransmission)"))
        return out

    def unknown_cases(self) -> tuple[list, list]:
        known = set(COMMAND_SET.values())
        unknown_sets = [s for s in range(256) if s not in known]
        sets = [((self.frame(s, self.rng.randrange(256), self.rng.randbytes(self.rng.randrange(0, 4))),),
                 f"command set {s:#04x}") for s in unknown_sets]
        known_ids = {(s, i) for s, i in COMMANDS_SENT} | {(2, 0), (2, 1)}
        # not in the control set (1): its other ids are gimbal and flight commands in DJI's later SDKs
        ids = [((self.frame(s, i, self.rng.randbytes(self.rng.randrange(0, 4))),), f"command {s:#04x}/{i:#04x}")
               for s in sorted(known) if s != 1 for i in range(256) if (s, i) not in known_ids]
        return sets, ids

    def command_cases(self) -> dict[str, list]:
        p, prof = self.profile, self.prof
        q = command_value(p, 0, 0, {"arbitrary": 0})
        version = [((self.frame(0, 0, v),), note) for v, note in (
            (bytes([0xFF]), "value 0xFF"), (b"", "no value"), (q + b"\0", "one byte too many"),
            (bytes(64), "64 zero bytes"), (bytes([0xFF]) * 200, "200 bytes"))]
        version += [((self.frame(0, 0, q, session=s),), f"session {s}") for s in (0, 1, 31)]

        def activation(app_id: int, level: int, sdk: int, note: str):
            v = command_value(p, 0, 1, {"app_id": app_id, "api_level": level, "sdk_version": sdk,
                                        "bundle_id": bytes(32)})
            return ((self.frame(0, 1, v),), note)
        activation_cases = [activation(a, 2, prof.sdk_version, f"app id {a:#x}") for a in (0, 1, 0x7FFFFFFF, 0xFFFFFFFF)]
        activation_cases += [activation(1, lv, prof.sdk_version, f"API level {lv}") for lv in (0, 3, 0xFFFFFFFF)]
        activation_cases += [activation(1, 2, sdk, f"SDK version {sdk:#x}") for sdk in (0, 0xFFFFFFFF)]
        a = command_value(p, 0, 1, {"app_id": 1, "api_level": 2, "sdk_version": prof.sdk_version,
                                    "bundle_id": bytes(32)})
        activation_cases += [((self.frame(0, 1, a[:n]),), f"activation value cut to {n} bytes") for n in (0, 1, 4, 11)]
        activation_cases.append(((self.frame(0, 1, a + b"\xff"),), "activation value one byte too long"))

        items = len(prof.flag_bits)
        frequency = []
        for codes, note in (([6] * 16, "every code 6 (undefined)"), ([0xFF] * 16, "every code 0xFF"),
                            ([5] * items + [0xFF] * (16 - items), "keep, then 0xFF in the unused slots"),
                            ([0] * 16, "every item off (0 Hz)"), ([4] * 16, "every item at the highest rate"),
                            ([5] * 15 + [6], "code 6 in the last slot")):
            frequency.append(((self.frame(0, 0x10, bytes(codes)),), note))
        frequency += [((self.frame(0, 0x10, bytes([5]) * n),), f"{n} codes") for n in (0, 1, 15, 17, 32)]

        control = [((self.frame(1, 0, v),), note) for v, note in (
            (bytes([0]), "release"), (b"", "no value"), (bytes([0, 0]), "release, one byte too many"),
            (bytes([0]) * 64, "release, 64 bytes"))]
        control += [((self.frame(1, 0, bytes([0]), session=s),), f"release in session {s}") for s in (0, 1, 31)]
        if self.allow_motion:
            control += [((self.frame(1, 0, bytes([v])),), f"request value {v}") for v in (2, 0x7F, 0x80, 0xFF)]
        return {"command.version": version, "command.activation": activation_cases, "command.frequency": frequency,
                "command.control": control}

    def movement_cases(self) -> list:
        if not self.allow_motion:
            return []
        out = []
        for mode in ZERO_VELOCITY_MODES:
            for z in (0.0, -0.0):
                v = encode_movement_control(mode, z, z, z, z)
                f = self.frame(1, 3, v, session=0)
                out.append(((f,), f"mode {mode:#04x}, setpoints {z}"))
                out.append(((f[:7], f[7:]), f"mode {mode:#04x}, split"))
                out.append(((f[:-1] + bytes([f[-1] ^ 0xFF]),), f"mode {mode:#04x}, bad CRC-32"))
                out.append(((self.frame(1, 3, v[:9], session=0),), f"mode {mode:#04x}, value cut to 9 bytes"))
                out.append(((self.frame(1, 3, v + b"\0", session=0),), f"mode {mode:#04x}, one byte too many"))
        return out

    # ---- the generated kinds ----------------------------------------------

    def generated(self, op: str) -> Iterator[tuple[tuple[bytes, ...], str]]:
        batch = 0
        while True:
            s = self.seed * SEED_STRIDE + batch
            drawn = drawn_inputs(op, self.profile, GENERATED_BATCH, s)
            if not drawn:
                return
            for i, inp in enumerate(drawn):
                data = bytes.fromhex(inp["hex"])
                writes = tuple(w for w in split_chunks(data, inp.get("chunks", [])) if w) or (data,)
                yield writes, f"strategy seed {s} #{i}"
            batch += 1


def cases(profile: str, seed: int, allow_motion: bool = False, kinds: tuple[str, ...] | None = None,
          withheld: dict[str, int] | None = None) -> Iterator[FuzzCase]:
    """Every case of a session, round-robin over the kinds (each kind's list
    shuffled by the seed), the generated kinds without end. Cases that are
    not `safe` are counted into `withheld` by kind and never yielded."""
    b = Builder(profile, seed, allow_motion)
    fixed: dict[str, list] = {**b.vector_cases(), "header": b.header_cases(), "length": b.length_cases(), "truncated": b.truncated_cases(),
                              "split": b.split_cases(), "garbage": b.garbage_cases(),
                              "encryption": b.encryption_cases(), "session": b.session_cases()}
    fixed["unknown.set"], fixed["unknown.id"] = b.unknown_cases()
    fixed.update(b.command_cases())
    fixed["movement.zero"] = b.movement_cases()
    shuffle = random.Random(seed)
    streams: dict[str, Iterator] = {}
    for kind in KINDS:
        if kinds is not None and kind not in kinds:
            continue
        if kind in MOTION_KINDS and not allow_motion:
            continue
        if kind.startswith("generated."):
            streams[kind] = b.generated("decode_frame" if kind == "generated.frame" else "decode_stream")
        else:
            items = list(fixed[kind])
            shuffle.shuffle(items)
            streams[kind] = iter(items)
    numbers = dict.fromkeys(streams, 0)
    while streams:
        for kind in list(streams):
            for writes, source in streams[kind]:
                writes = tuple(w for w in writes if w)
                if not writes:   # an empty input (a vector of no bytes) sends nothing
                    continue
                if safe(b"".join(writes), allow_motion):
                    numbers[kind] += 1
                    yield FuzzCase(f"{kind}.{numbers[kind]}", kind, writes, source)
                    break
                if withheld is not None:
                    withheld[kind] = withheld.get(kind, 0) + 1
            else:
                del streams[kind]
