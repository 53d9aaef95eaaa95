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

Exit status: EXIT_STATUS below (also the --help epilog and docs/ACCEPTANCE.md).
An active run always ends through ActiveRun.clean_up (device_active.py).
"""
from __future__ import annotations

import argparse
import contextlib
import math
import os
import sys
import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .errors import UsageError, one_line
from .report import ERROR, FAIL, PASS, SKIP, Result

EXIT_STATUS = ("exit status: 0 every check passed, 1 a check failed or errored, 2 usage or port error, "
               "130 interrupted by SIGINT, 143 by SIGTERM (an interrupted run releases control, restores the "
               "rates it changed and still writes its reports; a second SIGINT cuts that clean-up short)")

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
    if an.first_t is None:  # the window never started; link.stall reports the silence
        return Result(cat, cid, SKIP, "no byte received: no rate to measure")
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

    def __init__(self, url: str, baud: int, analyzer, capture=None) -> None:
        self.url, self.baud, self.an, self.cap = url, baud, analyzer, capture
        self.state = LinkState()
        self.ser = None
        self.stop = threading.Event()
        self.wlock = threading.Lock()
        self.thread: threading.Thread | None = None
        # a section no signal exception may interrupt (Interrupts.critical in a live run)
        self.critical = contextlib.nullcontext

    def _open(self):
        import serial

        return serial.serial_for_url(self.url, baudrate=self.baud, timeout=0.05, write_timeout=1.0)

    def open(self, start: bool = True) -> None:
        """Open the port and (unless `start` is False) start reading."""
        try:
            self.ser = self._open()
        except Exception as e:  # SerialException, ValueError (bad URL), OSError
            raise UsageError(f"cannot open port {self.url}: {one_line(e)}") from None
        if start:
            self.start(self.cap)

    def start(self, capture) -> None:
        """Attach the capture, then start reading: the capture holds every byte the analyzer counts."""
        with self.critical():   # a signal here leaves either no reader or a started one
            self.cap = capture
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
                self.state.disconnects.append([t, None, one_line(e)])
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
        """Record and register the bytes, then send them. In that order: an ACK
        that comes back at once finds its command (else it is dropped and the
        command sent again), and the capture keeps the order the device saw.
        Bytes a failing write may have sent in part stay recorded."""
        with self.critical(), self.wlock:
            if self.ser is None:
                raise PortDown("the port is down")
            ts = time.time_ns()
            if self.cap:
                self.cap.tx(data, ts)
            self.an.feed_tx(ts / 1e9, data)
            try:
                self.ser.write(data)
            except Exception as e:
                raise PortDown(one_line(e)) from None

    def close(self) -> None:
        self.stop.set()
        if self.thread and self.thread.ident is not None:
            self.thread.join(2.0)
        self.state.t_end = time.time()
        with self.wlock:
            if self.ser is not None:
                try:
                    self.ser.close()
                except Exception:
                    pass


# --------------------------------------------------------------------------
# Command line


def add_arguments(ap: argparse.ArgumentParser, profiles: tuple[str, ...]) -> None:
    from .options import baud_rate, non_negative_float, fraction, positive_float, uint32

    src = ap.add_mutually_exclusive_group(required=True)
    src.add_argument("--port", metavar="URL", help="serial port: /dev/ttyUSB0, a pty path, socket://HOST:PORT, rfc2217://...")
    src.add_argument("--replay", metavar="FILE", help="run the passive checks on a pcapng capture instead")
    ap.add_argument("--baud", type=baud_rate, default=230400, help="baud rate (default 230400)")
    ap.add_argument("--profile", required=True, choices=profiles, help="broadcast wire profile of the flight controller")
    ap.add_argument("--duration", type=positive_float, default=10.0, metavar="S", help="seconds of passive listening (default 10)")
    ap.add_argument("--active", action="store_true", help="also send commands: version, activation, frequency, control")
    ap.add_argument("--allow-motion", action="store_true", help="with --active: send movement control (MOVES THE AIRCRAFT)")
    ap.add_argument("--app-id", type=uint32, help="app id for activation (with --active)")
    ap.add_argument("--key-env", metavar="VAR", help="environment variable holding the app key (64 hex characters)")
    ap.add_argument("--encrypt", action="store_true", help="AES-256 encrypt the commands sent (needs --key-env)")
    ap.add_argument("--capture", metavar="FILE", help="pcapng capture file (default captures/device-<time>-<pid>.pcapng)")
    ap.add_argument("--no-capture", action="store_true", help="do not record a capture")
    ap.add_argument("--junit", metavar="FILE", help="write a JUnit XML report")
    ap.add_argument("--html", metavar="FILE", help="write a self-contained HTML report with plots")
    ap.add_argument("--rate-tolerance", type=fraction, default=0.10, metavar="FRAC", help="allowed rate error (default 0.10)")
    ap.add_argument("--max-link-errors", type=non_negative_float, default=0.001, metavar="FRAC",
                    help="allowed link incidents per frame, per kind (default 0.001)")
    ap.add_argument("--max-jitter-ms", type=positive_float, default=25.0, metavar="MS", help="allowed arrival spread (default 25)")
    ap.add_argument("--stall-timeout", type=positive_float, default=1.0, metavar="S", help="longest silence allowed (default 1)")
    ap.add_argument("--flight-status-enum", choices=("old", "new"), help="override the profile's flight status enum")
    ap.add_argument("--expect-rate", action="append", default=[], metavar="ITEM=HZ",
                    help="a rate the FC is configured for, when not the profile default (repeatable)")
    ap.add_argument("--active-window", type=positive_float, default=2.0, metavar="S",
                    help="seconds to measure rates after setting frequencies (default 2)")
    ap.add_argument("--motion-seconds", type=positive_float, default=1.5, metavar="S",
                    help="seconds each movement command is held (default 1.5; position 5/3 of it)")
    ap.add_argument("-q", "--quiet", action="store_true", help="print only the summary and the failures")
    ap.epilog = EXIT_STATUS


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
    an = Analyzer(args.profile, key, opts.expect_rates, opts.flight_status_enum)
    if args.replay:
        return _replay(args, an, opts)

    from .device_active import Interrupts

    if args.allow_motion:
        print(MOTION_WARNING, file=sys.stderr, flush=True)
    port = Port(args.port, args.baud, an)
    port.open(start=False)   # before the capture: a port that cannot be opened leaves no file behind
    interrupts = Interrupts()
    interrupts.install()
    try:
        cap = _open_capture(args, port)
        port.critical = interrupts.critical
        return _live(args, opts, an, port, cap, key, interrupts)
    finally:
        interrupts.uninstall()


def _open_capture(args, port: Port):
    from .capture import CaptureWriter, default_capture_path

    if args.no_capture:
        return None
    path = Path(args.capture) if args.capture else default_capture_path()
    meta_c = {"tool": "osdkc device", "profile": args.profile, "port": args.port, "baud": args.baud,
              "started": time.strftime("%Y-%m-%dT%H:%M:%S%z")}
    try:
        cap = CaptureWriter(path, meta_c)
    except OSError as e:
        port.close()
        raise UsageError(f"cannot write the capture {path}: {e.strerror or e}") from None
    return cap


def _live(args, opts: Options, an, port: Port, cap, key, interrupts) -> int:
    """Listen, run the active checks (which clean up after themselves however
    they end), then report every result measured, whatever ended the run."""
    from .device_active import EXIT_BY_SIGNAL, ActiveRun, Commander, not_reached
    from .report import conforms

    results: list[Result] = [Result("link", "link.open", PASS, f"opened {args.port} at {args.baud} baud")]
    run: ActiveRun | None = None
    error = ""
    try:
        if cap:
            print(f"osdkc device: capturing to {cap.path}", file=sys.stderr, flush=True)
        port.start(cap)
        end = time.monotonic() + args.duration
        while time.monotonic() < end:
            time.sleep(min(0.1, max(0.0, end - time.monotonic())))
        if args.active and port.ser is None:
            results.append(Result("active", "active.version", ERROR, "port down: active checks not run"))
        elif args.active:
            run = ActiveRun(Commander(port, an, args.profile, key, args.encrypt), an, opts, args.app_id,
                            args.allow_motion, args.active_window, args.motion_seconds, interrupts)
            run.run()
    except KeyboardInterrupt:
        pass   # the signal is in interrupts.signals; ActiveRun has cleaned up
    except Exception as e:   # a bug of ours: the clean-up ran, the results so far are still reported
        error = f"{type(e).__name__}: {one_line(e)}"
    finally:
        interrupts.mode = "report"
        port.close()
        an.finish(port.state.t_end)
        if cap:
            cap.close()
    with an.lock:
        results += passive_results(an, opts, port.state)
    signame = interrupts.first
    phase = interrupts.first_phase if signame else (run.stopped_in or run.phase) if run else "passive"
    if run:
        results += run.results
    if args.active and (signame or error):
        why = f"interrupted by {signame}" if signame else "stopped by an error"
        results += not_reached(results, f"the run was {why} during phase {phase}")
    cleanup = (run.cleanup_cut if run and run.cleanup_cut else "complete") if run else "nothing to undo"
    if signame:
        results.append(Result("run", "run.complete", ERROR, f"interrupted by {signame} during phase {phase}; "
                              f"clean-up: {cleanup}", {"signals": interrupts.signals, "phase": phase,
                                                       "clean-up": cleanup}, kind="interrupted"))
    elif error:
        results.append(Result("run", "run.complete", ERROR, f"the run stopped on an internal error during phase "
                              f"{phase}: {error}; clean-up: {cleanup}", {"phase": phase, "clean-up": cleanup},
                              kind="exception"))
    meta = {"profile": args.profile, "port": args.port, "baud": args.baud, "duration s": args.duration,
            "capture": str(cap.path) if cap else "none", "active": args.active,
            "interrupted": f"{signame} during phase {phase}" if signame else "no", "clean-up": cleanup}
    print_results(results, args.quiet)
    write_reports(args, results, an, meta)
    ok = conforms(results)
    if signame:
        print(f"\nosdkc device: INTERRUPTED by {signame} during phase {phase}, clean-up {cleanup} "
              f"({args.profile} on {args.port})")
        return EXIT_BY_SIGNAL.get(signame, 130)
    print(f"\nosdkc device: {'PASS' if ok else 'FAIL'} ({args.profile} on {args.port})")
    return 0 if ok else 1


def _replay(args, an, opts: Options) -> int:
    from .capture import CaptureError, RX, open_capture

    try:
        with open_capture(args.replay) as capf:  # block by block: memory does not grow with the file
            for rec in capf:
                (an.feed_rx if rec.direction == RX else an.feed_tx)(rec.t, rec.data)
    except OSError as e:
        raise UsageError(f"cannot read capture {args.replay}: {e.strerror or e}") from None
    except CaptureError as e:  # names the file and the offset of the damage
        raise UsageError(str(e)) from None
    an.finish()
    results = passive_results(an, opts, None)
    meta = {"profile": args.profile, "replay": args.replay, "records": capf.count,
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
