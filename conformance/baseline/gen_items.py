"""Write the baseline's broadcast item table (items.h) from spec/rules.yaml.

The SDK compiles its item sizes in; so does the baseline, but from the
spec's own numbers, so that it cannot drift from them.

    python gen_items.py OUT.h
"""
from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from osdk_conformance.rules import default_rules  # noqa: E402


def main(out: str) -> int:
    rules = default_rules()
    names = rules.profile_names
    profiles = [rules.profile(n) for n in names]
    width = max(len(p.flag_bits) for p in profiles)
    lines = [
        "/* Generated from spec/rules.yaml by conformance/baseline/gen_items.py. Do not edit. */",
        "#define PROFILE_COUNT %d" % len(profiles),
        "#define MAX_ITEMS %d" % width,
        "static const char *const PROFILE_IDS[PROFILE_COUNT] = {%s};" % ", ".join(f'"{n}"' for n in names),
        "static const unsigned ITEM_COUNT[PROFILE_COUNT] = {%s};" % ", ".join(str(len(p.flag_bits)) for p in profiles),
        "/* items in flag-bit order */",
        "static const char *const ITEM_NAMES[PROFILE_COUNT][MAX_ITEMS] = {",
        *("    {%s}," % ", ".join(f'"{i}"' for i in p.flag_bits) for p in profiles),
        "};",
        "static const unsigned ITEM_SIZES[PROFILE_COUNT][MAX_ITEMS] = {",
        *("    {%s}," % ", ".join(str(s) for s in p.item_sizes.values()) for p in profiles),
        "};",
    ]
    Path(out).write_text("\n".join(lines) + "\n")
    return 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        print("usage: gen_items.py OUT.h", file=sys.stderr)
        raise SystemExit(2)
    raise SystemExit(main(sys.argv[1]))
