"""The three places the spec states the same fact must agree.

spec/*.ksy (byte layout), spec/rules.yaml (rules the layout cannot say) and
spec/ERRATA.md (decisions where sources disagree) name the same enums, bit
orders, item sizes and bit fields. These tests read each file on its own
terms (the ksy through osdk_conformance.ksy, the rules as plain YAML) and
compare, so a change in one that is not made in the others fails here.
"""
from __future__ import annotations

import copy
import re
from pathlib import Path
from typing import Any, Iterator

import pytest
import yaml

from osdk_conformance import ksy
from osdk_conformance.trace import Resolver, _pointer

ROOT = Path(__file__).resolve().parents[1]
SPEC = ROOT / "spec"
RULES_PATH = SPEC / "rules.yaml"
ERRATA_PATH = SPEC / "ERRATA.md"
PROFILES = ("m100-fw2.3", "m100-fw3.1", "a3-fw3.1")

PRIMITIVE_SIZES = {"u1": 1, "s1": 1, "u2": 2, "s2": 2, "u4": 4, "s4": 4, "f4": 4, "u8": 8, "s8": 8, "f8": 8}


@pytest.fixture(scope="module")
def rules() -> dict[str, Any]:
    return yaml.safe_load(RULES_PATH.read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def index() -> ksy.KsyIndex:
    return ksy.load()


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
    "enums/profile": ("osdk_payload", "profile"),
    "control_mode/fields/0": ("osdk_control_mode", "horizontal_logic"),
    "control_mode/fields/1": ("osdk_control_mode", "vertical_logic"),
    "control_mode/fields/2": ("osdk_control_mode", "yaw_logic"),
    "control_mode/fields/3": ("osdk_control_mode", "horizontal_frame"),
    "control_mode/fields/4": ("osdk_control_mode", "stable_mode"),
    "frame/enc": ("osdk_frame", "encryption"),
}
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
    compared = set(SHARED_ENUMS.values())
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
    assert index.enums[("osdk_payload", "profile")] == {n: p.replace("-", "_").replace(".", "_") for n, p in enumerate(ids)}
    # the payload's broadcast switch sends each profile to its own ksy
    cases = index.files["osdk_payload"]["types"]["broadcast"]["seq"][0]["type"]["cases"]
    assert cases == {f"profile::{profile_file(p)[len('osdk_broadcast_'):]}": profile_file(p) for p in ids}


# ------------------------------------------------------ sizes from the ksy


def _parse_type(ref: str, file_id: str) -> tuple[str, str, list[str]]:
    m = re.fullmatch(r"(?:(\w+)::)?(\w+)(?:\((.*)\))?", ref)
    assert m, ref
    args = [a.strip() for a in m.group(3).split(",")] if m.group(3) else []
    return m.group(1) or file_id, m.group(2), args


def _literal(text: str) -> bool | str:
    """A type argument: a boolean literal, or an enum literal kept as its text."""
    if text in ("true", "false"):
        return text == "true"
    assert re.fullmatch(r"\w+::\w+", text), f"only boolean and enum literal arguments are supported, got {text!r}"
    return text


def _instance_flags(body: dict[str, Any], env: dict[str, Any]) -> dict[str, bool]:
    """The type's boolean instances of the form `param == enum::x` or `param != enum::x`."""
    out = {}
    for name, inst in body.get("instances", {}).items():
        m = re.fullmatch(r"(\w+) (==|!=) (\w+::\w+)", str(inst.get("value", "")))
        if m and m.group(1) in env:
            out[name] = (env[m.group(1)] == m.group(3)) == (m.group(2) == "==")
    return out


def type_size(index: ksy.KsyIndex, file_id: str, type_name: str, args: list[str]) -> int:
    """Bytes of a ksy user type whose size is fixed once its params are known.
    The type is one of the file's `types`, or an imported file's top-level type."""
    local = index.files[file_id].get("types", {})
    if type_name in local:
        body = local[type_name]
    else:
        assert type_name in index.files[file_id]["meta"].get("imports", []), f"{file_id}: unknown type {type_name}"
        file_id, body = type_name, index.files[type_name]
    params = [p["id"] for p in body.get("params", [])]
    assert len(params) == len(args), f"{file_id}::{type_name} takes {params}, got {args}"
    env = {p: _literal(a) for p, a in zip(params, args)}
    return seq_size(index, file_id, body["seq"], {**env, **_instance_flags(body, env)})


def field_size(index: ksy.KsyIndex, file_id: str, f: dict[str, Any], env: dict[str, Any]) -> tuple[int, int]:
    """(bytes, bits) one seq entry occupies; 0 when its `if` is false."""
    cond = f.get("if")
    if cond is not None:
        assert cond in env, f"{f['id']}: condition {cond!r} is not a known boolean"
        if not env[cond]:
            return 0, 0
    t = f.get("type")
    if isinstance(t, str) and re.fullmatch(r"b\d+", t):
        return 0, int(t[1:])
    if "size" in f:
        assert isinstance(f["size"], int), f"{f['id']}: size {f['size']!r} is not fixed"
        return f["size"], 0
    assert isinstance(t, str), f"{f['id']}: no fixed size"
    if t in PRIMITIVE_SIZES:
        return PRIMITIVE_SIZES[t], 0
    return type_size(index, *_parse_type(t, file_id)), 0


def seq_size(index: ksy.KsyIndex, file_id: str, seq: list[dict[str, Any]], env: dict[str, Any]) -> int:
    total, bits = 0, 0
    for f in seq:
        nbytes, nbits = field_size(index, file_id, f, env)
        if nbits:
            bits += nbits
            continue
        if nbytes:
            assert bits % 8 == 0, f"{f['id']}: bit fields before it do not fill whole bytes"
            total, bits = total + bits // 8, 0
        total += nbytes
    assert bits % 8 == 0, "trailing bit fields do not fill whole bytes"
    return total + bits // 8


def test_size_calculator_on_known_types(index: ksy.KsyIndex) -> None:
    it = "osdk_broadcast_items"
    assert type_size(index, it, "time_stamp", ["false"]) == 4
    assert type_size(index, it, "time_stamp", ["true"]) == 9
    assert type_size(index, it, "gimbal", ["false"]) == 12
    assert type_size(index, it, "gimbal", ["true"]) == 13
    assert type_size(index, it, "control_info", ["false"]) == 1
    assert type_size(index, it, "control_info", ["true"]) == 2
    assert type_size(index, it, "velocity", []) == 13
    assert type_size(index, it, "rtk_detail", []) == 44
    assert type_size(index, "osdk_payload", "version_ack_value", ["profile::m100_fw2_3"]) == 38   # E30
    assert type_size(index, "osdk_payload", "version_ack_value", ["profile::m100_fw3_1"]) == 49
    assert type_size(index, "osdk_payload", "version_ack_value", ["profile::a3_fw3_1"]) == 49
    assert type_size(index, "osdk_payload", "activation_request", []) == 44
    assert seq_size(index, "osdk_movement_control", index.files["osdk_movement_control"]["seq"], {}) == 17


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
    return {f["id"]: field_size(index, profile_file(profile), {**f, "if": None}, {})[0] for f in items}


@pytest.mark.parametrize("profile", PROFILES)
def test_item_sizes_match_ksy(rules: dict[str, Any], index: ksy.KsyIndex, profile: str) -> None:
    from_ksy = ksy_item_sizes(index, profile)
    p = rules["profiles"][profile]
    assert from_ksy == p["item_sizes"]
    assert (from_ksy["time_stamp"], from_ksy["gimbal"], from_ksy["control_info"]) == (
        p["time_stamp_size"], p["gimbal_size"], p["control_info_size"])


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
    a3 = {f["id"]: f for f in index.files[profile_file("a3-fw3.1")]["seq"]}
    assert set(rules["units"]["items"]) == set(rules["profiles"]["a3-fw3.1"]["flag_bits"])
    for item, spec in rules["units"]["items"].items():
        t = a3[item].get("type")
        if t in PRIMITIVE_SIZES:  # a bare byte: the item is its own single field
            assert list(spec["fields"]) == [item]
            continue
        _, type_name, _ = _parse_type(t, "osdk_broadcast_a3_fw3_1")
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
    with pytest.raises(AssertionError, match="whole bytes"):
        ksy_item_sizes(index, "a3-fw3.1")
    assert ksy_item_sizes(index, "m100-fw2.3")["gimbal"] == 12  # no limit byte on FW 2.3


def test_size_and_order_comparison_bite_on_a_changed_profile(tmp_path: Path, rules: dict[str, Any]) -> None:
    index = _ksy_copy(tmp_path, {"osdk_broadcast_m100_fw3_1.ksy": (
        "osdk_broadcast_items::time_stamp(true)", "osdk_broadcast_items::time_stamp(false)")})
    sizes = ksy_item_sizes(index, "m100-fw3.1")
    assert sizes["time_stamp"] == 4 != rules["profiles"]["m100-fw3.1"]["item_sizes"]["time_stamp"]
    flags, _ = _broadcast_items(index, "m100-fw3.1")
    assert flags == rules["profiles"]["m100-fw3.1"]["flag_bits"]
