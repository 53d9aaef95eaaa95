"""Command and ACK values, chosen by command set, id, direction and profile.

Mirrors spec/osdk_payload.ksy. `osdk_payload(cmd_set, cmd_id, is_ack, profile)`
is that ksy type with its params: the dispatch key is
(is_ack ? 0x10000 : 0) + cmd_set * 0x100 + cmd_id, as in the ksy; a key
with no type keeps the value as raw bytes (`unknown_value`); bytes left
after a known value are rejected (Terminated stands for the ksy's
`trailing` field, which must be empty).
"""
from __future__ import annotations

import functools

from construct import Array, Bytes, Enum, GreedyBytes, Int8ul, Int16ul, Int32ul, Pass, Struct, Terminated

from osdk_conformance.core.rules import default_rules

from . import broadcast as broadcast_profiles
from .combinators import when
from .control import movement_control
from .enums import (
    ACTIVATION_RESULT, COMMAND_SET, CONTROL_ACK, CONTROL_REQUEST_CODE, FREQUENCY_ACK, FREQUENCY_CODE,
    VERSION_ACK, enum_int, profile_value,
)

__all__ = [
    "osdk_payload", "payload", "key", "BODY_BY_KEY",
    "version_query", "version_ack_value", "has_version_id", "VERSION_ID_SIZE", "activation_request", "activation_ack_value", "frequency_request",
    "frequency_ack_value", "control_request", "control_ack_value", "broadcast", "lost_control",
    "lost_control_ack_value", "unknown_value",
]

version_query = Struct("arbitrary" / Int8ul)

VERSION_ID_SIZE = 11


# Values of the profiles whose version ACK has no version ID (rules.yaml
# profiles.<id>.version_ack.version_id false), the exceptions the ksy's
# `has_version_id` names too.
_WITHOUT_VERSION_ID = frozenset(
    p.value for p in map(default_rules().profile, default_rules().profile_names) if not p.has_version_id)


def has_version_id(profile) -> bool:
    """Whether the profile's version ACK carries the 11-byte version ID
    between the CRC and the name: FW 3.1 firmware does, M100 FW 2.3 does not
    (ERRATA E30). rules.yaml says it for each profile; as in the ksy, a
    value outside the enum has it."""
    return profile_value(profile) not in _WITHOUT_VERSION_ID


@functools.cache
def version_ack_value(profile):
    """The version ACK in a profile (see has_version_id)."""
    return Struct(
        "ack_code" / Enum(Int16ul, **VERSION_ACK),
        "version_crc" / Int32ul,
        "version_id" / when(has_version_id(profile), Bytes(VERSION_ID_SIZE)),
        "version_name" / Bytes(32),
    )

activation_request = Struct(
    "app_id" / Int32ul,
    "api_level" / Int32ul,
    "sdk_version" / Int32ul,
    "bundle_id" / Bytes(32),
)

activation_ack_value = Struct("ack_code" / Enum(Int16ul, **ACTIVATION_RESULT))

frequency_request = Struct("codes" / Array(16, Enum(Int8ul, **FREQUENCY_CODE)))

frequency_ack_value = Struct("ack_code" / Enum(Int16ul, **FREQUENCY_ACK))

control_request = Struct("request" / Enum(Int8ul, **CONTROL_REQUEST_CODE))

control_ack_value = Struct("ack_code" / Enum(Int16ul, **CONTROL_ACK))

lost_control = Struct("reason" / Int8ul)

lost_control_ack_value = Struct("ack_code" / Int16ul)

unknown_value = Struct("raw" / GreedyBytes)


@functools.cache
def broadcast(profile):
    """The broadcast value in a profile; a profile outside the enum leaves
    `data` absent, as the ksy switch without a default does."""
    try:
        data = broadcast_profiles.for_profile(profile)
    except KeyError:
        data = Pass
    return Struct("data" / data)


def key(cmd_set: int, cmd_id: int, is_ack: bool) -> int:
    """The ksy dispatch key: 0x1SSII for ACKs, 0x0SSII for commands."""
    return (0x10000 if is_ack else 0) + cmd_set * 0x100 + cmd_id


BODY_BY_KEY = {
    0x0000: version_query,
    0x0001: activation_request,
    0x0010: frequency_request,
    0x0100: control_request,
    0x0103: movement_control,
    0x0200: broadcast,  # needs the profile
    0x0201: lost_control,
    0x10000: version_ack_value,  # needs the profile
    0x10001: activation_ack_value,
    0x10010: frequency_ack_value,
    0x10100: control_ack_value,
    0x10201: lost_control_ack_value,
}
"""Value type by dispatch key; any other key is `unknown_value`."""


@functools.lru_cache(maxsize=4096)
def _payload(k: int, profile: int):
    body = BODY_BY_KEY.get(k, unknown_value)
    if body is broadcast or body is version_ack_value:
        body = body(profile)
    return Struct("body" / body, Terminated)


def osdk_payload(cmd_set, cmd_id: int, is_ack: bool, profile):
    """osdk_payload(cmd_set, cmd_id, is_ack, profile): the construct of one
    value. cmd_set may be an int or a command_set enum value; profile an int,
    ksy name or profile id."""
    return _payload(key(enum_int(cmd_set, COMMAND_SET), int(cmd_id), bool(is_ack)), profile_value(profile))


payload = osdk_payload
"""Short name within this module (osdk_conformance._construct.payload.payload)."""
