"""The three places the spec states the same fact must agree.

spec/*.ksy (byte layout), spec/rules.yaml (rules the layout cannot say) and
spec/ERRATA.md (decisions where sources disagree) name the same enums, bit
orders, item sizes and bit fields. These tests read each file on its own
terms (the ksy through osdk_conformance.core.ksy, the rules as plain YAML) and
compare, so a change in one that is not made in the others fails here.

The profile ksy files and the profile parts of osdk_payload.ksy are written
from rules.yaml by tools/gen_profile_ksy.py; the tests below check that they
are current, and still read them on their own terms, so a generator that
wrote something else than the rules say would fail here too.
"""
from __future__ import annotations

import copy
import importlib.util
import re
from pathlib import Path
from typing import Any, Iterator

import pytest
import yaml

from osdk_conformance.core import ksy
from osdk_conformance.core.rules import Rules, ksy_name, load_rules
from osdk_conformance.traceability.trace import Resolver, _pointer
from osdk_conformance._construct.payload import has_version_id, version_ack_value

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "spec"
RULES_PATH = SPEC / "rules.yaml"
ERRATA_PATH = SPEC / "ERRATA.md"
PROFILES = ("m100-fw2.3", "m100-fw3.1", "a3-fw3.1")
PRIMITIVE_SIZES = ksy.PRIMITIVE_SIZES


def _gen_tool() -> Any:
    spec = importlib.util.spec_from_file_location("gen_profile_ksy_under_test", ROOT / "tools" / "gen_profile_ksy.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


GEN = _gen_tool()


@pytest.fixture(scope="module")
def rules() -> dict[str, Any]:
    return yaml.safe_load(RULES_PATH.read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def index() -> ksy.KsyIndex:
    return ksy.load()


@pytest.fixture(scope="module")
def loaded() -> Rules:
    return load_rules()


def profile_file(profile: str) -> str:
    """ksy file id of a broadcast profile: a3-fw3.1 -> osdk_broadcast_a3_fw3_1."""
    return "osdk_broadcast_" + profile.replace("-", "_").replace(".", "_")


def _values(block: list[dict[str, Any]]) -> dict[int, str]:
    return {v["value"]: v["name"] for v in block}


# ------------------------------------------------------------------ enums

# rules.yaml location of an enum's values -> (ksy file id, ksy enum name)
SHARED_ENUMS = {
    "enums/cur_mov_control_mode": ("osdk_broadcast_items", "cur_mov_control_mode"),
    "enums/control_device": ("osdk_broadcast_items", "control_device"),
    "enums/frequency_code": ("osdk_payload", "frequency_code"),
    "enums/activation_result": ("osdk_payload", "activation_result"),
    "enums/control_ack": ("osdk_payload", "control_ack"),
    "enums/frequency_ack": ("osdk_payload", "frequency_ack"),
    "enums/version_ack": ("osdk_payload", "version_ack"),
    "control_mode/fields/0": ("osdk_control_mode", "horizontal_logic"),
    "control_mode/fields/1": ("osdk_control_mode", "vertical_logic"),
    "control_mode/fields/2": ("osdk_control_mode", "yaw_logic"),
    "control_mode/fields/3": ("osdk_control_mode", "horizontal_frame"),
    "control_mode/fields/4": ("osdk_control_mode", "stable_mode"),
    "frame/enc": ("osdk_frame", "encryption"),
}
# The ksy enum made from rules.yaml profiles (their `value`s), compared in
# test_profile_enum_names_follow_profile_ids.
PROFILE_ENUM = ("osdk_payload", "profile")
# ksy enums with no rules.yaml counterpart, and why.
KSY_ONLY_ENUMS = {
    ("osdk_frame", "command_set"): "command set names only label the dispatch; no rule refers to them",
    ("osdk_payload", "control_request_code"): "obtain/release request byte; no rule beyond the layout",
}


def _rules_node(rules: dict[str, Any], where: str) -> Any:
    node: Any = rules
    for part in where.split("/"):
        node = node[int(part)] if isinstance(node, list) else node[part]
    return node


def enum_mismatches(rules: dict[str, Any], index: ksy.KsyIndex, where: str) -> list[str]:
    """value -> name pairs that differ between a rules.yaml enum and its ksy enum."""
    file_id, enum = SHARED_ENUMS[where]
    in_rules = _values(_rules_node(rules, where)["values"])
    in_ksy = index.enums[(file_id, enum)]
    return [f"{where} vs {file_id}.ksy enum {enum}: {v}: {in_rules.get(v)!r} / {in_ksy.get(v)!r}"
            for v in sorted(set(in_rules) | set(in_ksy)) if in_rules.get(v) != in_ksy.get(v)]


@pytest.mark.parametrize("where", sorted(SHARED_ENUMS))
def test_enum_values_agree(rules: dict[str, Any], index: ksy.KsyIndex, where: str) -> None:
    assert enum_mismatches(rules, index, where) == []


def test_control_mode_field_names_are_ksy_enum_names(rules: dict[str, Any], index: ksy.KsyIndex) -> None:
    for n, f in enumerate(rules["control_mode"]["fields"]):
        assert SHARED_ENUMS[f"control_mode/fields/{n}"] == ("osdk_control_mode", f["name"])
        assert index.files["osdk_control_mode"]["seq"][4 - n]["enum"] == f["name"]


def test_every_ksy_enum_is_compared_or_listed(index: ksy.KsyIndex) -> None:
    compared = set(SHARED_ENUMS.values()) | {PROFILE_ENUM}
    assert set(index.enums) == compared | set(KSY_ONLY_ENUMS)
    assert not compared & set(KSY_ONLY_ENUMS)


def test_every_rules_enum_is_compared(rules: dict[str, Any]) -> None:
    """Each enum of rules.yaml that a ksy also defines is in SHARED_ENUMS; the
    flight status enums are rules-only (the ksy keeps flight_status a plain u1
    because the enum depends on the profile and an override)."""
    in_rules = {f"enums/{name}" for name in rules["enums"]}
    assert in_rules <= set(SHARED_ENUMS)
    assert set(rules["flight_status"]["enums"]) == {"old", "new"}


def test_encryption_name_and_description(rules: dict[str, Any]) -> None:
    enc = rules["frame"]["enc"]
    assert _values(enc["values"]) == {0: "plain", 1: "aes256"}
    assert "AES-256-ECB" in enc["note"]


def test_profile_enum_names_follow_profile_ids(rules: dict[str, Any], index: ksy.KsyIndex) -> None:
    ids = list(rules["profiles"])
    assert ids == list(PROFILES)
    assert [rules["profiles"][p]["value"] for p in ids] == [0, 1, 2]
    assert index.enums[PROFILE_ENUM] == {rules["profiles"][p]["value"]: p.replace("-", "_").replace(".", "_") for p in ids}
    # the payload's broadcast switch sends each profile to its own ksy, which it imports
    cases = index.files["osdk_payload"]["types"]["broadcast"]["seq"][0]["type"]["cases"]
    assert cases == {f"profile::{profile_file(p)[len('osdk_broadcast_'):]}": profile_file(p) for p in ids}
    imports = index.files["osdk_payload"]["meta"]["imports"]
    assert [i for i in imports if i.startswith("osdk_broadcast_")] == [profile_file(p) for p in ids]
    broadcast_files = {f for f in index.files if f.startswith("osdk_broadcast_") and f != "osdk_broadcast_items"}
    assert broadcast_files == {profile_file(p) for p in ids}


# ------------------------------------------------------ sizes from the ksy


def _parse_type(ref: str, file_id: str) -> tuple[str, str, list[Any]]:
    return ksy.parse_type_ref(ref, file_id)


def test_size_calculator_on_known_types(index: ksy.KsyIndex) -> None:
    """The ksy size calculator the rules loader takes item sizes from, on PROTOCOL-FACTS numbers."""
    it = "osdk_broadcast_items"
    assert index.ref_size(f"{it}::time_stamp(false)", it) == 4
    assert index.ref_size(f"{it}::time_stamp(true)", it) == 9
    assert index.type_size(it, "gimbal", {"has_limit_byte": False}) == 12
    assert index.type_size(it, "gimbal", {"has_limit_byte": True}) == 13
    assert index.type_size(it, "control_info", {"has_mode": False}) == 1
    assert index.type_size(it, "control_info", {"has_mode": True}) == 2
    assert index.type_size(it, "velocity") == 13
    assert index.type_size(it, "rtk_detail") == 44
    assert index.ref_size("version_ack_value(profile::m100_fw2_3)", "osdk_payload") == 38   # E30
    assert index.ref_size("version_ack_value(profile::m100_fw3_1)", "osdk_payload") == 49
    assert index.ref_size("version_ack_value(profile::a3_fw3_1)", "osdk_payload") == 49
    assert index.type_size("osdk_payload", "activation_request") == 44
    assert index.seq_size("osdk_movement_control", index.files["osdk_movement_control"]["seq"], {}) == 17
    with pytest.raises(ksy.KsyError, match=r"takes params \['has_limit_byte'\], got \[\]"):
        index.type_size(it, "gimbal")
    with pytest.raises(ksy.KsyError, match="not a known boolean"):
        index.seq_size(it, index.files[it]["types"]["gimbal"]["seq"], {})


def _broadcast_items(index: ksy.KsyIndex, profile: str) -> tuple[list[str], list[dict[str, Any]]]:
    seq = index.files[profile_file(profile)]["seq"]
    flags = [f["id"][len("has_"):] for f in seq if f["id"].startswith("has_")]
    items = [f for f in seq if f.get("if", "").startswith("has_")]
    return flags, items


@pytest.mark.parametrize("profile", PROFILES)
def test_flag_bit_order_matches_ksy(rules: dict[str, Any], index: ksy.KsyIndex, profile: str) -> None:
    flags, items = _broadcast_items(index, profile)
    assert flags == rules["profiles"][profile]["flag_bits"]
    # the items follow in flag order, each guarded by its own flag
    assert [f["id"] for f in items] == flags
    assert all(f["if"] == f"has_{f['id']}" for f in items)
    # flag word: one bit per item, the rest reserved and required zero
    seq = index.files[profile_file(profile)]["seq"]
    assert seq[len(flags)] == {**seq[len(flags)], "id": "reserved_flags", "type": f"b{16 - len(flags)}", "valid": 0}
    assert rules["frame"]["broadcast"]["unknown_flag_bits"] == "reject"


def ksy_item_sizes(index: ksy.KsyIndex, profile: str) -> dict[str, int]:
    """Size of each broadcast item of a profile, computed from its ksy."""
    _, items = _broadcast_items(index, profile)
    return {f["id"]: index.field_size(profile_file(profile), {**f, "if": None}, {})[0] for f in items}


# PROTOCOL-FACTS §3, item by item in flag-bit order.
FACTS_SIZES = {
    "m100-fw2.3": [4, 16, 12, 13, 12, 25, 6, 12, 12, 1, 1, 1],
    "m100-fw3.1": [9, 16, 12, 13, 12, 25, 6, 12, 13, 1, 1, 2],
    "a3-fw3.1": [9, 16, 12, 13, 12, 25, 32, 44, 6, 12, 13, 1, 1, 2],
}


@pytest.mark.parametrize("profile", PROFILES)
def test_item_sizes_match_ksy(loaded: Rules, index: ksy.KsyIndex, profile: str) -> None:
    """The profile's ksy file, read on its own, gives the sizes the rules
    compute from item_params, and both are PROTOCOL-FACTS' sizes."""
    from_ksy = ksy_item_sizes(index, profile)
    p = loaded.profile(profile)
    assert from_ksy == dict(p.item_sizes)
    assert list(from_ksy.values()) == FACTS_SIZES[profile]
    assert (p.time_stamp_size, p.gimbal_size, p.control_info_size) == (
        from_ksy["time_stamp"], from_ksy["gimbal"], from_ksy["control_info"])


@pytest.mark.parametrize("profile", PROFILES)
def test_profile_ksy_items_are_the_rules_items(rules: dict[str, Any], index: ksy.KsyIndex, profile: str) -> None:
    """Each item of a profile's ksy has the type, params and doc rules.yaml gives it."""
    p = rules["profiles"][profile]
    _, items = _broadcast_items(index, profile)
    for f in items:
        spec = rules["broadcast_items"][f["id"]]
        assert f["doc"] == spec["doc"]
        if spec["type"] == "u1":
            assert f["type"] == "u1"
            continue
        file_id, type_name, args = _parse_type(f["type"], profile_file(profile))
        assert (file_id, type_name) == ("osdk_broadcast_items", spec["type"])
        assert dict(zip(spec.get("params", []), args)) == p["item_params"].get(f["id"], {})
        assert len(args) == len(spec.get("params", []))


# ------------------------------------------- generated from rules.yaml


def test_generated_ksy_is_current() -> None:
    """spec/osdk_broadcast_<profile>.ksy and the marked parts of osdk_payload.ksy
    are what tools/gen_profile_ksy.py writes from rules.yaml (`make regen`)."""
    assert GEN.drift() == []


def test_generated_ksy_says_so(rules: dict[str, Any]) -> None:
    for profile in rules["profiles"]:
        assert (SPEC / f"{profile_file(profile)}.ksy").read_text(encoding="utf-8").startswith(GEN.FILE_MARK + "\n")
    for path in SPEC.glob("*.ksy"):
        if not path.name.startswith("osdk_broadcast_") or path.name == "osdk_broadcast_items.ksy":
            assert GEN.FILE_MARK not in path.read_text(encoding="utf-8"), path.name
    parts = [m.group("part") for m in GEN.REGION.finditer((SPEC / "osdk_payload.ksy").read_text(encoding="utf-8"))]
    assert parts == ["imports", "version id", "broadcast cases", "profile enum"]


@pytest.fixture()
def spec_copy(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """The generator pointed at a copy of spec/."""
    spec = tmp_path / "spec"
    spec.mkdir()
    for path in SPEC.glob("*.ksy"):
        (spec / path.name).write_bytes(path.read_bytes())
    monkeypatch.setattr(GEN, "ROOT", tmp_path)
    monkeypatch.setattr(GEN, "SPEC", spec)
    monkeypatch.setattr(GEN, "PAYLOAD", spec / "osdk_payload.ksy")
    return spec


def test_drift_is_found_and_repaired(spec_copy: Path) -> None:
    payload = spec_copy / "osdk_payload.ksy"
    original = payload.read_text(encoding="utf-8")
    payload.write_text(original.replace("            profile::a3_fw3_1: osdk_broadcast_a3_fw3_1\n", ""), encoding="utf-8")
    m100 = spec_copy / "osdk_broadcast_m100_fw3_1.ksy"
    m100_text = m100.read_text(encoding="utf-8")
    m100.write_text(m100_text.replace("time_stamp(true)", "time_stamp(false)"), encoding="utf-8")
    stale = spec_copy / "osdk_broadcast_n3_fw3_1.ksy"
    stale.write_text(m100_text, encoding="utf-8")
    assert GEN.drift() == [
        "spec/osdk_broadcast_m100_fw3_1.ksy differs from what rules.yaml gives",
        "spec/osdk_broadcast_n3_fw3_1.ksy is generated for a profile that rules.yaml no longer has",
        "spec/osdk_payload.ksy differs from what rules.yaml gives",
    ]
    assert sorted(p.name for p in GEN.write()) == [
        "osdk_broadcast_m100_fw3_1.ksy", "osdk_broadcast_n3_fw3_1.ksy", "osdk_payload.ksy"]
    assert payload.read_text(encoding="utf-8") == original
    assert m100.read_text(encoding="utf-8") == m100_text
    assert not stale.exists()
    assert (spec_copy / "osdk_broadcast_items.ksy").exists()  # hand-written: never touched
    assert GEN.drift() == []


def test_a_region_marker_is_required(spec_copy: Path) -> None:
    payload = spec_copy / "osdk_payload.ksy"
    text = payload.read_text(encoding="utf-8")
    payload.write_text(text.replace("(broadcast cases): do not edit", "(broadcast cases): edit"), encoding="utf-8")
    with pytest.raises(SystemExit, match=r"must mark each of .* \(missing \['broadcast cases'\], repeated \[\]\)"):
        GEN.drift()


def test_a_new_profile_is_generated_from_the_rules(tmp_path: Path, rules: dict[str, Any]) -> None:
    """A fourth profile, written in rules.yaml only, gets its ksy file, its
    enum value and its switch case."""
    data = copy.deepcopy(rules)
    data["profiles"]["m600-fw3.2"] = {**copy.deepcopy(data["profiles"]["a3-fw3.1"]), "value": 3}
    data["profiles"]["m600-fw3.2"]["covers"] = {**data["profiles"]["a3-fw3.1"]["covers"], "aircraft": ["M600"],
                                                "sdk_version": 0x03020A00}
    data["control_mode"]["bit0_by_profile"]["m600-fw3.2"] = data["control_mode"]["bit0_by_profile"]["a3-fw3.1"]
    data["control_modes"]["profile_ranges"]["m600-fw3.2"] = "seed"
    for c in data["control_modes"]["combinations"]:
        c["ranges"] = {**c["ranges"], "m600-fw3.2": c["ranges"]["a3-fw3.1"]}
    path = tmp_path / "rules.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    want = GEN.outputs(load_rules(path))
    text = want[SPEC / "osdk_broadcast_m600_fw3_2.ksy"]
    doc = yaml.safe_load(text)
    assert doc["meta"]["id"] == "osdk_broadcast_m600_fw3_2"
    assert doc["meta"]["application"] == "M600 with firmware 3.2 (OSDK 3.2)"
    assert [f["id"] for f in doc["seq"]][:14] == [f"has_{i}" for i in data["profiles"]["a3-fw3.1"]["flag_bits"]]
    a3 = want[SPEC / "osdk_broadcast_a3_fw3_1.ksy"]
    assert text.split("seq:\n", 1)[1] == a3.split("seq:\n", 1)[1]   # same items, same params
    payload = yaml.safe_load(want[SPEC / "osdk_payload.ksy"])
    assert payload["enums"]["profile"][3] == {"id": "m600_fw3_2", "doc": "m600-fw3.2, M600 with firmware 3.2."}
    assert payload["types"]["broadcast"]["seq"][0]["type"]["cases"]["profile::m600_fw3_2"] == "osdk_broadcast_m600_fw3_2"
    assert payload["meta"]["imports"][-1] == "osdk_broadcast_m600_fw3_2"


# ERRATA E30: the version ACK of FW 3.1 firmware carries an 11-byte version
# ID between the CRC and the name (49 bytes); M100 FW 2.3's does not (38).
FACTS_VERSION_ACK_SIZE = {"m100-fw2.3": 38, "m100-fw3.1": 49, "a3-fw3.1": 49}


@pytest.mark.parametrize("profile", PROFILES)
def test_version_ack_layout_follows_the_rules(rules: dict[str, Any], index: ksy.KsyIndex, profile: str) -> None:
    """rules.yaml says per profile whether the version ACK has the ID; the
    ksy's has_version_id (generated from it) and Construct's agree, in size."""
    version_id = rules["profiles"][profile]["version_ack"]["version_id"]
    size = index.ref_size(f"version_ack_value(profile::{ksy_name(profile)})", "osdk_payload")
    assert size == FACTS_VERSION_ACK_SIZE[profile] == 38 + 11 * version_id
    assert has_version_id(profile) is version_id
    assert version_ack_value(profile).sizeof() == size
    assert "E30" in _cited(rules["profiles"][profile]["version_ack"]["source"])


def _payload_with_version_ids(tmp_path: Path, rules: dict[str, Any], version_ids: dict[str, bool]) -> dict[str, Any]:
    """osdk_payload.ksy as the generator writes it from rules.yaml with other version_ack.version_id values."""
    data = copy.deepcopy(rules)
    for profile, version_id in version_ids.items():
        data["profiles"][profile]["version_ack"].update(version_id=version_id, source="decision: test")
    path = tmp_path / "rules.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False), encoding="utf-8")
    return yaml.safe_load(GEN.outputs(load_rules(path))[SPEC / "osdk_payload.ksy"])


@pytest.mark.parametrize(("version_ids", "expr"), [
    ({}, "profile != profile::m100_fw2_3"),
    ({"m100-fw3.1": False}, "profile != profile::m100_fw2_3 and profile != profile::m100_fw3_1"),
    ({"m100-fw2.3": True}, "true"),
])
def test_has_version_id_is_generated_from_the_rules(tmp_path: Path, rules: dict[str, Any],
                                                   version_ids: dict[str, bool], expr: str) -> None:
    payload = _payload_with_version_ids(tmp_path, rules, version_ids)
    assert payload["types"]["version_ack_value"]["instances"]["has_version_id"]["value"] == expr


# --------------------------------------------------------------- bit fields


def _bit_layout(seq: list[dict[str, Any]]) -> list[tuple[str, int, int]]:
    """(name, lsb, width) of the bN fields of a seq, LSB first (bit-endian le)."""
    out, lsb = [], 0
    for f in seq:
        t = f.get("type")
        if isinstance(t, str) and re.fullmatch(r"b\d+", t):
            out.append((f["id"], lsb, int(t[1:])))
            lsb += int(t[1:])
    return out


@pytest.mark.parametrize(("block", "file_id", "type_name"), [
    ("device_byte", "osdk_broadcast_items", "control_info"),
    ("velocity_status", "osdk_broadcast_items", "velocity"),
    ("gimbal_limit", "osdk_broadcast_items", "gimbal_limit"),
])
def test_bit_fields_match_ksy(rules: dict[str, Any], index: ksy.KsyIndex, block: str, file_id: str, type_name: str) -> None:
    assert index.files[file_id]["meta"]["bit-endian"] == "le"
    ksy_bits = _bit_layout(index.files[file_id]["types"][type_name]["seq"])
    assert ksy_bits == [(f["name"], f["lsb"], f["width"]) for f in rules[block]["fields"]]
    enums = {f["name"]: f.get("enum") for f in rules[block]["fields"] if f["kind"] == "enum"}
    for f in index.files[file_id]["types"][type_name]["seq"]:
        if f["id"] in enums:
            assert f["enum"] == enums[f["id"]]


def test_control_mode_bits_match_ksy(rules: dict[str, Any], index: ksy.KsyIndex) -> None:
    doc = index.files["osdk_control_mode"]
    assert doc["meta"]["bit-endian"] == "le"
    ksy_bits = sorted(_bit_layout(doc["seq"]), key=lambda x: x[1])
    assert ksy_bits == sorted(((f["name"], f["lsb"], f["width"]) for f in rules["control_mode"]["fields"]), key=lambda x: x[1])


def test_bit0_yaw_frame_names_match_horizontal_frame_names(rules: dict[str, Any], index: ksy.KsyIndex) -> None:
    """On FW 2.3 bit 0 is a frame selector; it reuses the frame names of bits 2-1."""
    fw23 = rules["control_mode"]["bit0_by_profile"]["m100-fw2.3"]
    assert _values(fw23["values"]) == index.enums[("osdk_control_mode", "horizontal_frame")]


# ------------------------------------------------------------------- units


# rules.yaml units fields that stand for a whole byte of bit fields in the ksy
UNIT_ALIASES = {
    ("velocity", "status"): {"data_valid", "sensor_id", "reserved"},
    ("control_info", "device"): {"control_device", "onboard_requested", "virtual_rc", "reserved"},
}


def test_unit_fields_name_ksy_fields(rules: dict[str, Any], index: ksy.KsyIndex) -> None:
    assert set(rules["units"]["items"]) == set(rules["broadcast_items"])
    for item, spec in rules["units"]["items"].items():
        profile = next(p for p, v in rules["profiles"].items() if item in v["flag_bits"])
        t = next(f for f in index.files[profile_file(profile)]["seq"] if f["id"] == item).get("type")
        if t in PRIMITIVE_SIZES:  # a bare byte: the item is its own single field
            assert list(spec["fields"]) == [item]
            continue
        _, type_name, _ = _parse_type(t, profile_file(profile))
        ksy_fields = {f["id"] for f in index.files["osdk_broadcast_items"]["types"][type_name]["seq"]}
        for name in spec["fields"]:
            assert UNIT_ALIASES.get((item, name), {name}) <= ksy_fields, f"units.items.{item}.fields.{name}"


# ------------------------------------------------------------------ errata

REQUIRED_ERRATA_FIELDS = ("Status", "Sources", "Evidence", "Decision", "Spec", "Vectors")


def errata_entries() -> Iterator[tuple[str, str, str]]:
    """(id, title, body) of each '## Exx: title' section."""
    text = ERRATA_PATH.read_text(encoding="utf-8")
    parts = re.split(r"^## ", text, flags=re.M)
    for part in parts[1:]:
        head, _, body = part.partition("\n")
        m = re.fullmatch(r"(E\d\d): (.+)", head.strip())
        if m:
            yield m.group(1), m.group(2), body


ERRATA = list(errata_entries())


def _spec_refs(body: str) -> list[str]:
    m = re.search(r"^- \*\*Spec:\*\* (.+)$", body, flags=re.M)
    assert m, "no **Spec:** line"
    return re.findall(r"`([^`]+)`", m.group(1))


def test_errata_ids_are_numbered_from_e01_without_gaps() -> None:
    assert len(ERRATA) >= 30
    assert [eid for eid, _, _ in ERRATA] == [f"E{n:02d}" for n in range(1, len(ERRATA) + 1)]


@pytest.mark.parametrize(("eid", "title", "body"), ERRATA, ids=[e[0] for e in ERRATA])
def test_errata_entry_has_required_fields(eid: str, title: str, body: str) -> None:
    found = re.findall(r"^- \*\*(\w+):\*\*", body, flags=re.M)
    assert found == list(REQUIRED_ERRATA_FIELDS), f"{eid}: fields {found}"
    for name in REQUIRED_ERRATA_FIELDS:
        value = re.search(rf"^- \*\*{name}:\*\*(.*(?:\n  .*)*)", body, flags=re.M).group(1)
        assert value.strip(), f"{eid}: {name} is empty"
    assert re.search(r"^- \*\*Status:\*\* (decided|open|disputed)\b", body, flags=re.M), eid
    assert re.search(r"^  - (seed|sdk-doc|sdk-code|facts):", body, flags=re.M), f"{eid}: no source listed"


@pytest.mark.parametrize(("eid", "title", "body"), ERRATA, ids=[e[0] for e in ERRATA])
def test_errata_spec_references_resolve(eid: str, title: str, body: str) -> None:
    resolver = Resolver()
    refs = _spec_refs(body)
    assert refs, f"{eid}: Spec names nothing"
    for ref in refs:
        target, _, frag = ref.partition("#")
        assert target.endswith(".ksy") or target == "rules.yaml", f"{eid}: {ref} is not a ksy or rules reference"
        if target == "rules.yaml":
            # either a top-level key or a JSON pointer
            assert frag in resolver.rules or (frag.startswith("/") and _pointer(resolver.rules, frag)), f"{eid}: {ref}"
        else:
            assert ksy.load().element_exists(ref), f"{eid}: {ref}"


def _sources(node: Any) -> Iterator[str]:
    if isinstance(node, dict):
        for k, v in node.items():
            if isinstance(v, str) and k.endswith("source"):
                yield v
            else:
                yield from _sources(v)
    elif isinstance(node, list):
        for v in node:
            yield from _sources(v)


def _cited(text: str) -> set[str]:
    return {eid for group in re.findall(r"errata ((?:E\d\d(?:, )?)+)", text) for eid in re.findall(r"E\d\d", group)}


def test_rules_cite_only_existing_errata(rules: dict[str, Any]) -> None:
    known = {eid for eid, _, _ in ERRATA}
    cited = set().union(*(_cited(s) for s in _sources(rules)))
    assert cited - known == set()
    assert len(cited) >= 25


ERRATA_NAMING_RULES = [e for e in ERRATA if any(r.startswith("rules.yaml#") for r in _spec_refs(e[2]))]


@pytest.mark.parametrize(("eid", "title", "body"), ERRATA_NAMING_RULES, ids=[e[0] for e in ERRATA_NAMING_RULES])
def test_errata_naming_rules_are_cited_there(rules: dict[str, Any], eid: str, title: str, body: str) -> None:
    """An errata entry whose decision lives in rules.yaml is cited by a
    `source` inside one of the rules nodes its Spec line names."""
    nodes = [ref.partition("#")[2] for ref in _spec_refs(body) if ref.startswith("rules.yaml#")]
    hits = [n for n in nodes for s in _sources(_rules_node(rules, n.strip("/"))) if eid in _cited(s)]
    assert hits, f"{eid}: no source under {nodes} cites it"


def test_e15_is_data_in_rules(rules: dict[str, Any]) -> None:
    b0 = rules["control_mode"]["bit0_by_profile"]
    assert {p: b["meaning"] for p, b in b0.items()} == {
        "m100-fw2.3": "yaw_frame", "m100-fw3.1": "stable_mode", "a3-fw3.1": "stable_mode"}
    assert "E15" in _cited(b0["m100-fw2.3"]["source"])
    assert "E05" in _cited(rules["control_modes"]["combinations"][12]["source"])
    assert "E05" in _cited(rules["control_modes"]["seed_ranges"]["vert_thrust"]["source"])


# ------------------------------------------------- the comparisons bite


def test_enum_comparison_bites(rules: dict[str, Any], index: ksy.KsyIndex) -> None:
    bad = copy.deepcopy(rules)
    bad["frame"]["enc"]["values"][1]["name"] = "aes256_ecb"
    assert enum_mismatches(bad, index, "frame/enc") == ["frame/enc vs osdk_frame.ksy enum encryption: 1: 'aes256_ecb' / 'aes256'"]
    bad["enums"]["control_ack"]["values"].pop()
    assert enum_mismatches(bad, index, "enums/control_ack") == [
        "enums/control_ack vs osdk_payload.ksy enum control_ack: 201: None / 'in_ioc_mode'"]


def _ksy_copy(tmp_path: Path, edit: dict[str, tuple[str, str]]) -> ksy.KsyIndex:
    """An index of a copy of spec/*.ksy with text replaced in some files."""
    for path in SPEC.glob("*.ksy"):
        text = path.read_text(encoding="utf-8")
        if path.name in edit:
            old, new = edit[path.name]
            assert text.count(old) == 1, (path.name, old)
            text = text.replace(old, new)
        (tmp_path / path.name).write_text(text, encoding="utf-8")
    return ksy.load(tmp_path)


def test_size_comparison_bites(tmp_path: Path, rules: dict[str, Any]) -> None:
    # the gimbal limit byte grows by one bit: 9 bits no longer fill whole bytes
    index = _ksy_copy(tmp_path, {"osdk_broadcast_items.ksy": (
        "      - id: reserved\n        type: b5", "      - id: reserved\n        type: b6")})
    with pytest.raises(ksy.KsyError, match="whole bytes"):
        ksy_item_sizes(index, "a3-fw3.1")
    assert ksy_item_sizes(index, "m100-fw2.3")["gimbal"] == 12  # no limit byte on FW 2.3


def test_size_and_order_comparison_bite_on_a_changed_profile(tmp_path: Path, rules: dict[str, Any],
                                                            loaded: Rules) -> None:
    index = _ksy_copy(tmp_path, {"osdk_broadcast_m100_fw3_1.ksy": (
        "osdk_broadcast_items::time_stamp(true)", "osdk_broadcast_items::time_stamp(false)")})
    sizes = ksy_item_sizes(index, "m100-fw3.1")
    assert sizes["time_stamp"] == 4 != loaded.profile("m100-fw3.1").item_sizes["time_stamp"]
    flags, _ = _broadcast_items(index, "m100-fw3.1")
    assert flags == rules["profiles"]["m100-fw3.1"]["flag_bits"]
