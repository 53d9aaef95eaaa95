"""The version reply as DJI's host releases read it (ERRATA E30).

Two readers exist and a flight controller's reply must satisfy both:

- the fixed reader of the 2.3 and 3.1.x hosts: u16 code, u32 CRC, then 11
  bytes of version ID on FW 3.1 (none on FW 2.3), then 32 bytes of name;
- the scanning reader of the 3.3 to 3.9 hosts: u16 code, then a run up to
  the first NUL (at most 16 bytes: CRC and ID together), the name from the
  byte after that NUL, and the firmware version parsed out of the name: past
  the first space ("SDK-v1.0") and the second ("BETA"), the hardware name
  up to "-", then four "."-separated decimal numbers, the last ended by a
  NUL; no step may run past byte 64 of the reply. For hardware "M100" the
  third number is multiplied by 10 (an M100 reports a tenth of it).

This is our own statement of those rules for tests and diagnostics, not a
copy of DJI's code; the facts are in PROTOCOL-FACTS section 2 and E30.
"""
from __future__ import annotations

import struct
from dataclasses import dataclass

ID_SIZE = 11
NAME_SIZE = 32
SCAN_LIMIT = 16          # the scanning reader's CRC-and-ID buffer
NAME_LIMIT = 64          # no byte past this offset of the reply is read for the name
M100_FIX = "M100"        # hardware whose third firmware number the 3.9.0 host multiplies by 10


class VersionReplyError(ValueError):
    """The reply cannot be read the way that host reads it (the host gives up:
    "Drone version not obtained")."""


@dataclass(frozen=True)
class VersionReading:
    code: int
    crc: int | None
    version_id: bytes | None       # up to the first NUL
    name: bytes                    # the 32-byte field, NULs stripped at the end
    hardware: str | None = None    # the scanning reader only
    firmware: tuple[int, int, int, int] | None = None   # after the M100 correction

    @property
    def firmware_word(self) -> int | None:
        """The firmware as the SDK version word the host then activates with."""
        if self.firmware is None:
            return None
        a, b, c, d = self.firmware
        return (a & 0xFF) << 24 | (b & 0xFF) << 16 | (c & 0xFF) << 8 | (d & 0xFF)


def _until_nul(b: bytes) -> bytes:
    return b.split(b"\0", 1)[0]


def read_fixed(value: bytes, with_id: bool) -> VersionReading:
    """The 2.3 and 3.1.x hosts: fixed offsets, the ID only on FW 3.1."""
    need = 6 + (ID_SIZE if with_id else 0) + NAME_SIZE
    if len(value) < need:
        raise VersionReplyError(f"{len(value)} bytes, the fixed reader takes {need}")
    code, crc = struct.unpack_from("<HI", value)
    pos = 6
    vid = None
    if with_id:
        vid = _until_nul(value[pos:pos + ID_SIZE])
        pos += ID_SIZE
    return VersionReading(code, crc, vid, value[pos:pos + NAME_SIZE].rstrip(b"\0"))


def _number(value: bytes, pos: int, end: bytes) -> tuple[int, int]:
    n = 0
    while True:
        if pos >= len(value) or pos > NAME_LIMIT:
            raise VersionReplyError(f"the firmware number is not ended by {end!r} within {NAME_LIMIT} bytes")
        ch = value[pos]
        if ch == end[0]:
            return n, pos + 1
        if not 0x30 <= ch <= 0x39:
            # the 3.9.0 host would fold any byte into the number; a digit is what the form has
            raise VersionReplyError(f"byte {ch:#04x} at offset {pos} in a firmware number")
        n = n * 10 + ch - 0x30
        pos += 1


def read_scanning(value: bytes) -> VersionReading:
    """The 3.3 to 3.9 hosts (`Vehicle::parseDroneVersionInfo`): NUL scan,
    then the firmware version out of the name, with the M100 correction."""
    if len(value) < 3:
        raise VersionReplyError(f"{len(value)} bytes: no room for the code and a CRC-and-ID run")
    code = struct.unpack_from("<H", value)[0]
    nul = value.find(b"\0", 2)
    if nul < 0 or nul - 2 > SCAN_LIMIT:
        raise VersionReplyError(f"no NUL within the {SCAN_LIMIT}-byte CRC-and-ID run")
    run = value[2:nul]
    name_at = nul + 1
    name = value[name_at:name_at + NAME_SIZE]
    pos = name_at
    for what in ("first", "second"):
        sp = value.find(b" ", pos, NAME_LIMIT + 1)
        if sp < 0:
            raise VersionReplyError(f"no {what} space in the name within {NAME_LIMIT} bytes")
        pos = sp + 1
    dash = value.find(b"-", pos, NAME_LIMIT + 1)
    if dash < 0:
        raise VersionReplyError(f"no '-' after the hardware name within {NAME_LIMIT} bytes")
    hardware = value[pos:dash].decode("ascii", "replace")
    pos = dash + 1
    numbers = []
    for end in (b".", b".", b".", b"\0"):
        n, pos = _number(value, pos, end)
        numbers.append(n)
    if hardware == M100_FIX:
        numbers[2] *= 10
    crc = vid = None
    if len(run) >= 4:   # below FW 3.2 the run is the CRC, then the ID
        crc = struct.unpack_from("<I", run)[0]
        vid = run[4:]
    return VersionReading(code, crc, vid, name.rstrip(b"\0"), hardware, tuple(numbers))


def agree(value: bytes) -> tuple[VersionReading, VersionReading]:
    """A FW 3.1 reply (with the ID) as both readers see it;
    VersionReplyError when they do not read the same CRC, ID and name. (A
    FW 2.3 reply has no NUL in its first 16 bytes after the code, so only the
    fixed reader can read it: the 3.3 to 3.9 hosts do not support FW 2.3.)"""
    fixed, scanned = read_fixed(value, with_id=True), read_scanning(value)
    if (fixed.crc, fixed.version_id, fixed.name) != (scanned.crc, scanned.version_id, scanned.name):
        raise VersionReplyError(f"the fixed reader sees CRC {fixed.crc:#010x}, ID {fixed.version_id!r}, name "
                                f"{fixed.name!r}; the scanning reader CRC {scanned.crc}, ID {scanned.version_id!r}, "
                                f"name {scanned.name!r}")
    return fixed, scanned


def host_problem(code: int, crc: int, version_id: bytes, name: bytes, sdk_version: int) -> str | None:
    """Why DJI's 3.3 to 3.9 hosts could not use a FW 3.1 version reply with
    these fields (they would stop before activating, or activate with another
    version than `sdk_version`, the profile's), or None when they can."""
    value = struct.pack("<HI", code, crc) + version_id + name
    try:
        _, scanned = agree(value)
    except VersionReplyError as e:
        return f"DJI's 3.3 to 3.9 hosts cannot read it ({e}): they stop at \"Drone version not obtained\""
    if scanned.firmware_word != sdk_version:
        a, b, c, d = scanned.firmware
        return (f"DJI's 3.3 to 3.9 hosts read firmware {a}.{b}.{c}.{d} from it (hardware {scanned.hardware!r}), "
                f"not the profile's {sdk_version >> 24}.{sdk_version >> 16 & 0xFF}.{sdk_version >> 8 & 0xFF}."
                f"{sdk_version & 0xFF}: they activate with that version or refuse it")
    return None
