"""The version reply the simulator sends is one every DJI host release reads
(ERRATA E30): DJI's fixed reader (2.3, 3.1.x) and its scanning reader (3.3
to 3.9) agree on it, and the firmware the scanning reader derives is the
SDK version the profile's host activates with. Under --encrypt the version
and activation ACKs stay plain (no DJI host holds the key before activation).
"""
from __future__ import annotations

import struct

import pytest

from osdk_conformance.core import version_reply as vr
from osdk_conformance.core.deframe import Frame, deframe
from osdk_conformance.core.rules import profile as load_profile, profile_names
from osdk_conformance.core.wire import encode, open_frame
from osdk_conformance.sim.simulator import VERSION_CRC, SimConfig, Simulator
from osdk_conformance.sim.simulator import VERSION_ID as SIM_ID
from osdk_conformance._construct.payload import osdk_payload

KEY = bytes(range(32))
VERSION_ID = SIM_ID.ljust(vr.ID_SIZE, b"\0")


class Wire:
    """The simulator's side of a port, in memory."""

    def __init__(self) -> None:
        self.sent = bytearray()

    def connected(self) -> bool:
        return True

    def write(self, data: bytes) -> int:
        self.sent += data
        return len(data)

    def pending_input(self) -> int:
        return 0


def exchange(sim: Simulator, wire: Wire, cmd_set: int, cmd_id: int, body: dict, seq: int, key: bytes | None = None):
    """Send one command in session 2; the ACK frame the simulator answers with (opened), or None."""
    value = osdk_payload(cmd_set, cmd_id, False, sim.profile.name).build({"body": body})
    wire.sent.clear()
    sim.on_frame(encode(cmd_set=cmd_set, cmd_id=cmd_id, value=value, session=2, seq=seq, key=key), 0.0)
    acks = [open_frame(ev.raw, sim.cfg.key) for ev in deframe([bytes(wire.sent)]) if isinstance(ev, Frame)]
    return acks[0] if acks else None


def version_value(profile: str, **cfg) -> bytes:
    wire = Wire()
    sim = Simulator(SimConfig(profile=profile, **cfg), wire)
    return exchange(sim, wire, 0, 0, {"arbitrary": 0}, 1).value


FW31 = [p for p in profile_names() if load_profile(p).has_version_id]


@pytest.mark.parametrize("profile", FW31)
def test_both_dji_readers_read_the_simulators_fw31_reply_alike(profile):
    value = version_value(profile)
    fixed, scanned = vr.agree(value)
    assert fixed.version_id == SIM_ID and fixed.crc == VERSION_CRC
    assert fixed.name.decode() == load_profile(profile).version_name
    # the firmware the 3.3-3.9 host derives (with its M100 correction) is the version it then activates with
    assert scanned.firmware_word == load_profile(profile).sdk_version


def test_the_m100_reports_a_tenth_of_its_third_number():
    names = {p: load_profile(p).version_name for p in profile_names()}
    assert names["m100-fw3.1"] == "SDK-v1.0 BETA M100-03.01.01.00"   # DJI_APITest.h, 3.1.9.1 to 3.2.2
    assert names["a3-fw3.1"] == "SDK-v1.0 BETA A3-03.01.100.00"
    for p, name in names.items():   # the 2.3 name is inferred by the same rule (rules.yaml says so)
        reply = struct.pack("<HI", 0, VERSION_CRC) + VERSION_ID + name.encode().ljust(32, b"\0")
        assert vr.read_scanning(reply).firmware_word == load_profile(p).sdk_version, p


def test_the_fw23_reply_is_read_by_the_fixed_reader_only():
    value = version_value("m100-fw2.3")
    fixed = vr.read_fixed(value, with_id=False)
    assert fixed.name.decode() == load_profile("m100-fw2.3").version_name and fixed.version_id is None
    with pytest.raises(vr.VersionReplyError, match="no NUL within"):
        vr.read_scanning(value)


@pytest.mark.parametrize(("what", "reply", "message"), [
    # the simulator's former reply: an 8-character ID and three NULs, a name without spaces
    ("former simulator reply", struct.pack("<HI", 0, VERSION_CRC) + b"SIM-0001\0\0\0"
     + b"SIM-M100-03.01.10.00".ljust(32, b"\0"), "no first space"),
    ("CRC with a 0x00 byte", struct.pack("<HI", 0, 0x12003456) + VERSION_ID
     + b"SDK-v1.0 BETA M100-03.01.01.00".ljust(32, b"\0"), None),
    ("no NUL in the ID", struct.pack("<HI", 0, VERSION_CRC) + b"ABCDEFGHIJKLMNOP" * 2 + bytes(32), "no NUL within"),
    ("letters in a number", struct.pack("<HI", 0, VERSION_CRC) + VERSION_ID
     + b"SDK-v1.0 BETA M100-03.0x.01.00".ljust(32, b"\0"), "firmware number"),
])
def test_replies_the_readers_cannot_share_are_told_apart(what, reply, message):
    if message is None:   # the scanning reader reads it, but not as the fixed reader does
        with pytest.raises(vr.VersionReplyError, match="the fixed reader sees"):
            vr.agree(reply)
    else:
        with pytest.raises(vr.VersionReplyError, match=message):
            vr.read_scanning(reply)


def test_an_m100_reply_that_already_says_10_reads_as_a_firmware_dji_refuses():
    reply = (struct.pack("<HI", 0, VERSION_CRC) + VERSION_ID + b"SDK-v1.0 BETA M100-03.01.10.00".ljust(32, b"\0"))
    assert vr.read_scanning(reply).firmware == (3, 1, 100, 0)


@pytest.mark.parametrize("handshake_too", [False, True])
def test_encrypt_keeps_the_handshake_plain_unless_asked(handshake_too):
    wire = Wire()
    sim = Simulator(SimConfig(profile="m100-fw3.1", key=KEY, encrypt=True, encrypt_handshake=handshake_too), wire)
    version = exchange(sim, wire, 0, 0, {"arbitrary": 0}, 1)
    activation = exchange(sim, wire, 0, 1, {"app_id": 7, "api_level": 2, "sdk_version": 0x03010A00,
                                            "bundle_id": bytes(32)}, 2)
    control = exchange(sim, wire, 1, 0, {"request": 1}, 3, key=KEY)
    assert (version.encrypted, activation.encrypted) == (handshake_too, handshake_too)
    assert control.encrypted
    assert osdk_payload(0, 1, True, "m100-fw3.1").parse(activation.value).body.ack_code == "success"
    vr.agree(version.value)


@pytest.mark.parametrize("profile", FW31)
def test_the_acceptance_check_passes_dji_form_and_names_what_breaks_dji_hosts(profile):
    prof = load_profile(profile)
    name = prof.version_name.encode().ljust(32, b"\0")
    assert vr.host_problem(0, VERSION_CRC, VERSION_ID, name, prof.sdk_version) is None
    former = b"SIM-M100-03.01.10.00".ljust(32, b"\0")
    assert "Drone version not obtained" in vr.host_problem(0, VERSION_CRC, VERSION_ID, former, prof.sdk_version)
    short_id = b"SIM-0001".ljust(11, b"\0")   # the scanning reader then starts the name two NULs early
    assert "cannot read it" in vr.host_problem(0, VERSION_CRC, short_id, name, prof.sdk_version)
    tenfold = name.rstrip(b"\0").replace(b".01.00", b".10.00").replace(b".100.00", b".10.00").ljust(32, b"\0")
    assert "activate with that version or refuse it" in vr.host_problem(0, VERSION_CRC, VERSION_ID, tenfold,
                                                                         prof.sdk_version)
