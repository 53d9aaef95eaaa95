"""The byte streams `osdkc bench` decodes: deterministic, generated once, cached.

Corpora (CORPORA): `a3-hour`, one hour of a3-fw3.1 flight data at 100 Hz
with every item of the profile in every frame (360,000 frames), and one
`<profile>-mixed` corpus per profile, ten minutes of what a merged two-way
capture holds: the broadcast at 50 Hz with each item at its default rate
(so the flag word varies), movement control commands at 50 Hz, the
start-up exchange (version query, activation, frequency, control
authority) and then a version query every ten seconds, each with its ACK,
and line faults (noise runs, frames with a bad CRC-32, frames cut short).

The values follow sim.Vehicle flying a fixed, seeded schedule of movement
commands, so time stamps advance, attitude, velocity and position move and
the battery drains. They are modelled once per item, in the item's fullest
form; reference.values cuts them to the profile's variant and sends an item
nobody models at rest. Building each of 360,000 frames with the Construct
spec would take minutes, so each distinct frame shape is built once with
it (a Template) and the varying fields are then written into a copy at
offsets found by building the template twice with different sentinel
values: the layout and the wire format of each field come from the spec,
not from this file. A sample of the frames is decoded with the Construct
spec again to check the result.

What each corpus holds is known by construction, so its Corpus record
carries the counts every implementation must report: frames, errors and
garbage bytes. Faults are shaped so that those counts are exact: noise
never holds 0xAA, and a broken frame is used only when no 0xAA follows its
start byte (so the receiver's rescan finds nothing in it).

Files are cached under .cache/bench/, keyed by GENERATOR_VERSION and a
digest of this file and the spec sources, and written atomically (parallel
tests may ask for the same corpus at once).
"""
from __future__ import annotations

import functools
import hashlib
import json
import math
import os
import random
import struct
import tempfile
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Callable

from osdk_conformance._construct.control import encode_movement_control
from osdk_conformance._construct.payload import VERSION_ID_SIZE, payload, version_ack_value

from osdk_conformance.core.crc import crc16, crc32
from osdk_conformance.core.deframe import Frame, deframe
from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.paths import CACHE, SPEC
from osdk_conformance.core.rules import crc_params, profile as load_profile, profile_names
from osdk_conformance.core.wire import encode
from osdk_conformance.reference import values
from osdk_conformance.reference.decode import Decoder
from osdk_conformance.sim import simulator

GENERATOR_VERSION = 1
SEED = 0x05D4
CACHE_DIR = CACHE / "bench"
NOISE_FREE = 0x55  # stands in for 0xAA in noise: a start byte would make the counts depend on chance


@dataclass(frozen=True)
class CorpusSpec:
    name: str
    profile: str
    seconds: float
    broadcast_hz: int
    mixed: bool
    description: str


CORPORA: dict[str, CorpusSpec] = {c.name: c for c in (
    CorpusSpec("a3-hour", "a3-fw3.1", 3600, 100, False,
               "one hour of a3-fw3.1 broadcast at 100 Hz, every item in every frame"),
    *(CorpusSpec(f"{p}-mixed", p, 600, 50, True,
                 f"10 min of {p}: broadcast at 50 Hz (items at their default rates), movement control at 50 Hz, "
                 "command/ACK exchanges, line noise, bad CRC-32 and cut frames")
      for p in profile_names()),
)}


@dataclass(frozen=True)
class Corpus:
    """A corpus file and the counts its decoding must give (None: a file of unknown content)."""

    name: str
    profile: str
    seconds: float | None
    path: str
    bytes: int
    frames: int | None
    errors: int | None
    garbage_bytes: int | None
    description: str

    def expected(self) -> dict[str, int]:
        return {"bytes": self.bytes, "frames": self.frames, "errors": self.errors, "garbage_bytes": self.garbage_bytes}


# ---- templates ---------------------------------------------------------------------


def _sentinel(fmt: str, byte: int):
    return struct.unpack(fmt, bytes([byte]) * struct.calcsize(fmt))[0]


def _with(nested: dict, path: str, value) -> dict:
    """A copy of `nested` with the field at dotted `path` replaced."""
    head, _, rest = path.partition(".")
    out = dict(nested)
    out[head] = _with(nested[head], rest, value) if rest else value
    return out


def _crc_layout(n: int) -> list[tuple[Callable[[bytes], int], int, int, int, int]]:
    """(function, first covered, end covered, stored at, width) of both CRCs of an n-byte frame, from rules.yaml."""
    out = []
    for name, fn in (("crc16", crc16), ("crc32", crc32)):
        p = crc_params(name)
        out.append((fn, p.covers[0] % n, p.covers[1] % n + 1, p.stored_at[0] % n, p.width // 8))
    return out


class Template:
    """One frame shape, built once with the Construct spec; `frame()` writes
    new values of the chosen fields into a copy and recomputes both CRCs."""

    def __init__(self, build: Callable[[dict], bytes], base: dict, fields: dict[str, str]) -> None:
        self.raw = build(base)
        self.crcs = _crc_layout(len(self.raw))
        crcs = {at + k for _, _, _, at, width in self.crcs for k in range(width)}
        self.slots: list[tuple[struct.Struct, int]] = []
        for path, fmt in fields.items():
            a, b = build(_with(base, path, _sentinel(fmt, 0x11))), build(_with(base, path, _sentinel(fmt, 0x22)))
            diff = [i for i, (x, y) in enumerate(zip(a, b)) if x != y and i not in crcs]
            size = struct.calcsize(fmt)
            if len(a) != len(self.raw) or len(diff) != size or diff[-1] - diff[0] != size - 1:
                raise RuntimeError(f"corpus template: {path} is not a {size}-byte field ({fmt}) in the frame")
            self.slots.append((struct.Struct(fmt), diff[0]))
        self.paths = tuple(fields)

    def frame(self, given: dict) -> bytes:
        out = bytearray(self.raw)
        for (st, at), path in zip(self.slots, self.paths):
            st.pack_into(out, at, given[path])
        for fn, lo, hi, at, width in self.crcs:   # CRC-16 first: CRC-32 covers it
            out[at:at + width] = fn(bytes(out[lo:hi])).to_bytes(width, "little")
        return bytes(out)


# ---- what the aircraft does ------------------------------------------------------------

# Mode bytes of documented combinations in every profile (rules.yaml): horizontal
# velocity + vertical velocity + yaw rate, tilt + height + yaw angle, position offset +
# height + yaw angle; each with how to draw its setpoints.
_SCHEDULE = (
    (0x48, lambda r: (r.uniform(-5, 5), r.uniform(-5, 5), r.uniform(-1, 1), r.uniform(-30, 30))),
    (0x10, lambda r: (r.uniform(-10, 10), r.uniform(-10, 10), r.uniform(5, 40), r.uniform(-180, 180))),
    (0x90, lambda r: (r.uniform(-20, 20), r.uniform(-20, 20), r.uniform(5, 40), r.uniform(-180, 180))),
)
COMMAND_PERIOD = 20.0  # s between changes of the commanded motion


class Flight:
    """sim.Vehicle under a seeded schedule of movement commands."""

    def __init__(self, rng: random.Random) -> None:
        self.rng = rng
        self.vehicle = simulator.Vehicle()
        self.command = (0x48, (0.0, 0.0, 0.0, 0.0))
        self.next_change = 0.0
        self.t = 0.0

    def advance(self, t: float) -> None:
        if t >= self.next_change:
            mode, draw = self.rng.choice(_SCHEDULE)
            self.command = (mode, draw(self.rng))
            self.next_change = t + COMMAND_PERIOD
        mode, (x, y, z, yaw) = self.command
        self.vehicle.set_command(mode, x, y, z, yaw, t)   # renewed every tick, so it never times out
        self.vehicle.step(t - self.t, t)
        self.t = t


def _at_rest(prof) -> dict:
    """The items' fields that do not change from frame to frame, each item in
    its fullest form (fields not given are at rest: zero, false)."""
    zero3 = {"x": 0.0, "y": 0.0, "z": 0.0}
    gps = {"date": 20240601, "time": 120000, "longitude": 0, "latitude": 0, "height_msl": 0,
           "vel_n": 0.0, "vel_e": 0.0, "vel_d": 0.0}
    return {
        "time_stamp": {"time": 0, "nano_time": 0, "sync_flag": 0},
        "quaternion": {"q0": 1.0, "q1": 0.0, "q2": 0.0, "q3": 0.0},
        "acceleration": zero3, "angular_rate": zero3,
        "velocity": {**zero3, "data_valid": True, "sensor_id": 0, "reserved": 0},
        "position": {"latitude": 0.0, "longitude": 0.0, "altitude": 0.0, "height": 0.0, "gps_health": 5},
        "gps_detail": gps,
        "rtk_detail": {**gps, "longitude": 0.0, "latitude": 0.0, "height_msl": 0.0, "yaw": 0,
                       "position_flag": 50, "yaw_flag": 1},
        "magnetometer": {"x": 0, "y": 0, "z": -420},
        "rc": {"roll": 0, "pitch": 0, "yaw": 0, "throttle": 0, "mode": 8000, "gear": -4545},
        "gimbal": {"roll": 0.0, "pitch": -30.0, "yaw": 0.0,
                   "limit": {"pitch_limit": False, "roll_limit": False, "yaw_limit": False, "reserved": 0}},
        "flight_status": 2 if prof.flight_status_enum == "new" else 3,
        "battery": 100,
        "control_info": {"cur_mov_control_mode": 4, "control_device": 2, "onboard_requested": True,
                         "virtual_rc": False, "reserved": 0},
    }


def _item_values(f: Flight, t: float) -> dict:
    """Dotted path (item.field, or the item when it is one number) -> value of
    every field that changes from frame to frame, for time t (s); a profile
    whose variant of an item lacks the field leaves it out."""
    v = f.vehicle
    lat, lon = v.lat_lon()
    amsl = simulator.HOME_ALT + v.height
    q = simulator.euler_to_quaternion(v.roll, v.pitch, v.yaw)
    s = int(t)
    tod = 120000 + (s // 3600) * 10000 + (s // 60 % 60) * 100 + s % 60
    dlat, dlon = math.degrees(lat), math.degrees(lon)
    out = {
        "time_stamp.time": round(t * 400) & 0xFFFFFFFF, "time_stamp.nano_time": round(t * 1e9) & 0xFFFFFFFF,
        "position.latitude": lat, "position.longitude": lon, "position.altitude": amsl, "position.height": v.height,
        "gps_detail.time": tod, "gps_detail.longitude": round(dlon * 1e7), "gps_detail.latitude": round(dlat * 1e7),
        "gps_detail.height_msl": round(amsl * 1000),
        "rtk_detail.time": tod, "rtk_detail.longitude": dlon, "rtk_detail.latitude": dlat,
        "rtk_detail.height_msl": amsl, "rtk_detail.yaw": round(math.degrees(v.yaw)),
        "magnetometer.x": round(300 * math.cos(v.yaw)), "magnetometer.y": round(-300 * math.sin(v.yaw)),
        "rc.roll": round(800 * math.sin(t / 7)), "rc.pitch": round(800 * math.sin(t / 11)),
        "rc.yaw": round(500 * math.sin(t / 13)), "rc.throttle": round(300 * math.sin(t / 17)),
        "gimbal.pitch": -30.0 + 10 * math.sin(t / 5), "gimbal.yaw": math.degrees(v.yaw),
        "battery": max(0, 100 - int(t / 60)),
    }
    for i, c in enumerate(q):
        out[f"quaternion.q{i}"] = c
    for item, vec in (("acceleration", v.accel), ("velocity", (v.vn, v.ve, v.vu)), ("angular_rate", v.rates)):
        for axis, c in zip("xyz", vec):
            out[f"{item}.{axis}"] = c
    for item in ("gps_detail", "rtk_detail"):
        for name, c in (("vel_n", v.vn * 100), ("vel_e", v.ve * 100), ("vel_d", -v.vu * 100)):
            out[f"{item}.{name}"] = c
    return out


class Frames:
    """Templates of one profile's frames, built on first use."""

    def __init__(self, profile: str) -> None:
        self.profile = profile
        self.prof = load_profile(profile)
        self._payload = payload
        model = _at_rest(self.prof)
        self._base = {it: values.fit(profile, it, model[it]) if it in model else values.rest(profile, it)
                      for it in self.prof.flag_bits}
        self._broadcast: dict[tuple[str, ...], Template] = {}
        self._movement: dict[int, Template] = {}

    def broadcast(self, items: tuple[str, ...], seq: int, varying: dict) -> bytes:
        """The broadcast frame carrying `items`, with the fields `varying`
        (_item_values) gives; the same fields in every call."""
        tpl = self._broadcast.get(items)
        if tpl is None:
            tpl = self._broadcast[items] = self._broadcast_template(items, tuple(varying))
        varying["seq"] = seq
        return tpl.frame(varying)

    def _broadcast_template(self, items: tuple[str, ...], varying: tuple[str, ...]) -> Template:
        data = values.broadcast_data(self.profile, items, self._base)
        fields = {"seq": "<H"}
        for it in items:
            layout = values.fields(self.profile, it)
            for path in varying:
                item, _, name = path.partition(".")
                if item == it and name in layout:   # the profile's variant may lack it (FW 2.3 time stamp)
                    if layout[name].format is None:
                        raise RuntimeError(f"corpus template: {path} is a bit field, it cannot vary")
                    fields[path] = layout[name].format
        value = self._payload(2, 0, False, self.profile)

        def build(v: dict) -> bytes:
            body = {"data": {**data, **{it: v[it] for it in items}}}
            return encode(cmd_set=2, cmd_id=0, value=value.build({"body": body}), seq=v["seq"])

        return Template(build, {"seq": 0, **{it: data[it] for it in items}}, fields)

    def movement(self, mode: int, seq: int, setpoints: tuple[float, float, float, float]) -> bytes:
        tpl = self._movement.get(mode)
        if tpl is None:
            tpl = self._movement[mode] = self._movement_template(mode)
        return tpl.frame(dict(zip(("seq", "x", "y", "z", "yaw"), (seq, *setpoints))))

    def _movement_template(self, mode: int) -> Template:
        def build(v: dict) -> bytes:
            return encode(cmd_set=1, cmd_id=3, value=encode_movement_control(mode, v["x"], v["y"], v["z"], v["yaw"]),
                          seq=v["seq"])

        return Template(build, {"seq": 0, "x": 0.0, "y": 0.0, "z": 0.0, "yaw": 0.0},
                        {"seq": "<H", "x": "<f", "y": "<f", "z": "<f", "yaw": "<f"})

    def exchange(self, cmd: tuple[int, int], body: dict, ack: dict, session: int, seq: int) -> tuple[bytes, bytes]:
        """A command (onboard computer -> FC) and its ACK (FC -> onboard computer)."""
        request = encode(cmd_set=cmd[0], cmd_id=cmd[1], value=self._payload(*cmd, False, self.profile).build(
            {"body": body}), session=session, seq=seq)
        answer = encode(value=self._payload(*cmd, True, self.profile).build({"body": ack}), is_ack=True,
                        session=session, seq=seq)
        return request, answer


# ---- corpora --------------------------------------------------------------------------


CHECK_EVERY = 997  # frames between two decoded by the reference as a check of the templates


class _Writer:
    """Appends to the corpus file and keeps the counts a decoder must report."""

    def __init__(self, fh, profile: str) -> None:
        self.fh = fh
        self.reference = Decoder(profile)
        self.bytes = self.frames = self.errors = self.garbage = 0

    def frame(self, raw: bytes) -> None:
        if self.frames < 64 or self.frames % CHECK_EVERY == 0:
            self._check(raw)
        self._put(raw)
        self.frames += 1

    def _check(self, raw: bytes) -> None:
        events = list(deframe([raw]))
        ev = self.reference.event(events[0]) if len(events) == 1 and isinstance(events[0], Frame) else None
        if ev is None or ev["kind"] != "frame":
            raise RuntimeError(f"corpus generator: frame {self.frames} does not decode: {ev or events}")

    def noise(self, raw: bytes) -> None:
        self._put(raw)
        self.garbage += len(raw)

    def broken(self, raw: bytes) -> None:
        """A frame the receiver rejects once (bad CRC-32: nothing after its start byte is a start byte)."""
        self._put(raw)
        self.errors += 1
        self.garbage += len(raw) - 1

    def _put(self, raw: bytes) -> None:
        self.fh.write(raw)
        self.bytes += len(raw)


def _noise(rng: random.Random) -> bytes:
    return rng.randbytes(rng.randrange(1, 17)).replace(b"\xaa", bytes([NOISE_FREE]))


def _fault(rng: random.Random, frame: bytes) -> bytes | None:
    """The frame with a corrupt CRC-32 or cut short, when that makes exactly one rejection; else None."""
    if rng.random() < 0.5:
        out = frame[:-1] + bytes([frame[-1] ^ rng.randrange(1, 256)])
    else:
        out = frame[:rng.randrange(12, len(frame))]
    return out if 0xAA not in out[1:] else None


def _write(spec: CorpusSpec, seconds: float, w: _Writer) -> None:
    rng = random.Random(f"{SEED}:{spec.name}")
    frames = Frames(spec.profile)
    prof = frames.prof
    flight = Flight(random.Random(f"{SEED}:{spec.name}:flight"))
    hz = spec.broadcast_hz
    n = round(seconds * hz)
    every = {it: (round(hz / min(r, hz)) if r else 0) for it, r in prof.default_rates_hz.items()}
    all_items = tuple(prof.flag_bits)
    fc_seq = onboard_seq = 0
    session_seq = 0
    for i in range(n):
        t = i / hz
        flight.advance(t)
        if spec.mixed:
            items = tuple(it for it in all_items if every[it] and i % every[it] == 0)
        else:
            items = all_items
        raw = frames.broadcast(items, fc_seq, _item_values(flight, t))
        fc_seq = (fc_seq + 1) & 0xFFFF
        if not spec.mixed:
            w.frame(raw)
            continue
        if rng.random() < 0.01:
            w.noise(_noise(rng))
        broken = _fault(rng, raw) if rng.random() < 0.004 and i < n - hz else None
        if broken is not None:
            w.broken(broken)
        else:
            w.frame(raw)
        mode, setpoints = flight.command
        w.frame(frames.movement(mode, onboard_seq, setpoints))
        onboard_seq = (onboard_seq + 1) & 0xFFFF
        if i % (10 * hz) == 0:
            for cmd, body, ack in _exchanges(prof, i // (10 * hz)):
                session_seq = (session_seq + 1) & 0xFFFF
                for raw in frames.exchange(cmd, body, ack, 1 + session_seq % 31, session_seq):
                    w.frame(raw)


def _exchanges(prof, k: int) -> list[tuple[tuple[int, int], dict, dict]]:
    """The command/ACK exchanges of the k-th ten-second slot: the start-up sequence first, then heartbeats."""
    # every field the version ACK has in some profile; the profile's layout keeps its own (ERRATA E30)
    version = ((0x00, 0x00), {"arbitrary": 0},
               values.cut(version_ack_value(prof.name), {
                   "ack_code": "activated", "version_crc": 0x5A17C0DE,
                   "version_id": b"BENCH-ID".ljust(VERSION_ID_SIZE, b"\0"),
                   "version_name": b"BENCH-FC".ljust(32, b"\0")}))
    if k:
        return [version]
    return [
        version,
        ((0x00, 0x01), {"app_id": 1024, "api_level": 2, "sdk_version": prof.sdk_version, "bundle_id": bytes(32)},
         {"ack_code": "success"}),
        ((0x00, 0x10), {"codes": [4] * len(prof.flag_bits) + [5] * (16 - len(prof.flag_bits))},
         {"ack_code": "success"}),
        ((0x01, 0x00), {"request": 1}, {"ack_code": 3}),
        ((0x01, 0x00), {"request": 1}, {"ack_code": 2}),
    ]


@functools.cache
def _spec_digest() -> str:
    h = hashlib.sha256(Path(__file__).read_bytes())
    # what shapes the values (reference.values) and moves them (sim.Vehicle) as well as the spec
    for p in [Path(values.__file__), Path(simulator.__file__), *sorted((SPEC / "construct").glob("*.py")),
              SPEC / "rules.yaml"]:
        h.update(p.read_bytes())
    return h.hexdigest()[:12]


def corpus(name: str, seconds: float | None = None, cache_dir: Path | None = None) -> Corpus:
    """The corpus `name` (CORPORA), `seconds` long (default: its own length): from the cache, or generated."""
    try:
        spec = CORPORA[name]
    except KeyError:
        raise UsageError(f"no corpus {name!r} (known: {', '.join(CORPORA)})") from None
    seconds = spec.seconds if seconds is None else seconds
    if not seconds > 0:
        raise UsageError(f"a corpus must last more than 0 seconds, got {seconds}")
    cache = Path(cache_dir or CACHE_DIR)
    stem = f"{name}-{seconds:g}s-v{GENERATOR_VERSION}-{_spec_digest()}"
    path, meta = cache / f"{stem}.bin", cache / f"{stem}.json"
    if path.exists() and meta.exists():
        return Corpus(**{**json.loads(meta.read_text()), "path": str(path)})
    cache.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=cache, prefix=f".{stem}.")
    try:
        with os.fdopen(fd, "wb", buffering=1 << 20) as fh:
            w = _Writer(fh, spec.profile)
            _write(spec, seconds, w)
        c = Corpus(name=name, profile=spec.profile, seconds=seconds, path=str(path), bytes=w.bytes,
                   frames=w.frames, errors=w.errors, garbage_bytes=w.garbage, description=spec.description)
        os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise
    meta_tmp = meta.with_suffix(f".json.{os.getpid()}")
    meta_tmp.write_text(json.dumps(asdict(c), indent=2) + "\n")
    os.replace(meta_tmp, meta)
    for old in cache.glob(f"{name}-{seconds:g}s-v*"):   # earlier generators' or specs' copies
        if old.stem != stem and old.suffix in (".bin", ".json"):
            old.unlink(missing_ok=True)
    return c


def user_input(path: str, profile: str) -> Corpus:
    """A capture of the user's own (raw bytes): the implementations are checked against each other only."""
    try:
        size = os.stat(path).st_size
        with open(path, "rb"):
            pass
    except OSError as e:
        raise UsageError(f"cannot read {path}: {e.strerror or e}") from None
    if not os.path.isfile(path):
        raise UsageError(f"{path} is not a file")
    return Corpus(name=Path(path).name, profile=profile, seconds=None, path=str(Path(path).resolve()), bytes=size,
                  frames=None, errors=None, garbage_bytes=None, description=f"the file {path}")
