"""Tests of spec/rules.yaml, its schema and the loader osdk_conformance.core.rules."""
from __future__ import annotations

import copy
import json
from collections import Counter
from pathlib import Path
from typing import Any, Callable

import pytest
import yaml
from jsonschema import Draft202012Validator

from osdk_conformance.core import rules as rules_module
from osdk_conformance.core.rules import (
    CLASSIFICATIONS,
    Rules,
    RulesError,
    broadcast_item,
    errata_ids,
    load_rules,
    profile_names,
)

ROOT = Path(__file__).resolve().parents[1]
RULES_PATH = ROOT / "spec" / "rules.yaml"
SCHEMA_PATH = ROOT / "spec" / "rules.schema.json"
PROFILES = ("m100-fw2.3", "m100-fw3.1", "a3-fw3.1")


@pytest.fixture(scope="module")
def rules() -> Rules:
    return load_rules()


@pytest.fixture(scope="module")
def raw() -> dict[str, Any]:
    return yaml.safe_load(RULES_PATH.read_text(encoding="utf-8"))


# ---------------------------------------------------------------- schema


def test_schema_is_valid_draft_2020_12() -> None:
    Draft202012Validator.check_schema(json.loads(SCHEMA_PATH.read_text(encoding="utf-8")))


def test_rules_validate_against_schema(raw: dict[str, Any]) -> None:
    validator = Draft202012Validator(json.loads(SCHEMA_PATH.read_text(encoding="utf-8")))
    errors = [f"{list(e.absolute_path)}: {e.message}" for e in validator.iter_errors(raw)]
    assert errors == []


def test_top_level_keys(raw: dict[str, Any]) -> None:
    assert list(raw) == [
        "crc", "frame", "profiles", "broadcast_items", "frequencies", "control_mode", "control_modes",
        "enums", "flight_status", "device_byte", "velocity_status", "gimbal_limit",
        "rc_channels", "plausibility", "units",
    ]


def test_default_path_loads(rules: Rules) -> None:
    assert rules.path == RULES_PATH
    assert rules.profile_names == PROFILES
    assert profile_names() == PROFILES


# ------------------------------------------------------- control mode byte

# The 14 rows of the seed's Combinations table: bits 7-3 of control_mode_byte.
SEED_PATTERNS = {
    1: "00000", 2: "00001", 3: "01000", 4: "01001", 5: "10000", 6: "10001", 7: "00010",
    8: "00011", 9: "01010", 10: "01011", 11: "10010", 12: "10011", 13: "00100", 14: "00101",
}


# Yaw-angle combinations (bit 3 = 0): on m100-fw2.3 bit 0 is the yaw frame and
# must be 0 with a yaw angle (errata E15).
YAW_ANG_INDICES = {1, 3, 5, 7, 9, 11, 13}


def _documented_bytes(profile: str = "a3-fw3.1") -> dict[int, int]:
    out = {}
    for index, top in SEED_PATTERNS.items():
        for frame in (0b00, 0b01):
            for stable in (0, 1):
                if profile == "m100-fw2.3" and stable and index in YAW_ANG_INDICES:
                    continue
                out[int(top, 2) << 3 | frame << 1 | stable] = index
    return out


# documented: 14 combinations x 2 frames x 2 values of bit 0 (56); on FW 2.3
# the 7 yaw-angle combinations lose bit 0 = 1 (14 bytes), and so do the 2
# undocumented and 3 later-firmware yaw-angle triples (4 and 6 bytes).
# 16 undocumented = (hori_vel|hori_pos) x vert_thrust x 2 yaw x 4;
# 24 later_firmware = angular rate x 3 vertical x 2 yaw x 4.
EXPECTED_COUNTS = {
    "m100-fw2.3": {"documented": 42, "undocumented": 12, "later_firmware": 18, "invalid": 184},
    "m100-fw3.1": {"documented": 56, "undocumented": 16, "later_firmware": 24, "invalid": 160},
    "a3-fw3.1": {"documented": 56, "undocumented": 16, "later_firmware": 24, "invalid": 160},
}


@pytest.mark.parametrize("profile", PROFILES)
def test_every_byte_has_exactly_one_classification(rules: Rules, profile: str) -> None:
    documented = _documented_bytes(profile)
    assert len(documented) == EXPECTED_COUNTS[profile]["documented"]
    counts: Counter[str] = Counter()
    for byte in range(256):
        result = rules.classify_control_mode(byte, profile)
        assert result["classification"] in CLASSIFICATIONS
        assert result["reasons"], f"byte 0x{byte:02x} has no reason"
        counts[result["classification"]] += 1
        if byte in documented:
            assert result["classification"] == "documented", f"0x{byte:02x}"
            assert result["combination"] == documented[byte]
        else:
            assert result["classification"] != "documented", f"0x{byte:02x}"
            assert result["combination"] is None
    assert counts == EXPECTED_COUNTS[profile]


def _byte(h: int, v: int, yaw: int, frame: int = 0, stable: int = 0) -> int:
    return h << 6 | v << 4 | yaw << 3 | frame << 1 | stable


@pytest.mark.parametrize(
    ("byte", "expected"),
    [
        (_byte(3, 0, 0), "later_firmware"),
        (_byte(3, 2, 1, 1, 1), "later_firmware"),
        (_byte(0, 3, 0), "invalid"),
        (_byte(3, 3, 0), "invalid"),          # invalid outranks later_firmware
        (_byte(0, 0, 0, frame=2), "invalid"),
        (_byte(0, 0, 0, frame=3), "invalid"),
        (_byte(3, 0, 0, frame=2), "invalid"),
        (_byte(1, 2, 0), "undocumented"),
        (_byte(2, 2, 1, 1, 1), "undocumented"),
        (_byte(1, 2, 0, frame=2), "invalid"),
        (0x4B, "documented"),                  # facts §1 worked frame: combination 4
    ],
)
def test_classification_examples(rules: Rules, byte: int, expected: str) -> None:
    assert rules.classify_control_mode(byte, "a3-fw3.1")["classification"] == expected


def test_classification_fields_and_notes(rules: Rules) -> None:
    r = rules.classify_control_mode(0x4B, "m100-fw3.1")
    assert r["fields"] == {
        "horizontal_logic": "hori_vel", "vertical_logic": "vert_vel", "yaw_logic": "yaw_rate",
        "horizontal_frame": "body", "stable_mode": "stable",
    }
    assert r["combination"] == 4
    assert r["preconditions"] == ["hori_vel_gps_or_guidance"]
    assert any("horizontal control only" in s for s in r["reasons"])
    r = rules.classify_control_mode(_byte(0, 0, 0, frame=1), "m100-fw3.1")
    assert any("ground frame" in s for s in r["reasons"])
    assert rules.classify_control_mode(0xC0, "a3-fw3.1")["fields"]["horizontal_logic"] is None


# ------------------------------------------- bit 0 on FW 2.3 (errata E15)


def test_bit0_meaning_is_data_per_profile(raw: dict[str, Any]) -> None:
    b0 = raw["control_mode"]["bit0_by_profile"]
    assert set(b0) == set(PROFILES)
    assert b0["m100-fw3.1"]["meaning"] == b0["a3-fw3.1"]["meaning"] == "stable_mode"
    fw23 = b0["m100-fw2.3"]
    assert fw23["meaning"] == "yaw_frame"
    assert {v["value"]: v["name"] for v in fw23["values"]} == {0: "ground", 1: "body"}
    assert fw23["yaw_ang_requires"] == 0
    assert fw23["violation"]["classification"] == "invalid"
    assert "E15" in fw23["violation"]["reason"] and "E15" in fw23["source"]


@pytest.mark.parametrize("index", sorted(YAW_ANG_INDICES))
@pytest.mark.parametrize("frame", [0, 1])
def test_fw23_yaw_angle_with_bit0_set_is_invalid(rules: Rules, index: int, frame: int) -> None:
    byte = int(SEED_PATTERNS[index], 2) << 3 | frame << 1 | 1
    r = rules.classify_control_mode(byte, "m100-fw2.3")
    assert r["classification"] == "invalid"
    assert r["combination"] is None
    assert r["bit0"] == {"meaning": "yaw_frame", "name": "body"}
    assert any(s.startswith("bit 0 = 1 (yaw frame body)") and "errata E15" in s for s in r["reasons"])
    assert rules.input_ranges(byte, "m100-fw2.3") is None
    # the same byte is a documented combination with stable mode on FW 3.1
    for profile in ("m100-fw3.1", "a3-fw3.1"):
        r31 = rules.classify_control_mode(byte, profile)
        assert (r31["classification"], r31["combination"]) == ("documented", index)
        assert r31["bit0"] == {"meaning": "stable_mode", "name": "stable"}
        assert not any("yaw frame" in s for s in r31["reasons"])
    # bit 0 clear is the ground yaw frame and stays documented on FW 2.3
    r0 = rules.classify_control_mode(byte & ~1, "m100-fw2.3")
    assert (r0["classification"], r0["combination"]) == ("documented", index)
    assert r0["bit0"] == {"meaning": "yaw_frame", "name": "ground"}


@pytest.mark.parametrize("index", sorted(set(SEED_PATTERNS) - YAW_ANG_INDICES))
def test_fw23_yaw_rate_may_use_either_yaw_frame(rules: Rules, index: int) -> None:
    for bit0, frame_name in ((0, "ground"), (1, "body")):
        byte = int(SEED_PATTERNS[index], 2) << 3 | bit0
        r = rules.classify_control_mode(byte, "m100-fw2.3")
        assert (r["classification"], r["combination"]) == ("documented", index)
        assert r["bit0"]["name"] == frame_name
        assert any(f"yaw rate in the {frame_name} frame" in s for s in r["reasons"])
        assert not any("stable mode set" in s for s in r["reasons"])


def test_fw23_bit0_does_not_rescue_invalid_bytes(rules: Rules) -> None:
    # an undefined vertical logic stays invalid whatever bit 0 means
    r = rules.classify_control_mode(_byte(0, 3, 0, stable=1), "m100-fw2.3")
    assert r["classification"] == "invalid"
    assert any(s.startswith("bit 0 = 1") and "E15" in s for s in r["reasons"])
    assert any("vertical_logic" in s for s in r["reasons"])
    # angular-rate horizontal with yaw angle and bit 0 set: invalid outranks later_firmware
    assert rules.classify_control_mode(_byte(3, 0, 0, stable=1), "m100-fw2.3")["classification"] == "invalid"
    assert rules.classify_control_mode(_byte(3, 0, 0, stable=1), "m100-fw3.1")["classification"] == "later_firmware"


def test_bad_arguments_raise_rules_error(rules: Rules) -> None:
    with pytest.raises(RulesError, match="unknown profile"):
        rules.classify_control_mode(0, "m100-fw9")
    with pytest.raises(RulesError, match="0..255"):
        rules.classify_control_mode(256, "a3-fw3.1")
    with pytest.raises(RulesError, match="index"):
        rules.combination(19)
    with pytest.raises(RulesError, match="unknown enum"):
        rules.enum("nope")
    with pytest.raises(RulesError, match="unknown CRC"):
        rules.crc_params("crc8")


def test_combinations_and_undocumented(rules: Rules) -> None:
    for index, top in SEED_PATTERNS.items():
        c = rules.combination(index)
        assert c["documented"] is True
        assert c["pattern"] == f"0b{top}xxy"
        assert c["mask"] == 0xF8 and c["value"] == int(top, 2) << 3
    for index in range(15, 19):
        c = rules.combination(index)
        assert c["documented"] is False and c["vertical"] == "vert_thrust"
        assert c["horizontal"] in ("hori_vel", "hori_pos")


SEED_RANGES = {
    "vert_vel": (-4, 4), "vert_pos": (0, None), "vert_thrust": (10, 100),
    "hori_atti_tilt_ang": (-30, 30), "hori_vel": (-10, 10), "hori_pos": (None, None),
    "yaw_ang": (-180, 180), "yaw_rate": (-100, 100),
}


@pytest.mark.parametrize("profile", PROFILES)
def test_input_ranges_are_the_seed_ranges(rules: Rules, profile: str) -> None:
    for byte, index in _documented_bytes(profile).items():
        c = rules.combination(index)
        ranges = rules.input_ranges(byte, profile)
        assert ranges is not None
        for axis, logic in (("vertical", c["vertical"]), ("horizontal", c["horizontal"]), ("yaw", c["yaw"])):
            assert (ranges[axis]["min"], ranges[axis]["max"]) == SEED_RANGES[logic]
    assert rules.input_ranges(_byte(1, 2, 0), profile) is None
    assert rules.input_ranges(_byte(3, 0, 0), profile) is None


def test_later_sdk_limits_are_informative_only(raw: dict[str, Any]) -> None:
    later = raw["control_modes"]["later_sdk_limits"]
    assert later["informative"] is True and later["used_by_profiles"] == []
    got = {k: (v["min"], v["max"]) for k, v in later["ranges"].items()}
    assert got == {"vert_vel": (-5, 5), "hori_atti_tilt_ang": (-35, 35), "hori_vel": (-30, 30), "yaw_rate": (-150, 150)}
    assert set(raw["control_modes"]["profile_ranges"].values()) == {"seed"}
    assert raw["control_modes"]["accuracy"]["attitude_deg"] == 0.5
    assert raw["control_modes"]["accuracy"]["speed_mps"] == 0.2


def test_preconditions(rules: Rules) -> None:
    hori_pos, hori_vel, vert_pos = _byte(2, 0, 0), _byte(1, 0, 0), _byte(0, 1, 0)
    assert rules.evaluate_preconditions(hori_pos, {"gps_health": 3}) == {"hori_pos_gps": True}
    assert rules.evaluate_preconditions(hori_pos, {"gps_health": 2}) == {"hori_pos_gps": False}
    assert rules.evaluate_preconditions(hori_vel, {"gps_health": 1, "guidance_working": True}) == {"hori_vel_gps_or_guidance": True}
    assert rules.evaluate_preconditions(hori_vel, {"gps_health": 1, "guidance_working": False}) == {"hori_vel_gps_or_guidance": False}
    assert rules.evaluate_preconditions(hori_vel, {"gps_health": 1}) == {"hori_vel_gps_or_guidance": None}
    indoor = {"indoor": True, "guidance_installed": True, "height_m": 1.0}
    assert rules.evaluate_preconditions(vert_pos, indoor) == {"vert_pos_indoor": True}
    assert rules.evaluate_preconditions(vert_pos, {**indoor, "height_m": 5.0}) == {"vert_pos_indoor": False}
    assert rules.evaluate_preconditions(vert_pos, {**indoor, "guidance_installed": False}) == {"vert_pos_indoor": False}
    assert rules.evaluate_preconditions(vert_pos, {"indoor": False}) == {"vert_pos_indoor": True}


# ----------------------------------------------------------------- enums


def test_cur_mov_control_mode_formula(rules: Rules) -> None:
    e = rules.enum("cur_mov_control_mode")
    vertical, horizontal, yaw = ("vel", "pos", "thr"), ("ang", "vel", "pos"), ("ang", "rate")
    for v, vn in enumerate(vertical):
        for h, hn in enumerate(horizontal):
            for y, yn in enumerate(yaw):
                assert e[v * 6 + h * 2 + y + 1] == f"horiz_{hn}_vert_{vn}_yaw_{yn}"
    assert e[0] == "atti_stop"
    assert {k: e[k] for k in (97, 98, 99, 100)} == {
        97: "gps_atti_ctrl_cl_yaw_rate", 98: "gps_atti_ctrl_yaw_rate",
        99: "atti_ctrl_yaw_rate", 100: "atti_ctrl_stop",
    }
    assert len(e) == 23


def test_combination_index_matches_cur_mov_control_mode(rules: Rules) -> None:
    short = {"hori_atti_tilt_ang": "ang", "hori_vel": "vel", "hori_pos": "pos",
             "vert_vel": "vel", "vert_pos": "pos", "vert_thrust": "thr", "yaw_ang": "ang", "yaw_rate": "rate"}
    e = rules.enum("cur_mov_control_mode")
    for index in range(1, 19):
        c = rules.combination(index)
        assert e[index] == f"horiz_{short[c['horizontal']]}_vert_{short[c['vertical']]}_yaw_{short[c['yaw']]}"


def test_enums_match_naming(rules: Rules) -> None:
    assert rules.enum("control_device") == {0: "rc", 1: "mobile_device", 2: "onboard_device"}
    assert rules.enum("frequency_code") == {
        0: "hz_0", 1: "hz_1", 2: "hz_10", 3: "hz_50", 4: "hz_100", 5: "keep", 6: "hz_200", 7: "hz_400"}
    assert rules.enum("activation_result") == {
        0: "success", 1: "invalid_parameters", 2: "cannot_recognize_encrypted_package", 3: "new_app_id",
        4: "no_response_from_app", 5: "no_internet", 6: "server_rejected", 7: "level_insufficient",
        8: "wrong_sdk_version"}
    assert rules.enum("control_ack") == {
        0: "rc_not_in_f_mode", 1: "released", 2: "obtained", 3: "obtain_in_progress",
        4: "release_in_progress", 0xC9: "in_ioc_mode"}
    assert rules.enum("frequency_ack") == {0: "success", 1: "parameter_error"}
    assert rules.enum("version_ack") == {0x0000: "activated", 0xFF01: "not_activated"}
    assert rules.enum("flight_status_old") == {
        1: "standby", 2: "take_off", 3: "in_air", 4: "landing", 5: "finish_landing"}
    assert rules.enum("flight_status_new") == {0: "motor_off", 1: "on_ground_motor_on", 2: "in_air_motor_on"}
    assert rules.enum("horizontal_logic") == {0: "hori_atti_tilt_ang", 1: "hori_vel", 2: "hori_pos"}
    assert rules.enum("vertical_logic") == {0: "vert_vel", 1: "vert_pos", 2: "vert_thrust"}
    assert rules.enum("yaw_logic") == {0: "yaw_ang", 1: "yaw_rate"}
    assert rules.enum("horizontal_frame") == {0: "ground", 1: "body"}
    assert rules.enum("stable_mode") == {0: "non_stable", 1: "stable"}
    assert rules.enum("profile") == {0: "m100_fw2_3", 1: "m100_fw3_1", 2: "a3_fw3_1"}


def test_frequency_codes(rules: Rules, raw: dict[str, Any]) -> None:
    assert [rules.frequency_hz(c) for c in range(8)] == [0, 1, 10, 50, 100, None, 200, 400]
    later = {c["value"] for c in raw["frequencies"]["codes"] if c["availability"] == "later_sdk"}
    assert later == {6, 7}
    assert raw["frequencies"]["request"]["length"] == 16


# -------------------------------------------------------------- profiles

FACTS_BIT_ORDER = {
    "m100-fw2.3": ["time_stamp", "quaternion", "acceleration", "velocity", "angular_rate", "position",
                   "magnetometer", "rc", "gimbal", "flight_status", "battery", "control_info"],
    "m100-fw3.1": ["time_stamp", "quaternion", "acceleration", "velocity", "angular_rate", "position",
                   "magnetometer", "rc", "gimbal", "flight_status", "battery", "control_info"],
    "a3-fw3.1": ["time_stamp", "quaternion", "acceleration", "velocity", "angular_rate", "position",
                 "gps_detail", "rtk_detail", "magnetometer", "rc", "gimbal", "flight_status", "battery",
                 "control_info"],
}
# PROTOCOL-FACTS §3, item by item.
FACTS_SIZES = {
    "m100-fw2.3": [4, 16, 12, 13, 12, 25, 6, 12, 12, 1, 1, 1],
    "m100-fw3.1": [9, 16, 12, 13, 12, 25, 6, 12, 13, 1, 1, 2],
    "a3-fw3.1": [9, 16, 12, 13, 12, 25, 32, 44, 6, 12, 13, 1, 1, 2],
}


# The params of the parametric items: FW 2.3 the short forms, FW 3.1 the long ones (errata E28).
FACTS_PARAMS = {
    False: {"time_stamp": {"has_ns_and_sync": False}, "gimbal": {"has_limit_byte": False}, "control_info": {"has_mode": False}},
    True: {"time_stamp": {"has_ns_and_sync": True}, "gimbal": {"has_limit_byte": True}, "control_info": {"has_mode": True}},
}


@pytest.mark.parametrize(("name", "value", "n_items", "total", "variants"), [
    ("m100-fw2.3", 0, 12, 115, (4, 12, 1)),
    ("m100-fw3.1", 1, 12, 122, (9, 13, 2)),
    ("a3-fw3.1", 2, 14, 198, (9, 13, 2)),
])
def test_profile_layout(rules: Rules, name: str, value: int, n_items: int, total: int,
                        variants: tuple[int, int, int]) -> None:
    p = rules.profile(name)
    assert p.value == value and p.ksy_name == name.replace("-", "_").replace(".", "_")
    assert {k: dict(v) for k, v in p.item_params.items()} == FACTS_PARAMS[name != "m100-fw2.3"]
    assert len(p.flag_bits) == n_items
    assert list(p.flag_bits) == FACTS_BIT_ORDER[name]
    assert list(p.item_sizes.values()) == FACTS_SIZES[name]
    assert sum(p.item_sizes.values()) == total == p.full_payload_size
    assert (p.time_stamp_size, p.gimbal_size, p.control_info_size) == variants
    assert p.payload_size(p.all_flags) == total
    assert p.payload_size(0) == 0
    with pytest.raises(RulesError):
        p.payload_size(1 << n_items)


def test_broadcast_items(rules: Rules, raw: dict[str, Any]) -> None:
    assert set(rules.broadcast_item_names) == set().union(*(rules.profile(n).flag_bits for n in PROFILES))
    assert rules.broadcast_item("gimbal").params == ("has_limit_byte",)
    assert rules.broadcast_item("acceleration").type == rules.broadcast_item("angular_rate").type == "vector3f"
    assert {i for i in rules.broadcast_item_names if rules.broadcast_item(i).type == "u1"} == {"flight_status", "battery"}
    assert all(b["source"] and b["doc"] for b in raw["broadcast_items"].values())
    with pytest.raises(RulesError, match="unknown broadcast item 'compass'"):
        rules.broadcast_item("compass")


# The ERRATA entries that decide each item's size and fields, which every
# golden vector of the item alone is flagged with (E29: the spec's names, not
# the seed's typos; E25: the battery byte's 0-100 bound).
FACTS_ITEM_ERRATA = {
    "time_stamp": ("E08",), "quaternion": ("E29",), "acceleration": ("E18",), "velocity": ("E04",),
    "angular_rate": ("E18",), "position": ("E01", "E29"), "gps_detail": ("E06", "E13"),
    "rtk_detail": ("E06", "E14"), "magnetometer": ("E07",), "rc": ("E07",), "gimbal": ("E09",),
    "flight_status": ("E19",), "battery": ("E25",), "control_info": ("E03",),
}


def test_broadcast_item_errata(rules: Rules) -> None:
    assert {i: rules.broadcast_item(i).errata for i in rules.broadcast_item_names} == FACTS_ITEM_ERRATA
    assert set().union(*FACTS_ITEM_ERRATA.values()) <= errata_ids()
    assert broadcast_item("position") == rules.broadcast_item("position")


# ERRATA E30: FW 3.1 firmware (M100 and A3) sends an 11-byte version ID
# between the CRC and the name of the version ACK; M100 FW 2.3 does not.
FACTS_VERSION_ID = {"m100-fw2.3": False, "m100-fw3.1": True, "a3-fw3.1": True}


def test_version_ack_per_profile(rules: Rules, raw: dict[str, Any]) -> None:
    assert {name: rules.profile(name).has_version_id for name in PROFILES} == FACTS_VERSION_ID
    for name in PROFILES:
        assert "errata E30" in raw["profiles"][name]["version_ack"]["source"], name


def test_variant_sizes_of_a_profile_without_the_item(rules: Rules) -> None:
    p = rules.profile("m100-fw2.3")
    no_gimbal = type(p)(**{**p.__dict__, "flag_bits": tuple(i for i in p.flag_bits if i != "gimbal")})
    with pytest.raises(RulesError, match="no item 'gimbal'"):
        no_gimbal.gimbal_size


def _items_ksy_copy(tmp_path: Path, old: str, new: str) -> Path:
    text = rules_module.ITEMS_KSY_PATH.read_text(encoding="utf-8")
    assert text.count(old) == 1, old
    path = tmp_path / "osdk_broadcast_items.ksy"
    path.write_text(text.replace(old, new), encoding="utf-8")
    return path


def test_item_sizes_are_computed_from_the_item_types(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """An extra s2 channel in the ksy rc type makes rc 14 bytes in every profile."""
    monkeypatch.setattr(rules_module, "ITEMS_KSY_PATH", _items_ksy_copy(
        tmp_path, "      - id: gear\n        type: s2\n", "      - id: gear\n        type: s2\n"
                  "      - id: aux\n        type: s2\n        doc: An extra channel.\n"))
    changed = load_rules()
    assert [changed.profile(name).item_sizes["rc"] for name in PROFILES] == [14, 14, 14]
    assert [changed.profile(name).full_payload_size for name in PROFILES] == [115 + 2, 122 + 2, 198 + 2]


@pytest.mark.parametrize(("old", "new", "message"), [
    ("      - id: reserved\n        type: b5", "      - id: reserved\n        type: b6",
     r"profiles\.m100-fw3\.1: the size of gimbal cannot be worked out .*whole bytes"),
    ("  gimbal:\n    doc:", "  gimbal_angles:\n    doc:",
     r"broadcast_items\.gimbal\.type: 'gimbal' is not a type of osdk_broadcast_items\.ksy"),
    ("      - id: has_limit_byte\n", "      - id: with_limit_byte\n",
     r"broadcast_items\.gimbal\.params: \['has_limit_byte'\], but osdk_broadcast_items\.ksy gimbal has params \['with_limit_byte'\]"),
])
def test_item_types_that_do_not_fit_the_rules(tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                              old: str, new: str, message: str) -> None:
    monkeypatch.setattr(rules_module, "ITEMS_KSY_PATH", _items_ksy_copy(tmp_path, old, new))
    with pytest.raises(RulesError, match=message):
        load_rules()


def test_errata_are_read_from_errata_md(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """An errata id the rules list must head an entry of spec/ERRATA.md."""
    text = rules_module.ERRATA_PATH.read_text(encoding="utf-8")
    assert text.count("\n## E09: ") == 1
    shortened = tmp_path / "ERRATA.md"
    shortened.write_text(text.replace("\n## E09: ", "\n## Gimbal: "), encoding="utf-8")
    monkeypatch.setattr(rules_module, "ERRATA_PATH", shortened)
    with pytest.raises(RulesError, match=r"broadcast_items\.gimbal\.errata: E09 is not an entry of .*ERRATA\.md"):
        load_rules()
    monkeypatch.setattr(rules_module, "ERRATA_PATH", tmp_path / "absent.md")
    with pytest.raises(RulesError, match="cannot read the errata .*absent.md"):
        load_rules()


def test_unreadable_item_types(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(rules_module, "ITEMS_KSY_PATH", tmp_path / "missing.ksy")
    with pytest.raises(RulesError, match="cannot read the broadcast item types"):
        load_rules()


def test_facts_worked_broadcast_sizes(rules: Rules) -> None:
    # facts §1: A3 broadcast with flags 0x1800 carries flight status and battery: 2 bytes.
    p = rules.profile("a3-fw3.1")
    assert p.bit("flight_status") == 11 and p.bit("battery") == 12
    assert p.payload_size(0x1800) == 2


SEED_RATES = {
    "time_stamp": 100, "quaternion": 100, "acceleration": 100, "velocity": 100, "angular_rate": 100,
    "position": 100, "gps_detail": 50, "rtk_detail": 50, "magnetometer": 0, "rc": 50, "gimbal": 50,
    "flight_status": 10, "battery": 1, "control_info": 0,
}


@pytest.mark.parametrize("name", PROFILES)
def test_default_rates(rules: Rules, name: str) -> None:
    p = rules.profile(name)
    assert dict(p.default_rates_hz) == {item: SEED_RATES[item] for item in p.flag_bits}


def test_flight_status_defaults(rules: Rules) -> None:
    assert rules.profile("m100-fw2.3").flight_status_enum == "old"
    assert rules.profile("m100-fw3.1").flight_status_enum == "old"
    a3 = rules.profile("a3-fw3.1")
    assert (a3.flight_status_enum, a3.flight_status_overridable) == ("new", True)
    assert rules.flight_status_enum("a3-fw3.1", "old") == rules.enum("flight_status_old")
    with pytest.raises(RulesError):
        rules.flight_status_enum("m100-fw3.1", "new")
    table = [("M100", "9.9.9.9", "old"), ("A3", "1.4.9.9", "old"), ("A3", "1.5.0.0", "new"),
             ("M600", "1.0.0.79", "old"), ("M600", "1.0.0.80", "new"), ("N3", "1.0.0.0", "new")]
    for aircraft, fw, expected in table:
        assert rules.flight_status_enum_for(aircraft, fw) == expected


def test_rc_gear_as_seed_says(raw: dict[str, Any]) -> None:
    gear = {v["label"]: v["value"] for v in raw["rc_channels"]["channels"]["gear"]["values"]}
    assert gear == {"gear_down": -4545, "gear_up": -10000}
    mode = {v["value"]: v["label"] for v in raw["rc_channels"]["channels"]["mode"]["values"]}
    assert mode == {-8000: "P", 0: "A", 8000: "F"}


# ------------------------------------------------------------------ CRCs


def _reflect(value: int, bits: int) -> int:
    return int(f"{value:0{bits}b}"[::-1], 2)


def reference_crc(params: Any, data: bytes) -> int:
    """Bit-at-a-time CRC in the Rocksoft model (MSB-first register, inputs and
    output reflected as the parameters say), fed with the Rocksoft init."""
    width, top = params.width, 1 << (params.width - 1)
    mask = (1 << width) - 1
    reflect = _reflect
    reg = params.init_rocksoft
    for byte in data:
        if params.reflect_in:
            byte = reflect(byte, 8)
        reg ^= byte << (width - 8)
        for _ in range(8):
            reg = ((reg << 1) ^ params.poly) & mask if reg & top else (reg << 1) & mask
    if params.reflect_out:
        reg = reflect(reg, width)
    return reg ^ params.xorout


def lsb_first_crc(params: Any, data: bytes) -> int:
    """Bit-at-a-time reflected CRC as the SDK runs it: LSB-first register
    loaded with `init` as stated, reflected polynomial."""
    assert params.reflect_in and params.reflect_out and params.init_form == "reflected_register"
    poly = _reflect(params.poly, params.width)
    reg = params.init
    for byte in data:
        reg ^= byte
        for _ in range(8):
            reg = (reg >> 1) ^ poly if reg & 1 else reg >> 1
    return reg ^ params.xorout


@pytest.mark.parametrize("name", ["crc16", "crc32"])
def test_both_init_forms_give_the_check_value(rules: Rules, name: str) -> None:
    p = rules.crc_params(name)
    assert lsb_first_crc(p, b"123456789") == p.check
    assert reference_crc(p, b"123456789") == p.check
    assert p.init_rocksoft == _reflect(p.init, p.width)
    for data in (b"", b"\x00", bytes(range(256))):
        assert lsb_first_crc(p, data) == reference_crc(p, data)


@pytest.mark.parametrize("name", ["crc16", "crc32"])
def test_crc_check_and_residue(rules: Rules, name: str) -> None:
    p = rules.crc_params(name)
    assert reference_crc(p, b"123456789") == p.check
    for data in (b"123456789", b"", b"\xaa\x00\xff", bytes(range(40))):
        crc = reference_crc(p, data)
        assert reference_crc(p, data + crc.to_bytes(p.width // 8, "little")) == p.residue


def test_crc_values_from_facts(rules: Rules) -> None:
    assert rules.crc_params("crc16").check == 0x2752
    assert rules.crc_params("crc32").check == 0xE4D9DC14
    assert rules.crc_params("crc16").init == 0x3AA3
    assert rules.crc_params("crc32").init == 0x00003AA3


@pytest.mark.parametrize("frame_hex", [
    "aa230000000000003412e17201034b0000803f000000c00000003f0000f041fcdb01ba",
    "aa1600000000000007001ede02000018035769c676b2",
])
def test_crc_coverage_on_facts_frames(rules: Rules, frame_hex: str) -> None:
    frame = bytes.fromhex(frame_hex)
    c16, c32 = rules.crc_params("crc16"), rules.crc_params("crc32")
    assert len(frame) == int.from_bytes(frame[1:3], "little") & 0x3FF
    first, last = c16.covers
    s_first, s_last = c16.stored_at
    assert reference_crc(c16, frame[first:last + 1]) == int.from_bytes(frame[s_first:s_last + 1], "little")
    first, last = c32.covers
    assert (first, last) == (0, -5) and c32.stored_at == (-4, -1)
    assert reference_crc(c32, frame[first:len(frame) + last + 1]) == int.from_bytes(frame[-4:], "little")
    assert reference_crc(c32, frame) == c32.residue


# ----------------------------------------------------- corrupted rules files


def _write(tmp_path: Path, data: Any) -> Path:
    path = tmp_path / "rules.yaml"
    # libyaml's emitter where PyYAML has it: the pure-Python one takes a quarter of a second per copy
    path.write_text(yaml.dump(data, Dumper=getattr(yaml, "CSafeDumper", yaml.SafeDumper), sort_keys=False),
                    encoding="utf-8")
    return path


def _mutations() -> list[tuple[str, Callable[[dict[str, Any]], None], str]]:
    def param_as_text(d: dict[str, Any]) -> None:
        d["profiles"]["m100-fw2.3"]["item_params"]["gimbal"]["has_limit_byte"] = "no"

    def bad_logic(d: dict[str, Any]) -> None:
        d["control_modes"]["combinations"][2]["horizontal"] = "hori_speed"

    def unknown_key(d: dict[str, Any]) -> None:
        d["frame"]["colour"] = "blue"

    def missing_section(d: dict[str, Any]) -> None:
        del d["units"]

    def bad_sof(d: dict[str, Any]) -> None:
        d["frame"]["sof"] = 0xAB

    def layout_note_size(d: dict[str, Any]) -> None:
        d["profiles"]["a3-fw3.1"]["layout_note"] = "the 4-byte time stamp and the 13-byte gimbal item"

    def description_size(d: dict[str, Any]) -> None:
        d["profiles"]["m100-fw2.3"]["description"] = "Matrice 100: 4-byte time stamp, 13-byte gimbal item, 12 items"

    def description_count(d: dict[str, Any]) -> None:
        d["profiles"]["a3-fw3.1"]["description"] = "A3 family: 12 items"

    def description_unknown_item(d: dict[str, Any]) -> None:
        d["profiles"]["m100-fw2.3"]["description"] = "Matrice 100: 32-byte gps detail"

    def unknown_flag_item(d: dict[str, Any]) -> None:
        d["profiles"]["m100-fw2.3"]["flag_bits"][6] = "compass"

    def missing_params(d: dict[str, Any]) -> None:
        del d["profiles"]["m100-fw2.3"]["item_params"]["gimbal"]

    def wrong_param_name(d: dict[str, Any]) -> None:
        d["profiles"]["m100-fw2.3"]["item_params"]["control_info"] = {"has_cur_mov_control_mode": False}

    def params_for_absent_item(d: dict[str, Any]) -> None:
        d["profiles"]["m100-fw2.3"]["item_params"]["gps_detail"] = {"has_date": True}

    def param_as_number(d: dict[str, Any]) -> None:
        d["profiles"]["m100-fw2.3"]["item_params"]["gimbal"]["has_limit_byte"] = 1

    def params_for_plain_type(d: dict[str, Any]) -> None:
        d["broadcast_items"]["battery"]["params"] = ["percent"]

    def unknown_item_type(d: dict[str, Any]) -> None:
        d["broadcast_items"]["rc"]["type"] = "remote"

    def unused_item(d: dict[str, Any]) -> None:
        d["broadcast_items"]["compass"] = {"type": "magnetometer", "doc": "Compass.", "source": "decision: test"}

    def profile_value_order(d: dict[str, Any]) -> None:
        d["profiles"]["m100-fw2.3"]["value"], d["profiles"]["m100-fw3.1"]["value"] = 1, 0

    def bad_profile_id(d: dict[str, Any]) -> None:
        d["profiles"] = {("M100 fw2.3" if k == "m100-fw2.3" else k): v for k, v in d["profiles"].items()}

    def combination_missing_profile(d: dict[str, Any]) -> None:
        del d["control_modes"]["combinations"][0]["ranges"]["a3-fw3.1"]

    def unknown_profile_named(d: dict[str, Any]) -> None:
        d["gimbal_limit"]["applies_to_profiles"] = ["m100-fw3.1", "a3-fw3.2"]

    def unknown_plausibility_item(d: dict[str, Any]) -> None:
        d["plausibility"]["enum_membership"][0]["item"] = "status"

    def wrong_value(d: dict[str, Any]) -> None:
        d["control_modes"]["undocumented"][0]["value"] = 0x68

    def duplicate_enum(d: dict[str, Any]) -> None:
        d["enums"]["control_ack"]["values"][1]["value"] = 0

    def wrong_cur_mov(d: dict[str, Any]) -> None:  # values 3 and 4 swapped
        values = d["enums"]["cur_mov_control_mode"]["values"]
        values[3]["name"], values[4]["name"] = values[4]["name"], values[3]["name"]

    def drifted_range(d: dict[str, Any]) -> None:
        c = d["control_modes"]["combinations"][0]
        c["ranges"] = copy.deepcopy(c["ranges"])
        c["ranges"]["a3-fw3.1"]["vertical"]["max"] = 5

    def bit0_missing_profile(d: dict[str, Any]) -> None:
        del d["control_mode"]["bit0_by_profile"]["a3-fw3.1"]

    def bit0_yaw_frame_incomplete(d: dict[str, Any]) -> None:
        del d["control_mode"]["bit0_by_profile"]["m100-fw2.3"]["violation"]

    def bit0_stable_with_values(d: dict[str, Any]) -> None:
        d["control_mode"]["bit0_by_profile"]["a3-fw3.1"]["yaw_ang_requires"] = 0

    def no_version_ack(d: dict[str, Any]) -> None:
        del d["profiles"]["m100-fw3.1"]["version_ack"]

    def version_id_as_size(d: dict[str, Any]) -> None:
        d["profiles"]["a3-fw3.1"]["version_ack"] = {"version_id": 11, "source": "decision: test"}

    def unknown_errata(d: dict[str, Any]) -> None:
        d["broadcast_items"]["rc"]["errata"] = ["E07", "E99"]

    def malformed_errata(d: dict[str, Any]) -> None:
        d["broadcast_items"]["gimbal"]["errata"] = ["errata E09"]

    return [
        ("profile_value_order", profile_value_order, r"profiles: values must be 0\.\.2 in file order, found \[1, 0, 2\]"),
        ("bad_profile_id", bad_profile_id, r"profiles: 'M100 fw2\.3' does not match"),
        ("bit0_missing_profile", bit0_missing_profile,
         r"control_mode\.bit0_by_profile: must name every profile once \(differs in \['a3-fw3\.1'\]\)"),
        ("combination_missing_profile", combination_missing_profile,
         r"control_modes\.combinations\[index 1\]\.ranges: must name every profile once \(differs in \['a3-fw3\.1'\]\)"),
        ("unknown_profile_named", unknown_profile_named, r"gimbal_limit\.applies_to_profiles: 'a3-fw3\.2' is not a profile"),
        ("unknown_plausibility_item", unknown_plausibility_item,
         r"plausibility\.enum_membership\[0\]\.item: 'status' is not in broadcast_items"),
        ("unknown_flag_item", unknown_flag_item, r"profiles\.m100-fw2\.3\.flag_bits: 'compass' is not in broadcast_items"),
        ("missing_params", missing_params,
         r"profiles\.m100-fw2\.3\.item_params\.gimbal: gives \[\], broadcast_items\.gimbal has params \['has_limit_byte'\]"),
        ("wrong_param_name", wrong_param_name,
         r"item_params\.control_info: gives \['has_cur_mov_control_mode'\], broadcast_items\.control_info has params \['has_mode'\]"),
        ("params_for_absent_item", params_for_absent_item, r"profiles\.m100-fw2\.3\.item_params\.gps_detail: not an item of this profile"),
        ("param_as_number", param_as_number, r"profiles\.m100-fw2\.3\.item_params\.gimbal: has_limit_byte must be bool"),
        ("params_for_plain_type", params_for_plain_type, r"broadcast_items\.battery\.params: a bare byte \(u1\) has no params"),
        ("unknown_item_type", unknown_item_type, r"broadcast_items\.rc\.type: 'remote' is not a type of osdk_broadcast_items\.ksy"),
        ("unused_item", unused_item, r"broadcast_items\.compass: no profile has this item"),
        ("layout_note_size", layout_note_size, r"profiles\.a3-fw3\.1\.layout_note: says '4-byte time stamp', but time_stamp is 9 bytes"),
        ("description_size", description_size, r"profiles\.m100-fw2\.3\.description: says '13-byte gimbal item', but gimbal is 12 bytes"),
        ("description_count", description_count, r"profiles\.a3-fw3\.1\.description: says '12 items', but the profile has 14"),
        ("description_unknown_item", description_unknown_item,
         r"profiles\.m100-fw2\.3\.description: '32-byte gps detail' names no item of this profile"),
        ("bit0_yaw_frame_incomplete", bit0_yaw_frame_incomplete, r"bit0_by_profile\.m100-fw2\.3: 'violation' is a required property"),
        ("bit0_stable_with_values", bit0_stable_with_values, r"bit0_by_profile\.a3-fw3\.1: .* should not be valid"),
        ("no_version_ack", no_version_ack, r"profiles\.m100-fw3\.1: 'version_ack' is a required property"),
        ("version_id_as_size", version_id_as_size, r"profiles\.a3-fw3\.1\.version_ack\.version_id: 11 is not of type 'boolean'"),
        ("unknown_errata", unknown_errata, r"broadcast_items\.rc\.errata: E99 is not an entry of spec/ERRATA\.md"),
        ("malformed_errata", malformed_errata, r"broadcast_items\.gimbal\.errata\.0: 'errata E09' does not match"),
        ("param_as_text", param_as_text, r"profiles\.m100-fw2\.3\.item_params\.gimbal\.has_limit_byte: 'no' is not of type 'boolean', 'integer'"),
        ("bad_logic", bad_logic, r"control_modes\.combinations\.2\.horizontal: 'hori_speed' is not one of"),
        ("unknown_key", unknown_key, r"frame: Additional properties are not allowed \('colour'"),
        ("missing_section", missing_section, r"'units' is a required property"),
        ("bad_sof", bad_sof, r"frame\.sof: 170 was expected"),
        ("wrong_value", wrong_value, r"value 0x68, expected 0x60"),
        ("duplicate_enum", duplicate_enum, r"enums\.control_ack: duplicate values \[0\]"),
        ("wrong_cur_mov", wrong_cur_mov, r"cur_mov_control_mode\[3\] is 'horiz_vel_vert_vel_yaw_rate', expected 'horiz_vel_vert_vel_yaw_ang'"),
        ("drifted_range", drifted_range, r"ranges\.a3-fw3\.1\.vertical: differs from seed_ranges\.vert_vel"),
    ]


@pytest.mark.parametrize(("label", "mutate", "message"), _mutations(), ids=[m[0] for m in _mutations()])
def test_corrupted_rules_raise_clear_error(
    tmp_path: Path, raw: dict[str, Any], label: str, mutate: Callable[[dict[str, Any]], None], message: str
) -> None:
    data = copy.deepcopy(raw)
    mutate(data)
    path = _write(tmp_path, data)
    with pytest.raises(RulesError, match=message) as info:
        load_rules(path)
    assert str(path) in str(info.value)
    # no chained exception leaks into the traceback
    assert info.value.__cause__ is None
    assert info.value.__context__ is None or info.value.__suppress_context__


def test_unmodified_copy_loads(tmp_path: Path, raw: dict[str, Any]) -> None:
    assert load_rules(_write(tmp_path, raw)).profile_names == PROFILES


def test_yaml_syntax_error(tmp_path: Path) -> None:
    path = tmp_path / "rules.yaml"
    path.write_text(RULES_PATH.read_text(encoding="utf-8").replace("crc:\n", "crc: [\n", 1), encoding="utf-8")
    with pytest.raises(RulesError, match="is not valid YAML"):
        load_rules(path)


def test_duplicate_key_rejected(tmp_path: Path) -> None:
    text = RULES_PATH.read_text(encoding="utf-8")
    text = text.replace("    width: 16\n", "    width: 16\n    width: 17\n", 1)
    path = tmp_path / "rules.yaml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(RulesError, match="duplicate key 'width'"):
        load_rules(path)


def test_missing_file(tmp_path: Path) -> None:
    with pytest.raises(RulesError, match="cannot read rules file"):
        load_rules(tmp_path / "absent.yaml")


def test_not_a_mapping(tmp_path: Path) -> None:
    path = tmp_path / "rules.yaml"
    path.write_text("- just\n- a list\n", encoding="utf-8")
    with pytest.raises(RulesError, match="mapping at the top level"):
        load_rules(path)
