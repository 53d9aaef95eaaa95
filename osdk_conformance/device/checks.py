"""The passive checks of the acceptance suite: what a broadcast stream, live
or replayed from a capture, must show (link health, decoding, the profile,
rates, flags, sequence, jitter, plausible values). Each check returns a
named Result; docs/ACCEPTANCE.md lists them.
"""
from __future__ import annotations

from bisect import bisect_left, bisect_right
from dataclasses import dataclass
from typing import Any

from osdk_conformance.core.rules import profile as load_profile
from osdk_conformance.core.stats import percentile
from osdk_conformance.device.hostload import HostLoad
from osdk_conformance.device.port import LinkState
from osdk_conformance.harness.report import FAIL, PASS, SKIP, Result
from osdk_conformance.reference.decode import profiles_decoding

@dataclass
class Options:
    profile: str
    duration: float = 5.0
    rate_tolerance: float = 0.10
    max_link_errors: float = 0.001
    max_loss: float = 0.001
    max_jitter_ms: float = 25.0
    stall_timeout: float = 1.0
    settle: float = 0.3
    flight_status_enum: str | None = None
    expect_rates: dict[str, int] | None = None
    host: HostLoad | None = None   # a live run's host load (None for a replay: not known)


# --------------------------------------------------------------------------
# Passive checks (live and replay)


def _rate(n: int, total: int) -> str:
    return f"{n}/{total}" + (f" ({100.0 * n / total:.2f}%)" if total else "")


def link_checks(an, opts: Options, link: LinkState | None) -> list[Result]:
    out = []
    total = an.frames
    kinds: dict[str, list] = {"noise": [], "header": [], "crc": [], "short": []}
    for inc in an.incidents:
        kinds[inc[1]].append(inc)
    if an.rx_bytes == 0:
        out.append(Result("link", "link.data", FAIL,
                          "no byte received: flight controller off, wrong port, TX/RX swapped, or the OPEN "
                          "protocol output is disabled (DJI Assistant)", kind="no_data"))
    else:
        out.append(Result("link", "link.data", PASS, f"{an.rx_bytes} bytes received"))
    if an.rx_bytes >= 64 and total == 0:
        out.append(Result("link", "link.baud", FAIL,
                          f"{an.rx_bytes} bytes and not one valid frame: wrong baud rate (the flight controller's "
                          "rate is set in DJI Assistant) or this port does not carry the OPEN protocol",
                          kind="wrong_baud"))
    elif total:
        out.append(Result("link", "link.baud", PASS, f"{total} valid frames: the baud rate matches"))
    else:
        out.append(Result("link", "link.baud", SKIP, "too few bytes to judge the baud rate"))

    def incident_check(cid: str, found: list, what: str, verdict: str) -> Result:
        n = len(found)
        details: dict[str, Any] = {"incidents": n, "frames": total, "bytes lost": sum(i[2] for i in found)}
        if found:
            details["examples"] = [f"t={i[0] - (an.first_t or 0):.3f}s: {i[3]}" for i in found[:5]]
        limit = opts.max_link_errors * max(total, 1)
        if total == 0:
            return Result("link", cid, SKIP, "no valid frame to compare with")
        if n > limit:
            return Result("link", cid, FAIL, f"{verdict}: {_rate(n, total + n)} {what} "
                          f"(limit {opts.max_link_errors:.3%})", details, kind=cid.split(".")[1])
        return Result("link", cid, PASS, f"{n} {what} in {total} frames", details)

    out.append(incident_check("link.framing", kinds["noise"] + kinds["header"], "noise/header incidents",
                              "bytes outside frames (line noise, a second talker, or bad headers)"))
    out.append(incident_check("link.crc", kinds["crc"], "CRC failures", "frames with a wrong CRC-16 or CRC-32"))
    out.append(incident_check("link.short_frames", kinds["short"], "frames cut short",
                              "frames interrupted before their LEN (bytes lost or truncated frames)"))
    if link is not None:
        if link.disconnects:
            desc = []
            for lost, back, why in link.disconnects:
                rel = lost - link.t_open
                desc.append(f"lost at t={rel:.2f}s ({why})" + (f", back after {back - lost:.2f}s" if back
                                                                else ", never came back"))
            out.append(Result("link", "link.connection", FAIL, "device unplugged or port lost: " + "; ".join(desc),
                              {"disconnects": desc}, kind="unplugged"))
        else:
            out.append(Result("link", "link.connection", PASS, "the port stayed open for the whole run"))
    out.append(stall_check(an, opts, link))
    return out


def stall_check(an, opts: Options, link) -> Result:
    if not an.rx_chunks:
        return Result("link", "link.stall", SKIP if an.rx_bytes else FAIL,
                      "no data at all" if not an.rx_bytes else "", kind="stalled")
    times = [t for t, _ in an.rx_chunks]
    end = link.t_end if link else times[-1]
    gaps = [(b - a, a) for a, b in zip(times, times[1:])]
    gaps.append((end - times[-1], times[-1]))
    if link:
        gaps.insert(0, (times[0] - link.t_open, link.t_open))
        # silence while the port was down is the connection check's business
        gaps = [(g, a) for g, a in gaps if not any(lo <= a + g / 2 <= (hi or end) for lo, hi, _ in link.disconnects)]
    limit = stall_limit(an, opts)
    host_gaps = [(g, a) for g, a in gaps if g > limit and _fc_kept_sending(an, a, a + g, limit)]
    gaps = [x for x in gaps if x not in host_gaps]
    worst = max(gaps, default=(0.0, 0.0))
    t0 = link.t_open if link else times[0]
    if host_gaps:
        g, a = max(host_gaps)
        note = (f"; the host read nothing for {g:.2f}s from t={a - t0:.2f}s while the flight controller's time stamps "
                "show it kept sending: host scheduling or the serial adapter"
                + (f" ({opts.host.text()})" if opts.host else ""))
    else:
        note = ""
    if worst[0] > limit:
        return Result("link", "link.stall", FAIL,
                      f"stream stalled: no byte for {worst[0]:.2f}s from t={worst[1] - t0:.2f}s "
                      f"(limit {limit:g}s){note}", {"longest silence s": round(worst[0], 3)}, kind="stalled")
    return Result("link", "link.stall", PASS, f"longest silence {worst[0] * 1000:.0f} ms (limit {limit:g}s){note}",
                  {"host-side silences s": [round(g, 3) for g, _ in host_gaps]} if host_gaps else {})


def _fc_kept_sending(an, a: float, b: float, limit: float) -> bool:
    """Whether the frames read on either side of the silence [a, b] are no
    further apart on the flight controller's own clock than `limit`: then
    the FC went on sending and the bytes waited on the host's side."""
    times, clocks = an.item_times.get("time_stamp", []), an.item_clock.get("time_stamp", [])
    i = bisect_right(times, a) - 1
    j = bisect_left(times, b)
    if i < 0 or j >= len(times) or clocks[i] is None or clocks[j] is None:
        return False
    return clocks[j] - clocks[i] <= limit


def stall_limit(an, opts: Options) -> float:
    """--stall-timeout, stretched to three broadcast periods when the FC is configured slower than that:
    an FC whose fastest item is at 1 Hz is silent for a second between frames by design."""
    fastest = [max(e.rates.values()) for e in an.epochs if any(e.rates.values())]
    return max([opts.stall_timeout] + [3.0 / hz for hz in fastest])


def decode_checks(an, opts: Options) -> list[Result]:
    out = []
    nerr = sum(an.decode_errors.values())
    details = {"errors by class": an.decode_errors, "examples": an.decode_examples,
               "frames by command": an.cmd_frames}
    if an.frames == 0:
        out.append(Result("decode", "decode.frames", SKIP, "no valid frame"))
    elif nerr:
        msg = f"{_rate(nerr, an.frames)} frames do not decode for {opts.profile}"
        if an.encrypted_unopened:
            msg += f" ({an.encrypted_unopened} encrypted and no key: give --key-env)"
        out.append(Result("decode", "decode.frames", FAIL, msg, details, kind="undecodable"))
    else:
        out.append(Result("decode", "decode.frames", PASS, f"all {an.frames} frames decode for {opts.profile}", details))
    out.append(profile_check(an, opts))
    return out


def profile_check(an, opts: Options) -> Result:
    bad = an.undecoded_broadcasts
    nb = len(an.bcast)
    if not bad:
        if nb == 0:
            return Result("decode", "decode.profile", FAIL if an.frames else SKIP,
                          "no broadcast frame received" if an.frames else "no valid frame", kind="no_broadcast")
        return Result("decode", "decode.profile", PASS, f"{nb} broadcast frames match the {opts.profile} layout")
    prof = load_profile(opts.profile)
    sizes = []
    for v in bad[:3]:
        flags = v[0] | v[1] << 8 if len(v) >= 2 else 0
        try:
            want = prof.payload_size(flags) + 2
        except Exception:
            want = None
        sizes.append(f"flags 0x{flags:04x}: {len(v)} bytes, {opts.profile} expects "
                     + (f"{want}" if want is not None else "no such flag bits"))
    fits = profiles_decoding(bad, opts.profile)
    details = {"payload sizes": sizes, "broadcasts that decode": nb, "broadcasts that do not": len(bad)}
    if fits:
        return Result("decode", "decode.profile", FAIL,
                      f"wrong profile: the broadcast does not fit {opts.profile} but fits {' and '.join(fits)} "
                      f"(run with --profile {fits[0]})", details, kind="wrong_profile")
    return Result("decode", "decode.profile", FAIL,
                  f"{len(bad)} broadcast frames fit no known profile (item sizes do not match)", details,
                  kind="wrong_profile")


def stream_checks(an, opts: Options, epoch: int = 0) -> list[Result]:
    """Rates, flags, sequence, duplicates and jitter over one configuration epoch."""
    ep = an.epochs[epoch]
    t0, t1 = ep.start + opts.settle, an.epoch_end(epoch)
    out = [rate_check(an, opts, ep.rates, t0, t1, "stream.rates", "stream"),
           flags_check(an, ep.rates, t0, t1, "stream.flags", "stream")]
    frames = an.frames_between(t0, t1)
    out += sequence_checks(an, frames, opts)
    out.append(jitter_check(an, frames, opts, max(ep.rates.values(), default=0), t0, t1))
    return out


def rate_check(an, opts: Options, rates: dict, t0: float, t1: float, cid: str, cat: str) -> Result:
    if an.first_t is None:  # the window never started; link.stall reports the silence
        return Result(cat, cid, SKIP, "no byte received: no rate to measure")
    m = an.measure_rates(rates, t0, t1)
    bad, unmeasured = [], []
    for item, r in m.items():
        exp = r["expected_hz"]
        if exp == 0:
            if r["frames"]:
                bad.append(f"{item}: configured 0 Hz, present in {r['frames']} frames")
        elif r["measured_hz"] is None:
            if (t1 - t0) * exp >= 4:
                bad.append(f"{item}: configured {exp} Hz, only {r['frames']} frames in {t1 - t0:.1f}s")
            else:
                unmeasured.append(item)
        elif abs(r["measured_hz"] - exp) > opts.rate_tolerance * exp:
            bad.append(f"{item}: measured {r['measured_hz']} Hz, configured {exp} Hz")
    details = {"window s": round(t1 - t0, 3), "per item": m, "tolerance": f"{opts.rate_tolerance:.0%}"}
    if unmeasured:
        details["too slow to measure in this window"] = unmeasured
    if t1 - t0 <= 0:
        return Result(cat, cid, SKIP, "no time to measure")
    if bad:
        return Result(cat, cid, FAIL, "measured rates do not follow the configuration: " + "; ".join(bad[:4])
                      + (" ..." if len(bad) > 4 else ""), details, kind="rate")
    return Result(cat, cid, PASS, f"{len(m) - len(unmeasured)} item rates within {opts.rate_tolerance:.0%} "
                  "of the configuration", details)


def flags_check(an, rates: dict, t0: float, t1: float, cid: str, cat: str) -> Result:
    frames = an.frames_between(t0, t1)
    if not frames:
        return Result(cat, cid, SKIP, "no broadcast frame in the window")
    top = max(rates.values(), default=0)
    bits = an.prof.flag_bits
    always = [i for i, item in enumerate(bits) if rates.get(item, 0) == top and top > 0]
    never = [i for i, item in enumerate(bits) if rates.get(item, 0) == 0]
    missing = sum(1 for _, _, f in frames if any(not f >> b & 1 for b in always))
    extra = sum(1 for _, _, f in frames if any(f >> b & 1 for b in never))
    details = {"frames": len(frames), f"items at the frame rate ({top} Hz)": [bits[b] for b in always],
               "items off": [bits[b] for b in never],
               "flag words seen": sorted({f"0x{f:04x}" for _, _, f in frames})[:16]}
    if missing or extra:
        parts = []
        if missing:
            parts.append(f"{missing} frames lack an item configured at the frame rate")
        if extra:
            parts.append(f"{extra} frames carry an item configured off (0 Hz)")
        return Result(cat, cid, FAIL, "flag words do not match the configured rates: " + "; ".join(parts),
                      details, kind="flags")
    return Result(cat, cid, PASS, f"flag words of {len(frames)} frames match the configured rates", details)


def _seq_deltas(frames) -> list[int]:
    return [(b[1] - a[1]) % 65536 for a, b in zip(frames, frames[1:])]


def sequence_checks(an, frames, opts: Options) -> list[Result]:
    out = []
    deltas = _seq_deltas(frames)
    if len(deltas) < 2:
        out.append(Result("stream", "stream.sequence", SKIP, "too few broadcast frames"))
    else:
        step = max(set(deltas), key=deltas.count)
        if step == 0:
            out.append(Result("stream", "stream.sequence", PASS,
                              "broadcasts all carry one SEQ: the flight controller does not number them, so "
                              "frame loss cannot be measured from SEQ"))
        else:
            lost = sum(d // step - 1 for d in deltas if d > step and d < 32768)
            odd = sum(1 for d in deltas if d % step or d >= 32768)
            details = {"step": step, "frames": len(frames), "lost": lost, "out of order or odd steps": odd}
            expected = len(frames) + lost
            if lost > opts.max_loss * expected or odd > opts.max_loss * expected:
                out.append(Result("stream", "stream.sequence", FAIL,
                                  f"{_rate(lost, expected)} broadcast frames lost (SEQ gaps)"
                                  + (f", {odd} SEQ steps out of order" if odd else ""), details, kind="loss"))
            else:
                out.append(Result("stream", "stream.sequence", PASS,
                                  f"SEQ steps by {step}: {lost} of {expected} frames lost", details))
    dup = sum(1 for d in deltas if d == 0) if deltas and max(set(deltas), key=deltas.count) != 0 else 0
    if dup:
        out.append(Result("stream", "stream.duplicates", FAIL,
                          f"{dup} broadcast frames repeat the SEQ of the frame before"
                          f" ({an.duplicates} byte-for-byte copies)", kind="duplicate"))
    else:
        out.append(Result("stream", "stream.duplicates", PASS if deltas else SKIP, "no repeated frame"))
    return out


def _spread_ms(residuals: list[float]) -> float:
    return (percentile(residuals, 99.5) - percentile(residuals, 0.5)) * 1000


def arrival_spread(frames) -> tuple[float, float]:
    """(frame period s, spread ms) of the times (first element of each frame
    tuple) around a steady clock, frames placed by their SEQ steps (second
    element; a lost frame leaves its slot empty)."""
    deltas = _seq_deltas(frames)
    step = max(set(deltas), key=deltas.count) or 1
    k, idx = 0, [0]
    for d in deltas:
        k += d // step if d and d % step == 0 and d < 32768 else 1
        idx.append(k)
    ts = [f[0] for f in frames]
    period = (ts[-1] - ts[0]) / idx[-1] if idx[-1] else 0
    return period, _spread_ms([t - ts[0] - i * period for t, i in zip(ts, idx)])


def fc_clock_spread(an, t0: float, t1: float) -> tuple[float, float, int] | None:
    """(period s, spread ms, frames) of the flight controller's own time
    stamps of the frames read in the window that carry them, around a steady
    clock, frames placed by their SEQ steps as for the arrival spread: what
    the FC controls, whatever the host did to the arrival times. None with
    fewer than 10 such frames."""
    stamped = [(c, seq) for t, seq, c in an.fc_stamps if t0 <= t <= t1 and c is not None]
    if len(stamped) < 10:
        return None
    period, spread = arrival_spread(stamped)
    return period, spread, len(stamped)


def jitter_check(an, frames, opts: Options, top_hz: int, t0: float, t1: float) -> Result:
    """The FC's cadence on its own time stamps where the frames carry them;
    the spread of arrival times is the host's as much as the FC's, so it is
    judged only without time stamps, and never on a busy host."""
    if len(frames) < 10 or not top_hz:
        return Result("stream", "stream.jitter", SKIP, "too few broadcast frames")
    period, host_spread = arrival_spread(frames)
    details: dict[str, Any] = {"frame period ms": round(period * 1000, 3),
                               "arrival spread p0.5..p99.5 ms (host side)": round(host_spread, 2),
                               "limit ms": opts.max_jitter_ms}
    if opts.host is not None:
        details.update(opts.host.details())
    host_note = ""
    if host_spread > opts.max_jitter_ms:
        host_note = (f"; the arrival times spread {host_spread:.1f} ms on this host"
                     + (f" ({opts.host.text()})" if opts.host else "")
                     + ": host scheduling or the serial adapter, not the flight controller")
    fc = fc_clock_spread(an, t0, t1)
    if fc is not None:
        fc_period, fc_spread, n = fc
        details.update({"clock": "flight controller time stamp", "FC frame period ms": round(fc_period * 1000, 3),
                        "FC time stamp spread p0.5..p99.5 ms": round(fc_spread, 2), "time-stamped frames": n})
        if fc_spread > opts.max_jitter_ms:
            return Result("stream", "stream.jitter", FAIL,
                          f"the flight controller's own time stamps spread {fc_spread:.1f} ms around a steady "
                          f"{1 / fc_period if fc_period else 0:.1f} Hz clock (limit {opts.max_jitter_ms} ms){host_note}", details,
                          kind="jitter")
        return Result("stream", "stream.jitter", PASS,
                      f"FC time stamps spread {fc_spread:.1f} ms ({n} frames){host_note}", details)
    details["clock"] = "arrival (no time stamp item in the frames)"
    if host_spread <= opts.max_jitter_ms:
        return Result("stream", "stream.jitter", PASS, f"arrival spread {host_spread:.1f} ms", details)
    if opts.host is None or opts.host.busy:
        why = (f"a busy host ({opts.host.text()})" if opts.host else "a replay, whose host load is not known")
        return Result("stream", "stream.jitter", SKIP,
                      f"arrival times spread {host_spread:.1f} ms on {why}, and the frames carry no time stamp: "
                      "the flight controller's jitter cannot be told from the host's (broadcast the time stamp "
                      "item to measure it)", details)
    return Result("stream", "stream.jitter", FAIL,
                  f"arrival times spread {host_spread:.1f} ms around a steady {1 / period if period else 0:.1f} Hz "
                  f"clock (limit {opts.max_jitter_ms} ms) on an idle host ({opts.host.text()}); the frames carry "
                  "no time stamp to tell the FC's part", details, kind="jitter")


VALUE_TEXT = {
    "quaternion_norm": "attitude quaternion is a unit quaternion (|q| within 1e-3 of 1)",
    "gps_health": "GPS health within 0..5",
    "battery": "battery within 0..100 %",
    "rc_channels": "RC sticks within -10000..10000, mode in {-8000, 0, 8000}, gear in {-10000, -4545}",
    "flight_status": "flight status is a value of the profile's enum",
    "time_stamp": "time stamp (1/400 s ticks) never goes back",
    "control_info": "control device and current control mode are defined values",
    "finite": "every float is finite",
}


def value_checks(an) -> list[Result]:
    out = []
    for rule, f in an.findings.items():
        cid = f"values.{rule}"
        if f.samples == 0:
            out.append(Result("values", cid, SKIP, f"item not broadcast: {VALUE_TEXT[rule]} not checked"))
        elif f.count:
            out.append(Result("values", cid, FAIL, f"{_rate(f.count, f.samples)} samples break: {VALUE_TEXT[rule]}",
                              {"examples": f.examples}, kind="implausible"))
        else:
            out.append(Result("values", cid, PASS, f"{f.samples} samples: {VALUE_TEXT[rule]}"))
    return out


def passive_results(an, opts: Options, link=None) -> list[Result]:
    return link_checks(an, opts, link) + decode_checks(an, opts) + stream_checks(an, opts) + value_checks(an)


