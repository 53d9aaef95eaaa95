"""`osdkc sim`: a simulated flight controller on a pseudo-terminal or TCP port.

It speaks the device side of the OPEN protocol that the acceptance suite
(`osdkc device`) checks: flight data broadcast in a chosen wire profile at
the rates the frequency command sets (defaults from spec/rules.yaml),
answers to version query, activation, set frequency, obtain/release control
(the first request answers "in progress", the repeat succeeds; obtaining
needs the RC mode switch in F) and movement control, which drives a small
motion model so that commanded attitude, velocity, yaw, yaw rate, position
offsets, height and thrust show up in the broadcast state.

Every frame it sends is built with the Construct spec (osdk_construct).
Fault injection (per broadcast frame, reproducible with --seed): noise
bytes, bit flips, dropped bytes, truncated frames, bad CRCs, duplicated
frames, jitter, rate drift, implausible values, another profile's layout,
a stalled stream, an unplugged-and-back port, a baud rate mismatch. Link
faults for `osdkc doctor` to tell apart: an FC that never reads its RX line
(--deaf), one that broadcasts nothing until activated, a loopback line with
no FC on it, a different baud rate per direction (--rx-baud).
Planted firmware bugs (--bug, sim/bugs.py) model receive-path bugs of real
flight controllers for a device fuzzer to find; SIGHUP restarts it (a power
cycle), as a user brings a hung flight controller back.
"""
from __future__ import annotations

import argparse
import contextlib
import errno
import fcntl
import json
import math
import os
import random
import select
import signal
import socket
import struct
import subprocess
import sys
import termios
import time
import tty
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path

from osdk_conformance._construct.payload import VERSION_ID_SIZE, osdk_payload, version_ack_value

from osdk_conformance.core.deframe import Deframer, Frame
from osdk_conformance.core.errors import UsageError, exit_status_of_signal
from osdk_conformance.core.options import (baud_rate, non_negative_float, non_negative_int, probability, rate_change,
                                           tcp_port, uint32)
from osdk_conformance.core.priority import keep_priority
from osdk_conformance.core.rules import hz_of_code, profile as load_profile, profile_names
from osdk_conformance.core.tty import split_speeds
from osdk_conformance.core.wire import encode, key_option, open_frame
from osdk_conformance.reference.values import broadcast_data, cut
from osdk_conformance.sim.bugs import BUGS, REBOOT_PAUSE_S, PlantedBugs

R_EARTH = 6378137.0
G = 9.80665
HOME_LAT, HOME_LON = math.radians(22.5431), math.radians(113.9425)
HOME_ALT = 52.0
COMMAND_TIMEOUT = 0.5   # s without movement control: hover
TAU = 0.25              # s, first-order lag of every controlled quantity
RC_MODE = {"P": -8000, "A": 0, "F": 8000}
FAULTS = ("noise", "bitflip", "drop_bytes", "truncate", "bad_crc", "duplicate")
VERSION_ID = b"SIM-000001"
"""The FW 3.1 version ACK's version ID: 10 characters and one NUL, the one
form that DJI's fixed reader (11 bytes) and its scanning reader (up to the
first NUL) read alike (ERRATA E30)."""
VERSION_CRC = 0x5A17C0DE
"""No 0x00 byte: the scanning reader would end the CRC-and-ID run inside it."""
HANDSHAKE = frozenset({(0x00, 0x00), (0x00, 0x01)})
"""Version query and activation: their ACKs go out plain even with --encrypt,
because DJI hosts install the key only once activation succeeded (ERRATA E30)."""


class _VersionNames(Mapping):
    """Profile id -> the version name the simulator answers a version query
    with: rules.yaml's `version_ack.version_name`, DJI's form."""

    def __getitem__(self, name: str) -> bytes:
        if name not in profile_names():
            raise KeyError(name)
        return load_profile(name).version_name.encode()

    def __iter__(self) -> Iterator[str]:
        return iter(profile_names())

    def __len__(self) -> int:
        return len(profile_names())


VERSION_NAME: Mapping[str, bytes] = _VersionNames()


def _wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


def _clamp(v: float, lim: float) -> float:
    return max(-lim, min(lim, v))


def euler_to_quaternion(roll: float, pitch: float, yaw: float) -> tuple[float, float, float, float]:
    cr, sr = math.cos(roll / 2), math.sin(roll / 2)
    cp, sp = math.cos(pitch / 2), math.sin(pitch / 2)
    cy, sy = math.cos(yaw / 2), math.sin(yaw / 2)
    return (cr * cp * cy + sr * sp * sy, sr * cp * cy - cr * sp * sy,
            cr * sp * cy + sr * cp * sy, cr * cp * sy - sr * sp * cy)


def quaternion_to_euler(q0: float, q1: float, q2: float, q3: float) -> tuple[float, float, float]:
    roll = math.atan2(2 * (q0 * q1 + q2 * q3), 1 - 2 * (q1 * q1 + q2 * q2))
    pitch = math.asin(max(-1.0, min(1.0, 2 * (q0 * q2 - q3 * q1))))
    yaw = math.atan2(2 * (q0 * q3 + q1 * q2), 1 - 2 * (q2 * q2 + q3 * q3))
    return roll, pitch, yaw


@dataclass
class Vehicle:
    """Point-mass multirotor in the air, NEU ground frame, first-order lags."""

    n: float = 0.0
    e: float = 0.0
    height: float = 10.0
    vn: float = 0.0
    ve: float = 0.0
    vu: float = 0.0
    roll: float = 0.0
    pitch: float = 0.0
    yaw: float = 0.0
    rates: tuple[float, float, float] = (0.0, 0.0, 0.0)
    accel: tuple[float, float, float] = (0.0, 0.0, 0.0)
    command: dict | None = None
    command_t: float = -1e9
    hold_yaw: float = 0.0

    def set_command(self, mode: int, x: float, y: float, z: float, yaw: float, now: float) -> None:
        hl, vl, yl, frame = mode >> 6 & 3, mode >> 4 & 3, mode >> 3 & 1, mode >> 1 & 3
        cmd = {"h": hl, "v": vl, "y": yl, "body": frame == 1, "x": x, "yv": y, "z": z, "yaw": yaw}
        if hl == 2:  # position offset: target = here + offset (rotated when in the body frame)
            dn, de = self._to_ground(x, y, cmd["body"])
            cmd["target"] = (self.n + dn, self.e + de)
        self.command, self.command_t = cmd, now

    def active_command(self, now: float) -> dict | None:
        return self.command if self.command and now - self.command_t <= COMMAND_TIMEOUT else None

    def _to_ground(self, x: float, y: float, body: bool) -> tuple[float, float]:
        if not body:
            return x, y
        c, s = math.cos(self.yaw), math.sin(self.yaw)
        return c * x - s * y, s * x + c * y

    def step(self, dt: float, now: float) -> None:
        if dt <= 0:
            return
        a = 1 - math.exp(-dt / TAU)
        cmd = self.active_command(now)
        roll_t = pitch_t = 0.0
        vn_t = ve_t = vu_t = 0.0
        yaw_rate_t = None
        if cmd is None:
            yaw_t = self.hold_yaw
        else:
            if cmd["h"] == 0:  # tilt angles (deg): attitude follows, velocity builds up from the tilt
                roll_t, pitch_t = math.radians(_clamp(cmd["x"], 30)), math.radians(_clamp(cmd["yv"], 30))
                fwd, right = -G * math.tan(pitch_t) * 0.5, G * math.tan(roll_t) * 0.5
                vn_t, ve_t = self._to_ground(fwd, right, True)
            elif cmd["h"] == 1:
                vn_t, ve_t = self._to_ground(_clamp(cmd["x"], 10), _clamp(cmd["yv"], 10), cmd["body"])
            elif cmd["h"] == 2:
                tn, te = cmd["target"]
                vn_t, ve_t = _clamp((tn - self.n) * 1.5, 10), _clamp((te - self.e) * 1.5, 10)
            if cmd["v"] == 0:
                vu_t = _clamp(cmd["z"], 4)
            elif cmd["v"] == 1:
                vu_t = _clamp((cmd["z"] - self.height) * 1.5, 4)
            elif cmd["v"] == 2:
                vu_t = _clamp((cmd["z"] - 40.0) / 10.0, 4)
            if cmd["y"] == 0:
                yaw_t = math.radians(cmd["yaw"])
                self.hold_yaw = yaw_t
            else:
                yaw_rate_t = math.radians(_clamp(cmd["yaw"], 100))
        if cmd is None or cmd["h"] != 0:
            # cosmetic tilt from the velocity error, small enough not to matter
            c, s = math.cos(self.yaw), math.sin(self.yaw)
            en, ee = vn_t - self.vn, ve_t - self.ve
            pitch_t = _clamp(-(c * en + s * ee) * 0.02, 0.2)
            roll_t = _clamp((-s * en + c * ee) * 0.02, 0.2)
        if yaw_rate_t is None:
            yaw_rate_t = _clamp(_wrap(yaw_t - self.yaw) / TAU, math.radians(150))
        else:
            self.hold_yaw = self.yaw
        old_v = (self.vn, self.ve, self.vu)
        old_att = (self.roll, self.pitch)
        self.vn += (vn_t - self.vn) * a
        self.ve += (ve_t - self.ve) * a
        self.vu += (vu_t - self.vu) * a
        if self.height <= 0 and self.vu < 0:
            self.vu = 0.0
        self.n += self.vn * dt
        self.e += self.ve * dt
        self.height = max(0.0, self.height + self.vu * dt)
        self.roll += (roll_t - self.roll) * a
        self.pitch += (pitch_t - self.pitch) * a
        yaw_rate = self.rates[2] + (yaw_rate_t - self.rates[2]) * min(1.0, a * 3)
        self.yaw = _wrap(self.yaw + yaw_rate * dt)
        self.rates = ((self.roll - old_att[0]) / dt, (self.pitch - old_att[1]) / dt, yaw_rate)
        self.accel = ((self.vn - old_v[0]) / dt, (self.ve - old_v[1]) / dt, (self.vu - old_v[2]) / dt)

    def lat_lon(self) -> tuple[float, float]:
        lat = HOME_LAT + self.n / R_EARTH
        return lat, HOME_LON + self.e / (R_EARTH * math.cos(HOME_LAT))


# --------------------------------------------------------------------------
# Transports


class PtyTransport:
    """A pseudo-terminal; the slave side is what a client opens. With `link`,
    a symlink names the slave, so an unplugged-and-back port keeps its name."""

    def __init__(self, link: str | None = None) -> None:
        self.link = link
        self.master = self.slave = -1
        self.unplugged_slave = -1
        self._open()

    def _open(self) -> None:
        self.master, self.slave = os.openpty()
        tty.setraw(self.slave)   # no echo, no line discipline, before anyone opens it
        os.set_blocking(self.master, False)
        self.path = os.ttyname(self.slave)
        if self.link:
            tmp = f"{self.link}.tmp{os.getpid()}"
            try:
                os.unlink(tmp)
            except FileNotFoundError:
                pass
            os.symlink(self.path, tmp)
            os.replace(tmp, self.link)

    @property
    def url(self) -> str:
        return self.link or self.path

    def read_fds(self) -> list[int]:
        return [self.master] if self.master >= 0 else []

    def connected(self) -> bool:
        return self.master >= 0

    def on_readable(self, fd: int) -> bytes:
        try:
            return os.read(self.master, 65536)
        except BlockingIOError:
            return b""
        except OSError as e:
            if e.errno == errno.EIO:   # no client has the slave open: nothing to read
                return b""
            raise

    def write(self, data: bytes) -> int:
        if self.master < 0:
            return 0
        try:
            return os.write(self.master, data)
        except BlockingIOError:
            return 0
        except OSError as e:
            if e.errno == errno.EIO:
                return 0
            raise

    def pending_input(self) -> int:
        """Bytes written by us and not yet read by the client."""
        if self.slave < 0:
            return 0
        try:
            return struct.unpack("i", fcntl.ioctl(self.slave, termios.FIONREAD, b"\0\0\0\0"))[0]
        except OSError:
            return 0

    def speeds(self) -> tuple[int, int] | None:
        """The client's (input, output) speed: termios keeps both, and a
        client may set them apart (what it receives at, what it sends at)."""
        try:
            cflag = termios.tcgetattr(self.slave)[2]
        except (OSError, termios.error):
            return None
        return split_speeds(cflag)

    def unplug(self) -> None:
        # The name goes first, and the slave stays open until the port is
        # back: a host that reopens the port in between finds no such file,
        # and the kernel cannot give this terminal's number to another
        # program's new pseudo-terminal, which a reopening host would reach.
        if self.link:
            try:
                os.unlink(self.link)
            except FileNotFoundError:
                pass
        if self.master >= 0:
            os.close(self.master)
        if self.slave >= 0:
            self._release_unplugged()
            self.unplugged_slave = self.slave
        self.master = self.slave = -1

    def _release_unplugged(self) -> None:
        if self.unplugged_slave >= 0:
            os.close(self.unplugged_slave)
            self.unplugged_slave = -1

    def replug(self) -> None:
        self._open()
        self._release_unplugged()

    def close(self) -> None:
        self.unplug()
        self._release_unplugged()


class TcpTransport:
    """A TCP listener for pyserial's socket:// URLs; one client at a time."""

    def __init__(self, host: str, port: int) -> None:
        self.host = host
        self.port = port
        self.client: socket.socket | None = None
        self.listener: socket.socket | None = None
        self._listen()

    def _listen(self) -> None:
        s = socket.socket(socket.AF_INET, socket.SOCK_STREAM)
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        s.bind((self.host, self.port))
        s.listen(1)
        s.setblocking(False)
        self.port = s.getsockname()[1]
        self.listener = s

    @property
    def url(self) -> str:
        return f"socket://{self.host}:{self.port}"

    def read_fds(self) -> list[int]:
        fds = [self.listener.fileno()] if self.listener else []
        if self.client:
            fds.append(self.client.fileno())
        return fds

    def connected(self) -> bool:
        return self.client is not None

    def on_readable(self, fd: int) -> bytes:
        if self.listener and fd == self.listener.fileno():
            try:
                conn, _ = self.listener.accept()
            except BlockingIOError:
                return b""
            if self.client:
                conn.close()   # one client at a time, like a serial port
            else:
                conn.setblocking(False)
                conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
                self.client = conn
            return b""
        if self.client is None:
            return b""
        try:
            data = self.client.recv(65536)
        except BlockingIOError:
            return b""
        except OSError:
            data = b""
        if not data:
            self.client.close()
            self.client = None
        return data

    def write(self, data: bytes) -> int:
        if self.client is None:
            return 0
        try:
            return self.client.send(data)
        except BlockingIOError:
            return 0
        except OSError:
            self.client.close()
            self.client = None
            return 0

    def pending_input(self) -> int:
        return 0

    def speeds(self) -> tuple[int, int] | None:
        return None

    def unplug(self) -> None:
        if self.client:
            self.client.close()
            self.client = None
        if self.listener:
            self.listener.close()
            self.listener = None

    def replug(self) -> None:
        self._listen()

    def close(self) -> None:
        self.unplug()


# --------------------------------------------------------------------------
# The flight controller


@dataclass
class SimConfig:
    profile: str = "a3-fw3.1"
    seed: int | None = None
    app_id: int | None = None
    key: bytes | None = None
    encrypt: bool = False
    encrypt_handshake: bool = False   # with encrypt: the version and activation ACKs too (no DJI host reads them)
    rc_mode: str = "F"
    faults: dict[str, float] = field(default_factory=dict)
    jitter_ms: float = 0.0
    rate_drift: float = 0.0
    implausible: bool = False
    wrong_profile: str | None = None
    stall_at: float | None = None
    exit_after: float | None = None
    unplug_at: float | None = None
    unplug_on_release: bool = False   # unplug when the first release-control request arrives, unheard
    unplug_for: float = 1.0
    baud: int | None = None
    rx_baud: int | None = None        # the rate it reads at, when not `baud` (a different rate per direction)
    deaf: bool = False                # it never reads its RX line
    silent_until_activated: bool = False   # no broadcast before a successful activation
    loopback: bool = False            # no FC: the line returns what the host sends
    hold: bool = False
    rates: dict[str, int] | None = None
    log_broadcast: str | None = None   # JSON lines: SEQ and value (before fault injection) of every broadcast sent
    log_acks: str | None = None        # JSON lines: every ACK sent, with the command it answers
    bugs: tuple[str, ...] = ()         # planted firmware bugs (sim/bugs.py BUGS); none: a healthy flight controller


# A pty counts only the bytes that reached the client's side; bytes the
# kernel is still moving there do not show, and closing the port loses
# them. So the queue must stay empty for a moment before the stop, and a
# client that reads nothing is given up only after a pause longer than a
# loaded machine leaves a reader unscheduled (0.2 s lost frames at the end
# of soak runs).
DRAIN_SETTLE_S = 0.05
DRAIN_STUCK_S = 1.0

BEHIND_S = 2.0
"""How late the run loop may fall behind its frame schedule and still send
the frames it owes (stamped with the times they were due, in a burst): a
process starved of CPU on a busy host stands for a healthy FC whose frames
were delayed on the way. Further behind, it was suspended, and the frames in
between are skipped as a halted FC would."""

MAX_WAIT_S = 0.05
"""The longest the run loop sleeps in select(): a restart requested from a
signal handler or another thread cannot wake it, so this bounds how late the
restart (and a stop) is acted on."""

ANSWER_S = 0.02
"""With --rx-baud, how long after the command an ACK leaves: a real FC's
processing time, which the simulator otherwise skips. A host that writes at
one rate, drains and switches to the other has switched by then, as on a real
line; an ACK sent at once could beat the switch and reach it garbled."""


class Simulator:
    def __init__(self, cfg: SimConfig, transport) -> None:
        self.cfg = cfg
        self.t = transport
        self.rng = random.Random(cfg.seed)
        self.profile = load_profile(cfg.profile)
        self.wire_profile = load_profile(cfg.wrong_profile or cfg.profile)
        self._payload = osdk_payload
        self.rates = dict(self.profile.default_rates_hz)
        if cfg.rates:
            self.rates.update(cfg.rates)
        self.vehicle = Vehicle()
        self.deframer = Deframer()
        self.activated = False
        self.control = "rc"            # rc | onboard
        self.pending: str | None = None  # "obtain" | "release": the first request was answered "in progress"
        self.onboard_requested = False
        self.seq = 0
        self.outbuf = bytearray()
        self.answers: list[tuple[float, bytes]] = []   # with --rx-baud: (when it leaves, ACK frame), see ANSWER_S
        self.stats = {"frames_sent": 0, "broadcast_frames": 0, "acks_sent": 0, "bytes_sent": 0,
                      "frames_dropped_tx_full": 0, "broadcast_skipped_behind": 0, "commands_received": 0,
                      "frames_rejected": 0,
                      "movement_commands": 0, "movement_commands_encrypted": 0, "restarts": 0,
                      "faults": {f: 0 for f in FAULTS},
                      # Every byte the host sent is accounted for: heard as part of a frame, or
                      # discarded for a reason (not_a_frame is settled at exit, see rx_accounting).
                      "rx_bytes": 0, "rx_bytes_discarded": {"baud_mismatch": 0, "stalled": 0, "deaf": 0,
                                                            "not_a_frame": 0},
                      "bytes_echoed": 0, "bytes_echo_lost": 0}
        if cfg.silent_until_activated:
            self.stats["activated_after_s"] = None
        self._rx_frame_bytes = 0
        self.running = True
        self.broadcasting = not cfg.hold   # released by SIGUSR1; see _broadcasts for the rest
        self.start = time.monotonic()
        self.last_step = self.start
        self.frame_index = 0
        self.next_frame = self.start
        self.send_at = self.start
        self.last_stamp = self.start
        self.battery = 90.0
        self.unplugged_until: float | None = None
        # whether the client's output speed was the rate this FC reads at, at the start of the run
        # loop's last pass and of this one (on_received)
        self.sent_at_rx_rate = (False, False)
        self.last_ack: dict[int, tuple[int, bytes, bytes]] = {}   # session -> (seq, command frame, ACK frame)
        self._current_raw = b""
        self.boot = self.start   # the time stamp item counts from here; a reboot moves it
        self.resume_at: float | None = None   # a reboot keeps it deaf and silent until then
        # Requested by request_restart (maybe in a signal handler or another thread),
        # acted on by the run loop only: the one place the state changes.
        self.restart_requests = 0
        self.restart_requests_done = 0
        self.bugs = PlantedBugs(tuple(cfg.bugs), self.stats, self.start) if cfg.bugs else None
        self.broadcast_log = open(cfg.log_broadcast, "w", buffering=1) if cfg.log_broadcast else None
        self.ack_log = open(cfg.log_acks, "w", buffering=1) if cfg.log_acks else None
        self._current_value = b""

    # ---- broadcast -------------------------------------------------------

    def frame_rate(self) -> float:
        return max(self.rates.values(), default=0)

    def _broadcasts(self) -> bool:
        """Not held (--hold), a flight controller on the line (not
        --loopback) and, with --silent-until-activated, activated: asked each
        time rather than switched on at activation, so that a reboot, which
        loses the activation, makes such an FC silent again."""
        return (self.broadcasting and not self.cfg.loopback
                and (self.activated or not self.cfg.silent_until_activated))

    def _due_items(self) -> list[str]:
        base = self.frame_rate()
        out = []
        for item in self.wire_profile.flag_bits:
            hz = self.rates.get(item, 0)
            if hz > 0 and self.frame_index % max(1, round(base / hz)) == 0:
                out.append(item)
        return out

    def broadcast_value(self, items: list[str], now: float, stamp: float | None = None) -> bytes:
        """The broadcast payload carrying `items` at time `now`, its time
        stamp item saying `stamp` (default `now`). The state is
        modelled once, each item in its fullest form; the wire profile's
        layout keeps the fields its variants have (reference.values), and an
        item not modelled here goes out at rest."""
        p = self.wire_profile
        v = self.vehicle
        bad = self.cfg.implausible
        elapsed = now - self.start
        lat, lon = v.lat_lon()
        q = euler_to_quaternion(v.roll, v.pitch, v.yaw)
        if bad:
            q = tuple(2 * c for c in q)
        stamp = now if stamp is None else stamp
        ticks = int((stamp - self.boot) * 400) & 0xFFFFFFFF
        if bad:
            ticks = (0x7FFFFFFF - ticks * 3) & 0xFFFFFFFF
        in_control = self.control == "onboard"
        cmd = v.active_command(now) if in_control else None
        mode_value = 0
        if cmd and cmd["h"] < 3 and cmd["v"] < 3:
            mode_value = 1 + 6 * cmd["v"] + 2 * cmd["h"] + cmd["y"]
        amsl = HOME_ALT + v.height
        date, tod = 20240601, 120000 + int(elapsed) % 60
        model = {
            "time_stamp": {"time": ticks, "nano_time": int(stamp * 1e9) & 0xFFFFFFFF, "sync_flag": 0},
            "quaternion": dict(zip(("q0", "q1", "q2", "q3"), q)),
            "acceleration": dict(zip("xyz", v.accel)),
            "velocity": {"x": v.vn, "y": v.ve, "z": v.vu, "data_valid": True, "sensor_id": 0, "reserved": 0},
            "angular_rate": dict(zip("xyz", v.rates)),
            "position": {"latitude": lat, "longitude": lon, "altitude": amsl, "height": v.height,
                         "gps_health": 9 if bad else 5},
            "gps_detail": {"date": date, "time": tod, "longitude": round(math.degrees(lon) * 1e7),
                           "latitude": round(math.degrees(lat) * 1e7), "height_msl": round(amsl * 1000),
                           "vel_n": v.vn * 100, "vel_e": v.ve * 100, "vel_d": -v.vu * 100},
            "rtk_detail": {"date": date, "time": tod, "longitude": math.degrees(lon), "latitude": math.degrees(lat),
                           "height_msl": amsl, "vel_n": v.vn * 100, "vel_e": v.ve * 100, "vel_d": -v.vu * 100,
                           "yaw": round(math.degrees(v.yaw)), "position_flag": 50, "yaw_flag": 1},
            "magnetometer": {"x": round(300 * math.cos(v.yaw)), "y": round(-300 * math.sin(v.yaw)), "z": -420},
            "rc": {"roll": 20000 if bad else 0, "pitch": 0, "yaw": 0, "throttle": 0,
                   "mode": 1234 if bad else RC_MODE[self.cfg.rc_mode], "gear": -4545},
            "gimbal": {"roll": 0.0, "pitch": -30.0, "yaw": math.degrees(v.yaw),
                       "limit": {"pitch_limit": False, "roll_limit": False, "yaw_limit": False, "reserved": 0}},
            "flight_status": 77 if bad else (2 if self.profile.flight_status_enum == "new" else 3),
            "battery": 150 if bad else int(self.battery),
            "control_info": {"cur_mov_control_mode": mode_value,
                             "control_device": 5 if bad else (2 if in_control else 0),
                             "onboard_requested": self.onboard_requested, "virtual_rc": False, "reserved": 0},
        }
        data = broadcast_data(p.name, items, model)
        return self._payload(2, 0, False, p.name).build({"body": {"data": data}})

    def _next_seq(self) -> int:
        s = self.seq
        self.seq = (self.seq + 1) & 0xFFFF
        return s

    def emit_broadcast(self, now: float, stamp: float | None = None) -> None:
        """One broadcast frame, its time stamp item saying `stamp`: when the
        frame was due (a real FC's firmware composes it on its own clock; a
        late wake-up of this process stands for delay on the way, not for an
        FC that broke its cadence), the injected --jitter included."""
        items = self._due_items()
        self.frame_index += 1
        if not items:
            return
        value = self.broadcast_value(items, now, stamp)
        seq = self._next_seq()
        frame = encode(cmd_set=2, cmd_id=0, value=value, seq=seq,
                       key=self.cfg.key if self.cfg.encrypt else None)
        self.stats["broadcast_frames"] += 1
        queued = self.stats["frames_sent"]
        self._send(self._inject(frame), frames=1)
        if self.broadcast_log and self.stats["frames_sent"] > queued:
            self.broadcast_log.write(json.dumps({"seq": seq, "value": value.hex()}) + "\n")

    def _inject(self, frame: bytes) -> bytes:
        f, rng = self.cfg.faults, self.rng
        out = bytearray(frame)
        if f.get("bitflip") and rng.random() < f["bitflip"]:
            bit = rng.randrange(len(out) * 8)
            out[bit // 8] ^= 1 << (bit % 8)
            self.stats["faults"]["bitflip"] += 1
        if f.get("bad_crc") and rng.random() < f["bad_crc"] and len(out) > 12:
            out[-1] ^= rng.randrange(1, 256)
            self.stats["faults"]["bad_crc"] += 1
        if f.get("drop_bytes") and rng.random() < f["drop_bytes"]:
            del out[rng.randrange(len(out))]
            self.stats["faults"]["drop_bytes"] += 1
        if f.get("truncate") and rng.random() < f["truncate"] and len(out) > 1:
            del out[rng.randrange(1, len(out)):]
            self.stats["faults"]["truncate"] += 1
        if f.get("noise") and rng.random() < f["noise"]:
            out[0:0] = rng.randbytes(rng.randrange(1, 17))
            self.stats["faults"]["noise"] += 1
        if f.get("duplicate") and rng.random() < f["duplicate"]:
            out += frame
            self.stats["faults"]["duplicate"] += 1
        return bytes(out)

    def _send(self, data: bytes, frames: int) -> None:
        if not self.t.connected() or self.unplugged_until is not None:
            return
        if self.outbuf:
            # the client's buffer is full (nobody reads, or too slowly): a UART
            # goes on sending and these bytes are lost. Only the one frame the
            # buffer could not take (or its rest) is kept, so none arrives in part;
            # a queue of whole frames would reach a client that opens the port
            # later as seconds of stale frames no flight controller sends.
            self.stats["frames_dropped_tx_full"] += frames
            return
        if not self._at_speed(sending=True):
            data = bytes((b * 37 + 11) & 0xFF for b in data)   # what a receiver at the wrong speed sees
        self.outbuf += data
        self.stats["frames_sent"] += frames
        self.stats["bytes_sent"] += len(data)
        self._flush()

    def _flush(self) -> None:
        while self.outbuf:
            n = self.t.write(bytes(self.outbuf))
            if n <= 0:
                break
            del self.outbuf[:n]

    # ---- commands --------------------------------------------------------

    def on_bytes(self, data: bytes, now: float) -> None:
        if self.bugs is not None:
            self._on_bytes_with_bugs(data, now)
            return
        for ev in self.deframer.feed(data):
            if isinstance(ev, Frame):
                self._rx_frame_bytes += len(ev.raw)
                self.on_frame(ev.raw, now)
            else:
                self.stats["frames_rejected"] += 1

    def _on_bytes_with_bugs(self, data: bytes, now: float) -> None:
        """on_bytes with planted bugs: a frame that hangs or reboots the
        simulator is the last one heard; the bytes after it in this read are
        lost as to a stalled one."""
        bugs = self.bugs
        bugs.fed(data)
        for ev in self.deframer.feed(data):
            halted = bugs.overrun_by(ev, now)
            reboot = False
            if isinstance(ev, Frame):
                self._rx_frame_bytes += len(ev.raw)
                reboot = not halted and bugs.resets_on(ev.raw, now)
                if not (halted or reboot):
                    self.on_frame(ev.raw, now)
            else:
                self.stats["frames_rejected"] += 1
            if halted or reboot:
                self.stats["rx_bytes_discarded"]["stalled"] += bugs.received_after(ev)
                if reboot:
                    self._reboot(bugs.resume_at)
                    bugs.rebooted()
                return
            bugs.consumed(ev)
        bugs.overrun_pending(now)

    def _reboot(self, resume_at: float) -> None:
        """What every reboot (a planted reset, a restart) loses: the SEQ, the
        clock, activation, control authority, the rates, the commands, the
        receive buffer. It is deaf and silent until `resume_at`, when its
        clock starts again. The planted bugs' own state is the caller's to
        reset (PlantedBugs.rebooted, .power_cycled)."""
        self.resume_at = resume_at
        self.seq = 0
        self.boot = resume_at
        self.activated = False
        self.control = "rc"
        self.pending = None
        self.onboard_requested = False
        self.rates = {**self.profile.default_rates_hz, **(self.cfg.rates or {})}
        self.frame_index = 0
        self.vehicle.command = None
        self.last_ack.clear()
        self.answers.clear()
        self.deframer = Deframer()

    def request_restart(self) -> int:
        """Ask for a restart, a power cycle, as a user pulls the power of a
        hung flight controller: the run loop performs it within MAX_WAIT_S.
        Only counts the request, so it is safe in a signal handler and from
        another thread. Returns the request's number: the restart asked for
        is done once `restart_requests_done` has reached it. Requests made
        before the loop gets to them make one restart."""
        self.restart_requests += 1
        return self.restart_requests

    def _power_cycle(self, now: float) -> None:
        """A restart: a reboot that also ends a hang or a wedged command
        handler, loses what was still queued to send, and resumes after
        REBOOT_PAUSE_S like a boot, with or without planted bugs."""
        if self.bugs is not None:
            self.bugs.power_cycled()
        self.outbuf.clear()
        self._reboot(now + REBOOT_PAUSE_S)
        self.stats["restarts"] += 1

    def on_received(self, data: bytes, now: float, stalled: bool) -> None:
        """Bytes read from the host. The line speed is looked at now, when
        they arrive: a UART hears a host that writes right after setting its
        speed, so a check on a timer would lose the first command."""
        discarded = self.stats["rx_bytes_discarded"]
        self.stats["rx_bytes"] += len(data)
        if self.cfg.loopback:
            # a wire from the host's TX to its RX: the same bytes at the same speed, no FC. Written at
            # once, never queued: what the host's full receive buffer cannot take is lost, as on a wire
            echoed = max(0, self.t.write(data))
            self.stats["bytes_echoed"] += echoed
            self.stats["bytes_echo_lost"] += len(data) - echoed
            return
        if self.cfg.deaf:
            discarded["deaf"] += len(data)
            return
        if stalled:
            discarded["stalled"] += len(data)
            return
        # A pty has no line timing: a client that writes, drains and switches
        # to another speed at once has switched before the kernel hands this
        # process its bytes. So they are heard if the client sends at this FC's
        # rate now or did when the run loop's pass that reads them, or the
        # one before, began.
        if not (self._at_speed(sending=False) or any(self.sent_at_rx_rate)):
            discarded["baud_mismatch"] += len(data)
            return
        self.on_bytes(data, now)

    def rx_accounting(self) -> dict:
        """The receive counters at the end: bytes in no frame (garbage,
        rejected headers, a frame cut off when the run ended) are not_a_frame."""
        discarded = dict(self.stats["rx_bytes_discarded"])
        discarded["not_a_frame"] = (self.stats["rx_bytes"] - sum(v for k, v in discarded.items() if k != "not_a_frame")
                                    - self.stats["bytes_echoed"] - self.stats["bytes_echo_lost"]
                                    - self._rx_frame_bytes)
        return {"rx_bytes": self.stats["rx_bytes"], "rx_bytes_discarded": discarded}

    def _ack(self, cmd_set: int, cmd_id: int, session: int, seq: int, body: dict) -> None:
        if session == 0:
            return
        value = self._payload(cmd_set, cmd_id, True, self.profile.name).build({"body": body})
        encrypt = self.cfg.encrypt and (self.cfg.encrypt_handshake or (cmd_set, cmd_id) not in HANDSHAKE)
        frame = encode(value=value, is_ack=True, session=session, seq=seq, key=self.cfg.key if encrypt else None)
        self.stats["acks_sent"] += 1
        self.last_ack[session] = (seq, self._current_raw, frame)
        self._log_ack(cmd_set, cmd_id, session, seq, value, encrypt, resent=False)
        self._answer(frame)

    def _answer(self, frame: bytes) -> None:
        """Send an ACK: at once, or with --rx-baud after ANSWER_S (the run loop sends it)."""
        if self.cfg.rx_baud is None:
            self._send(frame, frames=1)
        else:
            self.answers.append((time.monotonic() + ANSWER_S, frame))

    def _log_ack(self, cmd_set: int, cmd_id: int, session: int, seq: int, value: bytes, encrypted: bool,
                 resent: bool) -> None:
        if self.ack_log:
            self.ack_log.write(json.dumps({
                "set": cmd_set, "id": cmd_id, "session": session, "seq": seq, "command": self._current_value.hex(),
                "value": value.hex(), "encrypted": encrypted, "resent": resent}) + "\n")

    def on_frame(self, raw: bytes, now: float) -> None:
        op = open_frame(raw, self.cfg.key)
        if op.problem or op.is_ack or op.cmd_set is None:
            return
        self._current_raw = raw
        self._current_value = op.value
        self.stats["commands_received"] += 1
        if op.cmd_set == 0x01 and op.cmd_id == 0x03:
            self.stats["movement_commands"] += 1
            self.stats["movement_commands_encrypted"] += op.encrypted
        if self.bugs is not None and self.bugs.wedged_by(op, raw, now):
            return
        if op.session > 0:
            cached = self.last_ack.get(op.session)
            if cached and cached[0] == op.seq and cached[1] == raw:
                # a retransmission (its ACK was lost or late): answer again, do not execute twice
                self.stats["acks_sent"] += 1
                if self.ack_log:
                    again = open_frame(cached[2], self.cfg.key)
                    self._log_ack(op.cmd_set, op.cmd_id, op.session, op.seq, again.value, again.encrypted, resent=True)
                self._answer(cached[2])
                return
        key = (op.cmd_set, op.cmd_id)
        try:
            req = self._payload(op.cmd_set, op.cmd_id, False, self.profile.name).parse(op.value).body
        except Exception:
            return   # a value that does not decode gets no answer, as from a real FC
        if key == (0x00, 0x00):
            # every field the ACK has in some profile; the profile's layout keeps its own (ERRATA E30)
            self._ack(0, 0, op.session, op.seq, cut(version_ack_value(self.profile.name), {
                "ack_code": "activated" if self.activated else "not_activated", "version_crc": VERSION_CRC,
                "version_id": VERSION_ID.ljust(VERSION_ID_SIZE, b"\0"),
                "version_name": VERSION_NAME[self.profile.name].ljust(32, b"\0")}))
        elif key == (0x00, 0x01):
            if self.cfg.app_id is not None and req.app_id != self.cfg.app_id:
                code = "invalid_parameters"
            elif req.sdk_version != self.profile.sdk_version:
                code = "wrong_sdk_version"
            else:
                code = "success"
                if self.cfg.silent_until_activated and self.stats["activated_after_s"] is None:
                    self.stats["activated_after_s"] = round(now - self.start, 3)   # and silent until then
                self.activated = True
            self._ack(0, 1, op.session, op.seq, {"ack_code": code})
        elif key == (0x00, 0x10):
            codes = [int(c) for c in req.codes]
            items = self.profile.flag_bits
            if any(c > 5 for c in codes[:len(items)]):
                self._ack(0, 0x10, op.session, op.seq, {"ack_code": "parameter_error"})
                return
            hz = hz_of_code()
            for item, c in zip(items, codes):
                if c != 5:
                    self.rates[item] = hz[c]
            self.frame_index = 0
            self._ack(0, 0x10, op.session, op.seq, {"ack_code": "success"})
        elif key == (0x01, 0x00):
            if self.cfg.unplug_on_release and int(req.request) == 0 and self.unplugged_until is None:
                self.cfg.unplug_on_release = False
                self._unplug(now)   # the request is lost with the cable: the host must send it again
                return
            self._ack(1, 0, op.session, op.seq, {"ack_code": self._control_request(int(req.request))})
        elif key == (0x01, 0x03):
            if self.control == "onboard":
                self.vehicle.set_command(op.value[0], float(req.x), float(req.y), float(req.z), float(req.yaw), now)

    def authority_state(self) -> dict:
        """Who has control and the broadcast rates now (for --stats: what a client left behind)."""
        return {"control": self.control, "control_pending": self.pending, "activated": self.activated,
                "rates": dict(self.rates),
                "initial_rates": {**self.profile.default_rates_hz, **(self.cfg.rates or {})}}

    def _control_request(self, obtain: int) -> int:
        if not self.activated:
            return 0xFF01   # not activated (the version query's code; decision, see docs/ACCEPTANCE.md)
        if obtain:
            if RC_MODE[self.cfg.rc_mode] != RC_MODE["F"]:
                self.pending = None
                return 0   # rc_not_in_f_mode
            self.onboard_requested = True
            if self.control == "onboard":
                return 2
            if self.pending == "obtain":
                self.pending, self.control = None, "onboard"
                return 2
            self.pending = "obtain"
            return 3
        if self.control == "rc":
            self.pending = None
            self.onboard_requested = False
            return 1
        if self.pending == "release":
            self.pending, self.control = None, "rc"
            self.onboard_requested = False
            return 1
        self.pending = "release"
        return 4

    # ---- main loop -------------------------------------------------------

    def _unplug(self, now: float) -> None:
        """The cable pulled: the port closes, what was not yet sent is lost;
        the run loop reopens it `unplug_for` s later."""
        self.t.unplug()
        self.outbuf.clear()
        self.answers.clear()
        self.unplugged_until = now + self.cfg.unplug_for

    def _halted(self, now: float) -> bool:
        """Deaf and silent: rebooting, or hung by a planted bug."""
        return ((self.resume_at is not None and now < self.resume_at)
                or (self.bugs is not None and self.bugs.halted(now)))

    def _at_speed(self, sending: bool) -> bool:
        """Whether the client's speed for one direction is this FC's: for
        what it sends, the client's input speed against --baud; for what it
        reads, the client's output speed against --rx-baud (else --baud).
        Looked at now, never cached: a client may write at one speed, drain,
        and switch to another to read the answer."""
        if self.cfg.baud is None:
            return True
        speeds = self.t.speeds()
        if speeds is None:   # a TCP port has no speed
            return True
        receives_at, sends_at = speeds
        baud = self.cfg.baud if sending else (self.cfg.rx_baud or self.cfg.baud)
        want = getattr(termios, f"B{baud}", None)
        return want is None or (receives_at if sending else sends_at) == want

    def run(self) -> None:
        cfg = self.cfg
        period = 0.0
        # the first frame is due when the loop starts, not when the simulator
        # was built: a start-up slowed by a busy host is not a broadcast that fell behind
        self.next_frame = self.send_at = max(self.send_at, time.monotonic())
        while self.running:
            now = time.monotonic()
            requested = self.restart_requests
            if requested != self.restart_requests_done:
                self._power_cycle(now)
                self.restart_requests_done = requested
            elapsed = now - self.start
            if cfg.exit_after is not None and elapsed >= cfg.exit_after:
                break
            if cfg.unplug_at is not None and self.unplugged_until is None and elapsed >= cfg.unplug_at:
                self._unplug(now)
                cfg.unplug_at = None
            if self.unplugged_until is not None and now >= self.unplugged_until:
                self.t.replug()
                self.unplugged_until = None
            stalled = (cfg.stall_at is not None and elapsed >= cfg.stall_at) or self._halted(now)
            # what on_received looks back on: bytes read in this pass were written in it or in the last one
            self.sent_at_rx_rate = (self.sent_at_rx_rate[1], self._at_speed(sending=False))
            rate = self.frame_rate()
            period = 1.0 / (rate * (1.0 + cfg.rate_drift)) if rate > 0 else 0.0
            wait = MAX_WAIT_S
            if self._broadcasts() and not stalled and period:
                wait = max(0.0, min(wait, self.send_at - now))
            elif self.resume_at is not None and now < self.resume_at:
                wait = min(wait, self.resume_at - now)   # a reboot ends on time
            if self.answers and not stalled:
                wait = max(0.0, min(wait, self.answers[0][0] - now))
            rfds = self.t.read_fds()
            wfds = [rfds[-1]] if self.outbuf and rfds else []
            try:
                r, w, _ = select.select(rfds, wfds, [], wait)
            except InterruptedError:
                continue
            now = time.monotonic()
            for fd in r:
                if self.unplugged_until is not None:
                    break   # a command unplugged the port (--unplug-on-release): its descriptors are closed
                data = self.t.on_readable(fd)
                if data:
                    self.on_received(data, now, stalled)
            if w:
                self._flush()
            stalled = stalled or self._halted(now)   # a planted bug that triggered on what was just read
            while self.answers and self.answers[0][0] <= now and not stalled:
                self._send(self.answers.pop(0)[1], frames=1)
            # the FC's state when the frame it owes was due, not when this late
            # process got round to it: its values must match its time stamp
            broadcasts = self._broadcasts()
            behind = broadcasts and not stalled and period and self.last_step < self.send_at < now
            t_state = self.send_at if behind else now
            self.vehicle.step(t_state - self.last_step, t_state)
            self.battery = max(0.0, self.battery - (t_state - self.last_step) / 60.0)
            self.last_step = t_state
            if not broadcasts or stalled or not period:
                self.next_frame = self.send_at = now
                continue
            if now >= self.send_at:
                self.last_stamp = max(self.send_at, self.last_stamp)   # injected jitter never runs the clock back
                self.emit_broadcast(now, stamp=self.last_stamp)
                self.next_frame += period
                if self.next_frame < now - BEHIND_S:   # suspended, not merely starved: do not burst
                    self.stats["broadcast_skipped_behind"] += round((now - self.next_frame) / period)
                    self.next_frame = now + period
                jitter = self.rng.uniform(0, cfg.jitter_ms / 1000.0) if cfg.jitter_ms else 0.0
                self.send_at = self.next_frame + jitter

    def drain(self, timeout: float = 3.0) -> None:
        """Give the client the chance to read what was sent (a clean stop loses no frame)."""
        end = time.monotonic() + timeout
        last, since = -1, time.monotonic()
        while time.monotonic() < end:
            if self.outbuf:
                self._flush()
            pending = self.t.pending_input() + len(self.outbuf)
            now = time.monotonic()
            if pending != last:
                last, since = pending, now
            elif pending == 0 and now - since >= DRAIN_SETTLE_S:
                return
            elif pending and now - since > DRAIN_STUCK_S:
                return   # nobody is reading
            time.sleep(0.01)


# --------------------------------------------------------------------------
# Command line


def add_arguments(ap: argparse.ArgumentParser, profiles: tuple[str, ...]) -> None:
    ap.add_argument("--profile", default="a3-fw3.1", choices=profiles, help="broadcast wire profile (default a3-fw3.1)")
    where = ap.add_mutually_exclusive_group()
    where.add_argument("--pty", action="store_true", help="open a pseudo-terminal (the default)")
    where.add_argument("--tcp", type=tcp_port, metavar="PORT", help="listen on TCP PORT (0: any free port) for socket:// URLs")
    ap.add_argument("--host", default="127.0.0.1", help="address to listen on with --tcp (default 127.0.0.1)")
    ap.add_argument("--link", metavar="PATH", help="with a pty: a symlink to it that survives --unplug-at")
    ap.add_argument("--seed", type=non_negative_int, help="random seed: the same seed gives the same faults")
    ap.add_argument("--app-id", type=uint32, help="app id activation accepts (default: any)")
    ap.add_argument("--key-env", metavar="VAR", help="environment variable holding the app key (64 hex characters)")
    ap.add_argument("--encrypt", action="store_true",
                    help="AES-256 encrypt every frame sent but the version and activation ACKs, which no DJI host "
                         "can decrypt: they install the key after activation (needs --key-env)")
    ap.add_argument("--encrypt-handshake", action="store_true",
                    help="with --encrypt: encrypt the version and activation ACKs too (for hosts that must cope)")
    ap.add_argument("--rc-mode", choices=tuple(RC_MODE), default="F", help="RC mode switch (obtain control needs F)")
    ap.add_argument("--rate", action="append", default=[], metavar="ITEM=HZ", help="initial rate of an item (repeatable)")
    ap.add_argument("--baud", type=baud_rate, help="the FC's baud rate; a pty client at another speed sees garbage")
    ap.add_argument("--hold", action="store_true", help="do not broadcast until SIGUSR1")
    ap.add_argument("--stats", metavar="FILE", help="write counters as JSON to FILE on exit")
    ap.add_argument("--log-broadcast", metavar="FILE",
                    help="write SEQ and value (hex, before fault injection) of every broadcast frame sent, "
                         "a JSON object a line")
    ap.add_argument("--log-acks", metavar="FILE",
                    help="write every ACK sent (command set and id, session, SEQ, the command's value, the ACK's "
                         "value in hex, encrypted or not), a JSON object a line")
    f = ap.add_argument_group("fault injection (probabilities are per broadcast frame)")
    for name in FAULTS:
        f.add_argument(f"--{name.replace('_', '-')}", type=probability, default=0.0, metavar="P",
                       help={"noise": "insert 1-16 random bytes before the frame",
                             "bitflip": "flip one random bit", "drop_bytes": "lose one random byte",
                             "truncate": "cut the frame short", "bad_crc": "corrupt the CRC-32",
                             "duplicate": "send the frame twice"}[name])
    f.add_argument("--jitter", type=non_negative_float, default=0.0, metavar="MS", help="delay each frame by 0..MS ms")
    f.add_argument("--rate-drift", type=rate_change, default=0.0, metavar="FRAC", help="run every rate FRAC faster (0.2 = +20%%)")
    f.add_argument("--implausible", action="store_true", help="broadcast implausible values (battery 150, ...)")
    f.add_argument("--wrong-profile", choices=profiles, help="broadcast in this profile's layout instead")
    f.add_argument("--stall-at", type=non_negative_float, metavar="S", help="stop sending and answering after S seconds")
    f.add_argument("--unplug-at", type=non_negative_float, metavar="S", help="close the port after S seconds ...")
    f.add_argument("--unplug-on-release", action="store_true",
                   help="close the port when the first release-control request arrives, unanswered ...")
    f.add_argument("--unplug-for", type=non_negative_float, default=1.0, metavar="S",
                   help="... and reopen it S seconds later")
    f.add_argument("--exit-after", type=non_negative_float, metavar="S", help="exit after S seconds")
    f.add_argument("--rx-baud", type=baud_rate, metavar="BAUD",
                   help="with --baud: read at BAUD while sending at --baud (a different rate per direction; "
                        "a pty client's output speed must be BAUD, its input speed --baud); ACKs leave "
                        f"{ANSWER_S * 1000:g} ms after the command, so a client may switch speeds in between")
    f.add_argument("--deaf", action="store_true",
                   help="never read the RX line (the FC's RX pin, or the host's TX wire, unconnected): no ACK, "
                        "the broadcast goes on")
    f.add_argument("--silent-until-activated", action="store_true",
                   help="broadcast nothing until an activation succeeds, as an FC whose broadcast frequencies "
                        "are all 0 until an app is activated (answers the version query and activation; a "
                        "restart loses the activation and silences it again)")
    f.add_argument("--loopback", action="store_true",
                   help="no flight controller: the host's TX wired to its RX (a loopback plug), every byte the "
                        "host sends comes back, and nothing else")
    b = ap.add_argument_group(
        "planted firmware bugs (for a device fuzzer to find; docs/ACCEPTANCE.md)",
        "SIGHUP (kill -HUP PID) restarts the simulated flight controller, as pulling its power does, "
        "bugs planted or not: a hang ends; SEQ, time stamp, activation, control authority, rates and "
        f"what was not yet sent are lost; the broadcast resumes {REBOOT_PAUSE_S:g} s later. A device "
        "fuzzer's --restart-cmd can use it.")
    b.add_argument("--bug", action="append", default=[], choices=tuple(BUGS), metavar="NAME",
                   help="plant this bug (repeatable; default none). "
                        + "; ".join(f"{name}: {what}" for name, what in BUGS.items()))


# ---- running the simulator as a child process (kit, soak, tests) ----------

def stop_child(proc) -> None:
    """SIGTERM a running `osdkc sim` (it drains and writes --stats), kill it
    if it does not end within 10 s."""
    if proc.poll() is not None:
        return
    proc.send_signal(signal.SIGTERM)
    try:
        proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()


@contextlib.contextmanager
def spawned(*sim_args: str, env: dict | None = None, new_session: bool = False, command: str = "sim"):
    """`osdkc sim SIM_ARGS` in a child process: yields (url, process) once it
    has printed the URL of its port, and stops it on the way out. With
    `new_session` a Ctrl-C at the terminal does not reach it, so a host can
    still hand back control through it before it is stopped. `command`
    "tap" runs `osdkc tap` the same way: it too prints its port first."""
    proc = subprocess.Popen([sys.executable, "-m", "osdk_conformance.cli", command, *sim_args],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env,
                            start_new_session=new_session, preexec_fn=keep_priority if new_session else None)
    held = -1
    try:
        url = proc.stdout.readline().strip()
        if not url:
            proc.wait()
            raise UsageError(f"osdkc {command} did not start: " + proc.stderr.read().strip())
        held = _hold_terminal(url)
        yield url, proc
    finally:
        stop_child(proc)
        if held >= 0:
            os.close(held)


def _hold_terminal(url: str) -> int:
    """The simulator's pseudo-terminal opened and left unread (-1 for a TCP
    port): while a descriptor is open the kernel keeps the terminal's number,
    so a host still reopening the port after the simulator died finds no
    such file instead of another program's new terminal of the same name."""
    if "://" in url:
        return -1
    try:
        return os.open(url, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
    except OSError:
        return -1


def _flight_controller_options(args: argparse.Namespace) -> list[str]:
    """The options given that shape what the flight controller sends or how
    it hears; with --loopback there is no flight controller to shape."""
    given = {"--bug": args.bug, "--deaf": args.deaf, "--silent-until-activated": args.silent_until_activated,
             "--hold": args.hold, "--baud": args.baud is not None, "--encrypt": args.encrypt,
             "--implausible": args.implausible, "--wrong-profile": args.wrong_profile is not None,
             "--stall-at": args.stall_at is not None, "--unplug-on-release": args.unplug_on_release,
             "--jitter": args.jitter > 0, "--rate-drift": args.rate_drift != 0,
             **{f"--{name.replace('_', '-')}": getattr(args, name) > 0 for name in FAULTS}}
    return [option for option, on in given.items() if on]


def run_sim(args: argparse.Namespace) -> int:
    key = key_option(args.key_env, args.encrypt)
    if args.encrypt_handshake and not args.encrypt:
        raise UsageError("--encrypt-handshake goes with --encrypt")
    if args.rx_baud is not None and args.baud is None:
        raise UsageError("--rx-baud goes with --baud (the rate it sends at)")
    if args.loopback and (fc_options := _flight_controller_options(args)):
        raise UsageError(f"--loopback is a line with no flight controller on it: not with {', '.join(fc_options)}")
    if args.deaf and (args.bug or args.unplug_on_release or args.rx_baud is not None):
        raise UsageError("--deaf hears nothing: not with --bug, --unplug-on-release or --rx-baud, "
                         "which act on what it hears")
    prof = load_profile(args.profile)
    rates = {}
    for spec in args.rate:
        item, _, hz = spec.partition("=")
        if item not in prof.flag_bits or hz not in ("0", "1", "10", "50", "100"):
            raise UsageError(f"--rate {spec}: want ITEM=HZ with ITEM one of {', '.join(prof.flag_bits)} "
                             "and HZ one of 0, 1, 10, 50, 100")
        rates[item] = int(hz)
    cfg = SimConfig(profile=args.profile, seed=args.seed, app_id=args.app_id, key=key, encrypt=args.encrypt,
                    encrypt_handshake=args.encrypt_handshake,
                    rc_mode=args.rc_mode, faults={n: getattr(args, n) for n in FAULTS}, jitter_ms=args.jitter,
                    rate_drift=args.rate_drift, implausible=args.implausible, wrong_profile=args.wrong_profile,
                    stall_at=args.stall_at, exit_after=args.exit_after, unplug_at=args.unplug_at,
                    unplug_on_release=args.unplug_on_release,
                    unplug_for=args.unplug_for, baud=args.baud, rx_baud=args.rx_baud, deaf=args.deaf,
                    silent_until_activated=args.silent_until_activated, loopback=args.loopback, hold=args.hold,
                    rates=rates or None,
                    log_broadcast=args.log_broadcast, log_acks=args.log_acks, bugs=tuple(dict.fromkeys(args.bug)))
    try:
        transport = TcpTransport(args.host, args.tcp) if args.tcp is not None else PtyTransport(args.link)
    except OSError as e:
        raise UsageError(f"cannot open the simulator's port: {e.strerror or e}") from None
    try:
        sim = Simulator(cfg, transport)
    except OSError as e:
        transport.close()
        option = "--log-acks" if args.log_acks and e.filename == args.log_acks else "--log-broadcast"
        raise UsageError(f"{option}: cannot write {e.filename}: {e.strerror or e}") from None

    stopped_by: list[str] = []

    def stop(signum, frame):
        stopped_by.append(signal.Signals(signum).name)
        sim.running = False

    def go(signum, frame):
        sim.broadcasting = True

    def power_cycle(signum, frame):
        sim.request_restart()

    signal.signal(signal.SIGINT, stop)
    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGUSR1, go)
    signal.signal(signal.SIGHUP, power_cycle)
    print(transport.url, flush=True)
    print(f"osdkc sim: {args.profile} flight controller on {transport.url}"
          + (f" (pty {transport.path})" if isinstance(transport, PtyTransport) and args.link else ""),
          file=sys.stderr, flush=True)
    try:
        sim.run()
        sim.drain()
    finally:
        transport.close()
        if sim.broadcast_log:
            sim.broadcast_log.close()
        if sim.ack_log:
            sim.ack_log.close()
        stats = dict(sim.stats, **sim.rx_accounting(), profile=args.profile, seconds=round(time.monotonic() - sim.start, 3),
                     last_seq=(sim.seq - 1) & 0xFFFF, **sim.authority_state())
        if args.stats:
            Path(args.stats).write_text(json.dumps(stats, indent=2) + "\n")
        print("osdkc sim: stopped" + (f" by {stopped_by[0]}" if stopped_by else "") + "; "
              + ", ".join(f"{k} {v}" for k, v in stats.items() if isinstance(v, int)), file=sys.stderr, flush=True)
    # a signal ends it the way it ends every osdkc command (130/143), after the
    # drain and the --stats file; --exit-after is a normal end
    return exit_status_of_signal(stopped_by[0]) if stopped_by else 0
