"""The generated Wireshark dissector (generated/wireshark/osdk.lua), checked
with tshark (installed by tools/apt-packages.sh) on pcapng captures written
by the kit's own CaptureWriter: the golden vectors' frames field by field,
their errors as expert info, a simulator run against `osdkc decode`, ACKs
matched to their commands as `osdkc decode --direction both` matches them;
and `osdkc wireshark install`."""
from __future__ import annotations

import functools
import json
import os
import random
import shutil
import subprocess
import time
from pathlib import Path
from typing import Any

import pytest
import serial

from osdk_conformance import _construct as osdk_construct
from osdk_conformance import api
from osdk_conformance.bench.corpus import corpus
from osdk_conformance.cli import main as osdkc
from osdk_conformance.core.capture import CaptureWriter
from osdk_conformance.core.commands import COMMANDS
from osdk_conformance.core.errors import UsageError
from osdk_conformance.device import wireshark
from osdk_conformance.core.rules import profile as load_profile
from osdk_conformance.harness.vectors import load_cases

ROOT = Path(__file__).resolve().parents[1]
LUA = ROOT / "generated" / "wireshark" / "osdk.lua"
PROFILES = ("m100-fw2.3", "m100-fw3.1", "a3-fw3.1")
# `make quick` dissects the newest profile's vectors; `make test` every profile's
ONE_PROFILE_QUICK = [pytest.param(p, marks=() if p == "a3-fw3.1" else pytest.mark.slow) for p in PROFILES]
HEADER_FIELDS = ("sof", "len", "ver", "session", "is_ack", "res0", "padding", "enc", "res1", "seq", "crc16", "crc32")
NAMED_COMMANDS = frozenset(COMMANDS.values()) | {"unknown"}

Fields = dict[str, list[str]]   # one dissected frame or rejected run: field name -> its values, in tree order


# ---------------------------------------------------------------- tshark

def _require_tools() -> None:
    if shutil.which("tshark") is None:
        pytest.fail("tshark is not installed; `make setup` installs it (tools/apt-packages.sh)")
    if not LUA.is_file():
        pytest.fail(f"{LUA} is missing; `.venv/bin/python tools/regen.py` writes it")


def _pairs(pairs: list[tuple[str, Any]]) -> list[tuple[str, Any]]:
    # tshark's JSON repeats a key for every occurrence of a field (and of a
    # protocol layer) in one object; keep them all, in order.
    return pairs


def _collect(node: Any, out: Fields) -> None:
    if not isinstance(node, list):
        return
    for key, value in node:
        if key.startswith("osdk.") and not key.endswith("_tree"):
            out.setdefault(key, []).extend(_leaf_values(value))
        _collect(value, out)


def _leaf_values(value: Any) -> list[str]:
    # A field with a subtree shows its own value beside `<name>_tree`; a
    # field that is only a subtree's head carries the subtree itself.
    return [value] if isinstance(value, str) else []


def tshark(capture: Path, profile: str, tmp_home: Path) -> list[list[Fields]]:
    """The dissection of `capture` with the dissector and `profile`: for each
    packet, its osdk trees (one per frame or rejected run shown there)."""
    _require_tools()
    # A dissector installed for the user running the tests (`osdkc wireshark
    # install`) would register the protocol a second time: an empty HOME.
    env = dict(os.environ, HOME=str(tmp_home), XDG_CONFIG_HOME=str(tmp_home / ".config"))
    run = subprocess.run(
        ["tshark", "-n", "-r", str(capture), "-X", f"lua_script:{LUA}", "-o", f"osdk.profile:{profile}",
         "-T", "json"], capture_output=True, env=env, timeout=600)
    assert run.returncode == 0, run.stderr.decode(errors="replace")
    text = run.stdout.decode()
    assert "Lua Error" not in text and "lua.error" not in text.lower(), text[:4000]
    packets = json.loads(text, object_pairs_hook=_pairs)
    out: list[list[Fields]] = []
    for packet in packets:
        layers = dict(packet)["_source"]
        trees: list[Fields] = []
        for name, layer in dict(layers)["layers"]:
            if name == "osdk":
                fields: Fields = {}
                _collect(layer, fields)
                trees.append(fields)
        out.append(trees)
    return out


def write_capture(path: Path, records: list[bytes]) -> Path:
    """A capture of `records`, each one rx packet, 1 ms apart."""
    return write_records(path, [("rx", data) for data in records])


# ---------------------------------------------------------------- the value model as fields

def expected_fields(prefix: str, value: Any, out: dict[str, list[tuple[str, Any]]]) -> None:
    """`value` of the JSON value model (docs/VALUE-MODEL.md) as the fields
    the dissector shows: `prefix.<key path>`; a float as its bits
    (`<path>.bits`), an enum as its value, an array as repeated fields."""
    if isinstance(value, dict):
        if "f32" in value or "f64" in value:
            out.setdefault(prefix + ".bits", []).append(("int", int(value.get("f32") or value["f64"], 16)))
        elif set(value) == {"value", "name"}:
            out.setdefault(prefix, []).append(("int", value["value"]))
        else:
            for key, item in value.items():
                expected_fields(f"{prefix}.{key}", item, out)
    elif isinstance(value, list):
        for item in value:
            expected_fields(prefix, item, out)
    elif isinstance(value, bool):
        out.setdefault(prefix, []).append(("bool", value))
    elif isinstance(value, int):
        out.setdefault(prefix, []).append(("int", value))
    elif isinstance(value, str):
        out.setdefault(prefix, []).append(("hex", value))
    else:
        raise AssertionError(f"{prefix}: not a value of the model: {value!r}")


def _same(kind: str, expected: Any, shown: str) -> bool:
    try:
        if kind == "bool":
            return shown.strip().lower() in (("1", "true") if expected else ("0", "false"))
        if kind == "int":
            return int(shown, 0) == expected
        digits = shown.replace(":", "").strip().lower()
        if digits == expected:
            return True
        # a one-byte field (sof) may be typed as an integer
        return int(shown, 0) == int(expected, 16) if expected else False
    except ValueError:
        return False


def body_root(command: str, body: Any) -> Any:
    # The broadcast's payload is one field, `data`, in the model; the
    # dissector names its items directly (osdk.broadcast.battery).
    return body["data"] if command == "broadcast" and isinstance(body, dict) and set(body) == {"data"} else body


def frame_fields(frame: dict, command: str | None) -> dict[str, list[tuple[str, Any]]]:
    """Every field the dissector must show for the frame model `frame`."""
    out: dict[str, list[tuple[str, Any]]] = {}
    for key in HEADER_FIELDS:
        if key in frame:
            expected_fields(f"osdk.{key}", frame[key], out)
    data = frame.get("data")
    if isinstance(data, dict) and "cmd_set" in data:
        expected_fields("osdk.cmd_set", data["cmd_set"], out)
        expected_fields("osdk.cmd_id", data["cmd_id"], out)
        body = data["value"]["body"]
        if command in NAMED_COMMANDS:
            expected_fields(f"osdk.{command}", body_root(command, body), out)
    elif isinstance(data, dict) and "ack_value" in data:
        expected_fields("osdk.ack_value", data["ack_value"], out)
    return out


def mismatches(expected: dict[str, list[tuple[str, Any]]], shown: Fields) -> list[str]:
    bad = []
    for name, values in expected.items():
        got = shown.get(name)
        if got is None:
            if values == [("hex", "")]:
                continue  # an empty byte field may be left out of the tree
            bad.append(f"{name} missing (want {[v for _, v in values]})")
        elif len(got) != len(values) or not all(_same(k, v, g) for (k, v), g in zip(values, got)):
            bad.append(f"{name} = {got}, want {[v for _, v in values]}")
    return bad


def errors_of(tree: Fields) -> set[str]:
    return {name.removeprefix("osdk.error.") for name in tree if name.startswith("osdk.error.")}


def command_of(hex_text: str, profile: str) -> str | None:
    """What `osdkc decode` calls the one frame of `hex_text`."""
    events = api.decode_hex(hex_text, profile)
    assert len(events) == 1 and events[0].kind == "frame", events
    return events[0].command


# ---------------------------------------------------------------- golden vectors

def _decode_frame_cases(profile: str, result: str) -> list:
    return [c for c in load_cases() if c.operation == "decode_frame" and c.result == result and c.profile == profile]


@functools.cache
def _dissected(profile: str, result: str, tmp: str) -> tuple[list, list[list[Fields]]]:
    cases = _decode_frame_cases(profile, result)
    capture = write_capture(Path(tmp) / f"{result}-{profile}.pcapng", [bytes.fromhex(c.input["hex"]) for c in cases])
    return cases, tshark(capture, profile, Path(tmp))


@pytest.fixture(scope="module")
def tmp_module(tmp_path_factory: pytest.TempPathFactory) -> str:
    return str(tmp_path_factory.mktemp("wireshark"))


@pytest.mark.parametrize("profile", ONE_PROFILE_QUICK)
def test_every_valid_vector_dissects_to_its_expected_fields(profile: str, tmp_module: str) -> None:
    cases, packets = _dissected(profile, "valid", tmp_module)
    assert cases and len(packets) == len(cases)
    failures = []
    for case, trees in zip(cases, packets):
        if len(trees) != 1:
            failures.append(f"{case.id}: {len(trees)} osdk trees in its packet, want 1")
            continue
        tree = trees[0]
        command = command_of(case.input["hex"], profile)
        bad = mismatches(frame_fields(case.expected["frame"], command), tree)
        if errors_of(tree):
            bad.append(f"expert errors {sorted(errors_of(tree))} on a valid frame")
        if command in NAMED_COMMANDS and tree.get("osdk.command") not in ([command], None):
            bad.append(f"osdk.command = {tree['osdk.command']}, want {command}")
        if bad:
            failures.append(f"{case.id}: " + "; ".join(bad))
    assert not failures, f"{len(failures)} of {len(cases)} frames differ:\n" + "\n".join(failures[:40])


def _stream_errors(case) -> tuple[list[str], bool]:
    """The error classes `osdkc decode` reports for the case's bytes as a
    stream, and whether the stream ends inside a frame (which a dissector
    cannot report: nothing tells it that the capture ends there)."""
    events = api.decode(bytes.fromhex(case.input["hex"]), case.profile)
    errors = [e.error for e in events if e.kind == "error"]
    return errors, bool(errors) and errors[-1] == "truncated_frame"


@pytest.mark.parametrize("profile", ONE_PROFILE_QUICK)
def test_every_invalid_vector_shows_its_error(profile: str, tmp_path: Path) -> None:
    # In a capture the bytes are a stream, not a frame handed over alone: a
    # vector whose bytes leave the stream inside a frame would swallow the
    # next vector's, so those are left out (they are the truncated_frame
    # class, reported only at the end of a stream). A vector whose class is
    # one of decode_frame's own (bad_sof: no start byte; length_mismatch:
    # bytes after the frame) must show what `osdkc decode` says of the
    # same bytes as a stream.
    # An empty input is no packet at all.
    cases = [c for c in _decode_frame_cases(profile, "invalid") if c.input["hex"] and not _stream_errors(c)[1]]
    assert len(cases) > 500
    capture = write_capture(tmp_path / "invalid.pcapng", [bytes.fromhex(c.input["hex"]) for c in cases])
    packets = tshark(capture, profile, tmp_path)
    assert len(packets) == len(cases)
    failures = []
    for case, trees in zip(cases, packets):
        shown = set().union(*map(errors_of, trees)) if trees else set()
        stream, _ = _stream_errors(case)
        want = case.expected["error"]
        if want in stream:
            if want not in shown:
                failures.append(f"{case.id}: shows {sorted(shown)}, want osdk.error.{want}")
        elif shown != set(stream):
            failures.append(f"{case.id} ({want}, as a stream {stream}): shows {sorted(shown)}")
    assert not failures, f"{len(failures)} of {len(cases)} vectors differ:\n" + "\n".join(failures[:40])


# ---------------------------------------------------------------- a simulator run

@pytest.mark.parametrize("profile", ONE_PROFILE_QUICK)
def test_simulator_capture_matches_osdkc_decode(profile: str, tmp_path: Path) -> None:
    # the simulator's bytes alone, read in pieces of random sizes, so frames are split across packets
    capture = tmp_path / "sim.pcapng"
    records = _simulator_session(capture, profile, 1.0, commands=[], seed=15)
    events = [e for e in api.decode_file(capture, profile, direction="both")
              if e.kind == "frame" and e.command == "broadcast"]
    assert len(events) >= 10, f"the simulator sent {len(events)} broadcasts in 1 s"
    last_packet = event_packets(events, records)  # where the dissector shows each frame
    first_packet = [packet_of(records, e.direction, e.offset) for e in events]
    assert any(a != b for a, b in zip(first_packet, last_packet)), "no frame was split across packets"

    packets = tshark(capture, profile, tmp_path)
    shown = [(i, tree) for i, trees in enumerate(packets) for tree in trees
             if tree.get("osdk.command") == ["broadcast"]]
    assert len(shown) == len(events), f"tshark shows {len(shown)} broadcasts, osdkc decode {len(events)}"
    failures = []
    for k, (event, (packet, tree)) in enumerate(zip(events, shown)):
        bad = mismatches(frame_fields(dict(event.frame), "broadcast"), tree)
        if packet != last_packet[k]:
            bad.append(f"shown in packet {packet + 1}, its last byte is in packet {last_packet[k] + 1}")
        if bad:
            failures.append(f"broadcast {k} (seq {event.frame['seq']}): " + "; ".join(bad))
    assert not failures, "\n".join(failures[:40])


# ---------------------------------------------------------------- osdkc wireshark install

def test_install_copies_the_dissector(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    _require_tools()
    target = tmp_path / "plugins"
    assert osdkc(["wireshark", "install", "--dir", str(target)]) == 0
    installed = target / "osdk.lua"
    assert installed.read_bytes() == LUA.read_bytes()
    assert str(installed) in capsys.readouterr().out
    # again: the file is replaced, not refused
    assert osdkc(["wireshark", "install", "--dir", str(target)]) == 0
    assert installed.read_bytes() == LUA.read_bytes()


def test_install_default_is_the_personal_lua_plugin_folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    _require_tools()
    monkeypatch.setenv("HOME", str(tmp_path))
    assert osdkc(["wireshark", "install"]) == 0
    folders = subprocess.run(["tshark", "-G", "folders"], capture_output=True, text=True,
                             env=dict(os.environ, HOME=str(tmp_path))).stdout
    lua_dir = next(line.split("\t")[-1] for line in folders.splitlines() if line.startswith("Personal Lua Plugins"))
    assert (Path(lua_dir) / "osdk.lua").read_bytes() == LUA.read_bytes()
    protocols = subprocess.run(["tshark", "-G", "protocols"], capture_output=True, text=True,
                               env=dict(os.environ, HOME=str(tmp_path))).stdout
    assert any(line.split("\t")[2:3] == ["osdk"] for line in protocols.splitlines())


def test_install_errors_are_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    blocker = tmp_path / "file"
    blocker.write_text("")
    assert osdkc(["wireshark", "install", "--dir", str(blocker)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "not a directory" in err
    with pytest.raises(UsageError, match="missing"):
        wireshark.install(tmp_path / "x", source=tmp_path / "absent.lua")


# ---------------------------------------------------------------- ACK matching

Record = tuple[str, bytes]   # ("rx" or "tx", the bytes of one read or write)


def write_records(path: Path, records: list[Record]) -> Path:
    writer = CaptureWriter(path, {"profile": "test"})
    t0 = 1_700_000_000 * 10**9
    for i, (direction, data) in enumerate(records):
        (writer.rx if direction == "rx" else writer.tx)(data, t0 + i * 1_000_000)
    writer.close()
    return path


def packet_of(records: list[Record], direction: str, offset: int) -> int:
    """The packet holding byte `offset` of one direction's stream."""
    total = 0
    for i, (d, data) in enumerate(records):
        if d == direction:
            total += len(data)
            if total > offset:
                return i
    raise AssertionError(f"no {direction} byte {offset} in the capture")


def event_packets(events: list, records: list[Record]) -> list[int]:
    """The packet holding each event's last byte (where the dissector shows
    it): offsets count the bytes of the event's own direction."""
    return [packet_of(records, e.direction, e.offset + (e.frame["len"] if e.kind == "frame" else e.length) - 1)
            for e in events]


def event_mismatches(event, tree: Fields) -> list[str]:
    """How the dissector's tree differs from an event of `osdkc decode
    --direction both`: a frame's fields, a matched ACK's `ack_of` and value
    fields, an error's class (with `ack_of` for an ACK value that did not
    decode), nothing for garbage."""
    ack_of = tree.get("osdk.ack_of")
    if event.kind == "garbage":
        return [f"garbage shown with fields {sorted(tree)}"] if tree else []
    if event.kind == "error":
        bad = [] if errors_of(tree) == {event.error} else [f"errors {sorted(errors_of(tree))}, want {event.error}"]
        if ack_of != ([event.ack_of] if event.ack_of else None):
            bad.append(f"osdk.ack_of = {ack_of}, want {event.ack_of}")
        return bad
    bad = mismatches(frame_fields(dict(event.frame), event.command), tree)
    if errors_of(tree):
        bad.append(f"expert errors {sorted(errors_of(tree))} on a frame")
    if event.ack_of is None:
        if ack_of is not None or any(".ack." in name for name in tree):
            bad.append(f"an unmatched ACK shown as the ACK of {ack_of}")
        return bad
    if ack_of != [event.ack_of]:
        bad.append(f"osdk.ack_of = {ack_of}, want {event.ack_of}")
    want: dict[str, list[tuple[str, Any]]] = {}
    expected_fields(f"osdk.{event.ack_of}.ack", event.ack, want)
    bad += mismatches(want, tree)
    shown = {name for name in tree if name.startswith(f"osdk.{event.ack_of}.ack.")}
    bad += [f"{name} shown, not in the ACK value" for name in sorted(shown - set(want))]
    return bad


def assert_dissected_as_decoded(capture: Path, records: list[Record], profile: str,
                                tmp: Path) -> tuple[list, list[list[Fields]]]:
    """tshark shows, packet by packet, the events of `osdkc decode
    --direction both` on `capture`; those events and tshark's packets are returned."""
    # A frame cut short by the end of the capture is reported when the
    # stream ends, which nothing tells a dissector; so is what a rescan of
    # its bytes after its start byte finds then.
    events = list(api.decode_file(capture, profile, direction="both"))
    cut = {d: min((e.offset for e in events if e.direction == d and e.error == "truncated_frame"), default=None)
           for d in ("rx", "tx")}
    events = [e for e in events if cut[e.direction] is None or e.offset < cut[e.direction]]
    want: list[list] = [[] for _ in records]
    for e, packet in zip(events, event_packets(events, records)):
        want[packet].append(e)
    packets = tshark(capture, profile, tmp)
    assert len(packets) == len(records)
    failures = []
    for i, (evs, trees) in enumerate(zip(want, packets)):
        if len(evs) != len(trees):
            failures.append(f"packet {i + 1} ({records[i][0]}): {len(trees)} osdk trees, "
                            f"osdkc decode {[e.kind for e in evs]}")
            continue
        for e, tree in zip(evs, trees):
            bad = event_mismatches(e, tree)
            if bad:
                failures.append(f"packet {i + 1}, {e.direction} offset {e.offset} ({e.kind}): " + "; ".join(bad))
    assert not failures, f"{len(failures)} events differ:\n" + "\n".join(failures[:40])
    return events, packets


def _session_commands(profile: str) -> list[tuple[bytes, str]]:
    """A version query, an activation, a set frequency and a control
    authority request, as the SDK sends them: sessions 2-31 (each with an ACK
    slot, ERRATA E32), distinct seqs."""
    prof = load_profile(profile)
    values = [
        ((0x00, 0x00), {"arbitrary": 1}, "version_query"),
        ((0x00, 0x01), {"app_id": 1015, "api_level": 2, "sdk_version": prof.sdk_version, "bundle_id": bytes(32)},
         "activation"),
        ((0x00, 0x10), {"codes": [1] * 16}, "set_frequency"),
        ((0x01, 0x00), {"request": 1}, "control_authority"),
    ]
    out = []
    for n, ((cmd_set, cmd_id), body, name) in enumerate(values):
        value = osdk_construct.osdk_payload(cmd_set, cmd_id, False, prof.value).build({"body": body})
        frame = api.encode_frame(cmd_set=cmd_set, cmd_id=cmd_id, value=value, session=(3, 2, 31, 17)[n],
                                 seq=(300, 7, 4242, 65535)[n])
        out.append((frame, name))
    return out


def _simulator_session(path: Path, profile: str, seconds: float, commands: list[bytes],
                       seed: int = 1515) -> list[Record]:
    """Both directions of a session with the simulator: the commands written
    (every other one in two writes) as tx records, everything read, in
    pieces of random sizes, as rx records, in the order they happened."""
    rng = random.Random(seed)
    records: list[Record] = []
    commands = list(commands)
    with api.simulator(profile, seed=15) as sim:
        port = serial.Serial(sim.url, timeout=0.02)
        try:
            end = time.monotonic() + seconds
            while time.monotonic() < end:
                if commands:
                    frame = commands.pop(0)
                    cut = rng.randint(1, len(frame) - 1) if len(commands) % 2 == 0 else len(frame)
                    for piece in (frame[:cut], frame[cut:]):
                        if piece:
                            records.append(("tx", piece))
                            port.write(piece)
                            port.flush()
                data = port.read(rng.randint(1, 97))
                if data:
                    records.append(("rx", data))
        finally:
            port.close()
    write_records(path, records)
    return records


@pytest.mark.parametrize("profile", ONE_PROFILE_QUICK)
def test_simulator_session_acks_match_osdkc_decode_both(profile: str, tmp_path: Path) -> None:
    capture = tmp_path / "session.pcapng"
    records = _simulator_session(capture, profile, 1.0, [frame for frame, _ in _session_commands(profile)])
    assert sum(1 for d, _ in records if d == "tx") == 6, "two of the four commands are written in two pieces"
    events, _ = assert_dissected_as_decoded(capture, records, profile, tmp_path)
    sent = {e.command for e in events if e.direction == "tx" and e.kind == "frame"}
    assert sent == {name for _, name in _session_commands(profile)}
    matched = [e.ack_of for e in events if e.direction == "rx" and e.ack_of]
    assert sorted(matched) == sorted(sent), f"the simulator's ACKs matched {matched}"
    assert any(e.command == "broadcast" for e in events)


def test_acks_are_matched_one_slot_per_session(tmp_path: Path) -> None:
    # ERRATA E32: an ACK before any command; a command's ACK twice (the
    # second finds the slot empty); a session-0 command's seq answered; a
    # session-1 command answered (never matched); a command replaced in its
    # session's slot by another with the same SEQ (the ACK is the later
    # one's) and one by another SEQ (an ACK of the first SEQ is not
    # matched); an ACK value too short for its command's layout; a
    # header-only ACK (matched, its empty value too short) and the full ACK
    # after it (not matched).
    profile = "a3-fw3.1"
    query = osdk_construct.osdk_payload(0, 0, False, 2).build({"body": {"arbitrary": 0}})

    def command(session: int, seq: int, cmd: tuple[int, int] = (0, 0), value: bytes = query) -> bytes:
        return api.encode_frame(cmd_set=cmd[0], cmd_id=cmd[1], value=value, session=session, seq=seq)

    def ack(session: int, seq: int, value: bytes = b"\x00\x00") -> bytes:
        return api.encode_frame(is_ack=True, session=session, seq=seq, value=value)

    records: list[Record] = [("rx", ack(3, 1)), ("tx", command(3, 2)), ("rx", ack(3, 2, b"\x01\x00" + bytes(47))),
                             ("rx", ack(3, 2)), ("tx", command(0, 9)), ("rx", ack(1, 9)),
                             ("tx", command(1, 4)), ("rx", ack(1, 4))]
    records += [("tx", command(5, 0, (0x00, 0x10), bytes(16))), ("tx", command(6, 0)), ("tx", command(6, 1)),
                ("tx", command(5, 0)), ("tx", command(7, 0)), ("rx", ack(5, 0, bytes(49))), ("rx", ack(6, 0)),
                ("rx", ack(6, 1, b"\x01")), ("tx", command(8, 3)), ("rx", ack(8, 3, b"")), ("rx", ack(8, 3))]
    capture = write_records(tmp_path / "acks.pcapng", records)
    events, packets = assert_dissected_as_decoded(capture, records, profile, tmp_path)
    acks = [e for e in events if e.direction == "rx"]
    assert [e.ack_of for e in acks] == [None, "version_query", None, None, None, "version_query", None,
                                        "version_query", "version_query", None]
    assert [e.kind for e in acks] == ["frame"] * 7 + ["error", "error", "frame"]
    assert acks[7].error == acks[8].error == "truncated_payload" and acks[8].length == 12
    unmatched = [packets[i][0] for i, (d, raw) in enumerate(records) if d == "rx" and len(raw) > 12
                 and i not in (2, 13, 15)]
    assert len(unmatched) == 6
    for tree in unmatched:
        assert "osdk.ack_value" in tree and "osdk.ack_of" not in tree
        assert not any(".ack." in name for name in tree), sorted(tree)
    assert packets[2][0]["osdk.version_query.ack.ack_code"] == ["1"]
    assert packets[17][0]["osdk.ack_of"] == ["version_query"]  # the header-only ACK


def test_raw_bytes_through_text2pcap_show_what_osdkc_decode_shows(tmp_path: Path) -> None:
    # docs/WIRESHARK.md, "Raw byte captures": a file of raw received bytes as one USER0 packet
    c = corpus("a3-fw3.1-mixed", seconds=3)
    raw = tmp_path / "run.bin"
    raw.write_bytes(Path(c.path).read_bytes())
    od = subprocess.run(["od", "-Ax", "-tx1", "-v", str(raw)], capture_output=True, check=True, timeout=60)
    capture = tmp_path / "run.pcapng"
    subprocess.run(["text2pcap", "-q", "-l", "147", "-", str(capture)], input=od.stdout, check=True,
                   capture_output=True, timeout=60)
    (trees,) = tshark(capture, c.profile, tmp_path)
    events = [ev for ev in api.decode_file(raw, c.profile)]
    shown = [(t.get("osdk.ack_of") or t.get("osdk.command"))[0] for t in trees
             if "osdk.ack_of" in t or "osdk.command" in t]
    assert shown == [ev.ack_of or ev.command for ev in events if ev.kind == "frame"]
    assert sum(1 for t in trees for k in t if k.startswith("osdk.error.")) >= sum(
        ev.kind == "error" and ev.error != "truncated_frame" for ev in events)
