"""Inline SVG plots for the acceptance report (no plotting library, no
script: the page works offline).

`plots_html(analyzer)` draws small multiples: one short panel per series,
every panel of a figure on one shared time axis, so fourteen broadcast
items read at a glance instead of as fourteen lines over each other.
Figures: the measured rate of each broadcast item (the configured rate
dashed behind it), link incidents (CRC failures, frames cut short, noise,
bad headers), attitude, velocity and position. Numbered vertical lines
mark the run's phases, from what the analyzer saw on the wire: set
frequency, control obtained and released, each run of movement commands.

Rates are honest: a rate is frames per second of time its bin really
covers. Bins tile each span of one configuration exactly (their width is
the span over a whole number of them), so no bin straddles a frequency
change and no bin is cut short at either end of the run; a frame read at
the very first moment of the run closes no interval (it and the others in
that first read were queued before the port was read), so a steady
100 Hz reads 100 in the first and the last bin. When the analyzer trusts
the flight controller's time stamp clock (Analyzer.fc_clock_trusted), a
frame is placed where its stamp says it was sent, not where a busy host
happened to read it: a host that was not scheduled for a moment reads a
burst of late frames, which by arrival empty one bin and overfill the
next, or fall into the next configuration's span.

An axis shows what the values are: a quantity that cannot go below zero
(a rate, a count) starts at zero, and all zero it runs 0..1 with "all 0"
written beside it; any other constant series gets its value ±1 and
"constant V".

`small_multiples` is also what the device fuzzer's liveness timeline
draws (fuzz_report.py). `checks_html(results)` is a table of every check
with its verdict.
"""
from __future__ import annotations

import html
import math
from dataclasses import dataclass, field
from typing import Sequence

from osdk_conformance.core.rules import default_rules

W = 900                  # figure width, px
ML, MR = 150, 110        # left margin (series name, y labels), right margin (notes)
PANEL_H, GAP = 46, 12    # one panel's height and the space between two
MARKER_ROW = 14          # height of one row of marker numbers above the panels
BOTTOM = 36              # x tick labels and the axis title
MAX_POINTS = 900         # per panel; a longer trace is thinned evenly
LINE, REFERENCE = "#1f5fa8", "#8c8c8c"
MARKER_COLOURS = {"frequency": "#7b3fa0", "control": "#d9480f", "movement": "#2b8a3e", "finding": "#c92a2a"}

BIN_S = 0.5              # nominal bin width of a run up to a minute; longer runs get 120 bins
FRAMES_PER_BIN = 5       # a slow item's bins are widened to hold about this many frames
MIN_BIN_S = 0.25         # a span of one configuration shorter than this is not binned (too short to say)
OBTAINED, RELEASED = 0x0002, 0x0001   # control authority ACK codes that say it is done


@dataclass
class Panel:
    name: str
    unit: str
    points: list[tuple[float, float]]                 # a NaN value breaks the line
    reference: list[tuple[float, float]] = field(default_factory=list)   # drawn dashed: what was expected
    floor: float | None = None                        # the least value the quantity can take (0 for rates)


@dataclass
class Marker:
    t: float
    label: str
    kind: str   # a key of MARKER_COLOURS


def _nice_ticks(lo: float, hi: float, n: int = 5) -> list[float]:
    if not math.isfinite(lo) or not math.isfinite(hi):
        return []
    if hi <= lo:
        hi = lo + 1.0
    raw = (hi - lo) / n
    mag = 10 ** math.floor(math.log10(raw))
    step = min((m * mag for m in (1, 2, 2.5, 5, 10) if m * mag >= raw), default=raw)
    start = math.ceil(lo / step) * step
    out, v = [], start
    while v <= hi + step * 1e-9:
        out.append(round(v, 10))
        v += step
    return out


def _fmt(v: float) -> str:
    return f"{v:.0f}" if abs(v) >= 100 or v == int(v) else f"{v:.3g}"


def y_range(panel: Panel) -> tuple[float, float, str]:
    """The panel's axis (low, high) and a note saying what a flat line is."""
    ys = [y for _, y in panel.points + panel.reference if math.isfinite(y)]
    base = panel.floor if panel.floor is not None else 0.0
    if not ys:
        return base, base + 1.0, "no data"
    lo, hi = min(ys), max(ys)
    if panel.floor is not None:
        lo = min(lo, panel.floor)
        if hi - lo <= 1e-12:
            return lo, lo + 1.0, f"all {_fmt(lo)}"
        return lo, hi + (hi - lo) * 0.08, ""
    if hi - lo <= 1e-9 * max(1.0, abs(hi)):
        return lo - 1.0, hi + 1.0, f"constant {_fmt(lo)}"
    pad = (hi - lo) * 0.06
    return lo - pad, hi + pad, ""


def _thin(points: list[tuple[float, float]]) -> list[tuple[float, float]]:
    if len(points) <= MAX_POINTS:
        return points
    k = math.ceil(len(points) / MAX_POINTS)
    return points[::k] + ([points[-1]] if (len(points) - 1) % k else [])


def _path(points: list[tuple[float, float]], sx, sy) -> str:
    """SVG path data; a non-finite value lifts the pen."""
    out, pen = [], "M"
    for x, y in points:
        if not (math.isfinite(x) and math.isfinite(y)):
            pen = "M"
            continue
        out.append(f"{pen}{sx(x):.1f},{sy(y):.1f}")
        pen = "L"
    return " ".join(out)


def _marker_rows(xs: list[float], spacing: float = 18.0) -> list[int]:
    """A row per marker number so that neighbours closer than `spacing` px do not overlap."""
    rows: list[int] = []
    last: list[float] = []
    for x in xs:
        row = next((i for i, r in enumerate(last) if x - r >= spacing), len(last))
        if row == len(last):
            last.append(x)
        last[row] = x
        rows.append(row)
    return rows


def small_multiples(title: str, panels: Sequence[Panel], span: tuple[float, float],
                    markers: Sequence[Marker] = (), xlabel: str = "t (s)") -> str:
    """One figure: a short panel per series, stacked on one time axis
    (`span`), each with its own y axis; `markers` are numbered vertical
    lines through every panel (numbered in the order given)."""
    e = html.escape
    head = f'<figure style="margin:1em 0"><figcaption><b>{e(title)}</b></figcaption>'
    if not panels:
        return head + "<p>No data.</p></figure>"
    x0, x1 = span
    if not (math.isfinite(x0) and math.isfinite(x1)) or x1 <= x0:   # a run of no length still gets an axis
        x0 = x0 if math.isfinite(x0) else 0.0
        x1 = x0 + 1.0
    pw = W - ML - MR

    def sx(x: float) -> float:
        return ML + (x - x0) / (x1 - x0) * pw

    shown = [(i, m) for i, m in enumerate(markers, 1) if x0 <= m.t <= x1]
    rows = _marker_rows([sx(m.t) for _, m in shown])
    top = (max(rows) + 1) * MARKER_ROW + 4 if rows else 6
    bottom_y = top + len(panels) * (PANEL_H + GAP) - GAP
    height = bottom_y + BOTTOM
    out = [head, f'<svg width="{W}" height="{height}" '
                 f'viewBox="0 0 {W} {height}" font-family="sans-serif" font-size="11" role="img" '
                 f'aria-label="{e(title)}">']
    xticks = [t for t in _nice_ticks(x0, x1, 8) if x0 <= t <= x1]
    for k, p in enumerate(panels):
        y_top = top + k * (PANEL_H + GAP)
        lo, hi, note = y_range(p)

        def sy(y: float, y_top=y_top, lo=lo, hi=hi) -> float:
            return y_top + PANEL_H - (y - lo) / (hi - lo) * PANEL_H

        out.append(f'<g class="panel" data-series="{e(p.name)}">'
                   f'<rect x="{ML}" y="{y_top}" width="{pw}" height="{PANEL_H}" fill="#fcfcfc" stroke="#bbb"/>')
        for t in xticks:
            out.append(f'<line x1="{sx(t):.1f}" y1="{y_top}" x2="{sx(t):.1f}" y2="{y_top + PANEL_H}" '
                       'stroke="#eee"/>')
        for t in [t for t in _nice_ticks(lo, hi, 2) if lo <= t <= hi]:
            out.append(f'<line x1="{ML - 3}" y1="{sy(t):.1f}" x2="{ML}" y2="{sy(t):.1f}" stroke="#888"/>'
                       f'<text x="{ML - 5}" y="{sy(t) + 3.5:.1f}" text-anchor="end" font-size="10" '
                       f'fill="#555">{_fmt(t)}</text>')
        out.append(f'<text x="6" y="{y_top + 15}" font-weight="bold">{e(p.name)}</text>'
                   f'<text x="6" y="{y_top + 29}" font-size="10" fill="#666">{e(p.unit)}</text>')
        if p.reference:
            out.append(f'<path class="reference" d="{_path(p.reference, sx, sy)}" fill="none" stroke="{REFERENCE}" '
                       'stroke-width="1.2" stroke-dasharray="5,3"/>')
        d = _path(_thin(p.points), sx, sy)
        if d:
            out.append(f'<path class="series" d="{d}" fill="none" stroke="{LINE}" stroke-width="1.5"/>')
        if note:
            out.append(f'<text x="{W - MR + 8}" y="{y_top + PANEL_H / 2 + 4}" font-size="10" '
                       f'fill="#555">{e(note)}</text>')
        out.append("</g>")
    for (i, m), row in zip(shown, rows):
        x, colour = sx(m.t), MARKER_COLOURS.get(m.kind, "#444")
        ty = row * MARKER_ROW + 11
        out.append(f'<g class="marker"><title>{i}: {e(m.label)} at {m.t:.2f} s</title>'
                   f'<line x1="{x:.1f}" y1="{ty + 2}" x2="{x:.1f}" y2="{bottom_y}" stroke="{colour}" '
                   'stroke-width="1" stroke-dasharray="3,2"/>'
                   f'<text x="{x:.1f}" y="{ty}" text-anchor="middle" font-size="10" font-weight="bold" '
                   f'fill="{colour}">{i}</text></g>')
    for t in xticks:
        out.append(f'<line x1="{sx(t):.1f}" y1="{bottom_y}" x2="{sx(t):.1f}" y2="{bottom_y + 4}" stroke="#888"/>'
                   f'<text x="{sx(t):.1f}" y="{bottom_y + 15}" text-anchor="middle">{_fmt(t)}</text>')
    out.append(f'<text x="{ML + pw / 2}" y="{height - 4}" text-anchor="middle">{e(xlabel)}</text>')
    out.append("</svg></figure>")
    return "".join(out)


def markers_html(markers: Sequence[Marker]) -> str:
    """The numbered list the figures' marker numbers refer to."""
    if not markers:
        return ""
    e = html.escape
    items = "".join(f'<li value="{i}"><span style="color:{MARKER_COLOURS.get(m.kind, "#444")};font-weight:bold">'
                    f"{m.t:.2f} s</span> {e(m.label)}</li>" for i, m in enumerate(markers, 1))
    return f'<ol class="phases" style="columns:2;font-size:.9em">{items}</ol>'


# ---- rates --------------------------------------------------------------------------------


def rate_bins(times: Sequence[float], start: float, end: float, width: float,
              run_start: float | None = None) -> list[tuple[float, float, float]]:
    """(bin start, bin end, frames per second) over [start, end], in equal
    bins that tile it exactly: round(span / width) of them, at least one;
    none when the span is shorter than MIN_BIN_S. A bin counts the frames
    that arrived in (its start, its end], the first bin also those at
    `start` unless that is `run_start` (see the module doc). `times` sorted."""
    span = end - start
    if span < MIN_BIN_S:
        return []
    n = max(1, round(span / width))
    w = span / n
    counts = [0] * n
    for t in times:
        if t < start or t > end or (t == start and t == run_start):
            continue
        counts[min(n - 1, max(0, math.ceil((t - start) / w) - 1))] += 1
    return [(start + i * w, end if i == n - 1 else start + (i + 1) * w, c / w) for i, c in enumerate(counts)]


def _steps(bins: list[tuple[float, float, float]], t0: float) -> list[tuple[float, float]]:
    out: list[tuple[float, float]] = []
    for a, b, r in bins:
        out += [(a - t0, r), (b - t0, r)]
    return out


def configurations(an) -> list[tuple[float, float, dict[str, int]]]:
    """(start, end, configured rates) of each span of the run with one
    configuration; a change starts when it was asked for (the device may
    apply it before its ACK comes back)."""
    t0, t1 = an.first_t, an.last_t or an.first_t
    out = []
    for i, ep in enumerate(an.epochs):
        start = t0 if i == 0 else (ep.start if ep.requested is None else min(ep.start, ep.requested))
        start, end = max(start, t0), min(an.epoch_end(i), t1)
        if end > start:
            out.append((start, end, ep.rates))
    return out


def frame_times(an) -> tuple[dict[str, list[float]], str]:
    """Each item's frame times for the rate panels, and which clock they are
    on: the flight controller's time stamps when the analyzer trusts that
    clock and every frame of the item has one, placed on the host's time
    axis by the frame that came with the least delay; else arrival times."""
    if not an.fc_clock_trusted():
        return an.item_times, "arrival"
    offset = min(t - c for t, _, c in an.fc_stamps if c is not None)
    out, stamped = {}, False
    for item, times in an.item_times.items():
        clocks = an.item_clock[item]
        if clocks and all(c is not None for c in clocks):
            out[item], stamped = sorted(c + offset for c in clocks), True
        else:
            out[item] = times
    return out, "flight controller time stamp" if stamped else "arrival"


def rate_panels(an, width: float) -> tuple[list[Panel], list[str], str]:
    """A panel per broadcast item that was configured or seen, the names of
    those neither configured nor seen (0 Hz throughout), and the clock the
    frames were placed by (`frame_times`)."""
    t0 = an.first_t
    spans = configurations(an)
    times_of, clock = frame_times(an)
    panels, silent = [], []
    for item, times in times_of.items():
        expected = [(a, b, rates.get(item, 0)) for a, b, rates in spans]
        if not times and not any(hz for _, _, hz in expected):
            silent.append(item)
            continue
        points: list[tuple[float, float]] = []
        for a, b, hz in expected:
            bins = rate_bins(times, a, b, max(width, FRAMES_PER_BIN / hz) if hz else width, run_start=t0)
            if bins:
                points += _steps(bins, t0) + [(b - t0, math.nan)]
        reference = [(x - t0, hz) for a, b, hz in expected for x in (a, b)]
        panels.append(Panel(item, "Hz", points, reference, floor=0.0))
    return panels, silent, clock


# ---- phases -------------------------------------------------------------------------------


def phases(an) -> list[Marker]:
    """What the run did, from the commands it sent and the ACKs it got, in time order."""
    t0 = an.first_t
    out = []
    for i, ep in enumerate(an.epochs[1:], 1):
        t = ep.start if ep.requested is None else min(ep.start, ep.requested)
        back = ep.rates == an.epochs[0].rates
        out.append(Marker(t - t0, "set frequency: " + ("back to the rates the run started with" if back
                                                       else "new rates (acknowledged)"), "frequency"))
    asked: dict[int, float] = {}
    done: dict[int, float] = {}
    for key, (t, cmd_set, cmd_id, value) in an.sent.items():
        if (cmd_set, cmd_id) != (1, 0) or not value:
            continue
        request = value[0]
        asked[request] = min(t, asked.get(request, t))
        ack = an.acks.get(key)
        if ack and len(ack[3]) >= 2 and int.from_bytes(ack[3][:2], "little") == (OBTAINED if request else RELEASED):
            done[request] = min(ack[0], done.get(request, ack[0]))
    for request, t in asked.items():
        if request in done:
            out.append(Marker(done[request] - t0, "control obtained" if request else "control released", "control"))
        else:
            out.append(Marker(t - t0, f"{'obtain' if request else 'release'} control asked, never confirmed",
                              "control"))
    rules = default_rules()
    for start, mode, zero, _ in an.movement:
        f = rules.classify_control_mode(mode, an.prof.name)["fields"]   # None for a value the spec leaves undefined
        how = ", ".join(str(f[k] or "undefined") for k in ("horizontal_logic", "vertical_logic", "yaw_logic"))
        out.append(Marker(start - t0, f"movement control 0x{mode:02x} ({how})" + (", all setpoints zero" if zero
                                                                                   else ""), "movement"))
    if an.movement:
        out.append(Marker(an.movement[-1][3] - t0, "last movement command", "movement"))
    return sorted(out, key=lambda m: m.t)


# ---- the section ----------------------------------------------------------------------------


def _incident_panels(an, t0: float, t1: float, width: float) -> list[Panel]:
    kinds = {"crc": "CRC failures", "short": "frames cut short", "noise": "noise", "header": "bad headers"}
    panels = []
    for kind, label in kinds.items():
        times = sorted(i[0] for i in an.incidents if i[1] == kind)
        bins = rate_bins(times, t0, t1, width)
        panels.append(Panel(label, "per second", _steps(bins, t0), floor=0.0))
    return panels


def _trace_panels(samples: list[tuple], t0: float, names: Sequence[tuple[int, str, str]]) -> list[Panel]:
    return [Panel(name, unit, [(s[0] - t0, s[i]) for s in samples]) for i, name, unit in names]


def _position_panels(samples: list[tuple], t0: float) -> list[Panel]:
    """North and east from the first sample (m), and the height."""
    if not samples:
        return []
    lat0, lon0 = samples[0][1], samples[0][2]
    r = 6378137.0
    return [Panel("north", "m from the start", [(s[0] - t0, (s[1] - lat0) * r) for s in samples]),
            Panel("east", "m from the start", [(s[0] - t0, (s[2] - lon0) * r * math.cos(lat0)) for s in samples]),
            Panel("height", "m", [(s[0] - t0, s[4]) for s in samples])]


def plots_html(an) -> str:
    """The report's plots section: the phases, then the five figures."""
    with an.lock:
        t0 = an.first_t
        if t0 is None:
            return "<h2>Plots</h2><p>No data received.</p>"
        t1 = an.last_t or t0
        width = BIN_S if t1 - t0 <= 60 else max(BIN_S, (t1 - t0) / 120)
        rates, silent, clock = rate_panels(an, width)
        incidents = _incident_panels(an, t0, t1, width)
        attitude = _trace_panels(an.traces["attitude"], t0, ((1, "roll", "deg"), (2, "pitch", "deg"),
                                                              (3, "yaw", "deg")))
        velocity = _trace_panels(an.traces["velocity"], t0, ((1, "x (north)", "m/s"), (2, "y (east)", "m/s"),
                                                              (3, "z (up)", "m/s")))
        position = _position_panels(an.traces["position"], t0)
        marks = phases(an)
    span = (0.0, t1 - t0)
    x = "t (s) from the first byte received"
    placed = ("where the flight controller's time stamps say they were sent" if clock != "arrival"
              else "when they arrived")
    notes = [f"Time runs from the first byte received; every figure shares it. Rates are frames per second "
             f"in bins of about {width:g} s (wider for slow items) that tile each span of one configuration, so "
             "no bin is partial and none straddles a frequency change; the dashed line is the configured rate. "
             f"Frames are counted {placed}."]
    if silent:
        notes.append(f"Neither configured nor seen (0 Hz throughout): {', '.join(silent)}.")
    return "\n".join([
        "<h2>Plots</h2>",
        *(f"<p>{html.escape(n)}</p>" for n in notes),
        markers_html(marks),
        small_multiples("Measured rate per item", rates, span, marks, x),
        small_multiples("Link incidents", incidents, span, marks, x),
        small_multiples("Attitude (from the quaternion)", attitude, span, marks, x),
        small_multiples("Velocity (ground frame)", velocity, span, marks, x),
        small_multiples("Position", position, span, marks, x),
    ])


def checks_html(results: Sequence) -> str:
    e = html.escape
    rows = "".join(f'<tr><td><code>{e(r.id)}</code></td><td class="{"good" if r.status == "pass" else ("bad" if r.status in ("fail", "error") else "")}">'
                   f"{e(r.status)}</td><td style=\"text-align:left\">{e(r.message)}</td></tr>" for r in results)
    return ("<h2>Every check</h2><table><thead><tr><th>check</th><th>verdict</th><th>what was found</th></tr>"
            f"</thead><tbody>{rows}</tbody></table>")
