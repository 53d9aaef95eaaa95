"""The tap report's own figure: the host's movement commands over time
(their cadence and their four setpoints), on the time axis of the
acceptance report's figures that follow it (device/plots.py), so what the
host asked for reads against the attitude and velocity the flight
controller reported."""
from __future__ import annotations

import html

from osdk_conformance.device.plots import Panel, phases, small_multiples

SETPOINTS = ("roll or x", "pitch or y", "throttle or z", "yaw")


def host_plots_html(judge) -> str:
    an = judge.an
    with an.lock:
        t0 = judge.t0
        moves = list(judge.moves)
        t1 = max(an.last_t or 0.0, judge.last_t or 0.0)
        marks = phases(an) if an.first_t is not None else []
    if not moves or t0 is None:
        return "<h2>The host's movement commands</h2><p>The host sent no movement control command.</p>"
    intervals = [(b.t - t0, 1000.0 * (b.t - a.t)) for a, b in zip(moves, moves[1:])]
    panels = [Panel("interval since the last command", "ms", intervals, floor=0.0)]
    for i, name in enumerate(SETPOINTS):
        panels.append(Panel(name, "as sent (unit by mode)", [(m.t - t0, m.setpoints[i]) for m in moves]))
    panels.append(Panel("under control (by the ACKs)", "1 yes, 0 no",
                        [(m.t - t0, 1.0 if m.under_control else 0.0) for m in moves], floor=0.0))
    note = ("Each movement command the host sent, when the tap read it: the interval since the one before "
            "(its cadence), the four setpoints as sent (their unit is the mode byte's: deg, m/s or m; "
            "`osdkc explain --mode` says which), and whether the host held control authority then. The "
            "figures after this one show what the flight controller reported on the same time axis.")
    return "\n".join(["<h2>The host's movement commands</h2>", f"<p>{html.escape(note)}</p>",
                      small_multiples("Movement commands of the host", panels, (0.0, max(t1 - t0, 0.001)), marks,
                                      "t (s) from the first byte the tap read, either way")])
