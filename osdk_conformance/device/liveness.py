"""Is the flight controller still well? The check `osdkc fuzz --port` makes
between cases, with bounded waits.

A check asks two things. The broadcast keeps arriving: a broadcast frame
came within `stall_timeout` of the check, and over the last `rate_window`
seconds the frame rate is within `rate_tolerance` of the configured one
(the fastest item's rate of the analyzer's current epoch: the profile's
defaults, --expect-rate, or what an acknowledged set frequency asked for).
A rate that reads low on the arrival clock is measured again as the device
sent it: SEQ steps over its own time stamps, when the frames carry them and
that clock keeps the host's time (Analyzer.fc_clock_trusted). A reader this
host left unscheduled reads a burst of late frames, or loses some in a full
buffer; neither is a slower broadcast.
A harmless command is answered: a version query gets an ACK within
`ack_timeout` that decodes as the version reply and names the same version
as before the first case. A device that restarted is caught by its
broadcast: the SEQ jumps back, or the time stamp runs backwards.

Before the query the link is padded (`Deframer.needs`) so that a frame a
case left unfinished cannot swallow it; when the query goes unanswered, the
check sends a longest frame's worth of padding and asks once more, and
says so (`retried`): a device that needs that is slow to recover, not dead.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field

from osdk_conformance.core.deframe import MAX_LEN
from osdk_conformance.core.wire import encode
from osdk_conformance._construct.payload import osdk_payload

SYMPTOMS = {
    "no_ack": "the version query was not answered",
    "bad_ack": "the version query was answered wrongly",
    "broadcast_stopped": "the broadcast stopped",
    "broadcast_slow": "the broadcast slowed below its configured rate",
    "reset": "the device restarted (broadcast SEQ or time stamp went back)",
}
# What only arrival times show: a busy host can make them fail (a reader left
# waiting, a stand-in flight controller starved on the same host).
TIMED_SYMPTOMS = ("no_ack", "broadcast_stopped", "broadcast_slow")
PROBE_SESSION = 2
KEEP_S = 30.0        # seconds of the analyzer's time series a session keeps (checks look back at most rate_window)
TRIM_EVERY_S = 10.0
FAILED_KEPT = 1000
PROBE_SEQS = 0x1FFF   # probes use SEQ 1..0x1FFF, the session's commands 0x2000.., the cases 0x4000..
COMMAND_SEQ_START = 0x2000
SEQ_JUMP = 0x8000   # a broadcast SEQ that moves back by more than a wrap could explain


@dataclass
class LivenessOptions:
    ack_timeout: float = 1.0
    stall_timeout: float = 1.0
    rate_window: float = 2.0
    rate_tolerance: float = 0.5


@dataclass
class Check:
    """One liveness check: when, after which case, what was wrong."""

    t: float
    after: str
    symptoms: list[str] = field(default_factory=list)
    details: dict = field(default_factory=dict)
    ack_s: float | None = None
    retried: bool = False

    @property
    def ok(self) -> bool:
        return not self.symptoms

    @property
    def timing_only(self) -> bool:
        return bool(self.symptoms) and all(s in TIMED_SYMPTOMS for s in self.symptoms)

    def describe(self) -> str:
        return "; ".join(f"{SYMPTOMS[s]} ({self.details[s]})" if s in self.details else SYMPTOMS[s]
                         for s in self.symptoms) or "live"


class Liveness:
    """The checks of one session over an analyzer (device/analysis.py) fed
    by the port; `send(data, comment)` writes to the device (paced)."""

    def __init__(self, an, send, profile: str, opts: LivenessOptions, key: bytes | None = None) -> None:
        self.an, self.send, self.profile, self.opts = an, send, profile, opts
        self.key = key   # the probe goes out AES-256 encrypted with it (--encrypt)
        self.seq = 0
        self.query = osdk_payload(0, 0, False, profile).build({"body": {"arbitrary": 0}})
        self.version: tuple[bytes, int] | None = None   # name and CRC before the first case
        # the timeline, per second of wall time: checks, failed checks, round trip sum (ms) and count,
        # broadcast frames; and the failed checks themselves (the first FAILED_KEPT)
        self.bins: dict[int, list[float]] = {}
        self.failed: list[Check] = []
        self._trimmed = time.time()
        self._bcast_seen = 0
        self._ts_back = 0
        self.window_start = 0.0

    def restarted_window(self) -> None:
        """Rates are measured from now on (after a rate change, a restart or a recovery)."""
        self.window_start = time.time()
        with self.an.lock:
            self._bcast_seen = len(self.an.bcast)
            self._ts_back = self.an.findings["time_stamp"].count

    def fill_rate_window(self) -> None:
        """Wait until the rate is judged again (a rate window since restarted_window)."""
        while (left := self.window_start + self.opts.rate_window - time.time()) > 0:
            time.sleep(min(left, 0.1))

    def rate_judged(self, c: Check) -> bool:
        """Whether check `c` judged the broadcast rate, or had none to judge."""
        with self.an.lock:
            expected = max(self.an.epochs[-1].rates.values(), default=0)
        return not expected or "rate_hz" in c.details or "broadcast_stopped" in c.symptoms

    def pad(self, comment: str, n: int | None = None) -> None:
        """Zero bytes (never a start byte) enough to finish any frame the
        device may be waiting for: what the analyzer's own copy of its
        receiver needs, or `n`."""
        with self.an.lock:
            need = self.an.tx_deframer.needs() if n is None else n
        while need:
            self.send(bytes(need), comment)
            with self.an.lock:
                need = self.an.tx_deframer.needs()

    def ask(self, after: str) -> tuple[bytes | None, float]:
        self.seq = self.seq % PROBE_SEQS + 1   # below the session's commands' and the cases' SEQs
        key = (PROBE_SESSION, self.seq)
        with self.an.lock:
            self.an.acks.pop(key, None)    # a case's ACK with this SEQ is not an answer to the probe
        t0 = time.monotonic()
        self.send(encode(cmd_set=0, cmd_id=0, value=self.query, session=PROBE_SESSION, seq=self.seq, key=self.key),
                  f"liveness probe after {after}")
        ack = self.an.wait_ack(PROBE_SESSION, self.seq, self.opts.ack_timeout)
        return (ack[3] if ack else None), time.monotonic() - t0

    def version_of(self, value: bytes) -> tuple[bytes, int] | None:
        try:
            body = osdk_payload(0, 0, True, self.profile).parse(value).body
        except Exception:  # noqa: BLE001 - any value that is not a version reply
            return None
        return bytes(body.version_name).rstrip(b"\0"), int(body.version_crc)

    def baseline(self) -> str | None:
        """Before the first case: the broadcast arrives and the version query is
        answered. None when it is so, else what is wrong."""
        first_frame_s = max(self.opts.stall_timeout * 3, 2.0)
        end = time.monotonic() + first_frame_s
        while time.monotonic() < end:
            with self.an.lock:
                if self.an.bcast:
                    break
            time.sleep(0.05)
        else:
            return f"no broadcast frame within {first_frame_s:g} s"
        self.pad("padding before the first probe", MAX_LEN + 1)
        value, _ = self.ask("start")
        if value is None:
            value, _ = self.ask("start")
        if value is None:
            return f"the version query was not answered within {self.opts.ack_timeout:g} s (two tries)"
        self.version = self.version_of(value)
        if self.version is None:
            return f"the version reply does not decode ({value.hex()})"
        self.restarted_window()
        return None

    def check(self, after: str) -> Check:
        c = Check(time.time(), after)
        self.pad(f"padding after {after}")
        value, waited = self.ask(after)
        if value is None:
            self.pad(f"padding after {after}, before a second probe", MAX_LEN + 1)
            c.retried = True
            value, waited = self.ask(after)
        if value is None:
            c.symptoms.append("no_ack")
            c.details["no_ack"] = f"no ACK within {self.opts.ack_timeout:g} s, twice"
        else:
            c.ack_s = waited
            got = self.version_of(value)
            if got != self.version:
                c.symptoms.append("bad_ack")
                c.details["bad_ack"] = (f"reply {value.hex()}" if got is None
                                        else f"version {got[0]!r} CRC {got[1]:#010x}, before "
                                             f"{self.version[0]!r} CRC {self.version[1]:#010x}")
        self.broadcast(c)
        row = self._bin(c.t)
        row[0] += 1
        if c.ack_s is not None:
            row[2] += c.ack_s * 1000
            row[3] += 1
        if not c.ok:
            row[1] += 1
            if len(self.failed) < FAILED_KEPT:
                self.failed.append(c)
        self._trim(c.t)
        return c

    def _bin(self, t: float) -> list[float]:
        return self.bins.setdefault(int(t), [0, 0, 0.0, 0, 0])

    def _trim(self, now: float) -> None:
        """Memory stays bounded however long the session runs."""
        if now - self._trimmed >= TRIM_EVERY_S:
            self._trimmed = now
            self._bcast_seen = max(0, self._bcast_seen - self.an.forget_before(now - KEEP_S))

    def broadcast(self, c: Check) -> None:
        """The broadcast half of a check: still arriving, at its rate, from a device that did not restart."""
        an, now = self.an, time.time()
        with an.lock:
            new = an.bcast[self._bcast_seen:]
            prev = an.bcast[self._bcast_seen - 1] if self._bcast_seen else None
            self._bcast_seen = len(an.bcast)
            ts_back = an.findings["time_stamp"].count - self._ts_back
            self._ts_back += ts_back
            last = an.bcast[-1][0] if an.bcast else None
            expected = max(an.epochs[-1].rates.values(), default=0)
            window = [b for b in an.bcast[-int(expected * self.opts.rate_window * 2 + 10):]
                      if b[0] >= now - self.opts.rate_window]
        for b in new:
            self._bin(b[0])[4] += 1
        seqs = ([prev[1]] if prev else []) + [b[1] for b in new]
        jumps = [(a, b) for a, b in zip(seqs, seqs[1:]) if (b - a) & 0xFFFF > SEQ_JUMP]
        if jumps or ts_back:
            c.symptoms.append("reset")
            c.details["reset"] = ", ".join(filter(None, [
                f"SEQ {jumps[0][0]} then {jumps[0][1]}" if jumps else "",
                f"time stamp went back {ts_back} time(s)" if ts_back else ""]))
        if expected and (last is None or now - last > self.opts.stall_timeout):
            c.symptoms.append("broadcast_stopped")
            c.details["broadcast_stopped"] = ("no broadcast frame since the start" if last is None
                                              else f"the last broadcast frame came {now - last:.2f} s ago")
        elif expected and now - self.window_start >= self.opts.rate_window:
            rate, clock = len(window) / self.opts.rate_window, "arrival"
            if rate < expected * (1 - self.opts.rate_tolerance) and (fc := self._fc_rate(window)) is not None:
                rate, clock = fc, "flight controller time stamp"
            c.details["rate_hz"] = round(rate, 1)
            if rate < expected * (1 - self.opts.rate_tolerance):
                c.symptoms.append("broadcast_slow")
                c.details["broadcast_slow"] = (f"{rate:.1f} frames/s over {self.opts.rate_window:g} s on the {clock} "
                                               f"clock, configured {expected} Hz")

    def _fc_rate(self, window: list[tuple[float, int, int]]) -> float | None:
        """Frames per second the device sent over `window` (broadcast entries,
        in arrival order), on its own clock: the SEQ steps from the first to
        the last frame that carries a time stamp, over the time between those
        stamps. SEQ steps count the frames this host lost (a reader left
        unscheduled lets the port's buffer overflow) as sent, which they were.
        None when fewer than three frames carry a stamp, the clock is not
        trusted, or the SEQ went back (a restart, judged apart)."""
        if len(window) < 3 or not self.an.fc_clock_trusted():
            return None
        t0, t1 = window[0][0], window[-1][0]
        with self.an.lock:
            stamps = [s for s in self.an.fc_stamps if t0 <= s[0] <= t1]
        if len(stamps) < 3 or stamps[0][2] is None or stamps[-1][2] is None:
            return None
        steps = (stamps[-1][1] - stamps[0][1]) & 0xFFFF
        span = stamps[-1][2] - stamps[0][2]
        if span <= 0 or not 0 < steps < SEQ_JUMP:
            return None
        return steps / span
