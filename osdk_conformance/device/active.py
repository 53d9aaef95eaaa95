"""The active part of `osdkc device`: commands sent to the flight controller,
and the one clean-up path that undoes what they changed.

Whatever ends an active run (the last check, SIGINT, SIGTERM, a failed
check, an exception, a lost port) goes through `ActiveRun.clean_up`: movement
commands have stopped (they are sent from this thread only), release control
is sent when obtain control was sent (its ACK may have been lost), the
broadcast frequencies the run found are set again when set frequency was
sent, each with bounded waits. `Interrupts` turns SIGINT and SIGTERM into one
exception, defers it while a frame is being written, and lets a second
signal cut the clean-up short (which the report then says).
"""
from __future__ import annotations

import contextlib
import math
import os
import signal
import sys
import time
from dataclasses import dataclass
from typing import Callable, Iterator

from osdk_conformance.core.commands import ack_code_text
from osdk_conformance.core.errors import exit_status_of_signal, one_line
from osdk_conformance.core.wire import encode
from osdk_conformance.device.analysis import CODE_OF_HZ
from osdk_conformance.device.checks import flags_check, rate_check
from osdk_conformance.device.port import PortDown
from osdk_conformance.core.version_reply import host_problem
from osdk_conformance.harness.report import ERROR, FAIL, PASS, SKIP, Result
from osdk_conformance._construct.control import encode_movement_control
from osdk_conformance._construct.payload import osdk_payload

# Test hook: a comma-separated list of phase names at which the run announces
# itself on stderr and waits HOLD_SECONDS, so a test can send a real signal
# at exactly that phase (tests/test_device_interrupt.py).
HOLD_ENV = "OSDKC_DEVICE_HOLD_AT"
HOLD_SECONDS = 10.0
# Test hook: phase names at which the run raises RuntimeError, standing for a
# bug of ours, so a test can show the clean-up runs on that route too.
RAISE_ENV = "OSDKC_DEVICE_RAISE_AT"
PHASES = ("version", "activation", "frequency", "frequency.window", "obtain", "obtain.pending", "movement.attitude",
          "movement.velocity", "movement.position", "movement.hover", "release", "restore")
ACTIVE_CHECKS = ("active.version", "active.activation", "active.frequency", "active.control_obtain",
                 "active.movement", "active.control_release", "active.frequency_restore")
# Exit status of a run ended by a signal: the shell's 128 + signal number, as
# `osdkc` returns 130 for any other command interrupted with Ctrl-C.
EXIT_BY_SIGNAL = {name: exit_status_of_signal(name) for name in ("SIGINT", "SIGTERM")}
CLEANUP_ACK_TIMEOUT, CLEANUP_TRIES = 0.5, 2   # after an interruption: at most ~2 s of waiting per command
# s the clean-up waits, in all, for a lost port to come back: before its
# first command and whenever a command finds the port down (a cable glitch
# must not leave the aircraft under onboard control)
CLEANUP_PORT_WAIT = 4.0
# why a check was skipped, in the few words of the summary line (device/verdict.py)
NO_APP_ID, NOTHING_TO_UNDO = "no --app-id", "nothing to undo"


class RunInterrupted(KeyboardInterrupt):
    """SIGINT or SIGTERM during the run (a KeyboardInterrupt: `except Exception` lets it through)."""

    def __init__(self, signame: str) -> None:
        super().__init__(signame)
        self.signame = signame


class CleanupCut(KeyboardInterrupt):
    """A second signal during the clean-up: stop cleaning up."""

    def __init__(self, signame: str) -> None:
        super().__init__(signame)
        self.signame = signame


class Interrupts:
    """SIGINT and SIGTERM handling for a live run.

    While running, a signal raises RunInterrupted (deferred to the end of a
    `critical()` section, so a frame is never half recorded or half sent).
    While cleaning up, the first signal is noted and the clean-up goes on; a
    further one raises CleanupCut. While the reports are written, signals
    are noted only: writing them is quick and they are what the user keeps."""

    def __init__(self, tool: str = "osdkc device") -> None:
        self.tool = tool   # who speaks on stderr
        self.signals: list[str] = []
        self.mode = "run"   # run | cleanup | report
        self.phase = "passive"               # kept up to date by ActiveRun.enter
        self.first_phase: str | None = None  # the phase the first signal came in
        self._deferring = 0
        self._pending: KeyboardInterrupt | None = None
        self._previous: dict = {}

    def install(self) -> None:
        for s in (signal.SIGINT, signal.SIGTERM):
            self._previous[s] = signal.signal(s, self._on_signal)

    def uninstall(self) -> None:
        for s, handler in self._previous.items():
            signal.signal(s, handler)
        self._previous = {}

    @property
    def first(self) -> str | None:
        return self.signals[0] if self.signals else None

    def _on_signal(self, signum, frame) -> None:
        name = signal.Signals(signum).name
        self.signals.append(name)
        self.first_phase = self.first_phase or self.phase
        if self.mode == "report":
            _say(f"{name} received: finishing the reports", self.tool)
            return
        if self.mode == "cleanup":
            if len(self.signals) == 1:
                _say(f"{name} received during the clean-up: finishing it ({name} again cuts it short)", self.tool)
                return
            exc: KeyboardInterrupt = CleanupCut(name)
        else:
            exc = RunInterrupted(name)
            self.mode = "cleanup"   # set here, not by the catcher: no gap where a second signal finds "run"
        if self._deferring:
            self._pending = self._pending or exc
            return
        raise exc

    @contextlib.contextmanager
    def critical(self):
        """No signal exception inside: it is raised when the section ends."""
        self._deferring += 1
        try:
            yield
        finally:
            self._deferring -= 1
            if not self._deferring and self._pending is not None:
                exc, self._pending = self._pending, None
                raise exc


class Ending:
    """How a live run ended: `error` is a bug of ours, "" when none (a signal
    is in `Interrupts.signals`)."""

    error = ""


@contextlib.contextmanager
def to_the_end(interrupts: Interrupts, port, an, cap) -> Iterator[Ending]:
    """The body of a live run (`osdkc device`, `osdkc fuzz --port`), whose own
    clean-up has run however it ended: a signal or a bug of ours ends it
    here, not the process, so that the reports are still written; then the
    port and the capture are closed, and signals only noted."""
    ending = Ending()
    try:
        yield ending
    except KeyboardInterrupt:
        pass
    except Exception as e:
        ending.error = f"{type(e).__name__}: {one_line(e)}"
    finally:
        interrupts.mode = "report"
        port.close()
        an.finish(port.state.t_end)
        if cap:
            cap.close()


def _say(text: str, tool: str = "osdkc device") -> None:
    print(f"{tool}: {text}", file=sys.stderr, flush=True)


class Commander:
    """Sends commands (session 2, ACK required, up to 3 tries) and waits for ACKs."""

    def __init__(self, port, an, profile: str, key: bytes | None, encrypt: bool, ack_timeout: float = 1.0) -> None:
        self.port, self.an, self.profile = port, an, profile
        self.key = key if encrypt else None
        self.payload = osdk_payload
        self.seq = 1
        self.ack_timeout = ack_timeout
        # s left to wait for a lost port to come back (0: a command that finds the port down fails at once)
        self.port_wait = 0.0

    def _next_seq(self) -> int:
        self.seq = (self.seq + 1) & 0xFFFF
        return self.seq

    def send_value(self, cmd_set: int, cmd_id: int, value: bytes, session: int = 0) -> bytes:
        """Send a command whose value is already encoded; no ACK is awaited."""

        seq = self._next_seq()
        frame = encode(cmd_set=cmd_set, cmd_id=cmd_id, value=value, session=session, seq=seq, key=self.key)
        self.port.write(frame)
        return frame

    def request(self, cmd_set: int, cmd_id: int, body: dict, tries: int = 3, ack_timeout: float | None = None):
        """(ACK value parsed, seconds) or (None, why)."""

        timeout = self.ack_timeout if ack_timeout is None else ack_timeout
        value = self.payload(cmd_set, cmd_id, False, self.profile).build({"body": body})
        seq = self._next_seq()
        with self.an.lock:
            self.an.acks.pop((2, seq), None)   # an earlier frame's ACK with this SEQ does not answer this one
        frame = encode(cmd_set=cmd_set, cmd_id=cmd_id, value=value, session=2, seq=seq, key=self.key)
        t0 = time.monotonic()
        for _ in range(tries):
            try:
                self._write(frame)
            except PortDown as e:
                return None, f"port down: {e}"
            ack = self.an.wait_ack(2, seq, timeout)
            if ack:
                try:
                    parsed = self.payload(cmd_set, cmd_id, True, self.profile).parse(ack[3]).body
                except Exception as e:
                    return None, f"ACK does not decode: {one_line(e)} (value {ack[3].hex()})"
                return parsed, time.monotonic() - t0
        return None, f"no ACK after {tries} tries of {timeout}s"

    def _write(self, frame: bytes) -> None:
        """Write; a port found down is waited for (within `port_wait`) and
        the frame written once more."""
        try:
            self.port.write(frame)
        except PortDown:
            if not self.await_port():
                raise
            self.port.write(frame)

    def await_port(self) -> bool:
        """Wait for the port (reopened by the reader thread), within what is
        left of `port_wait`; True when it is there."""
        t0 = time.monotonic()
        back = self.port.wait_back(self.port_wait)
        self.port_wait = max(0.0, self.port_wait - (time.monotonic() - t0))
        return back


def _code(v) -> tuple[int, str]:
    return int(v), str(v)


NOT_ACTIVATED = 0xFF01
FREQUENCY_PATTERN = {"time_stamp": 50, "quaternion": 50, "velocity": 10, "position": 10, "flight_status": 10,
                     "battery": 10, "control_info": 10}


@dataclass
class Changes:
    """What the run may have changed on the flight controller. Each flag is
    set before its command is sent, so the clean-up undoes a command whose
    ACK never came (or that was interrupted on its way out)."""

    frequency_sent: bool = False
    obtain_sent: bool = False


class ActiveRun:
    """The active checks, in order, then the clean-up (always)."""

    def __init__(self, cmd: Commander, an, opts, app_id: int | None, allow_motion: bool, window: float = 2.0,
                 motion_seconds: float = 1.5, interrupts: Interrupts | None = None) -> None:
        self.cmd, self.an, self.opts = cmd, an, opts
        self.app_id, self.allow_motion = app_id, allow_motion
        self.window, self.motion_seconds = window, motion_seconds
        self.interrupts = interrupts
        self.tool = interrupts.tool if interrupts else "osdkc device"
        # called before the clean-up's commands, when there are any (the fuzzer pads the link there)
        self.before_cleanup: Callable[[], None] | None = None
        self.results: list[Result] = []
        self.changes = Changes()
        self.phase = "start"
        self.stopped_in: str | None = None   # the phase an exception or a signal ended the checks in
        self.cleanup_cut: str | None = None   # what the clean-up left undone, when a second signal cut it
        self.freq_ok = False
        self._holds = set(filter(None, os.environ.get(HOLD_ENV, "").split(",")))
        self._raises = set(filter(None, os.environ.get(RAISE_ENV, "").split(",")))

    def res(self, cid: str, status: str, msg: str, details: dict | None = None, kind: str = "") -> None:
        self.results.append(Result("active", cid, status, msg, details or {}, kind=kind))

    def enter(self, phase: str) -> None:
        self.phase = phase
        if self.interrupts:
            self.interrupts.phase = phase
        if phase in self._holds:
            _say(f"phase {phase}: holding {HOLD_SECONDS:g} s ({HOLD_ENV})", self.tool)
            time.sleep(HOLD_SECONDS)
        if phase in self._raises:
            raise RuntimeError(f"raised at phase {phase} by the test hook {RAISE_ENV}")

    # ---- the run -------------------------------------------------------------------------

    def run(self, body: Callable[[], None] | None = None) -> list[Result]:
        """Every check (or `body`: `osdkc fuzz --port` runs its session under
        this clean-up); the clean-up runs however they end (an exception
        propagates after it)."""
        try:
            (body or self.checks)()
            if self.interrupts:
                self.interrupts.mode = "cleanup"   # from here on a signal does not stop the clean-up
        except BaseException:
            self.stopped_in = self.phase   # the clean-up moves self.phase on
            self.clean_up(interrupted=True)
            raise
        self.clean_up(interrupted=bool(self.interrupts and self.interrupts.signals))
        return self.results

    def checks(self) -> None:
        self.enter("version")
        version_ack = self.version()
        self.enter("activation")
        activated = self.activation(version_ack)
        self.enter("frequency")
        self.frequency(activated)
        self.enter("obtain")
        if not activated and self.app_id is None:
            self.res("active.control_obtain", SKIP, "control authority needs an activated app: no --app-id given",
                     kind=NO_APP_ID)
            obtained = False
        else:
            obtained = self.two_step(1, "active.control_obtain", 3, 2, 2)
        if not self.allow_motion:
            self.res("active.movement", SKIP, "movement control not tried (needs --allow-motion)",
                     kind="no --allow-motion")
        elif not obtained:
            self.res("active.movement", SKIP, "control authority not obtained: movement control not tried",
                     kind="no control authority")
        else:
            movement_check(self)

    def version(self):
        ack, info = self.cmd.request(0, 0, {"arbitrary": 0})
        if ack is None:
            self.res("active.version", FAIL, f"version query: {info}", kind="no_ack")
            return None
        name = bytes(ack.version_name).rstrip(b"\0")
        code = _code(ack.ack_code)
        printable = all(32 <= b < 127 for b in name) and name
        details = {"ack_code": ack_code_text(ack.ack_code), "version_crc": f"{ack.version_crc:#010x}",
                   "version_name": name.decode("ascii", "replace"), "ack after s": round(info, 3)}
        if ack.version_id is not None:   # FW 3.1 profiles: the reply parsed in the profile's layout (ERRATA E30)
            details["version_id"] = bytes(ack.version_id).rstrip(b"\0").decode("ascii", "replace")
        problem = None
        if ack.version_id is not None:   # what DJI's 3.3 to 3.9 hosts make of it (ERRATA E30)
            problem = host_problem(code[0], int(ack.version_crc), bytes(ack.version_id), bytes(ack.version_name),
                                   self.an.prof.sdk_version)
        if code[0] not in (0x0000, NOT_ACTIVATED) or not printable:
            self.res("active.version", FAIL, "version ACK: unknown code or unprintable version name", details,
                     "bad_ack")
        elif problem:
            self.res("active.version", FAIL, f"version ACK {name.decode()!r}: {problem}", details, "bad_ack")
        else:
            self.res("active.version", PASS, f"version {name.decode()} ({code[1]})", details)
        return ack

    def activation(self, version_ack) -> bool:
        if self.app_id is None:
            activated = version_ack is not None and int(version_ack.ack_code) == 0
            self.res("active.activation", SKIP, "no --app-id given: activation not tried"
                     + ("; the version query says the app is already activated" if activated else ""), kind=NO_APP_ID)
            return activated
        ack, info = self.cmd.request(0, 1, {"app_id": self.app_id, "api_level": 2,
                                            "sdk_version": self.an.prof.sdk_version, "bundle_id": bytes(32)})
        if ack is None:
            self.res("active.activation", FAIL, f"activation: {info}", kind="no_ack")
            return False
        code = _code(ack.ack_code)
        if code[0] != 0:
            self.res("active.activation", FAIL, f"activation refused: {ack_code_text(ack.ack_code)}", kind="refused")
            return False
        v, _ = self.cmd.request(0, 0, {"arbitrary": 0})
        if v is None or int(v.ack_code) != 0:
            self.res("active.activation", FAIL, "activation succeeded but the version query still says "
                     "not activated", kind="not_activated")
            return False
        self.res("active.activation", PASS, f"activated app id {self.app_id}; version query now says activated")
        return True

    def frequency(self, activated: bool) -> None:
        prof, an, opts = self.an.prof, self.an, self.opts
        pattern = {item: FREQUENCY_PATTERN.get(item, 0) for item in prof.flag_bits}
        n_epochs = len(an.epochs)
        self.changes.frequency_sent = True
        ack, info = self.cmd.request(0, 0x10, {"codes": rate_codes(prof, pattern)})
        if ack is None:
            self.res("active.frequency", FAIL, f"set frequency: {info}", kind="no_ack")
            return
        if int(ack.ack_code) != 0:
            self.changes.frequency_sent = False   # refused, so not applied: nothing to restore
        if int(ack.ack_code) == NOT_ACTIVATED and not activated and self.app_id is None:
            self.res("active.frequency", SKIP, "set frequency needs an activated app on this flight controller: "
                     "no --app-id given", kind=NO_APP_ID)
            return
        if int(ack.ack_code) != 0:
            self.res("active.frequency", FAIL, f"set frequency refused: {ack_code_text(ack.ack_code)}", kind="refused")
            return
        self.enter("frequency.window")
        time.sleep(opts.settle + self.window)
        with an.lock:
            ep = an.epochs[n_epochs] if len(an.epochs) > n_epochs else None
            if ep is None:
                self.res("active.frequency", ERROR, "the ACK was not seen by the analyzer")
                return
            t0 = ep.start + opts.settle
            r = rate_check(an, opts, ep.rates, t0, t0 + self.window, "active.frequency", "active")
            fl = flags_check(an, ep.rates, t0, t0 + self.window, "active.frequency", "active")
        if r.status == PASS and fl.status == PASS:
            self.freq_ok = True
            self.res("active.frequency", PASS, "rates and flag words follow the new frequencies: " + r.message,
                     r.details)
        else:
            bad = [x.message for x in (r, fl) if x.status != PASS]
            self.res("active.frequency", FAIL, "; ".join(bad), {**r.details, **fl.details}, "rate")

    # ---- control authority ---------------------------------------------------------------

    def control_device(self, want: int, timeout: float = 1.0) -> list[int]:
        """Control devices the broadcast showed, until `want` shows up or the time is over."""
        seen: list[int] = []
        end = time.monotonic() + timeout
        while time.monotonic() < end:
            time.sleep(0.1)
            with self.an.lock:
                ci = self.an.latest.get("control_info")
            if ci and ci[0] > time.time() - 0.3:
                seen.append(ci[1]["control_device"]["value"])
                if seen[-1] == want:
                    break
        return seen

    def two_step(self, request: int, cid: str, progress: int, done: int, device_after: int,
                 tries: int = 3, ack_timeout: float | None = None) -> bool:
        what = "obtain" if request else "release"
        acks: list[str] = []
        if request:
            self.changes.obtain_sent = True
        for _ in range(2):
            a, info = self.cmd.request(1, 0, {"request": request}, tries, ack_timeout)
            if a is None:
                self.res(cid, FAIL, f"{what} control: {info}", {"acks": acks}, "no_ack")
                return False
            acks.append(ack_code_text(a.ack_code))
            code = int(a.ack_code)
            if code == done:
                break
            if code == progress and request:
                self.enter("obtain.pending")
            if code != progress:
                why = {0: "the RC mode switch is not in F mode", 0xC9: "the flight controller is in IOC mode",
                       NOT_ACTIVATED: "the app is not activated"}.get(code, "unexpected answer")
                self.res(cid, FAIL, f"{what} control answered {ack_code_text(a.ack_code)}: {why}", {"acks": acks},
                         "refused")
                return False
        if int(a.ack_code) != done:
            self.res(cid, FAIL, f"still not done after two requests: {acks}", {"acks": acks}, "refused")
            return False
        note = " (answered done at once, no 'in progress' step)" if int(acks[0].split()[0], 16) != progress else ""
        seen = self.control_device(device_after) if self.freq_ok else []
        details = {"acks": acks, "control device in broadcast": seen[-3:]}
        if self.freq_ok and seen and seen[-1] != device_after:
            self.res(cid, FAIL, f"ACKs {acks} but the broadcast control device is {seen[-1]}, not {device_after}",
                     details, "state")
            return False
        self.res(cid, PASS, f"ACKs {' then '.join(acks)}{note}", details)
        return True

    # ---- the clean-up --------------------------------------------------------------------

    def clean_up(self, interrupted: bool) -> None:
        """Release control if obtain was sent, restore the frequencies if set
        frequency was sent; bounded (shorter waits after an interruption or an
        error); a second signal cuts it short."""
        if self.interrupts:
            self.interrupts.mode = "cleanup"
        steps = []
        if self.changes.obtain_sent:
            steps.append("release control")
        if self.changes.frequency_sent:
            steps.append("restore the broadcast frequencies")
        tries, timeout = (CLEANUP_TRIES, CLEANUP_ACK_TIMEOUT) if interrupted else (3, None)
        done: list[str] = []
        try:
            if interrupted:
                _say(f"run ended during phase {self.phase}: movement commands stopped; "
                     + (f"now: {' and '.join(steps)} (SIGINT again cuts this short)" if steps else "nothing to undo"),
                     self.tool)
            if steps:
                self.cmd.port_wait = CLEANUP_PORT_WAIT
                self.cmd.await_port()
                if self.before_cleanup:
                    self.before_cleanup()
            self.enter("release")
            if self.changes.obtain_sent:
                self.two_step(0, "active.control_release", 4, 1, 0, tries, timeout)
                done.append("release control")
            elif "active.control_release" not in self._ids():
                self.res("active.control_release", SKIP, "control was not requested: nothing to release",
                         kind=NOTHING_TO_UNDO)
            self.enter("restore")
            if self.changes.frequency_sent:
                self.restore_frequencies(tries, timeout)
                done.append("restore the broadcast frequencies")
            else:
                self.res("active.frequency_restore", SKIP, "the frequencies were not changed: nothing to restore",
                         kind=NOTHING_TO_UNDO)
        except CleanupCut as e:
            left = [s for s in steps if s not in done]
            self.cleanup_cut = f"clean-up cut short by a second {e.signame}: not done: {', '.join(left) or 'none'}"
            _say(self.cleanup_cut, self.tool)

    def _ids(self) -> set[str]:
        return {r.id for r in self.results}

    def restore_frequencies(self, tries: int = 3, ack_timeout: float | None = None) -> None:
        """Set the rates the run started with again (the profile's defaults, or --expect-rate)."""
        start = self.an.epochs[0].rates
        ack, info = self.cmd.request(0, 0x10, {"codes": rate_codes(self.an.prof, start)}, tries, ack_timeout)
        if ack is None or int(ack.ack_code) != 0:
            self.res("active.frequency_restore", FAIL, "restoring the rates the run started with failed: "
                     f"{info if ack is None else ack_code_text(ack.ack_code)}",
                     kind="no_ack" if ack is None else "refused")
        else:
            self.res("active.frequency_restore", PASS, f"the rates the run started with ({self.an.epochs[0].source}) "
                     "are set again")



def not_reached(results: list[Result], why: str) -> list[Result]:
    """A SKIP for every active check missing from `results` (the run ended before it)."""
    have = {r.id for r in results}
    return [Result("active", cid, SKIP, f"not reached: {why}", kind="not reached") for cid in ACTIVE_CHECKS
            if cid not in have]


def rate_codes(prof, rates: dict[str, int]) -> list[int]:
    """Set frequency codes for `rates` (code 5, keep, for a rate no code stands for)."""

    return [CODE_OF_HZ.get(rates.get(i, 0), 5) for i in prof.flag_bits] + [0] * (16 - len(prof.flag_bits))


def movement_check(run: ActiveRun) -> None:
    """Attitude, then velocity and yaw rate, then position offset and height,
    each commanded at 50 Hz for `seconds` (position: 5/3 of it), then hover."""

    an, cmd, seconds = run.an, run.cmd, run.motion_seconds

    def state():
        with an.lock:
            return dict(an.latest)

    def stream(phase: str, mode: int, seconds: float, values) -> bool:
        end = time.monotonic() + seconds
        sent = 0
        while time.monotonic() < end:
            x, y, z, yaw = values() if callable(values) else values
            try:
                cmd.send_value(1, 3, encode_movement_control(mode, x, y, z, yaw), session=0)
            except PortDown:
                return False
            sent += 1
            if sent == 5:   # in the middle of the stream: where the hold test hook interrupts it
                run.enter(phase)
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
            run.res("active.movement", SKIP, f"cannot verify movement: the {need} item is not broadcast")
            return
    yaw0 = s["attitude"][1][2]
    # 1. attitude: tilt angles and yaw angle
    roll_t, pitch_t, yaw_t = 5.0, -3.0, (yaw0 + 20.0 + 180) % 360 - 180
    stream("movement.attitude", 0x00, seconds, (roll_t, pitch_t, 0.0, yaw_t))
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
    stream("movement.velocity", 0x48, seconds, (*vel_t, yaw_rate_t))
    vel, att = window("velocity", 0.4), window("attitude", min(1.0, seconds / 2))
    if vel and len(att) > 2:
        v = [sum(s[i] for s in vel) / len(vel) for i in (1, 2, 3)]
        dyaw = (att[-1][3] - att[0][3] + 180) % 360 - 180
        rate = dyaw / an.sample_span(att)
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

    stream("movement.position", 0x90, seconds * 5 / 3, offsets)
    n, e, h = where()
    details["position goal (north, east m; height m)"] = [goal[0], goal[1], round(goal[2], 2)]
    details["position reached"] = [round(n, 3), round(e, 3), round(h, 3)]
    if math.hypot(n - goal[0], e - goal[1]) > 0.5 or abs(h - goal[2]) > 0.5:
        problems.append(f"position {math.hypot(n - goal[0], e - goal[1]):.2f} m, height {abs(h - goal[2]):.2f} m "
                        "from the goal (limit 0.5 m)")
    stream("movement.hover", 0x48, 0.5, (0.0, 0.0, 0.0, 0.0))   # stop and hover
    if problems:
        run.res("active.movement", FAIL, "the state does not follow the commands: " + "; ".join(problems), details,
                "motion")
    else:
        run.res("active.movement", PASS, "attitude, velocity, yaw rate and position follow the commands", details)
