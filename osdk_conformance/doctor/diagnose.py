"""The doctor's steps, in the order that tells the causes of a dead link apart.

1. The port on this host (ports.py): missing, not allowed, held by another
   program or a login console. Nothing is opened before these are clear.
2. Listen, sending nothing, at the asked rate (or the usual ones in turn):
   CRC-valid frames settle the baud rate at once (a wrong rate cannot pass
   a CRC-16 and a CRC-32 by chance); bytes without a frame at every rate are
   a console, noise, or not this protocol; no byte at all is wiring, the
   FC's API output, or a silent FC.
3. From the frames: the profile the broadcast fits, encryption and the key,
   the line's error rate.
4. Ask what is safe: a version query (the FC's RX line and the host's TX
   wire). No answer at the rate it sends at, but an answer to a query sent
   at another rate, is a different rate per direction; no answer at all,
   with a healthy broadcast, is an FC that hears nothing. A query that comes
   back byte for byte is a loopback.
5. With --app-id, activation, whose every answer has its remedy in the spec.

The listening and the ACK matching are the acceptance suite's own
(device.port.Port feeding device.analysis.Analyzer, device.active.Commander):
a diagnosis and a verdict read the same bytes the same way.
"""
from __future__ import annotations

import errno
import os
import termios
import time
from dataclasses import dataclass, field
from typing import Callable

import serial

from osdk_conformance.core.commands import COMMANDS
from osdk_conformance.core.deframe import MAX_LEN, Deframer, Frame
from osdk_conformance.core.errors import one_line
from osdk_conformance.core.rules import default_rules
from osdk_conformance.core.tty import with_input_speed
from osdk_conformance.core.wire import encode, open_frame
from osdk_conformance.device.active import Commander
from osdk_conformance.device.analysis import Analyzer
from osdk_conformance.device.port import Port
from osdk_conformance.doctor import ports, remedies
from osdk_conformance.doctor.findings import NOT_CHECKED, OK, PROBLEM, WARNING, Diagnosis, Finding
from osdk_conformance.reference.decode import profiles_decoding

# The rates DJI's flight controllers are set to in DJI Assistant, most common first after the default.
BAUDS = (230400, 115200, 460800, 921600, 1000000)
FRAMES_TO_SETTLE = 3        # CRC-valid frames that settle a baud rate
# bytes without one valid frame that rule a rate out: three of the longest frames there are
GARBAGE_ENOUGH = 3 * MAX_LEN
LISTEN_S = 1.0              # per rate, or until FRAMES_TO_SETTLE frames: an FC broadcasts at 1 Hz or more
HEALTH_S = 2.0              # the line's error rate is measured over this long at the rate found
ACK_WAIT_S = 0.5            # per version query (the FC answers within milliseconds)
NOISY = 0.01                # a line losing more than 1 frame in 100 is a problem, not a warning
RAW_KEEP = 256 * 1024       # bytes kept of what was heard (a console's text, the broadcast's frames)


class RawTap:
    """The bytes of one listen, for what the analyzer does not keep: a
    console's text, the broadcast values to fit to a profile, an echo. It is
    device.port.Port's capture."""

    def __init__(self) -> None:
        self.rx_bytes = bytearray()
        self.tx_bytes = bytearray()

    def rx(self, data: bytes, ts: int, comment: str | None = None) -> None:
        if len(self.rx_bytes) < RAW_KEEP:
            self.rx_bytes += data[:RAW_KEEP - len(self.rx_bytes)]

    def tx(self, data: bytes, ts: int, comment: str | None = None) -> None:
        if len(self.tx_bytes) < RAW_KEEP:
            self.tx_bytes += data


@dataclass
class Listen:
    """One open of the port at one rate."""

    baud: int
    port: Port
    an: Analyzer
    tap: RawTap
    t0: float = field(default_factory=time.monotonic)

    @property
    def frames(self) -> int:
        """CRC-valid frames of any kind: what settles a baud rate."""
        return self.an.frames

    @property
    def broadcasts(self) -> int:
        """Frames the FC sent unasked: every frame that is not an ACK (one encrypted with a key this host
        does not have, or decrypted with the wrong one to noise, counts too)."""
        return sum(self.an.cmd_frames.values()) + self.an.encrypted_unopened

    def wait(self, seconds: float, until: Callable[[], bool] = lambda: False) -> None:
        end = time.monotonic() + seconds
        while time.monotonic() < end and not until():
            time.sleep(0.02)

    def close(self) -> None:
        self.port.close()


@dataclass
class Options:
    port: str
    baud: int | None = None
    profile: str | None = None
    key: bytes | None = None
    app_id: int | None = None
    say: Callable[[str], None] = lambda text: None


class Doctor:
    def __init__(self, opts: Options) -> None:
        self.o = opts
        self.d = Diagnosis(opts.port)
        self.t0 = time.monotonic()
        self.listen: Listen | None = None
        self.profile = opts.profile or "a3-fw3.1"

    # ---- the run -------------------------------------------------------------------------

    def run(self) -> Diagnosis:
        try:
            self._steps()
        finally:
            if self.listen is not None:
                self.listen.close()
            self.d.seconds = time.monotonic() - self.t0
        return self.d

    def _steps(self) -> None:
        if not self.port_on_host():
            return
        found = self.find_baud()
        if found is None:
            return
        if found.broadcasts:
            self.judge_frames(found)
        self.ask(found)

    # ---- 1. the port on this host --------------------------------------------------------

    def port_on_host(self) -> bool:
        self.o.say("looking at the port")
        facts = ports.inspect(self.o.port)
        if facts.is_url:
            self.d.add(Finding("port.found", OK, f"{self.o.port} is a network port: nothing local to check"))
        elif not facts.exists:
            self.d.add(Finding("port.found", PROBLEM, f"{self.o.port} does not exist",
                               {"serial devices on this host": facts.candidates or "none"},
                               remedies.port_missing(facts.candidates)))
            return False
        else:
            self.d.add(Finding("port.found", OK, f"{self.o.port} exists ({facts.path})"))
            if not facts.allowed:
                self.d.add(Finding("port.permission", PROBLEM, f"this user may not open {facts.path}",
                                   {"group that may": facts.owner_group, "in that group": facts.in_group},
                                   remedies.permission(facts.owner_group)))
                return False
            self.d.add(Finding("port.permission", OK, "this user may read and write it"))
            if facts.is_serial is False:
                self.d.add(Finding("port.serial", PROBLEM, f"{facts.path} is not a serial port",
                                   {"serial devices on this host": facts.candidates or "none"},
                                   remedies.port_missing(facts.candidates)))
                return False
            consoles = [h for h in facts.holders if h.is_console]
            if consoles:
                self.d.add(Finding("port.console", PROBLEM, f"a login console runs on this port: "
                                   f"{consoles[0].describe()}", {"programs": [h.describe() for h in consoles]},
                                   remedies.console(facts.path)))
                return False
            if facts.holders:
                self.d.add(Finding("port.busy", PROBLEM, f"another program has this port open: "
                                   f"{facts.holders[0].describe()}",
                                   {"programs": [h.describe() for h in facts.holders]},
                                   remedies.busy(facts.holders)))
                return False
            self.d.add(Finding("port.free", OK, "no other program has it open"))
        try:
            serial.serial_for_url(self.o.port, baudrate=self.o.baud or BAUDS[0], timeout=0).close()
        except (serial.SerialException, OSError, ValueError) as e:
            self.d.add(self._open_failure(e))
            return False
        return True

    def _open_failure(self, e: BaseException) -> Finding:
        code = getattr(e, "errno", None)
        if code in (errno.EACCES, errno.EPERM):
            return Finding("port.permission", PROBLEM, f"this user may not open {self.o.port}",
                           {"error": one_line(e)}, remedies.permission(None))
        if code == errno.EBUSY:
            return Finding("port.busy", PROBLEM, f"{self.o.port} is in exclusive use", {"error": one_line(e)},
                           remedies.busy([]))
        return Finding("port.open", PROBLEM, f"cannot open {self.o.port}", {"error": one_line(e)},
                       "check the port name; for a network port, that the server listens")

    # ---- 2. listening --------------------------------------------------------------------

    def _open(self, baud: int) -> Listen:
        if self.listen is not None:
            self.listen.close()
        tap = RawTap()
        an = Analyzer(self.profile, self.o.key)
        port = Port(self.o.port, baud, an, tap)
        port.open()
        self.listen = Listen(baud, port, an, tap)
        return self.listen

    def find_baud(self) -> Listen | None:
        order = ([self.o.baud] if self.o.baud else []) + [b for b in BAUDS if b != self.o.baud]
        heard: dict[int, int] = {}
        for i, baud in enumerate(order):
            self.o.say(f"listening at {baud} baud")
            ln = self._open(baud)
            ln.wait(LISTEN_S, lambda: ln.frames >= FRAMES_TO_SETTLE
                    or (not ln.frames and ln.an.rx_bytes > GARBAGE_ENOUGH))
            heard[baud] = ln.an.rx_bytes
            if ln.frames:
                self._baud_found(ln, asked=self.o.baud, tried=order[:i + 1])
                return ln
            if i == 0 and ln.an.rx_bytes == 0:
                return self._no_bytes(ln)   # silence at one rate is silence at every rate
        text = _console_text(self.listen.tap.rx_bytes if self.listen else b"")
        if text:
            self.d.add(Finding("link.console", PROBLEM, "text on the line, not frames: a login console or "
                               "boot messages", {"text": text}, remedies.console(self.o.port)))
        else:
            self.d.add(Finding("link.baud", PROBLEM, "bytes arrive but no valid frame at any usual baud rate",
                               {"bytes heard per rate": heard}, remedies.NO_FRAME_AT_ANY_RATE))
        return None

    def _baud_found(self, ln: Listen, asked: int | None, tried: list[int], how: str = "CRC-valid frames") -> None:
        evidence = {"baud": ln.baud, "valid frames": ln.frames, "rates tried": tried,
                    "how sure": "each valid frame passed a CRC-16 and a CRC-32: bytes at a wrong rate pass "
                                "both by chance about once in 2^48 tries"}
        if asked and ln.baud != asked:
            self.d.add(Finding("link.baud", PROBLEM, f"the flight controller sends at {ln.baud} baud, not {asked}",
                               evidence, remedies.wrong_baud(ln.baud, asked)))
        else:
            found = "as asked" if asked else "found by listening"
            self.d.add(Finding("link.baud", OK, f"{ln.baud} baud: {how} ({found})", evidence))

    def _no_bytes(self, ln: Listen) -> Listen | None:
        """Nothing heard. A query tells the rest apart: it comes back (a
        loopback), it is answered (an FC that does not broadcast), or not."""
        self.o.say("nothing heard: asking the flight controller for its version")
        probe = encode(cmd_set=0, cmd_id=0, value=b"\x00", session=2, seq=0x5A5A)
        ln.port.write(probe)
        ln.wait(ACK_WAIT_S, lambda: len(ln.tap.rx_bytes) >= len(probe))
        if probe in bytes(ln.tap.rx_bytes):
            self.d.add(Finding("link.loopback", PROBLEM, "what this host sends comes back unchanged: the line "
                               "is a loopback", {"sent": probe.hex(), "received": bytes(ln.tap.rx_bytes[:64]).hex()},
                               remedies.LOOPBACK))
            return None
        tried = [ln.baud]
        while not ln.an.acks:
            rest = [b for b in BAUDS if b not in tried]
            if not rest:
                self.d.add(Finding("link.bytes", PROBLEM, "not one byte received, and no answer to a version "
                                   "query at any usual baud rate", {"listened s": LISTEN_S, "rates asked": tried},
                                   remedies.NO_BYTES))
                return None
            ln = self._open(rest[0])
            tried.append(rest[0])
            ln.port.write(probe)
            ln.wait(ACK_WAIT_S, lambda: bool(ln.an.acks))
        # ask() says what an FC that answers and does not broadcast means
        self._baud_found(ln, self.o.baud, tried, "the flight controller answers a query")
        return ln

    # ---- 3. what the frames say ----------------------------------------------------------

    def judge_frames(self, ln: Listen) -> None:
        ln.wait(HEALTH_S - (time.monotonic() - ln.t0))
        values, encrypted, unopened = _broadcast_values(bytes(ln.tap.rx_bytes), self.o.key)
        self._encryption(encrypted, unopened)
        if values:
            self._profile(values)
        elif not unopened:
            self.d.add(Finding("link.profile", NOT_CHECKED, "no broadcast frame to fit to a profile"))
        self._health(ln)

    def _encryption(self, encrypted: int, unopened: int) -> None:
        if not encrypted:
            self.d.add(Finding("link.encryption", OK, "frames are not encrypted"
                               + (" (a key was given: it is not needed)" if self.o.key else "")))
        elif self.o.key is None:
            self.d.add(Finding("link.encryption", PROBLEM, f"{encrypted} frames are AES-encrypted and no key "
                               "was given", {"encrypted frames": encrypted}, remedies.NO_KEY))
        elif unopened:
            self.d.add(Finding("link.encryption", PROBLEM, "the frames are encrypted with another key: "
                               f"{unopened} of {encrypted} do not decrypt with the one given",
                               {"encrypted frames": encrypted, "not decrypted": unopened}, remedies.WRONG_KEY))
        else:
            self.d.add(Finding("link.encryption", OK, f"{encrypted} encrypted frames decrypt with the key given"))

    def _profile(self, values: list[bytes]) -> None:
        fits = profiles_decoding(values, "")
        rules = default_rules()
        evidence = {"broadcast frames": len(values), "profiles they fit": fits or "none"}
        if self.o.profile:
            if self.o.profile in fits:
                self.d.add(Finding("link.profile", OK, f"the broadcast fits {self.o.profile}"
                                   + _enum_note(rules, self.o.profile), evidence))
            else:
                self.d.add(Finding("link.profile", PROBLEM, f"the broadcast does not fit {self.o.profile}"
                                   + (f"; it fits {' and '.join(fits)}" if fits else ""), evidence,
                                   remedies.wrong_profile(fits)))
            return
        if not fits:
            self.d.add(Finding("link.profile", PROBLEM, "the broadcast fits no known profile", evidence,
                               remedies.wrong_profile(fits)))
            return
        self.profile = fits[0]
        more = f" (also fits {', '.join(fits[1:])}: give --profile to choose)" if len(fits) > 1 else ""
        self.d.add(Finding("link.profile", OK, f"the broadcast fits {fits[0]}{more}" + _enum_note(rules, fits[0]),
                           evidence))

    def _health(self, ln: Listen) -> None:
        an = ln.an
        seconds = max(1e-3, (an.last_t or 0) - (an.first_t or 0)) if an.first_t else HEALTH_S
        kinds: dict[str, int] = {}
        for inc in an.incidents:
            kinds[inc[1]] = kinds.get(inc[1], 0) + 1
        lost = sum(kinds.values())
        share = lost / max(1, lost + an.frames)
        evidence = {"seconds": round(seconds, 2), "valid frames": an.frames, "errors by kind": kinds,
                    "errors per s": round(lost / seconds, 2), "baud": ln.baud}
        stalls = [round(d, 2) for _, d in ln.port.state.host_stalls]
        if not lost:
            self.d.add(Finding("line.health", OK, f"no error in {an.frames} frames over {seconds:.1f} s", evidence))
        elif stalls:
            # bytes a stalled reader left in a full buffer are lost on this host, not on the line
            self.d.add(Finding("line.health", WARNING, f"{lost} errors, but this host did not read the port for "
                               f"{max(stalls):.1f} s: the errors may be this host's, not the line's",
                               {**evidence, "reader stalls s": stalls, "load average": os.getloadavg()[0]},
                               "run the doctor again on a less busy host"))
        else:
            verdict = PROBLEM if share > NOISY else WARNING
            self.d.add(Finding("line.health", verdict, f"{lost} errors to {an.frames} valid frames "
                               f"({100 * share:.1f}%) over {seconds:.1f} s", evidence, remedies.noisy(ln.baud)))

    # ---- 4. asking -----------------------------------------------------------------------

    def ask(self, ln: Listen) -> None:
        cmd = Commander(ln.port, ln.an, self.profile, self.o.key, encrypt=False, ack_timeout=ACK_WAIT_S)
        self.o.say("asking the flight controller for its version")
        ack, info = cmd.request(0, 0, {"arbitrary": 0})
        if ack is None:
            self._unanswered(ln, info)
            return
        name = bytes(ack.version_name).rstrip(b"\0").decode("ascii", "replace")
        activated = int(ack.ack_code) == 0
        self.d.add(Finding("fc.answers", OK, f"the flight controller answers: version {name!r}, "
                           + ("activated" if activated else "not activated"),
                           {"version name": name, "ack after s": round(info, 3)}))
        if self.o.app_id is not None:
            self.activate(ln, cmd)
        elif not activated and not ln.broadcasts:
            self.d.add(Finding("fc.broadcast", PROBLEM, "the flight controller is not activated and broadcasts "
                               "nothing", {}, remedies.BROADCAST_OFF))
        elif not ln.broadcasts:
            self.d.add(Finding("fc.broadcast", PROBLEM, "the flight controller answers but broadcasts nothing", {},
                               remedies.BROADCAST_OFF))

    def _unanswered(self, ln: Listen, why: str) -> None:
        """The broadcast arrives, the query is not answered: at which rate does the FC listen, if at all?"""
        self.o.say("no answer: trying the other rates for the direction to the flight controller")
        for baud in BAUDS:
            if baud == ln.baud:
                continue
            if _query_at(ln, 0x6000 + baud // 1000, baud):
                self.d.add(Finding("fc.rx_baud", PROBLEM, f"the flight controller listens at {baud} baud but "
                                   f"sends at {ln.baud}", {"sends at": ln.baud, "answers queries sent at": baud},
                                   remedies.split_baud(ln.baud, baud)))
                return
        self.d.add(Finding("fc.deaf", PROBLEM, "the broadcast arrives but the flight controller answers no "
                           "version query, at any baud rate", {"query": why, "rates tried": list(BAUDS)},
                           remedies.DEAF))

    # ---- 5. activation -------------------------------------------------------------------

    def activate(self, ln: Listen, cmd: Commander) -> None:
        self.o.say(f"activating app id {self.o.app_id}")
        prof = default_rules().profile(self.profile)
        ack, info = cmd.request(0, 1, {"app_id": self.o.app_id, "api_level": 2, "sdk_version": prof.sdk_version,
                                       "bundle_id": bytes(32)})
        if ack is None:
            self.d.add(Finding("fc.activation", PROBLEM, f"activation not answered: {info}", {},
                               remedies.ACTIVATION_UNANSWERED))
            return
        code = int(ack.ack_code)
        meaning = remedies.ack_meaning("activation_result", code)
        evidence = {"code": code, "name": meaning.name, "sdk version sent": f"0x{prof.sdk_version:08X}"}
        if code != 0:
            self.d.add(Finding("fc.activation", PROBLEM, f"activation refused: code {code} {meaning.name}",
                               evidence, meaning.remedy))
            return
        self.d.add(Finding("fc.activation", OK, f"activated app id {self.o.app_id}", evidence))
        if not ln.broadcasts:
            ln.wait(LISTEN_S, lambda: ln.broadcasts > 0)
            if ln.broadcasts:
                self.d.add(Finding("fc.broadcast", OK, "the broadcast started after activation"))
                ln.t0 = time.monotonic()   # the line's health over a whole window of broadcast
                self.judge_frames(ln)
            else:
                self.d.add(Finding("fc.broadcast", PROBLEM, "activated, and still no broadcast", {},
                                   remedies.BROADCAST_OFF))


def _query_at(ln: Listen, seq: int, baud: int) -> bool:
    """A version query sent at `baud` while the port still receives at the
    rate the FC sends at: the port's output speed alone is changed (termios
    keeps an input and an output speed), until the answer came or the wait
    ran out. True when it was answered."""
    port = ln.port
    frame = encode(cmd_set=0, cmd_id=0, value=b"\x00", session=2, seq=seq)
    with port.wlock:
        ser = port.ser
        if ser is None or not hasattr(ser, "fd"):   # a network port has no speed of its own
            return False
        attrs = termios.tcgetattr(ser.fd)
        out = getattr(termios, f"B{baud}")
        receive = attrs[2] & termios.CBAUD
        split = list(attrs)
        # the C library sets one speed for both directions (CBAUD); the kernel takes an input speed of
        # its own in CIBAUD. A UART driver that cannot split them keeps one rate: see docs/DOCTOR.md.
        split[2] = with_input_speed(attrs[2], receive)
        split[4] = split[5] = out
        termios.tcsetattr(ser.fd, termios.TCSADRAIN, split)
        try:
            ts = time.time_ns()
            port.cap.tx(frame, ts)
            ln.an.feed_tx(ts / 1e9, frame)
            ser.write(frame)
            ser.flush()
            return ln.an.wait_ack(2, seq, ACK_WAIT_S) is not None
        finally:
            termios.tcsetattr(ser.fd, termios.TCSADRAIN, attrs)


def _broadcast_values(raw: bytes, key: bytes | None) -> tuple[list[bytes], int, int]:
    """(the broadcast values, frames with ENC set, encrypted frames that did not open) in `raw`."""
    values: list[bytes] = []
    encrypted = unopened = 0
    for ev in Deframer().feed(raw):
        if not isinstance(ev, Frame):
            continue
        op = open_frame(ev.raw, key)
        encrypted += op.encrypted
        # AES with the wrong key "decrypts" too, to noise: a command the protocol does not have
        wrong_key = op.encrypted and not op.is_ack and (op.cmd_set, op.cmd_id) not in COMMANDS
        if op.problem or wrong_key:
            unopened += op.encrypted
            continue
        if not op.is_ack and (op.cmd_set, op.cmd_id) == (2, 0):
            values.append(op.value)
    return values, encrypted, unopened


def _console_text(raw: bytes) -> str:
    """The text in what was heard, when it is mostly text (a getty's prompt,
    a kernel console): the first printable lines, or ""."""
    if len(raw) < 8:
        return ""
    printable = sum(32 <= b < 127 or b in (9, 10, 13) for b in raw)
    if printable / len(raw) < 0.9:
        return ""
    lines = [ln.strip() for ln in raw.decode("ascii", "replace").splitlines() if ln.strip()]
    return " | ".join(lines[:3])[:160]


def _enum_note(rules, profile: str) -> str:
    return f"; flight status uses the {rules.profile(profile).flight_status_enum} enum"

