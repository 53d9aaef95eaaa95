"""`osdkc plot`: flight data as the small multiples the acceptance report draws.

One panel per series, every panel on one time axis (device/plots.py,
`small_multiples`), in a self-contained HTML page (no script, works
offline) or a standalone SVG. The time axis is the flight controller's
time stamp where the frames carry one (free of the host's scheduling),
else the capture time, else the frame's number; it starts at 0 at the
first frame drawn.

Series are named by item, with a few derived the way people read them:

- `attitude`: roll, pitch and yaw in degrees, from the quaternion;
- `position`: latitude and longitude in degrees (the item sends radians),
  then its altitude and height;
- `velocity`: its x, y, z and the speed (the vector's magnitude);
- any other item: each of its numeric fields as it is (`battery` in %).
"""
from __future__ import annotations

import html
import math
import re
from typing import Iterable, Sequence

import numpy as np

from osdk_conformance.core.errors import UsageError
from osdk_conformance.device.plots import MAX_POINTS, Panel, small_multiples
from osdk_conformance.flight.columns import FlightData
from osdk_conformance.flight.records import attitude_of

UNITS = {"battery": "%", "velocity": "m/s", "acceleration": "m/s²", "angular_rate": "rad/s",
         "position.altitude": "m", "position.height": "m", "gimbal": "deg"}


def _axis(data: FlightData) -> tuple[np.ndarray, str]:
    fc = data.fc_time
    if data.rows and not np.isnan(fc).any():
        return fc - fc[0], "flight controller time (s)"
    if data.has_capture_time and data.rows:
        t = data.time
        return t - np.nanmin(t), "capture time (s)"
    return np.arange(data.rows, dtype=np.float64), "frame"


def _thinned(x: np.ndarray, y: np.ndarray, mask: np.ndarray) -> list[tuple[float, float]]:
    y = np.where(mask, y.astype(np.float64), np.nan)
    k = max(1, math.ceil(len(x) / MAX_POINTS))
    return list(zip(x[::k].tolist(), y[::k].tolist()))


def _quaternion(data: FlightData) -> tuple[np.ndarray, ...]:
    q = [data.values(f"quaternion.q{i}").astype(np.float64) for i in range(4)]
    return tuple(q) + (data.valid("quaternion.q0"),)


def series(data: FlightData, items: Iterable[str]) -> list[tuple[str, str, np.ndarray, np.ndarray]]:
    """(name, unit, values as float64, present) of each series the items ask for."""
    out: list[tuple[str, str, np.ndarray, np.ndarray]] = []
    for item in items:
        if item == "attitude":
            if "quaternion" not in data.items:
                raise UsageError(f"attitude needs the quaternion item, which the {data.profile} broadcast lacks")
            q0, q1, q2, q3, ok = _quaternion(data)
            # the records' formula (one way to turn the quaternion into angles), over every frame
            roll, pitch, yaw = (np.asarray(a, dtype=np.float64) for a in np.vectorize(attitude_of, otypes=[float] * 3)(q0, q1, q2, q3))
            out += [("roll", "deg", roll, ok), ("pitch", "deg", pitch, ok), ("yaw", "deg", yaw, ok)]
            continue
        columns = data.columns_of([item])
        if item == "position":
            for c in columns:
                if c.name in ("position.latitude", "position.longitude"):
                    out.append((c.name, "deg", np.degrees(data.values(c.name).astype(np.float64)),
                                data.valid(c.name)))
                elif c.kind.startswith("f"):
                    out.append((c.name, UNITS.get(c.name, ""), data.values(c.name).astype(np.float64),
                                data.valid(c.name)))
            continue
        for c in columns:
            if c.kind == "bool" or c.field == "reserved" or c.enum:
                continue   # flags and enums are not curves
            out.append((c.name, UNITS.get(c.name, UNITS.get(c.item, "")), data.values(c.name).astype(np.float64),
                        data.valid(c.name)))
        if item == "velocity":
            x, y, z = (data.values(f"velocity.{a}").astype(np.float64) for a in "xyz")
            out.append(("speed", "m/s", np.sqrt(x * x + y * y + z * z), data.valid("velocity.x")))
    return out


def figure(data: FlightData, items: Sequence[str], title: str) -> str:
    if not data.rows:
        raise UsageError(f"{data.source}: no broadcast frame decodes as {data.profile} "
                         f"({data.counts['frames']} frames, {data.counts['errors']} errors)")
    x, xlabel = _axis(data)
    panels = [Panel(name, unit, _thinned(x, values, present)) for name, unit, values, present in series(data, items)]
    span = (0.0, float(x[-1]) if len(x) else 1.0)
    return small_multiples(title, panels, span, xlabel=xlabel)


def page(data: FlightData, items: Sequence[str]) -> str:
    title = f"{data.source}: {', '.join(items)}"
    counts = ", ".join(f"{v:,} {k.replace('_', ' ')}" for k, v in data.counts.items() if v)
    e = html.escape
    return ("<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\">"
            f"<title>{e(title)}</title></head><body style=\"font-family:sans-serif;margin:1.5em\">"
            f"<h1 style=\"font-size:1.3em\">{e(data.source)}</h1>"
            f"<p>Profile {e(data.profile)}; {data.rows:,} broadcast frames drawn ({e(counts)}).</p>"
            f"{figure(data, items, ', '.join(items))}</body></html>\n")


def svg(data: FlightData, items: Sequence[str]) -> str:
    """The figure as a standalone SVG document."""
    fig = figure(data, items, f"{data.source}: {', '.join(items)}")
    body = re.search(r"<svg .*</svg>", fig, re.S)
    if body is None:   # no panel: the figure says "No data."
        raise UsageError(f"{data.source}: nothing to draw of {', '.join(items)}")
    return body.group(0).replace("<svg ", '<svg xmlns="http://www.w3.org/2000/svg" ', 1) + "\n"
