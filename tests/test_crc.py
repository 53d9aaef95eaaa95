"""The frame checksums (osdk_conformance.core.crc).

Checked four ways: the check values over b"123456789" that rules.yaml and
PROTOCOL-FACTS §1 give; the residue property the SDK relies on (the CRC over
data followed by its little-endian CRC is 0); the table-driven engine
against a bit-at-a-time reference written here, for the two frame CRCs and
for well-known catalogue CRCs (two of which Python's standard library also
computes); and the CRC fields of the two worked frames.
"""
from __future__ import annotations

import binascii
import dataclasses
import zlib

import pytest
from hypothesis import given
from hypothesis import strategies as st

from osdk_conformance.core import crc, rules

CHECK_INPUT = b"123456789"

# Worked frames of PROTOCOL-FACTS §1.
MOVEMENT_FRAME = bytes.fromhex("aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba")
BROADCAST_FRAME = bytes.fromhex("aa1600000000000007001ede02000018035769c676b2")


def bitwise_reference(spec: crc.CrcSpec, data: bytes) -> int:
    """One bit at a time, no table: bytes enter least significant bit first
    into a right-shifting register (reflect_in) or most significant bit
    first into a left-shifting one."""
    top = 1 << (spec.width - 1)
    mask = (1 << spec.width) - 1
    reg = spec.init
    reflected_poly = int(f"{spec.poly:0{spec.width}b}"[::-1], 2)
    for byte in data:
        for i in range(8):
            if spec.reflect_in:
                bit = (byte >> i) & 1
                feedback = (reg ^ bit) & 1
                reg >>= 1
                if feedback:
                    reg ^= reflected_poly
            else:
                bit = (byte >> (7 - i)) & 1
                feedback = bool(reg & top) ^ bit
                reg = (reg << 1) & mask
                if feedback:
                    reg ^= spec.poly
    if spec.reflect_out != spec.reflect_in:
        reg = int(f"{reg:0{spec.width}b}"[::-1], 2)
    return reg ^ spec.xorout


def _spec(name: str) -> crc.CrcSpec:
    p = rules.crc_params(name)
    return crc.CrcSpec(width=p.width, poly=p.poly, init=p.init, reflect_in=p.reflect_in,
                       reflect_out=p.reflect_out, xorout=p.xorout)


# Catalogue CRCs with both shift directions. Their init values are symmetric
# under bit reversal (0 or all ones), so the catalogue's convention and the
# engine's (init is the register's start value) agree for them.
CATALOGUE = {
    "CRC-16/ARC": (crc.CrcSpec(16, 0x8005, 0x0000, True, True, 0x0000), 0xBB3D),
    "CRC-16/XMODEM": (crc.CrcSpec(16, 0x1021, 0x0000, False, False, 0x0000), 0x31C3),
    "CRC-16/IBM-3740": (crc.CrcSpec(16, 0x1021, 0xFFFF, False, False, 0x0000), 0x29B1),
    "CRC-32/ISO-HDLC": (crc.CrcSpec(32, 0x04C11DB7, 0xFFFFFFFF, True, True, 0xFFFFFFFF), 0xCBF43926),
    "CRC-32/MPEG-2": (crc.CrcSpec(32, 0x04C11DB7, 0xFFFFFFFF, False, False, 0x00000000), 0x0376E6E7),
    "CRC-32/BZIP2": (crc.CrcSpec(32, 0x04C11DB7, 0xFFFFFFFF, False, False, 0xFFFFFFFF), 0xFC891918),
}
CATALOGUE_ENGINES = {name: crc.Crc(spec) for name, (spec, _) in CATALOGUE.items()}


# --- check values ---------------------------------------------------------------------

def test_crc16_check_value():
    assert crc.crc16(CHECK_INPUT) == 0x2752 == rules.crc_params("crc16").check


def test_crc32_check_value():
    assert crc.crc32(CHECK_INPUT) == 0xE4D9DC14 == rules.crc_params("crc32").check


def test_tables_match_the_published_second_entries():
    # PROTOCOL-FACTS §1: table entry [1] = 0xC0C1 (CRC16), 0x77073096 (CRC32).
    assert crc.engine("crc16").table[1] == 0xC0C1
    assert crc.engine("crc32").table[1] == 0x77073096


def test_empty_input_gives_init():
    assert crc.crc16(b"") == 0x3AA3
    assert crc.crc32(b"") == 0x00003AA3


def test_init_is_the_register_start_value_not_reflected():
    """The check values hold only with init used as is; reflecting it (the
    Rocksoft convention for reflected CRCs) would give other values."""
    for name, check in (("crc16", 0x2752), ("crc32", 0xE4D9DC14)):
        s = _spec(name)
        as_rocksoft = crc.CrcSpec(s.width, s.poly, crc.reflect(s.init, s.width), s.reflect_in, s.reflect_out, s.xorout)
        assert crc.Crc(as_rocksoft)(CHECK_INPUT) != check


@pytest.mark.parametrize("name", sorted(CATALOGUE))
def test_catalogue_check_values(name):
    assert CATALOGUE_ENGINES[name](CHECK_INPUT) == CATALOGUE[name][1]


@given(data=st.binary(max_size=300))
def test_standard_library_agrees(data):
    assert CATALOGUE_ENGINES["CRC-32/ISO-HDLC"](data) == zlib.crc32(data)
    assert CATALOGUE_ENGINES["CRC-16/XMODEM"](data) == binascii.crc_hqx(data, 0)


# --- residue ------------------------------------------------------------------------------

@given(data=st.binary(max_size=1100))
def test_residue_is_zero(data):
    assert rules.crc_params("crc16").residue == 0 and rules.crc_params("crc32").residue == 0
    assert crc.crc16(data + crc.crc16(data).to_bytes(2, "little")) == 0
    assert crc.crc32(data + crc.crc32(data).to_bytes(4, "little")) == 0


@given(data=st.binary(min_size=1, max_size=200), bit=st.integers(0, 7), pos=st.integers(0, 199))
def test_a_flipped_bit_is_detected(data, bit, pos):
    pos %= len(data)
    damaged = bytearray(data)
    damaged[pos] ^= 1 << bit
    assert crc.crc16(bytes(damaged)) != crc.crc16(data)
    assert crc.crc32(bytes(damaged)) != crc.crc32(data)


# --- table against bitwise reference ---------------------------------------------------------

@pytest.mark.parametrize("name", ["crc16", "crc32"])
@given(data=st.binary(max_size=200))
def test_table_matches_bitwise_reference(name, data):
    assert crc.engine(name)(data) == bitwise_reference(_spec(name), data)


@given(data=st.binary(max_size=300), init=st.integers(0, 2**32 - 1), xorout=st.integers(0, 2**32 - 1))
def test_zlib_path_matches_the_table(data, init, xorout):
    """Blocks with zlib's polynomial go to zlib.crc32; the table still says what they compute."""
    engine = crc.Crc(dataclasses.replace(_spec("crc32"), init=init, xorout=xorout))
    assert engine._run == engine._zlib
    assert engine(data) == engine._table_driven(data)


@given(data=st.binary(max_size=48))
def test_table_matches_bitwise_reference_for_catalogue_crcs(data):
    for name, (spec, _) in CATALOGUE.items():
        assert CATALOGUE_ENGINES[name](data) == bitwise_reference(spec, data), name


@given(
    width=st.sampled_from([8, 16, 24, 32]),
    poly=st.integers(1, 2**32 - 1), init=st.integers(0, 2**32 - 1), xorout=st.integers(0, 2**32 - 1),
    reflect_in=st.booleans(), reflect_out=st.booleans(), data=st.binary(max_size=40),
)
def test_any_parameter_block_matches_bitwise_reference(width, poly, init, xorout, reflect_in, reflect_out, data):
    mask = (1 << width) - 1
    spec = crc.CrcSpec(width, poly & mask | 1, init & mask, reflect_in, reflect_out, xorout & mask)
    assert crc.Crc(spec)(data) == bitwise_reference(spec, data)


def test_reference_itself_gives_the_check_values():
    assert bitwise_reference(_spec("crc16"), CHECK_INPUT) == 0x2752
    assert bitwise_reference(_spec("crc32"), CHECK_INPUT) == 0xE4D9DC14


def test_width_must_be_whole_bytes():
    with pytest.raises(ValueError):
        crc.Crc(crc.CrcSpec(12, 0x80F, 0, False, False, 0))


# --- worked frames ---------------------------------------------------------------------------

@pytest.mark.parametrize("frame", [MOVEMENT_FRAME, BROADCAST_FRAME], ids=["movement", "broadcast"])
def test_worked_frames_carry_correct_crcs(frame):
    assert crc.crc16(frame[:10]) == int.from_bytes(frame[10:12], "little")
    assert crc.crc32(frame[:-4]) == int.from_bytes(frame[-4:], "little")
    # and the way the SDK checks them: over the bytes including the stored CRC
    assert crc.crc16(frame[:12]) == 0
    assert crc.crc32(frame) == 0
