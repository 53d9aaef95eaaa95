#!/usr/bin/env python3
"""Generate the golden vectors in vectors/ (format: vectors/FORMAT.md).

usage: tools/gen_vectors.py [--out DIR] [--suite NAME ...] [--check]

Deterministic: every suite draws from its own random.Random(seed), ids are
stable, and files are written with sorted keys, so the same spec gives the
same bytes. `expected` comes from osdk_conformance.reference.answer, except
for hand-written edge cases (the worked frames of PROTOCOL-FACTS, the
latitude/longitude order, ...), whose expected value is written out here
from the spec and checked against the reference: any disagreement stops the
generator.

Layout of a file: the suite header and groups are indented; each test is
one line of compact JSON (one line per case keeps 30,000 cases diffable
and the files under 30 MB; the bytes are still a pure function of the spec).

--check regenerates into a scratch directory and fails (exit 1) when the
result differs from vectors/, byte for byte (with --suite: those suites'
files only). --suite limits generation to the named suites; MANIFEST.json of
the output directory is rewritten over the suite files it then holds.
"""
from __future__ import annotations

import argparse
import filecmp
import hashlib
import json
import random
import struct
import sys
import tempfile
import time
from pathlib import Path
from typing import Any, Callable

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from osdk_construct.payload import VERSION_ID_SIZE, has_version_id  # noqa: E402
from osdk_conformance import model, reference, vectors  # noqa: E402
from osdk_conformance import vector_tables as vt  # noqa: E402
from osdk_conformance.crc import crc16, crc32  # noqa: E402
from osdk_conformance.rules import classify_control_mode, default_rules, input_ranges, profile as rules_profile  # noqa: E402
from osdk_conformance.spec_rules import RULES, rule_flag  # noqa: E402
from osdk_conformance.trace import errata_ids  # noqa: E402
from osdk_conformance.vectors import (  # noqa: E402
    ERRATA_SUMMARY, VECTORS_DIR, dump_suite, manifest_text, project_result, same_json,
)

PROFILES = reference.PROFILES
GENERATOR = "tools/gen_vectors.py"
ERRATA = errata_ids()
PAYLOAD_ARGS = {"cmd_set": 0x02, "cmd_id": 0x00, "is_ack": False}


class GenerationError(Exception):
    """A hand-written expectation disagrees with the reference, or a case is malformed."""


# ============================================================== the suite builder


class Suite:
    def __init__(self, name: str, description: str, seed: int) -> None:
        self.name = name
        self.description = description
        self.rng = random.Random(seed)
        self.groups: dict[tuple[str, str | None], list[dict]] = {}
        self.ids: set[str] = set()
        self.used: set[str] = set()

    def add(self, op: str, profile: str | None, id: str, category: str, comment: str, input: dict,
            flags: list[str], *, expected: dict | None = None, error: str | None = None,
            acceptable: str | None = None) -> dict:
        """One case. Without `expected`/`error` the reference's answer is the
        expectation; with them (hand-written from the spec) the reference
        must agree. `acceptable=CLASS` makes a case the reference answers
        validly also pass when rejected with CLASS."""
        if id in self.ids:
            raise GenerationError(f"duplicate id {id}")
        for f in flags:
            if f.startswith("rule:"):
                if f[5:] not in RULES:
                    raise GenerationError(f"{id}: unknown rule {f}")
            elif f not in ERRATA:
                raise GenerationError(f"{id}: unknown flag {f}")
        if not flags:
            raise GenerationError(f"{id}: no flags")
        ref = reference.answer(op, profile, input)
        if "unsupported" in ref:
            raise GenerationError(f"{id}: the reference does not support {op} / {profile}")
        got_result = project_result(op, ref["result"]) if ref["ok"] else None
        if expected is not None and not (ref["ok"] and same_json(got_result, expected)):
            raise GenerationError(f"{id}: hand-written expectation disagrees with the reference\n"
                                  f"  written:   {json.dumps(expected, sort_keys=True)}\n"
                                  f"  reference: {json.dumps(ref, sort_keys=True)}")
        if error is not None and (ref["ok"] or ref["error"] != error):
            raise GenerationError(f"{id}: written error {error}, reference answered {json.dumps(ref)}")
        if acceptable is not None:
            if not ref["ok"]:
                raise GenerationError(f"{id}: acceptable case the reference rejects: {ref}")
            result, exp = "acceptable", {"value": got_result, "error": acceptable}
        elif ref["ok"]:
            result, exp = "valid", got_result
        else:
            result, exp = "invalid", {"error": ref["error"]}
        test = {"id": id, "category": category, "comment": comment, "input": input, "result": result,
                "expected": exp, "flags": sorted(set(flags))}
        self.ids.add(id)
        self.used.update(flags)
        self.groups.setdefault((op, profile), []).append(test)
        return test

    def document(self) -> dict:
        notes = {}
        for f in sorted(self.used):
            notes[f] = RULES[f[5:]] if f.startswith("rule:") else f"ERRATA {f}: {ERRATA_SUMMARY.get(f, '')}"
        groups = [{"operation": op, "profile": prof, "tests": tests} for (op, prof), tests in self.groups.items()]
        return {
            "suite": self.name, "description": self.description, "generator": GENERATOR,
            "numberOfTests": sum(len(g["tests"]) for g in groups), "notes": notes, "testGroups": groups,
        }


def R(*names: str) -> list[str]:
    return [rule_flag(n) for n in names]


# ============================================================== values and bytes


def f32(value: float) -> int:
    return struct.unpack("<I", struct.pack("<f", value))[0]


def f64(value: float) -> int:
    return struct.unpack("<Q", struct.pack("<d", value))[0]


def f32_value(bits: int) -> float:
    return struct.unpack("<f", struct.pack("<I", bits))[0]


def f32_model(bits: int) -> dict:
    return model.float_model(bits, 32)


def f32_next_up(bits: int) -> int:
    """The bits of the smallest float32 above this finite one."""
    if bits == 0x80000000:
        return 0x00000001
    return bits - 1 if bits & 0x80000000 else bits + 1


def f32_next_down(bits: int) -> int:
    """The bits of the largest float32 below this finite one."""
    if bits == 0x00000000:
        return 0x80000001
    return bits + 1 if bits & 0x80000000 else bits - 1


F32_SPECIALS = {
    "qnan": 0x7FC00000, "snan": 0x7F800001, "nan_payload": 0x7FC12345, "neg_nan": 0xFFC00000,
    "inf": 0x7F800000, "neg_inf": 0xFF800000, "neg_zero": 0x80000000, "denormal_min": 0x00000001,
    "neg_denormal_max": 0x807FFFFF, "f32_max": 0x7F7FFFFF,
}
F64_SPECIALS = {
    "qnan": 0x7FF8000000000000, "snan": 0x7FF0000000000001, "neg_inf": 0xFFF0000000000000,
    "neg_zero": 0x8000000000000000, "denormal_min": 0x0000000000000001,
}
NON_FINITE = {"qnan", "snan", "nan_payload", "neg_nan", "inf", "neg_inf"}


def le16(v: int) -> bytes:
    return struct.pack("<H", v)


class Values:
    """Random item values, compact in JSON: floats are multiples of 1/8
    (exact in float32, short to print), integers span their whole type."""

    def __init__(self, rng: random.Random, specials: list[tuple[int, int]] | None = None) -> None:
        self.rng = rng
        self.specials = specials  # when given: (f32 bits, f64 bits) used in turn for every float
        self.turn = 0

    def _special(self, width: int) -> int:
        pair = self.specials[self.turn % len(self.specials)]
        self.turn += 1
        return pair[0] if width == 32 else pair[1]

    def f4(self) -> int:
        if self.specials:
            return self._special(32)
        return f32(self.rng.randint(-80000, 80000) / 8)

    def f8(self) -> int:
        if self.specials:
            return self._special(64)
        return f64(self.rng.randint(-3_000_000, 3_000_000) / 1_048_576)

    def u(self, bits: int) -> int:
        return self.rng.getrandbits(bits)

    def s(self, bits: int) -> int:
        return self.rng.getrandbits(bits) - (1 << (bits - 1))


def item_bytes(item: str, profile: str, v: Values) -> bytes:
    """One broadcast item with values from `v`, packed from the layout of
    PROTOCOL-FACTS section 3 with struct (independently of osdk_construct)."""
    fw3 = profile != "m100-fw2.3"
    if item == "time_stamp":
        return struct.pack("<IIB", v.u(32), v.u(32), v.u(8)) if fw3 else struct.pack("<I", v.u(32))
    if item == "quaternion":
        return struct.pack("<4I", *(v.f4() for _ in range(4)))
    if item in ("acceleration", "angular_rate"):
        return struct.pack("<3I", *(v.f4() for _ in range(3)))
    if item == "velocity":
        return struct.pack("<3IB", v.f4(), v.f4(), v.f4(), v.u(8))
    if item == "position":
        return struct.pack("<QQIIB", v.f8(), v.f8(), v.f4(), v.f4(), v.u(8))
    if item == "gps_detail":
        return struct.pack("<IIiiiIII", v.u(32), v.u(32), v.s(32), v.s(32), v.s(32), v.f4(), v.f4(), v.f4())
    if item == "rtk_detail":
        return struct.pack("<IIQQIIIIhBB", v.u(32), v.u(32), v.f8(), v.f8(), v.f4(), v.f4(), v.f4(), v.f4(),
                           v.s(16), v.u(8), v.u(8))
    if item == "magnetometer":
        return struct.pack("<3h", *(v.s(16) for _ in range(3)))
    if item == "rc":
        return struct.pack("<6h", *(v.s(16) for _ in range(6)))
    if item == "gimbal":
        angles = struct.pack("<3I", v.f4(), v.f4(), v.f4())
        return angles + bytes([v.u(8)]) if fw3 else angles
    if item in ("flight_status", "battery"):
        return bytes([v.u(8)])
    if item == "control_info":
        return bytes([v.rng.choice(CUR_MODES), v.u(8)]) if fw3 else bytes([v.u(8)])
    raise GenerationError(f"no item {item}")


CUR_MODES = [*range(0, 19), 97, 98, 99, 100]
FLOAT_ITEMS = ("quaternion", "acceleration", "velocity", "angular_rate", "position", "gps_detail", "rtk_detail",
               "gimbal")


def payload(profile: str, flags: int, v: Values) -> bytes:
    """Flag word and the flagged items in bit order."""
    p = rules_profile(profile)
    out = le16(flags)
    for bit, item in enumerate(p.flag_bits):
        if flags >> bit & 1:
            out += item_bytes(item, profile, v)
    return out


def broadcast_flags_model(profile: str, present: set[str]) -> dict:
    """The flag-word part of a broadcast model, from the profile's bit order."""
    out: dict[str, Any] = {f"has_{item}": item in present for item in rules_profile(profile).flag_bits}
    out["reserved_flags"] = 0
    return out


def bc_input(data: bytes) -> dict:
    return {"hex": data.hex(), **PAYLOAD_ARGS}


def frame_bytes(*, cmd_set: int | None = None, cmd_id: int | None = None, value: bytes = b"", is_ack: bool = False,
                session: int = 0, seq: int = 0, enc: int = 0, padding: int = 0, ver: int = 0, res0: int = 0,
                res1: int = 0, length: int | None = None, data: bytes | None = None) -> bytes:
    """A frame packed field by field (PROTOCOL-FACTS section 1) with any header
    values, LEN computed unless given, and both CRCs right for what is there."""
    if data is None:
        data = value if cmd_set is None else bytes([cmd_set, cmd_id]) + value
    if length is None:
        length = 12 + (len(data) + 4 if data else 0)
    head = bytes([0xAA]) + le16((length & 0x3FF) | ver << 10) + bytes([session | is_ack << 5 | res0 << 6,
                                                                          padding | enc << 5])
    head += res1.to_bytes(3, "little") + le16(seq)
    head += le16(crc16(head))
    if not data:
        return head
    body = head + data
    return body + struct.pack("<I", crc32(body))


def flip(data: bytes, bit: int) -> bytes:
    b = bytearray(data)
    b[bit // 8] ^= 1 << (bit % 8)
    return bytes(b)


# The two worked frames of PROTOCOL-FACTS section 1, verbatim.
WORKED_MOVEMENT = "aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba"
WORKED_BROADCAST = "aa1600000000000007001ede02000018035769c676b2"


def enum(value: int, name: str | None) -> dict:
    return {"value": value, "name": name}


# ============================================================== control_mode.json


def mode_flags(byte: int, profile: str, c: dict) -> list[str]:
    flags = R("control.fields")
    raw = c["raw"]
    if None in c["fields"].values():
        flags += R("control.undefined", "enums.unnamed") + ["E16"]
    if None not in (c["fields"]["horizontal_logic"], c["fields"]["vertical_logic"], c["fields"]["yaw_logic"]):
        flags += R("control.combinations")
        if c["combination"] is None and c["classification"] == "undocumented":
            flags += ["E16"]
    if c["classification"] != "documented":
        flags += R("control.classification")
    if raw["stable_mode"]:
        flags += ["E15"]
    if profile == "m100-fw2.3" and raw["yaw_logic"] == 0 and raw["stable_mode"]:
        flags += R("control.bit0_fw2_3")
    if c["fields"]["horizontal_logic"] == "hori_pos" or c["fields"]["vertical_logic"] == "vert_thrust":
        flags += ["E29"]  # the spec's names (hori_pos, vert_thrust), not the seed's typos
    if c["fields"]["vertical_logic"] == "vert_thrust" and c["combination"]:
        flags += ["E05"]
    return flags


def gen_control_mode() -> Suite:
    s = Suite("control_mode", "Every control mode byte in every profile, classified (op classify_control_mode): "
                              "fields and enum names, documented / undocumented / later_firmware / invalid, "
                              "combination index.", seed=101)
    # Hand-written from the seed's mode table and ERRATA E15: the worked frame's
    # mode byte, and bit 0 on FW 2.3.
    fields_4b = {"stable_mode": enum(1, "stable"), "horizontal_frame": enum(1, "body"),
                 "yaw_logic": enum(1, "yaw_rate"), "vertical_logic": enum(0, "vert_vel"),
                 "horizontal_logic": enum(1, "hori_vel")}
    fields_41 = {"stable_mode": enum(1, "stable"), "horizontal_frame": enum(0, "ground"),
                 "yaw_logic": enum(0, "yaw_ang"), "vertical_logic": enum(0, "vert_vel"),
                 "horizontal_logic": enum(1, "hori_vel")}
    hand = {
        ("a3-fw3.1", 0x4B): {"fields": fields_4b, "classification": "documented", "combination": 4},
        ("m100-fw2.3", 0x4B): {"fields": fields_4b, "classification": "documented", "combination": 4},
        ("m100-fw2.3", 0x41): {"fields": fields_41, "classification": "invalid", "combination": None},
        ("m100-fw3.1", 0x41): {"fields": fields_41, "classification": "documented", "combination": 3},
    }
    for profile in PROFILES:
        for byte in range(256):
            c = classify_control_mode(byte, profile)
            label = c["classification"] + (f", combination {c['combination']}" if c["combination"] else "")
            comment = f"mode byte 0x{byte:02x} ({byte:08b}) on {profile}: {label}; {c['reasons'][0]}"
            expected = hand.get((profile, byte))
            if expected:
                comment = "hand-written from the seed mode table and ERRATA E15: " + comment
            s.add("classify_control_mode", profile, f"control_mode.{profile}.0x{byte:02x}", "control.mode_byte",
                  comment, {"byte": byte}, mode_flags(byte, profile, c), expected=expected)
    return s


# ============================================================== control_ranges.json


def mc_hex(byte: int, x: int, y: int, z: int, yaw: int) -> str:
    return (bytes([byte]) + struct.pack("<4I", x, y, z, yaw)).hex()


def mid(limits: dict) -> float:
    lo, hi = limits.get("min"), limits.get("max")
    if lo is not None and hi is not None:
        return (lo + hi) / 2
    if lo is not None:
        return lo + 1.5
    if hi is not None:
        return hi - 1.5
    return 0.0


def gen_control_ranges() -> Suite:
    s = Suite("control_ranges", "check_movement_control: every documented mode byte of every profile at and just "
                                "outside each input range limit (float32 neighbours), non-finite and special "
                                "setpoints, every undefined mode byte, and wrong value lengths.", seed=202)
    rng = s.rng
    axes = ("x", "y", "z", "yaw")
    for profile in PROFILES:
        op = "check_movement_control"
        base_id = f"control_ranges.{profile}"
        # Hand-written: the worked frame's value (PROTOCOL-FACTS section 1), combination 4.
        worked = "4b0000803f000000c00000003f0000f041"
        s.add(op, profile, f"{base_id}.worked_value", "control.ranges",
              "hand-written: the value of the PROTOCOL-FACTS movement control frame (0x4B, x 1.0, y -2.0, z 0.5, "
              "yaw 30.0) is combination 4 and within its ranges",
              {"hex": worked}, R("control.ranges", "control.value", "control.combinations"),
              expected={"value": {"control_mode": {"stable_mode": enum(1, "stable"), "horizontal_frame": enum(1, "body"),
                                                   "yaw_logic": enum(1, "yaw_rate"), "vertical_logic": enum(0, "vert_vel"),
                                                   "horizontal_logic": enum(1, "hori_vel")},
                                  "x": f32_model(0x3F800000), "y": f32_model(0xC0000000),
                                  "z": f32_model(0x3F000000), "yaw": f32_model(0x41F00000)},
                        "combination": 4})
        # Value length: the 17 bytes, else a frame-style class.
        for n, cls in ((0, "truncated_payload"), (1, "truncated_payload"), (16, "truncated_payload"),
                       (18, "length_mismatch"), (21, "length_mismatch")):
            data = bytes.fromhex(worked + "00" * 4)[:n]
            s.add(op, profile, f"{base_id}.length.{n}", "control.value_length",
                  f"{n} bytes instead of 17: {cls}", {"hex": data.hex()},
                  R("control.value", "payload.truncated" if cls == "truncated_payload" else "payload.trailing"),
                  error=cls)
        for byte in range(256):
            c = classify_control_mode(byte, profile)
            bid = f"{base_id}.0x{byte:02x}"
            if c["classification"] != "documented":
                flags = R("control.undefined_mode")
                flags += ["E16"]
                if None in c["fields"].values():
                    flags += R("control.undefined")
                if profile == "m100-fw2.3" and c["raw"]["yaw_logic"] == 0 and c["raw"]["stable_mode"]:
                    flags += R("control.bit0_fw2_3") + ["E15"]
                if c["fields"]["vertical_logic"] == "vert_thrust":
                    flags += ["E16"]
                s.add(op, profile, f"{bid}.undefined", "control.undefined_mode",
                      f"mode byte 0x{byte:02x} is {c['classification']} on {profile}: undefined_mode whatever the "
                      f"setpoints ({c['reasons'][0]})",
                      {"hex": mc_hex(byte, f32(1.0), f32(-1.0), f32(50.0), f32(5.0))}, flags, error="undefined_mode")
                continue
            ranges = input_ranges(byte, profile)
            base = {a: f32(mid(ranges[reference.AXIS_RANGE[a]])) for a in axes}
            thrust = c["fields"]["vertical_logic"] == "vert_thrust"
            common = R("control.ranges", "control.combinations")
            if c["raw"]["stable_mode"]:
                common += ["E15"]
            if profile == "m100-fw2.3" and c["raw"]["yaw_logic"] == 1 and c["raw"]["stable_mode"]:
                common += R("control.bit0_fw2_3")
            s.add(op, profile, f"{bid}.mid", "control.ranges",
                  f"0x{byte:02x} (combination {c['combination']}), every setpoint mid-range", {"hex": mc_hex(byte, *base.values())},
                  common)
            vals = dict(base)
            for a in axes:
                lim = ranges[reference.AXIS_RANGE[a]]
                lo, hi = lim.get("min"), lim.get("max")
                vals[a] = f32(rng.uniform(lo if lo is not None else -1e6, hi if hi is not None else 1e6))
            s.add(op, profile, f"{bid}.random", "control.ranges",
                  f"0x{byte:02x}, random setpoints within the ranges", {"hex": mc_hex(byte, *vals.values())}, common)
            for a in axes:
                which = reference.AXIS_RANGE[a]
                lim = ranges[which]
                flags = common + (["E05"] if thrust and a == "z" else []) + (["E16"])
                for end, limit in (("min", lim.get("min")), ("max", lim.get("max"))):
                    vals = dict(base)
                    if limit is None:
                        vals[a] = 0xFF7FFFFF if end == "min" else 0x7F7FFFFF
                        s.add(op, profile, f"{bid}.{a}.{end}_unbounded_finite", "control.ranges",
                              f"0x{byte:02x}: {a} ({which}) has no {end}imum; the largest finite float32 is in range",
                              {"hex": mc_hex(byte, *vals.values())}, flags)
                        vals[a] = 0xFF800000 if end == "min" else 0x7F800000
                        s.add(op, profile, f"{bid}.{a}.{end}_unbounded_inf", "control.non_finite",
                              f"0x{byte:02x}: {a} ({which}) has no {end}imum, yet an infinity is out of range",
                              {"hex": mc_hex(byte, *vals.values())}, flags + R("control.non_finite"))
                        continue
                    at = f32(limit)
                    outside = f32_next_down(at) if end == "min" else f32_next_up(at)
                    vals[a] = at
                    s.add(op, profile, f"{bid}.{a}.at_{end}", "control.ranges",
                          f"0x{byte:02x}: {a} ({which}) exactly at its {end}imum {limit}: limits are inclusive",
                          {"hex": mc_hex(byte, *vals.values())}, flags)
                    vals[a] = outside
                    s.add(op, profile, f"{bid}.{a}.outside_{end}", "control.ranges",
                          f"0x{byte:02x}: {a} ({which}) one float32 step {'below' if end == 'min' else 'above'} "
                          f"its {end}imum {limit} ({f32_value(outside)!r})",
                          {"hex": mc_hex(byte, *vals.values())}, flags)
        # Special setpoints, per documented combination (ground frame, bit 0 clear) and axis.
        for index in range(1, 15):
            byte = default_rules().combination(index)["value"]
            ranges = input_ranges(byte, profile)
            base = {a: f32(mid(ranges[reference.AXIS_RANGE[a]])) for a in axes}
            for a in axes:
                for name in ("qnan", "snan", "neg_nan", "inf", "neg_inf", "neg_zero", "denormal_min", "neg_denormal_max"):
                    vals = dict(base)
                    vals[a] = F32_SPECIALS[name]
                    flags = R("control.ranges", "floats.bit_exact")
                    if name in NON_FINITE:
                        flags += R("control.non_finite")
                    if index in (13, 14) and a == "z":
                        flags += ["E05"]
                    s.add(op, profile, f"{base_id}.special.c{index}.{a}.{name}", "control.special_floats",
                          f"combination {index} (0x{byte:02x}): {a} = {name} (0x{F32_SPECIALS[name]:08x}) against the "
                          f"{reference.AXIS_RANGE[a]} range {ranges[reference.AXIS_RANGE[a]].get('min')}.."
                          f"{ranges[reference.AXIS_RANGE[a]].get('max')}",
                          {"hex": mc_hex(byte, *vals.values())}, flags)
        add_movement_precedence(s, profile)
    # ERRATA E15, written by hand: 0x41 (velocity, yaw angle, bit 0 set) is the
    # stable flag on FW 3.1 but a body yaw frame with yaw angle on FW 2.3.
    s.add("check_movement_control", "m100-fw2.3", "control_ranges.m100-fw2.3.e15_yaw_angle_body_frame",
          "control.bit0_fw2_3", "hand-written (ERRATA E15): on FW 2.3 bit 0 = 1 with yaw angle asks for a body yaw "
          "frame, which yaw angle does not allow: undefined_mode",
          {"hex": mc_hex(0x41, f32(1.0), f32(-1.0), f32(0.5), f32(30.0))},
          R("control.bit0_fw2_3", "control.undefined_mode") + ["E15"], error="undefined_mode")
    s.add("check_movement_control", "m100-fw3.1", "control_ranges.m100-fw3.1.e15_stable_yaw_angle",
          "control.bit0_fw2_3", "hand-written (ERRATA E15): the same bytes on FW 3.1: bit 0 is the stable flag, "
          "combination 3, accepted",
          {"hex": mc_hex(0x41, f32(1.0), f32(-1.0), f32(0.5), f32(30.0))},
          R("control.bit0_fw2_3", "control.ranges") + ["E15"],
          expected={"value": {"control_mode": {"stable_mode": enum(1, "stable"), "horizontal_frame": enum(0, "ground"),
                                               "yaw_logic": enum(0, "yaw_ang"), "vertical_logic": enum(0, "vert_vel"),
                                               "horizontal_logic": enum(1, "hori_vel")},
                              "x": f32_model(0x3F800000), "y": f32_model(0xBF800000),
                              "z": f32_model(0x3F000000), "yaw": f32_model(0x41F00000)},
                    "combination": 3})
    return s


# ============================================================== broadcast.json

SIZE_NOTE = {"time_stamp": "E08", "gimbal": "E09", "control_info": "E03", "gps_detail": "E06", "rtk_detail": "E06",
             "magnetometer": "E07", "rc": "E07", "position": "E01", "velocity": "E04", "acceleration": "E18",
             "angular_rate": "E18", "flight_status": "E19", "quaternion": "E29", "battery": "E25"}


def gen_broadcast(a3_valid_every: int) -> Suite:
    s = Suite("broadcast", "decode_payload of the flight data broadcast (set 0x02, id 0x00) in each profile: "
                           "every single item, every flag word, all-items payloads, special floats, truncated and "
                           "long payloads, reserved flag bits, and the errata decisions about items.", seed=303)
    rng = s.rng
    op = "decode_payload"
    for profile in PROFILES:
        p = rules_profile(profile)
        order = R(f"broadcast.flag_order.{profile}")
        pid = f"broadcast.{profile}"
        # -- every single item
        for bit, item in enumerate(p.flag_bits):
            data = payload(profile, 1 << bit, Values(rng))
            assert len(data) == 2 + p.item_sizes[item]
            flags = order + R("broadcast.item_sizes", "broadcast.item_fields") + [SIZE_NOTE[item]]
            if item == "time_stamp" and profile == "m100-fw2.3":
                flags += ["E28"]
            if profile == "m100-fw2.3":
                flags += ["E27"]
            if item == "rtk_detail":
                flags += ["E14"]
            if item == "gps_detail":
                flags += ["E13"]
            if item == "control_info" and profile != "m100-fw2.3":
                flags += ["E02"]
            if item == "position":
                flags += ["E29"]  # latitude/longitude, not the seed's lati/longti
            s.add(op, profile, f"{pid}.single.{item}", "broadcast.single_item",
                  f"only {item} (flag bit {bit}, {p.item_sizes[item]} bytes in {profile}), random values",
                  bc_input(data), flags)
            # the item one byte short, and missing altogether
            s.add(op, profile, f"{pid}.truncated.{item}.short_by_1", "broadcast.bounds",
                  f"flag bit {bit} ({item}) set, the item one byte short: truncated_payload",
                  bc_input(data[:-1]), order + R("broadcast.bounds") + ["E25"], error="truncated_payload")
            s.add(op, profile, f"{pid}.truncated.{item}.missing", "broadcast.bounds",
                  f"flag bit {bit} ({item}) set, no item bytes at all: truncated_payload",
                  bc_input(data[:2]), R("broadcast.bounds") + ["E25"], error="truncated_payload")
            s.add(op, profile, f"{pid}.trailing.{item}", "broadcast.bounds",
                  f"only {item}, then one byte more than the flags announce: length_mismatch",
                  bc_input(data + b"\x00"), R("broadcast.bounds") + ["E25"], error="length_mismatch")
        # -- all items
        for k in range(3):
            data = payload(profile, p.all_flags, Values(rng))
            s.add(op, profile, f"{pid}.all_items.{k}", "broadcast.all_items",
                  f"every item of {profile} present ({len(data)} bytes), random values #{k}", bc_input(data),
                  order + R("broadcast.item_sizes", "broadcast.item_fields") + (["E27"] if profile == "m100-fw2.3" else []))
            s.add(op, profile, f"{pid}.all_items.{k}.short_by_1", "broadcast.bounds",
                  "every item present, the payload one byte short: truncated_payload", bc_input(data[:-1]),
                  R("broadcast.bounds") + ["E25"], error="truncated_payload")
            s.add(op, profile, f"{pid}.all_items.{k}.trailing", "broadcast.bounds",
                  "every item present, then 3 bytes more: length_mismatch", bc_input(data + b"\x01\x02\x03"),
                  R("broadcast.bounds") + ["E25"], error="length_mismatch")
        # -- special floats in every float-bearing item
        specials32 = list(F32_SPECIALS.values())
        specials64 = list(F64_SPECIALS.values())
        pairs = [(specials32[i % len(specials32)], specials64[i % len(specials64)]) for i in range(len(specials32))]
        for item in FLOAT_ITEMS:
            if item not in p.flag_bits:
                continue
            for shift in range(3):
                v = Values(rng, pairs[shift:] + pairs[:shift])
                data = payload(profile, 1 << p.bit(item), v)
                s.add(op, profile, f"{pid}.special_floats.{item}.{shift}", "broadcast.special_floats",
                      f"{item} with NaN (quiet, signalling, payload, negative), infinities, -0.0, denormals and "
                      f"the largest float32 as values (rotation {shift}); every bit survives",
                      bc_input(data), R("floats.bit_exact", "broadcast.item_fields"))
        # -- flag word itself
        s.add(op, profile, f"{pid}.flag_word.empty", "broadcast.flag_word", "empty payload: no flag word",
              bc_input(b""), R("broadcast.flag_word") + ["E25"], error="truncated_payload")
        s.add(op, profile, f"{pid}.flag_word.one_byte", "broadcast.flag_word", "one byte: half a flag word",
              bc_input(b"\x01"), R("broadcast.flag_word") + ["E25"], error="truncated_payload")
        s.add(op, profile, f"{pid}.flag_word.none_set_trailing", "broadcast.bounds",
              "flag word 0 and one more byte: length_mismatch", bc_input(b"\x00\x00\x00"),
              R("broadcast.bounds", "broadcast.flag_word") + ["E25"], error="length_mismatch")
        # -- reserved flag bits
        for bit in range(len(p.flag_bits), 16):
            for with_items in (False, True):
                base = p.all_flags if with_items else 0
                data = payload(profile, base, Values(rng))
                data = le16(base | 1 << bit) + data[2:]
                s.add(op, profile, f"{pid}.reserved_flag.bit{bit}{'.with_items' if with_items else ''}",
                      "broadcast.reserved_flags",
                      f"reserved flag bit {bit} set{' next to every item' if with_items else ''}: reserved_bits",
                      bc_input(data), R("broadcast.reserved_flags") + ["E25"], error="reserved_bits")
        # -- errata about items
        gen_broadcast_errata(s, profile, rng)
    # -- every flag word of every profile (compact: small cases, random values)
    for profile in PROFILES:
        p = rules_profile(profile)
        order = R(f"broadcast.flag_order.{profile}")
        pid = f"broadcast.{profile}"
        n = 1 << len(p.flag_bits)
        for flags in range(n):
            data = payload(profile, flags, Values(rng))
            items = bin(flags).count("1")
            sampled = rng.randrange(a3_valid_every) == 0
            if profile != "a3-fw3.1" or items <= 2 or items >= len(p.flag_bits) - 2 or sampled:
                s.add(op, profile, f"{pid}.flags.0x{flags:04x}", "broadcast.flag_subsets",
                      f"flag word 0x{flags:04x}, random values", bc_input(data),
                      order + R("broadcast.item_sizes"))
            else:
                # Size budget: a3-fw3.1 has 16384 flag words and a valid
                # decode of an average one takes ~2 KB. Every flag word still
                # appears once: valid when it has at most 2 or all but at most
                # 2 items (every pair of items in order), or is in a seeded
                # sample; otherwise its random-valued payload one byte short
                # of what the word announces (the sizes of its items add up).
                s.add(op, profile, f"{pid}.flags.0x{flags:04x}.short_by_1", "broadcast.flag_subsets",
                      f"flag word 0x{flags:04x}, random values, one byte short", bc_input(data[:-1]),
                      order + R("broadcast.item_sizes", "broadcast.bounds"), error="truncated_payload")
    return s


def gen_broadcast_errata(s: Suite, profile: str, rng: random.Random) -> None:
    op = "decode_payload"
    p = rules_profile(profile)
    pid = f"broadcast.{profile}"
    fw3 = profile != "m100-fw2.3"

    # E01, hand-written: latitude first. 0.5 rad, -2.0 rad, altitude 100.5 m, height 3.25 m, health 4.
    data = le16(1 << 5) + struct.pack("<ddffB", 0.5, -2.0, 100.5, 3.25, 4)
    s.add(op, profile, f"{pid}.e01.latitude_first", "broadcast.item_fields",
          "hand-written (ERRATA E01): the position item starts with latitude (0.5 rad), then longitude (-2.0 rad), "
          "altitude, height, GPS health; a decoder following the seed's table would swap them",
          bc_input(data), R("broadcast.item_fields") + ["E01", "E29"],
          expected={"value": {"data": {**broadcast_flags_model(profile, {"position"}), "position": {
              "latitude": {"f64": "0x3fe0000000000000", "value": 0.5},
              "longitude": {"f64": "0xc000000000000000", "value": -2.0},
              "altitude": {"f32": "0x42c90000", "value": 100.5},
              "height": {"f32": "0x40500000", "value": 3.25},
              "gps_health": 4}}}})

    # E02: every cur_mov_control_mode value, and unnamed ones.
    if fw3:
        names = {0: "atti_stop", 97: "gps_atti_ctrl_cl_yaw_rate", 98: "gps_atti_ctrl_yaw_rate",
                 99: "atti_ctrl_yaw_rate", 100: "atti_ctrl_stop"}
        for vi, vname in enumerate(("vel", "pos", "thr")):
            for hi, hname in enumerate(("ang", "vel", "pos")):
                for yi, yname in enumerate(("ang", "rate")):
                    names[1 + 6 * vi + 2 * hi + yi] = f"horiz_{hname}_vert_{vname}_yaw_{yname}"
        for mode in [*range(0, 19), 19, 96, 97, 98, 99, 100, 101, 255]:
            data = le16(1 << p.bit("control_info")) + bytes([mode, 0x0A])
            expected = {"value": {"data": {**broadcast_flags_model(profile, {"control_info"}), "control_info": {
                "cur_mov_control_mode": enum(mode, names.get(mode)), "control_device": enum(2, "onboard_device"),
                "onboard_requested": True, "virtual_rc": False, "reserved": 0}}}}
            s.add(op, profile, f"{pid}.e02.cur_mov_control_mode.{mode}", "broadcast.control_info",
                  f"hand-written (ERRATA E02): control info with current mode {mode} "
                  f"({names.get(mode) or 'no name: decodes with name null, not an error'}), device byte 0x0a",
                  bc_input(data), R("broadcast.item_fields") + ["E02"] + (R("enums.unnamed") if mode not in names else []),
                  expected=expected)

    # E03: the device byte alone on FW 2.3, after the mode byte on FW 3.1; reserved bits never an error.
    for dev in (0x00, 0x01, 0x02, 0x03, 0x07, 0x08, 0x10, 0xE0, 0xFF):
        item = bytes([5, dev]) if fw3 else bytes([dev])
        data = le16(1 << p.bit("control_info")) + item
        s.add(op, profile, f"{pid}.e03.device_byte.0x{dev:02x}", "broadcast.control_info",
              f"control info ({len(item)} byte{'s' if fw3 else ''} in {profile}) with device byte 0x{dev:02x}"
              + ("; device values 3..7 have no name" if dev & 7 > 2 else "")
              + ("; reserved bits 5-7 set, still valid" if dev & 0xE0 else ""),
              bc_input(data), R("broadcast.item_fields", "broadcast.reserved_item_bits", "broadcast.item_sizes") + ["E03"]
              + (R("enums.unnamed") if dev & 7 > 2 else []))
    other = bytes([0x02]) if fw3 else bytes([0x05, 0x02])
    s.add(op, profile, f"{pid}.e03.other_firmware_size", "broadcast.control_info",
          f"control info in the size of the other firmware ({len(other)} byte): "
          + ("truncated_payload" if fw3 else "length_mismatch"),
          bc_input(le16(1 << p.bit("control_info")) + other), R("broadcast.item_sizes", "broadcast.bounds") + ["E03"])

    # E04: velocity status byte.
    for status in (0x00, 0x01, 0x06, 0x07, 0x0D, 0x0F, 0x1F, 0xE1, 0xFF):
        data = le16(1 << p.bit("velocity")) + struct.pack("<fffB", 1.5, -0.25, 0.0, status)
        s.add(op, profile, f"{pid}.e04.velocity_status.0x{status:02x}", "broadcast.velocity",
              f"velocity with status byte 0x{status:02x}: data_valid {status & 1}, sensor_id {status >> 1 & 15}, "
              f"reserved {status >> 5} (informative bits, never an error)",
              bc_input(data), R("broadcast.item_fields", "broadcast.reserved_item_bits") + ["E04"])

    # E05 is about movement control (control_ranges.json); E06/E13/E14: GPS and RTK detail.
    if profile == "a3-fw3.1":
        data = le16(1 << 6) + struct.pack("<IIiiifff", 20170315, 123456, 1139876543, 225432100, -45678, 12.5, -3.0, 0.25)
        s.add(op, profile, f"{pid}.e13.gps_detail_longitude_first", "broadcast.item_fields",
              "hand-written (ERRATA E13): GPS detail is date 20170315 (decimal yyyymmdd), time 123456 (hhmmss), "
              "longitude 113.9876543 deg x 1e7 before latitude 22.54321 deg x 1e7, height -45678 mm, "
              "velocities 12.5, -3.0, 0.25 cm/s (32 bytes)",
              bc_input(data), R("broadcast.item_fields", "broadcast.item_sizes") + ["E13", "E06"],
              expected={"value": {"data": {**broadcast_flags_model(profile, {"gps_detail"}), "gps_detail": {
                  "date": 20170315, "time": 123456, "longitude": 1139876543, "latitude": 225432100,
                  "height_msl": -45678, "vel_n": {"f32": "0x41480000", "value": 12.5},
                  "vel_e": {"f32": "0xc0400000", "value": -3.0}, "vel_d": {"f32": "0x3e800000", "value": 0.25}}}}})
        for yaw in (-32768, -1, 0, 1800, 32767):
            data = le16(1 << 7) + struct.pack("<IIddffffhBB", 20170315, 235959, 113.5, 22.25, 50.5, 1.0, 2.0, 3.0,
                                              yaw, 50, 16)
            s.add(op, profile, f"{pid}.e14.rtk_yaw.{yaw}", "broadcast.item_fields",
                  f"RTK detail (44 bytes) with yaw {yaw} decoded as a raw i16, no range check",
                  bc_input(data), R("broadcast.item_fields", "broadcast.item_sizes") + ["E14", "E06"])
        for item, size, sizes in (("gps_detail", 68, "later firmware GPS detail (68 bytes)"),
                                  ("rtk_detail", 74, "the 74 bytes the A3 OPENProtocol edition lists"),
                                  ("time_stamp", 15, "later firmware time stamp (15 bytes)"),
                                  ("position", 50, "later firmware position (50 bytes)"),
                                  ("flight_status", 4, "later firmware flight status (4 bytes)"),
                                  ("battery", 13, "later firmware battery (13 bytes)")):
            data = le16(1 << p.bit(item)) + bytes(rng.getrandbits(8) for _ in range(size))
            s.add(op, profile, f"{pid}.e20.later_firmware.{item}", "broadcast.later_firmware",
                  f"{sizes} decoded as {profile} ({p.item_sizes[item]} bytes): length_mismatch, not a misread",
                  bc_input(data), R("broadcast.bounds", "broadcast.item_sizes") + ["E20", "E25"] +
                  (["E13"] if item == "gps_detail" else ["E14"] if item == "rtk_detail" else []),
                  error="length_mismatch")

    # E07: magnetometer and RC.
    for tag, vals in (("extremes", (-32768, 32767, 0)), ("signs", (-1, 1, -300))):
        data = le16(1 << p.bit("magnetometer")) + struct.pack("<3h", *vals)
        s.add(op, profile, f"{pid}.e07.magnetometer.{tag}", "broadcast.item_fields",
              f"magnetometer (3 x i16, 6 bytes) {vals}", bc_input(data),
              R("broadcast.item_fields", "broadcast.item_sizes") + ["E07"])
    for tag, vals in (("nominal_p_gear_up", (-10000, 10000, 0, 5000, -8000, -10000)),
                      ("nominal_a_gear_down", (0, 0, 0, 0, 0, -4545)),
                      ("nominal_f", (10000, -10000, 10000, -10000, 8000, -4545)),
                      ("off_nominal", (-32768, 32767, 12000, -12000, 7000, -6000))):
        data = le16(1 << p.bit("rc")) + struct.pack("<6h", *vals)
        s.add(op, profile, f"{pid}.e17.rc.{tag}", "broadcast.item_fields",
              f"RC (6 x i16: roll, pitch, yaw, throttle, mode, gear) {vals}; raw values are always kept "
              f"(ranges and switch positions are plausibility, not decoding)",
              bc_input(data), R("broadcast.item_fields", "broadcast.item_sizes") + ["E07", "E17"])

    # E08: time stamp sizes.
    data = le16(1) + (struct.pack("<IIB", 400, 2_500_000, 1) if fw3 else struct.pack("<I", 400))
    s.add(op, profile, f"{pid}.e08.time_stamp", "broadcast.time_stamp",
          f"time stamp of {profile}: {'time 400, nano_time 2500000, sync_flag 1 (9 bytes)' if fw3 else 'time 400 (4 bytes)'}",
          bc_input(data), R("broadcast.item_sizes", "broadcast.item_fields") + ["E08"])
    other = struct.pack("<I", 400) if fw3 else struct.pack("<IIB", 400, 2_500_000, 1)
    s.add(op, profile, f"{pid}.e08.time_stamp_other_firmware", "broadcast.time_stamp",
          f"time stamp in the other firmware's size ({len(other)} bytes) decoded as {profile}",
          bc_input(le16(1) + other), R("broadcast.item_sizes", "broadcast.bounds") + ["E08", "E28"])

    # E09: gimbal with and without the limit byte.
    for limit in ((0x00, 0x01, 0x02, 0x04, 0xF8, 0xFF) if fw3 else (None,)):
        item = struct.pack("<fff", 1.5, -90.0, 180.0) + (bytes([limit]) if limit is not None else b"")
        s.add(op, profile, f"{pid}.e09.gimbal{'.limit_0x%02x' % limit if limit is not None else ''}",
              "broadcast.gimbal",
              f"gimbal roll 1.5, pitch -90, yaw 180 ({len(item)} bytes)"
              + (f", limit byte 0x{limit:02x}" + ("; reserved bits set, still valid" if limit & 0xF8 else "")
                 if limit is not None else ", no limit byte on FW 2.3"),
              bc_input(le16(1 << p.bit("gimbal")) + item),
              R("broadcast.item_fields", "broadcast.item_sizes", "broadcast.reserved_item_bits") + ["E09"])
    other = struct.pack("<fff", 1.5, -90.0, 180.0) + (b"" if fw3 else b"\x01")
    s.add(op, profile, f"{pid}.e09.gimbal_other_firmware", "broadcast.gimbal",
          f"gimbal in the other firmware's size ({len(other)} bytes) decoded as {profile}",
          bc_input(le16(1 << p.bit("gimbal")) + other), R("broadcast.item_sizes", "broadcast.bounds") + ["E09"])

    # E18: units are not on the wire: acceleration and angular rate decode as plain floats.
    for item in ("acceleration", "angular_rate"):
        data = le16(1 << p.bit(item)) + struct.pack("<fff", 9.8125, -0.5, 1.0)
        s.add(op, profile, f"{pid}.e18.{item}", "broadcast.item_fields",
              f"{item} x 9.8125, y -0.5, z 1.0: plain float32, m/s^2 or g (acceleration) is a device setting",
              bc_input(data), R("broadcast.item_fields", "floats.bit_exact") + ["E18"])

    # E19: flight status is a raw byte; the old/new enum is applied by plausibility, not decoding.
    for value in (0, 1, 2, 3, 4, 5, 6, 255):
        data = le16(1 << p.bit("flight_status")) + bytes([value])
        s.add(op, profile, f"{pid}.e19.flight_status.{value}", "broadcast.flight_status",
              f"flight status {value}: decoded as the raw byte in every profile (old enum on M100, new on A3)",
              bc_input(data), R("broadcast.item_fields") + ["E19"],
              expected={"value": {"data": {**broadcast_flags_model(profile, {"flight_status"}), "flight_status": value}}})

    # E25/worked broadcast: flight status 3 and battery 87 at bits 11/12 (a3) -- the worked
    # frame's value; in the M100 profiles bit 12 is reserved (E28: the profile decides).
    value = bytes.fromhex("00180357")
    if profile == "a3-fw3.1":
        s.add(op, profile, f"{pid}.worked_value", "broadcast.worked",
              "hand-written: the value of the PROTOCOL-FACTS broadcast frame, flags 0x1800 (flight status 3, "
              "battery 87) in the A3 layout",
              bc_input(value), R("broadcast.flag_order.a3-fw3.1") + ["E28"],
              expected={"value": {"data": {**broadcast_flags_model(profile, {"flight_status", "battery"}),
                                           "flight_status": 3, "battery": 87}}})
    else:
        s.add(op, profile, f"{pid}.worked_value", "broadcast.worked",
              "the A3 worked broadcast value decoded as an M100 profile: bit 12 is reserved there (reserved_bits); "
              "the layout comes from the profile, never from the bytes",
              bc_input(value), R("broadcast.profile_select", "broadcast.reserved_flags") + ["E28"],
              error="reserved_bits")

    # E28: the same bytes in each profile mean different things.
    data = le16(1 << 6) + bytes(range(32))
    s.add(op, profile, f"{pid}.e28.bit6_32_bytes", "broadcast.profile_select",
          "flag bit 6 and 32 bytes: GPS detail in a3-fw3.1, a 6-byte magnetometer plus 26 stray bytes in the M100 "
          "profiles (length_mismatch)", bc_input(data), R("broadcast.profile_select") + ["E28"])
    data = le16(1 << 8) + struct.pack("<fff", 1.0, 2.0, 3.0) + b"\x07"
    s.add(op, profile, f"{pid}.e28.bit8_13_bytes", "broadcast.profile_select",
          "flag bit 8 and 13 bytes: gimbal with limit byte in m100-fw3.1, gimbal and a stray byte in m100-fw2.3, "
          "a 6-byte magnetometer and 7 stray bytes in a3-fw3.1", bc_input(data), R("broadcast.profile_select") + ["E28"])

    # E27: the 2.x doc's size table (position 24, magnetometer 12, RC 10) is wrong.
    if profile == "m100-fw2.3":
        items = {"time_stamp": 4, "quaternion": 16, "acceleration": 12, "velocity": 13, "angular_rate": 12,
                 "position": 24, "magnetometer": 12, "rc": 10, "gimbal": 12, "flight_status": 1, "battery": 1,
                 "control_info": 1}
        data = le16(0x0FFF) + bytes(sum(items.values()))
        s.add(op, profile, f"{pid}.e27.doc_2x_sizes", "broadcast.item_sizes",
              "every item in the sizes of the 2.x doc table (118 bytes instead of 117): length_mismatch",
              bc_input(data), R("broadcast.item_sizes", "broadcast.bounds") + ["E27"], error="length_mismatch")
        data = le16(1 << 6) + bytes(12)
        s.add(op, profile, f"{pid}.e27.magnetometer_12", "broadcast.item_sizes",
              "magnetometer in the 2.x table's 12 bytes: length_mismatch (it is 3 x i16)",
              bc_input(data), R("broadcast.item_sizes", "broadcast.bounds") + ["E27", "E07"], error="length_mismatch")
        data = le16(0x0FFF) + bytes(117)
        s.add(op, profile, f"{pid}.e27.all_items_117", "broadcast.item_sizes",
              "every item, all zero: 117 bytes after the flag word (the sizes of the structs)",
              bc_input(data), R("broadcast.item_sizes") + ["E27"])


# ============================================================== payloads.json


def gen_payloads() -> Suite:
    s = Suite("payloads", "decode_payload of every other command and ACK value of osdk_payload.ksy (valid, short, "
                          "long) and of commands the spec does not describe.", seed=404)
    rng = s.rng
    op = "decode_payload"
    for profile in PROFILES:
        pid = f"payloads.{profile}"

        def add(name: str, cmd_set: int, cmd_id: int, is_ack: bool, data: bytes, comment: str, flags: list[str],
                **kw: Any) -> None:
            s.add(op, profile, f"{pid}.{name}", "payload." + name.split(".")[0],
                  comment, {"hex": data.hex(), "cmd_set": cmd_set, "cmd_id": cmd_id, "is_ack": is_ack}, flags, **kw)

        def lengths(name: str, cmd_set: int, cmd_id: int, is_ack: bool, good: bytes, rule: str, errata: list[str]) -> None:
            add(f"{name}.short_by_1", cmd_set, cmd_id, is_ack, good[:-1], f"{name}, one byte short: truncated_payload",
                R(rule, "payload.truncated") + errata, error="truncated_payload")
            add(f"{name}.trailing", cmd_set, cmd_id, is_ack, good + b"\x00", f"{name}, one byte too many: length_mismatch",
                R(rule, "payload.trailing") + errata, error="length_mismatch")

        # version query and its ACK
        for b in (0x00, 0x01, 0xFF):
            add(f"version_query.0x{b:02x}", 0, 0, False, bytes([b]), f"get version, arbitrary byte 0x{b:02x}",
                R("payload.version_query"))
        add("version_query.empty", 0, 0, False, b"", "get version with no byte: truncated_payload",
            R("payload.version_query", "payload.truncated"), error="truncated_payload")
        add("version_query.two_bytes", 0, 0, False, b"\x00\x00", "get version with two bytes: length_mismatch",
            R("payload.version_query", "payload.trailing"), error="length_mismatch")
        name_bytes = b"SDK-v1.0 BETA M100-03.01.10.00".ljust(32, b"\x00")
        # FW 3.1 puts an 11-byte version ID between the CRC and the name, FW 2.3 none (E30)
        id_bytes = b"" if profile == "m100-fw2.3" else b"01.00.0100".ljust(11, b"\x00")
        for code, cname in ((0x0000, "activated"), (0xFF01, "not_activated"), (0x0001, None)):
            data = struct.pack("<HI", code, 0x12345678) + id_bytes + name_bytes
            kw = {}
            if code == 0x0000:
                kw["expected"] = {"value": {"ack_code": enum(0, "activated"), "version_crc": 0x12345678,
                                            **({"version_id": id_bytes.hex()} if id_bytes else {}),
                                            "version_name": name_bytes.hex()}}
            add(f"version_ack.0x{code:04x}", 0, 0, True, data,
                f"version ACK, code 0x{code:04x} ({cname or 'no name'}), CRC 0x12345678, "
                + ("a NUL-padded 11-byte version ID, " if id_bytes else "no version ID (FW 2.3), ")
                + "a NUL-padded 32-byte name" + ("; hand-written" if kw else ""),
                R("payload.version_ack") + ["E30"] + (R("enums.unnamed") if cname is None else []), **kw)
        lengths("version_ack", 0, 0, True, struct.pack("<HI", 0, 1) + id_bytes + name_bytes, "payload.version_ack",
                ["E30"])
        if id_bytes:
            add("version_ack.fw2_3_layout", 0, 0, True, struct.pack("<HI", 0, 1) + name_bytes,
                "the FW 2.3 version ACK (no version ID, 38 bytes) in a FW 3.1 profile: 11 bytes short, "
                "truncated_payload", R("payload.version_ack", "payload.truncated") + ["E30"], error="truncated_payload")
        else:
            add("version_ack.fw3_1_layout", 0, 0, True,
                struct.pack("<HI", 0, 1) + b"01.00.0100".ljust(11, b"\x00") + name_bytes,
                "the FW 3.1 version ACK (11-byte version ID, 49 bytes) in the FW 2.3 profile: 11 bytes too many, "
                "length_mismatch", R("payload.version_ack", "payload.trailing") + ["E30"], error="length_mismatch")
        # activation
        for prof_name, version in (("m100-fw2.3", 0x02030A00), ("m100-fw3.1", 0x03010A00), ("a3-fw3.1", 0x03016400)):
            data = struct.pack("<III", 1012345, 2, version) + b"12345678901234567890123456789012"
            kw = {}
            if prof_name == profile:
                kw["expected"] = {"value": {"app_id": 1012345, "api_level": 2, "sdk_version": version,
                                            "bundle_id": b"12345678901234567890123456789012".hex()}}
            add(f"activation_request.{prof_name}", 0, 1, False, data,
                f"activation with app id 1012345, API level 2 at offset 4, SDK version 0x{version:08x} ({prof_name}), "
                f"32-byte bundle id (44 bytes)" + ("; hand-written" if kw else ""),
                R("payload.activation_request") + ["E12", "E31"], **kw)
        data40 = struct.pack("<II", 1012345, 0x03010A00) + b"1" * 32
        add("activation_request.forty_bytes", 0, 1, False, data40,
            "the 40-byte activation of a client that left out the API level word: truncated_payload",
            R("payload.activation_request", "payload.truncated") + ["E12"], error="truncated_payload")
        lengths("activation_request", 0, 1, False, struct.pack("<III", 1, 2, 3) + bytes(32), "payload.activation_request",
                ["E12"])
        for code in range(0, 10):
            add(f"activation_ack.{code}", 0, 1, True, le16(code), f"activation ACK code {code}",
                R("payload.activation_ack") + (R("enums.unnamed") if code > 8 else []) + ["E12"])
        lengths("activation_ack", 0, 1, True, le16(0), "payload.activation_ack", [])
        # frequencies
        codes = list(range(8)) + [8, 255] + [0] * 6
        add("frequency_request.all_codes", 0, 0x10, False, bytes(codes),
            "set frequency with codes 0..7, then 8 and 255 (no name), then zeros; 6 and 7 are later-SDK codes",
            R("payload.frequency_request", "enums.unnamed") + ["E11"])
        hz_code = {0: 0, 1: 1, 10: 2, 50: 3, 100: 4}
        rp = rules_profile(profile)
        defaults = [hz_code[rp.default_rates_hz[i]] for i in rp.flag_bits]
        data = bytes(defaults + [0] * (16 - len(defaults)))
        add("frequency_request.default_rates", 0, 0x10, False, data,
            f"set frequency to the default rates of {profile} (ERRATA E10), reserved tail zero",
            R("payload.frequency_request") + ["E10", "E11", "E31"])
        add("frequency_request.reserved_tail", 0, 0x10, False, bytes([5] * 12 + [1, 2, 3, 4]),
            "set frequency, keep everything, non-zero tail bytes: reported by rules, decoded here",
            R("payload.frequency_request") + ["E11"])
        lengths("frequency_request", 0, 0x10, False, bytes(16), "payload.frequency_request", ["E11"])
        for code in (0, 1, 2):
            add(f"frequency_ack.{code}", 0, 0x10, True, le16(code), f"set frequency ACK {code}",
                R("payload.frequency_ack") + (R("enums.unnamed") if code > 1 else []))
        lengths("frequency_ack", 0, 0x10, True, le16(0), "payload.frequency_ack", [])
        # control authority
        for b in (0, 1, 2):
            add(f"control_request.{b}", 1, 0, False, bytes([b]), f"control request {b}",
                R("payload.control_request") + (R("enums.unnamed") if b > 1 else ["E31"]))
        lengths("control_request", 1, 0, False, b"\x01", "payload.control_request", [])
        names = {0: "rc_not_in_f_mode", 1: "released", 2: "obtained", 3: "obtain_in_progress", 4: "release_in_progress",
                 0xC9: "in_ioc_mode"}
        for code in (0, 1, 2, 3, 4, 5, 6, 0xC9, 0xFFFF):
            add(f"control_ack.0x{code:04x}", 1, 0, True, le16(code),
                f"control ACK 0x{code:04x}: {names.get(code) or 'no name (5 and 6 are SDK-local, never on the wire)'}"
                "; hand-written", R("payload.control_ack") + ["E26", "E31"] + (R("enums.unnamed") if code not in names else []),
                expected={"value": {"ack_code": enum(code, names.get(code))}})
        lengths("control_ack", 1, 0, True, le16(2), "payload.control_ack", ["E26"])
        # movement control as a payload: any mode byte parses
        for byte in (0x00, 0x4B, 0xFF):
            data = bytes([byte]) + struct.pack("<ffff", 0.5, -0.5, 10.0, 90.0)
            add(f"movement_control.0x{byte:02x}", 1, 3, False, data,
                f"movement control value with mode byte 0x{byte:02x}: the layout parses any byte (unnamed fields "
                f"have name null); check_movement_control judges it", R("payload.movement_control", "control.fields")
                + (R("enums.unnamed") if byte == 0xFF else []) + (["E31"] if byte == 0x4B else []))
        lengths("movement_control", 1, 3, False, bytes(17), "payload.movement_control", [])
        # lost control and its ACK (E24)
        add("lost_control.0x04", 2, 1, False, b"\x04", "lost control authority, reason 0x04",
            R("payload.lost_control") + ["E31"])
        lengths("lost_control", 2, 1, False, b"\x04", "payload.lost_control", [])
        add("lost_control_ack.zero", 2, 1, True, b"\x00\x00",
            "the device's 2-byte zero answer to a lost-control push in session > 0",
            R("payload.lost_control_ack") + ["E24", "E31"])
        lengths("lost_control_ack", 2, 1, True, b"\x00\x00", "payload.lost_control_ack", ["E24"])
        # unknown commands and ACKs: raw
        for (cs, ci, ack, n) in ((0x00, 0x02, False, 5), (0x01, 0x01, False, 0), (0x01, 0x03, True, 2),
                                 (0x02, 0x00, True, 3), (0x03, 0x00, False, 7), (0xFF, 0xFF, True, 1)):
            data = bytes(rng.getrandbits(8) for _ in range(n))
            what = {(0x01, 0x03, True): "ACK of movement control (it has none)",
                    (0x02, 0x00, True): "ACK of the broadcast (it has none)"}.get((cs, ci, ack), "a command the spec does not describe")
            add(f"unknown.0x{cs:02x}{ci:02x}{'.ack' if ack else ''}", cs, ci, ack, data,
                f"set 0x{cs:02x} id 0x{ci:02x}{' ACK' if ack else ''}: {what}; the {n}-byte value stays raw",
                R("payload.unknown"), expected={"value": {"raw": data.hex()}})
    return s


# ============================================================== frames.json


def gen_frames() -> Suite:
    s = Suite("frames", "decode_frame: exactly one frame's bytes: the worked frames, every header field's invalid "
                        "values, single-bit CRC errors, truncation at every byte, header-only, AES and ACK frames, "
                        "and values that do not decode.", seed=505)
    rng = s.rng
    op = "decode_frame"
    move = bytes.fromhex(WORKED_MOVEMENT)
    for profile in PROFILES:
        pid = f"frames.{profile}"
        bcast_value = payload(profile, 1 | 1 << rules_profile(profile).bit("battery"), Values(rng))
        bcast = frame_bytes(cmd_set=2, cmd_id=0, value=bcast_value, seq=7)

        def add(name: str, category: str, comment: str, data: bytes, flags: list[str], **kw: Any) -> None:
            s.add(op, profile, f"{pid}.{name}", category, comment, {"hex": data.hex()}, flags, **kw)

        # worked frames, hand-written
        add("worked.movement_control", "frame.worked",
            "hand-written: the PROTOCOL-FACTS movement control frame (session 0, seq 0x1234, mode 0x4B, x 1.0, "
            "y -2.0, z 0.5, yaw 30.0); CRC-16 0x72e1 and CRC-32 0xba01dbfc as stored little-endian",
            move, R("frame.crc16", "frame.crc32", "frame.data", "frame.len") + ["E21"],
            expected={"frame": {
                "sof": "aa", "len": 35, "ver": 0, "session": 0, "is_ack": False, "res0": 0, "padding": 0,
                "enc": enum(0, "plain"), "res1": 0, "seq": 0x1234, "crc16": 0x72E1,
                "data": {"cmd_set": enum(1, "control"), "cmd_id": 3, "value": {"body": {
                    "control_mode": {"stable_mode": enum(1, "stable"), "horizontal_frame": enum(1, "body"),
                                     "yaw_logic": enum(1, "yaw_rate"), "vertical_logic": enum(0, "vert_vel"),
                                     "horizontal_logic": enum(1, "hori_vel")},
                    "x": f32_model(0x3F800000), "y": f32_model(0xC0000000), "z": f32_model(0x3F000000),
                    "yaw": f32_model(0x41F00000)}}},
                "crc32": 0xBA01DBFC}})
        worked_b = bytes.fromhex(WORKED_BROADCAST)
        if profile == "a3-fw3.1":
            add("worked.broadcast", "frame.worked",
                "hand-written: the PROTOCOL-FACTS broadcast frame (seq 7, flags 0x1800, flight status 3, battery 87)",
                worked_b, R("frame.crc16", "frame.crc32", "frame.data", "broadcast.flag_order.a3-fw3.1") + ["E21"],
                expected={"frame": {
                    "sof": "aa", "len": 22, "ver": 0, "session": 0, "is_ack": False, "res0": 0, "padding": 0,
                    "enc": enum(0, "plain"), "res1": 0, "seq": 7, "crc16": 0xDE1E,
                    "data": {"cmd_set": enum(2, "push"), "cmd_id": 0, "value": {"body": {"data": {
                        **broadcast_flags_model(profile, {"flight_status", "battery"}),
                        "flight_status": 3, "battery": 87}}}},
                    "crc32": 0xB276C669}})
        else:
            add("worked.broadcast", "frame.worked",
                "the A3 worked broadcast frame decoded with an M100 profile: flag bit 12 is reserved there",
                worked_b, R("frame.crc32", "broadcast.profile_select", "broadcast.reserved_flags") + ["E28", "E25"],
                error="reserved_bits")
        add("broadcast", "frame.valid", f"a {profile} broadcast frame (time stamp and battery)", bcast,
            R("frame.data", f"broadcast.flag_order.{profile}"))

        # SOF
        for b in (0x00, 0xAB, 0x2A, 0x55):
            data = bytes([b]) + move[1:]
            add(f"sof.0x{b:02x}", "frame.sof", f"first byte 0x{b:02x}, not the start byte: bad_sof (a stream "
                f"reports such bytes as garbage instead)", data,
                R("frame.sof"), error="bad_sof")
        # VER
        for ver in range(1, 64):
            add(f"ver.{ver}", "frame.ver", f"header version {ver} (both CRCs right): bad_version",
                frame_bytes(cmd_set=1, cmd_id=3, value=move[14:-4], seq=0x1234, ver=ver), R("frame.ver"),
                error="bad_version")
        # RES0, RES1
        for res0 in (1, 2, 3):
            add(f"res0.{res0}", "frame.reserved", f"RES0 = {res0}: reserved_bits",
                frame_bytes(cmd_set=1, cmd_id=3, value=move[14:-4], res0=res0), R("frame.reserved") + ["E29"],
                error="reserved_bits")
        for res1 in (0x000001, 0x000080, 0x000100, 0x010000, 0x800000, 0xFFFFFF):
            add(f"res1.0x{res1:06x}", "frame.reserved", f"RES1 = 0x{res1:06x}: reserved_bits",
                frame_bytes(cmd_set=1, cmd_id=3, value=move[14:-4], res1=res1), R("frame.reserved") + ["E29"],
                error="reserved_bits")
        # LEN
        for length in list(range(0, 12)) + [13, 14, 15, 16]:
            data = frame_bytes(length=length, data=b"")
            add(f"len.{length}", "frame.len", f"LEN {length} (header only, CRC-16 right): impossible_length", data,
                R("frame.len") + ["E22"], error="impossible_length")
            if length >= 12:
                data = frame_bytes(length=length, data=b"")
                data += bytes(length - 12)
                add(f"len.{length}.with_bytes", "frame.len",
                    f"LEN {length} and {length} bytes in all: still impossible_length", data,
                    R("frame.len") + ["E22"], error="impossible_length")
        add("len.17.one_data_byte", "frame.data", "LEN 17: a command frame with only the command set: truncated_payload",
            frame_bytes(data=b"\x01"), R("frame.data", "frame.len") + ["E22"], error="truncated_payload")
        add("len.18.set_and_id", "frame.data", "LEN 18: version query with no value byte: truncated_payload",
            frame_bytes(cmd_set=0, cmd_id=0), R("frame.data", "payload.truncated") + ["E22"], error="truncated_payload")
        add("len.17.ack_one_byte", "frame.data", "LEN 17: an ACK frame with a 1-byte value (session 1)",
            frame_bytes(is_ack=True, session=1, value=b"\x00"), R("frame.data", "frame.len", "frame.session") + ["E22"])
        big = bytes(rng.getrandbits(8) for _ in range(1005))
        add("len.1023", "frame.len", "LEN 1023, the largest frame: an unknown command with a 1005-byte value",
            frame_bytes(cmd_set=0x00, cmd_id=0x7F, value=big), R("frame.len", "payload.unknown") + ["E22"])
        # header-only frames
        for session, is_ack, seq in ((0, False, 0), (5, False, 0xFFFF), (1, True, 1), (31, True, 0x1234)):
            add(f"header_only.s{session}{'.ack' if is_ack else ''}", "frame.header_only",
                f"header-only frame (LEN 12, no DATA, no CRC-32), session {session}, {'ACK' if is_ack else 'command'}, "
                f"seq {seq}", frame_bytes(session=session, is_ack=is_ack, seq=seq), R("frame.header_only") + ["E22"])
        add("header_only.ack_session0", "frame.session", "header-only ACK in session 0: bad_session",
            frame_bytes(session=0, is_ack=True), R("frame.header_only", "frame.session") + ["E24"], error="bad_session")
        add("header_only.ack_session0.enc1", "frame.session",
            "header-only ACK in session 0 with ENC 1 and no padding: two rules broken, the first in wire order "
            "(SESSION/ACK before ENC) is reported: bad_session (found by osdkc fuzz)",
            frame_bytes(session=0, is_ack=True, enc=1), R("frame.header_only", "frame.session", "frame.enc")
            + ["E23", "E24"], error="bad_session")
        # ENC and PADDING
        for enc in range(2, 8):
            add(f"enc.{enc}", "frame.enc", f"ENC {enc} (plain-sized DATA, PADDING 0): bad_encryption",
                frame_bytes(cmd_set=1, cmd_id=3, value=move[14:-4], enc=enc), R("frame.enc") + ["E23"],
                error="bad_encryption")
            add(f"enc.{enc}.blocks", "frame.enc", f"ENC {enc} with 16-byte DATA and PADDING 4: bad_encryption",
                frame_bytes(data=bytes(16), enc=enc, padding=4), R("frame.enc") + ["E23"], error="bad_encryption")
        for padding in (1, 15, 16, 31):
            add(f"plain.padding.{padding}", "frame.enc", f"plain frame with PADDING {padding}: bad_encryption",
                frame_bytes(cmd_set=1, cmd_id=3, value=move[14:-4], padding=padding), R("frame.enc") + ["E23"],
                error="bad_encryption")
        for blocks, padding in ((1, 1), (1, 16), (2, 7), (4, 16)):
            data = bytes(rng.getrandbits(8) for _ in range(16 * blocks))
            add(f"aes.{blocks}blocks.padding{padding}", "frame.aes",
                f"AES frame, {blocks} block(s) of ciphertext, PADDING {padding}: valid, DATA kept raw",
                frame_bytes(data=data, enc=1, padding=padding), R("frame.enc", "frame.aes_raw") + ["E23"])
        add("aes.ack", "frame.aes", "AES ACK frame (session 3), one block: valid, kept raw",
            frame_bytes(data=bytes(range(16)), enc=1, padding=14, is_ack=True, session=3), R("frame.aes_raw", "frame.session"))
        for padding, blocks, why in ((0, 1, "PADDING 0"), (17, 2, "PADDING 17"), (31, 2, "PADDING 31")):
            add(f"aes.padding{padding}", "frame.enc", f"AES frame with {why}: bad_encryption",
                frame_bytes(data=bytes(16 * blocks), enc=1, padding=padding), R("frame.enc") + ["E23"],
                error="bad_encryption")
        for size in (15, 17, 31):
            add(f"aes.data{size}", "frame.enc", f"AES frame with {size} bytes of DATA (not whole blocks): bad_encryption",
                frame_bytes(data=bytes(size), enc=1, padding=1), R("frame.enc") + ["E23"], error="bad_encryption")
        add("aes.header_only", "frame.enc", "AES flag on a header-only frame: bad_encryption",
            frame_bytes(enc=1, padding=16), R("frame.enc", "frame.header_only") + ["E23"], error="bad_encryption")
        # sessions and ACKs
        for session in (0, 1, 2, 31):
            add(f"ack.session{session}", "frame.session",
                f"control ACK frame in session {session}" + (": bad_session" if session == 0 else ""),
                frame_bytes(is_ack=True, session=session, seq=40, value=b"\x02\x00"), R("frame.session", "frame.data")
                + ["E24"])
            add(f"command.session{session}", "frame.session", f"control request command in session {session}",
                frame_bytes(cmd_set=1, cmd_id=0, value=b"\x01", session=session, seq=40), R("frame.session"))
        # unknown command set
        add("unknown_set", "frame.valid", "command set 0x05 (no name), id 0x01: value kept raw",
            frame_bytes(cmd_set=5, cmd_id=1, value=b"\x01\x02\x03"), R("frame.data", "payload.unknown", "enums.unnamed"))
        # values that do not decode
        add("value.movement_16_bytes", "frame.value", "movement control frame with a 16-byte value: truncated_payload",
            frame_bytes(cmd_set=1, cmd_id=3, value=bytes(16)), R("frame.data", "payload.truncated"))
        add("value.broadcast_reserved", "frame.value", "broadcast frame with reserved flag bit 15: reserved_bits",
            frame_bytes(cmd_set=2, cmd_id=0, value=le16(0x8000)), R("broadcast.reserved_flags") + ["E25"])
        add("value.broadcast_trailing", "frame.value", "broadcast frame, flag word 0 and one byte: length_mismatch",
            frame_bytes(cmd_set=2, cmd_id=0, value=b"\x00\x00\x00"), R("broadcast.bounds") + ["E25"])
        add("value.broadcast_short", "frame.value", "broadcast frame promising a time stamp it lacks: truncated_payload",
            frame_bytes(cmd_set=2, cmd_id=0, value=b"\x01\x00\x01"), R("broadcast.bounds") + ["E25"])
        # CRC-16: every bit of the header
        for bit in range(96):
            data = flip(move, bit)
            err = "bad_sof" if bit < 8 else "bad_crc16"
            add(f"crc16.bit{bit}", "frame.crc16",
                f"movement frame with header bit {bit} (byte {bit // 8}, bit {bit % 8}) flipped: {err}"
                + (" (the start byte is no longer 0xAA)" if bit < 8 else ""),
                data, R("frame.crc16") + (R("frame.sof") if bit < 8 else []) + ["E21"], error=err)
        # CRC-32: every bit of one frame
        for bit in range(len(bcast) * 8):
            data = flip(bcast, bit)
            err = "bad_sof" if bit < 8 else "bad_crc16" if bit < 96 else "bad_crc32"
            add(f"crc32.bit{bit}", "frame.crc32" if bit >= 96 else "frame.crc16",
                f"broadcast frame with bit {bit} (byte {bit // 8}) flipped: {err}", data,
                R("frame.crc32" if bit >= 96 else "frame.crc16") + ["E21"], error=err)
        # truncation at every byte
        for n in range(len(move)):
            add(f"truncated.{n}", "frame.truncation", f"the movement frame cut after {n} of {len(move)} bytes: "
                "truncated_frame", move[:n], R("frame.truncation"), error="truncated_frame")
        for extra in (b"\x00", b"\xaa", bytes(12)):
            add(f"extra.{len(extra)}.{extra[:1].hex()}", "frame.extra_bytes",
                f"the movement frame followed by {len(extra)} more byte(s): length_mismatch", move + extra,
                R("frame.extra_bytes"), error="length_mismatch")
        add_rule_pairs(s, profile, "decode_frame", "precedence", add)
        add_header_bits(s, profile, add, stream=False)
    return s


# ============================================================== streams.json


def gen_streams() -> Suite:
    s = Suite("streams", "decode_stream: frames found in byte streams as the SDK receiver finds them: garbage, "
                         "resynchronisation after bad headers and CRCs, a frame hidden in a corrupt one, reads split "
                         "at every point, truncated tails, and ACKs decoded from their command.", seed=606)
    rng = s.rng
    op = "decode_stream"
    move = bytes.fromhex(WORKED_MOVEMENT)

    def noise(n: int, allow_sof: bool = False) -> bytes:
        out = bytearray()
        while len(out) < n:
            b = rng.getrandbits(8)
            if b != 0xAA or allow_sof:
                out.append(b)
        return bytes(out)

    for profile in PROFILES:
        pid = f"streams.{profile}"
        bc = frame_bytes(cmd_set=2, cmd_id=0, seq=9, value=payload(profile, rules_profile(profile).all_flags, Values(rng)))

        def add(name: str, category: str, comment: str, data: bytes, flags: list[str], chunks: list[int] | None = None,
                **kw: Any) -> None:
            s.add(op, profile, f"{pid}.{name}", category, comment,
                  {"hex": data.hex(), "chunks": chunks if chunks is not None else [len(data)]}, flags, **kw)

        add("back_to_back", "stream.frames", "the worked movement frame, a broadcast, a version query (session 1) and "
            "a header-only frame, back to back",
            move + bc + frame_bytes(cmd_set=0, cmd_id=0, value=b"\x01", session=1, seq=3) + frame_bytes(session=2, seq=4),
            R("frame.sof", "frame.header_only", "frame.len"))
        g1, g2, g3 = noise(5), noise(17), noise(3)
        add("garbage_between", "stream.garbage", "garbage (no 0xAA) before, between and after two frames: three "
            "garbage runs", g1 + move + g2 + bc + g3, R("stream.garbage", "frame.sof"))
        add("garbage_only", "stream.garbage", "64 bytes without a start byte: one garbage event", noise(64),
            R("stream.garbage"))
        add("empty", "stream.garbage", "no bytes at all: no events", b"", R("stream.garbage"))
        # noise containing 0xAA
        for k in range(3):
            n = noise(48, allow_sof=True)
            n = bytes(0xAA if i % 7 == k else b for i, b in enumerate(n))
            add(f"noise_with_sof.{k}", "stream.resync", "noise with many 0xAA bytes, then the movement frame: each "
                "false start byte is rejected (drop one byte, rescan), then the frame is found", n + move,
                R("stream.resync", "frame.crc16"))
        # header errors resync
        bad_ver = frame_bytes(cmd_set=1, cmd_id=3, value=move[14:-4], ver=1)
        add("bad_version_then_frame", "stream.resync", "a frame with VER 1, then a good frame: bad_version, garbage, "
            "frame", bad_ver + move, R("stream.resync", "frame.ver"))
        bad_len = frame_bytes(length=14, data=b"")
        add("impossible_length_then_frame", "stream.resync", "a header with LEN 14, then a good frame",
            bad_len + move, R("stream.resync", "frame.len") + ["E22"])
        bad16 = flip(move, 8 * 10)
        add("bad_crc16_then_frame", "stream.resync", "the movement frame with a wrong CRC-16, then a broadcast",
            bad16 + bc, R("stream.resync", "frame.crc16"))
        bad32 = flip(move, len(move) * 8 - 1)
        add("bad_crc32_then_frame", "stream.resync", "the movement frame with a wrong CRC-32, then a broadcast: "
            "bad_crc32 covers the frame, the rest is rescanned", bad32 + bc, R("stream.resync", "frame.crc32"))
        # a valid frame hidden inside a corrupt one
        inner = bytes.fromhex(WORKED_MOVEMENT)
        outer = bytearray(frame_bytes(cmd_set=0x00, cmd_id=0x7E, value=b"\x11\x22" + inner + b"\x33"))
        outer[-1] ^= 0x5A
        add("hidden_frame", "stream.resync", "an unknown command whose value carries the whole movement frame, with a "
            "wrong CRC-32: bad_crc32 at 0, then the inner frame is found at offset 16",
            bytes(outer), R("stream.resync", "frame.crc32"))
        # truncated tail
        for cut in (1, 5, 12, 20, len(move) - 1):
            add(f"truncated_tail.{cut}", "stream.truncated_tail",
                f"a broadcast, then the first {cut} bytes of the movement frame: truncated_frame (then rescanned)",
                bc + move[:cut], R("stream.truncated_tail", "frame.truncation"))
        # every split point of one frame
        for k in range(1, len(move)):
            add(f"split.{k}", "stream.chunking", f"the movement frame in two reads of {k} and {len(move) - k} bytes",
                move, R("stream.chunking"), chunks=[k, len(move) - k])
        add("split.bytewise", "stream.chunking", "garbage, two frames and garbage, one byte per read",
            g1 + move + g2 + bc + g3, R("stream.chunking", "stream.garbage"), chunks=[1] * len(g1 + move + g2 + bc + g3))
        add("split.empty_reads", "stream.chunking", "reads of 0 bytes between the pieces change nothing", move + bc,
            R("stream.chunking"), chunks=[0, 7, 0, 0, 30, 0, len(move + bc) - 37])
        # frames whose value does not decode
        add("value_error", "stream.frames", "a broadcast promising more than it carries: an error event with its "
            "length, then the next frame", frame_bytes(cmd_set=2, cmd_id=0, value=b"\x02\x00\x01") + move,
            R("broadcast.bounds") + ["E25"])
        add("ack_session0", "stream.frames", "an ACK frame in session 0: bad_session as an error event",
            frame_bytes(is_ack=True, session=0, value=b"\x00\x00") + move, R("frame.session") + ["E24"])
        # ACK matching
        cmd = frame_bytes(cmd_set=1, cmd_id=0, value=b"\x01", session=2, seq=40)
        ack = frame_bytes(is_ack=True, value=b"\x03\x00", session=2, seq=40)
        add("ack.matched", "stream.ack", "obtain control (session 2, seq 40) then its ACK 3: the ACK decodes as "
            "obtain_in_progress", cmd + ack, R("stream.ack_match", "payload.control_ack") + ["E26"])
        add("ack.matched_bad_value", "stream.ack", "obtain control, then an ACK with a 3-byte value: decoded as the "
            "control ACK, length_mismatch", cmd + frame_bytes(is_ack=True, value=b"\x03\x00\x00", session=2, seq=40),
            R("stream.ack_match", "payload.trailing"))
        add("ack.unmatched", "stream.ack", "an ACK with no command before it: a frame with the raw ACK value",
            ack + cmd, R("stream.ack_match"))
        add("ack.other_seq", "stream.ack", "an ACK whose SEQ matches no command: raw", cmd +
            frame_bytes(is_ack=True, value=b"\x03\x00\x00", session=2, seq=41), R("stream.ack_match"))
        vq = frame_bytes(cmd_set=0, cmd_id=0, value=b"\x00", session=1, seq=77)
        vack = frame_bytes(is_ack=True, session=1, seq=77, value=struct.pack("<HI", 0xFF01, 7)
                           + bytes(0 if profile == "m100-fw2.3" else 11) + bytes(32))
        add("ack.session1_version", "stream.ack", "get version in session 1 and its ACK (not_activated): matched",
            vq + vack, R("stream.ack_match", "payload.version_ack") + ["E24", "E30"])
        lc = frame_bytes(cmd_set=2, cmd_id=1, value=b"\x04", session=3, seq=5)
        lack = frame_bytes(is_ack=True, session=3, seq=5, value=b"\x00\x00")
        add("ack.lost_control", "stream.ack", "a lost-control push in session 3 and the device's 2-byte zero ACK",
            lc + lack, R("stream.ack_match", "payload.lost_control_ack") + ["E24"])
        mc0 = frame_bytes(cmd_set=1, cmd_id=3, value=move[14:-4], session=0, seq=6)
        add("ack.session0_command", "stream.ack", "a movement command in session 0 wants no ACK; a later ACK with "
            "session 1 and the same SEQ is not matched", mc0 + frame_bytes(is_ack=True, session=1, seq=6, value=b"\x00"),
            R("stream.ack_match", "frame.session"))
        add_ack_memory(add, profile)
        # a random mix
        for k in range(3):
            parts = []
            for _ in range(8):
                choice = rng.randrange(5)
                if choice == 0:
                    parts.append(noise(rng.randrange(1, 20), allow_sof=True))
                elif choice == 1:
                    parts.append(move)
                elif choice == 2:
                    parts.append(bc)
                elif choice == 3:
                    parts.append(flip(bc, rng.randrange(len(bc) * 8)))
                else:
                    parts.append(frame_bytes(cmd_set=0, cmd_id=0x10, value=bytes(rng.randrange(6) for _ in range(16)),
                                             session=rng.randrange(32), seq=rng.getrandbits(16)))
            data = b"".join(parts)
            sizes, left = [], len(data)
            while left > 0:
                sizes.append(min(left, rng.randrange(1, 40)))
                left -= sizes[-1]
            add(f"mix.{k}", "stream.mix", f"random mix #{k} of frames, corrupted frames and noise, random read sizes",
                data, R("stream.resync", "stream.chunking"), chunks=sizes)
        add_stream_errors(s, profile, add)
        add_rule_pairs(s, profile, "decode_stream", "precedence", add)
        add_header_bits(s, profile, add, stream=True)
        add_ack_situations(s, profile)
    return s


# ============================================================== encode.json


def gen_encode() -> Suite:
    s = Suite("encode", "encode_movement_control and encode_frame: the PROTOCOL-FACTS worked frames, every mode "
                        "byte, float bit patterns, ACKs, header-only and maximum-length frames.", seed=707)
    rng = s.rng

    def mc(id: str, category: str, comment: str, mode: int, xs: tuple[int, int, int, int], flags: list[str],
           **kw: Any) -> None:
        data = bytes([mode]) + struct.pack("<4I", *xs)
        problems = {reference.answer("check_movement_control", p, {"hex": data.hex()}).get("error") for p in PROFILES}
        problems.discard(None)
        inp = {"mode": mode, **{k: f32_model(b) for k, b in zip(("x", "y", "z", "yaw"), xs)}}
        if problems and "expected" not in kw:
            why = sorted(problems)[0]
            kw["acceptable"] = why
            comment += f"; check_movement_control rejects it ({why}) in some profile, so an encoder may refuse it"
        s.add("encode_movement_control", None, id, category, comment, inp, flags, **kw)

    mc("encode.movement_control.worked", "encode.movement_control",
       "hand-written: the value of the PROTOCOL-FACTS movement control frame", 0x4B,
       (f32(1.0), f32(-2.0), f32(0.5), f32(30.0)), R("encode.movement_control", "floats.bit_exact"),
       expected={"hex": "4b0000803f000000c00000003f0000f041"})
    for byte in range(256):
        c = classify_control_mode(byte, "a3-fw3.1")
        if c["combination"]:
            ranges = input_ranges(byte, "a3-fw3.1")
            xs = tuple(f32(mid(ranges[reference.AXIS_RANGE[a]])) for a in ("x", "y", "z", "yaw"))
        else:
            xs = (f32(1.0), f32(2.0), f32(3.0), f32(4.0))
        mc(f"encode.movement_control.mode.0x{byte:02x}", "encode.movement_control",
           f"mode byte 0x{byte:02x} with fixed setpoints", byte, xs,
           R("encode.movement_control", "control.fields"))
    for name, bits in F32_SPECIALS.items():
        xs = (bits, f32_next_up(0) if bits != 1 else 0, 0x3F800000, bits)
        mc(f"encode.movement_control.special.{name}", "encode.floats",
           f"x and yaw {name} (0x{bits:08x}): the bits go to the wire unchanged", 0x48, xs,
           R("encode.movement_control", "floats.bit_exact"))
    for k in range(20):
        xs = tuple(rng.getrandbits(32) for _ in range(4))
        mc(f"encode.movement_control.random_bits.{k}", "encode.floats", "random float32 bit patterns (any NaN kept)",
           rng.getrandbits(8), xs, R("encode.movement_control", "floats.bit_exact"))

    def fr(id: str, category: str, comment: str, inp: dict, flags: list[str], **kw: Any) -> None:
        s.add("encode_frame", None, id, category, comment, inp, flags, **kw)

    fr("encode.frame.worked.movement_control", "encode.frame",
       "hand-written: the PROTOCOL-FACTS movement control frame (session 0, seq 0x1234)",
       {"cmd_set": 1, "cmd_id": 3, "is_ack": False, "session": 0, "seq": 0x1234,
        "value": "4b0000803f000000c00000003f0000f041"}, R("encode.frame", "frame.crc16", "frame.crc32") + ["E21"],
       expected={"hex": WORKED_MOVEMENT})
    fr("encode.frame.worked.broadcast", "encode.frame",
       "hand-written: the PROTOCOL-FACTS broadcast frame (seq 7, flags 0x1800, flight status 3, battery 87)",
       {"cmd_set": 2, "cmd_id": 0, "is_ack": False, "session": 0, "seq": 7, "value": "00180357"},
       R("encode.frame", "frame.crc16", "frame.crc32") + ["E21"], expected={"hex": WORKED_BROADCAST})
    fr("encode.frame.header_only_ack", "encode.frame", "an ACK with an empty value is the 12-byte header alone",
       {"is_ack": True, "session": 2, "seq": 513, "value": ""}, R("encode.frame", "frame.header_only") + ["E22"])
    for session in (1, 2, 31):
        fr(f"encode.frame.ack.session{session}", "encode.frame", f"control ACK (obtained) in session {session}",
           {"is_ack": True, "session": session, "seq": 40, "value": "0200"}, R("encode.frame", "frame.session") + ["E24"])
    fr("encode.frame.ack.session0", "encode.frame", "an ACK in session 0 cannot be sent: bad_session",
       {"is_ack": True, "session": 0, "seq": 40, "value": "0200"}, R("encode.frame", "frame.session") + ["E24"],
       error="bad_session")
    fr("encode.frame.lost_control_ack", "encode.frame", "the 2-byte zero answer to lost control, session 4",
       {"is_ack": True, "session": 4, "seq": 9, "value": "0000"}, R("encode.frame", "payload.lost_control_ack") + ["E24"])
    fr("encode.frame.max_command", "encode.frame", "a command with a 1005-byte value: LEN 1023, the maximum",
       {"cmd_set": 0, "cmd_id": 0x7F, "is_ack": False, "session": 0, "seq": 1, "value": bytes(1005).hex()},
       R("encode.frame", "frame.len") + ["E22"])
    fr("encode.frame.too_long_command", "encode.frame", "a command with a 1006-byte value would need LEN 1024: "
       "impossible_length", {"cmd_set": 0, "cmd_id": 0x7F, "is_ack": False, "session": 0, "seq": 1,
                             "value": bytes(1006).hex()}, R("encode.frame", "frame.len") + ["E22"],
       error="impossible_length")
    fr("encode.frame.max_ack", "encode.frame", "an ACK with a 1007-byte value: LEN 1023",
       {"is_ack": True, "session": 1, "seq": 1, "value": bytes(1007).hex()}, R("encode.frame", "frame.len") + ["E22"])
    fr("encode.frame.too_long_ack", "encode.frame", "an ACK with a 1008-byte value: impossible_length",
       {"is_ack": True, "session": 1, "seq": 1, "value": bytes(1008).hex()}, R("encode.frame", "frame.len") + ["E22"],
       error="impossible_length")
    fr("encode.frame.too_long_ack_session0", "encode.frame", "an ACK in session 0 with a 1008-byte value breaks "
       "two rules: the length is checked first, impossible_length", {"is_ack": True, "session": 0, "seq": 1,
                                                                       "value": bytes(1008).hex()},
       R("encode.frame", "frame.len", "frame.session") + ["E22", "E24"], error="impossible_length")
    fr("encode.frame.seq_max", "encode.frame", "SEQ 0xFFFF, session 31",
       {"cmd_set": 1, "cmd_id": 0, "is_ack": False, "session": 31, "seq": 0xFFFF, "value": "01"},
       R("encode.frame", "frame.session"))
    for k in range(30):
        is_ack = rng.random() < 0.3
        value = bytes(rng.getrandbits(8) for _ in range(rng.randrange(0 if is_ack else 0, 60)))
        inp: dict[str, Any] = {"is_ack": is_ack, "session": rng.randrange(1 if is_ack else 0, 32),
                               "seq": rng.getrandbits(16), "value": value.hex()}
        if not is_ack:
            inp = {"cmd_set": rng.randrange(4), "cmd_id": rng.getrandbits(8), **inp}
        fr(f"encode.frame.random.{k}", "encode.frame", f"random {'ACK' if is_ack else 'command'} frame #{k}", inp,
           R("encode.frame", "frame.crc16", "frame.crc32"))
    return s


# ============================================================== bug classes (osdk_conformance.vector_tables)
#
# The classes of bugs an independent implementation could otherwise get
# wrong and still pass: each is generated from the lists of
# osdk_conformance.vector_tables (every frame error class, every pair of
# frame rules, every header bit, every command kind and ACK situation,
# every undefined mode byte), and `osdkc vectors coverage` shows a table
# per class computed from the vectors' bytes.

GOOD_FRAME = frame_bytes(cmd_set=1, cmd_id=0, value=b"\x01", seq=0x0203)
"""A small valid frame (control request, session 0) placed after or inside bad ones."""


def reseal(data: bytes) -> bytes:
    """Both CRCs recomputed over what is there, after a byte was edited."""
    b = bytearray(data)
    b[10:12] = le16(crc16(bytes(b[:10])))
    if len(b) > 12:
        b[-4:] = struct.pack("<I", crc32(bytes(b[:-4])))
    return bytes(b)


def flip_last(data: bytes) -> bytes:
    return data[:-1] + bytes([data[-1] ^ 0x01])


def crc16_wrong(data: bytes) -> bytes:
    """A bit of the stored CRC-16 flipped, the CRC-32 still right for the bytes."""
    b = flip(data, 80)
    return b[:-4] + struct.pack("<I", crc32(b[:-4])) if len(b) > 12 else b


PAIR_BASE = {"cmd_set": 1, "cmd_id": 0, "value": b"\x01", "session": 2, "seq": 0x0102}
"""The frame every pair of broken rules starts from: a control request in session 2."""

# How each rule of vt.FRAME_RULES is broken, in every way that takes a
# different path through a decoder (variant tag -> header values for
# frame_bytes, and an edit of the finished bytes at a stage: 0 before both
# CRCs are recomputed, 1 after, 2 last).
Breaker = tuple[dict, int, Callable[[bytes], bytes] | None]
BREAKERS: dict[str, dict[str, Breaker]] = {
    "sof": {"": ({}, 0, lambda d: b"\x55" + d[1:])},
    "crc16": {"": ({}, 1, crc16_wrong)},
    "ver": {"": ({"ver": 1}, 0, None)},
    "res0": {"": ({"res0": 1}, 0, None)},
    "res1": {"": ({"res1": 0x000001}, 0, None)},  # its lowest bit alone: a decoder reading ENC one bit wide sees 0
    "len": {"below12": ({"length": 3}, 0, None), "13to16": ({"length": 14}, 0, None)},
    "size": {"extra": ({}, 2, lambda d: d + b"\x00"), "short": ({}, 2, lambda d: d[:-1])},
    "crc32": {"": ({}, 1, flip_last)},
    "session": {"": ({"is_ack": True, "session": 0, "cmd_set": None, "cmd_id": None, "value": b"\x02\x00"}, 0, None)},
    # plain DATA with padding (the value is still decoded), an undefined ENC, AES without padding
    "enc": {"plain_padding": ({"padding": 1}, 0, None), "enc2": ({"enc": 2}, 0, None),
            "aes_padding0": ({"enc": 1}, 0, None)},
    "value": {"trailing": ({"value": b"\x01\x00"}, 0, None), "short": ({"value": b""}, 0, None)},
}
RULE_FLAGS = {"sof": "frame.sof", "crc16": "frame.crc16", "ver": "frame.ver", "res0": "frame.reserved",
              "res1": "frame.reserved", "len": "frame.len", "size": "frame.extra_bytes", "crc32": "frame.crc32",
              "session": "frame.session", "enc": "frame.enc", "value": "payload.trailing",
              "size-short": "frame.truncation", "value-short": "payload.truncated"}
"""The rule flag of each breaker ("rule" or "rule-variant")."""


def broken_frame(breakers: list[Breaker]) -> bytes | None:
    """PAIR_BASE with every breaker applied, or None when two of them need
    the same header value to differ."""
    wanted: dict[str, Any] = {}
    for fields, _, _ in breakers:
        for k, v in fields.items():
            if k in wanted and wanted[k] != v:
                return None
            wanted[k] = v
    data = frame_bytes(**{**PAIR_BASE, **wanted})
    for stage in (0, 1, 2):
        edits = [edit for _, at, edit in breakers if at == stage and edit]
        for edit in edits:
            data = edit(data)
        if stage == 0 and edits:
            data = reseal(data)
    return data


def first_rule(broken: set[str], context: str) -> vt.FrameRule:
    return next(r for r in vt.FRAME_RULES if r.name in broken and context in r.contexts)


def variant_pairs(a: str, b: str, profile: str, context: str) -> list[tuple[str, bytes, set[str], list[str]]]:
    """(id part, frame bytes, rules it breaks, rule flags) for every way of
    breaking both a and b together; GenerationError when there is none."""
    out = []
    for ta, ba in BREAKERS[a].items():
        for tb, bb in BREAKERS[b].items():
            data = broken_frame([ba, bb])
            broken = vt.broken_rules(data, profile, context) if data else set()
            if {a, b} <= broken:
                names = [f"{n}-{t}" if t else n for n, t in ((a, ta), (b, tb))]
                flags = R(*{RULE_FLAGS.get(name, RULE_FLAGS[name.split("-")[0]]) for name in names})
                out.append((".".join(names), data, broken, flags))
    if not out:
        raise GenerationError(f"rules {a} and {b} cannot be broken together; list the pair in "
                              f"vector_tables.IMPOSSIBLE_PAIRS with the reason")
    return out


def add_rule_pairs(s: Suite, profile: str, context: str, prefix: str,
                   add: Callable[..., None]) -> None:
    """One case per pair of frame rules that can fire on one frame
    (vt.rule_pairs) and per way of breaking each: the frame alone
    (decode_frame) or followed by GOOD_FRAME (decode_stream)."""
    for a, b in vt.rule_pairs(context):
        for name, data, broken, flags in variant_pairs(a, b, profile, context):
            add_rule_pair(profile, context, f"{prefix}.{name}", a, b, data, broken, flags, add)


def add_rule_pair(profile: str, context: str, id: str, a: str, b: str, data: bytes, broken: set[str],
                  flags: list[str], add: Callable[..., None]) -> None:
    first = first_rule(broken, context)
    also = sorted(broken - {a, b}, key=[r.name for r in vt.FRAME_RULES].index)
    what = f"{a} and {b} broken on one frame{' (and ' + ', '.join(also) + ')' if also else ''}"
    if context == "decode_frame":
        ref = reference.answer("decode_frame", profile, {"hex": data.hex()})
        if ref["ok"] or ref["error"] not in first.classes:
            raise GenerationError(f"{id}: the reference answers {ref}, precedence says {first.name}")
        add(id, "frame.precedence", f"{what}: {first.name} comes first, {ref['error']}", data, flags,
            error=ref["error"])
        return
    events = reference.answer("decode_stream", profile, {"hex": (data + GOOD_FRAME).hex(),
                                                         "chunks": [len(data) + len(GOOD_FRAME)]})
    ev = events["result"]["events"][0]
    if ev["kind"] != "error" or ev["offset"] != 0 or ev["error"] not in first.classes:
        raise GenerationError(f"{id} in a stream: first event {ev}, precedence says {first.name}")
    add(id, "stream.precedence", f"{what}, then a good frame: {first.name} comes first ({ev['error']} covering "
        f"{ev['length']} byte(s)), and scanning resumes where that class says", data + GOOD_FRAME,
        flags + R("stream.resync"))


def stream_error_makers() -> dict[str, tuple[str, Callable[[bytes], bytes]]]:
    """A bad frame per way of producing each stream error class:
    name -> (class, make(inner)), `inner` carried inside the frame's DATA."""

    def unknown(inner: bytes, **kw: Any) -> bytes:
        return frame_bytes(cmd_set=0, cmd_id=0x7E, value=b"\x11" + inner + b"\x22", seq=0x0405, **kw)

    return {
        "crc16": ("bad_crc16", lambda inner: flip(unknown(inner), 80)),
        "ver": ("bad_version", lambda inner: unknown(inner, ver=1)),
        "res0": ("reserved_bits", lambda inner: unknown(inner, res0=1)),
        "res1": ("reserved_bits", lambda inner: unknown(inner, res1=0x000001)),
        "len3": ("impossible_length", lambda inner: frame_bytes(length=3, data=b"") + b"\x11" + inner),
        "len14": ("impossible_length", lambda inner: frame_bytes(length=14, data=b"") + b"\x11" + inner),
        "crc32": ("bad_crc32", lambda inner: flip_last(unknown(inner))),
        "truncated": ("truncated_frame", lambda inner: unknown(inner + bytes(24))[:15 + len(inner)]),
        "session": ("bad_session", lambda inner: frame_bytes(is_ack=True, session=0, seq=0x0405,
                                                             value=b"\x02\x00" + inner)),
        "enc": ("bad_encryption", lambda inner: unknown(inner, enc=2)),
        "padding": ("bad_encryption", lambda inner: unknown(inner, padding=1)),
        "activation_short": ("truncated_payload", lambda inner: frame_bytes(cmd_set=0, cmd_id=1, seq=0x0405,
                                                                             value=inner + b"\x00")),
        "control_trailing": ("length_mismatch", lambda inner: frame_bytes(cmd_set=1, cmd_id=0, seq=0x0405,
                                                                           value=b"\x01\x22" + inner)),
        "broadcast_reserved": ("reserved_bits", lambda inner: frame_bytes(cmd_set=2, cmd_id=0, seq=0x0405,
                                                                           value=le16(0x8000) + inner)),
    }


STREAM_ERROR_FLAGS = {"bad_crc16": "frame.crc16", "bad_version": "frame.ver", "impossible_length": "frame.len",
                      "bad_crc32": "frame.crc32", "truncated_frame": "stream.truncated_tail",
                      "bad_session": "frame.session", "bad_encryption": "frame.enc",
                      "truncated_payload": "payload.truncated", "length_mismatch": "payload.trailing"}


def add_stream_errors(s: Suite, profile: str, add: Callable[..., None]) -> None:
    """Every stream error class (vt.stream_error_classes), each way of
    producing it: the bad frame then a good one; with a good frame inside
    its DATA as well (found only where scanning resumes after the start
    byte); and that one fed a byte at a time."""
    makers = stream_error_makers()
    missing = set(vt.stream_error_classes()) - {cls for cls, _ in makers.values()}
    if missing:
        raise GenerationError(f"no stream error vector produces {', '.join(sorted(missing))}")
    for name, (cls, make) in makers.items():
        flags = R("stream.resync", STREAM_ERROR_FLAGS.get(cls) or
                  ("broadcast.reserved_flags" if name.startswith("broadcast") else "frame.reserved"))
        for shape, data, chunks, what in (
                ("then_good", make(b"") + GOOD_FRAME, None, "then a good frame"),
                ("hidden", make(GOOD_FRAME) + GOOD_FRAME, None,
                 "with a good frame inside its DATA, then the same good frame"),
                ("hidden.bytewise", make(GOOD_FRAME) + GOOD_FRAME, [1] * (len(make(GOOD_FRAME)) + len(GOOD_FRAME)),
                 "with a good frame inside its DATA, then the same good frame, one byte per read")):
            ref = reference.answer("decode_stream", profile, {"hex": data.hex(), "chunks": [len(data)]})
            ev = ref["result"]["events"][0]
            if ev["kind"] != "error" or ev["offset"] != 0 or ev["error"] != cls:
                raise GenerationError(f"stream error {name}: first event {ev}, want {cls} at 0")
            resumes = "after its start byte" if ev["length"] < len(make(b"")) or cls in (
                "bad_crc32", "truncated_frame") else "after the frame"
            add(f"stream_error.{name}.{shape}", "stream.error_classes",
                f"{cls} ({name}) {what}: the error at offset 0 covers {ev['length']} byte(s) and scanning "
                f"resumes {resumes}", data, flags + (R("stream.chunking") if chunks else []), chunks=chunks)


def header_bit_frames(field: str, k: int) -> list[tuple[str, dict]]:
    """Valid frames with bit k of a header field set (or, for LEN, also
    every other bit set), as frame_bytes arguments; [] for a field whose
    bits only appear in invalid frames, which the frames suite already has
    for every value (VER, RES0, ENC 2..7) or which are set here (RES1)."""
    if field == "len":
        out = []
        for tag, length in (("set", 17 | 1 << k), ("all_but", 0x3FF & ~(1 << k))):
            if length == 17:  # the one DATA byte of a LEN 17 frame is an ACK's value
                out.append((tag, {"is_ack": True, "session": 1, "value": b"\x00", "seq": 0x0607}))
            else:
                out.append((tag, {"cmd_set": 0, "cmd_id": 0x7F, "value": bytes(length - 18), "seq": 0x0607}))
        return out
    if field == "session":
        return [("command", {"cmd_set": 1, "cmd_id": 0, "value": b"\x01", "session": 1 << k, "seq": 0x0607}),
                ("ack", {"is_ack": True, "value": b"\x02\x00", "session": 1 << k, "seq": 0x0607})]
    if field == "padding":
        return [("aes", {"data": bytes(range(32)), "enc": 1, "padding": 1 << k, "seq": 0x0607})]
    if field == "seq":
        return [("command", {"cmd_set": 1, "cmd_id": 0, "value": b"\x01", "seq": 1 << k})]
    if field == "res1":
        return [("set", {"cmd_set": 1, "cmd_id": 0, "value": b"\x01", "res1": 1 << k})]
    return []


def add_header_bits(s: Suite, profile: str, add: Callable[..., None], stream: bool) -> None:
    """Every bit of every header field (vt.header_bits, from the spec's
    layout) set in a frame: a decoder that reads a field one bit too wide,
    too narrow or shifted misreads these. In streams, LEN bits only (LEN
    decides where the next frame starts), each frame followed by a good one."""
    for field, k, pos in vt.header_bits():
        if stream and field != "len":
            continue
        for tag, kw in header_bit_frames(field, k):
            if stream and tag != "set":
                continue
            data = frame_bytes(**kw)
            if bool(data[pos // 8] >> (pos % 8) & 1) != (tag != "all_but"):
                raise GenerationError(f"header bit {field}.{k} is not as {tag} says in its frame")
            value = kw.get("res1") or kw.get("session") or kw.get("padding") or kw.get("seq")
            what = {"set": f"LEN {len(data)} (bit {k} set)", "all_but": f"LEN {len(data)} (every bit but {k} set)"}.get(
                tag, f"{field} {value} (bit {k} set), {tag}" if field != "res1" else f"RES1 0x{value:06x}")
            flags = R({"len": "frame.len", "session": "frame.session", "padding": "frame.enc", "seq": "frame.data",
                       "res1": "frame.reserved"}[field])
            if stream:
                add(f"header_bits.{field}.bit{k}", "stream.header_bits",
                    f"a frame with {what}, then a good frame: LEN decides where the next frame starts",
                    data + GOOD_FRAME, flags + R("stream.resync"))
            else:
                add(f"header_bits.{field}.bit{k}.{tag}", "frame.header_bits",
                    f"header bit {pos} (byte {pos // 8}, bit {pos % 8}) is bit {k} of {field}: {what}",
                    data, flags)


COMMAND_VALUES: dict[str, tuple[tuple[int, int], bytes, bytes | None, bytes]] = {
    # kind: ((set, id), a command value, one that does not decode, an ACK value)
    "version_query": ((0x00, 0x00), b"\x00", b"", struct.pack("<HI", 0, 7) + bytes(32)),
    "activation": ((0x00, 0x01), struct.pack("<III", 1012345, 2, 0x03010A00) + bytes(32), bytes(40), le16(0)),
    "set_frequency": ((0x00, 0x10), bytes(range(8)) + bytes(8), bytes(15), le16(0)),
    "control_authority": ((0x01, 0x00), b"\x01", b"\x01\x00", le16(2)),
    "movement_control": ((0x01, 0x03), bytes.fromhex("4b0000803f000000c00000003f0000f041"), bytes(16), b"\x00"),
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
        "matched_session1": cmd(session=1) + ack(session=1),
        "matched_bad_value": cmd() + ack(v=ack_value + b"\x00"),
        "repeated_ack": cmd() + ack() + ack(),
        "ack_before_command": ack() + cmd(),
        "other_session": cmd() + ack(session=3),
        "other_seq": cmd() + ack(seq=n + 1),
        "session0_command": cmd(session=0) + ack(session=1),
        "rejected_command": cmd(v=bad or b"") + ack(),
        "retransmitted_command": cmd() + cmd() + ack() + ack(),
        "replaced_command": cmd(v=ovalue, c=(ocs, oci)) + cmd() + ack(),
        "interleaved": cmd(v=ovalue, c=(ocs, oci)) + cmd(seq=n + 1) + ack(seq=n + 1) + ack(v=oack),
        "header_only_ack": cmd() + frame_bytes(is_ack=True, session=2, seq=n) + ack(),
    }
    return {k: v for k, v in out.items() if vt.feasible_situation(kind, k)}


def add_ack_memory(add: Callable[..., None], profile: str) -> None:
    """What ACK matching remembers (PROTOCOL.md "ACK matching"), each case
    telling the rule from the outsider check's wrong guesses (docs/OUTSIDER-CHECK.md
    F4-F6): a decoded ACK shows which command it was matched to, a raw one
    that none was remembered."""
    flags = R("stream.ack_match", "stream.ack_memory")
    obtain = frame_bytes(cmd_set=1, cmd_id=0, value=b"\x01", session=2, seq=40)
    ack_obtained = frame_bytes(is_ack=True, value=le16(2), session=2, seq=40)
    add("ack.memory.bad_value_forgets", "stream.ack_memory",
        "obtain control, an ACK whose 3-byte value does not decode, then a good ACK with the same key: the first "
        "ACK used the entry up, so the second is not matched (raw)",
        obtain + frame_bytes(is_ack=True, value=b"\x02\x00\x00", session=2, seq=40) + ack_obtained, flags)
    bad_activation = frame_bytes(cmd_set=0, cmd_id=1, value=bytes(40), session=2, seq=40)
    add("ack.memory.undecodable_command_changes_nothing", "stream.ack_memory",
        "obtain control, then a 40-byte activation (does not decode) with the same session and SEQ, then an ACK "
        "with code 2: still matched to obtain control (obtained), neither forgotten nor taken over by activation",
        obtain + bad_activation + ack_obtained, flags)

    def control_ack(seq: int) -> bytes:
        return frame_bytes(is_ack=True, value=le16(2), session=2, seq=seq)

    if profile != PROFILES[0]:
        return   # the table does not depend on the profile: its 1,000-frame stream is generated once
    obtains = b"".join(frame_bytes(cmd_set=1, cmd_id=0, value=b"\x01", session=2, seq=q) for q in range(1, 1025))
    again = frame_bytes(cmd_set=0, cmd_id=0, value=b"\x00", session=2, seq=1)
    newer = b"".join(frame_bytes(cmd_set=1, cmd_id=0, value=b"\x01", session=2, seq=q) for q in (1025, 1026))
    add("ack.memory.limit_and_replacement", "stream.ack_memory",
        "1024 obtain-control commands (session 2, SEQ 1..1024), a version query with SEQ 1 (replaces the oldest "
        "entry, which keeps its place), two new commands SEQ 1025 and 1026, then ACKs for SEQ 1, 2, 3 and 1026: at "
        "most 1024 are remembered and the oldest goes first, so SEQ 1 and 2 are raw, SEQ 3 and 1026 match",
        obtains + again + newer + b"".join(control_ack(q) for q in (1, 2, 3, 1026)), flags)


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
                         R("stream.ack_match") + (["E24"] if situation in ("session0_command", "matched_session1") else []))
            case = vectors.cases_of({"testGroups": [{"operation": "decode_stream", "profile": profile,
                                                     "tests": [test]}]}, "streams.json")[0]
            if (kind, situation) not in vt.ack_situations(case):
                raise GenerationError(f"ack.{kind}.{situation}: the stream does not show that situation "
                                      f"({sorted(vt.ack_situations(case))})")


def add_movement_precedence(s: Suite, profile: str) -> None:
    """check_movement_control with two of its checks failing (length, mode,
    range; vt.movement_checks): every undefined mode byte of the profile
    with a value of 1, 16 or 18 bytes or a NaN setpoint (in turn), and
    every documented one 16 or 18 bytes long with a setpoint out of range.
    The length is checked first (the value must parse), then the mode, then
    the ranges."""
    op = "check_movement_control"
    turn = 0
    for byte in range(256):
        c = classify_control_mode(byte, profile)
        full = bytes.fromhex(mc_hex(byte, f32(1.0), f32(-1.0), 0x7FC00000, f32(5.0)))  # z NaN: out of any range
        finite = bytes.fromhex(mc_hex(byte, f32(1.0), f32(-1.0), f32(0.5), f32(5.0)))
        if c["classification"] == "documented":
            for n in (16, 18):
                data = (full + b"\x00")[:n]
                cls = "truncated_payload" if n < 17 else "length_mismatch"
                s.add(op, profile, f"control_ranges.{profile}.precedence.0x{byte:02x}.length{n}_range",
                      "control.precedence", f"documented mode 0x{byte:02x}, z NaN (out of range), value {n} bytes "
                      f"long: the length is checked first, {cls}", {"hex": data.hex()},
                      R("control.value", "control.non_finite"), error=cls)
            continue
        kind = ("1", "16", "18", "range")[turn % 4]
        turn += 1
        if kind == "range":
            data, cls, what = full, "undefined_mode", "17 bytes with z NaN: the mode is checked before the ranges"
        else:
            n = int(kind)
            data = (finite + b"\x00")[:n]
            cls = "truncated_payload" if n < 17 else "length_mismatch"
            what = f"{n} byte(s): the length is checked before the mode, {cls}"
        s.add(op, profile, f"control_ranges.{profile}.precedence.0x{byte:02x}.{kind}", "control.precedence",
              f"mode 0x{byte:02x} is {c['classification']} on {profile}, value of {what}", {"hex": data.hex()},
              R("control.undefined_mode", "control.value" if kind != "range" else "control.non_finite"), error=cls)


# ============================================================== driver

SUITES: dict[str, Callable[[], Suite]] = {
    "control_mode": gen_control_mode,
    "control_ranges": gen_control_ranges,
    "broadcast": lambda: gen_broadcast(A3_VALID_EVERY),
    "payloads": gen_payloads,
    "frames": gen_frames,
    "streams": gen_streams,
    "encode": gen_encode,
}
A3_VALID_EVERY = 16
"""In a3-fw3.1, about one flag word in this many (seeded sample) decodes
validly in broadcast.json besides those with <= 2 or >= 12 items; the others
appear one byte short (size budget, see gen_broadcast)."""


def generate(out: Path, suites: list[str], manifest: bool = True, verbose: bool = True) -> dict[str, int]:
    out.mkdir(parents=True, exist_ok=True)
    counts: dict[str, int] = {}
    for name in suites:
        t0 = time.perf_counter()
        suite = SUITES[name]()
        text = dump_suite(suite.document())
        (out / f"{name}.json").write_text(text, encoding="utf-8")
        counts[name] = sum(len(t) for t in suite.groups.values())
        if verbose:
            print(f"  {name:<15} {counts[name]:>6} cases  {len(text.encode()) / 1e6:6.2f} MB  "
                  f"{time.perf_counter() - t0:5.1f} s")
    if manifest:
        files = sorted(p.name for p in out.glob("*.json") if p.name != "MANIFEST.json" and not p.name.endswith(".schema.json"))
        (out / "MANIFEST.json").write_text(manifest_text({f: hashlib.sha256((out / f).read_bytes()).hexdigest() for f in files}),
                                           encoding="utf-8")
    return counts


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, help="write here instead of vectors/")
    ap.add_argument("--suite", action="append", choices=sorted(SUITES), help="only this suite (repeatable)")
    ap.add_argument("--check", action="store_true", help="regenerate into a scratch directory and compare with vectors/")
    args = ap.parse_args(argv)
    suites = args.suite or list(SUITES)
    t0 = time.perf_counter()
    try:
        if args.check:
            with tempfile.TemporaryDirectory() as tmp:
                generate(Path(tmp), suites, manifest=not args.suite, verbose=False)
                names = [f"{n}.json" for n in suites] + ([] if args.suite else ["MANIFEST.json"])
                bad = [n for n in names if not (VECTORS_DIR / n).exists()
                       or not filecmp.cmp(Path(tmp) / n, VECTORS_DIR / n, shallow=False)]
                if not args.suite:
                    extra = {p.name for p in VECTORS_DIR.glob("*.json")} - set(names) - {"vectors.schema.json"}
                    bad += [f"{n} (not generated)" for n in sorted(extra)]
            if bad:
                print("gen_vectors --check: vectors/ differs from what the spec generates: " + ", ".join(bad)
                      + "\n  run: .venv/bin/python tools/gen_vectors.py", file=sys.stderr)
                return 1
            print(f"gen_vectors --check: vectors/ is up to date ({len(names)} files, {time.perf_counter() - t0:.1f} s)")
            return 0
        out = args.out or VECTORS_DIR
        counts = generate(out, suites)
        print(f"gen_vectors: {sum(counts.values())} cases in {len(counts)} files, {time.perf_counter() - t0:.1f} s")
        return 0
    except GenerationError as e:
        print(f"gen_vectors: {e}", file=sys.stderr)
        return 1


if __name__ == "__main__":
    raise SystemExit(main())
