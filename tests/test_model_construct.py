"""model.from_construct (converters specialised per Container shape) against
model.from_construct_generic (the field-by-field walk that defines the value
model): the same JSON text for every event of every bench corpus, and the
same value or the same error for values no parser makes (other types in a
known shape, subclasses, odd keys, unset or out-of-range floats)."""
from __future__ import annotations

import pytest
from construct import Container, EnumInteger, EnumIntegerString, ListContainer

from osdk_conformance.bench.corpus import CORPORA, corpus
from osdk_conformance.core import model
from osdk_conformance.core.deframe import deframe
from osdk_conformance.reference.decode import Decoder
from osdk_conformance._construct import parse_frame
from osdk_conformance._construct.floats import F32, F64

SECONDS = 20  # of each corpus, the length test_accel.py reads too: every message type, item rates down to 1 Hz, line faults


# `make quick` leaves out the hour-long corpus
@pytest.mark.parametrize("name", [pytest.param(n, marks=pytest.mark.slow) if n == "a3-hour" else n for n in CORPORA])
def test_every_event_of_a_corpus_has_the_generic_model(name):
    spec = CORPORA[name]
    with open(corpus(name, seconds=SECONDS).path, "rb") as f:
        data = f.read()
    fast, generic = Decoder(spec.profile), Decoder(spec.profile)
    fast._fast = None  # the compiled broadcast frames have their own test (test_fast_frames.py)
    generic._fast = None
    generic._model = model.from_construct_generic
    kinds = set()
    for n, ev in enumerate(deframe([data])):
        a, b = fast.event(ev), generic.event(ev)
        assert model.dumps(a) == model.dumps(b), f"event {n} of {name}"
        kinds.add(a["kind"])
    assert "frame" in kinds
    if spec.mixed:
        assert {"error", "garbage"} <= kinds


def outcome(convert, value):
    try:
        return "ok", model.dumps(convert(value))
    except Exception as e:  # noqa: BLE001 - the class and text are what is compared
        return "error", type(e).__name__, str(e)


def same(value) -> tuple:
    expected = outcome(model.from_construct_generic, value)
    assert outcome(model.from_construct, value) == expected
    return expected


def unset_f32() -> F32:
    return object.__new__(F32)


def odd_floats() -> list:
    f32 = [0x00000000, 0x80000000, 0x3F800000, 0x7F800000, 0xFF800000, 0x7FC00000, 0x7F800001, 0xFFA00005, 0x00000001]
    f64 = [0, 1 << 63, 0x3FF0000000000000, 0x7FF0000000000000, 0xFFF0000000000000, 0x7FF0000000000001]
    return [F32(b) for b in f32] + [F64(b) for b in f64]


def test_floats_of_every_kind_in_one_container():
    floats = odd_floats()
    c = Container({f"f{i}": f for i, f in enumerate(floats)})
    assert same(c)[0] == "ok"
    for f in floats:
        assert same(f)[0] == "ok"


def shapes():
    """Containers of one key sequence with values of differing types: the
    first call compiles the converter for its types, the later ones miss."""
    named = EnumIntegerString.new(2, "push")
    flagged = EnumIntegerString.new(3, "odd")
    flagged.ieee_bits = 0x3F800000  # an attribute the generic walk reads as a float
    flagged.ieee_width = 32
    values = [
        1, True, None, F32(0x40490FDB), F64(1), b"\x01\xab", bytearray(b"\xff"), named, flagged, EnumInteger(7),
        ListContainer([1, named, Container(a=F32(0))]), Container(x=1, _io=None), Container(), [1], {"a": 1},
        1.5, "text", unset_f32(), F32(0), type("Sub", (Container,), {})(x=F32(1)), type("IntSub", (int,), {})(4),
    ]
    for first in values:
        for other in values:
            yield Container(a=first, b=other, trailing=b"", _hidden=other)


def test_one_key_sequence_with_any_value_types():
    for c in shapes():
        same(c)
        same(Container(outer=c, n=3))


def test_errors_are_the_generic_walks():
    broken = F32(1)
    broken.ieee_bits = 1 << 40  # too wide to pack
    assert same(Container(x=broken))[0] == "error"
    assert same(Container(x=unset_f32()))[0] == "error"
    assert same(Container({1: 2}))[0] == "error"            # a key that is not a string
    assert same(Container(x=[1]))[0] == "error"             # a list that is not a ListContainer
    assert same(Container(x=Container(y=1.5)))[0] == "error"
    assert same(object())[0] == "error"


def test_a_container_changed_after_its_converter_was_made():
    c = Container(x=F32(0x3F800000), y=2, limit=Container(a=True, b=3))
    same(c)
    c.y = None
    same(c)
    c.limit.b = EnumInteger(5)
    same(c)
    c.limit = b"\x00"
    same(c)
    del c["x"]
    same(c)


def test_parsed_frames_take_the_fast_path(monkeypatch):
    # falling back to the generic walk would be correct but slow: a parsed
    # broadcast frame must convert without it
    with open(corpus("a3-hour", seconds=1).path, "rb") as f:
        raw = next(ev.raw for ev in deframe([f.read()]) if hasattr(ev, "raw"))
    parsed = parse_frame(raw, CORPORA["a3-hour"].profile)
    expected = model.from_construct_generic(parsed)

    def refuse(value):
        raise AssertionError("the generic walk was used")

    monkeypatch.setattr(model, "from_construct_generic", refuse)
    for _ in range(2):  # the first call compiles, the second uses what it made
        assert model.from_construct(parsed) == expected
