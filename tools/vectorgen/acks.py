"""Bug class "command kind x ACK situation" (osdk_conformance.harness.vector_tables)
and what ACK matching remembers: every command kind in every situation an
ACK can meet it in, in streams."""
from __future__ import annotations

import struct
from typing import Callable

from osdk_conformance._construct.payload import VERSION_ID_SIZE, has_version_id

from osdk_conformance.harness import vector_tables as vt
from osdk_conformance.harness import vectors

from .builder import PROFILES, GenerationError, R, Suite
from .scalars import le16
from .wire import WORKED_MOVEMENT_VALUE, frame_bytes

COMMAND_VALUES: dict[str, tuple[tuple[int, int], bytes, bytes | None, bytes]] = {
    # kind: ((set, id), a command value, one that does not decode, an ACK value)
    "version_query": ((0x00, 0x00), b"\x00", b"", struct.pack("<HI", 0, 7) + bytes(32)),
    "activation": ((0x00, 0x01), struct.pack("<III", 1012345, 2, 0x03010A00) + bytes(32), bytes(40), le16(0)),
    "set_frequency": ((0x00, 0x10), bytes(range(8)) + bytes(8), bytes(15), le16(0)),
    "control_authority": ((0x01, 0x00), b"\x01", b"\x01\x00", le16(2)),
    "movement_control": ((0x01, 0x03), bytes.fromhex(WORKED_MOVEMENT_VALUE), bytes(16), b"\x00"),
    "broadcast": ((0x02, 0x00), b"\x00\x00", b"\x00", b"\x00\x01"),
    "lost_control": ((0x02, 0x01), b"\x04", b"", le16(0)),
    "unknown": ((0x05, 0x01), b"\x10\x20", None, b"\x30"),
}


def command_values(kind: str, profile: str) -> tuple[tuple[int, int], bytes, bytes | None, bytes]:
    """COMMAND_VALUES[kind], with the version ACK in the profile's layout (ERRATA E30)."""
    key, value, bad, ack_value = COMMAND_VALUES[kind]
    if kind == "version_query" and has_version_id(profile):
        ack_value = ack_value[:6] + bytes(VERSION_ID_SIZE) + ack_value[6:]
    return key, value, bad, ack_value


def ack_situation_streams(kind: str, other: str, profile: str) -> dict[str, bytes]:
    """The stream of each vt.ACK_SITUATIONS entry for a command kind
    (`other`: a second kind, for the situations with two commands)."""
    (cs, ci), value, bad, ack_value = command_values(kind, profile)
    (ocs, oci), ovalue, _, oack = command_values(other, profile)
    n = 0x0A0B

    def cmd(session: int = 2, seq: int = n, v: bytes = value, c: tuple[int, int] = (cs, ci)) -> bytes:
        return frame_bytes(cmd_set=c[0], cmd_id=c[1], value=v, session=session, seq=seq)

    def ack(session: int = 2, seq: int = n, v: bytes = ack_value) -> bytes:
        return frame_bytes(is_ack=True, session=session, seq=seq, value=v)

    out = {
        "matched": cmd() + ack(),
        "session1_ack": cmd(session=1) + ack(session=1),
        "matched_bad_value": cmd() + ack(v=ack_value + b"\x00"),
        "repeated_ack": cmd() + ack() + ack(),
        "ack_before_command": ack() + cmd(),
        "other_session": cmd() + ack(session=3),
        "other_seq": cmd() + ack(seq=n + 1),
        "session0_command": cmd(session=0) + ack(session=1),
        "rejected_command": cmd(v=bad or b"") + ack(),
        "retransmitted_command": cmd() + cmd() + ack() + ack(),
        "replaced_command": cmd(v=ovalue, c=(ocs, oci)) + cmd() + ack(),
        "superseded_command": cmd() + cmd(v=ovalue, c=(ocs, oci), seq=n + 1) + ack() + ack(seq=n + 1, v=oack),
        "interleaved": cmd(v=ovalue, c=(ocs, oci)) + cmd(session=3, seq=n + 1) + ack(session=3, seq=n + 1)
        + ack(v=oack),
        "header_only_ack": cmd() + frame_bytes(is_ack=True, session=2, seq=n) + ack(),
    }
    return {k: v for k, v in out.items() if vt.feasible_situation(kind, k)}


def add_ack_memory(add: Callable[..., None], profile: str) -> None:
    """What ACK matching remembers (PROTOCOL.md "ACK matching": one slot per
    session 2..31, ERRATA E32), each case telling the rule from the outsider
    check's wrong guesses (docs/OUTSIDER-CHECK.md F4-F6): a decoded ACK shows
    which command it was matched to, a raw one that none was waiting."""
    flags = R("stream.ack_match", "stream.ack_memory") + ["E32"]
    obtain = frame_bytes(cmd_set=1, cmd_id=0, value=b"\x01", session=2, seq=40)
    ack_obtained = frame_bytes(is_ack=True, value=le16(2), session=2, seq=40)
    add("ack.memory.bad_value_forgets", "stream.ack_memory",
        "obtain control, an ACK whose 3-byte value does not decode, then a good ACK with the same session and SEQ: "
        "the first ACK emptied the session's slot, so the second is not matched (raw)",
        obtain + frame_bytes(is_ack=True, value=b"\x02\x00\x00", session=2, seq=40) + ack_obtained, flags)
    bad_activation = frame_bytes(cmd_set=0, cmd_id=1, value=bytes(40), session=2, seq=40)
    add("ack.memory.undecodable_command_changes_nothing", "stream.ack_memory",
        "obtain control, then a 40-byte activation (does not decode) with the same session and SEQ, then an ACK "
        "with code 2: still matched to obtain control (obtained), the slot neither emptied nor taken by activation",
        obtain + bad_activation + ack_obtained, flags)
    if profile == PROFILES[0]:
        add_ack_memory_slots(add, flags)


def add_ack_memory_slots(add: Callable[..., None], flags: list[str]) -> None:
    """The 30 slots, one per session 2..31, all held at once, and sessions 0
    and 1, which have none. The slots do not depend on the profile: the
    stream is generated for one."""

    def obtain(session: int, seq: int) -> bytes:
        return frame_bytes(cmd_set=1, cmd_id=0, value=b"\x01", session=session, seq=seq)

    def control_ack(session: int, seq: int) -> bytes:
        return frame_bytes(is_ack=True, value=le16(2), session=session, seq=seq)

    commands = b"".join(obtain(s, 100 + s) for s in range(2, 32)) + obtain(1, 101) + obtain(0, 100)
    order = [s for k in range(30) for s in [2 + (k * 7) % 30]]  # every session once, in another order
    acks = control_ack(1, 101) + control_ack(0, 100) + b"".join(control_ack(s, 100 + s) for s in order)
    add("ack.memory.one_slot_per_session", "stream.ack_memory",
        "obtain control in every session 2..31 (SEQ 100 + session), then in session 1 (SEQ 101) and session 0 "
        "(SEQ 100), then ACKs with code 2: the session-1 and session-0 ones first, which are not matched (raw), then "
        "one for each session 2..31 in another order (2, 9, 16, ...), all matched: one slot per session, 30 held at "
        "once, none forgotten",
        commands + acks, flags)


E32_SITUATIONS = frozenset({"session1_ack", "superseded_command", "interleaved", "header_only_ack", "other_seq"})
"""Situations where one slot per session (ERRATA E32) decides what matches."""


def add_ack_situations(s: Suite, profile: str) -> None:
    """Every command kind (vt.command_kinds) in every ACK situation
    (vt.ACK_SITUATIONS); the generator checks that each stream shows the
    situation it is named after, as the coverage table reads it."""
    kinds = vt.command_kinds()
    if set(kinds) != set(COMMAND_VALUES):
        raise GenerationError(f"COMMAND_VALUES must cover exactly the command kinds {kinds}")
    for i, kind in enumerate(kinds):
        other = kinds[(i + 1) % len(kinds)]
        layout = "with" if vt.has_ack_layout(kind) else "without"
        for situation, data in ack_situation_streams(kind, other, profile).items():
            test = s.add("decode_stream", profile, f"streams.{profile}.ack.{kind}.{situation}",
                         "stream.ack_situations", f"{kind} ({layout} an ACK layout): {vt.ACK_SITUATIONS[situation]}",
                         {"hex": data.hex(), "chunks": [len(data)]},
                         R("stream.ack_match") + (["E24"] if situation in ("session0_command", "session1_ack") else [])
                         + (["E32"] if situation in E32_SITUATIONS else []))
            case = vectors.cases_of({"testGroups": [{"operation": "decode_stream", "profile": profile,
                                                     "tests": [test]}]}, "streams.json")[0]
            if (kind, situation) not in vt.ack_situations(case):
                raise GenerationError(f"ack.{kind}.{situation}: the stream does not show that situation "
                                      f"({sorted(vt.ack_situations(case))})")
