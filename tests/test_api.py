"""The Python API (osdk_conformance/api.py) and its documentation.

Every ```python block of docs/API.md runs here, in order, in one namespace,
and must print exactly its `#>` lines, so the page cannot drift from the
code. The other tests hold each function to what it fronts: the golden
vectors for the operations the testee protocol also has, the reference
decoder for events, bit-exact floats through encoding and decoding, one
error type for bad input, and a simulator that stops however its block ends.
"""
from __future__ import annotations

import contextlib
import inspect
import io
import re
import struct
import sys
import threading
import time
from pathlib import Path

import pytest
import serial

from osdk_conformance import api
from osdk_conformance.core.capture import CaptureWriter
from osdk_conformance.core.deframe import split_chunks
from osdk_conformance.core.wire import open_frame
from osdk_conformance.harness.vectors import VECTORS_DIR, compare, load_cases
from osdk_conformance.reference import codec
from osdk_conformance.reference.decode import decode_events
from osdk_conformance.reference.worked_examples import BROADCAST, MOVEMENT, WORKED_FRAMES

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "docs" / "API.md"
BLOCK = re.compile(r"^```python\n(.*?)^```", re.S | re.M)
A3 = "a3-fw3.1"
KEY = bytes(range(32))


# ---------------------------------------------------------------- docs/API.md

def doc_blocks() -> list[str]:
    return BLOCK.findall(DOC.read_text(encoding="utf-8"))


def shown_output(block: str) -> list[str]:
    """The `#>` lines of a block: what it prints, one line each."""
    return [line.strip()[3:] if line.strip() != "#>" else ""
            for line in block.splitlines() if line.strip().startswith("#>")]


@pytest.mark.slow
def test_every_example_of_the_api_page_prints_what_it_shows(tmp_path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    blocks = doc_blocks()
    assert len(blocks) >= 8
    namespace: dict = {"__name__": "docs_api"}
    for n, block in enumerate(blocks):
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            exec(compile(block, f"docs/API.md python block {n + 1}", "exec"), namespace)
        assert out.getvalue().splitlines() == shown_output(block), f"docs/API.md python block {n + 1}"


def test_the_readme_example_prints_what_it_shows() -> None:
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    section = readme.split("\n### Python API\n", 1)[1].split("\n## ", 1)[0]
    assert "(docs/API.md)" in section
    (block,) = BLOCK.findall(section)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        exec(compile(block, "README.md, Python API", "exec"), {"__name__": "readme"})
    assert out.getvalue().splitlines() == shown_output(block) != []


def test_every_section_of_the_api_page_has_an_example_that_shows_output() -> None:
    sections = re.split(r"^## ", DOC.read_text(encoding="utf-8"), flags=re.M)[1:]
    for section in sections:
        if section.startswith(("What is stable", "Reference")):
            continue
        title = section.splitlines()[0]
        assert any(shown_output(b) for b in BLOCK.findall(section)), f"section {title!r} has no example output"


def test_the_api_page_names_every_public_name() -> None:
    text = DOC.read_text(encoding="utf-8")
    reference = text.split("\n## Reference\n", 1)[1]
    assert [name for name in api.__all__ if f"`api.{name}" not in reference] == []


# ---------------------------------------------------------------- the interface itself

def test_every_public_name_exists_is_documented_and_fully_annotated() -> None:
    assert len(set(api.__all__)) == len(api.__all__)
    for name in api.__all__:
        obj = getattr(api, name)
        if inspect.isfunction(obj):
            assert obj.__doc__, name
            sig = inspect.signature(obj)
            assert sig.return_annotation is not inspect.Signature.empty, name
            assert all(p.annotation is not inspect.Parameter.empty for p in sig.parameters.values()), name
        elif inspect.isclass(obj):
            assert obj.__doc__, name
            for attr, member in vars(obj).items():
                if not attr.startswith("_") and (inspect.isfunction(member) or isinstance(member, property)):
                    assert member.__doc__, f"{name}.{attr}"


def test_the_package_is_marked_typed_and_the_wheel_carries_the_marker() -> None:
    assert (ROOT / "osdk_conformance" / "py.typed").is_file()
    pyproject = (ROOT / "pyproject.toml").read_text()
    data = pyproject.split("[tool.setuptools.package-data]", 1)[1].split("\n[", 1)[0]
    assert re.search(r'^"osdk_conformance" = \["py\.typed"\]$', data, re.M)


# ---------------------------------------------------------------- decoding

def test_decoded_events_are_the_reference_decoders_events() -> None:
    stream = bytes.fromhex(BROADCAST.hex) + b"\x00\xaa\x01" + bytes.fromhex(MOVEMENT.hex)
    events = api.decode(stream, A3)
    assert [ev.model for ev in events] == list(decode_events([stream], A3))
    assert [ev.kind for ev in events] == ["frame", "garbage", "error", "garbage", "frame"]
    assert events[0].value["data"]["battery"] == 87 and events[4].command == "movement_control"
    assert events[2].error == "bad_crc16" and events[2].length == 1 and events[2].frame is None
    assert api.decode_hex(" ".join(re.findall("..", BROADCAST.hex)), A3)[0].model == events[0].model
    assert api.decode_hex("0x" + BROADCAST.hex.upper(), A3)[0].to_json() == events[0].to_json()


def test_a_header_only_frame_and_an_unmatched_ack_have_no_value() -> None:
    header_only, ack = api.decode(api.encode_frame() + api.encode_frame(is_ack=True, session=3, value=b"\x02\x00"), A3)
    assert header_only.command == "none" and header_only.value is None
    assert ack.command == "ack" and ack.ack_of is None and ack.value is None
    assert ack.frame["data"]["ack_value"] == "0200"


def test_decode_stream_takes_chunks_or_a_file_object_and_gives_the_same_events() -> None:
    stream = bytes.fromhex(MOVEMENT.hex) * 2 + bytes.fromhex(BROADCAST.hex)
    whole = [ev.model for ev in api.decode(stream, A3)]
    assert [ev.model for ev in api.decode_stream([bytes([b]) for b in stream], A3)] == whole
    assert [ev.model for ev in api.decode_stream(io.BytesIO(stream), A3)] == whole


def test_the_api_decodes_every_stream_vector_as_the_golden_vectors_expect() -> None:
    for case in load_cases([VECTORS_DIR / "streams.json"]):
        chunks = split_chunks(bytes.fromhex(case.input["hex"]), case.input["chunks"])
        events = [ev.model for ev in api.decode_stream(chunks, case.profile)]
        passed, why = compare(case, {"ok": True, "result": {"events": events}})
        assert passed, f"{case.id}: {why}"


def two_way_capture(path: Path) -> tuple[bytes, bytes]:
    query = api.encode_frame(cmd_set=0x01, cmd_id=0x00, value=b"\x01", session=2, seq=9)
    answer = api.encode_frame(is_ack=True, session=2, seq=9, value=b"\x03\x00")
    writer = CaptureWriter(path, {"profile": A3})
    writer.tx(query)
    writer.rx(bytes.fromhex(BROADCAST.hex) + answer[:5])
    writer.rx(answer[5:])
    writer.close()
    return query, answer


def test_a_capture_decodes_by_direction(tmp_path) -> None:
    path = tmp_path / "run.pcapng"
    query, _ = two_way_capture(path)
    rx = list(api.decode_file(path, A3))
    assert [ev.command for ev in rx] == ["broadcast", "ack"] and all(ev.direction is None for ev in rx)
    tx = list(api.decode_file(str(path), A3, direction="tx"))
    assert [ev.command for ev in tx] == ["control_authority"]
    both = list(api.decode_file(path, A3, direction="both"))
    assert [(ev.direction, ev.command, ev.ack_of) for ev in both] == [
        ("tx", "control_authority", None), ("rx", "broadcast", None), ("rx", None, "control_authority")]
    assert both[2].value == {"ack_code": {"value": 3, "name": "obtain_in_progress"}}
    assert [ev.model for ev in api.decode(path.read_bytes(), A3, direction="both")] == [ev.model for ev in both]


def test_a_damaged_capture_or_tx_of_raw_bytes_is_an_input_error(tmp_path) -> None:
    path = tmp_path / "run.pcapng"
    two_way_capture(path)
    data = bytearray(path.read_bytes())
    shb_length = struct.unpack_from("<I", data, 4)[0]
    struct.pack_into("<I", data, shb_length - 4, shb_length + 4)   # the trailing copy of the first block's length
    with pytest.raises(api.InputError, match="damaged capture at offset 0"):
        api.decode(bytes(data), A3)
    with pytest.raises(api.InputError, match="pcapng"):
        api.decode(bytes.fromhex(BROADCAST.hex), A3, direction="tx")


@pytest.mark.parametrize("call, message", [
    (lambda: api.decode_hex("aa1", A3), "not a hex string"),
    (lambda: api.decode_hex("zz", A3), "not a hex string"),
    (lambda: api.decode_hex(b"aa", A3), "must be a str"),
    (lambda: api.decode(BROADCAST.hex, A3), "must be bytes, got str; for hex text use"),
    (lambda: api.decode([0xAA], A3), "must be bytes"),
    (lambda: api.decode(b"", "a3"), "unknown profile 'a3'"),
    (lambda: api.decode(b"", A3, direction="up"), "direction must be one of rx, tx, both"),
    (lambda: api.decode_stream([b""], "m600"), "unknown profile"),
    (lambda: api.decode_file("x.bin", None), "unknown profile"),
    (lambda: api.decode_file(3, A3), "path must be a str or path-like"),
    (lambda: list(api.decode_stream(["aa"], A3)), "each chunk must be bytes, got str"),
    (lambda: api.decode_stream(7, A3), "source must be a binary file object or an iterable of bytes"),
])
def test_bad_decoding_arguments_are_input_errors(call, message) -> None:
    with pytest.raises(api.InputError, match=re.escape(message)):
        call()


def test_a_file_that_is_not_there_is_an_os_error_when_reading_starts(tmp_path) -> None:
    events = api.decode_file(tmp_path / "absent.bin", A3)
    with pytest.raises(FileNotFoundError):
        next(events)


# ---------------------------------------------------------------- encoding

@pytest.mark.parametrize("worked", WORKED_FRAMES, ids=lambda w: w.name.split(",")[0])
def test_encode_frame_builds_the_worked_frames(worked) -> None:
    assert api.encode_frame(**worked.build).hex() == worked.hex


def test_the_api_encodes_every_encode_vector_as_the_golden_vectors_expect() -> None:
    for case in load_cases([VECTORS_DIR / "encode.json"]):
        inp = case.input
        if case.operation == "encode_movement_control":
            def make() -> bytes:
                return api.encode_movement_control(inp["mode"], *(api.ieee_float(inp[k]) for k in ("x", "y", "z", "yaw")))
        else:
            def make() -> bytes:
                return api.encode_frame(cmd_set=inp.get("cmd_set"), cmd_id=inp.get("cmd_id"), is_ack=inp["is_ack"],
                                        session=inp["session"], seq=inp["seq"], value=bytes.fromhex(inp["value"]))
        if case.result == "invalid":
            with pytest.raises(api.InputError):
                make()
            continue
        want = case.expected["hex"] if "hex" in case.expected else case.expected["value"]["hex"]
        assert make().hex() == want, case.id


@pytest.mark.parametrize("bits", [0x7FA00001, 0xFFC00000, 0x7F800000, 0xFF800000, 0x80000000, 0x00000001, 0x3F800000])
def test_movement_control_floats_go_out_and_come_back_bit_for_bit(bits) -> None:
    value = api.encode_movement_control(0x4B, api.F32(bits), -0.0, api.F32(bits), 0.0)
    assert value == bytes([0x4B]) + struct.pack("<IIII", bits, 0x80000000, bits, 0)
    ev = api.decode(api.encode_frame(cmd_set=1, cmd_id=3, value=value), A3)[0]
    assert ev.value["x"]["f32"] == f"0x{bits:08x}"
    assert api.ieee_float(ev.value["x"]) == api.F32(bits)
    assert api.ieee_float(ev.value["y"]) == api.F32(0x80000000) != api.F32(0)


def test_python_floats_are_rounded_to_float32() -> None:
    value = api.encode_movement_control(0, 0.1, float("nan"), float("-inf"), 1e-46)
    assert value[1:] == struct.pack("<ffff", 0.1, float("nan"), float("-inf"), 1e-46)


@pytest.mark.parametrize("call, message", [
    (lambda: api.encode_movement_control(256, 0, 0, 0, 0), "mode must be an integer 0..255"),
    (lambda: api.encode_movement_control(True, 0, 0, 0, 0), "mode must be an integer"),
    (lambda: api.encode_movement_control(0, "1", 0, 0, 0), "x must be a number or an F32"),
    (lambda: api.encode_movement_control(0, 0, api.F64(0), 0, 0), "y must be a number or an F32"),
    (lambda: api.encode_movement_control(0, 0, 0, 0, 1e300), "float32"),
    (lambda: api.encode_frame(cmd_set=1), "give both cmd_set and cmd_id"),
    (lambda: api.encode_frame(cmd_set=256, cmd_id=0), "cmd_set must be an integer 0..255"),
    (lambda: api.encode_frame(session=32), "session must be an integer 0..31"),
    (lambda: api.encode_frame(seq=-1), "seq must be an integer 0..65535"),
    (lambda: api.encode_frame(value="00"), "value must be bytes"),
    (lambda: api.encode_frame(is_ack=True, value=b"\x00"), "(bad_session): an ACK frame is never in session 0"),
    (lambda: api.encode_frame(cmd_set=0, cmd_id=0, value=bytes(1006)), "exceeds the 1023-byte maximum"),
    (lambda: api.encode_frame(value=b"\x00", is_ack=True, session=1, key=b"short"), "32 bytes"),
    (lambda: api.encode_broadcast(A3, {"wind": 3}), "has no broadcast item wind"),
    (lambda: api.encode_broadcast("m100-fw2.3", {"rtk_detail": {}}), "has no broadcast item rtk_detail"),
    (lambda: api.encode_broadcast(A3, {"gimbal": {"spin": 1}}), "no profile's gimbal has a field 'spin'"),
    (lambda: api.encode_broadcast(A3, {"gimbal": 1.0}), "gimbal is a record of fields"),
    (lambda: api.encode_broadcast(A3, {"battery": 300}), "broadcast on a3-fw3.1"),
    (lambda: api.encode_broadcast(A3, {"battery": "full"}), "broadcast on a3-fw3.1"),
    (lambda: api.encode_broadcast(A3, ["battery"]), "items must be a mapping"),
    (lambda: api.encode_broadcast_frame("fw3", {}), "unknown profile"),
    (lambda: api.ieee_float({"f16": "0x0000"}), "not a float of the value model"),
])
def test_bad_encoding_arguments_are_input_errors(call, message) -> None:
    with pytest.raises(api.InputError, match=re.escape(message)):
        call()


def test_an_encrypted_frame_opens_with_its_key() -> None:
    raw = api.encode_frame(cmd_set=1, cmd_id=3, value=bytes.fromhex(MOVEMENT.build["value"].hex()), seq=5, key=KEY)
    assert api.decode(raw, A3)[0].command == "encrypted"
    opened = open_frame(raw, KEY)
    assert (opened.cmd_set, opened.cmd_id, opened.value) == (1, 3, MOVEMENT.build["value"])


def test_encode_broadcast_builds_the_worked_value_and_cuts_items_to_each_profile() -> None:
    assert api.encode_broadcast(A3, {"battery": 87, "flight_status": 3}).hex() == BROADCAST.build["value"].hex()
    assert api.encode_broadcast_frame(A3, {"flight_status": 3, "battery": 87}, seq=7).hex() == BROADCAST.hex
    for profile in api.profiles():
        everything = dict.fromkeys(api.broadcast_items(profile))
        data = api.decode(api.encode_broadcast_frame(profile, everything), profile)[0].value["data"]
        assert [k for k in data if not k.startswith(("has_", "reserved"))] == list(api.broadcast_items(profile))
        assert data["battery"] == 0


def test_broadcast_floats_keep_their_bits() -> None:
    roll, lat = api.F32(0xFF800001), api.F64(0x8000000000000000)
    raw = api.encode_broadcast_frame(A3, {"gimbal": {"roll": roll, "pitch": -0.0}, "position": {"latitude": lat}})
    data = api.decode(raw, A3)[0].value["data"]
    assert api.ieee_float(data["gimbal"]["roll"]) == roll
    assert data["gimbal"]["pitch"] == {"f32": "0x80000000", "value": -0.0}
    assert api.ieee_float(data["position"]["latitude"]) == lat and data["position"]["latitude"]["f64"] == "0x8000000000000000"


# ---------------------------------------------------------------- control mode and movement control

@pytest.mark.slow
def test_classify_and_check_answer_every_control_vector_as_the_reference_does() -> None:
    cases = load_cases([VECTORS_DIR / "control_mode.json", VECTORS_DIR / "control_ranges.json"])
    assert {c.operation for c in cases} == {"classify_control_mode", "check_movement_control"}
    for case in cases:
        if case.operation == "classify_control_mode":
            response = api.classify_control_mode(case.input["byte"], case.profile).response()
        else:
            response = api.check_movement_control(bytes.fromhex(case.input["hex"]), case.profile).response()
        assert response == codec.answer(case.operation, case.profile, case.input), case.id
        passed, why = compare(case, response)
        assert passed, f"{case.id}: {why}"


def test_a_control_mode_carries_its_reasons_and_ranges() -> None:
    documented = api.classify_control_mode(0x4B, A3)
    assert documented.documented and documented.combination == 4 and documented.reasons
    assert documented.input_ranges["yaw"]["unit"] == "deg/s"
    undocumented = api.classify_control_mode(0x60, A3)
    assert not undocumented.documented and undocumented.combination is None and undocumented.input_ranges is None
    assert api.classify_control_mode(0x08, "m100-fw2.3").classification == "documented"
    assert api.classify_control_mode(0x01, "m100-fw2.3").classification == "invalid"   # ERRATA E15: yaw angle needs bit 0 clear


def test_checked_setpoints_are_bit_exact_and_nan_is_out_of_range() -> None:
    check = api.check_movement_control(api.encode_movement_control(0x4B, -0.0, 0.0, 4.0, -100.0), A3)
    assert check.ok and check.setpoints["x"] == api.F32(0x80000000) and check.setpoints["z"] == api.F32.from_float(4.0)
    nan = api.check_movement_control(api.encode_movement_control(0x4B, 0.0, 0.0, 0.0, api.F32(0x7FC00001)), A3)
    assert (nan.ok, nan.error, nan.setpoints) == (False, "out_of_range", None)
    assert nan.detail.startswith("yaw = NaN is NaN")
    short = api.check_movement_control(b"\x4b\x00", A3)
    assert (short.ok, short.error) == (False, "truncated_payload")
    assert api.check_movement_control(bytes(18), A3).error == "length_mismatch"


@pytest.mark.parametrize("call, message", [
    (lambda: api.classify_control_mode(256, A3), "control mode byte must be an integer 0..255"),
    (lambda: api.classify_control_mode(-1, A3), "control mode byte must be an integer 0..255"),
    (lambda: api.classify_control_mode(1.0, A3), "control mode byte must be an integer 0..255"),
    (lambda: api.classify_control_mode(0, "A3"), "unknown profile 'A3'"),
    (lambda: api.check_movement_control("4b00", A3), "value must be bytes"),
    (lambda: api.check_movement_control(bytes(17), "any"), "unknown profile"),
    (lambda: api.broadcast_items("any"), "unknown profile"),
])
def test_bad_control_arguments_are_input_errors(call, message) -> None:
    with pytest.raises(api.InputError, match=re.escape(message)):
        call()


# ---------------------------------------------------------------- a conformance run

# A testee that claims two operations and one profile, and answers every
# encode_frame with the same wrong frame: failures, skips and coverage.
WRONG_TESTEE = '''
import json, sys
for line in sys.stdin:
    req = json.loads(line)
    if req["op"] == "capabilities":
        out = {"ok": True, "result": {"name": "wrong", "operations": ["encode_frame", "classify_control_mode"],
                                      "profiles": ["a3-fw3.1"]}}
    elif req["op"] == "encode_frame":
        out = {"ok": True, "result": {"hex": "aa0c00000000000000003a86"}}
    else:
        out = {"ok": False, "unsupported": True}
    print(json.dumps(out), flush=True)
'''


@pytest.mark.slow
def test_a_failing_testee_gives_failures_skips_and_coverage(tmp_path) -> None:
    script = tmp_path / "wrong_testee.py"
    script.write_text(WRONG_TESTEE)
    listed = tmp_path / "known.txt"
    listed.write_text("encode.frame.worked.broadcast  # known\n")
    run = api.run_conformance([sys.executable, str(script)], filter="worked", failure_list=listed)
    assert (run.verdict, run.conforms, run.complete, run.exit_status) == ("DOES NOT CONFORM", False, False, 1)
    assert run.testee == "wrong" and run.command == (sys.executable, str(script)) and run.failure_list == str(listed)
    by_id = {r.id: r for r in run.results}
    failed = by_id["encode.frame.worked.movement_control"]
    assert (failed.status, failed.kind, failed.bad) == ("fail", "mismatch", True)
    assert failed.details["expected"] == {"hex": MOVEMENT.hex}
    assert by_id["encode.frame.worked.broadcast"].status == "xfail"
    assert by_id["frames.a3-fw3.1.worked.broadcast"].kind == "op_not_claimed"
    assert run.failures == (failed,)
    assert run.statuses == {"pass": 0, "fail": 1, "xfail": 1, "xpass": 0, "skip": 13, "error": 0}
    rows = {(c.operation, c.profile): c for c in run.coverage}
    assert (rows["encode_frame", None].ran, rows["encode_frame", None].available) == (2, 2)
    assert rows["decode_frame", "m100-fw2.3"].skipped == {"operation not claimed": 2}
    assert run.capabilities == api.Capabilities("wrong", frozenset({"encode_frame", "classify_control_mode"}),
                                                frozenset({A3}))
    assert run.summary().endswith("\n" + run.verdict_line) and "coverage (cases run / available)" in run.summary()


@pytest.mark.slow
def test_a_testee_that_claims_part_of_the_suite_conforms_for_that_part() -> None:
    # the native decoder decodes and does nothing else
    run = api.run_conformance(impl="accel", profiles=["m100-fw2.3"], filter=".worked")
    assert (run.conforms, run.complete, run.exit_status, run.cases) == (True, False, 0, 7)
    assert run.verdict_line == "CONFORMS for decode_frame, decode_payload: 3 of 7 cases"
    assert {c.profile for c in run.coverage} == {"m100-fw2.3", None}
    assert {c.operation: c.skipped for c in run.coverage if c.ran == 0} == {
        "check_movement_control": {"operation not claimed": 1},
        "encode_frame": {"operation not claimed": 2}, "encode_movement_control": {"operation not claimed": 1}}
    assert "construct" in api.bundled_implementations() and "kaitai-python" in api.bundled_implementations()


@pytest.mark.parametrize("kwargs, message", [
    ({}, "give either a testee command or impl"),
    ({"testee": "x", "impl": "construct"}, "give either a testee command or impl"),
    ({"impl": "cobol"}, "no bundled implementation 'cobol'"),
    ({"testee": "/nonexistent/testee"}, "cannot start testee"),
    ({"testee": ""}, "the testee command is empty"),
    ({"testee": 7}, "testee must be a command line or a list of its words"),
    ({"impl": "construct", "filter": "no such case"}, "no vector matches"),
    ({"impl": "construct", "profiles": ["a3"]}, "unknown profile 'a3'"),
    ({"impl": "construct", "timeout": float("nan")}, "timeout must be"),
    ({"impl": "construct", "memory_mb": -1}, "memory_mb must be"),
    ({"impl": "construct", "failure_list": "/nonexistent/list.txt"}, "cannot read the failure list"),
    ({"impl": "construct", "vectors": ["/nonexistent/v.json"]}, "v.json"),
])
def test_bad_run_arguments_are_input_errors(kwargs, message) -> None:
    with pytest.raises(api.InputError, match=re.escape(message)):
        api.run_conformance(**kwargs)


# ---------------------------------------------------------------- the simulator

def sim_threads() -> list[threading.Thread]:
    return [t for t in threading.enumerate() if t.name == "osdkc-sim"]


def read_frames(url: str, profile: str, wanted: int, seconds: float = 10.0) -> list[api.Event]:
    with serial.Serial(url, timeout=0.1) as port:
        data, end = b"", time.monotonic() + seconds
        while time.monotonic() < end:
            data += port.read(4096)
            frames = [ev for ev in api.decode(data, profile) if ev.kind == "frame"]
            if len(frames) >= wanted:
                return frames
    raise AssertionError(f"{len(data)} bytes in {seconds} s, not {wanted} frames")


def test_the_simulator_broadcasts_on_its_port_and_stops_when_the_block_ends() -> None:
    before = len(sim_threads())
    with api.simulator("m100-fw2.3", rates={"battery": 50}, seed=1) as sim:
        assert sim.profile == "m100-fw2.3" and sim.url.startswith("/dev/")
        frames = read_frames(sim.url, "m100-fw2.3", 3)
        assert {ev.command for ev in frames} == {"broadcast"}
        # battery at 50 Hz is in every other frame of the 100 Hz stream; FW 2.3's time stamp has no nano_time
        assert any("battery" in ev.value["data"] for ev in frames)
        assert all(list(ev.value["data"]["time_stamp"]) == ["time"] for ev in frames)
        assert sim.stats()["broadcast_frames"] >= 3 and sim.authority()["control"] == "rc"
        url = sim.url
    assert len(sim_threads()) == before
    with pytest.raises(serial.SerialException):
        serial.Serial(url, timeout=0.1).close()


def test_a_planted_bug_triggers_and_the_stats_say_so() -> None:
    with api.simulator(A3, bugs=["unknown-cmd-silence"]) as sim:
        read_frames(sim.url, A3, 1)
        with serial.Serial(sim.url, timeout=0.1) as port:
            port.write(api.encode_frame(cmd_set=0x7E, cmd_id=0x01, value=b"", session=2, seq=9))
            end = time.monotonic() + 5
            while time.monotonic() < end and not sim.stats()["bug_triggers"]["unknown-cmd-silence"]:
                port.read(4096)
        stats = sim.stats()
    assert stats["bugs"] == ["unknown-cmd-silence"] and stats["bug_triggers"] == {"unknown-cmd-silence": 1}
    assert stats["bug_events"][0]["bug"] == "unknown-cmd-silence"


def test_the_simulator_stops_when_the_block_raises() -> None:
    before = len(sim_threads())
    with pytest.raises(ZeroDivisionError):
        with api.simulator(A3, faults={"noise": 0.5}, seed=3) as sim:
            assert len(sim_threads()) == before + 1
            read_frames(sim.url, A3, 1)
            1 / 0
    assert len(sim_threads()) == before


@pytest.mark.parametrize("kwargs, message", [
    ({"profile": "a3"}, "unknown profile"),
    ({"rates": {"wind": 10}}, "rates: wind=10"),
    ({"rates": {"battery": 20}}, "rates: battery=20"),
    ({"rc_mode": "S"}, "rc_mode must be one of P, A, F"),
    ({"faults": {"bitflip": 1.5}}, "faults: bitflip=1.5"),
    ({"faults": {"smoke": 0.1}}, "faults: smoke=0.1"),
    ({"encrypt": True}, "encrypt needs the key"),
    ({"key": b"k"}, "32 bytes"),
    ({"app_id": -1}, "app_id must be an integer"),
    ({"wrong_profile": "m100"}, "unknown profile"),
    ({"bugs": "long-frame-hang"}, "bugs: 'long-frame-hang': want a list"),
    ({"bugs": ["segfault"]}, "bugs: ['segfault']"),
])
def test_bad_simulator_arguments_are_input_errors_before_it_starts(kwargs, message) -> None:
    before = len(sim_threads())
    with pytest.raises(api.InputError, match=re.escape(message)):
        with api.simulator(**kwargs):
            pass
    assert len(sim_threads()) == before
