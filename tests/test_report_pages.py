"""The HTML reports as a reader sees them: every kind of page made by the
real commands on small real runs, rendered by a real headless Chromium
(Debian's, pinned in tools/apt-packages.sh), its DOM and its screenshot
checked.

- run, passing: `osdkc run --impl accel` on a few vectors, most of them of
  an operation the native decoder does not claim (a partial testee);
- run, failing: the same decoder cases against a planted-bug mutant that
  decodes -0.0 as 0.0;
- device, passing: `osdkc sim` and an active `osdkc device` run with
  movement control, so every kind of phase is on the plots;
- device, failing: a simulator that flips bits, listened to passively (CRC
  failures: a failure no busy host can cause or hide);
- fuzz: `osdkc fuzz --port` against a simulator with a planted bug it finds;
- tap, failing: `osdkc tap --replay` of a session of `osdkc host` recorded
  through the tap, the host streaming movement at 5 Hz.

Each page must show its verdict first (in the DOM, and in the pixels near
the top of the screenshot), what failed before any table, and plots whose
panels have drawn paths. The device and fuzz runs measure timing, so the
page tests are `realtime`; the pure tests of the plot, diff and JUnit
helpers below them are not. OSDK_REPORT_SHOTS=DIR keeps the screenshots.
"""
from __future__ import annotations

import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
import zlib
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from html.parser import HTMLParser
from itertools import accumulate
from pathlib import Path

import pytest

# every report kind rendered in headless Chromium: `make quick` leaves it out
pytestmark = pytest.mark.slow

from osdk_conformance.bench import tap_hosts
from osdk_conformance.core.paths import ROOT
from osdk_conformance.core.wire import encode
from osdk_conformance.device.analysis import Analyzer
from osdk_conformance.device.plots import Panel, phases, rate_bins, small_multiples, y_range
from osdk_conformance.harness import report
from osdk_conformance.harness.report import Result
from osdk_conformance.harness.vectors import compared_answers
from osdk_conformance.sim.simulator import spawned

CLI = [sys.executable, "-m", "osdk_conformance.cli"]
CHROMIUM = shutil.which("chromium")
WINDOW = (1280, 2000)
VERDICT_OK, VERDICT_NO = bytes.fromhex("e3f6e3"), bytes.fromhex("fde2e2")   # report.py's .ok and .no
TOP_ROWS = 300            # "near the top": the verdict banner lies within these pixel rows
SPECIAL = "a3-fw3.1.special"   # 24 decode_payload cases (-0.0, NaN, infinities) and 448 of check_movement_control


# ---- the pages ------------------------------------------------------------------------------


@dataclass
class Page:
    kind: str
    html: Path
    junit: Path
    status: int
    last_line: str     # the command's verdict line
    output: str
    dom: "Dom | None" = None
    shot: "Screenshot | None" = None


def _command(kind: str, out: Path, args: list[str], cwd: Path = ROOT) -> Page:
    page = Page(kind, out / f"{kind}.html", out / f"{kind}.xml", 0, "", "")
    proc = subprocess.run(CLI + args + ["--html", str(page.html), "--junit", str(page.junit)], cwd=cwd,
                          stdin=subprocess.DEVNULL, capture_output=True, text=True, timeout=180)
    page.status, page.output = proc.returncode, proc.stdout + proc.stderr
    page.last_line = proc.stdout.rstrip().splitlines()[-1] if proc.stdout.strip() else ""
    assert "Traceback" not in page.output, page.output[-3000:]
    return page


def run_pass(out: Path) -> Page:
    return _command("run-pass", out, ["run", "--impl", "accel", "--filter", SPECIAL, "--quiet"])


def run_fail(out: Path) -> Page:
    mutant = f"{sys.executable} {ROOT / 'conformance' / 'testees' / 'mutant_testee.py'} neg_zero_normalised"
    return _command("run-fail", out, ["run", "--testee", mutant, "--filter", f"{SPECIAL}_floats", "--quiet"])


def device_pass(out: Path) -> Page:
    with spawned("--app-id", "1234", "--seed", "1") as (url, _):
        return _command("device-pass", out, [
            "device", "--port", url, "--profile", "a3-fw3.1", "--duration", "1", "--active", "--allow-motion",
            "--yes", "--app-id", "1234", "--active-window", "0.5", "--motion-seconds", "1.2",
            "--max-jitter-ms", "150", "--no-capture", "-q"])


def device_fail(out: Path) -> Page:
    with spawned("--profile", "a3-fw3.1", "--seed", "7", "--bitflip", "0.05") as (url, _):
        return _command("device-fail", out, ["device", "--port", url, "--profile", "a3-fw3.1", "--duration", "2.5",
                                             "--max-jitter-ms", "150", "--no-capture", "-q"])


def fuzz(out: Path) -> Page:
    with spawned("--bug", "long-frame-hang", "--baud", "921600") as (url, proc):
        return _command("fuzz", out, [
            "fuzz", "--port", url, "--profile", "a3-fw3.1", "--kind", "length", "--cases", "30", "--seed", "3",
            "--baud", "921600", "--ack-timeout", "0.3", "--restart-cmd", f"kill -HUP {proc.pid}",
            "--max-findings", "1", "--minimise-trials", "3", "--findings-dir", str(out / "found"), "--no-capture",
            "-q"], cwd=out)


def tap_fail(out: Path) -> Page:
    """`osdkc tap --replay` of a session recorded through the tap: a host that streams movement at 5 Hz."""
    session = tap_hosts.run_session("slow-cadence", 1, out / "tap-session", "m100-fw3.1", seconds=1.0)
    return _command("tap-fail", out, ["tap", "--replay", session["capture"], "--profile", "m100-fw3.1", "-q"])


def render(page: Page, out: Path) -> Page:
    """One Chromium run per page: its screenshot and its DOM after layout,
    in a fresh profile, with every network feature off (the page must not
    need one)."""
    png = out / f"{page.kind}.png"
    with tempfile.TemporaryDirectory(dir=out) as profile:
        proc = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                               "--no-first-run", "--disable-background-networking", "--disable-component-update",
                               "--disable-sync", f"--user-data-dir={profile}", f"--screenshot={png}", "--dump-dom",
                               f"--window-size={WINDOW[0]},{WINDOW[1]}", page.html.as_uri()],
                              capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0 and png.exists(), proc.stderr[-2000:]
    page.dom = Dom.parse(proc.stdout)
    page.shot = Screenshot(png.read_bytes())
    return page


@pytest.fixture(scope="module")
def pages(tmp_path_factory) -> dict[str, Page]:
    if CHROMIUM is None:
        pytest.fail("chromium is not installed; `make setup` installs it (tools/apt-packages.sh)")
    out = tmp_path_factory.mktemp("pages")
    # the passing device run alone: it measures rates and motion, and a simulator not read in time
    # loses frames as a UART does; then the rest side by side, each page rendered once it is written
    passed = device_pass(out)
    tapped = tap_fail(out)   # a live session too, recorded through the tap, then judged from its capture
    with ThreadPoolExecutor(max_workers=5) as pool:
        jobs = [pool.submit(render, passed, out), pool.submit(render, tapped, out)]
        jobs += [pool.submit(lambda f: render(f(out), out), f) for f in (fuzz, device_fail, run_pass, run_fail)]
        rendered = {p.kind: p for p in (j.result() for j in jobs)}
    keep = os.environ.get("OSDK_REPORT_SHOTS")
    if keep:
        Path(keep).mkdir(parents=True, exist_ok=True)
        for kind in rendered:
            shutil.copy(out / f"{kind}.png", Path(keep) / f"{kind}.png")
    return rendered


EXIT = {"run-pass": 0, "run-fail": 1, "device-pass": 0, "device-fail": 1, "fuzz": 1, "tap-fail": 1}
FAILING = [k for k, status in EXIT.items() if status]
PLOTTED = ("device-pass", "device-fail", "fuzz", "tap-fail")


# ---- reading the rendered page ---------------------------------------------------------------


@dataclass
class Element:
    tag: str
    attrs: dict
    index: int
    parent: "Element | None"
    text: list[str] = field(default_factory=list)

    @property
    def classes(self) -> set[str]:
        return set((self.attrs.get("class") or "").split())

    @property
    def content(self) -> str:
        return "".join(self.text)

    def within(self, other: "Element") -> bool:
        p = self.parent
        while p is not None and p is not other:
            p = p.parent
        return p is other


class Dom(HTMLParser):
    """The elements of a page in document order, each with its parent and its text."""

    VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source", "track", "wbr"}

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.elements: list[Element] = []
        self._open: list[Element] = []

    @classmethod
    def parse(cls, text: str) -> "Dom":
        dom = cls()
        dom.feed(text)
        dom.close()
        return dom

    def handle_starttag(self, tag, attrs) -> None:
        el = Element(tag, dict(attrs), len(self.elements), self._open[-1] if self._open else None)
        self.elements.append(el)
        if tag not in self.VOID:
            self._open.append(el)

    def handle_startendtag(self, tag, attrs) -> None:
        self.elements.append(Element(tag, dict(attrs), len(self.elements), self._open[-1] if self._open else None))

    def handle_endtag(self, tag) -> None:
        for i in range(len(self._open) - 1, -1, -1):
            if self._open[i].tag == tag:
                del self._open[i:]
                return

    def handle_data(self, data) -> None:
        for el in self._open:
            el.text.append(data)

    def all(self, tag: str, cls: str | None = None, inside: Element | None = None) -> list[Element]:
        return [e for e in self.elements if e.tag == tag and (cls is None or cls in e.classes)
                and (inside is None or e.within(inside))]

    def heading(self, words: str) -> Element:
        return next(e for e in self.all("h2") if e.content.startswith(words))


class Screenshot:
    """A PNG as Chromium writes it (8-bit RGB or RGBA, not interlaced):
    chunks and CRCs checked, the image data inflated at once, rows
    unfiltered only as far as a check reads."""

    def __init__(self, data: bytes) -> None:
        assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
        pos, idat, ihdr = 8, [], None
        while pos < len(data):
            n, kind = struct.unpack(">I4s", data[pos:pos + 8])
            body = data[pos + 8:pos + 8 + n]
            assert zlib.crc32(kind + body) == struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])[0], kind
            if kind == b"IHDR":
                ihdr = struct.unpack(">IIBBBBB", body)
            elif kind == b"IDAT":
                idat.append(body)
            pos += 12 + n
        self.width, self.height, depth, colour, _, _, interlace = ihdr
        assert depth == 8 and colour in (2, 6) and interlace == 0, ihdr
        self.bpp = 3 if colour == 2 else 4
        self.stride = self.width * self.bpp
        self._raw = zlib.decompress(b"".join(idat))
        assert len(self._raw) == self.height * (self.stride + 1), "image data of the wrong size"
        self.rows: list[bytes] = []

    def row(self, y: int) -> bytes:
        while len(self.rows) <= y:
            self.rows.append(self._unfilter(len(self.rows)))
        return self.rows[y]

    def _unfilter(self, y: int) -> bytes:
        s, bpp = self.stride, self.bpp
        kind, cur = self._raw[y * (s + 1)], self._raw[y * (s + 1) + 1:(y + 1) * (s + 1)]
        prev = self.rows[y - 1] if y else bytes(s)
        if kind == 0:
            return cur
        if kind == 2:   # Up, all bytes at once: a sum per byte with no carry into the next
            a, b = int.from_bytes(cur, "big"), int.from_bytes(prev, "big")
            low, high = int.from_bytes(b"\x7f" * s, "big"), int.from_bytes(b"\x80" * s, "big")
            return (((a & low) + (b & low)) ^ ((a ^ b) & high)).to_bytes(s, "big")
        out = bytearray(s)
        if kind == 1:
            for c in range(bpp):
                out[c::bpp] = bytes(accumulate(cur[c::bpp], lambda t, x: (t + x) & 255))
            return bytes(out)
        for i in range(s):
            a = out[i - bpp] if i >= bpp else 0
            b = prev[i]
            if kind == 3:
                out[i] = (cur[i] + ((a + b) >> 1)) & 255
                continue
            c = prev[i - bpp] if i >= bpp else 0
            pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
            out[i] = (cur[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        return bytes(out)

    def colours(self, y: int) -> set[bytes]:
        """The distinct colours (RGB) of row y."""
        r, bpp = self.row(y), self.bpp
        return {r[i:i + 3] for i in range(0, len(r), bpp)}

    def rows_with(self, colour: bytes, rows: int) -> list[int]:
        return [y for y in range(min(rows, self.height)) if colour in self.colours(y)]


# ---- what every page shows -------------------------------------------------------------------


def body_children(dom: Dom) -> list[Element]:
    body = dom.all("body")[0]
    return [e for e in dom.elements if e.parent is body]


@pytest.mark.realtime
@pytest.mark.parametrize("kind", EXIT)
def test_the_page_leads_with_its_verdict(pages, kind):
    page = pages[kind]
    assert page.status == EXIT[kind], page.output[-3000:]
    title, banner, counts = body_children(page.dom)[:3]
    assert title.tag == "h1"
    assert banner.tag == "p" and "verdict" in banner.classes, banner.attrs
    assert banner.content and banner.content in page.last_line, (banner.content, page.last_line)
    assert ("no" if EXIT[kind] else "ok") in banner.classes
    assert counts.tag == "p" and "counts" in counts.classes and re.match(r"[\d,]+ (case|check)s?: ", counts.content)
    # and in the pixels: the banner's colour, near the top of what a reader sees first
    shot = page.shot
    assert (shot.width, shot.height) == WINDOW
    assert shot.rows_with(VERDICT_NO if EXIT[kind] else VERDICT_OK, TOP_ROWS)


@pytest.mark.realtime
@pytest.mark.parametrize("kind", EXIT)
def test_the_page_needs_no_network(pages, kind):
    assert not re.search(r"(https?|ftp)://|<script|<link", pages[kind].html.read_text())


@pytest.mark.realtime
@pytest.mark.parametrize("kind", EXIT)
def test_the_screenshot_is_not_blank(pages, kind):
    shot = pages[kind].shot
    colours = set()
    for y in range(TOP_ROWS):
        colours |= shot.colours(y)
    assert len(colours) > 20, len(colours)   # text, banner, background: not one flat colour


@pytest.mark.realtime
@pytest.mark.parametrize("kind", FAILING)
def test_what_failed_comes_before_any_table(pages, kind):
    dom = pages[kind].dom
    failures = next(e for e in dom.all("h2") if e.attrs.get("id") == "failures")
    cases = dom.all("details", "case")
    assert cases and cases[0].index > failures.index
    assert {"s-fail", "s-error", "s-xpass"} & dom.all("span", "status")[0].classes
    for words in ("About this run", "By category"):
        assert failures.index < dom.heading(words).index
    outside = [t for t in dom.all("table") if not any(t.within(c) for c in cases)]
    assert outside and all(failures.index < t.index for t in outside)


@pytest.mark.realtime
@pytest.mark.parametrize("kind", [k for k in EXIT if not EXIT[k]])
def test_a_passing_page_has_no_failure_section(pages, kind):
    dom = pages[kind].dom
    assert not [e for e in dom.all("h2") if e.attrs.get("id") == "failures"]
    assert not dom.all("details", "case")


# ---- plots ------------------------------------------------------------------------------------


def path_points(d: str) -> list[list[tuple[float, float]]]:
    """The pen-down runs of an SVG path drawn with M and L only."""
    runs: list[list[tuple[float, float]]] = []
    for cmd, x, y in re.findall(r"([ML])(-?[\d.]+),(-?[\d.]+)", d):
        if cmd == "M":
            runs.append([])
        runs[-1].append((float(x), float(y)))
    return runs


@pytest.mark.realtime
@pytest.mark.parametrize("kind", PLOTTED)
def test_every_plot_panel_is_drawn(pages, kind):
    dom = pages[kind].dom
    figures = dom.all("figure")
    first = 1 if kind == "tap-fail" else 0   # the tap's page: the host's commands come first
    assert len(figures) == (1 if kind == "fuzz" else 5 + first)
    for fig in figures:
        [svg] = dom.all("svg", inside=fig)
        panels = dom.all("g", "panel", inside=svg)
        assert panels, fig.content[:200]
        for panel in panels:
            name = panel.attrs.get("data-series")
            series = dom.all("path", "series", inside=panel)
            if kind == "fuzz" and name in ("round trip", "failed checks") and not series:
                continue   # a second without an answered probe has no round trip to draw
            assert series and any(len(run) >= 2 for run in path_points(series[0].attrs["d"])), name
    # small multiples: one panel per broadcast item, not one chart of fourteen lines
    if kind != "fuzz":
        rates = dom.all("g", "panel", inside=dom.all("svg")[first])
        assert len(rates) >= 10 and len({p.attrs["data-series"] for p in rates}) == len(rates)


@pytest.mark.realtime
def test_the_plots_are_on_screen(pages):
    page = pages["device-pass"]
    rates = len(page.dom.all("g", "panel", inside=page.dom.all("svg")[0]))
    # the series colour (#1f5fa8; antialiased, so any strongly blue pixel) in the rows of the rate
    # figure, which starts under the banner, the counts and the list of phases: a line in every panel
    blue = [y for y in range(TOP_ROWS, 4 * TOP_ROWS)
            if any(p[2] - p[0] > 80 and p[2] - p[1] > 40 for p in page.shot.colours(y))]
    assert len(blue) >= rates, (len(blue), rates)


@pytest.mark.realtime
def test_the_plots_mark_each_phase_of_an_active_run(pages):
    dom = pages["device-pass"].dom
    rates = dom.all("svg")[0]
    titles = [m.content for m in dom.all("g", "marker", inside=rates)]
    for words in ("set frequency: new rates", "control obtained", "movement control 0x00",
                  "movement control 0x48", "movement control 0x90", "last movement command", "control released",
                  "set frequency: back to the rates the run started with"):
        assert any(words in t for t in titles), (words, titles)
    listed = [li.content for li in dom.all("li", inside=dom.all("ol", "phases")[0])]
    assert len(listed) == len(titles)


def _reference_y(ref: list[tuple[float, float]], x: float) -> float:
    """The configured rate's y at x, on the horizontal piece that covers it."""
    for (xa, ya), (xb, yb) in zip(ref, ref[1:]):
        if ya == yb and xa - 0.5 <= x <= xb + 0.5:
            return ya
    raise AssertionError(f"no reference at x={x}")


@pytest.mark.realtime
def test_a_steady_rate_reads_steady_in_the_first_and_the_last_bin(pages):
    dom = pages["device-pass"].dom
    panel = next(p for p in dom.all("g", "panel") if p.attrs.get("data-series") == "time_stamp")
    rect = dom.all("rect", inside=panel)[0]
    zero = float(rect.attrs["y"]) + float(rect.attrs["height"])
    [ref] = path_points(dom.all("path", "reference", inside=panel)[0].attrs["d"])
    runs = [r for r in path_points(dom.all("path", "series", inside=panel)[0].attrs["d"]) if len(r) >= 2]
    for x, y in (runs[0][0], runs[-1][-1]):   # the run's first bin, and the last one before the rates were set back
        want = _reference_y(ref, x)
        assert abs(y - want) <= 0.15 * (zero - want), (x, y, want)


@pytest.mark.realtime
def test_an_all_zero_panel_has_an_axis_from_zero(pages):
    dom = pages["device-pass"].dom
    incidents = dom.all("svg")[1]
    for panel in dom.all("g", "panel", inside=incidents):
        labels = [t.content for t in dom.all("text", inside=panel)]
        assert "all 0" in labels and "0" in labels and "-1" not in labels, labels


# ---- the run report: the difference at a glance, a small JUnit -------------------------------


@pytest.mark.realtime
def test_a_failed_case_shows_expected_and_actual_side_by_side(pages):
    dom = pages["run-fail"].dom
    tables = dom.all("table", "diff")
    assert len(tables) == 3   # the three cases -0.0 breaks
    for table in tables:
        left, right = [], []
        for tr in dom.all("tr", inside=table)[1:]:
            le, ri = dom.all("td", inside=tr)
            left.append(le)
            right.append(ri)
        keys = [[re.match(r'\s*"([^"]+)":', c.content) for c in side] for side in (left, right)]
        assert [k and k[1] for k in keys[0]] == [k and k[1] for k in keys[1]]   # one key order
        marks = [[m.content for m in dom.all("mark", inside=c)] for c in left], \
                [[m.content for m in dom.all("mark", inside=c)] for c in right]
        want = [m for ms in marks[0] for m in ms]
        got = [m for ms in marks[1] for m in ms]
        assert len(want) == len(got) >= 1   # every -0.0 of the case, and nothing else
        for w, g in zip(want, got):
            assert re.search(r'"0x80+", "value": -0\.0', w) and re.search(r'"0x0+", "value": 0\.0', g), (w, g)


@pytest.mark.realtime
def test_the_junit_of_a_partial_testee_has_one_testcase_per_skip_reason(pages):
    page = pages["run-pass"]
    # "CONFORMS for decode_payload: 24 of 472 cases": the native decoder claims decoding alone
    m = re.fullmatch(r"CONFORMS for decode_payload: ([\d,]+) of ([\d,]+) cases", page.last_line)
    assert m, page.last_line
    decoded, chosen = (int(g.replace(",", "")) for g in m.groups())
    skipped_cases = chosen - decoded
    assert skipped_cases > 100
    root = ET.parse(page.junit).getroot()
    assert root.get("tests") == str(chosen) and root.get("skipped") == str(skipped_cases)
    skipped = [tc for tc in root.iter("testcase") if tc.find("skipped") is not None]
    # one testcase per category and reason: the check_movement_control cases all fall in one category
    assert [tc.get("name") for tc in skipped] == [f"{skipped_cases:,} skipped: op_not_claimed"]
    assert skipped[0].find("skipped").get("message").startswith(f"{skipped_cases:,} skipped (op_not_claimed), e.g. ")
    assert sum(tc.find("skipped") is None for tc in root.iter("testcase")) == decoded


# ---- the helpers, without a browser --------------------------------------------------------------


def test_rate_bins_tile_the_span_and_skip_the_backlog_of_the_first_read():
    # 100 Hz for 7.03 s, the first read bringing five frames queued before the port was opened
    times = [0.0] * 5 + [i / 100 for i in range(1, 704)]
    bins = rate_bins(times, 0.0, 7.03, 0.5, run_start=0.0)
    assert len(bins) == 14 and bins[0][0] == 0.0 and bins[-1][1] == 7.03
    # 50.2 frames per bin on average: a bin holds 50 or 51, and one frame in half a second is 2 Hz
    assert all(abs(r - 100) < 2.5 for _, _, r in bins), [round(r, 1) for _, _, r in bins]
    assert rate_bins(times, 7.0, 7.03, 0.5) == []   # too short to say anything


def test_axes_say_what_a_flat_line_is():
    assert y_range(Panel("crc", "per second", [(0, 0.0), (1, 0.0)], floor=0.0)) == (0.0, 1.0, "all 0")
    assert y_range(Panel("roll", "deg", [(0, 5.0), (1, 5.0)])) == (4.0, 6.0, "constant 5")
    lo, hi, note = y_range(Panel("rate", "Hz", [(0, 100.0), (1, 100.0)], [(0, 50.0), (1, 50.0)], floor=0.0))
    assert lo == 0.0 and hi > 100 and note == ""
    svg = small_multiples("t", [Panel("a", "u", [(0, 1.0), (1, math.nan), (2, 2.0)])], (0, 2))
    assert 'd="M' in svg and svg.count("M") >= 2   # a NaN lifts the pen


def test_the_diff_keeps_one_key_order_and_every_bit():
    expected = {"ok": True, "result": {"b": {"f32": "0x80000000", "value": -0.0}, "a": 1, "c": [1, 2]}}
    actual = {"ok": True, "result": {"a": 1.0, "c": [1, 2, 3], "b": {"f32": "0x00000000", "value": 0.0}}}
    page = report.diff_html(expected, actual)
    rows = re.findall(r"<tr><td[^>]*>(.*?)</td><td[^>]*>(.*?)</td></tr>", page)
    keys = [[re.match(r"\s*&quot;(\w+)&quot;:", c) for c in side] for side in zip(*rows)]
    assert [k and k[1] for k in keys[0]] == [k and k[1] for k in keys[1]]
    assert '<mark>{&quot;f32&quot;: &quot;0x80000000&quot;, &quot;value&quot;: -0.0}</mark>' in page
    assert '<mark>{&quot;f32&quot;: &quot;0x00000000&quot;, &quot;value&quot;: 0.0}</mark>' in page
    assert "&quot;a&quot;: 1.0" in page and "<mark>3</mark>" in page   # 1 and 1.0 agree; each shown as written
    assert "2 differences marked" in page
    # what compare() looks at: an error's detail and the fields of a stream event it ignores are left out
    want, got = compared_answers("decode_frame", "invalid", {"error": "bad_crc16"},
                                 {"ok": False, "error": "bad_crc32", "detail": "x"})
    assert want == {"ok": False, "error": "bad_crc16"} and got == {"ok": False, "error": "bad_crc32"}
    want, got = compared_answers("decode_stream", "valid", {"events": [{"kind": "garbage", "offset": 0, "length": 2}]},
                                 {"ok": True, "result": {"events": [{"kind": "garbage", "offset": 0, "length": 3,
                                                                     "detail": "noise"}], "stats": {}}})
    assert got == {"ok": True, "result": {"events": [{"kind": "garbage", "offset": 0, "length": 3}]}}


def test_junit_collapses_skips_per_reason_and_keeps_the_counts():
    results = [Result("c", f"c.{i}", "skip", f"the testee does not support op{i % 2}", kind="op_not_claimed")
               for i in range(1000)]
    results += [Result("c", "c.alone", "skip", "not run: interrupted", kind="interrupted"),
                Result("c", "c.ok", "pass"), Result("c", "c.bad", "fail", "wrong", kind="mismatch")]
    root = ET.fromstring(report.junit_xml(results, "s"))
    names = [tc.get("name") for tc in root.iter("testcase")]
    assert names == ["1,000 skipped: op_not_claimed", "c.alone", "c.ok", "c.bad"]
    assert root.get("tests") == "1003" and root.get("skipped") == "1001" and root.get("failures") == "1"
    body = next(root.iter("skipped")).text
    assert "c.0: the testee does not support op0" in body and "… and 995 more" in body


def test_the_page_lists_what_failed_before_the_tables():
    results = [Result(f"cat{i:02}", f"cat{i:02}.ok", "pass") for i in range(70)]
    results += [Result("cat50", "cat50.bad", "fail", "wrong", {"expected": {"a": 1}, "actual": {"a": 2}}),
                Result("cat60", "cat60.known", "xfail", "listed")]
    page = report.html_report(results, "t", diff=lambda r: (r.details["expected"], r.details["actual"])
                              if "expected" in r.details else None)
    assert page.index('id="failures"') < page.index("<h2>By category</h2>") < page.index('id="known"')
    assert page.index('class="verdict no"') < page.index('class="counts"') < page.index('id="failures"')
    assert "72 cases: <span class=\"s-fail\">1 failed</span>" in page and '<table class="diff">' in page
    assert '<a href="#cat-cat50">' in page and '<a href="#known-cat60">' in page


def test_a_detail_of_records_is_a_table():
    rates = {"time_stamp": {"expected_hz": 100, "frames": 276, "measured_hz": 125.0},
             "magnetometer": {"expected_hz": 0, "frames": 0, "measured_hz": None}}
    page = report.html_report([Result("stream", "stream.rates", "fail", "too fast", {"per item": rates,
                                                                                    "window s": 2.2})], "t")
    assert ('<table class="records"><thead><tr><th></th><th>expected_hz</th><th>frames</th><th>measured_hz</th>'
            "</tr></thead><tbody><tr><td>time_stamp</td><td>100</td><td>276</td><td>125.0</td></tr>"
            "<tr><td>magnetometer</td><td>0</td><td>0</td><td>none</td></tr></tbody></table>") in page
    assert "<pre>2.2</pre>" in page


def test_movement_commands_sent_are_phases_of_the_plots():
    an = Analyzer("a3-fw3.1")
    an.feed_rx(100.0, b"")   # the run's first byte: time 0 of the plots

    def move(t: float, mode: int, *setpoints: float) -> None:   # session 0: no ACK, not in `sent`
        an.feed_tx(t, encode(cmd_set=1, cmd_id=3, value=bytes([mode]) + struct.pack("<4f", *setpoints), session=0,
                             seq=int(t * 100) & 0xFFFF))

    for i in range(50):
        move(101.0 + i * 0.02, 0x48, 1.0, -0.5, 0.3, 10.0)
    for i in range(25):
        move(102.0 + i * 0.02, 0x48, 0.0, 0.0, 0.0, 0.0)
    move(104.0, 0x48, 0.0, 0.0, 0.0, 0.0)   # after a second without one: a run of its own
    assert [(m[0], m[1], m[2]) for m in an.movement] == [(101.0, 0x48, False), (102.0, 0x48, True),
                                                           (104.0, 0x48, True)]
    labels = [(round(m.t, 2), m.label) for m in phases(an)]
    assert labels == [(1.0, "movement control 0x48 (hori_vel, vert_vel, yaw_rate)"),
                      (2.0, "movement control 0x48 (hori_vel, vert_vel, yaw_rate), all setpoints zero"),
                      (4.0, "movement control 0x48 (hori_vel, vert_vel, yaw_rate), all setpoints zero"),
                      (4.0, "last movement command")]
    an.forget_before(103.0)
    assert [m[0] for m in an.movement] == [104.0]
