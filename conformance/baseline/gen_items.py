"""Write the baseline's broadcast item table (items.h) from the spec.

The SDK compiles its item layout in; so does the baseline, but from the
spec (spec/rules.yaml: the broadcast items, each profile's items in flag-bit
order; their sizes, computed from the item layouts), so that it cannot drift
from it and a new item or profile needs no edit here or in baseline.c.

items.h holds `broadcast_t`, the latest value of every item any profile has,
each slot as large as the item's largest variant, and per profile the slot
and size of each flag bit's item.

    python gen_items.py OUT.h
"""
from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from osdk_conformance.core.rules import default_rules  # noqa: E402


def render() -> str:
    rules = default_rules()
    names = rules.profile_names
    profiles = [rules.profile(n) for n in names]
    width = max(len(p.flag_bits) for p in profiles)
    slots = {item: max(p.item_sizes.get(item, 0) for p in profiles) for item in rules.broadcast_item_names}
    slots = {item: size for item, size in slots.items() if size}  # an item no profile sends needs no slot
    lines = [
        "/* Generated from spec/ by conformance/baseline/gen_items.py. Do not edit. */",
        "#include <stddef.h>",
        "#include <stdint.h>",
        "",
        "#define PROFILE_COUNT %d" % len(profiles),
        "#define MAX_ITEMS %d" % width,
        "static const char *const PROFILE_IDS[PROFILE_COUNT] = {%s};" % ", ".join(f'"{n}"' for n in names),
        "static const unsigned ITEM_COUNT[PROFILE_COUNT] = {%s};" % ", ".join(str(len(p.flag_bits)) for p in profiles),
        "",
        "/* The latest value of every item (the SDK keeps one such struct); a slot",
        "   holds the item's largest variant. uint8_t arrays: no padding. */",
        "typedef struct {",
        *(f"    uint8_t {item}[{size}];" for item, size in slots.items()),
        "} broadcast_t;",
        "",
        "/* Per profile, items in flag-bit order: where each goes in broadcast_t, and its size. */",
        "#define AT(item) offsetof(broadcast_t, item)",
        "static const size_t ITEM_OFFSETS[PROFILE_COUNT][MAX_ITEMS] = {",
        *("    {%s}," % ", ".join(f"AT({i})" for i in p.flag_bits) for p in profiles),
        "};",
        "#undef AT",
        "static const unsigned ITEM_SIZES[PROFILE_COUNT][MAX_ITEMS] = {",
        *("    {%s}," % ", ".join(str(p.item_sizes[i]) for i in p.flag_bits) for p in profiles),
        "};",
    ]
    return "\n".join(lines) + "\n"


def main(out: str) -> int:
    Path(out).write_text(render())
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print("usage: gen_items.py OUT.h", file=sys.stderr)
        raise SystemExit(2)
    raise SystemExit(main(sys.argv[1]))
