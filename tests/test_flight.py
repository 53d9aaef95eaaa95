"""Flight data for people (osdk_conformance/flight): the native columns, the
typed records, tables, `osdkc decode --format`, `osdkc plot`.

They are a second shape of what the value model says, so they are held to
it: on every broadcast vector (the golden answer, not our decoder's), on
every stream vector, and on a bench corpus of each profile, every column of
every row must be what the value model holds, floats bit for bit, and an
item the value model lacks must be absent. The records must be the columns
in Python types. Then the time columns, the commands' files and exit
statuses, bad input, and Ctrl-C.
"""
from __future__ import annotations

import csv
import io
import json
import math
import os
import signal
import struct
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pyarrow.parquet as pq
import pytest

from osdk_conformance import api
from osdk_conformance.bench.corpus import corpus
from osdk_conformance.flight import columns, records, tables
from osdk_conformance.harness.vectors import load_checked_cases

ROOT = Path(__file__).resolve().parents[1]
VECTORS = ROOT / "vectors"
PROFILES = api.profiles()
A3 = "a3-fw3.1"


def osdkc(*args: str, env: dict | None = None, stdin=None, timeout: float = 120) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "osdk_conformance", *args], capture_output=True, text=True,
                          timeout=timeout, env={**os.environ, **(env or {})}, stdin=stdin, cwd=ROOT)


# ---------------------------------------------------------------- the value model, flattened

def leaves(model: dict, prefix: str = "", root: bool = True) -> dict[str, tuple[str, int | bool]]:
    """name -> (what, value) of every leaf of a broadcast's value model: floats as
    their bits, enums as their value, bools, ints. The root's flag bits (has_*) and
    checked fields are not leaves of a table: presence says them."""
    out: dict[str, tuple[str, int | bool]] = {}
    for key, v in model.items():
        if root and (key.startswith("has_") or key in ("reserved_flags", "trailing")):
            continue
        name = prefix + key
        if isinstance(v, dict) and ("f32" in v or "f64" in v):
            out[name] = ("float", int(v.get("f32") or v.get("f64"), 16))
        elif isinstance(v, dict) and set(v) == {"value", "name"}:
            out[name] = ("int", v["value"])
        elif isinstance(v, dict):
            out.update(leaves(v, name + ".", root=False))
        elif isinstance(v, bool):
            out[name] = ("bool", v)
        else:
            out[name] = ("int", v)
    return out


def assert_row_is(data: columns.FlightData, row: int, model: dict, where: str) -> None:
    want = leaves(model)
    names = {c.name for c in data.columns}
    assert set(want) <= names, f"{where}: the value model has leaves no column holds: {set(want) - names}"
    for c in data.columns:
        valid = bool(data.valid(c.name)[row])
        if c.name not in want:
            assert not valid, f"{where}: {c.name} is present, the value model has no such value"
            continue
        assert valid, f"{where}: {c.name} is absent, the value model has {want[c.name]}"
        what, value = want[c.name]
        got = int(data.bits(c.name)[row]) if what == "float" else data.values(c.name)[row].item()
        assert got == value and type(got) is type(value), f"{where}: {c.name} is {got!r}, the value model has {value!r}"


def broadcast_frame(payload: bytes) -> bytes:
    return api.encode_frame(cmd_set=0x02, cmd_id=0x00, value=payload)


# ---------------------------------------------------------------- agreement with the value model

@pytest.fixture(scope="module")
def broadcast_vectors() -> dict[str, list]:
    by_profile: dict[str, list] = {p: [] for p in PROFILES}
    for case in load_checked_cases([VECTORS / "broadcast.json"]):
        if case.operation == "decode_payload" and (case.input["cmd_set"], case.input["cmd_id"]) == (2, 0) \
                and not case.input["is_ack"]:
            by_profile[case.profile].append(case)
    return by_profile


@pytest.mark.parametrize("profile", PROFILES)
def test_every_broadcast_vector_is_its_value_model_in_the_columns(broadcast_vectors, profile) -> None:
    cases = broadcast_vectors[profile]
    valid = [c for c in cases if c.result == "valid"]
    invalid = [c for c in cases if c.result != "valid"]
    assert valid and invalid
    stream = b"".join(broadcast_frame(bytes.fromhex(c.input["hex"])) for c in valid + invalid)
    data = columns.read(stream, profile)
    assert data.rows == len(valid)
    assert data.counts["errors"] == len(invalid) and data.counts["frames"] == len(valid)
    assert not data.has_capture_time
    for row, case in enumerate(valid):
        assert_row_is(data, row, case.expected["value"]["data"], case.id)


def test_every_stream_vector_gives_the_rows_its_expected_events_hold() -> None:
    checked = 0
    for case in load_checked_cases([VECTORS / "streams.json"]):
        want = [ev for ev in case.expected.get("events", ())
                if ev.get("kind") == "frame" and ev.get("command") == "broadcast"]
        data = columns.read(bytes.fromhex(case.input["hex"]), case.profile)
        assert data.rows == len(want), case.id
        for row, ev in enumerate(want):
            assert int(data.offset[row]) == ev["offset"], case.id
            assert_row_is(data, row, ev["frame"]["data"]["value"]["body"]["data"], case.id)
            checked += 1
    assert checked > 100


@pytest.mark.parametrize("profile", PROFILES)
def test_a_bench_corpus_is_its_value_model_frame_for_frame(profile) -> None:
    c = corpus(f"{profile}-mixed", seconds=20)
    raw = Path(c.path).read_bytes()
    data = columns.read(raw, profile)
    broadcasts = [ev for ev in api.decode(raw, profile) if ev.command == "broadcast"]
    assert data.rows == len(broadcasts) > 500
    assert data.counts["frames"] == c.frames and data.counts["garbage_bytes"] == c.garbage_bytes
    for row, ev in enumerate(broadcasts):
        assert int(data.offset[row]) == ev.offset
        assert_row_is(data, row, ev.value["data"], f"{c.name} frame at {ev.offset}")


def float_of(bits: int, kind: str) -> float:
    return struct.unpack("<f", struct.pack("<I", bits))[0] if kind == "f32" else \
        struct.unpack("<d", struct.pack("<Q", bits))[0]


def test_records_are_the_value_model_in_python_types(broadcast_vectors) -> None:
    cases = [c for c in broadcast_vectors[A3] if c.result == "valid"][::20]
    data = columns.read(b"".join(broadcast_frame(bytes.fromhex(c.input["hex"])) for c in cases), A3)
    kinds = {c.name: c.kind for c in data.columns}
    checked = 0
    for rec, case in zip(records.records(data), cases, strict=True):
        model = case.expected["value"]["data"]
        for item in data.items:
            if item not in model:
                assert getattr(rec, item) is None, (case.id, item)
        for name, (what, want) in leaves(model).items():
            *path, field = name.split(".")
            node = rec
            for part in path:
                node = getattr(node, part)
            got = getattr(node, field)
            if what == "float":
                assert type(got) is float and node.bits(field) == want, (case.id, name)
                ref = float_of(want, kinds[name])
                assert got == ref or (math.isnan(got) and math.isnan(ref)), (case.id, name)
            elif what == "bool":
                assert type(got) is bool and got == want, (case.id, name)
            else:
                assert isinstance(got, int) and not isinstance(got, bool) and got == want, (case.id, name)
            checked += 1
    assert checked > 1000


def test_enums_are_int_enums_and_an_unnamed_value_stays_an_int() -> None:
    frame = broadcast_frame(api.encode_broadcast(A3, {"control_info": {"control_device": 2, "cur_mov_control_mode": 4}}))
    rec = next(records.records(columns.read(frame, A3)))
    assert rec.control_info.control_device.name == "onboard_device" and rec.control_info.control_device == 2
    assert rec.control_info.cur_mov_control_mode.name == "horiz_vel_vert_vel_yaw_rate"
    assert rec.battery is None and rec.attitude is None and rec.fc_time is None
    members = records.int_enum("osdk_broadcast_items.cur_mov_control_mode")
    unnamed = next(v for v in range(256) if v not in {m.value for m in members})
    values = api.encode_broadcast(A3, {"control_info": {"control_device": 0}})
    data = bytearray(values)
    # control_info's mode byte is the first byte of the item, the last item of the payload (2 bytes)
    data[-2] = unnamed
    got = columns.read(broadcast_frame(bytes(data)), A3)
    assert api.decode(broadcast_frame(bytes(data)), A3)[0].value["data"]["control_info"]["cur_mov_control_mode"] == \
        {"value": unnamed, "name": None}   # the value model takes it, without a name
    value = next(records.records(got)).control_info.cur_mov_control_mode
    assert type(value) is int and value == unnamed


def test_nan_infinities_and_negative_zero_keep_their_bits_everywhere(tmp_path) -> None:
    bits = [0x7FC00001, 0xFF800000, 0x7F800000, 0x80000000]   # a NaN with a payload, -inf, inf, -0.0
    q = {f"q{i}": api.F32(b) for i, b in enumerate(bits)}
    frame = broadcast_frame(api.encode_broadcast(A3, {"quaternion": q}))
    data = columns.read(frame, A3)
    assert [int(data.bits(f"quaternion.q{i}")[0]) for i in range(4)] == bits
    table = tables.to_arrow(data, ["quaternion"])
    view = table.column("quaternion.q0").chunks[0].buffers()[1]
    assert np.frombuffer(view, dtype=np.uint32)[0] == bits[0]
    path = tmp_path / "q.parquet"
    pq.write_table(table, path)
    back = pq.read_table(path)
    assert [int(np.frombuffer(back.column(f"quaternion.q{i}").chunks[0].buffers()[1], dtype=np.uint32)[0])
            for i in range(4)] == bits
    rec = next(records.records(data))
    assert math.isnan(rec.quaternion.q0) and rec.quaternion.q1 == -math.inf
    assert math.copysign(1.0, rec.quaternion.q3) == -1.0 and rec.quaternion.bits("q3") == 0x80000000


# ---------------------------------------------------------------- time

def test_a_frame_takes_the_time_of_the_record_that_completed_it_and_raw_bytes_have_none(tmp_path) -> None:
    f1 = api.encode_broadcast_frame(A3, {"time_stamp": {"time": 400}, "battery": 50}, seq=1)
    f2 = api.encode_broadcast_frame(A3, {"time_stamp": {"time": 800}, "battery": 49}, seq=2)
    path = tmp_path / "t.pcapng"
    # f2 is split over two records: it is complete at the second one
    api.write_capture(path, [("rx", 10.0, f1), ("rx", 10.25, f2[:5]), ("tx", 10.3, b"\x00"), ("rx", 10.5, f2[5:])])
    data = columns.read(path, A3)
    assert data.has_capture_time
    assert data.time_ns.tolist() == [10_000_000_000, 10_500_000_000]
    assert data.fc_time.tolist() == [1.0, 2.0]
    table = tables.to_arrow(data)
    assert table.column_names[:3] == ["offset", "time", "fc_time"]
    assert [t.value for t in table.column("time").to_pylist()] == [10_000_000_000, 10_500_000_000] or \
        table.column("time").cast("int64").to_pylist() == [10_000_000_000, 10_500_000_000]
    events = [ev for ev in api.decode_file(path, A3)]
    assert [(ev.time, ev.fc_time) for ev in events] == [(10.0, 1.0), (10.5, 2.0)]
    raw = columns.read(f1 + f2, A3)
    assert not raw.has_capture_time and "time" not in tables.to_arrow(raw).column_names
    assert [ev.time for ev in api.decode(f1 + f2, A3)] == [None, None]


def test_an_item_table_has_only_the_frames_that_carried_it_with_their_own_times(tmp_path) -> None:
    frames = [api.encode_broadcast_frame(A3, {"time_stamp": {"time": 4 * i}, **({"battery": 90} if i % 5 == 0 else {})},
                                         seq=i) for i in range(20)]
    path = tmp_path / "slow.pcapng"
    api.write_capture(path, [("rx", 100 + i / 100, f) for i, f in enumerate(frames)])
    t = tables.item_table(columns.read(path, A3), "battery")
    assert t.num_rows == 4 and t.column("battery").to_pylist() == [90] * 4
    assert t.column("fc_time").to_pylist() == [0.0, 0.05, 0.1, 0.15]


# ---------------------------------------------------------------- the commands

@pytest.fixture(scope="module")
def flight_capture(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("flight") / "flight.pcapng"
    frames = []
    for i in range(200):
        half = math.radians(i / 2) / 2
        items = {"time_stamp": {"time": 8 * i}, "battery": 100 - i // 20,
                 "quaternion": {"q0": math.cos(half), "q1": 0.0, "q2": 0.0, "q3": math.sin(half)},
                 "velocity": {"x": 1.0, "y": 2.0, "z": 2.0}}
        frames.append(("rx", 1_700_000_000 + i / 50, api.encode_broadcast_frame(A3, items, seq=i % 65536)))
    frames.append(("tx", 1_700_000_005, api.encode_frame(cmd_set=0, cmd_id=0, value=b"\x00", session=2, seq=1)))
    frames.append(("rx", 1_700_000_005, api.encode_broadcast_frame(A3, {"battery": 1}, seq=9)[:7]))   # cut by the end
    api.write_capture(path, frames)
    return path


def test_decode_csv_reads_back_to_the_table(flight_capture) -> None:
    done = osdkc("decode", "--profile", A3, "--format", "csv", "--items", "battery,quaternion.q3,velocity",
                 str(flight_capture))
    assert done.returncode == 0, done.stderr
    rows = list(csv.DictReader(io.StringIO(done.stdout)))
    assert len(rows) == 200
    assert list(rows[0]) == ["offset", "time", "fc_time", "quaternion.q3", "velocity.x", "velocity.y", "velocity.z",
                             "velocity.data_valid", "velocity.sensor_id", "velocity.reserved", "battery"]
    data = columns.read(flight_capture, A3)
    q3 = data.values("quaternion.q3")
    assert [np.float32(float(r["quaternion.q3"])) for r in rows] == list(q3)   # the decimal reads back exactly
    assert rows[-1]["battery"] == "91" and rows[-1]["fc_time"] == "3.98"
    assert "200 broadcast frames in the table" in done.stderr
    assert "ends inside a frame" in done.stderr          # the cut tail is the capture's end, not an error


def test_decode_parquet_writes_the_file_and_jsonl_stays_the_value_model(flight_capture, tmp_path) -> None:
    out = tmp_path / "f.parquet"
    done = osdkc("decode", "--profile", A3, "--format", "parquet", "-o", str(out), str(flight_capture))
    assert done.returncode == 0, done.stderr
    table = pq.read_table(out)
    assert table.num_rows == 200 and "rtk_detail.yaw" in table.column_names
    assert table.column("rtk_detail.yaw").null_count == 200 and table.column("battery").null_count == 0
    assert not (tmp_path / "f.parquet.partial").exists()
    jsonl = osdkc("decode", "--profile", A3, str(flight_capture))
    plain = osdkc("decode", "--profile", A3, "--format", "jsonl", str(flight_capture))
    assert jsonl.stdout == plain.stdout and json.loads(jsonl.stdout.splitlines()[0])["kind"] == "frame"
    assert "time" not in json.loads(jsonl.stdout.splitlines()[0])   # the value model is unchanged


@pytest.mark.parametrize("args, words", [
    (["--format", "parquet"], "parquet is a binary format: give -o FILE"),
    (["--format", "csv", "--items", "battery,altitude"], "no item 'altitude'"),
    (["--format", "csv", "--items", ","], "--items names no item"),
    (["--items", "battery"], "--items is for --format csv or parquet"),
    (["--format", "csv", "--direction", "both"], "--direction rx only"),
    (["--format", "csv", "--pretty"], "--pretty is for the JSON lines"),
    (["--format", "xml"], "invalid choice"),
])
def test_bad_table_options_are_one_line_and_exit_2(flight_capture, args, words) -> None:
    done = osdkc("decode", "--profile", A3, *args, str(flight_capture))
    assert done.returncode == 2 and words in done.stderr, done.stderr
    assert "Traceback" not in done.stderr and len(done.stderr.strip().splitlines()) == 1, done.stderr


def test_table_exit_status_follows_the_json_lines(tmp_path) -> None:
    empty = tmp_path / "empty.bin"
    empty.write_bytes(b"")
    done = osdkc("decode", "--profile", A3, "--format", "csv", str(empty))
    assert done.returncode == 1 and "no frame found" in done.stderr
    text = tmp_path / "notes.txt"
    text.write_text("this is not a capture\n")
    assert osdkc("decode", "--profile", A3, "--format", "csv", str(text)).returncode == 1
    bad = bytearray(api.encode_broadcast_frame(A3, {"battery": 3}))
    bad[-1] ^= 0xFF
    broken = tmp_path / "broken.bin"
    broken.write_bytes(api.encode_broadcast_frame(A3, {"battery": 4}) + bytes(bad))
    done = osdkc("decode", "--profile", A3, "--format", "csv", str(broken))
    assert done.returncode == 1 and "1 errors" in done.stderr and len(done.stdout.splitlines()) == 2
    wrong = osdkc("decode", "--profile", "m100-fw2.3", "--format", "csv",
                  str(Path(corpus(f"{A3}-mixed", seconds=3).path)))
    assert wrong.returncode == 1 and "no broadcast decoded as m100-fw2.3" in wrong.stderr
    missing = osdkc("decode", "--profile", A3, "--format", "csv", str(tmp_path / "nope.bin"))
    assert missing.returncode == 2 and "Traceback" not in missing.stderr


def test_without_the_native_decoder_a_table_is_a_clear_error(flight_capture) -> None:
    done = osdkc("decode", "--profile", A3, "--format", "csv", str(flight_capture), env={"OSDKC_ACCEL": "0"})
    assert done.returncode == 2 and "need the native decoder" in done.stderr and "Traceback" not in done.stderr
    with pytest.raises(api.InputError, match="native decoder"):
        os.environ["OSDKC_ACCEL"] = "0"
        try:
            api.table(flight_capture, A3)
        finally:
            del os.environ["OSDKC_ACCEL"]


def test_plot_draws_each_series_as_a_panel_in_html_and_svg(flight_capture, tmp_path) -> None:
    page = tmp_path / "flight.html"
    done = osdkc("plot", str(flight_capture), "--profile", A3, "--items", "battery,attitude,velocity", "-o", str(page))
    assert done.returncode == 0, done.stderr
    html = page.read_text()
    panels = [s for s in ("battery", "roll", "pitch", "yaw", "velocity.x", "speed") if f'data-series="{s}"' in html]
    assert panels == ["battery", "roll", "pitch", "yaw", "velocity.x", "speed"]
    assert "flight controller time (s)" in html and html.count('class="series"') == 9  # x, y, z, sensor_id and speed of velocity
    svg = tmp_path / "flight.svg"
    assert osdkc("plot", str(flight_capture), "--profile", A3, "--items", "attitude", "-o", str(svg)).returncode == 0
    root = ET.fromstring(svg.read_text())
    assert root.tag == "{http://www.w3.org/2000/svg}svg"
    yaw = tables.to_arrow(columns.read(flight_capture, A3))   # the plotted yaw is the quaternion's, in degrees
    q = [np.float64(yaw.column(f"quaternion.q{i}")[199].as_py()) for i in range(4)]
    assert round(records.attitude_of(*q).yaw, 3) == 99.5


@pytest.mark.parametrize("args, words", [
    (["--items", "battery", "-o", "x.png"], "the output is .html or .svg"),
    (["--items", "attitude", "--profile", "m100-fw2.3", "-o", "x.html"], "no broadcast frame decodes as m100-fw2.3"),
    (["--items", "battery,voltage", "-o", "x.html"], "no item 'voltage'"),
])
def test_bad_plots_are_one_line_and_exit_2(flight_capture, tmp_path, args, words) -> None:
    if "--profile" not in args:
        args = [*args, "--profile", A3]
    args = [a if a not in ("x.png", "x.html") else str(tmp_path / a) for a in args]
    done = osdkc("plot", str(flight_capture), *args)
    assert done.returncode == 2 and words in done.stderr, done.stderr
    assert "Traceback" not in done.stderr and not list(tmp_path.iterdir())


def test_ctrl_c_stops_a_table_being_read_from_a_pipe_and_leaves_no_file(tmp_path) -> None:
    out = tmp_path / "live.parquet"
    proc = subprocess.Popen([sys.executable, "-m", "osdk_conformance", "decode", "--profile", A3, "--format",
                             "parquet", "-o", str(out), "-"], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, cwd=ROOT)
    frame = api.encode_broadcast_frame(A3, {"battery": 7})
    for _ in range(50):
        proc.stdin.write(frame * 20)
        proc.stdin.flush()
        time.sleep(0.02)
    proc.send_signal(signal.SIGINT)
    t0 = time.monotonic()
    _, err = proc.communicate(timeout=10)
    assert time.monotonic() - t0 < 2.0
    assert proc.returncode == 130 and b"Traceback" not in err, err
    assert not out.exists() and not (tmp_path / "live.parquet.partial").exists()


def test_without_the_flight_extra_each_command_says_what_to_install(flight_capture, tmp_path) -> None:
    # a numpy that cannot be imported stands for an install without the extra
    fake = tmp_path / "no-extra" / "numpy"
    fake.mkdir(parents=True)
    (fake / "__init__.py").write_text("raise ImportError('No module named numpy')\n")
    env = {"PYTHONPATH": str(fake.parent)}
    for args in (["decode", "--profile", A3, "--format", "csv", str(flight_capture)],
                 ["plot", str(flight_capture), "--profile", A3, "-o", str(tmp_path / "p.html")],
                 ["watch", "--capture", str(flight_capture), "--profile", A3, "--duration", "0.1"]):
        done = osdkc(*args, env=env)
        assert done.returncode == 2 and "pip install 'osdk-conformance[flight]'" in done.stderr, (args, done.stderr)
        assert "Traceback" not in done.stderr and len(done.stderr.strip().splitlines()) == 1, done.stderr
    plain = osdkc("decode", "--profile", A3, str(flight_capture), env=env)   # the JSON lines need nothing of it
    assert plain.returncode == 0 and plain.stdout.count("\n") == 202, plain.stderr
    api_use = subprocess.run([sys.executable, "-c", "from osdk_conformance import api\ntry:\n    api.table(b'', 'a3-fw3.1')\n"
                              "except api.InputError as e:\n    print(e)"], capture_output=True, text=True, cwd=ROOT,
                             env={**os.environ, **env}, timeout=60)
    assert "pip install 'osdk-conformance[flight]'" in api_use.stdout, api_use.stderr


def test_the_bench_measures_the_table_the_records_and_the_csv_and_states_their_targets() -> None:
    from osdk_conformance.bench import flight_data, report
    c = corpus("a3-hour", seconds=5)
    got = flight_data.measure(c, timeout=120, repeats=1)
    assert got["ok"], got
    assert got["rows"] == c.frames and got["columns"] == 68 and got["runs"] == 1
    assert all(got[k] > 0 for k in ("table_seconds", "records_seconds", "csv_seconds"))
    targets = report._flight_targets(got)
    assert [t["target"].split(" in < ")[-1] for t in targets] == ["0.5 s", "2 s", "5 s"]
    assert all("extrapolated from 5 s" in t["measured"] for t in targets)
