"""`osdkc device`: acceptance suite for a flight controller on a serial port.

    osdkc device --port /dev/ttyUSB0 --baud 230400 --profile a3-fw3.1 --duration 10
    osdkc device --port socket://127.0.0.1:5760 --profile m100-fw3.1 --active --app-id 1234567 --key-env OSDK_KEY
    osdkc device --replay captures/device-....pcapng --profile a3-fw3.1

Passive checks listen to the broadcast; `--active` adds the command
exchange (version, activation, frequencies, control authority) and, only
with `--allow-motion`, movement control. Every received and sent byte is
recorded in a pcapng capture (capture.py) that `--replay` checks offline.
Each check is a named Result (category = check group, id = check name), so
the reports are those of `osdkc run`. docs/ACCEPTANCE.md lists every check.

Exit status: 0 every check passed, 1 a check failed, 2 usage or port error.
"""
from __future__ import annotations

import argparse
import math
import os
import sys
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .errors import UsageError
from .report import ERROR, FAIL, PASS, SKIP, Result

MOTION_WARNING = """\
!!! WARNING: --allow-motion sends MOVEMENT CONTROL commands. On a real flight
!!! controller this MOVES THE AIRCRAFT (attitude, velocity, position and height
!!! changes of several metres). Remove the propellers or use the DJI simulator,
!!! keep the RC in hand and be ready to take over."""


@dataclass
class Options:
    profile: str
    duration: float = 5.0
    rate_tolerance: float = 0.10
    max_link_errors: float = 0.001
    max_loss: float = 0.001
    max_jitter_ms: float = 25.0
    stall_timeout: float = 1.0
    settle: float = 0.3
    flight_status_enum: str | None = None
    expect_rates: dict[str, int] | None = None


# --------------------------------------------------------------------------
# Passive checks (live and replay)


def _rate(n: int, total: int) -> str:
    return f"{n}/{total}" + (f" ({100.0 * n / total:.2f}%)" if total else "")


def link_checks(an, opts: Options, link: "LinkState | None") -> list[Result]:
    out = []
    total = an.frames
    kinds: dict[str, list] = {"noise": [], "header": [], "crc": [], "short": []}
    for inc in an.incidents:
        kinds[inc[1]].append(inc)
    if an.rx_bytes == 0:
        out.append(Result("link", "link.data", FAIL,
                          "no byte received: flight controller off, wrong port, TX/RX swapped, or the OPEN "
                          "protocol output is disabled (DJI Assistant)", kind="no_data"))
    else:
        out.append(Result("link", "link.data", PASS, f"{an.rx_bytes} bytes received"))
    if an.rx_bytes >= 64 and total == 0:
        out.append(Result("link", "link.baud", FAIL,
                          f"{an.rx_bytes} bytes and not one valid frame: wrong baud rate (the flight controller's "
                          "rate is set in DJI Assistant) or this port does not carry the OPEN protocol",
                          kind="wrong_baud"))
    elif total:
        out.append(Result("link", "link.baud", PASS, f"{total} valid frames: the baud rate matches"))
    else:
        out.append(Result("link", "link.baud", SKIP, "too few bytes to judge the baud rate"))

    def incident_check(cid: str, found: list, what: str, verdict: str) -> Result:
        n = len(found)
        details: dict[str, Any] = {"incidents": n, "frames": total, "bytes lost": sum(i[2] for i in found)}
        if found:
            details["examples"] = [f"t={i[0] - (an.first_t or 0):.3f}s: {i[3]}" for i in found[:5]]
        limit = opts.max_link_errors * max(total, 1)
        if total == 0:
            return Result("link", cid, SKIP, "no valid frame to compare with")
        if n > limit:
            return Result("link", cid, FAIL, f"{verdict}: {_rate(n, total + n)} {what} "
                          f"(limit {opts.max_link_errors:.3%})", details, kind=cid.split(".")[1])
        return Result("link", cid, PASS, f"{n} {what} in {total} frames", details)

    out.append(incident_check("link.framing", kinds["noise"] + kinds["header"], "noise/header incidents",
                              "bytes outside frames (line noise, a second talker, or bad headers)"))
    out.append(incident_check("link.crc", kinds["crc"], "CRC failures", "frames with a wrong CRC-16 or CRC-32"))
    out.append(incident_check("link.short_frames", kinds["short"], "frames cut short",
                              "frames interrupted before their LEN (bytes lost or truncated frames)"))
    if link is not None:
        if link.disconnects:
            desc = []
            for lost, back, why in link.disconnects:
                rel = lost - link.t_open
                desc.append(f"lost at t={rel:.2f}s ({why})" + (f", back after {back - lost:.2f}s" if back
                                                                else ", never came back"))
            out.append(Result("link", "link.connection", FAIL, "device unplugged or port lost: " + "; ".join(desc),
                              {"disconnects": desc}, kind="unplugged"))
        else:
            out.append(Result("link", "link.connection", PASS, "the port stayed open for the whole run"))
    out.append(stall_check(an, opts, link))
    return out


def stall_check(an, opts: Options, link) -> Result:
    if not an.rx_chunks:
        return Result("link", "link.stall", SKIP if an.rx_bytes else FAIL,
                      "no data at all" if not an.rx_bytes else "", kind="stalled")
    times = [t for t, _ in an.rx_chunks]
    end = link.t_end if link else times[-1]
    gaps = [(b - a, a) for a, b in zip(times, times[1:])]
    gaps.append((end - times[-1], times[-1]))
    if link:
        gaps.insert(0, (times[0] - link.t_open, link.t_open))
        # silence while the port was down is the connection check's business
        gaps = [(g, a) for g, a in gaps if not any(lo <= a + g / 2 <= (hi or end) for lo, hi, _ in link.disconnects)]
    worst = max(gaps, default=(0.0, 0.0))
    t0 = link.t_open if link else times[0]
    limit = stall_limit(an, opts)
    if worst[0] > limit:
        return Result("link", "link.stall", FAIL,
                      f"stream stalled: no byte for {worst[0]:.2f}s from t={worst[1] - t0:.2f}s "
                      f"(limit {limit:g}s)", {"longest silence s": round(worst[0], 3)}, kind="stalled")
    return Result("link", "link.stall", PASS, f"longest silence {worst[0] * 1000:.0f} ms (limit {limit:g}s)")


def stall_limit(an, opts: Options) -> float:
    """--stall-timeout, stretched to three broadcast periods when the FC is configured slower than that:
    an FC whose fastest item is at 1 Hz is silent for a second between frames by design."""
    fastest = [max(e.rates.values()) for e in an.epochs if any(e.rates.values())]
    return max([opts.stall_timeout] + [3.0 / hz for hz in fastest])


def decode_checks(an, opts: Options) -> list[Result]:
    out = []
    nerr = sum(an.decode_errors.values())
    nb = len(an.bcast)
    details = {"errors by class": an.decode_errors, "examples": an.decode_examples,
               "frames by command": an.cmd_frames}
    if an.frames == 0:
        out.append(Result("decode", "decode.frames", SKIP, "no valid frame"))
    elif nerr:
        msg = f"{_rate(nerr, an.frames)} frames do not decode for {opts.profile}"
        if an.encrypted_unopened:
            msg += f" ({an.encrypted_unopened} encrypted and no key: give --key-env)"
        out.append(Result("decode", "decode.frames", FAIL, msg, details, kind="undecodable"))
    else:
        out.append(Result("decode", "decode.frames", PASS, f"all {an.frames} frames decode for {opts.profile}", details))
    out.append(profile_check(an, opts))
    return out


def profile_check(an, opts: Options) -> Result:
    from osdk_construct.payload import osdk_payload

    from .rules import profile as load_profile

    bad = an.undecoded_broadcasts
    nb = len(an.bcast)
    if not bad:
        if nb == 0:
            return Result("decode", "decode.profile", FAIL if an.frames else SKIP,
                          "no broadcast frame received" if an.frames else "no valid frame", kind="no_broadcast")
        return Result("decode", "decode.profile", PASS, f"{nb} broadcast frames match the {opts.profile} layout")
    prof = load_profile(opts.profile)
    sizes = []
    for v in bad[:3]:
        flags = v[0] | v[1] << 8 if len(v) >= 2 else 0
        try:
            want = prof.payload_size(flags) + 2
        except Exception:
            want = None
        sizes.append(f"flags 0x{flags:04x}: {len(v)} bytes, {opts.profile} expects "
                     + (f"{want}" if want is not None else "no such flag bits"))
    fits = []
    from .cli import PROFILES
    for other in PROFILES:
        if other == opts.profile:
            continue
        c = osdk_payload(2, 0, False, other)
        ok = 0
        for v in bad:
            try:
                c.parse(v)
                ok += 1
            except Exception:
                pass
        if ok == len(bad):
            fits.append(other)
    details = {"payload sizes": sizes, "broadcasts that decode": nb, "broadcasts that do not": len(bad)}
    if fits:
        return Result("decode", "decode.profile", FAIL,
                      f"wrong profile: the broadcast does not fit {opts.profile} but fits {' and '.join(fits)} "
                      f"(run with --profile {fits[0]})", details, kind="wrong_profile")
    return Result("decode", "decode.profile", FAIL,
                  f"{len(bad)} broadcast frames fit no known profile (item sizes do not match)", details,
                  kind="wrong_profile")


def stream_checks(an, opts: Options, epoch: int = 0) -> list[Result]:
    """Rates, flags, sequence, duplicates and jitter over one configuration epoch."""
    ep = an.epochs[epoch]
    t0, t1 = ep.start + opts.settle, an.epoch_end(epoch)
    out = [rate_check(an, opts, ep.rates, t0, t1, "stream.rates", "stream"),
           flags_check(an, ep.rates, t0, t1, "stream.flags", "stream")]
    frames = an.frames_between(t0, t1)
    out += sequence_checks(an, frames, opts)
    out.append(jitter_check(frames, opts, max(ep.rates.values(), default=0)))
    return out


def rate_check(an, opts: Options, rates: dict, t0: float, t1: float, cid: str, cat: str) -> Result:
    m = an.measure_rates(rates, t0, t1)
    bad, unmeasured = [], []
    for item, r in m.items():
        exp = r["expected_hz"]
        if exp == 0:
            if r["frames"]:
                bad.append(f"{item}: configured 0 Hz, present in {r['frames']} frames")
        elif r["measured_hz"] is None:
            if (t1 - t0) * exp >= 4:
                bad.append(f"{item}: configured {exp} Hz, only {r['frames']} frames in {t1 - t0:.1f}s")
            else:
                unmeasured.append(item)
        elif abs(r["measured_hz"] - exp) > opts.rate_tolerance * exp:
            bad.append(f"{item}: measured {r['measured_hz']} Hz, configured {exp} Hz")
    details = {"window s": round(t1 - t0, 3), "per item": m, "tolerance": f"{opts.rate_tolerance:.0%}"}
    if unmeasured:
        details["too slow to measure in this window"] = unmeasured
    if t1 - t0 <= 0:
        return Result(cat, cid, SKIP, "no time to measure")
    if bad:
        return Result(cat, cid, FAIL, "measured rates do not follow the configuration: " + "; ".join(bad[:4])
                      + (" ..." if len(bad) > 4 else ""), details, kind="rate")
    return Result(cat, cid, PASS, f"{len(m) - len(unmeasured)} item rates within {opts.rate_tolerance:.0%} "
                  "of the configuration", details)


def flags_check(an, rates: dict, t0: float, t1: float, cid: str, cat: str) -> Result:
    frames = an.frames_between(t0, t1)
    if not frames:
        return Result(cat, cid, SKIP, "no broadcast frame in the window")
    top = max(rates.values(), default=0)
    bits = an.prof.flag_bits
    always = [i for i, item in enumerate(bits) if rates.get(item, 0) == top and top > 0]
    never = [i for i, item in enumerate(bits) if rates.get(item, 0) == 0]
    missing = sum(1 for _, _, f in frames if any(not f >> b & 1 for b in always))
    extra = sum(1 for _, _, f in frames if any(f >> b & 1 for b in never))
    details = {"frames": len(frames), f"items at the frame rate ({top} Hz)": [bits[b] for b in always],
               "items off": [bits[b] for b in never],
               "flag words seen": sorted({f"0x{f:04x}" for _, _, f in frames})[:16]}
    if missing or extra:
        parts = []
        if missing:
            parts.append(f"{missing} frames lack an item configured at the frame rate")
        if extra:
            parts.append(f"{extra} frames carry an item configured off (0 Hz)")
        return Result(cat, cid, FAIL, "flag words do not match the configured rates: " + "; ".join(parts),
                      details, kind="flags")
    return Result(cat, cid, PASS, f"flag words of {len(frames)} frames match the configured rates", details)


def _seq_deltas(frames) -> list[int]:
    return [(b[1] - a[1]) % 65536 for a, b in zip(frames, frames[1:])]


def sequence_checks(an, frames, opts: Options) -> list[Result]:
    out = []
    deltas = _seq_deltas(frames)
    if len(deltas) < 2:
        out.append(Result("stream", "stream.sequence", SKIP, "too few broadcast frames"))
    else:
        step = max(set(deltas), key=deltas.count)
        if step == 0:
            out.append(Result("stream", "stream.sequence", PASS,
                              "broadcasts all carry one SEQ: the flight controller does not number them, so "
                              "frame loss cannot be measured from SEQ"))
        else:
            lost = sum(d // step - 1 for d in deltas if d > step and d < 32768)
            odd = sum(1 for d in deltas if d % step or d >= 32768)
            details = {"step": step, "frames": len(frames), "lost": lost, "out of order or odd steps": odd}
            expected = len(frames) + lost
            if lost > opts.max_loss * expected or odd > opts.max_loss * expected:
                out.append(Result("stream", "stream.sequence", FAIL,
                                  f"{_rate(lost, expected)} broadcast frames lost (SEQ gaps)"
                                  + (f", {odd} SEQ steps out of order" if odd else ""), details, kind="loss"))
            else:
                out.append(Result("stream", "stream.sequence", PASS,
                                  f"SEQ steps by {step}: {lost} of {expected} frames lost", details))
    dup = sum(1 for d in deltas if d == 0) if deltas and max(set(deltas), key=deltas.count) != 0 else 0
    if dup:
        out.append(Result("stream", "stream.duplicates", FAIL,
                          f"{dup} broadcast frames repeat the SEQ of the frame before"
                          f" ({an.duplicates} byte-for-byte copies)", kind="duplicate"))
    else:
        out.append(Result("stream", "stream.duplicates", PASS if deltas else SKIP, "no repeated frame"))
    return out


def jitter_check(frames, opts: Options, top_hz: int) -> Result:
    if len(frames) < 10 or not top_hz:
        return Result("stream", "stream.jitter", SKIP, "too few broadcast frames")
    deltas = _seq_deltas(frames)
    step = max(set(deltas), key=deltas.count) or 1
    k, idx = 0, [0]
    for d in deltas:
        k += d // step if d and d % step == 0 and d < 32768 else 1
        idx.append(k)
    ts = [f[0] for f in frames]
    period = (ts[-1] - ts[0]) / idx[-1] if idx[-1] else 0
    from .device_analysis import percentile
    resid = [t - ts[0] - i * period for t, i in zip(ts, idx)]
    spread = (percentile(resid, 99.5) - percentile(resid, 0.5)) * 1000
    details = {"frame period ms": round(period * 1000, 3), "arrival spread p0.5..p99.5 ms": round(spread, 2),
               "limit ms": opts.max_jitter_ms}
    if spread > opts.max_jitter_ms:
        return Result("stream", "stream.jitter", FAIL,
                      f"arrival times spread {spread:.1f} ms around a steady {1 / period if period else 0:.1f} Hz "
                      f"clock (limit {opts.max_jitter_ms} ms)", details, kind="jitter")
    return Result("stream", "stream.jitter", PASS, f"arrival spread {spread:.1f} ms", details)


VALUE_TEXT = {
    "quaternion_norm": "attitude quaternion is a unit quaternion (|q| within 1e-3 of 1)",
    "gps_health": "GPS health within 0..5",
    "battery": "battery within 0..100 %",
    "rc_channels": "RC sticks within -10000..10000, mode in {-8000, 0, 8000}, gear in {-10000, -4545}",
    "flight_status": "flight status is a value of the profile's enum",
    "time_stamp": "time stamp (1/400 s ticks) never goes back",
    "control_info": "control device and current control mode are defined values",
    "finite": "every float is finite",
}


def value_checks(an) -> list[Result]:
    out = []
    for rule, f in an.findings.items():
        cid = f"values.{rule}"
        if f.samples == 0:
            out.append(Result("values", cid, SKIP, f"item not broadcast: {VALUE_TEXT[rule]} not checked"))
        elif f.count:
            out.append(Result("values", cid, FAIL, f"{_rate(f.count, f.samples)} samples break: {VALUE_TEXT[rule]}",
                              {"examples": f.examples}, kind="implausible"))
        else:
            out.append(Result("values", cid, PASS, f"{f.samples} samples: {VALUE_TEXT[rule]}"))
    return out


def passive_results(an, opts: Options, link=None) -> list[Result]:
    return link_checks(an, opts, link) + decode_checks(an, opts) + stream_checks(an, opts) + value_checks(an)


# --------------------------------------------------------------------------
# The port


@dataclass
class LinkState:
    t_open: float = 0.0
    t_end: float = 0.0
    disconnects: list = field(default_factory=list)   # [t_lost, t_back or None, why]


class PortDown(Exception):
    pass


class Port:
    """The serial port, a reader thread that feeds the analyzer and the
    capture, reopening after the device goes away, and a writer."""

    def __init__(self, url: str, baud: int, analyzer, capture) -> None:
        self.url, self.baud, self.an, self.cap = url, baud, analyzer, capture
        self.state = LinkState()
        self.ser = None
        self.stop = threading.Event()
        self.wlock = threading.Lock()
        self.thread: threading.Thread | None = None

    def _open(self):
        import serial

        return serial.serial_for_url(self.url, baudrate=self.baud, timeout=0.05, write_timeout=1.0)

    def open(self) -> None:
        try:
            self.ser = self._open()
        except Exception as e:  # SerialException, ValueError (bad URL), OSError
            raise UsageError(f"cannot open port {self.url}: {_one_line(e)}") from None
        self.state.t_open = time.time()
        self.thread = threading.Thread(target=self._reader, name="osdkc-reader", daemon=True)
        self.thread.start()

    def _reader(self) -> None:
        while not self.stop.is_set():
            ser = self.ser
            if ser is None:
                try:
                    ser = self._open()
                except Exception:
                    self.stop.wait(0.25)
                    continue
                self.ser = ser
                self.state.disconnects[-1][1] = time.time()
            try:
                waiting = ser.in_waiting
                data = ser.read(min(65536, waiting) if waiting else 1)
            except Exception as e:
                t = time.time()
                self.state.disconnects.append([t, None, _one_line(e)])
                with self.wlock:
                    try:
                        ser.close()
                    except Exception:
                        pass
                    self.ser = None
                continue
            if data:
                ts = time.time_ns()
                if self.cap:
                    self.cap.rx(data, ts)
                self.an.feed_rx(ts / 1e9, data)

    def write(self, data: bytes) -> None:
        with self.wlock:
            if self.ser is None:
                raise PortDown("the port is down")
            ts = time.time_ns()
            try:
                self.ser.write(data)
            except Exception as e:
                raise PortDown(_one_line(e)) from None
        if self.cap:
            self.cap.tx(data, ts)
        self.an.feed_tx(ts / 1e9, data)

    def close(self) -> None:
        self.stop.set()
        if self.thread:
            self.thread.join(2.0)
        self.state.t_end = time.time()
        with self.wlock:
            if self.ser is not None:
                try:
                    self.ser.close()
                except Exception:
                    pass


def _one_line(e: Exception) -> str:
    return " ".join(str(e).split()) or type(e).__name__


# --------------------------------------------------------------------------
# Active checks


class Commander:
    """Sends commands (session 2, ACK required, up to 3 tries) and waits for ACKs."""

    def __init__(self, port: Port, an, profile: str, key: bytes | None, encrypt: bool,
                 ack_timeout: float = 1.0) -> None:
        from osdk_construct.payload import osdk_payload

        self.port, self.an, self.profile = port, an, profile
        self.key = key if encrypt else None
        self.payload = osdk_payload
        self.seq = 1
        self.ack_timeout = ack_timeout

    def _next_seq(self) -> int:
        self.seq = (self.seq + 1) & 0xFFFF
        return self.seq

    def send_value(self, cmd_set: int, cmd_id: int, value: bytes, session: int = 0) -> bytes:
        """Send a command whose value is already encoded; no ACK is awaited."""
        from .device_wire import encode

        seq = self._next_seq()
        frame = encode(cmd_set=cmd_set, cmd_id=cmd_id, value=value, session=session, seq=seq, key=self.key)
        self.port.write(frame)
        return frame

    def request(self, cmd_set: int, cmd_id: int, body: dict, tries: int = 3):
        """(ACK value parsed, seconds) or (None, why)."""
        from .device_wire import encode

        value = self.payload(cmd_set, cmd_id, False, self.profile).build({"body": body})
        seq = self._next_seq()
        frame = encode(cmd_set=cmd_set, cmd_id=cmd_id, value=value, session=2, seq=seq, key=self.key)
        t0 = time.monotonic()
        for _ in range(tries):
            try:
                self.port.write(frame)
            except PortDown as e:
                return None, f"port down: {e}"
            ack = self.an.wait_ack(2, seq, self.ack_timeout)
            if ack:
                try:
                    parsed = self.payload(cmd_set, cmd_id, True, self.profile).parse(ack[3]).body
                except Exception as e:
                    return None, f"ACK does not decode: {_one_line(e)} (value {ack[3].hex()})"
                return parsed, time.monotonic() - t0
        return None, f"no ACK after {tries} tries of {self.ack_timeout}s"


def _code(v) -> tuple[int, str]:
    return int(v), str(v)


def active_checks(cmd: Commander, an, opts: Options, app_id: int | None, allow_motion: bool,
                  window: float = 2.0, motion_seconds: float = 1.5) -> list[Result]:
    prof = an.prof
    out: list[Result] = []

    def res(cid, status, msg, details=None, kind=""):
        out.append(Result("active", cid, status, msg, details or {}, kind=kind))

    # version
    ack, info = cmd.request(0, 0, {"arbitrary": 0})
    if ack is None:
        res("active.version", FAIL, f"version query: {info}", kind="no_ack")
    else:
        name = bytes(ack.version_name).rstrip(b"\0")
        code = _code(ack.ack_code)
        printable = all(32 <= b < 127 for b in name) and name
        details = {"ack_code": f"{code[0]:#06x} {code[1]}", "version_crc": f"{ack.version_crc:#010x}",
                   "version_name": name.decode("ascii", "replace"), "ack after s": round(info, 3)}
        if code[0] not in (0x0000, 0xFF01) or not printable:
            res("active.version", FAIL, "version ACK: unknown code or unprintable version name", details, "bad_ack")
        else:
            res("active.version", PASS, f"version {name.decode()} ({code[1]})", details)
    # activation
    if app_id is None:
        res("active.activation", SKIP, "no --app-id given: activation not tried")
        activated = ack is not None and int(ack.ack_code) == 0
    else:
        ack, info = cmd.request(0, 1, {"app_id": app_id, "api_level": 2, "sdk_version": prof.sdk_version,
                                       "bundle_id": bytes(32)})
        activated = False
        if ack is None:
            res("active.activation", FAIL, f"activation: {info}", kind="no_ack")
        else:
            code = _code(ack.ack_code)
            if code[0] != 0:
                res("active.activation", FAIL, f"activation refused: {code[0]} {code[1]}", kind="refused")
            else:
                v, _ = cmd.request(0, 0, {"arbitrary": 0})
                if v is None or int(v.ack_code) != 0:
                    res("active.activation", FAIL, "activation succeeded but the version query still says "
                        "not activated", kind="not_activated")
                else:
                    activated = True
                    res("active.activation", PASS, f"activated app id {app_id}; version query now says activated")
    # frequency
    pattern = {item: 0 for item in prof.flag_bits}
    pattern.update({"time_stamp": 50, "quaternion": 50, "velocity": 10, "position": 10, "flight_status": 10,
                    "battery": 10, "control_info": 10})
    from .device_analysis import CODE_OF_HZ
    codes = [CODE_OF_HZ[pattern[i]] for i in prof.flag_bits] + [0] * (16 - len(prof.flag_bits))
    n_epochs = len(an.epochs)
    ack, info = cmd.request(0, 0x10, {"codes": codes})
    freq_ok = False
    if ack is None:
        res("active.frequency", FAIL, f"set frequency: {info}", kind="no_ack")
    elif int(ack.ack_code) != 0:
        res("active.frequency", FAIL, f"set frequency refused: {_code(ack.ack_code)}", kind="refused")
    else:
        time.sleep(opts.settle + window)
        with an.lock:
            ep = an.epochs[n_epochs] if len(an.epochs) > n_epochs else None
            if ep is None:
                res("active.frequency", ERROR, "the ACK was not seen by the analyzer")
            else:
                t0 = ep.start + opts.settle
                r = rate_check(an, opts, ep.rates, t0, t0 + window, "active.frequency", "active")
                fl = flags_check(an, ep.rates, t0, t0 + window, "active.frequency", "active")
                if r.status == PASS and fl.status == PASS:
                    freq_ok = True
                    res("active.frequency", PASS, "rates and flag words follow the new frequencies: " + r.message,
                        r.details)
                else:
                    bad = [x.message for x in (r, fl) if x.status != PASS]
                    res("active.frequency", FAIL, "; ".join(bad), {**r.details, **fl.details}, "rate")
    # control authority
    def control_device(want: int, timeout=1.0):
        """Control devices the broadcast showed, until `want` shows up or the time is over."""
        seen = []
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            time.sleep(0.1)
            with an.lock:
                ci = an.latest.get("control_info")
            if ci and ci[0] > time.time() - 0.3:
                seen.append(int(ci[1].control_device))
                if seen[-1] == want:
                    break
        return seen

    def two_step(request: int, cid: str, progress: int, done: int, device_after: int):
        acks = []
        for _ in range(2):
            a, info = cmd.request(1, 0, {"request": request})
            if a is None:
                res(cid, FAIL, f"{'obtain' if request else 'release'} control: {info}", {"acks": acks}, "no_ack")
                return False
            acks.append(f"{int(a.ack_code)} {a.ack_code}")
            code = int(a.ack_code)
            if code == done:
                break
            if code != progress:
                why = {0: "the RC mode switch is not in F mode", 0xC9: "the flight controller is in IOC mode",
                       0xFF01: "the app is not activated"}.get(code, "unexpected answer")
                res(cid, FAIL, f"{'obtain' if request else 'release'} control answered {code} ({a.ack_code}): {why}",
                    {"acks": acks}, "refused")
                return False
        if int(a.ack_code) != done:
            res(cid, FAIL, f"still not done after two requests: {acks}", {"acks": acks}, "refused")
            return False
        if acks[0].split()[0] != str(progress):
            note = " (answered done at once, no 'in progress' step)"
        else:
            note = ""
        seen = control_device(device_after) if freq_ok else []
        details = {"acks": acks, "control device in broadcast": seen[-3:]}
        if freq_ok and seen and seen[-1] != device_after:
            res(cid, FAIL, f"ACKs {acks} but the broadcast control device is {seen[-1]}, not {device_after}",
                details, "state")
            return False
        res(cid, PASS, f"ACKs {' then '.join(acks)}{note}", details)
        return True

    obtained = two_step(1, "active.control_obtain", 3, 2, 2)
    if not allow_motion:
        res("active.movement", SKIP, "movement control not tried (needs --allow-motion)")
    elif not obtained:
        res("active.movement", SKIP, "control authority not obtained: movement control not tried")
    else:
        movement_check(cmd, an, opts, res, motion_seconds)
    two_step(0, "active.control_release", 4, 1, 0)
    # restore the profile's default rates
    defaults = [CODE_OF_HZ.get(prof.default_rates_hz[i], 5) for i in prof.flag_bits] + [0] * (16 - len(prof.flag_bits))
    ack, info = cmd.request(0, 0x10, {"codes": defaults})
    if ack is None or int(ack.ack_code) != 0:
        res("active.frequency_restore", FAIL, f"restoring the default rates failed: {info if ack is None else ack.ack_code}",
            kind="no_ack" if ack is None else "refused")
    else:
        res("active.frequency_restore", PASS, "default rates restored")
    return out


def movement_check(cmd: Commander, an, opts: Options, res, seconds: float = 1.5) -> None:
    """Attitude, then velocity and yaw rate, then position offset and height,
    each commanded at 50 Hz for `seconds` (position: 5/3 of it), then hover."""
    from osdk_construct.control import encode_movement_control

    def state():
        with an.lock:
            return dict(an.latest)

    def stream(mode: int, seconds: float, values):
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            x, y, z, yaw = values() if callable(values) else values
            try:
                cmd.send_value(1, 3, encode_movement_control(mode, x, y, z, yaw), session=0)
            except PortDown:
                return False
            time.sleep(0.02)
        return True

    def window(key: str, seconds: float):
        t_end = time.time()
        with an.lock:
            return [s for s in an.traces[key] if s[0] >= t_end - seconds]

    problems, details = [], {}
    s = state()
    for need in ("attitude", "velocity", "position"):
        if need not in s:
            res("active.movement", SKIP, f"cannot verify movement: the {need} item is not broadcast")
            return
    yaw0 = s["attitude"][1][2]
    # 1. attitude: tilt angles and yaw angle
    roll_t, pitch_t, yaw_t = 5.0, -3.0, (yaw0 + 20.0 + 180) % 360 - 180
    stream(0x00, seconds, (roll_t, pitch_t, 0.0, yaw_t))
    att = window("attitude", 0.4)
    if att:
        r = sum(a[1] for a in att) / len(att)
        p = sum(a[2] for a in att) / len(att)
        y = math.degrees(math.atan2(sum(math.sin(math.radians(a[3])) for a in att),
                                    sum(math.cos(math.radians(a[3])) for a in att)))
        err = (abs(r - roll_t), abs(p - pitch_t), abs((y - yaw_t + 180) % 360 - 180))
        details["attitude command (roll, pitch, yaw deg)"] = [roll_t, pitch_t, round(yaw_t, 2)]
        details["attitude reached"] = [round(r, 2), round(p, 2), round(y, 2)]
        if max(err) > 0.5:
            problems.append(f"attitude off by {max(err):.2f} deg (accuracy 0.5 deg)")
    else:
        problems.append("no attitude sample during the attitude command")
    # 2. velocity and yaw rate
    vel_t, yaw_rate_t = (1.0, -0.5, 0.3), 10.0
    stream(0x48, seconds, (*vel_t, yaw_rate_t))
    vel, att = window("velocity", 0.4), window("attitude", min(1.0, seconds / 2))
    if vel and len(att) > 2:
        v = [sum(s[i] for s in vel) / len(vel) for i in (1, 2, 3)]
        dyaw = (att[-1][3] - att[0][3] + 180) % 360 - 180
        rate = dyaw / (att[-1][0] - att[0][0])
        details["velocity command (x, y, z m/s; yaw rate deg/s)"] = [*vel_t, yaw_rate_t]
        details["velocity reached"] = [round(x, 3) for x in v] + [round(rate, 2)]
        if max(abs(a - b) for a, b in zip(v, vel_t)) > 0.2:
            problems.append(f"velocity off by {max(abs(a - b) for a, b in zip(v, vel_t)):.2f} m/s (accuracy 0.2 m/s)")
        if abs(rate - yaw_rate_t) > 0.5:
            problems.append(f"yaw rate {rate:.2f} deg/s for {yaw_rate_t} (limit 0.5 deg/s)")
    else:
        problems.append("no velocity/attitude samples during the velocity command")
    # 3. position offset and height, closed loop on the broadcast position
    lat0, lon0, _alt0, h0 = state()["position"][1]
    goal = (2.0, 1.0, h0 + 1.0)

    def where():
        lat, lon, _alt, h = state()["position"][1]
        return (lat - lat0) * 6378137.0, (lon - lon0) * 6378137.0 * math.cos(lat0), h

    def offsets():
        n, e, _h = where()
        return goal[0] - n, goal[1] - e, goal[2], yaw_t

    stream(0x90, seconds * 5 / 3, offsets)
    n, e, h = where()
    details["position goal (north, east m; height m)"] = [goal[0], goal[1], round(goal[2], 2)]
    details["position reached"] = [round(n, 3), round(e, 3), round(h, 3)]
    if math.hypot(n - goal[0], e - goal[1]) > 0.5 or abs(h - goal[2]) > 0.5:
        problems.append(f"position {math.hypot(n - goal[0], e - goal[1]):.2f} m, height {abs(h - goal[2]):.2f} m "
                        "from the goal (limit 0.5 m)")
    stream(0x48, 0.5, (0.0, 0.0, 0.0, 0.0))   # stop and hover
    if problems:
        res("active.movement", FAIL, "the state does not follow the commands: " + "; ".join(problems), details,
            "motion")
    else:
        res("active.movement", PASS, "attitude, velocity, yaw rate and position follow the commands", details)


# --------------------------------------------------------------------------
# Command line


def add_arguments(ap: argparse.ArgumentParser, profiles: tuple[str, ...]) -> None:
    src = ap.add_mutually_exclusive_group(required=True)
    src.add_argument("--port", metavar="URL", help="serial port: /dev/ttyUSB0, a pty path, socket://HOST:PORT, rfc2217://...")
    src.add_argument("--replay", metavar="FILE", help="run the passive checks on a pcapng capture instead")
    ap.add_argument("--baud", type=int, default=230400, help="baud rate (default 230400)")
    ap.add_argument("--profile", required=True, choices=profiles, help="broadcast wire profile of the flight controller")
    ap.add_argument("--duration", type=float, default=10.0, metavar="S", help="seconds of passive listening (default 10)")
    ap.add_argument("--active", action="store_true", help="also send commands: version, activation, frequency, control")
    ap.add_argument("--allow-motion", action="store_true", help="with --active: send movement control (MOVES THE AIRCRAFT)")
    ap.add_argument("--app-id", type=int, help="app id for activation (with --active)")
    ap.add_argument("--key-env", metavar="VAR", help="environment variable holding the app key (64 hex characters)")
    ap.add_argument("--encrypt", action="store_true", help="AES-256 encrypt the commands sent (needs --key-env)")
    ap.add_argument("--capture", metavar="FILE", help="pcapng capture file (default captures/device-<time>-<pid>.pcapng)")
    ap.add_argument("--no-capture", action="store_true", help="do not record a capture")
    ap.add_argument("--junit", metavar="FILE", help="write a JUnit XML report")
    ap.add_argument("--html", metavar="FILE", help="write a self-contained HTML report with plots")
    ap.add_argument("--rate-tolerance", type=float, default=0.10, metavar="FRAC", help="allowed rate error (default 0.10)")
    ap.add_argument("--max-link-errors", type=float, default=0.001, metavar="FRAC",
                    help="allowed link incidents per frame, per kind (default 0.001)")
    ap.add_argument("--max-jitter-ms", type=float, default=25.0, metavar="MS", help="allowed arrival spread (default 25)")
    ap.add_argument("--stall-timeout", type=float, default=1.0, metavar="S", help="longest silence allowed (default 1)")
    ap.add_argument("--flight-status-enum", choices=("old", "new"), help="override the profile's flight status enum")
    ap.add_argument("--expect-rate", action="append", default=[], metavar="ITEM=HZ",
                    help="a rate the FC is configured for, when not the profile default (repeatable)")
    ap.add_argument("--active-window", type=float, default=2.0, metavar="S",
                    help="seconds to measure rates after setting frequencies (default 2)")
    ap.add_argument("--motion-seconds", type=float, default=1.5, metavar="S",
                    help="seconds each movement command is held (default 1.5; position 5/3 of it)")
    ap.add_argument("-q", "--quiet", action="store_true", help="print only the summary and the failures")


def _options(args) -> Options:
    from .rules import RulesError, default_rules

    prof = default_rules().profile(args.profile)
    rates = {}
    for spec in args.expect_rate:
        item, _, hz = spec.partition("=")
        if item not in prof.flag_bits or not hz.isdigit():
            raise UsageError(f"--expect-rate {spec}: want ITEM=HZ, ITEM one of {', '.join(prof.flag_bits)}")
        rates[item] = int(hz)
    try:
        if args.flight_status_enum:
            default_rules().flight_status_enum(args.profile, args.flight_status_enum)
    except RulesError as e:
        raise UsageError(str(e)) from None
    return Options(profile=args.profile, duration=args.duration, rate_tolerance=args.rate_tolerance,
                   max_link_errors=args.max_link_errors, max_jitter_ms=args.max_jitter_ms,
                   stall_timeout=args.stall_timeout, flight_status_enum=args.flight_status_enum,
                   expect_rates=rates or None)


def print_results(results: list[Result], quiet: bool, stream=None) -> None:
    from .report import summary_table

    stream = stream or sys.stdout
    for r in results:
        if quiet and r.status in (PASS, SKIP):
            continue
        stream.write(f"{r.status.upper():5} {r.id:28} {r.message}\n")
    stream.write("\n" + summary_table(results) + "\n")


def write_reports(args, results: list[Result], an, meta: dict) -> None:
    from .device_plots import checks_html, plots_html
    from .report import write_html, write_junit

    if args.junit:
        write_junit(args.junit, results, "osdkc device", {k: str(v) for k, v in meta.items()})
    if args.html:
        write_html(args.html, results, f"OPEN protocol acceptance: {meta.get('profile')}", meta,
                   extra_html=checks_html(results) + plots_html(an))


def run_device(args: argparse.Namespace) -> int:
    from .device_analysis import Analyzer
    from .device_wire import key_option

    opts = _options(args)
    key = key_option(args.key_env, args.encrypt)
    if args.allow_motion and not args.active:
        raise UsageError("--allow-motion needs --active")
    if args.duration <= 0 or args.active_window <= 0 or args.motion_seconds <= 0:
        raise UsageError("--duration, --active-window and --motion-seconds must be positive")
    an = Analyzer(args.profile, key, opts.expect_rates, opts.flight_status_enum)
    if args.replay:
        return _replay(args, an, opts)

    from .capture import CaptureWriter, default_capture_path

    if args.allow_motion:
        print(MOTION_WARNING, file=sys.stderr, flush=True)
    cap = None
    port = Port(args.port, args.baud, an, None)
    port.open()   # before the capture: a port that cannot be opened leaves no file behind
    if not args.no_capture:
        path = Path(args.capture) if args.capture else default_capture_path()
        meta_c = {"tool": "osdkc device", "profile": args.profile, "port": args.port, "baud": args.baud,
                  "started": time.strftime("%Y-%m-%dT%H:%M:%S%z")}
        try:
            cap = CaptureWriter(path, meta_c)
        except OSError as e:
            port.close()
            raise UsageError(f"cannot write the capture {path}: {e.strerror or e}") from None
        port.cap = cap
        print(f"osdkc device: capturing to {path}", file=sys.stderr, flush=True)
    results: list[Result] = [Result("link", "link.open", PASS, f"opened {args.port} at {args.baud} baud")]
    interrupted = False
    try:
        end = time.monotonic() + args.duration
        while time.monotonic() < end:
            time.sleep(min(0.1, max(0.0, end - time.monotonic())))
        active: list[Result] = []
        if args.active:
            if port.ser is None:
                active.append(Result("active", "active.version", ERROR, "port down: active checks not run"))
            else:
                cmd = Commander(port, an, args.profile, key, args.encrypt)
                active = active_checks(cmd, an, opts, args.app_id, args.allow_motion, args.active_window,
                                       args.motion_seconds)
    except KeyboardInterrupt:
        interrupted = True
        active = []
    finally:
        port.close()
        an.finish(port.state.t_end)
        if cap:
            cap.close()
    with an.lock:
        results += passive_results(an, opts, port.state)
    results += active
    if interrupted:
        results.append(Result("run", "run.complete", ERROR, "interrupted by the user", kind="interrupted"))
    meta = {"profile": args.profile, "port": args.port, "baud": args.baud, "duration s": args.duration,
            "capture": str(cap.path) if cap else "none", "active": args.active}
    print_results(results, args.quiet)
    write_reports(args, results, an, meta)
    from .report import conforms
    ok = conforms(results)
    print(f"\nosdkc device: {'PASS' if ok else 'FAIL'} ({args.profile} on {args.port})")
    return 0 if ok else 1


def _replay(args, an, opts: Options) -> int:
    from .capture import CaptureError, RX, read_capture

    try:
        capf = read_capture(args.replay)
    except (OSError, CaptureError) as e:
        raise UsageError(f"cannot read capture {args.replay}: {getattr(e, 'strerror', None) or e}") from None
    for rec in capf.records:
        (an.feed_rx if rec.direction == RX else an.feed_tx)(rec.t, rec.data)
    an.finish()
    results = passive_results(an, opts, None)
    meta = {"profile": args.profile, "replay": args.replay, "records": len(capf.records),
            "incomplete last block bytes": capf.partial_tail, **{f"capture {k}": v for k, v in capf.comment.items()}}
    if capf.partial_tail:
        print(f"osdkc device: {args.replay} ends in an incomplete block ({capf.partial_tail} bytes; "
              "the recording process was killed): replaying the complete blocks", file=sys.stderr)
    print_results(results, args.quiet)
    write_reports(args, results, an, meta)
    from .report import conforms
    ok = conforms(results)
    print(f"\nosdkc device: {'PASS' if ok else 'FAIL'} ({args.profile}, replay of {args.replay})")
    return 0 if ok else 1
