"""`osdkc host`: a whole onboard-computer session, healthy or with planted bugs.

    osdkc host --port /dev/pts/3 --profile m100-fw3.1 --app-id 1234567 --key-env OSDK_KEY --yes
    osdkc host --port /dev/pts/3 --profile a3-fw3.1 --app-id 1234567 --key-env OSDK_KEY --bug gap --seed 7 --yes

The session is what a correct host program does (PROTOCOL-FACTS §2): the
version query, activation, the broadcast frequencies, control authority
(asked again while the ACK says "in progress", errata E26), movement
control streamed at --rate Hz for --seconds (velocity in the ground frame,
small setpoints that wander with --seed), release of control, the default
frequencies back. It is the reference a tap is checked against (`osdkc tap`
must find nothing in it) and, with `--bug NAME` (host/bugs.py), a host that
gets one thing wrong that the tap must catch. It moves an aircraft: on a
terminal it asks first (--yes for scripts), and a Ctrl-C or SIGTERM at any
moment ends the movement and releases control before it exits (a second one
cuts that short).

Exit status: 0 the session ran to its end, 1 the flight controller refused
or did not answer a step, 2 usage or port error or movement not confirmed,
130/143 interrupted.
"""
from __future__ import annotations

import argparse
import random
import sys
import time

from osdk_conformance.core.errors import UsageError, exit_status_of_signal
from osdk_conformance.core.options import baud_rate, non_negative_int, positive_float, uint32
from osdk_conformance.core.rules import default_rules
from osdk_conformance.core.wire import encode, key_option
from osdk_conformance.device.acceptance import MOTION_WARNING, confirm_motion
from osdk_conformance.device.active import CleanupCut, Commander, Interrupts, RunInterrupted, rate_codes
from osdk_conformance.device.analysis import Analyzer
from osdk_conformance.device.port import Port, PortDown
from osdk_conformance.sim.host_bugs import BUGS
from osdk_conformance._construct.control import encode_movement_control

TOOL = "osdkc host"
VELOCITY_MODE = 0x48      # horizontal velocity, vertical velocity, yaw rate, ground frame: documented everywhere
OBTAINED, RELEASED, OBTAINING, RELEASING = 2, 1, 3, 4


def add_arguments(ap: argparse.ArgumentParser, profiles: tuple[str, ...]) -> None:
    ap.add_argument("--port", required=True, metavar="URL", help="the flight controller's port (or a tap's)")
    ap.add_argument("--profile", required=True, choices=profiles, help="broadcast wire profile of the flight controller")
    ap.add_argument("--baud", type=baud_rate, default=230400, help="baud rate (default 230400)")
    ap.add_argument("--app-id", type=uint32, required=True, help="app id to activate with")
    ap.add_argument("--key-env", metavar="VAR", required=True,
                    help="environment variable holding the app key (64 hex characters)")
    ap.add_argument("--encrypt", action="store_true", help="AES-256 encrypt the commands after activation")
    ap.add_argument("--rate", type=positive_float, default=50.0, metavar="HZ",
                    help="movement commands per second (default 50, what DJI's users are told: OSDK#456)")
    ap.add_argument("--seconds", type=positive_float, default=2.0, metavar="S",
                    help="seconds of movement control (default 2)")
    ap.add_argument("--seed", type=non_negative_int, default=0, help="seed of the setpoints and of where a bug strikes")
    ap.add_argument("--bug", action="append", default=[], choices=tuple(BUGS), metavar="NAME",
                    help="plant a host bug (repeatable): " + "; ".join(f"{k}: {v[0]}" for k, v in BUGS.items()))
    ap.add_argument("--yes", action="store_true", help="do not ask before sending movement control (for scripts)")


def plan(args) -> str:
    return (f"movement control for {args.seconds:g} s at {args.rate:g} Hz: velocities under 2 m/s in the ground "
            f"frame, yaw rate under 20 deg/s" + (f", with planted bug(s) {', '.join(args.bug)}" if args.bug else ""))


class Session:
    def __init__(self, args, cmd: Commander, an: Analyzer, interrupts: Interrupts) -> None:
        self.args, self.cmd, self.an, self.interrupts = args, cmd, an, interrupts
        self.bugs = set(args.bug)
        self.rng = random.Random(args.seed)
        self.prof = default_rules().profile(args.profile)
        self.asked_control = False
        self.frequencies_set = False
        self.failed = ""

    def say(self, text: str) -> None:
        print(f"{TOOL}: {text}", file=sys.stderr, flush=True)

    def step(self, what: str, cmd_set: int, cmd_id: int, body: dict, want: tuple[int, ...] = (0,)):
        self.interrupts.phase = what
        ack, info = self.cmd.request(cmd_set, cmd_id, body)
        if ack is None:
            self.failed = f"{what}: {info}"
            return None
        if int(ack.ack_code) not in want:
            self.failed = f"{what}: answered {int(ack.ack_code):#06x}"
            return None
        return ack

    def run(self) -> bool:
        if self.step("version", 0, 0, {"arbitrary": 0}, (0, 0xFF01)) is None:
            return False
        activation = {"app_id": self.args.app_id, "api_level": 2, "sdk_version": self.prof.sdk_version,
                      "bundle_id": bytes(32)}
        if "wrong-session" in self.bugs:
            value = self.cmd.payload(0, 1, False, self.args.profile).build({"body": activation})
            self.cmd.send_value(0, 1, value, session=0)
            time.sleep(0.05)
        if self.step("activation", 0, 1, activation) is None:
            return False
        if self.args.encrypt:
            self.cmd.key = self.an.key
        rates = {item: 50 if self.prof.default_rates_hz[item] else 0 for item in self.prof.flag_bits}
        rates["control_info"] = 10 if "control_info" in rates else 0
        if self.step("frequency", 0, 0x10, {"codes": rate_codes(self.prof, rates)}) is None:
            return False
        self.frequencies_set = True
        if "no-control" not in self.bugs and not self.obtain():
            return False
        self.stream()
        return True

    def obtain(self) -> bool:
        self.asked_control = True
        if "retry-storm" in self.bugs:
            value = self.cmd.payload(1, 0, False, self.args.profile).build({"body": {"request": 1}})
            seq = self.cmd._next_seq()
            frame = encode(cmd_set=1, cmd_id=0, value=value, session=2, seq=seq, key=self.cmd.key)
            for _ in range(20):
                self.cmd.port.write(frame)
                time.sleep(0.005)
            time.sleep(0.2)
        for _ in range(3):   # errata E26: the first request answers "in progress"
            ack = self.step("obtain control", 1, 0, {"request": 1}, (OBTAINED, OBTAINING))
            if ack is None:
                return False
            if int(ack.ack_code) == OBTAINED:
                return True
        self.failed = "obtain control: still in progress after 3 requests"
        return False

    def stream(self) -> None:
        """Movement at the planned rate, every bug that bends it planted on the way."""
        self.interrupts.phase = "movement"
        hz = 5.0 if "slow-cadence" in self.bugs else self.args.rate
        count = max(2, round(self.args.seconds * hz))
        mode = VELOCITY_MODE
        if "invalid-mode" in self.bugs or "later-firmware-mode" in self.bugs:
            want = "invalid" if "invalid-mode" in self.bugs else "later_firmware"
            rules = default_rules()
            mode = self.rng.choice([b for b in range(256)
                                    if rules.classify_control_mode(b, self.args.profile)["classification"] == want])
        gap_at = self.rng.randrange(count // 4, 3 * count // 4) if "gap" in self.bugs else -1
        crc_at = self.rng.randrange(1, count - 1) if "bad-crc" in self.bugs else -1
        wild = set(self.rng.sample(range(count), 3)) if "out-of-range" in self.bugs else set()
        vx = vy = 0.0
        next_t = time.monotonic()
        for i in range(count):
            vx = max(-2.0, min(2.0, vx + self.rng.uniform(-0.2, 0.2)))
            vy = max(-2.0, min(2.0, vy + self.rng.uniform(-0.2, 0.2)))
            x = self.rng.uniform(12.0, 20.0) * self.rng.choice((-1, 1)) if i in wild else vx
            value = encode_movement_control(mode, x, vy, self.rng.uniform(-0.3, 0.3), self.rng.uniform(-20, 20))
            if i == crc_at:
                frame = bytearray(encode(cmd_set=1, cmd_id=3, value=value, session=0, seq=self.cmd._next_seq(),
                                         key=self.cmd.key))
                frame[-1] ^= 0x5A
                self.cmd.port.write(bytes(frame))
            else:
                self.cmd.send_value(1, 3, value, session=0)
            next_t += 1.0 / hz + (1.0 if i == gap_at else 0.0)
            time.sleep(max(0.0, next_t - time.monotonic()))

    def release(self, tries: int = 3, ack_timeout: float | None = None) -> None:
        """Hand control back (asked again while in progress); the default rates back."""
        self.interrupts.phase = "release"
        if self.asked_control and "no-release" not in self.bugs:
            for _ in range(3):
                ack, info = self.cmd.request(1, 0, {"request": 0}, tries, ack_timeout)
                if ack is None or int(ack.ack_code) != RELEASING:
                    if ack is None:
                        self.failed = self.failed or f"release control: {info}"
                    break
        if self.frequencies_set and "no-release" not in self.bugs:
            self.cmd.request(0, 0x10, {"codes": rate_codes(self.prof, dict(self.prof.default_rates_hz))},
                             tries, ack_timeout)


def run_host(args: argparse.Namespace) -> int:
    key = key_option(args.key_env, args.encrypt)
    if key is None:
        raise UsageError("--key-env names no key")
    print(MOTION_WARNING, file=sys.stderr, flush=True)
    refused = confirm_motion(TOOL, plan(args), args.yes)
    if refused is not None:
        return refused
    an = Analyzer(args.profile, key)
    port = Port(args.port, args.baud, an)
    port.open()
    interrupts = Interrupts(TOOL)
    interrupts.install()
    cmd = Commander(port, an, args.profile, None, False, ack_timeout=0.5)
    session = Session(args, cmd, an, interrupts)
    signame = None
    try:
        try:
            done = session.run()
        except RunInterrupted as e:
            signame, done = e.signame, False
        except PortDown as e:
            session.failed, done = f"port down: {e}", False
        interrupts.mode = "cleanup"
        try:
            # after a signal: one try each, quickly, so the whole stop stays within 2 s
            session.release(*((1, 0.4) if signame else (3, None)))
        except (CleanupCut, PortDown):
            pass
    finally:
        interrupts.mode = "report"
        port.close()
        interrupts.uninstall()
    if signame:
        session.say(f"interrupted by {signame} during {interrupts.first_phase}; control released")
        return exit_status_of_signal(signame)
    if not done or session.failed:
        session.say(f"the session stopped: {session.failed}")
        return 1
    session.say("session complete" + (f" (planted: {', '.join(args.bug)})" if args.bug else ""))
    return 0
