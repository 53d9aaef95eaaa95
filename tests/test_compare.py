"""The judge's comparison of an answer with its expected result: the quick
test for an answer equal to the expectation (vectors._same) never passes an
answer the full walk (vectors._value_difference) would fail, whatever the
values: booleans against numbers, integers against floats, float models by
their bits (hex in any case, -0.0, NaN), nested objects and arrays."""
from __future__ import annotations

from hypothesis import given, strategies as st

from osdk_conformance.harness.vectors import _same, _value_difference, difference

FLOAT_MODELS = st.builds(lambda key, bits, upper: {key: (f"0x{bits:08X}" if upper else f"0x{bits:08x}")},
                         st.sampled_from(["f32", "f64"]),
                         st.sampled_from([0, 0x80000000, 0x3F800000, 0x7FC00000, 0x7F800001, 0xFFFFFFFF]),
                         st.booleans())
SCALARS = st.one_of(st.none(), st.booleans(), st.integers(-3, 3), st.sampled_from([0.0, -0.0, 1.0, float("nan")]),
                    st.sampled_from(["", "a", "0x0"]), FLOAT_MODELS)
VALUES = st.recursive(SCALARS, lambda inner: st.one_of(
    st.lists(inner, max_size=3), st.dictionaries(st.sampled_from(["a", "b", "ack_code"]), inner, max_size=3)),
    max_leaves=8)


@given(VALUES, VALUES)
def test_the_quick_test_agrees_with_the_full_walk(expected, got):
    if _same(expected, got):
        assert _value_difference(expected, got, "result") is None
    assert (difference(expected, got) is None) == (_value_difference(expected, got, "result") is None)


@given(VALUES)
def test_a_value_equals_its_copy_unless_it_holds_a_nan(value):
    import json

    copy = json.loads(json.dumps(value))
    assert (difference(value, copy) is None) == ("nan" not in json.dumps(value).lower())


def test_the_confusions_the_full_walk_reports_are_not_passed_quickly():
    for expected, got in [(True, 1), (1, True), (0, False), ("1", 1), (None, 0), ([1], (1,)), ({"a": 1}, {"a": 1, "b": 2}),
                          ({"f32": "0x00000000"}, {"f32": "0x80000000"}), ({"f64": "0x0"}, 0.0), (float("nan"), float("nan"))]:
        assert not _same(expected, got), (expected, got)
        assert difference(expected, got) is not None, (expected, got)
    assert difference({"f32": "0x3f800000"}, {"f32": "0x3F800000"}) is None  # the bits, not the spelling
    assert difference(1, 1.0) is None  # JSON has one kind of number
