"""A fuzzing session against a flight controller on a serial port.

The shape is boofuzz's: cases are sent one after another (device/fuzz_cases.py),
a liveness check follows each (device/liveness.py), every byte goes into the
pcapng capture with the case id as its block comment, and a failed check is a
finding. A finding is then confirmed by replaying, from the capture, the
cases sent since the last good check (and, if that is not enough, the ones
before them), and minimised: first to the fewest cases (delta debugging),
then to the fewest writes and bytes. Between trials the device is brought
back by the restart command when there is one (a relay that power-cycles
it, or `kill -HUP` for `osdkc sim`), else by waiting for it to recover.

A busy host can fail a check on timing alone (a reader left waiting, a
stand-in flight controller starved on the same host), so such a check first
faces two controls. The device, brought back, is checked with no case sent:
failing the same way, the symptom is not a case's doing, and the session
ends there (INCONCLUSIVE when this host was busy). And a failure the replay
does not confirm, seen while this host was busy (its reader not scheduled
for HOST_STALL_S, or more runnable work than cores), is not a finding: it is
counted as a check not judged, host too busy; so is, on a busy host, a
broadcast that is live but slower than configured, without a replay: it
is what a stand-in FC starved on the same host shows.

Bytes go out (PacedPort) no faster than the line carries them (10 bits a byte at the
baud rate), so a pseudo-terminal sees what a UART would, and the time a
case takes is the time it would take on the wire.

Safety is the acceptance run's (device/active.py): SIGINT and SIGTERM become
one exception at a point where no frame is half sent, and whatever ends the
session (its budget, a signal, a lost port, a bug of ours) the clean-up runs:
control is released when it was requested, the broadcast rates are set
back when a set frequency was sent. Control is only ever requested with
`allow_motion`, and then only so that the zero-setpoint movement cases reach
the command handler.
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field
from typing import Callable, Iterator

from osdk_conformance.core.capture import TX, open_capture
from osdk_conformance.core.deframe import Deframer, Frame
from osdk_conformance.core.wire import open_frame
from osdk_conformance.device.active import ActiveRun, Commander, rate_codes
from osdk_conformance.device.fuzz_cases import MOTION_KINDS, FuzzCase, cases as all_cases
from osdk_conformance.device.hostload import HostClock
from osdk_conformance.device.liveness import COMMAND_SEQ_START, Check, Liveness, LivenessOptions
from osdk_conformance.device.port import PortDown


@dataclass
class SessionOptions:
    profile: str
    seed: int
    seconds: float | None = None
    max_cases: int | None = None
    allow_motion: bool = False
    app_id: int | None = None
    baud: int = 230400
    liveness: LivenessOptions = field(default_factory=LivenessOptions)
    recover_timeout: float = 5.0
    minimise_trials: int = 40
    max_findings: int = 5
    kinds: tuple[str, ...] | None = None


@dataclass
class Finding:
    number: int
    check: Check
    suspects: list[FuzzCase]           # the cases sent since the last good check
    confirmed: bool | None = None       # None: could not be replayed (the device did not come back)
    why_unconfirmed: str = ""
    reproducer: list[FuzzCase] = field(default_factory=list)
    trials: int = 0
    repeats: int = 0                    # later failures with the same symptoms, not minimised again
    repeated_after: list[str] = field(default_factory=list)   # the case ids they followed (the first 20)
    repeated_kinds: set[str] = field(default_factory=set)     # and the kinds of all of them
    from_capture: bool = True

    @property
    def kinds(self) -> list[str]:
        return sorted({c.kind for c in (self.reproducer or self.suspects)})


@dataclass
class NotJudged:
    """A check that failed on timing alone while this host was busy: no finding."""
    check: Check
    after: str
    host: str
    replayed: bool   # the replay did not fail (else, a slowed broadcast alone: not replayed)


@dataclass
class SessionOutcome:
    sent: dict[str, int] = field(default_factory=dict)          # cases sent, by kind
    withheld: dict[str, int] = field(default_factory=dict)      # not sent for safety, by kind
    findings: list[Finding] = field(default_factory=list)
    checks: int = 0
    retried_checks: int = 0
    bytes_sent: int = 0                     # bytes sent while fuzzing: cases, padding, probes, rate restores
    seconds: float = 0.0
    start_problem: str = ""                 # the device was not live before the first case
    port_lost: str = ""                      # the port went down during the session
    stopped: str = ""                        # why the session ended before its budget
    motion: str = "not allowed (--allow-motion not given)"
    case_seconds: float = 0.0               # time spent sending cases and checking (not replays)
    not_judged: list[NotJudged] = field(default_factory=list)
    unwell: str = ""                         # failed the same way with no case sent: the session ended there
    unwell_host: str = ""                    # how busy this host was then ("" when it was not)


def sets_frequency(case: FuzzCase) -> bool:
    """Whether the case holds a whole set frequency command (sent from a fresh
    receiver: the padding before each case sees to that). A device obeys it,
    in any session: the rates must be set back before the liveness check,
    which would otherwise report the broadcast the case itself slowed."""
    return any(isinstance(ev, Frame) and (op := open_frame(ev.raw)).cmd_set == 0 and op.cmd_id == 0x10
               and not op.is_ack for ev in Deframer().feed(case.data))


class PacedPort:
    """The port, written no faster than the line carries bytes (everything
    the session sends: cases, padding, probes, rate restores, the clean-up)."""

    def __init__(self, port, baud: int) -> None:
        self.port = port
        self.byte_s = 10.0 / baud
        self.free_at = 0.0
        self.bytes = 0

    def write(self, data: bytes, comment: str | None = None) -> None:
        now = time.monotonic()
        if self.free_at > now:
            time.sleep(self.free_at - now)
        self.port.write(data, comment)
        self.free_at = max(now, self.free_at) + len(data) * self.byte_s
        self.bytes += len(data)

    def __getattr__(self, name: str):
        return getattr(self.port, name)


class FuzzSession:
    def __init__(self, port, an, opts: SessionOptions, cmd: Commander, capture_path=None,
                 restart: Callable[[], str | None] | None = None, interrupts=None,
                 progress: Callable[[str], None] | None = None, host: HostClock | None = None) -> None:
        self.an, self.opts, self.cmd = an, opts, cmd
        self.port = PacedPort(port, opts.baud)
        cmd.port = self.port
        cmd.seq = COMMAND_SEQ_START
        self.capture_path = capture_path
        self.restart = restart
        self.interrupts = interrupts
        self.progress = progress or (lambda text: None)
        self.send = self.port.write
        self.live = Liveness(an, self.send, opts.profile, opts.liveness, cmd.key)
        # the clean-up of the acceptance run, reused: release control and restore the rates
        self.cleanup = ActiveRun(cmd, an, None, opts.app_id, opts.allow_motion, interrupts=interrupts)
        self.cleanup.before_cleanup = self._pad_before_cleanup
        self.out = SessionOutcome()
        self.recent: list[FuzzCase] = []   # cases sent since the last good check
        self.history: list[FuzzCase] = []  # the last cases sent (for a wider replay)
        self.live_now = False              # the last check or recovery found the device live
        self.host = host or HostClock()    # how busy this host is (a test gives one of its own)
        self.since_ok = time.time()        # when the device was last found live

    # ---- the session -----------------------------------------------------

    def run(self) -> SessionOutcome:
        """Fuzz until the budget is spent; the clean-up runs however it ends
        (a signal propagates as RunInterrupted after it)."""
        return self._guarded(self._fuzz)

    def replay(self, cases: list[FuzzCase]) -> SessionOutcome:
        """Send a reproducer's cases once to a live device and check it; a
        failed check is finding 1 (not minimised again)."""

        def once(t0: float) -> None:
            problem = self.live.baseline()
            if problem:
                self.out.start_problem = problem
                return
            if self.opts.allow_motion and not self._obtain_control():
                self.out.stopped = f"the reproducer was not sent: movement control {self.out.motion}"
                return
            for c in cases:
                self._send_case(c)
            check = self.live.check("the reproducer")
            self.out.checks += 1
            if not check.ok:
                self.out.findings.append(Finding(1, check, list(cases), True, reproducer=list(cases)))
        return self._guarded(once)

    def _guarded(self, body: Callable[[float], None]) -> SessionOutcome:
        """`body` under the acceptance run's clean-up (ActiveRun.run)."""
        t0 = time.monotonic()

        def timed() -> None:
            try:
                body(t0)
            finally:
                self.out.seconds = time.monotonic() - t0
        self.cleanup.run(timed)
        return self.out

    def _pad_before_cleanup(self) -> None:
        """A case cut short by a signal may leave the device waiting for the
        rest of a frame: finish it, or it swallows the release command."""
        try:
            self.live.pad("padding before the clean-up")
        except (PortDown, OSError):
            pass   # the clean-up waits for the port itself

    def _fuzz(self, t0: float) -> None:
        problem = self.live.baseline()
        if problem:
            self.out.start_problem = problem
            return
        kinds = self.opts.kinds
        if self.opts.allow_motion and not self._obtain_control():
            self.opts.allow_motion = False
            if kinds is not None:
                kinds = tuple(k for k in kinds if k not in MOTION_KINDS)
                if not kinds:
                    self.out.stopped = f"no case kind left to send: movement control {self.out.motion}"
                    return
        source: Iterator[FuzzCase] = all_cases(self.opts.profile, self.opts.seed, self.opts.allow_motion, kinds,
                                               self.out.withheld)
        n, bytes_before = 0, self.port.bytes
        unrated: list[FuzzCase] = []   # the cases sent since a check last judged the broadcast rate
        for case in source:
            if self.opts.max_cases is not None and n >= self.opts.max_cases:
                break
            if self.opts.seconds is not None and time.monotonic() - t0 >= self.opts.seconds:
                break
            n += 1
            started = time.monotonic()
            try:
                self._send_case(case)
                check = self.live.check(case.id)
            except PortDown as e:   # the device went away (a USB reset, a lost cable): the session cannot go on
                self.out.port_lost = f"the port went down after {case.id}: {e}"
                return
            self.out.case_seconds += time.monotonic() - started
            self.out.checks += 1
            self.out.retried_checks += check.retried
            self.out.bytes_sent = self.port.bytes - bytes_before
            self.live_now = check.ok
            unrated = [] if self.live.rate_judged(check) else (unrated + [case])[-32:]
            if check.ok:
                self.recent = []
                self.since_ok = time.time()
                continue
            if not self._on_failure(check):
                return
        if unrated and self.live_now:
            # the budget ran out within a rate window of the session's start (or of its last rate change):
            # the last cases' rate is judged once that window is full, or the report would claim a check it
            # never made
            self.live.fill_rate_window()
            self.recent = unrated
            check = self.live.check(f"{unrated[-1].id}, a full rate window later")
            self.out.checks += 1
            self.out.retried_checks += check.retried
            if not check.ok:
                self._on_failure(check)

    def _send_case(self, case: FuzzCase) -> None:
        resets_rates = sets_frequency(case)
        if resets_rates:   # before the bytes go out: a signal during them still has the rates restored
            self.cleanup.changes.frequency_sent = True
        for w in case.writes:
            self.send(w, case.id)
        self.out.sent[case.kind] = self.out.sent.get(case.kind, 0) + 1
        self.recent.append(case)
        self.history = (self.history + [case])[-32:]
        if resets_rates:
            self.live.pad(f"padding after {case.id}")
            self._restore_rates(case.id)

    def _restore_rates(self, after: str) -> None:
        """Back to the rates the session started with, at once: a boundary
        set frequency (every item off) must not read as a stopped broadcast."""
        self.cleanup.changes.frequency_sent = True
        codes = rate_codes(self.an.prof, self.an.epochs[0].rates)
        self.cmd.request(0, 0x10, {"codes": codes}, tries=2, ack_timeout=self.opts.liveness.ack_timeout)
        self.live.restarted_window()

    def _obtain_control(self) -> bool:
        """With --allow-motion: control authority (activation first, when an app id is given)."""
        if self.opts.app_id is not None:
            self.cmd.request(0, 1, {"app_id": self.opts.app_id, "api_level": 2,
                                    "sdk_version": self.an.prof.sdk_version, "bundle_id": bytes(32)})
        self.cleanup.changes.obtain_sent = True
        for _ in range(3):
            ack, info = self.cmd.request(1, 0, {"request": 1})
            if ack is None:
                self.out.motion = f"allowed, but control authority was not obtained: {info}"
                return False
            code = int(ack.ack_code)
            if code == 2:
                self.out.motion = "allowed: control authority obtained, zero-setpoint velocity cases sent"
                return True
            if code != 3:
                self.out.motion = f"allowed, but control authority was refused (ACK code {code:#06x})"
                return False
        self.out.motion = "allowed, but control authority stayed 'in progress'"
        return False

    # ---- a finding ----------------------------------------------------------

    def _on_failure(self, check: Check) -> bool:
        """Confirm and minimise a failed check; False ends the session."""
        suspects, self.recent = self.recent, []
        # what the check looked back on: the rate window, the stall time-out, two probes
        lo = self.opts.liveness
        since = min(self.since_ok, check.t - max(lo.rate_window, lo.stall_timeout, 2 * lo.ack_timeout))
        busy = self._host_busy(since) if check.timing_only else ""
        if busy and check.symptoms == ["broadcast_slow"]:
            # a broadcast still live but slower: what a stand-in FC starved on this host shows; a replay would
            # only measure how busy the host is
            self.out.not_judged.append(NotJudged(check, suspects[-1].id, busy, replayed=False))
            return True
        # One finding per set of symptoms: a device that wedges on every unknown
        # command set would otherwise spend the budget minimising the same bug.
        same = next((f for f in self.out.findings if f.check.symptoms == check.symptoms), None)
        if same is not None:
            same.repeats += 1
            same.repeated_kinds.add(suspects[-1].kind)
            if len(same.repeated_after) < 20:
                same.repeated_after.append(suspects[-1].id)
            self.progress(f"finding {same.number} again after {suspects[-1].id}")
            return self._recover() is None or self._stop("the device did not recover after a repeated finding")
        f = Finding(len(self.out.findings) + 1, check, suspects)
        problem = self._recover()
        if problem:
            self._found(f)
            f.confirmed, f.why_unconfirmed = None, problem
            return self._stop(f"the device did not come back after finding {f.number}: {problem}")
        if check.timing_only and self._trial(f, [], check):
            self.out.unwell = (f"after {suspects[-1].id}: {check.describe()}; brought back, it failed the same way "
                               "with no case sent: not a case's doing")
            self.out.unwell_host = busy or self._host_busy(since)
            return self._stop("the device failed its check with no case sent")
        replayed, f.from_capture = self._from_capture(suspects)
        windows = [replayed]
        if len(self.history) > len(suspects):   # the cause may lie further back
            windows.append(self._from_capture(self.history)[0])
        for window in windows:
            if self._trial(f, window, check):
                f.confirmed, f.reproducer = True, window
                break
        else:
            f.confirmed = False
            f.why_unconfirmed = (f"replaying the last {len(windows[-1])} case(s) from the capture did not fail "
                                 "the check again")
        # asked again: a reader that was stopped with the rest of this process records its stall only once it
        # runs again, which may be after the check that the stall failed
        busy = busy or (self._host_busy(since) if check.timing_only else "")
        if not f.confirmed and busy:
            self.out.not_judged.append(NotJudged(check, suspects[-1].id, busy, replayed=True))
            self.progress(f"a check after {suspects[-1].id} failed on timing alone while this host was busy; "
                          "its cases replayed without failure: no finding")
            return self._recover() is None or self._stop("the device did not come back after a replay")
        self._found(f)
        if f.confirmed:
            f.reproducer = self._minimise(f, f.reproducer, check)
        if self._recover() is not None:
            return self._stop(f"the device did not come back after minimising finding {f.number}")
        if len(self.out.findings) >= self.opts.max_findings:
            return self._stop(f"{self.opts.max_findings} findings (--max-findings)")
        return True

    def _found(self, f: Finding) -> None:
        self.out.findings.append(f)
        self.progress(f"finding {f.number} after {f.suspects[-1].id}: {f.check.describe()}")

    def _host_busy(self, since: float) -> str:
        """How this host was busy since `since` (wall time), or "" when it was not:
        the port's reader not scheduled for HOST_STALL_S or more, or more
        runnable work than cores."""
        state = getattr(self.port.port, "state", None)
        stalls = [s for t, s in (state.host_stalls if state else []) if t + s >= since]
        load = self.host.load()
        if not stalls and not load.busy:
            return ""
        return ((f"this host did not read the port for up to {max(stalls):.1f} s; " if stalls else "")
                + load.text())

    def _stop(self, why: str) -> bool:
        self.out.stopped = why
        return False

    def _recover(self) -> str | None:
        """Bring the device back (restart command, else waiting); None when it
        is live again, else why not."""
        note = ""
        if self.restart is not None:
            note = self.restart() or ""
            if note:
                return f"the restart command failed: {note}"
        end = time.monotonic() + self.opts.recover_timeout
        while True:
            self.live.restarted_window()
            if self._healthy():
                self.live.restarted_window()
                self.live_now = True
                self.since_ok = time.time()
                return None
            if time.monotonic() >= end:
                break
            time.sleep(0.2)
        how = "after the restart command" if self.restart else "by itself (no --restart-cmd given)"
        return f"not live {how} within {self.opts.recover_timeout:g} s"

    def _healthy(self) -> bool:
        try:
            self.live.pad("padding while waiting for recovery", 1024)
            value, _ = self.live.ask("recovery")
        except PortDown:
            return False
        if value is None or self.live.version_of(value) != self.live.version:
            return False
        with self.an.lock:
            last = self.an.bcast[-1][0] if self.an.bcast else None
        return last is not None and time.time() - last <= self.opts.liveness.stall_timeout

    def _from_capture(self, sent: list[FuzzCase]) -> tuple[list[FuzzCase], bool]:
        """The cases as the capture recorded them (block comment = case id),
        or as kept in memory when there is no capture."""
        if self.capture_path is None:
            return list(sent), False
        want = {c.id: c for c in sent}
        writes: dict[str, list[bytes]] = {}
        try:
            with open_capture(self.capture_path) as cap:
                for rec in cap:
                    if rec.direction == TX and rec.comment in want:
                        writes.setdefault(rec.comment, []).append(rec.data)
        except (OSError, ValueError):
            return list(sent), False
        out = [FuzzCase(c.id, c.kind, tuple(writes[c.id]), c.source) if c.id in writes else c for c in sent]
        return out, all(c.id in writes for c in sent)

    def _trial(self, f: Finding, cases: list[FuzzCase], original: Check) -> bool:
        """Send `cases` (none: a control) to a live device; True when the
        check fails the same way. A slowed broadcast is judged over a whole
        rate window from the device's recovery."""
        if f.trials >= self.opts.minimise_trials:
            return False
        if not self.live_now and self._recover() is not None:
            return False
        f.trials += 1
        tag = f"finding {f.number} trial {f.trials}"
        for c in cases:   # as first sent: each case from a receiver that waits for nothing
            self.live.pad(f"padding in {tag}")
            for w in c.writes:
                self.send(w, f"{tag}: {c.id}")
        if any(sets_frequency(c) for c in cases):
            self.live.pad(f"padding after {tag}")
            self._restore_rates(tag)
        if "broadcast_slow" in original.symptoms:
            self.live.fill_rate_window()
        check = self.live.check(tag)
        self.live_now = check.ok
        return bool(set(check.symptoms) & set(original.symptoms))

    def _minimise(self, f: Finding, cases: list[FuzzCase], original: Check) -> list[FuzzCase]:
        """Fewest cases (ddmin), then fewest writes and bytes of what is left."""
        cases = self._ddmin(f, cases, original)
        if len(cases) != 1:
            return cases
        case = cases[0]
        writes = list(case.writes)

        def works(ws: list[bytes]) -> bool:
            ws = [w for w in ws if w]
            return bool(ws) and self._trial(f, [FuzzCase(case.id, case.kind, tuple(ws), case.source)], original)

        if len(writes) > 1 and works([b"".join(writes)]):
            writes = [b"".join(writes)]
        i = 0
        while len(writes) > 1 and i < len(writes):
            if works(writes[:i] + writes[i + 1:]):
                writes = writes[:i] + writes[i + 1:]
            else:
                i += 1
        # the shortest ending, then the shortest start, by bisection
        lo, hi = 1, len(writes[-1])
        while lo < hi and f.trials < self.opts.minimise_trials:
            mid = (lo + hi) // 2
            if works(writes[:-1] + [writes[-1][:mid]]):
                hi = mid
            else:
                lo = mid + 1
        writes[-1] = writes[-1][:hi]
        lo, hi = 0, len(writes[0]) - 1
        while lo < hi and f.trials < self.opts.minimise_trials:
            mid = (lo + hi + 1) // 2
            if works([writes[0][mid:]] + writes[1:]):
                lo = mid
            else:
                hi = mid - 1
        writes[0] = writes[0][lo:]
        return [FuzzCase(case.id, case.kind, tuple(w for w in writes if w), case.source)]

    def _ddmin(self, f: Finding, cases: list[FuzzCase], original: Check) -> list[FuzzCase]:
        n = 2
        while len(cases) >= 2 and f.trials < self.opts.minimise_trials:
            size = max(1, len(cases) // n)
            parts = [cases[i:i + size] for i in range(0, len(cases), size)]
            for i, part in enumerate(parts):
                if self._trial(f, part, original):
                    cases, n = part, 2
                    break
                rest = [c for j, p in enumerate(parts) if j != i for c in p]
                if len(parts) > 2 and self._trial(f, rest, original):
                    cases, n = rest, max(n - 1, 2)
                    break
            else:
                if n >= len(cases):
                    break
                n = min(len(cases), n * 2)
        return cases
