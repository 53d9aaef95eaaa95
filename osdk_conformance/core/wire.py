"""Frames on the wire for the simulator and the acceptance suite.

Both ends build every frame with the Construct spec (osdk_construct:
`build_frame` for the frame, `osdk_payload` for the value) and both open a
received frame here: header fields, optional AES-256-ECB decryption of DATA
(PROTOCOL-FACTS §1: DATA padded to whole 16-byte blocks, PADDING says how
many bytes to drop, CRCs over the ciphertext), then command set, id and
value bytes.
"""
from __future__ import annotations

import os
from dataclasses import dataclass

from osdk_conformance.core.capture import TX
from osdk_conformance.core.deframe import HEADER_LEN, header_fields
from osdk_conformance.core.deframe import Deframer, Frame
from osdk_conformance.core.errors import UsageError
from osdk_conformance._construct.frame import build_frame

BLOCK = 16


class KeyError_(ValueError):
    """An app key that is not 64 hex characters."""


def parse_key(text: str | None) -> bytes | None:
    """The 32-byte AES key from the app key text (64 hex characters)."""
    if text is None:
        return None
    t = text.strip()
    try:
        key = bytes.fromhex(t)
    except ValueError:
        raise KeyError_("the app key must be 64 hex characters (32 bytes)") from None
    if len(key) != 32:
        raise KeyError_(f"the app key must be 64 hex characters (32 bytes), got {len(t)} characters")
    return key


def key_from_env(var: str | None) -> bytes | None:
    """The key held by environment variable `var` (None when var is None)."""
    if not var:
        return None
    if var not in os.environ:
        raise KeyError_(f"environment variable {var} is not set")
    return parse_key(os.environ[var])


def key_option(key_env: str | None, encrypt: bool) -> bytes | None:
    """The key of `--key-env VAR` for a command, checked with `--encrypt`;
    a bad or missing key is a usage error."""

    try:
        key = key_from_env(key_env)
    except KeyError_ as e:
        raise UsageError(str(e)) from None
    if encrypt and key is None:
        raise UsageError("--encrypt needs --key-env")
    return key


def _cipher(key: bytes):
    from cryptography.hazmat.primitives.ciphers import Cipher, algorithms, modes

    return Cipher(algorithms.AES(key), modes.ECB())


def encrypt(data: bytes, key: bytes) -> tuple[bytes, int]:
    """(ciphertext, padding): DATA padded with 16 - len % 16 zero bytes."""
    pad = BLOCK - len(data) % BLOCK
    enc = _cipher(key).encryptor()
    return enc.update(data + bytes(pad)) + enc.finalize(), pad


def decrypt(data: bytes, key: bytes, padding: int) -> bytes:
    if not data or len(data) % BLOCK or not 1 <= padding <= BLOCK:
        raise ValueError("encrypted DATA is not whole 16-byte blocks with 1..16 bytes of padding")
    dec = _cipher(key).decryptor()
    plain = dec.update(data) + dec.finalize()
    return plain[:-padding]


def encode(*, cmd_set: int | None = None, cmd_id: int | None = None, value: bytes = b"", is_ack: bool = False,
           session: int = 0, seq: int = 0, key: bytes | None = None) -> bytes:
    """A complete frame, built with the Construct spec; encrypted when `key` is given."""

    if key is None:
        return build_frame(cmd_set=cmd_set, cmd_id=cmd_id, value=value, is_ack=is_ack, session=session, seq=seq)
    data = bytes(value) if cmd_set is None else bytes([cmd_set, cmd_id]) + bytes(value)
    cipher, pad = encrypt(data, key)
    return build_frame(value=cipher, is_ack=is_ack, session=session, seq=seq, enc=1, padding=pad)


@dataclass
class Opened:
    """A received frame, decrypted when needed."""

    header: dict
    is_ack: bool
    session: int
    seq: int
    encrypted: bool
    cmd_set: int | None
    cmd_id: int | None
    value: bytes          # command value, or ACK value
    problem: str = ""     # why DATA could not be opened ("" when it could)


def open_frame(raw: bytes, key: bytes | None = None) -> Opened:
    h = header_fields(raw)
    data = raw[HEADER_LEN:-4] if len(raw) > HEADER_LEN else b""
    encrypted = h["enc"] != 0
    problem = ""
    if encrypted:
        if h["enc"] != 1:
            problem = f"ENC {h['enc']} is not a known encryption"
        elif key is None:
            problem = "frame is AES-encrypted and no key was given"
        else:
            try:
                data = decrypt(data, key, h["padding"])
            except ValueError as e:
                problem = str(e)
    if problem:
        return Opened(h, h["is_ack"], h["session"], h["seq"], encrypted, None, None, b"", problem)
    if h["is_ack"]:
        return Opened(h, True, h["session"], h["seq"], encrypted, None, None, data)
    if len(data) < 2:
        return Opened(h, False, h["session"], h["seq"], encrypted, None, None, b"",
                      "" if not data else "DATA shorter than command set and id")
    return Opened(h, False, h["session"], h["seq"], encrypted, data[0], data[1], data[2:])


def commands_sent(records, key: bytes | None = None) -> list[Opened]:
    """The frames of a capture's sent (tx) records, opened, in the order they were sent."""

    deframer, out = Deframer(), []
    for rec in records:
        if rec.direction == TX:
            out += [open_frame(ev.raw, key) for ev in deframer.feed(rec.data) if isinstance(ev, Frame)]
    return out
