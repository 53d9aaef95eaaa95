"""Inline SVG plots for the acceptance report (no plotting library needed).

`plots_html(analyzer)` returns markup with four line charts: measured rate
per broadcast item over time, link incidents (CRC failures, frames cut
short, noise) over time, attitude (roll, pitch, yaw) and velocity traces.
`checks_html(results)` is a table of every check with its verdict.
"""
from __future__ import annotations

import html
import math
from typing import Sequence

PALETTE = ("#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
           "#bcbd22", "#17becf", "#393b79", "#637939", "#8c6d31", "#843c39")
W, H = 860, 260
ML, MR, MT, MB = 60, 170, 20, 40


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


def line_chart(title: str, series: dict[str, list[tuple[float, float]]], xlabel: str = "t (s)",
               ylabel: str = "", max_points: int = 1500) -> str:
    """An SVG line chart of named (x, y) series."""
    pts = [p for s in series.values() for p in s if math.isfinite(p[1])]
    e = html.escape
    head = f'<figure><figcaption><b>{e(title)}</b></figcaption>'
    if not pts:
        return head + "<p>No data.</p></figure>"
    x0, x1 = min(p[0] for p in pts), max(p[0] for p in pts)
    y0, y1 = min(p[1] for p in pts), max(p[1] for p in pts)
    if x1 <= x0:
        x1 = x0 + 1
    if y1 - y0 < 1e-9:
        y0, y1 = y0 - 1, y1 + 1
    pad = (y1 - y0) * 0.05
    y0, y1 = y0 - pad, y1 + pad
    pw, ph = W - ML - MR, H - MT - MB

    def sx(x: float) -> float:
        return ML + (x - x0) / (x1 - x0) * pw

    def sy(y: float) -> float:
        return MT + ph - (y - y0) / (y1 - y0) * ph

    out = [head, f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" viewBox="0 0 {W} {H}" '
                 f'font-family="sans-serif" font-size="11" role="img" aria-label="{e(title)}">',
           f'<rect x="{ML}" y="{MT}" width="{pw}" height="{ph}" fill="#fff" stroke="#888"/>']
    for t in _nice_ticks(x0, x1):
        out.append(f'<line x1="{sx(t):.1f}" y1="{MT + ph}" x2="{sx(t):.1f}" y2="{MT + ph + 4}" stroke="#888"/>'
                   f'<text x="{sx(t):.1f}" y="{MT + ph + 16}" text-anchor="middle">{_fmt(t)}</text>')
    for t in _nice_ticks(y0, y1):
        out.append(f'<line x1="{ML}" y1="{sy(t):.1f}" x2="{ML + pw}" y2="{sy(t):.1f}" stroke="#eee"/>'
                   f'<text x="{ML - 6}" y="{sy(t) + 4:.1f}" text-anchor="end">{_fmt(t)}</text>')
    out.append(f'<text x="{ML + pw / 2}" y="{H - 6}" text-anchor="middle">{e(xlabel)}</text>')
    if ylabel:
        out.append(f'<text x="14" y="{MT + ph / 2}" transform="rotate(-90 14 {MT + ph / 2})" '
                   f'text-anchor="middle">{e(ylabel)}</text>')
    for i, (name, s) in enumerate(series.items()):
        color = PALETTE[i % len(PALETTE)]
        s = [p for p in s if math.isfinite(p[1])]
        if len(s) > max_points:
            k = math.ceil(len(s) / max_points)
            s = s[::k]
        if s:
            path = " ".join(f"{sx(x):.1f},{sy(y):.1f}" for x, y in s)
            out.append(f'<polyline fill="none" stroke="{color}" stroke-width="1.5" points="{path}"/>')
        ly = MT + 12 + i * 15
        out.append(f'<line x1="{W - MR + 10}" y1="{ly - 4}" x2="{W - MR + 28}" y2="{ly - 4}" stroke="{color}" '
                   f'stroke-width="3"/><text x="{W - MR + 32}" y="{ly}">{e(name)}</text>')
    out.append("</svg></figure>")
    return "".join(out)


def _binned_rate(times: list[float], t0: float, t1: float, width: float) -> list[tuple[float, float]]:
    n = max(1, math.ceil((t1 - t0) / width))
    counts = [0] * n
    for t in times:
        i = int((t - t0) / width)
        if 0 <= i < n:
            counts[i] += 1
    return [(t0 + (i + 0.5) * width - t0, c / width) for i, c in enumerate(counts)]


def plots_html(an) -> str:
    with an.lock:
        t0 = an.first_t
        if t0 is None:
            return "<h2>Plots</h2><p>No data received.</p>"
        t1 = an.last_t or t0
        width = 0.5 if t1 - t0 <= 60 else max(0.5, (t1 - t0) / 120)
        rates = {item: _binned_rate(ts, t0, t1, width) for item, ts in an.item_times.items() if ts}
        kinds = {"crc": "CRC failures", "short": "frames cut short", "noise": "noise", "header": "bad headers"}
        incidents = {label: _binned_rate([i[0] for i in an.incidents if i[1] == k], t0, t1, width)
                     for k, label in kinds.items()}
        att = an.traces["attitude"]
        vel = an.traces["velocity"]
        attitude = {n: [(s[0] - t0, s[i]) for s in att] for i, n in ((1, "roll"), (2, "pitch"), (3, "yaw"))}
        velocity = {n: [(s[0] - t0, s[i]) for s in vel] for i, n in ((1, "x (north)"), (2, "y (east)"), (3, "z (up)"))}
    return "\n".join([
        "<h2>Plots</h2>",
        line_chart(f"Measured rate per item ({width:g} s bins)", rates, ylabel="Hz"),
        line_chart(f"Link incidents ({width:g} s bins)", incidents, ylabel="per second"),
        line_chart("Attitude (from the quaternion)", attitude, ylabel="degrees"),
        line_chart("Velocity (ground frame)", velocity, ylabel="m/s"),
    ])


def checks_html(results: Sequence) -> str:
    e = html.escape
    rows = "".join(f'<tr><td><code>{e(r.id)}</code></td><td class="{"good" if r.status == "pass" else ("bad" if r.status in ("fail", "error") else "")}">'
                   f"{e(r.status)}</td><td style=\"text-align:left\">{e(r.message)}</td></tr>" for r in results)
    return ("<h2>Every check</h2><table><thead><tr><th>check</th><th>verdict</th><th>what was found</th></tr>"
            f"</thead><tbody>{rows}</tbody></table>")
