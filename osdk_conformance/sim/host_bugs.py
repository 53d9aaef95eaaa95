"""Planted host bugs for `osdkc host --bug NAME` (the simulated flight controller's are in bugs.py).

The healthy `osdkc host` is our model of a correct onboard program; a tap
has to be shown to catch what real host programs get wrong (USER-RESEARCH
rows 3 and 5: cadence, mode bytes, authority). Each bug models one, is off
unless named, and names the check of `osdkc tap` that must catch it.
"""
from __future__ import annotations

BUGS: dict[str, tuple[str, str]] = {
    "no-control": ("sends its movement commands without ever asking for control authority", "host.order"),
    "invalid-mode": ("sends movement with a mode byte the spec leaves undefined for the profile", "host.mode"),
    "later-firmware-mode": ("sends movement with a mode byte only later firmware defines", "host.mode"),
    "out-of-range": ("sends a few horizontal velocities of 12 to 20 m/s, beyond the mode's 10", "host.setpoints"),
    "slow-cadence": ("streams movement at 5 Hz", "host.cadence"),
    "gap": ("stops streaming movement for 1 s in the middle, still in control", "host.cadence"),
    "bad-crc": ("sends one movement frame with its CRC-32 wrong", "host.frames"),
    "wrong-session": ("sends its activation in session 0, where no ACK is wanted, before the real one",
                      "host.sessions"),
    "no-release": ("ends its session without releasing control authority", "host.release"),
    "retry-storm": ("sends its obtain-control request 20 times 5 ms apart without waiting for the ACK",
                    "host.retries"),
}
"""Bug name -> (what the host does, the tap check that catches it): `osdkc host
--help`, docs/TAP.md, `osdkc bench --only tap` and the tests read them from here."""


def caught_by(name: str) -> str:
    return BUGS[name][1]
