#!/usr/bin/env python3
"""Write the profile-dependent parts of spec/ from spec/rules.yaml.

usage: tools/gen_profile_ksy.py [--check]

rules.yaml `profiles` and `broadcast_items` are the one definition of how
each wire profile composes the flight data broadcast. From them this tool
writes:

- spec/osdk_broadcast_<profile>.ksy, one per profile: the u2 flag word (a
  `has_<item>` bit per item in flag-bit order, the rest `reserved_flags`,
  valid 0), then each item of the profile as its type in
  osdk_broadcast_items.ksy with the profile's `item_params` (or u1), then
  `trailing`, which must be empty. Each file says it is generated.
- in spec/osdk_payload.ksy, which is otherwise hand-written, the parts that
  list the profiles: the imports of the profile files, the cases of the
  broadcast's `switch-on: profile`, the enum `profile` (profile values
  and ksy names), and the `value` of version_ack_value's `has_version_id`
  from each profile's `version_ack.version_id` (ERRATA E30). Each part sits
  between a line
  `# --- generated from rules.yaml profiles by tools/gen_profile_ksy.py (<part>): do not edit ---`
  and a line `# --- end generated ---`, indented as its content.

Profile files that this tool wrote for a profile no longer in the rules are
removed. tools/regen.py runs this first (and --check with its own --check),
so the Kaitai compiler always sees current files.

--check changes nothing and fails (exit 1) when a file differs from what the
rules give.
"""
from __future__ import annotations

import argparse
import json
import re
import sys
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from osdk_conformance.core.rules import ITEMS_KSY_ID, Profile, Rules, load_rules  # noqa: E402

SPEC = ROOT / "spec"
PAYLOAD = SPEC / "osdk_payload.ksy"
TOOL = "tools/gen_profile_ksy.py"
FILE_MARK = f"# Generated from spec/rules.yaml (profiles, broadcast_items) by {TOOL}: do not edit."
REGION = re.compile(
    r"^(?P<indent>[ ]*)# --- generated from rules\.yaml profiles by tools/gen_profile_ksy\.py "
    r"\((?P<part>[a-z ]+)\): do not edit ---\n(?P<body>.*?)^(?P=indent)# --- end generated ---$",
    re.M | re.S)
# The implementation every profile's item sizes and field semantics follow.
SDK_REF = "https://github.com/dji-sdk/Onboard-SDK/blob/3.1.9/osdk-core/src/DJI_App.cpp"


def profile_file(p: Profile) -> Path:
    return SPEC / f"osdk_broadcast_{p.ksy_name}.ksy"


def _scalar(text: str) -> str:
    """`text` as a YAML scalar on one line: plain when YAML reads it back
    unchanged, else double-quoted."""
    try:
        plain = yaml.safe_load(f"k: {text}") == {"k": text}
    except yaml.YAMLError:
        plain = False
    return text if plain else json.dumps(text)


def _ksy_literal(value: bool | int) -> str:
    return ("true" if value else "false") if isinstance(value, bool) else str(value)


def _firmware(p: Profile) -> str:
    """major.minor of the SDK version word the profile activates with (0x03010A00 -> 3.1)."""
    return f"{p.sdk_version >> 24}.{p.sdk_version >> 16 & 0xFF}"


def application(p: Profile) -> str:
    """Who speaks the profile: "A3, N3 and M600 with firmware 3.1"."""
    names = list(p.aircraft)
    who = names[0] if len(names) == 1 else f"{', '.join(names[:-1])} and {names[-1]}"
    return f"{who} with firmware {_firmware(p)}"


def _item_type(rules: Rules, p: Profile, item: str) -> str:
    b = rules.broadcast_item(item)
    if b.type == "u1":
        return b.type
    args = p.item_params.get(item, {})
    call = f"({', '.join(_ksy_literal(args[name]) for name in b.params)})" if b.params else ""
    return f"{ITEMS_KSY_ID}::{b.type}{call}"


def _reserved_doc(first: int) -> str:
    if first == 15:
        return "Flag bit 15 carries no item in this profile and must be 0."
    return f"Flag bits {first}-15 carry no item in this profile and must be 0."


def profile_ksy(rules: Rules, name: str) -> str:
    """The text of spec/osdk_broadcast_<profile>.ksy."""
    p = rules.profile(name)
    bc = rules.data["frame"]["broadcast"]
    app = application(p)
    osdk = f"{app} (OSDK {_firmware(p)})"
    lines = [
        FILE_MARK,
        "meta:",
        f"  id: osdk_broadcast_{p.ksy_name}",
        f"  title: {_scalar(f'DJI Onboard SDK OPEN protocol - flight data broadcast, profile {p.name}')}",
        f"  application: {_scalar(osdk)}",
        "  license: CC0-1.0",
        "  ks-version: '0.11'",
        "  endian: le",
        "  bit-endian: le",
        "  imports:",
        f"    - {ITEMS_KSY_ID}",
        "doc: |",
        f"  Payload of the flight data broadcast (command set 0x{bc['cmd_set']:02x}, id 0x{bc['cmd_id']:02x}) as sent",
        f"  by {osdk}. A u2 flag word says which items follow; the items follow in",
        "  flag-bit order, each only when its bit is set. This profile uses",
        f"  {p.layout_note}.",
        "  A flag word that promises more bytes than the payload holds is an error",
        "  (the DJI SDK reads past the end instead; spec/ERRATA.md E25), and so are set",
        "  reserved flag bits and bytes left over after the last item.",
        "doc-ref:",
        f"  - osdk-conformance shared/reference/PROTOCOL-FACTS.md section 3 (profile {p.name})",
        f"  - {SDK_REF}",
        "seq:",
    ]
    for bit, item in enumerate(p.flag_bits):
        words = item.replace("_", " ")
        lines += [
            f"  - id: has_{item}",
            "    type: b1",
            f"    doc: {_scalar(f'Flag bit {bit}, the {words} item is present.')}",
        ]
    if len(p.flag_bits) < 16:
        lines += [
            "  - id: reserved_flags",
            f"    type: b{16 - len(p.flag_bits)}",
            # Kaitai reads a b1 as a boolean, wider bit fields as integers
            f"    valid: {'false' if len(p.flag_bits) == 15 else 0}",
            f"    doc: {_reserved_doc(len(p.flag_bits))}",
        ]
    for item in p.flag_bits:
        lines += [
            f"  - id: {item}",
            f"    type: {_item_type(rules, p, item)}",
            f"    if: has_{item}",
            f"    doc: {_scalar(rules.broadcast_item(item).doc)}",
        ]
    lines += [
        "  - id: trailing",
        "    size-eos: true",
        "    valid:",
        "      expr: _.length == 0",
        "    doc: Bytes after the last present item; a conforming payload has none.",
    ]
    return "\n".join(lines) + "\n"


def has_version_id_expr(profiles: list[Profile]) -> str:
    """The ksy expression of `has_version_id`: the param `profile` is none of
    the profiles whose version ACK lacks the ID (`true` when every profile
    has it). Written as the exceptions so that a profile value outside the
    enum reads the ID, as FW 3.1 and later firmware send it."""
    without = [f"profile != profile::{p.ksy_name}" for p in profiles if not p.has_version_id]
    return " and ".join(without) or "true"


def payload_parts(rules: Rules) -> dict[str, list[str]]:
    """The generated parts of osdk_payload.ksy, by part name, as lines
    without their indentation (the marker line gives it)."""
    profiles = [rules.profile(n) for n in rules.profile_names]
    enum = ["profile:"]
    for p in profiles:
        enum += [f"  {p.value}:", f"    id: {p.ksy_name}", f"    doc: {_scalar(f'{p.name}, {application(p)}.')}"]
    return {
        "imports": [f"- osdk_broadcast_{p.ksy_name}" for p in profiles],
        "broadcast cases": [f"profile::{p.ksy_name}: osdk_broadcast_{p.ksy_name}" for p in profiles],
        "profile enum": enum,
        "version id": [f"value: {_scalar(has_version_id_expr(profiles))}"],
    }


def fill_regions(text: str, parts: dict[str, list[str]], where: str) -> str:
    """`text` with the body of each marked region replaced by its part."""
    found: list[str] = []

    def body(m: re.Match[str]) -> str:
        part, indent = m.group("part"), m.group("indent")
        if part not in parts:
            raise SystemExit(f"gen_profile_ksy: {where} has a generated part {part!r} this tool does not know")
        found.append(part)
        head = m.group(0).split("\n", 1)[0]
        return "\n".join([head, *(indent + line for line in parts[part]), f"{indent}# --- end generated ---"])

    out = REGION.sub(body, text)
    missing = sorted(set(parts) - set(found))
    duplicated = sorted({p for p in found if found.count(p) > 1})
    if missing or duplicated:
        raise SystemExit(f"gen_profile_ksy: {where} must mark each of {sorted(parts)} once "
                         f"(missing {missing}, repeated {duplicated})")
    return out


def outputs(rules: Rules | None = None) -> dict[Path, str | None]:
    """Every file this tool owns and what it must hold; None: the file must not exist."""
    rules = rules or load_rules()
    want: dict[Path, str | None] = {}
    for name in rules.profile_names:
        want[profile_file(rules.profile(name))] = profile_ksy(rules, name)
    for path in sorted(SPEC.glob("osdk_broadcast_*.ksy")):
        if path not in want and path.read_text(encoding="utf-8").startswith(FILE_MARK):
            want[path] = None
    want[PAYLOAD] = fill_regions(PAYLOAD.read_text(encoding="utf-8"), payload_parts(rules), PAYLOAD.name)
    return want


def drift(want: dict[Path, str | None] | None = None) -> list[str]:
    """What differs between spec/ and the rules; empty when spec/ is current."""
    out = []
    for path, text in (want or outputs()).items():
        rel = path.relative_to(ROOT)
        if text is None:
            out.append(f"{rel} is generated for a profile that rules.yaml no longer has")
        elif not path.exists():
            out.append(f"{rel} is missing")
        elif path.read_text(encoding="utf-8") != text:
            out.append(f"{rel} differs from what rules.yaml gives")
    return out


def write(want: dict[Path, str | None] | None = None) -> list[Path]:
    """Bring spec/ up to date; the paths written or removed."""
    changed = []
    for path, text in (want or outputs()).items():
        if text is None:
            path.unlink()
            changed.append(path)
        elif not path.exists() or path.read_text(encoding="utf-8") != text:
            path.write_text(text, encoding="utf-8")
            changed.append(path)
    return changed


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--check", action="store_true", help="fail if spec/ is not what rules.yaml gives")
    args = ap.parse_args(argv)
    if args.check:
        problems = drift()
        for d in problems:
            print(f"gen_profile_ksy: {d} (run tools/gen_profile_ksy.py or `make regen`)", file=sys.stderr)
        if not problems:
            print("gen_profile_ksy: spec/ matches rules.yaml")
        return 1 if problems else 0
    for path in write():
        print(f"gen_profile_ksy: wrote {path.relative_to(ROOT)}" if path.exists() else
              f"gen_profile_ksy: removed {path.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
