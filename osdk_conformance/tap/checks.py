"""The tap's checks: what a host sent (host.*), how host and flight
controller got on (pair.*), and, on the same capture, every passive check
of the acceptance suite about the flight controller (device/checks.py).
docs/TAP.md lists them with their limits.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from osdk_conformance.core.rules import default_rules
from osdk_conformance.core.stats import percentile
from osdk_conformance.device.analysis import Finding
from osdk_conformance.device.hostload import HOST_TOO_BUSY
from osdk_conformance.device.checks import (Options as DeviceOptions, decode_checks, link_checks, stream_checks,
                                             value_checks)
from osdk_conformance.harness.report import FAIL, PASS, SKIP, Result
from osdk_conformance.tap.judge import ACK_PATIENCE_S, NEEDS_ACK, HostJudge

AXES = ("x", "y", "z", "yaw")
# which of the four setpoints each range of a mode bounds (facts §2 row 0x01/0x03: roll-or-x, pitch-or-y,
# throttle-or-z, yaw)
RANGE_OF_AXIS = {"x": "horizontal", "y": "horizontal", "z": "vertical", "yaw": "yaw"}


@dataclass
class TapOptions:
    """Limits of the host checks; `device` those of the flight controller's."""

    device: DeviceOptions
    min_movement_hz: float = 10.0     # below it users report movement commands ignored (OSDK#456, #760)
    max_movement_gap: float = 0.5     # s between movement commands under control
    max_tries: int = 5                # transmissions of one command before it is a retry storm
    min_resend_s: float = 0.05        # a resend sooner than this after the last one is part of a storm
    ack_timeout: float = ACK_PATIENCE_S   # s an ACK may take before it is late
    release_grace: float = 2.0        # s of silence at the end that make a session over (control must be back)
    stalls: list = field(default_factory=list)   # (t, s) this tap's mover was not scheduled (live runs: Link.late)


def _finding(cat: str, cid: str, f: Finding, ok: str, bad: str, kind: str) -> Result:
    if not f.count:
        return Result(cat, cid, PASS, ok)
    return Result(cat, cid, FAIL, f"{f.count} {bad}; first: {f.examples[0]}", {"examples": f.examples}, kind=kind)


def frame_checks(j: HostJudge) -> list[Result]:
    out = []
    if j.frames == 0:
        return [Result("host", "host.frames", FAIL if j.malformed_bytes or j.leading_bytes else SKIP,
                       f"the host sent {j.leading_bytes + j.malformed_bytes} bytes and not one valid frame"
                       if j.leading_bytes + j.malformed_bytes else "the host sent nothing",
                       kind="no_frame" if j.leading_bytes else "no_data")]
    joined = f" ({j.leading_bytes} bytes before the first frame: the recording began mid-frame)" if j.leading_bytes else ""
    out.append(_finding("host", "host.frames", j.malformed,
                        f"{j.frames} frames, every byte in a well-formed frame{joined}",
                        f"time(s) the receiver dropped bytes of the host's ({j.malformed_bytes} bytes: header, CRC16, "
                        "CRC32 or length wrong)", "malformed"))
    if j.encrypted_without_key:
        out.append(Result("host", "host.encryption", SKIP,
                          f"{j.encrypted_without_key} frames are encrypted and no key was given (--key-env): "
                          "their commands are not judged", kind="no key"))
    else:
        out.append(_finding("host", "host.encryption", j.unopened, "every frame's DATA opens (ENC, padding, key)",
                            "frame(s) whose DATA does not open", "encryption"))
    out.append(_finding("host", "host.commands", j.unknown, "every command is one of the spec's",
                        "frame(s) that are no command a host sends", "unknown_command"))
    out.append(_finding("host", "host.values", j.bad_values, "every command's value decodes by the spec",
                        "command value(s) that do not decode", "bad_value"))
    return out


def session_checks(j: HostJudge, o: TapOptions) -> list[Result]:
    out = []
    no_ack = [c for c in j.commands if c.session == 0 and c.name in NEEDS_ACK]
    if no_ack:
        c = no_ack[0]
        out.append(Result("host", "host.sessions", FAIL,
                          f"{len(no_ack)} command(s) whose outcome only an ACK tells sent in session 0 (no ACK "
                          f"wanted, facts §1); first: {c.name} at {j.at(c.t)}", kind="session_0"))
    elif j.session_clash.count:
        out.append(_finding("host", "host.sessions", j.session_clash, "", "command(s) sent in a session whose "
                            "last command still waited for its ACK (an ACK is matched against the one command "
                            "waiting in its session: errata E32)", "session_clash"))
    else:
        used = sorted({c.session for c in j.commands})
        out.append(Result("host", "host.sessions", PASS, f"sessions used: {used or 'none'}; one command waits "
                                                        "in a session at a time"))
    out.append(_finding("host", "host.sequence", j.seq_reuse, "a new command never reuses the SEQ of one that "
                        "waits for its ACK", "SEQ reuse(s) while the command with that SEQ waited", "seq_reuse"))
    # retries
    storms = []
    for c in j.commands:
        tries = 1 + len(c.resent)
        gaps = [b - a for a, b in zip([c.t, *c.resent], c.resent)]
        if tries > o.max_tries or any(g < o.min_resend_s for g in gaps):
            storms.append((c, tries, min(gaps) if gaps else None))
    resent = [c for c in j.commands if c.resent]
    details = {"commands": len(j.commands), "resent": len(resent),
               "transmissions": sum(1 + len(c.resent) for c in j.commands)}
    if storms:
        c, tries, gap = storms[0]
        out.append(Result("host", "host.retries", FAIL,
                          f"{len(storms)} command(s) sent in a retry storm (more than {o.max_tries} transmissions, "
                          f"or resent within {o.min_resend_s * 1000:.0f} ms); first: {c.name} seq {c.seq}, "
                          f"{tries} transmissions, {gap * 1000:.1f} ms apart at least", details, kind="retry_storm"))
    else:
        gave_up = [c for c in j.commands if c.session > 0 and c.ack_t is None and not c.superseded]
        note = (f"; {len(gave_up)} left unanswered at the end" if gave_up else "")
        out.append(Result("host", "host.retries", PASS,
                          f"{len(resent)} of {len(j.commands)} commands resent, none more than {o.max_tries} times "
                          f"or within {o.min_resend_s * 1000:.0f} ms{note}", details))
    return out


def order_checks(j: HostJudge, o: TapOptions) -> list[Result]:
    out = []
    if not j.commands and not j.moves:
        return [Result("host", "host.order", SKIP, "the host sent no command", kind="no command")]
    problems = []
    if j.control_asked_before_activation.count:
        problems.append(j.control_asked_before_activation.examples[0])
    outside = [m for m in j.moves if not m.under_control]
    if outside:
        problems.append(f"{len(outside)} movement command(s) sent without control authority (obtained by an "
                        f"ACK 0x0002); first at {j.at(outside[0].t)}")
    if problems:
        out.append(Result("host", "host.order", FAIL, "; ".join(problems),
                          {"movement without control": len(outside)}, kind="order"))
    else:
        steps = [s for s, t in (("version", j.version_at), ("activation", j.activated_at)) if t is not None]
        out.append(Result("host", "host.order", PASS, "order kept: " + " -> ".join(
            steps + (["control obtained"] if j.authority else []) + (["movement"] if j.moves else []))))
    # released at the end
    end = j.an.last_t or j.last_t or 0.0
    if not j.authority:
        out.append(Result("host", "host.release", SKIP, "the host never held control authority", kind="no control"))
    elif not j.authority[-1][1]:
        out.append(Result("host", "host.release", PASS, f"control released at {j.at(j.authority[-1][0])}"))
    elif j.last_t is not None and end - j.last_t >= o.release_grace:
        out.append(Result("host", "host.release", FAIL,
                          f"the host fell silent at {j.at(j.last_t)} ({end - j.last_t:.1f} s before the end) "
                          "still holding control authority: never released", kind="not_released"))
    else:
        out.append(Result("host", "host.release", SKIP, "the recording ended while the host still held control "
                                                       "and was still sending", kind="still in control"))
    return out


def movement_checks(j: HostJudge, o: TapOptions) -> list[Result]:
    if not j.moves:
        return [Result("host", cid, SKIP, "no movement control command sent", kind="no movement")
                for cid in ("host.mode", "host.setpoints", "host.cadence")]
    out = []
    modes: dict[int, int] = {}
    for m in j.moves:
        modes[m.mode] = modes.get(m.mode, 0) + 1
    bad = {}
    for mode in modes:
        c = j.mode_meaning(mode)
        if c["classification"] != "documented":
            bad[mode] = c
    used = ", ".join(f"{mode:#04x} x{n}" for mode, n in modes.items())
    if bad:
        mode, c = next(iter(bad.items()))
        out.append(Result("host", "host.mode", FAIL,
                          f"{len(bad)} mode byte(s) not documented for {j.profile}: {mode:#04x} is "
                          f"{c['classification'].replace('_', ' ')} ({'; '.join(c['reasons'])}); "
                          f"`osdkc explain --mode {mode:#04x} --profile {j.profile}` says more",
                          {"modes": used, **{f"{k:#04x}": v["classification"] for k, v in bad.items()}},
                          kind=c["classification"]))
    else:
        out.append(Result("host", "host.mode", PASS, f"mode bytes used: {used}, each documented for {j.profile}"))
    out.append(_setpoint_check(j))
    out.append(_cadence_check(j, o))
    changes = [(b.t, a.mode, b.mode) for a, b in zip(j.moves, j.moves[1:]) if a.mode != b.mode]
    out.append(Result("host", "host.mode_changes", PASS,
                      f"{len(changes)} mode change(s)" + (": " + ", ".join(f"{j.at(t)} {a:#04x}->{b:#04x}"
                                                                          for t, a, b in changes[:10])
                                                          if changes else ""),
                      {"changes": len(changes)}))
    return out


def _setpoint_check(j: HostJudge) -> Result:
    f = Finding()
    judged = 0
    for m in j.moves:
        ranges = j.ranges(m.mode)
        if ranges is None:
            continue   # host.mode says why: no range exists for the byte
        judged += 1
        bad = []
        for axis, v in zip(AXES, m.setpoints):
            r = ranges[RANGE_OF_AXIS[axis]]
            lo, hi = r.get("min"), r.get("max")
            if not math.isfinite(v):
                bad.append(f"{axis} {v}")
            elif (lo is not None and v < lo) or (hi is not None and v > hi):
                bad.append(f"{axis} {v:g} {r.get('unit', '')} outside {lo if lo is not None else '-inf'}.."
                           f"{hi if hi is not None else 'inf'}")
        f.add(not bad, lambda: f"{j.at(m.t)} mode {m.mode:#04x}: " + ", ".join(bad))
    if not judged:
        return Result("host", "host.setpoints", SKIP, "no movement command with a documented mode byte",
                      kind="no documented mode")
    if f.count:
        return Result("host", "host.setpoints", FAIL, f"{f.count} of {judged} movement commands out of their "
                      f"mode's input range (errata E16); first: {f.examples[0]}", {"examples": f.examples},
                      kind="out_of_range")
    return Result("host", "host.setpoints", PASS, f"{judged} movement commands within their mode's input ranges")


def _cadence_check(j: HostJudge, o: TapOptions) -> Result:
    end = j.an.last_t or j.last_t or 0.0
    spans = j.control_spans(end)
    times = [m.t for m in j.moves if m.under_control]
    if len(times) < 2:
        return Result("host", "host.cadence", SKIP, "fewer than 2 movement commands under control",
                      kind="too few")
    n = len(times)
    span = times[-1] - times[0]
    hz = (n - 1) / span if span > 0 else float("inf")
    # a gap across a change of authority (released, obtained again) is two sessions of control, not a gap
    changes = [t for t, _ in j.authority]
    gaps = sorted(((b - a, a) for a, b in zip(times, times[1:]) if not any(a < t < b for t in changes)),
                  reverse=True) or [(0.0, times[0])]
    longest, at = gaps[0]
    # how much of the longest gap this tap was not running: a gap it read late is partly its own
    lost = sum(min(t + s, at + longest) - max(t, at) for t, s in o.stalls if t < at + longest and t + s > at)
    details = {"commands": n, "hz": round(hz, 2), "longest gap s": round(longest, 3),
               "under control s": round(sum(b - a for a, b in spans), 3),
               "median interval ms": round(1000 * percentile([g for g, _ in gaps], 50), 2)}
    msg = f"{n} movement commands under control at {hz:.1f} Hz, longest gap {longest * 1000:.0f} ms at {j.at(at)}"
    limits = f"(at least {o.min_movement_hz:g} Hz, gaps at most {o.max_movement_gap * 1000:.0f} ms)"
    if hz < o.min_movement_hz or longest > o.max_movement_gap:
        if hz >= o.min_movement_hz and longest - lost <= o.max_movement_gap:
            return Result("host", "host.cadence", SKIP,
                          f"not judged: this tap was not scheduled for {lost:.2f} s of the longest gap, so the gap "
                          f"may be this machine's. Measured: {msg} {limits}", details, kind=HOST_TOO_BUSY)
        slow = "too slow" if hz < o.min_movement_hz else "a gap too long"
        return Result("host", "host.cadence", FAIL, f"{msg}: {slow} {limits}; the flight controller stops "
                      "following movement that is not streamed (OSDK#456, #760)", details, kind="cadence")
    return Result("host", "host.cadence", PASS, f"{msg} {limits}", details)


def frequency_check(j: HostJudge) -> Result:
    if not j.frequency_requests:
        return Result("host", "host.frequency", SKIP, "no set-frequency request sent", kind="none sent")
    rules = default_rules()
    prof = rules.profile(j.profile)
    known = {c["value"]: c for c in rules.data["frequencies"]["codes"]}
    later = {c["value"] for c in rules.data["frequencies"]["codes"] if c["availability"] != "all"}
    bad, asked, tails = [], [], []
    for t, codes in j.frequency_requests:
        for item, code in zip(prof.flag_bits, codes):
            if code not in known or code in later:
                why = "undefined" if code not in known else "only in later SDKs (errata E11)"
                bad.append(f"{j.at(t)}: {item} code {code} ({why})")
        tail = codes[len(prof.flag_bits):]
        if any(tail):   # reserved: reported, not a failure (errata E11; DJI's 3.9.0 leaves them as given)
            tails.append(f"{j.at(t)}: {tail}")
        asked.append(", ".join(f"{item} {known[c]['hz'] if c in known and known[c]['hz'] is not None else 'keep'}"
                               for item, c in zip(prof.flag_bits, codes) if c != 5 and c in known))
    if bad:
        return Result("host", "host.frequency", FAIL, f"{len(bad)} frequency code(s) {j.profile} does not take; "
                      f"first: {bad[0]}", {"examples": bad[:5]}, kind="bad_code")
    note = (f"; the reserved bytes after the last item are not 0 in {len(tails)} request(s) (first {tails[0]}): "
            "receivers ignore them, errata E11 asks for 0") if tails else ""
    return Result("host", "host.frequency", PASS,
                  f"{len(j.frequency_requests)} request(s), every code valid; last asked: {asked[-1] or 'keep all'}"
                  f"{note}", {"reserved bytes not 0": tails[:5]} if tails else {})


def pair_checks(j: HostJudge, o: TapOptions) -> list[Result]:
    j.settle()
    out = []
    answered = [c for c in j.commands if c.ack_t is not None]
    by_name: dict[str, list[float]] = {}
    for c in answered:
        by_name.setdefault(c.name, []).append(c.ack_t - c.t)
    late = [c for c in answered if c.ack_t - c.last_sent > o.ack_timeout]
    details = {name: f"{len(v)} ACKs, median {1000 * percentile(v, 50):.1f} ms, max {1000 * max(v):.1f} ms"
               for name, v in by_name.items()}
    if not j.commands:
        out.append(Result("pair", "pair.ack_latency", SKIP, "no command sent", kind="no command"))
    elif late:
        c = late[0]
        out.append(Result("pair", "pair.ack_latency", FAIL, f"{len(late)} ACK(s) later than {o.ack_timeout:g} s "
                          f"after the last transmission; first: {c.name} seq {c.seq}, "
                          f"{c.ack_t - c.last_sent:.2f} s", details, kind="late_ack"))
    else:
        out.append(Result("pair", "pair.ack_latency", PASS,
                          "; ".join(f"{k}: {v}" for k, v in details.items()) or "no ACK expected", details))
    end = j.an.last_t or j.last_t or 0.0
    unanswered = [c for c in j.commands if c.session >= 2 and c.ack_t is None and not c.superseded
                  and end - c.last_sent > o.ack_timeout]
    if unanswered:
        c = unanswered[0]
        out.append(Result("pair", "pair.unanswered", FAIL,
                          f"{len(unanswered)} well-formed command(s) in an ACK-required session never answered; "
                          f"first: {c.name} session {c.session} seq {c.seq} at {j.at(c.t)} "
                          f"({1 + len(c.resent)} transmissions)", kind="unanswered"))
    else:
        out.append(Result("pair", "pair.unanswered", PASS, f"every command that needs an ACK got one "
                                                          f"({len(answered)} ACKs)"))
    if j.stray_acks.count:
        out.append(_finding("pair", "pair.stray_acks", j.stray_acks, "", "ACK(s) that answer no command the host "
                            "sent in their session", "stray_ack"))
    # control lost while the host still sends movement
    lost = []
    for t, dev in j.fc_took_control():
        after = [m for m in j.moves if t + o.max_movement_gap < m.t]
        regained = next((ta for ta, held in j.authority if ta > t), None)
        still = [m for m in after if regained is None or m.t < regained]
        if still:
            lost.append(f"{j.at(t)}: control went to {default_rules().enum('control_device').get(dev, dev)}; the host "
                        f"sent {len(still)} movement command(s) after it, until {j.at(still[-1].t)}")
    for t in j.lost_control:
        still = [m for m in j.moves if m.t > t + o.max_movement_gap and m.under_control]
        if still:
            lost.append(f"{j.at(t)}: the FC said control authority was lost (0x02/0x01); the host sent "
                        f"{len(still)} movement command(s) after it")
    if lost:
        out.append(Result("pair", "pair.control", FAIL, "the host kept sending movement after it lost control: "
                          + "; ".join(lost[:3]), kind="control_lost"))
    elif j.device_changes or j.lost_control:
        devs = [d for _, d in j.device_changes]
        out.append(Result("pair", "pair.control", PASS,
                          f"control device in the broadcast: {' -> '.join(map(str, devs))}; no movement sent "
                          "after control was lost"))
    else:
        out.append(Result("pair", "pair.control", SKIP, "the broadcast carries no control info",
                          kind="no control info"))
    return out


def host_results(j: HostJudge, o: TapOptions) -> list[Result]:
    return (frame_checks(j) + session_checks(j, o) + order_checks(j, o) + movement_checks(j, o)
            + [frequency_check(j)])


def longest_epoch(an) -> int:
    """The span of one broadcast configuration that lasted longest: a host
    sets the frequencies it wants soon after it starts, so the profile's
    defaults (the acceptance suite's passive window) may last a moment only."""
    spans = [an.epoch_end(i) - ep.start for i, ep in enumerate(an.epochs)]
    return max(range(len(spans)), key=spans.__getitem__)


def fc_results(j: HostJudge, o: TapOptions, link=None) -> list[Result]:
    """The acceptance suite's passive checks on the same capture, the
    stream's over the longest configuration (categories fc.link, fc.decode, ...)."""
    an = j.an
    epoch = longest_epoch(an)
    stream = stream_checks(an, o.device, epoch)
    if epoch:
        where = f"the rates the host set, acknowledged at {j.at(an.epochs[epoch].start)}"
        stream = [replace(r, message=f"{r.message} (over {where})") for r in stream]
    results = link_checks(an, o.device, link) + decode_checks(an, o.device) + stream + value_checks(an)
    return [replace(r, category=f"fc.{r.category}") for r in results]


def tap_results(j: HostJudge, o: TapOptions, link=None) -> list[Result]:
    """Every check: the host's, the pair's, then the flight controller's."""
    return host_results(j, o) + pair_checks(j, o) + fc_results(j, o, link)
