"""`osdkc soak`: throughput benchmark of the receiver against `osdkc sim`.

Starts `osdkc sim` in a child process on a pseudo-terminal with every item
of the profile at 100 Hz, holding its broadcast until the receiver has the
port open (SIGUSR1), receives and decodes for the chosen duration with the
acceptance suite's own receiver (device.Port + device_analysis.Analyzer),
then stops the simulator (SIGTERM: it stops sending and waits until the
receiver has read every byte) and compares: frames sent (the simulator's
count), frames received and decoded, frames lost (must be 0), decode latency
(simulator send time, carried in the time stamp item's nanosecond field as
CLOCK_MONOTONIC, to the end of decoding: p50/p95/p99/max) and the
receiver's CPU use.
"""
from __future__ import annotations

import argparse
import json
import resource
import signal
import sys
import tempfile
import time
from pathlib import Path

from osdk_conformance.core.errors import UsageError
from osdk_conformance.core.options import baud_rate, positive_float, positive_int
from osdk_conformance.core.rules import profile as load_profile
from osdk_conformance.core.stats import percentile
from osdk_conformance.device.analysis import Analyzer
from osdk_conformance.device.port import Port
from osdk_conformance.sim.simulator import spawned, stop_child


def add_arguments(ap: argparse.ArgumentParser, profiles: tuple[str, ...]) -> None:
    ap.add_argument("--duration", type=positive_float, default=60.0, metavar="S", help="seconds of streaming (default 60)")
    ap.add_argument("--baud", type=baud_rate, default=921600, help="baud rate of the pty (default 921600)")
    ap.add_argument("--profile", default="a3-fw3.1", choices=profiles, help="wire profile (default a3-fw3.1)")
    ap.add_argument("--hz", type=positive_int, default=100, choices=(1, 10, 50, 100), help="rate of every item (default 100)")
    ap.add_argument("--json", action="store_true", help="print the numbers as one JSON object")


def _cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def run_soak(args: argparse.Namespace) -> int:
    prof = load_profile(args.profile)
    with tempfile.TemporaryDirectory(prefix="osdkc-soak-") as tmp:
        stats_path = Path(tmp) / "sim.json"
        sim_args = ["--profile", args.profile, "--hold", "--baud", str(args.baud), "--stats", str(stats_path)]
        for item in prof.flag_bits:
            sim_args += ["--rate", f"{item}={args.hz}"]
        with spawned(*sim_args) as (url, sim):
            an = Analyzer(args.profile)
            latencies: list[float] = []

            def on_broadcast(t, data):
                ts = data.get("time_stamp")
                if ts is not None and ts.get("nano_time") is not None:
                    now = time.monotonic_ns() & 0xFFFFFFFF
                    latencies.append(((now - ts["nano_time"]) & 0xFFFFFFFF) / 1e6)

            an.on_broadcast = on_broadcast
            port = Port(url, args.baud, an, None)
            port.open()
            cpu0, wall0 = _cpu(), time.monotonic()
            sim.send_signal(signal.SIGUSR1)
            time.sleep(args.duration)
            stop_child(sim)
            # the sim waited until every byte was read; give the reader a moment to decode the last ones
            time.sleep(0.3)
            port.close()
            wall, cpu = time.monotonic() - wall0, _cpu() - cpu0
            an.finish()
            try:
                sent = json.loads(stats_path.read_text())
            except (OSError, ValueError):
                raise UsageError("osdkc sim left no statistics: " + sim.stderr.read().strip()) from None
    received = len(an.bcast)
    seqs = [b[1] for b in an.bcast]
    gaps = sum(((b - a) % 65536) - 1 for a, b in zip(seqs, seqs[1:]) if (b - a) % 65536 > 1)
    frame_bytes = 12 + 2 + 2 + prof.full_payload_size + 4
    out = {
        "profile": args.profile, "baud": args.baud, "items": len(prof.flag_bits), "rate_hz": args.hz,
        "frame_bytes": frame_bytes, "link_use": round(frame_bytes * 10 * args.hz / args.baud, 3),
        "duration_s": round(wall, 2),
        "frames_sent": sent["broadcast_frames"], "frames_received": received,
        "frames_lost": sent["broadcast_frames"] - received, "seq_gaps": gaps,
        "link_incidents": len(an.incidents), "decode_errors": sum(an.decode_errors.values()),
        "latency_ms": {k: round(percentile(latencies, p), 3) for k, p in
                       (("p50", 50), ("p95", 95), ("p99", 99), ("max", 100))},
        "receiver_cpu_s": round(cpu, 2), "receiver_cpu_percent": round(100 * cpu / wall, 1) if wall else None,
    }
    if args.json:
        print(json.dumps(out))
    else:
        lat = out["latency_ms"]
        print(f"soak: {args.profile}, {out['items']} items at {args.hz} Hz, {frame_bytes}-byte frames, "
              f"pty at {args.baud} baud ({out['link_use']:.0%} of the line), {out['duration_s']} s")
        print(f"  frames sent      {out['frames_sent']}")
        print(f"  frames received  {out['frames_received']}")
        print(f"  frames lost      {out['frames_lost']}  (SEQ gaps {gaps}, link incidents {out['link_incidents']}, "
              f"decode errors {out['decode_errors']})")
        print(f"  decode latency   p50 {lat['p50']} ms, p95 {lat['p95']} ms, p99 {lat['p99']} ms, max {lat['max']} ms")
        print(f"  receiver CPU     {out['receiver_cpu_s']} s = {out['receiver_cpu_percent']}% of one core")
    ok = out["frames_lost"] == 0 and gaps == 0 and not out["decode_errors"] and received > 0
    # with --json, standard output is the JSON object alone (as with every --json)
    print(f"soak: {'PASS' if ok else 'FAIL'}: {out['frames_lost']} frames lost", file=sys.stderr if args.json else sys.stdout)
    return 0 if ok else 1
