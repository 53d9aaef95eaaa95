"""What the acceptance suite measures in a received byte stream.

`Analyzer` takes received (rx) and sent (tx) bytes with their times, live
from a port or replayed from a capture, and keeps everything the checks
need: link incidents (noise, CRC failures, frames cut short), decoded
broadcast frames (flags, sequence numbers, arrival times, item times),
value plausibility findings, attitude/velocity/position traces, ACKs of
the commands sent, and "epochs": spans of time with one set of configured
broadcast rates (profile defaults, then whatever an acknowledged set
frequency command asked for). The functions of checks.py
turn this into Results.

Payloads are decoded by reference/decode.py's `payload_body` (the native
decoder when it is installed, else Construct), so the values kept in
`latest` and handed to `on_broadcast` are the JSON value model
(docs/VALUE-MODEL.md): dicts, floats as {"f32"/"f64": hex, "value": ...},
enums as {"value": int, "name": ...}.
"""
from __future__ import annotations

import math
import threading
from bisect import bisect_left
from dataclasses import dataclass, field
from typing import Any, Callable, Sequence

from osdk_conformance.core.errors import one_line
from osdk_conformance.core.deframe import HEADER_LEN, Deframer, Frame, Garbage, Rejected
from osdk_conformance.core.rules import default_rules, hz_of_code
from osdk_conformance.core.wire import open_frame
from osdk_conformance.reference.decode import DecodeFailure, payload_body
from osdk_conformance.reference import values
from osdk_conformance.sim.simulator import quaternion_to_euler

HZ_OF_CODE = hz_of_code()
CODE_OF_HZ = {v: k for k, v in HZ_OF_CODE.items()}
MAX_EXAMPLES = 5
CLOCK_AGREEMENT = 0.5    # a time stamp clock that runs off the host's by more is not trusted for rates
CLOCK_MIN_SPAN = 0.5      # seconds of time stamps before the FC's clock can be compared with the host's
MOVEMENT_GAP = 0.5        # s between movement commands that ends a run of them (the FC hovers after that long)


@dataclass
class Epoch:
    start: float
    rates: dict[str, int]
    source: str
    requested: float | None = None   # when the command setting these rates was first sent


@dataclass
class Finding:
    """Violations of one value rule: how many, out of how many samples, first examples."""

    samples: int = 0
    count: int = 0
    examples: list[str] = field(default_factory=list)

    def add(self, ok: bool, example: Callable[[], str]) -> None:
        """One sample; `example()` describes a violation, and is only called
        for the ones kept (formatting every sample cost more than checking it)."""
        self.samples += 1
        if not ok:
            self.count += 1
            if len(self.examples) < MAX_EXAMPLES:
                self.examples.append(example())


_VECTOR_ITEMS = (("acceleration", ("x", "y", "z")), ("velocity", ("x", "y", "z")),
                 ("angular_rate", ("x", "y", "z")), ("gimbal", ("roll", "pitch", "yaw")))
"""Items of three floats that must be finite, with their field names."""

VALUE_RULES = ("quaternion_norm", "gps_health", "battery", "rc_channels", "flight_status", "time_stamp",
               "control_info", "finite")


class Analyzer:
    def __init__(self, profile: str, key: bytes | None = None, expect_rates: dict[str, int] | None = None,
                 flight_status_enum: str | None = None, ack_reorder_s: float = 0.0) -> None:
        """`ack_reorder_s`: how much sooner than its command an ACK may be
        read and still answer it. 0 for one port, where the answer cannot
        overtake the question; two ports (a Y-cable's two adapters,
        tap/judge.REORDER_S) deliver each line with its own latency."""
        rules = default_rules()
        self.rules = rules
        self.prof = rules.profile(profile)
        self.key = key
        # the native decoder when it is installed: about a tenth of Construct's time per broadcast frame
        self._body = payload_body(profile)
        self.lock = threading.RLock()
        self.ack_cond = threading.Condition(self.lock)
        self.rx_deframer = Deframer()
        self.tx_deframer = Deframer()
        rates = dict(self.prof.default_rates_hz)
        rates.update(expect_rates or {})
        self.epochs: list[Epoch] = [Epoch(0.0, rates, "expected" if expect_rates else "profile defaults")]
        self.first_t: float | None = None
        self.last_t: float | None = None
        self.rx_bytes = 0
        self.rx_chunks: list[tuple[float, int]] = []   # arrival time, bytes
        # link
        self.frames = 0
        self.incidents: list[tuple[float, str, int, str]] = []   # t, kind, bytes, detail
        self._gap: list[Any] = []
        self._gap_t = 0.0
        self._last_end: int | None = None
        self.leading_bytes = 0
        # decode
        self.decode_errors: dict[str, int] = {}
        self.decode_examples: list[str] = []
        self.undecoded_broadcasts: list[bytes] = []
        self.encrypted_unopened = 0
        # stream
        self.bcast: list[tuple[float, int, int]] = []          # t, seq, flags
        self.bcast_raw_prev: bytes | None = None
        self.duplicates = 0
        self.item_times: dict[str, list[float]] = {i: [] for i in self.prof.flag_bits}
        # the same frames on the flight controller's own clock (its time stamp item, s), None when not known
        self.item_clock: dict[str, list[float | None]] = {i: [] for i in self.prof.flag_bits}
        # t, SEQ and FC clock (s, None when its ticks went back) of every frame with a time stamp item
        self.fc_stamps: list[tuple[float, int, float | None]] = []
        self._clock_ticks: int | None = None
        self._clock_s = 0.0
        self.cmd_frames: dict[str, int] = {}
        # values
        fs = rules.flight_status_enum(profile, flight_status_enum)
        self.flight_status_values = fs
        self.findings: dict[str, Finding] = {r: Finding() for r in VALUE_RULES}
        self._prev_ticks: int | None = None
        rc = rules.data["rc_channels"]["channels"]
        self.rc_rules = rc
        # (channel, min, max, allowed values or None when continuous), worked out once, not per frame
        self._rc_checks = [(ch, r.get("min"), r.get("max"),
                            None if r["kind"] == "continuous" else [x["value"] for x in r["values"]])
                           for ch, r in rc.items()]
        self.control_devices = rules.enum("control_device")
        self.cur_modes = rules.enum("cur_mov_control_mode")
        # item -> (arrival time, value): floats as numbers for attitude (deg), the vectors and position,
        # the value model for time_stamp, rc and control_info
        self.latest: dict[str, tuple[float, Any]] = {}
        self.traces: dict[str, list[tuple]] = {"attitude": [], "velocity": [], "position": []}
        # commands sent and their ACKs
        self.sent: dict[tuple[int, int], tuple[float, int, int, bytes]] = {}  # (session, seq) -> t, set, id, value
        self.acks: dict[tuple[int, int], tuple[float, int, int, bytes]] = {}  # (session, seq) -> t, set, id, value
        self.ack_reorder_s = ack_reorder_s
        self._early_acks: dict[tuple[int, int], tuple[float, bytes]] = {}   # ACKs read before any command they answer
        # movement control, sent in session 0 (no ACK) so not in `sent`: one entry per run of commands
        # with one mode byte and kind of setpoint, [first t, mode byte, all setpoints zero, last t]
        self.movement: list[list] = []
        self.on_broadcast: Callable[[float, Any], None] | None = None
        # `osdkc tap` judges the sender of the tx bytes too (tap/judge.py): every event of the tx stream, with
        # the frame opened (None for bytes the receiver dropped), and every rx frame opened
        self.on_tx: Callable[[float, Any, Any], None] | None = None
        self.on_rx_frame: Callable[[float, Any], None] | None = None

    # ---- input -----------------------------------------------------------

    def feed_rx(self, t: float, chunk: bytes) -> None:
        with self.lock:
            if self.first_t is None:
                self.first_t = t
                self.epochs[0].start = t
            self.last_t = t
            self.rx_bytes += len(chunk)
            self.rx_chunks.append((t, len(chunk)))
            for ev in self.rx_deframer.feed(chunk):
                self._rx_event(t, ev)

    def feed_tx(self, t: float, chunk: bytes) -> None:
        with self.lock:
            for ev in self.tx_deframer.feed(chunk):
                if not isinstance(ev, Frame):
                    if self.on_tx:
                        self.on_tx(t, ev, None)
                    continue
                op = open_frame(ev.raw, self.key)
                if self.on_tx:
                    self.on_tx(t, ev, op)
                if not op.is_ack and op.cmd_set is not None and op.session > 0:
                    key, new = (op.session, op.seq), (t, op.cmd_set, op.cmd_id, op.value)
                    old = self.sent.get(key)
                    if old is None or old[1:] != new[1:]:   # a retransmission keeps the first send time
                        self.sent[key] = new
                        early = self._early_acks.pop(key, None)
                        if early is not None and t - early[0] <= self.ack_reorder_s:
                            self._acked(key, early[0], new, early[1])
                if not op.is_ack and not op.problem and (op.cmd_set, op.cmd_id) == (1, 3) and op.value:
                    self._movement(t, op.value)

    def _movement(self, t: float, value: bytes) -> None:
        mode, zero = value[0], not any(value[1:])
        last = self.movement[-1] if self.movement else None
        if last and last[1] == mode and last[2] == zero and t - last[3] <= MOVEMENT_GAP:
            last[3] = t
        else:
            self.movement.append([t, mode, zero, t])

    def finish(self, t: float | None = None) -> None:
        with self.lock:
            cut_end = -1
            for ev in self.rx_deframer.finish():
                if isinstance(ev, Rejected) and ev.error == "truncated_frame":
                    # the run ended in the middle of a frame: not the device's fault, and neither are the
                    # rest of its bytes, which the receiver then scans again as garbage
                    cut_end = max(cut_end, ev.offset + ev.length)
                    continue
                if not isinstance(ev, Frame) and ev.offset < cut_end:
                    continue
                self._rx_event(self.last_t or 0.0, ev)
            self._close_gap(final=True)
            if t is not None:
                self.last_t = max(self.last_t or t, t)

    # ---- link ------------------------------------------------------------

    def _rx_event(self, t: float, ev) -> None:
        if isinstance(ev, Frame):
            if self._gap:
                self._close_gap(end=ev.offset)
            self._last_end = ev.offset + len(ev.raw)
            self.frames += 1
            self._frame(t, ev.raw)
        else:
            if not self._gap:
                self._gap_t = t
            self._gap.append(ev)

    def _close_gap(self, end: int | None = None, final: bool = False) -> None:
        gap, self._gap = self._gap, []
        if not gap:
            return
        start = gap[0].offset
        if end is None:
            last = gap[-1]
            end = last.offset + last.length
        n = end - start
        if self._last_end is None:
            # bytes before the first good frame: the run joined the stream mid-frame
            self.leading_bytes += n
            return
        first = gap[0]
        if isinstance(first, Garbage):
            kind, detail = "noise", f"{n} byte(s) outside any frame"
        elif first.error == "bad_crc32":
            if n < first.length:
                kind, detail = "short", f"frame of LEN {first.length} interrupted after {n} byte(s) by the next frame"
            else:
                kind, detail = "crc", first.detail
        elif n < HEADER_LEN:
            kind, detail = "short", f"frame interrupted after {n} byte(s), inside its header"
        elif first.error == "bad_crc16":
            kind, detail = "crc", first.detail
        elif first.error == "truncated_frame":
            kind, detail = "short", first.detail
        else:
            kind, detail = "header", f"{first.error}: {first.detail}"
        self.incidents.append((self._gap_t, kind, n, detail))

    # ---- frames ----------------------------------------------------------

    def _frame(self, t: float, raw: bytes) -> None:
        op = open_frame(raw, self.key)
        if op.problem:
            if op.encrypted:
                self.encrypted_unopened += 1
            self._decode_error("undecodable", op.problem)
            return
        if self.on_rx_frame:
            self.on_rx_frame(t, op)
        if op.is_ack:
            with self.ack_cond:
                key = (op.session, op.seq)
                sent = self.sent.get(key)
                if sent:
                    self._acked(key, t, sent, op.value)
                elif self.ack_reorder_s > 0:   # its command may still be on its way, on the other line
                    self._early_acks = {k: v for k, v in self._early_acks.items() if t - v[0] <= self.ack_reorder_s}
                    self._early_acks[key] = (t, op.value)
                self.ack_cond.notify_all()
            return
        name = {(2, 0): "broadcast", (2, 1): "lost_control"}.get((op.cmd_set, op.cmd_id), "other")
        self.cmd_frames[name] = self.cmd_frames.get(name, 0) + 1
        if name != "broadcast":
            try:
                self._body(op.value, op.cmd_set, op.cmd_id, False)
            except Exception as e:
                cls, detail = _failure(e)
                self._decode_error(cls, f"command {op.cmd_set:#04x}/{op.cmd_id:#04x}: {detail}")
            return
        try:
            data = self._body(op.value, 2, 0, False)["data"]
        except Exception as e:
            cls, detail = _failure(e)
            self._decode_error(cls, f"broadcast seq {op.seq}, {len(op.value)} bytes: {detail}")
            if len(self.undecoded_broadcasts) < 200:
                self.undecoded_broadcasts.append(op.value)
            return
        flags = op.value[0] | op.value[1] << 8
        self.bcast.append((t, op.seq, flags))
        if self.bcast_raw_prev == raw:
            self.duplicates += 1
        self.bcast_raw_prev = raw
        ts = data.get("time_stamp")
        clock = self._fc_clock(ts["time"]) if ts is not None else None
        if ts is not None:
            self.fc_stamps.append((t, op.seq, clock))
        for bit, item in enumerate(self.prof.flag_bits):
            if flags >> bit & 1:
                self.item_times[item].append(t)
                self.item_clock[item].append(clock)
        self._values(t, data, clock)
        if self.on_broadcast:
            self.on_broadcast(t, data)

    def _decode_error(self, cls: str, detail: str) -> None:
        self.decode_errors[cls] = self.decode_errors.get(cls, 0) + 1
        if len(self.decode_examples) < MAX_EXAMPLES:
            self.decode_examples.append(f"{cls}: {detail}")

    # ---- values ----------------------------------------------------------

    def _values(self, t: float, d, clock: float | None = None) -> None:
        f = self.findings
        ts = d.get("time_stamp")
        if ts is not None:
            ticks, prev = ts["time"], self._prev_ticks
            if prev is not None:
                back = (ticks - prev) % (1 << 32) > (1 << 31)
                f["time_stamp"].add(not back, lambda: f"t={t:.3f}: time {ticks} after {prev}")
            self._prev_ticks = ticks
            self.latest["time_stamp"] = (t, ts)
        quat = d.get("quaternion")
        if quat is not None:
            q = [_float(quat["q0"]), _float(quat["q1"]), _float(quat["q2"]), _float(quat["q3"])]
            norm = math.sqrt(sum(c * c for c in q))
            f["quaternion_norm"].add(abs(norm - 1.0) <= 1e-3, lambda: f"t={t:.3f}: |q| = {norm:.6g}")
            if all(math.isfinite(c) for c in q):
                r, p, y = (math.degrees(a) for a in quaternion_to_euler(*q))
                self.traces["attitude"].append((t, r, p, y, clock))
                self.latest["attitude"] = (t, (r, p, y))
        for item, keys in _VECTOR_ITEMS:
            v = d.get(item)
            if v is not None:
                vals = [_float(v[k]) for k in keys]
                f["finite"].add(all(math.isfinite(x) for x in vals), lambda: f"t={t:.3f}: {item} {vals}")
                self.latest[item] = (t, vals)
                if item == "velocity":
                    self.traces["velocity"].append((t, *vals, clock))
        pos = d.get("position")
        if pos is not None:
            vals = [_float(pos["latitude"]), _float(pos["longitude"]), _float(pos["altitude"]), _float(pos["height"])]
            f["finite"].add(all(math.isfinite(x) for x in vals), lambda: f"t={t:.3f}: position {vals}")
            health = pos["gps_health"]
            f["gps_health"].add(0 <= health <= 5, lambda: f"t={t:.3f}: gps_health {health}")
            self.latest["position"] = (t, vals)
            self.traces["position"].append((t, *vals, clock))
        battery = d.get("battery")
        if battery is not None:
            f["battery"].add(0 <= battery <= 100, lambda: f"t={t:.3f}: battery {battery}%")
        status = d.get("flight_status")
        if status is not None:
            f["flight_status"].add(status in self.flight_status_values,
                                   lambda: f"t={t:.3f}: flight status {status} not in "
                                           f"{sorted(self.flight_status_values)}")
        rc = d.get("rc")
        if rc is not None:
            bad = []
            for ch, lo, hi, allowed in self._rc_checks:
                v = rc[ch]
                if allowed is None:
                    if not lo <= v <= hi:
                        bad.append(f"{ch} {v} outside {lo}..{hi}")
                elif v not in allowed:
                    bad.append(f"{ch} {v} not one of {allowed}")
            f["rc_channels"].add(not bad, lambda: f"t={t:.3f}: " + "; ".join(bad))
            self.latest["rc"] = (t, rc)
        ci = d.get("control_info")
        if ci is not None:
            dev = ci["control_device"]["value"]
            bad = [] if dev in self.control_devices else [f"control device {dev}"]
            mode = ci.get("cur_mov_control_mode")
            if mode is not None and mode["value"] not in self.cur_modes:
                bad.append(f"cur_mov_control_mode {mode['value']}")
            f["control_info"].add(not bad, lambda: f"t={t:.3f}: " + ", ".join(bad) + " not defined")
            self.latest["control_info"] = (t, ci)

    def _acked(self, key: tuple[int, int], t: float, sent: tuple[float, int, int, bytes], ack: bytes) -> None:
        self.acks[key] = (t, sent[1], sent[2], ack)
        if (sent[1], sent[2]) == (0x00, 0x10):
            self._frequency_acked(t, sent[3], ack, sent[0])

    # ---- configuration epochs ------------------------------------------------

    def _frequency_acked(self, t: float, request: bytes, ack: bytes, requested: float | None = None) -> None:
        if len(ack) < 2 or int.from_bytes(ack[:2], "little") != 0 or len(request) < 16:
            return
        # an ACK read before its command is added when the command comes: in order of time all the same
        at = len(self.epochs)
        while at > 1 and self.epochs[at - 1].start > t:
            at -= 1
        rates = dict(self.epochs[at - 1].rates)
        for item, code in zip(self.prof.flag_bits, request):
            if code in HZ_OF_CODE:
                rates[item] = HZ_OF_CODE[code]
        self.epochs.insert(at, Epoch(t, rates, f"set frequency acknowledged at t={t:.3f}", requested))

    def epoch_end(self, i: int) -> float:
        """Where epoch i's measurements stop: when the next configuration was
        requested (the device may apply it before its ACK arrives, and a frame
        at the new rates can come in the very read that brings the ACK)."""
        if i + 1 < len(self.epochs):
            nxt = self.epochs[i + 1]
            return nxt.start if nxt.requested is None else min(nxt.start, nxt.requested)
        return self.last_t or self.epochs[i].start

    def _fc_clock(self, ticks: int) -> float | None:
        """The flight controller's time stamp (1/400 s ticks, 32 bits) as
        seconds that only go forward; None for a frame whose ticks went back."""
        prev, self._clock_ticks = self._clock_ticks, ticks
        if prev is not None:
            step = (ticks - prev) % (1 << 32)
            if step >= 1 << 31:
                return None
            self._clock_s += step / values.FC_TICKS_PER_S
        return self._clock_s

    # ---- measurements --------------------------------------------------------

    def fc_clock_trusted(self) -> bool:
        """Whether the flight controller's time stamp clock keeps the host's
        time within CLOCK_AGREEMENT, over every stamp so far. A busy host
        only ever delays an arrival, so the least arrival-minus-stamp in the
        first and in the last third of the stamps is where a frame came
        without delay: the slope between those two is the clock's error,
        whatever bursts of late frames lie in between. A clock that counts in
        the wrong unit, or an FC that stamps at random, is not trusted."""
        with self.lock:
            stamps = [(t, c) for t, _, c in self.fc_stamps if c is not None]
        if len(stamps) < 6 or stamps[-1][1] - stamps[0][1] < CLOCK_MIN_SPAN:
            return False
        third = len(stamps) // 3
        early = min(stamps[:third], key=lambda s: s[0] - s[1])
        late = min(stamps[-third:], key=lambda s: s[0] - s[1])
        fc = late[1] - early[1]
        return fc > 0 and abs((late[0] - early[0]) - fc) <= CLOCK_AGREEMENT * fc

    def measure_rates(self, rates: dict[str, int], t0: float, t1: float) -> dict[str, dict]:
        """Per item: expected Hz, frames carrying it that arrived in [t0, t1],
        measured Hz: (frames - 1) / the time from the first to the last, on
        the flight controller's time stamp clock when every one of those
        frames has it and that clock keeps the host's time over the run
        (fc_clock_trusted): a host that was not scheduled for a moment reads
        a burst of late frames, which on the arrival clock look like a
        higher rate, then a lower one. Else on the arrival clock."""
        trusted = self.fc_clock_trusted()
        out = {}
        for item in self.prof.flag_bits:
            pairs = [(t, c) for t, c in zip(self.item_times[item], self.item_clock[item]) if t0 <= t <= t1]
            n, measured, clock = len(pairs), None, "arrival"
            if n >= 3:
                span = pairs[-1][0] - pairs[0][0]
                fc = pairs[-1][1] - pairs[0][1] if all(c is not None for _, c in pairs) else None
                if trusted and fc is not None and fc > 0:
                    span, clock = fc, "flight controller time stamp"
                measured = (n - 1) / span if span > 0 else None
            out[item] = {"expected_hz": rates.get(item, 0), "frames": n,
                         "measured_hz": None if measured is None else round(measured, 2), "clock": clock}
        return out

    def sample_span(self, samples: Sequence[tuple]) -> float:
        """Seconds from the first to the last of trace samples (their FC clock
        last): on the flight controller's clock when both have it and it is
        trusted, else on the arrival clock."""
        first, last = samples[0], samples[-1]
        if first[-1] is not None and last[-1] is not None and self.fc_clock_trusted():
            return last[-1] - first[-1]
        return last[0] - first[0]

    def forget_before(self, t: float) -> int:
        """Drop what arrived before `t` from the time series (a session of
        hours, `osdkc fuzz --port`, keeps a bounded window): the broadcast
        list, item times, traces, reads, incidents, commands sent and their
        ACKs, and the epochs between the first (what a clean-up restores) and
        the current one. Returns how many broadcast entries went, for a
        reader that indexes `bcast`."""
        with self.lock:
            cut = bisect_left(self.bcast, t, key=lambda b: b[0])
            del self.bcast[:cut]
            del self.fc_stamps[:bisect_left(self.fc_stamps, t, key=lambda b: b[0])]
            for item, times in self.item_times.items():
                k = bisect_left(times, t)
                del times[:k]
                del self.item_clock[item][:k]
            for trace in self.traces.values():
                del trace[:bisect_left(trace, t, key=lambda s: s[0])]
            del self.rx_chunks[:bisect_left(self.rx_chunks, t, key=lambda c: c[0])]
            self.incidents = [i for i in self.incidents if i[0] >= t]
            self.movement = [m for m in self.movement if m[3] >= t]
            for table in (self.sent, self.acks):
                for key in [k for k, v in table.items() if v[0] < t]:
                    del table[key]
            if len(self.epochs) > 2:
                self.epochs = [self.epochs[0]] + [e for e in self.epochs[1:-1] if e.start >= t] + [self.epochs[-1]]
            return cut

    def frames_between(self, t0: float, t1: float) -> list[tuple[float, int, int]]:
        return [b for b in self.bcast if t0 <= b[0] <= t1]

    def wait_ack(self, session: int, seq: int, timeout: float) -> tuple[float, int, int, bytes] | None:
        with self.ack_cond:
            self.ack_cond.wait_for(lambda: (session, seq) in self.acks, timeout)
            return self.acks.get((session, seq))


def _failure(exc: Exception) -> tuple[str, str]:
    """Error class and detail of a payload that did not decode; any other
    exception (a bug of ours) is "undecodable", so the receiver goes on."""
    if isinstance(exc, DecodeFailure):
        return exc.error_class, exc.detail
    return "undecodable", one_line(exc)


def _float(m: dict) -> float:
    """A float of the value model as a number; float() reads "NaN" and "Infinity" too."""
    return float(m["value"])


