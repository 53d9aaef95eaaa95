"""Loader and accessors for spec/rules.yaml.

spec/rules.yaml holds the protocol rules that the byte layout cannot say
(CRC parameters, frame constraints, wire profiles, frequency codes, the
control mode byte and its documented combinations, enums, bit fields,
plausibility bounds, units). This module reads it, validates it against
spec/rules.schema.json (JSON Schema draft 2020-12), cross-checks the parts
that refer to each other, and offers small typed accessors.

The size of each broadcast item in each profile is not written in the rules:
it is computed from the item's type in spec/osdk_broadcast_items.ksy with the
params the profile gives (`item_params`), through the ksy index
(osdk_conformance.core.ksy). The ksy is the layout's source of truth; the
Construct transcription (osdk_construct) stays an independent second copy
that the tests hold against these sizes, and core does not depend on it.

Every failure to load, and every lookup of something the rules do not
define, raises RulesError with a message that names the file and the path
of the offending entry.

    rules = load_rules()
    rules.classify_control_mode(0x4B, "a3-fw3.1")["classification"]  # "documented"
"""
from __future__ import annotations

import copy
import functools
import json
import operator
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from types import MappingProxyType
from typing import Any

import yaml

from osdk_conformance.core import ksy
from osdk_conformance.core.paths import ROOT, SPEC
from osdk_conformance.core.schema_check import SchemaCheck

DEFAULT_RULES_PATH = SPEC / "rules.yaml"
DEFAULT_SCHEMA_PATH = SPEC / "rules.schema.json"
ERRATA_PATH = SPEC / "ERRATA.md"
ITEMS_KSY_PATH = SPEC / "osdk_broadcast_items.ksy"
ITEMS_KSY_ID = "osdk_broadcast_items"
BARE_BYTE = "u1"  # the one broadcast item layout that is not a type of ITEMS_KSY_PATH

CLASSIFICATIONS = ("documented", "undocumented", "later_firmware", "invalid")
LOGIC_FIELDS = ("horizontal_logic", "vertical_logic", "yaw_logic")
AXIS_OF_FIELD = {"horizontal_logic": "horizontal", "vertical_logic": "vertical", "yaw_logic": "yaw"}
# Short forms used by the cur_mov_control_mode names (horiz_<h>_vert_<v>_yaw_<y>).
_SHORT = {
    "hori_atti_tilt_ang": "ang", "hori_vel": "vel", "hori_pos": "pos",
    "vert_vel": "vel", "vert_pos": "pos", "vert_thrust": "thr",
    "yaw_ang": "ang", "yaw_rate": "rate",
}
_STORAGE_MAX = {"u3": 7, "u8": 0xFF, "u16": 0xFFFF}
_MAX_REPORTED_ERRORS = 12


class RulesError(ValueError):
    """spec/rules.yaml could not be loaded, or a lookup asked for something it does not define."""


# --------------------------------------------------------------------------
# Typed views


@dataclass(frozen=True)
class CrcParams:
    """Rocksoft-style CRC parameter block (poly in normal form)."""

    name: str
    width: int
    poly: int
    reflect_in: bool
    reflect_out: bool
    init: int                     # as the sources state it; see init_form
    init_form: str                # "reflected_register" or "rocksoft"
    init_rocksoft: int            # the same init in Rocksoft/catalogue form
    xorout: int
    check: int
    residue: int
    stored: str
    covers: tuple[int, int]       # inclusive byte positions; negative = from frame end
    stored_at: tuple[int, int]


def ksy_name(profile_id: str) -> str:
    """A profile's name in the ksy files (enum `profile`, osdk_broadcast_<name>.ksy):
    the id with '-' and '.' written as '_' (rules.yaml frame.broadcast.profile_enum)."""
    return profile_id.replace("-", "_").replace(".", "_")


@dataclass(frozen=True)
class BroadcastItem:
    """One entry of rules.yaml `broadcast_items`."""

    name: str
    type: str                             # type in osdk_broadcast_items.ksy, or "u1"
    params: tuple[str, ...]               # ids of that type's params, in ksy order
    doc: str
    errata: tuple[str, ...]               # ERRATA.md entries that decide its size and fields


@dataclass(frozen=True)
class Profile:
    """One broadcast wire profile."""

    name: str
    value: int                            # u8 of enum `profile` (osdk_payload.ksy)
    description: str
    aircraft: tuple[str, ...]
    firmware: str
    sdk_version: int
    flag_bits: tuple[str, ...]            # index = flag bit
    item_params: Mapping[str, Mapping[str, bool | int]]  # parametric item -> its ksy params
    item_sizes: Mapping[str, int]         # in flag-bit order; computed from osdk_broadcast_items.ksy
    default_rates_hz: Mapping[str, int]   # in flag-bit order
    flight_status_enum: str               # "old" or "new"
    flight_status_overridable: bool
    flight_status_alternatives: tuple[str, ...]
    layout_note: str
    has_version_id: bool                  # version ACK carries the 11-byte version ID (ERRATA E30)
    version_name: str                     # what the FC answers a version query with, DJI's form (ERRATA E30)

    @property
    def ksy_name(self) -> str:
        return ksy_name(self.name)

    # The three variant sizes by name, until their last users read item_sizes.
    @property
    def time_stamp_size(self) -> int:
        return self._size("time_stamp")

    @property
    def gimbal_size(self) -> int:
        return self._size("gimbal")

    @property
    def control_info_size(self) -> int:
        return self._size("control_info")

    def _size(self, item: str) -> int:
        self.bit(item)  # RulesError naming the profile's items when it has no such item
        return self.item_sizes[item]

    def bit(self, item: str) -> int:
        """Flag bit of an item in this profile."""
        try:
            return self.flag_bits.index(item)
        except ValueError:
            raise RulesError(f"profile {self.name}: no item {item!r} (items: {', '.join(self.flag_bits)})") from None

    @property
    def all_flags(self) -> int:
        """Flag word with every item of this profile present."""
        return (1 << len(self.flag_bits)) - 1

    @property
    def full_payload_size(self) -> int:
        """Bytes of all items together (flag word not included)."""
        return sum(self.item_sizes.values())

    def payload_size(self, flags: int) -> int:
        """Bytes the items announced by `flags` occupy (flag word not included)."""
        if not 0 <= flags <= 0xFFFF or flags & ~self.all_flags:
            raise RulesError(f"profile {self.name}: flag word 0x{flags:04x} sets bits with no item")
        return sum(size for bit, size in enumerate(self.item_sizes.values()) if flags >> bit & 1)


# --------------------------------------------------------------------------
# YAML loading without silent duplicate keys


class _StrictLoader(ksy.SafeLoader):  # type: ignore[misc,valid-type]
    """SafeLoader that rejects a key written twice in one mapping."""


def _construct_mapping(loader: _StrictLoader, node: yaml.MappingNode, deep: bool = False) -> dict[Any, Any]:
    seen: dict[Any, yaml.Node] = {}
    for key_node, _ in node.value:
        if key_node.tag == "tag:yaml.org,2002:merge":
            continue
        key = loader.construct_object(key_node, deep=True)
        try:
            if key in seen:
                raise yaml.constructor.ConstructorError(
                    "while constructing a mapping", node.start_mark,
                    f"found duplicate key {key!r}", key_node.start_mark)
        except TypeError:
            continue  # unhashable keys are reported by the base constructor
        seen[key] = key_node
    loader.flatten_mapping(node)
    return ksy.SafeLoader.construct_mapping(loader, node, deep=deep)


_StrictLoader.add_constructor(yaml.resolver.BaseResolver.DEFAULT_MAPPING_TAG, _construct_mapping)


def _display(path: Path) -> str:
    try:
        return str(path.relative_to(ROOT))
    except ValueError:
        return str(path)


def _json_path(parts: Sequence[Any]) -> str:
    return ".".join(str(p) for p in parts) or "(top level)"


@functools.lru_cache(maxsize=4)
def _validator(schema_path: Path) -> SchemaCheck:
    try:
        schema = json.loads(schema_path.read_text(encoding="utf-8"))
    except OSError as exc:
        raise RulesError(f"cannot read rules schema {_display(schema_path)}: {exc.strerror or exc}") from None
    except json.JSONDecodeError as exc:
        raise RulesError(f"rules schema {_display(schema_path)} is not valid JSON: {exc}") from None
    check = SchemaCheck(schema)
    problem = check.schema_problem()
    if problem:
        raise RulesError(f"rules schema {_display(schema_path)} is not a valid draft 2020-12 schema: {problem}")
    return check


def _resolve(path: str | Path | None, default: Path) -> Path:
    if path is None:
        return default
    p = Path(path)
    return p if p.is_absolute() else ROOT / p


def load_rules(path: str | Path | None = None, schema_path: str | Path | None = None) -> Rules:
    """Read, validate and cross-check a rules file.

    `path` defaults to spec/rules.yaml; a relative path is taken relative
    to the repository root. `schema_path` defaults to spec/rules.schema.json.
    Raises RulesError on any problem.
    """
    rules_path = _resolve(path, DEFAULT_RULES_PATH)
    shown = _display(rules_path)
    try:
        text = rules_path.read_text(encoding="utf-8")
    except OSError as exc:
        raise RulesError(f"cannot read rules file {shown}: {exc.strerror or exc}") from None
    except UnicodeDecodeError as exc:
        raise RulesError(f"rules file {shown} is not UTF-8: {exc}") from None
    try:
        data = yaml.load(text, Loader=_StrictLoader)  # noqa: S506 - a SafeLoader subclass
    except yaml.YAMLError as exc:
        raise RulesError(f"rules file {shown} is not valid YAML: {exc}") from None
    if not isinstance(data, dict):
        raise RulesError(f"rules file {shown} must hold a mapping at the top level, found {type(data).__name__}")

    validator = _validator(_resolve(schema_path, DEFAULT_SCHEMA_PATH))
    errors = sorted(validator.iter_errors(data), key=lambda e: (list(map(str, e.absolute_path)), e.message))
    if errors:
        raise RulesError(_listing(f"rules file {shown} does not match the rules schema:",
                                  [f"{_json_path(e.absolute_path)}: {e.message}" for e in errors]))
    items_index = _items_index()
    problems = _cross_check(data)
    sizes, layout_problems = _broadcast_layout(data, items_index)
    problems += layout_problems
    problems += _errata_references(data)
    if problems:
        raise RulesError(_listing(f"rules file {shown} is inconsistent:", problems))
    return Rules(data, rules_path, sizes)


def _items_index() -> ksy.KsyIndex:
    # Only the item types: the profile ksy files are generated from the rules
    # and must not be needed to load them.
    try:
        return ksy.load_file(ITEMS_KSY_PATH)
    except (OSError, yaml.YAMLError, KeyError, TypeError) as exc:
        raise RulesError(f"cannot read the broadcast item types {_display(ITEMS_KSY_PATH)}: {exc}") from None


_ERRATA_HEADING = re.compile(r"^## (E\d+):", re.M)


def errata_ids(path: Path | None = None) -> set[str]:
    """The ids of the entries of spec/ERRATA.md (its "## Exx: ..." headings)."""
    path = path or ERRATA_PATH
    try:
        return set(_ERRATA_HEADING.findall(path.read_text(encoding="utf-8")))
    except OSError as exc:
        raise RulesError(f"cannot read the errata {_display(path)}: {exc.strerror or exc}") from None


def _errata_references(d: Mapping[str, Any]) -> list[str]:
    """Every errata id the rules list names an entry of ERRATA.md."""
    named = [(f"broadcast_items.{item}.errata", e)
             for item, spec in d["broadcast_items"].items() for e in spec.get("errata", [])]
    if not named:
        return []
    known = errata_ids()
    return [f"{where}: {e} is not an entry of {_display(ERRATA_PATH)}" for where, e in named if e not in known]


def _listing(title: str, problems: list[str]) -> str:
    lines = [f"  {p}" for p in problems[:_MAX_REPORTED_ERRORS]]
    if len(problems) > len(lines):
        lines.append(f"  ... and {len(problems) - len(lines)} more")
    return "\n".join([title, *lines])


# --------------------------------------------------------------------------
# Cross-checks the schema cannot express


_SIZE_CLAIM = re.compile(r"(\d+)-byte (\w+(?: \w+)?)")
_COUNT_CLAIM = re.compile(r"\b(\d+) items\b")


def _broadcast_layout(d: Mapping[str, Any], index: ksy.KsyIndex) -> tuple[dict[str, dict[str, int]], list[str]]:
    """The size of every item of every profile, from its ksy type and the
    profile's params, and the problems found on the way: an item type that
    osdk_broadcast_items.ksy lacks, params that are not its params (in its
    order) or of the wrong kind, and prose in `description` / `layout_note`
    whose "<n>-byte <item>" or "<n> items" disagrees with the layout."""
    out: list[str] = []
    types = index.files[ITEMS_KSY_ID].get("types") or {}
    usable: set[str] = set()
    for item, spec in d["broadcast_items"].items():
        where = f"broadcast_items.{item}"
        params = spec.get("params", [])
        if spec["type"] == BARE_BYTE:
            if params:
                out.append(f"{where}.params: a bare byte ({BARE_BYTE}) has no params")
            else:
                usable.add(item)
            continue
        if spec["type"] not in types:
            out.append(f"{where}.type: {spec['type']!r} is not a type of {ITEMS_KSY_ID}.ksy")
            continue
        declared = [q["id"] for q in types[spec["type"]].get("params") or []]
        if params != declared:
            out.append(f"{where}.params: {params}, but {ITEMS_KSY_ID}.ksy {spec['type']} has params {declared}")
            continue
        usable.add(item)

    sizes: dict[str, dict[str, int]] = {}
    for pname, p in d["profiles"].items():
        where = f"profiles.{pname}"
        sizes[pname] = {}
        for item in p["flag_bits"]:
            spec = d["broadcast_items"].get(item)
            if item not in usable or sorted(p["item_params"].get(item, {})) != sorted(spec.get("params", [])):
                continue  # reported by _cross_check or above
            if spec["type"] == BARE_BYTE:
                sizes[pname][item] = ksy.PRIMITIVE_SIZES[BARE_BYTE]
                continue
            given = p["item_params"].get(item, {})
            ksy_types = {q["id"]: q.get("type") for q in types[spec["type"]].get("params") or []}
            # a ksy bool param takes true/false, any other (u1, s2, ...) an integer
            wrong = [name for name, value in given.items() if isinstance(value, bool) != (ksy_types[name] == "bool")]
            if wrong:
                out.append(f"{where}.item_params.{item}: {', '.join(f'{n} must be {ksy_types[n]}' for n in wrong)}")
                continue
            try:
                sizes[pname][item] = index.type_size(ITEMS_KSY_ID, spec["type"], given)
            except ksy.KsyError as exc:
                out.append(f"{where}: the size of {item} cannot be worked out from {ITEMS_KSY_ID}.ksy: {exc}")
        if len(sizes[pname]) != len(p["flag_bits"]):
            continue
        phrases = {item.replace("_", " "): item for item in p["flag_bits"]}
        for key in ("description", "layout_note"):
            for m in _SIZE_CLAIM.finditer(p[key]):
                words = m.group(2).split(" ")
                item = phrases.get(" ".join(words)) or phrases.get(words[0])
                if item is None:
                    out.append(f"{where}.{key}: {m.group(0)!r} names no item of this profile")
                elif int(m.group(1)) != sizes[pname][item]:
                    out.append(f"{where}.{key}: says {m.group(0)!r}, but {item} is {sizes[pname][item]} bytes")
            for m in _COUNT_CLAIM.finditer(p[key]):
                if int(m.group(1)) != len(p["flag_bits"]):
                    out.append(f"{where}.{key}: says {m.group(0)!r}, but the profile has {len(p['flag_bits'])}")
    return sizes, out


def _reflect(value: int, bits: int) -> int:
    return int(f"{value:0{bits}b}"[::-1], 2)


def _field_mask(field: Mapping[str, Any]) -> int:
    return ((1 << field["width"]) - 1) << field["lsb"]


def _cross_check(d: Mapping[str, Any]) -> list[str]:
    out: list[str] = []

    # crc: parameters fit their width; the two spellings of init agree
    for name, c in d["crc"].items():
        top = (1 << c["width"]) - 1
        for key in ("poly", "init", "init_rocksoft", "xorout", "check", "residue"):
            if c[key] > top:
                out.append(f"crc.{name}.{key}: 0x{c[key]:x} does not fit in {c['width']} bits")
        reversed_init = _reflect(c["init"], c["width"]) if c["reflect_in"] else c["init"]
        expected = reversed_init if c["init_form"] == "reflected_register" else c["init"]
        if c["init_rocksoft"] != expected:
            out.append(f"crc.{name}.init_rocksoft: 0x{c['init_rocksoft']:x}, expected 0x{expected:x} "
                       f"for init 0x{c['init']:x} in {c['init_form']} form")

    # enums: unique values and names, values fit the storage
    enum_blocks = dict(d["enums"])
    enum_blocks.update({f"flight_status_{k}": v for k, v in d["flight_status"]["enums"].items()})
    for ename, block in enum_blocks.items():
        values = [v["value"] for v in block["values"]]
        names = [v["name"] for v in block["values"]]
        if len(set(values)) != len(values):
            out.append(f"enums.{ename}: duplicate values {sorted(v for v in set(values) if values.count(v) > 1)}")
        if len(set(names)) != len(names):
            out.append(f"enums.{ename}: duplicate names {sorted(n for n in set(names) if names.count(n) > 1)}")
        top = _STORAGE_MAX[block["storage"]]
        for v in values:
            if not 0 <= v <= top:
                out.append(f"enums.{ename}: value {v} does not fit {block['storage']}")

    # frequencies: codes match the frequency_code enum
    freq = d["frequencies"]
    code_names = {c["value"]: c["name"] for c in freq["codes"]}
    if code_names != {v["value"]: v["name"] for v in d["enums"]["frequency_code"]["values"]}:
        out.append("frequencies.codes: values/names differ from enums.frequency_code")
    in_scope_hz = {c["hz"] for c in freq["codes"] if c["availability"] == "all" and c["hz"] is not None}

    # profiles: values 0, 1, ... in file order (the ksy enum `profile`, and
    # every table indexed by profile value, follow it); distinct ksy names
    profiles = d["profiles"]
    values = [p["value"] for p in profiles.values()]
    if values != list(range(len(profiles))):
        out.append(f"profiles: values must be 0..{len(profiles) - 1} in file order, found {values}")
    names = [ksy_name(pname) for pname in profiles]
    if len(set(names)) != len(names):
        out.append(f"profiles: two ids give the same ksy name ({sorted(n for n in set(names) if names.count(n) > 1)})")
    items = d["broadcast_items"]
    for pname, p in profiles.items():
        where = f"profiles.{pname}"
        bits = p["flag_bits"]
        for item in bits:
            if item not in items:
                out.append(f"{where}.flag_bits: {item!r} is not in broadcast_items")
        if set(p["default_rates_hz"]) != set(bits):
            out.append(f"{where}.default_rates_hz: items {sorted(set(p['default_rates_hz']) ^ set(bits))} do not match flag_bits")
        for item in sorted(set(p["item_params"]) - set(bits)):
            out.append(f"{where}.item_params.{item}: not an item of this profile")
        for item in bits:
            if item not in items:
                continue
            want, given = items[item].get("params", []), p["item_params"].get(item, {})
            if sorted(given) != sorted(want):
                out.append(f"{where}.item_params.{item}: gives {sorted(given)}, broadcast_items.{item} has params {want}")
        for item, rate in p["default_rates_hz"].items():
            if rate["hz"] not in in_scope_hz:
                out.append(f"{where}.default_rates_hz.{item}: {rate['hz']} Hz has no frequency code in scope")
        fs = p["flight_status_enum"]
        if fs["default"] in fs.get("alternatives", []):
            out.append(f"{where}.flight_status_enum: default {fs['default']!r} repeated in alternatives")
        if not fs["overridable"] and fs.get("alternatives"):
            out.append(f"{where}.flight_status_enum: alternatives given but overridable is false")
        if len(bits) > freq["request"]["length"]:
            out.append(f"{where}.flag_bits: {len(bits)} items exceed the {freq['request']['length']}-byte frequency request")

    for item in items:
        if not any(item in p["flag_bits"] for p in profiles.values()):
            out.append(f"broadcast_items.{item}: no profile has this item")

    # every other mention of a profile or an item names a defined one
    known_items = set(items)
    for where, item in [("units.items", i) for i in d["units"]["items"]] + [
            (f"plausibility.{k}.item", v["item"]) for k, v in d["plausibility"].items() if isinstance(v, dict)] + [
            (f"plausibility.enum_membership[{n}].item", m["item"]) for n, m in enumerate(d["plausibility"]["enum_membership"])]:
        if item not in known_items:
            out.append(f"{where}: {item!r} is not in broadcast_items")
    known_profiles = set(profiles)
    mentions = [("gimbal_limit.applies_to_profiles", d["gimbal_limit"].get("applies_to_profiles", []))]
    mentions += [(f"units.items.{i}.fields.{f}.profiles", spec["profiles"])
                 for i, u in d["units"]["items"].items() for f, spec in u["fields"].items() if "profiles" in spec]
    for where, named in mentions:
        for pname in named:
            if pname not in known_profiles:
                out.append(f"{where}: {pname!r} is not a profile")
    cmodes_profiles = [("control_modes.profile_ranges", d["control_modes"]["profile_ranges"])]
    cmodes_profiles += [(f"control_modes.combinations[index {c['index']}].ranges", c["ranges"])
                        for c in d["control_modes"]["combinations"]]
    for where, by_profile in cmodes_profiles:
        if set(by_profile) != known_profiles:
            out.append(f"{where}: must name every profile once (differs in {sorted(set(by_profile) ^ known_profiles)})")

    # control mode byte fields: disjoint, cover the byte, every value classified once
    cm = d["control_mode"]
    fields = {f["name"]: f for f in cm["fields"]}
    if len(fields) != len(cm["fields"]):
        out.append("control_mode.fields: a field is listed twice")
    used = 0
    for f in cm["fields"]:
        mask = _field_mask(f)
        if mask > 0xFF:
            out.append(f"control_mode.fields.{f['name']}: bits run past bit 7")
        if used & mask:
            out.append(f"control_mode.fields.{f['name']}: overlaps another field")
        used |= mask
        defined = [v["value"] for v in f["values"]] + [u["value"] for u in f["undefined"]]
        if sorted(defined) != list(range(1 << f["width"])):
            out.append(f"control_mode.fields.{f['name']}: values and undefined must list 0..{(1 << f['width']) - 1} exactly once")
    if used != 0xFF:
        out.append(f"control_mode.fields: bits 0x{0xFF & ~used:02x} belong to no field")
    if set(cm["bit0_by_profile"]) != set(d["profiles"]):
        out.append(f"control_mode.bit0_by_profile: must name every profile once "
                   f"(differs in {sorted(set(cm['bit0_by_profile']) ^ set(d['profiles']))})")
    for pname, b0 in cm["bit0_by_profile"].items():
        if b0["meaning"] == "yaw_frame" and sorted(v["value"] for v in b0["values"]) != [0, 1]:
            out.append(f"control_mode.bit0_by_profile.{pname}.values: must name bit values 0 and 1")
    if set(cm["classification_precedence"]) != set(CLASSIFICATIONS):
        out.append("control_mode.classification_precedence: must list every classification once")
    for pre in cm["preconditions"]:
        f = fields.get(pre["applies_to"]["field"])
        if f is None or pre["applies_to"]["value"] not in {v["name"] for v in f["values"]}:
            out.append(f"control_mode.preconditions.{pre['id']}: applies_to names no value of {pre['applies_to']['field']}")
    if out:
        return out  # combination checks below rely on well-formed fields

    # combinations: consistent with the fields, the enum and the seed ranges
    cmodes = d["control_modes"]
    logic_mask = 0
    for name in LOGIC_FIELDS:
        logic_mask |= _field_mask(fields[name])
    cur_mov = {v["value"]: v["name"] for v in d["enums"]["cur_mov_control_mode"]["values"]}
    seen: dict[tuple[str, str, str], int] = {}
    entries = [("combinations", c) for c in cmodes["combinations"]] + [("undocumented", c) for c in cmodes["undocumented"]]
    for group, c in entries:
        where = f"control_modes.{group}[index {c['index']}]"
        key = (c["horizontal"], c["vertical"], c["yaw"])
        if key in seen:
            out.append(f"{where}: same logic as index {seen[key]}")
        seen[key] = c["index"]
        if c["mask"] != logic_mask:
            out.append(f"{where}: mask 0x{c['mask']:02x}, expected 0x{logic_mask:02x} (the logic bits)")
        expected_value = 0
        for fname, logic in zip(LOGIC_FIELDS, key):
            f = fields[fname]
            code = {v["name"]: v["value"] for v in f["values"]}.get(logic)
            if code is None:
                out.append(f"{where}: {logic!r} is not a value of {fname}")
                continue
            expected_value |= code << f["lsb"]
        if c["value"] != expected_value:
            out.append(f"{where}: value 0x{c['value']:02x}, expected 0x{expected_value:02x}")
        if c["pattern"] != f"0b{expected_value >> 3:05b}xxy":
            out.append(f"{where}: pattern {c['pattern']} does not match value 0x{expected_value:02x}")
        enum_name = "horiz_{}_vert_{}_yaw_{}".format(*(_SHORT[k] for k in key))
        if cur_mov.get(c["index"]) != enum_name:
            out.append(f"{where}: cur_mov_control_mode[{c['index']}] is {cur_mov.get(c['index'])!r}, expected {enum_name!r}")
        if group == "combinations":
            for prof, ranges in c["ranges"].items():
                if cmodes["profile_ranges"][prof] != "seed":
                    continue
                for fname, logic in zip(LOGIC_FIELDS, key):
                    axis = AXIS_OF_FIELD[fname]
                    if ranges[axis] != cmodes["seed_ranges"][logic]:
                        out.append(f"{where}.ranges.{prof}.{axis}: differs from seed_ranges.{logic}")
    documented = sorted(c["index"] for c in cmodes["combinations"])
    if documented != list(range(1, 15)):
        out.append(f"control_modes.combinations: indices must be 1..14, found {documented}")
    n_logic = 1
    for name in LOGIC_FIELDS:
        n_logic *= len(fields[name]["values"])
    if len(seen) != n_logic:
        out.append(f"control_modes: combinations and undocumented cover {len(seen)} of {n_logic} logic triples")

    # flight status transitions use the enum's names
    for which, t in d["flight_status"]["transitions"].items():
        names = {v["name"] for v in d["flight_status"]["enums"][which]["values"]}
        mentioned = {e["from"] for e in t["edges"]} | {e["to"] for e in t["edges"]}
        mentioned |= set(t["sequences"]["takeoff"]) | set(t["sequences"]["landing"])
        for n in sorted(mentioned - names):
            out.append(f"flight_status.transitions.{which}: {n!r} is not in the {which} enum")

    # bit fields: disjoint, inside the byte, enums exist
    for bname in ("device_byte", "velocity_status", "gimbal_limit"):
        used = 0
        for f in d[bname]["fields"]:
            mask = _field_mask(f)
            if mask >> d[bname]["width"] or used & mask:
                out.append(f"{bname}.{f['name']}: bits overlap or run past the byte")
            used |= mask
            if f["kind"] == "enum" and f["enum"] not in enum_blocks:
                out.append(f"{bname}.{f['name']}: unknown enum {f['enum']!r}")
        if used != (1 << d[bname]["width"]) - 1:
            out.append(f"{bname}: some bits belong to no field")

    for cname, ch in d["rc_channels"]["channels"].items():
        if ch["kind"] == "continuous" and ch["min"] >= ch["max"]:
            out.append(f"rc_channels.channels.{cname}: min must be below max")
    return out


# --------------------------------------------------------------------------
# The rules


_OPS = {"==": operator.eq, "!=": operator.ne, "<": operator.lt, "<=": operator.le, ">": operator.gt, ">=": operator.ge}


class Rules:
    """Validated content of a rules file, with typed accessors.

    `data` is the raw (validated) mapping; accessors return copies.
    """

    def __init__(self, data: dict[str, Any], path: Path, item_sizes: Mapping[str, Mapping[str, int]]) -> None:
        self.data = data
        self.path = path
        self._item_sizes = item_sizes
        cm = data["control_mode"]
        self._fields: dict[str, dict[str, Any]] = {f["name"]: f for f in cm["fields"]}
        self._severity = {c: i for i, c in enumerate(cm["classification_precedence"])}
        self._by_logic: dict[tuple[str, str, str], tuple[bool, dict[str, Any]]] = {}
        for c in data["control_modes"]["combinations"]:
            self._by_logic[(c["horizontal"], c["vertical"], c["yaw"])] = (True, c)
        for c in data["control_modes"]["undocumented"]:
            self._by_logic[(c["horizontal"], c["vertical"], c["yaw"])] = (False, c)
        self._combo_by_index = {c["index"]: (dc, c) for dc, c in self._by_logic.values()}

    # ---- names -----------------------------------------------------------

    @property
    def profile_names(self) -> tuple[str, ...]:
        """The profile ids in value order (the loader checks that file order is value order)."""
        return tuple(sorted(self.data["profiles"], key=lambda n: self.data["profiles"][n]["value"]))

    def _check_profile(self, name: str) -> dict[str, Any]:
        try:
            return self.data["profiles"][name]
        except (KeyError, TypeError):
            raise RulesError(f"unknown profile {name!r} (known: {', '.join(self.profile_names)})") from None

    # ---- CRC -------------------------------------------------------------

    def crc_params(self, name: str) -> CrcParams:
        """Parameters of "crc16" or "crc32"."""
        try:
            c = self.data["crc"][name]
        except (KeyError, TypeError):
            raise RulesError(f"unknown CRC {name!r} (known: {', '.join(self.data['crc'])})") from None
        return CrcParams(
            name=name, width=c["width"], poly=c["poly"], reflect_in=c["reflect_in"],
            reflect_out=c["reflect_out"], init=c["init"], init_form=c["init_form"],
            init_rocksoft=c["init_rocksoft"], xorout=c["xorout"], check=c["check"],
            residue=c["residue"], stored=c["stored"],
            covers=(c["covers"]["first_byte"], c["covers"]["last_byte"]),
            stored_at=(c["stored_at"]["first_byte"], c["stored_at"]["last_byte"]),
        )

    # ---- profiles --------------------------------------------------------

    def profile(self, name: str) -> Profile:
        """Bit order, item params and sizes, default rates and variants of one profile."""
        p = self._check_profile(name)
        bits = tuple(p["flag_bits"])
        fs = p["flight_status_enum"]
        return Profile(
            name=name,
            value=p["value"],
            description=p["description"],
            aircraft=tuple(p["covers"]["aircraft"]),
            firmware=p["covers"]["firmware"],
            sdk_version=p["covers"]["sdk_version"],
            flag_bits=bits,
            item_params=MappingProxyType({i: MappingProxyType(dict(p["item_params"][i]))
                                          for i in bits if i in p["item_params"]}),
            item_sizes=MappingProxyType({i: self._item_sizes[name][i] for i in bits}),
            default_rates_hz=MappingProxyType({i: p["default_rates_hz"][i]["hz"] for i in bits}),
            flight_status_enum=fs["default"],
            flight_status_overridable=fs["overridable"],
            flight_status_alternatives=tuple(fs.get("alternatives", ())),
            layout_note=p["layout_note"],
            has_version_id=p["version_ack"]["version_id"],
            version_name=p["version_ack"]["version_name"],
        )

    @property
    def broadcast_item_names(self) -> tuple[str, ...]:
        return tuple(self.data["broadcast_items"])

    def broadcast_item(self, name: str) -> BroadcastItem:
        """Layout type, params, doc and errata of one broadcast item."""
        try:
            b = self.data["broadcast_items"][name]
        except (KeyError, TypeError):
            raise RulesError(f"unknown broadcast item {name!r} (known: {', '.join(self.broadcast_item_names)})") from None
        return BroadcastItem(name=name, type=b["type"], params=tuple(b.get("params", ())), doc=b["doc"],
                             errata=tuple(b.get("errata", ())))

    # ---- enums -----------------------------------------------------------

    @property
    def enum_names(self) -> tuple[str, ...]:
        return (tuple(self.data["enums"])
                + ("profile",)
                + tuple(f"flight_status_{k}" for k in self.data["flight_status"]["enums"])
                + tuple(self._fields))

    def enum(self, name: str) -> dict[int, str]:
        """value -> name of an enum: those under `enums`, `profile` (made from
        the profiles' values and ksy names), flight_status_old /
        flight_status_new, and the control mode byte fields (horizontal_logic ...)."""
        if name == "profile":
            return {self.data["profiles"][n]["value"]: ksy_name(n) for n in self.profile_names}
        if name in self.data["enums"]:
            values = self.data["enums"][name]["values"]
        elif name.startswith("flight_status_") and name[len("flight_status_"):] in self.data["flight_status"]["enums"]:
            values = self.data["flight_status"]["enums"][name[len("flight_status_"):]]["values"]
        elif name in self._fields:
            values = self._fields[name]["values"]
        else:
            raise RulesError(f"unknown enum {name!r} (known: {', '.join(self.enum_names)})")
        return {v["value"]: v["name"] for v in values}

    def flight_status_enum(self, profile: str, override: str | None = None) -> dict[int, str]:
        """The flight status enum a profile uses, or an allowed override ("old"/"new")."""
        p = self.profile(profile)
        which = p.flight_status_enum if override is None else override
        if which != p.flight_status_enum and which not in p.flight_status_alternatives:
            raise RulesError(f"profile {profile} cannot use the {which!r} flight status enum")
        return self.enum(f"flight_status_{which}")

    def flight_status_enum_for(self, aircraft: str, firmware: str) -> str:
        """"old" or "new" for an aircraft and its firmware package version (seed table)."""
        try:
            version = tuple(int(x) for x in firmware.split("."))
        except ValueError:
            raise RulesError(f"firmware version {firmware!r} is not dotted numbers") from None
        for row in self.data["flight_status"]["compatibility"]:
            if row["aircraft"] != aircraft:
                continue
            fw = row["firmware"]
            if fw.get("all"):
                return row["enum"]
            bound = tuple(int(x) for x in (fw.get("below") or fw["at_least"]).split("."))
            if ("below" in fw and version < bound) or ("at_least" in fw and version >= bound):
                return row["enum"]
        raise RulesError(f"no flight status compatibility row for {aircraft} firmware {firmware}")

    # ---- control mode byte ----------------------------------------------

    def decode_control_mode(self, byte: int) -> dict[str, int]:
        """Raw value of each control mode field."""
        if not isinstance(byte, int) or not 0 <= byte <= 0xFF:
            raise RulesError(f"control mode byte must be an integer 0..255, got {byte!r}")
        return {name: byte >> f["lsb"] & ((1 << f["width"]) - 1) for name, f in self._fields.items()}

    def classify_control_mode(self, byte: int, profile: str) -> dict[str, Any]:
        """Classify one control mode byte for a profile.

        Returns {"byte", "profile", "raw": {field: int}, "fields": {field: name or None},
        "classification": documented|undocumented|later_firmware|invalid,
        "combination": index 1..14 when documented else None,
        "bit0": {"meaning": stable_mode|yaw_frame, "name": what bit 0 says on this profile},
        "reasons": [str], "preconditions": [precondition ids that apply]}.

        The byte layout names bit 0 `stable_mode` in every profile, but on
        m100-fw2.3 it selects the yaw frame (errata E15,
        rules.yaml control_mode.bit0_by_profile); there a yaw-angle byte with
        bit 0 set is classified `invalid`.
        """
        self._check_profile(profile)
        raw = self.decode_control_mode(byte)
        names = self._field_names(raw)
        found: list[tuple[str, str]] = []   # (classification, reason)
        for fname, value in raw.items():
            if names[fname] is None:
                f = self._fields[fname]
                u = next(u for u in f["undefined"] if u["value"] == value)
                found.append((u["classification"], f"{fname} 0b{value:0{f['width']}b}: {u['reason']}"))

        # Bit 0 is the stable flag on FW 3.1 but the yaw frame on FW 2.3 (errata E15).
        cm = self.data["control_mode"]
        bit0 = cm["bit0_by_profile"][profile]
        bit0_name = names["stable_mode"]
        if bit0["meaning"] == "yaw_frame":
            bit0_name = next(v["name"] for v in bit0["values"] if v["value"] == raw["stable_mode"])
            if names["yaw_logic"] == "yaw_ang" and raw["stable_mode"] != bit0["yaw_ang_requires"]:
                found.append((bit0["violation"]["classification"],
                              f"bit 0 = {raw['stable_mode']} (yaw frame {bit0_name}) with yaw angle: {bit0['violation']['reason']}"))

        combination: int | None = None
        logic = tuple(names[f] for f in LOGIC_FIELDS)
        if None not in logic:
            documented, c = self._by_logic[logic]  # type: ignore[index]
            label = "/".join(logic)  # type: ignore[arg-type]
            if documented:
                combination = c["index"]
                found.append(("documented", f"combination {c['index']} ({label}), {c['source']}"))
            else:
                found.append(("undocumented", f"{label} is not among the 14 documented combinations "
                                              f"(would be index {c['index']}); no input range is documented"))
        classification = min((cls for cls, _ in found), key=self._severity.__getitem__)
        if classification != "documented":
            combination = None
        reasons = [r for _, r in sorted(found, key=lambda cr: self._severity[cr[0]])]

        if bit0["meaning"] == "stable_mode":
            if names["stable_mode"] == "stable" and cm["stable_mode_scope"]["value"] == "horizontal_only":
                reasons.append("stable mode set: it affects horizontal control only")
        elif names["yaw_logic"] == "yaw_rate":
            reasons.append(f"bit 0 on {profile} is the yaw frame (errata E15): yaw rate in the {bit0_name} frame")
        if names["yaw_logic"] == "yaw_ang" and cm["yaw_angle_forces_ground_frame"]["value"]:
            reasons.append("yaw angle: the autopilot references yaw to the ground frame whatever the frame bits say")
        return {
            "byte": byte,
            "profile": profile,
            "raw": raw,
            "fields": names,
            "classification": classification,
            "combination": combination,
            "bit0": {"meaning": bit0["meaning"], "name": bit0_name},
            "reasons": reasons,
            "preconditions": [p["id"] for p in self._preconditions_for(names)],
        }

    def _field_names(self, raw: Mapping[str, int]) -> dict[str, str | None]:
        return {fname: next((v["name"] for v in self._fields[fname]["values"] if v["value"] == value), None)
                for fname, value in raw.items()}

    def _preconditions_for(self, names: Mapping[str, str | None]) -> list[dict[str, Any]]:
        return [p for p in self.data["control_mode"]["preconditions"]
                if names.get(p["applies_to"]["field"]) == p["applies_to"]["value"]]

    def evaluate_preconditions(self, byte: int, signals: Mapping[str, Any]) -> dict[str, bool | None]:
        """For each precondition that applies to `byte`: True when satisfied
        (requirement met / advisory not triggered), False when not, None when
        a needed signal is missing from `signals`."""
        names = self._field_names(self.decode_control_mode(byte))
        result: dict[str, bool | None] = {}
        for p in self._preconditions_for(names):
            dnf = p.get("functional_if_any") or p["discouraged_if_any"]
            holds = _eval_dnf(dnf, signals)
            if holds is None:
                result[p["id"]] = None
            else:
                result[p["id"]] = holds if p["kind"] == "requirement" else not holds
        return result

    def combination(self, index: int) -> dict[str, Any]:
        """A combination by index: 1..14 documented, 15..18 undocumented.
        The copy carries "documented": bool."""
        if index not in self._combo_by_index:
            raise RulesError(f"no control mode combination with index {index!r} (1..{max(self._combo_by_index)})")
        documented, c = self._combo_by_index[index]
        out = copy.deepcopy(c)
        out["documented"] = documented
        return out

    def input_ranges(self, byte: int, profile: str) -> dict[str, dict[str, Any]] | None:
        """{"vertical", "horizontal", "yaw"} -> {min, max, unit, ...} for a
        documented byte in a profile; None when the byte is not documented
        (no input range exists for it). min/max None mean unbounded."""
        cls = self.classify_control_mode(byte, profile)
        if cls["combination"] is None:
            return None
        return copy.deepcopy(self._combo_by_index[cls["combination"]][1]["ranges"][profile])

    # ---- frequencies -----------------------------------------------------

    def frequency_hz(self, code: int) -> int | None:
        """Hz of a frequency code (None for "keep"); RulesError for codes with no rate."""
        for c in self.data["frequencies"]["codes"]:
            if c["value"] == code:
                return c["hz"]
        raise RulesError(f"frequency code {code!r} has no rate (codes 0..7)")


def _eval_dnf(dnf: Sequence[Sequence[Mapping[str, Any]]], signals: Mapping[str, Any]) -> bool | None:
    unknown = False
    for conj in dnf:
        value: bool | None = True
        for cond in conj:
            if cond["signal"] not in signals:
                value = None if value is not False else False
                continue
            if not _OPS[cond["op"]](signals[cond["signal"]], cond["value"]):
                value = False
        if value is True:
            return True
        unknown = unknown or value is None
    return None if unknown else False


# --------------------------------------------------------------------------
# Module-level shortcuts over the default rules file


@functools.lru_cache(maxsize=1)
def default_rules() -> Rules:
    """spec/rules.yaml, loaded once."""
    return load_rules()


def classify_control_mode(byte: int, profile: str) -> dict[str, Any]:
    return default_rules().classify_control_mode(byte, profile)


def input_ranges(byte: int, profile: str) -> dict[str, dict[str, Any]] | None:
    return default_rules().input_ranges(byte, profile)


def combination(index: int) -> dict[str, Any]:
    return default_rules().combination(index)


def profile(name: str) -> Profile:
    return default_rules().profile(name)


def profile_names() -> tuple[str, ...]:
    """The profile ids of spec/rules.yaml in value order."""
    return default_rules().profile_names


def broadcast_item(name: str) -> BroadcastItem:
    return default_rules().broadcast_item(name)


def enum(name: str) -> dict[int, str]:
    return default_rules().enum(name)


def hz_of_code() -> dict[int, int]:
    """Frequency code -> Hz for the codes that set a rate (not "keep", not the
    later SDKs' codes): what the set-frequency command's bytes mean."""
    codes = default_rules().data["frequencies"]["codes"]
    return {c["value"]: c["hz"] for c in codes if c["hz"] is not None and c.get("availability") == "all"}


def crc_params(name: str) -> CrcParams:
    return default_rules().crc_params(name)
