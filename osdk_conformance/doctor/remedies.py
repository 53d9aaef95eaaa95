"""What to do about each finding. Where each remedy comes from is in
docs/DOCTOR.md; the meaning and remedy of an ACK code are the spec's
(spec/rules.yaml enums), not a copy here."""
from __future__ import annotations

from dataclasses import dataclass

from osdk_conformance.core.rules import default_rules


def port_missing(candidates: list[str]) -> str:
    if not candidates:
        return ("no serial device is present: plug the USB-serial adapter in (dmesg shows the name it gets), "
                "or enable the UART (Raspberry Pi: enable_uart=1; Jetson: ttyTHS*)")
    return f"use one of the serial devices present, e.g. {candidates[0]} (/dev/serial/by-id names survive re-plugging)"


def permission(group: str | None) -> str:
    if group and group not in ("root",):
        return (f"add yourself to the {group} group (sudo usermod -aG {group} $USER) and log in again; "
                "do not run the kit as root")
    return "give this user read and write access to the device (a udev rule, or the group that owns it)"


def console(path: str) -> str:
    name = path.rsplit("/", 1)[-1]
    return (f"stop the login console on this UART (sudo systemctl disable --now serial-getty@{name}.service) "
            "and remove console=... for it from the kernel command line (Raspberry Pi: cmdline.txt; "
            "raspi-config: no login shell over serial)")


def busy(holders) -> str:
    if not holders:
        return "close the program that holds the port open exclusively"
    who = ", ".join(f"{h.program} (pid {h.pid})" for h in holders)
    return (f"close {who}: two programs reading one serial port each get part of the bytes, so ACKs and "
            "frames go missing (ModemManager: sudo systemctl disable --now ModemManager)")


def wrong_baud(found: int, asked: int) -> str:
    return f"use --baud {found} (or set the flight controller to {asked} baud in DJI Assistant)"


def split_baud(sends: int, listens: int) -> str:
    return (f"the two directions run at different rates: set one baud rate for both, {sends} on the host "
            "and in DJI Assistant; check the adapter's configuration (some bridge chips allow split rates)")


def wrong_profile(fits: list[str]) -> str:
    if fits:
        return f"run with --profile {fits[0]}"
    return ("the broadcast's item sizes match no known profile: a firmware newer than the spec knows; "
            "capture it (osdkc device --capture) and report it")


def noisy(baud: int) -> str:
    high = (" At this rate also check the adapter's clock error (an FTDI FT232 makes 921600 exactly), "
            "or try a lower rate." if baud >= 921600 else "")
    return ("connect the adapter's ground to the flight controller's ground, shorten the lead or use a "
            f"twisted pair away from motor and ESC wiring.{high}")


NO_BYTES = ("check the wiring (the FC's TX to the adapter's RX, grounds connected), that the OPEN protocol "
            "output is enabled in DJI Assistant (API control, with a baud rate), that the FC is powered, and "
            "that this is the port the adapter is on")
NO_FRAME_AT_ANY_RATE = ("the bytes are not the OPEN protocol at any usual rate: a swapped or floating RX line "
                        "picks up noise; check the wiring and ground, and that this port is the FC's API port")
LOOPBACK = ("the host's TX is wired to its own RX (a loopback plug, or TX and RX bridged): connect the "
            "adapter's TX to the FC's RX and the adapter's RX to the FC's TX")
BROADCAST_OFF = ("the FC sends no broadcast: activate the app (--app-id with --key-env), and check the "
                 "broadcast frequencies in DJI Assistant (all 0 means no broadcast)")
NO_KEY = "give the app key: --key-env VAR, with VAR holding the 64 hex digits of the key"
WRONG_KEY = "the key does not decrypt the FC's frames: use the key of the app the FC was activated with"
DEAF = ("the FC does not hear this host: check the adapter's TX to the FC's RX wire (and that TX and RX are "
        "not both on the FC's TX), that API control is enabled in DJI Assistant, that the FC reads at the rate it "
        "sends at, and that no other program writes to or reads from the port")
ACTIVATION_UNANSWERED = ("activation got no ACK although the version query did: check the app id, and that "
                         "the FC's firmware supports the SDK version sent")


@dataclass(frozen=True)
class Meaning:
    name: str
    remedy: str


def ack_meaning(enum: str, code: int) -> Meaning:
    """The name and remedy the spec gives an ACK code of `enum` (rules.yaml enums)."""
    for v in default_rules().data["enums"][enum]["values"]:
        if v["value"] == code:
            return Meaning(v["name"], v.get("remedy", ""))
    return Meaning("undefined", f"code {code} is not defined by the spec for this command")
