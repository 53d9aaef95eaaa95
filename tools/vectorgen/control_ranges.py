"""control_ranges.json: check_movement_control at and just outside every
input range limit, with special setpoints, undefined mode bytes, wrong
value lengths, and two failing checks at once (which is reported first)."""
from __future__ import annotations

from osdk_conformance.core.rules import classify_control_mode, default_rules, input_ranges
from osdk_conformance.reference import codec as reference

from .builder import PROFILES, R, Suite
from .control_mode import FIELDS_0X4B, FIELDS_0X41, bit0_is_yaw_frame
from .scalars import F32_SPECIALS, NON_FINITE, f32, f32_model, f32_next_down, f32_next_up, f32_value
from .wire import WORKED_MOVEMENT_VALUE, movement_hex

OP = "check_movement_control"
AXES = ("x", "y", "z", "yaw")
SPECIAL_SETPOINTS = ("qnan", "snan", "neg_nan", "inf", "neg_inf", "neg_zero", "denormal_min", "neg_denormal_max")


def mid(limits: dict) -> float:
    """A setpoint well inside a range (1.5 from a lone limit, 0 when unbounded)."""
    lo, hi = limits.get("min"), limits.get("max")
    if lo is not None and hi is not None:
        return (lo + hi) / 2
    if lo is not None:
        return lo + 1.5
    if hi is not None:
        return hi - 1.5
    return 0.0


def mid_setpoints(byte: int, profile: str) -> dict[str, int]:
    """Every axis mid-range for the mode byte, as float32 bits."""
    ranges = input_ranges(byte, profile)
    return {a: f32(mid(ranges[reference.AXIS_RANGE[a]])) for a in AXES}


def gen_control_ranges() -> Suite:
    s = Suite("control_ranges", "check_movement_control: every documented mode byte of every profile at and just "
                                "outside each input range limit (float32 neighbours), non-finite and special "
                                "setpoints, every undefined mode byte, and wrong value lengths.", seed=202)
    for profile in PROFILES:
        add_worked_value_and_lengths(s, profile)
        for byte in range(256):
            c = classify_control_mode(byte, profile)
            if c["classification"] != "documented":
                add_undefined_mode(s, profile, byte, c)
            else:
                add_documented_mode(s, profile, byte, c)
        add_special_setpoints(s, profile)
        add_movement_precedence(s, profile)
    add_e15_cases(s)
    return s


def add_worked_value_and_lengths(s: Suite, profile: str) -> None:
    base_id = f"control_ranges.{profile}"
    s.add(OP, profile, f"{base_id}.worked_value", "control.ranges",
          "hand-written: the value of the PROTOCOL-FACTS movement control frame (0x4B, x 1.0, y -2.0, z 0.5, "
          "yaw 30.0) is combination 4 and within its ranges",
          {"hex": WORKED_MOVEMENT_VALUE}, R("control.ranges", "control.value", "control.combinations"),
          expected={"value": {"control_mode": FIELDS_0X4B,
                              "x": f32_model(0x3F800000), "y": f32_model(0xC0000000),
                              "z": f32_model(0x3F000000), "yaw": f32_model(0x41F00000)},
                    "combination": 4})
    # Value length: the 17 bytes, else a frame-style class.
    for n, cls in ((0, "truncated_payload"), (1, "truncated_payload"), (16, "truncated_payload"),
                   (18, "length_mismatch"), (21, "length_mismatch")):
        data = bytes.fromhex(WORKED_MOVEMENT_VALUE + "00" * 4)[:n]
        s.add(OP, profile, f"{base_id}.length.{n}", "control.value_length",
              f"{n} bytes instead of 17: {cls}", {"hex": data.hex()},
              R("control.value", "payload.truncated" if cls == "truncated_payload" else "payload.trailing"),
              error=cls)


def add_undefined_mode(s: Suite, profile: str, byte: int, c: dict) -> None:
    flags = R("control.undefined_mode") + ["E16"]
    if None in c["fields"].values():
        flags += R("control.undefined")
    if bit0_is_yaw_frame(c) and c["raw"]["yaw_logic"] == 0 and c["raw"]["stable_mode"]:
        flags += R("control.bit0_fw2_3") + ["E15"]
    s.add(OP, profile, f"control_ranges.{profile}.0x{byte:02x}.undefined", "control.undefined_mode",
          f"mode byte 0x{byte:02x} is {c['classification']} on {profile}: undefined_mode whatever the "
          f"setpoints ({c['reasons'][0]})",
          {"hex": movement_hex(byte, f32(1.0), f32(-1.0), f32(50.0), f32(5.0))}, flags, error="undefined_mode")


def add_documented_mode(s: Suite, profile: str, byte: int, c: dict) -> None:
    """Mid-range and random setpoints, then each axis at and beyond each limit."""
    bid = f"control_ranges.{profile}.0x{byte:02x}"
    ranges = input_ranges(byte, profile)
    base = mid_setpoints(byte, profile)
    common = R("control.ranges", "control.combinations")
    if c["raw"]["stable_mode"]:
        common += ["E15"]
    if bit0_is_yaw_frame(c) and c["raw"]["yaw_logic"] == 1 and c["raw"]["stable_mode"]:
        common += R("control.bit0_fw2_3")
    s.add(OP, profile, f"{bid}.mid", "control.ranges",
          f"0x{byte:02x} (combination {c['combination']}), every setpoint mid-range",
          {"hex": movement_hex(byte, *base.values())}, common)
    vals = dict(base)
    for a in AXES:
        lim = ranges[reference.AXIS_RANGE[a]]
        lo, hi = lim.get("min"), lim.get("max")
        vals[a] = f32(s.rng.uniform(lo if lo is not None else -1e6, hi if hi is not None else 1e6))
    s.add(OP, profile, f"{bid}.random", "control.ranges",
          f"0x{byte:02x}, random setpoints within the ranges", {"hex": movement_hex(byte, *vals.values())}, common)
    thrust = c["fields"]["vertical_logic"] == "vert_thrust"
    for a in AXES:
        flags = common + (["E05"] if thrust and a == "z" else []) + ["E16"]
        for end in ("min", "max"):
            add_axis_limit(s, profile, byte, base, a, end, ranges[reference.AXIS_RANGE[a]].get(end), flags)


def add_axis_limit(s: Suite, profile: str, byte: int, base: dict[str, int], a: str, end: str,
                   limit: float | None, flags: list[str]) -> None:
    """One axis at one end of its range and one float32 step beyond; for an
    unbounded end, the largest finite float32 (in range) and the infinity (not)."""
    bid = f"control_ranges.{profile}.0x{byte:02x}"
    which = reference.AXIS_RANGE[a]
    vals = dict(base)
    if limit is None:
        vals[a] = 0xFF7FFFFF if end == "min" else 0x7F7FFFFF
        s.add(OP, profile, f"{bid}.{a}.{end}_unbounded_finite", "control.ranges",
              f"0x{byte:02x}: {a} ({which}) has no {end}imum; the largest finite float32 is in range",
              {"hex": movement_hex(byte, *vals.values())}, flags)
        vals[a] = 0xFF800000 if end == "min" else 0x7F800000
        s.add(OP, profile, f"{bid}.{a}.{end}_unbounded_inf", "control.non_finite",
              f"0x{byte:02x}: {a} ({which}) has no {end}imum, yet an infinity is out of range",
              {"hex": movement_hex(byte, *vals.values())}, flags + R("control.non_finite"))
        return
    at = f32(limit)
    outside = f32_next_down(at) if end == "min" else f32_next_up(at)
    vals[a] = at
    s.add(OP, profile, f"{bid}.{a}.at_{end}", "control.ranges",
          f"0x{byte:02x}: {a} ({which}) exactly at its {end}imum {limit}: limits are inclusive",
          {"hex": movement_hex(byte, *vals.values())}, flags)
    vals[a] = outside
    s.add(OP, profile, f"{bid}.{a}.outside_{end}", "control.ranges",
          f"0x{byte:02x}: {a} ({which}) one float32 step {'below' if end == 'min' else 'above'} "
          f"its {end}imum {limit} ({f32_value(outside)!r})",
          {"hex": movement_hex(byte, *vals.values())}, flags)


def add_special_setpoints(s: Suite, profile: str) -> None:
    """Special floats per documented combination (ground frame, bit 0 clear) and axis."""
    for index in range(1, 15):
        byte = default_rules().combination(index)["value"]
        ranges = input_ranges(byte, profile)
        base = mid_setpoints(byte, profile)
        for a in AXES:
            limits = ranges[reference.AXIS_RANGE[a]]
            for name in SPECIAL_SETPOINTS:
                vals = dict(base)
                vals[a] = F32_SPECIALS[name]
                flags = R("control.ranges", "floats.bit_exact")
                if name in NON_FINITE:
                    flags += R("control.non_finite")
                if index in (13, 14) and a == "z":
                    flags += ["E05"]  # the thrust combinations
                s.add(OP, profile, f"control_ranges.{profile}.special.c{index}.{a}.{name}", "control.special_floats",
                      f"combination {index} (0x{byte:02x}): {a} = {name} (0x{F32_SPECIALS[name]:08x}) against the "
                      f"{reference.AXIS_RANGE[a]} range {limits.get('min')}..{limits.get('max')}",
                      {"hex": movement_hex(byte, *vals.values())}, flags)


def add_e15_cases(s: Suite) -> None:
    """ERRATA E15, written by hand: 0x41 (velocity, yaw angle, bit 0 set) is the
    stable flag on FW 3.1 but a body yaw frame with yaw angle on FW 2.3."""
    value = {"hex": movement_hex(0x41, f32(1.0), f32(-1.0), f32(0.5), f32(30.0))}
    s.add(OP, "m100-fw2.3", "control_ranges.m100-fw2.3.e15_yaw_angle_body_frame",
          "control.bit0_fw2_3", "hand-written (ERRATA E15): on FW 2.3 bit 0 = 1 with yaw angle asks for a body yaw "
          "frame, which yaw angle does not allow: undefined_mode",
          value, R("control.bit0_fw2_3", "control.undefined_mode") + ["E15"], error="undefined_mode")
    s.add(OP, "m100-fw3.1", "control_ranges.m100-fw3.1.e15_stable_yaw_angle",
          "control.bit0_fw2_3", "hand-written (ERRATA E15): the same bytes on FW 3.1: bit 0 is the stable flag, "
          "combination 3, accepted",
          value, R("control.bit0_fw2_3", "control.ranges") + ["E15"],
          expected={"value": {"control_mode": FIELDS_0X41,
                              "x": f32_model(0x3F800000), "y": f32_model(0xBF800000),
                              "z": f32_model(0x3F000000), "yaw": f32_model(0x41F00000)},
                    "combination": 3})


def add_movement_precedence(s: Suite, profile: str) -> None:
    """check_movement_control with two of its checks failing (length, mode,
    range; vt.movement_checks): every undefined mode byte of the profile
    with a value of 1, 16 or 18 bytes or a NaN setpoint (in turn), and
    every documented one 16 or 18 bytes long with a setpoint out of range.
    The length is checked first (the value must parse), then the mode, then
    the ranges."""
    turn = 0
    for byte in range(256):
        c = classify_control_mode(byte, profile)
        full = bytes.fromhex(movement_hex(byte, f32(1.0), f32(-1.0), 0x7FC00000, f32(5.0)))  # z NaN: out of any range
        finite = bytes.fromhex(movement_hex(byte, f32(1.0), f32(-1.0), f32(0.5), f32(5.0)))
        if c["classification"] == "documented":
            for n in (16, 18):
                data = (full + b"\x00")[:n]
                cls = "truncated_payload" if n < 17 else "length_mismatch"
                s.add(OP, profile, f"control_ranges.{profile}.precedence.0x{byte:02x}.length{n}_range",
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
        s.add(OP, profile, f"control_ranges.{profile}.precedence.0x{byte:02x}.{kind}", "control.precedence",
              f"mode 0x{byte:02x} is {c['classification']} on {profile}, value of {what}", {"hex": data.hex()},
              R("control.undefined_mode", "control.value" if kind != "range" else "control.non_finite"), error=cls)
