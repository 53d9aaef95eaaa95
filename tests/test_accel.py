"""The native accelerator (osdk_conformance/reference/_accel.c, loaded by
reference/accel.py) against the pure-Python reference it stands in for.

The golden vectors hold it to the spec (`osdkc run --impl accel`, in
test_runner's run of every bundled implementation); here it must give the
reference's events key for key, in the same order, on whole streams: every
bench corpus (broadcasts with every item, commands, ACKs matched by session
and sequence number, noise, bad CRCs, frames cut short), cut into reads at
random, both directions of a capture, and single payloads. `detail` is the
one field allowed to differ: it is text for people, worded by each decoder.
The switch (OSDKC_ACCEL) and the fallback when the module is missing are
tested through the commands and the API that use them.
"""
from __future__ import annotations

import json
import random
import subprocess
import sys
from pathlib import Path

import pytest

from osdk_conformance import api
from osdk_conformance.bench.corpus import CORPORA, corpus
from osdk_conformance.core import model
from osdk_conformance.core.capture import CaptureWriter
from osdk_conformance.core.deframe import Frame, deframe, split_chunks
from osdk_conformance.core.errors import UsageError
from osdk_conformance.reference import accel
from osdk_conformance.reference.decode import (DecodeFailure, both_directions_events, decode_events, payload_body,
                                               stream_events)

ROOT = Path(__file__).resolve().parents[1]
SECONDS = 20  # of traffic per corpus: every kind of event, in a few seconds of test


def text(events) -> list[str]:
    """Events as JSON lines without `detail` (the key itself must still be there)."""
    return [model.dumps({k: ("…" if k == "detail" else v) for k, v in ev.items()}) for ev in events]


def random_reads(data: bytes, seed: int) -> list[bytes]:
    rng = random.Random(seed)
    sizes = []
    while sum(sizes) < len(data):
        sizes.append(rng.choice((0, 1, 2, 11, 12, 13, rng.randrange(1, 5000))))
    return split_chunks(data, sizes)


@pytest.fixture
def native(monkeypatch):
    monkeypatch.setenv(accel.ENV, "1")
    assert accel.available(), "the native decoder is not built; `make setup` builds it"


@pytest.mark.parametrize("name", list(CORPORA))
def test_events_are_the_references_whatever_the_reads(name, native) -> None:
    c = corpus(name, seconds=SECONDS)
    data = Path(c.path).read_bytes()
    reference = text(decode_events([data], c.profile))
    assert len(reference) >= c.frames
    native = list(stream_events([data], c.profile))
    assert text(native) == reference
    assert text(stream_events(random_reads(data, seed=len(data)), c.profile)) == reference
    # api.Event takes a decoder's events as they are: every key must be one of its fields
    assert {key for ev in native for key in ev} <= set(api.Event.__dataclass_fields__)


def test_both_directions_of_a_capture_match_acks_across_directions(tmp_path, native) -> None:
    c = corpus("a3-fw3.1-mixed", seconds=SECONDS)
    data = Path(c.path).read_bytes()
    path = tmp_path / "run.pcapng"
    writer = CaptureWriter(path, {"profile": c.profile})
    commands, cursor = 0, 0
    for ev in deframe([data]):
        if isinstance(ev, Frame) and not ev.raw[3] >> 5 & 1 and ev.raw[3] & 0x1F:  # a command in a session
            writer.rx(data[cursor:ev.offset])  # what came before it, faults included
            writer.tx(ev.raw)
            cursor = ev.offset + len(ev.raw)
            commands += 1
    writer.rx(data[cursor:])
    writer.close()
    assert commands >= 5  # the start-up exchange and a version query every ten seconds
    capture = [path.read_bytes()]
    reference = text(both_directions_events(capture, c.profile, "run.pcapng"))
    assert sum('"ack_of"' in line for line in reference) >= commands // 2
    assert text(stream_events(capture, c.profile, "both", "run.pcapng")) == reference


def test_payload_bodies_and_their_failures_are_the_references(monkeypatch) -> None:
    c = corpus("m100-fw3.1-mixed", seconds=SECONDS)
    frames = [ev.raw for ev in deframe([Path(c.path).read_bytes()]) if isinstance(ev, Frame)][:400]
    cases = [(raw[14:-4], raw[12], raw[13], False) for raw in frames if not raw[3] >> 5 & 1 and len(raw) > 16]
    cases += [(value[:cut], s, i, a) for value, s, i, a in cases[:50] for cut in (0, 1, len(value) - 1)]
    cases += [(b"\x00" * 20, 0x01, 0x03, False), (b"\x01\x00", 0x00, 0x00, True), (b"", 0x02, 0x00, False)]

    def run(switch: str) -> list:
        monkeypatch.setenv(accel.ENV, switch)
        body = payload_body(c.profile)
        out = []
        for value, cmd_set, cmd_id, is_ack in cases:
            try:
                out.append(model.dumps(body(value, cmd_set, cmd_id, is_ack)))
            except DecodeFailure as e:
                out.append(e.error_class)
        return out

    native, pure = run("1"), run("0")
    assert native == pure
    assert any(not x.startswith("{") for x in native) and any(x.startswith("{") for x in native)


def test_the_switch(monkeypatch) -> None:
    monkeypatch.setenv(accel.ENV, "0")
    assert accel.native() is None and accel.describe() == f"pure Python ({accel.ENV}=0)"
    for value in ("", "auto", "1", "on"):
        monkeypatch.setenv(accel.ENV, value)
        assert accel.native() is not None and accel.describe().startswith("native (")
    monkeypatch.setenv(accel.ENV, "sometimes")
    with pytest.raises(UsageError, match="OSDKC_ACCEL='sometimes'"):
        accel.native()


def test_without_the_module_pure_python_decodes_and_asking_for_it_is_an_error(monkeypatch) -> None:
    import importlib

    real = importlib.import_module

    def no_native(name, *args):
        if name == accel.MODULE:
            raise ImportError(f"No module named {name!r}")
        return real(name, *args)

    monkeypatch.setattr(importlib, "import_module", no_native)
    accel._import.cache_clear()
    try:
        monkeypatch.delenv(accel.ENV, raising=False)
        assert accel.native() is None and "no native decoder" in accel.describe()
        events = api.decode_hex("aa1600000000000007001ede02000018035769c676b2", "a3-fw3.1")
        assert events[0].value["data"]["battery"] == 87
        monkeypatch.setenv(accel.ENV, "1")
        with pytest.raises(UsageError, match="native decoder is not installed"):
            accel.native()
    finally:
        monkeypatch.undo()
        accel._import.cache_clear()


@pytest.mark.parametrize("switch, says", [("0", "pure Python"), ("1", "native")])
def test_decode_and_version_say_and_use_the_chosen_decoder(switch, says, tmp_path) -> None:
    c = corpus("m100-fw2.3-mixed", seconds=5)
    env = {"OSDKC_ACCEL": switch, "PATH": "/usr/bin:/bin"}
    version = subprocess.run([sys.executable, "-m", "osdk_conformance", "--version"], env=env, cwd=tmp_path,
                             capture_output=True, text=True, timeout=60)
    assert version.returncode == 0 and f"decoder: {says}" in version.stdout
    out = subprocess.run([sys.executable, "-m", "osdk_conformance", "decode", "--profile", c.profile, c.path],
                         env=env, cwd=tmp_path, capture_output=True, text=True, timeout=120)
    assert out.returncode == 1  # the corpus has line faults: errors were reported
    reference = text(decode_events([Path(c.path).read_bytes()], c.profile))
    assert [line for line in text(json.loads(x) for x in out.stdout.splitlines())] == reference


def test_a_bad_switch_is_a_one_line_usage_error(tmp_path) -> None:
    out = subprocess.run([sys.executable, "-m", "osdk_conformance", "decode", "--profile", "a3-fw3.1", "--hex", "aa"],
                         env={"OSDKC_ACCEL": "maybe", "PATH": "/usr/bin:/bin"}, cwd=tmp_path,
                         capture_output=True, text=True, timeout=60)
    assert out.returncode == 2 and out.stdout == ""
    assert out.stderr.strip().splitlines() == ["osdkc: OSDKC_ACCEL='maybe': use 1 (the native decoder), 0 (pure "
                                               "Python) or auto"]


def test_the_native_module_refuses_what_it_cannot_use() -> None:
    module = accel._import()[0]
    assert module is not None
    with pytest.raises(TypeError):
        module.Decoder(1, None)
    with pytest.raises(TypeError):
        module.Decoder(1, len, 4)  # no pending limit any more: one ACK slot per session (ERRATA E32)
    decoder = module.Decoder(1, len)
    with pytest.raises(TypeError):
        decoder.feed("not bytes")
    with pytest.raises(ValueError, match="direction"):
        decoder.feed(b"\xaa", "sideways")
    with pytest.raises(module.DecodeError) as e:
        module.decode_frame(b"\x55" * 20, 1)
    assert e.value.args[0] == "bad_sof"
    # memoryview and bytearray are bytes too
    assert decoder.feed(bytearray(b"\x00\x01")) == [] and decoder.finish() == [
        {"offset": 0, "kind": "garbage", "length": 2}]


def test_the_native_decoder_cannot_be_fed_from_inside_itself_or_before_init() -> None:
    module = accel._import()[0]
    short_broadcast = api.encode_frame(cmd_set=0x02, cmd_id=0x00, value=b"\x01\x00")  # a time stamp promised, not there

    def header_fields_that_feeds_again(raw: bytes) -> dict:
        decoder.feed(raw)  # the deframer is in the middle of its own callback
        return {}

    decoder = module.Decoder(1, header_fields_that_feeds_again)
    with pytest.raises(RuntimeError, match="already decoding"):
        decoder.feed(short_broadcast)
    # still usable afterwards, and an error event is what a well-behaved header_fields gives
    decoder.__init__(1, lambda raw: {"len": len(raw)})
    (event,) = decoder.feed(short_broadcast)
    assert event["error"] == "truncated_payload" and event["frame_header"] == {"len": len(short_broadcast)}
    with pytest.raises(RuntimeError, match="__init__"):
        module.Decoder.__new__(module.Decoder).feed(b"\xaa")
