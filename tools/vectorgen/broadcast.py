"""broadcast.json: decode_payload of the flight data broadcast (set 0x02,
id 0x00) in every profile. The items, their bits and variants come from
the layout (broadcast_values); the ERRATA entries that decide each item from
rules.yaml `broadcast_items.<item>.errata`."""
from __future__ import annotations

from osdk_conformance.core.rules import broadcast_item
from osdk_conformance.core.rules import profile as rules_profile

from .broadcast_errata import DOC_2X_PROFILE, add_broadcast_errata
from .broadcast_values import Values, bc_input, float_items, has_field, payload
from .builder import PROFILES, GenerationError, R, Suite
from .scalars import F32_SPECIALS, F64_SPECIALS, le16

OP = "decode_payload"

FULL_FLAG_WORDS = 1 << 12
"""A profile with at most this many flag words decodes every one validly
in broadcast.json; a larger one (a3-fw3.1: 16,384) only a sample of them,
for the size of the file (see add_flag_words)."""

VALID_SAMPLE_EVERY = 16
"""In a profile with more than FULL_FLAG_WORDS flag words, about one flag
word in this many (seeded sample) decodes validly besides those with <= 2
or all but <= 2 items; the others appear one byte short."""


def gen_broadcast() -> Suite:
    s = Suite("broadcast", "decode_payload of the flight data broadcast (set 0x02, id 0x00) in each profile: "
                           "every single item, every flag word, all-items payloads, special floats, truncated and "
                           "long payloads, reserved flag bits, and the errata decisions about items.", seed=303)
    for profile in PROFILES:
        add_single_items(s, profile)
        add_all_items(s, profile)
        add_special_floats(s, profile)
        add_flag_word_bounds(s, profile)
        add_reserved_flags(s, profile)
        add_broadcast_errata(s, profile)
    for profile in PROFILES:
        add_flag_words(s, profile)
    return s


def single_item_flags(profile: str, item: str) -> list[str]:
    flags = R(f"broadcast.flag_order.{profile}", "broadcast.item_sizes", "broadcast.item_fields")
    flags += broadcast_item(item).errata  # an item with none is flagged by its rules alone
    if has_field(profile, item, "cur_mov_control_mode"):
        flags += ["E02"]  # the mode enum the seed garbled
    if profile == DOC_2X_PROFILE:
        # its short time stamp is one of the forms the SDK tells apart only by version strings
        flags += ["E27"] + (["E28"] if item == "time_stamp" else [])
    return flags


def add_single_items(s: Suite, profile: str) -> None:
    """Each item alone with random values, then one byte short, without its
    bytes, and with one byte too many."""
    p = rules_profile(profile)
    pid = f"broadcast.{profile}"
    for bit, item in enumerate(p.flag_bits):
        data = payload(profile, 1 << bit, Values(s.rng))
        if len(data) != 2 + p.item_sizes[item]:  # the Construct layout and the ksy sizes (rules.py) disagree
            raise GenerationError(f"{profile} {item}: packed {len(data) - 2} bytes, the profile says "
                                  f"{p.item_sizes[item]}")
        s.add(OP, profile, f"{pid}.single.{item}", "broadcast.single_item",
              f"only {item} (flag bit {bit}, {p.item_sizes[item]} bytes in {profile}), random values",
              bc_input(data), single_item_flags(profile, item))
        s.add(OP, profile, f"{pid}.truncated.{item}.short_by_1", "broadcast.bounds",
              f"flag bit {bit} ({item}) set, the item one byte short: truncated_payload",
              bc_input(data[:-1]), R(f"broadcast.flag_order.{profile}", "broadcast.bounds") + ["E25"],
              error="truncated_payload")
        s.add(OP, profile, f"{pid}.truncated.{item}.missing", "broadcast.bounds",
              f"flag bit {bit} ({item}) set, no item bytes at all: truncated_payload",
              bc_input(data[:2]), R("broadcast.bounds") + ["E25"], error="truncated_payload")
        s.add(OP, profile, f"{pid}.trailing.{item}", "broadcast.bounds",
              f"only {item}, then one byte more than the flags announce: length_mismatch",
              bc_input(data + b"\x00"), R("broadcast.bounds") + ["E25"], error="length_mismatch")


def add_all_items(s: Suite, profile: str) -> None:
    p = rules_profile(profile)
    pid = f"broadcast.{profile}"
    for k in range(3):
        data = payload(profile, p.all_flags, Values(s.rng))
        s.add(OP, profile, f"{pid}.all_items.{k}", "broadcast.all_items",
              f"every item of {profile} present ({len(data)} bytes), random values #{k}", bc_input(data),
              R(f"broadcast.flag_order.{profile}", "broadcast.item_sizes", "broadcast.item_fields")
              + (["E27"] if profile == DOC_2X_PROFILE else []))
        s.add(OP, profile, f"{pid}.all_items.{k}.short_by_1", "broadcast.bounds",
              "every item present, the payload one byte short: truncated_payload", bc_input(data[:-1]),
              R("broadcast.bounds") + ["E25"], error="truncated_payload")
        s.add(OP, profile, f"{pid}.all_items.{k}.trailing", "broadcast.bounds",
              "every item present, then 3 bytes more: length_mismatch", bc_input(data + b"\x01\x02\x03"),
              R("broadcast.bounds") + ["E25"], error="length_mismatch")


def add_special_floats(s: Suite, profile: str) -> None:
    """Every float of every float-bearing item set to special values, in three rotations."""
    specials32 = list(F32_SPECIALS.values())
    specials64 = list(F64_SPECIALS.values())
    pairs = [(specials32[i % len(specials32)], specials64[i % len(specials64)]) for i in range(len(specials32))]
    p = rules_profile(profile)
    for item in float_items(profile):
        for shift in range(3):
            data = payload(profile, 1 << p.bit(item), Values(s.rng, pairs[shift:] + pairs[:shift]))
            s.add(OP, profile, f"broadcast.{profile}.special_floats.{item}.{shift}", "broadcast.special_floats",
                  f"{item} with NaN (quiet, signalling, payload, negative), infinities, -0.0, denormals and "
                  f"the largest float32 as values (rotation {shift}); every bit survives",
                  bc_input(data), R("floats.bit_exact", "broadcast.item_fields"))


def add_flag_word_bounds(s: Suite, profile: str) -> None:
    pid = f"broadcast.{profile}"
    s.add(OP, profile, f"{pid}.flag_word.empty", "broadcast.flag_word", "empty payload: no flag word",
          bc_input(b""), R("broadcast.flag_word") + ["E25"], error="truncated_payload")
    s.add(OP, profile, f"{pid}.flag_word.one_byte", "broadcast.flag_word", "one byte: half a flag word",
          bc_input(b"\x01"), R("broadcast.flag_word") + ["E25"], error="truncated_payload")
    s.add(OP, profile, f"{pid}.flag_word.none_set_trailing", "broadcast.bounds",
          "flag word 0 and one more byte: length_mismatch", bc_input(b"\x00\x00\x00"),
          R("broadcast.bounds", "broadcast.flag_word") + ["E25"], error="length_mismatch")


def add_reserved_flags(s: Suite, profile: str) -> None:
    """Each flag bit above the profile's last item, alone and next to every item."""
    p = rules_profile(profile)
    for bit in range(len(p.flag_bits), 16):
        for with_items in (False, True):
            base = p.all_flags if with_items else 0
            data = payload(profile, base, Values(s.rng))
            data = le16(base | 1 << bit) + data[2:]
            s.add(OP, profile, f"broadcast.{profile}.reserved_flag.bit{bit}{'.with_items' if with_items else ''}",
                  "broadcast.reserved_flags",
                  f"reserved flag bit {bit} set{' next to every item' if with_items else ''}: reserved_bits",
                  bc_input(data), R("broadcast.reserved_flags") + ["E25"], error="reserved_bits")


def add_flag_words(s: Suite, profile: str) -> None:
    """Every flag word of the profile once, with random values (compact: small cases)."""
    p = rules_profile(profile)
    order = R(f"broadcast.flag_order.{profile}")
    n = 1 << len(p.flag_bits)
    for flags in range(n):
        data = payload(profile, flags, Values(s.rng))
        items = bin(flags).count("1")
        sampled = s.rng.randrange(VALID_SAMPLE_EVERY) == 0
        if n <= FULL_FLAG_WORDS or items <= 2 or items >= len(p.flag_bits) - 2 or sampled:
            s.add(OP, profile, f"broadcast.{profile}.flags.0x{flags:04x}", "broadcast.flag_subsets",
                  f"flag word 0x{flags:04x}, random values", bc_input(data), order + R("broadcast.item_sizes"))
        else:
            # Size budget: a valid decode of an average a3-fw3.1 flag word
            # takes ~2 KB. Every flag word still appears once: valid when it
            # has at most 2 or all but at most 2 items (every pair of items in
            # order), or is in a seeded sample; otherwise its random-valued
            # payload one byte short of what the word announces (the sizes
            # of its items add up).
            s.add(OP, profile, f"broadcast.{profile}.flags.0x{flags:04x}.short_by_1", "broadcast.flag_subsets",
                  f"flag word 0x{flags:04x}, random values, one byte short", bc_input(data[:-1]),
                  order + R("broadcast.item_sizes", "broadcast.bounds"), error="truncated_payload")
